#pragma once
// Union-find over the integers 0..n-1: which faces, corners or parts are joined. The one implementation
// every stage uses (components, spanning forests, flat faces, fans of corners, parts).
#include <numeric>
#include <vector>

namespace foldkit::unfold {

/// The root of `x` in the forest `parent` (parent[r] == r at a root), halving the path on the way.
inline int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x)
    x = parent[x] = parent[parent[x]];
  return x;
}

/// Disjoint sets of 0..n-1, each named by its root. join(a, b) puts a's set under b's root, so a caller
/// that numbers sets by their roots (in element order) gets the same numbers whatever the path halving did.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(static_cast<std::size_t>(n)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int size() const { return static_cast<int>(parent_.size()); }
  /// The root of x's set.
  int find(int x) { return find_root(parent_, x); }
  /// Joins the sets of a and b under b's root; false when they were one set already.
  bool join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[a] = b;
    return true;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace foldkit::unfold
