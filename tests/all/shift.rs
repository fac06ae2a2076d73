//! Issue 32 item 3: shifts without rolling (CONTACT T = 1, Cattaneo), `[rolling] motion =
//! "shift"`: the creepage keys are rigid shifts per step [mm], the traction of the last step stays
//! in place. References: Cattaneo–Mindlin's closed form (Johnson 1985, Contact Mechanics §7.1,
//! eqs. 7.28–7.29) and CONTACT's printed output of its example `cattaneo.inp`, case 2.

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;
use creepbench::solvers::contact::force::FORCE_TOL;

/// Run the exact solver on a scene whose files sit in `dir`.
fn run_in(text: &str, dir: &std::path::Path) -> Result<History, String> {
    let scene = Scene::from_toml(text, dir).map_err(|e| e.to_string())?;
    let p = creepbench::pipeline::resolve(&scene).map_err(|e| e.to_string())?;
    Ok(run(&p, "contact"))
}

/// Last value of a history's column.
fn last(h: &History, column: &str) -> f64 {
    *h.column(column).unwrap().last().unwrap()
}

const G_MPA: f64 = 200.0;
const NU: f64 = 0.42;
const MU: f64 = 0.4;

/// A Hertzian circle of radius `a_mm` (FN chosen freely: the pressure is Hertz's), `n` × `n`
/// elements over it, a shift scene with the given creepage table.
fn circle(a_mm: f64, fn_n: f64, n: usize, creepage: &str) -> String {
    format!(
        "name = \"cattaneo\"\nsolvers = [\"contact\"]\n[contact]\na_mm = {a_mm:?}\nb_mm = {a_mm:?}\nfn_n = {fn_n:?}\nmu = {MU}\n[material]\ng_mpa = {G_MPA:?}\npoisson = {NU}\n[grid]\nmx = {n}\nmy = {n}\n[rolling]\nmotion = \"shift\"\n[creepage]\n{creepage}\n"
    )
}

/// Cattaneo–Mindlin, a circle of quasi-identical materials loaded by Fx < μ FN from zero:
/// adhesion radius c = a (1 − Fx/μFN)^(1/3) (Johnson eq. 7.28) and the shift of the two bodies'
/// far points δ = 3 μ FN (2 − ν)/(8 G a) [1 − (1 − Fx/μFN)^(2/3)] (eq. 7.29 with both bodies'
/// compliances (2 − ν)/G added: 8 in place of the single body's 16).
#[test]
fn cattaneo_mindlin_adhesion_radius_and_shift() {
    let dir = tempdir("shift_cattaneo_mindlin");
    let (a_mm, fn_n, n) = (1.0, 10.0, 48);
    let ratio = 0.5;
    let creepage = format!("kind = \"step\"\nfx_over_fn = {:?}\nsteps = 2", ratio * MU);
    let h = run_in(&circle(a_mm, fn_n, n, &creepage), &dir).unwrap();
    let dx = 2.0 * a_mm / n as f64;
    let c_mm = a_mm * (1.0 - ratio).powf(1.0 / 3.0);
    let delta_mm = 3.0 * MU * fn_n * (2.0 - NU) / (8.0 * G_MPA * a_mm) * (1.0 - (1.0 - ratio).powf(2.0 / 3.0));
    let (cx, n_adh) = (h.column("cx").unwrap(), h.column("n_adhesion").unwrap());
    let fx = h.column("fx_over_fn").unwrap();
    // Row 0 (step 1) loads from zero; row 1 (step 2) keeps the force: no further shift.
    assert_eq!(cx.len(), 2);
    let c_found = (n_adh[0] * dx * dx / std::f64::consts::PI).sqrt();
    println!(
        "shift {:.6e} mm vs {delta_mm:.6e} ({:+.2e} rel.); adhesion {} elements vs {:.1}, c {c_found:.4} vs {c_mm:.4} mm (dx {dx:.4})",
        cx[0],
        cx[0] / delta_mm - 1.0,
        n_adh[0],
        std::f64::consts::PI * c_mm * c_mm / (dx * dx)
    );
    assert!((fx[0] - ratio * MU).abs() <= FORCE_TOL * MU && (fx[1] - ratio * MU).abs() <= FORCE_TOL * MU);
    // The adhesion area's equivalent radius within half an element of Cattaneo's c.
    assert!((c_found - c_mm).abs() <= 0.5 * dx, "c {c_found} vs {c_mm}");
    // The shift: the discretised contact's edge differs from the circle by O(dx) (CONTACT on its
    // 19 x 19 grid of this circle: −0.2 %); here 48 x 48, measured −8.4e-4: within 2e-3.
    assert!((cx[0] / delta_mm - 1.0).abs() < 2e-3, "{} vs {delta_mm}", cx[0]);
    assert!(cx[1].abs() < 1e-6 * delta_mm, "a held force shifts no further: {}", cx[1]);
    assert_eq!(n_adh[1], n_adh[0]);
}

/// The field h = 0.01 (x² + y²) of CONTACT's `cattaneo.inp` case 2 (B1 = B3 = 0.01, IBASE 1), per
/// element of its 19 × 19 grid.
fn cattaneo_field(dir: &std::path::Path, x0: f64, dx: f64) {
    let mut csv = String::from("ix,iy,h_mm\n");
    for iy in 1..=19 {
        for ix in 1..=19 {
            let (x, y) = (x0 + (ix as f64 - 0.5) * dx, x0 + (iy as f64 - 0.5) * dx);
            csv.push_str(&format!("{ix},{iy},{:?}\n", 0.01 * (x * x + y * y)));
        }
    }
    std::fs::write(dir.join("h.csv"), csv).unwrap();
}

/// CONTACT's examples/cattaneo.inp case 2 (eve70a/CONTACT d431cdb, examples/cattaneo.ref_out): FN
/// 9.1954 N, G 200 MPa, ν 0.42, FSTAT = FKIN = 0.4, T = 1, F = 2 with FX/FSTAT/FN = −0.875, FY = 0,
/// 19 × 19 elements of 0.13333 mm from −1.26667 mm. Printed: SHIFT X 8.155E-03, FX −3.218,
/// NADH 45, NSLIP 132. Signs: this project's fx = −FX (fx_over_fn = 0.875 · 0.4), cx = CKSI.
#[test]
fn contact_cattaneo_case_2() {
    let dir = tempdir("shift_contact_cattaneo");
    let (x0, dx) = (-1.26667, 0.13333);
    let x1 = x0 + 19.0 * dx;
    cattaneo_field(&dir, x0, dx);
    let text = format!(
        "name = \"cattaneo2\"\nsolvers = [\"contact\"]\n[contact]\nfn_n = 9.1954\nmu = 0.4\n[geometry]\nkind = \"field\"\nfield = \"h.csv\"\n[material]\ng_mpa = 200.0\npoisson = 0.42\n[grid]\nmx = 19\nmy = 19\nx_mm = [{x0:?}, {x1:?}]\ny_mm = [{x0:?}, {x1:?}]\n[rolling]\nmotion = \"shift\"\n[creepage]\nkind = \"step\"\nfx_over_fn = 0.35\nsteps = 1\n"
    );
    let h = run_in(&text, &dir).unwrap();
    let (cx, fx) = (last(&h, "cx"), last(&h, "fx_over_fn"));
    let (n_adh, n_slip) = (last(&h, "n_adhesion"), last(&h, "n_slip"));
    println!("cx {cx:.6e} (printed 8.155E-03), FX {:.5} (printed -3.218), NADH {n_adh}, NSLIP {n_slip}", -fx * 9.1954);
    // Four printed digits: within half a unit of the last one.
    assert!((cx - 8.155e-3).abs() <= 0.5e-6, "{cx:e}");
    assert!((-fx * 9.1954 + 3.218).abs() <= 0.5e-3, "{fx}");
    assert_eq!((n_adh, n_slip), (45.0, 132.0));
}

/// Shifts: only the exact model, and no steady state.
#[test]
fn shifts_refuse_other_models_and_sweeps() {
    let dir = tempdir("shift_refused");
    let step = "kind = \"step\"\nc = 0.001\nsteps = 2";
    let e =
        run_in(&circle(1.0, 10.0, 8, step).replace("[\"contact\"]", "[\"contact\", \"fastsim\"]"), &dir).unwrap_err();
    assert!(e.contains("solvers") && e.contains("fastsim") && e.contains("shift") && e.contains("contact"), "{e}");
    let sweep = "kind = \"sweep\"\nover = \"cx\"\nfrom = 0.0\nto = 0.001\npoints = 2";
    let e = run_in(&circle(1.0, 10.0, 8, sweep), &dir).unwrap_err();
    assert!(e.contains("rolling.motion") && e.contains("sweep"), "{e}");
    let e = run_in(&circle(1.0, 10.0, 8, step).replace("\"shift\"", "\"slide\""), &dir).unwrap_err();
    assert!(e.contains("rolling.motion") && e.contains("shift"), "{e}");
}

/// A shift start (`[init] kind = "shift"`) is read once, in the scene reader: only before a
/// rolling time history, only for the models that solve shifts.
#[test]
fn a_shift_start_needs_a_rolling_history_and_the_exact_model() {
    let dir = tempdir("shift_start_refused");
    let rolling = |creepage: &str| circle(1.0, 10.0, 8, creepage).replace("motion = \"shift\"", "motion = \"rolling\"");
    let step = "kind = \"step\"\nc = 0.001\nsteps = 2\n[init]\nkind = \"shift\"";
    let e = run_in(&circle(1.0, 10.0, 8, step), &dir).unwrap_err();
    assert!(
        e.contains("init.kind") && e.contains("rolling.motion = \"shift\"") && e.contains("kind = \"zero\""),
        "{e}"
    );
    let sweep = "kind = \"sweep\"\nover = \"cx\"\nfrom = 0.0\nto = 0.001\npoints = 2\n[init]\nkind = \"shift\"";
    let e = run_in(&rolling(sweep), &dir).unwrap_err();
    assert!(e.contains("init.kind") && e.contains("sweep"), "{e}");
    let e = run_in(&rolling(step).replace("[\"contact\"]", "[\"contact\", \"fastsim\"]"), &dir).unwrap_err();
    assert!(e.contains("fastsim") && e.contains("init.kind = \"shift\""), "{e}");
    // The exact model runs it: the shift of step 0 (c_before = 0: no shift, no traction), then rolling.
    let h = run_in(&rolling(step), &dir).unwrap();
    let steps: Vec<usize> = h.rows.iter().map(|r| r.sample.step).collect();
    assert_eq!(steps, vec![0, 1, 2]);
    assert_eq!(h.rows[0].fx_over_fn, 0.0);
    assert!(h.rows[2].fx_over_fn > 0.0);
}
