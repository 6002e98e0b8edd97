"""GearTrain.plot(): Matplotlib (fig, ax) of the curve with its certified nodes and cusps where the
projection puts them (orthographic views: the plot command's axes; lonlat: degrees)."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import sphtroch  # noqa: E402


def markers(ax, label):
    line = next(l for l in ax.get_lines() if l.get_label() == label)
    return np.column_stack([line.get_xdata(), line.get_ydata()])


def test_top_view_marks_the_nodes_where_they_project():
    tr = sphtroch.GearTrain("pi/3", "pi/2", 2)  # Fig. 5(f): four nodes
    fig, ax = tr.plot()
    nodes = tr.node_set()
    np.testing.assert_array_equal(markers(ax, "nodes"), nodes.positions[:, :2])  # top: (x, y)
    assert "4 nodes, 0 cusps" in ax.get_title()
    curve = [l for l in ax.get_lines() if l.get_label().startswith("_")]
    drawn = np.vstack([np.column_stack([l.get_xdata(), l.get_ydata()]) for l in curve])
    assert np.all(np.hypot(drawn[:, 0], drawn[:, 1]) <= 1 + 1e-12)  # everything inside the outline
    plt.close(fig)


def test_front_view_and_lonlat_and_a_given_axes():
    tr = sphtroch.GearTrain(1.0, "ap", "5/2")
    fig, ax = tr.plot(view="front")
    cusps = tr.cusp_set()
    np.testing.assert_array_equal(markers(ax, "cusps"), cusps.positions[:, [0, 2]])  # front: (x, z)
    plt.close(fig)
    fig, ax = plt.subplots()
    same_fig, same_ax = tr.plot(ax, view="lonlat")
    assert same_fig is fig and same_ax is ax
    got = markers(ax, "nodes")
    nodes = tr.node_set()
    np.testing.assert_allclose(got[:, 0], np.degrees(nodes.longitude), rtol=0, atol=1e-12)
    np.testing.assert_allclose(got[:, 1], np.degrees(np.arcsin(nodes.positions[:, 2])), rtol=0, atol=1e-9)
    curve = ax.get_lines()[0]
    lon = np.asarray(curve.get_xdata(), dtype=float)
    steps = np.abs(np.diff(lon[~np.isnan(lon)]))
    assert np.nanmax(np.abs(np.diff(lon))) < 180  # broken (NaN) where the longitude wraps
    assert steps.size > 0
    plt.close(fig)
    with pytest.raises(sphtroch.InvalidInput, match="view"):
        tr.plot(view="iso")
    assert math.isclose(tr.a2, 1.0)
