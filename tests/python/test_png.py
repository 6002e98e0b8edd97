"""`plot -o FILE.png` and `atlas --svg FILE.png`: the tool's SVG rendered by librsvg, decoded here by
an independent reader (matplotlib.image.imread): the PNG has the SVG's size in pixels, a white
background, and the curve drawn in the SVG's own stroke colour. Without the png component
(`sphtroch --version` says `png no`), .png is refused with one line naming librsvg and no file."""
import os
import re
import subprocess
import tempfile

import matplotlib.image as mpimg
import numpy as np
from conftest import EXE


def has_png():
    version = subprocess.run([EXE, "--version"], capture_output=True, text=True, check=True).stdout
    return "png yes" in version


def run(args, cwd):
    return subprocess.run([EXE, *args], cwd=cwd, capture_output=True, text=True)


def svg_size_and_colour(svg, element):
    """(width, height) of the SVG and the stroke colour of its first `element` as RGB in [0, 1]."""
    size = re.search(r'<svg[^>]* width="(\d+)" height="(\d+)"', svg)
    colour = re.search(r"<" + element + r" [^>]*stroke:#([0-9a-f]{6})", svg).group(1)
    return (int(size.group(1)), int(size.group(2))), np.array([int(colour[k:k + 2], 16) for k in (0, 2, 4)]) / 255.0


def pixels_near(image, colour, tol=0.06):
    return int(np.sum(np.all(np.abs(image[:, :, :3] - colour) <= tol, axis=2)))


def test_plot_png_is_the_svg_rendered():
    plot = ["plot", "--a2", "0.7", "--a3", "2.5", "--n", "13/5", "--view", "top", "--labels", "none"]
    with tempfile.TemporaryDirectory() as d:
        done = run(plot + ["-o", "p.png"], d)
        if not has_png():
            assert done.returncode == 2 and done.stdout == "" and os.listdir(d) == []
            assert "librsvg" in done.stderr and done.stderr.count("\n") == 1
            return
        assert done.returncode == 0 and done.stdout == "" and done.stderr == ""
        assert run(plot + ["-o", "p.svg"], d).returncode == 0
        with open(os.path.join(d, "p.png"), "rb") as f:
            assert f.read(8) == b"\x89PNG\r\n\x1a\n"
        image = mpimg.imread(os.path.join(d, "p.png"))
        with open(os.path.join(d, "p.svg")) as f:
            (width, height), curve = svg_size_and_colour(f.read(), "path")
        assert image.shape[:2] == (height, width)
        assert np.all(image[0, 0, :3] == 1.0) and np.all(image[-1, -1, :3] == 1.0)  # white corners
        assert pixels_near(image, curve) >= 200  # the curve's stroke
        assert 0.01 < np.mean(np.any(image[:, :, :3] < 0.9, axis=2)) < 0.6  # drawn, not blank, not filled


def test_atlas_png_and_other_formats():
    with tempfile.TemporaryDirectory() as d:
        done = run(["atlas", "--n", "2", "--grid", "16", "--svg", "m.PNG"], d)
        if has_png():
            assert done.returncode == 0
            image = mpimg.imread(os.path.join(d, "m.PNG"))
            assert image.shape[:2] == (624, 938)  # the map's SVG size (512 px map, legend)
        else:
            assert done.returncode == 2 and os.listdir(d) == []
        for args in (["plot", "--a2", "1", "--a3", "2", "--n", "2", "-o", "p.jpg"],
                     ["atlas", "--n", "2", "--grid", "4", "--svg", "m.pdf"]):
            bad = run(args, d)
            assert bad.returncode == 2 and bad.stdout == "" and bad.stderr.count("\n") == 1
            assert not os.path.exists(os.path.join(d, args[-1]))
