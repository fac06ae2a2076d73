"""run() as `creepbench run` does it, and a Python model in a suite's check() and run() (issue 34
items 2 and 4): run in-process where a scene lists it, validated, compared, gated and reported as
an external model is."""

import re

import polars as pl
import pytest

import creepbench
from conftest import ROOT, run_cli
from test_inprocess import fastsim_as_python

#: Two thesis scenes with CONTACT data, cheap models only.
SCENES = {"step_cx001": ["uba", "fastsim"], "steady_fastsim_g22": ["fastsim"]}


def make_suite(folder, extra=()):
    """The scenes in `folder`, their `solvers` the cheap models plus `extra`."""
    folder.mkdir()
    for name, models in SCENES.items():
        text = (ROOT / "scenes" / "thesis" / f"{name}.toml").read_text()
        listed = ", ".join(f'"{m}"' for m in [*models, *extra])
        text, n = re.subn(r"(?m)^solvers = \[.*\]$", f"solvers = [{listed}]", text)
        assert n == 1, name
        (folder / f"{name}.toml").write_text(text)
    return folder


def test_run_is_the_cli_run(tmp_path):
    suite = make_suite(tmp_path / "suite")
    none = tmp_path / "no_golden"
    cli = run_cli("run", "--suite", suite, "--results", tmp_path / "cli_res", "--report", tmp_path / "cli_rep",
                  "--golden", none, "--quiet")
    assert cli.returncode == 0, cli.stderr
    # A model given but listed by no scene changes nothing.
    rep = creepbench.run(suite, reference="reference", results=tmp_path / "res", report=tmp_path / "rep", golden=none,
                         models={"mine": fastsim_as_python()})
    assert isinstance(rep, creepbench.RunReport)
    assert rep.report == str(tmp_path / "rep" / "validation.md") and rep.results == str(tmp_path / "res")
    gates = next(line for line in cli.stdout.splitlines() if line.startswith("gates: "))
    assert str(rep).splitlines()[0] == gates
    assert rep.verdict.gated > 0 and rep.passed and bool(rep) and rep.failed == 0
    # The same report: every table and the findings' CSV byte for byte.
    for f in ["results.csv", *(f"tables/{p.name}" for p in (tmp_path / "cli_rep" / "tables").iterdir())]:
        assert (tmp_path / "rep" / f).read_bytes() == (tmp_path / "cli_rep" / f).read_bytes(), f
    for name in SCENES:
        for f in (tmp_path / "cli_res" / name).glob("*.csv"):
            if f.name == "timing.csv":  # wall times
                continue
            assert (tmp_path / "res" / name / f.name).read_bytes() == f.read_bytes(), f
    # Findings with their worst points: each against CONTACT names its step and both values.
    contact = [f for f in rep.findings if f.against.startswith("CONTACT") and f.quantity == "fx_over_fn"]
    assert {(f.scene, f.solver) for f in contact} >= {("step_cx001", "uba"), ("steady_fastsim_g22", "fastsim")}
    for f in contact:
        assert f.step is not None and f.diff == abs(f.ours - f.theirs)


def findings_of(verdict, solver):
    return {(f.scene, f.against, f.quantity, f.step): (f.ours, f.theirs, f.diff) for f in verdict.findings
            if f.solver == solver}


def test_an_in_process_model_is_run_compared_and_reported_in_a_suite(tmp_path):
    suite = make_suite(tmp_path / "suite", ["mine"])
    rep = creepbench.run(suite, reference="reference", results=tmp_path / "res", report=tmp_path / "rep", golden=tmp_path / "no_golden",
                         models={"mine": fastsim_as_python()})
    # Its history is written as an external model's, and equals FASTSIM's it wraps.
    for name in SCENES:
        mine = pl.read_csv(tmp_path / "res" / name / "mine.csv")
        fastsim = pl.read_csv(tmp_path / "res" / name / "fastsim.csv")
        assert mine["fx_over_fn"].equals(fastsim["fx_over_fn"]), name
    # Its comparisons with CONTACT are FASTSIM's, finding for finding, and the report lists them.
    mine, fastsim = findings_of(rep.verdict, "mine"), findings_of(rep.verdict, "fastsim")
    contact = {k: v for k, v in mine.items() if k[1].startswith("CONTACT")}
    assert len(contact) >= 2 and all(fastsim[k] == v for k, v in contact.items())
    rows = pl.read_csv(tmp_path / "rep" / "results.csv")
    mine_rows = rows.filter(pl.col("solver") == "mine").drop("solver")
    assert mine_rows.height > 0
    assert mine_rows.equals(rows.filter(pl.col("solver") == "fastsim").drop("solver"))
    assert "mine" in (tmp_path / "rep" / "validation.md").read_text()

    # check() against that run: the same model passes, a modified one fails at its worst point.
    same = creepbench.check(suite, reference="reference", against=tmp_path / "res", models={"mine": fastsim_as_python()})
    assert same.passed and any(f.solver == "mine" and f.gated for f in same.findings)
    changed = creepbench.check(suite, reference="reference", against=tmp_path / "res", models={"mine": fastsim_as_python(scale=1.01)})
    assert not changed.passed and {f.solver for f in changed.failures} == {"mine"}
    worst = max((f for f in changed.failures if f.quantity == "fx_over_fn"), key=lambda f: f.diff / f.allowed)
    before = pl.read_csv(tmp_path / "res" / worst.scene / "mine.csv")
    assert worst.step is not None and worst.theirs == before.filter(pl.col("step") == worst.step)["fx_over_fn"][0]
    assert worst.diff == abs(worst.ours - worst.theirs) > worst.allowed


def test_a_suite_scene_naming_a_model_not_given_is_refused(tmp_path):
    suite = make_suite(tmp_path / "suite", ["mine"])
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.check(suite, reference="reference", against=tmp_path)
    assert e.value.value == '"mine"' and "solvers[" in e.value.field and "fastsim" in e.value.allowed


def test_bad_output_in_a_suite_is_refused_naming_scene_and_model(tmp_path):
    suite = make_suite(tmp_path / "suite", ["mine"])
    with pytest.raises(creepbench.RunError) as e:
        creepbench.run(suite, reference="reference", results=tmp_path / "res", report=tmp_path / "rep", golden=tmp_path / "no_golden",
                       models={"mine": fastsim_as_python(drop_rows=3)})
    assert "mine" in str(e.value) and "rows" in str(e.value)
    # Nothing was written: the run stops before its results.
    assert not (tmp_path / "res").exists()


def test_run_refuses_to_write_into_golden(tmp_path):
    suite = make_suite(tmp_path / "suite")
    golden = tmp_path / "golden"
    golden.mkdir()
    with pytest.raises(creepbench.RunError) as e:
        creepbench.run(suite, reference="reference", results=golden / "res", report=tmp_path / "rep", golden=golden)
    assert "refusing to write" in str(e.value) and "only `creepbench bless` writes" in str(e.value)
    assert not (golden / "res").exists() and not (tmp_path / "rep").exists()
