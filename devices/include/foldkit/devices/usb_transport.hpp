#pragma once
// USB cutting plotters over libusb: finding them, and a Transport that sends a job to one. libusb stays
// inside devices/src; this header only speaks ids, options and DeviceError.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "foldkit/devices/transport.hpp"
#include "foldkit/devices/usb_ids.hpp"
#include "foldkit/devices/usb_session.hpp"

namespace foldkit::devices {

/// Whether the current user may open a device node.
enum class UsbAccess { Ok, PermissionDenied, Unknown };

/// A cutter seen on the bus. Devices of a cutter vendor that are not in the table have
/// known_model == false and id.model == "unknown model".
struct FoundDevice {
  UsbId id;
  bool known_model = false;
  std::uint8_t bus = 0;      ///< USB bus number
  std::uint8_t address = 0;  ///< device address on that bus
  UsbAccess access = UsbAccess::Unknown;
};

/// "Silhouette Cameo 3 (usb 003:017, 0b4d:112f)": how messages name a device.
std::string describe_usb_device(const FoundDevice& device);

/// Lists connected devices whose ids are in `known`, or whose vendor makes cutters, sorted by bus and
/// address. Tries to open each to report access. Throws DeviceError when USB cannot be scanned at all.
std::vector<FoundDevice> find_usb_cutters(std::span<const UsbId> known);

/// Which device to open: its ids, and bus/address when several of the same model are connected.
struct UsbSelector {
  UsbId id;
  std::optional<std::uint8_t> bus;
  std::optional<std::uint8_t> address;
};

/// A Transport to one cutter: kernel printer driver detached, interface 0 claimed, bulk endpoints and
/// packet sizes from the descriptors. Move-only; closing releases the interface and gives the device
/// back to the kernel driver.
class UsbTransport final : public Transport {
 public:
  struct Impl;
  explicit UsbTransport(std::unique_ptr<Impl> impl);
  UsbTransport(UsbTransport&&) noexcept;
  UsbTransport& operator=(UsbTransport&&) noexcept;
  UsbTransport(const UsbTransport&) = delete;
  UsbTransport& operator=(const UsbTransport&) = delete;
  ~UsbTransport() override;

  void write(std::span<const std::byte> bytes) override;
  DeviceState status() override;
  void close() override;
  std::string describe() const override;

  /// Sends a command and returns its reply up to and including its ETX (GP-GL) or CR (HP-GL); nullopt
  /// after just writing it when the device has no IN endpoint.
  bool reads_replies() const override { return true; }
  std::optional<std::vector<std::byte>> request(std::span<const std::byte> command,
                                                std::chrono::milliseconds timeout) override;
  /// wMaxPacketSize of the bulk OUT endpoint.
  std::size_t out_packet_bytes() const;
  /// wMaxPacketSize of the bulk IN endpoint; 0 when the device has none.
  std::size_t in_packet_bytes() const;
  /// Bytes the device accepted so far.
  std::size_t bytes_sent() const;

 private:
  std::unique_ptr<Impl> impl_;
};

/// Opens the cutter `selector` names. Throws DeviceError: not found, permission denied (with the udev
/// rule to install), busy, unplugged.
std::unique_ptr<UsbTransport> open_usb_cutter(const UsbSelector& selector, const UsbOptions& options = {});

}  // namespace foldkit::devices
