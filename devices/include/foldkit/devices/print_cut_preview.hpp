#pragma once
// What a print-and-cut job does to the printed page: the sheet as printed, with the lines a (simulated)
// cutter cut drawn over it, so a misaligned cut shows as lines beside their print.
#include <filesystem>
#include <vector>

#include "foldkit/devices/profile.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/devices/simulated_device.hpp"
#include "foldkit/sheet/sheet.hpp"

namespace foldkit::devices {

/// The blade strokes the simulated device executed, in sheet mm (y down), placed by the marks it found.
/// `mat` as in PlanOptions; the sheet's top-left is assumed at the cutting area's origin (offset 0).
std::vector<std::vector<Vec2>> simulated_cuts_mm(const SimulatedDevice& sim, const DeviceProfile& device,
                                                 const std::string& mat);

/// Writes a PNG of `sheet` as printed (in `print`'s styles, colours and fold lines, at its png_dpi) with
/// `cuts_mm` over it in red. Atomic; throws OutputError.
void render_print_and_cut(const Sheet& sheet, const std::vector<std::vector<Vec2>>& cuts_mm,
                          const std::filesystem::path& png, const RenderOptions& print = {});

}  // namespace foldkit::devices
