"""examples/traction_curves.py runs and gives what it promises."""

import subprocess
import sys

import polars as pl

import creepbench
from conftest import ROOT


def test_the_example_draws_every_model_and_gates_a_modified_one(tmp_path):
    run = subprocess.run(
        [sys.executable, "examples/traction_curves.py", str(tmp_path)],
        cwd=ROOT, capture_output=True, text=True, timeout=600,
    )
    assert run.returncode == 0, run.stdout + run.stderr
    curves = pl.read_csv(tmp_path / "traction_curves.csv")
    assert curves.columns == ["cx", *creepbench.model_names()]
    assert curves.height == 101
    # Every curve starts at 0 and saturates below mu = 0.4; CONTACT's FASTSIM and FaStrip divide
    # their totals by the prescribed FN, not by the load their discrete pressure carries, so at full
    # slip they reach mu times that load over FN (1.00043 on this grid), as CONTACT prints.
    over_prescribed_fn = {"fastsim_contact": 1.001, "fastrip_contact": 1.001}
    for m in creepbench.model_names():
        bound = 0.4 * over_prescribed_fn.get(m, 1.0) + 1e-9
        assert curves[m][0] == 0.0 and 0.2 < curves[m][-1] <= bound, m
    assert "unmodified model against its baseline: PASS" in run.stdout
    assert "modified model (k = 0.8) against it: FAIL" in run.stdout
    assert (tmp_path / "baseline" / "steady_fastsim_g22" / "fastsim_k.csv").exists()
    # The suite run: the report lists the Python model's rows beside FASTSIM's.
    assert f"report: {tmp_path / 'report' / 'validation.md'}" in run.stdout
    rows = pl.read_csv(tmp_path / "report" / "results.csv")
    assert set(rows["solver"]) == {"fastsim", "fastsim_k"}
    assert (tmp_path / "results" / "steady_fastsim_g22" / "fastsim_k.csv").exists()


def test_the_speed_script_runs():
    run = subprocess.run(
        [sys.executable, "examples/steady_speed.py", "1000"], cwd=ROOT, capture_output=True, text=True, timeout=300
    )
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.count("us per creepage") == 2 and "fixed overhead" in run.stdout
