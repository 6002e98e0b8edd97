// sphtroch/wrist/wrist_ik_output.hpp — a wrist's inverse kinematics (wrist_ik.hpp) as JSON and as
// text, for `sphtroch wrist ik` and every front end that reports it.
//
//   const sphtroch::Wrist wrist({{0.0, 0.0}, {1.0, 0.0}, {0.5, 0.0}},
//                               {{sphtroch::ChainRate(1), sphtroch::ChainRate(0)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(1)},
//                                {sphtroch::ChainRate(0), sphtroch::ChainRate(2)}});
//   const sphtroch::WristTarget target = sphtroch::WristTarget::pointing(sphtroch::Vector3d(0.6, 0, 0.8));
//   sphtroch::WristIkResult r;   // from sphtroch::wrist_ik(wrist, target)
//   nlohmann::json j = sphtroch::wrist_ik_json(wrist, target, r);   // the schema below
//   std::string t = sphtroch::wrist_ik_text(wrist, target, r);      // for people
//
// JSON: "count" (solutions listed), "certified", "on_fold", "solutions" [{"motors" [u_1, ...]
// (radians, motor j in [0, T_j)), "box_radius" (radians: the root is within it in every
// motor)}], "wrist" {"twists", "phases" (as reduced to [-pi, pi]), "coupling" (rows of exact
// "p/q"), "axis" (unit), "periods" [T_j]}, "target" {"kind": "pointing", "direction"} or
// {"kind": "orientation", "quaternion" [w, x, y, z], "matrix" (by rows)}, "certificate" {"method",
// "why" ("" when certified), "boxes", "undecided", "undecided_at" (at most 16 box centres)}.
// Numbers are doubles printed to round-trip (nlohmann-json's shortest form).
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/wrist/wrist.hpp"
#include "sphtroch/wrist/wrist_ik_result.hpp"
#include "sphtroch/wrist/wrist_target.hpp"

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace sphtroch {

/// The wrist block: twists, phases, coupling, axis and the periods T_j (radians).
inline nlohmann::json wrist_json(const Wrist& wrist, const std::vector<double>& periods) {
  nlohmann::json twists = nlohmann::json::array(), phases = nlohmann::json::array(), coupling = nlohmann::json::array();
  for (std::size_t i = 0; i < wrist.joints(); ++i) {
    twists.push_back(wrist.joint(i).twist);
    phases.push_back(wrist.joint(i).phase);
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t j = 0; j < wrist.motors(); ++j) row.push_back(wrist.coupling(i, j).str());
    coupling.push_back(row);
  }
  const Vector3d& a = wrist.axis();
  return {{"twists", twists}, {"phases", phases}, {"coupling", coupling}, {"axis", {a.x(), a.y(), a.z()}}, {"periods", periods}};
}

inline nlohmann::json wrist_json(const Wrist& wrist, const WristIkResult& r) { return wrist_json(wrist, r.periods); }

inline nlohmann::json wrist_target_json(const WristTarget& t) {
  if (t.kind == WristTarget::Kind::pointing)
    return {{"kind", "pointing"}, {"direction", {t.direction.x(), t.direction.y(), t.direction.z()}}};
  const Matrix3d m = t.rotation_matrix();
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) rows.push_back({m(i, 0), m(i, 1), m(i, 2)});
  return {{"kind", "orientation"}, {"quaternion", {t.rotation.w(), t.rotation.x(), t.rotation.y(), t.rotation.z()}}, {"matrix", rows}};
}

inline nlohmann::json wrist_ik_json(const Wrist& wrist, const WristTarget& target, const WristIkResult& r) {
  nlohmann::json j;
  j["count"] = r.solutions.size();
  j["certified"] = r.certified;
  j["on_fold"] = r.on_fold;
  nlohmann::json solutions = nlohmann::json::array();
  for (const WristSolution& s : r.solutions) solutions.push_back({{"motors", s.motors}, {"box_radius", s.box_radius}});
  j["solutions"] = solutions;
  j["wrist"] = wrist_json(wrist, r);
  j["target"] = wrist_target_json(target);
  j["certificate"] = {{"method", "interval branch and bound over the motor torus, each root proved unique in its box by the Krawczyk test"},
                      {"why", r.why},
                      {"boxes", r.boxes},
                      {"undecided", r.undecided},
                      {"undecided_at", r.undecided_at}};
  return j;
}

/// "(a, b, c)" of shortest round-trip numbers.
inline std::string wrist_tuple_text(const std::vector<double>& v) {
  std::string t;
  for (const double x : v) t += (t.empty() ? "" : ", ") + number_text(x);
  return "(" + t + ")";
}

inline std::string wrist_ik_text(const Wrist& wrist, const WristTarget& target, const WristIkResult& r) {
  std::ostringstream out;
  out << "wrist: " << wrist.joints() << " joints, " << wrist.motors() << " motors, coupling " << wrist.coupling_text() << ", periods "
      << wrist_tuple_text(r.periods) << "\n";
  if (target.kind == WristTarget::Kind::pointing)
    out << "target: the tool axis along " << wrist_tuple_text({target.direction.x(), target.direction.y(), target.direction.z()}) << "\n";
  else
    out << "target: the frame of the quaternion (w, x, y, z) = "
        << wrist_tuple_text({target.rotation.w(), target.rotation.x(), target.rotation.y(), target.rotation.z()}) << "\n";
  out << "solutions: " << r.solutions.size()
      << (r.certified ? " (certified: each the only root in its box, every other box of the torus excluded)"
                      : " found (NOT certified: " + r.why + ")")
      << "\n";
  std::size_t id = 0;
  for (const WristSolution& s : r.solutions)
    out << "  S" << ++id << "  u = " << wrist_tuple_text(s.motors) << "  within " << number_text(s.box_radius) << "\n";
  if (r.on_fold) out << "on a fold: a double root (singular Jacobian) is undecided\n";
  return out.str();
}

}  // namespace sphtroch
