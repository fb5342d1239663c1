"""Timings of the Python package (not a test: run by hand, figures for docs).

    PYTHONPATH=build/python AFFORD_DATA_DIR=. /usr/bin/python3 python/bench/bench_python.py [--cli build/cli/afford]

1. one frame from Python: state.step(thumb) with a tuple, a NumPy array and
   the script's own thumb (None), median of several passes over the
   paper-nutcracker session, in microseconds per frame;
2. the same grid explored from Python and by the afford program, seconds
   (median of 3 runs each, every core).
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import afford

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRID = dict(placements=3, thumbs=3, efforts=9)


def frame_times(model, kind, passes=5):
    state0 = model.state()
    thumbs = [state0.script_thumb(k * model.timestep) for k in range(1, int(model.duration / model.timestep) + 1)]
    samples = [None] * len(thumbs) if kind == "script" else [
        tuple(t) if kind == "tuple" else np.array(t) for t in thumbs]
    per_frame = []
    for _ in range(passes):
        state = model.state()
        step = state.step
        start = time.perf_counter()
        for s in samples:
            step(s)
        per_frame.append((time.perf_counter() - start) / len(samples) * 1e6)
    return statistics.median(per_frame)


def explore_times(cli, runs=3):
    obj = os.path.join(REPO, "objects", "nutcracker.yaml")
    py, prog = [], []
    for _ in range(runs):
        start = time.perf_counter()
        afford.explore(obj, **GRID)
        py.append(time.perf_counter() - start)
        with tempfile.TemporaryDirectory() as out:
            start = time.perf_counter()
            subprocess.run([cli, "explore", obj, "--placements", "3", "--thumbs", "3", "--efforts", "9", "--out", out],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            prog.append(time.perf_counter() - start)
    return statistics.median(py), statistics.median(prog)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", default=os.path.join(REPO, "build", "cli", "afford"))
    parser.add_argument("--no-explore", action="store_true")
    args = parser.parse_args()
    model = afford.load(os.path.join(REPO, "sessions", "paper-nutcracker.yaml"))
    for kind in ("tuple", "numpy", "script"):
        print(f"frame from Python, thumb as {kind}: {frame_times(model, kind):.2f} us")
    if not args.no_explore:
        py, prog = explore_times(args.cli)
        print(f"explore nutcracker, every shipped actee, 3x3x9: Python {py:.2f} s, afford program {prog:.2f} s "
              f"({(py / prog - 1) * 100:+.1f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
