#pragma once
// Shared body of the simulated-device fuzz targets: the input is a byte stream sent to a SimulatedDevice
// of one protocol. The first byte picks the profile (among the built-in ones of that protocol), whether
// ESC 04 is required first, and where the stream is split into two writes (parsers must not care).
// A foldkit::Error is an accepted outcome; a crash, sanitizer report, hang or other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"

namespace foldkit::fuzz {

/// The built-in device profiles that speak `protocol`.
inline std::vector<devices::DeviceProfile> profiles_of(devices::Protocol protocol) {
  std::vector<devices::DeviceProfile> out;
  for (auto& d : devices::load_profiles(std::filesystem::path(FOLDKIT_SOURCE_DIR) / "profiles").devices)
    if (d.protocol == protocol) out.push_back(d);
  return out;
}

/// Sends `data` (control byte first) to a simulated device built from one of `profiles`.
inline int run_simulated_device(std::span<const devices::DeviceProfile> profiles, const std::uint8_t* data,
                                std::size_t size) {
  if (size == 0 || profiles.empty()) return 0;
  const std::uint8_t control = data[0];
  const auto bytes = std::span(reinterpret_cast<const std::byte*>(data) + 1, size - 1);
  devices::SimOptions options;
  options.require_initialize = (control & 0x80) != 0;
  devices::SimulatedDevice device(profiles[(control & 0x7f) % profiles.size()], options);
  const std::size_t split = bytes.empty() ? 0 : (control * 7u) % bytes.size();
  try {
    device.write(bytes.first(split));
    device.write(bytes.subspan(split));
    (void)device.status();
    device.close();
  } catch (const foldkit::Error&) {
  }
  return 0;
}

}  // namespace foldkit::fuzz
