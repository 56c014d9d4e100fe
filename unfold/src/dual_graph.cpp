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

EdgeStates spanning_forest(const Mesh& mesh, const std::vector<double>& weight,
                           const EdgeConstraints& constraints, double threshold) {
  const int ne = mesh.num_edges();
  EdgeStates state(ne, EdgeState::Cut);
  DisjointSets sets(mesh.num_faces());
  std::vector<EdgeId> order;
  order.reserve(ne);
  for (EdgeId e : all_ids<EdgeId>(ne)) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.boundary() || constraints.cut(e)) continue;
    if (constraints.fold(e)) {
      if (sets.join(edge.face[0], edge.face[1])) state[e] = EdgeState::Fold;
      continue;
    }
    if (weight[e.index()] < threshold) order.push_back(e);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](EdgeId a, EdgeId b) { return weight[a.index()] < weight[b.index()]; });
  for (EdgeId e : order)
    if (sets.join(mesh.edge(e).face[0], mesh.edge(e).face[1])) state[e] = EdgeState::Fold;
  return state;
}

int count_components(const Mesh& mesh) {
  DisjointSets sets(mesh.num_faces());
  int components = mesh.num_faces();
  for (const MeshEdge& e : mesh.edges)
    if (!e.boundary() && sets.join(e.face[0], e.face[1])) --components;
  return components;
}

}  // namespace foldkit::unfold
