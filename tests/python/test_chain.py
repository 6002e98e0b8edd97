"""sphtroch.Chain: a gear-coupled rotation chain from Python. Expected values: the curve from a
product of rotation matrices written here with NumPy (P = prod_i Rz(N_i s + P_i) Rx(A_i) z), its
speed from central differences of that product, the CLI's bytes (`sphtroch chain trace --format
npy`, `chain classify --json`, the text report), GearTrain's curve for k = 2, and the invariant that
both parameters of a node give one point."""
import json
import pickle
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import sphtroch
from conftest import EXE, cli_json, run_cli


def rz(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


def model(stages, s):
    """P(s) of [(twist, rate as Fraction, phase)]."""
    r = np.eye(3)
    for twist, rate, phase in stages:
        r = r @ rz(float(rate) * s + phase) @ rx(twist)
    return r[:, 2]


WRIST = [(np.pi / 2, Fraction(1), 0.0), (1.2, Fraction(-2, 3), 0.3), (0.4, Fraction(5, 3), -1.0)]


def wrist():
    return sphtroch.Chain(twists=["pi/2", 1.2, 0.4], rates=[1, "-2/3", Fraction(5, 3)], phases=[0, 0.3, -1.0])


def test_trace_is_the_rotation_product_and_the_cli_bytes(tmp_path):
    c = wrist()
    assert len(c) == 3 and c.rates == ("1", "-2/3", "5/3")
    assert c.period == pytest.approx(6 * np.pi, rel=1e-15)  # L = 3, g = gcd(3, -2, 5) = 1
    t, P, V = c.trace(samples=400, velocity=True)
    assert t.shape == (400,) and P.shape == (400, 3) and V.shape == (400, 3)
    for i in range(0, 400, 7):
        assert np.linalg.norm(P[i] - model(WRIST, t[i])) < 1e-13
        h = 1e-5
        d = (model(WRIST, t[i] + h) - model(WRIST, t[i] - h)) / (2 * h)
        assert np.linalg.norm(V[i] - d) < 1e-8
    out = tmp_path / "w.npy"
    subprocess.run([EXE, "chain", "trace", "--twists", "pi/2,1.2,0.4", "--rates", "1,-2/3,5/3", "--phases", "0,0.3,-1",
                    "--samples", "400", "--velocity", "-o", str(out)], check=True)
    cli = np.load(out)
    assert np.array_equal(cli[:, 0], t) and np.array_equal(cli[:, 1:4], P) and np.array_equal(cli[:, 4:7], V)
    # The default count: 360 sum |N_i| L / g = 360 (3 + 2 + 5).
    assert c.trace()[0].shape == (3600,)


def test_two_stages_are_the_gear_train():
    rng = np.random.default_rng(45)
    for _ in range(40):
        a2, a3, ph = rng.uniform(0.05, 3.09), rng.uniform(0.05, 3.09), rng.uniform(-3, 3)
        n = Fraction(int(rng.integers(1, 8)) * int(rng.choice([-1, 1])), int(rng.integers(1, 8)))
        chain = sphtroch.Chain(twists=[a2, a3], rates=[1, n], phases=[0, ph])
        train = sphtroch.GearTrain(a2, a3, n, phase=ph)
        assert chain.train == train
        tc, pc = chain.trace(samples=101)
        tt, pt = train.trace(samples=101)
        assert np.array_equal(tc, tt) and np.array_equal(pc, pt)
    assert sphtroch.Chain(twists=[1, 2, 3], rates=[1, 2, 3]).train is None
    assert sphtroch.Chain(twists=[1, 2], rates=[0, 2]).train is None


def test_classify_and_report_are_the_cli_and_nodes_are_self_intersections():
    c = wrist()
    args = ["--twists", "pi/2,1.2,0.4", "--rates", "1,-2/3,5/3", "--phases", "0,0.3,-1"]
    got = c.classify()
    assert got == json.loads(run_cli("chain", "classify", *args, "--json"))
    assert c.report() == run_cli("chain", "classify", *args)
    assert got["certified"] and got["counts"]["nodes"] == len(c.nodes()) > 0
    assert c.cusps() == got["cusps"]
    for node in c.nodes():
        points = [model(WRIST, s) for s in node["params"]]
        assert len(points) == node["branches"]
        for p in points[1:]:
            assert np.linalg.norm(p - points[0]) < 1e-12
        assert np.linalg.norm(np.array(node["position"]) - points[0]) < 1e-12


def test_boundaries_are_the_cli_and_refuse_bad_ranges():
    # A3 of three stages: the slab search; its dict is the CLI's JSON, its counts either side
    # of each event are classify()'s just below and above (the census at one value).
    c = sphtroch.Chain(twists=[1.2, 0.9, 0.7], rates=[1, 2, -3])
    got = c.boundaries("A3:0.8:0.94")
    assert got == json.loads(run_cli("chain", "boundaries", "--twists", "1.2,0.9,0.7", "--rates", "1,2,-3",
                                     "--vary", "A3:0.8:0.94", "--json"))
    assert got["certified"] and [e["kind"] for e in got["events"]] == ["cusp", "tangency"]
    for e in got["events"]:
        assert e["root"]["certified"] and e["bracket"][0] <= e["value"] <= e["bracket"][1]
        for value, key in ((e["bracket"][0] - 1e-6, "nodes_below"), (e["bracket"][1] + 1e-6, "nodes_above")):
            counts = sphtroch.Chain(twists=[1.2, 0.9, value], rates=[1, 2, -3]).classify()["counts"]
            assert counts["nodes"] == e[key]
    for bad in ("A3:1:0", "A4:0:1", "A3:0", 3):
        with pytest.raises(sphtroch.InvalidInput) as err:
            c.boundaries(bad)
        assert err.value.field == "vary"


def test_svg_is_the_picture_chain_plot_draws(tmp_path):
    out = tmp_path / "w.svg"
    subprocess.run([EXE, "chain", "plot", "--twists", "pi/2,1.2,0.4", "--rates", "1,-2/3,5/3", "--phases", "0,0.3,-1",
                    "--view", "top", "--labels", "numbers", "-o", str(out)], check=True)
    assert wrist().svg(view="top", labels="numbers") == out.read_text()
    with pytest.raises(sphtroch.InvalidInput) as e:
        wrist().svg(size=10)
    assert e.value.field == "size"


def test_export_urdf_is_the_cli_document_and_from_urdf_reads_it_back(tmp_path):
    """export_urdf's text is the bytes `chain export --urdf` writes; from_urdf of that file gives
    the chain of the model (rotation product written here) and the census `chain classify --urdf`
    prints for the same file."""
    cli_file = tmp_path / "cli.urdf"
    subprocess.run([EXE, "chain", "export", "--twists", "pi/2,1.2,0.4", "--rates", "1,-2/3,5/3", "--phases", "0,0.3,-1",
                    "--urdf", str(cli_file)], check=True)
    written = tmp_path / "py.urdf"
    text = wrist().export_urdf(written)
    assert text == cli_file.read_text() == written.read_text()
    read = sphtroch.Chain.from_urdf(written, "base_link", "tool")
    assert read.rates == ("1", "-2/3", "5/3")
    _, p = read.trace(samples=97)
    for k in (0, 13, 50, 96):  # the read chain draws the model's curve (its frame: joint 1's axis is z)
        assert np.abs(p[k] - model(WRIST, read.period * k / 97)).max() < 1e-12
    assert read.classify() == cli_json("chain", "classify", "--urdf", str(written), "--from", "base_link", "--to", "tool", "--json")
    assert pickle.loads(pickle.dumps(read)) == read
    assert repr(read).startswith("Chain(twists=")


def test_from_urdf_refuses_as_the_cli_does(tmp_path):
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='r'><link name='a'/></robot>")
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Chain.from_urdf(bad, "a", "b")
    done = subprocess.run([EXE, "chain", "classify", "--urdf", str(bad), "--from", "a", "--to", "b"], capture_output=True, text=True)
    assert done.returncode == 2
    assert e.value.field in done.stderr and str(e.value) in done.stderr
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Chain.from_urdf(tmp_path / "missing.urdf", "a", "b")
    assert e.value.field == "urdf"
    with pytest.raises(sphtroch.InvalidInput) as e:
        wrist().export_urdf(written := tmp_path / "w.urdf") and sphtroch.Chain.from_urdf(written, "base_link", "tool", axis=(0, 0))
    assert e.value.field == "axis"


def test_an_uncertified_census_raises_with_its_nodes():
    # 16 joints, all twists 1, rates 1..16: points where several branches touch stay undecided.
    c = sphtroch.Chain(twists=",".join(["1"] * 16), rates=",".join(str(i) for i in range(1, 17)))
    assert c.classify()["certified"] is False
    with pytest.raises(sphtroch.UncertifiedResult) as e:
        c.nodes()
    assert len(e.value.nodes) > 0


def test_kinematics_speed_is_the_derivative():
    c = wrist()
    s = np.linspace(-c.period, c.period, 57)
    k = c.kinematics(s)
    for i, si in enumerate(s):
        h = 1e-5
        d = (model(WRIST, si + h) - model(WRIST, si - h)) / (2 * h)
        assert abs(k["speed"][i] - np.linalg.norm(d)) < 1e-8
    with pytest.raises(sphtroch.InvalidInput) as e:
        c.kinematics([c.period * 1.01])
    assert e.value.field == "t"


def test_value_semantics():
    c = wrist()
    same = sphtroch.Chain("1.5707963267948966,1.2,0.4", "1,-4/6,5/3", "0,0.3,-1")
    assert c == same and hash(c) == hash(same)
    assert c != sphtroch.Chain(twists=["pi/2", 1.2, 0.4], rates=[1, "-2/3", "5/3"])
    back = pickle.loads(pickle.dumps(c))
    assert back == c and repr(back) == repr(c)
    assert eval(repr(c), {"Chain": sphtroch.Chain}) == c
    assert (c == 5) is False


@pytest.mark.parametrize("kwargs, field", [
    (dict(twists=[1, 2], rates=[1]), "rates"),
    (dict(twists=[1, float("nan")], rates=[1, 2]), "twists"),
    (dict(twists=[1, 4], rates=[1, 2]), "twists"),
    (dict(twists=[1, 2], rates=[1, "x"]), "rates"),
    (dict(twists=[1, 2], rates=[1, 0.1 + 0.2]), "rates"),
    (dict(twists=[1, 2], rates=[0, 0]), "rates"),
    (dict(twists=[1, 2], rates=[1, 2], phases=[0]), "phases"),
    (dict(twists=[1, 2], rates=[1, 2], phases=[0, float("inf")]), "phases"),
    (dict(twists=b"1,2", rates=[1, 2]), "twists"),
    (dict(twists={1: 2}, rates=[1, 2]), "twists"),
    (dict(twists=[1, "1,2"], rates=[1, 2, 3]), "twists"),
    (dict(twists=[1, 2], rates=[1, True]), "rates"),
    (dict(twists=[1] * 17, rates=[1] * 17), "twists"),
])
def test_bad_input_names_the_argument(kwargs, field):
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Chain(**kwargs)
    assert e.value.field == field
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("make, by_value", [(lambda: sphtroch.Chain.__new__(sphtroch.Chain), True),
                                            (lambda: sphtroch.GearTrain.__new__(sphtroch.GearTrain), True),
                                            (lambda: sphtroch.Clinostat.__new__(sphtroch.Clinostat), False),
                                            (lambda: pickle.loads(b"\x80\x02csphtroch._sphtroch\nChain\nq\x00)\x81q\x01."), True)])
def test_an_object_made_without_init_raises_instead_of_reading_memory(make, by_value):
    obj = make()
    uses = [lambda: obj.period, lambda: repr(obj)] + ([lambda: hash(obj), lambda: obj == obj] if by_value else [])
    for use in uses:
        with pytest.raises(sphtroch.InvalidInput) as e:
            use()
        assert e.value.field == "self"


class RaisingList:
    def __len__(self):
        raise ZeroDivisionError("len")

    def __getitem__(self, i):
        raise ZeroDivisionError("item")


@pytest.mark.parametrize("kwargs, field", [
    (dict(twists=np.array(1.0), rates=[1]), "twists"),
    (dict(twists=np.ones((3, 1)), rates=[1, 1, 1]), "twists"),
    (dict(twists=[1, 1, 1], rates=[np.bool_(False), np.bool_(False), np.bool_(True)]), "rates"),
    (dict(twists=[1, 1], rates=[1, None]), "rates"),
    (dict(twists=RaisingList(), rates=[1]), "twists"),
])
def test_arrays_bools_and_raising_containers_are_bad_input(kwargs, field):
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Chain(**kwargs)
    assert e.value.field == field
