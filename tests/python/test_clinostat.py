"""sphtroch.Clinostat against independent computations: the gravity against a rotation model written
here with NumPy (exact turn counts with fractions), the train against the report's Eq. 4 written
here, every number against `sphtroch clinostat ... --json` (exact equality), the dwell map against
a fine sampling classified by healpy (python3-healpy), and the refusals naming the CLI's options."""
import math
from fractions import Fraction

import numpy as np
import pytest

import sphtroch
from conftest import cli_json
from stub_info import tree, typed_dicts

# --- the model -------------------------------------------------------------------------------


def rotation(k, angle):
    """Rot(k, angle) for one axis k (3,) and angles (N,): (N, 3, 3), Rodrigues' formula."""
    k = np.asarray(k, dtype=float)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    c, s = np.cos(angle)[:, None, None], np.sin(angle)[:, None, None]
    return c * np.eye(3) + s * cross + (1 - c) * np.outer(k, k)


def frame_angle(rpm, phase_deg, t):
    """phase + 2 pi rpm t / 60 in radians: the whole turns of rpm t / 60 removed exactly (Fraction)
    for up to 5000 times; for more (the fine sampling, t < 1000 s) in floats (~1e-14 rad)."""
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.size > 5000:
        turns = float(rpm) * t / 60
        return math.radians(phase_deg) + 2 * math.pi * (turns - np.floor(turns))
    exact = [Fraction(rpm) * Fraction(float(x)) / 60 for x in t]
    return math.radians(phase_deg) + np.array([2 * math.pi * float(x - math.floor(x)) for x in exact])


def model_gravity(outer, inner, t, tilt=90.0, frame=90.0, phase_outer=0.0, phase_inner=0.0):
    """g = R^T (0, 0, -1), R = Rot(u, phi_o) Rot(v, phi_i): (N, 3)."""
    psi, beta = math.radians(tilt), math.radians(frame)
    u = np.array([math.sin(psi), 0.0, math.cos(psi)])
    w = np.array([-math.cos(psi), 0.0, math.sin(psi)])
    v = math.cos(beta) * u + math.sin(beta) * w
    r = rotation(u, frame_angle(outer, phase_outer, t)) @ rotation(v, frame_angle(inner, phase_inner, t))
    return np.einsum("nji,j->ni", r, np.array([0.0, 0.0, -1.0]))


def eq4(train, theta2):
    """The report's Eq. 4, P = Rz(theta2) Rx(a2) Rz(n theta2 + theta_p) Rx(a3) z, for (N,) theta2."""
    def rz(a):
        c, s = np.cos(a), np.sin(a)
        z, o = np.zeros_like(a), np.ones_like(a)
        return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1), np.stack([z, z, o], -1)], -2)

    def rx(a):
        c, s = math.cos(a), math.sin(a)
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])

    n = train.p / train.q
    return rz(theta2) @ rx(train.a2) @ rz(n * theta2 + train.phase) @ rx(train.a3) @ np.array([0.0, 0.0, 1.0])


# (positional speeds, keyword settings, exact outer, exact inner): speeds in every accepted form.
MACHINES = [
    ((1.33, 2), {}, Fraction(133, 100), Fraction(2)),
    ((Fraction(4, 3), "-2.5"), {"tilt": 60.0, "frame_angle": 75.0, "phase_outer": 10.0, "phase_inner": -30.0},
     Fraction(4, 3), Fraction(-5, 2)),
    (("0.7", np.float64(1.1)), {"tilt": 35.5, "frame_angle": 120.0, "phase_outer": 725.0}, Fraction(7, 10), Fraction(11, 10)),
    ((np.int64(3), 0), {"tilt": 90.0}, Fraction(3), Fraction(0)),
    ((2, 2), {"tilt": 45.0, "frame_angle": 0.0}, Fraction(2), Fraction(2)),
]
IDS = ["1.33/2", "4/3,-2.5 tilted", "0.7/1.1", "single axis", "parallel axes"]


@pytest.mark.parametrize("args,kwargs,outer,inner", MACHINES, ids=IDS)
def test_gravity_is_the_rotation_model(args, kwargs, outer, inner):
    c = sphtroch.Clinostat(*args, **kwargs)
    t = np.concatenate([np.linspace(0.0, 600.0, 241), [1234.5678, 1e5 + 0.25, 1e6 - 0.125, -77.7]])
    want = model_gravity(outer, inner, t, kwargs.get("tilt", 90.0), kwargs.get("frame_angle", 90.0),
                         kwargs.get("phase_outer", 0.0), kwargs.get("phase_inner", 0.0))
    got = c.gravity(t)
    assert got.shape == (len(t), 3) and got.dtype == np.float64
    assert np.max(np.abs(got - want)) <= 1e-12
    assert np.array_equal(c.gravity(t[7]), got[7]) and c.gravity(t[7]).shape == (3,)
    assert np.array_equal(c.gravity(list(t[:5])), got[:5])
    assert np.array_equal(c.effective_gravity(t), got)  # no offset: the same vector


def test_the_model_is_not_trivially_satisfied():
    c = sphtroch.Clinostat(1.33, 2)
    t = np.linspace(0, 100, 11)
    assert np.max(np.abs(c.gravity(t) - model_gravity(Fraction(2), Fraction(133, 100), t))) > 0.1  # speeds swapped
    assert np.max(np.abs(c.gravity(t) - model_gravity(Fraction(133, 100), Fraction(2), t, tilt=80))) > 0.01


@pytest.mark.parametrize("args,kwargs,outer,inner", MACHINES[:3], ids=IDS[:3])
def test_the_train_draws_the_gravity(args, kwargs, outer, inner):
    c = sphtroch.Clinostat(*args, **kwargs)
    tr, m = c.train, c.train_map
    assert Fraction(tr.p, tr.q) == outer / inner and c.train_note == ""
    assert tr.a2 == pytest.approx(math.radians(kwargs.get("frame_angle", 90.0)), abs=1e-15)
    assert tr.a3 == pytest.approx(math.pi - math.radians(kwargs.get("tilt", 90.0)), abs=1e-15)
    assert m["rotation"].shape == (3, 3) and np.allclose(m["rotation"] @ m["rotation"].T, np.eye(3), atol=1e-15)
    assert m["theta2_rate"] == pytest.approx(-2 * math.pi * float(inner) / 60, rel=1e-15)
    t = np.linspace(0, 300, 97)
    drawn = eq4(tr, m["theta2_at_0"] + m["theta2_rate"] * t) @ m["rotation"].T
    assert np.max(np.abs(drawn - c.gravity(t))) <= 1e-12


def test_a_machine_whose_path_is_a_circle_has_no_train():
    for c in (sphtroch.Clinostat(3, 0), sphtroch.Clinostat(2, 2, tilt=45.0, frame_angle=0.0), sphtroch.Clinostat(1, 2, tilt=0.0)):
        assert c.train is None and c.train_map is None and "circle" in c.train_note
        assert c._repr_svg_() is None


def test_a_machine_beyond_the_trains_limits_keeps_its_gravity():
    # Equal speeds and axes 0.01 degree from antiparallel: the train would have n = 1 and a2 within
    # 1.8e-4 rad of pi, which GearTrain refuses (the planet barely turns); the machine is fine.
    c = sphtroch.Clinostat(1, 1, frame_angle=179.99)
    assert c.train is None and c.train_map is None and c.train_note.startswith("no gear train: ")
    t = np.linspace(0, 60, 13)
    assert np.max(np.abs(c.gravity(t) - model_gravity(Fraction(1), Fraction(1), t, frame=179.99))) <= 1e-12
    assert c.period == 60.0


def test_exact_speeds():
    c = sphtroch.Clinostat(1.33, 2)
    assert c.outer_rpm == "1.33" and c.inner_rpm == "2"
    assert Fraction(c.train.p, c.train.q) == Fraction(133, 200) and c.train.ratio == "133/200"
    assert c.period == 6000.0  # both frames back after 100 min: 1.33 * 100 and 2 * 100 whole turns
    assert sphtroch.Clinostat(np.float64(1.33), 2.0).train == c.train
    assert sphtroch.Clinostat("1.33", "2").train == c.train == sphtroch.Clinostat(Fraction(133, 100), 2).train
    third = sphtroch.Clinostat(Fraction(4, 3), 2)
    assert third.outer_rpm == "4/3" and third.train.ratio == "2/3" and third.period == 90.0
    assert sphtroch.Clinostat("-0.000001", 1).outer_rpm == "-0.000001"


def test_properties_and_repr():
    c = sphtroch.Clinostat("4/3", -2, tilt=60, frame_angle=75.5, phase_outer=-10, phase_inner=1e6, offset=[0.05, 0, -0.01])
    assert (c.tilt, c.frame_angle, c.phase_outer, c.phase_inner) == (60.0, 75.5, -10.0, 1e6)
    assert c.offset == (0.05, 0.0, -0.01) and sphtroch.Clinostat(1, 2).offset is None
    assert repr(c) == ("Clinostat(outer_rpm='4/3', inner_rpm='-2', tilt=60.0, frame_angle=75.5, phase_outer=-10.0, "
                       "phase_inner=1000000.0, offset=(0.05, 0.0, -0.01))")
    again = eval("sphtroch." + repr(c))
    assert repr(again) == repr(c) and again.train == c.train
    assert np.array_equal(again.effective_gravity([3.5]), c.effective_gravity([3.5]))
    svg = sphtroch.Clinostat(1.33, 2)._repr_svg_()
    assert svg == sphtroch.Clinostat(1.33, 2).train._repr_svg_() and svg.lstrip().startswith("<?xml")


def test_the_stub_lists_every_public_member():
    cls = next(n for n in tree().body if getattr(n, "name", "") == "Clinostat")
    members = {n.name for n in cls.body if hasattr(n, "name") and not n.name.startswith("_")}
    assert members == {m for m in dir(sphtroch.Clinostat) if not m.startswith("_")}


def test_results_have_the_stubs_typed_dict_keys():
    td = typed_dicts()
    c = sphtroch.Clinostat(1.33, 2)
    assert set(c.worst_window_mean(600)) == set(td["WorstWindowMean"])
    assert set(c.time_to(0.05, 10)) == set(td["TimeToEpsilon"])
    assert set(c.coverage_summary(600, 4)) == set(td["CoverageSummary"])
    assert set(c.train_map) == set(td["ClinostatTrainMap"])


# --- the CLI's numbers -------------------------------------------------------------------------

CLI_CASES = [
    # (CLI options, Python arguments, window, epsilon, resolution, coverage, nside, start)
    (["--outer", "1.33", "--inner", "2"], ((1.33, 2), {}), 600, 0.01, 1, 6000, 8, 0),
    (["--outer", "4/3", "--inner=-2.5", "--tilt", "60", "--frame-angle", "75", "--phase-outer", "10",
      "--phase-inner=-30"],
     ((Fraction(4, 3), "-2.5"), {"tilt": 60, "frame_angle": 75, "phase_outer": 10, "phase_inner": -30}), 45.5, 0.05, 0.5,
     500, 4, 12.5),
    (["--outer", "1.33", "--inner", "2", "--offset", "0.05,0,0.02"], ((1.33, 2), {"offset": (0.05, 0, 0.02)}), 600, 0.02, 5,
     700, 8, -100),
    (["--outer", "3", "--inner", "0", "--tilt", "80"], ((3, 0), {"tilt": 80.0}), 7, 0.2, 1, 100, 2, 0),
    (["--outer", "1", "--inner", "1", "--frame-angle", "45"], ((1, 1), {"frame_angle": 45}), 30, 0.1, 1, 120, 8, 0),
]


@pytest.mark.parametrize("case", CLI_CASES, ids=["1.33/2", "4/3,-2.5 tilted", "offset", "single axis", "resonance"])
def test_the_numbers_are_the_clis(case):
    options, (args, kwargs), window, epsilon, resolution, duration, nside, start = case
    cli = cli_json("clinostat", *options, "--window", str(window), "--epsilon", str(epsilon), "--resolution", str(resolution),
                   "--coverage", str(duration), "--nside", str(nside), f"--start={start}", "--json")
    c = sphtroch.Clinostat(*args, **kwargs)
    if cli["train"] is None:
        assert c.train is None and c.train_map is None and c.train_note == cli["train_note"]
    else:
        t, m = cli["train"], c.train_map
        assert (t["n"], t["a2"], t["a3"], t["phase"]) == (c.train.ratio, c.train.a2, c.train.a3, c.train.phase)
        assert (t["theta2_at_0"], t["theta2_rate"]) == (m["theta2_at_0"], m["theta2_rate"])
        assert t["rotation"] == m["rotation"].tolist() and c.train_note == "" and "train_note" not in cli
    assert cli["averaged"] == ("effective gravity at the offset" if "offset" in kwargs else "gravity")
    assert cli["period_s"] == c.period
    assert cli["mean_over_period"] == c.mean_over_period.tolist()
    assert cli["worst_window_mean"] == c.worst_window_mean(window)
    assert cli["time_to_epsilon"] == c.time_to(epsilon, resolution)
    dwell = c.coverage(duration, nside, start)
    assert dwell.dtype == np.float64 and dwell.shape == (12 * nside * nside,)
    assert cli["coverage"].pop("dwell_s") == dwell.tolist()
    assert cli["coverage"].pop("order") == "RING"
    assert cli["coverage"] == c.coverage_summary(duration, nside=nside, start=start)


@pytest.mark.parametrize("case", CLI_CASES, ids=["1.33/2", "4/3,-2.5 tilted", "offset", "single axis", "resonance"])
def test_the_report_is_the_clis_json_object(case):
    """Clinostat.report() is `sphtroch clinostat --json`'s object itself: the same members, the same
    doubles, with and without the options (the two front ends share no code above the library)."""
    options, (args, kwargs), window, epsilon, resolution, duration, nside, start = case
    c = sphtroch.Clinostat(*args, **kwargs)
    assert c.report() == cli_json("clinostat", *options, "--json")
    assert c.report(window=window) == cli_json("clinostat", *options, "--window", str(window), "--json")
    full = cli_json("clinostat", *options, "--window", str(window), "--epsilon", str(epsilon), "--resolution", str(resolution),
                    "--coverage", str(duration), "--nside", str(nside), f"--start={start}", "--json")
    got = c.report(window=window, epsilon=epsilon, resolution=resolution, coverage=duration, nside=nside, start=start)
    assert got == full
    assert set(got) == {"train", "averaged", "period_s", "mean_over_period", "worst_window_mean", "time_to_epsilon",
                        "coverage"} | ({"train_note"} if got["train"] is None else set())
    band = c.report(window=window, band=True)
    assert band == cli_json("clinostat", *options, "--window", str(window), "--band", "--json")
    assert band["window_band"]["max"]["upper"] == band["worst_window_mean"]["upper"]
    mid = (band["window_band"]["min"]["lower"] + band["window_band"]["max"]["upper"]) / 2
    for tolerance in (mid, mid / 4):  # the target inside and (a band wider than 1e-9) outside or decided
        target = c.report(window=window, band=True, target_g=mid, tolerance=tolerance)
        assert target == cli_json("clinostat", *options, "--window", str(window), "--band", f"--target-g={mid!r}",
                                  f"--tolerance={tolerance!r}", "--json")
    running = c.report(running_mean=[30, window], start=start)
    assert running == cli_json("clinostat", *options, "--running-mean", f"30,{window}", f"--start={start}", "--json")
    for m in running["running_mean"]:  # the mean of the sampled gravity (Simpson's rule on 20001 points)
        t = np.linspace(start, start + m["t_s"], 20001)
        g = c.effective_gravity(t) if "offset" in kwargs else c.gravity(t)
        w = np.ones(t.size)
        w[1:-1:2], w[2:-1:2] = 4, 2
        simpson = (w[:, None] * g).sum(axis=0) * (t[1] - t[0]) / 3
        assert np.abs(simpson / m["t_s"] - m["mean"]).max() < 1e-10


def test_the_environments_gravity_scales_the_report_as_the_clis_gravity():
    """Clinostat(..., gravity_g0=G).report() is `sphtroch clinostat ... --gravity G --json`'s object;
    its means are G times the unit machine's (0.5: exactly, a power of two)."""
    options = ["--outer", "5", "--inner", "0.05", "--tilt", "67.7901"]
    half = sphtroch.Clinostat(5, "0.05", tilt=67.7901, gravity_g0=0.5)
    unit = sphtroch.Clinostat(5, "0.05", tilt=67.7901)
    assert half.gravity_g0 == 0.5 and unit.gravity_g0 == 1.0 and "gravity_g0=0.5" in repr(half) and "gravity" not in repr(unit)
    got = half.report(window=600, band=True, target_g=0.12, tolerance=0.004, running_mean=[300])
    assert got == cli_json("clinostat", *options, "--gravity", "0.5", "--window", "600", "--band", "--target-g", "0.12",
                           "--tolerance", "0.004", "--running-mean", "300", "--json")
    assert got["gravity_g0"] == 0.5 and got["target"]["inside"] is True
    assert got["running_mean"][0]["magnitude"] == 0.5 * unit.report(running_mean=[300])["running_mean"][0]["magnitude"]
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Clinostat(1, 2, gravity_g0=0)
    assert e.value.field == "gravity"


def test_the_report_refuses_as_the_cli_does():
    c = sphtroch.Clinostat(1.33, 2)
    for kwargs, field in (({"window": 0}, "window"), ({"epsilon": -1}, "epsilon"), ({"resolution": 2}, "resolution"),
                          ({"coverage": 600, "nside": 3}, "nside"), ({"running_mean": [0]}, "running-mean"),
                          ({"running_mean": [10, float("nan")]}, "running-mean"), ({"band": True}, "band"),
                          ({"window": 60, "target_g": 0.1, "tolerance": 0.1}, "target-g"),
                          ({"window": 60, "band": True, "target_g": 0.1, "tolerance": -0.1}, "tolerance"),
                          ({"window": 60, "band": True, "target_g": 0.1, "tolerance": float("nan")}, "tolerance"),
                          ({"window": 60, "band": True, "target_g": 0.1}, "tolerance")):
        with pytest.raises(sphtroch.InvalidInput) as e:
            c.report(**kwargs)
        assert e.value.field == field


def test_the_averages_follow_the_offset():
    centre, off = sphtroch.Clinostat(1.33, 2), sphtroch.Clinostat(1.33, 2, offset=(0.5, 0, 0))
    t = np.linspace(0, 100, 51)
    assert np.array_equal(off.gravity(t), centre.gravity(t))
    assert np.max(np.abs(off.effective_gravity(t) - off.gravity(t))) > 1e-4  # a / g0 at 0.5 m and ~0.2 rad/s
    assert np.linalg.norm(off.window_mean(0, 6000) - centre.window_mean(0, 6000)) > 1e-6
    assert np.array_equal(off.coverage(600, 4), centre.coverage(600, 4))  # the dwell map is of g_s


def test_window_mean_is_the_mean_of_sampled_gravity():
    c = sphtroch.Clinostat("4/3", "-2.5", tilt=60, frame_angle=75, offset=(0.1, 0.2, 0))
    t0, w = 37.25, 45.0
    t = t0 + (np.arange(200000) + 0.5) * (w / 200000)  # midpoint rule, error ~ (w/N)^2 |f''| << 1e-9
    assert np.max(np.abs(c.window_mean(t0, w) - c.effective_gravity(t).mean(axis=0))) < 1e-9
    assert np.max(np.abs(c.window_mean(t0, 0) - c.effective_gravity(t0))) <= 1e-14  # the series' value at t0


# --- the dwell map against a fine sampling -----------------------------------------------------


@pytest.mark.parametrize("args,kwargs,outer,inner,duration,nside,start",
                         [((1.33, 2), {}, Fraction(133, 100), Fraction(2), 600.0, 8, 0.0),
                          (("4/3", "-2.5"), {"tilt": 60.0, "frame_angle": 75.0, "phase_outer": 10.0}, Fraction(4, 3),
                           Fraction(-5, 2), 200.0, 4, 33.0)],
                         ids=["1.33/2 nside 8", "4/3,-2.5 nside 4"])
def test_coverage_against_a_fine_sampling(args, kwargs, outer, inner, duration, nside, start):
    import healpy  # python3-healpy

    c = sphtroch.Clinostat(*args, **kwargs)
    dwell, summary = c.coverage(duration, nside, start), c.coverage_summary(duration, nside, start)
    dt = 2e-3
    steps = int(round(duration / dt))
    t = start + (np.arange(steps) + 0.5) * dt
    g = model_gravity(outer, inner, t, kwargs.get("tilt", 90.0), kwargs.get("frame_angle", 90.0),
                      kwargs.get("phase_outer", 0.0), kwargs.get("phase_inner", 0.0))
    cells = healpy.vec2pix(nside, g[:, 0], g[:, 1], g[:, 2])  # RING
    fine = np.bincount(cells, minlength=12 * nside * nside) * dt
    changes = np.flatnonzero(cells[1:] != cells[:-1])
    moves = np.bincount(cells[changes], minlength=fine.size) + np.bincount(cells[changes + 1], minlength=fine.size)
    assert changes.size > 20  # the path crosses many cells
    assert np.all(np.abs(dwell - fine) <= summary["bound_s"] + dt * moves), np.max(np.abs(dwell - fine) - dt * moves)
    assert set(np.flatnonzero(dwell > 0)) == set(np.flatnonzero(fine > 0))
    assert summary["fraction"] == np.count_nonzero(dwell) / dwell.size
    assert abs(dwell.sum() - duration) <= 1e-9 * duration
    assert summary["dwell_cv"] == pytest.approx(np.std(dwell) / (duration / dwell.size), rel=1e-12)


# --- refusals ----------------------------------------------------------------------------------


def refused(call, field):
    with pytest.raises(sphtroch.InvalidInput) as info:
        call()
    assert info.value.field == field, str(info.value)
    assert str(info.value).startswith(field + " = ") and info.value.valid
    return info.value


BAD_MACHINES = [
    (lambda: sphtroch.Clinostat("1.3333333", 2), "outer"),
    (lambda: sphtroch.Clinostat(0.1 + 0.2, 2), "outer"),
    (lambda: sphtroch.Clinostat(1e-5, 2), "outer"),
    (lambda: sphtroch.Clinostat(1001, 2), "outer"),
    (lambda: sphtroch.Clinostat(Fraction(1, 3000000), 2), "outer"),
    (lambda: sphtroch.Clinostat(float("nan"), 2), "outer"),
    (lambda: sphtroch.Clinostat(True, 2), "outer"),
    (lambda: sphtroch.Clinostat(None, 2), "outer"),
    (lambda: sphtroch.Clinostat(1 + 2j, 2), "outer"),
    (lambda: sphtroch.Clinostat(2, "fast"), "inner"),
    (lambda: sphtroch.Clinostat(2, "1e2"), "inner"),
    (lambda: sphtroch.Clinostat(0, "0/5"), "inner"),
    (lambda: sphtroch.Clinostat(1, 2, tilt=180.5), "tilt"),
    (lambda: sphtroch.Clinostat(1, 2, tilt=float("nan")), "tilt"),
    (lambda: sphtroch.Clinostat(1, 2, tilt="90"), "tilt"),
    (lambda: sphtroch.Clinostat(1, 2, frame_angle=-1), "frame-angle"),
    (lambda: sphtroch.Clinostat(1, 2, phase_outer=2e6), "phase-outer"),
    (lambda: sphtroch.Clinostat(1, 2, phase_inner=float("inf")), "phase-inner"),
    (lambda: sphtroch.Clinostat(1, 2, offset=(11, 0, 0)), "offset"),
    (lambda: sphtroch.Clinostat(1, 2, offset=(0.1, 0)), "offset"),
    (lambda: sphtroch.Clinostat(1, 2, offset=("0.1", 0, 0)), "offset"),
    (lambda: sphtroch.Clinostat(1, 2, offset=(float("nan"), 0, 0)), "offset"),
    (lambda: sphtroch.Clinostat(1, 2, offset=0.1), "offset"),
]


@pytest.mark.parametrize("k", range(len(BAD_MACHINES)))
def test_bad_settings_name_the_clis_option(k):
    call, field = BAD_MACHINES[k]
    refused(call, field)


C = sphtroch.Clinostat(1.33, 2)
BAD_CALLS = [
    (lambda: C.gravity("1"), "t"), (lambda: C.gravity([[1.0, 2.0]]), "t"), (lambda: C.gravity([0, 2e12]), "t"),
    (lambda: C.effective_gravity(float("nan")), "t"), (lambda: C.window_mean(0, -1), "window"),
    (lambda: C.window_mean(float("inf"), 1), "t0"), (lambda: C.worst_window_mean(0), "window"),
    (lambda: C.worst_window_mean(2e9), "window"), (lambda: C.time_to(0), "epsilon"), (lambda: C.time_to(0.01, 0), "resolution"),
    (lambda: C.time_to(1e-12), "epsilon"), (lambda: C.time_to(1e-7), "resolution"), (lambda: C.coverage(0), "coverage"), (lambda: C.coverage(10, nside=3), "nside"),
    (lambda: C.coverage(10, nside=True), "nside"), (lambda: C.coverage(10, start=float("nan")), "start"),
    (lambda: C.coverage_summary(1e12, nside=1024), "coverage"),
]


@pytest.mark.parametrize("k", range(len(BAD_CALLS)))
def test_bad_arguments_name_the_argument(k):
    call, field = BAD_CALLS[k]
    refused(call, field)


def test_a_too_long_period_is_refused_as_the_cli_does():
    c = sphtroch.Clinostat("1.000001", "999.999999")
    e = refused(lambda: c.worst_window_mean(10), "outer")
    assert "too long" in e.problem
