// src/cli/reports.hpp — the printers of the analysis commands, shared by `sphtroch classify`,
// `nodes`, `plot` and `sphtroch scene` so that a scene's outputs are the commands' bytes.
// Defined in analysis_commands.cpp; the declarations need no CGAL.
#pragma once

#include "cli_common.hpp"

#include "sphtroch/node.hpp"
#include "sphtroch/sampling.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace sphtroch {
struct Classification;
struct ZExtremes;
}  // namespace sphtroch

namespace sphtroch::cli {

/// `classify --json`; `text` holds the angles as the user wrote them (a2_text, a3_text).
nlohmann::json classification_json(const TrainOptions& text, const Classification& c);
/// `classify` (text report).
void write_classification_text(std::ostream& out, const TrainOptions& text, const Classification& c);
/// `nodes`: kind,x,y,z,t1,t2,branches — node rows, then cusp rows.
void write_nodes_csv(std::ostream& out, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps);
/// The "z_extremes" object of `classify --json`.
nlohmann::json z_extremes_json(const ZExtremes& z);
/// `plot`: the SVG of the analysed train's plot trajectory with nodes, cusps and the caption.
std::string plot_svg(const TrainOptions& text, const GearTrain& analysed, const Trajectory<double>& trajectory,
                     const std::vector<Node>& nodes, const std::vector<Cusp>& cusps);

}  // namespace sphtroch::cli
