#pragma once
// Writing output files all-or-nothing: bytes go to a temporary file in the target's directory, which
// replaces the target by rename only once everything was written. A crash, a full disk or an exception
// never leaves a half-written file under the target's name.
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>
#include <string_view>

namespace foldkit::devices {

/// A temporary file that becomes `target` on commit() and is removed if never committed.
/// Throws OutputError naming `target` when the directory is missing or not writable.
class AtomicFile {
 public:
  /// Creates a uniquely named temporary file beside `target`.
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  /// The stream to write the contents to (binary).
  std::ostream& stream() { return stream_; }
  /// Where the file ends up.
  const std::filesystem::path& target() const { return target_; }
  /// The temporary file being written.
  const std::filesystem::path& temp_path() const { return temp_; }
  /// Flushes, syncs to disk and renames over the target. Throws OutputError on any write failure.
  void commit();

 private:
  std::filesystem::path target_, temp_;
  std::ofstream stream_;
  bool committed_ = false;
};

/// Writes `target` atomically with `writer` filling the stream. If the writer throws, nothing is left
/// behind and the exception propagates.
void write_file_atomically(const std::filesystem::path& target,
                           const std::function<void(std::ostream&)>& writer);

/// Writes `bytes` to `target` atomically.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

}  // namespace foldkit::devices
