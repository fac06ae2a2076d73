"""creepbench from Python: wheel-rail creep-force models and their validation harness.

Everything is computed by the Rust library the ``creepbench`` command line is built on
(PyO3 bindings): the same scene checks and error text, the same models, the same gate.
Units are in the names: mm, N, MPa, s; creepages cx, cy are dimensionless, the spin cs is
in 1/mm; forces come back as fx/fn, fy/fn (dimensionless) and the spin moment mz in N*mm.

* :func:`simulate` runs a scene (path, TOML text or dict) and returns a :class:`Simulation`:
  the resolved scene, each model's history and the metrics as polars DataFrames, the
  traction fields as numpy arrays; a Python callable runs as a model in-process.
  :func:`simulate_study` runs every point of a study file: a list of them.
* :func:`simulate_wheelrail` runs a wheel–rail scene (wheel and rail profiles, track, wheelset
  cases) and returns a :class:`WheelRailSimulation`: each model's totals and patches per case.
* :func:`check` runs suites through the gate and returns a :class:`Verdict`; :func:`run`
  runs them as ``creepbench run`` does (result folders and the report) and returns a
  :class:`RunReport`. Python callables run in-process as models in both.
* :func:`steady` evaluates a built-in model's steady forces for an (N, 3) array of creepages.
* :class:`Stepper` steps a model with memory (UBA, relaxation, the exact solver) from Python.

Every error the package raises is a :class:`CreepbenchError`: invalid input a
:class:`SceneError` (also a ``ValueError``), a failure while running a :class:`RunError`.
Paths are never defaulted: suites, references, golden data and output folders are given by the
caller (relative paths are relative to the current folder, as on the command line).

See docs/python.md in the repository.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import polars as pl

from . import _creepbench as _cb
from .errors import CreepbenchError, RunError, SceneError

__all__ = [
    "CreepbenchError",
    "Finding",
    "RunError",
    "RunReport",
    "SceneError",
    "Simulation",
    "Stepper",
    "Verdict",
    "WheelRailSimulation",
    "check",
    "loading",
    "model_names",
    "run",
    "simulate",
    "simulate_study",
    "simulate_wheelrail",
    "steady",
    "STEADY_CHUNK_ROWS",
]

Path = Union[str, "os.PathLike[str]"]
Scene = Union[Path, Mapping[str, Any]]
Model = Callable[[Dict[str, Any]], Any]

#: Rows per chunk of :func:`steady`: one model per chunk of this many consecutive rows,
#: whatever the thread count (so the result is the same bit for bit with any thread count).
STEADY_CHUNK_ROWS: int = _cb.STEADY_CHUNK_ROWS

#: The material of the thesis's scenes, used when ``material`` is not given [MPa, -].
DEFAULT_MATERIAL = {"g_mpa": 82000.0, "poisson": 0.28}
#: Rolling at 1 m/s with Courant number 1, used when ``rolling`` is not given [mm/s, -].
DEFAULT_ROLLING = {"v_mm_s": 1000.0, "courant": 1.0}


def model_names() -> List[str]:
    """The built-in models' names, in registry order (``uba``, ``fastsim``, ``contact``, ...)."""
    return list(_cb.model_names())


def loading(scene: Union[Path, Mapping[str, Any]], *, pandas: bool = False) -> Any:
    """The loading of every row of a resolved scene (scene.json as a dict, or the path of a
    scene.json), sampled from its declared ``loading`` as the models' runs sample it: a
    DataFrame with the columns of an external model's ``loading.csv`` (docs/models.md):
    step, t_s [s], cx, cy, cs [1/mm], fn_n [N], mu, then those some row gives of v_mm_s, courant,
    fx_target, fy_target, pen_mm, chi_deg, b1_per_mm ... b6_mm (null where a row leaves one out).
    The initial state (step 0) comes first when the scene has one."""
    if isinstance(scene, Mapping):
        text = json.dumps(scene)
    else:
        with open(os.fspath(scene), encoding="utf-8") as f:
            text = f.read()
    names, columns = _cb.loading(text)
    df = pl.DataFrame({n: c for n, c in zip(names, columns)}).fill_nan(None)
    df = df.with_columns(pl.col("step").cast(pl.Int64))
    return _to_pandas(df) if pandas else df


@dataclass(frozen=True)
class Finding:
    """One comparison's worst point (``check``'s findings, docs/gate.md).

    ``ours`` and ``theirs`` are the two values at the worst ``step`` (None for a scalar),
    ``diff`` = |ours - theirs| (NaN when they cannot be matched), ``allowed`` the tolerance,
    ``gated`` whether it counts for the verdict, ``passed`` whether it is within it,
    ``ratio`` |diff| / allowed as the console prints it.
    """

    scene: str
    solver: str
    against: str
    quantity: str
    step: Optional[int]
    ours: float
    theirs: float
    diff: float
    allowed: float
    gated: bool
    passed: bool
    ratio: str
    note: str


@dataclass(frozen=True)
class Verdict:
    """The gate's verdict: ``passed`` when no gated comparison failed.

    ``findings`` holds every comparison (its worst point), ``failures`` the gated ones that
    missed their tolerance, ``loosened`` the tolerance-file rules that loosen a default gate.
    ``bool(verdict)`` is ``verdict.passed``, so ``assert creepbench.check(...)`` gates in pytest.
    """

    findings: List[Finding]
    loosened: List[str] = field(default_factory=list)

    @property
    def gated(self) -> int:
        return sum(f.gated for f in self.findings)

    @property
    def failures(self) -> List[Finding]:
        return [f for f in self.findings if f.gated and not f.passed]

    @property
    def failed(self) -> int:
        return len(self.failures)

    @property
    def passed(self) -> bool:
        return self.failed == 0

    def __bool__(self) -> bool:
        return self.passed

    def __str__(self) -> str:
        word = "PASS" if self.passed else "FAIL"
        lines = [f"{word}: {self.gated} gated comparisons, {self.failed} failed"]
        for f in self.failures[:20]:
            at = "" if f.step is None else f" step {f.step}"
            lines.append(
                f"  {f.scene} {f.solver} {f.quantity}{at} vs {f.against}: "
                f"ours {f.ours!r}, theirs {f.theirs!r}, |diff| {f.diff:.3g} > allowed {f.allowed:.3g}"
            )
        return "\n".join(lines)

    def to_frame(self) -> pl.DataFrame:
        """The findings as a polars DataFrame (one row each)."""
        rows = [f.__dict__ for f in self.findings]
        return pl.DataFrame(rows, infer_schema_length=None) if rows else pl.DataFrame()


def _verdict(findings: Sequence[Mapping[str, Any]], loosened: Sequence[str]) -> Verdict:
    return Verdict([Finding(**f) for f in findings], list(loosened))


@dataclass(frozen=True)
class RunReport:
    """What :func:`run` made, as ``creepbench run`` prints it: ``results`` (the result folders'
    folder), ``report`` (the path of validation.md; figures/, tables/ and results.csv beside
    it), the gates' ``verdict`` over the report's findings and the ``oscillating`` histories.
    ``passed``, ``failed``, ``findings`` and ``failures`` are the verdict's; ``bool(report)`` is
    ``report.passed``."""

    results: str
    report: str
    verdict: Verdict
    oscillating: List[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return self.verdict.passed

    @property
    def failed(self) -> int:
        return self.verdict.failed

    @property
    def findings(self) -> List[Finding]:
        return self.verdict.findings

    @property
    def failures(self) -> List[Finding]:
        return self.verdict.failures

    def __bool__(self) -> bool:
        return self.passed

    def __str__(self) -> str:
        return f"gates: {self.verdict}\nreport: {self.report}"


def _to_pandas(df: pl.DataFrame) -> Any:
    """A polars DataFrame as a pandas one, column by column through numpy (no pyarrow): floats
    and integers keep their bits, an integer column with nulls becomes pandas' nullable Int64."""
    import pandas as pd

    columns: Dict[str, Any] = {}
    for name in df.columns:
        col = df[name]
        if col.dtype.is_integer() and col.null_count() > 0:
            columns[name] = pd.array(col.to_list(), dtype="Int64")
        elif col.dtype == pl.Utf8:
            columns[name] = np.array(col.to_list(), dtype=object)
        else:
            columns[name] = col.to_numpy()
    return pd.DataFrame(columns)


class Simulation:
    """One scene's results, as ``creepbench simulate`` writes them to ``out/<name>/``.

    ``scene`` is the resolved scene (scene.json as a dict), ``histories[model]`` each model's
    history (a polars DataFrame with the columns of ``<model>.csv``: step, t_s [s], cx, cy,
    cs [1/mm], fn_n [N], fx_over_fn, fy_over_fn, mu, the model's extra columns, mz_nmm [N*mm]),
    ``metrics`` the metrics (solver, metric, value, step), ``fields`` the traction fields
    (with ``fields=True``: per built-in model ``step`` and ``pn_mpa``, ``px_mpa``, ``py_mpa``
    [MPa] as (steps, my, mx) arrays; ``x_mm``, ``y_mm`` the element centres).
    """

    def __init__(self, raw: Any, pandas: bool = False) -> None:
        self._raw = raw
        self.name: str = raw.name
        self.solvers: List[str] = list(raw.solvers)
        self.warnings: List[str] = list(raw.warnings)
        files = dict(raw.files())
        self.scene: Dict[str, Any] = json.loads(files["scene.json"])
        self.histories: Dict[str, Any] = {}
        for s in self.solvers:
            names, columns = raw.history(s)
            df = pl.DataFrame({n: c for n, c in zip(names, columns)})
            df = df.with_columns(pl.col("step").cast(pl.Int64))
            self.histories[s] = _to_pandas(df) if pandas else df
        metrics = pl.DataFrame(
            [tuple(m) for m in raw.metrics()],
            schema={"solver": pl.Utf8, "metric": pl.Utf8, "value": pl.Float64, "step": pl.Int64},
            orient="row",
        )
        self.metrics: Any = _to_pandas(metrics) if pandas else metrics
        self.fields: Dict[str, Any] = dict(raw.fields())

    def files(self) -> Dict[str, str]:
        """The result folder's files as the CLI writes them: ``{file name: text}``."""
        return dict(self._raw.files())

    def save(self, folder: Union[str, "os.PathLike[str]"]) -> str:
        """Write the result folder ``folder/<name>/`` as ``creepbench simulate --out folder``
        does (a baseline for :meth:`check`); returns its path."""
        return os.fspath(self._raw.save(os.fspath(folder)))

    def check(
        self,
        *,
        reference: Path,
        golden: Optional[Path] = None,
        against: Optional[Path] = None,
        tolerances: Sequence[Path] = (),
    ) -> Verdict:
        """Gate this scene's results as ``creepbench check`` does: every model (in-process
        ones included) against the references in the folder ``reference`` (CONTACT, the
        thesis: the repository's ``reference/``) and, if given, against a baseline: the
        ``golden`` folder, or ``against``, a folder of earlier results (e.g. written by
        :meth:`save`), each history column and metric within the default tolerances
        (docs/gate.md), with the tolerance files ``tolerances`` applied."""
        _one_baseline(golden, against, required=False)
        baseline = golden if against is None else against
        findings, loosened = self._raw.gate(
            os.fspath(reference),
            None if baseline is None else os.fspath(baseline),
            against is not None,
            [os.fspath(t) for t in tolerances],
        )
        return _verdict(findings, loosened)

    def __repr__(self) -> str:
        return f"Simulation({self.name!r}, solvers={self.solvers})"


def _one_baseline(golden: Optional[Path], against: Optional[Path], required: bool) -> None:
    """Refuse both baselines at once (and, when ``required``, neither)."""
    given = f"golden={golden!r}, against={against!r}"
    if golden is not None and against is not None:
        raise SceneError(f"invalid input: `golden, against` = {given}: allowed: one of them", "golden, against", given, "one of them")
    if required and golden is None and against is None:
        raise SceneError(
            f"invalid input: `golden, against` = {given}: allowed: a golden folder or a results folder",
            "golden, against",
            given,
            "a golden folder or a results folder",
        )


def _kind(scene: Any) -> Tuple[str, Any]:
    """How a scene is given: a path (a string that names an existing file, or any path-like),
    TOML text (any other string holding ``=`` or a line break), or a dict."""
    if isinstance(scene, Mapping):
        return "table", dict(scene)
    if isinstance(scene, os.PathLike):
        return "path", os.fspath(scene)
    if isinstance(scene, str):
        if os.path.exists(scene) or not ("=" in scene or "\n" in scene):
            return "path", scene
        return "toml", scene
    kind = type(scene).__name__
    raise SceneError(
        f"invalid input: `scene` = {kind}: allowed: a path, TOML text or a dict", "scene", kind, "a path, TOML text or a dict"
    )


def _columns(out: Any) -> Tuple[List[str], List[np.ndarray]]:
    """An in-process model's output (polars or pandas DataFrame, or a dict of columns) as
    column names and float64 arrays."""
    if isinstance(out, pl.DataFrame):
        names = list(out.columns)
        return names, [out[n].cast(pl.Float64).to_numpy() for n in names]
    if isinstance(out, Mapping):
        names = [str(k) for k in out.keys()]
        return names, [np.ascontiguousarray(np.asarray(v, dtype=np.float64).ravel()) for v in out.values()]
    if hasattr(out, "columns"):  # pandas
        names = [str(c) for c in out.columns]
        return names, [np.ascontiguousarray(np.asarray(out[c], dtype=np.float64)) for c in out.columns]
    raise TypeError(f"an in-process model returns a DataFrame or a dict of columns, not {type(out).__name__}")


def _adapt(model: Model) -> Callable[[str], Tuple[List[str], List[np.ndarray]]]:
    def call(scene_json: str) -> Tuple[List[str], List[np.ndarray]]:
        names, columns = _columns(model(json.loads(scene_json)))
        return names, [np.ascontiguousarray(c, dtype=np.float64) for c in columns]

    return call


def simulate(
    scene: Scene,
    solvers: Optional[Sequence[str]] = None,
    *,
    models: Optional[Mapping[str, Model]] = None,
    fields: bool = False,
    pandas: bool = False,
) -> Simulation:
    """Run a scene as ``creepbench simulate`` does and return its :class:`Simulation`.

    ``scene``: a path to a scene file, TOML text, or a dict of the same keys
    (docs/scene-format.md; units mm, N, MPa, s); a string is a path when it names an existing
    file or holds neither ``=`` nor a line break, TOML text otherwise. A study file is refused
    (:func:`simulate_study` runs one). ``solvers`` narrows
    the scene's model list. ``models`` maps names to Python callables run in-process as
    models: each is called with the resolved scene (scene.json as a dict; its ``history`` lists
    the loading of every row) and returns the history as a DataFrame or a dict of columns
    ``step, t_s, cx, cy, cs, fn_n, fx_over_fn, fy_over_fn[, mu, ...]``, validated as an
    external model's output is; the scene's ``solvers`` must list the name. ``fields=True``
    keeps the built-in models' traction fields (they run a second time). ``pandas=True`` gives
    pandas DataFrames. Invalid input raises :class:`SceneError` (``field``, ``value``,
    ``allowed``), a failing model :class:`CreepbenchError`.
    """
    kind, value = _kind(scene)
    (raw,) = _cb.simulate(kind, value, list(solvers or []), _models(models), fields, False)
    return Simulation(raw, pandas)


def simulate_study(
    study: Path,
    solvers: Optional[Sequence[str]] = None,
    *,
    models: Optional[Mapping[str, Model]] = None,
    fields: bool = False,
    pandas: bool = False,
) -> List[Simulation]:
    """Run every point of a study file (a TOML file with a ``[study]`` table, docs/studies.md)
    as ``creepbench simulate`` does: one :class:`Simulation` per point, in the study's order.
    The other arguments as in :func:`simulate`; a scene file is refused."""
    raw = _cb.simulate("path", os.fspath(study), list(solvers or []), _models(models), fields, True)
    return [Simulation(r, pandas) for r in raw]


class WheelRailSimulation:
    """One wheel–rail scene's results, as ``creepbench simulate`` writes them to ``out/<name>/``.

    ``totals[model]``: ``<model>.csv``, one row per case (``contact_case``, the wheelset's
    position and velocity, the total forces on the rail in track and wheelset coordinates
    ``fx_tr_n`` … ``fz_ws_n`` [N], the patch count); ``patches[model]``: ``<model>_patches.csv``,
    one row per case and patch (``contact_case``, ``patch`` from 1 in CONTACT's order, the
    reference point ``ycp_r_mm`` …, the contact angle ``deltcp_rad``, the creepages ``cksi``,
    ``ceta``, ``cphi_per_mm`` [1/mm], ``fn_n``, ``fx_n``, ``fs_n`` [N], ``mn_nmm`` [N*mm] and the
    element counts). Columns, signs and frames: docs/wheelrail.md and docs/scene-format.md.
    """

    def __init__(self, raw: Any, pandas: bool = False) -> None:
        import io

        self._raw = raw
        self.name: str = raw.name
        self.solvers: List[str] = list(raw.solvers)
        files = dict(raw.files())

        def frame(text: str) -> Any:
            df = pl.read_csv(io.StringIO(text), infer_schema_length=None)
            return _to_pandas(df) if pandas else df

        self.totals: Dict[str, Any] = {s: frame(files[f"{s}.csv"]) for s in self.solvers}
        self.patches: Dict[str, Any] = {s: frame(files[f"{s}_patches.csv"]) for s in self.solvers}

    def files(self) -> Dict[str, str]:
        """The result folder's files as the CLI writes them: ``{file name: text}``."""
        return dict(self._raw.files())

    def save(self, folder: Union[str, "os.PathLike[str]"]) -> str:
        """Write the result folder ``folder/<name>/`` as ``creepbench simulate --out folder``
        does; returns its path."""
        return os.fspath(self._raw.save(os.fspath(folder)))

    def __repr__(self) -> str:
        return f"WheelRailSimulation({self.name!r}, solvers={self.solvers})"


def simulate_wheelrail(
    scene: Scene,
    solvers: Optional[Sequence[str]] = None,
    *,
    pandas: bool = False,
) -> WheelRailSimulation:
    """Run a wheel–rail scene (a ``[wheelrail]`` table: profiles, track, wheelset cases;
    docs/scene-format.md) as ``creepbench simulate`` does and return its
    :class:`WheelRailSimulation`. ``scene``: a path, TOML text or a dict, as in :func:`simulate`
    (the profile paths of a scene file are taken from its folder, those of TOML text or a dict
    from the current folder). ``solvers`` narrows the scene's model list. Invalid input raises
    :class:`SceneError`, a case without a solution too (its message names the case)."""
    kind, value = _kind(scene)
    return WheelRailSimulation(_cb.simulate_wheelrail(kind, value, list(solvers or [])), pandas)


Suites = Union[Path, Sequence[Path]]


def _suites(suite: Suites) -> List[str]:
    return [os.fspath(suite)] if isinstance(suite, (str, os.PathLike)) else [os.fspath(s) for s in suite]


def _models(models: Optional[Mapping[str, Model]]) -> List[Tuple[str, Any]]:
    return [(str(n), _adapt(f)) for n, f in (models or {}).items()]


def check(
    suite: Suites,
    *,
    reference: Path,
    golden: Optional[Path] = None,
    against: Optional[Path] = None,
    tolerances: Sequence[Path] = (),
    strict: bool = False,
    models: Optional[Mapping[str, Model]] = None,
) -> Verdict:
    """Run suites (folders of scenes, e.g. the repository's ``scenes/thesis``) through the gate
    as ``creepbench check --suite`` does: every result against the references in the folder
    ``reference`` (the repository's ``reference/``) and a baseline, either ``golden`` (blessed
    results, the repository's ``golden/``) or ``against`` (a previous results folder), the
    tolerance files applied (``strict``: refuse any loosening). ``models`` maps names to
    Python callables run in-process as models (as in :func:`simulate`) on every scene whose
    ``solvers`` lists the name, validated, compared and gated as an external model is."""
    _one_baseline(golden, against, required=True)
    findings, loosened = _cb.check(
        _suites(suite),
        os.fspath(reference),
        os.fspath(golden if golden is not None else against),
        None if against is None else os.fspath(against),
        [os.fspath(t) for t in tolerances],
        strict,
        _models(models),
    )
    return _verdict(findings, loosened)


def run(
    suite: Suites,
    *,
    results: Path,
    report: Path,
    reference: Path,
    golden: Path,
    fits: Optional[Path] = None,
    models: Optional[Mapping[str, Model]] = None,
) -> RunReport:
    """Run suites as ``creepbench run --suite ... --results ... --report ...`` does: each
    scene's result folder in ``results``, then the report (validation.md, figures, tables,
    results.csv) in ``report`` from this run's results alone (another run's scene folders in
    ``results`` are left out and named on standard error), gated against ``golden`` and the references
    with each suite's tolerance file; the fit files of the folder ``fits`` run too when given.
    ``models`` as in :func:`check`: an in-process model's history is written, compared and
    reported as an external model's. Returns a :class:`RunReport`."""
    out, md, findings, loosened, oscillating = _cb.run(
        _suites(suite),
        os.fspath(reference),
        os.fspath(golden),
        os.fspath(results),
        os.fspath(report),
        None if fits is None else os.fspath(fits),
        _models(models),
    )
    return RunReport(os.fspath(out), os.fspath(md), _verdict(findings, loosened), list(oscillating))


def _table(
    model: str,
    contact: Mapping[str, Any],
    grid: Mapping[str, Any],
    material: Optional[Mapping[str, Any]],
    rolling: Optional[Mapping[str, Any]],
    model_options: Optional[Mapping[str, Any]],
) -> Dict[str, Any]:
    table: Dict[str, Any] = {
        "name": "python",
        "solvers": [model],
        "contact": dict(contact),
        "material": dict(material or DEFAULT_MATERIAL),
        "grid": dict(grid),
        "rolling": dict(rolling or DEFAULT_ROLLING),
        # Only resolves the problem: the creepages come from the caller.
        "creepage": {"kind": "sweep", "from": 0.0, "to": 0.01, "points": 2},
    }
    if model_options:
        table["model"] = dict(model_options)
    return table


def steady(
    model: str,
    creepages: Any,
    *,
    contact: Mapping[str, Any],
    grid: Mapping[str, Any],
    material: Optional[Mapping[str, Any]] = None,
    model_options: Optional[Mapping[str, Any]] = None,
) -> np.ndarray:
    """Steady rolling forces of a built-in model for many creepages in one call.

    ``creepages``: an (N, 3) array of (cx, cy, cs [1/mm]). ``contact``: the scene's
    ``[contact]`` keys (``a_mm``, ``b_mm``, ``fn_n`` [N], ``mu``), ``grid``: ``[grid]``
    (``mx``, ``my``), ``material``: ``[material]`` (default G 82000 MPa, poisson 0.28),
    ``model_options``: ``[model]``. Returns an (N, 3) float64 array of fx/fn, fy/fn and
    mz [N*mm]. The work runs in Rust on every core, without the GIL: one model per chunk of
    :data:`STEADY_CHUNK_ROWS` consecutive rows, whatever the thread count, so the result is
    the same bit for bit with any thread count and run to run. Every model but the exact
    solver (``contact``) solves each row on its own: the result equals the scene's sweep over
    these creepages bit for bit. The exact solver starts each solve from the previous row's
    solution, as the CLI's sweep does: within the first chunk it is the sweep bit for bit;
    from each later chunk's first row on it starts afresh (as the sweep's first point), and
    those rows agree with the sweep's to the solver's tolerance (``contact_solver.tolerance``,
    1e-7 on the traction): the tests hold fx/fn, fy/fn and mz / (mu fn a) to 1e-9 over a
    300-point sweep (measured 6e-11 in fx/fn).
    """
    c = np.ascontiguousarray(creepages, dtype=np.float64)
    if c.ndim == 1 and c.shape[0] == 3:
        c = c.reshape(1, 3)
    table = _table(model, contact, grid, material, None, model_options)
    return _cb.steady(model, c, table)


class Stepper:
    """A built-in model stepped one time step at a time (for a multibody loop).

    ``Stepper("uba", contact=dict(a_mm=8.56, b_mm=4.08, fn_n=1e5, mu=0.4), grid=dict(mx=22,
    my=22))``; ``rolling`` (``v_mm_s`` [mm/s], ``courant``) sets the time step
    ``dt_s = courant dx / v``. Each :meth:`step` rolls one time step from the model's state;
    the contact is reloaded when ``fn_n`` or ``mu`` changes.
    """

    def __init__(
        self,
        model: str,
        *,
        contact: Mapping[str, Any],
        grid: Mapping[str, Any],
        material: Optional[Mapping[str, Any]] = None,
        rolling: Optional[Mapping[str, Any]] = None,
        model_options: Optional[Mapping[str, Any]] = None,
    ) -> None:
        self._inner = _cb.Stepper(model, _table(model, contact, grid, material, rolling, model_options))

    @property
    def model(self) -> str:
        return self._inner.model

    @property
    def dt_s(self) -> float:
        """The time step [s]."""
        return self._inner.dt_s

    @property
    def steps(self) -> int:
        """Time steps taken so far."""
        return self._inner.steps

    def step(self, cx: float, cy: float, cs: float, fn_n: float, mu: float) -> Tuple[float, float, float]:
        """One time step to creepages cx, cy, spin cs [1/mm] at load fn_n [N], friction mu:
        returns (fx/fn, fy/fn, mz [N*mm])."""
        return self._inner.step(float(cx), float(cy), float(cs), float(fn_n), float(mu))

    def steady(self, cx: float, cy: float, cs: float, fn_n: float, mu: float) -> Tuple[float, float, float]:
        """Steady rolling at these creepages (the model's state becomes the steady one):
        returns (fx/fn, fy/fn, mz [N*mm])."""
        return self._inner.steady(float(cx), float(cy), float(cs), float(fn_n), float(mu))

    def field(self) -> Optional[Dict[str, np.ndarray]]:
        """The last solve's traction field, if the model has one: ``pn_mpa``, ``px_mpa``,
        ``py_mpa`` [MPa] as (my, mx) arrays."""
        f = self._inner.field()
        return None if f is None else dict(f)
