#pragma once
// Writing output files all-or-nothing, and never over something that is not a file of ours to replace.
// A regular file is written to a temporary file in the target's directory, which replaces the target by
// rename only once everything was written: a crash, a full disk, an exception or a signal never leaves a
// half-written file under the target's name. A target that is a symbolic link is written to the file the
// link names (the link stays a link). A character or block device or a FIFO (/dev/null, a printer port)
// is never renamed over: its bytes are kept in memory and written into it on commit, as is standard
// output, named "-".
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

namespace foldkit::devices {

/// What an output path names once links are followed.
enum class OutputKind {
  File,    ///< a regular file, or a path where one will be created: temporary file and rename
  Node,    ///< a character or block device or a FIFO: written into directly
  Stdout,  ///< "-": standard output
};

/// Where bytes for `target` really go.
struct OutputDestination {
  std::filesystem::path path;  ///< `target` with every symbolic link followed (itself for "-")
  OutputKind kind = OutputKind::File;
};

/// Resolves `target`. Throws OutputError naming `target` for a link loop or a directory.
OutputDestination resolve_output(const std::filesystem::path& target);

/// Whether `a` and `b` name the same existing file (same device and inode, links followed), so that
/// writing one would destroy the other. False when either does not exist or is "-".
bool is_same_file(const std::filesystem::path& a, const std::filesystem::path& b);

/// An output that becomes `target` on commit() and leaves nothing behind if never committed.
/// Throws OutputError naming `target` when the directory is missing or not writable.
class AtomicFile {
 public:
  /// Creates a uniquely named temporary file beside the resolved target (or opens the node).
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  /// The stream to write the contents to (binary).
  std::ostream& stream();
  /// Where the file ends up, as given.
  const std::filesystem::path& target() const;
  /// The temporary file being written; empty for a device node or standard output.
  const std::filesystem::path& temp_path() const;
  /// Flushes, syncs to disk and renames over the target (or writes the bytes into the node).
  /// Throws OutputError on any write failure.
  void commit();

 private:
  friend class AtomicFileSet;
  struct State;
  std::unique_ptr<State> state_;
};

/// Several outputs that appear together or not at all: commit() writes and syncs every temporary file
/// first, then renames them; if a rename fails, the files already replaced get their old contents back.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  /// Starts the output for `target`; the reference stays valid until the set is destroyed.
  AtomicFile& add(std::filesystem::path target);
  /// Commits every file or none. Throws OutputError naming the file that failed.
  void commit();
  /// The files of the set, in the order added.
  std::vector<std::filesystem::path> targets() const;

 private:
  std::vector<AtomicFile> files_;
};

/// Writes `target` atomically with `writer` filling the stream. If the writer throws, nothing is left
/// behind and the exception propagates.
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(std::ostream&)>& writer);

/// Writes `bytes` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

/// Removes every temporary file of an uncommitted AtomicFile in this process. For a process that is
/// about to end on a signal: afterwards no AtomicFile can commit (commits wait forever). Thread-safe;
/// not async-signal-safe (call it from a thread that received the signal through sigwait).
void remove_pending_temporaries() noexcept;

}  // namespace foldkit::devices
