#!/usr/bin/env python3
"""The pictures the docs show that the tool draws, made by the tool: `--write` (the CMake target
`figures`) writes them into data/figures/, `--check` (ctest docs:figures) draws them again in a
temporary directory and compares them with the committed files byte for byte, so that a figure
in the docs is what the tool of this tree draws.

  python3 scripts/doc_figures.py SPHTROCH_EXE --write|--check [REPO_ROOT]

FIGURES names each file with the command that draws it ({out} is the file); a figure that needs
a component the tool lacks (`sphtroch --version` lists them) is left out, saying so.
Exit 1 naming every figure that differs or fails to draw; 2 on bad arguments; 0 otherwise.
"""
import pathlib
import subprocess
import sys
import tempfile

WRIST = ["--twists", "pi/2,pi/3,pi/4", "--rates", "1,1/2,-3/2", "--phases", "0,0.3,0"]
# (file under data/figures, the component it needs or None, the arguments after the tool)
FIGURES = [
    ("clinostat_plot.svg", "healpix",
     ["clinostat", "--outer", "1.33", "--inner", "2", "--coverage", "3600", "--epsilon", "0.01", "--plot", "{out}"]),
    ("wrist_path.svg", None, ["chain", "plot", *WRIST, "-o", "{out}"]),
    ("wrist_dwell.svg", None, ["chain", "plot", *WRIST, "--style", "density", "-o", "{out}"]),
]


def components(exe):
    """The components the tool says it has ("healpix", "png", ...)."""
    text = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout
    inside = text[text.find("(components:") + len("(components:"):text.rfind(")")]
    return {part.split()[0] for part in inside.split(",") if part.split()[1:] == ["yes"]}


def draw(exe, args, out):
    """Runs the tool with {out} replaced; returns an error text or None."""
    run = subprocess.run([exe] + [a.replace("{out}", str(out)) for a in args], capture_output=True, text=True)
    if run.returncode != 0 or not out.exists():
        return f"exit {run.returncode}: {run.stderr.strip()}"
    return None


def main(argv):
    if len(argv) not in (3, 4) or argv[2] not in ("--write", "--check"):
        print(__doc__.strip().splitlines()[3].strip(), file=sys.stderr)
        return 2
    exe, mode = argv[1], argv[2]
    root = pathlib.Path(argv[3] if len(argv) == 4 else pathlib.Path(__file__).resolve().parent.parent)
    have = components(exe)
    problems = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, needs, args in FIGURES:
            if needs is not None and needs not in have:
                print(f"{name}: left out (the tool has no {needs} component)")
                continue
            committed = root / "data" / "figures" / name
            out = committed if mode == "--write" else pathlib.Path(tmp) / name
            error = draw(exe, args, out)
            if error is not None:
                problems.append(f"{name}: sphtroch {' '.join(args)}: {error}")
            elif mode == "--check" and (not committed.exists() or committed.read_bytes() != out.read_bytes()):
                problems.append(f"{name}: differs from what `sphtroch {' '.join(args)}` draws "
                                "(cmake --build build --target figures writes it)")
            else:
                print(f"{name}: {'written' if mode == '--write' else 'as drawn'}")
    for p in problems:
        print("FAIL " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
