"""`sphtroch trace -o FILE.dxf|.obj` and `--radius` (issue 22), read back by independent readers:
Debian's ezdxf for DXF, a parser written here for OBJ. Expected values: the tool's own CSV trace
at radius 1 (exact text), times the radius in Python (one IEEE multiplication: the same double)."""
import math
import os
import subprocess
import tempfile

import ezdxf
import pytest

from conftest import EXE, run_cli

TRAINS = [("pi/2", "pi/2", "1"), ("0.7", "2.5", "13/5"), ("1.1", "ap+0.01", "-7/3")]


def unit_trace(a2, a3, n, *extra):
    rows = run_cli("trace", "--a2", a2, "--a3", a3, "--n", n, *extra).splitlines()[1:]
    return [tuple(float(v) for v in r.split(",")) for r in rows]


@pytest.mark.parametrize("a2,a3,n", TRAINS)
@pytest.mark.parametrize("extra,closed", [(("--samples", "997"), True), (("--turns", "1.5"), False)])
def test_dxf_is_a_3d_polyline_through_the_trace(a2, a3, n, extra, closed):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "path.DXF")  # the suffix in any case
        assert run_cli("trace", "--a2", a2, "--a3", a3, "--n", n, *extra, "--radius", "25", "-o", path) == ""
        doc = ezdxf.readfile(path)
    assert doc.units == ezdxf.units.MM  # $INSUNITS: millimetres, as the STEP file states
    assert doc.header["$MEASUREMENT"] == 1  # metric
    entities = list(doc.modelspace())
    assert [e.dxftype() for e in entities] == ["POLYLINE"]
    poly = entities[0]
    assert poly.is_3d_polyline and poly.is_closed == closed
    got = [tuple(v.dxf.location) for v in poly.vertices]
    want = [(25 * x, 25 * y, 25 * z) for _, x, y, z in unit_trace(a2, a3, n, *extra)]
    assert got == want  # exactly: within 1e-12 x radius a fortiori


@pytest.mark.parametrize("a2,a3,n", TRAINS)
def test_obj_vertices_and_lines_join_the_trace_in_order(a2, a3, n):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "path.obj")
        run_cli("trace", "--a2", a2, "--a3", a3, "--n", n, "--samples", "2500", "--radius", "0.5", "-o", path)
        with open(path) as f:
            lines = f.read().splitlines()
    vertices = [tuple(float(v) for v in l.split()[1:]) for l in lines if l.startswith("v ")]
    edges = []
    for l in lines:
        if l.startswith("l "):
            idx = [int(i) for i in l.split()[1:]]
            edges += list(zip(idx, idx[1:]))
    assert all(l.startswith(("v ", "l ")) for l in lines)
    assert vertices == [(0.5 * x, 0.5 * y, 0.5 * z) for _, x, y, z in unit_trace(a2, a3, n, "--samples", "2500")]
    assert edges == [(i, i + 1) for i in range(1, 2500)] + [(2500, 1)]  # in order, closed


def test_radius_scales_positions_and_velocities_not_parameters():
    unit = unit_trace("pi/3", "pi/2", "5/2", "--samples", "50", "--velocity")
    big = unit_trace("pi/3", "pi/2", "5/2", "--samples", "50", "--velocity", "--radius", "25")
    assert [r[0] for r in big] == [r[0] for r in unit]
    assert [r[1:4] for r in big] == [tuple(25 * v for v in r[1:4]) for r in unit]  # exactly 25 x
    for b, u in zip(big, unit):
        assert all(math.isclose(bv, 25 * uv, rel_tol=1e-15, abs_tol=1e-13) for bv, uv in zip(b[4:], u[4:]))


def has_step():
    """Whether this build of the tool has the STEP component (sphtroch --version says)."""
    version = subprocess.run([EXE, "--version"], capture_output=True, text=True, check=True).stdout
    return "step yes" in version


STEP_REFUSED = [] if has_step() else [(["-o", "p.step"], "--output"), (["--format", "step"], "--format")]


@pytest.mark.parametrize("args,field", STEP_REFUSED + [(["--radius", "0"], "--radius"), (["--radius", "nan"], "--radius"),
                                                       (["--format", "dwg"], "--format"),
                                                       (["--tolerance", "1e-3"], "--tolerance")])
def test_refusals_name_the_option_and_write_nothing(args, field):
    with tempfile.TemporaryDirectory() as d:
        done = subprocess.run([EXE, "trace", "--a2", "1", "--a3", "2", "--n", "2", *args], cwd=d,
                              capture_output=True, text=True)
        assert done.returncode == 2 and done.stdout == "" and os.listdir(d) == []
        assert done.stderr.startswith("sphtroch: " + field + " = ") and done.stderr.count("\n") == 1
