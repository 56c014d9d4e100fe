// foldkit: mesh -> unfolding -> layout -> PDF/SVG/PNG or a cutting plotter.
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "foldkit/error.hpp"
#include "interrupt.hpp"
#include "usage_errors.hpp"

int main(int argc, char** argv) {
  // First: every thread started later (worker pools) must inherit the blocked SIGINT/SIGTERM.
  const foldkit::cli::SignalHandling signals;
  CLI::App app{"foldkit: turn a 3D triangle mesh into a papercraft sheet to print, cut, fold and glue"};
  app.set_version_flag("--version", FOLDKIT_VERSION);
  app.require_subcommand(1);
  foldkit::cli::setup_make(app);
  foldkit::cli::setup_unfold(app);
  foldkit::cli::setup_inspect(app);
  foldkit::cli::setup_bench(app);
  foldkit::cli::setup_cut(app);
  foldkit::cli::setup_profiles(app);
  foldkit::cli::setup_devices(app);
  foldkit::cli::setup_sim(app);
  foldkit::cli::setup_calibrate(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive as parse errors with exit code 0.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << foldkit::cli::usage_error_message(app, e);
    return static_cast<int>(foldkit::ExitCode::Usage);
  } catch (const foldkit::Error& e) {
    std::cerr << "foldkit: " << e.what() << "\n";
    return static_cast<int>(e.exit_code());
  } catch (const std::bad_alloc&) {
    std::cerr << "foldkit: out of memory\n";
    return static_cast<int>(foldkit::ExitCode::Failure);
  } catch (const std::exception& e) {
    std::cerr << "foldkit: internal error: " << e.what() << "\n";
    return static_cast<int>(foldkit::ExitCode::Failure);
  }
  return 0;
}
