// sphtroch chain classify | nodes — the certified census of a rotation chain's curve
// (exact/chain_classification.hpp): its nodes and cusps, as text or JSON
// (exact/chain_census_output.hpp), or as the nodes table of `sphtroch nodes` (io/node_csv.hpp,
// the t columns are the motor parameter s). Exit 3 after the output when it is not certified.
// The census is classify_chain's (exact/chain_classification.hpp): for k = 2 the gear train's,
// checked by the chain census; for rates 1,n and phases 0,theta_p the table is `sphtroch nodes`'s,
// byte for byte.
#include "cli_common.hpp"

#include "sphtroch/exact/chain_classification.hpp"
#include "sphtroch/exact/chain_census_output.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/node_csv.hpp"

namespace sphtroch::cli {

namespace {

struct ChainCensusOptions {
  ChainText chain;
  std::string output, radius;
  bool json = false, degrees = false;
};

void check_chain_certified(const ChainCensus& c) {
  if (!c.certified)
    throw UncertifiedResult{"chain: the census is not certified: " + c.why + " (exit status 3; see docs/chains.md)"};
}

void run_chain_classify(const ChainCensusOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const ChainCensus c = classify_chain(chain);
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
  const ChainCensus c = classify_chain(chain);
  write_output(o.output, [&](std::ostream& out) { write_nodes_csv(out, c.nodes, c.cusps, csv); });
  check_chain_certified(c);
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
    cmd->add_option("--radius", o->radius, "scale the positions x,y,z by R in [1e-100, 1e100]");
    cmd->add_flag("--degrees", o->degrees, "t1, t2 in degrees (header t1_deg,t2_deg)");
    add_output_option(*cmd, o->output, "the table");
    cmd->footer("t1, t2 are the first two branch parameters s (radians). Exit 3 when not certified.");
    actions.emplace_back(cmd, [o] { run_chain_nodes(*o); });
  }
}

}  // namespace sphtroch::cli
