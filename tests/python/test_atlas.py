"""atlas(): (G, G) arrays; the census against the report's criteria for n = 2 (Eqs. 43, 46) and
n = 1 (Eq. 24) evaluated here; the same cells as `sphtroch atlas --csv`."""
import csv
import io
import math
import os
import signal
import threading
import time

import pytest

import numpy as np
import sphtroch
from conftest import cli_json, run_cli


def test_shapes_dtypes_and_cell_centres():
    g = 16
    a = sphtroch.atlas(2, grid=g, a2=(0.2, 3.0), a3=("0", "pi"), threads=2)
    for k in ("a2", "a3", "nodes", "crossings", "tangencies", "cusps", "analytic_nodes", "analytic_cusps", "agree",
              "cusps_agree"):
        assert a[k].shape == (g, g), k
        assert not a[k].flags.owndata or k == "cusps_agree"
    centres2 = 0.2 + (np.arange(g) + 0.5) * (3.0 - 0.2) / g
    centres3 = (np.arange(g) + 0.5) * math.pi / g
    np.testing.assert_allclose(a["a2"], np.repeat(centres2[:, None], g, axis=1), rtol=0, atol=1e-15)
    np.testing.assert_allclose(a["a3"], np.repeat(centres3[None, :], g, axis=0), rtol=0, atol=1e-15)
    assert np.array_equal(a["nodes"], a["crossings"] + a["tangencies"])
    assert a["cusps_agree"].dtype == np.bool_ and a["cusps_agree"].all()


def test_n1_node_counts_follow_eq24():
    g = 20
    a = sphtroch.atlas(1, grid=g)
    a2, a3 = a["a2"], a["a3"]
    inside = (a2 / 2 < a3) & (a3 < math.pi - a2 / 2)  # Eq. 24: one node inside, none outside
    far = np.abs(a3 - a2 / 2) > 1e-6
    far &= np.abs(a3 - (math.pi - a2 / 2)) > 1e-6
    assert np.array_equal(a["nodes"][far], inside[far].astype(np.int64))
    assert (a["agree"] == 1).all()


def test_other_n_has_no_prediction():
    a = sphtroch.atlas("5/2", grid=6)
    assert (a["analytic_nodes"] == -1).all() and (a["agree"] == -1).all()


def test_same_cells_as_the_tool(tmp_path):
    out = tmp_path / "atlas.csv"
    run_cli("atlas", "--n", "2", "--grid", "12", "--threads", "1", "-o", str(out))
    text = "".join(line for line in out.read_text().splitlines(True) if not line.startswith("#"))
    rows = list(csv.DictReader(io.StringIO(text)))
    a = sphtroch.atlas(2, grid=12, threads=1)
    assert len(rows) == 144
    for row in rows:
        i, j = int(row["i"]), int(row["j"])
        assert int(row["nodes"]) == a["nodes"][i, j] and int(row["cusps"]) == a["cusps"][i, j]


def test_boundaries_equal_the_cli_json_exactly():
    # The same doubles as `sphtroch boundaries --json` (issue 21): no bisection needed.
    for n, a2 in [("2", "pi/3"), ("13/5", "0.7"), ("-7/3", "1.9"), ("1", "0.3")]:
        assert sphtroch.boundaries(n, a2) == cli_json("boundaries", "--n", n, "--a2", a2, "--json")
    events = sphtroch.boundaries(2, math.pi / 3)["events"]
    assert [e["kind"] for e in events] == ["pitch_cone", "pole", "pole", "pitch_cone"]
    assert events[1]["a3"] == math.pi / 3  # a3 = a2: the north pole on the curve (closed form)
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.boundaries(2, 4.0)
    assert e.value.field == "a2"


def test_boundary_loci_equal_the_cli_csv():
    rows = run_cli("boundaries", "--n", "3", "--a2", "0.2:3", "--steps", "40").splitlines()
    assert rows[1] == "locus,kind,m,label,a2,a3,b"
    loci = sphtroch.boundary_loci(3, (0.2, 3.0), steps=40, threads=1)
    mine = [f"{i},{l['kind']},{'' if l['m'] is None else l['m']},{'' if l['label'] is None else l['label']},"
            f"{a2!r},{a3!r},{b!r}" for i, l in enumerate(loci) for a2, a3, b in zip(l["a2"], l["a3"], l["b"])]
    parsed = [r.split(",") for r in rows[2:]]
    assert len(mine) == len(parsed)
    for got, want in zip(mine, parsed):
        g = got.split(",")
        assert g[:4] == want[:4] and [float(x) for x in g[4:]] == [float(x) for x in want[4:]]


def _interrupt_after(seconds):
    """SIGINT to this process after `seconds` (as Ctrl-C would send it); returns the time it was sent."""
    sent = []

    def send():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(seconds, send)
    timer.start()
    return timer, sent


@pytest.mark.parametrize("call", ["atlas", "boundary_loci"])
def test_ctrl_c_interrupts_a_long_call_within_half_a_second(call):
    # A 512^2 atlas of n = 13/5 (or 10,000 loci samples) takes tens of seconds here; SIGINT after 1 s.
    timer, sent = _interrupt_after(1.0)
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            if call == "atlas":
                sphtroch.atlas("13/5", grid=512, threads=2)
            else:
                sphtroch.boundary_loci("13/5", steps=10000, threads=2)
    finally:
        timer.cancel()
    raised = time.monotonic()
    assert sent, "the call ended before the interrupt was sent: make it longer"
    assert raised - sent[0] <= 0.5, f"KeyboardInterrupt {raised - sent[0]:.3f} s after SIGINT"
    assert raised - start < 5.0


def test_progress_reports_cells_done_and_can_stop_the_call():
    calls = []
    a = sphtroch.atlas(2, grid=48, threads=2, progress=lambda done, total: calls.append((done, total)))
    assert a["nodes"].shape == (48, 48)
    assert calls and calls[-1] == (48 * 48, 48 * 48)
    assert all(total == 48 * 48 for _, total in calls)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        sphtroch.atlas("13/5", grid=512, threads=2, progress=stop)
    loci_calls = []
    sphtroch.boundary_loci(2, steps=40, threads=1, progress=lambda d, t: loci_calls.append((d, t)))
    assert loci_calls[-1] == (40, 40)
    with pytest.raises(sphtroch.InvalidInput, match="progress"):
        sphtroch.atlas(2, grid=4, progress=3)


def test_atlas_legend_distinguishes_the_regions_of_13_5():
    """Issue 22: the legend lumped 117..221 nodes into one colour while the diagonal boundary-case
    counts took entries. Now every region count (cells off the pole lines a3 = a2, pi - a2,
    counted here from the arrays) has an entry of its own colour; the pole lines' own counts
    share one grey entry."""
    import re
    g = 100
    a = sphtroch.atlas("13/5", grid=g, svg=True)
    i, j = np.indices((g, g))
    on_line = (i == j) | (i + j == g - 1)
    node_cells = (a["nodes"] > 0) & (a["cusps"] == 0)
    regions = sorted(set(a["nodes"][node_cells & ~on_line].tolist()))
    line_only = sorted(set(a["nodes"][node_cells & on_line].tolist()) - set(regions))
    assert {117, 143, 169, 195, 221} <= set(regions) and len(regions) <= 8
    legend = a["svg"].split('<g class="legend">', 1)[1]
    entries = re.findall(r'fill:(#[0-9a-f]{6})"/>\s*<text[^>]*>(\d+) nodes \((\d+) cells\)</text>', legend)
    assert [int(n) for _, n, _ in entries] == regions
    colours = [c for c, _, _ in entries]
    assert len(set(colours)) == len(colours)  # one shade each
    assert colours == sorted(colours, reverse=True)  # light to dark with the count (hex: darker = smaller)
    for colour, n, cells in entries:  # the cells counted in the legend are the census's
        assert int(cells) == int(np.count_nonzero(node_cells & (a["nodes"] == int(n))))
    grey = re.search(r">on α3 = α2, π − α2 \((\d+) cells\):</text>\s*<text[^>]*>([0-9, ]+) nodes<", legend)
    assert grey and [int(x) for x in grey.group(2).split(", ")] == line_only
