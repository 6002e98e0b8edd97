// Tests of the I/O headers: number_text.hpp (round-trip), npy.hpp (header written and parsed),
// polyline_input.hpp (CSV by header or headerless, .npy, errors with line numbers),
// output_file.hpp (staged files, devices and FIFOs written directly, all-or-nothing commits, every
// system call and allocation failing in turn through the SPHTROCH_OUTPUT_FAULT_INJECTION seam),
// parallel_for.hpp (order, errors) and trace_output.hpp (same bytes for any thread count).
// Expected values come from the formats' definitions and from invariants, not from the code.
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "test_support.hpp"

#include "sphtroch/core/curve.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/io/trace_output.hpp"

#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>
#include <sys/sysmacros.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <functional>
#include <memory>
#include <random>
#include <set>

using namespace sphtroch;
using sphtroch::test::expect_invalid;
using sphtroch::test::slurp;
using sphtroch::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/// Writes a file byte for byte.
void put(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

/// A .npy file built by hand from the format's definition (not by npy_header).
std::string npy_by_hand(const std::string& dict, const std::string& data, int major = 1) {
  std::string h = std::string("\x93NUMPY", 6) + static_cast<char>(major) + '\0';
  const std::size_t len = dict.size();
  h += static_cast<char>(len & 0xff);
  h += static_cast<char>(len >> 8);
  if (major >= 2) h += std::string(2, '\0');
  return h + dict + data;
}

std::string doubles(const std::vector<double>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

}  // namespace

TEST_CASE("number_text: every double round-trips exactly, and the form is the shortest", "[io][numbers]") {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                0.1,
                                1.0 / 3.0,
                                DBL_MAX,
                                -DBL_MAX,
                                DBL_MIN,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                DBL_MIN / 3,
                                std::nextafter(1.0, 2.0),
                                std::nextafter(1.0, 0.0),
                                1e23,
                                9007199254740993.0,
                                6.123233995736766e-17};
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i) values.push_back(unit(rng));
  for (int i = 0; i < 100000; ++i) {  // random bit patterns: every exponent, subnormals included
    std::uint64_t b = rng();
    double v;
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  for (double v : values) {
    char buf[kMaxNumberChars];
    const char* end = write_number(buf, v);
    REQUIRE(end - buf <= static_cast<std::ptrdiff_t>(kMaxNumberChars));
    const auto back = parse_number(std::string_view(buf, static_cast<std::size_t>(end - buf)));
    REQUIRE(back.has_value());
    REQUIRE(bits(*back) == bits(v));  // -0.0 keeps its sign, subnormals their last bit
  }
  CHECK(number_text(0.1) == "0.1");
  CHECK(number_text(-0.0) == "-0");
  CHECK(number_text(1e-11) == "1e-11");
  CHECK(number_text(std::numeric_limits<double>::denorm_min()) == "5e-324");
  CHECK(number_text(DBL_MAX) == "1.7976931348623157e+308");
  // Shortest: with one significant digit fewer (%.*g rounds correctly) the value is lost.
  for (std::size_t i = 0; i < 5000; ++i) {
    const double v = values[i];
    const std::string s = number_text(v);
    std::string digits;
    for (char c : s.substr(0, s.find('e'))) if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    digits.erase(0, digits.find_first_not_of('0'));
    if (digits.find_last_not_of('0') != std::string::npos) digits.erase(digits.find_last_not_of('0') + 1);
    if (digits.size() < 2) continue;
    char shorter[40];
    std::snprintf(shorter, sizeof shorter, "%.*g", static_cast<int>(digits.size() - 1), v);
    INFO(s << " vs " << shorter);
    CHECK(std::strtod(shorter, nullptr) != v);
  }
}

TEST_CASE("report_number: number_text's digits as a person writes them and 0 for -0", "[io][numbers]") {
  // Fixed notation for 1e-4 <= |v| < 1e16, else d.ddde-5 / d.ddde16 (no '+', no leading zeros).
  CHECK(report_number(-0.0) == "0");
  CHECK(report_number(0.0) == "0");
  CHECK(report_number(1e-4) == "0.0001");
  CHECK(report_number(-1e-4) == "-0.0001");
  CHECK(report_number(1e-5) == "1e-5");
  CHECK(report_number(2.5e-11) == "2.5e-11");
  CHECK(report_number(0.001) == "0.001");
  CHECK(report_number(37.55) == "37.55");
  CHECK(report_number(1200.0) == "1200");
  CHECK(report_number(1e15) == "1000000000000000");
  CHECK(report_number(1e16) == "1e16");
  CHECK(report_number(DBL_MAX) == "1.7976931348623157e308");
  CHECK(report_number(std::numeric_limits<double>::denorm_min()) == "5e-324");
  CHECK(report_number(1.0 / 3.0) == number_text(1.0 / 3.0));
  CHECK(seconds_text(1.0234e-6) == "1.02e-6");
  CHECK(seconds_text(123456.0) == "123000");
  // Every finite value reads back as itself (a zero as +0), in as many significant digits as number_text.
  std::mt19937_64 rng(20261201);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<double> values;
  for (int e = -12; e <= 20; ++e) values.push_back(std::pow(10.0, e) * unit(rng));
  for (int i = 0; i < 20000; ++i) {
    std::uint64_t b = rng();
    double v;
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  const auto significant = [](const std::string& s) {
    std::string digits;
    for (char c : s.substr(0, s.find('e'))) if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    digits.erase(0, digits.find_first_not_of('0'));
    return digits.substr(0, digits.find_last_not_of('0') + 1);
  };
  for (const double v : values) {
    const std::string s = report_number(v);
    INFO(number_text(v) << " as " << s);
    const auto back = parse_number(s);
    REQUIRE(back.has_value());
    CHECK(bits(*back) == bits(v == 0 ? 0.0 : v));
    CHECK(significant(s) == significant(number_text(v)));
    CHECK(s.find("e+") == std::string::npos);
    CHECK(s.find("e-0") == std::string::npos);
  }
}

TEST_CASE("number_text: parse_number accepts numbers only, whole, finite", "[io][numbers]") {
  CHECK(parse_number("2.5e-3") == 2.5e-3);
  CHECK(parse_number("+1") == 1.0);
  CHECK(parse_number(".5") == 0.5);
  for (const char* bad : {"", " 1", "1 ", "1,", "nan", "inf", "-inf", "1e999", "-1e999", "0.1e310", "0x10", "+-1", "--1",
                          "1e", "e1", "abc"})
    CHECK_FALSE(parse_number(bad).has_value());
}

TEST_CASE("number_text: a magnitude below the smallest subnormal reads as a signed zero", "[io][numbers]") {
  // Below 2^-1075 (half the smallest subnormal, 4.9e-324) the nearest double is zero, as strtod
  // and JSON readers (scene files) give it; above the largest double there is none.
  for (const char* tiny : {"1e-400", "0.000001e-320", "123456e-330", "100000000000000000000e-420", "1e-99999999999"}) {
    const auto v = parse_number(tiny);
    REQUIRE(v.has_value());
    CHECK(*v == 0.0);
    CHECK_FALSE(std::signbit(*v));
  }
  const auto negative = parse_number("-1e-400");
  REQUIRE(negative.has_value());
  CHECK(*negative == 0.0);
  CHECK(std::signbit(*negative));
  CHECK(parse_number("4.9406564584124654e-324") == std::numeric_limits<double>::denorm_min());
  CHECK(parse_number("0e-99999") == 0.0);
}

TEST_CASE("number_text: the fallback without floating-point to_chars writes and reads what the standard library does", "[io][numbers]") {
  // The WebAssembly build (emscripten's libc++) has no floating-point to_chars/from_chars and uses
  // detail::shortest_text / detail::read_decimal: they must agree byte for byte with libstdc++'s.
  std::vector<double> values = {0.0, -0.0, 1.0, 0.1, 1e-5, 1e-4, 1e-3, 1e15, 1e16, 1e21, 1e22, 1e23, 123456.0,
                                1234567.0, 0.000123, 5e-324, DBL_MIN, DBL_MAX, -DBL_MAX, 9007199254740993.0,
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN()};
  for (int e = -1074; e <= 1023; ++e) {  // powers of two: the lopsided round-trip intervals
    const double p = std::ldexp(1.0, e);
    values.insert(values.end(), {p, std::nextafter(p, 0.0), std::nextafter(p, HUGE_VAL), 3 * p, -p});
  }
  for (int k = -30; k <= 30; ++k) values.push_back(std::pow(10.0, k));
  std::mt19937_64 rng(20261125);
  for (int i = 0; i < 200000; ++i) {  // random bit patterns: every exponent, subnormals included
    std::uint64_t b = rng();
    double v;
    std::memcpy(&v, &b, sizeof v);
    values.push_back(v);
  }
  std::uniform_int_distribution<int> small(-100000, 100000);
  for (int i = 0; i < 20000; ++i) values.push_back(small(rng) / 1000.0);
  std::size_t differing = 0;
  std::vector<std::string> texts;
  for (const double v : values) {
    char expected[64], got[64];
    const std::string want(expected, std::to_chars(expected, expected + sizeof expected, v).ptr);
    const std::string have(got, detail::shortest_text(got, v));
    if (want != have && ++differing <= 10) FAIL_CHECK(want << " written as " << have);
    texts.push_back(want);
  }
  CHECK(differing == 0);
  // Reading: every text above, and texts that end early, overflow, underflow or are not numbers.
  for (const char* odd : {"1e", "1e+", "1e-x", ".5", "5.", ".", "-", "-.e1", "e5", "0x1p3", "00012.500", "1E5",
                          "1e-400", "-1e-400", "2e-324", "3e-324", "1e999", "-1e999", "1e-99999999999", "INF",
                          "-Infinity", "infinit", "nan(123)", "NaN(", "nan(x", "+1", " 1", "1.2.3",
                          "123456789012345678901234567890e-40", "4.9406564584124654e-324"})
    texts.emplace_back(odd);
  for (const std::string& t : texts) {
    const char* first = t.data();
    const char* last = first + t.size();
    double want = 42.0, have = 42.0;
    const auto a = std::from_chars(first, last, want);
    const auto b = detail::read_decimal(first, last, have);
    INFO('"' << t << '"');
    REQUIRE(b.ptr - first == a.ptr - first);
    REQUIRE(b.ec == a.ec);
    if (a.ec == std::errc()) REQUIRE((bits(want) == bits(have) || (std::isnan(want) && std::isnan(have))));
  }
}

TEST_CASE("npy: the header is the documented dict, padded to 64 bytes, and parses back", "[io][npy]") {
  const std::string h = npy_header(1000, 4);
  CHECK(h.size() % 64 == 0);
  CHECK(h.compare(0, 8, std::string("\x93NUMPY\x01\x00", 8)) == 0);
  const std::size_t len = static_cast<unsigned char>(h[8]) | static_cast<unsigned char>(h[9]) << 8;
  CHECK(len + 10 == h.size());
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (1000, 4), }";
  CHECK(h.compare(10, dict.size(), dict) == 0);
  CHECK(h.find_first_not_of(' ', 10 + dict.size()) == h.size() - 1);  // spaces, then '\n'

  CHECK(h.back() == '\n');
  const NpyHeader p = parse_npy_header(h, "input", "x.npy");
  CHECK(p.item_bytes == 8);
  CHECK(p.shape == std::vector<std::uint64_t>{1000, 4});
  CHECK(p.data_offset == h.size());
}

TEST_CASE("npy: headers numpy.save writes are read, others are refused with one line", "[io][npy]") {
  // Version 2.0 with a 32-bit length, double quotes, no trailing comma, float32.
  const NpyHeader v2 =
      parse_npy_header(npy_by_hand("{\"descr\": \"<f4\", \"fortran_order\": False, \"shape\": (7, 3)}\n", "", 2), "input", "a");
  CHECK(v2.item_bytes == 4);
  CHECK(v2.shape == std::vector<std::uint64_t>{7, 3});
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"{'descr': '>f8', 'fortran_order': False, 'shape': (2, 3), }", "big-endian"},
      {"{'descr': '<i8', 'fortran_order': False, 'shape': (2, 3), }", "dtype <i8"},
      {"{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }", "Fortran order"},
      {"{'descr': '<f8', 'shape': (2, 3), }", "needs the keys"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), 'x': 1}", "unexpected or repeated key"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3)", "malformed"},
      {"{'descr': [('a', '<f8')], 'fortran_order': False, 'shape': (2,), }", "structured"},
      {"{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999999, 3), }", "shape too large"},
      {"{'descr': '<f8', 'fortran_order': Maybe, 'shape': (2, 3), }", "True or False"},
  };
  for (const auto& [dict, problem] : bad) {
    INFO(dict);
    const InvalidInput e = expect_invalid([&] { parse_npy_header(npy_by_hand(dict, ""), "input", "f.npy"); });
    CHECK(e.field() == "input");
    CHECK(e.value() == "f.npy");
    CHECK(e.problem().find(problem) != std::string::npos);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
  CHECK(expect_invalid([] { npy_preamble_length(std::string("\x93NUMPY\x09\x00\x10\x00", 10), "input", "v9"); })
            .problem()
            .find("version 9.0") != std::string::npos);
  CHECK(expect_invalid([] { npy_preamble_length(std::string("\x93NUMP", 5), "input", "short"); }).problem().find("magic") !=
        std::string::npos);
}

TEST_CASE("polyline_input: CSV with a header takes x, y, z by name, headerless takes 3 numbers", "[io][csv]") {
  TempDir dir;
  const fs::path trace = dir.path / "trace.csv", plain = dir.path / "plain.csv", crlf = dir.path / "crlf.csv";
  put(trace, "t,x,y,z,vx,vy,vz\n0,1,0,0,9,9,9\n1,0,1,0,9,9,9\n2,0,0,1,9,9,9\n");
  put(plain, "\n1, 0, 0\n\n0,1,0\n0,0,1");  // blank lines, spaces, no final newline
  put(crlf, "\xEF\xBB\xBF\"Z\",\"Y\",\"X\"\r\n3,2,1\r\n6,5,4\r\n");  // BOM, quoted names, other order
  const PolylineInput a = read_polyline(trace.string());
  REQUIRE(a.vertices.size() == 3);
  CHECK(a.vertices[1] == Vector3d(0, 1, 0));
  CHECK(a.format == "csv with header");
  const PolylineInput b = read_polyline(plain.string());
  REQUIRE(b.vertices.size() == 3);
  CHECK(b.vertices[0] == Vector3d(1, 0, 0));
  CHECK(b.vertices[2] == Vector3d(0, 0, 1));
  const PolylineInput c = read_polyline(crlf.string());
  REQUIRE(c.vertices.size() == 2);
  CHECK(c.vertices[0] == Vector3d(1, 2, 3));
  CHECK(c.vertices[1] == Vector3d(4, 5, 6));
}

TEST_CASE("polyline_input: bad CSV rows are refused naming the line", "[io][csv][errors]") {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0,0,1,5\n1,0,1,5\n", "line 1 has 4 numbers"},  // a row of 4 numbers is not a header
      {"t,x,y\n0,1,2\n", "without a column z"},
      {"x,y,x,z\n1,2,3,4\n", "names column x twice"},
      {"x,y,z\n1,2,3\n4,5\n", "line 3 has 2 fields"},
      {"x,y,z\n1,2,3\n4,5,6,7\n", "line 3 has more than 3 fields"},
      {"1,2,3\n4,nan,6\n", "line 2 column 2 is not a finite number"},
      {"1,2,3\n4,5,1e999\n", "line 2 column 3 is not a finite number"},
      {"1,2,3\n4,5,6x\n", "line 2 column 3"},
  };
  for (const auto& [text, problem] : cases) {
    INFO(text);
    const fs::path p = dir.path / "bad.csv";
    put(p, text);
    const InvalidInput e = expect_invalid([&] { read_polyline(p.string()); });
    CHECK(e.problem().find(problem) != std::string::npos);
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
  CHECK(expect_invalid([&] { read_polyline((dir.path / "missing.csv").string()); }).problem().find("cannot be read") == 0);
  CHECK(expect_invalid([&] { read_polyline(dir.path.string()); }).problem() == "is a directory");
}

TEST_CASE("polyline_input: a large CSV spans many blocks and both parser threads, errors keep their line", "[io][csv]") {
  TempDir dir;
  const fs::path p = dir.path / "big.csv";
  std::string text = "t,x,y,z\n";
  const std::size_t rows = 300000;  // ~9 MB: three 4 MiB blocks
  for (std::size_t i = 0; i < rows; ++i)
    text += number_text(static_cast<double>(i)) + ",0.5," + number_text(1.0 / static_cast<double>(i + 1)) + "," +
            number_text(-static_cast<double>(i)) + "\n";
  put(p, text);
  for (std::size_t threads : {1, 2}) {
    const PolylineInput in = read_polyline(p.string(), "input", threads);
    REQUIRE(in.vertices.size() == rows);
    for (std::size_t i = 0; i < rows; i += 997) {
      CHECK(in.vertices[i].x() == 0.5);
      CHECK(in.vertices[i].y() == 1.0 / static_cast<double>(i + 1));
      CHECK(in.vertices[i].z() == -static_cast<double>(i));
    }
  }
  const std::size_t bad_row = 250000;  // in the third block, second half
  const std::size_t at = text.find("\n" + number_text(static_cast<double>(bad_row)) + ",") + 1;
  text.insert(text.find(',', at) + 1, "x");
  put(p, text);
  CHECK(expect_invalid([&] { read_polyline(p.string()); }).problem().find("line " + std::to_string(bad_row + 2) + " ") == 0);
}

TEST_CASE("polyline_input: .npy by magic bytes, whatever the name, float32 and trace arrays", "[io][npy]") {
  TempDir dir;
  const fs::path a = dir.path / "a.csv", b = dir.path / "b", c = dir.path / "c.npy";
  put(a, npy_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }\n", doubles({1, 2, 3, 4, 5, 6})));
  put(b, npy_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 4), }\n", doubles({0, 1, 2, 3, 9, 4, 5, 6})));
  const float f[6] = {1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f};
  put(c, npy_by_hand("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }\n",
                     std::string(reinterpret_cast<const char*>(f), sizeof f)));
  for (const fs::path& p : {a, b}) {
    const PolylineInput in = read_polyline(p.string());
    REQUIRE(in.vertices.size() == 2);
    CHECK(in.vertices[0] == Vector3d(1, 2, 3));
    CHECK(in.vertices[1] == Vector3d(4, 5, 6));
  }
  const PolylineInput in = read_polyline(c.string());
  REQUIRE(in.vertices.size() == 2);
  CHECK(in.vertices[1] == Vector3d(4.5, 5.5, 6.5));
  CHECK(in.format == "npy <f4 (2, 3)");
  // Fewer bytes than the shape says, more bytes, a 1-D array, a (N, 5) array.
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {npy_by_hand(dict, doubles({1, 2, 3, 4, 5})), "truncated"},
      {npy_by_hand(dict, doubles({1, 2, 3, 4, 5, 6, 7})), "bytes after the array's data"},
      {npy_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }\n", doubles({1, 2, 3, 4, 5, 6})), "shape (6,)"},
      {npy_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 5), }\n", doubles({1, 2, 3, 4, 5})), "shape (1, 5)"},
      {npy_by_hand(dict, "").substr(0, 20), "truncated header"},
  };
  for (const auto& [bytes, problem] : bad) {
    INFO(problem);
    const fs::path p = dir.path / "bad.npy";
    put(p, bytes);
    CHECK(expect_invalid([&] { read_polyline(p.string()); }).problem().find(problem) != std::string::npos);
  }
}

TEST_CASE("output_file: a file appears only on commit, with no temporary left, discard leaves the old file",
          "[io][output]") {
  TempDir dir;
  const fs::path p = dir.path / "out.csv";
  put(p, "old\n");
  {
    OutputFile f = OutputFile::open(p.string(), "--output");
    f.write("new\n");
    f.flush();
    CHECK(slurp(p) == "old\n");  // until commit the target is untouched
  }  // destroyed without commit: discarded
  CHECK(slurp(p) == "old\n");
  CHECK(dir.entries() == std::vector<std::string>{"out.csv"});
  OutputFile f = OutputFile::open(p.string(), "--output");
  for (int i = 0; i < 300000; ++i) f.write("0123456789");  // more than the buffer
  f.commit();
  CHECK(fs::file_size(p) == 3000000u);
  CHECK(dir.entries() == std::vector<std::string>{"out.csv"});
  // A 255-byte file name still works: the temporary name is short.
  const fs::path longname = dir.path / std::string(255, 'a');
  OutputFile g = OutputFile::open(longname.string(), "--output");
  g.write("x");
  g.commit();
  CHECK(slurp(longname) == "x");
}

TEST_CASE("output_file: a device or FIFO target is written directly, never replaced", "[io][output][device]") {
  TempDir dir;
  const fs::path full = dir.path / "full", null = dir.path / "null", fifo = dir.path / "fifo";
  REQUIRE(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) == 0);  // a copy of /dev/full
  REQUIRE(::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);  // a copy of /dev/null
  OutputFile n = OutputFile::open(null.string(), "--output");
  n.write("data");
  n.commit();
  CHECK(fs::is_character_file(null));
  OutputFile f = OutputFile::open(full.string(), "--output");
  f.write("data");
  try {
    f.commit();
    FAIL("writing to a full device succeeded");
  } catch (const OutputError& e) {
    CHECK(e.error_number() == ENOSPC);
    CHECK(std::string(e.what()).find("--output = " + full.string()) == 0);
  }
  CHECK(fs::is_character_file(full));
  // A FIFO: the bytes arrive at the reader, the FIFO stays a FIFO.
  REQUIRE(::mkfifo(fifo.c_str(), 0666) == 0);
  std::string got;
  std::thread reader([&] { got = slurp(fifo); });
  OutputFile w = OutputFile::open(fifo.string(), "--output");
  w.write("through the fifo\n");
  w.commit();
  reader.join();
  CHECK(got == "through the fifo\n");
  CHECK(fs::is_fifo(fifo));
}

TEST_CASE("output_file: commit_together puts back every file when a later rename fails", "[io][output]") {
  TempDir dir;
  const fs::path a = dir.path / "a.csv", blocker = dir.path / "b.csv";
  put(a, "previous a\n");
  {
    OutputFile fa = OutputFile::open(a.string(), "--output");
    fa.write("new a\n");
    OutputFile fb = OutputFile::open(blocker.string(), "--pairs");
    fb.write("new b\n");
    fs::create_directory(blocker);           // renaming a file onto a directory fails (EISDIR)
    fs::create_directory(blocker / "keep");  // non-empty
    CHECK_THROWS_AS(commit_together({&fa, &fb}), OutputError);
  }
  CHECK(slurp(a) == "previous a\n");
  CHECK(fs::is_directory(blocker));
  std::vector<std::string> entries = dir.entries();
  std::sort(entries.begin(), entries.end());
  CHECK(entries == std::vector<std::string>{"a.csv", "b.csv", "b.csv/keep"});
  // A new file (no previous one) is removed again.
  const fs::path fresh = dir.path / "fresh.csv";
  {
    OutputFile ff = OutputFile::open(fresh.string(), "--output");
    ff.write("x");
    const fs::path blocker2 = dir.path / "c.csv";
    OutputFile fb2 = OutputFile::open(blocker2.string(), "--pairs");
    fb2.write("y");
    fs::create_directory(blocker2);
    fs::create_directory(blocker2 / "keep");
    CHECK_THROWS_AS(commit_together({&ff, &fb2}), OutputError);
  }
  CHECK_FALSE(fs::exists(fresh));
  entries = dir.entries();
  std::sort(entries.begin(), entries.end());
  CHECK(entries == std::vector<std::string>{"a.csv", "b.csv", "b.csv/keep", "c.csv", "c.csv/keep"});
}

TEST_CASE("parallel_blocks: blocks are consumed in order for any thread count, errors come back", "[io][parallel]") {
  for (std::size_t threads : {1, 2, 3, 7}) {
    std::vector<std::size_t> seen;
    for_each_block_in_order(
        100, threads, [](std::size_t b, std::string& s) { s = std::to_string(b); },
        [&](const std::string& s) { seen.push_back(std::stoul(s)); });
    REQUIRE(seen.size() == 100);
    for (std::size_t i = 0; i < seen.size(); ++i) CHECK(seen[i] == i);
    CHECK_THROWS_WITH(for_each_block_in_order(
                          50, threads,
                          [](std::size_t b, std::string&) {
                            if (b == 17) throw std::runtime_error("producer");
                          },
                          [](const std::string&) {}),
                      "producer");
    std::size_t consumed = 0;
    CHECK_THROWS_WITH(for_each_block_in_order(
                          50, threads, [](std::size_t, std::string&) {},
                          [&](const std::string&) {
                            if (++consumed == 5) throw std::runtime_error("consumer");
                          }),
                      "consumer");
  }
}

TEST_CASE("trace_output: the same bytes for 1, 2 and 5 threads, CSV rows = the curve, npy = the same doubles",
          "[io][trace]") {
  TempDir dir;
  const GearTrain train(1.0, 2.0, Ratio(7, 3));
  const TracerCurve<double> curve(train);
  const UniformSampling<double> s = period_sampling(curve, 40000);  // three blocks
  std::string first_csv, first_npy;
  for (std::size_t threads : {1, 2, 5}) {
    for (TraceFormat format : {TraceFormat::csv, TraceFormat::npy}) {
      const fs::path p = dir.path / (format == TraceFormat::csv ? "t.csv" : "t.npy");
      OutputFile out = OutputFile::open(p.string(), "--output");
      write_trace(out, curve, s, {format, true, threads});
      out.commit();
      const std::string bytes = slurp(p);
      std::string& first = format == TraceFormat::csv ? first_csv : first_npy;
      if (first.empty()) first = bytes;
      CHECK(bytes == first);
    }
  }
  // npy: header, then rows t, x, y, z, vx, vy, vz exactly as the curve computes them.
  const NpyHeader h = parse_npy_header(first_npy, "input", "t.npy");
  CHECK(h.shape == std::vector<std::uint64_t>{40000, 7});
  REQUIRE(first_npy.size() == h.data_offset + 40000 * 7 * 8);
  for (std::size_t i = 0; i < 40000; i += 1234) {
    double row[7];
    std::memcpy(row, first_npy.data() + h.data_offset + i * 56, sizeof row);
    const double t = s.parameter(i);
    const Vector3d P = curve.point(t), V = curve.velocity(t);
    CHECK(bits(row[0]) == bits(t));
    for (int k = 0; k < 3; ++k) {
      CHECK(bits(row[1 + k]) == bits(P[k]));
      CHECK(bits(row[4 + k]) == bits(V[k]));
    }
  }
  // CSV: the header and 40000 rows that parse back to the same doubles as the npy.
  const fs::path csv = dir.path / "t.csv";
  const PolylineInput back = read_polyline(csv.string());
  REQUIRE(back.vertices.size() == 40000);
  CHECK(first_csv.rfind("t,x,y,z,vx,vy,vz\n", 0) == 0);
  for (std::size_t i = 0; i < 40000; i += 777) CHECK(back.vertices[i] == curve.point(s.parameter(i)));
}

namespace {

/// The fault-injection hook (output_file.hpp's test seam): fails the fail_at-th call, counting
/// from 1, and records which operation it failed.
struct FaultPlan {
  static inline int calls = 0, fail_at = 0;
  static inline std::string failed;
  static int hook(const char* operation) {
    if (++calls != fail_at) return 0;
    failed = operation;
    return std::string(operation) == "alloc" ? ENOMEM : EIO;
  }
};

std::vector<std::string> sorted_entries(const TempDir& dir) {
  std::vector<std::string> e = dir.entries();
  std::sort(e.begin(), e.end());
  return e;
}

/// Runs `scenario` with the k-th system call or allocation of the writer failing, k = 1, 2, ...
/// until it runs without a fault. After each failure: an OutputError naming `field_hint`,
/// `untouched()` holds (no target changed) and the directory holds exactly `before` (no
/// temporary). Returns the operations failed along the way.
std::set<std::string> fail_each_call(const TempDir& dir, const std::function<void()>& scenario,
                                     const std::function<void()>& untouched, const std::string& field_hint) {
  std::set<std::string> failed;
  const std::vector<std::string> before = sorted_entries(dir);
  detail::output_fault_hook = &FaultPlan::hook;
  for (int k = 1;; ++k) {
    FaultPlan::calls = 0;
    FaultPlan::fail_at = k;
    FaultPlan::failed.clear();
    try {
      scenario();
    } catch (const OutputError& e) {
      INFO("call " << k << " (" << FaultPlan::failed << "): " << e.what());
      CHECK_FALSE(FaultPlan::failed.empty());
      CHECK(std::string(e.what()).find(field_hint) != std::string::npos);
      CHECK(std::string(e.what()).find("; valid: ") != std::string::npos);
      failed.insert(FaultPlan::failed);
      untouched();
      CHECK(sorted_entries(dir) == before);
      continue;
    }
    CHECK(FaultPlan::failed.empty());  // no exception: no fault was injected
    break;
  }
  detail::output_fault_hook = nullptr;
  return failed;
}

}  // namespace

TEST_CASE("output_file: fault injection: each write, fsync, close, link, rename and allocation failing in turn leaves nothing partial",
          "[io][output][faults]") {
  TempDir dir;
  const fs::path a = dir.path / "a.csv", b = dir.path / "b.csv", c = dir.path / "c.csv";
  put(a, "old a\n");
  put(c, "old c\n");
  const std::string big(OutputFile::kBufferBytes + 12345, 'x');  // several write(2) calls
  // One file: commit() (fsync, close, rename).
  const std::set<std::string> single = fail_each_call(
      dir,
      [&] {
        OutputFile f = OutputFile::open(c.string(), "--output");
        f.write("new c\n");
        f.write(big);
        f.commit();
      },
      [&] { CHECK(slurp(c) == "old c\n"); }, "--output = " + c.string());
  CHECK(slurp(c) == "new c\n" + big);
  // Two files together: one replacing a.csv (backup link), one new; b finished early (syncfs).
  const std::set<std::string> together = fail_each_call(
      dir,
      [&] {
        OutputFile fa = OutputFile::open(a.string(), "--output");
        fa.write(big);
        OutputFile fb = OutputFile::open(b.string(), "--pairs");
        fb.write("new b\n");
        fb.finish_writing(false);
        commit_together({&fa, &fb});
      },
      [&] {
        CHECK(slurp(a) == "old a\n");
        CHECK_FALSE(fs::exists(b));
      },
      " = " + dir.path.string());
  CHECK(slurp(a) == big);
  CHECK(slurp(b) == "new b\n");
  std::set<std::string> all = single;
  all.insert(together.begin(), together.end());
  CHECK(all == std::set<std::string>{"alloc", "close", "fsync", "link", "mkostemp", "rename", "write"});
}

TEST_CASE("output_file: D4 a path with a NUL byte is refused by the writer and the reader, never cut", "[io][output]") {
  TempDir dir;
  const std::string path = (dir.path / "o.csv").string() + std::string("\0x", 2);
  try {
    OutputFile::open(path, "--output");
    FAIL("a path with a NUL byte was opened");
  } catch (const OutputError& e) {
    CHECK(std::string(e.what()).find("o.csv\\0x: contains a NUL byte") != std::string::npos);
  }
  CHECK(dir.entries().empty());  // not o.csv, nor a temporary
  put(dir.path / "o.csv", "1,0,0\n");
  const InvalidInput e = expect_invalid([&] { read_polyline(path, "input"); });
  CHECK(e.problem() == "contains a NUL byte");
  CHECK(e.value().find("\\0x") != std::string::npos);
}

TEST_CASE("output_file: D5 more than 64 live temporaries are all removable by the signal handler", "[io][output][signals]") {
  TempDir dir;
  std::vector<OutputFile> files;
  for (int i = 0; i < 200; ++i) {
    files.push_back(OutputFile::open((dir.path / ("f" + std::to_string(i))).string(), "--output"));
    files.back().write("x");
    files.back().finish_writing(false);
  }
  REQUIRE(dir.entries().size() == 200);  // 200 temporaries, no target yet
  detail::TempRegistry::instance().unlink_all();  // what the SIGINT/SIGTERM/SIGHUP handler runs
  CHECK(dir.entries().empty());
  files.clear();
  // Nodes are reused: a new file after those 200 is registered and removed again.
  OutputFile g = OutputFile::open((dir.path / "g").string(), "--output");
  detail::TempRegistry::instance().unlink_all();
  CHECK(dir.entries().empty());
}

TEST_CASE("output_file: D0 a process that dies of abort() or a fault mid-write leaves no temporary", "[io][output][signals]") {
  // Fault injection by death: a child process installs the cleanup, stages two outputs, writes
  // part of them, then dies of the signal (as glibc's "stack smashing detected" calls abort()).
  // 0: a real fault (a write to a PROT_NONE page: SIGSEGV from the kernel, which the handler
  // leaves to happen again so that the replaced action, e.g. ASan's report, sees it).
  for (const int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGXFSZ, SIGTERM, 0}) {
    TempDir dir;
    std::ofstream(dir.path / "b.csv") << "old";
    std::fflush(nullptr);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      install_output_signal_cleanup();
      OutputFile a = OutputFile::open((dir.path / "a.csv").string(), "--output");
      OutputFile b = OutputFile::open((dir.path / "b.csv").string(), "--output");
      a.write(std::string(3 << 20, 'x'));  // past the buffer: bytes on disk
      b.write("partial");
      if (sig == SIGABRT) std::abort();
      if (sig == 0) {
        void* page = ::mmap(nullptr, 4096, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (page != MAP_FAILED) *static_cast<volatile char*>(page) = 1;
      }
      ::raise(sig);
      ::_exit(0);  // not reached
    }
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    INFO("signal " << sig << ", status " << status);
    CHECK(!(WIFEXITED(status) && WEXITSTATUS(status) == 0));  // it died (of the signal, or of a sanitizer's report)
    const std::vector<std::string> left = dir.entries();
    CHECK(left == std::vector<std::string>{"b.csv"});  // no a.csv, no .sphtroch-XXXXXX
    CHECK(slurp(dir.path / "b.csv") == "old");
  }
}

TEST_CASE("output_file: D6 finished staged outputs hold no descriptor until their common commit", "[io][output]") {
  TempDir dir;
  const auto open_descriptors = [] {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator("/proc/self/fd"), fs::directory_iterator()));
  };
  const std::size_t before = open_descriptors();
  std::vector<std::unique_ptr<OutputFile>> files;
  for (int i = 0; i < 1100; ++i) {
    files.push_back(std::make_unique<OutputFile>(OutputFile::open((dir.path / ("f" + std::to_string(i))).string(), "--output")));
    files.back()->write(std::to_string(i));
    files.back()->finish_writing(false);
  }
  CHECK(open_descriptors() == before);
  std::vector<OutputFile*> all;
  for (auto& f : files) all.push_back(f.get());
  commit_together(all);
  CHECK(dir.entries().size() == 1100);
  CHECK(slurp(dir.path / "f1099") == "1099");
  CHECK_THROWS_AS(files.front()->write("late"), OutputError);  // closed: no write after commit
}

TEST_CASE("polyline_input: D10 declared sizes are hints: a sparse 64 GB CSV or (3e9, 3) .npy reports its first bad row",
          "[io][csv][npy]") {
  TempDir dir;
  const fs::path csv = dir.path / "sparse.csv", npy = dir.path / "sparse.npy";
  std::string rows;
  for (int i = 0; i < 800000; ++i) rows += i % 2 ? "1,0,0\n" : "0,1,0\n";  // 4.8 MB: the first block is all rows
  put(csv, rows);
  fs::resize_file(csv, std::uintmax_t(64) << 30);  // a hole of NUL bytes: no disk used
  const InvalidInput e = expect_invalid([&] { read_polyline(csv.string()); });
  CHECK(e.problem().find("line 800001 ") == 0);
  const std::string header = npy_by_hand("{'descr': '<f8', 'fortran_order': False, 'shape': (3000000000, 3), }\n", "");
  put(npy, header + doubles({1, 0, 0, 0, 1, 0}));  // two good rows, then zeros
  fs::resize_file(npy, header.size() + std::uintmax_t(3000000000) * 24);
  const InvalidInput n = expect_invalid([&] { read_polyline(npy.string()); });
  CHECK(n.problem() == "row 2 (0, 0, 0) is not a finite nonzero vector");
}

TEST_CASE("npy and csv: D12 a NUL in a descr is escaped, a CSV field that is not a number is quoted", "[io][npy][csv]") {
  const InvalidInput e = expect_invalid([] {
    const char dict[] = "{'descr': '<f\0" "8', 'fortran_order': False, 'shape': (2, 3), }";
    parse_npy_header(npy_by_hand(std::string(dict, sizeof dict - 1), ""), "input", "n.npy");
  });
  CHECK(e.problem() == "dtype <f\\x008 is not float64 or float32");
  TempDir dir;
  for (const auto& [text, problem] : std::vector<std::pair<std::string, std::string>>{
           {"1,0,0\n1e,0.5,1\n", "line 2 column 1 is not a finite number: \"1e\""},
           {"1,0,0\n0.5,0x1p3,1\n", "line 2 column 2 is not a finite number: \"0x1p3\""},
           {"x,y,z\n1,0,0\n0,1,1e\n", "line 3 column 3 is not a finite number: \"1e\""},
           {"1,0,0\n0,1\n", "line 2 has 2 fields, not 3"}}) {
    INFO(text);
    put(dir.path / "e.csv", text);
    CHECK(expect_invalid([&] { read_polyline((dir.path / "e.csv").string()); }).problem() == problem);
  }
}
