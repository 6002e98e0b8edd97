"""Arguments NumPy or pybind11 would silently convert (or fail to cast) raise sphtroch.InvalidInput
naming the argument: string and complex arrays, NumPy complex and bool scalars, lone surrogates,
ratios that are not two whole numbers, truthy non-flags, text where a number is expected.

Expected values are the exception type (InvalidInput, a ValueError) and the field it names; the
one-line message starts with that field."""
import numpy as np
import pytest
import sphtroch

TRAIN = sphtroch.GearTrain(1.0, 2.0, 2, phase=0.3)
T, P = TRAIN.trace(samples=40)
THREE = P[[1, 10, 28]]
FIVE = P[[1, 7, 15, 22, 31]]


def refused(call, field):
    with pytest.raises(sphtroch.InvalidInput) as info:
        call()
    e = info.value
    assert isinstance(e, ValueError)
    assert e.field == field, str(e)
    assert e.valid, str(e)
    assert str(e).startswith(field + " = "), str(e)
    return e


def as_text(a):
    return np.asarray(a).astype(str)  # "1.0" rows NumPy's own cast would parse back


def as_complex(a):
    return np.asarray(a).astype(complex)  # NumPy's cast would drop the imaginary part


ARRAY_CALLS = [
    ("identify t", lambda conv: sphtroch.identify(conv(T), P), "t"),
    ("identify points", lambda conv: sphtroch.identify(T, conv(P)), "points"),
    ("synth_points points", lambda conv: sphtroch.synth_points(conv(THREE), n=2), "points"),
    ("fit points", lambda conv: sphtroch.fit(conv(P), n=2), "points"),
    ("fit node_at", lambda conv: sphtroch.fit(P, n=2, node_at=conv([0.0, 0.0, 1.0])), "node-at"),
    ("kinematics t", lambda conv: TRAIN.kinematics(conv(T)), "t"),
]


@pytest.mark.parametrize("name,call,field", ARRAY_CALLS, ids=[c[0] for c in ARRAY_CALLS])
def test_string_arrays_are_refused_not_parsed_as_numbers(name, call, field):
    e = refused(lambda: call(as_text), field)
    assert "dtype" in e.value and "numeric" in e.problem


@pytest.mark.parametrize("name,call,field", ARRAY_CALLS, ids=[c[0] for c in ARRAY_CALLS])
def test_complex_arrays_are_refused_not_cut_to_their_real_part(name, call, field):
    e = refused(lambda: call(as_complex), field)
    assert "complex" in e.value


@pytest.mark.parametrize("conv", [lambda a: np.asarray(a, dtype=object), lambda a: [str(x) for x in np.ravel(a)],
                                  lambda a: np.asarray(a) > 0],
                         ids=["object array", "list of str", "bool array"])
def test_kinematics_times_of_object_text_or_bool_are_refused(conv):
    refused(lambda: TRAIN.kinematics(conv(T)), "t")


@pytest.mark.parametrize("ratios", [(1.5, 2), "2,2", (2, 2, 2), (True, 2), (2**70, 1), (2, None), 7],
                         ids=["a float bound", "the CLI's text", "three bounds", "a bool bound", "beyond int64",
                              "None bound", "one number"])
def test_ratios_that_are_not_two_whole_numbers(ratios):
    refused(lambda: sphtroch.synth_points(THREE, ratios=ratios), "ratios")
    refused(lambda: sphtroch.fit(P, ratios=ratios), "ratios")


@pytest.mark.parametrize("value", ["yes", 1, 0, None, "False", np.array([True])],
                         ids=["truthy text", "one", "zero", "None", "the text False", "an array"])
def test_free_axis_is_a_flag_not_anything_truthy(value):
    refused(lambda: sphtroch.synth_points(FIVE, n=1, free_axis=value), "free_axis")


@pytest.mark.parametrize("name,call,field", [
    ("GearTrain teeth", lambda: sphtroch.GearTrain(0.7, 2.5, teeth="\ud800"), "teeth"),
    ("synth_points teeth", lambda: sphtroch.synth_points(THREE, teeth="\ud800"), "teeth"),
    ("fit teeth", lambda: sphtroch.fit(P, teeth="12..\ud800"), "teeth"),
    ("atlas a2 range text", lambda: sphtroch.atlas(2, grid=4, a2="0:\ud800"), "a2"),
    ("classify_a3_range a3 range text", lambda: sphtroch.classify_a3_range(1.0, 2, "\ud800"), "a3"),
], ids=lambda v: v if isinstance(v, str) else "")
def test_a_lone_surrogate_is_not_encodable_text(name, call, field):
    e = refused(call, field)
    assert "ud800" in e.value


@pytest.mark.parametrize("kwargs,field", [
    (dict(max_deviation="0.1"), "max-deviation"), (dict(max_deviation=None), "max-deviation"),
    (dict(max_deviation=True), "max-deviation"), (dict(max_deviation=np.complex128(1)), "max-deviation"),
    (dict(node_at=(0, 0, 1), node_tolerance="1e-3"), "node-tolerance"),
    (dict(node_at=(0, 0, 1), node_tolerance=True), "node-tolerance"),
    (dict(node_at=(0, 0, 1), node_tolerance=1j), "node-tolerance"),
], ids=["max_deviation text", "max_deviation None", "max_deviation bool", "max_deviation numpy complex",
        "node_tolerance text", "node_tolerance bool", "node_tolerance complex"])
def test_fit_reals_refuse_text_bool_none_and_complex(kwargs, field):
    refused(lambda: sphtroch.fit(P, n=2, **kwargs), field)


@pytest.mark.parametrize("name,call,field", [
    ("a2 numpy complex", lambda: sphtroch.GearTrain(np.complex128(1), 1, 2), "a2"),
    ("a2 numpy bool", lambda: sphtroch.GearTrain(np.bool_(True), 1, 2), "a2"),
    ("a2 0-d text array", lambda: sphtroch.GearTrain(np.array("1.0"), 1, 2), "a2"),
    ("n numpy complex", lambda: sphtroch.GearTrain(1, 1, np.complex128(2)), "n"),
    ("n numpy bool", lambda: sphtroch.GearTrain(1, 1, np.bool_(True)), "n"),
    ("phase numpy complex64", lambda: sphtroch.GearTrain(1, 1, 2, phase=np.complex64(0)), "phase"),
    ("turns numpy complex", lambda: TRAIN.trace(turns=np.complex128(1)), "turns"),
    ("turns numpy bool", lambda: TRAIN.trace(turns=np.bool_(True)), "turns"),
    ("turns 0-d text array", lambda: TRAIN.trace(turns=np.array("1")), "turns"),
    ("a3 range of numpy complex", lambda: sphtroch.classify_a3_range(1.0, 2, (np.complex128(0.5), 1.0)), "a3"),
], ids=lambda v: v if isinstance(v, str) else "")
def test_numpy_complex_bool_and_text_scalars_are_not_real_numbers(name, call, field):
    refused(call, field)


@pytest.mark.parametrize("name,call,field", [
    ("atlas grid", lambda: sphtroch.atlas(2, grid=np.bool_(True)), "grid"),
    ("atlas threads", lambda: sphtroch.atlas(2, grid=4, threads=np.bool_(True)), "threads"),
    ("boundary_loci steps", lambda: sphtroch.boundary_loci(2, steps=np.bool_(True)), "steps"),
], ids=lambda v: v if isinstance(v, str) else "")
def test_numpy_bool_is_not_a_count(name, call, field):
    refused(call, field)


def test_numpy_scalars_are_accepted_where_python_ones_are():
    # The stub's Count and Flag: NumPy integers and numpy.bool_ read as the Python int and bool.
    r = sphtroch.fit(P, n=2, candidates=np.int64(2), nodes=np.int32(len(TRAIN.nodes())), cusps=np.uint8(0))
    assert 1 <= len(r["candidates"]) <= 2, r["reason"]
    assert sphtroch.synth_points(THREE, ratios=(np.int64(2), np.int32(1)))["ratios"] == "2,1"
    assert sphtroch.synth_points(THREE, n=2, free_axis=np.bool_(False))["complete"] is True
    assert sphtroch.synth_points(FIVE, n=1, free_axis=np.bool_(True), threads=np.int64(1))["complete"] in (True, False)


@pytest.mark.parametrize("name,call,field", [
    ("svg labels", lambda: TRAIN.svg(labels=5), "labels"),
    ("svg view", lambda: TRAIN.svg(view=np.array([0.1, 0.2])), "view"),
], ids=lambda v: v if isinstance(v, str) else "")
def test_text_arguments_given_no_string_say_so(name, call, field):
    e = refused(call, field)
    assert e.problem == "not a string", str(e)


def test_an_empty_teeth_text_is_refused_naming_teeth():
    for call in (sphtroch.synth_points, sphtroch.synth_points_text):
        refused(lambda: call(THREE, teeth=""), "teeth")
    refused(lambda: sphtroch.fit(P, teeth=""), "teeth")


@pytest.mark.parametrize("teeth", ["39:15\x00", "39:15\x00junk", "39\x0015"])
def test_a_nul_byte_in_a_text_is_escaped_not_cut(teeth):
    e = refused(lambda: sphtroch.synth_points(THREE, teeth=teeth), "teeth")
    assert "\\x00" in str(e) and "; valid: " in str(e), str(e)

