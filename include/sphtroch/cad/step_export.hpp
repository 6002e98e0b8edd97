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
// care, because theta2 does not slow down there. More than kMaxStepPoints points is refused
// (InvalidInput naming "tolerance").
// Units: the file says millimetres; positions are radius (the cone distance, any unit the
// caller means) times the unit-sphere path. The product name holds the train and the tolerance.
#pragma once

#if !defined(SPHTROCH_HAVE_STEP)
#error "sphtroch/cad/step_export.hpp needs OpenCASCADE: link the CMake target sphtroch::step"
#endif

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"

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
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>

namespace sphtroch {

/// The most interpolation points a STEP path may take (a tolerance needing more is refused).
constexpr std::size_t kMaxStepPoints = std::size_t(1) << 20;

struct StepOptions {
  double radius = 1.0;          // positions are radius * P (the cone distance; > 0, finite)
  std::optional<double> tolerance;  // max |B - radius P|, in the radius' unit; none: 1e-6 * radius
  std::optional<double> turns;  // an open path of this many carrier turns (else the closed period)
};

struct StepPath {
  Handle(Geom_BSplineCurve) curve;  // parameter theta2 in [0, T]
  std::size_t points = 0;           // interpolation points N (+ 1 for the end)
  double tolerance = 0.0;           // the bound asked for (radius units)
  double checked_error = 0.0;       // the largest |B - radius P| at the check points (<= tolerance / 4)
  std::string product;              // "sphtroch a2=.. a3=.. n=p/q phase=.. radius=.. tolerance=.."
};

/// The checked B-spline of the train's path (see header). Throws InvalidInput for a radius or
/// tolerance that is not finite and positive, a tolerance below 1e-12 * radius, or one that
/// needs more than kMaxStepPoints points.
inline StepPath step_path(const GearTrain& train, const StepOptions& options);

/// The STEP AP214 file (ISO-10303-21 text) holding the path as one edge. Throws
/// std::runtime_error if OpenCASCADE cannot write it (e.g. no writable temporary directory).
inline std::string step_text(const StepPath& path);

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

/// max |B(theta) - radius P(theta)| at 3 points inside every span.
inline double checked_error(const Geom_BSplineCurve& b, const TracerCurve<double>& curve, double period,
                            std::size_t n, double radius) {
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    for (const double f : {0.25, 0.5, 0.75}) {
      const double t = period * (double(k) + f) / double(n);
      const gp_Pnt q = b.Value(t);
      const Vector3d p = radius * curve.point(t);
      worst = std::max(worst, std::hypot(q.X() - p.x(), q.Y() - p.y(), q.Z() - p.z()));
    }
  return worst;
}

inline std::string product_name(const GearTrain& train, const StepOptions& o, double tolerance) {
  return "sphtroch a2=" + number_text(train.a2()) + " a3=" + number_text(train.a3()) + " n=" + train.ratio().str() +
         " phase=" + number_text(train.phase()) + " radius=" + number_text(o.radius) +
         " tolerance=" + number_text(tolerance) + (o.turns ? " turns=" + number_text(*o.turns) : std::string());
}

}  // namespace step_detail

inline StepPath step_path(const GearTrain& train, const StepOptions& options) {
  if (!(std::isfinite(options.radius) && options.radius > 0.0))
    throw InvalidInput("radius", number_text(options.radius), "not a positive length", "finite > 0");
  const double tolerance = options.tolerance.value_or(1e-6 * options.radius);
  if (!(std::isfinite(tolerance) && tolerance >= 1e-12 * options.radius))
    throw InvalidInput("tolerance", number_text(tolerance), "below what double precision can check",
                       ">= 1e-12 * radius = " + number_text(1e-12 * options.radius));
  const double period = options.turns ? 2 * Constants<double>::pi() * *options.turns : train.period();
  const bool closed = !options.turns;
  const TracerCurve<double> curve(train);
  step_detail::silence_opencascade();
  const double start = std::ceil(8.0 * (1.0 + std::fabs(train.ratio().value())) * period);
  for (auto n = static_cast<std::size_t>(std::max(16.0, start)); n <= kMaxStepPoints; n *= 2) {
    Handle(Geom_BSplineCurve) b = step_detail::interpolate(curve, period, n, options.radius, closed);
    if (b.IsNull()) continue;
    const double error = step_detail::checked_error(*b, curve, period, n, options.radius);
    if (error <= tolerance / 4)
      return {b, n + 1, tolerance, error, step_detail::product_name(train, options, tolerance)};
  }
  throw InvalidInput("tolerance", number_text(tolerance), "needs more than " + std::to_string(kMaxStepPoints) +
                     " interpolation points for this path", "a larger tolerance (the default is 1e-6 * radius)");
}

inline std::string step_text(const StepPath& path) {
  step_detail::silence_opencascade();
  const char* tmp = std::getenv("TMPDIR");
  std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/sphtroch-step-XXXXXX";
  if (!::mkdtemp(dir.data())) throw std::runtime_error("STEP: cannot create a temporary directory in " + dir);
  const std::string file = dir + "/path.step";
  std::string text;
  bool written = false;
  try {
    STEPControl_Writer writer;
    Interface_Static::SetCVal("write.step.schema", "AP214IS");
    Interface_Static::SetCVal("write.step.unit", "MM");
    Interface_Static::SetCVal("write.step.product.name", path.product.c_str());
    const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(path.curve).Edge();
    written = writer.Transfer(edge, STEPControl_AsIs) == IFSelect_RetDone && writer.Write(file.c_str()) == IFSelect_RetDone;
    std::ifstream in(file, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const Standard_Failure&) {
    written = false;
  }
  std::remove(file.c_str());
  ::rmdir(dir.c_str());
  if (!written || text.empty()) throw std::runtime_error("STEP: OpenCASCADE could not write the path");
  return text;
}

}  // namespace sphtroch
