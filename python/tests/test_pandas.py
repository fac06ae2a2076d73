"""pandas on request (issue 34 item 2): simulate(..., pandas=True) gives the polars frames'
columns, values (bit for bit) and missing values as pandas DataFrames."""

import numpy as np
import pandas as pd
import polars as pl
import pytest

import creepbench
from conftest import ROOT


def same_frame(pd_frame, pl_frame):
    assert isinstance(pd_frame, pd.DataFrame)
    assert list(pd_frame.columns) == pl_frame.columns and len(pd_frame) == pl_frame.height
    for c in pl_frame.columns:
        ours, theirs = pd_frame[c], pl_frame[c]
        if theirs.dtype == pl.Float64:
            assert ours.dtype == np.float64, c
            assert np.array_equal(ours.to_numpy().view(np.int64), theirs.to_numpy().view(np.int64)), c
        elif theirs.dtype.is_integer():
            missing = theirs.is_null().to_list()
            assert ours.isna().tolist() == missing, c
            assert [None if m else int(v) for v, m in zip(ours, missing)] == theirs.to_list(), c
        else:
            assert ours.tolist() == theirs.to_list(), c


@pytest.mark.parametrize("scene", ["step_cx001", "steady_fastsim_g22"])
def test_pandas_frames_equal_the_polars_ones(scene):
    path = ROOT / "scenes" / "thesis" / f"{scene}.toml"
    by_polars = creepbench.simulate(path)
    by_pandas = creepbench.simulate(path, pandas=True)
    assert by_pandas.solvers == by_polars.solvers
    for m in by_polars.solvers:
        same_frame(by_pandas.histories[m], by_polars.histories[m])
        assert by_pandas.histories[m]["step"].dtype == np.int64
    same_frame(by_pandas.metrics, by_polars.metrics)
    # The step scene's scalar metrics (steady value, settling time) have no step: missing in both.
    assert (by_polars.metrics["step"].null_count() > 0) == (scene == "step_cx001")
