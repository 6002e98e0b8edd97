// Tests of certified_census.hpp and node_sets.hpp (issue 17): a printed node count is one that
// the polyline census and the independent root-count census agree on, or it is marked
// uncertified. Expected counts come from the root-count census (an independent method: a count
// of integer crossings of a 1D function, no sampling; the issue's own independent computation
// gives the same 832 for D1) and from invariants (a node has >= 2 branches; the phase only
// rotates the curve, Eq. 8).
#include "catch2/catch.hpp"

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/exact/certified_census.hpp"
#include "sphtroch/census/node_sets.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/census/root_census.hpp"

#include <string>
#include <vector>

using namespace sphtroch;

namespace {

/// The train as the CLI reads it ("pi-ap-1e-9" is a reference to the mirror cone).
GearTrain train_of(const std::string& n, const std::string& a2, const std::string& a3, double phase = 0.0) {
  TrainText text{a2, a3, n};
  text.phase = number_text(phase);
  return text.train();
}

void require_real_nodes(const std::vector<Node>& nodes) {
  for (const Node& n : nodes) {
    CHECK(n.branches >= 2);
    CHECK(n.params.size() == n.branches);
  }
}

}  // namespace

TEST_CASE("certified: D1 near_mirror_cone_52_35: no one-branch nodes, the count of the root census (832)",
          "[certified][hard][D1]") {
  // sphtroch classify --n 52/35 --a2 2.8907926475352435 --a3 pi-ap-1e-9 printed 845 with exit 0.
  const GearTrain train = train_of("52/35", "2.8907926475352435", "pi-ap-1e-9");
  const RootCensus root = root_census(train);
  REQUIRE(root.nodes.size() == 832);  // 16 roots x 52 (root_census.hpp), as computed independently
  const CertifiedCensus c = certified_census(train, {}, root);
  require_real_nodes(c.polyline.nodes);
  CHECK(c.certificate.certified);
  CHECK(c.polyline.nodes.size() == 832);
}

TEST_CASE("certified: D1 near_pitch_cone_-53_60: the same certified count at every phase", "[certified][hard][D1][phase]") {
  // 3136 nodes at phase 0 and 3133 at phase 866761.2414597012 before; root count 3127.
  for (double phase : {0.0, 866761.2414597012, -1e6, 0.5}) {
    INFO("phase " << phase);
    const GearTrain train = train_of("-53/60", "1.648984287094461", "ap+1e-9", phase);
    const RootCensus root = root_census(train);
    const CertifiedCensus c = certified_census(train, {}, root);
    require_real_nodes(c.polyline.nodes);
    CHECK(c.certificate.certified);
    CHECK(c.polyline.nodes.size() == root.nodes.size());
    CHECK(root.nodes.size() == 3127);  // the root census does not see the phase (Eq. 8)
  }
}

TEST_CASE("certified: escalation: a census too coarse at 1024 samples is certified one level up", "[certified][escalation]") {
  // n = 13/5 at a3 = pi - a_p - 1e-3: 221 nodes, loops near the cusp parameters; 1024 uniform
  // samples are about 5 per node. Whatever the first run finds, the certificate may only say
  // "certified" with the root census's node points, and every run is listed.
  const GearTrain train = train_of("13/5", "1.2", "pi-ap+1e-3");
  const RootCensus root = root_census(train);
  PolylineCensusSettings s;
  s.samples = 1024;
  const CertifiedCensus c = certified_census(train, s, root);
  REQUIRE(c.certificate.runs() >= 1);
  CHECK(c.certificate.samples.front() == 1024);
  for (std::size_t k = 1; k < c.certificate.runs(); ++k) CHECK(c.certificate.samples[k] == 4 * c.certificate.samples[k - 1]);
  CHECK(c.certificate.polyline_nodes.back() == c.polyline.nodes.size());
  std::string why;
  CHECK(c.certificate.certified == same_node_sets(c.polyline.nodes, root.nodes, why));
  CHECK(c.certificate.certified);
  require_real_nodes(c.polyline.nodes);
}

TEST_CASE("certified: a disagreement that escalation cannot remove is uncertified, with every run listed",
          "[certified][escalation][uncertified]") {
  // A root census with one node removed stands for a census that will never agree: the
  // certificate must say uncertified after kMaxCensusEscalations further runs, never certify.
  const GearTrain train = train_of("2", "pi/3", "pi/2");
  RootCensus root = root_census(train);
  REQUIRE(root.nodes.size() == 4);  // Table 1 row (f): 4 nodes (Eqs. 43 and 46 hold strictly)
  root.nodes.pop_back();
  PolylineCensusSettings s;
  s.samples = 1024;
  const CertifiedCensus c = certified_census(train, s, root);
  CHECK_FALSE(c.certificate.certified);
  CHECK(c.certificate.runs() == 1 + kMaxCensusEscalations);
  CHECK(c.certificate.samples == std::vector<std::size_t>{1024, 4096, 16384});
  CHECK(c.certificate.polyline_nodes == std::vector<std::size_t>{4, 4, 4});
  CHECK(c.certificate.root_nodes == 3);
  CHECK(c.certificate.disagreement == "4 vs 3 node points");
  CHECK_FALSE(c.certificate.stopped.empty());
}

TEST_CASE("certified: escalation stops before the sample bound", "[certified][escalation][cost]") {
  const GearTrain train = train_of("2", "pi/3", "pi/2");
  RootCensus root = root_census(train);
  root.nodes.clear();
  PolylineCensusSettings s;
  s.samples = kMaxEscalatedSamples / 2;  // one level up would be 2x the bound
  const CertifiedCensus c = certified_census(train, s, root);
  CHECK_FALSE(c.certificate.certified);
  CHECK(c.certificate.runs() == 1);
  CHECK(c.certificate.stopped.find("beyond the escalation bound") != std::string::npos);
}

TEST_CASE("certified: the analysis marks its classification, nodes and plot by the certificate", "[certified][analysis]") {
  const Analysis a(train_of("52/35", "2.8907926475352435", "pi-ap-1e-9"));
  CHECK(a.certificate().certified);
  const Classification& c = a.classification();
  CHECK(c.certified());
  CHECK(c.certificate.root_nodes == c.root.nodes.size());
  CHECK(c.nodes.size() == c.root.nodes.size());
}

TEST_CASE("certified: same_node_sets pairs nearest nodes one to one, by kind and branch count", "[certified][node_sets]") {
  Node a, b;
  a.position = Vector3d(0, 0, 1);
  a.branches = 2;
  b = a;
  b.position = Vector3d(0, 1e-9, 1).normalized();
  std::string why;
  CHECK(same_node_sets({a}, {b}, why));
  b.kind = NodeKind::tangency;
  CHECK_FALSE(same_node_sets({a}, {b}, why));
  CHECK(why.find("no match for the crossing node") == 0);
  b.kind = NodeKind::crossing;
  b.position = Vector3d(0, 1e-7, 1).normalized();  // beyond kAgreementDistance
  CHECK_FALSE(same_node_sets({a}, {b}, why));
  CHECK_FALSE(same_node_sets({a, a}, {b}, why));
  CHECK(why == "2 vs 1 node points");
}
