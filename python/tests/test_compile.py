"""afford.compile from parts is the session file it stands for."""

import numpy as np
import yaml

import afford


def test_compile_is_the_session(repo, nutcracker):
    session = yaml.safe_load((repo / "sessions" / "paper-nutcracker.yaml").read_text())
    model = afford.compile(repo / "objects" / "nutcracker.yaml",
                           {"file": repo / "actees" / "walnut.yaml", "at": "60 mm"},
                           script=session["script"], name="paper-nutcracker")
    assert model.name == "paper-nutcracker" and model.duration == nutcracker.duration
    a, b = model.run(), nutcracker.run()
    assert a["functions"] == b["functions"]
    for column in a["trace"]:
        assert np.array_equal(a["trace"][column], b["trace"][column]), column


def test_compile_without_actee(repo):
    script = yaml.safe_load((repo / "sessions" / "paper-nutcracker.yaml").read_text())["script"][:3]
    result = afford.compile(repo / "objects" / "nutcracker.yaml", script=script).run()
    assert result["frames"] == 2900  # to the third keyframe, at 2.9 s
    assert [f["name"] for f in result["functions"]] == []  # nothing to pinch, hold or crash
    assert not result["trace"]["held"].any()
