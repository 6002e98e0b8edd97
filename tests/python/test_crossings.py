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
    r = sphtroch.crossings(P)
    summary, rows = cli_crossings(P, tmp_path)
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
    closed = sphtroch.crossings(bow)
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
