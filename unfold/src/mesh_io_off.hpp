#pragma once
// Internal to unfold/: OFF files (ASCII and binary) read into a polygon soup by foldkit itself.
// OpenMesh's OFF reader trusts what it reads: it takes the counts from a different line than the header
// a checker sees, reads binary counts from text (a four-byte "1 1\n" becomes 170 million vertices to
// reserve), and keeps reading from a failed stream. The format is small enough to read strictly here.
#include <cstdint>
#include <string>

#include "face_colours.hpp"
#include "mesh_io_soup.hpp"

namespace foldkit::unfold::detail {

/// Reads an OFF file's text (at most `face_limit` faces declared): `[ST][C][N]OFF` with optional ` BINARY`,
/// the counts on the header line or the next, `#` comments (ASCII), faces of 3 or more indices with an
/// optional colour (3 or 4 numbers, bytes or 0–1 floats; binary: a component count then floats). Face colours
/// go to `colours`. Throws InputError(name, …) naming the line (ASCII) or record (binary) of the first
/// problem; never allocates more than the file's size can justify.
PolygonSoup read_off(const std::string& text, const std::string& name, int face_limit, RawColours& colours);

}  // namespace foldkit::unfold::detail
