#pragma once
// Strict tokenisers for the byte streams cutters receive: GP-GL (ETX-terminated commands and ESC
// sequences) and HP-GL (two-letter mnemonics terminated by ';'). Streaming (a command may straddle
// writes) and free of device state, so the simulated device and a fuzzer drive the same code.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace foldkit::devices {

/// One command: its mnemonic ("M", "TB", "PD", "ESC05" for ESC 0x05), numeric parameters and the
/// offset of its first byte in the whole stream.
struct ParsedCommand {
  std::size_t offset = 0;
  std::string name;
  std::vector<double> params;
};

/// GP-GL tokeniser. Throws DeviceError "GP-GL byte N: <problem>" for unknown mnemonics, wrong arity,
/// non-numeric parameters, unknown escapes or a command with no ETX within 4 KiB.
class GpglParser {
 public:
  /// Adds bytes; returns the commands they complete.
  std::vector<ParsedCommand> feed(std::span<const std::byte> bytes);
  /// End of stream: throws when it ends inside a command.
  void finish() const;
  /// Bytes consumed so far.
  std::size_t offset() const { return base_ + pending_.size(); }

 private:
  std::string pending_;
  std::size_t base_ = 0;  // stream offset of pending_[0]
};

/// HP-GL tokeniser: whitespace between commands is skipped; parameters are separated by commas or
/// spaces; every command ends with ';'. Throws DeviceError "HP-GL byte N: <problem>".
class HpglParser {
 public:
  std::vector<ParsedCommand> feed(std::span<const std::byte> bytes);
  void finish() const;
  std::size_t offset() const { return base_ + pending_.size(); }

 private:
  std::string pending_;
  std::size_t base_ = 0;
};

}  // namespace foldkit::devices
