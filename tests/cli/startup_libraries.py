#!/usr/bin/env python3
"""Fails (exit 1) when a call of the tool loads a shared library outside the allow-list: the C and
C++ runtime (libc, libm, libstdc++, libgcc_s, the loader, the vDSO) and GMP/MPFR (the exact
predicates), plus OpenMP's libgomp. Checked on `--version`, `trace`, `classify`, `chain trace`,
`clinostat` without coverage, `trace -o p.dxf` and `atlas --svg`. Every other library (OpenCASCADE,
librsvg, HEALPix with cfitsio and its network stack, urdfdom with its XML parser) lies in a plugin
opened only by the option that needs it: writing STEP or PNG, `clinostat --coverage`, `chain
--urdf` load theirs (the detection is checked on them), and a missing plugin is one line, exit 2,
no file. With a Python interpreter and the module's directory as extra arguments, `import
sphtroch` (and a GearTrain's classify) may add no library outside the allow-list to those Python
and NumPy load themselves.

  python3 tests/cli/startup_libraries.py SPHTROCH_EXE WORK_DIR [PYTHON MODULE_DIR]

Every shared library a process loads (at start and through dlopen) is read from the dynamic
loader's own log (LD_DEBUG=libs, LD_DEBUG_OUTPUT: glibc's ld.so writes one file per process). The
detection is itself checked: `--version` must show libc, and in a build with a plugin (`sphtroch
--version` says `step yes`, `png yes`, `urdf yes`, `healpix yes`) its option must show its libraries.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

EXE, WORK = os.path.abspath(sys.argv[1]), sys.argv[2]
PYTHON, MODULE_DIR = (sys.argv[3], sys.argv[4]) if len(sys.argv) > 4 else (None, None)
# The allow-list: a library's file name (after its directory) must match.
ALLOWED = re.compile(r"^(libc\.so[.0-9]*|libm\.so[.0-9]*|libstdc\+\+\.so[.0-9]*|libgcc_s\.so[.0-9]*|ld-linux[-x86_64]*\.so[.0-9]*"
                     r"|linux-vdso\.so[.0-9]*|libgmp\.so[.0-9]*|libmpfr\.so[.0-9]*|libgomp\.so[.0-9]*)$")
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


def outside_allow_list(libraries):
    return sorted(lib for lib in libraries if not ALLOWED.match(os.path.basename(lib)))


def no_heavy_libraries(args, cwd):
    done, libraries = run_logged(EXE, args, cwd)
    shown = "sphtroch " + " ".join(args)
    check(done.returncode == 0, f"{shown}: exit {done.returncode}: {done.stderr.strip()}")
    check(any("/libc.so" in lib for lib in libraries), f"{shown}: the loader's log names no libc (LD_DEBUG not read)")
    extra = outside_allow_list(libraries)
    check(not extra, f"{shown} loads {len(extra)} libraries outside the allow-list: {', '.join(extra)}")
    return done


def python_import_adds_nothing(cwd):
    """import sphtroch (and one classify) beside what Python and NumPy load by themselves."""
    env = dict(os.environ, PYTHONPATH=MODULE_DIR, PYTHONDONTWRITEBYTECODE="1")

    def loaded(code):
        with tempfile.TemporaryDirectory(dir=WORK) as logs:
            run_env = dict(env, LD_DEBUG="libs", LD_DEBUG_OUTPUT=os.path.join(logs, "ld"))
            done = subprocess.run([PYTHON, "-c", code], cwd=cwd, env=run_env, capture_output=True, text=True, timeout=120)
            text = "".join(open(f, errors="replace").read() for f in glob.glob(os.path.join(logs, "ld*")))
        check(done.returncode == 0, f"python -c {code!r}: exit {done.returncode}: {done.stderr.strip()[-300:]}")
        return set(re.findall(r"calling init: (\S+)", text))

    base = loaded("import numpy")
    with_module = loaded("import numpy, sphtroch; sphtroch.GearTrain(a2=1.0, a3=2.0, n=2).classify()")
    added = {lib for lib in with_module - base if "_sphtroch." not in os.path.basename(lib)}
    extra = outside_allow_list(added)
    check(any("_sphtroch." in os.path.basename(lib) for lib in with_module), "import sphtroch: the module itself is not in the loader's log")
    check(not extra, f"import sphtroch loads {len(extra)} libraries outside the allow-list: {', '.join(extra)}")


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
    component = plugin.removeprefix("sphtroch_").removesuffix(".so")
    check(f"{component} missing" in alone_version,
          f"sphtroch --version (no plugin) does not say '{component} missing': {alone_version!r}")


os.makedirs(WORK, exist_ok=True)
with tempfile.TemporaryDirectory(dir=WORK) as d:
    version = no_heavy_libraries(["--version"], d).stdout
    check("missing" not in version, f"--version of the built tool names a missing plugin: {version.strip()}")
    no_heavy_libraries(["trace", *TRAIN, "--samples", "10"], d)
    no_heavy_libraries(["trace", *TRAIN, "--samples", "10", "-o", "p.dxf"], d)
    no_heavy_libraries(["atlas", "--n", "2", "--grid", "4", "--svg", "a.svg"], d)
    no_heavy_libraries(["chain", "trace", "--twists", "1,2,0.5", "--rates", "1,2,-1", "--samples", "10"], d)
    no_heavy_libraries(["clinostat", "--outer", "1.33", "--inner", "2", "--window", "60"], d)
    if "analysis yes" in version:
        no_heavy_libraries(["classify", *TRAIN], d)
    if "step yes" in version:
        format_loads(["trace", *TRAIN, "-o", "p.step"], d, "p.step", r"/libTKSTEP[^/]*$")
        missing_plugin(["trace", *TRAIN, "-o", "q.step"], d, "q.step", "sphtroch_step.so")
    if "png yes" in version:
        format_loads(["atlas", "--n", "2", "--grid", "4", "--svg", "a.png"], d, "a.png", r"/librsvg[^/]*$")
        missing_plugin(["atlas", "--n", "2", "--grid", "4", "--svg", "b.png"], d, "b.png", "sphtroch_png.so")
    if "healpix yes" in version:
        format_loads(["clinostat", "--outer", "1.33", "--inner", "2", "--coverage", "60", "--plot", "c.svg"], d, "c.svg",
                     r"/libhealpix_cxx[^/]*$")
        missing_plugin(["clinostat", "--outer", "1.33", "--inner", "2", "--coverage", "60", "--plot", "e.svg"], d, "e.svg",
                       "sphtroch_healpix.so")
    if "urdf yes" in version:
        with open(os.path.join(d, "w.urdf"), "w") as f:
            f.write(subprocess.run([EXE, "chain", "export", "--twists", "1,2", "--rates", "1,3", "--urdf", "-"],
                                   capture_output=True, text=True, timeout=60).stdout)
        format_loads(["chain", "trace", "--urdf", "w.urdf", "--from", "base_link", "--to", "tool", "--samples", "10", "-o", "u.csv"],
                     d, "u.csv", r"/liburdfdom_model[^/]*$")
        missing_plugin(["chain", "trace", "--urdf", "w.urdf", "--from", "base_link", "--to", "tool", "--samples", "10", "-o", "v.csv"],
                       d, "v.csv", "sphtroch_urdf.so")
    if PYTHON:
        python_import_adds_nothing(d)
for p in problems:
    print("startup_libraries:", p)
print(f"startup_libraries: {len(problems)} problems ({version.strip()})")
sys.exit(1 if problems else 0)
