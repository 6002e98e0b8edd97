// sphtroch — command-line tool. Parsing and printing only; the work is in the library.
#include "cli_common.hpp"

#include "sphtroch/errors.hpp"
#include "sphtroch/version.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  using namespace sphtroch::cli;
  CLI::App app{"sphtroch " SPHTROCH_VERSION_STRING
               " - trajectories of spherical planetary gear trains (Lin & Tsai 1990)",
               "sphtroch"};
  app.set_version_flag("--version", std::string("sphtroch ") + SPHTROCH_VERSION_STRING);
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, Action>> actions;
  register_trace(app, actions);
  register_atlas(app, actions);
#ifdef SPHTROCH_HAVE_ANALYSIS
  register_analysis(app, actions);
  register_scene(app, actions);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "sphtroch: " << e.what() << " (see sphtroch --help)\n";
    return kBadInput;
  }
  try {
    for (auto& [command, action] : actions)
      if (command->parsed()) action();
  } catch (const sphtroch::InvalidInput& e) {
    std::cerr << "sphtroch: --" << e.what() << "\n";
    return kBadInput;
  } catch (const UsageError& e) {
    std::cerr << "sphtroch: " << e.message << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "sphtroch: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
