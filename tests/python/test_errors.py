"""Every bad argument raises sphtroch.InvalidInput (a ValueError) naming it: .field, .value, .valid."""
import math
from fractions import Fraction

import numpy as np
import pytest
import sphtroch

GOOD = dict(a2="pi/3", a3="pi/2", n="2")


def check(call, field, *in_value):
    with pytest.raises(sphtroch.InvalidInput) as info:
        call()
    e = info.value
    assert isinstance(e, ValueError)
    assert e.field == field, str(e)
    assert e.valid, str(e)
    for part in in_value:
        assert part in e.value, str(e)
    assert str(e).startswith(field + " = ")
    return e


@pytest.mark.parametrize("field,value", [
    ("a2", 0.0), ("a2", math.pi), ("a2", -1.0), ("a2", float("nan")), ("a2", "abc"), ("a2", "4"), ("a2", None),
    ("a2", True), ("a2", [1.0]),
    ("a3", 0.0), ("a3", "pi"), ("a3", "ap+4"), ("a3", float("inf")), ("a3", "nonsense"), ("a3", {}),
    ("n", 0), ("n", "0"), ("n", "1/0"), ("n", "x"), ("n", 1 / 3), ("n", 10**7), ("n", 10**30), ("n", Fraction(1, 10**7)),
    ("n", float("nan")), ("n", None), ("n", False), ("n", "2.5.1"),
    ("phase", float("inf")), ("phase", "pi/"), ("phase", None),
])
def test_gear_train_arguments(field, value):
    args = dict(GOOD, phase=0.0)
    args[field] = value
    check(lambda: sphtroch.GearTrain(**args), field)


@pytest.mark.parametrize("kwargs,field", [
    (dict(samples=2), "samples"), (dict(samples=10**7 + 1), "samples"), (dict(samples=-5), "samples"),
    (dict(samples=2.5), "samples"), (dict(samples="720"), "samples"), (dict(samples=True), "samples"),
    (dict(turns=0), "turns"), (dict(turns=-1), "turns"), (dict(turns=float("nan")), "turns"),
    (dict(turns=2e6), "turns"), (dict(turns="2"), "turns"),
])
def test_trace_arguments(kwargs, field):
    tr = sphtroch.GearTrain(**GOOD)
    check(lambda: tr.trace(**kwargs), field)


def test_default_sample_count_too_large():
    check(lambda: sphtroch.GearTrain(1, 1, "999999/1000000").trace(), "samples")


def test_classify_arguments():
    tr = sphtroch.GearTrain(**GOOD)
    check(lambda: tr.classify(samples=10), "samples", "10")
    check(lambda: tr.nodes(samples=10**8), "samples")
    check(lambda: tr.cusps(samples=1.5), "samples")


@pytest.mark.parametrize("points,what", [
    (np.zeros((10, 2)), "(10, 2)"), (np.zeros((10,)), "(10,)"), (np.zeros((4, 3, 1)), "(4, 3, 1)"),
    (np.zeros((0, 3)), ""), ([[1, 0, 0], [0, 1, 0]], ""), ("abc", ""), (None, ""), ([[1, 0, 0], [1, 0, 0], [0, 1, 0]], "index 0"),
    ([[1, 0, 0], [0, 1, 0], [0, 0, 0]], "index 2"), ([[1, 0, 0], [0, 1, 0], [0, 0, float("nan")]], "index 2"),
    ([[1, 0, 0], [-1, 0, 0], [0, 0, 1]], "index 0"), ([["a", "b", "c"]] * 3, ""),
    (np.eye(3, dtype=complex) + 1j, "complex"),  # not cast to the real part
])
def test_crossings_points_refused(points, what):
    e = check(lambda: sphtroch.crossings(points), "points", what)
    if isinstance(points, np.ndarray) and points.ndim != 2:
        assert "shape" in e.value


def test_crossings_open_needs_two_points():
    check(lambda: sphtroch.crossings(np.array([[1.0, 0, 0]]), closed=False), "points")
    assert sphtroch.crossings(np.array([[1.0, 0, 0], [0, 1.0, 0]]), closed=False)["crossings"] == 0


@pytest.mark.parametrize("kwargs,field", [
    (dict(n=0), "n"), (dict(n="2", grid=0), "grid"), (dict(n="2", grid=5000), "grid"), (dict(n=2, grid=8.5), "grid"),
    (dict(n=2, grid=8, a2=(1.0, 0.5)), "a2"), (dict(n=2, grid=8, a2=(0, 4)), "a2"), (dict(n=2, grid=8, a2="0:x"), "a2"),
        (dict(n=2, grid=8, a2="pi:0"), "a2"), (dict(n=2, grid=8, a2="0 :pi"), "a2"),
    (dict(n=2, grid=8, a3=(0, "x")), "a3"), (dict(n=2, grid=8, a3=(0, 1, 2)), "a3"),
    (dict(n=2, grid=8, threads=0), "threads"), (dict(n=2, grid=8, threads=5000), "threads"),
])
def test_atlas_arguments(kwargs, field):
    check(lambda: sphtroch.atlas(**kwargs), field)


@pytest.mark.parametrize("kwargs,field", [
    (dict(a2=0, n=2, a3=(0.1, 1)), "a2"), (dict(a2=1, n="q", a3=(0.1, 1)), "n"),
    (dict(a2=1, n=2, a3=(1, 0.1)), "a3"), (dict(a2=1, n=2, a3=(-0.1, 1)), "a3"), (dict(a2=1, n=2, a3=(0, 4)), "a3"),
    (dict(a2=1, n=2, a3=(0.1, 1), count=1), "count"), (dict(a2=1, n=2, a3=5), "a3"),
])
def test_classify_a3_range_arguments(kwargs, field):
    check(lambda: sphtroch.classify_a3_range(**kwargs), field)


def test_invalid_input_is_catchable_as_value_error_and_reports_the_tools_range():
    with pytest.raises(ValueError):
        sphtroch.GearTrain(4.0, 1.0, 2)
    e = check(lambda: sphtroch.GearTrain(4.0, 1.0, 2), "a2", "4")
    assert e.valid == "(0, pi) radians"


def test_d11_equality_with_another_type_is_false_not_type_error():
    tr = sphtroch.GearTrain(**GOOD)
    assert (tr == 5) is False and (tr != 5) is True and (tr == "pi/3") is False and (tr == None) is False  # noqa: E711
    assert tr == sphtroch.GearTrain(**GOOD) and not (tr != sphtroch.GearTrain(**GOOD))


@pytest.mark.parametrize("field", ["a2", "a3", "n", "phase"])
def test_d11_lone_surrogate_text_is_invalid_input_naming_the_field(field):
    args = dict(GOOD, phase=0.0)
    args[field] = "\ud800"
    e = check(lambda: sphtroch.GearTrain(**args), field)
    assert "ud800" in e.value


def test_d11_str_of_invalid_input_is_one_line():
    e = check(lambda: sphtroch.GearTrain("1\n2\tx\r", 1.0, 2), "a2")
    text = str(e)
    assert "\n" not in text and "\r" not in text and "\t" not in text
    assert "\\n" in text or "\\\\n" in text  # escaped as the tool escapes it (\n), inside the repr or the text
    e = check(lambda: sphtroch.GearTrain("pi/3", "1\n2", 2), "a3")
    assert "\n" not in str(e)


def test_d11_classify_a3_range_names_its_argument_a3():
    for a3 in ((1, 1), (1.0, 0.5), (-0.5, 1.0), (1.0, 4.0)):
        check(lambda: sphtroch.classify_a3_range(a2=1.0, n=2, a3=a3), "a3")


@pytest.mark.parametrize("value", ["yes", 1, 0, None, 1.0, "True", [True]])
def test_d11_flags_accept_only_true_or_false(value):
    P = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    tr = sphtroch.GearTrain(**GOOD)
    for call, field in ((lambda: sphtroch.crossings(P, closed=value), "closed"),
                        (lambda: sphtroch.crossings(P, pairs=value), "pairs"),
                        (lambda: tr.trace(samples=10, velocity=value), "velocity"),
                        (lambda: tr.classify_roots(literal=value), "literal"),
                        (lambda: sphtroch.classify_a3_range(1.0, 2, (0.5, 1.0), count=2, literal=value), "literal")):
        e = check(call, field)
        assert e.valid == "True or False"
    assert sphtroch.crossings(P, closed=np.bool_(False))["closed"] is False


@pytest.mark.parametrize("points", [
    np.array([["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]]),
    [["1", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]],
    np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=object),
    np.ones((3, 3), dtype=bool),
    np.array([[b"1", b"0", b"0"]] * 3),
])
def test_d11_string_and_non_numeric_arrays_are_refused(points):
    e = check(lambda: sphtroch.crossings(points), "points")
    assert "dtype" in e.value and "numeric" in e.problem


def test_ranges_as_the_cli_writes_them():
    """"LO:HI" text is the same range as the pair (lo, hi): one parser for the CLI and Python."""
    import math
    a = sphtroch.atlas(2, grid=4, a2="0:pi/2", a3="pi/4:3pi/4", threads=1)
    b = sphtroch.atlas(2, grid=4, a2=(0, math.pi / 2), a3=(math.pi / 4, 3 * math.pi / 4), threads=1)
    assert (a["a2"] == b["a2"]).all() and (a["a3"] == b["a3"]).all() and (a["nodes"] == b["nodes"]).all()
    r = sphtroch.classify_a3_range(1.0, 2, "0.5:2.5", count=11)
    assert r == sphtroch.classify_a3_range(1.0, 2, (0.5, 2.5), count=11)


def test_trains_are_equal_and_hash_alike_by_value():
    # The same angle written two ways is the same train (issue 21); a3 on the pitch cone ("ap") is
    # not the double it rounds to (the reference is kept), and another phase or n is another train.
    a = sphtroch.GearTrain("60deg", 1.2, "13/5")
    b = sphtroch.GearTrain("pi/3", 1.2, "13/5")
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    assert {a: "x"}[b] == "x"
    assert sphtroch.GearTrain("pi/3", 1.2, "26/10") == b  # n in lowest terms
    assert sphtroch.GearTrain("pi/3", 1.2, "13/5", 0.1) != b
    assert sphtroch.GearTrain("pi/3", 1.2, "13/5", "pi") == sphtroch.GearTrain("pi/3", 1.2, "13/5", "-pi")  # one angle
    assert hash(sphtroch.GearTrain("pi/3", 1.2, "13/5", "pi")) == hash(sphtroch.GearTrain("pi/3", 1.2, "13/5", "-pi"))
    assert sphtroch.GearTrain("pi/3", 1.2, "13/4") != b
    cone = sphtroch.GearTrain("pi/3", "ap", 2)
    assert cone == sphtroch.GearTrain("pi/3", "ap", 2) and hash(cone) == hash(sphtroch.GearTrain("pi/3", "ap", 2))
    assert cone != sphtroch.GearTrain("pi/3", cone.a3, 2)  # the same double, not on the cone by definition
    assert (a == 5) is False and a != "pi/3"
