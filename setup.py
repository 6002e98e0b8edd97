"""The Python package for pip (pyproject.toml): `pip install --no-build-isolation .`.

The extension is built by the project's own CMake (python/CMakeLists.txt: the same sources,
flags and generated docstrings as `cmake --build build`), configured for the running interpreter
with only the Python module on, and copied into the wheel next to the package's pure-Python files
(python/sphtroch: __init__.py, the stub __init__.pyi, py.typed). The version is the CMake project's.
An existing CMake build for the same interpreter (build/, or SPHTROCH_BUILD_DIR) is reused; else
setuptools' own build files go to build-pip/. An interpreter without wheel or NumPy (not Debian's)
is stopped at once with one line naming the one to use.
"""
import importlib.util
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent


def check_interpreter():
    """Stops at once, in one line, when the running Python lacks what the build needs: an
    interpreter that is not Debian's (pyenv, conda) has no wheel and no NumPy, and its venv's
    --system-site-packages are its own, not Debian's."""
    missing = [m for m in ("wheel", "numpy") if importlib.util.find_spec(m) is None]
    if missing:
        sys.stderr.write(f"sphtroch: this Python ({sys.executable}) has no {' and no '.join(missing)}, which the build "
                         "needs: make the venv with Debian's interpreter, /usr/bin/python3 -m venv --system-site-packages "
                         "venv && venv/bin/pip install --no-build-isolation . (docs/python.md)\n")
        sys.exit(1)


check_interpreter()

from setuptools import Extension, setup  # noqa: E402 (after the check: its failure is the one line above)
from setuptools.command.build_ext import build_ext  # noqa: E402


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(sphtroch VERSION ([0-9.]+)", text).group(1)


def existing_build():
    """The project's CMake build to reuse (SPHTROCH_BUILD_DIR, default build/ of the README), when it
    has the Python module on for this same interpreter (its Python3_EXECUTABLE and sys.executable
    resolve to one file): `cmake --build` then brings the module up to date, compiling only what
    changed, instead of a build from scratch in build-pip/ (minutes)."""
    build = pathlib.Path(os.environ.get("SPHTROCH_BUILD_DIR") or ROOT / "build")
    cache = build / "CMakeCache.txt"
    if not cache.is_file():
        return None
    text = cache.read_text(errors="replace")
    python = re.search(r"^Python3_EXECUTABLE:[A-Z]+=(.*)$", text, re.M)
    on = re.search(r"^SPHTROCH_BUILD_PYTHON:BOOL=ON$", text, re.M)
    same = python and os.path.realpath(python.group(1)) == os.path.realpath(sys.executable)
    return build if on and same else None


class CMakeBuild(build_ext):
    """Builds the CMake targets sphtroch_python, sphtroch_python_healpix and sphtroch_python_urdf (in an existing build for
    this interpreter, else in build-pip/), then copies the modules they made."""

    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        work = existing_build()
        if work is None:
            work = pathlib.Path(self.build_temp).resolve() / "cmake"
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(work), "-DCMAKE_BUILD_TYPE=Release",
                            f"-DPython3_EXECUTABLE={sys.executable}", "-DSPHTROCH_BUILD_PYTHON=ON",
                            "-DSPHTROCH_BUILD_CLI=OFF", "-DSPHTROCH_BUILD_TESTS=OFF", "-DSPHTROCH_BUILD_EXPLORER=OFF",
                            "-DSPHTROCH_BUILD_BENCH=OFF", "-DSPHTROCH_INSTALL=OFF"], check=True)
        cmake_target = {"sphtroch._sphtroch": "sphtroch_python", "sphtroch._sphtroch_healpix": "sphtroch_python_healpix",
                        "sphtroch._sphtroch_urdf": "sphtroch_python_urdf"}[ext.name]
        subprocess.run(["cmake", "--build", str(work), "--target", cmake_target, "-j", jobs], check=True)
        built = work / "python" / "sphtroch" / target.name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    version=project_version(),
    packages=["sphtroch"],
    package_dir={"sphtroch": "python/sphtroch"},
    package_data={"sphtroch": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("sphtroch._sphtroch", sources=[]), Extension("sphtroch._sphtroch_healpix", sources=[]),
                 Extension("sphtroch._sphtroch_urdf", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
