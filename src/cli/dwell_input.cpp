// The tool's side of the HEALPix plugin (dwell_input.hpp): requests out, results back.
#include "dwell_input.hpp"

#include "clinostat_fields.hpp"
#include "plugin_fields.hpp"
#include "plugin_loader.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

namespace sphtroch::cli {

#if defined(SPHTROCH_HAVE_HEALPIX_PLUGIN)
namespace {

/// The MODULE sphtroch_healpix (file name set in src/cli/CMakeLists.txt).
constexpr OutputPlugin kHealpixPlugin{"sphtroch_healpix.so", "a dwell map", "HEALPix", "leave out --coverage", "computed"};

double number(const std::string& text) {
  const std::optional<double> v = detail::strict_double(text);
  if (!v) throw std::runtime_error("the HEALPix plugin's reply: not a number: " + text);
  return *v;
}

std::vector<double> doubles(const std::string& bytes) {
  if (bytes.size() % sizeof(double) != 0) throw std::runtime_error("the HEALPix plugin's reply: a partial double");
  std::vector<double> out(bytes.size() / sizeof(double));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

}  // namespace

DwellMap dwell_map_by_plugin(const ClinostatSettings& machine, double start_s, double duration_s, int nside) {
  std::vector<std::string> request = {"dwell"};
  for (std::string& f : clinostat_fields(machine)) request.push_back(std::move(f));
  request.insert(request.end(), {number_text(start_s), number_text(duration_s), std::to_string(nside)});
  const std::vector<std::string> f = split_fields(run_output_plugin(kHealpixPlugin, "--coverage", join_fields(request)), 8);
  DwellMap d;
  d.nside = static_cast<int>(number(f[0]));
  d.start_s = number(f[1]), d.duration_s = number(f[2]), d.bound_s = number(f[3]);
  d.visited = static_cast<std::size_t>(number(f[4]));
  d.visited_fraction = number(f[5]), d.dwell_cv = number(f[6]);
  d.dwell_s = doubles(f[7]);
  return d;
}

std::vector<std::vector<Vector3d>> cell_outlines_by_plugin(int nside, int steps) {
  const std::vector<std::string> f =
      split_fields(run_output_plugin(kHealpixPlugin, "--plot", join_fields({"outlines", std::to_string(nside), std::to_string(steps)})), 2);
  const std::size_t per_cell = static_cast<std::size_t>(number(f[0]));
  const std::vector<double> xyz = doubles(f[1]);
  std::vector<std::vector<Vector3d>> cells;
  for (std::size_t k = 0; per_cell > 0 && k + 3 * per_cell <= xyz.size(); k += 3 * per_cell) {
    cells.emplace_back();
    for (std::size_t i = 0; i < per_cell; ++i) cells.back().emplace_back(xyz[k + 3 * i], xyz[k + 3 * i + 1], xyz[k + 3 * i + 2]);
  }
  return cells;
}

void require_dwell_maps(const std::string& option, const std::string&) { require_output_plugin(kHealpixPlugin, "--" + option); }

const char* healpix_plugin_state() noexcept { return output_plugin_state(kHealpixPlugin); }
#else
void require_dwell_maps(const std::string& option, const std::string& value) {
  throw InvalidInput(option, value, "this build of sphtroch has no HEALPix (libhealpix-cxx-dev)", "--" + option + " in a build with HEALPix");
}

DwellMap dwell_map_by_plugin(const ClinostatSettings&, double, double duration_s, int) {
  throw InvalidInput("coverage", report_number(duration_s), "this build of sphtroch has no HEALPix (libhealpix-cxx-dev)", "--coverage in a build with HEALPix");
}

std::vector<std::vector<Vector3d>> cell_outlines_by_plugin(int, int) { return {}; }

const char* healpix_plugin_state() noexcept { return "no"; }
#endif

}  // namespace sphtroch::cli
