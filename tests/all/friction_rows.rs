//! Coulomb friction per grid row (`[friction] mu_rows`, CONTACT's V = 3): equal rows give the
//! one-μ results bit for bit, the rows bound each row's traction, the models that cannot take it
//! and malformed keys are refused, and CONTACT's testbank case 8 imports as such a scene.

use crate::common;
use creepbench::error::InputError;
use creepbench::scene::Scene;
use std::path::Path;

/// The thesis contact on a 16 × 16 grid with `friction` TOML in place of `contact.mu`.
fn scene(name: &str, solvers: &str, friction: &str, creepage: &str) -> String {
    common::scene_text(name, solvers, 0.3, 16, creepage, "").replace("mu = 0.3\n", &format!("{friction}\n"))
}

fn rows(values: &[f64]) -> String {
    let list: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
    format!("[friction]\nlaw = \"coulomb\"\nmu_rows = [{}]", list.join(", "))
}

fn refused(text: &str) -> InputError {
    match Scene::from_toml(text, Path::new(".")) {
        Err(e) => e,
        Ok(scene) => creepbench::pipeline::resolve(&scene).expect_err("refused"),
    }
}

const SWEEP: &str = "kind = \"sweep\"\nover = \"cx\"\nat = [0.0005, 0.0015, 0.004]\ncy = 0.0007\ncs = 0.0001";
const STEPS: &str = "kind = \"step\"\nc = 0.001\ncy = -0.0005\ncs = 0.0002\nsteps = 12";

/// Every row at the same μ gives the one-μ solution bit for bit (the bound pressure is p itself,
/// μ_max the same coefficient): steady sweep and transient steps.
#[test]
fn equal_rows_give_the_one_mu_results_bit_for_bit() {
    for (kind, creepage) in [("sweep", SWEEP), ("steps", STEPS)] {
        let one = common::problem(&scene("one", "[\"contact\"]", "mu = 0.3", creepage));
        let per_row = common::problem(&scene("rows", "[\"contact\"]", &rows(&[0.3; 16]), creepage));
        assert_eq!(per_row.nominal.mu, 0.3);
        let (a, b) = (common::run(&one, "contact"), common::run(&per_row, "contact"));
        for column in ["fx_over_fn", "fy_over_fn", "mz_nmm", "n_adhesion", "n_slip", "iterations", "residual"] {
            let (x, y) = (a.column(column).unwrap(), b.column(column).unwrap());
            assert!(!x.is_empty());
            let bits = |v: &[f64]| v.iter().map(|f| f.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&x), bits(&y), "{kind}: {column}: {x:?} vs {y:?}");
        }
    }
}

/// In full sliding along x every element carries μ_j p: with the lower half of the rows at 0.2
/// and the upper at 0.4 on a pressure symmetric in y, Fx/FN = (0.2 + 0.4)/2, not the nominal 0.4;
/// the unequal halves turn the traction about z (the one-μ moment is zero by symmetry).
#[test]
fn rows_bound_their_own_traction_in_full_sliding() {
    let mu: Vec<f64> = (0..16).map(|j| if j < 8 { 0.2 } else { 0.4 }).collect();
    let creepage = "kind = \"sweep\"\nover = \"cx\"\nat = [0.5]";
    let p = common::problem(&scene("halves", "[\"contact\"]", &rows(&mu), creepage));
    assert_eq!(p.nominal.mu, 0.4);
    let h = common::run(&p, "contact");
    let fx = h.column("fx_over_fn").unwrap()[0];
    assert!((fx - 0.3).abs() < 1e-6, "fx/fn = {fx}");
    assert_eq!(h.column("n_adhesion").unwrap()[0], 0.0);
    let one = common::problem(&scene("one", "[\"contact\"]", "mu = 0.4", creepage));
    let h_one = common::run(&one, "contact");
    let fx_one = h_one.column("fx_over_fn").unwrap()[0];
    assert!((fx_one - 0.4).abs() < 1e-6, "fx/fn = {fx_one}");
    // Mz = Σ (x τy − y τx) dA: τx = μ_j p, so Mz ≈ −Σ y μ_j p dA, the upper half (y > 0) the
    // larger: negative, of the order 0.1 FN ȳ (ȳ the mean |y| of a half, about 0.42 b).
    let (mz, mz_one) = (h.column("mz_nmm").unwrap()[0], h_one.column("mz_nmm").unwrap()[0]);
    assert!(mz_one.abs() < 1e-6 * 100000.0 * 4.08, "{mz_one}");
    assert!(mz < -0.02 * 100000.0 * 4.08 && mz > -0.1 * 100000.0 * 4.08, "{mz}");
}

#[test]
fn models_and_keys_that_cannot_take_rows_are_refused() {
    let mu = rows(&[0.3; 16]);
    let e = refused(&scene("s", "[\"contact\", \"fastsim\"]", &mu, SWEEP));
    assert_eq!(e.field, "solvers");
    assert!(e.value.contains("fastsim") && e.allowed.contains("contact"), "{e}");
    let e = refused(&scene("s", "[\"contact\"]", &rows(&[0.3; 15]), SWEEP));
    assert_eq!((e.field.as_str(), e.value.as_str()), ("friction.mu_rows", "15 values"), "{e}");
    assert!(e.allowed.contains("grid.my = 16"), "{e}");
    let e = refused(&scene("s", "[\"contact\"]", &format!("mu = 0.3\n{mu}"), SWEEP));
    assert_eq!(e.field, "contact.mu", "{e}");
    let e = refused(&scene("s", "[\"contact\"]", &rows(&[[0.3; 15].as_slice(), &[0.0]].concat()), SWEEP));
    assert!(e.field.starts_with("friction.mu_rows"), "{e}");
    let falling = "[friction]\nlaw = \"exponential\"\nfkin = 0.2\nf1 = 0.1\nsabsh1_mm_s = 600.0\nmu_rows = [0.3]";
    let e = refused(&scene("s", "[\"contact\"]", falling, SWEEP));
    assert_eq!(e.field, "friction.mu_rows", "{e}");
}

/// testbank.inp case 8 (V = 3, FSTAT 0.20 … 0.60 over the 41 rows) imports as a steady scene
/// with `mu_rows`, the nominal μ their largest; its export is V = 3 with the rows after the
/// geometry, and imports back to the same rows.
#[test]
fn testbank_case_8_imports_its_rows_and_exports_them_back() {
    let deck = std::fs::read_to_string(common::root().join("reference/contact_public/testbank/testbank.inp")).unwrap();
    let imported = creepbench::import::contact::scene::import_text("testbank.inp", "testbank", &deck).unwrap();
    let s8 = imported.scenes.iter().find(|s| s.cases == [8, 8]).expect("case 8 imported");
    let text = &s8.files[0].1;
    assert!(text.contains("mu_rows = [0.2, 0.21, 0.22,") && text.contains("0.59, 0.6]"), "{text}");
    assert!(!text.contains("\nmu = "), "{text}");
    let status = &imported.statuses[7];
    assert!(status.notes.iter().any(|n| n.starts_with("V = 3: friction varying per grid row")), "{status:?}");
    let dir = common::tempdir("friction_rows_case_8");
    for (name, body) in &s8.files {
        std::fs::write(dir.join(name), body).unwrap();
    }
    let p = creepbench::pipeline::load(&dir.join(&s8.files[0].0), &[]).unwrap();
    let mu = p.friction_rows.as_ref().expect("rows").rows().to_vec();
    assert_eq!((mu.len(), mu[0], mu[40], p.nominal.mu), (41, 0.2, 0.6, 0.6));
    let exported = creepbench::export::contact::module3_input(&p);
    assert!(exported.contains("  3022020      L-D-C-M-Z-E"), "{exported}");
    let back = creepbench::import::contact::scene::import_text("back.inp", "back", &exported).unwrap();
    assert!(back.statuses.iter().all(|s| s.supported()), "{:?}", back.statuses);
    assert!(back.scenes[0].files[0].1.contains("mu_rows = [0.2, 0.21, 0.22,"));
}

/// A history that turns (the table's chi_deg: 0 for 10 steps, then 90) keeps each row's μ in the
/// bound after the turn: in full sliding |F|/FN = (0.2 + 0.4)/2 along x before it and along y
/// after it, not the nominal 0.4 of the largest row.
#[test]
fn a_turning_history_keeps_each_rows_bound() {
    let mu = rows(&(0..16).map(|j| if j < 8 { 0.2 } else { 0.4 }).collect::<Vec<f64>>());
    let dt_s = common::problem(&scene("dt", "[\"contact\"]", &mu, SWEEP)).rolling.dt_s;
    let dir = common::tempdir("friction_rows_turning");
    let mut csv = String::from("t_s,cx,cy,chi_deg\n");
    for k in 1..=20 {
        let (cx, cy, chi) = if k <= 10 { (0.5, 0.0, 0.0) } else { (0.0, 0.5, 90.0) };
        csv.push_str(&format!("{:?},{cx:?},{cy:?},{chi:?}\n", k as f64 * dt_s));
    }
    let file = dir.join("table.csv");
    std::fs::write(&file, csv).unwrap();
    let creepage = format!("kind = \"table\"\nfile = {:?}", file.to_str().unwrap());
    let h = common::run(&common::problem(&scene("turning", "[\"contact\"]", &mu, &creepage)), "contact");
    let (fx, fy) = (h.column("fx_over_fn").unwrap(), h.column("fy_over_fn").unwrap());
    assert_eq!(fx.len(), 20);
    for k in [9, 19] {
        let f = fx[k].hypot(fy[k]);
        assert!((f - 0.3).abs() < 1e-6, "step {}: |F|/FN = {f}", k + 1);
    }
    assert!(fy[19].abs() > 0.29, "{}", fy[19]);
}
