"""The stub against what the runtime accepts (issue: NumPy scalars were rejected by mypy): `mypy
--strict` (Debian's python3-mypy) passes on typed_example.py, which also runs, and reports exactly
the marked lines of typed_wrong.py."""
import os
import pathlib
import re
import subprocess
import sys

import pytest

HERE = pathlib.Path(__file__).parent
STUB_DIR = pathlib.Path(os.environ["SPHTROCH_SOURCE_DIR"]) / "python"


def mypy(script, cache):
    env = dict(os.environ, MYPYPATH=str(STUB_DIR))
    return subprocess.run([sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(cache), "--no-error-summary",
                           str(script)], capture_output=True, text=True, env=env)


def test_typed_example_passes_mypy_strict_and_runs(tmp_path):
    r = mypy(HERE / "typed_example.py", tmp_path / "cache")
    assert r.returncode == 0, r.stdout + r.stderr
    run = subprocess.run([sys.executable, str(HERE / "typed_example.py")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr


def test_wrong_script_fails_on_exactly_the_marked_lines(tmp_path):
    script = HERE / "typed_wrong.py"
    r = mypy(script, tmp_path / "cache")
    assert r.returncode == 1, r.stdout + r.stderr
    reported = {int(m.group(1)) for m in re.finditer(r"typed_wrong\.py:(\d+): error", r.stdout)}
    marked = {k for k, line in enumerate(script.read_text().splitlines(), 1) if "# error:" in line}
    assert reported == marked, r.stdout
