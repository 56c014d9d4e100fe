#include "foldkit/devices/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "foldkit/error.hpp"

namespace fs = std::filesystem;

namespace foldkit::devices {
namespace {

// Links followed before a path is taken for a loop (Linux's own limit).
constexpr int kMaxLinkHops = 40;

std::string errno_text(int err) {
  return std::generic_category().message(err);
}

// The temporary files of this process that are not committed yet. Process-wide because a signal is:
// the thread that receives SIGINT/SIGTERM must find every file to remove without a path to its owner.
struct PendingTemporaries {
  std::mutex mutex;
  std::set<std::string> paths;
};

PendingTemporaries& pending() {
  // Never destroyed: a signal may arrive while static destructors run.
  static PendingTemporaries* const instance = new PendingTemporaries;
  return *instance;
}

void unregister_temp(const fs::path& p) {
  std::lock_guard lock(pending().mutex);
  pending().paths.erase(p.string());
}

// The temporary must live in the target's directory: rename() is only atomic within one file system.
fs::path directory_of(const fs::path& target) {
  fs::path dir = target.parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

// A new, uniquely named, hidden file beside `destination` (hidden so that a crash between creation and
// rename leaves no file that looks like output). `tag` tells temporaries from backups.
fs::path make_hidden_file(const fs::path& destination, const std::string& target, const char* tag) {
  std::string name(".");
  name.append(destination.filename().string()).append(tag).append("-XXXXXX");
  std::string pattern = (directory_of(destination) / name).string();
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());
  if (fd < 0) throw OutputError(target, "cannot create file: " + errno_text(errno));
  // mkstemp creates 0600; output files should get the usual permissions under the user's umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  (void)::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  return fs::path(buffer.data());
}

// Created, opened and registered under one lock. A signal's clean-up that ran between creating and
// registering would miss a file that exists; one that ran before the stream opens the file by name
// would see it created again after its unlink.
fs::path open_registered_temporary(const fs::path& destination, const std::string& target,
                                   std::ofstream& stream) {
  std::lock_guard lock(pending().mutex);
  fs::path temp = make_hidden_file(destination, target, ".tmp");
  stream.open(temp, std::ios::binary | std::ios::trunc);
  if (!stream) {
    const int err = errno;
    ::unlink(temp.c_str());
    throw OutputError(target, "cannot open temporary file: " + errno_text(err));
  }
  pending().paths.insert(temp.string());
  return temp;
}

void write_all(int fd, const std::string& bytes, const std::string& target) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw OutputError(target, "write failed: " + errno_text(n < 0 ? errno : EIO));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

OutputDestination resolve_output(const fs::path& target) {
  if (target == "-") return {target, OutputKind::Stdout};
  if (target.filename().empty()) throw OutputError(target.string(), "not a file name");
  fs::path p = target;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    // Anything we cannot stat is a file to create; creating it reports the real problem.
    if (::lstat(p.c_str(), &st) != 0) return {p, OutputKind::File};
    if (S_ISLNK(st.st_mode)) {
      if (hops >= kMaxLinkHops) throw OutputError(target.string(), "too many levels of symbolic links");
      std::error_code ec;
      const fs::path link = fs::read_symlink(p, ec);
      if (ec) throw OutputError(target.string(), "cannot read link: " + ec.message());
      p = link.is_absolute() ? link : p.parent_path() / link;
      continue;
    }
    if (S_ISDIR(st.st_mode)) throw OutputError(target.string(), "is a directory");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) || S_ISFIFO(st.st_mode)) return {p, OutputKind::Node};
    if (S_ISSOCK(st.st_mode)) throw OutputError(target.string(), "is a socket");
    return {p, OutputKind::File};
  }
}

bool is_same_file(const fs::path& a, const fs::path& b) {
  if (a == "-" || b == "-") return false;
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

struct AtomicFile::State {
  fs::path target;
  OutputDestination destination;
  fs::path temp;             // File: the temporary being written
  std::ofstream file;        // File
  std::ostringstream bytes;  // Node, Stdout: everything, written on commit
  bool committed = false;

  std::ostream& stream() {
    if (destination.kind == OutputKind::File) return file;
    return bytes;
  }

  // Step 1 of a commit: everything written and on disk, nothing visible yet.
  void finish_writing() {
    if (destination.kind != OutputKind::File) {
      if (!bytes) throw OutputError(target.string(), "write failed (out of memory?)");
      return;
    }
    file.flush();
    const bool written = static_cast<bool>(file);
    file.close();
    if (!written || file.fail()) throw OutputError(target.string(), "write failed (disk full?)");
    // fsync before rename so that after a power loss the target is either the old or the new file.
    const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    const bool synced = ::fsync(fd) == 0;
    const int err = errno;
    ::close(fd);
    if (!synced) throw OutputError(target.string(), "cannot sync to disk: " + errno_text(err));
  }

  // Step 2, for a node or standard output: the bytes go out.
  void write_direct() {
    if (destination.kind == OutputKind::Stdout) {
      write_all(STDOUT_FILENO, bytes.str(), "standard output");
    } else {
      // A FIFO blocks here until a reader opens it, as any writer of a FIFO does.
      const int fd = ::open(destination.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
      if (fd < 0) throw OutputError(target.string(), "cannot open: " + errno_text(errno));
      try {
        write_all(fd, bytes.str(), target.string());
      } catch (...) {
        ::close(fd);
        throw;
      }
      if (::close(fd) != 0 && errno != EINTR)
        throw OutputError(target.string(), "write failed: " + errno_text(errno));
    }
    committed = true;
  }
};

AtomicFile::AtomicFile(fs::path target) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.target = std::move(target);
  s.destination = resolve_output(s.target);
  if (s.destination.kind != OutputKind::File) return;
  const fs::path dir = directory_of(s.destination.path);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw OutputError(s.target.string(), "directory " + dir.string() + " does not exist");
  s.temp = open_registered_temporary(s.destination.path, s.target.string(), s.file);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept = default;

AtomicFile::~AtomicFile() {
  if (!state_ || state_->committed || state_->temp.empty()) return;
  if (state_->file.is_open()) state_->file.close();
  ::unlink(state_->temp.c_str());
  unregister_temp(state_->temp);
}

std::ostream& AtomicFile::stream() {
  return state_->stream();
}

const fs::path& AtomicFile::target() const {
  return state_->target;
}

const fs::path& AtomicFile::temp_path() const {
  return state_->temp;
}

void AtomicFile::commit() {
  if (state_->committed) return;
  state_->finish_writing();
  if (state_->destination.kind != OutputKind::File) {
    state_->write_direct();
    return;
  }
  std::lock_guard lock(pending().mutex);
  if (::rename(state_->temp.c_str(), state_->destination.path.c_str()) != 0)
    throw OutputError(state_->target.string(), "cannot replace file: " + errno_text(errno));
  pending().paths.erase(state_->temp.string());
  state_->committed = true;
}

AtomicFile& AtomicFileSet::add(fs::path target) {
  files_.emplace_back(std::move(target));
  return files_.back();
}

std::vector<fs::path> AtomicFileSet::targets() const {
  std::vector<fs::path> out;
  for (const AtomicFile& f : files_)
    out.push_back(f.target());
  return out;
}

void AtomicFileSet::commit() {
  for (AtomicFile& f : files_)
    f.state_->finish_writing();
  {
    // Held until every rename is done or undone, so a signal's clean-up never sees half a set.
    std::lock_guard lock(pending().mutex);
    struct Replaced {
      AtomicFile::State* file;
      fs::path backup;  // a hard link to the old contents; empty when there were none
    };
    std::vector<Replaced> replaced;
    auto undo = [&] {
      for (auto it = replaced.rbegin(); it != replaced.rend(); ++it) {
        const char* dest = it->file->destination.path.c_str();
        if (it->backup.empty())
          ::unlink(dest);
        else
          ::rename(it->backup.c_str(), dest);
      }
    };
    for (AtomicFile& f : files_) {
      AtomicFile::State& s = *f.state_;
      if (s.committed || s.destination.kind != OutputKind::File) continue;
      Replaced r{&s, {}};
      try {
        if (::access(s.destination.path.c_str(), F_OK) == 0) {
          r.backup = make_hidden_file(s.destination.path, s.target.string(), ".old");
          ::unlink(r.backup.c_str());
          if (::link(s.destination.path.c_str(), r.backup.c_str()) != 0)
            throw OutputError(s.target.string(), "cannot keep the old file: " + errno_text(errno));
        }
        if (::rename(s.temp.c_str(), s.destination.path.c_str()) != 0)
          throw OutputError(s.target.string(), "cannot replace file: " + errno_text(errno));
      } catch (...) {
        if (!r.backup.empty()) ::unlink(r.backup.c_str());
        undo();
        throw;
      }
      replaced.push_back(std::move(r));
    }
    for (Replaced& r : replaced) {
      if (!r.backup.empty()) ::unlink(r.backup.c_str());
      pending().paths.erase(r.file->temp.string());
      r.file->committed = true;
    }
  }
  // Bytes sent into a device cannot be taken back: they go last, once every file is in place.
  for (AtomicFile& f : files_) {
    if (!f.state_->committed) f.state_->write_direct();
  }
}

void write_file_atomically(const fs::path& target, const std::function<void(std::ostream&)>& writer) {
  AtomicFile file(target);
  writer(file.stream());
  file.commit();
}

void write_file_atomically(const fs::path& target, std::string_view bytes) {
  write_file_atomically(target, [bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void remove_pending_temporaries() noexcept {
  // Locked for good: the process is ending, and no rename may follow the clean-up.
  pending().mutex.lock();
  for (const std::string& p : pending().paths)
    ::unlink(p.c_str());
  pending().paths.clear();
}

}  // namespace foldkit::devices
