"""Shared fixtures: the repository's folder (the tests run from it) and the CLI binary."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
#: The Rust test that runs this suite sets it to the binary cargo built.
CLI = os.environ.get("CREEPBENCH_BIN", str(ROOT / "target" / "release" / "creepbench"))
#: The thesis's scene settings the models' options come from.
THESIS_MODEL = {"flexibility": "kalker", "coefficients": "table", "pressure": "parabolic"}
CONTACT = {"a_mm": 8.56, "b_mm": 4.08, "fn_n": 100000.0, "mu": 0.4}
GRID = {"mx": 22, "my": 22}


@pytest.fixture(autouse=True)
def in_repository(monkeypatch):
    monkeypatch.chdir(ROOT)


def run_cli(*args, timeout=300):
    """Run the CLI; its completed process (never waits forever)."""
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=ROOT)
