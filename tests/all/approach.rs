//! Issue 32 item 3: the normal problem with the approach prescribed (CONTACT N = 0, PEN), a
//! creepage table's `pen_mm` column in place of `fn_n`. The exact solver finds FN (the history's
//! `fn_n`); references: Hertz's closed form for a circle, δ = 3 FN / (4 a E*) with a ∝ FN^(1/3)
//! (Johnson 1985, eq. 4.23), and the solver's own FN-prescribed twin.

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

/// A circular Hertz contact, a = b = 5 mm at the nominal 50 kN, on 40 x 40 elements over 1.5 a
/// (the contact at 1.5 times the load still inside), the table `c.csv` in `dir`.
fn text(solvers: &str) -> String {
    r#"name = "approach"
solvers = SOLVERS
[contact]
a_mm = 5.0
b_mm = 5.0
fn_n = 50000.0
mu = 0.3
[material]
g_mpa = 82000.0
poisson = 0.28
[grid]
mx = 40
my = 40
scale = 1.5
[creepage]
kind = "table"
file = "c.csv"
"#
    .replace("SOLVERS", solvers)
}

/// Run the scene with `table` as its `c.csv`.
fn run_table(name: &str, table: &str, solvers: &str) -> Result<History, String> {
    let dir = tempdir(name);
    std::fs::write(dir.join("c.csv"), table).unwrap();
    let scene = Scene::from_toml(&text(solvers), &dir).map_err(|e| e.to_string())?;
    let p = creepbench::pipeline::resolve(&scene).map_err(|e| e.to_string())?;
    Ok(run(&p, "contact"))
}

/// Hertz's approach [mm] of the circle at `fn_n` [N]: a = 5 (FN/50000)^(1/3) mm, δ = a²/R =
/// 3 FN / (4 a E*), E* = G/(1 − ν) for two identical bodies.
fn hertz_approach_mm(fn_n: f64) -> f64 {
    let a_mm = 5.0 * (fn_n / 50000.0f64).cbrt();
    3.0 * fn_n / (4.0 * a_mm * 82000.0 / (1.0 - 0.28))
}

#[test]
fn the_force_of_a_prescribed_approach_is_hertzs() {
    for f in [25000.0, 50000.0, 75000.0] {
        let table = format!("t_s,cx,pen_mm\n0.002,0.001,{:?}\n", hertz_approach_mm(f));
        let h = run_table("approach_hertz", &table, "[\"contact\"]").unwrap();
        let fn_n = h.column("fn_n").unwrap();
        // Every row (the five steps) holds the one approach: one FN.
        assert!(fn_n.iter().all(|&x| x == fn_n[0]) && fn_n.len() == 5, "{fn_n:?}");
        let got = fn_n[0];
        println!("approach {:.6e} mm: FN {got:.1} N, Hertz {f} N, {:+.3e}", hertz_approach_mm(f), got / f - 1.0);
        // The grid's accuracy: 5.3 to 7.6 elements per contact radius.
        // Measured +2.5e-4, +1.5e-4, +2.7e-4.
        assert!((got / f - 1.0).abs() < 5e-4, "FN {got} N vs Hertz {f} N");
    }
}

#[test]
fn a_prescribed_approach_and_its_force_give_the_same_history() {
    let pens = [0.08, 0.1, 0.12, 0.1];
    let mut by_pen = String::from("t_s,cx,pen_mm\n");
    for (k, p) in pens.iter().enumerate() {
        by_pen.push_str(&format!("{:?},{:?},{p:?}\n", 0.002 * k as f64, 0.0005 * (k + 1) as f64));
    }
    let a = run_table("approach_twin_pen", &by_pen, "[\"contact\"]").unwrap();
    // The twin: the FN found, row by row, prescribed (each row's own step: one row per step).
    let (t, cx, fn_n) = (a.column("t_s").unwrap(), a.column("cx").unwrap(), a.column("fn_n").unwrap());
    let mut by_force = String::from("t_s,cx,fn_n\n");
    for k in 0..t.len() {
        by_force.push_str(&format!("{:?},{:?},{:?}\n", t[k], cx[k], fn_n[k]));
    }
    let b = run_table("approach_twin_fn", &by_force, "[\"contact\"]").unwrap();
    assert_eq!(a.rows.len(), b.rows.len());
    // The FN found varies with the approach (the test would see an ignored column).
    assert!(fn_n.iter().any(|&f| f > 1.2 * fn_n[0]), "{fn_n:?}");
    for col in ["fx_over_fn", "fy_over_fn", "n_adhesion", "n_slip"] {
        let (d, k) = max_abs_diff(&a.column(col).unwrap(), &b.column(col).unwrap());
        println!("{col}: largest |difference| {d:.2e} at row {k}");
        // Same pressure to the normal solves' tolerance 1e-10: forces within 1e-8 of FN.
        assert!(d < 1e-8, "{col}: {d:e} at row {k}");
    }
}

#[test]
fn an_approach_with_a_force_column_or_a_model_without_it_is_refused() {
    let both = run_table("approach_both", "t_s,cx,fn_n,pen_mm\n0.002,0.001,50000.0,0.1\n", "[\"contact\"]");
    let e = both.unwrap_err();
    assert!(e.contains("columns fn_n, pen_mm") && e.contains("both given") && e.contains("exactly one"), "{e}");
    let negative = run_table("approach_negative", "t_s,cx,pen_mm\n0.002,0.001,-0.1\n", "[\"contact\"]");
    let e = negative.unwrap_err();
    assert!(e.contains("column pen_mm") && e.contains("(0, 10] mm"), "{e}");
    let uba = run_table("approach_uba", "t_s,cx,pen_mm\n0.002,0.001,0.1\n", "[\"contact\", \"uba\"]");
    let e = uba.unwrap_err();
    assert!(e.contains("\"uba\" with the approach prescribed") && e.contains("contact"), "{e}");
}

/// The quadratic `h = B (x − x0)² + B y²` of CONTACT's IBASE = 1 (B(1..6) = B, 0, B, −2 B x0, 0,
/// B x0²) on a 24 x 20 grid of 0.5 mm over x_C in [−5, 7] mm, y in [−5, 5] mm.
const B_PER_MM: f64 = 0.004;

fn field_scene(dir: &std::path::Path, table: &str, solvers: &str) -> Result<History, String> {
    let mut h = String::from("ix,iy,h_mm\n");
    for iy in 0..20 {
        for ix in 0..24 {
            let (x, y) = (-5.0 + 0.5 * (ix as f64 + 0.5), -5.0 + 0.5 * (iy as f64 + 0.5));
            h.push_str(&format!("{},{},{:?}\n", ix + 1, iy + 1, B_PER_MM * (x * x + y * y)));
        }
    }
    std::fs::write(dir.join("h.csv"), h).unwrap();
    std::fs::write(dir.join("c.csv"), table).unwrap();
    let text = format!(
        r#"name = "moving"
solvers = {solvers}
[contact]
fn_n = 20000.0
mu = 0.3
[geometry]
kind = "field"
field = "h.csv"
[material]
g_mpa = 82000.0
poisson = 0.28
[grid]
mx = 24
my = 20
x_mm = [-5.0, 7.0]
y_mm = [-5.0, 5.0]
[creepage]
kind = "table"
file = "c.csv"
"#
    );
    let scene = Scene::from_toml(&text, dir).map_err(|e| e.to_string())?;
    let p = creepbench::pipeline::resolve(&scene).map_err(|e| e.to_string())?;
    Ok(run(&p, "contact"))
}

/// CONTACT's B(1..6) of the quadratic moved to x0 [mm], as a table row's columns.
fn moved(x0: f64) -> String {
    let b = B_PER_MM;
    format!("{b:?},0.0,{b:?},{:?},0.0,{:?}", -2.0 * b * x0, b * x0 * x0)
}

#[test]
fn an_undeformed_distance_per_row_moves_the_contact() {
    let dir = tempdir("approach_moving");
    // Rolling at cx = 0.001 under the approach 0.05 mm, the quadratic moved by one element (0.5 mm
    // along CONTACT's x) per step from x0 = 0 (the [geometry]'s own) to 1.5 mm.
    let dt = 0.5 / 1000.0;
    let mut table = String::from("t_s,cx,pen_mm,b1_per_mm,b2_per_mm,b3_per_mm,b4,b5,b6_mm\n");
    for k in 0..4 {
        table.push_str(&format!("{:?},0.001,0.05,{}\n", dt * (k + 1) as f64, moved(0.5 * k as f64)));
    }
    let h = field_scene(&dir, &table, "[\"contact\"]").unwrap();
    let fn_n = h.column("fn_n").unwrap();
    assert_eq!(fn_n.len(), 4);
    // Moved by whole elements on a uniform grid, the contact (inside it) carries the same load.
    for f in &fn_n {
        assert!((f / fn_n[0] - 1.0).abs() < 1e-9, "{fn_n:?}");
    }
    // The first row is the geometry's own quadratic: as the scene without the columns.
    let plain = field_scene(&dir, "t_s,cx,pen_mm\n0.0005,0.001,0.05\n", "[\"contact\"]").unwrap();
    let (f0, p0) = (h.column("fx_over_fn").unwrap()[0], plain.column("fx_over_fn").unwrap()[0]);
    assert!((f0 - p0).abs() < 1e-12 && (fn_n[0] / plain.column("fn_n").unwrap()[0] - 1.0).abs() < 1e-12);
    // Rolling over a contact that moves with the rolling: the traction builds up from zero, so
    // the force changes from step to step (the test would see rows solved alike).
    let fx = h.column("fx_over_fn").unwrap();
    assert!(fx.windows(2).all(|w| w[1] != w[0]), "{fx:?}");
}

#[test]
fn an_undeformed_distance_per_row_needs_all_six_a_grid_and_the_exact_model() {
    let dir = tempdir("approach_moving_refused");
    let five = "t_s,cx,b1_per_mm,b2_per_mm,b3_per_mm,b4,b5\n0.0005,0.001,0.004,0.0,0.004,0.0,0.0\n";
    let e = field_scene(&dir, five, "[\"contact\"]").unwrap_err();
    assert!(e.contains("5 of the columns") && e.contains("all six"), "{e}");
    let six = format!("t_s,cx,b1_per_mm,b2_per_mm,b3_per_mm,b4,b5,b6_mm\n0.0005,0.001,{}\n", moved(0.0));
    let e = field_scene(&dir, &six, "[\"contact\", \"fastsim\"]").unwrap_err();
    assert!(e.contains("\"fastsim\" with an undeformed distance per row"), "{e}");
    std::fs::write(dir.join("c.csv"), &six).unwrap();
    let hertz = text("[\"contact\"]");
    let e = Scene::from_toml(&hertz, &dir).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("with a Hertzian contact") && e.contains("explicit grid"), "{e}");
}
