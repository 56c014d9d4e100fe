// The glTF 2.0 container and data layer. Numbers the file states (counts, offsets, lengths) are only
// trusted after they are checked against bytes that exist: no allocation is ever sized by a count alone.
#include "gltf_document.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "foldkit/error.hpp"

namespace foldkit::unfold::detail::gltf {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;    // "JSON"
constexpr std::uint32_t kChunkBinary = 0x004E4942;  // "BIN\0"
constexpr std::size_t kGlbHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;
// Real documents nest a handful of levels; a deeper one is an attack on the parser's stack.
constexpr int kMaxJsonDepth = 64;
constexpr std::uint64_t kMinByteStride = 4;
constexpr std::uint64_t kMaxByteStride = 252;

// The component types of glTF 2.0 accessors (the OpenGL enum values the format uses).
constexpr std::uint64_t kUnsignedByte = 5121;
constexpr std::uint64_t kUnsignedShort = 5123;
constexpr std::uint64_t kUnsignedInt = 5125;
constexpr std::uint64_t kFloat = 5126;

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return v;
}

std::size_t component_bytes(std::uint64_t type) {
  switch (type) {
    case 5120:
    case kUnsignedByte:
      return 1;
    case 5122:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

std::size_t components_of(std::string_view type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

// Depth of [ and { outside strings, checked before the parser sees the text.
bool nesting_within(std::string_view text, int max_depth) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return false;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return true;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percent_decode(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      out += s[i];
      continue;
    }
    const int hi = i + 2 < s.size() ? hex_value(s[i + 1]) : -1;
    const int lo = i + 2 < s.size() ? hex_value(s[i + 2]) : -1;
    if (hi < 0 || lo < 0) throw std::invalid_argument("malformed percent escape");
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return out;
}

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;
  if (c == '/' || c == '_') return 63;
  return -1;
}

std::string base64_decode(std::string_view s) {
  while (!s.empty() && s.back() == '=')
    s.remove_suffix(1);
  std::string out;
  out.reserve(s.size() / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int have = 0;
  for (char c : s) {
    const int v = base64_value(c);
    if (v < 0) throw std::invalid_argument("malformed base64");
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    if ((have += 6) >= 8) {
      have -= 8;
      out += static_cast<char>((bits >> have) & 0xFF);
    }
  }
  return out;
}

bool starts_with_ci(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[i])) != prefix[i]) return false;
  return true;
}

// Built by append: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...).
std::string quoted(std::string_view key) {
  std::string out(1, '\'');
  out.append(key);
  out += '\'';
  return out;
}

std::string printable_json(const Json& j) {
  return j.is_string() ? printable(j.get<std::string>()) : "(not a string)";
}

std::string json_type_name(const Json& j) {
  if (j.is_object()) return "an object";
  if (j.is_array()) return "an array";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_number()) return "a number";
  return "null";
}

}  // namespace

std::string printable(std::string_view text) {
  constexpr std::size_t kMaxChars = 80;
  std::string s(text.substr(0, kMaxChars));
  if (text.size() > kMaxChars) s += "...";
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return s;
}

std::optional<std::string> decode_data_uri(std::string_view uri) {
  if (!starts_with_ci(uri, "data:")) return std::nullopt;
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) throw std::invalid_argument("data URI without a comma");
  const std::string_view header = uri.substr(0, comma);
  const std::string_view payload = uri.substr(comma + 1);
  const bool base64 = header.size() >= 7 && header.substr(header.size() - 7) == ";base64";
  return base64 ? base64_decode(payload) : percent_decode(payload);
}

fs::path uri_to_relative_path(std::string_view uri) {
  if (uri.empty()) throw std::invalid_argument("empty URI");
  if (uri.front() == '/' || uri.front() == '\\') throw std::invalid_argument("an absolute path");
  const std::size_t colon = uri.find(':');
  if (colon != std::string_view::npos && uri.substr(0, colon).find('/') == std::string_view::npos)
    throw std::invalid_argument("not a relative file reference");
  const std::string path = percent_decode(uri);
  if (path.find('\0') != std::string::npos) throw std::invalid_argument("a NUL byte in the path");
  return fs::path(path);
}

Document::Document(const std::string& bytes, fs::path folder, std::string name, Limits limits)
    : folder_(std::move(folder)), name_(std::move(name)), limits_(limits) {
  std::string_view json_text = bytes;
  if (bytes.size() >= 4 && le32(bytes, 0) == kGlbMagic) {
    if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes) fail("GLB", "truncated header");
    if (le32(bytes, 4) != kGlbVersion)
      fail("GLB", "container version " + std::to_string(le32(bytes, 4)) + ", not 2");
    if (le32(bytes, 8) != bytes.size())
      fail("GLB", "header states " + std::to_string(le32(bytes, 8)) + " bytes, the file has " +
                      std::to_string(bytes.size()));
    std::size_t at = kGlbHeaderBytes;
    bool first = true;
    while (at + kChunkHeaderBytes <= bytes.size()) {
      const std::uint64_t length = le32(bytes, at);
      const std::uint32_t type = le32(bytes, at + 4);
      at += kChunkHeaderBytes;
      if (length > bytes.size() - at) fail("GLB", "a chunk runs past the end of the file");
      if (first && type != kChunkJson) fail("GLB", "the first chunk is not JSON");
      if (first) json_text = std::string_view(bytes).substr(at, length);
      if (!first && type == kChunkBinary && !glb_binary_) glb_binary_ = bytes.substr(at, length);
      first = false;
      at += length;
    }
    if (first) fail("GLB", "no JSON chunk");
  }
  if (!nesting_within(json_text, kMaxJsonDepth))
    fail("JSON", "nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
  root_ = Json::parse(json_text.begin(), json_text.end(), nullptr, /*allow_exceptions=*/false);
  if (root_.is_discarded() || !root_.is_object()) fail("JSON", "not a valid glTF JSON document");

  const Json* asset = member(root_, "asset", Json::value_t::object, "document");
  if (!asset) fail("document", "no 'asset' (not a glTF file)");
  const Json* version = member(*asset, "version", Json::value_t::string, "asset");
  if (!version || version->get<std::string>().rfind("2.", 0) != 0)
    fail("asset", "glTF version " + (version ? printable_json(*version) : std::string("(none)")) +
                      " is not supported (2.x expected)");
  if (const Json* required = member(root_, "extensionsRequired", Json::value_t::array, "document"))
    for (const Json& ext : *required) {
      const std::string e = ext.is_string() ? ext.get<std::string>() : "";
      // Material extensions only change shading, which paper does not print.
      if (e.rfind("KHR_materials_", 0) != 0 && e != "KHR_lights_punctual")
        fail("document", "needs the extension " + printable_json(ext) + ", which foldkit cannot read");
    }
  for (const char* key : {"accessors", "bufferViews", "buffers", "meshes", "nodes", "scenes", "materials",
                          "textures", "images"}) {
    if (const Json* list = member(root_, key, Json::value_t::array, "document"))
      for (std::size_t i = 0; i < list->size(); ++i)
        if (!(*list)[i].is_object()) fail(std::string(key) + " " + std::to_string(i), "is not an object");
  }
  buffers_.resize(array("buffers").size());
}

void Document::fail(const std::string& where, const std::string& problem) const {
  throw InputError(name_, "glTF " + where + ": " + problem);
}

const Json* Document::member(const Json& object, std::string_view key, Json::value_t type,
                             const std::string& where) const {
  const auto it = object.find(key);
  if (it == object.end()) return nullptr;
  const bool number_wanted = type == Json::value_t::number_float;
  if (number_wanted ? !it->is_number() : it->type() != type)
    fail(where, quoted(key) + " is " + json_type_name(*it));
  return &*it;
}

const Json& Document::array(std::string_view key) const {
  const auto it = root_.find(key);
  return it == root_.end() ? empty_array_ : *it;
}

std::optional<std::size_t> Document::index(const Json& object, std::string_view key, std::string_view into,
                                           const std::string& where) const {
  const auto it = object.find(key);
  if (it == object.end()) return std::nullopt;
  return as_index(*it, into, where + ", " + quoted(key));
}

std::size_t Document::as_index(const Json& value, std::string_view into, const std::string& where) const {
  if (!value.is_number_unsigned()) fail(where, "is not an index");
  const std::uint64_t i = value.get<std::uint64_t>();
  const std::size_t size = array(into).size();
  if (i >= size)
    fail(where,
         "is " + std::to_string(i) + ", but there are " + std::to_string(size) + " " + std::string(into));
  return static_cast<std::size_t>(i);
}

std::optional<std::vector<double>> Document::numbers(const Json& object, std::string_view key, std::size_t n,
                                                     const std::string& where) const {
  const Json* list = member(object, key, Json::value_t::array, where);
  if (!list) return std::nullopt;
  if (list->size() != n) fail(where, quoted(key) + " needs " + std::to_string(n) + " numbers");
  std::vector<double> out;
  for (const Json& x : *list) {
    if (!x.is_number() || !std::isfinite(x.get<double>()))
      fail(where, quoted(key) + " holds something that is not a finite number");
    out.push_back(x.get<double>());
  }
  return out;
}

std::string Document::read_external(const std::string& uri, std::uint64_t length,
                                    const std::string& where) const {
  fs::path relative;
  try {
    relative = uri_to_relative_path(uri);
  } catch (const std::invalid_argument& e) {
    fail(where, "uri is " + std::string(e.what()));
  }
  const fs::path file = folder_ / relative;
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    fail(where, printable(file.string()) + " is missing or not a regular file");
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec || size > limits_.max_file_bytes) fail(where, printable(file.string()) + " is over the size limit");
  if (size < length) fail(where, printable(file.string()) + " has fewer bytes than its byteLength");
  std::string data(static_cast<std::size_t>(length), '\0');
  std::ifstream in(file, std::ios::binary);
  if (!in.read(data.data(), static_cast<std::streamsize>(length)))
    fail(where, "cannot read " + printable(file.string()));
  return data;
}

const std::string& Document::buffer(std::size_t b) {
  if (buffers_[b]) return *buffers_[b];
  const Json& buf = array("buffers")[b];
  const std::string here = "buffer " + std::to_string(b);
  const auto length_it = buf.find("byteLength");
  if (length_it == buf.end() || !length_it->is_number_unsigned()) fail(here, "no byteLength");
  const std::uint64_t length = length_it->get<std::uint64_t>();
  if (length > limits_.max_file_bytes) fail(here, "byteLength is over the size limit");
  const Json* uri = member(buf, "uri", Json::value_t::string, here);
  std::string data;
  if (!uri) {
    if (!glb_binary_ || b != 0) fail(here, "has no uri and is not a GLB's binary chunk");
    data = *glb_binary_;
  } else {
    std::optional<std::string> inline_data;
    try {
      inline_data = decode_data_uri(uri->get<std::string>());
    } catch (const std::invalid_argument& e) {
      fail(here, e.what());
    }
    data = inline_data ? std::move(*inline_data) : read_external(uri->get<std::string>(), length, here);
  }
  if (data.size() < length) fail(here, "holds fewer bytes than its byteLength");
  data.resize(static_cast<std::size_t>(length));
  return *(buffers_[b] = std::move(data));
}

std::string_view Document::view_bytes(std::size_t v, const std::string& where) {
  const Json& view = array("bufferViews")[v];
  const std::string here = where + ", buffer view " + std::to_string(v);
  const std::optional<std::size_t> b = index(view, "buffer", "buffers", here);
  if (!b) fail(here, "names no buffer");
  const auto unsigned_or = [&](const char* key, std::uint64_t fallback) {
    const auto it = view.find(key);
    if (it == view.end()) return fallback;
    if (!it->is_number_unsigned()) fail(here, quoted(key) + " is not a whole number");
    return it->get<std::uint64_t>();
  };
  const std::uint64_t offset = unsigned_or("byteOffset", 0);
  const std::uint64_t length = unsigned_or("byteLength", 0);
  const std::string& data = buffer(*b);
  if (length == 0 || offset > data.size() || length > data.size() - offset)
    fail(here, "lies outside its buffer");
  return std::string_view(data).substr(static_cast<std::size_t>(offset), static_cast<std::size_t>(length));
}

Document::Span Document::accessor_span(std::size_t a, std::string_view type, const std::string& where) {
  const Json& acc = array("accessors")[a];
  const std::string here = where + ", accessor " + std::to_string(a);
  const Json* t = member(acc, "type", Json::value_t::string, here);
  if (!t || *t != type) fail(here, "is not of type " + std::string(type));
  if (acc.contains("sparse")) fail(here, "sparse accessors are not supported");
  const auto ct = acc.find("componentType");
  const auto count_it = acc.find("count");
  if (ct == acc.end() || !ct->is_number_unsigned() || component_bytes(ct->get<std::uint64_t>()) == 0)
    fail(here, "no valid componentType");
  if (count_it == acc.end() || !count_it->is_number_unsigned() || count_it->get<std::uint64_t>() == 0)
    fail(here, "no valid count");
  const auto view = index(acc, "bufferView", "bufferViews", here);
  if (!view) fail(here, "has no bufferView");
  const Element element{components_of(type), component_bytes(ct->get<std::uint64_t>()),
                        ct->get<std::uint64_t>()};
  const std::uint64_t element_bytes = element.components * element.component_bytes;
  const Json& view_json = array("bufferViews")[*view];
  std::uint64_t stride = element_bytes;
  if (const auto s = view_json.find("byteStride"); s != view_json.end()) {
    if (!s->is_number_unsigned() || s->get<std::uint64_t>() < kMinByteStride ||
        s->get<std::uint64_t>() > kMaxByteStride)
      fail(here, "byteStride out of range");
    stride = std::max(stride, s->get<std::uint64_t>());
  }
  std::uint64_t offset = 0;
  if (const auto o = acc.find("byteOffset"); o != acc.end()) {
    if (!o->is_number_unsigned()) fail(here, "byteOffset is not a whole number");
    offset = o->get<std::uint64_t>();
  }
  const std::string_view bytes = view_bytes(*view, here);
  const std::uint64_t count = count_it->get<std::uint64_t>();
  if (count > limits_.max_elements - elements_read_)
    fail(here, "the file's accessors hold more elements than its face limit allows");
  elements_read_ += count;
  // count <= bytes.size() first, so the product below cannot overflow.
  if (count > bytes.size() || offset > bytes.size() ||
      (count - 1) * stride + element_bytes > bytes.size() - offset)
    fail(here, std::to_string(count) + " elements do not fit in its buffer view");
  const auto normalized = acc.find("normalized");
  return Span{bytes.substr(static_cast<std::size_t>(offset)), static_cast<std::size_t>(count),
              static_cast<std::size_t>(stride), element,
              normalized != acc.end() && normalized->is_boolean() && normalized->get<bool>()};
}

namespace {

template <typename T>
T load_le(std::string_view bytes, std::size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

double component(std::string_view bytes, std::size_t at, std::uint64_t type) {
  switch (type) {
    case kUnsignedByte:
      return load_le<std::uint8_t>(bytes, at);
    case kUnsignedShort:
      return load_le<std::uint16_t>(bytes, at);
    case kUnsignedInt:
      return load_le<std::uint32_t>(bytes, at);
    default:
      return load_le<float>(bytes, at);
  }
}

}  // namespace

std::vector<Vec3> Document::read_vec3(std::size_t a, const std::string& where) {
  const Span s = accessor_span(a, "VEC3", where);
  if (s.element.component_type != kFloat)
    fail(where + ", accessor " + std::to_string(a), "positions must be floats");
  std::vector<Vec3> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const std::size_t at = i * s.stride;
    out[i] = {load_le<float>(s.bytes, at), load_le<float>(s.bytes, at + 4), load_le<float>(s.bytes, at + 8)};
  }
  return out;
}

std::vector<Vec2> Document::read_vec2(std::size_t a, const std::string& where) {
  const Span s = accessor_span(a, "VEC2", where);
  double scale = 1;
  if (s.element.component_type == kUnsignedByte)
    scale = 1.0 / 255;
  else if (s.element.component_type == kUnsignedShort)
    scale = 1.0 / 65535;
  else if (s.element.component_type != kFloat)
    fail(where + ", accessor " + std::to_string(a),
         "texture coordinates must be floats or normalised integers");
  std::vector<Vec2> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const std::size_t at = i * s.stride;
    const std::size_t step = s.element.component_bytes;
    out[i] = {scale * component(s.bytes, at, s.element.component_type),
              scale * component(s.bytes, at + step, s.element.component_type)};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
      fail(where + ", accessor " + std::to_string(a), "a texture coordinate is not a finite number");
  }
  return out;
}

std::vector<std::uint32_t> Document::read_indices(std::size_t a, const std::string& where) {
  const Span s = accessor_span(a, "SCALAR", where);
  const std::uint64_t t = s.element.component_type;
  if (t != kUnsignedByte && t != kUnsignedShort && t != kUnsignedInt)
    fail(where + ", accessor " + std::to_string(a), "indices must be unsigned integers");
  std::vector<std::uint32_t> out(s.count);
  for (std::size_t i = 0; i < s.count; ++i)
    out[i] = static_cast<std::uint32_t>(component(s.bytes, i * s.stride, t));
  return out;
}

}  // namespace foldkit::unfold::detail::gltf
