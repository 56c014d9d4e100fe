#pragma once
// Reducing a mesh to a face budget before unfolding (the seed's preprocessing): fewer, larger faces are
// easier to cut, fold and glue.
#include "foldkit/unfold/mesh.hpp"

namespace foldkit::unfold {

/// Collapses edges by least quadric error (OpenMesh's decimater, with a guard against flipping face
/// normals) until the mesh has at most `max_faces` faces or no collapse is allowed. Keeps the mesh
/// manifold and its orientation; returns it unchanged when it is already small enough.
Mesh decimate(const Mesh& mesh, int max_faces);

}  // namespace foldkit::unfold
