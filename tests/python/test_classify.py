"""classify(), nodes(), cusps(), classify_roots(), classify_a3_range(): the report's cases of
data/reference/paper_cases.csv (expected counts from the report), and the same dict as
`sphtroch classify --json` (the tool's output, not the module's, is the reference)."""
import math

import numpy as np

import pytest
import sphtroch
from conftest import cli_angle, cli_json, paper_cases, run_cli

CASES = paper_cases()


def without_timing(report):
    report = dict(report)
    report["work"] = {k: v for k, v in report["work"].items() if k != "seconds"}
    return report


@pytest.mark.parametrize("case", CASES, ids=[c["id"] for c in CASES])
def test_paper_case_counts(case):
    n = f'{case["n_num"]}/{case["n_den"]}'
    tr = sphtroch.GearTrain(case["a2_symbolic"], cli_angle(case["a3_symbolic"]), n)
    rep = tr.classify()
    assert rep["counts"]["nodes"] == int(case["nodes"])
    assert rep["counts"]["cusps"] == int(case["cusps"])
    assert len(tr.nodes()) == int(case["nodes"])
    assert len(tr.cusps()) == int(case["cusps"])
    roots = tr.classify_roots()
    assert (roots["nodes"], roots["cusps"]) == (int(case["nodes"]), int(case["cusps"]))
    # The CSV's radians (rounded decimals) read onto the same boundaries by default.
    by_value = sphtroch.GearTrain(float(case["a2_rad"]), float(case["a3_rad"]), int(case["n_num"]) / int(case["n_den"]))
    assert by_value.classify_roots()["nodes"] == int(case["nodes"])


@pytest.mark.parametrize("case", CASES, ids=[c["id"] for c in CASES])
def test_classify_equals_the_tools_json(case):
    a2, a3, n = case["a2_symbolic"], cli_angle(case["a3_symbolic"]), f'{case["n_num"]}/{case["n_den"]}'
    cli = cli_json("classify", "--a2", a2, "--a3", a3, "--n", n, "--json")
    mine = sphtroch.GearTrain(a2, a3, n).classify()
    assert without_timing(mine) == without_timing(cli)


def test_literal_and_samples_reach_the_census():
    args = ("--a2", "pi/2", "--a3", "pi/4", "--n", "1")
    cli = cli_json("classify", *args, "--literal", "--samples", "4096", "--json")
    mine = sphtroch.GearTrain("pi/2", "pi/4", 1).classify(literal=True, samples=4096)
    assert without_timing(mine) == without_timing(cli)
    assert mine["inputs"]["literal"] is True


def test_nodes_and_cusps_are_the_reports_lists():
    tr = sphtroch.GearTrain("pi/3", "pi/2", 2)  # Fig. 5(f): four crossing nodes (Eqs. 43, 46)
    rep = tr.classify()
    assert tr.nodes() == rep["nodes"] and len(rep["nodes"]) == 4
    for node in tr.nodes():
        x, y, z = node["position"]
        assert math.isclose(x * x + y * y + z * z, 1.0, abs_tol=1e-12)
        assert node["kind"] == "crossing" and node["branches"] == 2
    cusp_train = sphtroch.GearTrain("2pi/3", "pi-ap", 2)  # Fig. 5(e): spherical nephroid, 2 cusps
    assert cusp_train.cusps() == cusp_train.classify()["cusps"] and len(cusp_train.cusps()) == 2


def test_classify_roots_against_the_report_n1():
    # Eq. 24 (n = 1): a node iff a2/2 < a3 < pi - a2/2.
    a2 = math.pi / 2
    for a3, nodes in [(0.6, 0), (0.9, 1), (2.0, 1), (2.5, 0)]:
        r = sphtroch.GearTrain(a2, a3, 1).classify_roots()
        assert r["nodes"] == nodes and r["analytic_nodes"] == nodes and r["agrees_with_report"]


def test_classify_a3_range_intervals_follow_eq24():
    runs = sphtroch.classify_a3_range("pi/2", 1, (0.1, math.pi - 0.1), count=281)
    assert [r["class"] for r in runs] == ["simple curve", "nodes", "simple curve"]
    assert sum(r["samples"] for r in runs) == 281
    # The class changes between neighbouring samples around a3 = a2/2 and pi - a2/2 (Eq. 24).
    step = (math.pi - 0.2) / 280
    assert runs[0]["a3_last"] < math.pi / 4 < runs[1]["a3_first"] <= runs[0]["a3_last"] + step + 1e-12
    assert runs[1]["a3_last"] < 3 * math.pi / 4 < runs[2]["a3_first"]


def test_classify_a3_range_takes_the_whole_range_as_atlas_does():
    # (0, pi) as atlas takes it: the ends are the nearest trains, 1e-6 inside (Eq. 24 again).
    runs = sphtroch.classify_a3_range("pi/2", 1, (0, math.pi), count=101)
    assert runs[0]["a3_first"] == 1e-6 and runs[-1]["a3_last"] == math.pi - 1e-6
    assert [r["class"] for r in runs] == ["simple curve", "nodes", "simple curve"]
    assert sphtroch.classify_a3_range("pi/2", 1, "0:pi", count=101) == runs


def test_d1_certified_nodes_near_the_mirror_cone():
    """Issue 17, D1: 845 nodes (13 with one branch) were printed as certain; the root-count census,
    and an independent computation, give 832 (16 roots x 52)."""
    tr = sphtroch.GearTrain(a2="2.8907926475352435", a3="pi-ap-1e-9", n="52/35")
    c = tr.classify()
    assert c["certified"] is True and c["agreement"]["ok"] is True
    assert c["counts"]["nodes"] == 832 == c["censuses"]["root_count"]["nodes"]
    nodes = tr.nodes()
    assert len(nodes) == 832
    assert all(n["branches"] >= 2 and len(n["params"]) == n["branches"] for n in nodes)


def test_uncertified_result_is_a_runtime_error_with_both_counts_documented():
    assert issubclass(sphtroch.UncertifiedResult, RuntimeError)
    assert "UncertifiedResult" in sphtroch.__all__
    assert "root_nodes" in sphtroch.UncertifiedResult.__doc__


@pytest.mark.parametrize("case", CASES, ids=[c["id"] for c in CASES])
def test_one_node_schema_for_classify_and_classify_roots(case):
    """classify_roots()["node_points"] are node dicts of the same schema as classify()["nodes"] and
    the same points: the expected positions come from classify (the certified polyline census
    checked against the root census), matched nearest to within 1e-9."""
    tr = sphtroch.GearTrain(case["a2_symbolic"], cli_angle(case["a3_symbolic"]), f'{case["n_num"]}/{case["n_den"]}')
    full, roots = tr.classify()["nodes"], tr.classify_roots()["node_points"]
    assert len(roots) == len(full) == int(case["nodes"])
    for node in roots:
        assert set(node) == set(full[0]) if full else True
        nearest = min(full, key=lambda f: math.dist(f["position"], node["position"]))
        assert math.dist(nearest["position"], node["position"]) < 1e-9
        assert (nearest["kind"], nearest["branches"]) == (node["kind"], node["branches"])
        assert math.isclose(node["longitude"], math.atan2(node["position"][1], node["position"][0]), abs_tol=1e-15)


def test_svg_is_the_cli_plot_and_jupyter_shows_it():
    # GearTrain.svg() draws what `sphtroch plot` draws (the same bytes), with the view, size and
    # label options; _repr_svg_ is svg() with its defaults (issue 21).
    tr = sphtroch.GearTrain("pi/3", "pi/2", "2")
    for kwargs, flags in [({}, []), ({"view": "top", "labels": "none"}, ["--view", "top", "--labels", "none"]),
                          ({"view": ("30deg", 0.2), "size": 300}, ["--view", "30deg,0.2", "--size", "300"]),
                          ({"markers": "none", "style": "density"}, ["--markers", "none", "--style", "density"])]:
        assert tr.svg(**kwargs) == run_cli("plot", "--a2", "pi/3", "--a3", "pi/2", "--n", "2", *flags)
    svg = tr._repr_svg_()
    assert svg == tr.svg() and svg.startswith("<?xml") and svg.rstrip().endswith("</svg>")
    assert all(f">N{i}</text>" in svg for i in range(1, 5)) and ">N5</text>" not in svg  # Fig. 5(f): 4 nodes
    assert ">N1</text>" not in tr.svg(labels="none")
    for bad in [{"view": "up"}, {"view": (0, 2)}, {"labels": "most"}, {"size": 10}, {"labels": 3}, {"markers": "few"},
                {"style": "heat"}]:
        with pytest.raises(sphtroch.InvalidInput) as e:
            tr.svg(**bad)
        assert e.value.field == next(iter(bad))


@pytest.mark.parametrize("a2,a3,n", [("0.7", "2.5", "13/5"), ("pi/3", "pi/2", "2"), ("1.9", "0.4", "-7/3"),
                                     ("0.3", "1.2", "5/2"), ("pi/3", "ap", "2")])
def test_classify_names_the_nearest_event_and_crossing_it_changes_the_counts_as_printed(a2, a3, n):
    # Issue 22: the design's robustness. The nearest event is one of `sphtroch boundaries` at that
    # a2 (the same a3 double), no other event is nearer, and a train just below / just above it
    # (1e-7 rad, beyond the 1e-10 boundary reading) has the counts it names.
    c = cli_json("classify", "--a2", a2, "--a3", a3, "--n", n, "--json")
    e = c["nearest_event"]
    events = cli_json("boundaries", "--a2", a2, "--n", n, "--json")["events"]
    analysed_a3 = e["a3"] - e["margin"]
    assert any(x["a3"] == e["a3"] and x["kind"] == e["kind"] and x["nodes_below"] == e["nodes_below"]
               and x["nodes_above"] == e["nodes_above"] for x in events)
    assert abs(e["margin"]) == min(abs(x["a3"] - analysed_a3) for x in events)
    for offset, key in [(-1e-7, "nodes_below"), (1e-7, "nodes_above")]:
        side = cli_json("classify", "--a2", a2, "--a3", repr(e["a3"] + offset), "--n", n, "--json")
        assert side["counts"]["nodes"] == e[key], (offset, side["counts"])


def test_node_set_and_cusp_set_are_the_census_as_arrays():
    tr = sphtroch.GearTrain("pi/3", "pi/2", 2)  # report Fig. 5(f): four crossings
    nodes = tr.nodes()
    s = tr.node_set()
    assert len(s) == 4 and s.kind == "nodes" and s.positions.shape == (4, 3) and s.positions.dtype == np.float64
    assert np.array_equal(s.positions, np.array([n["position"] for n in nodes]))
    assert np.array_equal(s.params, np.array([n["params"] for n in nodes]))
    assert list(s.kinds) == ["crossing"] * 4 and list(s.branches) == [2] * 4 and list(s.ids) == [1, 2, 3, 4]
    np.testing.assert_allclose(np.linalg.norm(s.positions, axis=1), 1.0, rtol=0, atol=1e-15)  # |P| = 1
    # Each node is the curve's point at both of its parameters (Eq. 4).
    for row in range(4):
        for t in s.params[row]:
            _, P = tr.trace(samples=3, turns=t / (2 * math.pi))  # open curve: the last sample is at t
            np.testing.assert_allclose(P[-1], s.positions[row], rtol=0, atol=1e-9)
    np.testing.assert_allclose(s.latitude, np.arcsin(s.positions[:, 2]), rtol=0, atol=1e-15)
    assert s.to_list() == nodes and list(s) == nodes and s[2] == nodes[2]
    cols = s.columns()
    assert list(cols) == ["id", "kind", "x", "y", "z", "longitude", "latitude", "branches", "t1", "t2"]
    assert all(len(v) == 4 for v in cols.values())
    svg = tr.svg(labels="numbers")
    assert all(f">N{i}<" in svg for i in s.ids) and ">N5<" not in svg  # ids are the plot's labels
    # Tracer on the pitch cone: one cusp each time theta3 = n theta2 + theta_p passes the contact
    # angle, |p| = 5 times a period for n = 5/2.
    c = sphtroch.GearTrain(1.0, "ap", "5/2").cusp_set()
    assert len(c) == len(sphtroch.GearTrain(1.0, "ap", "5/2").cusps()) == 5
    assert c.params.shape == (5, 1) and list(c.kinds) == ["cusp"] * 5 and list(c.branches) == [1] * 5
    empty = sphtroch.GearTrain(0.5, 0.2, 1).node_set()  # Eq. 24: a3 < a2/2, a simple curve
    assert len(empty) == 0 and empty.positions.shape == (0, 3) and empty.params.shape == (0, 2)
