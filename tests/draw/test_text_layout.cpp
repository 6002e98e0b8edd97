// Tests for sphtroch/draw/text_layout.hpp: the width bound, wrapping (each line fits, nothing is
// lost), short numbers.
#include "catch2/catch.hpp"

#include "sphtroch/draw/text_layout.hpp"

#include <string>
#include <vector>

using namespace sphtroch;

TEST_CASE("text_width_em: DejaVu Sans's advance widths rounded up, 1 em outside ASCII", "[text]") {
  CHECK(text_width_em("") == 0.0);
  CHECK(text_width_em("N12") == Approx(0.75 + 2 * 0.64));
  CHECK(text_width_em("a2 = pi/2") == Approx(0.62 + 0.64 + 0.32 + 0.84 + 0.32 + 0.64 + 0.28 + 0.34 + 0.64));
  CHECK(text_width_em("\u2014") == 1.0);  // the em dash: three bytes, one character
  CHECK(text_width_em("mm") > text_width_em("ii"));
}

TEST_CASE("wrap_text: every line fits, breaks after spaces and commas, the text comes back", "[text]") {
  const std::string caption = "twists pi/2,pi/3,pi/4, rates 1,1/2,-3/2, phases 0,0.3,0 \u2014 2 node(s) (2 crossing, 0 tangency), 0 cusp(s)";
  for (const double width : {80.0, 150.0, 200.0, 333.0, 500.0, 2000.0}) {
    const std::vector<std::string> lines = wrap_text(caption, width, 12);
    INFO("width " << width);
    REQUIRE(!lines.empty());
    std::size_t at = 0;  // the lines are the caption's text in order, a space dropped at a break
    for (const std::string& line : lines) {
      CHECK(text_width_em(line) * 12 <= width);
      CHECK(line.front() != ' ');
      CHECK(line.back() != ' ');
      if (at > 0 && caption[at] == ' ') ++at;
      CHECK(caption.compare(at, line.size(), line) == 0);
      at += line.size();
    }
    CHECK(at == caption.size());
  }
  CHECK(wrap_text(caption, 2000, 12).size() == 1);
  // Too wide for one line: the break after the em dash comes first, even where the greedy rule
  // would fill the line further.
  const std::string plot = "a2 = 0.7, a3 = 2.5, n = 13/5 \u2014 169 node(s) (169 crossing, 0 tangency), 0 cusp(s)";
  const double one_line = text_width_em(plot) * 12;
  const std::vector<std::string> two = wrap_text(plot, one_line - 1, 12);
  REQUIRE(two.size() == 2);
  CHECK(two[0] == "a2 = 0.7, a3 = 2.5, n = 13/5 \u2014");
  CHECK(two[1] == "169 node(s) (169 crossing, 0 tangency), 0 cusp(s)");
  CHECK(wrap_text(plot, one_line + 0.01, 12).size() == 1);
  CHECK(wrap_text("", 100, 12).empty());
  // A word wider than the line is cut between characters, never inside a UTF-8 sequence.
  const std::vector<std::string> cut = wrap_text("\u2014\u2014\u2014\u2014\u2014\u2014", 25, 10);
  CHECK(cut.size() == 3);
  for (const std::string& line : cut) CHECK(line == "\u2014\u2014");
}

TEST_CASE("picture_number: at most 6 significant digits, shortest form", "[text]") {
  CHECK(picture_number(1.5707963267948966) == "1.5708");
  CHECK(picture_number(1.0471975511965976) == "1.0472");
  CHECK(picture_number(2192) == "2192");
  CHECK(picture_number(0.3) == "0.3");
  CHECK(picture_number(0.000123456789) == "0.000123457");
  CHECK(picture_number(-2.5) == "-2.5");
  CHECK(picture_number(-0.0) == "0");
  CHECK(picture_number(123456789) == "123457000");
  CHECK(picture_number(4.6875, 3) == "4.69");
  CHECK(picture_number(1e-8) == "1e-08");
}
