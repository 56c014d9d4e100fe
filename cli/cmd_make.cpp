// Placeholder until the owner of this subcommand lands it.
#include "commands.hpp"

namespace foldkit::cli {
void setup_make(CLI::App& app) { app.add_subcommand("make", "(not yet available)"); }
}  // namespace foldkit::cli
