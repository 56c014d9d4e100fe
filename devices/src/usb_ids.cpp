#include "foldkit/devices/usb_ids.hpp"

#include <algorithm>
#include <cctype>

namespace foldkit::devices {

std::vector<UsbId> builtin_usb_ids() {
  return {
      {0x0b4d, 0x110a, "Graphtec Craft ROBO CC200-20"},
      {0x0b4d, 0x111a, "Graphtec Craft ROBO CC300-20"},
      {0x0b4d, 0x111c, "Silhouette SD 1"},
      {0x0b4d, 0x111d, "Silhouette SD 2"},
      {0x0b4d, 0x1121, "Silhouette Cameo"},
      {0x0b4d, 0x1122, "Graphtec CE6000-60"},
      {0x0b4d, 0x1123, "Silhouette Portrait"},
      {0x0b4d, 0x112b, "Silhouette Cameo 2"},
      {0x0b4d, 0x112c, "Silhouette Curio"},
      {0x0b4d, 0x112f, "Silhouette Cameo 3"},
      {0x0b4d, 0x1132, "Silhouette Portrait 2"},
      {0x0b4d, 0x1137, "Silhouette Cameo 4"},
      {0x0b4d, 0x1138, "Silhouette Cameo 4 Plus"},
      {0x0b4d, 0x1139, "Silhouette Cameo 4 Pro"},
      {0x0b4d, 0x113a, "Silhouette Portrait 3"},
      {0x0b4d, 0x113f, "Silhouette Portrait 4"},
      {0x0b4d, 0x1140, "Silhouette Cameo 5"},
      {0x0b4d, 0x1141, "Silhouette Cameo 5 Plus"},
      {0x0b4d, 0x1146, "Silhouette Cameo Pro MK II"},
      {0x3844, 0x0001, "Silhouette Cameo 5 Alpha"},
      {0x3844, 0x0002, "Silhouette Cameo 5 Alpha Plus"},
  };
}

bool is_cutter_vendor(std::uint16_t vendor) {
  // Roland DG publishes no per-model product ids, so its whole vendor id counts.
  return vendor == 0x0b4d || vendor == 0x3844 || vendor == 0x0b75;
}

namespace {
std::optional<std::uint16_t> parse_hex16(std::string_view text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  unsigned value = 0;
  for (char c : text) {
    if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = value * 16 + static_cast<unsigned>(std::isdigit(static_cast<unsigned char>(c))
                                                   ? c - '0'
                                                   : std::tolower(static_cast<unsigned char>(c)) - 'a' + 10);
  }
  if (value == 0) return std::nullopt;
  return static_cast<std::uint16_t>(value);
}
}  // namespace

std::optional<UsbId> parse_usb_id(std::string_view text) {
  const auto eq = text.find('=');
  const std::string_view ids = text.substr(0, eq);
  const auto colon = ids.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const auto vendor = parse_hex16(ids.substr(0, colon));
  const auto product = parse_hex16(ids.substr(colon + 1));
  if (!vendor || !product) return std::nullopt;
  std::string model = eq == std::string_view::npos ? std::string() : std::string(text.substr(eq + 1));
  if (eq != std::string_view::npos && model.empty()) return std::nullopt;
  if (model.empty()) model = "user-given " + std::string(ids);
  return UsbId{*vendor, *product, model};
}

std::optional<std::string> usb_model_name(std::span<const UsbId> known, std::uint16_t vendor,
                                          std::uint16_t product) {
  for (const auto& id : known)
    if (id.vendor == vendor && id.product == product) return id.model;
  return std::nullopt;
}

DeviceState parse_gpgl_status(std::span<const std::byte> reply) {
  // Replies may carry space padding before the digit; the ETX must be present or the reply is cut short.
  auto it = std::find_if(reply.begin(), reply.end(), [](std::byte b) { return b != std::byte{' '}; });
  if (it == reply.end() || std::next(it) == reply.end() || *std::next(it) != std::byte{0x03}) {
    return DeviceState::Unknown;
  }
  switch (static_cast<char>(*it)) {
    case '0':
      return DeviceState::Ready;
    case '1':
      return DeviceState::Busy;
    case '2':
      return DeviceState::NoMedia;
    case '3':
      return DeviceState::Paused;
    default:
      return DeviceState::Unknown;
  }
}

std::vector<std::span<const std::byte>> slice_at_etx(std::span<const std::byte> bytes,
                                                     std::size_t max_bytes) {
  std::vector<std::span<const std::byte>> slices;
  if (max_bytes == 0) max_bytes = 1;
  std::size_t start = 0;
  while (start < bytes.size()) {
    std::size_t len = std::min(max_bytes, bytes.size() - start);
    if (start + len < bytes.size()) {
      // Cut back to the last ETX in the window; a command longer than the window is sent whole-window.
      for (std::size_t i = len; i > 0; --i) {
        if (bytes[start + i - 1] == std::byte{0x03}) {
          len = i;
          break;
        }
      }
    }
    slices.push_back(bytes.subspan(start, len));
    start += len;
  }
  return slices;
}

}  // namespace foldkit::devices
