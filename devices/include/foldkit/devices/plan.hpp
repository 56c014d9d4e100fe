#pragma once
// Planning a job: sheet + device + media -> passes in device units. Decides which tool does what (labels
// drawn, folds scored or perforated, outlines cut last), orders each pass for short pen-up travel with
// insides before outlines, converts to device units once and checks every stroke against the cutting
// area and the mat before anything is encoded.
#include <optional>
#include <string>

#include "foldkit/devices/job.hpp"
#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/stroke_font.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

struct PlanOptions {
  std::string mat;                        ///< mat id; empty = the device's first mat (or its whole area)
  bool draw_labels = false;               ///< draw texts and label paths with the pen
  const StrokeFont* font = nullptr;       ///< font for texts (required when draw_labels and texts exist)
  bool score_folds = true;                ///< mark mountain and valley folds
  std::optional<FoldMethod> fold_method;  ///< overrides device and media
  bool regmarks = false;                  ///< print-and-cut: search the sheet's marks, cut relative to them
  double overcut_mm = 0;                  ///< closed cuts continue this far past their start
  bool order = true;                      ///< false keeps sheet order (for comparisons)
  Vec2 offset_mm{0, 0};                   ///< where the sheet's top-left corner sits in the cutting area
  /// Print-and-cut only (with regmarks): added to every stroke, not to the mark search, to correct the
  /// printer-to-cutter error `foldkit calibrate` measured (sheet mm: x right, y down).
  Vec2 print_cut_offset_mm{0, 0};
};

/// Plans the job. Throws DeviceError naming the first stroke that leaves the cutting area or the mat
/// (role, piece, point in mm), when regmarks are asked of a device without support or a sheet without
/// marks, or when a pass needs a tool the device lacks.
Job plan_job(const Sheet& sheet, const DeviceProfile& device, const MediaProfile& media,
             const PlanOptions& options = {});

/// The active cutting area (width across the carriage, length along the feed) for `mat_id`.
Vec2 cutting_area_mm(const DeviceProfile& device, const std::string& mat_id);

/// Tool-down length of a stroke in mm.
double stroke_length_mm(const Stroke& stroke, double units_per_mm);

}  // namespace foldkit::devices
