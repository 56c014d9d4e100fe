#pragma once
// Facts about USB cutting plotters that need no hardware: the known vendor/product ids, the GP-GL
// status reply, and how a byte stream is cut into slices that end on a command boundary.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "foldkit/devices/transport.hpp"

namespace foldkit::devices {

/// One USB model a cutter announces itself as.
struct UsbId {
  std::uint16_t vendor = 0;   ///< idVendor
  std::uint16_t product = 0;  ///< idProduct
  std::string model;          ///< human name, e.g. "Silhouette Cameo 3"
};

/// The ids of docs/plotter-protocols.md section 1.1 (same set as profiles/udev/60-foldkit-cutters.rules).
std::vector<UsbId> builtin_usb_ids();

/// Reads "0b4d:112f" or "0b4d:112f=My Cutter" (hex ids, optional model name), as given on a command
/// line for models newer than the table; nullopt when malformed or an id is 0 or beyond 16 bits.
std::optional<UsbId> parse_usb_id(std::string_view text);

/// The model name for an id in `known`, or nullopt.
std::optional<std::string> usb_model_name(std::span<const UsbId> known, std::uint16_t vendor,
                                          std::uint16_t product);

/// Whether a vendor makes cutters, so an unknown product of printer class is still worth listing.
bool is_cutter_vendor(std::uint16_t vendor);

/// Reads a GP-GL reply to ESC 0x05 ("0\x03" ready, "1\x03" moving, "2\x03" no media, "3\x03" paused).
DeviceState parse_gpgl_status(std::span<const std::byte> reply);

/// Splits a stream into slices of at most max_bytes, each ending just after an ETX (0x03) when one
/// lies inside the window, so a status poll never lands in the middle of a command.
std::vector<std::span<const std::byte>> slice_at_etx(std::span<const std::byte> bytes, std::size_t max_bytes);

}  // namespace foldkit::devices
