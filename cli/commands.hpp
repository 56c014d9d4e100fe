#pragma once
// Subcommands of the foldkit CLI: one file each (setup_* binds options, the callback does the work).
#include <CLI/CLI.hpp>

namespace foldkit::cli {

void setup_make(CLI::App& app);
void setup_unfold(CLI::App& app);
void setup_inspect(CLI::App& app);
void setup_bench(CLI::App& app);
void setup_cut(CLI::App& app);
void setup_profiles(CLI::App& app);
void setup_devices(CLI::App& app);
void setup_sim(CLI::App& app);
void setup_calibrate(CLI::App& app);

}  // namespace foldkit::cli
