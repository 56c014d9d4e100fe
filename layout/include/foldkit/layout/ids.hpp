#pragma once
// Strong index types: an index into one kind of list, so that a seam's index passed where a piece's, a
// side's or a printed number is wanted does not compile. (If unfold grows the same template, this one
// gives way to it.)
#include <compare>
#include <cstddef>

namespace foldkit::layout {

template <class Tag>
class StrongIndex {
 public:
  constexpr StrongIndex() = default;
  constexpr explicit StrongIndex(int value) : value_(value) {}
  constexpr explicit StrongIndex(std::size_t value) : value_(static_cast<int>(value)) {}
  constexpr int value() const { return value_; }
  /// The position in its list (for operator[]); only meaningful when valid().
  constexpr std::size_t index() const { return static_cast<std::size_t>(value_); }
  constexpr bool valid() const { return value_ >= 0; }
  friend constexpr auto operator<=>(const StrongIndex&, const StrongIndex&) = default;

 private:
  int value_ = -1;
};

struct SeamTag;
/// A seam's place in the list find_seams returns; not the number printed on it (number_seams).
using SeamId = StrongIndex<SeamTag>;

}  // namespace foldkit::layout
