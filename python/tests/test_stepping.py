"""Stepping a session from Python: the script's thumb gives the run's trace
bit for bit, any thumb target is taken as a tuple, a list or a NumPy array,
and a bad one is refused."""

import numpy as np
import pytest

import afford


def step_all(model, thumb=None):
    state = model.state()
    frames = []
    while state.next_t <= model.duration + 1e-9:
        frames.append(state.step(thumb(state) if thumb else None))
    return state, frames


def test_script_thumb_gives_the_run(nutcracker):
    trace = nutcracker.run()["trace"]
    state, frames = step_all(nutcracker, lambda s: tuple(s.script_thumb()))
    assert state.frame == len(trace["t"]) == 4000
    assert np.array_equal([f.t for f in frames], trace["t"])
    assert np.array_equal([f.angle for f in frames], trace["angle"])
    assert np.array_equal([f.effort_force for f in frames], trace["effort_force"])
    assert np.array_equal([f.actee_force for f in frames], trace["actee_force"])
    assert np.array_equal([f.held for f in frames], trace["held"])
    assert [f["name"] for f in state.functions()] == ["pinch", "hold", "crash"]
    inferred = [(e.function, e.t) for f in frames for e in f.events if e.kind == "inferred"]
    assert inferred == [(f["name"], f["t"]) for f in nutcracker.run()["functions"]]


def test_sample_kinds_agree(nutcracker):
    hashes = []
    for kind in (tuple, list, np.array):
        state = nutcracker.state()
        for _ in range(600):
            state.step(kind(state.script_thumb()))
        hashes.append(state.hash)
    script = nutcracker.state()
    for _ in range(600):
        script.step()
    assert hashes == [script.hash] * 3


def test_own_thumb_changes_the_frames(nutcracker):
    # The thumb kept 5 cm above the script's: it never reaches the arm, so
    # the hand never grasps and nothing is inferred.
    state, frames = step_all(nutcracker, lambda s: tuple(np.add(s.script_thumb(), (0, 0, 0.05))))
    assert not any(f.grasped for f in frames)
    assert state.functions() == []
    assert all(f.finger_forces == [0.0] * 5 for f in frames)


def test_frame_fields(nutcracker):
    state = nutcracker.state()
    frame = state.step()
    assert frame.t == pytest.approx(0.001) and state.t == frame.t and state.frame == 1
    assert 0 < frame.angle < 1.6  # rad
    assert len(frame.finger_forces) == 5
    assert frame.events == [] and not frame.broken


@pytest.mark.parametrize("bad", [(1.0, 2.0), "abc", (1.0, float("nan"), 0.0), np.zeros(4), ("a", 1, 2)])
def test_bad_samples(nutcracker, bad):
    state = nutcracker.state()
    with pytest.raises((TypeError, ValueError)):
        state.step(bad)
    assert state.frame == 0  # a refused sample steps nothing
