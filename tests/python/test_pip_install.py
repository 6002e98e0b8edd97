"""`pip install --no-build-isolation .` into a fresh venv (--system-site-packages: NumPy from Debian),
offline, from a copy of the source tree (so the test writes nothing into the tree); then, from
outside the tree, the installed package imports, computes, and shows its documentation; the
notebook example runs from the venv as a user runs it (its kernel registered from the venv)."""
import os
import pathlib
import shutil
import subprocess
import sys

SOURCE = pathlib.Path(os.environ["SPHTROCH_SOURCE_DIR"])
SKIP = shutil.ignore_patterns("build", "build-*", ".git", "node_modules", "*.egg-info", "__pycache__")


def run(args, cwd, env=None):
    r = subprocess.run(args, cwd=cwd, capture_output=True, text=True, env=env)
    assert r.returncode == 0, f"{args}:\n{r.stdout[-3000:]}\n{r.stderr[-3000:]}"
    return r.stdout


def test_pip_install_into_a_fresh_venv_and_import_from_outside(tmp_path):
    tree = tmp_path / "src"
    shutil.copytree(SOURCE, tree, ignore=SKIP)
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], tmp_path)
    python = str(venv / "bin" / "python")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env["CMAKE_BUILD_PARALLEL_LEVEL"] = "2"
    run([python, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir", str(tree)], tmp_path, env)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    check = (
        "import pathlib, pydoc, sphtroch\n"
        "assert pathlib.Path(sphtroch.__file__).is_relative_to(pathlib.Path(r'%s')), sphtroch.__file__\n"
        "t = sphtroch.GearTrain('pi/2', 'pi/2', 1)\n"
        "c = t.classify()\n"
        "assert c['counts']['nodes'] == 1 and c['certified'], c\n"  # Eq. 24: one node on a2 = a3 = pi/2, n = 1
        "doc = pydoc.render_doc(sphtroch.GearTrain.trace)\n"
        "assert 'The trajectory P(theta2) (Eq. 4)' in doc, doc\n"
        "stub = pathlib.Path(sphtroch.__file__).with_name('__init__.pyi')\n"
        "assert stub.is_file() and stub.with_name('py.typed').is_file()\n"
        "print(sphtroch.__version__)\n" % venv
    )
    out = run([python, "-c", check], elsewhere, env)
    cmake_version = (SOURCE / "CMakeLists.txt").read_text().split("project(sphtroch VERSION ")[1].split()[0]
    assert out.strip() == cmake_version


def test_an_interpreter_without_wheel_or_numpy_stops_at_once_with_one_line(tmp_path):
    """A venv without Debian's packages (as one made from a pyenv or conda python3 is): the build
    stops before any compiling, with one line naming the interpreter to use."""
    tree = tmp_path / "src"
    shutil.copytree(SOURCE, tree, ignore=SKIP)
    venv = tmp_path / "bare"
    run([sys.executable, "-m", "venv", str(venv)], tmp_path)  # no --system-site-packages: no wheel, no NumPy
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    r = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-build-isolation", "--no-index",
                        "--no-cache-dir", str(tree)], cwd=tmp_path, capture_output=True, text=True, env=env)
    assert r.returncode != 0
    lines = [l.strip() for l in (r.stdout + r.stderr).splitlines() if "sphtroch: this Python" in l]
    assert len(lines) == 1, r.stdout + r.stderr
    assert str(venv / "bin" / "python") in lines[0] and "/usr/bin/python3 -m venv --system-site-packages" in lines[0]
    assert not any(tree.rglob("CMakeCache.txt")), "the build was configured before the refusal"


def test_an_existing_build_for_this_interpreter_is_reused(tmp_path):
    """SPHTROCH_BUILD_DIR (default: the tree's build/) configured with this interpreter and the
    module on: pip brings that build's module up to date and copies it; no build of its own."""
    build = os.environ.get("SPHTROCH_BUILD_DIR_UNDER_TEST")
    assert build, "ctest passes the project's build directory"
    tree = tmp_path / "src"
    shutil.copytree(SOURCE, tree, ignore=SKIP)
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)], tmp_path)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env["SPHTROCH_BUILD_DIR"] = build
    run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-cache-dir",
         str(tree)], tmp_path, env)
    assert not any(tree.rglob("CMakeCache.txt")), "a build of its own was configured"
    out = run([str(venv / "bin" / "python"), "-c",
               "import sphtroch; print(sphtroch.GearTrain('pi/2', 'pi/2', 1).classify()['counts']['nodes'])"],
              tmp_path, env)
    assert out.strip() == "1"  # Eq. 24: one node on a2 = a3 = pi/2, n = 1
    run_the_notebook_from_the_venv(venv, tmp_path, env)


def run_the_notebook_from_the_venv(venv, tmp_path, env):
    """As docs/python.md says: the venv's interpreter registered as the kernel "sphtroch" in the
    user's Jupyter data directory (ipykernel install --user --name sphtroch; here JUPYTER_DATA_DIR
    is a temporary directory, so nothing is written to the real home), then
    examples/design_study.ipynb run through that kernel by Debian's /usr/bin/python3 (as Debian's
    Jupyter runs it) with no PYTHONPATH, so `import sphtroch` there can only come from the venv."""
    python = str(venv / "bin" / "python")
    jupyter_env = dict(env, JUPYTER_DATA_DIR=str(tmp_path / "jupyter-data"))
    run([python, "-m", "ipykernel", "install", "--user", "--name", "sphtroch"], tmp_path, jupyter_env)
    notebook = SOURCE / "examples" / "design_study.ipynb"
    script = (
        "import sys, nbformat, jupyter_client.kernelspec as ks\n"
        "from nbclient import NotebookClient\n"
        "spec = ks.KernelSpecManager().get_kernel_spec('sphtroch')\n"
        "assert spec.argv[0] == r'%s', spec.argv\n"
        "nb = nbformat.read(r'%s', as_version=4)\n"
        "NotebookClient(nb, timeout=300, kernel_name='sphtroch', resources={'metadata': {'path': r'%s'}}).execute()\n"
        "errors = [o for c in nb.cells for o in c.get('outputs', []) if o.get('output_type') == 'error']\n"
        "assert not errors, errors\n"
        "print(sum(1 for c in nb.cells if c.cell_type == 'code'))\n" % (python, notebook, tmp_path)
    )
    out = run(["/usr/bin/python3", "-c", script], tmp_path, jupyter_env)
    assert int(out.strip()) > 0
