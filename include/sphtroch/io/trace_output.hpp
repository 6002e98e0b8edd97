// sphtroch/io/trace_output.hpp — a sampled trajectory written as CSV or NumPy .npy, streamed: rows
// are computed and formatted in blocks on worker threads and written in order, so memory does
// not grow with the number of samples (2 x threads blocks of kTraceBlockRows rows).
//
//   sphtroch::TracerCurve<double> curve(train);
//   auto out = sphtroch::OutputFile::open("t.npy", "output");
//   sphtroch::write_trace(out, curve, sphtroch::period_sampling(curve, 1000000),
//                         {sphtroch::TraceFormat::npy, /*velocity=*/false, /*threads=*/2});
//   out.commit();
//
// CSV: the header "t,x,y,z" ("t,x,y,z,vx,vy,vz" with velocity; then ",speed,geodesic_curvature,
// tangential_acceleration" with kinematics), one row per sample, numbers in the shortest round-trip
// form (number_text.hpp); with degrees the first column is t in degrees ("t_deg"). npy: float64,
// C order, shape (N, 4), (N, 7), (N, 7) or (N, 10), the same columns. t = theta2 (radians), P (Eq. 4) and dP/dtheta2 = omega x P (Eq. 47a) in the base frame,
// the kinematics of core/kinematics.hpp. The bytes do not depend on the thread count.
// For CAD (positions only, no t): DXF — an ASCII DXF R12 file, its HEADER stating millimetres (as
// the STEP export does: a radius is a length in mm for CAD), whose ENTITIES section holds one 3-D
// POLYLINE (group 70 flag 8, plus 1 when closed: the last sample joins the first) with a VERTEX
// (flag 32) per sample, layer "0"; OBJ — a "v x y z" line per sample and "l" lines joining them
// in order (at most kObjLineVertices indices a line, consecutive lines sharing their end vertex;
// a closed curve ends with "l N 1"). TraceWriteOptions::radius scales every position and velocity
// (the cone distance in the user's unit: x * radius rounded once; 1 writes the unit sphere), the
// speed and the tangential acceleration, and divides the geodesic curvature (1/length).
#pragma once

#include "sphtroch/core/cone_distance.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/io/npy.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/sampling.hpp"

#include <algorithm>
#include <cstring>
#include <ostream>
#include <string>

namespace sphtroch {

enum class TraceFormat { csv, npy, dxf, obj };

struct TraceWriteOptions {
  TraceFormat format = TraceFormat::csv;
  bool velocity = false;    // csv, npy only
  std::size_t threads = 1;  // worker threads that compute and format blocks (1: none)
  double radius = 1.0;      // positions and velocities times this, [1e-100, 1e100] (core/cone_distance.hpp)
  bool closed = true;       // dxf, obj: the last sample joins the first (a period's samples)
  bool kinematics = false;  // csv, npy only: speed, geodesic_curvature, tangential_acceleration
  bool degrees = false;     // csv, npy only: the t column in degrees (header t_deg)
};

/// Indices on one OBJ "l" line at most.
constexpr std::size_t kObjLineVertices = 1000;

/// Rows per block: a CSV block of c columns takes at most 16384 c (kMaxNumberChars + 1) bytes,
/// 1.6 MB for t,x,y,z, 2.9 MB with velocities, 4.1 MB with kinematics too.
constexpr std::size_t kTraceBlockRows = 16384;

inline std::string trace_csv_header(bool velocity, bool kinematics = false, bool degrees = false) {
  return std::string(degrees ? "t_deg,x,y,z" : "t,x,y,z") + (velocity ? ",vx,vy,vz" : "") +
         (kinematics ? ",speed,geodesic_curvature,tangential_acceleration" : "") + "\n";
}

/// Characters of one CSV row at most (10 numbers, separators, newline).
constexpr std::size_t kMaxTraceRowChars = 10 * (kMaxNumberChars + 1);

/// Formats one CSV row of `count` numbers ("t,x,y,z,...\n") at out; returns its end.
inline char* write_csv_numbers(char* out, const double* values, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k) {
    if (k) *out++ = ',';
    out = write_number(out, values[k]);
  }
  *out++ = '\n';
  return out;
}

/// Formats one CSV row "t,x,y,z[,vx,vy,vz]\n" at out; returns its end.
inline char* write_trace_csv_row(char* out, double t, const Vector3d& p, const Vector3d* v) {
  const double row[7] = {t, p.x(), p.y(), p.z(), v ? v->x() : 0.0, v ? v->y() : 0.0, v ? v->z() : 0.0};
  return write_csv_numbers(out, row, v ? 7 : 4);
}

/// The CSV of an in-memory trajectory (velocities used when not empty); the same bytes as write_trace.
inline void write_trajectory_csv(std::ostream& out, const Trajectory<double>& tr,
                                 const std::vector<Vector3d>& velocities = {}) {
  const bool with_velocity = !velocities.empty();
  out << trace_csv_header(with_velocity);
  std::string block;
  for (std::size_t i = 0; i < tr.size(); i += kTraceBlockRows) {
    const std::size_t end = std::min(tr.size(), i + kTraceBlockRows);
    block.resize((end - i) * kMaxTraceRowChars);
    char* p = block.data();
    for (std::size_t k = i; k < end; ++k)
      p = write_trace_csv_row(p, tr.t[k], tr.points[k], with_velocity ? &velocities[k] : nullptr);
    out.write(block.data(), p - block.data());
  }
}

/// Streams the samples of `sampling` to `out` in the chosen format (see the top). Throws what
/// `out` throws (OutputError, BrokenPipe). Does not commit `out`.
namespace trace_output_detail {

/// DXF's HEADER section: R12 ($ACADVER AC1009), drawing units millimetres ($INSUNITS 4, metric
/// $MEASUREMENT 1), the unit the STEP export states: without it readers assume metres (ezdxf) or
/// none, and an import comes in 1000 times off.
constexpr const char* kDxfHeader =
    "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n4\n9\n$MEASUREMENT\n70\n1\n0\nENDSEC\n";

/// DXF: the file up to the first VERTEX, and from SEQEND to the end (see header).
inline std::string dxf_head(bool closed) {
  return std::string(kDxfHeader) + "0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n8\n0\n66\n1\n10\n0\n20\n0\n30\n0\n70\n" +
         (closed ? "9" : "8") + "\n";
}
constexpr const char* kDxfTail = "0\nSEQEND\n8\n0\n0\nENDSEC\n0\nEOF\n";

/// One DXF VERTEX of a 3-D polyline at p.
inline char* write_dxf_vertex(char* out, const Vector3d& p) {
  static const char head[] = "0\nVERTEX\n8\n0\n";
  out = std::copy(head, head + sizeof head - 1, out);
  for (int k = 0; k < 3; ++k) {
    *out++ = static_cast<char>('1' + k);
    *out++ = '0';
    *out++ = '\n';
    out = write_number(out, p[k]);
    *out++ = '\n';
  }
  static const char flag[] = "70\n32\n";
  return std::copy(flag, flag + sizeof flag - 1, out);
}

/// One OBJ vertex line "v x y z".
inline char* write_obj_vertex(char* out, const Vector3d& p) {
  *out++ = 'v';
  for (int k = 0; k < 3; ++k) {
    *out++ = ' ';
    out = write_number(out, p[k]);
  }
  *out++ = '\n';
  return out;
}

/// The OBJ "l" lines joining vertices 1 .. count in order (and count to 1 when closed).
inline void write_obj_lines(OutputFile& out, std::size_t count, bool closed) {
  std::string line;
  for (std::size_t first = 1; first < count; first += kObjLineVertices - 1) {
    const std::size_t last = std::min(count, first + kObjLineVertices - 1);
    line = "l";
    for (std::size_t i = first; i <= last; ++i) line += ' ' + std::to_string(i);
    out.write(line + '\n');
  }
  if (closed && count > 2) out.write("l " + std::to_string(count) + " 1\n");
}

}  // namespace trace_output_detail

/// Curve: TracerCurve<double>, or any curve with point, screw_axis and acceleration (ChainCurve<double>).
template <typename Curve>
void write_trace(OutputFile& out, const Curve& curve, const UniformSampling<double>& sampling, const TraceWriteOptions& options) {
  namespace d = trace_output_detail;
  const bool vel = options.velocity, kin = options.kinematics;
  check_cone_distance(options.radius);  // before the first byte
  const double scale = options.radius;
  const std::size_t cols = 4 + (vel ? 3 : 0) + (kin ? 3 : 0);
  if (options.format == TraceFormat::npy) out.write(npy_header(sampling.count, cols));
  else if (options.format == TraceFormat::dxf) out.write(d::dxf_head(options.closed));
  else if (options.format == TraceFormat::csv) out.write(trace_csv_header(vel, kin, options.degrees));
  const std::size_t blocks = (sampling.count + kTraceBlockRows - 1) / kTraceBlockRows;
  // Unit-sphere values, then times the radius (each coordinate rounded once more; none at radius 1).
  auto point = [&](double t) { return scale == 1.0 ? curve.point(t) : Vector3d(scale * curve.point(t)); };
  // omega x P0 = curve.velocity(t): at radius 1 from the point just evaluated, else from the
  // unit-sphere point again (times the radius, rounded once).
  auto velocity = [&](double t, const Vector3d& P) {
    if (scale == 1.0) return Vector3d(curve.screw_axis(t).cross(P));
    return Vector3d(scale * curve.screw_axis(t).cross(curve.point(t)));
  };
  auto produce = [&](std::size_t b, std::string& text) {
    const std::size_t first = b * kTraceBlockRows, last = std::min(sampling.count, first + kTraceBlockRows);
    if (options.format == TraceFormat::dxf || options.format == TraceFormat::obj) {
      text.resize((last - first) * (kMaxTraceRowChars + 40));
      char* p = text.data();
      for (std::size_t i = first; i < last; ++i) {
        const Vector3d P = point(sampling.parameter(i));
        p = options.format == TraceFormat::dxf ? d::write_dxf_vertex(p, P) : d::write_obj_vertex(p, P);
      }
      text.resize(static_cast<std::size_t>(p - text.data()));
      return;
    }
    // One row: t, P, [V], [speed, geodesic curvature, tangential acceleration] (see the top).
    auto row_of = [&](std::size_t i, double* row) {
      const double t = sampling.parameter(i);
      const Vector3d P = point(t);
      std::size_t c = 0;
      for (const double x : {options.degrees ? degrees(t) : t, P.x(), P.y(), P.z()}) row[c++] = x;
      if (vel) {
        const Vector3d V = velocity(t, P);
        for (const double x : {V.x(), V.y(), V.z()}) row[c++] = x;
      }
      if (kin) {
        const PathKinematics k = path_kinematics(curve, t);
        const bool unit = scale == 1.0;
        row[c++] = unit ? k.speed : scale * k.speed;
        row[c++] = unit ? k.geodesic_curvature : k.geodesic_curvature / scale;
        row[c++] = unit ? k.tangential_acceleration : scale * k.tangential_acceleration;
      }
    };
    // Rows are computed kRowRun at a time, then written: the samples of a run are independent, so
    // the processor overlaps their sine/cosine chains instead of waiting on each between numbers.
    constexpr std::size_t kRowRun = 64;
    double rows[kRowRun][10];
    const bool npy = options.format == TraceFormat::npy;
    text.resize((last - first) * cols * (npy ? sizeof(double) : kMaxNumberChars + 1));  // this row's width
    char* p = text.data();
    for (std::size_t run = first; run < last; run += kRowRun) {
      const std::size_t count = std::min(kRowRun, last - run);
      for (std::size_t k = 0; k < count; ++k) row_of(run + k, rows[k]);
      for (std::size_t k = 0; k < count; ++k) {
        if (!npy) {
          p = write_csv_numbers(p, rows[k], cols);
          continue;
        }
        std::memcpy(p, rows[k], cols * sizeof(double));
        p += cols * sizeof(double);
      }
    }
    text.resize(static_cast<std::size_t>(p - text.data()));
  };
  for_each_block_in_order(blocks, options.threads, produce, [&](const std::string& text) { out.write(text); });
  if (options.format == TraceFormat::dxf) out.write(d::kDxfTail);
  if (options.format == TraceFormat::obj) d::write_obj_lines(out, sampling.count, options.closed);
}

}  // namespace sphtroch
