#include "cli_common.hpp"

#include "sphtroch/parse.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace sphtroch::cli {

void TrainOptions::add_to(CLI::App& command) {
  command.add_option("--a2", a2, "carrier twist a2 in (0, pi): 1.25, pi/2, 2pi/3, 0.75pi, 90deg")->required();
  command.add_option("--a3", a3, "tracer twist a3 in (0, pi); also ap, pi-ap, a2, pi-a2 with an offset (ap+1e-6)")
      ->required();
  command.add_option("--n", n, "gear ratio n = p/q, p != 0: 2, 5/2, 2.5")->required();
  command.add_option("--phase", phase, "phase angle theta_p (Eq. 3), any finite angle")->capture_default_str();
}

GearTrain TrainOptions::train() const {
  const double a2v = parse_angle(a2, "a2");
  const A3Spec a3v = parse_a3(a3, "a3");
  const Ratio nv = parse_ratio(n, "n");
  const double ph = parse_angle(phase, "phase");
  return make_gear_train(a2v, a3v, nv, ph);
}

void add_output_option(CLI::App& command, std::string& path, const std::string& what) {
  command.add_option("-o,--output", path, "write " + what + " to FILE instead of stdout (never left partial)");
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string shortest_number(double v) {
  char buf[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string seconds_text(double seconds) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g", seconds);
  return buf;
}

void write_trajectory_csv(std::ostream& out, const Trajectory<double>& tr, const std::vector<Vector3d>& velocities) {
  const bool with_velocity = !velocities.empty();
  out << (with_velocity ? "t,x,y,z,vx,vy,vz\n" : "t,x,y,z\n");
  for (std::size_t i = 0; i < tr.size(); ++i) {
    const auto& p = tr.points[i];
    out << number(tr.t[i]) << ',' << number(p.x()) << ',' << number(p.y()) << ',' << number(p.z());
    if (with_velocity) {
      const auto& v = velocities[i];
      out << ',' << number(v.x()) << ',' << number(v.y()) << ',' << number(v.z());
    }
    out << '\n';
  }
}

std::size_t parse_count(const std::string& text, const std::string& field, std::size_t lo, std::size_t hi) {
  const std::string range = "integer " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw InvalidInput(field, text, "not a whole number", range);
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v < lo || v > hi) throw InvalidInput(field, text, "outside the valid range", range);
  return static_cast<std::size_t>(v);
}

void write_output(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path.empty() || path == "-") {
    // Build the text first: a failure half-way must not leave partial output on stdout either.
    std::ostringstream text;
    write(text);
    std::fwrite(text.str().data(), 1, text.str().size(), stdout);
    std::fflush(stdout);
    return;
  }
  StagedOutputs out;
  out.stage(path, "--output", write);
  out.commit();
}

StagedOutputs::~StagedOutputs() {
  for (const Pending& p : pending_) std::remove(p.tmp.c_str());
}

void StagedOutputs::stage(const std::string& path, const std::string& field,
                          const std::function<void(std::ostream&)>& write) {
  const std::string tmpl = path + ".tmp.XXXXXX";
  std::vector<char> name(tmpl.begin(), tmpl.end());
  name.push_back('\0');
  const int fd = mkstemp(name.data());
  if (fd < 0)
    throw UsageError{field + " = " + path + ": cannot be written (" + std::strerror(errno) +
                     "); valid: a path in an existing, writable directory"};
  // mkstemp creates the file 0600; give the result the mode a plain open() would (0666 & ~umask).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd, 0666 & ~mask);
  ::close(fd);
  pending_.push_back({path, field, name.data()});
  std::ofstream out(pending_.back().tmp, std::ios::binary | std::ios::trunc);
  write(out);
  out.flush();
  if (!out) throw UsageError{field + " = " + path + ": write failed; valid: a writable path with free space"};
}

void StagedOutputs::commit() {
  while (!pending_.empty()) {
    const Pending& p = pending_.front();
    if (std::rename(p.tmp.c_str(), p.path.c_str()) != 0)
      throw UsageError{p.field + " = " + p.path + ": cannot be replaced (" + std::strerror(errno) +
                       "); valid: a writable file path"};
    pending_.erase(pending_.begin());
  }
}

}  // namespace sphtroch::cli
