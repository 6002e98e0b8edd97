"""GearTrain.margin() and GearTrain.tolerance(): the same dicts as `sphtroch tolerance --json`
(the tool's output is the reference), the pole line's closed form for the margin, and the
refusals named by the Python argument."""
import math

import pytest
import sphtroch
from conftest import cli_json


def test_tolerance_equals_the_tools_json():
    tr = sphtroch.GearTrain(1, 2, "5/2")
    mine = tr.tolerance(da2=1e-3, da3=1e-3, dphase=1e-3, samples=10, seed=3)
    cli = cli_json("tolerance", "--a2", "1", "--a3", "2", "--n", "5/2", "--tol-a2", "1e-3", "--tol-a3", "1e-3",
                   "--tol-phase", "1e-3", "--samples", "10", "--seed", "3", "--json")
    assert mine == cli
    assert mine["topology"] == "holds"
    assert mine["monte_carlo"]["same_census"] == 10


def test_margin_brackets_the_pole_line():
    # The nearest boundary of (1, 2) for n = 5/2: the south pole line a3 = pi - a2, at L-infinity
    # distance (pi - 3)/2.
    m = sphtroch.GearTrain(1, 2, "5/2").margin()
    exact = (math.pi - 3) / 2
    assert m["lower"] <= exact <= m["upper"]
    assert m["converged"]
    assert m["nearest"]["kind"] == "pole"
    assert m == cli_json("tolerance", "--a2", "1", "--a3", "2", "--n", "5/2", "--tol-a2", "0", "--tol-a3", "0",
                         "--json")["margin"]


def test_degrees_as_text():
    tr = sphtroch.GearTrain(1, 2, "5/2")
    assert tr.tolerance(da2="0.1deg", da3="0.1deg")["box"]["a2"] == pytest.approx(math.pi / 1800, rel=1e-15)


@pytest.mark.parametrize("kwargs, field", [({"da2": -1e-3, "da3": 0}, "da2"), ({"da2": 0, "da3": float("nan")}, "da3"),
                                           ({"da2": 0, "da3": 1.5}, "da3"), ({"da2": 0, "da3": 0, "dphase": 7}, "dphase"),
                                           ({"da2": 0, "da3": 0, "samples": 0}, "samples")])
def test_refusals_name_the_argument(kwargs, field):
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.GearTrain(1, 2, "5/2").tolerance(**kwargs)
    assert e.value.field == field
