#!/usr/bin/env python3
"""A tiny external creep-force model for creepbench (README, "Bring your own model").

Usage: example_model.py SCENE_JSON OUT_CSV
Reads the resolved scene and its loading per row (loading.csv beside SCENE_JSON) and writes one
row per step: a steady model without memory,
Kalker's linear theory (f = G a b c11 cx / FN) saturated by the cubic law of
Vermeulen & Johnson: f = mu (1 - (1 - x)^3) for x = |f_lin| / (3 mu) < 1, else mu.
EXAMPLE_MODEL_SCALE (environment, default 1) scales the result: the tests use it to show that
`creepbench check` catches a drifting model.
"""
import csv, json, os, sys

def main(scene_path, out_path):
    s = json.load(open(scene_path))
    loading = os.path.join(os.path.dirname(scene_path), "loading.csv")
    history = [{k: float(v) for k, v in r.items() if v != ""} for r in csv.DictReader(open(loading))]
    scale = float(os.environ.get("EXAMPLE_MODEL_SCALE", "1"))
    g, a0, b0, fn0, c11, c22 = s["g_mpa"], s["a_mm"], s["b_mm"], s["fn_n"], s["c11"], s["c22"]
    rows = ["step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn"]
    for r in history:
        fn, mu = r["fn_n"], r["mu"]
        k = (fn / fn0) ** (1.0 / 3.0)  # Hertz: a, b grow with FN^(1/3)
        fx_lin = g * a0 * b0 * k * k * c11 * r["cx"] / fn
        fy_lin = g * a0 * b0 * k * k * c22 * r["cy"] / fn
        m = (fx_lin ** 2 + fy_lin ** 2) ** 0.5
        x = m / (3.0 * mu)
        f = mu * (1.0 - (1.0 - x) ** 3) if x < 1.0 else mu
        fx, fy = (fx_lin / m * f, fy_lin / m * f) if m > 0 else (0.0, 0.0)
        rows.append(f"{int(r['step'])},{r['t_s']!r},{r['cx']!r},{r['cy']!r},{r['cs']!r},{fn!r},{fx * scale!r},{fy * scale!r}")
    with open(out_path, "w") as out:
        out.write("\n".join(rows) + "\n")

if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: example_model.py SCENE_JSON OUT_CSV")
    main(sys.argv[1], sys.argv[2])
