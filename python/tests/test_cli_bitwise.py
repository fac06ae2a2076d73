"""The bindings give the CLI's results bit for bit (issue 34 item 6)."""

import numpy as np
import polars as pl
import pytest

import creepbench
from conftest import ROOT, run_cli

SCENES = ["step_cx001", "steady_fastsim_g22", "step_fn150"]


@pytest.mark.parametrize("scene", SCENES)
def test_simulate_equals_the_cli(scene, tmp_path):
    path = ROOT / "scenes" / "thesis" / f"{scene}.toml"
    cli = run_cli("simulate", path, "--out", tmp_path)
    assert cli.returncode == 0, cli.stderr
    sim = creepbench.simulate(path)
    folder = tmp_path / sim.name
    written = sorted(p.name for p in folder.iterdir() if not p.name.startswith("."))
    files = sim.files()
    assert sorted(files) == written
    for name, text in files.items():
        assert (folder / name).read_text() == text, name
    for model, df in sim.histories.items():
        # The CLI's CSV parsed by Python's own float() (correctly rounded): the same doubles.
        header, *rows = [line.split(",") for line in (folder / f"{model}.csv").read_text().splitlines()]
        assert df.columns == header
        for k, c in enumerate(header):
            theirs = np.array([float(r[k]) for r in rows])
            ours = df[c].cast(pl.Float64).to_numpy()
            assert np.array_equal(ours.view(np.int64), theirs.view(np.int64)), (model, c)
    theirs = pl.read_csv(folder / "metrics.csv", schema_overrides={"step": pl.Int64})
    ours = sim.metrics.select(theirs.columns)
    assert ours.equals(theirs)
    assert sim.scene["name"] == scene and sim.scene["solvers"] == sim.solvers


def test_toml_text_and_dict_give_the_same_results():
    import tomllib

    path = ROOT / "scenes" / "thesis" / "step_cx001.toml"
    text = path.read_text()
    by_path = creepbench.simulate(path, ["uba", "fastsim"])
    by_text = creepbench.simulate(text, ["uba", "fastsim"])
    by_dict = creepbench.simulate(tomllib.loads(text), solvers=["uba", "fastsim"])
    for other in (by_text, by_dict):
        assert other.solvers == ["uba", "fastsim"]
        for m in other.solvers:
            assert other.histories[m].equals(by_path.histories[m])


def test_fields_are_numpy_arrays_of_the_grid():
    sim = creepbench.simulate(ROOT / "scenes" / "thesis" / "step_cx001.toml", ["uba", "fastsim"], fields=True)
    f = sim.fields["uba"]
    assert f["px_mpa"].shape == (44, 22, 22) and f["pn_mpa"].dtype == np.float64
    assert list(f["step"]) == list(range(1, 45))
    assert sim.fields["x_mm"].shape == (22,) and sim.fields["y_mm"].shape == (22,)
    # The same field as the model gives when stepped from Python, bit for bit.
    doc = sim.scene
    stepper = creepbench.Stepper(
        "uba",
        contact={"a_mm": 8.56, "b_mm": 4.08, "fn_n": doc["fn_n"], "mu": doc["mu"]},
        grid={"mx": 22, "my": 22},
        model_options={k: doc["model"][k] for k in ("flexibility", "coefficients", "pressure")},
    )
    for r in sim.histories["uba"].iter_rows(named=True):
        stepper.step(r["cx"], r["cy"], r["cs"], r["fn_n"], r["mu"])
    last = stepper.field()
    for key in ("pn_mpa", "px_mpa", "py_mpa"):
        assert np.array_equal(last[key], f[key][-1]), key
    assert f["px_mpa"][-1].sum() > 0


@pytest.mark.parametrize("suite", ["scenes/nonhertz", "scenes/table"])
def test_check_is_the_cli_gate(suite):
    verdict = creepbench.check(suite, reference="reference", golden="golden")
    assert verdict.passed and bool(verdict)
    assert verdict.gated > 500 and verdict.failed == 0
    cli = run_cli("check", "--suite", suite)
    assert cli.returncode == 0, cli.stdout + cli.stderr
    assert cli.stdout.splitlines()[0] == str(verdict).splitlines()[0]
    assert verdict.to_frame().height == len(verdict.findings)


def test_check_fails_on_a_drift(tmp_path):
    import shutil

    golden = tmp_path / "golden"
    shutil.copytree(ROOT / "golden", golden)
    csv = golden / "nh_flat_sweep_cx" / "fastsim.csv"
    lines = csv.read_text().splitlines()
    cells = lines[5].split(",")
    k = lines[0].split(",").index("fx_over_fn")
    cells[k] = repr(float(cells[k]) + 1e-6)
    lines[5] = ",".join(cells)
    csv.write_text("\n".join(lines) + "\n")
    verdict = creepbench.check("scenes/nonhertz", reference="reference", golden=golden)
    assert not verdict.passed and verdict.failed == 1
    (f,) = verdict.failures
    assert (f.scene, f.solver, f.quantity, f.step) == ("nh_flat_sweep_cx", "fastsim", "fx_over_fn", int(cells[0]))
    assert f.diff == pytest.approx(1e-6, rel=1e-6)
