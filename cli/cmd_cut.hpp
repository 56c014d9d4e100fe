#pragma once
// `foldkit cut`: load -> unfold -> lay out -> plan -> encode -> send, to a USB cutter, a file or device node,
// or the simulated device.
#include <string>
#include <vector>

#include "colour_options.hpp"
#include "layout_options.hpp"
#include "unfold_options.hpp"

namespace foldkit::cli {

/// What `foldkit cut` was asked; the parser fills it, run_cut does the work.
struct CutArgs {
  std::string mesh;
  std::string device;  ///< profile id; empty: a simulated cameo4
  std::string media = "cardstock-220", mat;
  bool dry_run = false;  ///< to the simulated device
  std::string output, preview, overlay;
  std::vector<std::string> profiles;  ///< --profile files
  std::string usb_vid, usb_pid;       ///< hex, overriding the profile's
  bool labels = false;                ///< --draw-labels
  std::string fold_method;            ///< a name of devices::fold_method_choices(); empty: profile and media
  double overcut_mm = 0.5;
  int sheet = 0;  ///< 1-based; 0: all
  double ready_timeout_s = 120;
  std::vector<std::string> sim_faults;
  bool json = false, quiet = false;
  /// Whether the command line gave the registration mark's arm, inset and square (else the profile's).
  bool regmark_arm_given = false, regmark_inset_given = false, regmark_square_given = false;
  UnfoldCliOptions unfold;
  LayoutCliOptions layout;
  ColourCliOptions colour;
};

/// Checks the request, runs the pipeline (load_unfold_layout), and per sheet plans and bounds-checks the
/// job (devices::plan_job) before a byte is sent, encodes it and sends it (devices::send_job); prints the
/// summary on stdout (JSON with --json). Throws Error (usage, interrupted), InputError, LayoutError,
/// DeviceError.
void run_cut(CutArgs args);

}  // namespace foldkit::cli
