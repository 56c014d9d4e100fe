#pragma once
// Flat faces: the units no stage may cut. A planar polygon of the input file (a quad, an n-gon, convex or
// not) and any run of coplanar triangles prints as one polygon, so its triangles are folded together,
// always. A polygon that is not planar within the tolerance cannot lie flat: its triangles fold.
#include <numbers>
#include <vector>

#include "foldkit/unfold/dual_graph.hpp"
#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// Half a degree: below what a folded paper model shows, above the rounding of coordinates printed with
/// six significant digits.
constexpr double kDefaultFlatAngleDeg = 0.5;
constexpr double kDefaultFlatAngleRad = kDefaultFlatAngleDeg * std::numbers::pi / 180.0;

/// The partition of a mesh's triangles into flat faces.
struct FlatFaces {
  /// face_unit[f] in 0..unit_count-1: the flat face triangle f belongs to.
  std::vector<int> face_unit;
  int unit_count = 0;
  /// inside[e]: edge e joins two triangles of the same flat face (it is never cut and never drawn).
  std::vector<bool> inside;
  /// Number of input polygons of more than one triangle that are not planar within the tolerance.
  int non_planar_polygons = 0;
};

/// Groups triangles into flat faces: first the triangles of each input polygon (Mesh::face_polygon)
/// whose normals all lie within `flat_angle_rad` of the polygon's mean normal, then neighbouring faces
/// whose triangles all lie within `flat_angle_rad` of the first face's normal. A flat face stays a tree
/// of triangles (it joins a neighbour across exactly one edge), so it lies flat without a cut inside:
/// around a vertex inside a flat region one edge stays a (straight, invisible) seam between two faces.
FlatFaces find_flat_faces(const Mesh& mesh, double flat_angle_rad = kDefaultFlatAngleRad);

/// Adds the edges inside flat faces to `constraints` as forced folds. An edge the user forces to be
/// cut stays cut (the user named it); a user's kept edge that would close a loop with them is dropped.
void keep_flat_faces(const Mesh& mesh, const FlatFaces& flat, EdgeConstraints& constraints);

/// Marks UnfoldEdge::inside_face on the edges inside flat faces.
void mark_flat_faces(const FlatFaces& flat, Unfolding& unfolding);

}  // namespace foldkit::unfold
