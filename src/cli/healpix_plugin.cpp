// The HEALPix plugin (CMake MODULE sphtroch_healpix, the one binary of the tool that links
// HEALPix and, through it, cfitsio and its network stack): requests in plugin_fields.hpp's form,
// first field the operation:
//   "dwell", the clinostat (clinostat_fields.hpp), start, duration, nside  ->  nside, start,
//     duration, bound, visited, fraction, cv (round-trip decimals), the seconds per cell (raw doubles)
//   "outlines", nside, steps  ->  the points per cell, then every cell's outline (raw doubles, x y z)
// through machine/dwell_map.hpp. The C ABI and its error contract: output_plugin.hpp.
#include "clinostat_fields.hpp"
#include "output_plugin.hpp"
#include "plugin_fields.hpp"

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/machine/dwell_map.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace {

double number(const std::string& text) {
  const std::optional<double> v = sphtroch::detail::strict_double(text);
  if (!v) throw std::runtime_error("the HEALPix plugin's request: not a number: " + text);
  return *v;
}

std::string raw(const double* values, std::size_t count) { return std::string(reinterpret_cast<const char*>(values), count * sizeof(double)); }

std::string dwell_reply(const std::vector<std::string>& f) {
  using namespace sphtroch;
  const ClinostatSettings s = cli::clinostat_settings(f, 1);
  const std::size_t at = 1 + cli::kClinostatFields;
  const DwellMap d = dwell_map(Clinostat(s), number(f.at(at)), number(f.at(at + 1)), static_cast<int>(number(f.at(at + 2))));
  return cli::join_fields({std::to_string(d.nside), number_text(d.start_s), number_text(d.duration_s), number_text(d.bound_s),
                           std::to_string(d.visited), number_text(d.visited_fraction), number_text(d.dwell_cv),
                           raw(d.dwell_s.data(), d.dwell_s.size())});
}

std::string outlines_reply(const std::vector<std::string>& f) {
  const std::vector<std::vector<sphtroch::Vector3d>> cells = sphtroch::cell_outlines(static_cast<int>(number(f.at(1))), static_cast<int>(number(f.at(2))));
  std::vector<double> xyz;
  for (const auto& cell : cells)
    for (const sphtroch::Vector3d& v : cell) xyz.insert(xyz.end(), {v.x(), v.y(), v.z()});
  return sphtroch::cli::join_fields({std::to_string(cells.empty() ? 0 : cells.front().size()), raw(xyz.data(), xyz.size())});
}

std::string run_healpix_request(const std::string& text) {
  const std::vector<std::string> f = sphtroch::cli::split_fields(text);
  if (!f.empty() && f[0] == "dwell") return dwell_reply(f);
  if (!f.empty() && f[0] == "outlines") return outlines_reply(f);
  throw std::runtime_error("the HEALPix plugin's request: no such operation");
}

}  // namespace

SPHTROCH_OUTPUT_PLUGIN(run_healpix_request)
