#pragma once
// Sending an encoded job through a Transport: command-aligned chunks, status polling with bounded waits,
// answers to the queries in the stream (status, registration-mark search), progress, and a clean stop
// on cancel (tool up, end of job).
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/transport.hpp"

namespace foldkit::devices {

/// Where a send stands.
struct SendProgress {
  std::size_t bytes_sent = 0, bytes_total = 0;
  std::size_t strokes_done = 0, strokes_total = 0;
  double seconds_left = 0;  ///< from the job's estimate, scaled by the strokes still to do
  /// Ready while bytes flow; Busy, Paused (or Unknown) while waiting for the device to take more.
  DeviceState waiting_for = DeviceState::Ready;
};

struct SendOptions {
  Protocol protocol = Protocol::Gpgl;
  std::size_t chunk_bytes = 1024;  ///< slices end on a command boundary; 1 KiB as Silhouette's tools use
  std::chrono::milliseconds poll_interval{50};
  std::chrono::milliseconds ready_timeout{120000};   ///< longest wait for a busy or paused device
  std::chrono::milliseconds reply_timeout{5000};     ///< longest wait for a status reply (ESC 05)
  std::chrono::milliseconds query_timeout{10000};    ///< FG, TB71, FA, TC: the reference allows 10 s
  std::chrono::milliseconds regmark_timeout{40000};  ///< the mark search moves the head: slower
  /// Sent after a cancel instead of the protocol's default tail (a Graphtec ends differently).
  std::optional<std::string> abort_tail;
  double estimated_s = 0;                             ///< the job's estimated duration
  std::function<void(const SendProgress&)> progress;  ///< called after every chunk
  const std::atomic<bool>* cancel = nullptr;          ///< set (e.g. from SIGINT) to stop cleanly
};

/// How a send ended (errors are DeviceError instead).
struct SendResult {
  bool cancelled = false;
  std::size_t bytes_sent = 0;
  std::size_t strokes_done = 0, strokes_total = 0;
};

/// Sends `stream` (an encode_gpgl / encode_hpgl result) to `transport`. Throws DeviceError for no
/// media, marks not found, a mark search through a transport that drives a device but cannot read its
/// reply (before the first byte), a device busy or paused past ready_timeout, a missing reply, or any
/// transport error. On cancel, sends the protocol's abort tail (tool up, end of job) and returns cancelled.
/// Does not close the transport.
SendResult send_job(std::span<const std::byte> stream, Transport& transport, const SendOptions& options);

}  // namespace foldkit::devices
