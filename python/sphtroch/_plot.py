"""GearTrain.plot(): the curve in Matplotlib, as a 2-D view that reads well (contract: __init__.pyi).

view "top" / "front" / "side": orthographic, looking down -Z / along +Y / along -X (the plot
command's names), the near half solid and the far half dotted, the unit circle as the outline;
"lonlat": longitude and latitude (equirectangular, degrees), the curve broken where it wraps.
Nodes are red dots, cusps black crosses, from the certified census (node_set / cusp_set).
"""
import numpy as np

from ._sphtroch import InvalidInput

# Screen axes (right, up) and the direction towards the viewer, per view.
_VIEWS = {"top": ((1, 0, 0), (0, 1, 0), (0, 0, 1)),
          "front": ((1, 0, 0), (0, 0, 1), (0, -1, 0)),
          "side": ((0, 1, 0), (0, 0, 1), (1, 0, 0))}


def _runs(mask):
    """[start, stop) index runs where mask is True."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(np.int8), [0]))))
    return list(zip(edges[::2], edges[1::2]))


def _plot(self, ax=None, *, view="top", samples=None, literal=False):
    import matplotlib.pyplot as plt  # optional: only this method needs it

    if view not in ("top", "front", "side", "lonlat"):
        e = InvalidInput(f"view = {view!r}: not a view; valid: 'top', 'front', 'side' or 'lonlat'")
        e.field, e.value, e.problem, e.valid = "view", repr(view), "not a view", "'top', 'front', 'side' or 'lonlat'"
        raise e
    fig, ax = (plt.subplots(figsize=(5, 5)) if view != "lonlat" else plt.subplots(figsize=(8, 4))) if ax is None \
        else (ax.figure, ax)
    _, P = self.trace(samples=samples)
    P = np.vstack([P, P[:1]])  # closed
    nodes, cusps = self.node_set(literal=literal), self.cusp_set(literal=literal)
    if view == "lonlat":
        lon, lat = np.degrees(np.arctan2(P[:, 1], P[:, 0])), np.degrees(np.arcsin(np.clip(P[:, 2], -1, 1)))
        jump = np.abs(np.diff(lon)) > 180
        lon, lat = np.insert(lon, np.flatnonzero(jump) + 1, np.nan), np.insert(lat, np.flatnonzero(jump) + 1, np.nan)
        ax.plot(lon, lat, color="C0", lw=1)
        ax.plot(np.degrees(nodes.longitude), np.degrees(nodes.latitude), "o", color="red", ms=4, label="nodes")
        ax.plot(np.degrees(cusps.longitude), np.degrees(cusps.latitude), "x", color="black", ms=6, label="cusps")
        ax.set(xlim=(-180, 180), ylim=(-90, 90), xlabel="longitude (deg)", ylabel="latitude (deg)")
    else:
        right, up, towards = (np.array(v, dtype=float) for v in _VIEWS[view])
        x, y, depth = P @ right, P @ up, P @ towards
        for front, style in ((True, "-"), (False, ":")):
            for a, b in _runs((depth >= 0) == front):
                ax.plot(x[max(a - 1, 0):b + 1], y[max(a - 1, 0):b + 1], style, color="C0", lw=1)
        t = np.linspace(0, 2 * np.pi, 361)
        ax.plot(np.cos(t), np.sin(t), color="0.6", lw=0.8)
        ax.plot(nodes.positions @ right, nodes.positions @ up, "o", color="red", ms=4, label="nodes")
        ax.plot(cusps.positions @ right, cusps.positions @ up, "x", color="black", ms=6, label="cusps")
        ax.set(xlim=(-1.05, 1.05), ylim=(-1.05, 1.05), aspect="equal")
        ax.set_axis_off()
    ax.set_title(f"a2 = {self.texts[0]}, a3 = {self.texts[1]}, n = {self.ratio}: {len(nodes)} nodes, {len(cusps)} cusps")
    return fig, ax


def attach(train_class, doc):
    _plot.__name__ = _plot.__qualname__ = "plot"
    _plot.__doc__ = doc("GearTrain.plot")
    train_class.plot = _plot
