// An Eigen-only consumer (sphtroch::sphtroch, configured with CGAL hidden): report Fig. 3
// (a2 = a3 = pi/2, n = 1). The curve passes through the node of Eq. 25, (0, sin a3, cos a3) =
// (0, 1, 0), at theta2 = +-pi/2; classify_roots finds that one node and no cusp.
#include <sphtroch/sphtroch.hpp>

#ifdef SPHTROCH_HAVE_EXACT
#error "this consumer must build without sphtroch::exact"
#endif

#include <cmath>
#include <cstdio>

int main() {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig3(pi / 2, pi / 2, sphtroch::Ratio(1));
  const sphtroch::TracerCurve<double> curve(fig3);
  const Eigen::Vector3d node = curve.point(pi / 2);
  const sphtroch::RootClassification c = sphtroch::classify_roots(fig3);
  std::printf("P(pi/2) = (%.17g, %.17g, %.17g); %s, %zu node(s), %zu cusp(s)\n", node.x(), node.y(), node.z(),
              sphtroch::to_string(c.curve_class), c.nodes, c.cusps);
  const bool ok = (node - Eigen::Vector3d(0, 1, 0)).norm() < 1e-15 && c.nodes == 1 && c.cusps == 0 &&
                  c.node_points.size() == 1 && (c.node_points[0].position - Eigen::Vector3d(0, 1, 0)).norm() < 1e-12;
  return ok ? 0 : 1;
}
