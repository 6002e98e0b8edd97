"""Shared helpers of the Python tests: the tool (SPHTROCH_EXE), the source tree, the paper's cases.

ctest sets PYTHONPATH to <build>/python (the module), SPHTROCH_EXE to the tool and
SPHTROCH_SOURCE_DIR to the source tree (python/CMakeLists.txt).
"""
import csv
import json
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("SPHTROCH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXE = os.environ.get("SPHTROCH_EXE", "")


def run_cli(*args, stdin=None):
    """Runs the tool; returns its stdout (text). Fails the test on a non-zero exit."""
    if not EXE:
        pytest.fail("SPHTROCH_EXE is not set (run through ctest)")
    done = subprocess.run([EXE, *args], input=stdin, capture_output=True, check=False)
    assert done.returncode == 0, done.stderr.decode()
    return done.stdout.decode()


def cli_json(*args):
    return json.loads(run_cli(*args))


def paper_cases():
    """data/reference/paper_cases.csv: the report's stated cases (expected nodes and cusps)."""
    path = os.path.join(SOURCE_DIR, "data", "reference", "paper_cases.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) >= 10
    return rows


def cli_angle(symbolic):
    """The CSV's symbolic a3 in the tool's spelling ("a_p" is written "ap")."""
    return symbolic.replace("a_p", "ap")
