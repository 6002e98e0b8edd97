// src/cli/reports.hpp — compatibility only: the printers of the analysis commands moved to the
// library (sphtroch/report.hpp: classification text and JSON, z extremes JSON, the plot caption
// and SVG; sphtroch/csv_io.hpp: the nodes CSV). Code that included this header and called
// sphtroch::cli::classification_json(options, c) still compiles: TrainOptions is an InputText.
// New code: include the library headers and call sphtroch::classification_json(InputText, c).
#pragma once

#include "cli_common.hpp"

#include "sphtroch/csv_io.hpp"
#include "sphtroch/report.hpp"

namespace sphtroch::cli {

using sphtroch::classification_json;
using sphtroch::plot_svg;
using sphtroch::write_classification_text;
using sphtroch::write_nodes_csv;
using sphtroch::z_extremes_json;

}  // namespace sphtroch::cli
