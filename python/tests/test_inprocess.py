"""A Python callable as a model (issue 34 item 4): run in-process, validated as an external
model's output, compared and gated as any model."""

import tomllib

import numpy as np
import polars as pl
import pytest

import creepbench
from conftest import ROOT


def scene(solvers):
    doc = tomllib.loads((ROOT / "scenes" / "thesis" / "steady_fastsim_g22.toml").read_text())
    doc["solvers"] = solvers
    return doc


def fastsim_as_python(scale=1.0, drop_rows=0, nan_at=None):
    """FASTSIM through steady(), its creepages scaled: a 'modified model'."""

    def model(s):
        rows = creepbench.loading(s).to_dicts()[drop_rows:]
        c = np.array([[r["cx"], r["cy"], r["cs"]] for r in rows]) * scale
        f = creepbench.steady(
            "fastsim", c,
            contact={k: s[k] for k in ("a_mm", "b_mm", "fn_n", "mu")},
            grid={"mx": s["mx"], "my": s["my"]},
            model_options={k: s["model"][k] for k in ("flexibility", "coefficients", "pressure")},
        )
        if nan_at is not None:
            f[nan_at, 0] = np.nan
        return pl.DataFrame({
            "step": [r["step"] for r in rows], "t_s": [r["t_s"] for r in rows],
            "cx": [r["cx"] for r in rows], "cy": [r["cy"] for r in rows], "cs": [r["cs"] for r in rows],
            "fn_n": [r["fn_n"] for r in rows], "fx_over_fn": f[:, 0], "fy_over_fn": f[:, 1], "mz_nmm": f[:, 2],
        })

    return model


def test_an_in_process_model_runs_and_equals_what_it_wraps():
    sim = creepbench.simulate(scene(["fastsim", "mine"]), models={"mine": fastsim_as_python()})
    assert sim.solvers == ["fastsim", "mine"]
    a, b = sim.histories["mine"], sim.histories["fastsim"]
    for c in ["step", "cx", "fx_over_fn", "fy_over_fn", "mz_nmm"]:
        assert a[c].equals(b[c]), c
    assert "mine.csv" in sim.files()
    assert set(sim.metrics["solver"]) >= {"mine"}
    m = sim.metrics.filter(pl.col("solver") == "mine").drop("solver")
    f = sim.metrics.filter(pl.col("solver") == "fastsim").drop("solver")
    assert m.equals(f)


def test_an_in_process_model_is_gated_against_a_baseline(tmp_path):
    base = creepbench.simulate(scene(["mine"]), models={"mine": fastsim_as_python()})
    base.save(tmp_path)
    same = creepbench.simulate(scene(["mine"]), models={"mine": fastsim_as_python()})
    verdict = same.check(reference="reference", against=tmp_path)
    assert verdict.passed and verdict.gated > 0
    changed = creepbench.simulate(scene(["mine"]), models={"mine": fastsim_as_python(scale=1.01)})
    verdict = changed.check(reference="reference", against=tmp_path)
    assert not verdict.passed
    worst = max((f for f in verdict.failures if f.quantity == "fx_over_fn"), key=lambda f: f.diff)
    assert worst.solver == "mine" and worst.step is not None and worst.diff > worst.allowed
    assert "FAIL" in str(verdict)


@pytest.mark.parametrize(
    "model, says",
    [
        (fastsim_as_python(drop_rows=3), "rows"),
        (fastsim_as_python(nan_at=5), "not a finite number"),
        (lambda s: {"step": [1], "t_s": [0.0]}, "<in-process mine>"),
    ],
)
def test_bad_output_is_refused_as_an_external_models(model, says):
    with pytest.raises(creepbench.RunError) as e:
        creepbench.simulate(scene(["mine"]), models={"mine": model})
    assert says in str(e.value) and "mine" in str(e.value)


def test_an_exception_of_the_model_is_chained():
    def broken(s):
        raise KeyError("no such key")

    with pytest.raises(creepbench.RunError) as e:
        creepbench.simulate(scene(["mine"]), models={"mine": broken})
    assert isinstance(e.value.__cause__, KeyError)


def test_an_in_process_name_must_not_be_a_builtin():
    with pytest.raises(creepbench.SceneError) as e:
        creepbench.simulate(scene(["fastsim"]), models={"fastsim": fastsim_as_python()})
    assert e.value.field == "external.fastsim"
