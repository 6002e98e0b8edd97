"""Python on par with the CLI: every command of `sphtroch --help` (and every subcommand of `synth`
and `clinostat`) has a row in docs/python.md's table "CLI command -> Python call"; each row names
Python calls that exist, or says "CLI-only:" with a reason. And the calls added for parity print the CLI's bytes."""
import json
import os
import pathlib
import re
import subprocess

import pytest

import sphtroch
from conftest import EXE, SOURCE_DIR, run_cli


def untimed(text):
    """The text without the wall times the tool prints ("..., 0.00217 s" ending a line, JSON "seconds")."""
    text = re.sub(r"[0-9.]+(e-?[0-9]+)? s$", "T s", text, flags=re.M)
    return re.sub(r'"seconds": [0-9.]+(e-?[0-9]+)?', '"seconds": T', text)

DOC = pathlib.Path(SOURCE_DIR) / "docs" / "python.md"


def subcommands(*args):
    """The subcommand names a --help lists (CLI11's "Subcommands:" section)."""
    text = subprocess.run([EXE, *args, "--help"], capture_output=True, text=True, check=True).stdout
    section = text.split("Subcommands:", 1)[1]
    return [m.group(1) for m in re.finditer(r"^  (\S+)\s", section, re.M)]


def cli_commands():
    out = []
    for c in subcommands():
        if c == "synth":
            out += [f"{c} {s}" for s in subcommands(c)]
        elif c == "clinostat":  # a command of its own and the parent of design and merge
            out += [c] + [f"{c} {s}" for s in subcommands(c)]
        else:
            out.append(c)
    return out


def parity_table():
    """{command: second column} of the table whose header is | CLI command | Python |."""
    text = DOC.read_text()
    start = text.index("| CLI command | Python |")
    rows = {}
    for line in text[start:].splitlines()[2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip("|").split("|")]
        m = re.fullmatch(r"`sphtroch ([a-z\- ]+)`", cells[0])
        assert m, line
        rows[m.group(1)] = cells[1]
    return rows


def resolve(name):
    obj = sphtroch
    for part in name.split(".")[1:]:
        obj = getattr(obj, part)
    return obj


def test_every_cli_command_has_a_python_call_or_a_reason():
    commands = cli_commands()
    assert {"trace", "classify", "scene", "synth points", "synth merge", "clinostat", "clinostat design"} <= set(commands)
    table = parity_table()
    missing = [c for c in commands if c not in table]
    assert not missing, f"CLI commands with no row in docs/python.md: {missing}"
    assert not set(table) - set(commands), "rows for commands the CLI does not have"
    for command, python in table.items():
        calls = re.findall(r"`(sphtroch\.[A-Za-z_.]+)", python)
        if python.startswith("CLI-only:"):
            assert len(python) > len("CLI-only: ") + 20, f"{command}: say why it is CLI-only"
            continue
        assert calls, f"{command}: no Python call named ({python})"
        for call in calls:
            assert callable(resolve(call)) or isinstance(resolve(call), property), call


def test_report_is_the_text_classify_prints():
    tr = sphtroch.GearTrain("pi/3", "pi/2", 2)
    assert untimed(tr.report()) == untimed(run_cli("classify", "--a2", "pi/3", "--a3", "pi/2", "--n", "2"))
    tr = sphtroch.GearTrain(1.1, "ap+1e-6", "5/2", phase=0.3)
    assert untimed(tr.report(literal=True)) == untimed(run_cli("classify", "--a2", "1.1", "--a3", "ap+1e-6", "--n", "5/2",
                                                               "--phase", "0.3", "--literal"))


def test_scene_outputs_are_the_files_the_tool_writes(tmp_path):
    scene = {"trains": [
        {"name": "fig5f", "a2": "pi/3", "a3": "pi/2", "n": "2",
         "effects": {"trace": "a.csv", "nodes": "a_nodes.csv", "classification": "a.txt", "extrema": "a_z.json",
                     "screw_axis": "a_screw.csv", "plot": "a.svg"}},
        {"name": "cusped", "a2": 1.0, "a3": "ap", "n": "5/2", "samples": 500,
         "effects": {"cusps": "b_cusps.csv", "classification": "b.json", "velocity": "b_v.csv"}}]}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    done = subprocess.run([EXE, "scene", "scene.json"], cwd=tmp_path, capture_output=True)
    assert done.returncode == 0, done.stderr
    got = sphtroch.scene(scene)
    assert [t["name"] for t in got["trains"]] == ["fig5f", "cusped"]
    for train, written in zip(got["trains"], scene["trains"]):
        assert list(train["outputs"]) == list(written["effects"])
        for effect, path in written["effects"].items():
            assert untimed(train["outputs"][effect]) == untimed((tmp_path / path).read_text()), (train["name"], effect)
        assert train["uncertified"] == ""
        assert [e["effect"] for e in train["explanation"]["effects"]] == list(written["effects"])
    again = sphtroch.scene(json.dumps(scene))["trains"][0]["outputs"]
    assert {k: untimed(v) for k, v in again.items()} == {k: untimed(v) for k, v in got["trains"][0]["outputs"].items()}
    with pytest.raises(sphtroch.InvalidInput, match=r"trains\[0\]\.a2"):
        sphtroch.scene({"trains": [{"name": "x", "a2": "7", "a3": 1, "n": "2", "effects": {"trace": "x.csv"}}]})


def test_atlas_svg_and_summary_are_the_tools(tmp_path):
    a = sphtroch.atlas("5/2", grid=24, a2=(0.2, 3.0), threads=2, svg=True)
    svg = tmp_path / "map.svg"
    done = subprocess.run([EXE, "atlas", "--n", "5/2", "--grid", "24", "--a2", "0.2:3", "--threads", "2", "--svg", str(svg)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert a["svg"] == svg.read_text()
    # The summary: the same lines but the wall time.
    strip = lambda s: [l for l in s.splitlines() if not l.startswith("time:")]  # noqa: E731
    assert strip(a["summary"]) == strip(done.stdout)
    assert a["uncertified"] == ""
    assert "svg" not in sphtroch.atlas(2, grid=4)


def test_synth_text_reports_are_the_text_the_tool_prints(tmp_path):
    tr = sphtroch.GearTrain(1.0, 2.0, "1/2", phase=0.3)
    _, P = tr.trace(samples=40)
    three = P[[2, 11, 29]]
    points = tmp_path / "pts.csv"
    points.write_text("x,y,z\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in three))
    text = sphtroch.synth_points_text(three, teeth="12:24")
    assert text.startswith("n = 1/2 (teeth 12:24): ") and "plot it: sphtroch plot" in text
    assert untimed(text) == untimed(run_cli("synth", "points", "--input", str(points), "--teeth", "12:24"))
    tr = sphtroch.GearTrain(1.1, 0.9, 2, phase=0.4)
    _, path = tr.trace(samples=300)
    path_file = tmp_path / "path.csv"
    path_file.write_text("x,y,z\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in path))
    text = sphtroch.fit_text(path, n=2, nodes=2, candidates=3)
    assert text.startswith("fit: ")
    assert untimed(text) == untimed(run_cli("synth", "fit", "--input", str(path_file), "--n", "2", "--nodes", "2",
                                            "--candidates", "3"))
