"""Bad input raises afford.DataError naming the file, line and column, as
the program reports it; check() validates any kind of file."""

from pathlib import Path

import pytest

import afford

# The real macadamia curves the shipped measurement reads in place (../shared).
MACADAMIA = Path(__file__).resolve().parents[3] / "shared" / "data" / "real" / "macadamia"


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_load_names_the_bad_key(repo, tmp_path):
    text = (repo / "sessions" / "paper-nutcracker.yaml").read_text()
    text = text.replace("agent: ../agents/hand.yaml", f"agent: {repo}/agents/hand.yaml\nagnet: x")
    text = text.replace("../", f"{repo}/")
    path = write(tmp_path, "s.yaml", text)
    with pytest.raises(afford.DataError) as e:
        afford.load(path)
    err = e.value
    line = text.splitlines().index("agnet: x") + 1
    assert (err.file, err.line, err.column) == (str(path), line, 1)
    assert "agnet" in err.message and "did you mean" in err.message
    assert str(err) == f"{path}:{line}:1: {err.message}"
    assert isinstance(err, ValueError)


def test_missing_file(tmp_path):
    with pytest.raises(afford.DataError) as e:
        afford.load(tmp_path / "none.yaml")
    assert e.value.file == str(tmp_path / "none.yaml")


def test_check_ok_and_warnings(repo):
    assert afford.check(repo / "objects" / "nutcracker.yaml") == {"what": "object nutcracker", "warnings": []}
    assert afford.check(repo / "devices" / "glove.yaml")["what"].startswith("device ")


@pytest.mark.skipif(not MACADAMIA.exists(), reason=f"{MACADAMIA} is absent (the real curves are read in place)")
def test_check_measurement(repo):
    assert afford.check(repo / "measurements" / "macadamia-plates.yaml")["what"].startswith("measurement ")


def test_check_bad_number(repo, tmp_path):
    text = (repo / "objects" / "nutcracker.yaml").read_text()
    assert "\nmass: 190 g\n" in text
    path = write(tmp_path, "o.yaml", text.replace("\nmass: 190 g\n", "\nmass: 190 parsecs\n"))
    with pytest.raises(afford.DataError) as e:
        afford.check(path)
    line = text.splitlines().index("mass: 190 g") + 1
    assert (e.value.file, e.value.line, e.value.column) == (str(path), line, 7)
    assert "parsecs" in e.value.message


def test_check_matches_the_program(repo, tmp_path, cli):
    import subprocess
    path = write(tmp_path, "a.yaml", "actee: x\nmass: 1 kg\nlimt: 3 N\n")
    with pytest.raises(afford.DataError) as e:
        afford.check(path)
    from conftest import cli_path
    done = subprocess.run([str(cli_path()), "check", str(path)], capture_output=True, text=True)
    assert done.returncode == 1 and done.stderr.strip() == str(e.value)


def test_compile_error_is_located(repo):
    with pytest.raises(afford.DataError) as e:
        afford.compile(repo / "objects" / "nutcracker.yaml", {"file": repo / "actees" / "walnut.yaml", "at": "60 mm"},
                       script=[{"t": "0 s", "hand": {"position": ["80 mm", "40 mm", "190 mm"]}, "grip": "tight"}])
    assert e.value.file == "<afford.compile python>" and e.value.line > 1 and e.value.column > 1
