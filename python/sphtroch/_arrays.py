"""Nodes and cusps as NumPy arrays: PointSet (the contract and docstrings: __init__.pyi).

Built from the dicts of GearTrain.nodes() / cusps() (the certified census), so the arrays hold the
same numbers; the docstrings are the stub's, set at import from the compiled table (_doc).
"""

import numpy as np


class PointSet:
    def __init__(self, rows, kind):
        self.kind = kind
        self._rows = [dict(r) for r in rows]
        k = len(rows)
        self.ids = np.arange(1, k + 1, dtype=np.int64)
        self.positions = np.array([r["position"] for r in rows], dtype=np.float64).reshape(k, 3)
        if kind == "nodes":
            width = max((len(r["params"]) for r in rows), default=2)
            self.params = np.full((k, width), np.nan)
            for i, r in enumerate(rows):
                self.params[i, :len(r["params"])] = r["params"]
            self.kinds = np.array([r["kind"] for r in rows], dtype=str).reshape(k)
            self.branches = np.array([r["branches"] for r in rows], dtype=np.int64).reshape(k)
        else:
            self.params = np.array([[r["param"]] for r in rows], dtype=np.float64).reshape(k, 1)
            self.kinds = np.full(k, "cusp")
            self.branches = np.ones(k, dtype=np.int64)
        if kind == "nodes":  # the census's own values
            self.longitude = np.array([r["longitude"] for r in rows], dtype=np.float64).reshape(k)
            self.latitude = np.array([r["latitude"] for r in rows], dtype=np.float64).reshape(k)
        else:  # the same convention: atan2(y, x), asin(z)
            x, y, z = self.positions.T
            self.longitude = np.arctan2(y, x)
            self.latitude = np.arcsin(np.clip(z, -1.0, 1.0))

    def __len__(self):
        return len(self._rows)

    def __getitem__(self, i):
        return dict(self._rows[i])

    def __iter__(self):
        return (dict(r) for r in self._rows)

    def __repr__(self):
        return f"PointSet({self.kind}, {len(self)} point(s))"

    def to_list(self):
        return [dict(r) for r in self._rows]

    def columns(self):
        cols = {"id": self.ids, "kind": self.kinds, "x": self.positions[:, 0], "y": self.positions[:, 1],
                "z": self.positions[:, 2], "longitude": self.longitude, "latitude": self.latitude,
                "branches": self.branches}
        for j in range(self.params.shape[1]):
            cols[f"t{j + 1}"] = self.params[:, j]
        return cols

    def to_dataframe(self):
        import pandas  # optional: only this method needs it

        return pandas.DataFrame(self.columns())


def _node_set(self, *, literal=False, samples=None):
    return PointSet(self.nodes(literal=literal, samples=samples), "nodes")


def _cusp_set(self, *, literal=False, samples=None):
    return PointSet(self.cusps(literal=literal, samples=samples), "cusps")


def attach(train_class, doc):
    """Adds node_set / cusp_set to GearTrain and the stub's docstrings to everything here."""
    PointSet.__doc__ = doc("PointSet")
    for name in ("to_list", "columns", "to_dataframe"):
        getattr(PointSet, name).__doc__ = doc("PointSet." + name)
    for name, f in (("node_set", _node_set), ("cusp_set", _cusp_set)):
        f.__name__ = f.__qualname__ = name
        f.__doc__ = doc("GearTrain." + name)
        setattr(train_class, name, f)

