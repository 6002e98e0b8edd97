// sphtroch — command-line tool. Parsing and printing only; the work is in the library.
// Exit status: 0 success; 2 bad input or an output that cannot be written (one line on stderr);
// 3 the outputs are complete but a count they report is not certified (one line on stderr);
// 4 the output files (-o, --svg, a scene's) were written, then stdout failed (one line naming the
// files and the stdout error; the files stay: they are complete);
// killed by SIGPIPE (shell status 141) when the reader of stdout goes away; 1 only for an
// internal error (a bug).
#include "cli_common.hpp"
#include "dwell_input.hpp"
#include "png_output.hpp"
#include "urdf_input.hpp"
#ifdef SPHTROCH_HAVE_STEP
#include "step_output.hpp"
#endif

#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/version.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>

namespace {

using namespace sphtroch::cli;

/// The message as one line: control characters (a newline in a key, a path) escaped.
std::string one_line(const std::string& message) { return sphtroch::one_line_text(message); }

int fail(const std::string& message) {
  std::cerr << "sphtroch: " << one_line(message) << "\n";
  return kBadInput;
}

/// The first argument names a command (anything not starting with '-'): refuse an unknown one by
/// name, with the list, instead of CLI11's "A subcommand is required".
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == argv[1]) return std::nullopt;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  return std::string(argv[1]) + ": not a command; valid: " + names + " (see sphtroch --help)";
}

/// Every command, also the nested ones (`synth identify`).
std::vector<const CLI::App*> all_commands(const CLI::App& app) {
  std::vector<const CLI::App*> out;
  for (const CLI::App* sub : app.get_subcommands({})) {
    out.push_back(sub);
    for (const CLI::App* nested : all_commands(*sub)) out.push_back(nested);
  }
  return out;
}

/// A flag written with a value ("--velocity=true"): flags take none.
std::optional<std::string> flag_with_value(const CLI::App& app, int argc, char** argv) {
  for (const CLI::App* sub : all_commands(app))
    for (const CLI::Option* opt : sub->get_options())
      if (opt->get_expected_max() == 0)
        for (const std::string& name : opt->get_lnames())
          for (int i = 1; i < argc; ++i)
            if (std::string(argv[i]).rfind("--" + name + "=", 0) == 0)
              return std::string(argv[i]) + ": --" + name + " is a flag and takes no value; valid: --" + name +
                     " alone, or leave it out";
  return std::nullopt;
}

/// "sphtroch synth fit": the names from the tool down to this command.
std::string command_path(const CLI::App& command) {
  std::string path = command.get_name();
  for (const CLI::App* a = command.get_parent(); a != nullptr; a = a->get_parent()) path = a->get_name() + " " + path;
  return path;
}

/// Edit distance (insertions, deletions, substitutions, swaps of neighbours) between two short words.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

/// The command the words name (the deepest parsed one), or the tool.
const CLI::App& parsed_command(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands({}))
    if (sub->parsed()) return parsed_command(*sub);
  return app;
}

/// For a word "--xyz" the command has no option for: "--xyz: not an option of sphtroch trace;
/// did you mean --samples?" (the nearest option within a third of its length), or nothing.
std::optional<std::string> misspelt_option(const CLI::App& app, int argc, char** argv) {
  const CLI::App& command = parsed_command(app);
  std::vector<std::string> names{"help"};
  for (const CLI::Option* opt : command.get_options())
    for (const std::string& name : opt->get_lnames()) names.push_back(name);
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") break;  // what follows is not an option
    if (word.rfind("--", 0) != 0 || word.size() < 3 || word[2] == '=') continue;
    const std::string name = word.substr(2, word.find('=') - 2);
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    std::string best;
    std::size_t best_distance = name.size() / 3 + 1;
    for (const std::string& n : names)
      if (const std::size_t d = edit_distance(name, n); d < best_distance) {
        best_distance = d;
        best = n;
      }
    const std::string path = command.get_parent() ? command_path(command) : "sphtroch";
    return "--" + name + ": not an option of " + path + (best.empty() ? "" : "; did you mean --" + best + "?") +
           " (see " + path + " --help)";
  }
  return std::nullopt;
}

/// An option given with an empty value ("--samples ''") is an error, never the default.
void check_no_empty_values(const CLI::App& app) {
  for (const CLI::App* sub : all_commands(app))
    for (const CLI::Option* opt : sub->get_options())
      if (opt->count() > 0 && opt->get_expected_min() > 0)
        for (const std::string& v : opt->results())
          if (v.empty())
            throw UsageError{opt->get_name() + " = \"\": an empty value; valid: see " + command_path(*sub) +
                             " --help (leave the option out for its default)"};
}

/// "sphtroch X.Y.Z (components: analysis yes|no, step yes|missing|no, png yes|missing|no, urdf
/// yes|missing|no, healpix yes|missing|no)": the optional components this build has: analysis
/// (CGAL: classify, nodes, plot, scene, synth points/fit), step (OpenCASCADE: trace -o
/// FILE.step), png (librsvg: plot -o FILE.png, atlas --svg FILE.png), urdf (urdfdom: chain
/// --urdf) and healpix (HEALPix: clinostat --coverage); "missing": built with it, but its plugin
/// file is not where the tool looks (plugin_loader.hpp), so that option is refused.
std::string version_text() {
#ifdef SPHTROCH_HAVE_ANALYSIS
  const char* analysis = "yes";
#else
  const char* analysis = "no";
#endif
#ifdef SPHTROCH_HAVE_STEP
  const char* step = sphtroch::cli::step_plugin_state();
#else
  const char* step = "no";
#endif
  const char* png = sphtroch::cli::png_plugin_state();
  return std::string("sphtroch ") + SPHTROCH_VERSION_STRING + " (components: analysis " + analysis + ", step " + step +
         ", png " + png + ", urdf " + sphtroch::cli::urdf_plugin_state() + ", healpix " + sphtroch::cli::healpix_plugin_state() + ")";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sphtroch " SPHTROCH_VERSION_STRING
               " - trajectories of spherical planetary gear trains (Lin & Tsai 1990)",
               "sphtroch"};
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  app.option_defaults()->disable_flag_override();  // --velocity=value is an error, not a value
  sphtroch::install_output_signal_cleanup();  // temporaries removed on stop and fault signals; EPIPE, not SIGPIPE
  std::vector<std::pair<CLI::App*, Action>> actions;
  register_trace(app, actions);
  register_atlas(app, actions);
  register_boundaries(app, actions);
  register_synth(app, actions);
#ifdef SPHTROCH_HAVE_ANALYSIS
  register_analysis(app, actions);
  register_scene(app, actions);
#endif
  register_clinostat(app, actions);
  register_chain(app, actions);
#ifdef SPHTROCH_HAVE_WRIST
  register_wrist(app, actions);
#endif
  register_completion(app, actions);  // last: its script lists the commands above
  if (const auto bad = unknown_command(app, argc, argv)) return fail(*bad);
  if (const auto bad = flag_with_value(app, argc, argv)) return fail(*bad);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    app.exit(e);
    return std::cout.flush() ? 0 : fail("--help: the help text could not be written to stdout");
  } catch (const CLI::CallForAllHelp& e) {
    app.exit(e);
    return std::cout.flush() ? 0 : fail("--help: the help text could not be written to stdout");
  } catch (const CLI::CallForVersion& e) {
    app.exit(e);
    return std::cout.flush() ? 0 : fail("--version: the version could not be written to stdout");
  } catch (const CLI::ExtrasError& e) {
    if (const auto bad = misspelt_option(app, argc, argv)) return fail(*bad);
    return fail(std::string(e.what()) + " (see sphtroch --help)");
  } catch (const CLI::RequiredError& e) {  // checked before the extras: "--inptu" leaves --input missing
    if (const auto bad = misspelt_option(app, argc, argv)) return fail(*bad);
    return fail(std::string(e.what()) + " (see sphtroch --help)");
  } catch (const CLI::ParseError& e) {
    return fail(std::string(e.what()) + " (see sphtroch --help)");
  }
  try {
    check_no_empty_values(app);
    for (auto& [command, action] : actions)
      if (command->parsed()) action();
  } catch (const sphtroch::BrokenPipe&) {
    // The reader went away (`| head`): end quietly, as a filter killed by SIGPIPE does, after the
    // temporaries are gone (the destructors have run).
    std::signal(SIGPIPE, SIG_DFL);
    std::raise(SIGPIPE);
    return 141;
  } catch (const sphtroch::OutputError& e) {
    return fail(e.what());
  } catch (const sphtroch::InvalidInput& e) {
    return fail("--" + e.message());
  } catch (const UsageError& e) {
    return fail(e.message);
  } catch (const StdoutFailedAfterOutputs& e) {
    std::cerr << "sphtroch: " << one_line(e.message) << "\n";
    return kStdoutFailedAfterOutputs;
  } catch (const UncertifiedResult& e) {
    std::cerr << "sphtroch: " << one_line(e.message) << "\n";
    return kUncertified;
  } catch (const std::bad_alloc&) {
    std::cerr << "sphtroch: out of memory; valid: a smaller problem (see docs/cli.md: Errors and limits)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "sphtroch: internal error: " << one_line(e.what()) << "\n";
    return 1;
  }
  return 0;
}
