//! Issue 32 item 3: prescribed total tangential forces (CONTACT F = 1: Fx/FN with cy given; F = 2:
//! Fx/FN and Fy/FN), `[creepage] fx_over_fn`, `fy_over_fn` and the table columns of those names.
//! The exact solver finds the creepages (`solvers::contact::force`); the reference is its own
//! creepage-prescribed twin: prescribing the forces the twin gave, step by step, must give back the
//! twin's creepages, and the forces reached must be the forces prescribed.

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;
use creepbench::solvers::contact::force::FORCE_TOL;

const MU: f64 = 0.3;

/// A 20 x 20 grid of the thesis contact, Courant 1, `creepage` as given.
fn text(creepage: &str, solvers: &str) -> String {
    scene_text("force", solvers, MU, 20, creepage, "")
}

/// Run a scene whose table sits in `dir`.
fn run_in(text: &str, dir: &std::path::Path) -> Result<History, String> {
    let scene = Scene::from_toml(text, dir).map_err(|e| e.to_string())?;
    let p = creepbench::pipeline::resolve(&scene).map_err(|e| e.to_string())?;
    Ok(run(&p, "contact"))
}

/// The twin: a creepage history (cx and cy vary, with spin), its forces written back as the
/// prescribed-force table of a second scene.
fn twin(columns: &str) -> (History, History) {
    let dir = tempdir("prescribed_force_twin");
    let rows = "t_s,cx,cy\n0.0,0.0,0.0\n0.004,0.002,0.0004\n0.008,0.0005,-0.0003\n0.012,0.004,0.001\n";
    std::fs::write(dir.join("c.csv"), rows).unwrap();
    let creep = run_in(&text("kind = \"table\"\nfile = \"c.csv\"\ncs = 0.00005", "[\"contact\"]"), &dir).unwrap();
    let mut table = format!("t_s,{columns}\n");
    let (fx, fy, cy) =
        (creep.column("fx_over_fn").unwrap(), creep.column("fy_over_fn").unwrap(), creep.column("cy").unwrap());
    for (k, t) in creep.column("t_s").unwrap().iter().enumerate() {
        let line = match columns {
            "fx_over_fn,cy" => format!("{t:?},{:?},{:?}\n", fx[k], cy[k]),
            _ => format!("{t:?},{:?},{:?}\n", fx[k], fy[k]),
        };
        table.push_str(&line);
    }
    std::fs::write(dir.join("f.csv"), table).unwrap();
    let force = run_in(&text("kind = \"table\"\nfile = \"f.csv\"\ncs = 0.00005", "[\"contact\"]"), &dir).unwrap();
    (creep, force)
}

/// Largest |a − b| over two columns of two histories.
fn worst(a: &History, b: &History, column: &str) -> f64 {
    max_abs_diff(&a.column(column).unwrap(), &b.column(column).unwrap()).0
}

fn check_twin(columns: &str) {
    let (creep, force) = twin(columns);
    assert_eq!(creep.rows.len(), force.rows.len());
    let (dcx, dcy) = (worst(&creep, &force, "cx"), worst(&creep, &force, "cy"));
    let (dfx, dfy) = (worst(&creep, &force, "fx_over_fn"), worst(&creep, &force, "fy_over_fn"));
    println!("{columns}: |dcx| {dcx:.2e}, |dcy| {dcy:.2e}, |dfx| {dfx:.2e}, |dfy| {dfy:.2e}");
    // The forces reached meet the stopping test (FORCE_TOL mu) against the twin's.
    assert!(dfx <= FORCE_TOL * MU && dfy <= FORCE_TOL * MU, "{dfx:e} {dfy:e}");
    // The creepages found are the twin's: 1e-8 of creepages up to 4e-3 (the force error over the
    // smallest slope, in near-full slip, with the inner solves' own tolerance 1e-7).
    assert!(dcx < 1e-8 && dcy < 1e-8, "{dcx:e} {dcy:e}");
    assert!(force.column("termination").unwrap().iter().all(|&t| t == 0.0));
    // The creepages vary: the test would see a solver that ignored the force.
    assert!(force.column("cx").unwrap().iter().any(|&c| c > 0.003));
}

/// F = 2: Fx/FN and Fy/FN prescribed (table columns), every step of a transient history.
#[test]
fn prescribed_fx_and_fy_give_back_the_creepages() {
    check_twin("fx_over_fn,fy_over_fn");
}

/// F = 1: Fx/FN prescribed with cy given.
#[test]
fn prescribed_fx_with_cy_given_gives_back_cx() {
    check_twin("fx_over_fn,cy");
}

/// The step kind: a constant Fx/FN from zero traction; the creepage settles (after about three
/// contact lengths) at the one for which the steady solver gives that force.
#[test]
fn a_force_step_settles_at_the_steady_creepage() {
    let dir = tempdir("prescribed_force_step");
    let f = run_in(&text("kind = \"step\"\nfx_over_fn = 0.2\nsteps = 80", "[\"contact\"]"), &dir).unwrap();
    let (fx, cx) = (f.column("fx_over_fn").unwrap(), f.column("cx").unwrap());
    assert!(fx.iter().all(|v| (v - 0.2).abs() <= FORCE_TOL * MU), "{fx:?}");
    let steady = run_in(
        &text(&format!("kind = \"sweep\"\nfrom = {:?}\nto = 0.0\npoints = 1", cx[cx.len() - 1]), "[\"contact\"]"),
        &dir,
    )
    .unwrap();
    let last = steady.column("fx_over_fn").unwrap();
    println!("steady cx {:e}: twin's fx {:e}", cx[cx.len() - 1], last[last.len() - 1] - 0.2);
    // Within the two solvers' own tolerances (1e-7 on the traction change): measured 1.1e-8.
    assert!((last[last.len() - 1] - 0.2).abs() < 5e-8, "{}", last[last.len() - 1]);
}

/// Bad input: a force at or above mu, a model that takes creepages only, Fy alone, both columns.
#[test]
fn impossible_or_ambiguous_forces_are_refused() {
    let dir = tempdir("prescribed_force_refused");
    let err = |creepage: &str, solvers: &str| run_in(&text(creepage, solvers), &dir).unwrap_err();
    let e = err("kind = \"step\"\nfx_over_fn = 0.3\nsteps = 2", "[\"contact\"]");
    assert!(e.contains("creepage.fx_over_fn") && e.contains("below mu = 0.3") && e.contains("slides"), "{e}");
    let e = err("kind = \"step\"\nfx_over_fn = 0.1\nsteps = 2", "[\"contact\", \"fastsim\"]");
    assert!(e.contains("solvers") && e.contains("fastsim") && e.contains("contact"), "{e}");
    let e = err("kind = \"step\"\nc = 0.001\nfy_over_fn = 0.1\nsteps = 2", "[\"contact\"]");
    assert!(e.contains("creepage.fy_over_fn") && e.contains("F = 2"), "{e}");
    let e = err("kind = \"step\"\nc = 0.001\nfx_over_fn = 0.1\nsteps = 2", "[\"contact\"]");
    assert!(e.contains("creepage.c") && e.contains("only one of"), "{e}");
    let e =
        err("kind = \"sine\"\nc0 = 0.0\ncp = 0.001\nfreq_hz = 10.0\nperiods = 1.0\nfx_over_fn = 0.1", "[\"contact\"]");
    assert!(e.contains("creepage.fx_over_fn") && e.contains("step"), "{e}");
    std::fs::write(dir.join("both.csv"), "t_s,cx,fx_over_fn\n0.0,0.0,0.1\n").unwrap();
    let e = err("kind = \"table\"\nfile = \"both.csv\"", "[\"contact\"]");
    // Both columns: one cell per row (F changing within a history), never both in one row.
    assert!(e.contains("columns cx, fx_over_fn") && e.contains("both given"), "{e}");
    std::fs::write(dir.join("high.csv"), "t_s,fx_over_fn,mu\n0.0,0.1,0.3\n0.01,0.25,0.2\n").unwrap();
    let e = err("kind = \"table\"\nfile = \"high.csv\"", "[\"contact\"]");
    assert!(e.contains("creepage.fx_over_fn") && e.contains("below mu = 0.2"), "{e}");
}

/// `export contact` writes F = 1 (FXREL = −fx/μ, CONTACT's sign) with CETA given.
#[test]
fn export_writes_the_force_digit_and_fxrel() {
    let p = problem(&text("kind = \"step\"\nfx_over_fn = 0.15\nsteps = 2\ncy = 0.001", "[\"contact\"]"));
    let deck = creepbench::export::contact::module3_input(&p);
    assert!(deck.contains("  20211") && deck.contains("  00211"), "{deck}");
    assert!(deck.contains("100000.0   -0.5   0.001   0.0        FN, FXREL, CETA, CPHI"), "{deck}");
}
