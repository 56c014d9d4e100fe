#pragma once
// A laid-out sheet: the contract between layout/ and devices/. Geometry carries roles, never colours
// or tools; renderers and device profiles map roles to styles and tools.
#include <array>
#include <string>
#include <vector>

#include "foldkit/geom/colour.hpp"
#include "foldkit/geom/vec.hpp"

namespace foldkit {

/// Piece: the part letters printed inside each part. Sheet: what a sheet says about itself (its
/// number, the model, the scale check, the line legend); cutters leave both alone.
enum class PathRole { Cut, Mountain, Valley, Tab, Label, Hint, RegMark, Piece, Sheet };

/// Lower-case name of a role ("cut", "mountain", …): SVG group ids, profile keys, JSON.
inline const char* role_name(PathRole r) {
  switch (r) {
    case PathRole::Cut:
      return "cut";
    case PathRole::Mountain:
      return "mountain";
    case PathRole::Valley:
      return "valley";
    case PathRole::Tab:
      return "tab";
    case PathRole::Label:
      return "label";
    case PathRole::Hint:
      return "hint";
    case PathRole::RegMark:
      return "regmark";
    case PathRole::Piece:
      return "piece";
    case PathRole::Sheet:
      return "sheet";
  }
  return "?";
}

/// A polyline on the sheet, millimetres from the sheet's top-left corner, y pointing down.
struct Path {
  PathRole role = PathRole::Cut;
  std::vector<Vec2> points_mm;
  bool closed = false;
  int piece = -1;       ///< piece index, -1 when the path belongs to no piece (marks, hints)
  bool filled = false;  ///< drawn filled (registration square); cutters ignore fills
  /// Paths that must be told apart within a role (the direction arrows of seam pairs) carry an index
  /// into the renderer's palette of distinguishable colours; -1 draws the role's own colour.
  int tint = -1;
  /// A filled path with a tint is filled (and outlined) in the tint lightened for text to read on it,
  /// times this: the lighting of the assembly guide's views. 1 for everything else.
  double shade = 1;
};

/// A text on the sheet. `at_mm` is the left end of the baseline; the text runs along `angle_rad`
/// (0 = left to right, positive = clockwise on the page since y points down).
struct Text {
  std::string text;
  Vec2 at_mm;
  double height_mm = 3;
  double angle_rad = 0;
  PathRole role = PathRole::Label;
  int piece = -1;
  /// The length the layout reserved along the baseline, 0 for none. A renderer whose font sets the
  /// text wider squeezes it to this length, so it never runs into the lines the layout kept it from.
  double width_mm = 0;
  /// Set on a text that stands on dark filled paths of its own role (the guide's letters on its shaded
  /// views): a white halo is painted over those paths under it. Unlike the halos of coloured sheets,
  /// which go under every line, this one may cover lines: none beneath it needs to show.
  bool halo_over_paths = false;
};

/// A texture image that fills refer to: a file, or the encoded bytes a model file embedded.
struct SheetImage {
  std::string file;                 ///< path to read, or (when `data` is set) a name for messages
  std::vector<unsigned char> data;  ///< encoded PNG or JPEG; empty: read `file`
};

/// Colour printed under the lines of a piece: `outline_mm` filled with `colour` or, when `image` >= 0,
/// with that image mapped affinely so that texture coordinate uv[i] (u right, v up, the image is
/// [0,1]^2) lands on corners_mm[i]; the image is multiplied by `colour`. Cutters ignore fills.
struct Fill {
  std::vector<Vec2> outline_mm;  ///< closed polygon: a face grown by the bleed, or a tab
  Colour colour;
  int image = -1;  ///< index into Sheet::images, -1 for a flat colour
  std::array<Vec2, 3> corners_mm{};
  std::array<Vec2, 3> uv{};
  int piece = -1;
};

/// One sheet of paper with everything to print, draw, score and cut on it.
struct Sheet {
  Vec2 size_mm;  ///< width, height of the paper
  /// Area inside the margins; everything lies inside it but registration marks and the sheet furniture
  /// a full sheet puts in its margins (number, name, bar, parts line, legend row: PathRole::Sheet).
  Box2 printable_mm;
  std::vector<Path> paths;
  std::vector<Text> texts;
  /// Where the renderer draws a small legend of its line styles (cut, mountain, valley, tab); empty
  /// for none. Layout keeps the box free; only the renderer knows the styles.
  Box2 legend_mm;
  /// The legend's four entries side by side, each in a quarter of the box's width (a row in the top
  /// margin of a sheet without room for the stacked legend), rather than stacked.
  bool legend_in_row = false;
  /// Colour under everything else, in order (faces, then tabs); empty for a white sheet.
  std::vector<Fill> fills;
  std::vector<SheetImage> images;  ///< the textures `fills` refer to
};

}  // namespace foldkit
