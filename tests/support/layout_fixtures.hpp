#pragma once
// Unfoldings for the layout tests: the bundled example meshes unfolded with the MST baseline (each
// once per test binary), and a regular tetrahedron cut along a spanning tree, small enough to reason
// about by hand.
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/layout/layout.hpp"
#include "foldkit/unfold/mesh_io.hpp"
#include "foldkit/unfold/parts.hpp"
#include "foldkit/unfold/slits.hpp"
#include "foldkit/unfold/unfold.hpp"
#include "test_paths.hpp"

namespace foldkit::test {

struct UnfoldedExample {
  unfold::Mesh mesh;
  unfold::Unfolding unfolding;
};

/// examples/<name> loaded and unfolded with `method` (by default the MST baseline: many pieces of
/// all sizes, the harder case for packing), cached.
inline const UnfoldedExample& unfolded_example(const std::string& name,
                                               unfold::Method method = unfold::Method::Mst) {
  static std::map<std::pair<std::string, int>, UnfoldedExample> cache;
  const auto key = std::make_pair(name, static_cast<int>(method));
  auto it = cache.find(key);
  if (it == cache.end()) {
    UnfoldedExample ex;
    ex.mesh = unfold::load_mesh(example_mesh(name)).mesh;
    unfold::UnfoldOptions options;
    options.method = method;
    options.threads = 1;
    ex.unfolding = unfold::unfold_mesh(ex.mesh, options).unfolding;
    it = cache.emplace(key, std::move(ex)).first;
  }
  return it->second;
}

/// The parts the pipeline would start from: `unfolding` cut to fit the room of `options` (a --size is
/// needed) as large as the sheet allows.
inline unfold::PartsResult split_to_fit(const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
                                        const layout::LayoutOptions& options) {
  unfold::PartOptions parts;
  parts.room_mm = layout::piece_room_mm(options);
  parts.mm_per_unit = *options.size_mm / unfolding.model_extent;
  return unfold::split_into_parts(mesh, unfolding, parts);
}

/// A regular tetrahedron with unit edges, unfolded by flatten() with the three edges at vertex 0 cut:
/// one piece, three seams, fold angles all positive (convex).
inline UnfoldedExample tetrahedron() {
  const double s = 1 / std::sqrt(2.0);
  std::vector<Vec3> v = {{s, 0, -0.5}, {-s, 0, -0.5}, {0, s, 0.5}, {0, -s, 0.5}};
  for (Vec3& p : v)
    p = p * s;                                                                       // edge length 1
  std::vector<std::array<int, 3>> f = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};  // outward
  UnfoldedExample ex;
  ex.mesh = unfold::make_mesh(v, f, "tetrahedron");
  unfold::EdgeStates state(ex.mesh.num_edges(), unfold::EdgeState::Fold);
  for (unfold::EdgeId e : unfold::all_ids<unfold::EdgeId>(ex.mesh.num_edges()))
    if (ex.mesh.edge(e).v[0] == 0) state[e] = unfold::EdgeState::Cut;
  ex.unfolding = unfold::flatten(ex.mesh, state);
  return ex;
}

/// Pairs of faces across a seam of `u` narrower than `gap_units` that one part of `parts` (`u` cut
/// further) holds both of: slits a split left inside a part.
inline int narrow_pairs_in_one_part(const unfold::Unfolding& u, const unfold::Unfolding& parts,
                                    double gap_units) {
  const std::vector<std::vector<int>> partners = unfold::narrow_seam_partners(u, gap_units);
  int n = 0;
  for (int f = 0; f < u.num_faces(); ++f)
    for (int h : partners[f])
      n += f < h && parts.piece_of_face[f] == parts.piece_of_face[h];
  return n;
}

}  // namespace foldkit::test
