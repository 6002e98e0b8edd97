// tests/fuzz/fuzz_text_readers.cpp — the readers of text a user types or hands over whole: the XML
// shape check before urdfdom (io/xml_shape.hpp), a clinostat's settings (machine/clinostat_text.hpp)
// and a rotation chain's twists, rates and phases (io/chain_text.hpp).
//
// Input: the whole input is an XML document for check_xml_shape; its lines (split at '\n', at
// most 7) are the clinostat's outer, inner, tilt, frame angle, phases and offset, and the first
// three the chain's twists, rates and phases.
// Expected: sphtroch::InvalidInput naming a field of the reader, with one-line parts; a clinostat
// or chain that is read is one the machine or the chain accepts (or refuses with InvalidInput).
// Anything else thrown crashes; a broken invariant traps (FUZZ_CHECK); the shape check is linear
// (a slow input is a finding).
#include "fuzz_common.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/xml_shape.hpp"
#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/clinostat_text.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace {

void check_error(const sphtroch::InvalidInput& e, const std::set<std::string>& fields) {
  FUZZ_CHECK(fields.count(e.field()) == 1);
  FUZZ_CHECK(fuzz::one_line(e.problem()) && fuzz::one_line(e.valid_range()));
}

void xml_shape(const std::string& text) {
  try {
    sphtroch::check_xml_shape(text, "urdf", "a URDF document");
  } catch (const sphtroch::InvalidInput& e) {
    check_error(e, {"urdf"});
  }
}

void clinostat(const std::vector<std::string>& lines) {
  sphtroch::ClinostatText t;
  std::string* fields[] = {&t.outer, &t.inner, &t.tilt, &t.frame_angle, &t.phase_outer, &t.phase_inner, &t.offset};
  for (std::size_t k = 0; k < lines.size() && k < 7; ++k) *fields[k] = lines[k];
  try {
    const sphtroch::ClinostatSettings s = t.settings();
    FUZZ_CHECK(std::isfinite(s.tilt_deg) && std::isfinite(s.frame_angle_deg) && s.offset_m.allFinite());
    const sphtroch::Clinostat machine(s);
    FUZZ_CHECK(std::fabs(machine.gravity(0.0).norm() - 1) < 1e-12);
  } catch (const sphtroch::InvalidInput& e) {
    check_error(e, {"outer", "inner", "tilt", "frame-angle", "phase-outer", "phase-inner", "offset"});
  }
}

void chain(const std::vector<std::string>& lines) {
  sphtroch::ChainText t;
  t.twists = lines.size() > 0 ? lines[0] : "";
  t.rates = lines.size() > 1 ? lines[1] : "";
  t.phases = lines.size() > 2 ? lines[2] : "";
  try {
    const sphtroch::RotationChain c = t.chain();
    FUZZ_CHECK(c.size() >= 1 && std::isfinite(c.period()) && c.period() > 0);
    FUZZ_CHECK(std::fabs(sphtroch::ChainCurve<double>(c).point(0.5).norm() - 1) < 1e-12);
  } catch (const sphtroch::InvalidInput& e) {
    check_error(e, {"twists", "rates", "phases"});
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  xml_shape(text);
  std::vector<std::string> lines(1);
  for (const char c : text) {
    if (c == '\n') {
      if (lines.size() == 7) break;
      lines.emplace_back();
    } else {
      lines.back() += c;
    }
  }
  clinostat(lines);
  chain(lines);
  return 0;
}
