// sphtroch/wrist/wrist_cap_output.hpp — a wrist's fold-free cap about home (wrist_cap.hpp) as JSON
// and as text, for `sphtroch wrist cap` and every front end that reports it.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   sphtroch::WristCapResult r;   // from sphtroch::wrist_cap(wrist, home)
//   nlohmann::json j = sphtroch::wrist_cap_json(wrist, sphtroch::Vector3d(0, 0, 1), r);   // the schema below
//   std::string t = sphtroch::wrist_cap_text(wrist, sphtroch::Vector3d(0, 0, 1), r);      // for people
//
// JSON: "home" [x, y, z] (as normalised), "radius" {"lower", "upper", "width"} (radians: the
// angle from home to the nearest fold point lies in [lower, upper]), "certified", "home_on_fold"
// (lower = 0: home may lie on a fold, the cap may be a point), "count" (inverse-kinematics
// solutions at every direction inside the cap: wrist ik's certified count at home; null when not
// certified), "nearest_fold_point" [x, y, z] (unit; the fold point proved, at an angle <= upper
// from home; null when none was proved), "motors" [u_1, u_2] (its motor angles, radians in
// [0, T_j); null with it), "motors_radius" (the point with D = 0 lies within it of "motors", each
// motor), "wrist" (as wrist ik's), "certificate" {"method", "why" ("" when certified), "boxes",
// "ik_boxes"}. Numbers are doubles printed to round-trip.
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_cap_result.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"  // wrist_json, wrist_tuple_text

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace sphtroch {

inline nlohmann::json wrist_cap_json(const Wrist& wrist, const Vector3d& home, const WristCapResult& r) {
  const Vector3d h = home.normalized();
  nlohmann::json j;
  j["home"] = {h.x(), h.y(), h.z()};
  j["radius"] = {{"lower", r.lower}, {"upper", r.upper}, {"width", r.upper - r.lower}};
  j["certified"] = r.certified;
  j["home_on_fold"] = r.home_on_fold;
  j["count"] = r.count ? nlohmann::json(*r.count) : nlohmann::json(nullptr);
  j["nearest_fold_point"] = r.has_fold_point ? nlohmann::json(r.fold_point) : nlohmann::json(nullptr);
  j["motors"] = r.has_fold_point ? nlohmann::json(r.fold_motors) : nlohmann::json(nullptr);
  j["motors_radius"] = r.has_fold_point ? nlohmann::json(r.fold_motor_radius) : nlohmann::json(nullptr);
  j["wrist"] = wrist_json(wrist, r.periods);
  j["certificate"] = {{"method", "best-first interval branch and bound over the motor torus: boxes where det[P, dP/du1, dP/du2] "
                                 "excludes 0 or whose angle bound exceeds the best proved fold point discarded; fold points "
                                 "proved by the Krawczyk test on a line; count by wrist ik at home"},
                      {"why", r.why},
                      {"boxes", r.boxes},
                      {"ik_boxes", r.ik_boxes}};
  return j;
}

inline std::string wrist_cap_text(const Wrist& wrist, const Vector3d& home, const WristCapResult& r) {
  const Vector3d h = home.normalized();
  std::ostringstream out;
  out << "wrist: " << wrist.joints() << " joints, " << wrist.motors() << " motors, coupling " << wrist.coupling_text() << ", periods "
      << wrist_tuple_text(r.periods) << "\n";
  out << "home: " << wrist_tuple_text({h.x(), h.y(), h.z()}) << "\n";
  out << "cap radius: in [" << number_text(r.lower) << ", " << number_text(r.upper) << "] rad, " << number_text(r.upper - r.lower)
      << " wide" << (r.radius_certified ? " (certified: no fold point nearer than the lower end, one proved within the upper)" : " (NOT certified)")
      << "\n";
  if (r.has_fold_point)
    out << "nearest fold point: " << wrist_tuple_text({r.fold_point[0], r.fold_point[1], r.fold_point[2]}) << " at u = "
        << wrist_tuple_text({r.fold_motors[0], r.fold_motors[1]}) << " within " << number_text(r.fold_motor_radius) << "\n";
  if (r.home_on_fold) out << "home is on a fold (within " << number_text(r.upper) << " rad of one): the cap may be a point\n";
  if (r.count) out << "count inside the cap: " << *r.count << " (wrist ik at home, certified)\n";
  else if (r.home_on_fold) out << "count inside the cap: none (home on a fold: wrist ik at home has a double root)\n";
  else out << "count inside the cap: not known (wrist ik at home is not certified)\n";
  if (!r.certified) out << "NOT certified: " << r.why << "\n";
  return out.str();
}

}  // namespace sphtroch
