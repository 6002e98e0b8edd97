"""A typed user script: `mypy --strict` must accept it (tests/python/test_typing.py), and it runs.
NumPy scalars go wherever the runtime takes numbers, as a NumPy user writes them."""
from fractions import Fraction
from typing import List, Optional

import numpy as np
import numpy.typing as npt

import sphtroch


def sweep(a2: float, a3s: npt.NDArray[np.float64]) -> List[int]:
    counts: List[int] = []
    for a3 in a3s:  # np.float64 elements
        train = sphtroch.GearTrain(a2, a3, np.int64(2), phase=np.float64(0.1))
        info = train.classify(literal=np.bool_(False))  # a TypedDict: keys and value types checked
        nodes: int = info["counts"]["nodes"]
        kind: str = info["class"]
        counts.append(nodes if kind else 0)
    return counts


def main() -> None:
    train = sphtroch.GearTrain("pi/3", 1.2, Fraction(13, 5))
    t, p = train.trace(samples=np.int64(500))
    t2, p2, v = train.trace(samples=200, turns=np.float32(1.5), velocity=True)
    assert p.shape == (500, 3) and v.shape == p2.shape and t2.shape == (200,)
    svg: str = train.svg(size=np.int64(300), labels="none")
    assert "<svg" in svg[:200]
    print(sweep(1.0, np.linspace(0.2, 2.9, 5)))
    seen = {train: "memo"}  # GearTrain is hashable
    assert seen[sphtroch.GearTrain("60deg", 1.2, "13/5")] == "memo"
    by_teeth = sphtroch.GearTrain("pi/3", 1.2, teeth="39:15")  # the same train, 39:15 kept
    teeth: Optional[str] = by_teeth.teeth
    assert by_teeth == train and teeth == "39:15"
    a = sphtroch.atlas(np.int64(2), grid=np.int64(8), a2=(np.float64(0.1), "pi"), threads=np.int32(1),
                       progress=lambda done, total: None)
    print(int(a["nodes"].max()))
    events = sphtroch.boundaries(np.float64(2.5), np.float64(1.0))["events"]
    print(len(events))
    pts = sphtroch.crossings(p, closed=np.bool_(True), max_work=np.int64(10**7))
    print(pts["crossings"])
    margin: float = train.margin()["lower"]
    first = train.nodes()[0]["position"] if train.nodes() else [0.0, 0.0, 1.0]
    print(margin, len(first))
    machine = sphtroch.Clinostat(np.float64(1.33), Fraction(2), tilt=np.int64(90), offset=(0.01, 0, np.float64(0.0)))
    first_s: Optional[float] = machine.time_to(0.01, resolution=np.float64(10))["first_s"]
    g = machine.gravity(np.linspace(0.0, 60.0, 7))
    gear: Optional[sphtroch.GearTrain] = machine.train
    assert g.shape == (7, 3) and gear is not None and first_s is not None and machine.worst_window_mean(600)["certified"]


if __name__ == "__main__":
    main()
