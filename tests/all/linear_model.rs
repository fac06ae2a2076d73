//! Kalker's linear theory as a built-in model: against Kalker's published Table A1 on a circle,
//! against CONTACT's small-creepage slope, saturation at μ and the spin sign.

use crate::common;
use common::*;

fn circle_scene(creepage: &str, mu: f64) -> String {
    // A circle of radius 5 mm, ν = 0.25: a Table A1 node (a = b): c11 = 4.12, c22 = 3.67, c23 = 1.47.
    scene_text("lin", "[\"linear\"]", mu, 22, creepage, "")
        .replace("a_mm = 8.56", "a_mm = 5.0")
        .replace("b_mm = 4.08", "b_mm = 5.0")
        .replace("poisson = 0.28", "poisson = 0.25")
}

/// Fx = G a b C11 cx, Fy = G a b C22 cy + G (ab)^(3/2) C23 cs, with Kalker's tabulated
/// coefficients (Kalker 1990, Table A1; thesis App. A) for a = b, ν = 0.25.
#[test]
fn circle_matches_kalkers_table() {
    let (g, a, fn_n) = (82000.0, 5.0, 100000.0);
    let (cx, cy, cs) = (1e-5, 2e-5, 3e-6);
    let p = problem(&circle_scene(&format!("kind = \"step\"\nc = {cx}\nsteps = 2\ncy = {cy}\ncs = {cs}"), 0.4));
    let r = run(&p, "linear").rows[1].clone();
    let fx = g * a * a * 4.12 * cx / fn_n;
    let fy = (g * a * a * 3.67 * cy + g * a * a * a * 1.47 * cs) / fn_n;
    assert!((r.fx_over_fn / fx - 1.0).abs() < 1e-12, "fx {} vs {fx}", r.fx_over_fn);
    assert!((r.fy_over_fn / fy - 1.0).abs() < 1e-12, "fy {} vs {fy}", r.fy_over_fn);
}

/// The slope at zero creepage against CONTACT's exact theory on 88×88 (steady_exact_g88,
/// Richardson-extrapolated from its first two points, which already carry a little slip):
/// 153.1 against the table's 152.2, 0.6 % apart (Table A1 interpolated linearly in b/a between
/// 0.4 and 0.5, and CONTACT's discretisation).
#[test]
fn slope_matches_contact_exact_theory() {
    let (c1, f1, f2) =
        (1e-4, reference("steady_exact_g88", "fx_over_fn")[1], reference("steady_exact_g88", "fx_over_fn")[2]);
    let contact_slope = (4.0 * f1 - f2) / (2.0 * c1);
    let p = suite_problem("thesis", "steady_exact_g88", &["linear".into()]);
    let h = run(&p, "linear");
    let slope = h.rows[1].fx_over_fn / h.rows[1].sample.cx;
    println!("slope: linear {slope:.3}, CONTACT 88x88 {contact_slope:.3}");
    assert!((slope / contact_slope - 1.0).abs() < 0.01, "{slope} vs {contact_slope}");
}

/// Saturated at μ with the direction of the linear force kept; positive spin gives positive fy
/// (CONTACT's convention, C23 > 0); odd in the creepages.
#[test]
fn saturation_direction_and_signs() {
    let mu = 0.3;
    let p = problem(&circle_scene("kind = \"step\"\nc = 0.01\nsteps = 1\ncy = 0.01", mu));
    let r = &run(&p, "linear").rows[0];
    assert!((r.fx_over_fn.hypot(r.fy_over_fn) - mu).abs() < 1e-12, "|f| = {}", r.fx_over_fn.hypot(r.fy_over_fn));
    assert!((r.fy_over_fn / r.fx_over_fn - 3.67 / 4.12).abs() < 1e-12, "direction kept");
    let spin = problem(&circle_scene("kind = \"step\"\nc = 0.0\nsteps = 1\ncs = 1e-4", mu));
    assert!(run(&spin, "linear").rows[0].fy_over_fn > 0.0, "positive spin, positive fy");
    let neg = problem(&circle_scene("kind = \"step\"\nc = -0.01\nsteps = 1\ncy = -0.01", mu));
    let rn = &run(&neg, "linear").rows[0];
    assert_eq!((rn.fx_over_fn, rn.fy_over_fn), (-r.fx_over_fn, -r.fy_over_fn));
}
