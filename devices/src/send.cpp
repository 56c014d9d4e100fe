#include "foldkit/devices/send.hpp"

#include <algorithm>
#include <string>
#include <thread>

#include "foldkit/devices/command_parser.hpp"
#include "foldkit/devices/gpgl.hpp"
#include "foldkit/devices/hpgl.hpp"
#include "foldkit/devices/job.hpp"
#include "foldkit/devices/usb_ids.hpp"
#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

enum class Query { None, Status, RegMarks, Other };

struct Command {
  std::size_t begin = 0, end = 0;
  Query query = Query::None;
  bool starts_stroke = false;
};

// The stream's command boundaries, which commands are queries, and where strokes start. Our own
// parsers are used, so a malformed stream fails here, before any byte leaves.
std::vector<Command> split(std::span<const std::byte> stream, Protocol protocol) {
  std::vector<ParsedCommand> parsed;
  if (protocol == Protocol::Gpgl) {
    GpglParser p;
    parsed = p.feed(stream);
    p.finish();
  } else {
    HpglParser p;
    parsed = p.feed(stream);
    p.finish();
  }
  std::vector<Command> out(parsed.size());
  for (std::size_t i = 0; i < parsed.size(); ++i) {
    const ParsedCommand& c = parsed[i];
    out[i].begin = i == 0 ? 0 : c.offset;
    out[i].end = i + 1 < parsed.size() ? parsed[i + 1].offset : stream.size();
    const std::string& n = c.name;
    if (n == "ESC05") {
      out[i].query = Query::Status;
    } else if (n == "TB" && !c.params.empty() && (c.params[0] == 123 || c.params[0] == 124)) {
      out[i].query = Query::RegMarks;
    } else if (n == "FG" || n == "FA" || n == "TC" || n == "[" || n == "U" || n == "ESC15" || n == "OI" ||
               n == "OS" || n == "OH" || (n == "TB" && !c.params.empty() && c.params[0] == 71)) {
      out[i].query = Query::Other;
    }
    out[i].starts_stroke = protocol == Protocol::Gpgl ? n == "D" && i > 0 && parsed[i - 1].name == "M"
                                                      : n == "PD" && !(i > 0 && parsed[i - 1].name == "PD");
  }
  return out;
}

bool cancelled(const SendOptions& o) {
  return o.cancel && o.cancel->load();
}

const char* state_name(DeviceState s) {
  switch (s) {
    case DeviceState::Busy:
      return "busy";
    case DeviceState::Paused:
      return "paused (not ready)";
    default:
      return "not ready";
  }
}

// Waits until the device can take more: bounded by ready_timeout, interruptible by cancel.
void wait_ready(Transport& t, DeviceState state, const SendOptions& o,
                const std::function<void(DeviceState)>& waiting) {
  const auto deadline = std::chrono::steady_clock::now() + o.ready_timeout;
  while (true) {
    if (state == DeviceState::NoMedia)
      throw DeviceError(t.describe() + ": no media loaded (load the mat or the paper and try again)");
    if (state == DeviceState::Error) throw DeviceError(t.describe() + ": the device reports an error");
    if (state == DeviceState::Ready || state == DeviceState::Unknown || cancelled(o)) return;
    if (std::chrono::steady_clock::now() >= deadline)
      throw DeviceError(t.describe() + ": device " + state_name(state) + " for more than " +
                        std::to_string(o.ready_timeout.count() / 1000.0).substr(0, 5) +
                        " s (press its pause key, check the cover and the media)");
    waiting(state);
    std::this_thread::sleep_for(o.poll_interval);
    state = t.status();
  }
}

std::string text(const std::vector<std::byte>& reply) {
  std::string s(reply.size(), ' ');
  std::transform(reply.begin(), reply.end(), s.begin(), [](std::byte b) { return static_cast<char>(b); });
  return s;
}

// Cutting after a mark search nobody can read would cut whether or not the marks were found.
void check_replies_readable(const std::vector<Command>& commands, const Transport& transport) {
  const bool searches = std::any_of(commands.begin(), commands.end(),
                                    [](const Command& c) { return c.query == Query::RegMarks; });
  if (searches && transport.drives_device() && !transport.reads_replies())
    throw DeviceError(transport.describe() +
                      ": print-and-cut needs the registration-mark search's reply, and this connection "
                      "cannot be read; nothing was sent (use the cutter's USB connection)");
}

// The registration-mark search's reply: "0" (blanks and ETX aside) is found, anything else is not.
void check_marks_found(const std::vector<std::byte>& reply, const Transport& transport) {
  std::string r = text(reply);
  r.erase(std::remove_if(r.begin(), r.end(), [](char ch) { return ch == ' ' || ch == '\x03'; }), r.end());
  if (r != "0")
    throw DeviceError(transport.describe() +
                      ": registration marks not found (check they are printed dark, the sheet is "
                      "aligned with the mat's corner and the marks lie inside the rollers' reach)");
}

// One send: the stream goes out in chunks of whole commands, queries one by one with their replies read.
class Sender {
 public:
  Sender(std::span<const std::byte> stream, Transport& transport, const SendOptions& options)
      : stream_(stream), transport_(transport), options_(options) {}

  SendResult run(const std::vector<Command>& commands) {
    for (const Command& c : commands)
      result_.strokes_total += c.starts_stroke ? 1 : 0;
    wait(transport_.status());
    for (const Command& c : commands) {
      if (cancelled(options_)) {
        flush(c.begin);
        return abort();
      }
      if (c.query != Query::None) {
        flush(c.begin);
        query(c);
        continue;
      }
      strokes_in_chunk_ += c.starts_stroke ? 1 : 0;
      set_up_ = true;
      if (c.end - chunk_begin_ >= options_.chunk_bytes) {
        flush(c.end);
        // Stop-and-wait between slices: a device that stops taking data is noticed within ready_timeout.
        wait(transport_.status());
      }
    }
    flush(stream_.size());
    return result_;
  }

 private:
  void report(DeviceState waiting_for) const {
    if (!options_.progress) return;
    SendProgress p;
    p.waiting_for = waiting_for;
    p.bytes_sent = result_.bytes_sent;
    p.bytes_total = stream_.size();
    p.strokes_done = result_.strokes_done;
    p.strokes_total = result_.strokes_total;
    const double left = result_.strokes_total == 0 ? 0.0
                                                   : 1.0 - static_cast<double>(result_.strokes_done) /
                                                               static_cast<double>(result_.strokes_total);
    p.seconds_left = options_.estimated_s * left;
    options_.progress(p);
  }

  void wait(DeviceState state) const {
    wait_ready(transport_, state, options_, [this](DeviceState s) { report(s); });
  }

  // The abort tail is only for a device that has been set up: one still in the handshake is left alone
  // (a strict device rejects end-of-job commands before its initialisation).
  SendResult abort() {
    result_.cancelled = true;
    if (!set_up_) return result_;
    const std::string tail = options_.abort_tail                   ? *options_.abort_tail
                             : options_.protocol == Protocol::Gpgl ? gpgl_abort_tail()
                                                                   : hpgl_abort_tail();
    transport_.write(stream_bytes(tail));
    return result_;
  }

  // Writes the commands from the chunk's start up to `end`.
  void flush(std::size_t end) {
    if (end <= chunk_begin_) return;
    transport_.write(stream_.subspan(chunk_begin_, end - chunk_begin_));
    result_.bytes_sent = end;
    result_.strokes_done += strokes_in_chunk_;
    strokes_in_chunk_ = 0;
    chunk_begin_ = end;
    report(DeviceState::Ready);
  }

  void query(const Command& c) {
    const auto timeout = c.query == Query::RegMarks ? options_.regmark_timeout
                         : c.query == Query::Status ? options_.reply_timeout
                                                    : options_.query_timeout;
    const auto reply = transport_.request(stream_.subspan(c.begin, c.end - c.begin), timeout);
    result_.bytes_sent = chunk_begin_ = c.end;
    if (reply && c.query == Query::Status) wait(parse_gpgl_status(*reply));
    if (!reply && c.query == Query::RegMarks && transport_.drives_device())
      throw DeviceError(transport_.describe() + ": no reply to the registration-mark search");
    if (reply && c.query == Query::RegMarks) check_marks_found(*reply, transport_);
  }

  std::span<const std::byte> stream_;
  Transport& transport_;
  const SendOptions& options_;
  SendResult result_;
  std::size_t chunk_begin_ = 0, strokes_in_chunk_ = 0;
  bool set_up_ = false;
};

}  // namespace

SendResult send_job(std::span<const std::byte> stream, Transport& transport, const SendOptions& options) {
  const std::vector<Command> commands = split(stream, options.protocol);
  check_replies_readable(commands, transport);
  return Sender(stream, transport, options).run(commands);
}

}  // namespace foldkit::devices
