// Fills follow the pieces exactly: a face's fill is its own flat triangle on the sheet (through
// LayoutResult::to_sheet), so the texture lands where the face is cut, and the same affine map carries
// the texture on into the bleed. Growing is a bevelled offset of a convex polygon, so no corner reaches
// further than the bleed past its cut line: the bleeds of pieces `spacing` apart never meet.
#include "foldkit/layout/fills.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace foldkit::layout {
namespace {

// A tab's ends on its edge must lie this close to the face's edge on the sheet to be matched to it.
constexpr double kTabMatchMm = 1e-6;

// A convex polygon with edge k pushed out by grow_mm[k], corners bevelled: every point of the result is
// within max(grow_mm) of the polygon. Orientation-free: "out" is away from the centroid.
std::vector<Vec2> grown_convex(const std::vector<Vec2>& poly, const std::vector<double>& grow_mm) {
  const std::size_t n = poly.size();
  Vec2 centre{};
  for (Vec2 p : poly)
    centre += p;
  centre = centre / static_cast<double>(n);
  std::vector<Vec2> out_normal(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = poly[k], b = poly[(k + 1) % n];
    Vec2 normal = normalized(perp_ccw(b - a));
    if (dot(normal, centre - a) > 0) normal = -normal;
    out_normal[k] = normal;
  }
  std::vector<Vec2> out;
  out.reserve(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t before = (k + n - 1) % n;
    out.push_back(poly[k] + out_normal[before] * grow_mm[before]);
    out.push_back(poly[k] + out_normal[k] * grow_mm[k]);
  }
  return out;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + d * t));
}

// The rigid motion (no reflection) that carries from_a to to_a and the direction of from_b - from_a onto
// that of to_b - to_a: how face g unfolds across its shared edge onto face f's side.
struct Motion {
  Vec2 from, to;
  double angle = 0;
  Vec2 apply(Vec2 p) const { return to + rotated(p - from, angle); }
};

Motion motion_onto(Vec2 from_a, Vec2 from_b, Vec2 to_a, Vec2 to_b) {
  const Vec2 df = from_b - from_a, dt = to_b - to_a;
  return {from_a, to_a, std::atan2(dt.y, dt.x) - std::atan2(df.y, df.x)};
}

class SheetFiller {
 public:
  SheetFiller(LayoutResult& layout, const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
              const FillOptions& options)
      : layout_(layout), mesh_(mesh), u_(unfolding), o_(options), image_of_(layout.sheets.size()) {}

  void faces() {
    for (int f = 0; f < u_.num_faces(); ++f) {
      const int piece = u_.piece_of_face[f];
      std::array<Vec2, 3> corners;
      for (int i = 0; i < 3; ++i)
        corners[i] = layout_.to_sheet(piece, u_.flat[f][i]);
      std::vector<double> grow(3);
      for (int i = 0; i < 3; ++i) {
        const unfold::UnfoldEdge& e = u_.edges[u_.face_edges[f][i]];
        grow[i] = e.cut || e.boundary() ? o_.bleed_mm : o_.fold_overlap_mm;
      }
      add(f, piece, corners, {corners.begin(), corners.end()}, grow);
    }
  }

  // Each tab takes the texture of the face it glues under, unfolded across the seam onto the tab's side.
  void tabs() {
    for (std::size_t s = 0; s < layout_.sheets.size(); ++s) {
      Sheet& sheet = layout_.sheets[s];
      const std::size_t paths = sheet.paths.size();
      for (std::size_t k = 0; k < paths; ++k) {
        const Path& tab = sheet.paths[k];
        if (tab.role != PathRole::Tab || tab.piece < 0 || tab.points_mm.size() < 3) continue;
        tab_fill(tab);
      }
    }
  }

 private:
  void tab_fill(const Path& tab) {
    const Vec2 start = tab.points_mm.front(), end = tab.points_mm.back();
    for (int f : faces_of_piece(tab.piece)) {
      for (int i = 0; i < 3; ++i) {
        const unfold::UnfoldEdge& e = u_.edges[u_.face_edges[f][i]];
        if (!e.glued_seam()) continue;
        const Vec2 a = layout_.to_sheet(tab.piece, u_.flat[f][i]);
        const Vec2 b = layout_.to_sheet(tab.piece, u_.flat[f][(i + 1) % 3]);
        if (distance_to_segment(start, a, b) > kTabMatchMm || distance_to_segment(end, a, b) > kTabMatchMm)
          continue;
        const int g = e.face[0] == f ? e.face[1] : e.face[0];
        const int va = mesh_.faces[f][i], vb = mesh_.faces[f][(i + 1) % 3];
        int ga = -1, gb = -1;
        for (int k = 0; k < 3; ++k) {
          if (mesh_.faces[g][k] == va) ga = k;
          if (mesh_.faces[g][k] == vb) gb = k;
        }
        if (ga < 0 || gb < 0) return;
        const Motion m = motion_onto(u_.flat[g][ga], u_.flat[g][gb], u_.flat[f][i], u_.flat[f][(i + 1) % 3]);
        std::array<Vec2, 3> corners;
        for (int k = 0; k < 3; ++k)
          corners[k] = layout_.to_sheet(tab.piece, m.apply(u_.flat[g][k]));
        // The edge on the face only overlaps the face's fill; the tab's other sides are cut lines.
        std::vector<double> grow(tab.points_mm.size(), o_.bleed_mm);
        grow.back() = o_.fold_overlap_mm;
        add(g, tab.piece, corners, tab.points_mm, grow);
        return;
      }
    }
  }

  const std::vector<int>& faces_of_piece(int piece) {
    if (piece_faces_.empty()) piece_faces_ = u_.piece_faces();
    return piece_faces_[piece];
  }

  // A fill of face f's material over `outline` grown by `grow`, its texture mapped by f's coordinates
  // at `corners` (the face, or the face unfolded onto a tab).
  void add(int f, int piece, const std::array<Vec2, 3>& corners, const std::vector<Vec2>& outline,
           const std::vector<double>& grow) {
    const int material = mesh_.face_material.empty() ? -1 : mesh_.face_material[f];
    if (material < 0) return;
    const unfold::Material& mat = mesh_.materials[material];
    const int sheet = layout_.placements[piece].sheet;
    Fill fill;
    fill.outline_mm = grown_convex(outline, grow);
    fill.colour = mat.colour;
    fill.piece = piece;
    fill.corners_mm = corners;
    if (mat.texture_found && !mesh_.face_uv.empty()) {
      fill.image = image_index(sheet, material);
      fill.uv = mesh_.face_uv[f];
    }
    layout_.sheets[sheet].fills.push_back(std::move(fill));
  }

  int image_index(int sheet, int material) {
    auto [it, inserted] =
        image_of_[sheet].try_emplace(material, static_cast<int>(layout_.sheets[sheet].images.size()));
    if (inserted) {
      const unfold::Material& mat = mesh_.materials[material];
      layout_.sheets[sheet].images.push_back({mat.texture, mat.texture_data});
    }
    return it->second;
  }

  LayoutResult& layout_;
  const unfold::Mesh& mesh_;
  const unfold::Unfolding& u_;
  const FillOptions& o_;
  std::vector<std::map<int, int>> image_of_;  // per sheet: material -> image index
  std::vector<std::vector<int>> piece_faces_;
};

}  // namespace

bool has_colour(const unfold::Mesh& mesh) {
  return std::any_of(mesh.face_material.begin(), mesh.face_material.end(), [](int m) { return m >= 0; });
}

double fill_spacing_mm(const FillOptions& options) {
  // Two bleeds and half a millimetre of white between them, so that neither piece's cut crosses the
  // other's colour.
  return 2 * std::max(options.bleed_mm, 0.0) + 0.5;
}

void add_fills(LayoutResult& layout, const unfold::Mesh& mesh, const unfold::Unfolding& unfolding,
               const FillOptions& options) {
  if (!has_colour(mesh) || unfolding.num_faces() != mesh.num_faces()) return;
  SheetFiller filler(layout, mesh, unfolding, options);
  filler.faces();
  if (options.tab_fill == TabFill::Face) filler.tabs();
}

}  // namespace foldkit::layout
