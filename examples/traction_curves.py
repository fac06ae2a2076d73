"""Traction curves of every built-in model, and a modified model gated against its baseline.

Run from the repository's folder, with the package installed (docs/python.md):

    python examples/traction_curves.py [OUT_DIR]        # default out/python_example; Python 3.11+ (tomllib)

1. The steady longitudinal traction curve Fx/FN(cx) of every built-in model on the thesis's
   contact (a = 8.56 mm, b = 4.08 mm, FN = 100 kN, mu = 0.4, 22 x 22 elements), one call of
   creepbench.steady per model: OUT_DIR/traction_curves.csv, and traction_curves.svg when
   matplotlib is installed (the curves are computed either way).
2. A model written in Python (FASTSIM with its creepages reduced by a factor k, a common
   way to calibrate it to measurements) run in-process on a shipped scene: the unmodified model
   (k = 1) is saved as the baseline, then the modified one (k = 0.8) is gated against it as
   `creepbench check --against` would; the verdict names the worst point.
3. The modified model in a suite beside FASTSIM: creepbench.run writes the result folders and
   the report (OUT_DIR/report/validation.md) as `creepbench run` does, the Python model's rows
   and comparisons with CONTACT among the built-in ones'.
"""

from __future__ import annotations

import pathlib
import sys
import tomllib

import numpy as np
import polars as pl

import creepbench

CONTACT = {"a_mm": 8.56, "b_mm": 4.08, "fn_n": 100000.0, "mu": 0.4}
GRID = {"mx": 22, "my": 22}
MODEL = {"flexibility": "kalker", "coefficients": "table", "pressure": "parabolic"}
SCENE = pathlib.Path("scenes/thesis/steady_fastsim_g22.toml")
#: CONTACT's and the thesis's results (the repository's reference/; run from its folder).
REFERENCE = pathlib.Path("reference")


def traction_curves(points: int = 101) -> pl.DataFrame:
    """cx from 0 to 0.01 and Fx/FN of every built-in model."""
    cx = np.linspace(0.0, 0.01, points)
    creepages = np.column_stack([cx, np.zeros(points), np.zeros(points)])
    curves = {"cx": cx}
    for model in creepbench.model_names():
        forces = creepbench.steady(model, creepages, contact=CONTACT, grid=GRID, model_options=MODEL)
        curves[model] = forces[:, 0]
    return pl.DataFrame(curves)


def draw(curves: pl.DataFrame, path: pathlib.Path) -> bool:
    """The curves as an SVG figure, if matplotlib is there."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for model in curves.columns[1:]:
        ax.plot(curves["cx"], curves[model], label=model)
    ax.set_xlabel("longitudinal creepage cx [-]")
    ax.set_ylabel("Fx / FN [-]")
    ax.legend()
    fig.savefig(path)
    return True


def fastsim_reduced(k: float):
    """FASTSIM with its creepages times k, as a model of the scene (columns of <model>.csv)."""

    def model(scene: dict) -> pl.DataFrame:
        rows = creepbench.loading(scene)
        creepages = rows.select("cx", "cy", "cs").to_numpy() * k
        forces = creepbench.steady(
            "fastsim",
            creepages,
            contact={key: scene[key] for key in ("a_mm", "b_mm", "fn_n", "mu")},
            grid={"mx": scene["mx"], "my": scene["my"]},
            model_options={key: scene["model"][key] for key in MODEL},
        )
        return rows.select("step", "t_s", "cx", "cy", "cs", "fn_n").with_columns(
            fx_over_fn=forces[:, 0], fy_over_fn=forces[:, 1], mz_nmm=forces[:, 2]
        )

    return model


def gate_modified_model(out: pathlib.Path) -> tuple[creepbench.Verdict, creepbench.Verdict]:
    """The unmodified model against its saved baseline (passes), then the modified one (fails)."""
    scene = tomllib.loads(SCENE.read_text())
    scene["solvers"] = ["fastsim_k"]
    baseline = out / "baseline"
    creepbench.simulate(scene, models={"fastsim_k": fastsim_reduced(1.0)}).save(baseline)
    same = creepbench.simulate(scene, models={"fastsim_k": fastsim_reduced(1.0)}).check(reference=REFERENCE, against=baseline)
    modified = creepbench.simulate(scene, models={"fastsim_k": fastsim_reduced(0.8)}).check(reference=REFERENCE, against=baseline)
    return same, modified


def report_modified_model(out: pathlib.Path) -> creepbench.RunReport:
    """A one-scene suite running FASTSIM and the modified model, reported."""
    suite = out / "suite"
    suite.mkdir(exist_ok=True)
    text = SCENE.read_text().replace('solvers = ["uba", "fastsim"]', 'solvers = ["fastsim", "fastsim_k"]')
    (suite / SCENE.name).write_text(text)
    return creepbench.run(
        suite, results=out / "results", report=out / "report", reference=REFERENCE, golden=out / "no_golden",
        models={"fastsim_k": fastsim_reduced(0.8)},
    )


def main() -> int:
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python_example")
    out.mkdir(parents=True, exist_ok=True)
    curves = traction_curves()
    curves.write_csv(out / "traction_curves.csv")
    drew = draw(curves, out / "traction_curves.svg")
    print(f"traction curves of {len(curves.columns) - 1} models: {out / 'traction_curves.csv'}")
    print("figure:", out / "traction_curves.svg" if drew else "skipped (matplotlib not installed)")
    print("Fx/FN at cx = 0.01:", ", ".join(f"{m} {curves[m][-1]:.4f}" for m in curves.columns[1:]))
    same, modified = gate_modified_model(out)
    print("unmodified model against its baseline:", str(same).splitlines()[0])
    print("modified model (k = 0.8) against it:", modified)
    report = report_modified_model(out)
    print(report)
    # The gate told the two apart: the example succeeds.
    return 0 if same.passed and not modified.passed else 1


if __name__ == "__main__":
    sys.exit(main())
