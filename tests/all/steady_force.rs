//! Prescribed total tangential forces in steady rolling (CONTACT T = 3 with F = 1: FX and CETA
//! given; F = 2: FX and FY given): a sweep's `fx_over_fn`, `fy_over_fn` (or `over` one of them),
//! imported from CONTACT's steady cases. The exact solver finds the creepages by the same force
//! iteration as in transient rolling (`solvers::contact::force`), around its steady solve.
//! References: CONTACT's printed forces of `examples/tractcurv.inp` (the creepages CONTACT was
//! given come back within the printed rounding), and a hand-made deck
//! (tests/data/contact_decks/steady_forces.inp) whose forces are those of its creepage twins.

use crate::common::*;
use creepbench::comparison::references::contact_output::{self, CaseBody};
use creepbench::export::contact::module3_input;
use creepbench::history::History;
use creepbench::import::contact::scene::{import_text, Imported};
use creepbench::problem::Problem;
use creepbench::solvers::contact::force::FORCE_TOL;
use std::path::Path;

/// Write an import's files into `dir` and load each scene by name.
fn load_all(imported: &Imported, dir: &Path) -> Vec<(String, Problem)> {
    for s in &imported.scenes {
        for (name, text) in &s.files {
            std::fs::write(dir.join(name), text).unwrap();
        }
    }
    let load = |s: &creepbench::import::contact::scene::SceneFiles| {
        (s.name.clone(), creepbench::pipeline::load(&dir.join(&s.files[0].0), &[]).unwrap())
    };
    imported.scenes.iter().map(load).collect()
}

/// The history of the scene named `name`.
fn run_named(scenes: &[(String, Problem)], name: &str) -> History {
    let p = &scenes.iter().find(|(n, _)| n == name).unwrap_or_else(|| panic!("no scene {name}")).1;
    run(p, "contact")
}

/// The forces reached are the prescribed ones (the stopping test, FORCE_TOL μ), every solve ended
/// normally.
fn assert_forces_reached(p: &Problem, h: &History) {
    for (s, r) in p.loading.rows().zip(&h.rows) {
        let mu = s.mu;
        if let Some(f) = s.fx_target {
            assert!((r.fx_over_fn - f).abs() <= FORCE_TOL * mu, "step {}: fx {} for {f}", s.step, r.fx_over_fn);
        }
        if let Some(f) = s.fy_target {
            assert!((r.fy_over_fn - f).abs() <= FORCE_TOL * mu, "step {}: fy {} for {f}", s.step, r.fy_over_fn);
        }
    }
    assert!(h.column("termination").unwrap().iter().all(|&t| t == 0.0));
}

/// tractcurv.inp's first 18 cases (Hertzian a/b = 0.5, μ = 0.33, CKSI from 1e-5 to 0.01, partial
/// then full slip) with CONTACT's printed −FX/FSTAT/FN prescribed in place of CKSI (F = 1): the
/// creepage found is CKSI within the printed rounding. Bound: F(cx) is concave and increasing, so
/// the slope between CKSI = c_k and the creepage found (at most c_(k+1)) is at least the twin's
/// secant s_k over [c_k, c_(k+1)]; |cx − CKSI| · s_k must stay within one printed unit (2
/// half-units) of the prescribed force: the printed rounding, plus the creepage-prescribed twin's
/// own difference from CONTACT (gated at most 0.91 half-units, tractcurv case 14).
#[test]
fn contacts_printed_forces_give_back_its_creepages_in_steady_rolling() {
    const CASES: usize = 18;
    let printed = contact_output::read(&root().join("reference/contact_public/examples/tractcurv.ref_out")).unwrap();
    let totals = |case: usize| match &printed[case - 1].body {
        CaseBody::Totals(t) => t.clone(),
        other => panic!("case {case}: {other:?}"),
    };
    // The deck's cases 1 to 18, F = 1 with FXREL as printed (CONTACT's sign: body 1).
    let deck = std::fs::read_to_string(root().join("tests/data/contact_decks/tractcurv.inp")).unwrap();
    let mut text = String::new();
    let mut case = 0;
    for line in deck.lines() {
        if line.trim() == "3 MODULE" {
            case += 1;
            if case > CASES {
                break;
            }
        }
        let line = match line.split_whitespace().collect::<Vec<_>>().as_slice() {
            ["203100", ..] => line.replacen("203100", "203110", 1),
            [fn_n, cksi, ceta, cphi, "FN,", ..] => {
                let fx = totals(case).fx_over_fstat_fn().unwrap();
                assert_eq!(cksi.parse::<f64>().unwrap(), totals(case).cx().unwrap().value);
                format!(" {fn_n}  {:?}  {ceta}  {cphi}   FN, FXREL, CETA, CPHI", -fx.value)
            }
            _ => line.to_string(),
        };
        text.push_str(&line);
        text.push('\n');
    }
    text.push_str(" 0 MODULE\n");
    let imported = import_text("tractcurv_forces.inp", "tractcurv_forces", &text).unwrap();
    assert!(imported.statuses.iter().all(|s| s.supported()), "{:?}", imported.statuses);
    assert_eq!(imported.scenes.len(), 1, "one sweep over fx_over_fn");
    assert!(imported.scenes[0].files[0].1.contains("over = \"fx_over_fn\""), "{}", imported.scenes[0].files[0].1);
    let dir = tempdir("steady_force_tractcurv");
    let scenes = load_all(&imported, &dir);
    let (p, force) = (&scenes[0].1, run(&scenes[0].1, "contact"));
    assert_forces_reached(p, &force);
    // The creepage-prescribed twin: the imported public scene (cases 1 to 30).
    let twin = run(&suite_problem("contact_public", "tractcurv_1", &[]), "contact");
    let (c, f) = (twin.column("cx").unwrap(), twin.column("fx_over_fn").unwrap());
    let found = force.column("cx").unwrap();
    let mut worst = (0.0f64, 0);
    for k in 0..CASES {
        let half = totals(k + 1).fx_over_fstat_fn().unwrap().half_unit * p.nominal.mu;
        let secant = (f[k + 1] - f[k]) / (c[k + 1] - c[k]);
        assert!(secant > 0.0 && found[k] < c[k + 1], "case {}: found {} beyond c = {}", k + 1, found[k], c[k + 1]);
        let units = (found[k] - c[k]).abs() * secant / half;
        println!("case {:2}: CKSI {:e}, found {:.9e}, {units:.3} half-units of FX/FN", k + 1, c[k], found[k]);
        if units > worst.0 {
            worst = (units, k + 1);
        }
    }
    println!("worst {:.3} half-units (case {})", worst.0, worst.1);
    assert!(worst.0 <= 2.0, "case {}: {} half-units", worst.1, worst.0);
}

/// The hand-made deck: its F = 1 (Hertzian, CETA given) and F = 2 (grid, with spin) steady cases
/// give back the creepages of their creepage-prescribed twins, and the steady start under F = 1
/// gives the twin's creepage before the transient steps at the same force.
#[test]
fn a_hand_made_deck_of_steady_forces_imports_and_gives_back_its_twins() {
    let path = root().join("tests/data/contact_decks/steady_forces.inp");
    let imported = creepbench::import::contact::import(&path).unwrap();
    assert!(imported.statuses.iter().all(|s| s.supported()), "{:?}", imported.statuses);
    let steady_f: Vec<usize> = imported
        .statuses
        .iter()
        .filter(|s| s.notes.iter().any(|n| n.contains("prescribed tangential forces in steady rolling")))
        .map(|s| s.case)
        .collect();
    assert_eq!(steady_f, vec![4, 5, 6, 10, 11, 12, 13]);
    let names: Vec<&str> = imported.scenes.iter().map(|s| s.name.as_str()).collect();
    // Cases 4-6 one sweep over Fx/FN (CETA held); the F = 2 points lie on no line: one scene each.
    let expected = ["steady_forces_1", "steady_forces_4", "steady_forces_7", "steady_forces_10"];
    assert_eq!(names, [&expected[..], &["steady_forces_11", "steady_forces_12", "steady_forces_13"]].concat());
    let dir = tempdir("steady_force_hand_made");
    let scenes = load_all(&imported, &dir);
    let worst = |a: &[f64], b: &[f64]| max_abs_diff(a, b).0;
    // F = 1: cx found, cy as given.
    let (twin, force) = (run_named(&scenes, "steady_forces_1"), run_named(&scenes, "steady_forces_4"));
    assert_forces_reached(&scenes[1].1, &force);
    let dcx = worst(&twin.column("cx").unwrap(), &force.column("cx").unwrap());
    println!("F = 1: |dcx| {dcx:.2e}");
    assert!(dcx < 1e-10, "{dcx:e}");
    assert_eq!(force.column("cy").unwrap(), vec![0.0002; 3]);
    // F = 2 with spin: cx and cy found.
    let twin = run_named(&scenes, "steady_forces_7");
    for (k, name) in ["steady_forces_10", "steady_forces_11", "steady_forces_12"].iter().enumerate() {
        let force = run_named(&scenes, name);
        assert_forces_reached(&scenes[3 + k].1, &force);
        let (cx, cy) = (force.rows[0].sample.cx, force.rows[0].sample.cy);
        let (dcx, dcy) = ((cx - twin.rows[k].sample.cx).abs(), (cy - twin.rows[k].sample.cy).abs());
        println!("F = 2, {name}: cx {cx:e} (|d| {dcx:.2e}), cy {cy:e} (|d| {dcy:.2e}), cs {}", force.rows[0].sample.cs);
        assert!(dcx < 1e-10 && dcy < 1e-10, "{name}: {dcx:e} {dcy:e}");
        assert_eq!(force.rows[0].sample.cs, 0.0002);
    }
    // The steady start under case 5's FX: case 2's creepage; the transient steps reach the force.
    let start = run_named(&scenes, "steady_forces_13");
    assert_forces_reached(&scenes[6].1, &start);
    assert_eq!(start.rows[0].sample.step, 0);
    assert!((start.rows[0].sample.cx - 0.001).abs() < 1e-10, "{}", start.rows[0].sample.cx);
}

/// `export contact` writes a steady force sweep as T = 3, F = 1 cases (FXREL = −fx/μ) and F = 2
/// (FYREL), and `import contact` gives its rows back bit for bit.
#[test]
fn export_then_import_gives_back_a_steady_force_sweep() {
    let creepage = "kind = \"sweep\"\nover = \"fx_over_fn\"\nat = [0.05, 0.1, 0.15]\ncy = 0.0003\ncs = 0.0001";
    let f1 = problem(&scene_text("sf1", "[\"contact\"]", 0.3, 12, creepage, ""));
    let creepage = "kind = \"sweep\"\nover = \"fy_over_fn\"\nat = [-0.1, 0.05]\nfx_over_fn = 0.12\ncs = 0.0001";
    let f2 = problem(&scene_text("sf2", "[\"contact\"]", 0.3, 12, creepage, ""));
    for (p, f) in [(&f1, 1), (&f2, 2)] {
        let deck = module3_input(p);
        assert!(deck.contains(&format!("  2031{f}0      P-B-T-N-F-S")), "{deck}");
        let imported = import_text("sf.inp", "sf", &deck).unwrap();
        assert!(imported.statuses.iter().all(|s| s.supported()), "{:?}", imported.statuses);
        let dir = tempdir(&format!("steady_force_round_trip_{f}"));
        let back = load_all(&imported, &dir);
        assert_eq!(back.len(), 1, "{deck}");
        let rows = |p: &Problem| {
            p.loading.rows().map(|s| (s.fx_target, s.fy_target, s.cx, s.cy, s.cs, s.fn_n, s.mu)).collect::<Vec<_>>()
        };
        assert_eq!(rows(&back[0].1), rows(p), "F = {f}");
    }
}

/// |F| at or above μ FN has no partial-slip solution: refused naming the sweep point (a scene) or
/// the case (a deck: CONTACT accepts |FXREL| up to 1, full sliding, and refuses more; here the
/// case is refused with the project's reason).
#[test]
fn a_steady_force_at_or_above_mu_is_refused() {
    let text = |creepage: &str| scene_text("sat", "[\"contact\"]", 0.3, 12, creepage, "");
    let err = |creepage: &str| {
        let scene = creepbench::scene::Scene::from_toml(&text(creepage), Path::new(".")).map_err(|e| e.to_string());
        scene.and_then(|s| creepbench::pipeline::resolve(&s).map(|_| ()).map_err(|e| e.to_string())).unwrap_err()
    };
    let e = err("kind = \"sweep\"\nover = \"fx_over_fn\"\nat = [0.1, 0.3]");
    assert!(e.contains("creepage.fx_over_fn") && e.contains("sweep point 2") && e.contains("below mu = 0.3"), "{e}");
    let e = err("kind = \"sweep\"\nover = \"fy_over_fn\"\nat = [0.25]\nfx_over_fn = 0.2");
    assert!(e.contains("|(Fx, Fy)|/FN = 0.32") && e.contains("sweep point 1"), "{e}");
    let e = err("kind = \"sweep\"\nover = \"fx_over_fn\"\nat = [1.0]");
    assert!(e.contains("creepage.at[0]") && e.contains("fx_over_fn = 1"), "{e}");
    let e = err("kind = \"sweep\"\nover = \"fy_over_fn\"\nat = [0.1]");
    assert!(e.contains("fy_over_fn only together with fx_over_fn"), "{e}");
    let e = err("kind = \"sweep\"\nfx_over_fn = 0.1\ncx = 0.001\nat = [0.0]");
    assert!(e.contains("creepage.cx") && e.contains("only one of"), "{e}");
    let e = err("kind = \"sweep\"\nfx_over_fn = 0.1\nover = \"cx\"\nat = [0.0]");
    assert!(e.contains("creepage.over"), "{e}");
    // A deck: FXREL = 1 (full sliding) in a steady case.
    let deck = std::fs::read_to_string(root().join("tests/data/contact_decks/steady_forces.inp")).unwrap();
    let deck = deck.replacen("-0.520812673213386", "-1.0", 1);
    let imported = import_text("sat.inp", "sat", &deck).unwrap();
    let case5 = &imported.statuses[4];
    assert!(!case5.supported());
    let why = case5.refused.join("; ");
    assert!(why.contains("creepage.fx_over_fn") && why.contains("below mu = 0.3"), "{why}");
}

/// A steady force sweep whose points come in any order (near saturation, then a small force, the
/// opposite saturation, zero): every point starts from the last one's creepage and Jacobian and
/// still reaches its force (the iteration's trust region, `solvers::contact::force`).
#[test]
fn a_steady_force_sweep_in_any_order_reaches_every_force() {
    let text = suite_scene_text("contact_public", "tractcurv_1");
    let at = "at = [0.3298, 0.001, 0.32, -0.2, 0.0, 0.3299, -0.3299, 0.05]";
    let start = text.find("at = [").unwrap();
    let end = start + text[start..].find(']').unwrap() + 1;
    let text = format!("{}{at}{}", &text[..start], &text[end..]).replace("over = \"cx\"", "over = \"fx_over_fn\"");
    let p = problem(&text);
    let h = run(&p, "contact");
    assert_forces_reached(&p, &h);
    let cx = h.column("cx").unwrap();
    assert!(cx[0] > 0.004 && cx[6] < -0.006 && cx[4].abs() < 1e-9, "{cx:?}");
}
