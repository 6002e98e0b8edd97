#!/usr/bin/env python3
"""Draw docs/clinostat.md's convention figure: data/figures/clinostat_convention.svg.

  /usr/bin/python3 scripts/clinostat_figure.py [build/bin/sphtroch]

Left: the lab frame (Z up, gravity down), the outer axis u at tilt psi from the vertical, the inner
axis v at the frame angle beta from u (drawn for psi = 70 deg, beta = 60 deg so that neither is a
special case), and w. Right: the gravity path in the sample's frame for 1.33 / 2.00 rpm over its
first 3 minutes and over its whole 100-minute period, from `sphtroch clinostat --trace` (so the
figure shows what the tool computes). Needs matplotlib (python3-matplotlib).
"""
import io
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "sphtroch"  # stable ids: the file changes only when the picture does
matplotlib.rcParams["svg.fonttype"] = "none"
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def arrow(ax, v, colour, label, offset=1.12):
    ax.quiver(0, 0, 0, *v, color=colour, arrow_length_ratio=0.08, linewidth=2)
    ax.text(*(offset * np.asarray(v)), label, color=colour, fontsize=12)


def trace(exe, duration, samples):
    out = subprocess.run([exe, "clinostat", "--outer", "1.33", "--inner", "2", "--trace", "--duration", str(duration),
                          "--samples", str(samples)], check=True, capture_output=True, text=True).stdout
    return np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1)


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else "build/bin/sphtroch"
    psi, beta = np.radians(70), np.radians(60)
    u = np.array([np.sin(psi), 0, np.cos(psi)])
    w = np.array([-np.cos(psi), 0, np.sin(psi)])
    v = np.cos(beta) * u + np.sin(beta) * w
    fig = plt.figure(figsize=(11, 5.2))
    left = fig.add_subplot(1, 2, 1, projection="3d")
    for axis, name in ((np.eye(3)[0], "X"), (np.eye(3)[1], "Y"), (np.eye(3)[2], "Z")):
        arrow(left, 0.9 * axis, "0.55", name)
    arrow(left, u, "tab:blue", "u (outer)")
    arrow(left, v, "tab:green", "v (inner)")
    arrow(left, 0.7 * w, "tab:cyan", "w")
    arrow(left, [0, 0, -1], "tab:red", "gravity", 1.08)
    arc = np.array([np.sin(a) * np.array([1, 0, 0]) + np.cos(a) * np.array([0, 0, 1]) for a in np.linspace(0, psi, 30)]) * 0.35
    left.plot(*arc.T, color="tab:blue")
    left.text(*(0.42 * np.array([np.sin(psi / 2), 0, np.cos(psi / 2)])), "tilt ψ", color="tab:blue")
    arc = np.array([np.cos(a) * u + np.sin(a) * w for a in np.linspace(0, beta, 30)]) * 0.5
    left.plot(*arc.T, color="tab:green")
    left.text(*(0.58 * (np.cos(beta / 2) * u + np.sin(beta / 2) * w)), "frame angle β", color="tab:green")
    left.set_title("lab frame: u = (sin ψ, 0, cos ψ), v = cos β u + sin β w")
    right = fig.add_subplot(1, 2, 2, projection="3d")
    whole = trace(exe, 6000, 6001)
    first = trace(exe, 180, 721)
    right.plot(*whole[:, 1:].T, color="0.75", linewidth=0.6, label="one period (100 min)")
    right.plot(*first[:, 1:].T, color="tab:red", linewidth=1.2, label="first 3 min")
    right.scatter(*first[0, 1:], color="black", s=20, label="t = 0: (0, 0, −1)")
    right.set_title("gravity in the sample frame, 1.33 / 2.00 rpm (ψ = β = 90°)")
    right.legend(loc="lower left", fontsize=9)
    for ax in (left, right):
        ax.set_box_aspect((1, 1, 1))
        ax.set_xlim(-1, 1)
        ax.set_ylim(-1, 1)
        ax.set_zlim(-1, 1)
        ax.view_init(elev=18, azim=-60)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_zticks([])
    fig.tight_layout()
    fig.savefig("data/figures/clinostat_convention.svg", metadata={"Date": None})


if __name__ == "__main__":
    main()
