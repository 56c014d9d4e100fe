// Placeholder until the owner of this subcommand lands it.
#include "commands.hpp"

namespace foldkit::cli {
void setup_inspect(CLI::App& app) { app.add_subcommand("inspect", "(not yet available)"); }
}  // namespace foldkit::cli
