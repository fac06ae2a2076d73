"""Time creepbench.steady on FASTSIM at 22 x 22 (docs/python.md, "Speed").

    python examples/steady_speed.py [N]          # default N = 100000; run from the repository

Prints the time per creepage for N copies of the creepage the Rust benchmark uses
(`cargo bench -p creepbench-benches --bench solvers -- fastsim_creepage/22`: sine_f30_mu10's sample 3) and for N random
creepages, and a call's fixed overhead (N = 1). RAYON_NUM_THREADS=1 compares with the one-thread
benchmark.
"""

from __future__ import annotations

import sys
import time

import numpy as np

import creepbench


def best_of(calls: int, f) -> float:
    """The shortest of `calls` wall times of f() [s]."""
    times = []
    for _ in range(calls):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    sims = creepbench.simulate_study("scenes/thesis/study_sine_grid.toml", ["fastsim"])
    sim = next(s for s in sims if s.name == "sine_f30_mu10")
    row = sim.histories["fastsim"].row(3, named=True)
    contact = {"a_mm": sim.scene["a_mm"], "b_mm": sim.scene["b_mm"], "fn_n": row["fn_n"], "mu": row["mu"]}
    grid = {"mx": 22, "my": 22}
    options = {k: sim.scene["model"][k] for k in ("flexibility", "coefficients", "pressure")}

    def run(c):
        return lambda: creepbench.steady("fastsim", c, contact=contact, grid=grid, model_options=options)

    same = np.tile([row["cx"], row["cy"], row["cs"]], (n, 1))
    rng = np.random.default_rng(1)
    random = np.column_stack([rng.uniform(-0.01, 0.01, n), rng.uniform(-0.01, 0.01, n), rng.uniform(-0.001, 0.001, n)])
    print(f"FASTSIM 22x22, N = {n}: {best_of(5, run(same)) / n * 1e6:.3f} us per creepage (the benchmark's creepage)")
    print(f"FASTSIM 22x22, N = {n}: {best_of(3, run(random)) / n * 1e6:.3f} us per creepage (random creepages)")
    one = same[:1]
    print(f"fixed overhead (N = 1): {best_of(2000, run(one)) * 1e6:.1f} us")


if __name__ == "__main__":
    main()
