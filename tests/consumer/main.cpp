// Report Fig. 3 (a2 = a3 = pi/2, n = 1): the curve passes through the node of Eq. 25,
// (0, sin a3, cos a3) = (0, 1, 0), at theta2 = +-acos(Eq. 22b) = +-pi/2.
#include <sphtroch/sphtroch.hpp>

#include <cmath>
#include <cstdio>

int main() {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig3(pi / 2, pi / 2, sphtroch::Ratio(1));
  const sphtroch::TracerCurve<double> curve(fig3);
  const Eigen::Vector3d node = curve.point(pi / 2);
  std::printf("P(pi/2) = (%.17g, %.17g, %.17g)\n", node.x(), node.y(), node.z());
  return (node - Eigen::Vector3d(0, 1, 0)).norm() < 1e-15 ? 0 : 1;
}
