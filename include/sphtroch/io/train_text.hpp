// sphtroch/io/train_text.hpp — a gear train as the user wrote it: the four texts of a2, a3, n and
// the phase, kept as typed so that reports can echo them ("a2 = pi/2 = 1.5707963267948966 rad")
// and errors can name the field. Eigen only.
//
//   sphtroch::TrainText text{"pi/2", "ap+1e-6", "5/2"};   // phase defaults to "0"
//   sphtroch::GearTrain train = text.train();              // InvalidInput naming "a2", "a3", "n" or "phase"
//   sphtroch::TrainText gears{"1", "2", "", "0", "39:15"};  // n as tooth counts: n = 13/5, "39:15" echoed
//   sphtroch::Ratio n = sphtroch::ratio_of("", "39:15");      // 13/5: the ratio alone, of n or of teeth
//
// The forms are those of parse.hpp (angles, ratios, a3 relative to a pitch cone). The CLI's
// options and a scene's train entries both fill one of these; classification_output.hpp prints it.
#pragma once

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/io/parse.hpp"

#include <string>

namespace sphtroch {

/// n from its text or from tooth counts "ZS:ZP" (exactly one of the two non-empty). Throws
/// InvalidInput naming "n" or "teeth".
inline Ratio ratio_of(const std::string& n, const std::string& teeth) {
  if (teeth.empty() && n.empty()) throw InvalidInput("n", "(none)", "not given", "n = p/q, or tooth counts teeth ZS:ZP");
  if (teeth.empty()) return parse_ratio(n, "n");
  if (!n.empty()) throw InvalidInput("teeth", teeth, "given together with n = " + n, "one of n = p/q and teeth ZS:ZP");
  return parse_teeth(teeth, "teeth").ratio();
}

struct TrainText {
  std::string a2, a3, n, phase = "0";
  std::string teeth = "";  // "ZS:ZP" (core/teeth.hpp) instead of n, or empty

  /// n: from the tooth counts when given (then n must be empty), else from n. Throws InvalidInput
  /// naming "n" or "teeth".
  Ratio ratio() const { return ratio_of(n, teeth); }

  /// " (teeth 39:15)" when n was given as tooth counts, else "": what reports echo after n.
  std::string teeth_note() const { return teeth.empty() ? "" : " (teeth " + parse_teeth(teeth, "teeth").str() + ")"; }

  /// Parses the texts in the order a2, a3, n (or teeth), phase (the first that is not a value is
  /// reported), then validates the train (ranges: GearTrain). Throws InvalidInput whose field is
  /// "a2", "a3", "n", "teeth" or "phase".
  GearTrain train() const {
    const double a2v = parse_angle(a2, "a2");
    const A3Spec a3v = parse_a3(a3, "a3");
    const Ratio nv = ratio();
    const double phase_v = parse_angle(phase, "phase");
    return make_gear_train(a2v, a3v, nv, phase_v);
  }
};

/// " (teeth 39:15)" when a report echoes teeth for n (TeethSpec::of), else "".
inline std::string teeth_text(const TeethSpec& teeth, const Ratio& n) {
  const auto t = teeth.of(n);
  return t ? " (teeth " + t->str() + ")" : "";
}

/// The arguments that make `sphtroch trace` / `plot` draw this train ("--n 2 --a2 1.1 ...").
inline std::string train_arguments(const GearTrain& g) {
  return "--n " + g.ratio().str() + " --a2 " + number_text(g.a2()) + " --a3 " + number_text(g.a3()) + " --phase " +
         number_text(g.phase_given());
}

}  // namespace sphtroch
