#pragma once
// Checks the labels of a finished sheet from its geometry alone (what is printed, not what placement
// meant): labels crossing a cut or fold line, labels touching each other, texts turned more than 90
// degrees from upright, numbers that read as others upside down without their mark.
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::layout {

struct LabelAudit {
  int labels = 0;                  ///< seam labels (role Label) inside parts
  int crossing_lines = 0;          ///< seam labels or their hints whose box crosses a cut or fold line
  int touching = 0;                ///< seam labels or their hints whose box overlaps another text's box
  int turned = 0;                  ///< texts more than 90 degrees from upright
  int unmarked = 0;                ///< numbers that read as another number turned, printed without a period
  int letters = 0;                 ///< part letters
  int letters_crossing_lines = 0;  ///< part letters whose box crosses a cut or fold line
  /// Adds another sheet's counts.
  LabelAudit& operator+=(const LabelAudit& other);
  /// Labels a builder may misread: crossing a line or touching another text (issue 12's count).
  int unclear() const { return crossing_lines + touching; }
};

/// The audit of one sheet. Text boxes are the cap-height boxes of the widths layout reserves.
LabelAudit audit_labels(const Sheet& sheet);

}  // namespace foldkit::layout
