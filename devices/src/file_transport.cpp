#include "foldkit/devices/file_transport.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "foldkit/error.hpp"

namespace foldkit::devices {

FileTransport::FileTransport(std::filesystem::path path, std::chrono::milliseconds write_timeout)
    : path_(std::move(path)), timeout_(write_timeout) {
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (exists && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode))) {
    // Non-blocking so a printer that stops taking data cannot hang us; poll() bounds every wait.
    fd_ = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
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
