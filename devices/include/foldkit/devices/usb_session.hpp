#pragma once
// How a job's bytes go over a cutter's two bulk pipes, independent of libusb: slices that end on a
// command (ETX), a GP-GL status poll between slices, chunked writes with timeouts and bounded retries.
// UsbTransport runs this over libusb; tests run it over a scripted fake device.
#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "foldkit/devices/transport.hpp"
#include "foldkit/devices/usb_errors.hpp"

namespace foldkit::devices {

/// Timeouts and sizes of a USB session. Defaults follow the open Silhouette tools
/// (docs/plotter-protocols.md section 1.2); every wait is bounded by one of them.
struct UsbOptions {
  std::size_t slice_bytes = 1024;                   ///< status is polled between slices of this size
  std::size_t chunk_bytes = 4096;                   ///< largest bulk write, rounded to the packet size
  std::chrono::milliseconds write_timeout{10000};   ///< per bulk write
  int write_retries = 5;                            ///< timed-out writes with no progress, per chunk
  std::chrono::milliseconds retry_pause{1000};      ///< between those retries
  std::chrono::milliseconds status_timeout{5000};   ///< for the reply to one status query
  std::chrono::milliseconds poll_interval{50};      ///< between status queries while the cutter moves
  std::chrono::milliseconds ready_timeout{120000};  ///< longest wait for "ready" between slices
  std::chrono::milliseconds drain_timeout{10};      ///< reading stray replies before a query
  bool gpgl_status = true;  ///< poll ESC 0x05 between slices (GP-GL); off for HP-GL cutters
};

/// The result of one bulk transfer: how many bytes moved and whether it ended early.
struct UsbTransfer {
  UsbFault fault = UsbFault::None;
  std::size_t bytes = 0;
};

/// A claimed interface's bulk OUT and IN endpoints.
class BulkPipes {
 public:
  virtual ~BulkPipes() = default;
  /// One bulk OUT transfer of up to bytes.size(); may move fewer bytes on timeout.
  virtual UsbTransfer write_some(std::span<const std::byte> bytes, std::chrono::milliseconds timeout) = 0;
  /// One bulk IN transfer into buffer (sized at least one IN packet).
  virtual UsbTransfer read_some(std::span<std::byte> buffer, std::chrono::milliseconds timeout) = 0;
  /// wMaxPacketSize of the OUT endpoint, from its descriptor.
  virtual std::size_t out_packet_bytes() const = 0;
  /// wMaxPacketSize of the IN endpoint, from its descriptor; 0 when there is none.
  virtual std::size_t in_packet_bytes() const = 0;
};

/// Writes, status queries and replies over BulkPipes. Throws DeviceError with a usb_fault_message.
class UsbSession {
 public:
  /// pipes must outlive the session; context names the device in every message.
  UsbSession(BulkPipes& pipes, UsbOptions options, UsbFaultContext context);

  /// Sends bytes in ETX-aligned slices; with gpgl_status, waits for "ready" before each slice (not
  /// before the first when status() has just answered Ready).
  void write(std::span<const std::byte> bytes);
  /// One ESC 0x05 query: Ready, Busy (moving), NoMedia or Paused; Unknown without an IN pipe.
  DeviceState status();
  /// Sends a command and returns the reply up to and including its terminator: ETX for GP-GL
  /// ("FG\x03" -> "CAMEO 3 V1.60    \x03"), CR for HP-GL ("OI;" -> "GX-24\r").
  std::vector<std::byte> query(std::span<const std::byte> command, std::chrono::milliseconds timeout);
  /// Bytes the device accepted since the session opened.
  std::size_t bytes_sent() const { return bytes_sent_; }
  /// The bulk write size used: chunk_bytes rounded down to a multiple of the OUT packet size.
  std::size_t chunk_bytes() const { return chunk_bytes_; }

 private:
  void send_chunk(std::span<const std::byte> chunk, bool job_bytes);
  void wait_until_ready();
  void drain();
  // Throws DeviceError naming the device, the operation and how far the current write got.
  [[noreturn]] void fail(UsbFault fault, const std::string& operation,
                         std::chrono::milliseconds waited = {}) const;

  BulkPipes& pipes_;
  UsbOptions options_;
  UsbFaultContext context_;
  std::size_t chunk_bytes_;
  std::size_t bytes_sent_ = 0;
  std::size_t job_sent_ = 0;   // of the write in progress, for messages
  std::size_t job_total_ = 0;  // 0 when no write is in progress
  bool known_ready_ = false;   // the last status query said Ready and nothing was sent since
};

}  // namespace foldkit::devices
