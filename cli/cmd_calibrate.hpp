#pragma once
// `foldkit calibrate`: the print-and-cut calibration page and job, and the stored offset.
#include <optional>
#include <string>
#include <vector>

namespace foldkit::cli {

/// What `foldkit calibrate` was asked; the parser fills it, run_calibrate does the work.
struct CalibrateArgs {
  std::string device, media = "copy-80", mat, paper = "A4";
  std::vector<std::string> profiles;
  std::string pdf, job, preview;
  std::string offset;
  bool reset = false, verify = false, show = false, json = false;
};

/// Shows, stores or removes the stored offset, or writes the calibration page, its job and preview. Throws
/// Error, InputError or DeviceError.
void run_calibrate(const CalibrateArgs& args);

}  // namespace foldkit::cli
