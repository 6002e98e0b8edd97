"""sphtroch.Wrist: ik, cap and atlas return the very objects `sphtroch wrist ik|cap|atlas --json`
print (on six wrists: 2 and 3 motors, phases, a bent tool axis, a geared third joint); the
base x gear train wrist's count is 2|p| inside its zone and 0 outside (Eqs. 14/15: the z-extremes
of the train are cos(a2 + a3) and cos(a2 - a3)), each solution points the tool by an independent
product of rotation matrices written here; the 3R wrist's solutions hold the frame; pickling,
equality and refusals naming the argument."""
import fractions
import json
import math
import os
import pickle
import subprocess

import numpy as np
import pytest

import sphtroch

EXE = os.environ["SPHTROCH_EXE"]


def cli(*args):
    done = subprocess.run([EXE, "wrist", *args, "--json"], capture_output=True, text=True)
    assert done.returncode in (0, 3), done.stderr
    return json.loads(done.stdout)


def rz(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def frame(twists, coupling, phases, u):
    """F(u) = prod_i Rz(theta_i) Rx(A_i), theta_i = sum_j C_ij u_j + P_i (docs/wrists.md)."""
    f = np.eye(3)
    for a, row, p in zip(twists, coupling, phases):
        f = f @ rz(sum(float(c) * x for c, x in zip(row, u)) + p) @ rx(a)
    return f


WRISTS = [
    # (twists, coupling, phases, axis, target or frame)
    ("0,1,0.5", "1,0;0,1;0,3/2", None, None, ("target", "0.6,0,0.8")),
    ("pi/2,pi/4", "1,0;0,1", None, None, ("target", "0.3,0.4,0.866025403784439")),
    ("0.3,1.1,0.7", "1,1;1,-1;0,2", "0.1,0,-0.4", None, ("target", "0,0.6,0.8")),
    ("pi/2,pi/3,0.4", "1,0;0,1;0,-1/2", None, "0.6,0,0.8", ("target", "0.48,0.6,0.64")),
    ("pi/3,pi/2,pi/4", "1,0,0;0,1,0;0,0,1", None, None, ("target-frame", "0.5,0.1,0.7,0.5")),
    ("pi/2,pi/2,pi/3,0.5", "1,0,0;0,1,0;0,1,1;0,0,1", None, None, ("target-frame", "0.9,0.1,-0.3,0.3")),
]


@pytest.mark.parametrize("twists,coupling,phases,axis,goal", WRISTS)
def test_ik_is_the_cli_object(twists, coupling, phases, axis, goal):
    w = sphtroch.Wrist(twists, coupling, phases, axis)
    args = ["ik", "--twists", twists, "--coupling", coupling] + (["--phases", phases] if phases else []) + \
           (["--axis", axis] if axis else []) + ["--" + goal[0], goal[1]]
    want = cli(*args)
    got = w.ik(goal[1]) if goal[0] == "target" else w.ik(frame=goal[1])
    assert got == want
    assert got["count"] == len(got["solutions"]) and got["certified"]


@pytest.mark.parametrize("twists,coupling,phases,axis,goal", [w for w in WRISTS if w[4][0] == "target"])
def test_cap_and_atlas_are_the_cli_objects(twists, coupling, phases, axis, goal):
    w = sphtroch.Wrist(twists, coupling, phases, axis)
    common = ["--twists", twists, "--coupling", coupling] + (["--phases", phases] if phases else []) + (["--axis", axis] if axis else [])
    assert w.cap(goal[1]) == cli("cap", *common, "--home", goal[1])
    assert w.atlas(0.1) == cli("atlas", *common, "--width", "0.1")
    assert w.atlas(0.1, sphere_cell=0.05) == cli("atlas", *common, "--width", "0.1", "--sphere-cell", "0.05")


@pytest.mark.parametrize("p,q", [(3, 2), (2, 1), (-5, 3), (1, 1), (4, 3)])
def test_base_times_gear_train_counts_2p_inside_the_zone_and_0_outside(p, q):
    a2, a3 = 1.0, 0.5
    w = sphtroch.Wrist([0, a2, a3], [[1, 0], [0, 1], [0, fractions.Fraction(p, q)]])
    z_lo, z_hi = math.cos(a2 + a3), math.cos(a2 - a3)  # Eqs. 14/15: the train's z-extremes
    rng = np.random.default_rng(abs(p) * 10 + q)
    for _ in range(6):
        z = rng.uniform(z_lo + 0.02, z_hi - 0.02)
        phi = rng.uniform(0, 2 * math.pi)
        t = [math.sqrt(1 - z * z) * math.cos(phi), math.sqrt(1 - z * z) * math.sin(phi), z]
        r = w.ik(t)
        assert r["certified"] and r["count"] == 2 * abs(p)
        for s in r["solutions"]:
            tool = frame([0, a2, a3], [[1, 0], [0, 1], [0, p / q]], [0, 0, 0], s["motors"]) @ np.array([0, 0, 1])
            assert np.linalg.norm(tool - np.array(t)) < 1e-12
    for z in (z_hi + 0.05, z_lo - 0.05):
        if -1 < z < 1:
            t = [math.sqrt(1 - z * z), 0, z]
            assert w.ik(t)["count"] == 0


def test_3r_wrist_finds_the_motors_that_made_the_frame():
    twists, eye = [math.pi / 3, math.pi / 2, math.pi / 4], [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    made = [0.3, 1.2, 5.6]
    held = frame(twists, eye, [0, 0, 0], made)
    r = sphtroch.Wrist(twists, eye).ik(frame=held)  # a 3 x 3 array, by rows
    assert r["certified"] and r["count"] >= 1
    assert any(max(abs(a - b) for a, b in zip(s["motors"], made)) < 1e-9 for s in r["solutions"])
    for s in r["solutions"]:
        assert np.abs(frame(twists, eye, [0, 0, 0], s["motors"]) - held).max() < 1e-12


def test_value_semantics():
    w = sphtroch.Wrist("0,1,0.5", "1,0;0,1;0,3/2")
    assert w.motors == 2 and w.periods == pytest.approx([2 * math.pi, 4 * math.pi], rel=1e-15)
    assert pickle.loads(pickle.dumps(w)) == w and hash(pickle.loads(pickle.dumps(w))) == hash(w)
    assert w != sphtroch.Wrist("0,1,0.5", "1,0;0,1;0,2")
    assert "Wrist(twists='0,1,0.5', coupling='1,0;0,1;0,3/2')" == repr(w)


@pytest.mark.parametrize("kwargs,field", [
    (dict(twists="0,1,0.5", coupling="1,0;0,1;0,x"), "coupling"),
    (dict(twists="0,1,0.5", coupling="1,2;2,4;0,0"), "coupling"),       # rank 1
    (dict(twists="0,1,0.5", coupling="1,0;0,1"), "coupling"),           # rows != k
    (dict(twists=[0, float("nan"), 0.5], coupling="1,0;0,1;0,2"), "twists"),
    (dict(twists="0,1,0.5", coupling="1,0;0,1;0,1/0"), "coupling"),
    (dict(twists="0,1,0.5", coupling=[[1, 0], [0, 1], [0, True]]), "coupling"),
])
def test_bad_wrists_name_the_argument(kwargs, field):
    with pytest.raises(sphtroch.InvalidInput) as e:
        sphtroch.Wrist(**kwargs)
    assert e.value.field == field


def test_bad_targets_name_the_argument():
    w = sphtroch.Wrist("0,1,0.5", "1,0;0,1;0,3/2")
    for bad, field in [((0.6, 0, 0.9), "target"), ((float("nan"), 0, 1), "target"), ("0.6,0", "target")]:
        with pytest.raises(sphtroch.InvalidInput) as e:
            w.ik(bad)
        assert e.value.field == field
    with pytest.raises(sphtroch.InvalidInput) as e:
        w.ik(frame=(1, 0, 0, 0))
    assert e.value.field == "target-frame"
    with pytest.raises(sphtroch.InvalidInput) as e:
        w.cap((2, 0, 0))
    assert e.value.field == "home"
