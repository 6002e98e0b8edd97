// python/src/bind_chain.cpp — the class sphtroch.Chain (bindings.hpp): a gear-coupled rotation
// chain (core/rotation_chain.hpp) read from twists, rates and phases as `sphtroch chain` reads
// them (io/chain_text.hpp: each list is turned into the CLI's comma-separated text, so that the
// one reader checks it), or from a URDF (Chain.from_urdf: the reader of `chain --urdf`, in the
// extension _sphtroch_urdf), with trace, kinematics, classify, nodes, cusps, report, boundaries,
// svg, train, export_urdf (io/urdf_writer.hpp, `chain export --urdf`), repr, equality and pickling.
#include "bindings.hpp"
#include "exact_calls.hpp"

#include "sphtroch/core/kinematics.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/urdf_writer.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch::python {
namespace {

/// A chain and its three lists as the CLI's text (what repr and pickling give back).
struct Chain {
  RotationChain chain;
  std::string twists, rates, phases;
};


Chain make_chain(py::handle twists, py::handle rates, py::handle phases) {
  const auto angle_text = [](const char* field) {
    return [field](py::handle a) {
      std::string text;
      angle_arg(a, field, text);
      return text;
    };
  };
  Chain c{RotationChain({{0.0, ChainRate(1), 0.0}}), "", "", ""};
  ChainText text;
  text.twists = c.twists = list_text(twists, "twists", "a list of k angles in [0, pi] (radians or text), or the CLI's \"A1,...,Ak\"", angle_text("twists"),
                                     RotationChain::kMaxStages);
  text.rates = c.rates = list_text(rates, "rates", std::string("a list of k ") + kExactRateForms + ", or the CLI's \"N1,...,Nk\"",
                                   [](py::handle v) { return exact_rate_text(v, "rates"); }, RotationChain::kMaxStages);
  if (!phases.is_none())
    text.phases = c.phases = list_text(phases, "phases", "a list of k angles (radians or text), or the CLI's \"P1,...,Pk\"", angle_text("phases"),
                                     RotationChain::kMaxStages);
  c.chain = text.chain();
  return c;
}

py::tuple value_key(const Chain& c) {
  py::list key;
  const double pi = Constants<double>::pi();
  for (const ChainStage& s : c.chain.stages()) key.append(py::make_tuple(s.twist, s.rate.p(), s.rate.q(), s.phase == -pi ? pi : s.phase));
  return py::tuple(key);
}

py::tuple trace(const Chain& self, py::handle samples, py::handle velocity_flag) {
  const bool velocity = flag_arg(velocity_flag, "velocity");
  const std::size_t n = samples.is_none() ? chain_trace_sample_count(self.chain) : count_arg(samples, "samples", kMinSamples, kMaxSamples);
  auto tr = std::make_unique<Trajectory<double>>();
  {
    py::gil_scoped_release release;
    const ChainCurve<double> curve(self.chain);
    *tr = sample(curve, UniformSampling<double>{curve.period(), n, n, true}, velocity);  // `chain trace`'s sampling
  }
  const Trajectory<double>& v = *tr;
  const py::capsule owner = capsule_of(std::move(tr));
  const auto rows = static_cast<py::ssize_t>(v.size());
  py::array_t<double> t(std::vector<py::ssize_t>{rows}, v.t.data(), owner);
  py::array_t<double> p(std::vector<py::ssize_t>{rows, 3}, v.points.front().data(), owner);
  if (!velocity) return py::make_tuple(t, p);
  py::array_t<double> vel(std::vector<py::ssize_t>{rows, 3}, v.velocities.front().data(), owner);
  return py::make_tuple(t, p, vel);
}

/// kinematics(t): speed, geodesic curvature, tangential acceleration per unit s, |t| <= the period.
py::dict kinematics(const Chain& self, py::handle t) {
  const double period = self.chain.period();
  return kinematics_dict(ChainCurve<double>(self.chain), t, period, "an (N,) array of finite s with |s| <= the period " + number_text(period));
}

py::object classify(const Chain& self) {
  std::string text;
  {
    py::gil_scoped_release release;
    text = chain_classification_json_text(self.chain);
  }
  return from_json(text);
}

/// nodes(): the certified node list, else UncertifiedResult carrying it (the CLI's exit 3).
py::object nodes(const Chain& self) {
  const py::object all = classify(self);
  if (!all["certified"].cast<bool>())
    raise_uncertified("chain: the census is not certified: " + all["certificate"]["why"].cast<std::string>() + " (see docs/chains.md)",
                      all["nodes"], py::none(), py::none());
  return all["nodes"];
}

/// svg(): `sphtroch chain plot`'s SVG (the picture options: plot_options_arg).
std::string svg(const Chain& self, py::handle view, py::handle size, py::handle labels, py::handle markers, py::handle style) {
  const PlotOptions options = plot_options_arg(view, size, labels, markers, style);
  ChainText typed;  // the caption's angles as given (chain_plot_caption)
  typed.twists = self.twists;
  typed.rates = self.rates;
  typed.phases = self.phases;
  py::gil_scoped_release release;
  return chain_plot_svg_text(self.chain, options, typed);
}

/// boundaries(vary): `sphtroch chain boundaries --vary VARY --json` as a dict.
py::object boundaries(const Chain& self, py::handle vary) {
  const std::string text = text_arg(vary, "vary", "NAME:LO:HI, NAME = Ai (a twist) or Pi (a phase), LO < HI radians (A2:0:pi)");
  std::string json;
  {
    py::gil_scoped_release release;
    json = chain_boundaries_json_text(self.chain, text);
  }
  return from_json(json);
}

std::string report(const Chain& self) {
  py::gil_scoped_release release;
  return chain_classification_report_text(self.chain);
}

/// The gear train of a k = 2 chain with both rates not 0 (gear_train_of), else None.
py::object train(const Chain& self) {
  const std::optional<GearTrain> g = gear_train_of(self.chain);
  if (!g) return py::none();
  Train t{*g, {}};
  t.text.a2 = number_text(g->a2());
  t.text.a3 = number_text(g->a3());
  t.text.n = g->ratio().str();
  t.text.phase = number_text(g->phase());
  return py::cast(t);
}

/// The URDF reader of sphtroch._sphtroch_urdf (urdf_module.cpp), imported here on first use so
/// that `import sphtroch` loads no urdfdom: the chain, or InvalidInput as read_urdf_chain refuses.
RotationChain urdf_by_extension(const std::string& xml, const std::string& from, const std::string& to, const Vector3d& axis) {
  const py::object read = py::module_::import("sphtroch._sphtroch_urdf").attr("read_chain");
  const py::object r = read(xml, from, to, axis.x(), axis.y(), axis.z());
  if (py::isinstance<py::dict>(r)) {
    const py::tuple e = r.cast<py::dict>()["error"];
    throw InvalidInput(e[0].cast<std::string>(), e[1].cast<std::string>(), e[2].cast<std::string>(), e[3].cast<std::string>());
  }
  std::vector<ChainStage> stages;
  for (const py::handle stage : r) {
    const py::tuple t = py::reinterpret_borrow<py::tuple>(stage);
    stages.push_back({t[0].cast<double>(), ChainRate(t[1].cast<std::int64_t>(), t[2].cast<std::int64_t>()), t[3].cast<double>()});
  }
  return RotationChain(stages);
}

/// Chain.from_urdf(path, from_link, to_link, axis=None): `sphtroch chain ... --urdf PATH --from
/// --to [--axis]`'s chain (io/chain_text.hpp reads the file and checks the arguments), with its
/// lists as round-trip decimals and exact rates (what repr and pickling give back).
Chain from_urdf(py::handle path, const std::string& from, const std::string& to, py::handle axis) {
  ChainText text;
  text.urdf = py::module_::import("os").attr("fspath")(path).cast<std::string>();
  text.from = from;
  text.to = to;
  if (!axis.is_none()) {
    std::vector<std::string> items;
    for (const py::handle v : axis) items.push_back(number_text(v.cast<double>()));
    if (items.size() != 3) throw InvalidInput("axis", std::to_string(items.size()) + " numbers", "not three numbers", "(x, y, z): three finite numbers, not all 0");
    text.axis = items[0] + "," + items[1] + "," + items[2];
  }
  text.urdf_reader = &urdf_by_extension;
  Chain c{text.chain(), "", "", ""};
  for (const ChainStage& s : c.chain.stages()) {
    const std::string sep = c.twists.empty() ? "" : ",";
    c.twists += sep + number_text(s.twist);
    c.rates += sep + s.rate.str();
    c.phases += sep + number_text(s.phase);
  }
  return c;
}

/// Chain.export_urdf(path=None, *, name="sphtroch_chain"): `chain export --urdf`'s document; with
/// a path also written there.
std::string export_urdf(const Chain& self, py::handle path, const std::string& name) {
  const std::string xml = chain_to_urdf(self.chain, name);
  if (!path.is_none()) py::module_::import("pathlib").attr("Path")(path).attr("write_text")(xml);
  return xml;
}

std::string chain_repr(const Chain& c) {
  return "Chain(twists=" + repr_of(py::str(c.twists)) + ", rates=" + repr_of(py::str(c.rates)) +
         (c.phases.empty() ? std::string() : ", phases=" + repr_of(py::str(c.phases))) + ")";
}

}  // namespace

void bind_chain(py::module_& m) {
  py::class_<Chain>(m, "Chain", doc("Chain"))
      .def(py::init(&make_chain), py::arg("twists"), py::arg("rates"), py::arg("phases") = py::none(), doc("Chain.__init__"))
      .def_property_readonly("twists", checked(+[](const Chain& c) {
        py::list l;
        for (const ChainStage& s : c.chain.stages()) l.append(s.twist);
        return py::tuple(l);
      }), doc("Chain.twists"))
      .def_property_readonly("rates", checked(+[](const Chain& c) {
        py::list l;
        for (const ChainStage& s : c.chain.stages()) l.append(s.rate.str());
        return py::tuple(l);
      }), doc("Chain.rates"))
      .def_property_readonly("phases", checked(+[](const Chain& c) {
        py::list l;
        for (const ChainStage& s : c.chain.stages()) l.append(s.phase);
        return py::tuple(l);
      }), doc("Chain.phases"))
      .def_property_readonly("period", checked(+[](const Chain& c) { return c.chain.period(); }), doc("Chain.period"))
      .def_property_readonly("train", checked(&train), doc("Chain.train"))
      .def("__len__", checked(+[](const Chain& c) { return c.chain.size(); }), doc("Chain.__len__"))
      .def("trace", checked(&trace), py::kw_only(), py::arg("samples") = py::none(), py::arg("velocity") = false, doc("Chain.trace"))
      .def("kinematics", checked(&kinematics), py::arg("t"), doc("Chain.kinematics"))
      .def("classify", checked(&classify), doc("Chain.classify"))
      .def("nodes", checked(&nodes), doc("Chain.nodes"))
      .def("cusps", checked(+[](const Chain& c) -> py::object { return classify(c)["cusps"]; }), doc("Chain.cusps"))
      .def("report", checked(&report), doc("Chain.report"))
      .def("boundaries", checked(&boundaries), py::arg("vary"), doc("Chain.boundaries"))
      .def("svg", checked(&svg), py::kw_only(), py::arg("view") = py::none(), py::arg("size") = py::none(), py::arg("labels") = "auto",
           py::arg("markers") = "auto", py::arg("style") = "curve", doc("Chain.svg"))
      .def_static("from_urdf", &from_urdf, py::arg("path"), py::arg("from_link"), py::arg("to_link"),
                  py::arg("axis") = py::none(), doc("Chain.from_urdf"))
      .def("export_urdf", checked(&export_urdf), py::arg("path") = py::none(), py::kw_only(), py::arg("name") = "sphtroch_chain",
           doc("Chain.export_urdf"))
      .def("__repr__", checked(&chain_repr))
      .def("__eq__", checked(+[](const Chain& a, py::handle other) -> py::object {
        if (!py::isinstance<Chain>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
        return py::bool_(value_key(a).equal(value_key(value_of<Chain>(other))));
      }), doc("Chain.__eq__"))
      .def("__hash__", checked(+[](const Chain& c) { return py::hash(value_key(c)); }), doc("Chain.__hash__"))
      // Pickling calls the constructor again with the three texts (validated as any input).
      .def("__reduce__", [](py::object self) {
        const Chain& c = value_of<Chain>(self);
        const py::object phases = c.phases.empty() ? py::object(py::none()) : py::object(py::str(c.phases));
        return py::make_tuple(py::type::of(self), py::make_tuple(c.twists, c.rates, phases));
      });
}

}  // namespace sphtroch::python
