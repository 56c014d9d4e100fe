#include "foldkit/unfold/dual_graph.hpp"

#include <algorithm>
#include <numeric>

#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {

std::vector<double> min_perimeter_weights(const Mesh& mesh) {
  const int ne = mesh.num_edges();
  std::vector<double> length(ne);
  double lo = 0, hi = 0;
  bool any = false;
  for (int e = 0; e < ne; ++e) {
    length[e] = edge_length(mesh, e);
    if (mesh.edges[e].boundary()) continue;
    lo = any ? std::min(lo, length[e]) : length[e];
    hi = any ? std::max(hi, length[e]) : length[e];
    any = true;
  }
  std::vector<double> weight(ne, 0.0);
  for (int e = 0; e < ne; ++e) {
    if (mesh.edges[e].boundary())
      weight[e] = 1;
    else if (hi > lo)
      weight[e] = (hi - length[e]) / (hi - lo);
  }
  return weight;
}

std::vector<char> spanning_forest_cuts(const Mesh& mesh, const std::vector<double>& weight,
                                       const EdgeConstraints& constraints, double threshold) {
  const int ne = mesh.num_edges();
  std::vector<char> cut(ne, 1);
  DisjointSets sets(mesh.num_faces());
  std::vector<int> order;
  order.reserve(ne);
  for (int e = 0; e < ne; ++e) {
    if (mesh.edges[e].boundary() || constraints.cut(e)) continue;
    if (constraints.fold(e)) {
      if (sets.join(mesh.edges[e].face[0], mesh.edges[e].face[1])) cut[e] = 0;
      continue;
    }
    if (weight[e] < threshold) order.push_back(e);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] < weight[b]; });
  for (int e : order)
    if (sets.join(mesh.edges[e].face[0], mesh.edges[e].face[1])) cut[e] = 0;
  return cut;
}

int count_components(const Mesh& mesh) {
  DisjointSets sets(mesh.num_faces());
  int components = mesh.num_faces();
  for (const MeshEdge& e : mesh.edges)
    if (!e.boundary() && sets.join(e.face[0], e.face[1])) --components;
  return components;
}

}  // namespace foldkit::unfold
