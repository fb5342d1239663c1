"""Model.run() against `afford run`: the same functions and explanations as
--json, the same trace as trace.csv, the arrays handed over without a copy."""

import csv
import json

import numpy as np

import afford


def test_functions_as_run_json(cli, repo, nutcracker, tmp_path):
    expected = json.loads(cli("run", "sessions/paper-nutcracker.yaml", "--json", "--out", str(tmp_path)))
    got = nutcracker.run()
    assert got["session"] == expected["session"] == "paper-nutcracker"
    assert got["frames"] == expected["frames"]
    assert [f["name"] for f in got["functions"]] == [f["name"] for f in expected["functions"]] == \
        ["pinch", "hold", "crash"]
    for g, e in zip(got["functions"], expected["functions"]):
        assert float(f"{g['t']:.9g}") == e["t"]  # --json rounds to 9 digits
        assert [n["text"] for n in g["explanation"]] == [n["text"] for n in e["explanation"]]
        assert [n.get("detail") for n in g["explanation"]] == [n.get("detail") for n in e["explanation"]]
        assert [float(f"{n['t']:.9g}") for n in g["explanation"]] == [n["t"] for n in e["explanation"]]


def cli_trace(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.reader(lines))


def formatted(trace, column, i):
    v = trace[column][i]
    if column == "t":
        return f"{v:.6f}"
    if trace[column].dtype == np.bool_ or trace[column].dtype == np.int32:
        return str(int(v))
    return f"{v:.9g}"  # as trace.csv writes it (engine/session/trace.h)


def test_trace_equals_trace_csv(cli, nutcracker, tmp_path):
    cli("run", "sessions/paper-nutcracker.yaml", "--out", str(tmp_path))
    rows = cli_trace(tmp_path / "trace.csv")
    trace = nutcracker.run()["trace"]
    assert list(trace) == rows[0]  # the same columns in the same order
    assert all(len(a) == len(rows) - 1 for a in trace.values())
    for i, row in enumerate(rows[1:]):
        assert [formatted(trace, c, i) for c in rows[0]] == row, f"frame {i + 1}"


def test_trace_arrays_are_not_copies(nutcracker):
    trace = nutcracker.run()["trace"]
    for name, a in trace.items():
        assert not a.flags["OWNDATA"], name  # the run's own buffer, kept alive by the array
        assert a.flags["C_CONTIGUOUS"], name
    assert trace["angle"].dtype == np.float64 and trace["held"].dtype == np.bool_
    assert np.all(np.diff(trace["t"]) > 0)


def test_model_properties(nutcracker):
    assert nutcracker.name == "paper-nutcracker"
    assert nutcracker.timestep == 0.001
    assert nutcracker.duration == 4.0
    assert nutcracker.functions == ["pinch", "hold", "carry", "crash"]
    assert nutcracker.files[0].endswith("paper-nutcracker.yaml")
    assert nutcracker.warnings == []


def test_several_actees(repo):
    got = afford.load(repo / "sessions" / "walnut-then-hazelnut.yaml").run()
    assert got["frames"] > 0 and len(got["trace"]["t"]) == got["frames"]
