#!/usr/bin/env python3
"""Assemble a falling-friction reference set (the format of reference/contact_friction) from
CONTACT runs of exported scenes: how reference/contact_friction_hidden was made.

Usage (from the repository root):
    assemble_friction_reference.py RUNS SCENES OUT

RUNS/<run>/<case>/<case>.csv is `scripts/contact_to_csv.py <case>.inp --csv <case>.csv` of one
CONTACT run, <run> one of
    std0, stdp, stdm        CONTACT as built (slip-velocity stop 1e-3) with INISLP 0, +1, -1
    tight0, tightp, tightm  the build whose stop is 1e-7 (m_stang.f90 line 579) with INISLP 0, +1, -1
(each the input `creepbench export contact SCENES/<case>.toml` with only its INISLP lines changed;
RUNS/std0/<case>/wall.txt the run's wall time [s]). SCENES holds the scenes (law, memory, contact,
grid, speed), OUT gets cases.csv and one <case>.csv per case: std0's rows (the published values)
in the column order of reference/contact_friction with `fx_over_fn_tight`, `fy_over_fn_tight` of
tightp (as reference/contact_friction), then `n_adhesion_tight`, `n_slip_tight`,
`converged_tight` of tightp. The gate of a case is decided from the CONTACT runs alone:
    no     the tight runs with INISLP 0, +1, -1 differ by more than 1e-5 in fx/fn or fy/fn
           (several solutions), or a run did not converge;
    tight  one solution, but the published values are more than 2e-4 off the tight ones
           (CONTACT's own iteration error exceeds the published values' tolerance);
    yes    otherwise.
"""
import csv
import math
import os
import sys
import tomllib

ORDER = ["step", "t_s", "v_mm_s", "cx", "cy", "cs", "fn_n", "fx_n", "fy_n", "mz_nmm", "fx_over_fn", "fy_over_fn",
         "n_adhesion", "n_slip", "mu_min", "mu_max", "s_max_mm_s", "veldep_its", "converged"]
CASE_COLUMNS = ["name", "kind", "gate", "law", "law_name", "fkin", "f1", "sabsh1_mm_s", "f2", "sabsh2_mm_s", "fstat",
                "memdst_mm", "mem_s0_mm_s", "v_mm_s", "v_min_mm_s", "v_max_mm_s", "geometry", "a_mm", "b_mm",
                "a1_per_mm", "b1_per_mm", "fn_n", "mx", "my", "scale", "dx_mm", "dy_mm", "dq_mm", "courant", "init",
                "n_rows", "solver", "max_veldep_its", "all_converged", "dev_inislp_plus", "dev_inislp_minus",
                "dev_tight", "spread_tight", "steps_differing", "contact_wall_s", "note"]
LAWS = {"linear": 2, "rational": 3, "exponential": 4}
SPREAD_LIMIT, PUBLISHED_TOL = 1e-5, 2e-4


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def elliptic_ke(m):
    """Complete elliptic integrals K(m), E(m) (parameter m = k^2) by the AGM."""
    a, b, c = 1.0, math.sqrt(1.0 - m), math.sqrt(m)
    s, p = 0.5 * c * c, 1.0
    while abs(c) > 1e-16:
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        p *= 2
        s += 0.5 * p * c * c
    k = math.pi / (2 * a)
    return k, k * (1 - s)


def hertz_curvatures(a, b, fn, g, nu):
    """A1, B1 [1/mm] of the Hertzian contact with semi-axes a (x), b (y) under fn, both bodies (g, nu)."""
    estar = g / (1 - nu)
    big, small = (b, a) if a < b else (a, b)
    m = 1 - (small / big) ** 2
    k, e = elliptic_ke(m)
    c = 3 * fn / (2 * math.pi * a * b) * small / (estar * m * big ** 2)
    along_big, along_small = c * (k - e), c * ((big / small) ** 2 * e - k)
    return (along_small, along_big) if a < b else (along_big, along_small)


def max_diff(a, b, keys=("fx_over_fn", "fy_over_fn")):
    worst, at = 0.0, []
    for x, y in zip(a, b):
        assert x["step"] == y["step"]
        d = max(abs(float(x[k]) - float(y[k])) for k in keys)
        worst = max(worst, d)
        at.append((int(x["step"]), d))
    return worst, at


def g(v):
    return f"{v:.3g}"


def main(runs, scenes, out):
    os.makedirs(out, exist_ok=True)
    names = sorted(f[:-5] for f in os.listdir(scenes) if f.endswith(".toml"))
    table = []
    for name in names:
        sc = tomllib.load(open(os.path.join(scenes, name + ".toml"), "rb"))
        note = open(os.path.join(scenes, name + ".toml")).read().splitlines()[1].lstrip("# ")
        run = {r: rows(os.path.join(runs, r, name, name + ".csv")) for r in
               ["std0", "stdp", "stdm", "tight0", "tightp", "tightm"]}
        pub, tight = run["std0"], run["tightp"]
        assert all(len(run[r]) == len(pub) for r in run), name
        with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(ORDER + ["fx_over_fn_tight", "fy_over_fn_tight", "n_adhesion_tight", "n_slip_tight",
                                "converged_tight"])
            for p, t in zip(pub, tight):
                assert p["step"] == t["step"]
                w.writerow([p[k] for k in ORDER] + [t["fx_over_fn"], t["fy_over_fn"], t["n_adhesion"], t["n_slip"],
                                                     t["converged"]])
        converged = all(r["converged"] == "1" for k in run for r in run[k])
        spread = max(max_diff(tight, run["tightm"])[0], max_diff(tight, run["tight0"])[0])
        dev_tight, per_step = max_diff(pub, tight)
        gate = "no" if (spread > SPREAD_LIMIT or not converged) else ("tight" if dev_tight > PUBLISHED_TOL else "yes")
        differing = [s for s, d in per_step if d > PUBLISHED_TOL] if gate != "yes" else []
        if gate == "tight":
            worst = max(per_step, key=lambda sd: sd[1])
            note = (f"GATED AGAINST THE TIGHT VALUES ONLY: CONTACT's published values are up to {dev_tight:.3g} off "
                    f"its tight ones (step {worst[0]}; more than {PUBLISHED_TOL:g} in {len(differing)} rows), one "
                    f"solution per step (tight INISLP 0, +1, -1 within {spread:.2g}). " + note)
        elif gate == "no":
            note = f"NOT GATED: several solutions (tight INISLP runs {spread:.3g} apart) or a run not converged. " + note
        c, fr, gr, ro = sc["contact"], sc["friction"], sc["grid"], sc["rolling"]
        f2 = fr.get("f2", 0.0)
        mx, my, scale = gr["mx"], gr["my"], gr.get("scale", 1.0)
        dx, dy = 2 * c["a_mm"] * scale / mx, 2 * c["b_mm"] * scale / my
        a1, b1 = hertz_curvatures(c["a_mm"], c["b_mm"], c["fn_n"], 82000.0, 0.28)
        speeds = [float(r["v_mm_s"]) for r in pub]
        transient = sc["creepage"]["kind"] != "sweep"
        table.append({
            "name": name, "kind": "transient" if transient else "steady", "gate": gate,
            "law": LAWS[fr["law"]], "law_name": fr["law"], "fkin": fr["fkin"], "f1": fr["f1"],
            "sabsh1_mm_s": fr["sabsh1_mm_s"], "f2": f2, "sabsh2_mm_s": fr.get("sabsh2_mm_s", 1000.0) if f2 else 1000.0,
            "fstat": round(fr["fkin"] + fr["f1"] + f2, 12), "memdst_mm": fr.get("memory_mm", 0),
            "mem_s0_mm_s": fr.get("memory_s0_mm_s", 0), "v_mm_s": speeds[0], "v_min_mm_s": min(speeds),
            "v_max_mm_s": max(speeds), "geometry": "hertz", "a_mm": c["a_mm"], "b_mm": c["b_mm"],
            "a1_per_mm": f"{a1:.10g}", "b1_per_mm": f"{b1:.10g}", "fn_n": c["fn_n"], "mx": mx, "my": my,
            "scale": scale, "dx_mm": f"{dx:.10g}", "dy_mm": f"{dy:.10g}", "dq_mm": f"{dx * ro['courant']:.10g}",
            "courant": ro["courant"], "init": sc.get("init", {}).get("kind", "none") if transient else "none",
            "n_rows": len(pub), "solver": "G=4 INISLP=0 OMGSLP=0.5",
            "max_veldep_its": max(int(r["veldep_its"]) for r in pub), "all_converged": "yes" if converged else "no",
            "dev_inislp_plus": g(max_diff(pub, run["stdp"])[0]), "dev_inislp_minus": g(max_diff(pub, run["stdm"])[0]),
            "dev_tight": g(dev_tight), "spread_tight": g(spread), "steps_differing": " ".join(map(str, differing)),
            "contact_wall_s": f"{float(open(os.path.join(runs, 'std0', name, 'wall.txt')).read()):.2f}",
            "note": note,
        })
        print(f"{name}: gate {gate}, dev_tight {dev_tight:.3g}, spread {spread:.3g}, rows {len(pub)}")
    with open(os.path.join(out, "cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, CASE_COLUMNS, lineterminator="\n")
        w.writeheader()
        w.writerows(table)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
