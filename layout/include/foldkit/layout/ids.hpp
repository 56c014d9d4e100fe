#pragma once
// Strong index types of layout, on unfold's StrongIndex: a seam's index passed where a piece's, a
// side's or a printed number is wanted does not compile.
#include "foldkit/unfold/ids.hpp"

namespace foldkit::layout {

using unfold::StrongIndex;

/// A seam's place in the list find_seams returns; not the number printed on it (number_seams).
using SeamId = StrongIndex<struct SeamTag>;

}  // namespace foldkit::layout
