"""afford.explore against `afford explore`'s points.csv, and the GIL
released while it runs."""

import csv
import math
import threading
import time

import numpy as np
import pytest

import afford

GRID = ["--placements", "2", "--thumbs", "2", "--efforts", "4", "--grasps", "medium_wrap,tip_pinch"]


def test_points_as_points_csv(cli, repo, tmp_path):
    cli("explore", "objects/nutcracker.yaml", "--actees", "actees/walnut.yaml", "actees/sponge.yaml", *GRID,
        "--out", str(tmp_path))
    with open(tmp_path / "points.csv") as f:
        rows = list(csv.DictReader(f))
    got = afford.explore(repo / "objects" / "nutcracker.yaml", [repo / "actees" / "walnut.yaml",
                         repo / "actees" / "sponge.yaml"], placements=2, thumbs=2, efforts=4,
                         grasps=["medium_wrap", "tip_pinch"])
    assert list(got) == list(rows[0])  # the same columns in the same order
    assert all(len(column) == len(rows) for column in got.values())
    for i, row in enumerate(rows):
        for name, text in row.items():
            value = got[name][i]
            if isinstance(value, str):
                assert value == text, (i, name)
            elif text == "":
                assert math.isnan(value), (i, name)
            else:
                assert value == float(text), (i, name)  # points.csv writes doubles exactly


def test_columns_are_numpy(repo):
    got = afford.explore(repo / "objects" / "nutcracker.yaml", [repo / "actees"], placements=1, thumbs=1,
                         efforts=2, fixed_efforts=True, grasps=["medium_wrap"])
    assert got["effort_N"].dtype == np.float64 and got["actee"].dtype == object
    assert {"walnut", "hazelnut"} <= set(got["actee"])  # a folder gives each of its actees that fits


def test_gil_released(repo):
    # A second Python thread keeps running while explore runs on one worker:
    # it notes the time as it goes, and some of its notes fall in the middle
    # half of the call (with the GIL held it could run only at the ends).
    seen = []
    running = True

    def note_times():
        while running:
            seen.append(time.perf_counter())
            time.sleep(0.001)

    other = threading.Thread(target=note_times)
    other.start()
    try:
        start = time.perf_counter()
        afford.explore(repo / "objects" / "nutcracker.yaml", [repo / "actees" / "walnut.yaml"], placements=3,
                       thumbs=3, efforts=5, threads=1)
        end = time.perf_counter()
    finally:
        running = False
        other.join()
    quarter = (end - start) / 4
    assert end - start > 0.05  # long enough to tell
    assert sum(start + quarter < t < end - quarter for t in seen) >= 5


def test_bad_grid_is_a_value_error(repo):
    with pytest.raises(ValueError, match="expected a count from 1"):
        afford.explore(repo / "objects" / "nutcracker.yaml", placements=0)
    with pytest.raises(ValueError, match="not a grasp type"):
        afford.explore(repo / "objects" / "nutcracker.yaml", grasps=["claw"])
    with pytest.raises(ValueError, match="threads"):
        afford.explore(repo / "objects" / "nutcracker.yaml", threads=-1)


def test_bad_actee_is_a_data_error(repo, tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("actee: bad\nmass: 3 kg\nshape: cube\n")
    with pytest.raises(afford.DataError) as e:
        afford.explore(repo / "objects" / "nutcracker.yaml", [bad])
    assert e.value.file == str(bad) and e.value.line > 0
