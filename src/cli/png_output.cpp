// The SVG of plot / atlas as PNG: rendered by the PNG plugin (png_plugin.cpp, librsvg + cairo;
// with SPHTROCH_HAVE_PNG, else .png is refused up front), opened only here (plugin_loader.hpp).
#include "png_output.hpp"

#if defined(SPHTROCH_HAVE_PNG)
#include "plugin_loader.hpp"
#endif

#include <cctype>
#include <stdexcept>

namespace sphtroch::cli {

namespace {

#if defined(SPHTROCH_HAVE_PNG)
/// The MODULE sphtroch_png (file name set in src/cli/CMakeLists.txt).
constexpr OutputPlugin kPngPlugin{"sphtroch_png.so", "PNG", "librsvg",
                                  "FILE.svg (convert it, e.g. rsvg-convert FILE.svg -o FILE.png)"};

std::string png_from_svg(const std::string& svg, const std::string& path) { return run_output_plugin(kPngPlugin, path, svg); }
#else
std::string png_from_svg(const std::string&, const std::string&) {  // unreachable: check_svg_name refuses .png here
  throw std::runtime_error("PNG: this build of sphtroch has no librsvg component");
}
#endif

}  // namespace

bool names_png(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".png";
}

const char* png_plugin_state() noexcept {
#if defined(SPHTROCH_HAVE_PNG)
  return output_plugin_state(kPngPlugin);
#else
  return "no";
#endif
}

void require_png_writer(const std::string& path, const std::string& field) {
#if defined(SPHTROCH_HAVE_PNG)
  if (names_png(path)) require_output_plugin(kPngPlugin, "--" + field + " = " + path);
#else
  (void)path;
  (void)field;
#endif
}

std::string picture_bytes(const std::string& svg, const std::string& path) {
  return names_png(path) ? png_from_svg(svg, path) : svg;
}

}  // namespace sphtroch::cli
