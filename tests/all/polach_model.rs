//! Polach's model as a built-in model (issue 14's ladder): through the pipeline, its slope at zero
//! creepage is the linear theory's (Kalker's C11, C22), it tends to μ at large creepage, and the
//! falling friction follows μ0 ((1 − A) e^(−B w) + A) with w = s V.

use crate::common;
use common::*;
use creepbench::solvers::polach::resultant;

fn sweep(over: &str, from: f64, to: f64, points: usize) -> String {
    format!("kind = \"sweep\"\nover = \"{over}\"\nfrom = {from:e}\nto = {to:e}\npoints = {points}")
}

#[test]
fn polach_has_the_linear_slope_and_saturates_at_mu() {
    let mu = 0.4;
    for over in ["cx", "cy"] {
        let p = problem(&scene_text("pol", "[\"linear\", \"polach\"]", mu, 22, &sweep(over, 1e-8, 1e-8, 1), ""));
        let col = if over == "cx" { "fx_over_fn" } else { "fy_over_fn" };
        let (l, q) = (run(&p, "linear").column(col).unwrap()[0], run(&p, "polach").column(col).unwrap()[0]);
        assert!((q / l - 1.0).abs() < 1e-6, "{over}: polach {q}, linear {l}");
    }
    let p = problem(&scene_text("pol", "[\"polach\"]", mu, 22, &sweep("cx", 1.0, 1.0, 1), ""));
    let f = run(&p, "polach").rows[0].fx_over_fn;
    assert!(f < mu && mu - f < 1e-3, "{f}");
}

/// Polach's falling friction at each row's own speed: a sweep over the rolling speed at
/// cx = 0.2 (V = 1, 3, 5 m/s: w = 0.2, 0.6, 1.0 m/s) against Eq. 8 and the closed form of each row.
#[test]
fn polach_falls_with_the_rows_speed() {
    let mu0 = 0.5;
    let extra = "[model]\npolach_k_a = 1.0\npolach_k_s = 0.4\npolach_a = 0.4\npolach_b_s_per_m = 0.6";
    let creepage = format!("{}\ncx = 0.2", sweep("v_mm_s", 1000.0, 5000.0, 3));
    let p = problem(&scene_text("pol", "[\"polach\"]", mu0, 22, &creepage, extra));
    let f: Vec<f64> = run(&p, "polach").rows.iter().map(|r| r.fx_over_fn).collect();
    let (h, c, g) = (p.hertz(), p.coefficients, p.material.g_mpa);
    for (k, w_m_s) in [0.2f64, 0.6, 1.0].into_iter().enumerate() {
        let mu = mu0 * (0.6 * (-0.6 * w_m_s).exp() + 0.4);
        let eps = 2.0 / 3.0 * (3.0 * g * c.c11 / (8.0 * h.a_mm)) * std::f64::consts::PI * h.a_mm * h.a_mm * h.b_mm
            / (h.fn_n * mu)
            * 0.2;
        let expected = mu * resultant(eps, 1.0, 0.4);
        assert!((f[k] - expected).abs() < 1e-12, "row {k} (w = {w_m_s} m/s): {} vs {expected}", f[k]);
    }
    assert!(f[0] > f[1] && f[1] > f[2], "{f:?}");
}

#[test]
fn polach_falling_friction_and_reductions() {
    let mu0 = 0.5;
    let extra = "[model]\npolach_k_a = 1.0\npolach_k_s = 0.4\npolach_a = 0.4\npolach_b_s_per_m = 0.6";
    // cx = 0.2 at V = 1000 mm/s: w = 0.2 m/s.
    let p = problem(&scene_text("pol", "[\"polach\"]", mu0, 22, &sweep("cx", 0.2, 0.2, 1), extra));
    let f = run(&p, "polach").rows[0].fx_over_fn;
    let mu = mu0 * (0.6 * (-0.6f64 * 0.2).exp() + 0.4);
    // ε from the same definition: (2/3) C π a² b s / (Q μ), C = 3 G c11 / (8 a).
    let (h, c, g) = (p.hertz(), p.coefficients, p.material.g_mpa);
    let eps = 2.0 / 3.0 * (3.0 * g * c.c11 / (8.0 * h.a_mm)) * std::f64::consts::PI * h.a_mm * h.a_mm * h.b_mm
        / (h.fn_n * mu)
        * 0.2;
    let expected = mu * resultant(eps, 1.0, 0.4);
    assert!((f - expected).abs() < 1e-12, "{f} vs {expected}");
    assert!(f < mu && f > 0.3 * mu);
    // Out-of-range parameters are input errors naming the key.
    let bad = scene_text("pol", "[\"polach\"]", mu0, 22, &sweep("cx", 0.2, 0.2, 1), "[model]\npolach_k_s = 0.0");
    let scene = creepbench::scene::Scene::from_toml(&bad, std::path::Path::new(".")).unwrap();
    let e = creepbench::pipeline::resolve(&scene).unwrap_err().to_string();
    assert!(e.contains("model.polach_k_s"), "{e}");
}

/// A friction coefficient so small that Polach's ratio ε overflows (μ = 1e-310, allowed by
/// contact.mu's (0, 1000]; likewise a falling law's static value fkin + f1 + f2): full sliding,
/// f = μ, where the run used to fail with "non-finite traction coefficient at step 1" (exit 1).
#[test]
fn polach_slides_fully_where_its_ratio_overflows() {
    let step = "kind = \"step\"\nc = 0.3\nsteps = 3";
    let coulomb = problem(&scene_text("pol", "[\"polach\"]", 1e-310, 8, step, ""));
    let falling = scene_text(
        "pol",
        "[\"polach\"]",
        1.0,
        8,
        step,
        "[friction]\nlaw = \"exponential\"\nfkin = 0\nf1 = 1e-320\nsabsh1_mm_s = 600.0",
    )
    .replace("mu = 1\n", "");
    for (p, mu) in [(coulomb, 1e-310), (problem(&falling), 1e-320)] {
        for v in f(&run(&p, "polach")) {
            assert!(v.is_finite() && (v - mu).abs() <= 1e-3 * mu, "{v} vs {mu}");
        }
    }
    assert!((resultant(f64::INFINITY, 1.0, 1.0) - 1.0).abs() < 1e-15);
}
