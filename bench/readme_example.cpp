// The README's C++ example as a program (bench/consumer_compile.sh compiles it through both
// routes): report Fig. 5(f) classified (four nodes) and one period sampled at 720 points.
#include <sphtroch/classify.hpp>        // classify() (its definition: sphtroch::compiled, or the headers)
#include <sphtroch/core/sampling.hpp>   // sample_period()

int main() {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig5f(pi / 3, pi / 2, sphtroch::Ratio(2));    // report Fig. 5(f)
  const sphtroch::Classification c = sphtroch::classify(fig5f);           // c.nodes.size() == 4
  const auto trajectory = sphtroch::sample_period(sphtroch::TracerCurve<double>(fig5f), 720);
  return c.nodes.size() == 4 && trajectory.points.size() == 720 ? 0 : 1;
}
