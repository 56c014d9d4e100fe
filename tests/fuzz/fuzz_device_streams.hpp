#pragma once
// Shared body of fuzz_device_streams: arbitrary bytes into the GP-GL and HP-GL parsers and the simulated
// device. The only acceptable failure is a DeviceError; anything else (crash, hang, other exception) is a
// bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/error.hpp"

namespace foldkit::fuzz::streams {

// A two-holder device built in code so the fuzzer reads no files.
inline foldkit::devices::DeviceProfile device(foldkit::devices::Protocol protocol) {
  using namespace foldkit::devices;
  DeviceProfile d;
  d.id = "fuzz";
  d.name = "fuzz";
  d.protocol = protocol;
  d.units_per_mm = protocol == Protocol::Gpgl ? 20 : 40;
  d.area_width_mm = 100;
  d.area_max_length_mm = 100;
  d.holders = 2;
  d.tools = {{"blade", ToolKind::Blade, 1, 18}, {"pen", ToolKind::Pen, 2, 0}};
  d.speed_steps = {1, 10};
  d.force_steps = {1, 33};
  d.regmarks.supported = true;
  return d;
}

template <typename Parser>
void parse_split(std::span<const std::byte> bytes) {
  Parser p;
  try {
    const std::size_t cut = bytes.empty() ? 0 : static_cast<std::size_t>(bytes[0]) % bytes.size();
    (void)p.feed(bytes.first(cut));
    (void)p.feed(bytes.subspan(cut));
    p.finish();
  } catch (const foldkit::DeviceError&) {
  }
}

inline void simulate(foldkit::devices::Protocol protocol, std::span<const std::byte> bytes) {
  foldkit::devices::SimOptions o;
  o.require_initialize = false;  // reach the geometry checks with fewer bytes
  foldkit::devices::SimulatedDevice dev(device(protocol), o);
  try {
    dev.write(bytes);
    (void)dev.status();
    dev.close();
  } catch (const foldkit::DeviceError&) {
  }
}

}  // namespace foldkit::fuzz::streams

namespace foldkit::fuzz {

/// Feeds `data` to both parsers (split in two) and to a simulated device of each protocol.
inline int run_device_streams(const std::uint8_t* data, std::size_t size) {
  const auto bytes = std::as_bytes(std::span<const std::uint8_t>(data, size));
  streams::parse_split<devices::GpglParser>(bytes);
  streams::parse_split<devices::HpglParser>(bytes);
  streams::simulate(devices::Protocol::Gpgl, bytes);
  streams::simulate(devices::Protocol::Hpgl, bytes);
  return 0;
}

}  // namespace foldkit::fuzz
