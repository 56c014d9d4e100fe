#include "mesh_io_off.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "foldkit/error.hpp"
#include "mesh_io_ascii.hpp"

namespace foldkit::unfold::detail {
namespace {

// The fewest bytes a vertex and a face can take: "0 0 0\n" and "3 0 1 2\n" in ASCII; three floats,
// and a count with three indices and a colour count, in binary.
constexpr std::uint64_t kMinAsciiVertexBytes = 6;
constexpr std::uint64_t kMinAsciiFaceBytes = 8;
constexpr std::uint64_t kBinaryWordBytes = 4;
constexpr std::uint64_t kMinBinaryFaceBytes = 5 * kBinaryWordBytes;
// Geomview's binary OFF gives a face's colour as a component count and that many floats (RGBA at most).
constexpr std::uint32_t kMaxBinaryColourComponents = 4;

/// What the first word of the file says: `[ST][C][N]OFF`, then ` BINARY` or not.
struct OffHeader {
  bool texcoords = false, colours = false, normals = false, binary = false;
  std::size_t after_magic = 0;  ///< position after the magic word (ASCII counts may follow on its line)
  std::size_t body = 0;         ///< position after the header line
};

OffHeader read_header(const std::string& text, const std::string& name) {
  OffHeader h;
  // Comment lines may come before the magic word.
  std::size_t i = std::min(text.find_first_not_of(" \t\r\n"), text.size());
  while (i < text.size() && text[i] == '#')
    i = std::min(text.find_first_not_of(" \t\r\n", std::min(text.find('\n', i), text.size())), text.size());
  const std::size_t word_end = std::min(text.find_first_of(" \t\r\n", i), text.size());
  const std::string magic = text.substr(i, word_end - i);
  if (magic.find("OFF") == std::string::npos) throw InputError(name, "not an OFF file (no OFF header)");
  std::string_view rest(magic);
  auto take = [&](std::string_view prefix) {
    if (rest.substr(0, prefix.size()) != prefix) return false;
    rest.remove_prefix(prefix.size());
    return true;
  };
  h.texcoords = take("ST");
  h.colours = take("C");
  h.normals = take("N");
  if (rest != "OFF") throw InputError(name, "unsupported OFF variant '" + magic.substr(0, 32) + "'");
  h.after_magic = word_end;
  const std::size_t eol = std::min(text.find('\n', word_end), text.size());
  h.body = eol < text.size() ? eol + 1 : eol;
  const std::string_view line = std::string_view(text).substr(word_end, eol - word_end);
  const std::size_t word = line.find_first_not_of(" \t\r");
  h.binary = word != std::string_view::npos && line.substr(word, 6) == "BINARY";
  return h;
}

struct Counts {
  std::uint64_t vertices = 0, faces = 0;
  std::size_t end = 0;  ///< position after the counts line
};

// The counts are the first numbers after the magic word: on its line or on the first line after it
// that is not blank or a comment.
Counts read_ascii_counts(const std::string& text, std::size_t pos, const std::string& name) {
  while (pos < text.size()) {
    const std::size_t eol = std::min(text.find('\n', pos), text.size());
    std::string line = text.substr(pos, eol - pos);
    pos = eol < text.size() ? eol + 1 : eol;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const char* p = line.c_str();
    std::uint64_t n[2];
    for (std::uint64_t& count : n) {
      while (*p == ' ' || *p == '\t')
        ++p;
      char* stop = nullptr;
      errno = 0;
      count = std::strtoull(p, &stop, 10);
      if (stop == p || *p == '-' || errno != 0 || (*stop && *stop != ' ' && *stop != '\t' && *stop != '\r'))
        throw InputError(name, "unparsable OFF header (no vertex and face counts)");
      p = stop;
    }
    return {n[0], n[1], pos};
  }
  throw InputError(name, "unparsable OFF header (no vertex and face counts)");
}

PolygonSoup read_ascii(const std::string& text, const OffHeader& h, const std::string& name, int face_limit,
                       RawColours& colours) {
  const Counts c = read_ascii_counts(text, h.after_magic, name);
  check_face_limit(c.faces, face_limit, name);
  check_declared_counts(c.vertices, c.faces, kMinAsciiVertexBytes, kMinAsciiFaceBytes, text.size(), name);
  AsciiBlockOptions options;
  options.comments = true;
  PolygonSoup soup;
  const std::size_t faces_at =
      read_ascii_vertex_block(text, c.end, c.vertices, name, options, &soup.vertices);
  AsciiFaces faces;
  read_ascii_faces(text, faces_at, c.faces, c.vertices, name, options, &faces);
  soup.polygons = std::move(faces.polygons);
  colours.face_colour = std::move(faces.colours);
  return soup;
}

/// Little-endian words of a binary body, refusing to read past its end.
class BinaryWords {
 public:
  BinaryWords(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  bool can_take(std::uint64_t words) const { return words <= (bytes_.size() - at_) / kBinaryWordBytes; }

  std::uint32_t word(const std::string& what) {
    if (!can_take(1)) throw InputError(name_, "truncated file: " + what + " runs past the end of the file");
    std::uint32_t w = 0;
    for (std::size_t i = 0; i < kBinaryWordBytes; ++i)
      w |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes_[at_ + i])) << (8 * i);
    at_ += kBinaryWordBytes;
    return w;
  }

  double number(const std::string& what) {
    const std::uint32_t w = word(what);
    float f = 0;
    std::memcpy(&f, &w, sizeof f);
    return f;
  }

  std::size_t remaining() const { return bytes_.size() - at_; }

 private:
  std::string_view bytes_;
  const std::string& name_;
  std::size_t at_ = 0;
};

PolygonSoup read_binary(const std::string& text, const OffHeader& h, const std::string& name, int face_limit,
                        RawColours& colours) {
  if (h.colours) throw InputError(name, "unsupported OFF variant: binary COFF");
  BinaryWords in(std::string_view(text).substr(h.body), name);
  const std::uint64_t nv = in.word("the header"), nf = in.word("the header");
  (void)in.word("the header");  // edge count, unused
  check_face_limit(nf, face_limit, name);
  const std::uint64_t vertex_words = 3 + (h.normals ? 3 : 0) + (h.texcoords ? 2 : 0);
  check_declared_counts(nv, nf, vertex_words * kBinaryWordBytes, kMinBinaryFaceBytes, in.remaining(), name);
  PolygonSoup soup;
  soup.vertices.reserve(nv);
  for (std::uint64_t v = 0; v < nv; ++v) {
    const std::string vertex = "vertex " + std::to_string(v + 1);
    double xyz[3];
    for (std::uint64_t k = 0; k < vertex_words; ++k) {
      const double x = in.number(vertex);
      if (!std::isfinite(x) || !in_coordinate_range(x))
        throw InputError(name, vertex + " has a non-finite coordinate");
      if (k < 3) xyz[k] = x;
    }
    soup.vertices.push_back({xyz[0], xyz[1], xyz[2]});
  }
  soup.polygons.reserve(nf);
  for (std::uint64_t f = 0; f < nf; ++f) {
    const std::string face = "face " + std::to_string(f + 1);
    const std::uint32_t k = in.word(face);
    if (k < 3) throw InputError(name, face + " has " + std::to_string(k) + " vertices (at least 3 needed)");
    if (!in.can_take(std::uint64_t{k} + 1))
      throw InputError(name,
                       face + " declares " + std::to_string(k) + " vertices, more than the rest of the file");
    std::vector<int> polygon(k);
    for (int& index : polygon) {
      const std::uint32_t i = in.word(face);
      if (i >= nv)
        throw InputError(name, face + " references vertex " + std::to_string(std::uint64_t{i} + 1) +
                                   " (only " + std::to_string(nv) + " vertices)");
      index = static_cast<int>(i);
    }
    const std::uint32_t components = in.word(face);
    if (components > kMaxBinaryColourComponents)
      throw InputError(name, face + " declares " + std::to_string(components) + " colour components");
    double rgb[kMaxBinaryColourComponents] = {1, 1, 1, 1};
    for (std::uint32_t i = 0; i < components; ++i)
      rgb[i] = in.number(face);
    std::optional<Colour> colour;
    if (components >= 3 && std::isfinite(rgb[0] + rgb[1] + rgb[2]))
      colour =
          Colour{std::clamp(rgb[0], 0.0, 1.0), std::clamp(rgb[1], 0.0, 1.0), std::clamp(rgb[2], 0.0, 1.0)};
    colours.face_colour.push_back(colour);
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

}  // namespace

PolygonSoup read_off(const std::string& text, const std::string& name, int face_limit, RawColours& colours) {
  const OffHeader h = read_header(text, name);
  return h.binary ? read_binary(text, h, name, face_limit, colours)
                  : read_ascii(text, h, name, face_limit, colours);
}

}  // namespace foldkit::unfold::detail
