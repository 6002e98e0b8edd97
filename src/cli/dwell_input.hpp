// src/cli/dwell_input.hpp — the tool's dwell maps (clinostat --coverage, --plot; clinostat design
// --coverage): HEALPix lives in the HEALPix plugin (healpix_plugin.cpp), which the tool opens only
// when a command asks for a dwell map (plugin_loader.hpp), so that every other call loads neither
// HEALPix nor cfitsio and the network libraries it brings.
#pragma once

#include "sphtroch/core/types.hpp"
#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/dwell_map_result.hpp"

#include <string>
#include <vector>

namespace sphtroch::cli {

/// dwell_map's contract (machine/dwell_map.hpp) through the plugin. Throws InvalidInput as it
/// does, UsageError when the plugin is missing or broken, InvalidInput("coverage") in a build
/// without HEALPix.
DwellMap dwell_map_by_plugin(const ClinostatSettings& machine, double start_s, double duration_s, int nside);

/// cell_outlines' contract (machine/dwell_map.hpp) through the plugin.
std::vector<std::vector<Vector3d>> cell_outlines_by_plugin(int nside, int steps = 4);

/// Refuses up front, before any work: InvalidInput(option) in a build without HEALPix, UsageError
/// when its plugin is missing or cannot be opened (it is opened now, as a dwell map would).
void require_dwell_maps(const std::string& option, const std::string& value);

/// For --version: "yes" (the plugin file present), "missing", or "no" (a build without HEALPix).
const char* healpix_plugin_state() noexcept;

}  // namespace sphtroch::cli
