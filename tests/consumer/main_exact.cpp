// A consumer of COMPONENTS exact (sphtroch::exact): the exact crossing search on a sampled
// trajectory of report Fig. 3 finds the one node of Eq. 24/25 as one crossing of two edges, and
// classify() agrees, and its JSON report (classification_output.hpp, nlohmann-json through sphtroch::exact) says
// so. Built also against sphtroch::sphtroch alone, where it must not compile
// (run_consumer.cmake checks the #error names sphtroch::exact).
#include <sphtroch/exact/self_crossings.hpp>
#include <sphtroch/sphtroch.hpp>

#include <cstdio>

int main() {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig3(pi / 2, pi / 2, sphtroch::Ratio(1));
  const sphtroch::TracerCurve<double> curve(fig3);
  const auto sampled = sphtroch::sample_period(curve, 1001);
  const sphtroch::SelfCrossings sc = sphtroch::find_self_crossings(sampled.points, /*closed=*/true);
  const sphtroch::Classification c = sphtroch::classify(fig3);
  std::printf("crossings: %zu, touchings: %zu; classify: %s, %zu node(s)\n", sc.crossings.size(), sc.touchings.size(),
              sphtroch::to_string(c.curve_class), c.nodes.size());
  const nlohmann::json report = sphtroch::classification_json(sphtroch::TrainText{"pi/2", "pi/2", "1"}, c);
  const bool report_ok = report["counts"]["nodes"] == 1 && report["inputs"]["a2_text"] == "pi/2";
  return sc.crossings.size() == 1 && c.nodes.size() == 1 && c.agreement.ok() && report_ok ? 0 : 1;
}
