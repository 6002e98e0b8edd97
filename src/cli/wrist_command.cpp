// sphtroch wrist ik — every inverse-kinematics solution of a geared spherical wrist with 2 motors
// (pointing its tool axis) or 3 (holding a frame), each certified the only root in its box, the
// list certified complete or exit 3 naming what is undecided (sphtroch/wrist/wrist_ik.hpp); text
// or --json (sphtroch/wrist/wrist_ik_output.hpp). CGAL's interval headers only (sphtroch::interval).
#include "cli_common.hpp"

#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"
#include "sphtroch/wrist/wrist_text.hpp"

#include <memory>

namespace sphtroch::cli {

namespace {

struct WristIkOptions {
  WristText wrist;
  std::string output;
  bool json = false;
};

void run_wrist_ik(const WristIkOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {});
  const Wrist wrist = o.wrist.wrist();
  const WristTarget target = o.wrist.wrist_target(wrist);
  check_wrist_ik_cost(wrist);  // refused before any output
  const WristIkResult r = wrist_ik(wrist, target);
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << wrist_ik_json(wrist, target, r).dump(2) << "\n";
    else out << wrist_ik_text(wrist, target, r);
  });
  if (!r.certified) throw UncertifiedResult{"wrist ik: not certified: " + r.why + " (exit status 3; see docs/wrists.md)"};
}

}  // namespace

void register_wrist(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  CLI::App* wrist = app.add_subcommand("wrist", "a geared spherical wrist with 2 or 3 motors: its inverse kinematics (wrist ik)");
  wrist->require_subcommand(1);
  auto o = std::make_shared<WristIkOptions>();
  CLI::App* cmd = wrist->add_subcommand("ik", "every motor-angle solution pointing the tool (2 motors) or holding a frame (3), certified");
  cmd->add_option("--twists", o->wrist.twists, "A1,...,Ak: the twist after each joint, radians in [0, pi] (any angle form: pi/2), k <= 6");
  cmd->add_option("--coupling", o->wrist.coupling, "the k x m coupling by rows: \"c11,c12;c21,c22;...\", exact (p/q, decimals, 0), rank m");
  cmd->add_option("--phases", o->wrist.phases, "P1,...,Pk: each joint's angle with every motor at 0, radians (default all 0)");
  cmd->add_option("--axis", o->wrist.axis, "the tool axis X,Y,Z in the last body (default 0,0,1; pointing only)");
  cmd->add_option("--target", o->wrist.target, "X,Y,Z: point the tool axis along this unit vector (2 motors)");
  cmd->add_option("--target-frame", o->wrist.target_frame,
                  "hold this frame (3 motors): a unit quaternion w,x,y,z or a rotation matrix by rows (9 numbers)");
  cmd->add_flag("--json", o->json, "print one JSON object instead of text");
  add_output_option(*cmd, o->output, "the report");
  cmd->footer("theta_i = sum_j C_ij u_j + P_i, F(u) = Rz(theta_1) Rx(A1) ... Rz(theta_k) Rx(Ak), P(u) = F(u) axis.\n"
              "Every solution u on the motor torus [0, 2 pi L_1) x ... (L_j the lcm of column j's denominators),\n"
              "each proved the only root in its box by the Krawczyk test; exit 3 when a box stays undecided\n"
              "(a target on a fold: a double root). Refused up front when the torus needs more than " +
              number_text(kMaxWristStartBoxes) + " start boxes (docs/wrists.md).\n"
              "Example: sphtroch wrist ik --twists 0,1,0.5 --coupling \"1,0;0,1;0,2\" --target 0.6,0,0.8 --json");
  actions.emplace_back(cmd, [o] { run_wrist_ik(*o); });
}

}  // namespace sphtroch::cli
