"""trace(): Eq. 5 (and Eq. 4 with a phase) evaluated independently here in NumPy; the sampling of
`sphtroch trace`; arrays handed over without a copy."""
import math

import numpy as np
import pytest
import sphtroch
from conftest import run_cli


def eq5(a2, a3, n, t):
    """Report Eq. 5 (theta_p = 0), written out component by component."""
    s2, c2, s3, c3 = math.sin(a2), math.cos(a2), math.sin(a3), math.cos(a3)
    st, ct, sn, cn = np.sin(t), np.cos(t), np.sin(n * t), np.cos(n * t)
    x = ct * sn * s3 + st * cn * c2 * s3 + st * s2 * c3
    y = st * sn * s3 - ct * cn * c2 * s3 - ct * s2 * c3
    z = -cn * s2 * s3 + c2 * c3 + 0 * t
    return np.stack([x, y, z], axis=1)


def eq4(a2, a3, n, phase, t):
    """Report Eq. 4: P = Rz(theta2) Rx(a2) [s3 sa3, -c3 sa3, ca3], theta3 = n theta2 + theta_p (Eq. 3)."""
    th3 = n * t + phase
    carrier = np.stack([np.sin(th3) * math.sin(a3), -np.cos(th3) * math.sin(a3), np.full_like(t, math.cos(a3))], axis=1)
    out = np.empty_like(carrier)
    for k, th2 in enumerate(t):
        rz = np.array([[math.cos(th2), -math.sin(th2), 0], [math.sin(th2), math.cos(th2), 0], [0, 0, 1]])
        rx = np.array([[1, 0, 0], [0, math.cos(a2), -math.sin(a2)], [0, math.sin(a2), math.cos(a2)]])
        out[k] = rz @ rx @ carrier[k]
    return out


@pytest.mark.parametrize("a2,a3,n,p,q", [(math.pi / 3, math.pi / 2, "2", 2, 1), (1.1, 0.7, "5/2", 5, 2),
                                         (2.0, 2.5, "-3/2", -3, 2), (math.pi / 2, math.pi / 2, 1, 1, 1)])
def test_closed_trace_is_eq5_at_uniform_parameters(a2, a3, n, p, q):
    tr = sphtroch.GearTrain(a2=a2, a3=a3, n=n)
    t, P = tr.trace(samples=720)
    assert t.shape == (720,) and P.shape == (720, 3)
    assert t.dtype == np.float64 and P.dtype == np.float64
    np.testing.assert_allclose(t, 2 * math.pi * q * np.arange(720) / 720, rtol=0, atol=1e-12)
    np.testing.assert_allclose(P, eq5(a2, a3, p / q, t), rtol=0, atol=1e-13)
    np.testing.assert_allclose(np.linalg.norm(P, axis=1), 1.0, rtol=0, atol=1e-15)


def test_phase_follows_eq4_and_is_a_rotation_about_z1_eq8():
    a2, a3, n, phase = 1.0, 0.8, 2.0, 0.6
    t, P = sphtroch.GearTrain(a2, a3, 2, phase=phase).trace(samples=90)
    np.testing.assert_allclose(P, eq4(a2, a3, n, phase, t), rtol=0, atol=1e-13)
    # Eq. 8: with theta3 = n (theta2 + phase/n), P'(theta2) = R(-phase/n, Z1) P(theta2 + phase/n).
    c, s = math.cos(-phase / n), math.sin(-phase / n)
    rz = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    np.testing.assert_allclose(P, eq5(a2, a3, n, t + phase / n) @ rz.T, rtol=0, atol=1e-13)


def test_velocity_is_the_derivative_of_eq5():
    a2, a3, n = 1.2, 0.9, 7 / 3
    t, P, V = sphtroch.GearTrain(a2, a3, "7/3").trace(samples=400, velocity=True)
    h = 1e-6
    numeric = (eq5(a2, a3, n, t + h) - eq5(a2, a3, n, t - h)) / (2 * h)
    np.testing.assert_allclose(V, numeric, rtol=0, atol=1e-8)
    np.testing.assert_allclose(np.einsum("ij,ij->i", V, P), 0.0, atol=1e-13)  # |P| = 1


def test_open_trace_over_turns_includes_both_ends():
    tr = sphtroch.GearTrain("pi/3", "pi/2", "5/2")
    t, P = tr.trace(turns=1.5, samples=301)
    assert t[0] == 0.0 and t[-1] == pytest.approx(2 * math.pi * 1.5, abs=1e-12)
    np.testing.assert_allclose(P, eq5(math.pi / 3, math.pi / 2, 2.5, t), atol=1e-13)
    t_default, _ = tr.trace(turns=2)
    assert t_default.shape == (math.ceil(360 * (1 + 2.5) * 2 + 1),)  # 360 (1 + |n|) K + 1


def test_default_samples_are_360_per_q_plus_abs_p():
    t, _ = sphtroch.GearTrain("pi/3", "pi/2", "-5/2").trace()
    assert t.shape == (360 * (2 + 5),)


def test_angle_texts_are_the_tools_forms():
    a = sphtroch.GearTrain("2pi/3", "90deg", "2.5", phase="-pi/4")
    b = sphtroch.GearTrain(2 * math.pi / 3, math.pi / 2, 2.5, phase=-math.pi / 4)
    assert a.a2 == b.a2 and a.a3 == b.a3 and a.n == b.n == 2.5 and a.phase == b.phase
    assert a.ratio == "5/2" and (a.p, a.q) == (5, 2)
    from fractions import Fraction
    assert sphtroch.GearTrain(1, 1, Fraction(5, 2)).ratio == "5/2"
    assert sphtroch.GearTrain(1, 1, np.int64(3)).ratio == "3"
    on_cone = sphtroch.GearTrain("pi/2", "ap", 2)
    assert on_cone.a3 == pytest.approx(math.atan2(1.0, 2.0), abs=1e-15)  # a_p = atan2(sin a2, cos a2 + n)


def test_arrays_are_handed_over_without_a_copy():
    t, P, V = sphtroch.GearTrain(1, 1, 2).trace(samples=100, velocity=True)
    for a in (t, P, V):
        assert not a.flags.owndata and a.flags.c_contiguous
        assert type(a.base).__name__ == "PyCapsule"
    assert t.base is P.base is V.base  # one owner: the trajectory's C++ vectors
    del t, V
    P[0, 0] = 7.0  # still alive and writable after the others are gone
    assert P[0, 0] == 7.0


def test_same_numbers_as_the_tool(tmp_path):
    from conftest import run_cli
    out = tmp_path / "t.npy"
    run_cli("trace", "--a2", "pi/3", "--a3", "ap+0.1", "--n", "7/3", "--samples", "500", "--velocity", "-o", str(out))
    cli = np.load(out)
    t, P, V = sphtroch.GearTrain("pi/3", "ap+0.1", "7/3").trace(samples=500, velocity=True)
    assert np.array_equal(cli, np.column_stack([t, P, V]))


def test_kinematics_equals_the_tools_columns_and_classify_lists_the_dwell_points():
    import csv as _csv
    import io as _io
    tr = sphtroch.GearTrain("pi/3", 2, "5/2")
    t, P = tr.trace(samples=12)
    k = tr.kinematics(t)
    rows = list(_csv.DictReader(_io.StringIO(run_cli("trace", "--a2", "pi/3", "--a3", "2", "--n", "5/2", "--samples", "12",
                                                     "--kinematics"))))
    for key in ("speed", "geodesic_curvature", "tangential_acceleration"):
        assert k[key].shape == (12,) and k[key].dtype == np.float64
        assert k[key].tolist() == [float(r[key]) for r in rows], key
    _, _, V = tr.trace(samples=12, velocity=True)
    np.testing.assert_allclose(k["speed"], np.linalg.norm(V, axis=1), rtol=1e-15, atol=0)  # Eq. 47a: |omega x P|
    # The tracer on the pitch cone stops at its cusps: dwell points of speed 0 there.
    cone = sphtroch.GearTrain(1.0, "ap", "5/2")
    dwell = cone.classify()["dwell_points"]
    stops = [d for d in dwell if d["speed"] <= 1e-12]
    assert len(stops) == len(cone.cusps()) == 5
    with pytest.raises(sphtroch.InvalidInput, match="^t"):
        tr.kinematics([[0.0, 1.0]])
    with pytest.raises(sphtroch.InvalidInput, match="^t"):
        tr.kinematics([0.0, float("nan")])


def test_kinematics_refuses_what_it_cannot_answer():
    tr = sphtroch.GearTrain(1.0, 2.0, "7/3")
    for bad in ([1e308], [-1e308], [2 * math.pi * 1e6 * 1.001], ["a"], [[0.0]], None):
        with pytest.raises(sphtroch.InvalidInput, match="^t"):
            tr.kinematics(bad)
    k = tr.kinematics(np.array([], dtype=float))
    assert k["speed"].shape == (0,)
    edge = tr.kinematics([2 * math.pi * 1e6])
    assert all(np.isfinite(v).all() for v in edge.values())
    # On the pitch cone the speed at a cusp is reported as 0, its curvature and d|V| as 0 (undefined).
    cone = sphtroch.GearTrain("pi/2", "ap", 1)
    at = cone.cusps()[0]["param"]
    k = cone.kinematics([at])
    assert k["speed"][0] == 0.0 and k["geodesic_curvature"][0] == 0.0 and k["tangential_acceleration"][0] == 0.0
