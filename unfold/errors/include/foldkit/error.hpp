#pragma once
// The one error hierarchy of foldkit. Libraries throw these at the boundary where input is read;
// only cli/ turns them into messages and exit codes.
#include <stdexcept>
#include <string>

namespace foldkit {

/// Exit codes the CLI returns for each error class.
enum class ExitCode : int {
  Success = 0,
  Failure = 1,  ///< anything unexpected
  Usage = 2,    ///< bad command line
  Input = 3,    ///< unreadable or invalid input file (mesh, profile, seam list)
  Output = 4,   ///< cannot write an output file
  Layout = 5,   ///< the model cannot be laid out as asked (piece larger than the sheet…)
  Device = 6,   ///< device not found, busy, permission, timeout, out of bounds
  Interrupted = 130,
  Terminated = 143,
};

/// Base of every foldkit exception. what() is one line, ready to show to a user.
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, ExitCode code) : std::runtime_error(message), code_(code) {}
  ExitCode exit_code() const { return code_; }

 private:
  ExitCode code_;
};

/// A file given by the user cannot be used. Message: "<file>: <problem>".
class InputError : public Error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : Error(file + ": " + problem, ExitCode::Input), file_(file), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, problem_;
};

/// An output file cannot be written.
class OutputError : public Error {
 public:
  OutputError(const std::string& file, const std::string& problem)
      : Error(file + ": " + problem, ExitCode::Output) {}
};

/// The request cannot be met by the layout (e.g. the model does not fit the sheet at the asked size).
class LayoutError : public Error {
 public:
  explicit LayoutError(const std::string& message) : Error(message, ExitCode::Layout) {}
};

/// A device or transport problem.
class DeviceError : public Error {
 public:
  explicit DeviceError(const std::string& message) : Error(message, ExitCode::Device) {}
};

}  // namespace foldkit
