#include "foldkit/unfold/dual_graph.hpp"

#include <algorithm>
#include <numeric>

#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {

namespace {

// `measure` per edge mapped linearly onto [0, 1] over the interior edges, its largest value to
// `at_largest` (0 or 1); boundary edges weigh 1.
std::vector<double> normalised(const Mesh& mesh, const std::vector<double>& measure, double at_largest) {
  const int ne = mesh.num_edges();
  double lo = 0, hi = 0;
  bool any = false;
  for (int e = 0; e < ne; ++e) {
    if (mesh.edges[e].boundary()) continue;
    lo = any ? std::min(lo, measure[e]) : measure[e];
    hi = any ? std::max(hi, measure[e]) : measure[e];
    any = true;
  }
  std::vector<double> weight(ne, 0.0);
  for (int e = 0; e < ne; ++e) {
    if (mesh.edges[e].boundary()) {
      weight[e] = 1;
    } else if (hi > lo) {
      const double up = (measure[e] - lo) / (hi - lo);
      weight[e] = at_largest > 0 ? up : 1 - up;
    }
  }
  return weight;
}

}  // namespace

std::vector<double> min_perimeter_weights(const Mesh& mesh) {
  std::vector<double> length(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e)
    length[e] = edge_length(mesh, e);
  return normalised(mesh, length, 0);
}

namespace {

// The label size s that fits in face f beside its edge of `length` (edge_label_room), at most the length.
double side_room(const Mesh& mesh, int f, double length, double aspect) {
  // A label of height s and width aspect * s standing on the edge fits below the apex while
  // L (1 - s / h) >= aspect * s, i.e. s <= L h / (L + aspect h).
  const double height = 2 * face_area(mesh, f) / length;
  return std::min(length, length * height / (length + aspect * height));
}

}  // namespace

std::vector<double> edge_label_room(const Mesh& mesh, double label_aspect) {
  const double aspect = std::max(label_aspect, 0.0);
  std::vector<double> room(mesh.num_edges(), 0.0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    const double length = edge_length(mesh, e);
    if (edge.boundary() || !(length > 0)) continue;
    room[e] = std::min(side_room(mesh, edge.face[0], length, aspect),
                       side_room(mesh, edge.face[1], length, aspect));
  }
  return room;
}

std::vector<LabelFit> tight_edges(const Mesh& mesh, const CutOptions& options) {
  std::vector<LabelFit> tight(mesh.num_edges(), LabelFit::BothSides);
  if (!(options.label_room > 0)) return tight;
  const double aspect = std::max(options.label_aspect, 0.0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    if (edge.boundary()) continue;
    const double length = edge_length(mesh, e);
    int sides = 0;
    if (length > 0)
      for (int f : edge.face)
        sides += side_room(mesh, f, length, aspect) >= options.label_room ? 1 : 0;
    const bool on_tab = options.label_tab_length > 0 && length >= options.label_tab_length;
    tight[e] = sides == 2 ? LabelFit::BothSides : (sides == 1 && on_tab ? LabelFit::OnTab : LabelFit::Tight);
  }
  return tight;
}

namespace {

double median_interior(const Mesh& mesh, const std::vector<double>& measure) {
  std::vector<double> v;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edges[e].boundary()) v.push_back(measure[e]);
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::vector<double> balanced_weights(const Mesh& mesh, const CutOptions& options) {
  const std::vector<double> room = edge_label_room(mesh, options.label_aspect);
  const double tight = options.tight_share * median_interior(mesh, room);
  std::vector<double> weight = min_perimeter_weights(mesh);
  if (!(tight > 0)) return weight;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (!mesh.edges[e].boundary()) weight[e] *= std::min(1.0, room[e] / tight);
  return weight;
}

}  // namespace

std::vector<double> roomy_seam_weights(const Mesh& mesh, double label_aspect) {
  return normalised(mesh, edge_label_room(mesh, label_aspect), 1);
}

namespace {

std::vector<double> preferred_weights(const Mesh& mesh, const CutOptions& options) {
  switch (options.prefer) {
    case SeamPreference::Roomy:
      return roomy_seam_weights(mesh, options.label_aspect);
    case SeamPreference::Balanced:
      return balanced_weights(mesh, options);
    case SeamPreference::Short:
      break;
  }
  return min_perimeter_weights(mesh);
}

// How far each step of tightness (tight_edges) lowers an edge's weight: the whole [0, 1] range of the
// weights, so that tighter edges fold before every roomier one (the noise a fresh tree of the search
// adds, at most 0.3, reorders only the edges nearest a step).
constexpr double kTightWeightStep = 1;

}  // namespace

std::vector<double> cut_weights(const Mesh& mesh, const CutOptions& options) {
  std::vector<double> weight = preferred_weights(mesh, options);
  const std::vector<LabelFit> tight = tight_edges(mesh, options);
  for (int e = 0; e < mesh.num_edges(); ++e)
    weight[e] -= kTightWeightStep * static_cast<int>(tight[e]);
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
