"""steady() and Stepper against the per-scene results (issue 34 item 3)."""

import tomllib

import numpy as np
import pytest

import creepbench
from conftest import CONTACT, GRID, ROOT, THESIS_MODEL

STEADY_MODELS = [m for m in creepbench.model_names() if m != "contact"]


def bits(a):
    return np.ascontiguousarray(a, dtype=np.float64).view(np.int64)


def sweep_scene(models, points=101):
    doc = tomllib.loads((ROOT / "scenes" / "thesis" / "steady_fastsim_g22.toml").read_text())
    doc["solvers"] = models
    doc["creepage"]["points"] = points
    return doc


@pytest.mark.parametrize("model", STEADY_MODELS)
def test_steady_equals_the_sweep_scene_bit_for_bit(model):
    sim = creepbench.simulate(sweep_scene([model]))
    h = sim.histories[model]
    creepages = h.select("cx", "cy", "cs").to_numpy()
    out = creepbench.steady(model, creepages, contact=CONTACT, grid=GRID, model_options=THESIS_MODEL)
    assert out.shape == (h.height, 3) and out.dtype == np.float64
    for k, col in enumerate(["fx_over_fn", "fy_over_fn", "mz_nmm"]):
        assert np.array_equal(bits(out[:, k]), bits(h[col].to_numpy())), col


def test_steady_of_the_exact_solver_is_its_sweep_within_a_chunk():
    # Each solve starts from the previous row's solution, as the CLI's sweep does: the first
    # chunk is the sweep bit for bit, the next chunk starts afresh (docstring of steady()).
    n = creepbench.STEADY_CHUNK_ROWS
    assert n == 256
    h = creepbench.simulate(sweep_scene(["contact"], points=n + 44)).histories["contact"]
    out = creepbench.steady(
        "contact", h.select("cx", "cy", "cs").to_numpy(), contact=CONTACT, grid=GRID, model_options=THESIS_MODEL
    )
    for k, col in enumerate(["fx_over_fn", "fy_over_fn", "mz_nmm"]):
        sweep = h[col].to_numpy()
        assert np.array_equal(bits(out[:n, k]), bits(sweep[:n])), col
        # After the chunk's fresh start: the same steady state to the solver's tolerance, 1e-9
        # in fx/fn, fy/fn and in mz / (mu fn a) (measured 6e-11 in fx/fn, 3e-7 N mm in mz).
        bound = 1e-9 * (CONTACT["mu"] * CONTACT["fn_n"] * CONTACT["a_mm"] if col == "mz_nmm" else 1.0)
        assert np.abs(out[n:, k] - sweep[n:]).max() <= bound, col


THREADS_SCRIPT = """
import sys, numpy as np, creepbench
sys.path.insert(0, "python/tests")
from conftest import CONTACT, GRID, THESIS_MODEL
rng = np.random.default_rng(11)
c = np.column_stack([rng.uniform(-0.01, 0.01, 3000), rng.uniform(-0.01, 0.01, 3000), rng.uniform(-1e-3, 1e-3, 3000)])
out = [creepbench.steady(m, c[: (600 if m == "contact" else 3000)], contact=CONTACT, grid=GRID,
                         model_options=THESIS_MODEL) for m in creepbench.model_names()]
np.save(sys.argv[1], np.concatenate(out))
"""


def test_steady_is_bit_identical_with_any_thread_count(tmp_path):
    import os
    import subprocess
    import sys

    runs = {}
    for threads in (1, 3):
        out = tmp_path / f"threads{threads}.npy"
        env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
        run = subprocess.run([sys.executable, "-c", THREADS_SCRIPT, str(out)], cwd=ROOT, env=env,
                             capture_output=True, text=True, timeout=600)
        assert run.returncode == 0, run.stderr
        runs[threads] = np.load(out)
    assert runs[1].shape == (600 + 3000 * (len(creepbench.model_names()) - 1), 3)
    assert np.array_equal(bits(runs[1]), bits(runs[3]))


def test_steady_is_the_same_in_one_call_or_many():
    rng = np.random.default_rng(7)
    c = np.column_stack([rng.uniform(-0.01, 0.01, 2000), rng.uniform(-0.01, 0.01, 2000), rng.uniform(-0.001, 0.001, 2000)])
    whole = creepbench.steady("fastsim", c, contact=CONTACT, grid=GRID)
    parts = np.vstack([creepbench.steady("fastsim", c[k : k + 1], contact=CONTACT, grid=GRID) for k in range(0, 2000, 97)])
    assert np.array_equal(bits(whole[::97]), bits(parts))
    # Fx/FN and Fy/FN are bounded by mu (thesis Eq. 2.27).
    assert np.all(np.hypot(whole[:, 0], whole[:, 1]) <= CONTACT["mu"] * (1 + 1e-9))


@pytest.mark.parametrize("model", ["uba", "relaxation", "contact"])
def test_stepper_reproduces_a_transient_scene(model):
    doc = tomllib.loads((ROOT / "scenes" / "thesis" / "step_cx001.toml").read_text())
    h = creepbench.simulate(doc, [model]).histories[model]
    s = creepbench.Stepper(
        model, contact=doc["contact"], grid=doc["grid"], rolling=doc["rolling"], material=doc["material"],
        model_options=doc["model"],
    )
    assert s.dt_s == pytest.approx(h["t_s"][0], rel=1e-15)
    rows = [s.step(r["cx"], r["cy"], r["cs"], r["fn_n"], r["mu"]) for r in h.iter_rows(named=True)]
    out = np.array(rows)
    for k, col in enumerate(["fx_over_fn", "fy_over_fn", "mz_nmm"]):
        assert np.array_equal(bits(out[:, k]), bits(h[col].to_numpy())), col
    assert s.steps == h.height
    if model != "relaxation":
        f = s.field()
        assert f is not None and f["px_mpa"].shape == (22, 22)


def test_stepper_reloads_when_the_load_changes():
    s = creepbench.Stepper("fastsim", contact=CONTACT, grid=GRID)
    a = s.steady(0.002, 0.0, 0.0, 1e5, 0.4)
    b = s.steady(0.002, 0.0, 0.0, 5e4, 0.4)
    c = s.steady(0.002, 0.0, 0.0, 1e5, 0.4)
    assert a == c and a != b
