// sphtroch chain classify | nodes | plot | boundaries — the certified census of a rotation chain's curve
// (exact/chain_classification.hpp): its nodes and cusps, as text or JSON
// (chain/chain_census_output.hpp), or as the nodes table of `sphtroch nodes` (io/node_csv.hpp,
// the t columns are the motor parameter s), or drawn on the sphere (chain_picture_svg). Exit 3 after
// the output when it is not certified.
// The census is classify_chain's (exact/chain_classification.hpp): for k = 2 the gear train's,
// checked by the chain census; for rates 1,n and phases 0,theta_p the table is `sphtroch nodes`'s,
// byte for byte. boundaries: where the census changes as one twist or phase varies
// (chain/chain_family_events.hpp); exit 3 after the report when not certified.
#include "cli_common.hpp"
#include "png_output.hpp"

#include "sphtroch/chain/chain_family_events.hpp"
#include "sphtroch/exact/chain_classification.hpp"
#include "sphtroch/chain/chain_census_output.hpp"
#include "sphtroch/chain/chain_picture.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/node_csv.hpp"

namespace sphtroch::cli {

namespace {

struct ChainCensusOptions {
  ChainText chain;
  std::string output, radius;
  bool json = false, degrees = false;
  PlotFlags plot;  // plot only
};

/// classify_chain of the chain as read; a chain read from --urdf that the census refuses (a tool
/// axis that does not move) is refused naming --urdf, the option the user gave.
ChainCensus census_of(const ChainText& text, const RotationChain& chain) {
  try {
    return classify_chain(chain);
  } catch (const InvalidInput& e) {
    if (text.urdf.empty()) throw;
    throw InvalidInput("urdf", text.urdf + " (" + e.field() + " " + e.value() + ")", e.problem(), e.valid_range());
  }
}

void check_chain_certified(const ChainCensus& c) {
  if (!c.certified)
    throw UncertifiedResult{"chain: the census is not certified: " + c.why + " (exit status 3; see docs/chains.md)"};
}

void run_chain_classify(const ChainCensusOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const ChainCensus c = census_of(o.chain, chain);
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << chain_census_json(chain, c).dump(2) << "\n";
    else out << chain_census_text(chain, c);
  });
  check_chain_certified(c);
}

void run_chain_nodes(const ChainCensusOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const NodesCsvOptions csv{parse_radius(o.radius), o.degrees};  // checked before the work
  const ChainCensus c = census_of(o.chain, chain);
  write_output(o.output, [&](std::ostream& out) { write_nodes_csv(out, c.nodes, c.cusps, csv); });
  check_chain_certified(c);
}

/// The chain's curve (chain_plot_sample_count samples over the period) with the census's nodes
/// and cusps: SVG, or PNG for FILE.png.
void run_chain_plot(const ChainCensusOptions& o) {
  check_svg_name(o.output, "output");
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const PlotOptions options = o.plot.options();  // checked before the work
  const ChainCensus c = census_of(o.chain, chain);
  const std::string bytes = picture_bytes(chain_picture_svg(chain, c, options, &o.chain), o.output);
  write_output(o.output, [&](std::ostream& out) { out << bytes; }, "--output", kPictureOutputs);
  check_chain_certified(c);
}

struct ChainBoundariesOptions {
  ChainText chain;
  std::string vary, output;
  bool json = false;
};

/// chain boundaries --vary NAME:LO:HI: where the census changes along one family.
void run_chain_boundaries(const ChainBoundariesOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const ChainEvents events = chain_family_events(chain, parse_chain_vary(o.vary, chain.size()));
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) write_chain_events_json(out, chain, events);
    else write_chain_events_text(out, chain, events);
  });
  if (!events.certified)
    throw UncertifiedResult{"chain boundaries: not certified: " + events.why + " (exit status 3; see docs/chains.md)"};
}

}  // namespace

void register_chain_census(CLI::App& chain, std::vector<std::pair<CLI::App*, Action>>& actions) {
  {
    auto o = std::make_shared<ChainCensusOptions>();
    CLI::App* cmd = chain.add_subcommand("classify", "the chain's nodes and cusps, certified (text or --json)");
    add_chain_options(*cmd, o->chain);
    cmd->add_flag("--json", o->json, "print one JSON object instead of text (the node schema of classify --json)");
    add_output_option(*cmd, o->output, "the report");
    cmd->footer("Nodes: P(s) = P(t), s != t over the period, by interval branch and bound with the Krawczyk test;\n"
                "cusps: |P'| within 1e-7 sum |N_i| of 0 (docs/chains.md). Exit 3 when not certified.\n"
                "Example: sphtroch chain classify --twists pi/2,1.2,0.4 --rates 1,-2/3,5/3 --json");
    actions.emplace_back(cmd, [o] { run_chain_classify(*o); });
  }
  {
    auto o = std::make_shared<ChainCensusOptions>();
    CLI::App* cmd = chain.add_subcommand("nodes", "the chain's nodes and cusps as CSV kind,x,y,z,t1,t2,branches,id");
    add_chain_options(*cmd, o->chain);
    cmd->add_option("--radius", o->radius, "scale the positions x,y,z by R in [1e-100, 1e100]")->type_name("R");
    cmd->add_flag("--degrees", o->degrees, "t1, t2 in degrees (header t1_deg,t2_deg)");
    add_output_option(*cmd, o->output, "the table");
    cmd->footer("t1, t2 are the first two branch parameters s (radians). Exit 3 when not certified.");
    actions.emplace_back(cmd, [o] { run_chain_nodes(*o); });
  }
  {
    auto o = std::make_shared<ChainCensusOptions>();
    CLI::App* cmd = chain.add_subcommand("plot", "the chain's curve on the sphere as SVG (or PNG), nodes and cusps marked");
    add_chain_options(*cmd, o->chain);
    o->plot.add_to(*cmd);
    add_output_option(*cmd, o->output, "the picture (FILE.svg, or FILE.png with the librsvg component)");
    cmd->footer("The census of chain classify; labels N<i>, C<j> are the rows of `sphtroch chain nodes`.\n"
                "Exit 3, after the picture (its caption says NOT CERTIFIED), when the census is not certified.\n"
                "Example: sphtroch chain plot --twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 -o wrist.svg");
    actions.emplace_back(cmd, [o] { run_chain_plot(*o); });
  }
  {
    auto b = std::make_shared<ChainBoundariesOptions>();
    CLI::App* cmd = chain.add_subcommand("boundaries", "where the chain's census changes as one twist or phase varies (--vary)");
    add_chain_options(*cmd, b->chain);
    cmd->add_option("--vary", b->vary, "NAME:LO:HI: the twist Ai or phase Pi varied over [LO, HI] radians (A2:0:pi)")
        ->type_name("NAME:LO:HI")->required();
    cmd->add_flag("--json", b->json, "the events as JSON");
    add_output_option(*cmd, b->output, "the events");
    cmd->footer("Closed forms: P1 of any chain and P2 of a two-stage chain (no event: the curve turns about z);\n"
                "A2 of a two-stage chain (the gear train's boundaries: pitch cones, poles, self-tangencies).\n"
                "Every other family: one certified census per slab of the range, failed slabs halved to " +
                report_number(kChainEventWidth) + " rad,\n"
                "then bisected with the census at single values: cusp births, self-tangencies and triple points\n"
                "within the stated accuracy (docs/chains.md).\n"
                "Exit 3, after the report, when not certified.\n"
                "Example: sphtroch chain boundaries --twists pi/2,1 --rates 1,3 --vary A2:0:pi");
    actions.emplace_back(cmd, [b] { run_chain_boundaries(*b); });
  }
}

}  // namespace sphtroch::cli
