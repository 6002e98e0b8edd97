// sphtroch boundaries — the boundary set of the (a2, a3) map (boundary_events.hpp): the events at
// one a2 (text or JSON), or the boundary curves over an a2 range as CSV. Parsing and printing
// only; the formats are boundary_events_output.hpp's.
#include "cli_common.hpp"

#include "sphtroch/map/boundary_events_output.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/train_text.hpp"

namespace sphtroch::cli {

namespace {

struct BoundariesOptions {
  std::string n, teeth, a2 = "0:pi", steps, threads, output;
  bool json = false, degrees = false;
};

const char* const kA2Forms = "one angle in (0, pi) (1.2, pi/2, 90deg) for the events, or LO:HI with 0 <= LO < HI <= pi for the curves";

/// The work of run_boundaries; a refusal that names n names --teeth when the ratio was given as teeth.
void boundaries_of(const BoundariesOptions& o, const Ratio& n);

void run_boundaries(const BoundariesOptions& o) {
  const Ratio n = ratio_of(o.n, o.teeth);  // --n, or --teeth ZS:ZP
  try {
    boundaries_of(o, n);
  } catch (const InvalidInput& e) {
    if (o.teeth.empty() || e.field() != "n") throw;
    throw InvalidInput("teeth", o.teeth, "n = " + e.value() + ": " + e.problem(), e.valid_range());
  }
}

void boundaries_of(const BoundariesOptions& o, const Ratio& n) {
  const auto colon = o.a2.find(':');
  if (colon == std::string::npos) {  // one a2: the events
    if (!o.steps.empty())
      throw UsageError{"--steps = " + o.steps + ": only for the curves over an a2 range; valid: --a2 LO:HI with --steps"};
    const double a2 = parse_angle(o.a2, "a2");
    if (!(a2 > 0.0 && a2 < Constants<double>::pi())) throw InvalidInput("a2", o.a2, "outside the valid range", kA2Forms);
    const BoundarySet s = boundary_set(a2, n);
    if (o.json && o.degrees)
      throw UsageError{"--degrees: the JSON is in radians; valid: --degrees with the text or the CSV"};
    write_output(o.output,
                 [&](std::ostream& out) { o.json ? write_boundary_json(out, s) : write_boundary_text(out, s, o.degrees); });
    return;
  }
  if (o.json)
    throw UsageError{"--json: the curves over an a2 range are CSV; valid: --json with one --a2 angle, or leave it out"};
  const AngleRange a2 = parse_angle_range(o.a2, "a2", kA2Forms);
  const std::size_t steps = o.steps.empty() ? 720 : parse_count(o.steps, "steps", 1, kMaxLocusSteps);
  const std::size_t threads = parse_threads(o.threads);
  const std::vector<Locus> loci = boundary_loci(n, a2.lo, a2.hi, steps, threads);
  write_output(o.output, [&](std::ostream& out) { write_loci_csv(out, n, a2.lo, a2.hi, steps, loci, o.degrees); });
}

}  // namespace

void register_boundaries(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<BoundariesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "boundaries", "where the node count changes in a3: pitch cones, poles, self-tangency loci (any n)");
  cmd->footer(
      "One a2 (--a2 A): every a3 in (0, pi) where the census changes, ascending, with its kind\n"
      "(pitch_cone, pole, tangency), a3 to 1e-12 rad and the node points just below and above\n"
      "(as classify counts them: crossings + tangencies). Text, or JSON with --json.\n"
      "An a2 range (--a2 LO:HI, default 0:pi): the boundary curves as CSV\n"
      "locus,kind,m,label,a2,a3,b at --steps a2 samples (cell centres; default 720, 1 .. 10000).\n"
      "Example: sphtroch boundaries --n 3 --a2 pi/2");
  CLI::Option* ratio = cmd->add_option("--n", o->n, "gear ratio n = p/q, p != 0: 3, 5/2, -5/2")->type_name("P/Q");
  CLI::Option* gears = cmd->add_option("--teeth", o->teeth, "n as tooth counts ZS:ZP, sun:planet (39:15 is n = 13/5)")->type_name("ZS:ZP");
  ratio->excludes(gears);
  gears->excludes(ratio);
  cmd->add_option("--a2", o->a2, "carrier twist: one angle (events) or LO:HI (curves; default 0:pi)")->type_name("RAD|LO:HI");
  cmd->add_flag("--degrees", o->degrees, "angles printed in degrees (text: a3 = ... deg; CSV: a2_deg,a3_deg,b_deg)");
  cmd->add_flag("--json", o->json, "the events as JSON (one a2 only)");
  cmd->add_option("--steps", o->steps, "a2 samples of the curves (1 .. 10000; default 720)")->type_name("N");
  cmd->add_option("--threads", o->threads, "worker threads for the curves (1 .. 1024; default: cores)")->type_name("N");
  add_output_option(*cmd, o->output, "the events or the curves");
  actions.emplace_back(cmd, [o] { run_boundaries(*o); });
}

}  // namespace sphtroch::cli
