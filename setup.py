"""The Python package for pip (pyproject.toml): `pip install --no-build-isolation .`.

The extension is built by the project's own CMake (python/CMakeLists.txt: the same sources,
flags and generated docstrings as `cmake --build build`), configured for the running interpreter
with only the Python module on, and copied into the wheel next to the package's pure-Python files
(python/sphtroch: __init__.py, the stub __init__.pyi, py.typed). The version is the CMake project's.
setuptools' own build files go to build-pip/ (not the CMake build/ of the README).
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(sphtroch VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    """Configures and builds the CMake target sphtroch_python, then copies the module it made."""

    def build_extension(self, ext):
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        work = pathlib.Path(self.build_temp).resolve() / "cmake"
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(work), "-DCMAKE_BUILD_TYPE=Release",
                        f"-DPython3_EXECUTABLE={sys.executable}", "-DSPHTROCH_BUILD_PYTHON=ON",
                        "-DSPHTROCH_BUILD_CLI=OFF", "-DSPHTROCH_BUILD_TESTS=OFF", "-DSPHTROCH_BUILD_EXPLORER=OFF",
                        "-DSPHTROCH_BUILD_BENCH=OFF", "-DSPHTROCH_INSTALL=OFF"], check=True)
        subprocess.run(["cmake", "--build", str(work), "--target", "sphtroch_python", "-j", jobs], check=True)
        built = work / "python" / "sphtroch" / target.name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


setup(
    version=project_version(),
    packages=["sphtroch"],
    package_dir={"sphtroch": "python/sphtroch"},
    package_data={"sphtroch": ["__init__.pyi", "py.typed"]},
    ext_modules=[Extension("sphtroch._sphtroch", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
