#!/usr/bin/env bash
# sphtroch developer set-up, for a fresh Debian 12 machine (as root, or with sudo).
#
#   bash scripts/dev.sh run    # install what the tool needs, build only the tool (Release, build/), trace report Fig. 3
#   bash scripts/dev.sh test   # also what the tests need, build everything, run the whole suite through ctest
#
# Both are re-runnable and incremental: only missing Debian packages are installed (apt-get
# update runs only when something is missing), the build directory is reused and rebuilt
# incrementally. Environment: BUILD_DIR (default build), JOBS (default: all cores).
set -euo pipefail

usage() {
  echo "usage: bash scripts/dev.sh run|test" >&2
  exit 2
}
[[ $# -eq 1 ]] || usage
mode=$1
[[ $mode == run || $mode == test ]] || usage

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build_dir=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

# What the library and the tool need (libhealpix-cxx-dev and pkg-config: a clinostat's dwell map,
# `sphtroch clinostat --coverage`; liburdfdom-dev: rotation chains read from and written as URDF
# robot descriptions, `sphtroch chain --urdf`); the tests add python3-numpy (numpy.load/numpy.save round
# trips of the .npy files), libbenchmark-dev (bench/, built by bench/run) and the Python module's
# build and tests (pybind11-dev, python3-dev, python3-pytest; python3-matplotlib for the example),
# and jq (a console example of docs/cli.md pipes classify --json through it; ctest docs:console_examples),
# and for the explorer (explorer/, ctest label browser) emscripten, chromium and Node.js with npm
# (Node >= 20 for playwright-core; the npm packages come from explorer/test/package-lock.json), and
# python3-ezdxf (an independent reader of the DXF files trace writes; ctest python:cad_export), and
# python3-mypy (mypy --strict on a typed example against the stub; ctest python:typing), and
# python3-venv, python3-pip, python3-setuptools (pip install of the package into a venv; python:pip_install),
# python3-nbclient, python3-nbformat, python3-ipykernel (the example notebook runs headless; python:notebook),
# python3-tqdm (python:progress drives a tqdm bar), python3-healpy (an independent HEALPix pixel
# function for the clinostat's dwell maps; python:clinostat),
# help2man (the man page, written at build time) and man-db (`man sphtroch` after an install; cli:man_page).
# OpenCASCADE (trace -o FILE.step; optional for the library, asked for by `test`): Debian's CMake
# config of its DataExchange part needs the ocaf and visualization packages and libtbb-dev too.
packages=(build-essential cmake libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libmpfrc++-dev
          libcli11-dev nlohmann-json3-dev libhealpix-cxx-dev liburdfdom-dev pkg-config)
step_packages=(libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
               libocct-data-exchange-dev libocct-ocaf-dev libocct-visualization-dev libtbb-dev)
# librsvg2-dev (+ pkg-config): plot -o FILE.png renders the SVG (optional, asked for by `test`).
png_packages=(librsvg2-dev pkg-config)
if [[ $mode == test ]]; then
  packages+=(libbenchmark-dev python3-numpy pybind11-dev python3-dev python3-pytest python3-matplotlib jq
             emscripten chromium nodejs python3-ezdxf python3-mypy python3-venv python3-pip python3-setuptools
             python3-nbclient python3-nbformat python3-ipykernel python3-tqdm python3-healpy help2man man-db "${step_packages[@]}" "${png_packages[@]}")
fi

install_missing_packages() {
  local missing=() pkg
  for pkg in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$pkg")
    fi
  done
  if [[ ${#missing[@]} -eq 0 ]]; then
    echo "dev.sh: all ${#packages[@]} Debian packages present"
    return
  fi
  echo "dev.sh: installing missing Debian packages: ${missing[*]}"
  local sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    if ! command -v sudo >/dev/null; then
      echo "dev.sh: not root and sudo not found; install as root: apt-get install -y ${missing[*]}" >&2
      exit 1
    fi
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
}

configure_and_build() {
  # Configuring an existing build directory again is cheap and picks up new files. `run` builds
  # only the tool (a newcomer's first command stays short); `test` builds everything.
  # `test` builds the Python module for Debian's python3 (the interpreter the python3-* packages
  # serve), and asks for it explicitly: a module that cannot be built fails here, never skipped.
  local python=()
  if [[ $mode == test ]]; then
    python=(-DSPHTROCH_BUILD_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 -DSPHTROCH_BUILD_EXPLORER=ON
            -DSPHTROCH_WITH_STEP=ON -DSPHTROCH_WITH_PNG=ON)
  fi
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${python[@]}"
  if [[ $mode == run ]]; then
    cmake --build "$build_dir" -j "$jobs" --target sphtroch_cli
  else
    cmake --build "$build_dir" -j "$jobs"
  fi
}

install_missing_packages
# The browser tests' npm packages, exactly as locked (npm ci), unless already installed from this lockfile.
install_npm_packages() {
  local dir=explorer/test
  if ! command -v npm >/dev/null; then
    echo "dev.sh: npm not found (Debian's nodejs >= 20 brings it; NodeSource's package does)" >&2
    exit 1
  fi
  if [[ ! -f $dir/node_modules/.package-lock.json || $dir/package-lock.json -nt $dir/node_modules/.package-lock.json ]]; then
    npm ci --prefix "$dir" --no-audit --no-fund
  fi
}

if [[ $mode == test ]]; then
  install_npm_packages
  # The cluster test (ctest label `cluster`) runs a real one-node Slurm: slurm-wlm and munge.
  bash tests/cluster/install_slurm.sh
fi
configure_and_build

case $mode in
  run)
    # Report Fig. 3: a2 = a3 = pi/2, n = 1 (a spherical limacon with its node at (0, 1, 0), Eq. 25).
    "$build_dir/bin/sphtroch" trace --a2 pi/2 --a3 pi/2 --n 1 --samples 16
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure -j3  # 3 on 2 cores: several tests wait (FIFO timeouts, Slurm, cmake runs) rather than compute
    ;;
esac
