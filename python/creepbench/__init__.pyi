"""Type stubs of creepbench (units in the names: mm, N, MPa, s; cs in 1/mm; mz in N*mm)."""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt
import polars as pl

_Path = Union[str, "os.PathLike[str]"]
Scene = Union[_Path, Mapping[str, Any]]
Model = Callable[[Dict[str, Any]], Any]

DEFAULT_MATERIAL: Dict[str, float]
DEFAULT_ROLLING: Dict[str, float]
STEADY_CHUNK_ROWS: int
"""Rows per chunk of ``steady`` (fixed: the result is the same with any thread count)."""

class SceneError(ValueError):
    """Invalid input (a scene key, an argument): exactly the CLI's message."""

    field: str
    """The dotted field, e.g. ``contact.fn_n`` (prefixed by the file for a scene file)."""
    value: str
    """The value as given."""
    allowed: str
    """What is allowed."""

class CreepbenchError(RuntimeError):
    """A model, the gate or a file failed (an in-process model's exception is ``__cause__``)."""

def model_names() -> List[str]:
    """The built-in models' names, in registry order."""

class Finding:
    """One comparison's worst point."""

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

class Verdict:
    """The gate's verdict; ``bool(verdict)`` is ``verdict.passed``."""

    findings: List[Finding]
    loosened: List[str]
    @property
    def gated(self) -> int: ...
    @property
    def failures(self) -> List[Finding]: ...
    @property
    def failed(self) -> int: ...
    @property
    def passed(self) -> bool: ...
    def __bool__(self) -> bool: ...
    def to_frame(self) -> pl.DataFrame: ...

class RunReport:
    """What ``run`` made; ``bool(report)`` is ``report.passed``."""

    results: str
    """The folder of the result folders."""
    report: str
    """The path of validation.md."""
    verdict: Verdict
    oscillating: List[str]
    @property
    def passed(self) -> bool: ...
    @property
    def failed(self) -> int: ...
    @property
    def findings(self) -> List[Finding]: ...
    @property
    def failures(self) -> List[Finding]: ...
    def __bool__(self) -> bool: ...

class Simulation:
    """One scene's results, as ``creepbench simulate`` writes them."""

    name: str
    solvers: List[str]
    warnings: List[str]
    scene: Dict[str, Any]
    """The resolved scene (scene.json)."""
    histories: Dict[str, pl.DataFrame]
    """Per model: step, t_s [s], cx, cy, cs [1/mm], fn_n [N], fx_over_fn, fy_over_fn, mu, extra columns, mz_nmm [N*mm]."""
    metrics: pl.DataFrame
    """solver, metric, value, step."""
    fields: Dict[str, Any]
    """With ``fields=True``: per built-in model step and pn_mpa, px_mpa, py_mpa [MPa] (steps, my, mx); x_mm, y_mm."""
    def files(self) -> Dict[str, str]: ...
    def save(self, folder: _Path) -> str: ...
    def check(
        self,
        reference: _Path = "reference",
        golden: Optional[_Path] = None,
        against: Optional[_Path] = None,
        tolerances: Sequence[_Path] = (),
    ) -> Verdict: ...

def simulate(
    scene: Scene,
    solvers: Optional[Sequence[str]] = None,
    *,
    models: Optional[Mapping[str, Model]] = None,
    fields: bool = False,
    pandas: bool = False,
) -> Any:
    """Run a scene (path, TOML text or dict): a Simulation (a list for a study file of several points)."""

def check(
    suite: Union[_Path, Sequence[_Path]] = "scenes/thesis",
    *,
    reference: _Path = "reference",
    golden: _Path = "golden",
    against: Optional[_Path] = None,
    tolerances: Sequence[_Path] = (),
    strict: bool = False,
    models: Optional[Mapping[str, Model]] = None,
) -> Verdict:
    """Run suites through the gate as ``creepbench check`` does (``models``: in-process models where a scene lists them)."""

def run(
    suite: Union[_Path, Sequence[_Path]] = "scenes/thesis",
    *,
    results: _Path = "out/results",
    report: _Path = "out/report",
    reference: _Path = "reference",
    golden: _Path = "golden",
    fits: Optional[_Path] = None,
    models: Optional[Mapping[str, Model]] = None,
) -> RunReport:
    """Run suites as ``creepbench run`` does: result folders, the report and the gates' verdict."""

def steady(
    model: str,
    creepages: npt.ArrayLike,
    *,
    contact: Mapping[str, float],
    grid: Mapping[str, int],
    material: Optional[Mapping[str, float]] = None,
    model_options: Optional[Mapping[str, Any]] = None,
) -> npt.NDArray[np.float64]:
    """(N, 3) creepages (cx, cy, cs [1/mm]) -> (N, 3) fx/fn, fy/fn, mz [N*mm]; in Rust, in parallel (fixed chunks of STEADY_CHUNK_ROWS rows), without the GIL."""

class Stepper:
    """A built-in model stepped one time step at a time."""

    def __init__(
        self,
        model: str,
        *,
        contact: Mapping[str, float],
        grid: Mapping[str, int],
        material: Optional[Mapping[str, float]] = None,
        rolling: Optional[Mapping[str, float]] = None,
        model_options: Optional[Mapping[str, Any]] = None,
    ) -> None: ...
    @property
    def model(self) -> str: ...
    @property
    def dt_s(self) -> float: ...
    @property
    def steps(self) -> int: ...
    def step(self, cx: float, cy: float, cs: float, fn_n: float, mu: float) -> Tuple[float, float, float]:
        """One time step: (fx/fn, fy/fn, mz [N*mm])."""
    def steady(self, cx: float, cy: float, cs: float, fn_n: float, mu: float) -> Tuple[float, float, float]:
        """Steady rolling: (fx/fn, fy/fn, mz [N*mm])."""
    def field(self) -> Optional[Dict[str, npt.NDArray[np.float64]]]:
        """The last solve's pn_mpa, px_mpa, py_mpa [MPa] as (my, mx) arrays, if the model has a field."""
