#pragma once
// The flat net as a Wavefront OBJ: what `foldkit unfold -o net.obj` writes, for inspection or other tools.
#include <ostream>

#include "foldkit/unfold/mesh.hpp"
#include "foldkit/unfold/unfolding.hpp"

namespace foldkit::unfold {

/// Writes `u` as OBJ: face k of the net is face k of the input file (polygons whole), one `g piece_N` group
/// per piece, vertices shared only where a piece folds. A non-planar polygon the unfolding cut apart is
/// written as its triangles, which the header comment says.
void write_net_obj(std::ostream& out, const Mesh& mesh, const Unfolding& u);

}  // namespace foldkit::unfold
