// Placeholder until the owner of this subcommand lands it.
#include "commands.hpp"

namespace foldkit::cli {
void setup_unfold(CLI::App& app) { app.add_subcommand("unfold", "(not yet available)"); }
}  // namespace foldkit::cli
