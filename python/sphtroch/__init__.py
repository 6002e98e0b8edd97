"""sphtroch: trajectories of a point on the planet of a spherical planetary (bevel) gear train.

The C++ library (Lin & Tsai 1990) as a Python module: NumPy arrays in and out, the GIL released
during every computation. The API with its contracts is in __init__.pyi (and docs/python.md).

    import sphtroch
    tr = sphtroch.GearTrain(a2="pi/3", a3="pi/2", n="2")
    t, P = tr.trace(samples=720)          # float64 (N,), (N, 3)
    tr.classify()["class"]                # "nodes": the dict of `sphtroch classify --json`
"""
from ._sphtroch import (  # noqa: F401
    Chain,
    Clinostat,
    GearTrain,
    InvalidInput,
    UncertifiedResult,
    Wrist,
    __version__,
    atlas,
    boundaries,
    boundary_loci,
    classify_a3_range,
    crossings,
    fit,
    fit_text,
    identify,
    scene,
    synth_points,
    synth_points_text,
    _doc,
)
from . import _plot
from ._arrays import PointSet, attach as _attach

_attach(GearTrain, _doc)
_plot.attach(GearTrain, _doc)

__all__ = ["Chain", "Clinostat", "GearTrain", "InvalidInput", "PointSet", "UncertifiedResult", "Wrist", "atlas", "boundaries", "boundary_loci", "classify_a3_range", "crossings", "fit", "fit_text", "identify", "scene", "synth_points", "synth_points_text", "__version__"]
