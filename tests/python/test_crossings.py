"""crossings(): equal to `sphtroch crossings` on the same trace (counts and --pairs rows), exact
counts on hand-made polylines, points read in place, other dtypes converted once."""
import csv
import io

import numpy as np
import pytest
import sphtroch
from conftest import run_cli


def cli_crossings(points, tmp_path, closed=True):
    path = tmp_path / "p.npy"
    np.save(path, points)
    pairs = tmp_path / "pairs.csv"
    args = ["crossings", "--input", str(path), "--pairs", str(pairs), "--json"] + ([] if closed else ["--open"])
    import json
    summary = json.loads(run_cli(*args))
    rows = list(csv.DictReader(io.StringIO(pairs.read_text())))
    return summary, rows


@pytest.mark.parametrize("a2,a3,n,samples", [("pi/3", "pi/2", "2", 4000), ("1", "2", "7/3", 20000),
                                             ("pi/2", "pi/2", "1", 1000)])
def test_trace_crossings_equal_the_tool(a2, a3, n, samples, tmp_path):
    _, P = sphtroch.GearTrain(a2, a3, n).trace(samples=samples)
    r = sphtroch.crossings(P, pairs=True)
    summary, rows = cli_crossings(P, tmp_path)
    rows.sort(key=lambda row: (int(row["i"]), int(row["j"])))  # --pairs rows come in the search's order
    assert (r["vertices"], r["crossings"], r["touchings"]) == (summary["vertices"], summary["crossings"], summary["touchings"])
    assert (r["candidate_pairs"], r["predicates"]) == (summary["candidate_pairs"], summary["predicates"])
    assert r["pairs"].dtype == np.int64 and r["pairs"].shape == (len(rows), 2)
    assert r["pairs"].tolist() == [[int(row["i"]), int(row["j"])] for row in rows]
    assert r["kinds"] == [row["kind"] for row in rows]
    assert r["input_converted"] is False
    assert r["timings"]["seconds_search"] >= 0


def test_open_polyline_and_crossing_counts():
    # Fig. 5(f) (n = 2, a2 = pi/3, a3 = pi/2) has 4 crossing nodes (report Table 1 row f);
    # a fine closed polyline of it crosses itself exactly there.
    _, P = sphtroch.GearTrain("pi/3", "pi/2", 2).trace(samples=3000)
    assert sphtroch.crossings(P)["crossings"] == 4
    # A spherical "bow tie": the edges 0 and 2 of the closed quadrilateral cross at (1, 0, 0)-ish.
    bow = np.array([[1, -0.1, 0.1], [1, 0.1, -0.1], [1, 0.1, 0.1], [1, -0.1, -0.1]], dtype=float)
    closed = sphtroch.crossings(bow, pairs=True)
    assert closed["crossings"] == 1 and closed["pairs"].tolist() == [[0, 2]] and closed["kinds"] == ["crossing"]
    assert sphtroch.crossings(bow, closed=False)["crossings"] == 1  # edges 0 and 2 exist in the open one too
    assert sphtroch.crossings(bow[:3], closed=False)["crossings"] == 0


def test_points_in_other_layouts_are_converted_once():
    _, P = sphtroch.GearTrain("pi/3", "pi/2", 2).trace(samples=3000)
    ref = sphtroch.crossings(P)
    for other in (P.astype(np.float32).astype(np.float64), np.asfortranarray(P), P.tolist()):
        r = sphtroch.crossings(other)
        assert r["crossings"] == ref["crossings"]
    assert sphtroch.crossings(np.asfortranarray(P))["input_converted"] is True
    assert sphtroch.crossings(P.tolist())["input_converted"] is True
    assert sphtroch.crossings(P)["input_converted"] is False
    big = np.zeros((3000, 6))
    big[:, ::2] = P  # a strided view: converted, same result
    assert sphtroch.crossings(big[:, ::2])["crossings"] == ref["crossings"]


def numpy_brute_force(P, closed=True):
    """Crossing pairs of a polyline by the O(N^2) sign test in double precision (S2's rule:
    sign det[A,B,C] = -sign det[A,B,D] = -sign det[C,D,B] = sign det[C,D,A], all nonzero).
    Exact enough for random directions, which have no near-degenerate pairs."""
    n = len(P)
    e = n if closed else n - 1
    A, B = P[:e], P[(np.arange(e) + 1) % n]
    M = np.cross(A, B) @ P.T  # M[i, k] = det[A_i, B_i, P_k]
    head = (np.arange(e) + 1) % n
    sc = np.sign(M[:, :e])          # sc[i, j] = det[A_i, B_i, A_j]
    sd = np.sign(M[:, head])        # sd[i, j] = det[A_i, B_i, B_j]
    sa, sb = sc.T, sd.T             # sa[i, j] = det[A_j, B_j, A_i], sb = det[A_j, B_j, B_i]
    cross = (sc == -sd) & (sa == -sb) & (sa == sd) & (sc != 0) & (sa != 0)
    i, j = np.nonzero(np.triu(cross, 2))
    keep = ~((i == 0) & (j == e - 1)) if closed else np.ones(len(i), bool)
    return sorted(zip(i[keep].tolist(), j[keep].tolist()))


def random_directions(n, seed):
    return np.random.default_rng(seed).normal(size=(n, 3))


@pytest.mark.parametrize("closed", [True, False])
def test_d2_count_path_equals_brute_force_and_pairs_path(closed):
    P = random_directions(600, 5)
    expected = numpy_brute_force(P, closed)
    assert len(expected) > 10000
    counts = sphtroch.crossings(P, closed=closed)
    assert "pairs" not in counts and "kinds" not in counts  # the count path keeps no pair
    assert (counts["crossings"], counts["touchings"]) == (len(expected), 0)
    full = sphtroch.crossings(P, closed=closed, pairs=True)
    assert full["pairs"].tolist() == [list(p) for p in expected]
    assert set(full["kinds"]) == {"crossing"}
    assert full["candidate_pairs"] == counts["candidate_pairs"]


def test_d2_limits_raise_invalid_input_naming_them():
    P = random_directions(600, 6)
    total = sphtroch.crossings(P)["crossings"]
    assert sphtroch.crossings(P, max_crossings=total)["crossings"] == total
    for pairs in (False, True):
        with pytest.raises(sphtroch.InvalidInput) as e:
            sphtroch.crossings(P, pairs=pairs, max_crossings=total - 1)
        assert e.value.field == "max_crossings" and e.value.value == str(total - 1)
        assert "more than" in e.value.problem and "raise it" in e.value.valid
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.crossings(P, max_work=1000)
    assert e.value.field == "max_work" and "units of work" in e.value.problem
    # 60,000 random directions (about 1e9 crossings): refused by the default work bound.
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.crossings(random_directions(60000, 7))
    assert e.value.field == "max_work" and "estimated" in e.value.problem
    for bad in (-1, 2.5, "10", True, 10**16):
        with pytest.raises(sphtroch.InvalidInput) as e:
            sphtroch.crossings(P, max_crossings=bad)
        assert e.value.field == "max_crossings"
