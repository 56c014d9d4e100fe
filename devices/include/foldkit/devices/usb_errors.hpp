#pragma once
// What can go wrong talking to a USB cutter, and the one-line message a user gets for each. Pure: no
// libusb in this header, so the mapping is tested without hardware.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

namespace foldkit::devices {

/// The outcome of one USB operation, as foldkit distinguishes them for messages.
enum class UsbFault {
  None,              ///< success
  PermissionDenied,  ///< no access to the device node (udev rule missing)
  Busy,              ///< another program or a kernel driver holds the interface
  NotFound,          ///< no device with the requested ids is connected
  Unplugged,         ///< the device went away (unplugged, switched off)
  Timeout,           ///< the device did not take or give data in time
  Stall,             ///< an endpoint halted (the cutter rejected a transfer)
  Overflow,          ///< the device sent more than asked for
  Interrupted,       ///< a system call was interrupted (a signal); safe to retry
  Unsupported,       ///< the platform or device cannot do what was asked
  NoMedia,           ///< the cutter reports no mat or paper loaded
  Paused,            ///< the cutter is paused from its panel
  NoReply,           ///< the status reply was missing or unreadable
  Io,                ///< any other input/output error
};

/// Maps a libusb return code (LIBUSB_SUCCESS, LIBUSB_ERROR_*) to a fault; unknown codes become Io.
UsbFault usb_fault_from_libusb(int libusb_code);

/// Which device and operation a message is about, and how far a job got.
struct UsbFaultContext {
  std::string device;           ///< e.g. "Silhouette Cameo 3 (usb 003:017, 0b4d:112f)"
  std::uint16_t vendor = 0;     ///< for the udev rule line
  std::uint16_t product = 0;    ///< for the udev rule line
  std::string operation;        ///< e.g. "opening", "claiming interface 0", "writing", "reading status"
  std::size_t bytes_sent = 0;   ///< bytes of the current write already accepted by the device
  std::size_t bytes_total = 0;  ///< size of the current write; 0 when not writing
  std::chrono::milliseconds waited{0};  ///< how long we waited before giving up (Timeout, Busy moving)
};

/// The udev rule that gives the logged-in user and plugdev access to one cutter, as one line.
std::string udev_rule_line(std::uint16_t vendor, std::uint16_t product);

/// The file name of the udev rules foldkit ships (under profiles/udev/ in the source tree).
inline constexpr const char* kUdevRulesFile = "60-foldkit-cutters.rules";

/// One line a user can act on: what happened, to which device, and what to do about it.
std::string usb_fault_message(UsbFault fault, const UsbFaultContext& context);

}  // namespace foldkit::devices
