#include "foldkit/devices/file_transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "foldkit/error.hpp"

namespace foldkit::devices {

FileTransport::FileTransport(std::filesystem::path path, std::chrono::milliseconds write_timeout)
    : path_(std::move(path)), timeout_(write_timeout) {
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (exists && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode))) {
    // Non-blocking so a printer that stops taking data cannot hang us; poll() bounds every wait.
    // Read-write when the node allows it, so replies (the mark search's above all) can be read.
    // Not a FIFO: read-write opens one with no reader and would read our own bytes back.
    if (S_ISCHR(st.st_mode)) fd_ = ::open(path_.c_str(), O_RDWR | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    readable_ = fd_ >= 0;
    if (fd_ < 0) fd_ = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd_ < 0) {
      const int err = errno;
      if (err == EACCES || err == EPERM)
        throw DeviceError(path_.string() +
                          ": permission denied (join group \"lp\" for /dev/usb/lp*, \"dialout\" "
                          "for serial ports, then log in again)");
      if (err == ENXIO) throw DeviceError(path_.string() + ": no device is listening (unplugged?)");
      throw DeviceError(path_.string() + ": " + std::strerror(err));
    }
    node_ = true;
    return;
  }
  if (exists && S_ISDIR(st.st_mode)) throw OutputError(path_.string(), "is a directory");
  file_.emplace(path_);
}

FileTransport::~FileTransport() {
  if (fd_ >= 0) ::close(fd_);
}

void FileTransport::write(std::span<const std::byte> bytes) {
  if (closed_) throw DeviceError(describe() + ": write after close");
  if (file_) {
    file_->stream().write(reinterpret_cast<const char*>(bytes.data()),
                          static_cast<std::streamsize>(bytes.size()));
    if (!file_->stream()) throw OutputError(path_.string(), "write failed");
    return;
  }
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
      const int err = errno;
      throw DeviceError(describe() + ": " +
                        (err == ENODEV || err == EIO ? "device gone (unplugged?)" : std::strerror(err)) +
                        " after " + std::to_string(done) + " of " + std::to_string(bytes.size()) + " bytes");
    }
    pollfd p{fd_, POLLOUT, 0};
    const int r = ::poll(&p, 1, static_cast<int>(timeout_.count()));
    if (r == 0)
      throw DeviceError(describe() + ": the device took no data for " + std::to_string(timeout_.count()) +
                        " ms (busy, paused or out of media?)");
    if (r < 0 && errno != EINTR) throw DeviceError(describe() + ": " + std::strerror(errno));
    if (r > 0 && (p.revents & (POLLERR | POLLHUP)))
      throw DeviceError(describe() + ": device gone (unplugged?)");
  }
}

std::optional<std::vector<std::byte>> FileTransport::request(std::span<const std::byte> command,
                                                             std::chrono::milliseconds timeout) {
  write(command);
  if (!reads_replies()) return std::nullopt;
  // Replies end with ETX (GP-GL) or CR (HP-GL) and are short; more than this is not a reply.
  constexpr std::size_t kMaxReply = 4096;
  std::vector<std::byte> reply;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (reply.size() < kMaxReply) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(left.count()));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    char buf[256];
    const ssize_t n = ::read(fd_, buf, sizeof buf);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (n == 0 || (n < 0 && (errno == EINVAL || errno == EIO || errno == EBADF))) {
      // End of file or a refused read: a one-way port after all, no reply channel from now on (a job
      // without a mark search still goes through it as before; send_job refuses one with a search).
      readable_ = false;
      return std::nullopt;
    }
    if (n < 0) break;
    for (ssize_t i = 0; i < n; ++i) {
      reply.push_back(static_cast<std::byte>(buf[i]));
      if (buf[i] == '\x03' || buf[i] == '\r') return reply;
    }
  }
  throw DeviceError(describe() + ": no reply within " + std::to_string(timeout.count()) +
                    " ms (is the cutter switched on and ready?)");
}

void FileTransport::close() {
  if (closed_) return;
  closed_ = true;
  if (file_) {
    file_->commit();
    return;
  }
  if (fd_ >= 0) {
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) throw DeviceError(describe() + ": " + std::strerror(errno));
  }
}

std::string FileTransport::describe() const {
  return (node_ ? "device node " : "file ") + path_.string();
}

}  // namespace foldkit::devices
