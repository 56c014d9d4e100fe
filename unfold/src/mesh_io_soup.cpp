// Repairs run in an order where each step can rely on the previous one: indices valid, then welded,
// then triangulated, then edge-manifold, then consistently oriented (flips need orientation), then
// zero-area faces removed (collapses need manifold edges), then pinched vertices split, then closed
// components turned outward. make_mesh re-checks everything at the end.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <unordered_map>
#include <unordered_set>

#include "foldkit/error.hpp"
#include "foldkit/unfold/disjoint_sets.hpp"
#include "mesh_io_soup.hpp"

namespace foldkit::unfold::detail {
namespace {

using Tri = std::array<int, 3>;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

std::string plural(std::size_t n, const std::string& word) {
  if (n == 1) return "1 " + word;
  if (word.ends_with("vertex")) return std::to_string(n) + " " + word.substr(0, word.size() - 2) + "ices";
  return std::to_string(n) + " " + word + "s";
}

/// (face, corner) pairs of the faces using each undirected edge: flat sorted arrays rather than a hash map
/// of vectors, because it is rebuilt a few times per load and a million small vectors cost more than the
/// whole rest of the repair.
class EdgeFaces {
 public:
  using Uses = std::span<const std::pair<int, int>>;
  explicit EdgeFaces(const std::vector<Tri>& tris) {
    // Counting sort by the smaller vertex, then a tiny sort per vertex: linear where a global sort of
    // every half-edge was the slowest part of loading.
    int nv = 0;
    for (const Tri& t : tris)
      nv = std::max({nv, t[0] + 1, t[1] + 1, t[2] + 1});
    std::vector<int> bucket(static_cast<std::size_t>(nv) + 1, 0);
    for (const Tri& t : tris)
      for (int i = 0; i < 3; ++i)
        ++bucket[std::min(t[i], t[(i + 1) % 3]) + 1];
    for (int v = 0; v < nv; ++v)
      bucket[v + 1] += bucket[v];
    std::vector<std::pair<std::uint64_t, std::pair<int, int>>> all(tris.size() * 3);
    std::vector<int> fill(bucket.begin(), bucket.end() - 1);
    for (int f = 0; f < static_cast<int>(tris.size()); ++f)
      for (int i = 0; i < 3; ++i) {
        const int a = tris[f][i], b = tris[f][(i + 1) % 3];
        all[fill[std::min(a, b)]++] = {edge_key(a, b), {f, i}};
      }
    for (int v = 0; v < nv; ++v)
      std::sort(all.begin() + bucket[v], all.begin() + bucket[v + 1]);
    uses_.reserve(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (k == 0 || all[k].first != all[k - 1].first) {
        keys_.push_back(all[k].first);
        start_.push_back(static_cast<int>(k));
      }
      uses_.push_back(all[k].second);
    }
    start_.push_back(static_cast<int>(uses_.size()));
  }
  Uses at(std::uint64_t key) const {
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
    if (it == keys_.end() || *it != key) return {};
    return group(static_cast<std::size_t>(it - keys_.begin()));
  }
  bool count(std::uint64_t key) const { return !at(key).empty(); }
  std::size_t size() const { return keys_.size(); }
  Uses group(std::size_t k) const {
    return Uses(uses_.data() + start_[k], static_cast<std::size_t>(start_[k + 1] - start_[k]));
  }

  /// Iterates (key, uses) pairs.
  class Iterator {
   public:
    Iterator(const EdgeFaces* m, std::size_t k) : m_(m), k_(k) {}
    std::pair<std::uint64_t, Uses> operator*() const { return {m_->keys_[k_], m_->group(k_)}; }
    Iterator& operator++() {
      ++k_;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return k_ != o.k_; }

   private:
    const EdgeFaces* m_;
    std::size_t k_;
  };
  Iterator begin() const { return {this, 0}; }
  Iterator end() const { return {this, keys_.size()}; }

 private:
  std::vector<std::uint64_t> keys_;
  std::vector<int> start_;
  std::vector<std::pair<int, int>> uses_;
};

// Where each triangle's corners came from, so that texture coordinates and materials follow every repair:
// corner ids number the soup's polygon corners in order (polygon 0's first), polygon is the source polygon.
struct TriOrigin {
  std::vector<Tri> corner;
  std::vector<int> polygon;
  void flip(int f) { std::swap(corner[f][1], corner[f][2]); }
};

EdgeFaces edge_faces(const std::vector<Tri>& tris) {
  return EdgeFaces(tris);
}

// The file's polygon edges as sorted (smaller, larger) pairs, before any repair: what a user can name.
std::vector<std::array<int, 2>> polygon_edges(const std::vector<std::vector<int>>& polygons) {
  std::vector<std::array<int, 2>> edges;
  for (const auto& poly : polygons)
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// Twice the area over the squared longest edge (the height over the length) below which a triangle counts
// as zero-area: a 0.01 mm bump on a 1 m edge, below anything paper can show, yet above the rounding of
// a midpoint printed with 6 significant digits (tricky/degenerate.obj has one at 4.5e-6).
constexpr double kZeroAreaRelative = 1e-5;
// Edges shorter than this fraction of the longest edge of their face join coincident vertices.
constexpr double kCoincidentRelative = 1e-6;
// The largest coordinate magnitude accepted (float range, what OpenMesh's readers hold).
constexpr double kMaxCoordinate = 3.4028234663852886e38;

bool is_zero_area(const std::vector<Vec3>& p, const Tri& t) {
  const Vec3 a = p[t[0]], b = p[t[1]], c = p[t[2]];
  const double l2 = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  return norm(cross(b - a, c - a)) <= kZeroAreaRelative * l2 || l2 == 0.0;
}

std::vector<Tri> triangulate_all(const PolygonSoup& soup, TriOrigin& origin) {
  std::vector<Tri> tris;
  tris.reserve(soup.polygons.size());
  std::vector<Vec3> pts;
  int first_corner = 0;
  for (int p = 0; p < static_cast<int>(soup.polygons.size()); ++p) {
    const auto& poly = soup.polygons[p];
    const int c = first_corner;
    first_corner += static_cast<int>(poly.size());
    if (poly.size() == 3) {
      tris.push_back({poly[0], poly[1], poly[2]});
      origin.corner.push_back({c, c + 1, c + 2});
      origin.polygon.push_back(p);
      continue;
    }
    pts.clear();
    for (int v : poly)
      pts.push_back(soup.vertices[v]);
    for (const Tri& t : triangulate_polygon(pts)) {
      tris.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
      origin.corner.push_back({c + t[0], c + t[1], c + t[2]});
      origin.polygon.push_back(p);
    }
  }
  return tris;
}

void check_edge_manifold(const std::vector<Tri>& tris, const EdgeFaces& map,
                         const std::vector<int>& file_index, const std::string& name) {
  for (const auto& [key, uses] : map) {
    if (uses.size() <= 2) continue;
    const Tri& t = tris[uses[0].first];
    const int a = t[uses[0].second], b = t[(uses[0].second + 1) % 3];
    throw InputError(name, "non-manifold edge between vertices " + std::to_string(file_index[a] + 1) +
                               " and " + std::to_string(file_index[b] + 1) + " (" +
                               std::to_string(uses.size()) + " faces share it)");
  }
}

// Orients each component consistently by breadth-first search; keeps the majority orientation of the
// file so that a few flipped faces are what gets fixed.
std::size_t orient_consistently(std::vector<Tri>& tris, const EdgeFaces& map, const std::string& name,
                                TriOrigin* origin) {
  const int nf = static_cast<int>(tris.size());
  std::vector<int> component(nf, -1);
  std::vector<char> flipped(nf, 0);
  std::vector<int> queue;
  std::size_t total_flips = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (component[seed] >= 0) continue;
    queue.assign(1, seed);
    component[seed] = seed;
    std::vector<int> members;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int f = queue[q];
      members.push_back(f);
      for (int i = 0; i < 3; ++i) {
        const int a = tris[f][i], b = tris[f][(i + 1) % 3];
        for (auto [g, j] : map.at(edge_key(a, b))) {
          if (g == f) continue;
          // j indexes g as the file had it; g may have been flipped since, so look at it as it is now.
          (void)j;
          const auto& tg = tris[g];
          const bool same_direction =
              (tg[0] == a && tg[1] == b) || (tg[1] == a && tg[2] == b) || (tg[2] == a && tg[0] == b);
          if (component[g] < 0) {
            component[g] = seed;
            if (same_direction) {
              std::swap(tris[g][1], tris[g][2]);
              if (origin) origin->flip(g);
              flipped[g] = 1;
            }
            queue.push_back(g);
          } else if (same_direction) {
            throw InputError(name,
                             "non-orientable surface (like a Moebius strip): its faces cannot be "
                             "oriented consistently");
          }
        }
      }
    }
    const auto flips = static_cast<std::size_t>(
        std::count_if(members.begin(), members.end(), [&](int f) { return flipped[f]; }));
    if (2 * flips > members.size()) {
      for (int f : members) {
        std::swap(tris[f][1], tris[f][2]);
        if (origin) origin->flip(f);
      }
      total_flips += members.size() - flips;
    } else {
      total_flips += flips;
    }
  }
  return total_flips;
}

// Indexed files often repeat a vertex along a seam (texture or normal splits), which would leave the
// seam cut open. Coincident vertices on boundary edges are welded, but only when the welded mesh stays
// edge-manifold and orientable: the file's own connectivity wins over a weld that would break it.
std::size_t weld_boundary_seams(const std::vector<Vec3>& points, std::vector<Tri>& tris,
                                std::vector<int>& alias) {
  const EdgeFaces map = edge_faces(tris);
  std::map<std::array<double, 3>, int> first;
  std::vector<int> remap(points.size());
  std::iota(remap.begin(), remap.end(), 0);
  std::size_t welded = 0;
  for (const auto& [key, uses] : map) {
    if (uses.size() != 1) continue;
    for (int v : {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)}) {
      const Vec3 p = points[v];
      auto [it, inserted] = first.try_emplace({p.x, p.y, p.z}, v);
      if (!inserted && it->second != v && remap[v] == v) {
        remap[v] = it->second;
        ++welded;
      }
    }
  }
  if (welded == 0) return 0;
  std::vector<Tri> trial = tris;
  for (Tri& t : trial)
    for (int& v : t)
      v = remap[v];
  for (const Tri& t : trial)
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return 0;
  const EdgeFaces welded_map = edge_faces(trial);
  for (const auto& [key, uses] : welded_map)
    if (uses.size() > 2) return 0;
  try {
    std::vector<Tri> oriented = trial;
    orient_consistently(oriented, welded_map, "", nullptr);
  } catch (const InputError&) {
    return 0;
  }
  tris = std::move(trial);
  for (std::size_t v = 0; v < remap.size(); ++v)
    if (remap[v] != static_cast<int>(v)) alias[v] = remap[v];
  return welded;
}

// One pass of remove_zero_area: the adjacency of the triangles as the pass found them, and which faces a
// repair of this pass has already changed (touched) or deleted (removed). A face is repaired at most once
// per pass, so every repair sees the adjacency it was planned on.
struct ZeroAreaPass {
  EdgeFaces map;
  std::vector<std::vector<int>> vertex_faces;
  std::vector<char> touched, removed;

  ZeroAreaPass(std::size_t num_points, const std::vector<Tri>& tris)
      : map(edge_faces(tris)), vertex_faces(num_points), touched(tris.size(), 0), removed(tris.size(), 0) {
    for (int f = 0; f < static_cast<int>(tris.size()); ++f)
      for (int v : tris[f])
        vertex_faces[v].push_back(f);
  }
};

// The vertices of the faces around v, sorted, each once; false when one of those faces is already touched.
bool untouched_ring(const ZeroAreaPass& pass, const std::vector<Tri>& tris, int v, std::vector<int>& ring) {
  bool ok = true;
  for (int g : pass.vertex_faces[v]) {
    ok = ok && !pass.touched[g];
    for (int x : tris[g])
      ring.push_back(x);
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  return ok;
}

// Collapses edge u->w into u (removing the faces on it) when the link condition holds: the vertices both
// ends share are exactly the corners opposite the edge, so the surface is not glued to itself. The number
// of faces removed; 0 when the collapse is not made.
std::size_t collapse_edge(ZeroAreaPass& pass, std::vector<Tri>& tris, std::vector<int>& alias, int u, int w) {
  const auto& uses = pass.map.at(edge_key(u, w));
  bool ok = true;
  for (auto [g, j] : uses)
    ok = ok && !pass.touched[g];
  std::vector<int> opposite;
  for (auto [g, j] : uses)
    opposite.push_back(tris[g][(j + 2) % 3]);
  std::vector<int> nu, nw;
  ok = untouched_ring(pass, tris, u, nu) && ok;
  ok = untouched_ring(pass, tris, w, nw) && ok;
  if (!ok) return 0;
  std::vector<int> common;
  std::set_intersection(nu.begin(), nu.end(), nw.begin(), nw.end(), std::back_inserter(common));
  std::erase_if(common, [&](int v) { return v == u || v == w; });
  std::sort(opposite.begin(), opposite.end());
  if (common != opposite) return 0;  // collapsing would glue the surface to itself
  for (auto [g, j] : uses)
    pass.removed[g] = 1;
  for (int g : pass.vertex_faces[w]) {
    pass.touched[g] = 1;
    for (int& v : tris[g])
      if (v == w) v = u;
  }
  alias[w] = u;
  for (int g : pass.vertex_faces[u])
    pass.touched[g] = 1;
  return uses.size();
}

// Removes cap f, whose corner opposite its `longest` edge lies on that edge, by flipping the edge with the
// neighbour across it (or dropping f when it has none). 1 when the cap is gone, 0 when it must wait.
std::size_t flip_cap(ZeroAreaPass& pass, std::vector<Tri>& tris, TriOrigin& origin, int f, int longest) {
  const Tri t = tris[f];
  const int q = t[longest], r = t[(longest + 1) % 3], p = t[(longest + 2) % 3];
  const auto& uses = pass.map.at(edge_key(q, r));
  if (uses.size() == 1) {
    pass.removed[f] = pass.touched[f] = 1;  // a cap on the border covers nothing: drop it
    return 1;
  }
  const auto [g, j] = uses[0].first == f ? uses[1] : uses[0];
  if (pass.touched[g]) return 0;
  const int w = tris[g][(j + 2) % 3];
  if (w == p || pass.map.count(edge_key(p, w))) return 0;
  tris[f] = {p, q, w};
  tris[g] = {p, w, r};
  // The corners keep the texture coordinates of the corners they were (p and q of f, w and r of g).
  const Tri cf = origin.corner[f], cg = origin.corner[g];
  const int cp = cf[(longest + 2) % 3], cq = cf[longest], cw = cg[(j + 2) % 3], cr = cg[j];
  origin.corner[f] = {cp, cq, cw};
  origin.corner[g] = {cp, cw, cr};
  pass.touched[f] = pass.touched[g] = 1;
  return 1;  // the flipped-in pair covers what the neighbour covered: the cap is gone
}

// Repairs zero-area face f (not yet touched in this pass): a collapse when two corners coincide, else a
// flip. The number of faces the repair took away.
std::size_t repair_zero_area_face(ZeroAreaPass& pass, const std::vector<Vec3>& points, std::vector<Tri>& tris,
                                  std::vector<int>& alias, TriOrigin& origin, int f) {
  const Tri t = tris[f];
  double len2[3];
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = points[t[(i + 1) % 3]] - points[t[i]];
    len2[i] = dot(d, d);
  }
  const int shortest = static_cast<int>(std::min_element(len2, len2 + 3) - len2);
  const int longest = static_cast<int>(std::max_element(len2, len2 + 3) - len2);
  if (len2[shortest] <= kCoincidentRelative * kCoincidentRelative * len2[longest] || len2[longest] == 0.0)
    return collapse_edge(pass, tris, alias, t[shortest], t[(shortest + 1) % 3]);
  return flip_cap(pass, tris, origin, f, longest);
}

// Keeps the triangles (and their origins) that no repair removed.
void drop_removed(const std::vector<char>& removed, std::vector<Tri>& tris, TriOrigin& origin) {
  std::vector<Tri> kept;
  TriOrigin kept_origin;
  kept.reserve(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f)
    if (!removed[f]) {
      kept.push_back(tris[f]);
      kept_origin.corner.push_back(origin.corner[f]);
      kept_origin.polygon.push_back(origin.polygon[f]);
    }
  tris = std::move(kept);
  origin = std::move(kept_origin);
}

// Removes zero-area faces without changing the surface: a face with two coincident corners is removed by
// collapsing that edge (when the link condition keeps the mesh manifold); a face whose corner lies on the
// opposite edge is removed by flipping that edge with the neighbour across it. Repairs run in passes
// (a repair can make the next possible) until none is left or a pass makes no progress.
std::size_t remove_zero_area(std::vector<Vec3>& points, std::vector<Tri>& tris, std::vector<int>& alias,
                             const std::string& name, TriOrigin& origin) {
  constexpr int kMaxPasses = 32;
  std::size_t fixed = 0;
  for (int round = 0; round < kMaxPasses; ++round) {
    std::vector<int> degenerate;
    for (int f = 0; f < static_cast<int>(tris.size()); ++f)
      if (is_zero_area(points, tris[f])) degenerate.push_back(f);
    if (degenerate.empty()) return fixed;
    ZeroAreaPass pass(points.size(), tris);
    std::size_t progress = 0;
    for (int f : degenerate)
      if (!pass.touched[f]) progress += repair_zero_area_face(pass, points, tris, alias, origin, f);
    drop_removed(pass.removed, tris, origin);
    fixed += progress;
    if (progress == 0) break;
  }
  for (const Tri& t : tris)
    if (is_zero_area(points, t))
      throw InputError(name, "zero-area face (vertices " + std::to_string(t[0] + 1) + ", " +
                                 std::to_string(t[1] + 1) + ", " + std::to_string(t[2] + 1) +
                                 ") cannot be collapsed without tearing the surface");
  return fixed;
}

// A vertex whose faces form several fans (two surfaces touching at a point) gets one copy per fan.
std::size_t split_pinched_vertices(std::vector<Vec3>& points, std::vector<int>& file_index,
                                   std::vector<Tri>& tris) {
  const int nf = static_cast<int>(tris.size());
  DisjointSets fans(3 * nf);
  const EdgeFaces map = edge_faces(tris);
  for (const auto& [key, uses] : map) {
    if (uses.size() != 2) continue;
    const auto [f, i] = uses[0];
    const auto [g, j] = uses[1];
    // f traverses a->b, g traverses b->a: corner i of f joins corner j+1 of g, and the other end too.
    fans.join(3 * f + i, 3 * g + (j + 1) % 3);
    fans.join(3 * f + (i + 1) % 3, 3 * g + j);
  }
  std::vector<int> first_root(points.size(), -1);
  std::map<int, int> copy_of_root;
  std::vector<char> split(points.size(), 0);
  for (int c = 0; c < 3 * nf; ++c) {
    int& v = tris[c / 3][c % 3];
    const int r = fans.find(c);
    if (first_root[v] < 0) first_root[v] = r;
    if (first_root[v] == r) continue;
    auto [it, inserted] = copy_of_root.try_emplace(r, static_cast<int>(points.size()));
    if (inserted) {
      points.push_back(points[v]);
      file_index.push_back(file_index[v]);
      split[v] = 1;
    }
    v = it->second;
  }
  return static_cast<std::size_t>(std::count(split.begin(), split.end(), 1));
}

// Attribute lists must match the polygons they describe: a reader bug, not a user's, but checked here so
// that no repair indexes past them.
void check_attributes(const PolygonSoup& soup, const std::string& name) {
  const std::size_t n = soup.polygons.size();
  if (!soup.polygon_uvs.empty()) {
    if (soup.polygon_uvs.size() != n) throw InputError(name, "texture coordinates do not match the faces");
    for (std::size_t f = 0; f < n; ++f) {
      if (!soup.polygon_uvs[f].empty() && soup.polygon_uvs[f].size() != soup.polygons[f].size())
        throw InputError(name, "face " + std::to_string(f + 1) + " has " +
                                   std::to_string(soup.polygon_uvs[f].size()) + " texture coordinates for " +
                                   std::to_string(soup.polygons[f].size()) + " corners");
      for (Vec2 uv : soup.polygon_uvs[f])
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
          throw InputError(name, "face " + std::to_string(f + 1) + " has a non-finite texture coordinate");
    }
  }
  if (!soup.polygon_material.empty()) {
    if (soup.polygon_material.size() != n) throw InputError(name, "materials do not match the faces");
    for (int m : soup.polygon_material)
      if (m < -1 || m >= static_cast<int>(soup.materials.size()))
        throw InputError(name, "a face names material " + std::to_string(m + 1) + " of " +
                                   std::to_string(soup.materials.size()));
  }
}

// Removes polygons left with fewer than three corners, and their attributes (and file face index) with them.
void drop_short_polygons(PolygonSoup& soup, std::vector<int>& file_face) {
  std::size_t kept = 0;
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    if (soup.polygons[f].size() < 3) continue;
    soup.polygons[kept] = std::move(soup.polygons[f]);
    file_face[kept] = file_face[f];
    if (!soup.polygon_uvs.empty()) soup.polygon_uvs[kept] = std::move(soup.polygon_uvs[f]);
    if (!soup.polygon_material.empty()) soup.polygon_material[kept] = soup.polygon_material[f];
    ++kept;
  }
  soup.polygons.resize(kept);
  file_face.resize(kept);
  if (!soup.polygon_uvs.empty()) soup.polygon_uvs.resize(kept);
  if (!soup.polygon_material.empty()) soup.polygon_material.resize(kept);
}

// The mesh's face_uv, face_material and materials from where each triangle came from. A polygon without
// texture coordinates in a file that has some gets (0, 0) at every corner: it prints in its colour.
void attach_attributes(const PolygonSoup& soup, const TriOrigin& origin, Mesh& mesh) {
  if (!soup.polygon_uvs.empty()) {
    std::vector<Vec2> corner_uv;
    for (std::size_t f = 0; f < soup.polygons.size(); ++f)
      for (std::size_t k = 0; k < soup.polygons[f].size(); ++k)
        corner_uv.push_back(soup.polygon_uvs[f].empty() ? Vec2{} : soup.polygon_uvs[f][k]);
    mesh.face_uv.resize(origin.corner.size());
    for (std::size_t t = 0; t < origin.corner.size(); ++t)
      for (int i = 0; i < 3; ++i)
        mesh.face_uv[t][i] = corner_uv[origin.corner[t][i]];
  }
  if (!soup.polygon_material.empty()) {
    mesh.face_material.resize(origin.polygon.size());
    for (std::size_t t = 0; t < origin.polygon.size(); ++t)
      mesh.face_material[t] = soup.polygon_material[origin.polygon[t]];
  }
  mesh.materials = soup.materials;
}

// Every coordinate finite and in range, every polygon with three corners or more naming existing
// vertices, and at least one polygon.
void check_indices(const PolygonSoup& soup, const std::string& name) {
  const int nv = static_cast<int>(soup.vertices.size());
  for (int v = 0; v < nv; ++v) {
    const Vec3 p = soup.vertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(name, "vertex " + std::to_string(v + 1) + " has a non-finite coordinate");
    // Binary files reach here unchecked; far beyond any model, and products of such numbers overflow.
    if (std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) > kMaxCoordinate)
      throw InputError(name, "vertex " + std::to_string(v + 1) + ": coordinate out of range");
  }
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& poly = soup.polygons[f];
    if (poly.size() < 3)
      throw InputError(name, "face " + std::to_string(f + 1) + " has only " + std::to_string(poly.size()) +
                                 " vertices (truncated or malformed file)");
    for (int v : poly)
      if (v < 0 || v >= nv)
        throw InputError(name, "face " + std::to_string(f + 1) + " references vertex " +
                                   std::to_string(v + 1) + " (only " + std::to_string(nv) + " vertices)");
  }
  if (soup.polygons.empty()) throw InputError(name, "no faces in the file");
}

// Every vertex replaced by the first vertex at exactly its position, in the polygons; the replacement of
// each vertex (itself if first). The caller reports STL welding as corners -> vertices: OpenMesh's STL
// reader already merges some, this makes it exact whatever the reader did.
std::vector<int> weld_all_coincident(PolygonSoup& soup) {
  const int nv = static_cast<int>(soup.vertices.size());
  std::map<std::array<double, 3>, int> first;
  std::vector<int> remap(nv);
  for (int v = 0; v < nv; ++v) {
    const Vec3 p = soup.vertices[v];
    remap[v] = first.try_emplace({p.x, p.y, p.z}, v).first->second;
  }
  for (auto& poly : soup.polygons)
    for (int& v : poly)
      v = remap[v];
  return remap;
}

// Removes repeated corners from every polygon (with their texture coordinates), then the polygons left with
// fewer than three; the number of polygons removed.
std::size_t remove_repeated_corners(PolygonSoup& soup, std::vector<int>& file_face) {
  std::size_t dropped = 0;
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    auto& poly = soup.polygons[f];
    std::vector<int> clean;
    std::vector<Vec2> clean_uvs;
    for (std::size_t k = 0; k < poly.size(); ++k)
      if (std::find(clean.begin(), clean.end(), poly[k]) == clean.end()) {
        clean.push_back(poly[k]);
        if (!soup.polygon_uvs.empty() && !soup.polygon_uvs[f].empty())
          clean_uvs.push_back(soup.polygon_uvs[f][k]);
      }
    if (clean.size() < 3) ++dropped;
    poly = std::move(clean);
    if (!soup.polygon_uvs.empty()) soup.polygon_uvs[f] = std::move(clean_uvs);
  }
  if (dropped > 0) drop_short_polygons(soup, file_face);
  return dropped;
}

std::size_t count_unused_vertices(const PolygonSoup& soup) {
  std::vector<char> used(soup.vertices.size(), 0);
  for (const auto& poly : soup.polygons)
    for (int v : poly)
      used[v] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

// Keeps only the points some triangle uses, numbered in order of first use; renumbers the triangles and
// appends, per kept point, its vertex in the file to file_vertex.
std::vector<Vec3> keep_used_points(const std::vector<Vec3>& points, const std::vector<int>& file_index,
                                   std::vector<Tri>& tris, std::vector<int>& file_vertex) {
  std::vector<int> new_index(points.size(), -1);
  std::vector<Vec3> used;
  for (Tri& t : tris)
    for (int& v : t) {
      if (new_index[v] < 0) {
        new_index[v] = static_cast<int>(used.size());
        used.push_back(points[v]);
        file_vertex.push_back(file_index[v]);
      }
      v = new_index[v];
    }
  return used;
}

// How many connected components the triangles form, and how many closed ones were turned outward.
struct Components {
  std::size_t count = 0, turned = 0;
};

// Turns every closed component whose signed volume is negative (normals inward) the other way round.
Components turn_closed_components_outward(const std::vector<Vec3>& points, std::vector<Tri>& tris,
                                          TriOrigin& origin) {
  const int nf = static_cast<int>(tris.size());
  DisjointSets components_of(nf);
  const EdgeFaces map = edge_faces(tris);
  std::unordered_set<int> open;
  for (const auto& [key, uses] : map)
    if (uses.size() == 2) components_of.join(uses[0].first, uses[1].first);
  for (const auto& [key, uses] : map)
    if (uses.size() == 1) open.insert(components_of.find(uses[0].first));
  std::unordered_map<int, double> volume;
  for (int f = 0; f < nf; ++f) {
    const Vec3 a = points[tris[f][0]], b = points[tris[f][1]], c = points[tris[f][2]];
    volume[components_of.find(f)] += dot(a, cross(b, c));
  }
  // One pass over the faces for all components: a pass per inward component was quadratic (50,000
  // inverted tetrahedra took 81 s).
  Components out;
  std::unordered_set<int> inward;
  for (const auto& [root, vol] : volume) {
    ++out.count;
    if (open.count(root) || vol >= 0) continue;
    inward.insert(root);
    ++out.turned;
  }
  if (out.turned > 0)
    for (int f = 0; f < nf; ++f)
      if (inward.count(components_of.find(f))) {
        std::swap(tris[f][1], tris[f][2]);
        origin.flip(f);
      }
  return out;
}

}  // namespace

Repaired repair_soup(PolygonSoup soup, const std::string& name, const RepairOptions& options,
                     std::vector<std::string>& notes) {
  check_indices(soup, name);
  const int nv = static_cast<int>(soup.vertices.size());
  Repaired out;
  out.origin.file_edges = polygon_edges(soup.polygons);
  std::vector<int> file_index(nv);
  std::iota(file_index.begin(), file_index.end(), 0);
  // alias[p]: the point that replaced point p in every face (welds, collapses); p itself if none.
  std::vector<int> alias = options.weld_all ? weld_all_coincident(soup) : file_index;

  check_attributes(soup, name);
  std::vector<int> file_face(soup.polygons.size());  // the file's face index of each polygon
  std::iota(file_face.begin(), file_face.end(), 0);
  if (const std::size_t dropped = remove_repeated_corners(soup, file_face); dropped > 0) {
    notes.push_back("dropped " + plural(dropped, "face") + " with repeated corners");
    if (soup.polygons.empty()) throw InputError(name, "every face has repeated corners");
  }
  if (const std::size_t unused = count_unused_vertices(soup); unused > 0 && !options.weld_all)
    notes.push_back("ignored " + plural(unused, "vertex") + " used by no face");

  TriOrigin origin;
  std::vector<Tri> tris = triangulate_all(soup, origin);
  std::vector<Vec3> points = std::move(soup.vertices);
  if (!options.weld_all) {
    if (const std::size_t seams = weld_boundary_seams(points, tris, alias); seams > 0)
      notes.push_back("welded " + plural(seams, "coincident vertex") + " along open seams");
  }
  const EdgeFaces map = edge_faces(tris);
  check_edge_manifold(tris, map, file_index, name);
  if (const std::size_t flips = orient_consistently(tris, map, name, &origin); flips > 0)
    notes.push_back("re-oriented " + plural(flips, "face") + " to match their neighbours");
  if (const std::size_t fixed = remove_zero_area(points, tris, alias, name, origin); fixed > 0)
    notes.push_back("removed " + plural(fixed, "zero-area face") + " (collapsed or flipped)");
  if (tris.empty()) throw InputError(name, "every face has zero area");
  if (const std::size_t split = split_pinched_vertices(points, file_index, tris); split > 0)
    notes.push_back("split " + plural(split, "non-manifold vertex") + " into one copy per fan of faces");

  // Every vertex of the Mesh is on the surface.
  std::vector<Vec3> used = keep_used_points(points, file_index, tris, out.origin.file_vertex);
  out.origin.merged_into.resize(nv);
  for (int v = 0; v < nv; ++v)
    out.origin.merged_into[v] = find_root(alias, v);
  // Closed components are turned so their signed volume is positive (normals outward).
  const Components components = turn_closed_components_outward(used, tris, origin);
  if (components.turned > 0)
    notes.push_back("turned " + plural(components.turned, "closed component") + " outward");
  if (components.count > 1)
    notes.push_back(std::to_string(components.count) + " connected components: unfolded separately");
  out.mesh = make_mesh(std::move(used), std::move(tris), name);
  attach_attributes(soup, origin, out.mesh);
  out.mesh.face_polygon.resize(origin.polygon.size());
  for (std::size_t t = 0; t < origin.polygon.size(); ++t)
    out.mesh.face_polygon[t] = file_face[origin.polygon[t]];
  return out;
}

}  // namespace foldkit::unfold::detail
