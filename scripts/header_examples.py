#!/usr/bin/env python3
"""Extract the usage example at the top of every public header and write one C++ file that
compiles and runs them all (ctest header_examples:run), so that no documented example goes stale.

  python3 scripts/header_examples.py INCLUDE_DIR OUT.cpp [--list]

A header's example is the first run of comment lines indented by three spaces ("//   code";
continuation lines may be indented further) in its opening comment block. Each becomes the body of its own function, after a
shared prelude of the names the examples use (train, curve, pi, ...); trailing // comments are
dropped. Headers without an example must be listed in NO_EXAMPLE with the reason. Exits 1 when a
header has neither. The program calls every example in turn (in its working directory: ctest runs
it in an empty directory of the build tree) and exits 1 naming each one that throws.
"""
import pathlib
import re
import sys

NO_EXAMPLE = {
    "version.hpp": "two macros and a string",
    "core/types.hpp": "type aliases only",
    "sphtroch.hpp": "the umbrella header (its use is docs/library.md's consumer example)",
    "exact_implementation.hpp": "defines classify(); it may be included in one file of a program only",
    "exact/mpreal_support.hpp": "its example needs sphtroch::mpfr; compiled by test_scalar_types",
    "cad/step_export.hpp": "its example needs sphtroch::step (OpenCASCADE); run by test_cad",
    "machine/dwell_map.hpp": "its example needs sphtroch::healpix; the same calls run in test_machine",
    "io/urdf_chain.hpp": "its example needs sphtroch::urdf (urdfdom); the same calls run in test_io",
}

PRELUDE = r'''
#include <sphtroch/sphtroch.hpp>
#include <sphtroch/classify.hpp>
#include <sphtroch/exact/analysis.hpp>
#include <sphtroch/exact/arc_predicates.hpp>
#include <sphtroch/exact/polyline_census.hpp>
#include <sphtroch/exact/self_crossings.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

// The names the examples take as given.
namespace fixture {
const double kPi = sphtroch::Constants<double>::pi();
const sphtroch::GearTrain train(kPi / 3, kPi / 2, sphtroch::Ratio(5, 2));
const double a2 = train.a2(), a3 = train.a3();
const double pi = kPi;
const std::vector<Eigen::Vector3d> v = sphtroch::sample_period(sphtroch::TracerCurve<double>(train), 64).points;
const sphtroch::Ratio n(5, 2);
char buffer[64];
const std::size_t size = sizeof buffer;
const std::string text;
const std::size_t i = 1, j = 2, k = 3, rows = 10, threads = 2;
const sphtroch::TracerCurve<double> curve(train);
const std::vector<sphtroch::BranchPair> pairs;
sphtroch::AtlasSpec small_atlas() {
  sphtroch::AtlasSpec s;
  s.grid = 8;
  return s;
}
sphtroch::AtlasSpec spec = small_atlas();
const std::vector<sphtroch::AtlasCell> cells = sphtroch::compute_atlas(spec, {0, spec.grid}, 1);
const std::vector<sphtroch::AtlasCell> slice = sphtroch::compute_atlas(spec, sphtroch::shard_rows(8, {2, 4}), 1);
std::string csv_of(const std::vector<sphtroch::AtlasCell>& c, sphtroch::AtlasShard shard) {
  std::ostringstream out;
  sphtroch::write_atlas_csv(out, spec, shard, c);
  return out.str();
}
const std::string slice_text = csv_of(slice, {2, 4});
const sphtroch::AtlasCsv part1 = sphtroch::read_atlas_csv(csv_of(sphtroch::compute_atlas(spec, sphtroch::shard_rows(8, {1, 2}), 1), {1, 2}), "1");
const sphtroch::AtlasCsv part2 = sphtroch::read_atlas_csv(csv_of(sphtroch::compute_atlas(spec, sphtroch::shard_rows(8, {2, 2}), 1), {2, 2}), "2");
const std::vector<sphtroch::EdgePair> crossings;
const std::size_t blocks = 4;
std::string format_rows(std::size_t block) { return std::to_string(block) + "\n"; }
const double seconds = 1.0;
const sphtroch::Analysis analysis(train);
const sphtroch::ScrewAxisSamples samples;
sphtroch::OutputFile& standard_output() {
  static sphtroch::OutputFile f = sphtroch::OutputFile::open("-", "output");
  return f;
}
sphtroch::OutputFile& file = standard_output();
const sphtroch::SelfCrossings sc;
struct Sink {
  void write(const std::string&) {}
} out;
}  // namespace fixture
'''


def example_of(path):
    lines = path.read_text().splitlines()
    block = []
    for line in lines:
        if not line.startswith("//"):
            break
        block.append(line)
    run, started = [], False
    for line in block:
        m = re.match(r"^//   (\S.*)$", line) or (started and re.match(r"^//   (\s+\S.*)$", line))
        if m:
            run.append(m.group(1))
            started = True
        elif started:
            break
    return run


def strip_comment(code):
    out, in_str = [], False
    i = 0
    while i < len(code):
        c = code[i]
        if c == '"' and (i == 0 or code[i - 1] != "\\"):
            in_str = not in_str
        if not in_str and code.startswith("//", i):
            break
        out.append(c)
        i += 1
    return "".join(out).rstrip()


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    include_dir, out_path = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    listing = "--list" in sys.argv
    headers = sorted(include_dir.glob("sphtroch/**/*.hpp"))
    parts, includes, missing, calls = [PRELUDE], [], [], []
    for h in headers:
        name = h.relative_to(include_dir / "sphtroch").as_posix()
        example = example_of(h)
        if name in NO_EXAMPLE:
            continue
        if not example:
            missing.append(name)
            continue
        body = []
        for line in example:
            code = strip_comment(line)
            if code.startswith("#include"):
                includes.append(code)
            elif code:
                body.append("  " + code)
        fn = re.sub(r"\W", "_", name[:-4])
        parts.append(f"// {name}\n[[maybe_unused]] static void example_{fn}() {{\n  using namespace sphtroch;\n  using namespace fixture;\n"
                     + "\n".join(body) + "\n}\n")
        calls.append(f'  failures += run_example("{name}", example_{fn});')
        if listing:
            print(f"== {name}\n" + "\n".join(body))
    if missing:
        print("header_examples.py: no example (first '//   ' run of the opening comment) in: "
              + ", ".join(missing) + "; add one or list the header in NO_EXAMPLE", file=sys.stderr)
        return 1
    parts.append("static int run_example(const char* header, void (*example)()) {\n"
                 "  try {\n    example();\n    return 0;\n  } catch (const std::exception& e) {\n"
                 "    std::fprintf(stderr, \"header example of %s threw: %s\\n\", header, e.what());\n    return 1;\n  }\n}\n")
    parts.append("int main() {\n  int failures = 0;\n" + "\n".join(calls)
                 + "\n  std::printf(\"%d header examples run, %d threw\\n\", " + str(len(calls)) + ", failures);\n"
                 "  return failures == 0 ? 0 : 1;\n}\n")
    # The prelude's includes come first: sphtroch.hpp puts mpreal_support.hpp before Eigen and CGAL.
    text = "// Generated by scripts/header_examples.py from the headers' opening comments. Do not edit.\n" \
        + parts[0] + "\n".join(sorted(set(includes))) + "\n" + "\n".join(parts[1:])
    if not out_path.exists() or out_path.read_text() != text:
        out_path.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
