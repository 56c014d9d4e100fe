#include "foldkit/devices/path_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace foldkit::devices {
namespace {

// Points closer than this to an outline count as on it: sheet coordinates are millimetres produced by
// the layout, so a nanometre is far below any device resolution and far above rounding noise.
constexpr double kOnEdgeMm = 1e-6;
constexpr double kInf = std::numeric_limits<double>::infinity();

double dist(Vec2 a, Vec2 b) {
  return norm(a - b);
}

Box2 bounds(const std::vector<Vec2>& points) {
  Box2 box;
  for (Vec2 p : points)
    box.add(p);
  return box;
}

bool box_contains(const Box2& outer, const Box2& inner) {
  return inner.min.x >= outer.min.x - kOnEdgeMm && inner.min.y >= outer.min.y - kOnEdgeMm &&
         inner.max.x <= outer.max.x + kOnEdgeMm && inner.max.y <= outer.max.y + kOnEdgeMm;
}

double box_distance(const Box2& box, Vec2 p) {
  const double dx = std::fmax(std::fmax(box.min.x - p.x, p.x - box.max.x), 0.0);
  const double dy = std::fmax(std::fmax(box.min.y - p.y, p.y - box.max.y), 0.0);
  return std::hypot(dx, dy);
}

double area(const std::vector<Vec2>& ring) {
  double twice = 0;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    twice += cross(ring[j], ring[i]);
  return std::abs(twice) / 2;
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return dist(p, a + ab * t);
}

enum class Where { Outside, On, Inside };

Where locate(Vec2 p, const std::vector<Vec2>& ring) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if (segment_distance(p, a, b) <= kOnEdgeMm) return Where::On;
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
      if (p.x < x) inside = !inside;
    }
  }
  return inside ? Where::Inside : Where::Outside;
}

// A path in the tour: which input path, where the tool enters it and whether an open one runs backwards.
struct Node {
  std::size_t path = 0;
  std::size_t vertex = 0;  // closed: start vertex
  bool reversed = false;   // open: drawn from last to first
};

struct Problem {
  const std::vector<ToolPath>* paths = nullptr;
  std::vector<Box2> boxes;
  std::vector<std::vector<std::size_t>> children;    // paths that must come before this one
  std::vector<std::vector<std::size_t>> containers;  // paths that must come after this one

  const ToolPath& at(std::size_t i) const { return (*paths)[i]; }
  Vec2 entry(const Node& n) const {
    const auto& pts = at(n.path).points_mm;
    if (at(n.path).closed) return pts[n.vertex];
    return n.reversed ? pts.back() : pts.front();
  }
  // Overcut is left out while optimising: it moves a closed path's exit by a millimetre or two at
  // most, and leaving it out keeps 2-opt deltas exact. Final travel is measured on the real output.
  Vec2 exit(const Node& n) const {
    const auto& pts = at(n.path).points_mm;
    if (at(n.path).closed) return pts[n.vertex];
    return n.reversed ? pts.front() : pts.back();
  }
  Node flipped(Node n) const {
    if (!at(n.path).closed) n.reversed = !n.reversed;
    return n;
  }
};

double tour_cost(const Problem& pb, const std::vector<Node>& tour, Vec2 start) {
  double cost = 0;
  Vec2 cur = start;
  for (const Node& n : tour) {
    cost += dist(cur, pb.entry(n));
    cur = pb.exit(n);
  }
  return cost;
}

// Best way into path `i` from `from`: nearest end of an open path, nearest vertex of a closed one.
std::pair<double, Node> nearest_entry(const Problem& pb, std::size_t i, Vec2 from) {
  const ToolPath& path = pb.at(i);
  Node node{i, 0, false};
  if (!path.closed) {
    const double to_front = dist(from, path.points_mm.front()), to_back = dist(from, path.points_mm.back());
    node.reversed = to_back < to_front;
    return {std::fmin(to_front, to_back), node};
  }
  double best = kInf;
  for (std::size_t v = 0; v < path.points_mm.size(); ++v) {
    const double d = dist(from, path.points_mm[v]);
    if (d < best) {
      best = d;
      node.vertex = v;
    }
  }
  return {best, node};
}

std::vector<Node> nearest_neighbour_tour(const Problem& pb, const std::vector<std::size_t>& todo,
                                         Vec2 start) {
  std::vector<int> waiting(pb.paths->size(), 0);
  for (std::size_t i : todo)
    waiting[i] = static_cast<int>(pb.children[i].size());
  std::vector<std::size_t> available;
  for (std::size_t i : todo) {
    if (waiting[i] == 0) available.push_back(i);
  }
  std::vector<Node> tour;
  tour.reserve(todo.size());
  Vec2 cur = start;
  while (!available.empty()) {
    double best = kInf;
    std::size_t best_slot = 0;
    Node best_node;
    for (std::size_t slot = 0; slot < available.size(); ++slot) {
      const std::size_t i = available[slot];
      // The bounding box bounds every vertex's distance from below: most paths are skipped unopened.
      if (box_distance(pb.boxes[i], cur) >= best) continue;
      auto [d, node] = nearest_entry(pb, i, cur);
      if (d < best || (d == best && i < best_node.path)) {
        best = d;
        best_slot = slot;
        best_node = node;
      }
    }
    tour.push_back(best_node);
    cur = pb.exit(best_node);
    available.erase(available.begin() + static_cast<std::ptrdiff_t>(best_slot));
    for (std::size_t c : pb.containers[best_node.path]) {
      if (--waiting[c] == 0) available.push_back(c);
    }
  }
  return tour;
}

// Reversing tour[i..j] keeps the order of paths outside the segment and flips it inside, so it is
// allowed only when no path in the segment has to precede another one in it.
bool two_opt_round(const Problem& pb, std::vector<Node>& tour, Vec2 start) {
  const std::size_t n = tour.size();
  std::vector<std::size_t> pos(pb.paths->size(), 0);
  for (std::size_t k = 0; k < n; ++k)
    pos[tour[k].path] = k;
  bool improved = false;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Vec2 a = i == 0 ? start : pb.exit(tour[i - 1]);
    const Vec2 b = pb.entry(tour[i]);
    for (std::size_t j = i + 1; j < n; ++j) {
      bool blocked = false;
      for (std::size_t c : pb.children[tour[j].path])
        blocked |= pos[c] >= i;
      if (blocked) break;  // the pair stays inside every longer segment too
      const Vec2 c = pb.exit(tour[j]);
      const double before = dist(a, b) + (j + 1 < n ? dist(c, pb.entry(tour[j + 1])) : 0);
      const Node new_first = pb.flipped(tour[j]), new_last = pb.flipped(tour[i]);
      const double after =
          dist(a, pb.entry(new_first)) + (j + 1 < n ? dist(pb.exit(new_last), pb.entry(tour[j + 1])) : 0);
      if (after < before - 1e-9) {
        std::reverse(tour.begin() + static_cast<std::ptrdiff_t>(i),
                     tour.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        for (std::size_t k = i; k <= j; ++k) {
          tour[k] = pb.flipped(tour[k]);
          pos[tour[k].path] = k;
        }
        improved = true;
        break;  // tour[i] changed: restart the inner loop from the new segment start
      }
    }
  }
  return improved;
}

// Moves single paths to a better place in the tour within the window their constraints allow.
bool or_opt_round(const Problem& pb, std::vector<Node>& tour, Vec2 start) {
  bool improved = false;
  const std::size_t n = tour.size();
  if (n < 3) return false;
  std::vector<std::size_t> pos(pb.paths->size(), 0);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t q = 0; q < n; ++q)
      pos[tour[q].path] = q;
    const Node node = tour[k];
    const Vec2 prev = k == 0 ? start : pb.exit(tour[k - 1]);
    const bool has_next = k + 1 < n;
    const double removal_gain = dist(prev, pb.entry(node)) +
                                (has_next ? dist(pb.exit(node), pb.entry(tour[k + 1])) : 0) -
                                (has_next ? dist(prev, pb.entry(tour[k + 1])) : 0);
    // Feasible gaps: after every child, before every container. Gap g means "between g-1 and g".
    std::size_t lo = 0, hi = n;
    for (std::size_t c : pb.children[node.path])
      lo = std::max(lo, pos[c] + 1);
    for (std::size_t c : pb.containers[node.path])
      hi = std::min(hi, pos[c]);
    double best_gain = 1e-9;
    std::size_t best_gap = n + 1;
    Node best_node = node;
    for (std::size_t g = lo; g <= hi; ++g) {
      if (g == k || g == k + 1) continue;
      const Vec2 left = g == 0 ? start : pb.exit(tour[g - 1]);
      const bool right_exists = g < n;
      const double old_link = right_exists ? dist(left, pb.entry(tour[g])) : 0;
      for (int flip = 0; flip < 2; ++flip) {
        const Node cand = flip ? pb.flipped(node) : node;
        if (flip && pb.at(node.path).closed) break;
        const double insert_cost = dist(left, pb.entry(cand)) +
                                   (right_exists ? dist(pb.exit(cand), pb.entry(tour[g])) : 0) - old_link;
        if (removal_gain - insert_cost > best_gain) {
          best_gain = removal_gain - insert_cost;
          best_gap = g;
          best_node = cand;
        }
      }
    }
    if (best_gap <= n) {
      tour.erase(tour.begin() + static_cast<std::ptrdiff_t>(k));
      const std::size_t gap = best_gap > k ? best_gap - 1 : best_gap;
      tour.insert(tour.begin() + static_cast<std::ptrdiff_t>(gap), best_node);
      improved = true;
    }
  }
  (void)tour_cost;
  return improved;
}

// With neighbours fixed, each path's entry is chosen on its own: start vertex or direction.
bool reentry_round(const Problem& pb, std::vector<Node>& tour, Vec2 start) {
  bool improved = false;
  for (std::size_t k = 0; k < tour.size(); ++k) {
    const Vec2 prev = k == 0 ? start : pb.exit(tour[k - 1]);
    const bool has_next = k + 1 < tour.size();
    const Vec2 next = has_next ? pb.entry(tour[k + 1]) : Vec2{};
    auto cost = [&](const Node& n) {
      return dist(prev, pb.entry(n)) + (has_next ? dist(pb.exit(n), next) : 0);
    };
    Node best = tour[k];
    double best_cost = cost(best);
    const ToolPath& path = pb.at(best.path);
    if (path.closed) {
      for (std::size_t v = 0; v < path.points_mm.size(); ++v) {
        const Node cand{best.path, v, false};
        if (const double c = cost(cand); c < best_cost - 1e-9) {
          best = cand;
          best_cost = c;
        }
      }
    } else if (const Node cand = pb.flipped(best); cost(cand) < best_cost - 1e-9) {
      best = cand;
    }
    if (best.vertex != tour[k].vertex || best.reversed != tour[k].reversed) {
      tour[k] = best;
      improved = true;
    }
  }
  return improved;
}

void improve(const Problem& pb, std::vector<Node>& tour, Vec2 start, int max_rounds) {
  for (int round = 0; round < max_rounds; ++round) {
    bool improved = two_opt_round(pb, tour, start);
    improved |= or_opt_round(pb, tour, start);
    improved |= reentry_round(pb, tour, start);
    if (!improved) break;
  }
}

bool respects_precedence(const Problem& pb, const std::vector<Node>& tour) {
  std::vector<std::size_t> pos(pb.paths->size(), 0);
  for (std::size_t k = 0; k < tour.size(); ++k)
    pos[tour[k].path] = k;
  for (const Node& n : tour) {
    for (std::size_t c : pb.containers[n.path]) {
      if (pos[c] < pos[n.path]) return false;
    }
  }
  return true;
}

std::vector<OrderedPath> realise(const Problem& pb, const std::vector<Node>& tour, double overcut_mm) {
  std::vector<OrderedPath> out;
  out.reserve(tour.size());
  for (const Node& n : tour) {
    const ToolPath& path = pb.at(n.path);
    OrderedPath o;
    o.source = n.path;
    o.closed = path.closed;
    if (path.closed) {
      o.start_vertex = n.vertex;
      o.points_mm = closed_trajectory(path.points_mm, n.vertex, overcut_mm);
    } else {
      o.reversed = n.reversed;
      o.start_vertex = n.reversed ? path.points_mm.size() - 1 : 0;
      o.points_mm = path.points_mm;
      if (n.reversed) std::reverse(o.points_mm.begin(), o.points_mm.end());
    }
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace

bool lies_inside(const ToolPath& inner, const ToolPath& outer) {
  if (!outer.closed || outer.points_mm.size() < 3 || inner.points_mm.empty()) return false;
  if (!box_contains(bounds(outer.points_mm), bounds(inner.points_mm))) return false;
  if (inner.closed && inner.points_mm.size() >= 3 && !(area(inner.points_mm) < area(outer.points_mm)))
    return false;
  bool strictly = false;
  const auto& pts = inner.points_mm;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Where w = locate(pts[i], outer.points_mm);
    if (w == Where::Outside) return false;
    strictly |= w == Where::Inside;
  }
  // A fold line may touch the outline with both ends; its middle tells whether it runs inside.
  for (std::size_t i = 0; !strictly && i + 1 < pts.size(); ++i) {
    const Where w = locate((pts[i] + pts[i + 1]) / 2, outer.points_mm);
    if (w == Where::Outside) return false;
    strictly = w == Where::Inside;
  }
  return strictly;
}

std::vector<Vec2> closed_trajectory(const std::vector<Vec2>& closed, std::size_t start_vertex,
                                    double overcut_mm) {
  const std::size_t m = closed.size();
  if (m == 0) return {};
  start_vertex %= m;
  std::vector<Vec2> out;
  out.reserve(m + 3);
  for (std::size_t k = 0; k <= m; ++k)
    out.push_back(closed[(start_vertex + k) % m]);
  if (m == 1) return {closed[0]};
  double perimeter = 0;
  for (std::size_t k = 0; k < m; ++k)
    perimeter += dist(closed[k], closed[(k + 1) % m]);
  double left = std::fmin(std::fmax(overcut_mm, 0.0), perimeter);
  for (std::size_t k = 0; left > 0 && k < m; ++k) {
    const Vec2 a = closed[(start_vertex + k) % m], b = closed[(start_vertex + k + 1) % m];
    const double len = dist(a, b);
    if (len <= 0) continue;
    if (len >= left) {
      out.push_back(a + (b - a) * (left / len));
      break;
    }
    out.push_back(b);
    left -= len;
  }
  return out;
}

double pen_up_travel_mm(const std::vector<OrderedPath>& paths, Vec2 start_mm) {
  double travel = 0;
  Vec2 cur = start_mm;
  for (const OrderedPath& p : paths) {
    if (p.points_mm.empty()) continue;
    travel += dist(cur, p.points_mm.front());
    cur = p.points_mm.back();
  }
  return travel;
}

PathOrder order_paths(const std::vector<ToolPath>& paths, const PathOrderOptions& options) {
  Problem pb;
  pb.paths = &paths;
  const std::size_t n = paths.size();
  pb.boxes.resize(n);
  pb.children.resize(n);
  pb.containers.resize(n);
  std::vector<std::size_t> todo, empty;
  for (std::size_t i = 0; i < n; ++i) {
    (paths[i].points_mm.empty() ? empty : todo).push_back(i);
    pb.boxes[i] = bounds(paths[i].points_mm);
  }
  if (options.inside_first) {
    for (std::size_t outer : todo) {
      if (!paths[outer].closed || paths[outer].points_mm.size() < 3) continue;
      for (std::size_t inner : todo) {
        if (inner == outer || !box_contains(pb.boxes[outer], pb.boxes[inner])) continue;
        if (lies_inside(paths[inner], paths[outer])) {
          pb.children[outer].push_back(inner);
          pb.containers[inner].push_back(outer);
        }
      }
    }
  }

  // The input order, each path from its first point: the baseline, and a second starting tour.
  std::vector<Node> given;
  for (std::size_t i : todo)
    given.push_back({i, 0, false});
  auto finish = [&](std::vector<Node> tour) {
    std::vector<OrderedPath> out = realise(pb, tour, options.overcut_mm);
    for (std::size_t i : empty)
      out.push_back({i, {}, paths[i].closed, false, 0});
    return out;
  };
  PathOrder result;
  std::vector<OrderedPath> baseline = finish(given);
  result.travel_before_mm = pen_up_travel_mm(baseline, options.start_mm);

  std::vector<Node> tour = nearest_neighbour_tour(pb, todo, options.start_mm);
  improve(pb, tour, options.start_mm, options.max_rounds);
  result.paths = finish(tour);
  result.travel_after_mm = pen_up_travel_mm(result.paths, options.start_mm);

  if (respects_precedence(pb, given)) {
    // Local search from the given order as well: a good input order (e.g. a previous plan) is kept.
    improve(pb, given, options.start_mm, options.max_rounds);
    std::vector<OrderedPath> from_given = finish(given);
    const double travel = pen_up_travel_mm(from_given, options.start_mm);
    if (travel < result.travel_after_mm) {
      result.paths = std::move(from_given);
      result.travel_after_mm = travel;
    }
    if (result.travel_before_mm <= result.travel_after_mm) {
      result.paths = std::move(baseline);
      result.travel_after_mm = result.travel_before_mm;
    }
  }
  return result;
}

}  // namespace foldkit::devices
