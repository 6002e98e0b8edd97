#!/usr/bin/env python3
"""Fails (exit 1) when a call of the tool that writes neither STEP nor PNG loads OpenCASCADE,
librsvg, cairo or an output plugin; checks that STEP and PNG still load them, and that a missing
plugin is one line, exit 2, no file.

  python3 tests/cli/startup_libraries.py SPHTROCH_EXE WORK_DIR

Every shared library a process loads (at start and through dlopen) is read from the dynamic
loader's own log (LD_DEBUG=libs, LD_DEBUG_OUTPUT: glibc's ld.so writes one file per process). The
detection is itself checked: `--version` must show libc, and in a build with STEP or PNG
(`sphtroch --version` says `step yes`, `png yes`) writing that format must show its libraries.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

EXE, WORK = os.path.abspath(sys.argv[1]), sys.argv[2]
FORBIDDEN = re.compile(r"/(libTK[^/]*|librsvg[^/]*|libcairo[^/]*|sphtroch_step\.so|sphtroch_png\.so)$")
TRAIN = ["--a2", "0.7", "--a3", "2.5", "--n", "13/5"]
problems = []


def run_logged(exe, args, cwd):
    """(completed process, the set of library paths the loader opened for it)."""
    with tempfile.TemporaryDirectory(dir=WORK) as logs:
        env = dict(os.environ, LD_DEBUG="libs", LD_DEBUG_OUTPUT=os.path.join(logs, "ld"))
        done = subprocess.run([exe, *args], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)
        text = "".join(open(f, errors="replace").read() for f in glob.glob(os.path.join(logs, "ld*")))
    return done, set(re.findall(r"calling init: (\S+)", text))


def check(condition, message):
    if not condition:
        problems.append(message)


def no_heavy_libraries(args, cwd):
    done, libraries = run_logged(EXE, args, cwd)
    shown = "sphtroch " + " ".join(args)
    check(done.returncode == 0, f"{shown}: exit {done.returncode}: {done.stderr.strip()}")
    check(any("/libc.so" in lib for lib in libraries), f"{shown}: the loader's log names no libc (LD_DEBUG not read)")
    heavy = sorted(lib for lib in libraries if FORBIDDEN.search(lib))
    check(not heavy, f"{shown} loads {len(heavy)} libraries it does not use: {', '.join(heavy)}")
    return done


def format_loads(args, cwd, output, pattern):
    """Writing STEP / PNG works and loads its libraries (the detection sees them)."""
    done, libraries = run_logged(EXE, args, cwd)
    shown = "sphtroch " + " ".join(args)
    check(done.returncode == 0 and os.path.getsize(os.path.join(cwd, output)) > 0,
          f"{shown}: exit {done.returncode}: {done.stderr.strip()}")
    check(any(re.search(pattern, lib) for lib in libraries), f"{shown}: no library matching {pattern} was loaded")


def missing_plugin(args, cwd, output, plugin):
    """The tool alone, without its plugins beside it: one line naming the plugin, exit 2, no file."""
    alone = os.path.join(cwd, "alone", "bin")
    os.makedirs(alone, exist_ok=True)
    shutil.copy2(EXE, os.path.join(alone, "sphtroch"))
    done = subprocess.run([os.path.join(alone, "sphtroch"), *args], cwd=cwd, capture_output=True, text=True, timeout=120)
    shown = "sphtroch " + " ".join(args) + " (no plugin)"
    check(done.returncode == 2, f"{shown}: exit {done.returncode}, not 2")
    check(done.stderr.count("\n") == 1 and plugin in done.stderr and "is not there" in done.stderr,
          f"{shown}: stderr is not one line naming {plugin}: {done.stderr!r}")
    check(not os.path.exists(os.path.join(cwd, output)), f"{shown}: {output} was written")
    alone_version = subprocess.run([os.path.join(alone, "sphtroch"), "--version"], capture_output=True, text=True,
                                   timeout=60).stdout
    component = "step" if plugin == "sphtroch_step.so" else "png"
    check(f"{component} missing" in alone_version,
          f"sphtroch --version (no plugin) does not say '{component} missing': {alone_version!r}")


os.makedirs(WORK, exist_ok=True)
with tempfile.TemporaryDirectory(dir=WORK) as d:
    version = no_heavy_libraries(["--version"], d).stdout
    check("missing" not in version, f"--version of the built tool names a missing plugin: {version.strip()}")
    no_heavy_libraries(["trace", *TRAIN, "--samples", "10"], d)
    no_heavy_libraries(["trace", *TRAIN, "--samples", "10", "-o", "p.dxf"], d)
    no_heavy_libraries(["atlas", "--n", "2", "--grid", "4", "--svg", "a.svg"], d)
    if "step yes" in version:
        format_loads(["trace", *TRAIN, "-o", "p.step"], d, "p.step", r"/libTKSTEP[^/]*$")
        missing_plugin(["trace", *TRAIN, "-o", "q.step"], d, "q.step", "sphtroch_step.so")
    if "png yes" in version:
        format_loads(["atlas", "--n", "2", "--grid", "4", "--svg", "a.png"], d, "a.png", r"/librsvg[^/]*$")
        missing_plugin(["atlas", "--n", "2", "--grid", "4", "--svg", "b.png"], d, "b.png", "sphtroch_png.so")
for p in problems:
    print("startup_libraries:", p)
print(f"startup_libraries: {len(problems)} problems ({version.strip()})")
sys.exit(1 if problems else 0)
