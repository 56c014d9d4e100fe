#pragma once
// Writing a job's stream to a file (job.plt, job.gpgl: atomically, so a failed job leaves no half
// file) or to a device node (/dev/usb/lp0, a serial tty: written as it comes, with a bounded wait).
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/transport.hpp"

namespace foldkit::devices {

/// A Transport to a path. Regular files (or new paths) are written to a temporary file and renamed on
/// close(); character devices, FIFOs and sockets are opened read-write when they allow it (else
/// write-only) and written directly. status() is Unknown. On a readable node, request() reads the reply
/// up to its ETX or CR within the query's timeout, as over USB; a node that reads as end of file is a
/// one-way port from then on (request() returns nullopt, as on a write-only node). Throws DeviceError for
/// permission denied (naming the group to join), a node that takes no data within `write_timeout` (the same
/// bound as a busy USB cutter: --ready-timeout), a missing reply or a write error; OutputError for an
/// unwritable file.
class FileTransport final : public Transport {
 public:
  explicit FileTransport(std::filesystem::path path,
                         std::chrono::milliseconds write_timeout = std::chrono::milliseconds(120000));
  FileTransport(const FileTransport&) = delete;
  FileTransport& operator=(const FileTransport&) = delete;
  /// An unclosed regular file is discarded: a job that failed half-way leaves nothing behind.
  ~FileTransport() override;

  void write(std::span<const std::byte> bytes) override;
  DeviceState status() override { return DeviceState::Unknown; }
  std::optional<std::vector<std::byte>> request(std::span<const std::byte> command,
                                                std::chrono::milliseconds timeout) override;
  bool reads_replies() const override { return node_ && readable_; }
  bool drives_device() const override { return node_; }
  void close() override;
  std::string describe() const override;

  /// Whether the path is a device node rather than a regular file.
  bool is_device_node() const { return node_; }

 private:
  std::filesystem::path path_;
  std::chrono::milliseconds timeout_;
  std::optional<AtomicFile> file_;
  int fd_ = -1;
  bool node_ = false, readable_ = false;
  bool closed_ = false;
};

}  // namespace foldkit::devices
