// sphtroch atlas | atlas-merge — the classification map over (a2, a3) (atlas.hpp), its CSV
// (atlas_csv.hpp), shard slices joined back together, and the SVG map (atlas_svg.hpp).
// Eigen only: this translation unit must not include CGAL.
#include "cli_common.hpp"
#include "png_output.hpp"

#include "sphtroch/io/train_text.hpp"

#include "sphtroch/atlas/atlas.hpp"
#include "sphtroch/atlas/atlas_boundary_check.hpp"
#include "sphtroch/atlas/atlas_csv.hpp"
#include "sphtroch/atlas/atlas_slices.hpp"
#include "sphtroch/atlas/atlas_summary.hpp"
#include "sphtroch/atlas/atlas_svg.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/io/parse.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace sphtroch::cli {

namespace {

struct AtlasOptions {
  std::string n, teeth, grid, a2 = "0:pi", a3 = "0:pi", threads, shard, output, svg;
  bool literal = false, degrees = false;
};

struct MergeOptions {
  std::vector<std::string> slices;
  std::string output, svg;
  bool degrees = false;
};

/// --degrees changes the map only.
void check_degrees_with_svg(bool degrees, const std::string& svg) {
  if (degrees && svg.empty())
    throw UsageError{"--degrees: only the map (--svg) is drawn in degrees, the CSV and summary stay in radians; "
                     "valid: --degrees with --svg FILE.svg"};
}

/// Every cell centre must be a valid twist, strictly inside (0, pi): a range too narrow for the
/// grid (0:4.9e-324) would put centres at 0. Named by the range as typed.
void check_cell_centres(const AtlasSpec& spec, const AtlasOptions& o) {
  const double pi = Constants<double>::pi();
  auto check = [&](double (AtlasSpec::*at)(std::size_t) const, const std::string& text, const char* field) {
    bool ok = (spec.*at)(0) > 0.0 && (spec.*at)(spec.grid - 1) < pi;
    for (std::size_t k = 1; ok && k < spec.grid; ++k) ok = (spec.*at)(k - 1) < (spec.*at)(k);
    if (!ok)
      throw InvalidInput(field, text, "too narrow for the grid: its cell centres are not distinct angles in (0, pi)",
                         std::string(kAngleRangeForms) + ", wide enough for distinct cell centres");
  };
  check(&AtlasSpec::a2_at, o.a2, "a2");
  check(&AtlasSpec::a3_at, o.a3, "a3");
  for (std::size_t i = 0; i < spec.grid; ++i) {  // the carrier-twist bounds of GearTrain, per a2 row
    try {
      GearTrain::on_cone(spec.a2_at(i), A3Reference::pitch_cone, 0.0, spec.ratio);
    } catch (const InvalidInput& e) {
      throw InvalidInput("a2", o.a2, "its cell centre a2 = " + number_text(spec.a2_at(i)) + " is " + e.problem(),
                         e.valid_range());
    }
  }
}

/// Fails early (before any computing) when `path`'s directory cannot take a new file.
void check_writable(const std::string& path, const std::string& option) {
  if (path.empty() || path == "-") return;
  const auto slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw UsageError{option + " = " + path + ": cannot be written (" + std::strerror(errno) +
                     "); valid: a path in an existing, writable directory"};
}

/// After every output: an atlas whose counts are not certified ends the tool with status 3.
void check_atlas_certified(const AtlasSummary& summary, const AtlasBoundaryCheck* check) {
  const std::string why = atlas_uncertified(summary, check);
  if (!why.empty())
    throw UncertifiedResult{"the atlas is not certified: " + why + " (exit status 3; see docs/cli.md: Certified counts)"};
}

/// The map; with `degrees` its axes in degrees (--degrees).
std::string write_svg_text(const AtlasSpec& spec, const std::vector<AtlasCell>& cells, bool degrees) {
  AtlasSvgOptions options;
  options.degrees = degrees;
  return render_atlas_svg(spec, cells, options);
}

/// The paths of `paths` that name files (not empty, not stdout).
std::vector<std::string> written_files(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const std::string& p : paths)
    if (!p.empty() && p != "-") out.push_back(p);
  return out;
}

/// The atlas CSV (-o) and map (--svg): both appear or neither; then the summary (on stderr when the
/// CSV goes to stdout).
void write_atlas_outputs(const std::string& csv, const std::string& svg_path, const std::string& svg,
                         const std::function<void(std::ostream&)>& write_csv,
                         const std::function<void(std::ostream&)>& write_summary) {
  StagedOutputs outputs;
  if (!csv.empty()) outputs.stage(csv, "--output", write_csv);
  if (!svg_path.empty()) outputs.stage(svg_path, "--svg", [&](std::ostream& out) { out << svg; }, kPictureOutputs);
  outputs.commit();
  if (csv == "-") {
    write_summary(std::cerr);
    std::cerr.flush();
  } else {
    write_stdout_after_outputs(written_files({csv, svg_path}), write_summary);
  }
}

/// "\ratlas  37% (6062/16384 cells)" on stderr when it is a terminal; nothing otherwise.
AtlasProgress progress_bar() {
  if (!::isatty(STDERR_FILENO)) return {};
  return [](std::size_t done, std::size_t total) {
    const unsigned pct = total ? static_cast<unsigned>(100.0 * static_cast<double>(done) / static_cast<double>(total)) : 100;
    std::fprintf(stderr, "\ratlas %3u%% (%zu/%zu cells)", pct, done, total);
    if (done >= total) std::fprintf(stderr, "\r%*s\r", 60, "");
    std::fflush(stderr);
  };
}

void run_atlas(const AtlasOptions& o) {
  check_degrees_with_svg(o.degrees, o.svg);
  AtlasSpec spec;
  const TrainText n_text{"", "", o.n, "0", o.teeth};  // --n, or --teeth ZS:ZP (kept and echoed)
  spec.ratio = n_text.ratio();
  if (!o.teeth.empty()) spec.teeth = parse_teeth(o.teeth, "teeth");
  spec.grid = parse_count(o.grid, "grid", 1, kAtlasMaxGrid);
  spec.a2 = parse_angle_range(o.a2, "a2");
  spec.a3 = parse_angle_range(o.a3, "a3");
  spec.reading.literal = o.literal;
  check_cell_centres(spec, o);
  spec.validate();
  const unsigned hw = std::thread::hardware_concurrency();
  const std::size_t threads =
      o.threads.empty() ? std::max<std::size_t>(1, std::min<std::size_t>(hw, kAtlasMaxThreads))
                        : parse_count(o.threads, "threads", 1, kAtlasMaxThreads);
  std::optional<AtlasShard> shard;
  if (!o.shard.empty()) shard = parse_shard(o.shard, spec.grid, "grid (" + std::to_string(spec.grid) + ")");
  if (shard && !o.svg.empty())
    throw UsageError{"--svg = " + o.svg + ": cannot be combined with --shard = " + o.shard +
                     "; valid: draw the whole atlas (sphtroch atlas-merge --svg FILE slices...)"};
  check_writable(o.output, "--output");
  check_svg_name(o.svg, "svg");
  check_writable(o.svg, "--svg");
  check_distinct_files({{o.output, "--output"}, {o.svg, "--svg"}}, {});

  const AtlasRows rows = shard ? shard_rows(spec.grid, *shard) : AtlasRows{0, spec.grid};
  const auto start = std::chrono::steady_clock::now();
  const std::vector<AtlasCell> cells = compute_atlas(spec, rows, threads, progress_bar());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string svg = o.svg.empty() ? std::string() : picture_bytes(write_svg_text(spec, cells, o.degrees), o.svg);
  const AtlasSummary summary = summarize_atlas(cells, spec.ratio);
  const AtlasBoundaryCheck check = check_atlas_boundaries(spec, cells, threads);
  write_atlas_outputs(
      o.output, o.svg, svg, [&](std::ostream& out) { write_atlas_csv(out, spec, shard, cells); },
      [&](std::ostream& out) {
        write_atlas_summary(out, spec, summary, listed_disagreements(summary, cells), AtlasRun{rows, shard, seconds, threads});
        write_atlas_boundary_check(out, check, cells);
        write_atlas_certificate(out, summary, &check);
      });
  check_atlas_certified(summary, &check);
}

/// A slice that cannot be read as a file: a usage error naming it.
UsageError unreadable_slice(const UnreadableSlice& e) {
  return UsageError{"atlas-merge: slice = " + e.path() + ": " + e.problem() +
                    "; valid: a readable CSV written by sphtroch atlas"};
}

/// Joins the slices in shard order: the merged CSV streamed row by row (memory: one block and
/// one line per slice read, not the grid); with --svg the cells are also kept for the map
/// (56 bytes per cell). On standard output every slice is checked whole before the first byte.
void run_merge(const MergeOptions& o) {
  check_degrees_with_svg(o.degrees, o.svg);
  check_svg_name(o.svg, "svg");
  check_writable(o.output, "--output");
  check_writable(o.svg, "--svg");
  std::vector<NamedFile> inputs;
  for (const std::string& s : o.slices) inputs.push_back({s, "slice"});
  check_distinct_files({{o.output, "--output"}, {o.svg, "--svg"}}, inputs);
  if (std::count(o.slices.begin(), o.slices.end(), std::string("-")) > 1)
    throw UsageError{"atlas-merge: slice = -: standard input given twice; valid: each slice once, at most one as -"};
  try {
    const std::vector<AtlasSlice> sources = open_atlas_slices(o.slices);
    std::vector<AtlasCsvHead> heads;
    for (const AtlasSlice& s : sources) heads.push_back(s.head);
    const std::vector<std::size_t> order = atlas_slice_order(heads);
    const AtlasSpec& spec = heads.front().spec;

    AtlasSummary summary;
    std::vector<AtlasCell> listed, all;
    auto pass = [&](std::ostream* out) {
      summary = AtlasSummary{};
      listed.clear();
      all.clear();
      if (out) *out << atlas_csv_comment(spec) << '\n' << kAtlasCsvHeader << '\n';
      std::size_t k = 0;
      for (std::size_t at : order)
        for_each_atlas_row(sources[at], [&](const AtlasCell& c, std::string_view line) {
          const std::size_t before = summary.disagreement_count;
          add_to_summary(summary, c, k++, spec.ratio, 0);
          if (summary.disagreement_count > before && listed.size() < kMaxListedDisagreements) listed.push_back(c);
          if (!o.svg.empty()) all.push_back(c);
          if (out) out->write(line.data(), static_cast<std::streamsize>(line.size())).put('\n');
        });
    };
    StagedOutputs outputs;
    if (o.output.empty() || o.output == "-") pass(nullptr);  // every check before stdout sees a byte
    if (!o.output.empty()) outputs.stage(o.output, "--output", [&](std::ostream& out) { pass(&out); });
    if (!o.svg.empty())
      outputs.stage(o.svg, "--svg", [&](std::ostream& out) { out << picture_bytes(write_svg_text(spec, all, o.degrees), o.svg); }, kPictureOutputs);
    outputs.commit();
    auto write_summary = [&](std::ostream& out) {
      write_atlas_summary(out, spec, summary, listed, AtlasRun{AtlasRows{0, spec.grid}, std::nullopt, std::nullopt, 1});
      write_atlas_certificate(out, summary, nullptr);
    };
    if (o.output == "-") {
      write_summary(std::cerr);
      std::cerr.flush();
    } else {
      write_stdout_after_outputs(written_files({o.output, o.svg}), write_summary);
    }
    check_atlas_certified(summary, nullptr);
  } catch (const UnreadableSlice& e) {
    throw unreadable_slice(e);
  } catch (const InvalidInput& e) {
    throw UsageError{std::string("atlas-merge: ") + e.what()};
  }
}

}  // namespace

void register_atlas(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<AtlasOptions>();
  CLI::App* cmd = app.add_subcommand(
      "atlas", "classification map over (a2, a3): node/cusp census per cell vs the report's criteria (CSV, SVG)");
  cmd->footer(
      "Cells are sampled at their centres a = LO + (k + 1/2)(HI - LO)/G. Per cell: the root-count\n"
      "node census and the cusps (as `classify` reads the train), and the report's prediction\n"
      "(Eq. 24 for n = 1, Eqs. 43/46 for n = 2, pitch cone for every n). Without -o only a summary\n"
      "is printed; -o - writes the CSV to stdout and the summary to stderr.\n"
      "Shards: --shard I/K (1 <= I <= K <= G) computes rows [(I-1)G/K, IG/K) of a2; join the\n"
      "slices with `sphtroch atlas-merge -o atlas.csv slice*.csv` (byte-identical to one run).\n"
      "Example: sphtroch atlas --n 2 --grid 128 -o atlas.csv --svg atlas.svg");
  CLI::Option* ratio = cmd->add_option("--n", o->n, "gear ratio n = p/q, p != 0: 2, 5/2, 2.5 (or --teeth)")->type_name("P/Q");
  CLI::Option* gears =
      cmd->add_option("--teeth", o->teeth, "n as tooth counts ZS:ZP, sun:planet (39:15 is n = 13/5; echoed next to n)")->type_name("ZS:ZP");
  ratio->excludes(gears);
  gears->excludes(ratio);
  cmd->add_option("--grid", o->grid, "G: G x G cells (1 .. 4096)")->type_name("G")->required();
  cmd->add_option("--a2", o->a2, "a2 range LO:HI, 0 <= LO < HI <= pi (default 0:pi)")->type_name("LO:HI");
  cmd->add_option("--a3", o->a3, "a3 range LO:HI, 0 <= LO < HI <= pi (default 0:pi)")->type_name("LO:HI");
  cmd->add_option("--threads", o->threads, "worker threads (1 .. 1024; default: all cores)")->type_name("N");
  cmd->add_option("--shard", o->shard, "compute slice I of K (1 <= I <= K <= G) for a batch job array")->type_name("I/K");
  cmd->add_flag("--literal", o->literal, "analyse the cell centres as given (no snapping onto boundaries)");
  cmd->add_option("-o,--output", o->output,
                  "write the CSV to FILE (never left partial; - for stdout); without it only the summary")->type_name("FILE");
  cmd->add_option("--svg", o->svg, "draw the map to FILE.svg (not with --shard)")->type_name("FILE.svg");
  cmd->add_flag("--degrees", o->degrees, "the map's axes in degrees (the CSV stays in radians: atlas-merge reads it)");
  actions.emplace_back(cmd, [o] { run_atlas(*o); });

  auto m = std::make_shared<MergeOptions>();
  CLI::App* merge = app.add_subcommand("atlas-merge", "join atlas shard slices into the unsharded atlas (CSV, SVG)");
  merge->footer(
      "Slices in any order; refuses slices of different atlases, a missing or repeated shard.\n"
      "Example: sphtroch atlas-merge -o atlas.csv --svg atlas.svg slice-*.csv");
  merge->add_option("slices", m->slices, "slice CSV files written by sphtroch atlas --shard I/K")->type_name("FILE")->required();
  merge->add_option("-o,--output", m->output,
                    "write the merged CSV to FILE (never left partial; - for stdout); without it only the summary")->type_name("FILE");
  merge->add_option("--svg", m->svg, "draw the merged map to FILE.svg")->type_name("FILE.svg");
  merge->add_flag("--degrees", m->degrees, "the map's axes in degrees");
  actions.emplace_back(merge, [m] { run_merge(*m); });
}

}  // namespace sphtroch::cli
