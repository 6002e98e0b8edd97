// Separate compilation of classify() (classification.hpp, SPHTROCH_SEPARATE_EXACT) and the ODR
// of mixing modes: this file is compiled with SPHTROCH_SEPARATE_EXACT (tests/CMakeLists.txt) and
// sees only the declaration; separate_compilation_default.cpp includes the definitions as a
// header-only user does; separate_compilation_impl.cpp is the one file with
// exact_implementation.hpp. One program, three files: both callers must give the report's counts.
#include "test_support.hpp"

#include "sphtroch/classify.hpp"
#include "sphtroch/tolerance.hpp"

#if !defined(SPHTROCH_SEPARATE_EXACT)
#error "this file must be compiled with SPHTROCH_SEPARATE_EXACT"
#endif
#if defined(CGAL_VERSION_NR)
#error "separate mode must not pull in CGAL"
#endif

#include <cstddef>
#include <string>

// Defined in separate_compilation_default.cpp (header-only mode).
std::size_t classify_nodes_header_only(double a2, double a3, std::int64_t p, std::int64_t q);
// Defined in separate_compilation_umbrella.cpp (the umbrella header in separate mode).
// Defined in separate_compilation_default.cpp: tolerance --json's text, header-only mode.
std::string tolerance_json_header_only(double a2, double a3, std::int64_t p, std::int64_t q, double half_width);
std::size_t classify_nodes_via_umbrella(double a2, double a3, std::int64_t p, std::int64_t q, std::size_t& root_nodes);

TEST_CASE("separate compilation: classify() declared here, defined in one file, equal to header-only", "[exact][odr]") {
  for (const auto& row : sphtroch::test::paper_cases()) {
    INFO(row.id);
    const sphtroch::GearTrain train(row.a2, row.a3, sphtroch::Ratio(row.n_num, row.n_den));
    const sphtroch::Classification c = sphtroch::classify(train);
    CHECK(c.nodes.size() == row.nodes);
    CHECK(c.cusps.size() == row.cusps);
    CHECK(c.agreement.ok());
    CHECK(classify_nodes_header_only(row.a2, row.a3, row.n_num, row.n_den) == row.nodes);
    std::size_t root_nodes = 0;
    CHECK(classify_nodes_via_umbrella(row.a2, row.a3, row.n_num, row.n_den, root_nodes) == row.nodes);
    CHECK(root_nodes == row.nodes);
  }
}

TEST_CASE("separate compilation: tolerance_report() declared here, defined in one file, equal to header-only", "[exact][odr]") {
  // The same report in both modes: the census counts are the report's, the JSON identical.
  const auto rows = sphtroch::test::paper_cases();
  for (std::size_t k = 0; k < rows.size(); k += 5) {
    const auto& row = rows[k];
    INFO(row.id);
    const sphtroch::GearTrain train(row.a2, row.a3, sphtroch::Ratio(row.n_num, row.n_den));
    const sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {1e-4, 1e-4, 0.0});
    CHECK(r.node_count == row.nodes);
    CHECK(r.cusp_count == row.cusps);
    CHECK(r.margin.lower <= r.margin.upper);
    const sphtroch::TrainText typed{sphtroch::number_text(row.a2), sphtroch::number_text(row.a3),
                                    sphtroch::Ratio(row.n_num, row.n_den).str()};
    CHECK(sphtroch::tolerance_json(typed, r).dump() == tolerance_json_header_only(row.a2, row.a3, row.n_num, row.n_den, 1e-4));
  }
}
