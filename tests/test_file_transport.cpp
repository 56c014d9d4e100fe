// FileTransport: regular files atomically, device nodes (a FIFO stands in for /dev/usb/lp0) directly,
// with bounded waits.
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "foldkit/devices/file_transport.hpp"
#include "foldkit/devices/job.hpp"
#include "foldkit/devices/send.hpp"
#include "foldkit/error.hpp"
#include "test_paths.hpp"

namespace foldkit::devices {
namespace {

using foldkit::test::slurp;

TEST(FileTransport, WritesARegularFileOnlyWhenClosed) {
  const auto path = test::temp_dir("ft") / "job.gpgl";
  FileTransport t(path);
  EXPECT_FALSE(t.is_device_node());
  t.write(stream_bytes("M0,0\x03"));
  t.write(stream_bytes("D10,10\x03"));
  EXPECT_FALSE(std::filesystem::exists(path));
  t.close();
  t.close();  // twice is fine
  EXPECT_EQ(slurp(path), std::string("M0,0\x03"
                                     "D10,10\x03"));
  EXPECT_EQ(t.status(), DeviceState::Unknown);
}

TEST(FileTransport, LeavesNothingBehindWhenAJobFailsBeforeClose) {
  const auto dir = test::temp_dir("ft-fail");
  {
    FileTransport t(dir / "job.plt");
    t.write(stream_bytes("IN;PD"));
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(FileTransport, RefusesADirectory) {
  EXPECT_THROW(FileTransport(test::temp_dir("ft-dir")), OutputError);
}

TEST(FileTransport, StreamsToADeviceNodeAsItComes) {
  const auto fifo = test::temp_dir("ft-fifo") / "lp0";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    received = s.str();
  });
  // The reader opens the FIFO in its own time; opening for writing before it does is ENXIO.
  std::unique_ptr<FileTransport> t;
  for (int i = 0; i < 200 && !t; ++i) {
    try {
      t = std::make_unique<FileTransport>(fifo);
    } catch (const DeviceError&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  ASSERT_TRUE(t);
  EXPECT_TRUE(t->is_device_node());
  t->write(stream_bytes("IN;PU0,0;"));
  t->close();
  reader.join();
  EXPECT_EQ(received, "IN;PU0,0;");
}

TEST(FileTransport, SaysSoWhenNoDeviceListensOnTheNode) {
  const auto fifo = test::temp_dir("ft-noreader") / "lp0";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    FileTransport t(fifo);
    FAIL() << "opened a FIFO with no reader";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("no device is listening"), std::string::npos) << e.what();
  }
}

TEST(FileTransport, GivesUpOnANodeThatTakesNoDataWithinTheTimeout) {
  const auto fifo = test::temp_dir("ft-stall") / "lp0";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader that never reads: the pipe fills and the device "stalls".
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  FileTransport t(fifo, std::chrono::milliseconds(100));
  const std::string big(1 << 20, 'x');
  const auto start = std::chrono::steady_clock::now();
  try {
    t.write(stream_bytes(big));
    FAIL() << "a stalled node took 1 MiB";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("took no data"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  ::close(reader);
}

TEST(FileTransport, WritesToACharacterDevice) {
  FileTransport t("/dev/null");
  EXPECT_TRUE(t.is_device_node());
  t.write(stream_bytes("IN;"));
  t.close();
  EXPECT_EQ(t.describe(), "device node /dev/null");
}

TEST(FileTransport, RefusesPrintAndCutThroughANodeItCannotReadBeforeSendingAnything) {
  // A FIFO is written one way only: the mark search's reply could never be read, so the blade would cut
  // whether the marks were found or not.
  const auto fifo = test::temp_dir("ft-regmarks") / "lp0";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  FileTransport t(fifo);
  EXPECT_TRUE(t.drives_device());
  EXPECT_FALSE(t.reads_replies());
  const std::string stream =
      "\x1b\x04TB99\x03TB123,100,100,0,0\x03M0,0\x03"
      "D10,10\x03";
  SendOptions o;
  o.poll_interval = std::chrono::milliseconds(1);
  try {
    send_job(stream_bytes(stream), t, o);
    FAIL() << "print-and-cut went to a node that cannot be read";
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("print-and-cut needs the registration-mark search's reply"),
              std::string::npos)
        << e.what();
  }
  char buf[64];
  EXPECT_LE(::read(reader, buf, sizeof buf), 0);  // nothing was sent
  ::close(reader);
}

TEST(FileTransport, TakesANodeThatReadsAsEndOfFileForAOneWayPort) {
  // /dev/null can be opened read-write but reads as end of file: no replies will ever come, so queries
  // return nothing (as on a write-only node) instead of failing the job, and print-and-cut is refused.
  FileTransport t("/dev/null");
  EXPECT_TRUE(t.reads_replies());
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(t.request(stream_bytes("FG\x03"), std::chrono::milliseconds(2000)).has_value());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
  EXPECT_FALSE(t.reads_replies());
  const std::string stream =
      "\x1b\x04TB123,100,100,0,0\x03M0,0\x03"
      "D10,10\x03";
  EXPECT_THROW(send_job(stream_bytes(stream), t, {}), DeviceError);
}

// A pseudo-terminal in raw mode stands in for a cutter's two-way device node: its slave is a character
// device that can be read and written like /dev/usb/lp0, its master plays the cutter.
struct FakeCutterNode {
  int master = -1;
  std::string path;
  FakeCutterNode() {
    master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) return;
    path = ::ptsname(master);
    slave = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    termios t{};
    ::tcgetattr(slave, &t);
    ::cfmakeraw(&t);  // ETX must not be the interrupt character, nor echo come back
    ::tcsetattr(slave, TCSANOW, &t);
  }
  ~FakeCutterNode() {
    if (slave >= 0) ::close(slave);
    if (master >= 0) ::close(master);
  }
  // Held open until the host has written: with no slave open the master reads as hung up.
  int slave = -1;
  // Reads what the host sends; once `trigger` has arrived, answers `reply` once. Returns all it read
  // when the host closes the node or nothing comes for a while.
  std::string serve(const std::string& trigger, const std::string& reply) {
    std::string got;
    bool answered = false;
    while (true) {
      pollfd p{master, POLLIN, 0};
      if (::poll(&p, 1, 2000) <= 0) break;
      char buf[256];
      const ssize_t n = ::read(master, buf, sizeof buf);
      if (n <= 0) break;
      got.append(buf, static_cast<std::size_t>(n));
      if (slave >= 0) {
        ::close(slave);  // the host has the node open now: its close ends the session
        slave = -1;
      }
      if (!answered && got.find(trigger) != std::string::npos) {
        answered = true;
        if (::write(master, reply.data(), reply.size()) != static_cast<ssize_t>(reply.size())) break;
      }
    }
    return got;
  }
};

const std::string kMarkJob =
    "\x1b\x04TB99\x03TB123,100,100,0,0\x03M0,0\x03"
    "D10,10\x03";

TEST(FileTransport, ReadsTheMarkSearchReplyOnATwoWayNodeAndCutsWhenTheMarksAreFound) {
  FakeCutterNode node;
  if (node.path.empty()) GTEST_SKIP() << "no pseudo-terminal to stand in for the node";
  std::string received;
  std::jthread cutter([&] { received = node.serve("TB123,100,100,0,0\x03", "    0\x03"); });
  {
    FileTransport t(node.path);
    ASSERT_TRUE(t.reads_replies());
    SendOptions o;
    o.poll_interval = std::chrono::milliseconds(1);
    send_job(stream_bytes(kMarkJob), t, o);
    t.close();
  }
  cutter.join();
  EXPECT_EQ(received, kMarkJob);
}

TEST(FileTransport, StopsBeforeTheBladeWhenTheNodeSaysTheMarksWereNotFound) {
  // Before: a node was written blind, so the D after the search went out whatever the cutter answered.
  FakeCutterNode node;
  if (node.path.empty()) GTEST_SKIP() << "no pseudo-terminal to stand in for the node";
  std::string received;
  std::jthread cutter([&] { received = node.serve("TB123,100,100,0,0\x03", "    1\x03"); });
  {
    FileTransport t(node.path);
    SendOptions o;
    o.poll_interval = std::chrono::milliseconds(1);
    try {
      send_job(stream_bytes(kMarkJob), t, o);
      FAIL() << "cut although the marks were not found";
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("registration marks not found"), std::string::npos) << e.what();
    }
  }
  cutter.join();
  EXPECT_EQ(received.find("D10,10"), std::string::npos) << received;
  EXPECT_NE(received.find("TB123"), std::string::npos) << received;
}

TEST(FileTransport, WritesAPrintAndCutJobToARegularFileForLater) {
  const auto path = test::temp_dir("ft-regfile") / "job.gpgl";
  FileTransport t(path);
  EXPECT_FALSE(t.drives_device());
  const std::string stream =
      "\x1b\x04TB123,100,100,0,0\x03M0,0\x03"
      "D10,10\x03";
  send_job(stream_bytes(stream), t, {});
  t.close();
  EXPECT_TRUE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace foldkit::devices
