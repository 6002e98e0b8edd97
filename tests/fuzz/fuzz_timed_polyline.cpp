// tests/fuzz/fuzz_timed_polyline.cpp — the input of `sphtroch synth identify`:
// read_timed_polyline (polyline_input.hpp: a CSV whose header names t, x, y, z, or a .npy
// (N, 4) / (N, 7)), then identify (synthesis/identify.hpp) on what it read, as
// src/cli/synth_command.cpp does.
//
// Input: the file's bytes, written to a scratch file and read with 1 and with 2 threads; both
// results (t and vertices bit for bit and the format, or the error message) must be equal. As in
// fuzz_polyline_input, one CSV in four (by a hash of the bytes) is also amplified past the 64 KiB
// at which two threads split a block. What reads is identified with the default bounds
// (--max-terms 1000,1000), or, for one input in four, with small bounds P,Q in 1..8.
// Expected: sphtroch::InvalidInput: from the reader naming "input" and the path, from identify
// naming "t", "points" or "samples" (identify.hpp), each with a one-line problem and valid form.
// Anything else thrown crashes; a broken invariant traps.
#include "fuzz_common.hpp"
#include "fuzz_files.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/synthesis/identify.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace {

using sphtroch::InvalidInput;

/// What read_timed_polyline gave: the input read, or the error's message.
struct Outcome {
  std::optional<sphtroch::PolylineInput> input;
  std::string error;
};

Outcome read(const std::string& path, std::size_t threads) {
  Outcome o;
  try {
    o.input = sphtroch::read_timed_polyline(path, "input", threads);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "input" && e.value() == path);
    FUZZ_CHECK(fuzz::one_line(e.problem()) && fuzz::one_line(e.valid_range()));
    o.error = e.what();
  }
  return o;
}

bool same(const Outcome& a, const Outcome& b) {
  if (a.input.has_value() != b.input.has_value()) return false;
  if (!a.input) return a.error == b.error;
  const auto& x = *a.input;
  const auto& y = *b.input;
  if (x.format != y.format || x.vertices.size() != y.vertices.size() || x.t.size() != y.t.size()) return false;
  for (std::size_t i = 0; i < x.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!fuzz::same_bits(x.vertices[i][k], y.vertices[i][k])) return false;
  for (std::size_t i = 0; i < x.t.size(); ++i)
    if (!fuzz::same_bits(x.t[i], y.t[i])) return false;
  return true;
}

/// What the reader accepted: one t per vertex; CSV numbers finite; a .npy exactly its rows.
void check_read(const sphtroch::PolylineInput& in, std::string_view bytes) {
  FUZZ_CHECK(in.t.size() == in.vertices.size());
  if (sphtroch::looks_like_npy(bytes)) {
    const sphtroch::NpyHeader h = sphtroch::parse_npy_header(bytes, "input", "fuzz.npy");
    FUZZ_CHECK(h.shape.size() == 2 && (h.cols() == 4 || h.cols() == 7));  // (N, 3) has no t
    FUZZ_CHECK(in.vertices.size() == h.rows());
    FUZZ_CHECK(in.format.rfind("npy ", 0) == 0);
    // Vertices finite and nonzero (checked as read). t is copied as stored: a NaN t of a .npy
    // reaches identify, which refuses it ("t": not finite and increasing).
    for (const auto& v : in.vertices) FUZZ_CHECK(v.allFinite() && (v.array() != 0.0).any());  // 1e-200: nonzero
  } else {
    // The column t needs a header; only an input without a non-blank line reads as an empty
    // "csv" (identify then refuses it: too few samples).
    FUZZ_CHECK(in.format == "csv with header" || (in.format == "csv" && in.vertices.empty()));
    for (const auto& v : in.vertices) FUZZ_CHECK(v.allFinite());
    for (double t : in.t) FUZZ_CHECK(std::isfinite(t));  // "a t that is not a finite number is refused"
  }
}

/// identify on what was read, as `synth identify` runs it.
void identify(const sphtroch::PolylineInput& in, std::uint64_t hash) {
  sphtroch::IdentifyOptions bounds;
  if (hash % 4 == 1) {
    bounds.max_p = 1 + static_cast<std::int64_t>((hash >> 8) % 8);
    bounds.max_q = 1 + static_cast<std::int64_t>((hash >> 16) % 8);
  }
  try {
    const sphtroch::Identified id = sphtroch::identify(in.t, in.vertices, bounds);
    const double pi = sphtroch::Constants<double>::pi();
    const sphtroch::GearTrain& g = id.train;
    FUZZ_CHECK(g.a2() > 0 && g.a2() < pi && g.a3() > 0 && g.a3() < pi);
    FUZZ_CHECK(g.phase() >= -pi && g.phase() <= pi);
    FUZZ_CHECK(g.ratio().abs_p() <= bounds.max_p && g.ratio().q() <= bounds.max_q);
    // Accepted only when the fit is within max(kIdentifyTolerance, 10 x noise) (rms).
    FUZZ_CHECK(std::isfinite(id.residual) && std::isfinite(id.rms) && std::isfinite(id.noise));
    FUZZ_CHECK(id.rms <= id.residual * (1 + 4 * std::numeric_limits<double>::epsilon()));  // to rounding
    FUZZ_CHECK(id.rms <= std::max(sphtroch::kIdentifyTolerance, 10 * id.noise));
    FUZZ_CHECK(in.vertices.size() >= sphtroch::kMinIdentifySamples);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "t" || e.field() == "points" || e.field() == "samples");
    FUZZ_CHECK(fuzz::one_line(e.problem()) && fuzz::one_line(e.valid_range()));
  }
}

Outcome read_both_ways(std::string_view bytes) {
  const std::string path = fuzz::write_file("timed", bytes);
  Outcome one = read(path, 1);
  const Outcome two = read(path, 2);
  FUZZ_CHECK(same(one, two));
  if (one.input) check_read(*one.input, bytes);
  return one;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::uint64_t hash = fuzz::fnv1a(bytes);
  const Outcome o = read_both_ways(bytes);
  if (o.input) identify(*o.input, hash);

  // A CSV amplified past the 64 KiB at which two threads split a block: the header once, then
  // the rest repeated (each copy ending with '\n').
  if (!sphtroch::looks_like_npy(bytes) && size <= 4096 && hash % 4 == 0) {
    const std::size_t nl = bytes.find('\n');
    if (nl != std::string_view::npos && nl + 1 < size) {
      std::string body(bytes.substr(nl + 1));
      if (body.back() != '\n') body += '\n';
      std::string big(bytes.substr(0, nl + 1));
      while (big.size() <= (std::size_t(1) << 16) + 4096) big += body;
      (void)read_both_ways(big);
    }
  }
  return 0;
}
