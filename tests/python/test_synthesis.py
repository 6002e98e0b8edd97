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
