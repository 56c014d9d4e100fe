#include "mesh_io_ascii.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "foldkit/error.hpp"

namespace foldkit::unfold::detail {
namespace {

// A colour component above 1 is a byte (0–255), as OFF and PLY writers give them.
constexpr double kByteComponentAbove = 1.0;
constexpr double kByteScale = 255.0;

/// The whitespace-separated tokens of one line, without a comment when `comments`.
std::vector<std::string_view> tokens_of(std::string_view line, bool comments) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
      ++i;
    if (i == line.size() || (comments && line[i] == '#')) break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
      ++i;
    out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parse_index(std::string_view t, std::uint64_t& out) {
  const std::string s(t);
  char* stop = nullptr;
  errno = 0;
  out = std::strtoull(s.c_str(), &stop, 10);
  return !s.empty() && s[0] != '-' && errno == 0 && stop == s.c_str() + s.size();
}

bool parse_number(std::string_view t, double& out) {
  const std::string s(t);
  char* stop = nullptr;
  out = std::strtod(s.c_str(), &stop);
  return !s.empty() && stop == s.c_str() + s.size() && std::isfinite(out);
}

// Three or four numbers after a face's indices are its colour (alpha ignored); anything else (a
// colour-map index, nothing) is no colour.
std::optional<Colour> face_colour(const std::vector<std::string_view>& extra) {
  if (extra.size() != 3 && extra.size() != 4) return std::nullopt;
  double c[3];
  for (int i = 0; i < 3; ++i)
    if (!parse_number(extra[static_cast<std::size_t>(i)], c[i]) || c[i] < 0) return std::nullopt;
  const bool bytes = std::max({c[0], c[1], c[2]}) > kByteComponentAbove;
  const double scale = bytes ? kByteScale : 1.0;
  return Colour{std::min(c[0] / scale, 1.0), std::min(c[1] / scale, 1.0), std::min(c[2] / scale, 1.0)};
}

}  // namespace

bool in_coordinate_range(double x) {
  return std::fabs(x) <= kMaxCoordinate;
}

void check_face_limit(std::uint64_t triangles, int face_limit, const std::string& name) {
  if (triangles > static_cast<std::uint64_t>(face_limit))
    throw InputError(name, "at least " + std::to_string(triangles) + " triangles, over the limit of " +
                               std::to_string(face_limit) + " (decimate the mesh first)");
}

void check_declared_counts(std::uint64_t vertices, std::uint64_t faces, std::uint64_t min_bytes_per_vertex,
                           std::uint64_t min_bytes_per_face, std::size_t file_bytes,
                           const std::string& name) {
  const std::uint64_t needed = vertices * min_bytes_per_vertex + faces * min_bytes_per_face;
  if (vertices > (std::uint64_t{1} << 40) || faces > (std::uint64_t{1} << 40) || needed > file_bytes)
    throw InputError(name, "truncated file: the header declares " + std::to_string(vertices) +
                               " vertices and " + std::to_string(faces) + " faces, more than its " +
                               std::to_string(file_bytes) + " bytes can hold");
}

std::size_t read_ascii_vertex_block(const std::string& text, std::size_t pos, std::uint64_t vertices,
                                    const std::string& name, const AsciiBlockOptions& options,
                                    std::vector<Vec3>* positions) {
  const char* p = text.c_str() + std::min(pos, text.size());
  const char* const end = text.c_str() + text.size();
  std::size_t line_no = static_cast<std::size_t>(std::count(text.c_str(), p, '\n'));
  if (positions) positions->reserve(positions->size() + vertices);
  std::uint64_t v = 0;
  while (v < vertices && p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (!eol) eol = end;
    const std::string_view line(p, static_cast<std::size_t>(eol - p));
    p = eol + 1;
    ++line_no;
    const auto where = [&] { return " (line " + std::to_string(line_no) + ")"; };
    const std::string vertex = "vertex " + std::to_string(v + 1);
    // A vertex line may end in a comment in any format foldkit reads: PLY never has '#' in its body.
    const std::vector<std::string_view> words = tokens_of(line, true);
    if (words.empty()) continue;  // blank or comment line
    double xyz[3] = {0, 0, 0};
    for (std::size_t i = 0; i < words.size(); ++i) {
      const std::string tok(words[i]);
      char* stop = nullptr;
      const double x = std::strtod(tok.c_str(), &stop);
      if (stop != tok.c_str() + tok.size())
        throw InputError(name, "unparsable coordinate '" + tok.substr(0, 32) + "' of " + vertex + where());
      if (!std::isfinite(x)) throw InputError(name, vertex + " has a non-finite coordinate" + where());
      if (!in_coordinate_range(x))
        throw InputError(name, vertex + ": coordinate out of range '" + tok.substr(0, 32) + "'" + where());
      for (std::size_t axis = 0; axis < 3; ++axis)
        if (static_cast<std::size_t>(options.xyz_columns[axis]) == i) xyz[axis] = x;
    }
    const int numbers = static_cast<int>(words.size());
    if (numbers < 3) throw InputError(name, vertex + " has fewer than 3 coordinates" + where());
    if (options.exact_vertex_numbers > 0 && numbers != options.exact_vertex_numbers)
      throw InputError(name, vertex + " has " + std::to_string(numbers) + " values, the header declares " +
                                 std::to_string(options.exact_vertex_numbers) + where());
    if (positions) positions->push_back({xyz[0], xyz[1], xyz[2]});
    ++v;
  }
  if (v < vertices)
    throw InputError(
        name, "truncated file: " + std::to_string(v) + " of " + std::to_string(vertices) + " vertices");
  return static_cast<std::size_t>(std::min(p, end) - text.c_str());
}

void read_ascii_faces(const std::string& text, std::size_t pos, std::uint64_t faces, std::uint64_t vertices,
                      const std::string& name, const AsciiBlockOptions& options, AsciiFaces* out) {
  const char* p = text.c_str() + std::min(pos, text.size());
  const char* const end = text.c_str() + text.size();
  if (out) {
    out->polygons.reserve(out->polygons.size() + faces);
    out->colours.reserve(out->colours.size() + faces);
  }
  std::uint64_t f = 0;
  while (f < faces && p < end) {
    const char* eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (!eol) eol = end;
    const std::string_view line(p, static_cast<std::size_t>(eol - p));
    p = eol + 1;
    const std::vector<std::string_view> w = tokens_of(line, options.comments);
    if (w.empty()) continue;
    const std::string face = "face " + std::to_string(f + 1);
    std::uint64_t k = 0;
    if (!parse_index(w[0], k) || k < 3 || w.size() < k + 1)
      throw InputError(name, face + ": unparsable vertex list '" + std::string(line.substr(0, 32)) + "'");
    if (options.exact_face_numbers && w.size() != k + 1)
      throw InputError(name, face + ": " + std::to_string(w.size() - 1) + " numbers after a count of " +
                                 std::to_string(k));
    std::vector<int> polygon;
    polygon.reserve(k);
    for (std::uint64_t i = 1; i <= k; ++i) {
      std::uint64_t index = 0;
      // Vertices are numbered from 1 in messages, as for every other format.
      const bool parsed = parse_index(w[i], index);
      if (!parsed || index >= vertices)
        throw InputError(name, face + " references vertex " +
                                   (parsed ? std::to_string(index + 1) : std::string(w[i].substr(0, 24))) +
                                   " (only " + std::to_string(vertices) + " vertices)");
      polygon.push_back(static_cast<int>(index));
    }
    if (out) {
      out->polygons.push_back(std::move(polygon));
      out->colours.push_back(face_colour({w.begin() + static_cast<std::ptrdiff_t>(k) + 1, w.end()}));
    }
    ++f;
  }
  if (f < faces)
    throw InputError(name,
                     "truncated file: " + std::to_string(f) + " of " + std::to_string(faces) + " faces");
}

}  // namespace foldkit::unfold::detail
