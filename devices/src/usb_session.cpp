#include "foldkit/devices/usb_session.hpp"

#include <algorithm>
#include <thread>

#include "foldkit/devices/usb_ids.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// GP-GL replies end with ETX, HP-GL replies (OH, OI, OS) with CR; neither occurs inside a reply.
constexpr std::byte kEtx{0x03};
constexpr std::byte kCr{0x0d};
constexpr std::byte kStatusQuery[] = {std::byte{0x1b}, std::byte{0x05}};
// Replies are a few dozen bytes (status, "FG" model name, coordinates); more means a confused device.
constexpr std::size_t kMaxReplyBytes = 4096;
// A garbled status reply can be line noise once; three in a row means the device does not speak GP-GL.
constexpr int kMaxUnreadableStatus = 3;
// Stray replies left in the IN pipe are read and dropped before a query, at most this many packets.
constexpr int kMaxDrainReads = 8;

milliseconds since(Clock::time_point start) {
  return std::chrono::duration_cast<milliseconds>(Clock::now() - start);
}

}  // namespace

UsbSession::UsbSession(BulkPipes& pipes, UsbOptions options, UsbFaultContext context)
    : pipes_(pipes), options_(options), context_(std::move(context)) {
  const std::size_t packet = std::max<std::size_t>(1, pipes_.out_packet_bytes());
  // Whole packets per transfer: a short packet would end the transfer early on some devices.
  chunk_bytes_ = std::max(packet, options_.chunk_bytes / packet * packet);
  if (options_.slice_bytes == 0) options_.slice_bytes = chunk_bytes_;
  if (options_.write_retries < 0) options_.write_retries = 0;
}

void UsbSession::fail(UsbFault fault, const std::string& operation, milliseconds waited) const {
  UsbFaultContext c = context_;
  c.operation = operation;
  c.bytes_sent = job_sent_;
  c.bytes_total = job_total_;
  c.waited = waited;
  throw DeviceError(usb_fault_message(fault, c));
}

void UsbSession::write(std::span<const std::byte> bytes) {
  job_total_ = bytes.size();
  job_sent_ = 0;
  // Progress belongs in messages only while this write runs, also when it throws.
  struct EndOfJob {
    UsbSession& s;
    ~EndOfJob() { s.job_total_ = s.job_sent_ = 0; }
  } end_of_job{*this};
  const bool pace = options_.gpgl_status && pipes_.in_packet_bytes() > 0;
  const auto slices =
      pace ? slice_at_etx(bytes, options_.slice_bytes) : std::vector<std::span<const std::byte>>{bytes};
  for (const auto& slice : slices) {
    // A caller that just asked (send_job polls between its own slices) is not asked again.
    if (pace && !known_ready_) wait_until_ready();
    known_ready_ = false;
    for (std::size_t at = 0; at < slice.size(); at += chunk_bytes_) {
      send_chunk(slice.subspan(at, std::min(chunk_bytes_, slice.size() - at)), true);
    }
  }
}

void UsbSession::send_chunk(std::span<const std::byte> chunk, bool job_bytes) {
  std::size_t at = 0;
  int idle_attempts = 0;
  while (at < chunk.size()) {
    const UsbTransfer r = pipes_.write_some(chunk.subspan(at), options_.write_timeout);
    const std::size_t moved = std::min(r.bytes, chunk.size() - at);
    at += moved;
    if (job_bytes) {
      job_sent_ += moved;
      bytes_sent_ += moved;
    }
    const bool retryable =
        r.fault == UsbFault::None || r.fault == UsbFault::Timeout || r.fault == UsbFault::Interrupted;
    if (!retryable) fail(r.fault, "writing");
    if (moved > 0) {
      idle_attempts = 0;  // progress: the device is draining its buffer, keep going
      continue;
    }
    // No byte taken: the cutter's buffer is full while it moves. Wait a bounded number of times.
    if (++idle_attempts > options_.write_retries) {
      fail(UsbFault::Timeout, "writing", options_.write_timeout * idle_attempts);
    }
    std::this_thread::sleep_for(options_.retry_pause);
  }
}

void UsbSession::wait_until_ready() {
  const auto start = Clock::now();
  int unreadable = 0;
  for (;;) {
    const DeviceState state = status();
    switch (state) {
      case DeviceState::Ready:
        return;
      case DeviceState::NoMedia:
        fail(UsbFault::NoMedia, "waiting for ready");
      case DeviceState::Unknown:
      case DeviceState::Error:
        if (++unreadable >= kMaxUnreadableStatus) fail(UsbFault::NoReply, "reading status");
        break;
      case DeviceState::Busy:
      case DeviceState::Paused:
        unreadable = 0;
        break;
    }
    if (since(start) >= options_.ready_timeout) {
      fail(state == DeviceState::Paused ? UsbFault::Paused : UsbFault::Timeout,
           "waiting for the cutter to finish moving", options_.ready_timeout);
    }
    std::this_thread::sleep_for(options_.poll_interval);
  }
}

void UsbSession::drain() {
  std::vector<std::byte> buffer(std::max<std::size_t>(64, pipes_.in_packet_bytes()));
  for (int i = 0; i < kMaxDrainReads; ++i) {
    const UsbTransfer r = pipes_.read_some(buffer, options_.drain_timeout);
    if (r.fault == UsbFault::Unplugged) fail(r.fault, "reading");
    if (r.fault != UsbFault::None || r.bytes == 0) return;
  }
}

DeviceState UsbSession::status() {
  if (pipes_.in_packet_bytes() == 0) return DeviceState::Unknown;
  const auto reply = query(kStatusQuery, options_.status_timeout);
  const DeviceState state = parse_gpgl_status(reply);
  known_ready_ = state == DeviceState::Ready;
  return state;
}

std::vector<std::byte> UsbSession::query(std::span<const std::byte> command, milliseconds timeout) {
  if (pipes_.in_packet_bytes() == 0) fail(UsbFault::Unsupported, "reading (no IN endpoint)");
  known_ready_ = false;  // a query may move the head (registration-mark search)
  drain();
  send_chunk(command, false);
  std::vector<std::byte> reply;
  std::vector<std::byte> buffer(std::max<std::size_t>(64, pipes_.in_packet_bytes()));
  const auto start = Clock::now();
  for (;;) {
    const milliseconds left = timeout - since(start);
    if (left <= milliseconds{0}) fail(UsbFault::Timeout, "waiting for a reply", timeout);
    const UsbTransfer r = pipes_.read_some(buffer, left);
    if (r.fault == UsbFault::Timeout) fail(UsbFault::Timeout, "waiting for a reply", timeout);
    if (r.fault != UsbFault::None && r.fault != UsbFault::Interrupted) fail(r.fault, "reading a reply");
    const auto got = std::span<const std::byte>(buffer).first(std::min(r.bytes, buffer.size()));
    reply.insert(reply.end(), got.begin(), got.end());
    const auto etx =
        std::find_if(reply.begin(), reply.end(), [](std::byte b) { return b == kEtx || b == kCr; });
    if (etx != reply.end()) {
      reply.erase(std::next(etx), reply.end());
      return reply;
    }
    if (reply.size() > kMaxReplyBytes) fail(UsbFault::Overflow, "reading a reply");
    // An empty successful read returns at once on some stacks; do not spin on it.
    if (r.bytes == 0) std::this_thread::sleep_for(milliseconds{1});
  }
}

}  // namespace foldkit::devices
