#pragma once
// Where a job's bytes go: a USB cutter, a file or device node, or the simulated device.
#include <chrono>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace foldkit::devices {

/// What a device says about itself between writes.
enum class DeviceState { Ready, Busy, Paused, NoMedia, Error, Unknown };

/// A byte sink with a status query. Implementations throw DeviceError with a one-line message
/// (permission denied, busy, no media, timeout, unplugged) and never hang: every wait is bounded.
class Transport {
 public:
  virtual ~Transport() = default;
  /// Sends all bytes (blocking, bounded by the transport's timeouts).
  virtual void write(std::span<const std::byte> bytes) = 0;
  /// Asks the device for its state; Unknown when the transport cannot ask (plain files).
  virtual DeviceState status() = 0;
  /// Flushes and releases the device or file. Safe to call twice.
  virtual void close() = 0;
  /// Sends `command` and returns the device's reply (up to and including its terminator), or nullopt
  /// when this transport cannot read replies (files, device nodes). Throws DeviceError when no reply
  /// arrives within `timeout`. The default just writes.
  virtual std::optional<std::vector<std::byte>> request(std::span<const std::byte> command,
                                                        std::chrono::milliseconds timeout) {
    (void)timeout;
    write(command);
    return std::nullopt;
  }
  /// Whether request() can return replies (a USB cutter, a readable device node, the simulated device).
  virtual bool reads_replies() const { return false; }
  /// Whether bytes sent here drive a machine now (false for a plain file, written for later).
  virtual bool drives_device() const { return true; }
  /// A short description for messages, e.g. "usb 0b4d:1137 (Silhouette Cameo 4)" or "file job.gpgl".
  virtual std::string describe() const = 0;
};

}  // namespace foldkit::devices
