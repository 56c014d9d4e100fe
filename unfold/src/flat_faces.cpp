#include "foldkit/unfold/flat_faces.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <numeric>

#include "foldkit/unfold/disjoint_sets.hpp"

namespace foldkit::unfold {
namespace {

// The face across edge `corner` of face f, or -1 on the boundary.
int across(const Mesh& mesh, int f, int corner) {
  const MeshEdge& e = mesh.edges[mesh.face_edges[f][corner]];
  if (e.boundary()) return -1;
  return e.face[0] == f ? e.face[1] : e.face[0];
}

// Grows groups of faces (or of units) breadth-first. A member joins a group only across exactly one
// edge to it, so every group stays a tree of triangles that unfolds without a cut inside it.
class TreeGrowth {
 public:
  explicit TreeGrowth(const Mesh& mesh) : mesh_(mesh), group_(mesh.num_faces(), -1) {}

  int group(int f) const { return group_[f]; }
  int count() const { return count_; }

  // Starts a group at the faces `first` (already a tree) and takes in, breadth-first, the candidate sets
  // `members_of(g)` of neighbouring faces g that `accept` admits.
  template <class MembersOf, class Accept>
  void grow(const std::vector<int>& first, MembersOf members_of, Accept accept) {
    const int id = count_++;
    std::deque<int> queue;
    for (int f : first) {
      group_[f] = id;
      queue.push_back(f);
    }
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      for (int c = 0; c < 3; ++c) {
        const int g = across(mesh_, f, c);
        if (g < 0 || group_[g] >= 0 || !accept(g)) continue;
        const std::vector<int>& members = members_of(g);
        if (joining_edges(members, id) != 1) continue;
        for (int h : members) {
          group_[h] = id;
          queue.push_back(h);
        }
      }
    }
  }

 private:
  int joining_edges(const std::vector<int>& members, int id) const {
    int n = 0;
    for (int h : members)
      for (int c = 0; c < 3; ++c) {
        const int k = across(mesh_, h, c);
        n += k >= 0 && group_[k] == id;
      }
    return n;
  }

  const Mesh& mesh_;
  std::vector<int> group_;
  int count_ = 0;
};

Vec3 mean_normal(const Mesh& mesh, const std::vector<int>& faces) {
  Vec3 sum{};
  for (int f : faces)
    sum = sum + face_normal(mesh, f) * face_area(mesh, f);
  return norm(sum) > 0 ? normalized(sum) : sum;
}

bool within(const Mesh& mesh, const std::vector<int>& faces, Vec3 normal, double cos_tol) {
  return std::all_of(faces.begin(), faces.end(),
                     [&](int f) { return dot(face_normal(mesh, f), normal) >= cos_tol; });
}

}  // namespace

FlatFaces find_flat_faces(const Mesh& mesh, double flat_angle_rad) {
  const int nf = mesh.num_faces();
  const double cos_tol = std::cos(std::clamp(flat_angle_rad, 0.0, std::numbers::pi / 2));
  FlatFaces out;

  // Step 1: the planar polygons of the file, each a tree of its triangles.
  std::vector<std::vector<int>> polygon_faces;
  std::vector<int> polygon_of(nf);
  {
    std::vector<int> ids(nf);
    for (int f = 0; f < nf; ++f)
      ids[f] = mesh.polygon_of(f);
    std::vector<int> order(nf);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return ids[a] < ids[b]; });
    for (int i = 0; i < nf; ++i) {
      if (i == 0 || ids[order[i]] != ids[order[i - 1]]) polygon_faces.emplace_back();
      polygon_faces.back().push_back(order[i]);
      polygon_of[order[i]] = static_cast<int>(polygon_faces.size()) - 1;
    }
  }
  std::vector<char> planar(polygon_faces.size(), 1);
  for (std::size_t p = 0; p < polygon_faces.size(); ++p)
    if (polygon_faces[p].size() > 1) {
      planar[p] = within(mesh, polygon_faces[p], mean_normal(mesh, polygon_faces[p]), cos_tol);
      out.non_planar_polygons += !planar[p];
    }
  TreeGrowth polygons(mesh);
  std::vector<int> single(1);
  for (int f = 0; f < nf; ++f) {
    if (polygons.group(f) >= 0) continue;
    const int p = polygon_of[f];
    polygons.grow(
        {f},
        [&](int g) -> const std::vector<int>& {
          single[0] = g;
          return single;
        },
        [&](int g) { return planar[p] && polygon_of[g] == p; });
  }

  // Step 2: coplanar neighbours join the largest face among them, within the tolerance of its normal
  // (measured from one normal, so a gently curved surface does not creep into one face).
  std::vector<std::vector<int>> unit_faces(polygons.count());
  for (int f = 0; f < nf; ++f)
    unit_faces[polygons.group(f)].push_back(f);
  std::vector<double> unit_area(unit_faces.size(), 0);
  for (std::size_t u = 0; u < unit_faces.size(); ++u)
    for (int f : unit_faces[u])
      unit_area[u] += face_area(mesh, f);
  std::vector<int> order(unit_faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return unit_area[a] > unit_area[b]; });
  TreeGrowth flat(mesh);
  for (int u : order) {
    if (flat.group(unit_faces[u].front()) >= 0) continue;
    const Vec3 normal = mean_normal(mesh, unit_faces[u]);
    flat.grow(
        unit_faces[u], [&](int g) -> const std::vector<int>& { return unit_faces[polygons.group(g)]; },
        [&](int g) { return within(mesh, unit_faces[polygons.group(g)], normal, cos_tol); });
  }

  out.unit_count = flat.count();
  out.face_unit.resize(nf);
  for (int f = 0; f < nf; ++f)
    out.face_unit[f] = flat.group(f);
  out.inside.assign(mesh.edges.size(), false);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edges[e];
    out.inside[e] = !edge.boundary() && out.face_unit[edge.face[0]] == out.face_unit[edge.face[1]];
  }
  return out;
}

void keep_flat_faces(const Mesh& mesh, const FlatFaces& flat, EdgeConstraints& constraints) {
  const int ne = mesh.num_edges();
  EdgeMap<EdgeRule> user = constraints.rule;
  user.resize(ne, EdgeRule::Free);
  // The user's cuts stay; the folds are decided again below, flat faces first.
  EdgeMap<EdgeRule>& rule = constraints.rule;
  rule = user;
  for (EdgeRule& r : rule)
    if (r == EdgeRule::MustFold) r = EdgeRule::Free;
  DisjointSets folded(mesh.num_faces());
  auto fold = [&](EdgeId e) {
    if (folded.join(mesh.edge(e).face[0], mesh.edge(e).face[1])) rule[e] = EdgeRule::MustFold;
  };
  for (EdgeId e : all_ids<EdgeId>(ne))
    if (flat.inside[e.index()] && rule[e] != EdgeRule::MustCut) fold(e);
  for (EdgeId e : all_ids<EdgeId>(ne))
    if (user[e] == EdgeRule::MustFold) fold(e);
}

void mark_flat_faces(const FlatFaces& flat, Unfolding& unfolding) {
  for (std::size_t e = 0; e < unfolding.edges.size() && e < flat.inside.size(); ++e)
    unfolding.edges[e].inside_face = flat.inside[e] && !unfolding.edges[e].cut;
}

}  // namespace foldkit::unfold
