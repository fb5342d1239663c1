"""The same session gives the same bits: two runs, two steppers, two
explores on different thread counts."""

import numpy as np

import afford


def test_runs_are_identical(nutcracker, repo):
    a = nutcracker.run()
    b = afford.load(repo / "sessions" / "paper-nutcracker.yaml").run()
    assert a["functions"] == b["functions"]
    for name in a["trace"]:
        assert np.array_equal(a["trace"][name], b["trace"][name]), name


def test_steppers_are_identical(nutcracker):
    def hashes():
        state = nutcracker.state()
        out = []
        for k in range(3000):
            state.step((0.115, 0.12 - 1e-5 * k, 0.1))
            out.append(state.hash)
        return out

    assert hashes() == hashes()


def test_explore_same_on_any_thread_count(repo):
    grid = dict(actees=[repo / "actees" / "walnut.yaml", repo / "actees" / "egg.yaml"], placements=2, thumbs=1,
                efforts=3, grasps=["medium_wrap"])
    one = afford.explore(repo / "objects" / "nutcracker.yaml", threads=1, **grid)
    two = afford.explore(repo / "objects" / "nutcracker.yaml", threads=2, **grid)
    assert list(one) == list(two)
    for name in one:
        assert one[name].tolist() == two[name].tolist() or np.array_equal(one[name], two[name], equal_nan=True), name
