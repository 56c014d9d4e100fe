#include "foldkit/devices/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "foldkit/error.hpp"

namespace foldkit::devices {
namespace {

std::string errno_text(int err) {
  return std::generic_category().message(err);
}

// The temporary must live in the target's directory: rename() is only atomic within one file system.
std::filesystem::path directory_of(const std::filesystem::path& target) {
  std::filesystem::path dir = target.parent_path();
  return dir.empty() ? std::filesystem::path(".") : dir;
}

std::filesystem::path make_temp(const std::filesystem::path& target) {
  if (target.filename().empty()) throw OutputError(target.string(), "not a file name");
  const std::filesystem::path dir = directory_of(target);
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw OutputError(target.string(), "directory " + dir.string() + " does not exist");
  }
  if (std::filesystem::is_directory(target, ec)) throw OutputError(target.string(), "is a directory");
  // Hidden name so that a crash between creation and rename leaves no file that looks like output.
  std::string name(".");
  name.append(target.filename().string()).append(".tmp-XXXXXX");
  std::string pattern = (dir / name).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());
  if (fd < 0) throw OutputError(target.string(), "cannot create file: " + errno_text(errno));
  // mkstemp creates 0600; output files should get the usual permissions under the user's umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  return std::filesystem::path(buffer.data());
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)), temp_(make_temp(target_)) {
  stream_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    const int err = errno;
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
    throw OutputError(target_.string(), "cannot open temporary file: " + errno_text(err));
  }
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temp_(std::move(other.temp_)),
      stream_(std::move(other.stream_)),
      committed_(other.committed_) {
  // The moved-from object must not delete the file it no longer owns.
  other.committed_ = true;
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (stream_.is_open()) stream_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
}

void AtomicFile::commit() {
  if (committed_) return;
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) {
    throw OutputError(target_.string(), "write failed (disk full?)");
  }
  // fsync before rename so that after a power loss the target is either the old or the complete new file.
  const int fd = ::open(temp_.c_str(), O_RDONLY);
  if (fd >= 0) {
    const bool synced = ::fsync(fd) == 0;
    const int err = errno;
    ::close(fd);
    if (!synced) throw OutputError(target_.string(), "cannot sync to disk: " + errno_text(err));
  }
  if (::rename(temp_.c_str(), target_.c_str()) != 0) {
    throw OutputError(target_.string(), "cannot replace file: " + errno_text(errno));
  }
  committed_ = true;
}

void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(std::ostream&)>& writer) {
  AtomicFile file(target);
  writer(file.stream());
  file.commit();
}

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
  write_file_atomically(target, [bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace foldkit::devices
