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
// CSV: the header "t,x,y,z" ("t,x,y,z,vx,vy,vz" with velocity), then one row per sample, numbers
// in the shortest round-trip form (number_text.hpp). npy: float64, C order, shape (N, 4) or
// (N, 7), the same columns. t = theta2 (radians), P (Eq. 4) and dP/dtheta2 = omega x P (Eq. 47a)
// in the base frame. The bytes do not depend on the thread count.
#pragma once

#include "sphtroch/core/curve.hpp"
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

enum class TraceFormat { csv, npy };

struct TraceWriteOptions {
  TraceFormat format = TraceFormat::csv;
  bool velocity = false;
  std::size_t threads = 1;  // worker threads that compute and format blocks (1: none)
};

/// Rows per block: 16384 rows are at most 2.9 MB of CSV with velocities (1.3 MB without).
constexpr std::size_t kTraceBlockRows = 16384;

inline const char* trace_csv_header(bool velocity) { return velocity ? "t,x,y,z,vx,vy,vz\n" : "t,x,y,z\n"; }

/// Characters of one CSV row at most (7 numbers, separators, newline).
constexpr std::size_t kMaxTraceRowChars = 7 * (kMaxNumberChars + 1);

/// Formats one CSV row "t,x,y,z[,vx,vy,vz]\n" at out; returns its end.
inline char* write_trace_csv_row(char* out, double t, const Vector3d& p, const Vector3d* v) {
  out = write_number(out, t);
  for (int k = 0; k < 3; ++k) {
    *out++ = ',';
    out = write_number(out, p[k]);
  }
  if (v)
    for (int k = 0; k < 3; ++k) {
      *out++ = ',';
      out = write_number(out, (*v)[k]);
    }
  *out++ = '\n';
  return out;
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
inline void write_trace(OutputFile& out, const TracerCurve<double>& curve, const UniformSampling<double>& sampling,
                        const TraceWriteOptions& options) {
  const bool vel = options.velocity;
  const std::size_t cols = vel ? 7 : 4;
  if (options.format == TraceFormat::npy) out.write(npy_header(sampling.count, cols));
  else out.write(trace_csv_header(vel));
  const std::size_t blocks = (sampling.count + kTraceBlockRows - 1) / kTraceBlockRows;
  auto produce = [&](std::size_t b, std::string& text) {
    const std::size_t first = b * kTraceBlockRows, last = std::min(sampling.count, first + kTraceBlockRows);
    if (options.format == TraceFormat::npy) {
      text.resize((last - first) * cols * sizeof(double));
      char* p = text.data();
      for (std::size_t i = first; i < last; ++i) {
        const double t = sampling.parameter(i);
        const Vector3d P = curve.point(t);
        double row[7] = {t, P.x(), P.y(), P.z(), 0, 0, 0};
        if (vel) {
          const Vector3d V = curve.screw_axis(t).cross(P);  // = curve.velocity(t), one point evaluation
          row[4] = V.x(), row[5] = V.y(), row[6] = V.z();
        }
        std::memcpy(p, row, cols * sizeof(double));
        p += cols * sizeof(double);
      }
      return;
    }
    text.resize((last - first) * kMaxTraceRowChars);
    char* p = text.data();
    for (std::size_t i = first; i < last; ++i) {
      const double t = sampling.parameter(i);
      const Vector3d P = curve.point(t);
      if (vel) {
        const Vector3d V = curve.screw_axis(t).cross(P);
        p = write_trace_csv_row(p, t, P, &V);
      } else {
        p = write_trace_csv_row(p, t, P, nullptr);
      }
    }
    text.resize(static_cast<std::size_t>(p - text.data()));
  };
  for_each_block_in_order(blocks, options.threads, produce, [&](const std::string& text) { out.write(text); });
}

}  // namespace sphtroch
