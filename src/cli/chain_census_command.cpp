// sphtroch chain classify | nodes — the certified census of a rotation chain's curve
// (census/interval/chain_census.hpp): its nodes and cusps, as text or JSON
// (exact/chain_census_output.hpp), or as the nodes table of `sphtroch nodes` (io/node_csv.hpp,
// the t columns are the motor parameter s). Exit 3 after the output when it is not certified.
// k = 2 with both rates not 0 is the gear train a2 = A1, a3 = A2, n = N2 / N1, theta_p = P2 - n P1
// (theta2 = N1 s + P1): its nodes and cusps are the train's (`sphtroch classify`'s root and
// polyline censuses, with tangencies), their parameters mapped to s; the chain census of the
// train classify analyses (twists snapped onto a boundary within 1e-10, as classify reads them)
// runs beside them as a third census, and a certified chain census that disagrees leaves the
// answer not certified. For rates 1,n and phases 0,theta_p the table is `sphtroch nodes`'s, byte for byte.
#include "cli_common.hpp"

#include "sphtroch/census/interval/chain_census.hpp"
#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/exact/chain_census_output.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/node_csv.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

namespace sphtroch::cli {

namespace {

struct ChainCensusOptions {
  ChainText chain;
  std::string output, radius;
  bool json = false, degrees = false;
};

/// The gear train of a k = 2 chain with both rates not 0 (see top); nullopt when GearTrain refuses it.
std::optional<GearTrain> train_of(const RotationChain& chain) {
  if (chain.size() != 2 || chain.stages()[0].rate.is_zero() || chain.stages()[1].rate.is_zero()) return std::nullopt;
  const ChainStage& first = chain.stages()[0];
  const ChainStage& second = chain.stages()[1];
  std::int64_t p = second.rate.p() * first.rate.q(), q = second.rate.q() * first.rate.p();
  const std::int64_t g = std::gcd(p < 0 ? -p : p, q < 0 ? -q : q);
  p /= g, q /= g;
  try {
    const Ratio n(p, q);
    return GearTrain(first.twist, second.twist, n, second.phase - n.value() * first.phase);
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

/// theta2 of the train as s of the chain, in [0, period).
double chain_param(const RotationChain& chain, double theta2, double period) {
  const ChainStage& first = chain.stages()[0];
  const double s = (theta2 - first.phase) / first.rate.value();
  return chain_census_detail::reduce_param(s, period);
}

/// The chain of the train `classify` analyses: its twists as snapped onto a boundary within
/// 1e-10 (the default reading), the chain's rates and phases.
RotationChain analysed_chain(const RotationChain& chain, const GearTrain& analysed) {
  std::vector<ChainStage> stages = chain.stages();
  stages[0].twist = analysed.a2();
  stages[1].twist = analysed.a3();
  return RotationChain(stages);
}

/// The k = 2 census from the gear train's two censuses, checked by the chain census of the
/// analysed train (a smaller budget: a check only; a tangency's boxes may stay undecided).
ChainCensus train_census(const RotationChain& chain, const GearTrain& train) {
  const Analysis a(train);
  const ChainCensus check = chain_census(analysed_chain(chain, a.analysed()), kMaxChainBoxes / 10);
  ChainCensus c = check;
  c.method = "the gear train's root and polyline censuses (classify), checked by the chain census";
  c.nodes = a.nodes();
  for (Node& n : c.nodes) {
    for (double& t : n.params) t = chain_param(chain, t, c.period);
    std::sort(n.params.begin(), n.params.end());
  }
  c.cusps = a.cusps();
  for (Cusp& k : c.cusps) k.param = chain_param(chain, k.param, c.period);
  c.certified = a.certificate().certified;
  c.why = c.certified ? "" : "the gear train's censuses disagree: " + a.certificate().disagreement;
  if (c.certified && check.certified && (check.nodes.size() != c.nodes.size() || check.cusps.size() != c.cusps.size())) {
    c.certified = false;
    c.why = "the chain census finds " + std::to_string(check.nodes.size()) + " nodes and " + std::to_string(check.cusps.size()) +
            " cusps, the gear train's " + std::to_string(c.nodes.size()) + " and " + std::to_string(c.cusps.size());
  }
  return c;
}

/// The census `chain classify` and `chain nodes` print (see top).
ChainCensus census_of(const RotationChain& chain) {
  const std::optional<GearTrain> train = train_of(chain);
  return train ? train_census(chain, *train) : chain_census(chain);
}

void check_chain_certified(const ChainCensus& c) {
  if (!c.certified)
    throw UncertifiedResult{"chain: the census is not certified: " + c.why + " (exit status 3; see docs/chains.md)"};
}

void run_chain_classify(const ChainCensusOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {{o.chain.urdf, "--urdf"}});
  const RotationChain chain = o.chain.chain();
  const ChainCensus c = census_of(chain);
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
  const ChainCensus c = census_of(chain);
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
