// PNG pictures of `sphtroch plot -o FILE.png` and `sphtroch atlas --svg FILE.png`: the tool's SVG
// rendered by librsvg + cairo in the PNG plugin (png_plugin.cpp, in a build with PNG:
// SPHTROCH_HAVE_PNG), which the tool opens only when it writes a PNG (plugin_loader.hpp).
#pragma once

#include <string>

namespace sphtroch::cli {

/// Whether `path` ends in .png (any case).
bool names_png(const std::string& path);

/// For --version: "yes" (a build with PNG, the plugin file present), "missing" (with PNG, the
/// file absent), "no" (a build without PNG).
const char* png_plugin_state() noexcept;

/// Opens the PNG plugin now when `path` ends in .png (a build with PNG), so that a missing plugin
/// is refused before the work: UsageError "--<field> = <path>: PNG is written by the plugin ...".
void require_png_writer(const std::string& path, const std::string& field);

/// What to write for a picture to `path`: the SVG itself, or its PNG rendering when `path` ends
/// in .png (at the SVG's own size in pixels, white where the SVG is). REQUIRES: a .png path only
/// in a build with PNG (check_svg_name refuses it otherwise). Throws UsageError (naming `path`)
/// if the PNG plugin cannot be opened, std::runtime_error if librsvg cannot render the SVG.
std::string picture_bytes(const std::string& svg, const std::string& path);

}  // namespace sphtroch::cli
