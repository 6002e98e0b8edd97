// sphtroch/cad/step_export.hpp — the tracer's path as a STEP AP214 file for CAD: one cubic
// B-spline edge through the path, within a stated tolerance of it (OpenCASCADE 7.6).
//
//   const sphtroch::GearTrain train(0.7, 2.5, sphtroch::Ratio(13, 5));
//   sphtroch::StepOptions o;  o.radius = 25.0;  o.tolerance = 1e-4;   // mm, say
//   const sphtroch::StepPath path = sphtroch::step_path(train, o);   // the B-spline, checked
//   std::string file = sphtroch::step_text(path);                     // ISO-10303-21 text
//
// The B-spline (GeomAPI_Interpolate) interpolates radius * P(theta2) at N equally spaced
// parameters theta_k = T k / N (T: the period 2 pi q, or 2 pi K for an open curve of K turns) and
// keeps theta2 as its own parameter, with the exact end tangents radius * dP/dtheta2 (a closed
// path's ends meet at one point with one tangent). Its error e(theta) = |B(theta) -
// radius P(theta)| bounds the distance of every point of either curve to the other. N starts at
// 8 (1 + |n|) T and doubles until e, checked at 3 points inside every span (a cubic spline's error
// between knots peaks once per span), is at most tolerance / 4; the largest checked e is
// reported. P(theta) is analytic (Eq. 4), so e falls as N^-4: cusps (speed 0) need no special
// care, because theta2 does not slow down there. Cost bound, up front: a path whose first N is
// above kMaxStepPoints is refused (InvalidInput naming "turns", or "n" for a closed path), and so
// is a tolerance that the first level's error predicts (e ~ N^-4) to need more (naming
// "tolerance"). The file holds every real with 16 significant digits (kStepRealFormat: the most
// that OpenCASCADE's 24-byte number buffer holds for every double, sign and 3-digit exponent
// included; its default of 12-13 digits would move the curve by more than a tight tolerance, 16
// move it by at most 5e-16 relative, 2000x below the tightest tolerance, 1e-12 * radius), and
// its uncertainty is the tolerance.
// Units: the file says millimetres; positions are radius (the cone distance, any unit the
// caller means) times the unit-sphere path. The product name holds the train and the tolerance.
// Side effects (OpenCASCADE's own process-wide state): step_text sets the STEP writer's static
// parameters (schema AP214, unit, precision, product name) and both functions remove
// OpenCASCADE's console printers from its default messenger, so that nothing reaches stdout.
// Not thread-safe: call them from one thread at a time.
#pragma once

#if !defined(SPHTROCH_HAVE_STEP)
#error "sphtroch/cad/step_export.hpp needs OpenCASCADE: link the CMake target sphtroch::step"
#endif

#include "sphtroch/core/cone_distance.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <XSControl_WorkSession.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace sphtroch {

/// The most interpolation points a STEP path may take: OpenCASCADE evaluates a B-spline of N
/// knots in O(N) (BSplCLib::PoleIndex), so the check costs O(N^2): measured 30,000 points 1 s,
/// a 4.4 MB file.
constexpr std::size_t kMaxStepPoints = std::size_t(1) << 15;
/// The printf format of every real in the file: "-d.dddddddddddddddE-ddd" is 23 characters, so
/// every double fits OpenCASCADE's number buffer (StepData_StepWriter::Send(Real): char[24] with
/// the NUL; "%.17E" overflowed it by up to 2 bytes for a negative real with a 3-digit exponent).
constexpr const char* kStepRealFormat = "%.15E";
/// The longest text kStepRealFormat makes, NUL excluded (a test checks every kind of double).
constexpr int kStepRealChars = 23;
/// The fewest carrier turns of an open STEP path (a shorter arc's points merge in the kernel).
constexpr double kMinStepTurns = 1e-6;

struct StepOptions {
  double radius = 1.0;              // positions are radius * P (the cone distance; core/cone_distance.hpp)
  std::optional<double> tolerance;  // max |B - radius P|, in the radius' unit; none: 1e-6 * radius
  std::optional<double> turns;      // an open path of this many carrier turns, [1e-6, 1e6] (else the period)
};

struct StepPath {
  Handle(Geom_BSplineCurve) curve;  // parameter theta2 in [0, T]
  std::size_t points = 0;           // interpolation points N (+ 1 for the end)
  double tolerance = 0.0;           // the bound asked for (radius units)
  double checked_error = 0.0;       // the largest |B - radius P| at the check points (<= tolerance / 4)
  std::string product;              // "sphtroch a2=.. a3=.. n=p/q phase=.. radius=.. tolerance=.."
};

/// The refusals of step_path that need no computation (radius, tolerance, turns, a path too
/// long), so that a caller may check them before opening its output. Throws as step_path does.
inline void check_step_options(const GearTrain& train, const StepOptions& options);

/// The checked B-spline of the train's path (see header). Throws InvalidInput naming "radius"
/// (outside [1e-100, 1e100]: check_cone_distance), "tolerance" (not finite, below 1e-12 * radius, or needing more than
/// kMaxStepPoints points), "turns" (outside [1e-6, 1e6], or a path too long) or "n" (a closed
/// path too long); std::runtime_error if OpenCASCADE cannot interpolate.
inline StepPath step_path(const GearTrain& train, const StepOptions& options);

/// The STEP AP214 file (ISO-10303-21 text, reals with 17 digits, millimetres) holding the path as
/// one edge; its header names the product and `originating_system` (the tool writes "sphtroch
/// VERSION"), no author or organisation. Throws std::runtime_error if OpenCASCADE cannot translate it.
inline std::string step_text(const StepPath& path, const std::string& originating_system = "sphtroch");

// Implementation details follow.
namespace step_detail {

inline void silence_opencascade() {
  static const bool once = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    return true;
  }();
  (void)once;
}

inline gp_Pnt scaled_point(const Vector3d& p, double radius) { return gp_Pnt(radius * p.x(), radius * p.y(), radius * p.z()); }
inline gp_Vec scaled_vector(const Vector3d& v, double radius) { return gp_Vec(radius * v.x(), radius * v.y(), radius * v.z()); }

/// The interpolating B-spline through N + 1 points theta_k = T k / N (the last is the first's
/// point again for a closed path), or none if OpenCASCADE refuses.
inline opencascade::handle<Geom_BSplineCurve> interpolate(const TracerCurve<double>& curve, double period,
                                                           std::size_t n, double radius, bool closed) {
  const int count = static_cast<int>(n) + 1;
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, count);
  Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, count);
  for (int k = 0; k < count; ++k) {
    const double t = k + 1 == count ? period : period * double(k) / double(n);
    const Vector3d p = closed && k + 1 == count ? curve.point(0.0) : curve.point(t);
    points->SetValue(k + 1, scaled_point(p, radius));
    params->SetValue(k + 1, t);
  }
  try {
    GeomAPI_Interpolate fit(points, params, Standard_False, 1e-12 * radius);
    fit.Load(scaled_vector(curve.velocity(0.0), radius),
             scaled_vector(curve.velocity(closed ? 0.0 : period), radius), Standard_False);
    fit.Perform();
    if (!fit.IsDone()) return {};
    return fit.Curve();
  } catch (const Standard_Failure&) {
    return {};
  }
}

/// max |B(theta) - radius P(theta)| at 3 points inside every span; NaN if any is not a number.
inline double checked_error(const Geom_BSplineCurve& b, const TracerCurve<double>& curve, double period,
                            std::size_t n, double radius) {
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    for (const double f : {0.25, 0.5, 0.75}) {
      const double t = period * (double(k) + f) / double(n);
      const gp_Pnt q = b.Value(t);
      const Vector3d p = radius * curve.point(t);
      const double e = std::hypot(q.X() - p.x(), q.Y() - p.y(), q.Z() - p.z());
      if (!(e <= worst)) worst = e;  // NaN sticks
      if (std::isnan(worst)) return worst;
    }
  return worst;
}

inline std::string product_name(const GearTrain& train, const StepOptions& o, double tolerance) {
  return "sphtroch a2=" + number_text(train.a2()) + " a3=" + number_text(train.a3()) + " n=" + train.ratio().str() +
         " phase=" + number_text(train.phase()) + " radius=" + number_text(o.radius) +
         " tolerance=" + number_text(tolerance) + (o.turns ? " turns=" + number_text(*o.turns) : std::string());
}

/// The checked options: the tolerance (default 1e-6 radius) and the parameter span T.
inline std::pair<double, double> checked_tolerance_and_span(const GearTrain& train, const StepOptions& o) {
  check_cone_distance(o.radius);
  const double tolerance = o.tolerance.value_or(1e-6 * o.radius);
  if (!(std::isfinite(tolerance) && tolerance >= 1e-12 * o.radius))
    throw InvalidInput("tolerance", report_number(tolerance), "below what double precision can check",
                       ">= 1e-12 * radius = " + number_text(1e-12 * o.radius));
  if (o.turns && !(*o.turns >= kMinStepTurns && *o.turns <= 1e6))
    throw InvalidInput("turns", report_number(*o.turns), "outside the range STEP export takes", "[1e-6, 1e6] carrier turns");
  return {tolerance, o.turns ? 2 * Constants<double>::pi() * *o.turns : train.period()};
}

/// The first N: 8 (1 + |n|) per radian of the span, at least 16; refused above kMaxStepPoints.
inline std::size_t first_point_count(const GearTrain& train, const StepOptions& o, double span) {
  const double start = std::max(16.0, std::ceil(8.0 * (1.0 + std::fabs(train.ratio().value())) * span));
  if (!(start <= double(kMaxStepPoints)))
    throw InvalidInput(o.turns ? "turns" : "n", o.turns ? number_text(*o.turns) : train.ratio().str(),
                       "a path of " + number_text(span) + " rad of carrier angle needs more than " +
                           std::to_string(kMaxStepPoints) + " B-spline points",
                       o.turns ? "fewer turns" : "a ratio p/q with a smaller 8 (1 + |n|) 2 pi q (or --turns)");
  return static_cast<std::size_t>(start);
}

}  // namespace step_detail

inline void check_step_options(const GearTrain& train, const StepOptions& options) {
  const double span = step_detail::checked_tolerance_and_span(train, options).second;
  (void)step_detail::first_point_count(train, options, span);
}

inline StepPath step_path(const GearTrain& train, const StepOptions& options) {
  const auto [tolerance, span] = step_detail::checked_tolerance_and_span(train, options);
  const TracerCurve<double> curve(train);
  step_detail::silence_opencascade();
  std::size_t n = step_detail::first_point_count(train, options, span);
  const auto too_tight = [&](double predicted) {
    return InvalidInput("tolerance", report_number(tolerance), "needs about " + number_text(std::ceil(predicted)) +
                        " B-spline points, more than " + std::to_string(kMaxStepPoints),
                        "a larger tolerance (the default is 1e-6 * radius)");
  };
  for (;;) {
    Handle(Geom_BSplineCurve) b = step_detail::interpolate(curve, span, n, options.radius, !options.turns);
    if (b.IsNull()) throw std::runtime_error("STEP: OpenCASCADE could not interpolate the path with " + std::to_string(n) + " points");
    const double error = step_detail::checked_error(*b, curve, span, n, options.radius);
    if (!std::isfinite(error)) throw std::runtime_error("STEP: the B-spline is not finite");
    if (error <= tolerance / 4)
      return {b, n + 1, tolerance, error, step_detail::product_name(train, options, tolerance)};
    const double predicted = double(n) * std::pow(error / (tolerance / 4), 0.25);  // e ~ N^-4
    if (predicted > 2.0 * double(kMaxStepPoints) || 2 * n > kMaxStepPoints) throw too_tight(std::max(predicted, 2.0 * double(n)));
    n *= 2;
  }
}

namespace step_detail {

/// The header's FILE_DESCRIPTION and FILE_NAME: the product's name, `system` as the originating
/// system, no author or organisation (OpenCASCADE's own placeholders otherwise). The
/// MakeHeader made from the model edits the model's own header entities.
inline void name_the_file(const Handle(StepData_StepModel)& model, const std::string& product, const std::string& system) {
  APIHeaderSection_MakeHeader header(model);
  auto text = [](const std::string& s) { return Handle(TCollection_HAsciiString)(new TCollection_HAsciiString(s.c_str())); };
  header.SetName(text(product));
  header.SetAuthorValue(1, text(""));
  header.SetOrganizationValue(1, text(""));
  header.SetOriginatingSystem(text(system));
  header.SetAuthorisation(text(""));
  header.SetDescriptionValue(1, text("a spherical trochoid: the path of a point of a spherical planetary gear train"));
}

}  // namespace step_detail

inline std::string step_text(const StepPath& path, const std::string& originating_system) {
  step_detail::silence_opencascade();
  try {
    STEPControl_Writer writer;
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    Interface_Static::SetCVal("write.step.unit", "MM");
    Interface_Static::SetCVal("write.step.product.name", path.product.c_str());
    Interface_Static::SetIVal("write.precision.mode", 2);  // the uncertainty is ours:
    Interface_Static::SetRVal("write.precision.val", path.tolerance);
    const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(path.curve).Edge();
    if (writer.Transfer(edge, STEPControl_AsIs) != IFSelect_RetDone) throw std::runtime_error("STEP: OpenCASCADE could not translate the path");
    step_detail::name_the_file(writer.Model(), path.product, originating_system);
    const Handle(StepData_Protocol) protocol = Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol());
    StepData_StepWriter text_writer(writer.Model());
    text_writer.FloatWriter().SetFormat(kStepRealFormat);  // 16 digits, within OpenCASCADE's buffer
    text_writer.SendModel(protocol);
    std::ostringstream out;
    if (protocol.IsNull() || !text_writer.Print(out)) throw std::runtime_error("STEP: OpenCASCADE could not write the path");
    return out.str();
  } catch (const Standard_Failure& e) {
    throw std::runtime_error(std::string("STEP: OpenCASCADE failed: ") + e.GetMessageString());
  }
}

}  // namespace sphtroch
