// src/cli/cli_common.hpp — plumbing shared by the sphtroch commands: reading gear-train
// options, the one-line error contract (stderr, exit 2), and outputs through the library's one
// writer (sphtroch/io/output_file.hpp: stdout, devices and FIFOs directly; files through a
// temporary in the same directory, renamed when complete, so never left partial).
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <ostream>
#include <string>
#include <vector>

namespace sphtroch::cli {

/// Exit status for every kind of bad input.
constexpr int kBadInput = 2;

/// Exit status when a count, position or class printed is not certified (the outputs are
/// complete and say so; sphtroch::kUncertifiedExitStatus).
constexpr int kUncertified = 3;

/// Exit status when the output files (-o, --svg, a scene's) were written and committed, but
/// standard output (the summary, the explanation) then failed: the files are complete and stay.
constexpr int kStdoutFailedAfterOutputs = 4;

/// Raised for kStdoutFailedAfterOutputs: one line "outputs written: A, B; stdout failed: ...".
struct StdoutFailedAfterOutputs {
  std::string message;
};

/// Writes to stdout after the files in `written` were committed: a failure of stdout (not a
/// closed pipe, which ends quietly as before) throws StdoutFailedAfterOutputs naming them; with
/// no file written it is the usual OutputError (exit 2).
void write_stdout_after_outputs(const std::vector<std::string>& written, const std::function<void(std::ostream&)>& write);

/// Raised by a command after its outputs are complete when what they report is not certified.
struct UncertifiedResult {
  std::string message;  // one line: what is not certified, both counts
};

/// Raised by commands for bad input not covered by InvalidInput (e.g. an unwritable path).
struct UsageError {
  std::string message;  // one line, already naming the option, the value and the valid range
};

/// The gear-train options every analysis command shares: the library's TrainText (values kept
/// as text, parsed by train() so that errors name the option exactly as typed; InvalidInput's
/// field is the option name without "--").
struct TrainOptions : TrainText {
  void add_to(CLI::App& command);
};

/// Adds "-o,--output FILE" to a command.
void add_output_option(CLI::App& command, std::string& path, const std::string& what);

/// The picture options of `plot` and `chain plot` as typed: --view, --size, --labels, --markers,
/// --style (draw/svg_plot.hpp: set_plot_view, parse_plot_labels, parse_plot_style;
/// draw/mark_density.hpp: parse_mark_mode). options() reads them (InvalidInput naming the option).
struct PlotFlags {
  std::string view, size, labels, markers, style;
  void add_to(CLI::App& command);
  PlotOptions options() const;
};

/// Refuses (InvalidInput `field`) an SVG output named as another picture format (.png, .pdf, ...
/// in any case): SVG bytes in a .png are a file no viewer opens. Other names pass.
void check_svg_name(const std::string& path, const std::string& field);

/// The formats of text outputs (reports, tables, JSON, SVG): an output named with one of these
/// suffixes, or with none, or with one that names no format, gets the command's text.
extern const std::vector<std::string> kTextOutputs;
/// The formats of pictures: SVG, or PNG rendered from it (png_output.hpp).
extern const std::vector<std::string> kPictureOutputs;

/// Refuses (InvalidInput naming `field`, exit 2, before any file is opened) an
/// output whose suffix (any case, of the file name) names a format (a list of data, CAD and picture
/// formats: .stl, .step, .png, .npy, .pdf, ...) that is not among `writes`: a command writes the
/// format its suffix names or refuses it, never another one silently. Empty `writes`: no check
/// (a caller that validates its outputs' formats itself, as a scene does).
void check_output_suffix(const std::string& path, const std::string& field, const std::vector<std::string>& writes);

/// Writes text produced by `write` to stdout (path empty or "-"), or to `path` (see
/// OutputFile: a file appears complete or not at all). `field` names the option in errors;
/// `writes` the formats its suffix may name (check_output_suffix, checked first).
/// Validate before calling: on stdout the bytes go out as they are written.
void write_output(const std::string& path, const std::function<void(std::ostream&)>& write,
                  const std::string& field = "--output", const std::vector<std::string>& writes = kTextOutputs);

/// Several outputs that appear together or not at all (commit_together): stage() writes each;
/// commit() puts them all in place; the destructor removes every temporary not committed.
class StagedOutputs {
 public:
  void stage(const std::string& path, const std::string& field, const std::function<void(std::ostream&)>& write,
             const std::vector<std::string>& writes = kTextOutputs);
  /// The file of a stage, for writers that stream into it directly.
  OutputFile& open(const std::string& path, const std::string& field);
  void commit();

 private:
  std::vector<std::unique_ptr<OutputFile>> files_;
};

/// A name for the file a path reaches, equal for every alias of it (symlinks, "dir/../x",
/// hard links): "dev:ino" of an existing file, else "dev:ino/name" of its existing directory;
/// empty for stdout ("-" or "") and for paths whose directory does not exist.
std::string file_key(const std::string& path);

/// file_key of an input; for "-" the identity of standard input when it is a regular file
/// (`--input - -o in.csv < in.csv` must not replace what it reads), else empty.
std::string input_key(const std::string& path);

/// A file a command names on its command line or in a scene.
struct NamedFile {
  std::string path, field;  // field: "--output", "trains[0].effects.trace", ...
};

/// Throws UsageError when an output reaches an input or another output under any alias
/// (an output must never replace what the command reads, nor another output).
void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

/// Counts and count pairs are read by io/parse.hpp (one reader for every front end).
using sphtroch::parse_count;
using sphtroch::parse_count_pair;

/// Every number the tool writes in data (files, tables, JSON, plugin fields) is sphtroch::number_text
/// (core/number_text.hpp: the shortest form that reads back as the same double); in sentences for
/// people (text reports, help) report_number (the same digits: 0.0001, 1e-5, 0 for -0); measured
/// times in text reports are seconds_text.
using sphtroch::number_text;
using sphtroch::report_number;
using sphtroch::seconds_text;

/// The worker threads of a command: `text` ("" = all cores, capped at kMaxThreads) as a count.
constexpr std::size_t kMaxThreads = 1024;
std::size_t parse_threads(const std::string& text);
/// --radius: empty = 1, else a finite number > 0 (the cone distance, any unit); InvalidInput "radius".
double parse_radius(const std::string& text);

/// Registers a subcommand's action; main() runs the selected one and maps errors to exit codes.
using Action = std::function<void()>;
void register_trace(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_atlas(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);  // atlas, atlas-merge
void register_boundaries(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_synth(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);  // synth identify
void register_clinostat(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);  // clinostat_command.cpp
void register_clinostat_design(CLI::App& clinostat, std::vector<std::pair<CLI::App*, Action>>& actions);  // design, merge
void register_chain(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);  // chain trace (chain_command.cpp)
/// --twists, --rates, --phases of every chain subcommand, into the library's reader.
void add_chain_options(CLI::App& cmd, ChainText& chain);
#ifdef SPHTROCH_HAVE_WRIST
/// `wrist ik` (wrist_command.cpp; CGAL's interval headers, sphtroch::interval).
void register_wrist(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
#endif
/// `completion bash|zsh`: register it last, so that its script lists every command (completion_command.cpp).
void register_completion(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
#ifdef SPHTROCH_HAVE_ANALYSIS
void register_analysis(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_scene(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions);
void register_synth_points(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions);  // synth points, merge, fit
void register_synth_fit(CLI::App& synth, std::vector<std::pair<CLI::App*, Action>>& actions);  // synth_fit_command.cpp
void register_chain_census(CLI::App& chain, std::vector<std::pair<CLI::App*, Action>>& actions);  // chain classify, nodes
/// `synth merge` of synth fit shards (their texts already read), synth_fit_command.cpp.
void run_fit_merge(const std::vector<std::string>& paths, const std::vector<std::string>& texts, const std::string& output);
/// Parses and validates a scene's text as `sphtroch scene` does, without touching the file system
/// (output paths unchecked, nothing computed); returns the number of trains. Throws UsageError
/// (one line) for anything wrong. For tests/fuzz.
std::size_t validate_scene_text(const std::string& text);
#endif

}  // namespace sphtroch::cli
