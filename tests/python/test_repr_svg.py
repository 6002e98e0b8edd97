"""GearTrain._repr_svg_ (Jupyter's picture) is bounded and never raises: svg() when the census is
cheap (at most 2000 node points by |p| (|p| + q)), else the curve alone with a caption saying the
census was not run (cheap: at most 2000 node points |p| (|p| + q) and (|p| + q)^3 <= 1.5e5). Timing is no pass/fail criterion here (the decision is tested; the time is a
benchmark: docs/python.md)."""
import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest

import sphtroch

NOT_RUN = "census not run"


def estimated_nodes(train):
    return abs(train.p) * (abs(train.p) + train.q)


def cheap(train):
    return estimated_nodes(train) <= 2000 and (abs(train.p) + train.q) ** 3 <= 1.5e5


def parsed(svg):
    root = ET.fromstring(svg)
    assert root.tag.endswith("svg")
    return root


@pytest.mark.parametrize("a2, a3, n", [(1.0, 1.2, "1333/2000"), ("pi/3", "pi/2", "101/40"), (2.0, 0.5, "-997/3"),
                                       (0.4, 2.9, "1/1000"), (1.1, 1.0, "61/29")])
def test_large_ratios_draw_the_curve_only_and_say_so(a2, a3, n):
    tr = sphtroch.GearTrain(a2, a3, n)
    assert not cheap(tr)
    svg = tr._repr_svg_()
    text = "".join(parsed(svg).itertext())
    assert NOT_RUN in text and f"n = {tr.ratio}" in text
    assert ("beyond the census bound" in text) == (estimated_nodes(tr) > 200000)
    assert "<path" in svg or "<polyline" in svg  # the curve is drawn


def test_real_rpm_values_give_a_picture():
    tr = sphtroch.GearTrain(1.0, 1.2, Fraction("1.333") / Fraction("2.0"))  # the ratio of 1.333 and 2.0 rpm
    assert tr.ratio == "1333/2000"
    assert NOT_RUN in "".join(parsed(tr._repr_svg_()).itertext())


@pytest.mark.parametrize("n", ["2", "13/5", "7/3", "19/7", "40/9"])
def test_cheap_census_draws_what_svg_draws(n):
    tr = sphtroch.GearTrain("pi/3", "pi/2", n)
    assert cheap(tr)
    assert tr._repr_svg_() == tr.svg()
    assert NOT_RUN not in tr._repr_svg_()
