// sphtroch wrist ik, wrist cap, wrist atlas — every inverse-kinematics solution of a geared spherical wrist with 2 motors
// (pointing its tool axis) or 3 (holding a frame), each certified the only root in its box, the
// list certified complete or exit 3 naming what is undecided (sphtroch/wrist/wrist_ik.hpp); text
// or --json (sphtroch/wrist/wrist_ik_output.hpp); the largest cap about a home direction with no
// fold of a 2-motor wrist inside, its radius a certified bracket, and the count inside it
// (sphtroch/wrist/wrist_cap.hpp, wrist_cap_output.hpp); the critical curve enclosed in cells and
// the fold polylines (sphtroch/wrist/wrist_atlas.hpp, wrist_atlas_output.hpp). CGAL's interval headers only (sphtroch::interval).
#include "cli_common.hpp"
#include "png_output.hpp"

#include "sphtroch/io/parse.hpp"
#include "sphtroch/wrist/wrist_atlas.hpp"
#include "sphtroch/wrist/wrist_atlas_output.hpp"
#include "sphtroch/wrist/wrist_cap.hpp"
#include "sphtroch/wrist/wrist_cap_output.hpp"
#include "sphtroch/wrist/wrist_ik.hpp"
#include "sphtroch/wrist/wrist_ik_output.hpp"
#include "sphtroch/wrist/wrist_regions.hpp"
#include "sphtroch/wrist/wrist_regions_output.hpp"
#include "sphtroch/wrist/wrist_regions_svg.hpp"
#include "sphtroch/wrist/wrist_text.hpp"

#include <cctype>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch::cli {

namespace {

struct WristIkOptions {
  WristText wrist;
  std::string output, width, sphere_cell, threads;
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

void run_wrist_cap(const WristIkOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {});
  const Wrist wrist = o.wrist.wrist();
  const Vector3d home = o.wrist.home_direction();
  const WristCapResult r = wrist_cap(wrist, home);  // refuses bad input and cost before any output
  write_output(o.output, [&](std::ostream& out) {
    if (o.json) out << wrist_cap_json(wrist, home, r).dump(2) << "\n";
    else out << wrist_cap_text(wrist, home, r);
  });
  if (!r.certified) throw UncertifiedResult{"wrist cap: not certified: " + r.why + " (exit status 3; see docs/wrists.md)"};
}

/// The options every wrist subcommand shares: the wrist itself.
void add_wrist_options(CLI::App& cmd, WristText& w) {
  cmd.add_option("--twists", w.twists, "A1,...,Ak: the twist after each joint, radians in [0, pi] (any angle form: pi/2), k <= 6")
      ->type_name("A1,...,Ak");
  cmd.add_option("--coupling", w.coupling, "the k x m coupling by rows: \"c11,c12;c21,c22;...\", exact (p/q, decimals, 0), rank m")
      ->type_name("C11,C12;C21,C22;...");
  cmd.add_option("--phases", w.phases, "P1,...,Pk: each joint's angle with every motor at 0, radians (default all 0)")->type_name("P1,...,Pk");
  cmd.add_option("--axis", w.axis, "the tool axis X,Y,Z in the last body (default 0,0,1; pointing only)")->type_name("X,Y,Z");
}

void register_wrist_cap(CLI::App& wrist, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<WristIkOptions>();
  CLI::App* cmd = wrist.add_subcommand("cap", "the largest cap about a home direction with no fold inside (2 motors), certified, and its IK count");
  add_wrist_options(*cmd, o->wrist);
  cmd->add_option("--home", o->wrist.home, "X,Y,Z: the cap's centre, a unit vector")->type_name("X,Y,Z");
  cmd->add_flag("--json", o->json, "print one JSON object instead of text");
  add_output_option(*cmd, o->output, "the report");
  cmd->footer("The fold: det[P, dP/du1, dP/du2] = 0. The radius is the angle from home to the nearest fold point, a bracket\n"
              "[lower, upper] of width <= 1e-9 rad (interval branch and bound, fold points proved by the Krawczyk test);\n"
              "the count is wrist ik's at home. Exit 3 when the bracket or the count is not certified. 2 motors only;\n"
              "refused up front when the torus needs more than " + number_text(kMaxWristStartBoxes) + " start boxes (docs/wrists.md).\n"
              "Example: sphtroch wrist cap --twists 0,1,0.5 --coupling \"1,0;0,1;0,2\" --home 0.6,0,0.8 --json");
  actions.emplace_back(cmd, [o] { run_wrist_cap(*o); });
}

/// --width as typed: a finite number ("" = the default); its range is wrist_fold_atlas's.
double atlas_width(const std::string& text) {
  if (text.empty()) return kWristAtlasDefaultWidth;
  const std::optional<double> w = detail::strict_double(detail::trim(text));
  if (!w) throw InvalidInput("width", text, "not a finite number", "radians of joint motion per cell, 0.001 to 1 (default 0.05)");
  return *w;
}

/// --sphere-cell as typed: a finite number ("" = the default); its range is wrist_regions's.
double sphere_cell(const std::string& text) {
  if (text.empty()) return kWristRegionsDefaultStep;
  const std::optional<double> w = detail::strict_double(detail::trim(text));
  if (!w) throw InvalidInput("sphere-cell", text, "not a finite number", "radians per sphere cell, 0.003 to 0.5 (default 0.02)");
  return *w;
}

/// Whether the output's name ends in .svg or .png (any case): the picture instead of the report.
bool picture_output(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".svg" || tail == ".png";
}

void run_wrist_atlas(const WristIkOptions& o) {
  check_distinct_files({{o.output, "--output"}}, {});
  const bool picture = picture_output(o.output);
  if (picture) check_svg_name(o.output, "output");  // a .png needs the PNG plugin (refused up front without it)
  const Wrist wrist = o.wrist.wrist();
  const double step = sphere_cell(o.sphere_cell);
  check_wrist_regions_cost(step);
  const double width = atlas_width(o.width);
  const std::size_t threads = parse_threads(o.threads);
  const WristAtlasResult r = wrist_fold_atlas(wrist, width);  // refuses bad input and cost before any output
  const WristRegionsResult regions = wrist_regions(wrist, r, step, threads);
  const std::string bytes = picture ? picture_bytes(wrist_regions_svg(r, regions), o.output) : std::string();
  write_output(
      o.output,
      [&](std::ostream& out) {
        if (picture) {
          out << bytes;
        } else if (o.json) {
          out << wrist_atlas_report_json(wrist, r, regions).dump(2) << "\n";
        } else {
          out << wrist_atlas_text(wrist, r) << wrist_regions_text(regions);
        }
      },
      "--output", picture ? kPictureOutputs : kTextOutputs);
  if (!r.certified) throw UncertifiedResult{"wrist atlas: not certified: " + r.why + " (exit status 3; see docs/wrists.md)"};
  if (!regions.certified) throw UncertifiedResult{"wrist atlas: regions not certified: " + regions.why + " (exit status 3; see docs/wrists.md)"};
}

void register_wrist_atlas(CLI::App& wrist, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<WristIkOptions>();
  CLI::App* cmd = wrist.add_subcommand("atlas", "the critical curve det = 0 on the motor torus (2 motors), certified cells, and the fold polylines");
  add_wrist_options(*cmd, o->wrist);
  cmd->add_option("--width", o->width, "the cells' size, radians of joint motion (0.001 to 1; default 0.05)")->type_name("RAD");
  cmd->add_option("--sphere-cell", o->sphere_cell, "the sphere grid's cell size for the regions, radians (0.003 to 0.5; default 0.02)")
      ->type_name("RAD");
  cmd->add_option("--threads", o->threads, "worker threads for the regions' counts (1 .. 1024; default: all cores)")->type_name("N");
  cmd->add_flag("--json", o->json, "print one JSON object instead of text");
  add_output_option(*cmd, o->output, "the report; a name ending in .svg (or .png) gets the picture (regions by count, folds, legend)");
  cmd->footer("Every cell of the motor torus where det[P, dP/du1, dP/du2] may vanish (all others proved det != 0), a fold\n"
              "point proved in each by the Krawczyk test, and the fold set drawn as polylines through them; the regions of\n"
              "the sphere the folds cut out (grid cells proved fold-free, joined through edges), each with wrist ik's\n"
              "certified count at one interior point, the workspace (count > 0) and voids. Exit 3 when a cell has no\n"
              "proved point or a region stays undecided. 2 motors only; refused up front beyond " +
              number_text(kMaxWristAtlasCells) + " torus cells or " + number_text(kMaxWristRegionCells) + " sphere cells (docs/wrists.md).\n"
              "Example: sphtroch wrist atlas --twists 0,1,0.5 --coupling \"1,0;0,1;0,2\" --json; ... -o atlas.svg");
  actions.emplace_back(cmd, [o] { run_wrist_atlas(*o); });
}

}  // namespace

void register_wrist(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  CLI::App* wrist = app.add_subcommand("wrist", "a geared spherical wrist with 2 or 3 motors: its inverse kinematics (wrist ik), its fold-free cap about home (wrist cap), its fold curve (wrist atlas)");
  wrist->require_subcommand(1);
  auto o = std::make_shared<WristIkOptions>();
  CLI::App* cmd = wrist->add_subcommand("ik", "every motor-angle solution pointing the tool (2 motors) or holding a frame (3), certified");
  add_wrist_options(*cmd, o->wrist);
  cmd->add_option("--target", o->wrist.target, "X,Y,Z: point the tool axis along this unit vector (2 motors)")->type_name("X,Y,Z");
  cmd->add_option("--target-frame", o->wrist.target_frame,
                  "hold this frame (3 motors): a unit quaternion w,x,y,z or a rotation matrix by rows (9 numbers)")
      ->type_name("W,X,Y,Z|R11,...,R33");
  cmd->add_flag("--json", o->json, "print one JSON object instead of text");
  add_output_option(*cmd, o->output, "the report");
  cmd->footer("theta_i = sum_j C_ij u_j + P_i, F(u) = Rz(theta_1) Rx(A1) ... Rz(theta_k) Rx(Ak), P(u) = F(u) axis.\n"
              "Every solution u on the motor torus [0, 2 pi L_1) x ... (L_j the lcm of column j's denominators),\n"
              "each proved the only root in its box by the Krawczyk test; exit 3 when a box stays undecided\n"
              "(a target on a fold: a double root). Refused up front when the torus needs more than " +
              number_text(kMaxWristStartBoxes) + " start boxes (docs/wrists.md).\n"
              "Example: sphtroch wrist ik --twists 0,1,0.5 --coupling \"1,0;0,1;0,2\" --target 0.6,0,0.8 --json");
  actions.emplace_back(cmd, [o] { run_wrist_ik(*o); });
  register_wrist_cap(*wrist, actions);
  register_wrist_atlas(*wrist, actions);
}

}  // namespace sphtroch::cli
