// bench/bench_report.cpp — turns the JSON of sphtroch_bench (Google Benchmark, --benchmark_out)
// into one CSV per study and the plots, using the library's SVG writer (sphtroch/draw/svg.hpp).
//
//   sphtroch_bench_report bench.json OUT_DIR
//
// Reads the median aggregate of every benchmark (or its single run when run without repetitions);
// the benchmark name carries the parameters ("b_crossings/curve:7_3/N:1000"), the counters carry
// the values computed once outside the timing (errors, counts, bytes). Writes OUT_DIR/
// a_trace.csv, b_crossings.csv, c_predicates.csv, d_nodes.csv, e_s2.csv (when S2 ran),
// f_classify.csv, context.csv, crossings.svg, accuracy.svg; columns in data/bench/README.md.
// Exit status 1 when a benchmark reported an error (S2 disagreeing with the exact search is one),
// or when a crossing search differs from the brute force; 2 on unreadable input.
#include "sphtroch/draw/svg.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

struct Row {
  std::string study;
  std::map<std::string, std::string> params;
  double seconds = 0;      // median real time per iteration
  double cpu_seconds = 0;  // median CPU time per iteration
  json raw;
  double counter(const std::string& k, double fallback = NAN) const {
    return raw.contains(k) && raw[k].is_number() ? raw[k].get<double>() : fallback;
  }
  std::string param(const std::string& k) const {
    auto it = params.find(k);
    return it == params.end() ? std::string() : it->second;
  }
};

double unit_seconds(const std::string& unit) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  return 1.0;
}

/// Counts as integers, everything else with 6 significant digits; NaN as an empty field.
std::string num(double v) {
  if (std::isnan(v)) return "";
  char buf[64];
  if (v == std::floor(v) && std::fabs(v) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// ---- plots: log-log charts -------------------------------------------------------------------
struct Series {
  std::string label;
  std::string color;
  bool dashed = false;
  bool markers_only = false;
  std::vector<std::pair<double, double>> points;
};

std::string log_chart(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                      const std::vector<Series>& series) {
  const double W = 860, H = 460, L = 80, R = 330, T = 40, B = 60;
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const Series& s : series)
    for (auto [x, y] : s.points) {
      if (!(x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y))) continue;
      xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    }
  if (xmin > xmax) xmin = 1, xmax = 10, ymin = 1, ymax = 10;
  const double lx0 = std::floor(std::log10(xmin)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(xmax)));
  const double ly0 = std::floor(std::log10(ymin)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(ymax)));
  const auto px = [&](double x) { return L + (std::log10(x) - lx0) / (lx1 - lx0) * (W - L - R); };
  const auto py = [&](double y) { return H - B - (std::log10(y) - ly0) / (ly1 - ly0) * (H - T - B); };
  sphtroch::SvgWriter svg(W, H);
  svg.title(title);
  svg.rect(0, 0, W, H, "fill:white;stroke:none");
  svg.text(L, 24, title, "font:bold 14px sans-serif");
  const int ystep = (ly1 - ly0) > 8 ? 2 : 1;
  for (double e = lx0; e <= lx1; e += 1) {
    svg.line(px(std::pow(10, e)), T, px(std::pow(10, e)), H - B, "stroke:#ddd");
    svg.text(px(std::pow(10, e)), H - B + 18, "1e" + num(e), "font:11px sans-serif", "middle");
  }
  for (double e = ly0; e <= ly1; e += ystep) {
    svg.line(L, py(std::pow(10, e)), W - R, py(std::pow(10, e)), "stroke:#ddd");
    svg.text(L - 6, py(std::pow(10, e)) + 4, "1e" + num(e), "font:11px sans-serif", "end");
  }
  svg.rect(L, T, W - L - R, H - T - B, "fill:none;stroke:#333");
  svg.text((L + W - R) / 2, H - 16, xlabel, "font:12px sans-serif", "middle");
  svg.raw("<text x=\"16\" y=\"" + svg.num((T + H - B) / 2) + "\" transform=\"rotate(-90 16 " + svg.num((T + H - B) / 2) +
          ")\" style=\"font:12px sans-serif\" text-anchor=\"middle\">" + sphtroch::xml_escape(ylabel) + "</text>\n");
  double ly = T + 10;
  for (const Series& s : series) {
    std::vector<std::pair<double, double>> pts;
    for (auto p : s.points)
      if (p.first > 0 && p.second > 0 && std::isfinite(p.first) && std::isfinite(p.second)) pts.push_back(p);
    const std::string stroke = "fill:none;stroke-width:2;stroke:" + s.color + (s.dashed ? ";stroke-dasharray:6 4" : "");
    if (!s.markers_only && pts.size() > 1) {
      sphtroch::SvgPath d;
      d.move_to(px(pts[0].first), py(pts[0].second));
      for (std::size_t k = 1; k < pts.size(); ++k) d.line_to(px(pts[k].first), py(pts[k].second));
      svg.path(d, stroke);
    }
    for (auto p : pts) svg.circle(px(p.first), py(p.second), 3, "stroke:none;fill:" + s.color);
    svg.line(W - R + 12, ly, W - R + 36, ly, stroke);
    svg.circle(W - R + 24, ly, 3, "stroke:none;fill:" + s.color);
    svg.text(W - R + 42, ly + 4, s.label, "font:11px sans-serif");
    ly += 18;
  }
  return svg.finish();
}

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  return static_cast<bool>(f);
}

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: sphtroch_bench_report BENCH.json OUT_DIR\n";
    return 2;
  }
  json doc;
  try {
    std::ifstream in(argv[1]);
    if (!in) throw std::runtime_error("cannot open");
    // Google Benchmark prints non-finite values (the spread of a constant counter is 0/0) as
    // NaN / -nan / inf, which is not JSON: read them as null.
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text = std::regex_replace(text, std::regex(R"((:\s*)-?(nan|NaN|inf|Inf|INF|NAN)\b)"), "$1null");
    doc = json::parse(text);
  } catch (const std::exception& e) {
    std::cerr << "sphtroch_bench_report: " << argv[1] << ": unreadable benchmark JSON (" << e.what() << ")\n";
    return 2;
  }
  const std::string out = argv[2];
  int status = 0;

  // Collect one row per benchmark: the median aggregate if any, else the single iteration run.
  std::map<std::string, Row> rows;
  std::vector<std::string> order;
  for (const json& b : doc.at("benchmarks")) {
    const std::string run_name = b.value("run_name", b.value("name", ""));
    const bool aggregate = b.value("run_type", "") == "aggregate";
    if (aggregate && b.value("aggregate_name", "") != "median") continue;
    if (b.value("error_occurred", false)) {
      std::cerr << "sphtroch_bench_report: " << run_name << ": " << b.value("error_message", "error") << "\n";
      status = 1;
    }
    if (!aggregate && rows.count(run_name) && rows[run_name].raw.value("run_type", "") == "aggregate") continue;
    Row r;
    std::stringstream ss(run_name);
    std::string part;
    std::getline(ss, r.study, '/');
    while (std::getline(ss, part, '/')) {
      const auto c = part.find(':');
      if (c != std::string::npos) r.params[part.substr(0, c)] = part.substr(c + 1);
    }
    const double unit = unit_seconds(b.value("time_unit", "ns"));
    r.seconds = b.value("real_time", 0.0) * unit;
    r.cpu_seconds = b.value("cpu_time", 0.0) * unit;
    r.raw = b;
    if (!rows.count(run_name)) order.push_back(run_name);
    rows[run_name] = r;
  }
  const auto study = [&](const std::string& s) {
    std::vector<const Row*> v;
    for (const std::string& n : order)
      if (rows[n].study == s) v.push_back(&rows[n]);
    return v;
  };
  const json& ctx = doc.at("context");
  const int reps = doc.at("benchmarks").empty() ? 0 : doc["benchmarks"][0].value("repetitions", 1);

  {  // context
    std::ostringstream c;
    c << "date,host,num_cpus,mhz_per_cpu,load_avg_1m,load_avg_5m,load_avg_15m,benchmark_library_build_type,repetitions,s2\n";
    const json la = ctx.value("load_avg", json::array());
    c << ctx.value("date", "") << "," << ctx.value("host_name", "") << "," << ctx.value("num_cpus", 0) << ","
      << ctx.value("mhz_per_cpu", 0) << "," << (la.size() > 0 ? num(la[0].get<double>()) : "") << ","
      << (la.size() > 1 ? num(la[1].get<double>()) : "") << "," << (la.size() > 2 ? num(la[2].get<double>()) : "")
      << "," << ctx.value("library_build_type", "") << "," << reps << ",\"" << ctx.value("s2", "") << "\"\n";
    write_file(out + "/context.csv", c.str());
  }

  {  // a: trace cost and error
    std::ostringstream c;
    c << "scalar,method,reanchor_every,points,ns_per_point,max_error\n";
    for (const Row* r : study("a_trace")) {
      const double n = r->counter("points");
      c << r->param("scalar") << "," << r->param("method") << "," << r->param("k") << "," << num(n) << ","
        << num(r->seconds / n * 1e9) << "," << num(r->counter("max_error")) << "\n";
    }
    write_file(out + "/a_trace.csv", c.str());
  }

  std::map<std::string, double> ours_seconds;  // curve/N -> median seconds
  std::vector<Series> crossing_series;
  {  // b: crossing search vs N
    std::ostringstream c;
    c << "curve,vertices,seconds,ns_per_vertex,crossings,touchings,boxes,candidate_pairs,predicates,peak_bytes,"
         "bytes_per_vertex,equals_brute_force\n";
    std::map<std::string, Series> by_curve;
    for (const Row* r : study("b_crossings")) {
      const double n = r->counter("vertices");
      const double eq = r->counter("equals_brute_force");
      if (eq == 0) {
        std::cerr << "sphtroch_bench_report: " << r->raw.value("run_name", "") << ": differs from the brute force\n";
        status = 1;
      }
      c << r->param("curve") << "," << num(n) << "," << num(r->seconds) << "," << num(r->seconds / n * 1e9) << ","
        << num(r->counter("crossings")) << "," << num(r->counter("touchings")) << "," << num(r->counter("boxes")) << ","
        << num(r->counter("candidate_pairs")) << "," << num(r->counter("predicates")) << ","
        << num(r->counter("peak_bytes")) << "," << num(r->counter("peak_bytes") / n) << ","
        << (std::isnan(eq) ? "" : num(eq)) << "\n";
      ours_seconds[r->param("curve") + "/" + r->param("N")] = r->seconds;
      Series& s = by_curve[r->param("curve")];
      s.label = "exact, n = " + r->param("curve").replace(r->param("curve").find('_'), 1, "/");
      s.points.push_back({n, r->seconds / n * 1e9});
    }
    int k = 0;
    for (auto& [name, s] : by_curve) {
      s.color = kColors[k++ % 8];
      crossing_series.push_back(s);
    }
    write_file(out + "/b_crossings.csv", c.str());
  }

  {  // e: S2
    const auto s2 = study("e_s2");
    if (s2.empty()) {
      std::cerr << "sphtroch_bench_report: no S2 results (" << ctx.value("s2", "not built") << "); e_s2.csv not written\n";
    } else {
      std::ostringstream c;
      c << "curve,vertices,s2_seconds,exact_seconds,s2_over_exact,s2_crossings,exact_crossings,same_pairs,"
           "s2_peak_bytes\n";
      std::map<std::string, Series> by_curve;
      for (const Row* r : s2) {
        const double n = r->counter("vertices");
        const auto it = ours_seconds.find(r->param("curve") + "/" + r->param("N"));
        const double ours = it == ours_seconds.end() ? NAN : it->second;
        if (r->counter("same_pairs") != 1) status = 1;
        c << r->param("curve") << "," << num(n) << "," << num(r->seconds) << "," << num(ours) << ","
          << num(r->seconds / ours) << "," << num(r->counter("crossings")) << "," << num(r->counter("ours_crossings"))
          << "," << num(r->counter("same_pairs")) << "," << num(r->counter("peak_bytes")) << "\n";
        Series& s = by_curve[r->param("curve")];
        s.label = "S2, n = " + r->param("curve").replace(r->param("curve").find('_'), 1, "/");
        s.dashed = true;
        s.points.push_back({n, r->seconds / n * 1e9});
      }
      int k = 0;
      for (auto& [name, s] : by_curve) {
        s.color = kColors[k++ % 8];
        crossing_series.push_back(s);
      }
      write_file(out + "/e_s2.csv", c.str());
    }
    write_file(out + "/crossings.svg",
               log_chart("Exact crossing search: time per vertex (median, 1 thread)", "vertices N",
                         "ns per vertex", crossing_series));
  }

  {  // c: exact vs plain predicates
    std::ostringstream c;
    c << "case,polylines,candidates,exact_crossings,exact_touchings,exact_ns_per_pair,plain_ns_per_pair,plain_wrong_decisions,"
         "plain_missed_crossings,plain_spurious_crossings\n";
    std::map<std::string, std::pair<const Row*, const Row*>> by_case;
    std::vector<std::string> names;
    for (const Row* r : study("c_predicates")) {
      if (!by_case.count(r->param("case"))) names.push_back(r->param("case"));
      (r->param("predicate") == "exact" ? by_case[r->param("case")].first : by_case[r->param("case")].second) = r;
    }
    for (const std::string& name : names) {
      const Row* e = by_case[name].first;
      const Row* p = by_case[name].second;
      if (!e || !p) continue;
      const double n = e->counter("candidates");
      c << name << "," << num(e->counter("polylines")) << "," << num(n) << "," << num(e->counter("exact_crossings")) << "," << num(e->counter("exact_touchings"))
        << "," << num(e->seconds / n * 1e9) << "," << num(p->seconds / n * 1e9) << ","
        << num(e->counter("wrong_decisions")) << "," << num(e->counter("missed_crossings")) << ","
        << num(e->counter("spurious_crossings")) << "\n";
    }
    write_file(out + "/c_predicates.csv", c.str());
  }

  std::vector<Series> accuracy;
  {  // d: node error vs time
    std::ostringstream c;
    c << "case,method,samples,seconds,max_error,nodes_expected,nodes_found\n";
    std::map<std::string, Series> by;
    for (const Row* r : study("d_nodes")) {
      c << r->param("case") << "," << r->param("method") << "," << num(r->counter("samples")) << ","
        << num(r->seconds) << "," << num(r->counter("max_error")) << "," << num(r->counter("nodes_expected")) << ","
        << num(r->counter("nodes_found")) << "\n";
      const std::string key = r->param("method") + " " + r->param("case");
      Series& s = by[key];
      s.label = (r->param("method") == "uniform_chords" ? "node, uniform chords, " : "node, census + Newton, ") +
                r->param("case");
      if (r->counter("nodes_found") == r->counter("nodes_expected"))
        s.points.push_back({r->seconds * 1e6, std::max(r->counter("max_error"), 1e-40)});
    }
    int k = 0;
    for (auto& [name, s] : by) {
      s.color = kColors[k++ % 8];
      s.dashed = name.rfind("uniform", 0) == 0;
      accuracy.push_back(s);
    }
    write_file(out + "/d_nodes.csv", c.str());
  }

  {  // f: classify
    std::ostringstream c;
    c << "case,milliseconds,nodes,nodes_expected,max_error,agreement\n";
    for (const Row* r : study("f_classify")) {
      const double err = r->counter("max_error");
      c << r->param("case") << "," << num(r->seconds * 1e3) << "," << num(r->counter("nodes")) << ","
        << num(r->counter("nodes_expected")) << "," << (err < 0 ? "" : num(err)) << "," << num(r->counter("agreement"))
        << "\n";
    }
    write_file(out + "/f_classify.csv", c.str());
  }

  {  // accuracy plot: trace (per point) and nodes (per call)
    std::map<std::string, Series> by;
    for (const Row* r : study("a_trace")) {
      const std::string key = r->param("method") == "direct" ? "direct sin/cos"
                              : r->param("k") == "0"         ? "recurrence"
                                                             : "recurrence, re-anchor " + r->param("k");
      Series& s = by["trace: " + key];
      s.label = "trace point, " + key;
      s.points.push_back({r->seconds / r->counter("points") * 1e6, std::max(r->counter("max_error"), 1e-40)});
    }
    int k = 4;
    for (auto& [name, s] : by) {  // points in the order float, double, long double, mpfr (as registered)
      s.color = kColors[k++ % 8];
      accuracy.push_back(s);
    }
    write_file(out + "/accuracy.svg", log_chart("Error vs time (medians); each trace line joins float, double, long double, mpfr128",
                                                "microseconds (per trace point; per node-finding call)",
                                                "max position error", accuracy));
  }
  return status;
}
