#include "foldkit/devices/device_model.hpp"

namespace foldkit::devices {
namespace {

// Every number below carries its source key from docs/plotter-protocols.md section 0.
constexpr std::uint16_t kGraphtec = 0x0b4d, kRoland = 0x0b75;
constexpr double kInchMm = 25.4;

// The GP-GL mnemonics of a Silhouette (2.1-2.6) and of Graphtec's own command list [GPGL-L].
const std::set<std::string> kSilhouetteCommands = {
    "ESC04", "ESC05", "ESC15", "FG", "FA", "TC", "TB", "TG", "FN", "FX", "FE", "FF", "FC", "FY", "TF",
    "TJ",    "SO",    "FO",    "FW", "M",  "D",  "J",  "!",  "\\", "Z",  "L",  "H",  "[",  "U"};
const std::set<std::string> kGraphtecCommands = {"M",  "D", "J", "!", "*", "FC",
                                                 "\\", "Z", "L", "H", "[", "U"};
const std::set<std::string> kHpglCommands = {"IN", "PA", "PR", "PU", "PD", "SP",
                                             "VS", "FS", "LT", "OI", "OS", "OH"};

Mat mat(const char* id, std::optional<int> code, double w_mm, double l_mm) {
  return {id, code, w_mm, l_mm};
}

// [IS CAMEO_MATS]: TG0 none, 1 Cameo 12x12, 2 Cameo 12x24, 3 Portrait 8x12, 8 Cameo Plus 15x15.
Mat cameo_12x12() {
  return mat("12x12", 1, 12 * kInchMm, 12 * kInchMm);
}
Mat cameo_12x24() {
  return mat("12x24", 2, 12 * kInchMm, 24 * kInchMm);
}

MachineModel silhouette(const char* name, std::uint16_t product, double width_mm, double length_mm,
                        int holders, int max_speed, GpglFamily family) {
  MachineModel m;
  DeviceProfile& d = m.facts;
  d.name = name;
  d.protocol = Protocol::Gpgl;
  d.firmware = name;
  d.usb_vendor = kGraphtec;
  d.usb_product = product;
  d.units_per_mm = 20;                   // 2.2: 1 SU = 0.05 mm
  d.axes = {true, false, false, false};  // 2.2: a = feed from the top edge, b = carriage from the left
  d.area_width_mm = width_mm;            // 1.1 [IS] DEVICE table
  d.area_max_length_mm = length_mm;
  d.holders = holders;             // 1.1: Cameo 3+ two holders; Portrait 3/4 single tool
  d.speed_steps = {1, max_speed};  // 2.3: ! 1-10 (Cameo <= 3), 1-30 (Cameo 4 line)
  d.force_steps = {1, 33};         // 2.3: FX 1-33
  d.gpgl_family = family;
  d.regmarks.supported = true;  // 2.4: TB123, type 2, 5 mm square
  d.regmarks.square_mm = 5;
  m.commands = kSilhouetteCommands;
  m.autoblade_holder_1 = true;
  return m;
}

// The Silhouette line [IS]: Cameo 3, 4, 5, Portrait 3 and Curio.
void add_silhouettes(std::vector<MachineModel>& out) {
  {
    MachineModel m = silhouette("Silhouette Cameo 3", 0x112f, 304.8, 3000, 2, 10, GpglFamily::Cameo3);
    m.facts.firmware = "CAMEO 3 V1.60";  // 2.1: the recorded FG reply
    m.facts.mats.push_back(cameo_12x12());
    m.facts.mats.push_back(cameo_12x24());
    out.push_back(m);
  }
  for (auto [name, pid, width] :
       {std::tuple{"Silhouette Cameo 4", 0x1137, 304.8}, std::tuple{"Silhouette Cameo 5", 0x1140, 330.2}}) {
    MachineModel m =
        silhouette(name, static_cast<std::uint16_t>(pid), width, 3000, 2, 30, GpglFamily::Cameo4);
    m.facts.mats.push_back(cameo_12x12());
    m.facts.mats.push_back(cameo_12x24());
    out.push_back(m);
  }
  {
    // 1.1: Portrait 3 203 mm wide, 18 290 mm long, single tool; [IS] runs it as the Cameo 4 line.
    MachineModel m = silhouette("Silhouette Portrait 3", 0x113a, 203.2, 18290, 1, 30, GpglFamily::Cameo4);
    m.facts.mats.push_back(mat("8x12", 3, 8 * kInchMm, 12 * kInchMm));
    out.push_back(m);
  }
  {
    // 1.1 [ST]: Curio beds 8.5x6 and 8.5x12 in, not auto-detected: no TG code is known.
    MachineModel m =
        silhouette("Silhouette Curio", 0x112c, 8.5 * kInchMm, 12 * kInchMm, 2, 10, GpglFamily::Cameo3);
    m.facts.mats = {mat("8.5x6", std::nullopt, 8.5 * kInchMm, 6 * kInchMm),
                    mat("8.5x12", std::nullopt, 8.5 * kInchMm, 12 * kInchMm)};
    m.commands.erase("TG");
    out.push_back(m);
  }
}

MachineModel graphtec_ce6000() {
  // Graphtec's own list [GPGL-L]; 0.1 mm steps and X = feed, Y = carriage [CE]; the origin at the
  // loaded sheet (a roll cutter). No Silhouette queries, status or mats.
  MachineModel m;
  DeviceProfile& d = m.facts;
  d.name = "Graphtec CE6000-60";
  d.protocol = Protocol::Gpgl;
  d.usb_vendor = kGraphtec;
  d.usb_product = 0x1122;
  d.units_per_mm = 10;
  d.axes = {true, false, false, true};
  d.area_width_mm = 603;
  d.area_max_length_mm = 50000;
  d.holders = 1;
  d.speed_steps = {101, 160};  // ! l: 101-160 = l - 100 cm/s (1-10 is the other form)
  d.force_steps = {1, 38};     // * a,f: f 1-38
  d.gpgl_family = GpglFamily::Graphtec;
  m.commands = kGraphtecCommands;
  return m;
}

MachineModel roland_gx24() {
  // Roland GX-24: HP-GL at 40 PLU/mm with Roland's !FS force [FM]; origin at the loaded sheet.
  MachineModel m;
  DeviceProfile& d = m.facts;
  d.name = "Roland GX-24";
  d.protocol = Protocol::Hpgl;
  d.firmware = "GX-24";
  d.usb_vendor = kRoland;
  d.usb_product = 0x0405;
  d.units_per_mm = 40;
  d.axes = {true, false, false, true};
  d.area_width_mm = 584;
  d.area_max_length_mm = 25000;
  d.holders = 1;
  d.speed_steps = {1, 50};
  d.force_steps = {30, 250};
  d.hpgl_force_command = "!FS";
  m.commands = kHpglCommands;
  m.commands.erase("FS");
  m.commands.insert("!FS");
  return m;
}

// What every built-in model has: its name as id and firmware (unless recorded) and a blade in holder 1.
void add_common_facts(MachineModel& m) {
  // Media without a mat (TG0) on every Silhouette that takes TG; listed last, the mats come first.
  if (m.commands.count("TG"))
    m.facts.mats.push_back(mat("none", 0, m.facts.area_width_mm, m.facts.area_max_length_mm));
  m.facts.id = m.facts.name;
  if (m.facts.firmware.empty()) m.facts.firmware = m.facts.name;
  m.facts.tools.push_back({"blade", ToolKind::Blade, 1, 0, m.autoblade_holder_1});
}

// Data more than logic: one block per machine, each fact with the source that gives it.
std::vector<MachineModel> builtin_models() {
  std::vector<MachineModel> out;
  add_silhouettes(out);
  out.push_back(graphtec_ce6000());
  out.push_back(roland_gx24());
  for (MachineModel& m : out)
    add_common_facts(m);
  return out;
}

}  // namespace

std::optional<MachineModel> builtin_machine_model(std::uint16_t usb_vendor, std::uint16_t usb_product) {
  if (usb_vendor == 0) return std::nullopt;
  for (MachineModel& m : builtin_models()) {
    if (m.facts.usb_vendor == usb_vendor && m.facts.usb_product == usb_product) return m;
  }
  return std::nullopt;
}

MachineModel machine_model(const DeviceProfile& profile) {
  if (auto m = builtin_machine_model(profile.usb_vendor, profile.usb_product)) return *m;
  MachineModel m;
  m.facts = profile;
  m.from_profile = true;
  if (profile.protocol == Protocol::Hpgl) {
    m.commands = kHpglCommands;
    if (profile.hpgl_force_command == "!FS") m.commands.insert("!FS");
  } else {
    m.commands = profile.gpgl_family == GpglFamily::Graphtec ? kGraphtecCommands : kSilhouetteCommands;
  }
  for (const Tool& t : profile.tools)
    m.autoblade_holder_1 |= t.autoblade;
  return m;
}

}  // namespace foldkit::devices
