#include "foldkit/layout/split.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include "foldkit/layout/pack.hpp"
#include "foldkit/layout/polygon.hpp"
#include "foldkit/layout/scale.hpp"

namespace foldkit::layout {
namespace {

// Only hull points matter for the fit test, so a part is kept as a hull that grows face by face.
bool fits(const std::vector<Vec2>& hull, const Triangle2& extra, double scale, Vec2 room) {
  std::vector<Vec2> points = hull;
  points.insert(points.end(), extra.begin(), extra.end());
  return max_fit_scale(points, room) >= scale;
}

Vec2 centroid(const Triangle2& t) {
  return (t[0] + t[1] + t[2]) * (1.0 / 3.0);
}

// Greedy growth leaves small leftovers where a part ran into the room's edge: merges every part into
// a neighbour (across a fold) whenever the two together still fit, smallest parts first. Renumbers the
// parts 0..n-1 and returns n.
int merge_parts(const unfold::Unfolding& u, const std::vector<int>& faces, double scale, Vec2 room,
                std::vector<int>& part, int parts) {
  std::vector<std::vector<Vec2>> hull(parts);
  std::vector<int> size(parts, 0);
  for (int f : faces) {
    hull[part[f]].insert(hull[part[f]].end(), u.flat[f].begin(), u.flat[f].end());
    size[part[f]] += 1;
  }
  for (auto& h : hull)
    h = convex_hull(std::move(h));
  std::vector<int> owner(parts);
  for (int p = 0; p < parts; ++p)
    owner[p] = p;
  auto find = [&](int p) {
    while (owner[p] != p)
      p = owner[p] = owner[owner[p]];
    return p;
  };
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<std::vector<int>> next(parts);
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const unfold::UnfoldEdge& edge = u.edges[u.face_edges[f][c]];
        if (edge.cut || edge.boundary()) continue;
        const int a = find(part[edge.face[0]]), b = find(part[edge.face[1]]);
        if (a != b) next[a].push_back(b);
      }
    std::vector<int> order;
    for (int p = 0; p < parts; ++p)
      if (find(p) == p) order.push_back(p);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a] < size[b]; });
    for (int p : order) {
      if (find(p) != p) continue;
      std::vector<int> around;
      for (int q : next[p])
        if (find(q) != p) around.push_back(find(q));
      std::stable_sort(around.begin(), around.end(), [&](int a, int b) { return size[a] < size[b]; });
      for (int q : around) {
        std::vector<Vec2> both = hull[p];
        both.insert(both.end(), hull[q].begin(), hull[q].end());
        if (max_fit_scale(both, room) < scale) continue;
        owner[p] = q;
        hull[q] = convex_hull(std::move(both));
        size[q] += size[p];
        for (int r : next[p])
          next[q].push_back(r);
        merged = true;
        break;
      }
    }
  }
  std::vector<int> renumber(parts, -1);
  int n = 0;
  for (int f : faces) {
    const int root = find(part[f]);
    if (renumber[root] < 0) renumber[root] = n++;
    part[f] = renumber[root];
  }
  return n;
}

// Grows parts over the folds of one piece; a face that would make its part too large waits for a
// later part. Round growth starts each part at the unassigned face lying furthest back along the
// piece's long axis and takes the faces nearest its start first, so parts come out roughly round
// (round parts nest; strips cut off a spindly net do not). Tree growth takes faces breadth-first along
// the folds from the first face of the piece, which often needs fewer parts. Neither wins everywhere.
int grow_parts(const unfold::Unfolding& u, const std::vector<int>& faces, double scale, Vec2 room, bool round,
               std::vector<int>& part) {
  std::vector<Vec2> points;
  for (int f : faces)
    points.insert(points.end(), u.flat[f].begin(), u.flat[f].end());
  const double axis_angle = min_area_rect_angle(points);
  Box2 box;
  for (Vec2 p : points)
    box.add(rotated(p, axis_angle));
  const bool x_long = box.width() >= box.height();
  auto along = [&](int f) {
    const Vec2 c = rotated(centroid(u.flat[f]), axis_angle);
    return x_long ? c.x : c.y;
  };
  std::vector<int> sweep = faces;
  if (round) std::stable_sort(sweep.begin(), sweep.end(), [&](int a, int b) { return along(a) < along(b); });
  long pushed = 0;  // tree growth: faces in the order they were reached

  int parts = 0;
  for (int seed : sweep) {
    if (part[seed] >= 0) continue;
    const int id = parts++;
    const Vec2 start = centroid(u.flat[seed]);
    using Entry = std::pair<double, int>;  // distance from the start, face
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> frontier;
    std::vector<Vec2> hull = convex_hull({u.flat[seed].begin(), u.flat[seed].end()});
    part[seed] = id;
    auto push_neighbours = [&](int f) {
      for (int c = 0; c < 3; ++c) {
        const unfold::UnfoldEdge& edge = u.edges[u.face_edges[f][c]];
        if (edge.cut || edge.boundary()) continue;
        const int g = edge.face[0] == f ? edge.face[1] : edge.face[0];
        if (part[g] < 0) frontier.push({round ? norm(centroid(u.flat[g]) - start) : double(pushed++), g});
      }
    };
    push_neighbours(seed);
    while (!frontier.empty()) {
      const int g = frontier.top().second;
      frontier.pop();
      if (part[g] >= 0 || !fits(hull, u.flat[g], scale, room)) continue;
      part[g] = id;
      std::vector<Vec2> grown = hull;
      grown.insert(grown.end(), u.flat[g].begin(), u.flat[g].end());
      hull = convex_hull(std::move(grown));
      push_neighbours(g);
    }
  }
  return merge_parts(u, faces, scale, room, part, parts);
}

}  // namespace

SplitResult split_to_fit(const unfold::Mesh& mesh, const unfold::Unfolding& u, const LayoutOptions& o,
                         double part_room_fraction, SplitGrowth growth) {
  SplitResult result{u, 0, 0};
  if (!o.size_mm || o.fit || !o.split_oversized || !(u.model_extent > 0)) return result;
  const double scale = *o.size_mm / u.model_extent;
  const Vec2 full_room = piece_room_mm(o);
  const Vec2 part_room = full_room * std::clamp(part_room_fraction, 0.05, 1.0);
  const auto pieces = u.piece_faces();

  std::vector<char> cut(u.edges.size(), 0);
  for (std::size_t e = 0; e < u.edges.size(); ++e)
    cut[e] = u.edges[e].cut ? 1 : 0;
  bool changed = false;
  std::vector<int> part(u.num_faces(), -1);
  for (const std::vector<int>& faces : pieces) {
    std::vector<Vec2> all;
    for (int f : faces)
      all.insert(all.end(), u.flat[f].begin(), u.flat[f].end());
    if (max_fit_scale(all, full_room) >= scale) continue;
    result.split_pieces += 1;
    std::vector<int> tree_part = part;
    const int tree =
        growth == SplitGrowth::Round ? 0 : grow_parts(u, faces, scale, part_room, false, tree_part);
    const int round = growth == SplitGrowth::Tree ? 0 : grow_parts(u, faces, scale, part_room, true, part);
    const bool use_tree = growth == SplitGrowth::Tree || (growth == SplitGrowth::Fewest && tree < round);
    if (use_tree) part = std::move(tree_part);
    result.new_pieces += use_tree ? tree : round;
    for (int f : faces)
      for (int c = 0; c < 3; ++c) {
        const int e = u.face_edges[f][c];
        const unfold::UnfoldEdge& edge = u.edges[e];
        if (edge.cut || edge.boundary()) continue;
        if (part[edge.face[0]] != part[edge.face[1]]) {
          cut[e] = 1;
          changed = true;
        }
      }
  }
  if (changed) result.unfolding = unfold::flatten(mesh, cut);
  return result;
}

SplitLayout split_and_layout(const unfold::Mesh& mesh, const unfold::Unfolding& u, const LayoutOptions& o) {
  SplitLayout best{split_to_fit(mesh, u, o, 1.0, SplitGrowth::Tree), {}};
  best.layout = layout_sheets(best.split.unfolding, o);
  if (best.split.split_pieces == 0) return best;

  // Parts as large as the sheet allows give the fewest seams but, cut from a spindly net, pack
  // poorly; smaller, rounder parts often save a sheet. Packing is a heuristic, so each split is judged
  // by laying it out. A sheet saved is worth up to 8 more parts to glue (measured: the smaller parts
  // save a sheet for 5 to 20 more parts on spot, bob and penguin at 150-250 mm).
  auto sheets_with_pieces = [](const LayoutResult& r) {
    return std::count_if(r.sheet_stats.begin(), r.sheet_stats.end(),
                         [](const SheetStats& s) { return s.pieces > 0; });
  };
  auto cost = [&](const SplitLayout& s) {
    return 8.0 * static_cast<double>(sheets_with_pieces(s.layout)) + s.split.unfolding.piece_count;
  };
  // Nets with tabs rarely pack above 60% of a sheet; the bound at that density stops the trials where
  // another sheet saved is unlikely, so a good first layout costs no extra time.
  constexpr double kReachableDensity = 0.6;
  const Box2 area = printable_area(o);
  const double used = best.layout.overall.piece_area_mm2 + best.layout.overall.tab_area_mm2;
  const long bound =
      std::max(1L, static_cast<long>(std::ceil(used / (kReachableDensity * area.width() * area.height()))));
  // Round growth at 0.7 and 0.5 did no better than tree growth on the meshes measured.
  const std::pair<double, SplitGrowth> tries[] = {
      {1.0, SplitGrowth::Round}, {0.7, SplitGrowth::Tree}, {0.5, SplitGrowth::Tree}};
  for (auto [fraction, growth] : tries) {
    if (sheets_with_pieces(best.layout) <= bound) break;
    SplitLayout trial{split_to_fit(mesh, u, o, fraction, growth), {}};
    trial.layout = layout_sheets(trial.split.unfolding, o);
    if (cost(trial) < cost(best)) best = std::move(trial);
  }
  return best;
}

}  // namespace foldkit::layout
