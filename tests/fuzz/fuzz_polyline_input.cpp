// tests/fuzz/fuzz_polyline_input.cpp — read_polyline (polyline_input.hpp: CSV with or without a
// header, or .npy by its magic bytes) and the .npy header functions (npy.hpp) on their own.
//
// read_polyline takes a path: the input is written to one in-memory file per process (memfd,
// reached as /proc/self/fd/N; a temporary file in $TMPDIR where memfd is missing) and read with 1
// and with 2 threads; both results (vertices bit for bit and format, or the error message) must be
// equal. Two threads only split blocks above 64 KiB, so for one input in four (chosen by a hash
// of the bytes, so that a reproducer reproduces) a CSV is also amplified past that size: its first
// line, then the rest repeated.
// Expected: sphtroch::InvalidInput. Anything else thrown crashes; a broken invariant traps.
#include "fuzz_common.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/io/polyline_input.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace {

using sphtroch::InvalidInput;

struct ScratchFile {
  int fd = -1;
  std::string path;
  bool unlink_at_exit = false;
};

ScratchFile& scratch() {
  static ScratchFile f = [] {
    ScratchFile s;
#ifdef MFD_CLOEXEC
    s.fd = ::memfd_create("sphtroch-fuzz-polyline", MFD_CLOEXEC);
    if (s.fd >= 0) {
      s.path = "/proc/self/fd/" + std::to_string(s.fd);
      if (::access(s.path.c_str(), R_OK) == 0) return s;
      ::close(s.fd);
    }
#endif
    const char* tmp = std::getenv("TMPDIR");
    std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/sphtroch-fuzz-polyline-XXXXXX";
    s.fd = ::mkstemp(templ.data());
    FUZZ_CHECK(s.fd >= 0);
    s.path = templ;
    s.unlink_at_exit = true;
    std::atexit([] { ::unlink(scratch().path.c_str()); });
    return s;
  }();
  return f;
}

void write_scratch(std::string_view bytes) {
  ScratchFile& s = scratch();
  FUZZ_CHECK(::ftruncate(s.fd, 0) == 0);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t k = ::pwrite(s.fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
    FUZZ_CHECK(k > 0);
    done += static_cast<std::size_t>(k);
  }
}

/// What read_polyline gave: the input read, or the error's message.
struct Outcome {
  std::optional<sphtroch::PolylineInput> input;
  std::string error;
};

Outcome read(const std::string& path, std::size_t threads) {
  Outcome o;
  try {
    o.input = sphtroch::read_polyline(path, "input", threads);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "input" && e.value() == path);
    FUZZ_CHECK(!e.problem().empty());
    o.error = e.what();
  }
  return o;
}

bool same(const Outcome& a, const Outcome& b) {
  if (a.input.has_value() != b.input.has_value()) return false;
  if (!a.input) return a.error == b.error;
  const auto& va = a.input->vertices;
  const auto& vb = b.input->vertices;
  if (a.input->format != b.input->format || va.size() != vb.size()) return false;
  for (std::size_t i = 0; i < va.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!fuzz::same_bits(va[i][k], vb[i][k])) return false;
  return true;
}

/// The header functions on the raw bytes; returns the header when it parses.
std::optional<sphtroch::NpyHeader> npy_header_of(std::string_view bytes) {
  std::size_t len = 0;
  try {
    len = sphtroch::npy_preamble_length(bytes, "input", "fuzz.npy");
    FUZZ_CHECK(len >= sphtroch::kNpyVersionEnd + 2);
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "input" && e.value() == "fuzz.npy");
  }
  try {
    const sphtroch::NpyHeader h = sphtroch::parse_npy_header(bytes, "input", "fuzz.npy");
    FUZZ_CHECK(len != 0 && h.data_offset == len && len <= bytes.size());
    FUZZ_CHECK(h.item_bytes == 4 || h.item_bytes == 8);
    try {
      (void)sphtroch::npy_data_bytes(h, "input", "fuzz.npy");
    } catch (const InvalidInput&) {
    }
    return h;
  } catch (const InvalidInput& e) {
    FUZZ_CHECK(e.field() == "input" && e.value() == "fuzz.npy");
    return std::nullopt;
  }
}

/// npy_header writes what parse_npy_header reads back: the same shape, data 64-byte aligned.
void npy_header_round_trip(std::uint64_t rows, std::uint64_t cols) {
  const std::string h = sphtroch::npy_header(rows, cols);
  FUZZ_CHECK(h.size() % 64 == 0);
  const sphtroch::NpyHeader back = sphtroch::parse_npy_header(h, "input", "round-trip.npy");
  FUZZ_CHECK(back.shape.size() == 2 && back.shape[0] == rows && back.shape[1] == cols);
  FUZZ_CHECK(back.item_bytes == 8 && back.data_offset == h.size());
}

void check_result(const Outcome& o, std::string_view bytes) {
  if (!o.input) return;
  const auto& in = *o.input;
  if (sphtroch::looks_like_npy(bytes)) {
    const auto h = npy_header_of(bytes);
    FUZZ_CHECK(h.has_value());  // read_polyline accepted it
    FUZZ_CHECK(in.format.rfind("npy ", 0) == 0);
    FUZZ_CHECK(in.vertices.size() == h->rows());
    FUZZ_CHECK(h->data_offset + sphtroch::npy_data_bytes(*h, "input", "fuzz.npy") == bytes.size());
  } else {
    FUZZ_CHECK(in.format == "csv" || in.format == "csv with header");
    for (const auto& v : in.vertices) FUZZ_CHECK(std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()));
  }
}

void read_both_ways(std::string_view bytes) {
  write_scratch(bytes);
  const std::string& path = scratch().path;
  const Outcome one = read(path, 1);
  const Outcome two = read(path, 2);
  FUZZ_CHECK(same(one, two));
  check_result(one, bytes);
}

std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  (void)npy_header_of(bytes);
  // Shapes up to 2^56 rows (a header of larger whole numbers is refused as "shape too large").
  if (size >= 4) npy_header_round_trip(data[0] | std::uint64_t(data[1]) << 8 | std::uint64_t(data[2]) << 48,
                                       data[3] | std::uint64_t(data[0]) << 24);
  read_both_ways(bytes);

  // A CSV amplified past the 64 KiB at which two threads split a block: the first line once,
  // then the rest repeated (each copy ending with '\n').
  if (!sphtroch::looks_like_npy(bytes) && size <= 4096 && fnv1a(bytes) % 4 == 0) {
    const std::size_t nl = bytes.find('\n');
    if (nl != std::string_view::npos && nl + 1 < size) {
      std::string body(bytes.substr(nl + 1));
      if (body.back() != '\n') body += '\n';
      std::string big(bytes.substr(0, nl + 1));
      while (big.size() <= (std::size_t(1) << 16) + 4096) big += body;
      read_both_ways(big);
    }
  }
  return 0;
}
