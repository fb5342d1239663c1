"""Shared by the package's tests: the repository, the afford program of the
same build (to compare with) and the shipped data found in the source tree."""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
# The shipped data of this source tree, not an installed copy.
os.environ.setdefault("AFFORD_DATA_DIR", str(REPO))

import afford  # noqa: E402  (after AFFORD_DATA_DIR is set)


def cli_path() -> Path:
    given = os.environ.get("AFFORD_CLI")
    return Path(given) if given else REPO / "build" / "cli" / "afford"


@pytest.fixture(scope="session")
def repo() -> Path:
    return REPO


@pytest.fixture(scope="session")
def cli():
    """Runs the afford program with the given arguments from the repository; returns its stdout."""
    program = cli_path()
    assert program.is_file(), f"the afford program is not built: {program} (set AFFORD_CLI)"

    def run(*args: str) -> str:
        done = subprocess.run([str(program), *args], cwd=REPO, capture_output=True, text=True, check=False)
        assert done.returncode == 0, f"afford {' '.join(args)} failed: {done.stderr}"
        return done.stdout

    return run


@pytest.fixture(scope="session")
def nutcracker() -> "afford.Model":
    return afford.load(REPO / "sessions" / "paper-nutcracker.yaml")
