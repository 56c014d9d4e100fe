#include "foldkit/layout/guide.hpp"

#include "foldkit/layout/piece_letters.hpp"
#include "foldkit/layout/polygon.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>
#include <span>
#include <utility>

namespace foldkit::layout {
namespace {

constexpr double kTitle_mm = 4;
constexpr double kText_mm = 2.6;
constexpr double kLine_mm = 4.2;
constexpr int kRaster = 160;             // pixels a side of the visibility raster per view
constexpr int kLeastVisiblePixels = 6;   // a part showing less than this gets no letter in the view
constexpr double kLetterGap_mm = 0.6;    // between two letters of a view
constexpr double kViewFill = 0.95;       // of its area a view fills, so letters at its rim stay inside
constexpr double kLeastSeenShare = 0.1;  // of the sphere's width, the least extent a view is scaled to

struct View {
  const char* name;
  Vec3 eye;  // from the model towards the viewer: along the model's right, up and front
};

constexpr std::array<View, 4> kViews = {{{"front", {0, 0, 1}},
                                         {"back", {0, 0, -1}},
                                         {"front right, from above", {1, 0.8, 1}},
                                         {"back left, from above", {-1, 0.8, -1}}}};

// The model's own axes: which way is up, and which side faces the viewer of the front view.
struct ModelFrame {
  Vec3 right, up, front;
  Vec3 operator()(Vec3 v) const { return right * v.x + up * v.y + front * v.z; }
};

// Y up, front towards +Z (OBJ and glTF convention); Z up, front towards -Y (CAD, STL, Blender's views).
constexpr ModelFrame kYUp{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr ModelFrame kZUp{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};

struct Camera {
  Vec3 right, up, eye;
};

Camera camera(Vec3 eye_direction, Vec3 model_up) {
  const Vec3 eye = normalized(eye_direction);
  const Vec3 right = normalized(cross(model_up, eye));
  return {right, cross(eye, right), eye};
}

// The share of the surface (0-1) that lies flat at the lowest level along `axis` (0 x, 1 y, 2 z),
// facing down: the base a model stands on when that axis is up.
double base_share(const unfold::Mesh& mesh, int axis) {
  constexpr double kLevelTolerance = 0.005;  // of the model's largest dimension
  const double facing_down = std::cos(10 * std::numbers::pi / 180);
  const auto along = [axis](Vec3 v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
  const unfold::MeshBounds bounds = unfold::bounds_of(mesh);
  const double lowest = along(bounds.lo), level = kLevelTolerance * bounds.largest_dimension();
  double base = 0, total = 0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const auto& t = mesh.faces[f];
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const Vec3 n = cross(b - a, c - a);
    const double twice_area = norm(n);
    total += twice_area;
    const bool on_floor = std::max({along(a), along(b), along(c)}) - lowest <= level;
    if (twice_area > 0 && on_floor && -along(n) >= facing_down * twice_area) base += twice_area;
  }
  return total > 0 ? base / total : 0;
}

}  // namespace

Vec3 upright_axis(const unfold::Mesh& mesh) {
  return base_share(mesh, 2) > base_share(mesh, 1) ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
}

namespace {

// A view's projection: model points to the sheet (mm, y down), centred in `area`.
struct Projection {
  Camera cam;
  Vec3 centre;
  Vec2 mid;
  double scale = 0;
  Vec2 operator()(Vec3 p) const {
    const Vec3 d = p - centre;
    return Vec2{mid.x + scale * dot(d, cam.right), mid.y - scale * dot(d, cam.up)};
  }
};

// Which part shows at each pixel of a view (kRaster x kRaster over the view's area, -1 for none).
struct PartRaster {
  Box2 area;
  double px = 0;  // pixel size, mm
  std::vector<int> owner = std::vector<int>(kRaster * kRaster, -1);
  Vec2 centre_mm(int x, int y) const { return {area.min.x + (x + 0.5) * px, area.min.y + (y + 0.5) * px}; }
};

// Faces far to near along the view direction (painter's order).
std::vector<int> far_to_near(const unfold::Mesh& mesh, const Projection& view) {
  const int n = mesh.num_faces();
  std::vector<double> depth(n);
  for (int f = 0; f < n; ++f) {
    const auto t = mesh.corners(f);
    depth[f] = dot((t[0] + t[1] + t[2]) * (1.0 / 3) - view.centre, view.cam.eye);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  return order;
}

// Marks the pixels whose centres lie inside the projected triangle as `part`'s.
void rasterize_triangle(std::span<const Vec2> p, int part, PartRaster& raster) {
  const Box2 b = bounds_of(p);
  const Box2& area = raster.area;
  const int x0 = std::max(0, static_cast<int>((b.min.x - area.min.x) / raster.px));
  const int x1 = std::min(kRaster - 1, static_cast<int>((b.max.x - area.min.x) / raster.px));
  const int y0 = std::max(0, static_cast<int>((b.min.y - area.min.y) / raster.px));
  const int y1 = std::min(kRaster - 1, static_cast<int>((b.max.y - area.min.y) / raster.px));
  const double area2 = cross(p[1] - p[0], p[2] - p[0]);
  for (int y = y0; y <= y1 && area2 != 0; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 c = raster.centre_mm(x, y);
      const double w0 = cross(p[1] - p[0], c - p[0]) / area2, w1 = cross(p[2] - p[1], c - p[1]) / area2,
                   w2 = cross(p[0] - p[2], c - p[2]) / area2;
      if (w0 >= 0 && w1 >= 0 && w2 >= 0) raster.owner[y * kRaster + x] = part;
    }
}

// The faces painted far to near, shaded by a light above the viewer; the raster keeps, per pixel, the
// part painted last.
void paint_faces(const unfold::Mesh& mesh, const std::vector<int>& tint_of_face, const Projection& view,
                 PartRaster& raster, Sheet& sheet) {
  const Vec3 light = normalized(view.cam.eye + view.cam.up * 0.6 + view.cam.right * 0.3);
  for (int f : far_to_near(mesh, view)) {
    const auto t = mesh.corners(f);
    const Vec3 normal = cross(t[1] - t[0], t[2] - t[0]);
    const double len = norm(normal);
    if (!(len > 0)) continue;
    const double facing = dot(normal, view.cam.eye) / len;
    // Back faces show only through holes of open meshes: drawn dark, as an inside would look.
    const double shade = facing > 0 ? 0.45 + 0.55 * std::max(0.0, dot(normal, light) / len) : 0.3;
    Path tri{PathRole::Piece, {view(t[0]), view(t[1]), view(t[2])}, true, -1, true, tint_of_face[f]};
    tri.shade = shade;
    rasterize_triangle(tri.points_mm, tint_of_face[f], raster);
    sheet.paths.push_back(std::move(tri));
  }
}

// A letter's box on the view, centred on `centre_mm` (y down), grown by the gap kept between letters.
Box2 letter_box(Vec2 centre_mm, double width_mm, double height_mm) {
  Box2 b;
  b.add(centre_mm - Vec2{0.5 * width_mm, 0.5 * height_mm});
  b.add(centre_mm + Vec2{0.5 * width_mm, 0.5 * height_mm});
  return grown(b, 0.5 * kLetterGap_mm);
}

double overlap_area(const Box2& a, const Box2& b) {
  const double w = std::min(a.max.x, b.max.x) - std::max(a.min.x, b.min.x);
  const double h = std::min(a.max.y, b.max.y) - std::max(a.min.y, b.min.y);
  return w > 0 && h > 0 ? w * h : 0;
}

// Per part, its visible pixels, nearest the middle of what shows of it first.
std::vector<std::vector<int>> pixels_by_part(const PartRaster& raster, int parts) {
  std::vector<std::vector<int>> pixels(parts);
  for (int i = 0; i < kRaster * kRaster; ++i)
    if (raster.owner[i] >= 0) pixels[raster.owner[i]].push_back(i);
  for (std::vector<int>& own : pixels) {
    if (own.empty()) continue;
    Vec2 mean{0, 0};
    for (int i : own)
      mean = mean + Vec2{static_cast<double>(i % kRaster), static_cast<double>(i / kRaster)};
    mean = mean * (1.0 / static_cast<double>(own.size()));
    const auto distance = [&](int i) {
      return norm(Vec2{static_cast<double>(i % kRaster), static_cast<double>(i / kRaster)} - mean);
    };
    std::stable_sort(own.begin(), own.end(), [&](int a, int b) { return distance(a) < distance(b); });
  }
  return pixels;
}

// Each visible part's letter on what shows of it, as near its middle as the letters placed before
// allow: parts that show least come first (they have the fewest spots), and a letter takes the nearest
// spot clear of the others, else the one it overlaps least. Letters of small neighbouring parts placed
// each at its own middle ran into each other ("PG" for P beside G).
void letter_visible_parts(const PartRaster& raster, const std::vector<std::string>& letter_of_tint,
                          const GuideOptions& o, Sheet& sheet) {
  const int parts = static_cast<int>(letter_of_tint.size());
  const std::vector<std::vector<int>> pixels = pixels_by_part(raster, parts);
  std::vector<int> order;
  for (int part = 0; part < parts; ++part)
    if (static_cast<int>(pixels[part].size()) >= kLeastVisiblePixels) order.push_back(part);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return pixels[a].size() < pixels[b].size(); });
  std::vector<Box2> placed;
  for (int part : order) {
    const std::string& letter = letter_of_tint[part];
    const double w = letter_width_mm(letter, o.letter_mm, PieceLetterOptions{});
    Vec2 best_centre;
    double least = 1e300;
    for (int i : pixels[part]) {
      const Vec2 centre = raster.centre_mm(i % kRaster, i / kRaster);
      const Box2 box = letter_box(centre, w, o.letter_mm);
      double overlap = 0;
      for (const Box2& other : placed)
        overlap += overlap_area(box, other);
      if (overlap < least) {
        least = overlap;
        best_centre = centre;
      }
      if (overlap == 0) break;
    }
    placed.push_back(letter_box(best_centre, w, o.letter_mm));
    Text text{letter, best_centre + Vec2{-0.5 * w, 0.5 * o.letter_mm}, o.letter_mm, 0, PathRole::Piece, -1};
    // Dark faces (the back faces, the shaded sides) would swallow a dark letter.
    text.halo_over_paths = true;
    sheet.texts.push_back(std::move(text));
  }
}

// The view as large as its area allows: scaled so that the mesh seen from this side fills it, where the
// sphere that holds the mesh left a long model seen end-on a small disc in the middle of its cell. The
// extent counts as at least a tenth of the sphere's so that a flat or thin model seen edge-on stays in
// proportion.
Projection fitted_projection(const unfold::Mesh& mesh, const Camera& cam, Vec3 centre, double radius,
                             const Box2& area) {
  Box2 seen;
  for (const Vec3& v : mesh.vertices)
    seen.add(Vec2{dot(v - centre, cam.right), -dot(v - centre, cam.up)});
  const double least = kLeastSeenShare * 2 * radius;
  const double scale = kViewFill * std::min(area.width() / std::max(seen.width(), least),
                                            area.height() / std::max(seen.height(), least));
  return {cam, centre, 0.5 * (area.min + area.max) - 0.5 * (seen.min + seen.max) * scale, scale};
}

// One view drawn into `cell` (sheet frame, y down): its name, the shaded faces, the parts' letters.
void draw_view(const unfold::Mesh& mesh, const std::vector<int>& tint_of_face,
               const std::vector<std::string>& letter_of_tint, const View& view, Vec3 centre, double radius,
               const Box2& cell, const GuideOptions& o, Sheet& sheet) {
  sheet.texts.push_back(
      Text{view.name, {cell.min.x, cell.min.y + kText_mm}, kText_mm, 0, PathRole::Sheet, -1});
  const Box2 area{{cell.min.x, cell.min.y + kText_mm + 1}, cell.max};
  const bool z_up = o.up == UpAxis::Auto ? upright_axis(mesh).z > 0 : o.up == UpAxis::Z;
  const ModelFrame& frame = z_up ? kZUp : kYUp;
  const Projection projection =
      fitted_projection(mesh, camera(frame(view.eye), frame.up), centre, radius, area);
  PartRaster raster;
  raster.area = area;
  raster.px = std::max(area.width(), area.height()) / kRaster;
  paint_faces(mesh, tint_of_face, projection, raster, sheet);
  letter_visible_parts(raster, letter_of_tint, o, sheet);
}

// "Glue order by part" lines: each part with the steps whose seams touch it, in letter order.
std::vector<std::string> order_by_part(const unfold::Unfolding& u, const LayoutResult& r,
                                       const std::vector<std::string>& letter_of_tint,
                                       const std::vector<int>& tint_of_piece) {
  // Numbers repeat from part to part: a step is found by its seam's edge.
  std::vector<int> step_of_edge(u.edges.size(), 0);
  for (const AssemblyStep& s : r.assembly)
    if (s.edge >= 0 && s.edge < static_cast<int>(step_of_edge.size())) step_of_edge[s.edge] = s.step;
  const int parts = static_cast<int>(letter_of_tint.size());
  std::vector<int> first(parts, 1 << 30), last(parts, 0);
  for (std::size_t e = 0; e < u.edges.size(); ++e) {
    const int step = step_of_edge[e];
    if (step <= 0) continue;
    for (int k = 0; k < 2; ++k) {
      const int f = u.edges[e].face[k];
      if (f < 0) continue;
      const int part = tint_of_piece[u.piece_of_face[f]];
      first[part] = std::min(first[part], step);
      last[part] = std::max(last[part], step);
    }
  }
  std::vector<std::string> lines{"Glue order by part (steps as printed beside the numbers):"};
  std::string line;
  for (int part = 0; part < parts; ++part) {
    std::string entry = letter_of_tint[part] + ": ";
    entry += last[part] == 0 ? std::string("-")
                             : std::to_string(first[part]).append("-").append(std::to_string(last[part]));
    if (!line.empty() && line.size() + entry.size() > 90) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : "   ") + entry;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

// Tints by letter: part A gets palette colour 0, and so on.
struct PartTints {
  std::vector<int> tint_of_piece;
  std::vector<std::string> letter_of_tint;
  std::vector<int> tint_of_face;
};

PartTints part_tints(const unfold::Mesh& mesh, const unfold::Unfolding& u, const LayoutResult& r) {
  const int pieces = u.piece_count;
  PartTints t;
  t.tint_of_piece.assign(pieces, 0);
  t.letter_of_tint.resize(pieces);
  for (int p = 0; p < pieces; ++p) {
    const std::string letter = p < static_cast<int>(r.piece_letters.size()) ? r.piece_letters[p] : "?";
    t.tint_of_piece[p] = std::clamp(letter_rank(letter), 0, pieces - 1);
    t.letter_of_tint[t.tint_of_piece[p]] = letter;
  }
  t.tint_of_face.assign(mesh.num_faces(), 0);
  for (int f = 0; f < mesh.num_faces() && f < static_cast<int>(u.piece_of_face.size()); ++f)
    t.tint_of_face[f] = t.tint_of_piece[u.piece_of_face[f]];
  return t;
}

// The title at the top; like every sheet, the guide says where it belongs and carries the scale check
// (bottom margin).
void add_title_and_foot(const GuideOptions& o, int pieces, std::size_t sheets, double y, Sheet& sheet) {
  constexpr double kBar_mm = 50, kTick_mm = 1.2;
  const Box2& area = sheet.printable_mm;
  const std::string title =
      (o.model_name.empty() ? std::string("Assembly guide") : o.model_name + ": assembly guide") + ", " +
      std::to_string(pieces) + (pieces == 1 ? " part on " : " parts on ") + std::to_string(sheets) +
      (sheets == 1 ? " sheet" : " sheets");
  sheet.texts.push_back(Text{title, {area.min.x, y}, kTitle_mm, 0, PathRole::Sheet, -1});
  const double foot = o.paper_mm.y - 0.5 * o.margin_mm + 1;
  const std::string n = std::to_string(sheets);
  sheet.texts.push_back(
      Text{"guide, after sheet " + n + "/" + n, {area.min.x, foot}, kText_mm, 0, PathRole::Sheet, -1});
  const Vec2 bar{area.max.x - kBar_mm, foot - 1};
  sheet.paths.push_back(Path{PathRole::Sheet, {bar, bar + Vec2{kBar_mm, 0}}, false, -1});
  sheet.paths.push_back(
      Path{PathRole::Sheet, {bar + Vec2{0, -kTick_mm}, bar + Vec2{0, kTick_mm}}, false, -1});
  sheet.paths.push_back(
      Path{PathRole::Sheet, {bar + Vec2{kBar_mm, -kTick_mm}, bar + Vec2{kBar_mm, kTick_mm}}, false, -1});
  sheet.texts.push_back(Text{"50 mm", bar + Vec2{-12, 1}, kText_mm, 0, PathRole::Sheet, -1});
}

// The notes under the views: where each part is (letter and sheet), then the glue order by part.
std::vector<std::string> guide_notes(const unfold::Unfolding& u, const LayoutResult& r, const PartTints& t) {
  constexpr std::size_t kLineChars = 90;
  const int pieces = u.piece_count;
  std::vector<std::string> notes{"Each part in its colour with its letter; where the parts are:"};
  std::string where;
  for (int tint = 0; tint < pieces; ++tint)
    for (int p = 0; p < pieces; ++p) {
      if (t.tint_of_piece[p] != tint || p >= static_cast<int>(r.placements.size())) continue;
      const std::string entry = t.letter_of_tint[tint] + " p" + std::to_string(r.placements[p].sheet + 1);
      if (!where.empty() && where.size() + entry.size() > kLineChars) {
        notes.push_back(where);
        where.clear();
      }
      where += (where.empty() ? "" : "   ") + entry;
    }
  if (!where.empty()) notes.push_back(where);
  if (!r.assembly.empty()) {
    const auto lines = order_by_part(u, r, t.letter_of_tint, t.tint_of_piece);
    notes.insert(notes.end(), lines.begin(), lines.end());
  }
  return notes;
}

// The centre of the mesh's bounding box and the radius of the sphere about it that holds the mesh.
std::pair<Vec3, double> bounding_sphere(const unfold::Mesh& mesh) {
  const unfold::MeshBounds bounds = unfold::bounds_of(mesh);
  const Vec3 centre = (bounds.lo + bounds.hi) * 0.5;
  double radius = 0;
  for (const Vec3& v : mesh.vertices)
    radius = std::max(radius, norm(v - centre));
  return {centre, radius};
}

}  // namespace

Sheet guide_sheet(const unfold::Mesh& mesh, const unfold::Unfolding& u, const LayoutResult& r,
                  const GuideOptions& o) {
  Sheet sheet;
  sheet.size_mm = o.paper_mm;
  sheet.printable_mm =
      Box2{{o.margin_mm, o.margin_mm}, {o.paper_mm.x - o.margin_mm, o.paper_mm.y - o.margin_mm}};
  const Box2& area = sheet.printable_mm;
  const PartTints tints = part_tints(mesh, u, r);
  const double title_y = area.min.y + kTitle_mm;
  add_title_and_foot(o, u.piece_count, r.sheets.size(), title_y, sheet);
  // The notes go at the bottom; the views share what is left in a 2 x 2 grid.
  const std::vector<std::string> notes = guide_notes(u, r, tints);
  const double notes_top = area.max.y - kLine_mm * static_cast<double>(notes.size());
  for (std::size_t i = 0; i < notes.size(); ++i)
    sheet.texts.push_back(Text{notes[i],
                               {area.min.x, notes_top + kLine_mm * (static_cast<double>(i) + 0.7)},
                               kText_mm,
                               0,
                               PathRole::Sheet,
                               -1});

  const auto [centre, radius] = bounding_sphere(mesh);
  if (!(radius > 0) || mesh.num_faces() == 0) return sheet;
  const double top = title_y + kLine_mm + 2, gap = 4;
  const double cell_w = 0.5 * (area.width() - gap), cell_h = 0.5 * (notes_top - top - 2 * gap);
  for (std::size_t v = 0; v < kViews.size(); ++v) {
    const double cx = area.min.x + static_cast<double>(v % 2) * (cell_w + gap);
    const double cy = top + static_cast<double>(v / 2) * (cell_h + gap);
    draw_view(mesh, tints.tint_of_face, tints.letter_of_tint, kViews[v], centre, radius,
              Box2{{cx, cy}, {cx + cell_w, cy + cell_h}}, o, sheet);
  }
  return sheet;
}

}  // namespace foldkit::layout
