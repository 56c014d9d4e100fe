#pragma once
// Ordering the paths of one tool pass on a cutting plotter: short pen-up travel, with everything that
// lies inside a closed outline done before that outline (once an outline is cut the piece may shift on
// the mat, so its inner folds and holes would land in the wrong place), and optional overcut.
// Pure geometry in sheet millimetres; device units and profiles are the caller's business.
#include <cstddef>
#include <vector>

#include "foldkit/geom/vec.hpp"

namespace foldkit::devices {

/// A polyline the tool follows with the pen or blade down. A closed path returns to its first point.
struct ToolPath {
  std::vector<Vec2> points_mm;
  bool closed = false;
};

struct PathOrderOptions {
  Vec2 start_mm{0, 0};       ///< where the tool is before the pass (the plotter's origin)
  bool inside_first = true;  ///< paths lying inside a closed path are done before it
  double overcut_mm = 0;     ///< closed paths continue this far past their start along themselves
  int max_rounds = 30;       ///< bound on improvement rounds (2-opt, re-entry): keeps time predictable
};

/// One path of the ordered pass, as the tool follows it.
struct OrderedPath {
  std::size_t source = 0;  ///< index of the input path
  /// Pen-down points in drawing order: open paths possibly reversed; closed paths start at their
  /// chosen vertex, return to it explicitly and continue by the overcut.
  std::vector<Vec2> points_mm;
  bool closed = false;
  bool reversed = false;         ///< an open path drawn from its last point to its first
  std::size_t start_vertex = 0;  ///< index in the input path where drawing starts
};

/// A pass in tool order with its pen-up travel. Every input path appears exactly once.
struct PathOrder {
  std::vector<OrderedPath> paths;
  double travel_before_mm = 0;  ///< pen-up travel in input order, each path from its first point
  double travel_after_mm = 0;   ///< pen-up travel of `paths`; never more than travel_before_mm
};

/// Orders `paths`: nearest neighbour among the paths whose contents are done, then 2-opt on the tour
/// (keeping inside-first) and re-choosing each closed path's start vertex and each open path's
/// direction. Deterministic. Empty paths are kept (at the end) and cost no travel.
PathOrder order_paths(const std::vector<ToolPath>& paths, const PathOrderOptions& options = {});

/// Pen-up travel in mm from `start_mm` through the paths in order (end of one to start of the next).
double pen_up_travel_mm(const std::vector<OrderedPath>& paths, Vec2 start_mm);

/// True when `inner` lies inside the closed path `outer`: all its points inside or on `outer`, at least
/// one point of it strictly inside, and (for a closed `inner`) a smaller area. Open `outer`: false.
bool lies_inside(const ToolPath& inner, const ToolPath& outer);

/// `closed` drawn from vertex `start_vertex` round to it again and on for `overcut_mm` along the path
/// (at most once more round).
std::vector<Vec2> closed_trajectory(const std::vector<Vec2>& closed, std::size_t start_vertex,
                                    double overcut_mm);

}  // namespace foldkit::devices
