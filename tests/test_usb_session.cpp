// The USB send loop over a scripted cutter: slicing, packet-sized chunks, status pacing, retries and
// every fault a user can meet mid-job, all bounded in time.
#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "device_fixtures.hpp"
#include "foldkit/devices/usb_ids.hpp"
#include "foldkit/devices/usb_session.hpp"
#include "foldkit/error.hpp"

using namespace foldkit::devices;
using namespace std::chrono_literals;

namespace {

using foldkit::test::bytes_of;
std::string text_of(std::span<const std::byte> b) {
  std::string s;
  for (auto c : b)
    s += static_cast<char>(c);
  return s;
}

// A cutter as seen through its two bulk pipes: answers ESC 0x05 from a script, keeps the job bytes.
struct FakeCutter : BulkPipes {
  std::size_t out_packet = 64, in_packet = 64;
  std::deque<std::string> status_script;  // replies to ESC 0x05, in order; "0\x03" once it runs out
  std::string pending_reply;              // what the IN pipe returns next
  std::size_t reply_piece = 64;           // at most this many reply bytes per IN transfer
  std::string received;                   // job bytes, status queries excluded
  std::vector<std::size_t> write_sizes;   // sizes of the job writes
  int status_queries = 0;
  std::size_t unplug_after = SIZE_MAX;  // job bytes accepted before the cable is pulled
  std::size_t accept_per_write = SIZE_MAX;
  int stall_writes = 0;  // this many writes take nothing and time out
  int write_calls = 0;

  UsbTransfer write_some(std::span<const std::byte> bytes, std::chrono::milliseconds) override {
    ++write_calls;
    if (received.size() >= unplug_after) return {UsbFault::Unplugged, 0};
    if (stall_writes > 0) {
      --stall_writes;
      return {UsbFault::Timeout, 0};
    }
    const std::string data = text_of(bytes);
    if (data == "\x1b\x05") {
      ++status_queries;
      pending_reply = status_script.empty() ? std::string("0\x03") : status_script.front();
      if (!status_script.empty()) status_script.pop_front();
      return {UsbFault::None, 2};
    }
    if (data == "FG\x03") {
      pending_reply = "CAMEO 3 V1.60    \x03";
      return {UsbFault::None, 3};
    }
    write_sizes.push_back(bytes.size());
    std::size_t n = std::min({bytes.size(), accept_per_write, unplug_after - received.size()});
    received += data.substr(0, n);
    if (n < bytes.size()) return {n == 0 ? UsbFault::Unplugged : UsbFault::Timeout, n};
    return {UsbFault::None, n};
  }
  UsbTransfer read_some(std::span<std::byte> buffer, std::chrono::milliseconds) override {
    if (pending_reply.empty()) return {UsbFault::Timeout, 0};
    const std::size_t n = std::min({buffer.size(), reply_piece, pending_reply.size()});
    for (std::size_t i = 0; i < n; ++i)
      buffer[i] = static_cast<std::byte>(pending_reply[i]);
    pending_reply.erase(0, n);
    return {UsbFault::None, n};
  }
  std::size_t out_packet_bytes() const override { return out_packet; }
  std::size_t in_packet_bytes() const override { return in_packet; }
};

UsbOptions fast() {
  UsbOptions o;
  o.write_timeout = 5ms;
  o.retry_pause = 1ms;
  o.status_timeout = 20ms;
  o.poll_interval = 1ms;
  o.ready_timeout = 200ms;
  o.drain_timeout = 1ms;
  return o;
}

UsbFaultContext cameo3() {
  UsbFaultContext c;
  c.device = "Silhouette Cameo 3 (usb 003:017, 0b4d:112f)";
  c.vendor = 0x0b4d;
  c.product = 0x112f;
  return c;
}

std::string gpgl_job(int moves) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on chains of operator+ with to_string.
  std::string job = "\x1b\x04TG1\x03";
  for (int i = 0; i < moves; ++i) {
    job.append("D").append(std::to_string(i * 10)).append(",").append(std::to_string(i * 7)).append("\x03");
  }
  return job.append("H\x03");
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const foldkit::DeviceError& e) {
    return e.what();
  }
  return "(no DeviceError)";
}

}  // namespace

TEST(UsbSession, TheWholeJobArrivesInOrderWithAStatusPollBeforeEachEtxAlignedSlice) {
  FakeCutter cutter;
  auto o = fast();
  o.slice_bytes = 100;
  UsbSession session(cutter, o, cameo3());
  const std::string job = gpgl_job(200);
  session.write(bytes_of(job));
  EXPECT_EQ(cutter.received, job);
  EXPECT_EQ(session.bytes_sent(), job.size());
  const auto slices = slice_at_etx(bytes_of(job), 100);
  EXPECT_EQ(cutter.status_queries, static_cast<int>(slices.size()));
  for (std::size_t i = 0; i < slices.size(); ++i)
    EXPECT_EQ(cutter.write_sizes[i], slices[i].size()) << i;
}

TEST(UsbSession, BulkWritesAreWholePacketsOfTheEndpointNotAnAssumed64Bytes) {
  for (std::size_t packet : {8u, 60u, 64u, 512u}) {
    FakeCutter cutter;
    cutter.out_packet = packet;
    auto o = fast();
    o.gpgl_status = false;  // one slice: only the chunking shows
    o.chunk_bytes = 1000;
    UsbSession session(cutter, o, cameo3());
    // The largest whole number of packets within the asked 1000 bytes, or one packet when it is larger.
    const std::size_t chunk = session.chunk_bytes();
    EXPECT_EQ(chunk % packet, 0u) << "packet " << packet;
    EXPECT_GE(chunk, packet) << "packet " << packet;
    EXPECT_TRUE(chunk <= 1000 || chunk == packet) << "packet " << packet << ": chunk " << chunk;
    EXPECT_GT(chunk + packet, 1000u) << "packet " << packet << ": room for one more packet";
    const std::string job = gpgl_job(300);
    session.write(bytes_of(job));
    EXPECT_EQ(cutter.received, job);
    for (std::size_t i = 0; i + 1 < cutter.write_sizes.size(); ++i) {
      EXPECT_EQ(cutter.write_sizes[i] % packet, 0u) << "packet " << packet;
      EXPECT_LE(cutter.write_sizes[i], session.chunk_bytes());
    }
    EXPECT_EQ(cutter.status_queries, 0);
  }
}

TEST(UsbSession, AMovingCutterIsWaitedForUntilItIsReady) {
  FakeCutter cutter;
  cutter.status_script = {"1\x03", "1\x03", "    1\x03", "0\x03"};
  UsbSession session(cutter, fast(), cameo3());
  session.write(bytes_of(gpgl_job(3)));
  EXPECT_EQ(cutter.received, gpgl_job(3));
  EXPECT_EQ(cutter.status_queries, 4);
}

TEST(UsbSession, NoMediaStopsTheJobBeforeAnyByteIsSent) {
  FakeCutter cutter;
  cutter.status_script = {"2\x03"};
  UsbSession session(cutter, fast(), cameo3());
  const std::string m = message_of([&] { session.write(bytes_of(gpgl_job(3))); });
  EXPECT_NE(m.find("no media loaded"), std::string::npos) << m;
  EXPECT_TRUE(cutter.received.empty());
}

TEST(UsbSession, UnplugMidJobEndsWithAMessageSayingHowFarItGot) {
  FakeCutter cutter;
  cutter.unplug_after = 100;
  auto o = fast();
  o.slice_bytes = 64;
  UsbSession session(cutter, o, cameo3());
  const std::string job = gpgl_job(100);
  const std::string m = message_of([&] { session.write(bytes_of(job)); });
  EXPECT_NE(m.find("unplugged"), std::string::npos) << m;
  EXPECT_NE(m.find(" of " + std::to_string(job.size()) + " bytes"), std::string::npos) << m;
  EXPECT_LE(session.bytes_sent(), 100u);
}

TEST(UsbSession, AStalledCutterTimesOutAfterABoundedNumberOfRetries) {
  FakeCutter cutter;
  cutter.stall_writes = 1000;
  auto o = fast();
  o.gpgl_status = false;
  o.write_retries = 3;
  UsbSession session(cutter, o, cameo3());
  const auto start = std::chrono::steady_clock::now();
  const std::string m = message_of([&] { session.write(bytes_of(gpgl_job(3))); });
  EXPECT_NE(m.find("did not respond"), std::string::npos) << m;
  EXPECT_EQ(cutter.write_calls, 4);  // the first try and three retries
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(UsbSession, ATimeoutThatStillMovedBytesIsResumedWhereItStopped) {
  FakeCutter cutter;
  cutter.accept_per_write = 5;
  auto o = fast();
  o.write_retries = 0;  // progress never counts as a retry
  UsbSession session(cutter, o, cameo3());
  const std::string job = gpgl_job(20);
  session.write(bytes_of(job));
  EXPECT_EQ(cutter.received, job);
}

TEST(UsbSession, ACutterThatNeverBecomesReadyTimesOutInsteadOfHanging) {
  FakeCutter cutter;
  cutter.status_script = std::deque<std::string>(100000, "1\x03");
  auto o = fast();
  o.ready_timeout = 50ms;
  UsbSession session(cutter, o, cameo3());
  const auto start = std::chrono::steady_clock::now();
  const std::string m = message_of([&] { session.write(bytes_of(gpgl_job(3))); });
  EXPECT_NE(m.find("did not respond within 0.05 s while waiting for the cutter to finish moving"),
            std::string::npos)
      << m;
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
}

TEST(UsbSession, APausedCutterIsReportedAsPaused) {
  FakeCutter cutter;
  cutter.status_script = std::deque<std::string>(100000, "3\x03");
  auto o = fast();
  o.ready_timeout = 20ms;
  UsbSession session(cutter, o, cameo3());
  const std::string m = message_of([&] { session.write(bytes_of(gpgl_job(3))); });
  EXPECT_NE(m.find("paused"), std::string::npos) << m;
}

TEST(UsbSession, GarbledStatusRepliesEndTheJobWithNoReply) {
  FakeCutter cutter;
  cutter.status_script = {"x\x03", "?\x03", "9\x03"};
  UsbSession session(cutter, fast(), cameo3());
  const std::string m = message_of([&] { session.write(bytes_of(gpgl_job(3))); });
  EXPECT_NE(m.find("no readable status reply"), std::string::npos) << m;
}

TEST(UsbSession, ASilentCutterTimesOutOnTheStatusQuery) {
  struct Silent final : FakeCutter {
    UsbTransfer read_some(std::span<std::byte>, std::chrono::milliseconds) override {
      return {UsbFault::Timeout, 0};
    }
  } cutter;
  UsbSession session(cutter, fast(), cameo3());
  const std::string m = message_of([&] { session.status(); });
  EXPECT_NE(m.find("did not respond within 0.02 s while waiting for a reply"), std::string::npos) << m;
}

TEST(UsbSession, AStatusJustReadAsReadyIsNotAskedAgainBeforeTheFirstSlice) {
  FakeCutter cutter;
  UsbSession session(cutter, fast(), cameo3());
  EXPECT_EQ(session.status(), DeviceState::Ready);
  session.write(bytes_of(gpgl_job(2)));
  EXPECT_EQ(cutter.status_queries, 1);
  session.write(bytes_of(gpgl_job(2)));  // bytes were sent since: ask again
  EXPECT_EQ(cutter.status_queries, 2);
}

TEST(UsbSession, HpglRepliesEndAtTheirCarriageReturn) {
  struct Roland final : FakeCutter {
    UsbTransfer write_some(std::span<const std::byte> bytes, std::chrono::milliseconds t) override {
      if (text_of(bytes) == "OI;") {
        pending_reply = "GX-24\r";
        return {UsbFault::None, 3};
      }
      return FakeCutter::write_some(bytes, t);
    }
  } cutter;
  UsbSession session(cutter, fast(), cameo3());
  EXPECT_EQ(text_of(session.query(bytes_of("OI;"), 100ms)), "GX-24\r");
}

TEST(UsbSession, HpglCuttersGetNoStatusQueries) {
  FakeCutter cutter;
  auto o = fast();
  o.gpgl_status = false;
  UsbSession session(cutter, o, cameo3());
  session.write(bytes_of("IN;SP1;PU0,0;PD100,100;PU;IN;"));
  EXPECT_EQ(cutter.status_queries, 0);
  EXPECT_EQ(cutter.received, "IN;SP1;PU0,0;PD100,100;PU;IN;");
}

TEST(UsbSession, AReplySplitOverSeveralPacketsIsJoinedUpToItsEtx) {
  FakeCutter cutter;
  cutter.reply_piece = 4;
  UsbSession session(cutter, fast(), cameo3());
  EXPECT_EQ(text_of(session.query(bytes_of("FG\x03"), 100ms)), "CAMEO 3 V1.60    \x03");
  EXPECT_EQ(session.status(), DeviceState::Ready);
}

TEST(UsbSession, StrayRepliesAreDroppedBeforeAQuery) {
  FakeCutter cutter;
  cutter.pending_reply = "1\x03";  // left over from an earlier query
  UsbSession session(cutter, fast(), cameo3());
  cutter.status_script = {"0\x03"};
  EXPECT_EQ(session.status(), DeviceState::Ready);
}

TEST(UsbSession, ADeviceWithoutAnInEndpointHasUnknownStatusAndIsNotPaced) {
  FakeCutter cutter;
  cutter.in_packet = 0;
  UsbSession session(cutter, fast(), cameo3());
  EXPECT_EQ(session.status(), DeviceState::Unknown);
  session.write(bytes_of(gpgl_job(5)));
  EXPECT_EQ(cutter.status_queries, 0);
  EXPECT_EQ(cutter.received, gpgl_job(5));
}
