//! FaStrip as a built-in model (issue 14's ladder; Sichani, Enblom & Berg, VSD 54(6) 2016): the
//! linear theory at small creepage (its design property), μ at full slip with the rigid slip's
//! direction, its creep forces against CONTACT's exact theory beside FASTSIM's, and the refusal of
//! a contact given per element. The signs are pinned with every other solver's in tests/all/envelope.rs.

use crate::common;
use common::*;
use creepbench::problem::Problem;
use creepbench::scene::Scene;
use std::path::Path;

fn sweep(over: &str, c: f64, extra_creepage: &str) -> String {
    format!("kind = \"sweep\"\nover = \"{over}\"\nfrom = {c:e}\nto = {c:e}\npoints = 1\n{extra_creepage}")
}

/// At small creepage FaStrip is Kalker's linear theory: its strip solution integrates to
/// `G a b C11 cx`, `G a b C22 cy` and `G (ab)^1.5 C23 cs` exactly over the ellipse (the scaling of
/// the creepages by Kalker's coefficients is made for that). On the grid the strip's full-adhesion
/// traction `∝ √((a_j − x)/(a_j + x))` is sampled at element centres, and its inverse-square-root
/// singularity at each strip's trailing edge gives an error of order √dx whose sign depends on
/// where the edge falls in its element: measured +3.6 % at 22×22 (cx and cy alike), +1.2 % at 44,
/// +1.3 % at 88, −0.43 % at 176. Spin's traction is proportional to the pressure at first order
/// (`τy = μ p φ'`), so Σ τ/Σ p carries no discretisation error: 3.3e-7 at cs = 1e-9/mm, the
/// second-order terms.
#[test]
fn small_creepage_is_the_linear_theory() {
    for (grid, tol_cx_cy) in [(22, 0.04), (176, 0.005)] {
        for (over, c, col) in [("cx", 1e-8, "fx_over_fn"), ("cy", 1e-8, "fy_over_fn"), ("cs", 1e-9, "fy_over_fn")] {
            let p = problem(&scene_text("fr", "[\"fastrip\", \"linear\"]", 0.4, grid, &sweep(over, c, ""), ""));
            let (fr, lin) = (run(&p, "fastrip").column(col).unwrap()[0], run(&p, "linear").column(col).unwrap()[0]);
            let err = fr / lin - 1.0;
            println!("{grid}x{grid} {over} = {c:e}: fastrip / linear theory - 1 = {err:+.3e}");
            let tol = if over == "cs" { 1e-6 } else { tol_cx_cy };
            assert!(err.abs() < tol, "{grid} {over}: {fr} vs {lin}");
        }
    }
}

/// Full slip: every element carries μ p, so |f| = μ; without spin the direction is the rigid
/// slip's (cx, cy): rows that slip from their leading edge take FASTSIM's direction with Kalker's
/// single flexibility (with three flexibilities it would be (cx/L1, cy/L2), 16 % off here).
#[test]
fn full_slip_gives_mu_along_the_rigid_slip() {
    let mu = 0.4;
    let p = problem(&scene_text("fr", "[\"fastrip\"]", mu, 22, &sweep("cx", 0.5, ""), ""));
    let h = run(&p, "fastrip");
    let r = &h.rows[0];
    assert!((r.fx_over_fn - mu).abs() < 1e-12 && r.fy_over_fn == 0.0, "{r:?}");
    assert_eq!(h.column("n_adhesion").unwrap()[0], 0.0);
    let p = problem(&scene_text("fr", "[\"fastrip\"]", mu, 22, &sweep("cx", 0.3, "cy = 0.4"), ""));
    let r = &run(&p, "fastrip").rows[0];
    assert!((r.fx_over_fn.hypot(r.fy_over_fn) - mu).abs() < 1e-12, "{r:?}");
    assert!((r.fy_over_fn / r.fx_over_fn - 0.4 / 0.3).abs() < 1e-12, "direction {}", r.fy_over_fn / r.fx_over_fn);
    // Negative creepages: the same forces, negated.
    let p = problem(&scene_text("fr", "[\"fastrip\"]", mu, 22, &sweep("cx", -0.3, "cy = -0.4"), ""));
    let n = &run(&p, "fastrip").rows[0];
    assert_eq!((n.fx_over_fn, n.fy_over_fn), (-r.fx_over_fn, -r.fy_over_fn));
}

/// The traction field stays within μ p: the adhesion area's strip solution by construction
/// (|φ'| < 1), the slip area on the bound; over sweeps in cx with cy and spin, in spin alone up to
/// a sliding contact (|φ'| ≥ 1), and in cy at spin on a wide contact, on a grid of 30 × 20.
#[test]
fn tractions_within_the_bound() {
    let mu = 0.3;
    let sweeps = [
        "kind = \"sweep\"\nfrom = -0.01\nto = 0.01\npoints = 41\ncy = 0.001\ncs = 0.0007",
        "kind = \"sweep\"\nover = \"cs\"\nfrom = -0.005\nto = 0.005\npoints = 41",
        "kind = \"sweep\"\nover = \"cy\"\nfrom = -0.006\nto = 0.006\npoints = 41\ncs = 0.001",
    ];
    let (mut adhesion, mut slip, mut worst) = (0usize, 0usize, 0.0f64);
    for (n, creepage) in sweeps.iter().enumerate() {
        let mut text = scene_text("fb", "[\"fastrip\"]", mu, 22, creepage, "")
            .replace("mx = 22", "mx = 30")
            .replace("my = 22", "my = 20");
        if n == 2 {
            text = text.replace("a_mm = 8.56", "a_mm = 4.0").replace("b_mm = 4.08", "b_mm = 8.0");
        }
        let p = problem(&text);
        let model = creepbench::solvers::builtin("fastrip").unwrap();
        let mut check = |_: &creepbench::problem::Sample, v: &creepbench::solvers::FieldView| {
            for k in 0..v.grid.len() {
                let (t, g) = (v.tx_mpa[k].hypot(v.ty_mpa[k]), mu * v.pressure_mpa[k]);
                if g > 0.0 {
                    worst = worst.max(t / g - 1.0);
                    if t < g * (1.0 - 1e-9) {
                        adhesion += 1
                    } else {
                        slip += 1
                    }
                } else {
                    assert_eq!(t, 0.0);
                }
            }
        };
        creepbench::history::sample_loop::run(&p, model, &[], Some(&mut check)).unwrap();
    }
    println!("{adhesion} elements inside the bound, {slip} on it; largest |t|/(mu p) - 1 = {worst:.1e}");
    assert!(worst < 1e-12 && adhesion > 1000 && slip > 1000, "{worst} {adhesion} {slip}");
}

/// A CONTACT steady sweep (reference/contact_envelope or reference/contact) with the scene's own
/// solvers replaced.
fn contact_case(folder: &str, case: &str) -> (Problem, Vec<(f64, f64)>) {
    let dir = root().join(format!("scenes/{folder}"));
    let text = suite_scene_text(folder, case);
    let text: Vec<String> = text
        .lines()
        .map(|l| if l.starts_with("solvers") { "solvers = [\"fastrip\", \"fastsim\"]".into() } else { l.into() })
        .collect();
    let p = creepbench::pipeline::resolve(&Scene::from_toml(&text.join("\n"), &dir).unwrap()).unwrap();
    let set = if folder == "thesis" { "contact" } else { "contact_envelope" };
    let mut rdr = csv::Reader::from_path(root().join(format!("reference/{set}/{case}.csv"))).unwrap();
    let h = rdr.headers().unwrap().clone();
    let col = |name: &str| h.iter().position(|c| c == name).unwrap();
    let (ix, iy) = (col("fx_over_fn"), col("fy_over_fn"));
    let rows = rdr.records().map(|r| r.unwrap()).map(|r| (r[ix].parse().unwrap(), r[iy].parse().unwrap())).collect();
    (p, rows)
}

/// Largest |Δfx|, |Δfy| of a model against the reference over a sweep.
fn worst(p: &Problem, solver: &str, reference: &[(f64, f64)]) -> f64 {
    let h = run(p, solver);
    let (fx, fy) = (h.column("fx_over_fn").unwrap(), h.column("fy_over_fn").unwrap());
    assert_eq!(fx.len(), reference.len());
    reference.iter().enumerate().map(|(k, (rx, ry))| (fx[k] - rx).abs().max((fy[k] - ry).abs())).fold(0.0, f64::max)
}

/// Against CONTACT's exact theory on its steady sweeps (the paper's own comparison tables were not
/// available here, so no published number is quoted). FaStrip is put forward as an alternative to
/// FASTSIM that keeps Kalker's linear theory at small creepage and follows the exact theory more
/// closely at larger creepage: on 9 of these 11 sweeps its worst |Δf| is below FASTSIM's (the cx
/// sweep by a factor 3.4, spin by 2.1, the circle by 2.4). Measured exceptions: the wide contact
/// b/a = 2 with spin (0.0193 against FASTSIM's 0.0131) and the cy sweep at spin 0.001 (0.0417
/// against 0.0416). Each worst |Δf| is also pinned at what it is (+3 %), so that it cannot grow
/// unnoticed.
#[test]
fn closer_to_the_exact_theory_than_fastsim() {
    #[rustfmt::skip]
    let cases: [(&str, &str, f64, bool); 11] = [
        // (suite, case, pinned worst |Δf| of fastrip, fastrip below fastsim)
        ("envelope", "steady_cy", 0.00394, true),
        ("envelope", "steady_cs", 0.0228, true),
        ("envelope", "steady_cx_eq_cy", 0.00611, true),
        ("envelope", "steady_cx_with_cs", 0.0279, true),
        ("envelope", "steady_cy_with_cs", 0.0430, false),
        ("envelope", "steady_circle_cy_with_cs", 0.00689, true),
        ("envelope", "steady_wide_cx_with_cs", 0.0199, false),
        ("envelope", "steady_slender_cy", 0.00742, true),
        ("envelope", "steady_large_spin", 0.0170, true),
        ("thesis", "steady_exact_g22", 0.00292, true),
        ("thesis", "steady_exact_g88", 0.00775, true),
    ];
    for (folder, case, pinned, below) in cases {
        let (p, reference) = contact_case(folder, case);
        let (fr, fs) = (worst(&p, "fastrip", &reference), worst(&p, "fastsim", &reference));
        println!("{case:<26} worst |df| against CONTACT: fastrip {fr:.5}, fastsim {fs:.5}");
        assert!(fr <= pinned, "{case}: fastrip {fr} above {pinned}");
        if below {
            assert!(fr < fs, "{case}: fastrip {fr}, fastsim {fs}");
        }
    }
}

/// A contact given per element is refused, naming `[geometry] kind` and what is allowed.
#[test]
fn refuses_a_contact_given_per_element() {
    let dir = root().join("scenes/nonhertz");
    let text = std::fs::read_to_string(dir.join("nh_flat_sweep_cx.toml")).unwrap();
    let text: Vec<String> = text
        .lines()
        .map(|l| if l.starts_with("solvers") { "solvers = [\"fastrip\"]".into() } else { l.into() })
        .collect();
    let scene = Scene::from_toml(&text.join("\n"), Path::new(&dir)).unwrap();
    let e = creepbench::pipeline::resolve(&scene).unwrap_err();
    assert_eq!(e.field, "geometry.kind", "{e}");
    assert!(e.value.contains("profile") && e.allowed.contains("Hertz's ellipse"), "{e}");
}
