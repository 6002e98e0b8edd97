#include "cli_common.hpp"

#include "png_output.hpp"

#include "sphtroch/draw/svg.hpp"

#include "sphtroch/core/cone_distance.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <thread>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace sphtroch::cli {

void TrainOptions::add_to(CLI::App& command) {
  command.add_option("--a2", a2, "carrier twist a2 in (0, pi): 1.25, pi/2, 2pi/3, 0.75pi, 90deg")->type_name("RAD")->required();
  command.add_option("--a3", a3, "tracer twist a3 in (0, pi); also ap, pi-ap, a2, pi-a2 with an offset (ap+1e-6)")->type_name("RAD")
      ->required();
  CLI::Option* ratio = command.add_option("--n", n, "gear ratio n = p/q, p != 0: 2, 5/2, 2.5 (sun-to-planet tooth ratio)")->type_name("P/Q");
  CLI::Option* gears = command.add_option("--teeth", teeth, "n as tooth counts ZS:ZP, sun:planet (39:15 is n = 13/5; ZS < 0: internal)")
      ->type_name("ZS:ZP");
  ratio->excludes(gears);
  gears->excludes(ratio);
  command.add_option("--phase", phase, "phase angle theta_p (Eq. 3), any finite angle")->type_name("RAD")->capture_default_str();
}

void PlotFlags::add_to(CLI::App& cmd) {
  cmd.add_option("--view", view,
                 "auto (default: from the curve's mean direction or a principal axis, stated in the picture), "
                 "top (along the sun axis), front, side, or AZ,EL (e.g. 30deg,45deg)")->type_name("auto|top|front|side|AZ,EL");
  cmd.add_option("--size", size, "width of the picture in px, and height above its notes and caption (64 .. 8192; default 520)")->type_name("PX");
  cmd.add_option("--labels", labels, "auto (default: labels kept one em apart, some left out), numbers (every N<i>/C<j>), none")->type_name("auto|numbers|none");
  cmd.add_option("--markers", markers,
                 "auto (default: every node and cusp marker up to 200 of them, none above; the picture says so), all, none")
                     ->type_name("auto|all|none");
  cmd.add_option("--style", style,
                 "curve (default: the lines, back half dashed) or density (time spent per steradian on the front half, "
                 "for dense curves)")->type_name("curve|density");
}

PlotOptions PlotFlags::options() const {
  PlotOptions p;
  if (!view.empty()) set_plot_view(p, view);
  if (!size.empty()) p.size_px = static_cast<double>(parse_count(size, "size", 64, 8192));
  if (!labels.empty()) p.labels = parse_plot_labels(labels);
  if (!markers.empty()) p.markers = parse_mark_mode(markers);
  if (!style.empty()) p.style = parse_plot_style(style);
  return p;
}

void check_svg_name(const std::string& path, const std::string& field) {
  const std::optional<std::string> ext = other_picture_format(path);
  if (!ext) return;
#if defined(SPHTROCH_HAVE_PNG)
  if (*ext == "png") return require_png_writer(path, field);  // rendered by the plugin (png_output.hpp)
  const std::string valid = "FILE.svg or FILE.png (another format: convert the SVG)";
#else
  const std::string valid = "FILE.svg (PNG needs the librsvg component, which this build of sphtroch does not have; "
                            "convert it, e.g. rsvg-convert FILE.svg -o FILE.png)";
#endif
  throw InvalidInput(field, path, "SVG is written, not ." + *ext, valid);
}

void add_output_option(CLI::App& command, std::string& path, const std::string& what) {
  command.add_option("-o,--output", path, "write " + what + " to FILE instead of stdout (never left partial)")->type_name("FILE");
}

double parse_radius(const std::string& text) {
  if (text.empty()) return 1.0;
  const std::optional<double> r = parse_number(text);
  if (!r) throw InvalidInput("radius", text, "not a number", "a length in [1e-100, 1e100] (the cone distance, any unit)");
  check_cone_distance(*r, "radius", text);
  return *r;
}

std::size_t parse_threads(const std::string& text) {
  if (!text.empty()) return parse_count(text, "threads", 1, kMaxThreads);
  return std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, kMaxThreads);
}

std::string file_key(const std::string& path) {
  if (path.empty() || path == "-") return {};
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  const auto slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (::stat(dir.c_str(), &st) != 0) return {};
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + "/" + name;
}

std::string input_key(const std::string& path) {
  if (path != "-") return file_key(path);
  struct stat st {};
  if (::fstat(STDIN_FILENO, &st) != 0 || !S_ISREG(st.st_mode)) return {};
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
}

void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
  std::vector<std::pair<std::string, const NamedFile*>> seen;
  for (const NamedFile& in : inputs)
    if (const std::string k = input_key(in.path); !k.empty()) seen.emplace_back(k, &in);
  const std::size_t input_count = seen.size();
  for (const NamedFile& out : outputs) {
    const std::string k = file_key(out.path);
    if (k.empty()) continue;
    for (std::size_t i = 0; i < seen.size(); ++i)
      if (seen[i].first == k)
        throw UsageError{out.field + " = " + out.path + ": is the same file as " + seen[i].second->field + " = " +
                         seen[i].second->path + (i < input_count ? " (an input would be replaced)" : "") +
                         "; valid: a distinct output path"};
    seen.emplace_back(k, &out);
  }
}

const std::vector<std::string> kTextOutputs = {"txt", "text", "csv", "tsv", "json", "svg"};
const std::vector<std::string> kPictureOutputs = {"svg", "png"};

namespace {

/// Suffixes that name a format: data, CAD, picture and document formats a user may expect a
/// command to write by name.
const std::vector<std::string> kNamedFormats = {
    "txt", "text", "csv", "tsv", "json", "jsonl", "yaml", "yml", "xml", "html", "htm", "md", "svg", "png", "jpg", "jpeg", "gif",
    "bmp", "tif", "tiff", "webp", "pdf", "eps", "ps", "npy", "npz", "mat", "h5", "hdf5", "fits", "parquet", "xls", "xlsx", "dxf",
    "obj", "stl", "ply", "off", "vtk", "vtp", "step", "stp", "iges", "igs", "3mf", "gltf", "glb", "urdf", "xyz"};

std::string lower_suffix(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size()) return "";
  std::string ext = name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

void check_output_suffix(const std::string& path, const std::string& option, const std::vector<std::string>& writes) {
  if (path.empty() || path == "-" || writes.empty()) return;  // empty: the caller checks its formats itself
  const std::string field = option.rfind("--", 0) == 0 ? option.substr(2) : option;  // InvalidInput's field has no "--"
  const std::string ext = lower_suffix(path);
  if (ext.empty() || std::find(kNamedFormats.begin(), kNamedFormats.end(), ext) == kNamedFormats.end()) return;
  if (std::find(writes.begin(), writes.end(), ext) != writes.end()) return;
  std::string valid;
  for (const std::string& w : writes) valid += (valid.empty() ? "FILE." : ", FILE.") + w;
  throw InvalidInput(field, path, "this command does not write ." + ext + " (the suffix names the format)",
                     valid + ", or a name without such a suffix");
}

void write_output(const std::string& path, const std::function<void(std::ostream&)>& write, const std::string& field,
                  const std::vector<std::string>& writes) {
  check_output_suffix(path, field, writes);
  OutputFile file = OutputFile::open(path, field);
  {
    OutputStream out(file);
    write(out);
  }
  file.commit();
}

void write_stdout_after_outputs(const std::vector<std::string>& written, const std::function<void(std::ostream&)>& write) {
  try {
    write_output("-", write);
  } catch (const BrokenPipe&) {
    throw;
  } catch (const OutputError& e) {
    if (written.empty()) throw;
    std::string files;
    for (std::size_t i = 0; i < written.size() && i < 3; ++i) files += (i ? ", " : "") + written[i];
    if (written.size() > 3) files += " (and " + std::to_string(written.size() - 3) + " more)";
    throw StdoutFailedAfterOutputs{"outputs written: " + files + "; stdout failed: " + e.what() +
                                   " (exit status 4: the files are complete)"};
  }
}

OutputFile& StagedOutputs::open(const std::string& path, const std::string& field) {
  files_.push_back(std::make_unique<OutputFile>(OutputFile::open(path, field)));
  return *files_.back();
}

void StagedOutputs::stage(const std::string& path, const std::string& field,
                          const std::function<void(std::ostream&)>& write, const std::vector<std::string>& writes) {
  check_output_suffix(path, field, writes);
  OutputFile& file = open(path, field);
  {
    OutputStream out(file);
    write(out);
  }
  file.finish_writing(false);  // no descriptor or buffer held until commit, which syncs (scenes of thousands of outputs)
}

void StagedOutputs::commit() {
  std::vector<OutputFile*> all;
  for (auto& f : files_) all.push_back(f.get());
  commit_together(all);
}

}  // namespace sphtroch::cli
