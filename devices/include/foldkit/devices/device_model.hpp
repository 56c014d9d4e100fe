#pragma once
// What the real machines are, written from the protocol facts (docs/plotter-protocols.md) and not read
// from the planner's profiles: the simulated device checks a job against these, so a wrong profile (a
// wrong TG code, origin or command) fails a dry run instead of passing its own test.
#include <optional>
#include <set>
#include <string>

#include "foldkit/devices/profile.hpp"

namespace foldkit::devices {

/// One machine model. `facts` holds what a profile would say (axes, area, mats with their TG codes,
/// holders, ranges), filled from the protocol facts; the rest is what only the machine knows.
struct MachineModel {
  DeviceProfile facts;
  std::set<std::string> commands;   ///< mnemonics it accepts ("M", "TB", "ESC05", "PD", "!FS")
  bool autoblade_holder_1 = false;  ///< TF d,1 sets the AutoBlade's depth
  int max_blade_offset = 46;        ///< FC values above are ignored by the device ([IS])
  bool from_profile = false;        ///< no built-in model: checking against the profile itself
};

/// The built-in model of the machine with this USB id, if there is one (Cameo 3/4/5, Portrait 3,
/// Curio, CE6000-60, GX-24).
std::optional<MachineModel> builtin_machine_model(std::uint16_t usb_vendor, std::uint16_t usb_product);

/// The built-in model for `profile`'s USB id, else one taken from the profile (from_profile = true:
/// test profiles, generic HP-GL, a user's new model).
MachineModel machine_model(const DeviceProfile& profile);

}  // namespace foldkit::devices
