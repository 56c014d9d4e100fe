#pragma once
// Small helpers the mesh-reading tests share: a mesh's signed volume (positive when it faces outward)
// and base64, for glTF documents with their buffers inline.
#include <string>

#include "foldkit/unfold/mesh.hpp"

namespace foldkit::test {

/// Signed volume enclosed by the faces: positive for a closed mesh whose faces look outward.
inline double signed_volume(const unfold::Mesh& m) {
  double v = 0;
  for (int f = 0; f < m.num_faces(); ++f) {
    const auto c = m.corners(f);
    v += dot(c[0], cross(c[1], c[2])) / 6;
  }
  return v;
}

/// Standard base64 with padding, as a glTF data: URI carries a buffer.
inline std::string base64(const std::string& blob) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < blob.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(blob[i]) << 16) |
                       (i + 1 < blob.size() ? static_cast<unsigned char>(blob[i + 1]) << 8 : 0) |
                       (i + 2 < blob.size() ? static_cast<unsigned char>(blob[i + 2]) : 0);
    out += kDigits[(n >> 18) & 63];
    out += kDigits[(n >> 12) & 63];
    out += i + 1 < blob.size() ? kDigits[(n >> 6) & 63] : '=';
    out += i + 2 < blob.size() ? kDigits[n & 63] : '=';
  }
  return out;
}

}  // namespace foldkit::test
