#pragma once
// Internal to unfold/: a glTF 2.0 document (.gltf JSON or .glb container) with its buffers, read
// defensively. Every index the document uses is checked before it is followed, every accessor against
// the bytes that back it, and every buffer against its source before a byte of it is held, so a hostile
// file ends in one InputError instead of a crash or an allocation sized by a number the file states.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "foldkit/geom/vec.hpp"

namespace foldkit::unfold::detail::gltf {

using Json = nlohmann::json;

/// What a document may cost to read.
struct Limits {
  std::uintmax_t max_file_bytes = 0;  ///< per buffer, external or embedded
  std::uint64_t max_elements = 0;     ///< accessor elements decoded in all, over every read
};

/// The parsed document and where its external files are looked up.
class Document {
 public:
  /// Parses `bytes` (GLB when they start with the `glTF` magic, JSON otherwise). External buffers and
  /// images are relative to `folder`. Throws InputError(name, ...).
  Document(const std::string& bytes, std::filesystem::path folder, std::string name, Limits limits);

  const Json& root() const { return root_; }
  const std::string& name() const { return name_; }
  const std::filesystem::path& folder() const { return folder_; }

  /// `object[key]` when it is there; throws when it is there with another JSON type than `type`.
  const Json* member(const Json& object, std::string_view key, Json::value_t type,
                     const std::string& where) const;
  /// The top-level array `key` (empty when absent); throws when it is not an array of objects.
  const Json& array(std::string_view key) const;
  /// `object[key]` as an index into the top-level array `into`; nullopt when absent; throws when it is
  /// not a whole number naming an element of `into`.
  std::optional<std::size_t> index(const Json& object, std::string_view key, std::string_view into,
                                   const std::string& where) const;
  /// `value` as an index into the top-level array `into`; throws otherwise.
  std::size_t as_index(const Json& value, std::string_view into, const std::string& where) const;
  /// A finite number array of exactly `n` elements at `object[key]`, or nullopt when absent.
  std::optional<std::vector<double>> numbers(const Json& object, std::string_view key, std::size_t n,
                                             const std::string& where) const;

  /// Accessor `a` as 3D float vectors (POSITION).
  std::vector<Vec3> read_vec3(std::size_t a, const std::string& where);
  /// Accessor `a` as 2D texture coordinates: float, or normalised unsigned byte/short.
  std::vector<Vec2> read_vec2(std::size_t a, const std::string& where);
  /// Accessor `a` as vertex indices (unsigned byte, short or int).
  std::vector<std::uint32_t> read_indices(std::size_t a, const std::string& where);
  /// The bytes of buffer view `v` (an embedded image).
  std::string_view view_bytes(std::size_t v, const std::string& where);

  /// An InputError naming the file, `where` in the document, and `problem`.
  [[noreturn]] void fail(const std::string& where, const std::string& problem) const;

 private:
  struct Element {
    std::size_t components;
    std::size_t component_bytes;
    std::uint64_t component_type;
  };
  /// The raw bytes of accessor `a` (checked against its view and buffer) and its layout.
  struct Span {
    std::string_view bytes;
    std::size_t count;
    std::size_t stride;
    Element element;
    bool normalized;
  };
  Span accessor_span(std::size_t a, std::string_view type, const std::string& where);
  const std::string& buffer(std::size_t b);
  std::string read_external(const std::string& uri, std::uint64_t length, const std::string& where) const;

  Json root_;
  Json empty_array_ = Json::array();
  std::filesystem::path folder_;
  std::string name_;
  Limits limits_;
  std::uint64_t elements_read_ = 0;
  std::optional<std::string> glb_binary_;
  std::vector<std::optional<std::string>> buffers_;
};

/// Text from the file made fit for a one-line message: control bytes replaced, length capped.
std::string printable(std::string_view text);

/// Decodes a `data:` URI's payload (base64 or percent-encoded); nullopt when `uri` is not a data URI.
/// Throws std::invalid_argument on malformed base64.
std::optional<std::string> decode_data_uri(std::string_view uri);

/// A relative URI reference as a file path: percent escapes decoded. Throws std::invalid_argument for
/// absolute paths, other schemes and malformed escapes.
std::filesystem::path uri_to_relative_path(std::string_view uri);

}  // namespace foldkit::unfold::detail::gltf
