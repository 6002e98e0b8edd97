"""identify(): the train of a timed trace, from trace()'s own arrays (the hidden train's values
are the expected ones)."""
import math

import numpy as np
import pytest

import sphtroch


@pytest.mark.parametrize("n,a2,a3,phase", [("5/2", 1.0, 2.0, 0.0), ("-7/3", 0.5, 2.5, 1.0), ("3", "pi/2", "pi/3", -2.0)])
def test_identify_gives_back_the_train(n, a2, a3, phase):
    tr = sphtroch.GearTrain(a2, a3, n, phase)
    t, P = tr.trace(samples=1500)
    r = sphtroch.identify(t, P)
    assert r["n"] == tr.ratio
    assert math.isclose(r["a2"], tr.a2, abs_tol=1e-12) and math.isclose(r["a3"], tr.a3, abs_tol=1e-12)
    assert abs(math.remainder(r["phase"] - tr.phase, 2 * math.pi)) < 1e-12
    assert r["residual"] < 1e-12


def test_identify_refuses_bad_samples():
    t, P = sphtroch.GearTrain(1.0, 1.0, 2).trace(samples=200)
    for args, field in [((t[:5], P[:5]), "samples"), ((t, P * 1.01), "points"), ((t[::-1], P), "t"),
                        ((t, P[:, :2]), "points"), ((t.reshape(-1, 2), P), "t")]:
        with pytest.raises(sphtroch.InvalidInput) as info:
            sphtroch.identify(*args)
        assert info.value.field == field


def test_synth_points_finds_the_hidden_train_among_all():
    # Three points of a known train (the forward model through trace()); expected: that train.
    train = sphtroch.GearTrain(a2=1.0, a3=2.0, n="1/2", phase=0.3)
    _, P = train.trace(samples=40)
    pts = P[[1, 10, 28]]
    r = sphtroch.synth_points(pts, n="1/2")
    assert r["complete"] is True
    hits = [s for s in r["solutions"]
            if abs(s["a2"] - 1.0) < 1e-9 and abs(s["a3"] - 2.0) < 1e-9
            and abs(math.remainder(s["phase"] - 0.3, math.pi)) < 1e-9]
    assert len(hits) == 1
    for s in r["solutions"]:
        assert s["residual"] <= 1e-12 and len(s["params"]) == 3
        assert s["counts"]["nodes"] == s["counts"]["crossings"] + s["counts"]["tangencies"]
        # the certified margin is the train's own (GearTrain.margin), and the census holds inside it
        m = s["certified_margin"]
        assert 0 < m["lower"] <= m["upper"]
        train = sphtroch.GearTrain(a2=s["a2"], a3=s["a3"], n="1/2")
        assert train.margin()["lower"] == m["lower"]
        corner = sphtroch.GearTrain(a2=s["a2"] + 0.99 * m["lower"], a3=s["a3"] - 0.99 * m["lower"], n="1/2")
        assert len(corner.classify()["nodes"]) == s["counts"]["nodes"]


def test_synth_points_refuses_bad_points():
    with pytest.raises(sphtroch.InvalidInput, match="points"):
        sphtroch.synth_points(np.array([[1.0, 0, 0], [0, 1.0, 0]]), n=1)
    with pytest.raises(sphtroch.InvalidInput, match="points"):
        sphtroch.synth_points(np.array([[1.0, 0, 0], [0, 1.0, 0], [1.0, 0, 0]]), n=1)


def tracer_point(a2, a3, n, phase, theta):
    """The model's point (Eqs. 3-4): Rz(theta) Rx(a2) Rz(n theta + phase) Rx(a3) z, written here."""
    def rz(a):
        return np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])

    def rx(a):
        return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    return rz(theta) @ rx(a2) @ rz(n * theta + phase) @ rx(a3) @ np.array([0.0, 0.0, 1.0])


def test_synth_points_free_axis_finds_the_train_and_its_axis():
    # Five points of a known train turned by a rotation R (sun axis R z); expected: that train and
    # axis (the axis up to sign; a3 becomes pi - a3 when it is reversed), and every solution's
    # frame carries its curve through the points.
    train = sphtroch.GearTrain(a2=0.9, a3=1.3, n=-1, phase=0.2)
    t, P = train.trace(samples=60)
    c, s_ = math.cos(0.7), math.sin(0.7)
    R = np.array([[1, 0, 0], [0, c, -s_], [0, s_, c]]) @ np.array([[c, 0, s_], [0, 1, 0], [-s_, 0, c]])
    pts = P[[2, 13, 25, 38, 51]] @ R.T
    r = sphtroch.synth_points(pts, n=-1, free_axis=True, threads=2)
    assert r["complete"] is True
    axis = R[:, 2]
    hits = 0
    for s in r["solutions"]:
        F = np.array(s["frame"]).T  # columns: the train's x, y, z in the points' coordinates
        assert np.allclose(F.T @ F, np.eye(3), atol=1e-14) and np.allclose(F[:, 2], s["axis"], atol=0)
        n = s["n"].split("/")
        n = float(n[0]) / (float(n[1]) if len(n) > 1 else 1.0)
        for k, theta in enumerate(s["params"]):
            assert np.linalg.norm(F @ tracer_point(s["a2"], s["a3"], n, s["phase"], theta) - pts[k]) < 1e-12
        flipped = np.dot(s["axis"], axis) < 0
        a3 = math.pi - s["a3"] if flipped else s["a3"]
        if np.linalg.norm(np.array(s["axis"]) * (-1 if flipped else 1) - axis) < 1e-9 and abs(s["a2"] - 0.9) < 1e-9 \
                and abs(a3 - 1.3) < 1e-9:
            hits += 1
    assert hits == 1
    with pytest.raises(sphtroch.InvalidInput, match="points"):
        sphtroch.synth_points(pts[:3], n=1, free_axis=True)
    with pytest.raises(sphtroch.InvalidInput, match="threads"):
        sphtroch.synth_points(pts[:3], n=1, threads=2)
    with pytest.raises(sphtroch.InvalidInput, match="ratios"):
        sphtroch.synth_points(pts, ratios=(7, 7), free_axis=True)


def test_synth_points_over_a_ratio_set_is_the_cli_json():
    # The same trains as --ratios 2,1 of the CLI would list: every ratio of the set is solved.
    train = sphtroch.GearTrain(a2=1.0, a3=2.0, n=2, phase=0.3)
    _, P = train.trace(samples=40)
    r = sphtroch.synth_points(P[[1, 10, 28]], ratios=(2, 1))
    assert r["ratios"] == "2,1"
    assert {s["n"] for s in r["solutions"]} <= {"-2", "-1", "1", "2"}
    assert any(s["n"] == "2" and abs(s["a2"] - 1.0) < 1e-9 and abs(s["a3"] - 2.0) < 1e-9 for s in r["solutions"])
    with pytest.raises(sphtroch.InvalidInput):
        sphtroch.synth_points(P[[1, 10, 28]], n=2, ratios=(2, 1))
    with pytest.raises(sphtroch.InvalidInput, match="over the bound"):  # the CLI's work bound, as --ratios 30,30
        sphtroch.synth_points(P[[1, 10, 28]], ratios=(30, 30))


def test_fit_gives_back_the_train_of_a_path_and_keeps_a_wanted_count():
    # A noisy sampled path of a known train (the forward model through trace()); expected: that
    # train first, within the noise; a wanted count is the census of every candidate (classify).
    train = sphtroch.GearTrain(a2=1.1, a3=0.9, n=2, phase=0.4)
    _, P = train.trace(samples=300)
    rng = np.random.default_rng(3)
    noisy = P + 1e-4 * rng.standard_normal(P.shape)
    noisy /= np.linalg.norm(noisy, axis=1)[:, None]
    r = sphtroch.fit(noisy, n=2)
    best = r["candidates"][0]
    assert r["reason"] == ""
    assert abs(best["a2"] - 1.1) < 1e-3 and abs(best["a3"] - 0.9) < 1e-3
    assert best["rms"] <= 2e-4
    hidden = train.classify()
    assert best["counts"]["nodes"] == len(hidden["nodes"])
    other = sphtroch.fit(noisy, n=2, nodes=4, candidates=3)
    assert 1 <= len(other["candidates"]) <= 3
    assert all(c["counts"]["nodes"] == 4 and c["census_certified"] for c in other["candidates"])
    none = sphtroch.fit(noisy, n=2, nodes=3)
    assert none["candidates"] == [] and "multiple of 2" in none["reason"]


def test_fit_refuses_bad_input():
    good = np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0], [0.6, 0.8, 0]])
    for args, field in [((good[:3],), "points"), ((good * 1.01,), "points"), ((good, ), "nodes")]:
        with pytest.raises(sphtroch.InvalidInput) as info:
            sphtroch.fit(*args, n=1, nodes=-1 if field == "nodes" else None)
        assert info.value.field == field
    with pytest.raises(sphtroch.InvalidInput):
        sphtroch.fit(good, n=1, ratios=(2, 2))
    for kwargs, field in [({"candidates": 0}, "candidates"), ({"candidates": -1}, "candidates"),
                          ({"nodes": 2**70}, "nodes"), ({"cusps": 1.5}, "cusps")]:
        with pytest.raises(sphtroch.InvalidInput) as info:
            sphtroch.fit(good, n=1, **kwargs)
        assert info.value.field == field


def test_teeth_as_the_cli_reads_them():
    # teeth="ZS:ZP" is n = ZS/ZP and is echoed; "MIN..MAX" is every ratio of two counts in it.
    train = sphtroch.GearTrain(a2=1.0, a3=2.0, n="1/2", phase=0.3)
    _, P = train.trace(samples=40)
    pts = P[[1, 10, 28]]
    r = sphtroch.synth_points(pts, teeth="12:24")
    assert r["teeth"] == "12:24" and r["complete"] is True
    assert all(s["n"] == "1/2" and s["teeth"] == "12:24" for s in r["solutions"])
    assert any(abs(s["a2"] - 1.0) < 1e-9 and abs(s["a3"] - 2.0) < 1e-9 for s in r["solutions"])
    f = sphtroch.fit(P, teeth="1..2", candidates=2)
    assert f["teeth"] == "1..2"
    assert f["candidates"][0]["rms"] < 1e-9
    for c in f["candidates"]:
        zs, zp = (int(v) for v in c["teeth"].split(":"))
        assert 1 <= abs(zs) <= 2 and 1 <= zp <= 2 and sphtroch.GearTrain(1, 1, f"{zs}/{zp}").ratio == c["n"]
    for bad in ["39:0", "0..3", "1..60", 39]:
        with pytest.raises(sphtroch.InvalidInput) as info:
            sphtroch.fit(P, teeth=bad)
        assert info.value.field == "teeth"
    with pytest.raises(sphtroch.InvalidInput) as info:
        sphtroch.fit(P, n=1, teeth="1:1")
    assert info.value.field == "teeth"
    with pytest.raises(sphtroch.InvalidInput) as info:
        sphtroch.synth_points(pts, teeth="1:1000")  # the CLI's work bound, as for --teeth
    assert info.value.field == "teeth"


def test_fit_with_a_node_point():
    # A node of the hidden train (its census through classify()) as the node point: that train
    # first, and every candidate's certified census has a node there.
    train = sphtroch.GearTrain(a2=1.1, a3=0.9, n=2, phase=0.4)
    _, P = train.trace(samples=300)
    node = np.array(train.classify()["nodes"][0]["position"], dtype=float)
    r = sphtroch.fit(P, n=2, node_at=node, candidates=3)
    assert r["candidates"], r["reason"]
    best = r["candidates"][0]
    assert abs(best["a2"] - 1.1) < 1e-7 and abs(best["a3"] - 0.9) < 1e-7
    assert all(c["node_distance"] <= 1e-6 for c in r["candidates"])
    for kwargs, field in [({"node_at": (0, 0, 1.1)}, "node-at"), ({"node_at": (1, 0)}, "node-at"),
                          ({"node_at": (1, 0, 0), "node_tolerance": 0.0}, "node-tolerance"),
                          ({"node_tolerance": 1e-3}, "node-tolerance")]:
        with pytest.raises(sphtroch.InvalidInput) as info:
            sphtroch.fit(P, n=2, **kwargs)
        assert info.value.field == field
