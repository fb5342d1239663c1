"""gap, effects, signals and export_mjcf give what the program prints."""

import json
import re
from pathlib import Path

import pytest

import afford

# The real macadamia curves the shipped measurement reads in place (../shared).
MACADAMIA = Path(__file__).resolve().parents[3] / "shared" / "data" / "real" / "macadamia"


@pytest.mark.skipif(not MACADAMIA.exists(), reason=f"{MACADAMIA} is absent (the real curves are read in place)")
def test_gap_as_json(cli, repo, monkeypatch):
    monkeypatch.chdir(repo)  # the report names the traces as the measurement's path leads to them
    expected = json.loads(cli("gap", "measurements/macadamia-plates.yaml", "--json"))
    assert afford.gap("measurements/macadamia-plates.yaml") == expected


def test_gap_unknown_effect(repo):
    with pytest.raises(ValueError, match="did you mean 'pivot_friction'"):
        afford.gap(repo / "measurements" / "macadamia-plates.yaml", effects=["pivot_fricton"])


def test_effects_as_describe(cli):
    text = cli("describe", "--effects")
    listed = re.findall(r"^  (\w+) \((\w+) file\): ", text, re.M)
    effects = afford.effects()
    assert [(e["name"], e["home"]) for e in effects] == listed
    for e in effects:
        for p in e["params"]:
            assert p["min"] <= p["max"] and f"      {p['key']}: {p['doc']}, {p['range']}\n" in text


def test_signals_as_rules_list(cli):
    text = cli("rules", "--list")
    signals = afford.signals()
    assert signals and all(s["signature"] in text and s["doc"] in text for s in signals)


def test_export_mjcf_as_the_program(cli, repo, tmp_path, monkeypatch):
    monkeypatch.chdir(repo)  # the scene's header names the session as given
    out = tmp_path / "scene.xml"
    cli("export", "--mjcf", "sessions/paper-nutcracker.yaml", "--out", str(out))
    assert afford.export_mjcf("sessions/paper-nutcracker.yaml") == out.read_text()
    assert afford.export_mjcf(afford.load("sessions/paper-nutcracker.yaml")) == out.read_text()


def test_export_mjcf_refuses_several_actees(repo):
    with pytest.raises(RuntimeError, match="one actee"):
        afford.export_mjcf(repo / "sessions" / "walnut-then-hazelnut.yaml")
