//! The subsurface stresses (src/physics/halfspace/stress.rs) against CONTACT's printed `.subs`
//! files of its example `subsurf` (reference/contact_subsurf/subsurf.ref_subs: case 2,
//! pn = 1 and px = 0.999 on the unit square; reference/contact_subsurf/subsurf.0001.subs: case 1,
//! pn = 1 alone, this project's run of the same deck): every printed number of all 6633 points,
//! in units of its last printed digit.

use crate::common::{root, tempdir};
use creepbench::physics::halfspace::invariants::invariants;
use creepbench::physics::halfspace::stress::{elastic_field, LoadedRectangle};
use std::process::Command;

/// One printed number and the unit of its last digit.
#[derive(Clone, Copy)]
struct Printed {
    value: f64,
    unit: f64,
}

fn printed(s: &str) -> Printed {
    let value: f64 = s.parse().unwrap_or_else(|_| panic!("not a number: {s}"));
    let (mantissa, exp) = match s.split_once(['E', 'e']) {
        Some((m, e)) => (m, e.parse::<i32>().unwrap()),
        None => (s, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    Printed { value, unit: 10f64.powi(exp - decimals) }
}

/// The data rows of a `.subs` file: X Y Z UX UY UZ SIGHYD SIGVM SIGXX SIGXY SIGXZ SIGYY SIGYZ SIGZZ.
fn rows(path: &str) -> Vec<Vec<Printed>> {
    let text = std::fs::read_to_string(root().join(path)).unwrap();
    let mut out = Vec::new();
    let mut header_next = false;
    for line in text.lines() {
        if line.starts_with('%') {
            // the line after "%   NX  NY  NZ" is the block's sizes, not a point
            header_next = line.contains("NX");
            continue;
        }
        if std::mem::take(&mut header_next) {
            continue;
        }
        out.push(line.split_whitespace().map(printed).collect());
    }
    out
}

/// CONTACT's one element: [XL, XL+DX] × [YL, YL+DY] with XL = −0.4999, YL = −0.4998, DX = DY = 1;
/// G = 1, ν = 0.28.
fn element(px: f64) -> LoadedRectangle {
    LoadedRectangle { x_mm: [-0.4999, 0.5001], y_mm: [-0.4998, 0.5002], traction_mpa: [px, 0.0, 1.0] }
}

/// Ours per printed column (from UX on).
fn ours(px: f64, p: [f64; 3]) -> [f64; 11] {
    let f = elastic_field(&[element(px)], 1.0, 0.28, p).unwrap();
    let s = f.sigma_mpa;
    let inv = invariants(&s);
    let [ux, uy, uz] = f.u_mm;
    [ux, uy, uz, inv.hydrostatic_mpa, inv.von_mises_mpa, s[0][0], s[0][1], s[0][2], s[1][1], s[1][2], s[2][2]]
}

/// The worst differences: below the surface (z > 0) in units of the printed digit; on the
/// surface (z = 0) in units of the printed digit where that exceeds CONTACT's surface noise, and
/// absolute. CONTACT evaluates every corner offset at |z| ≥ 5e-7 of its distance (its `epsrel`, so
/// that no component vanishes), so its surface values carry an error of that order times the
/// stress gradient (it prints σzz = 9.9e-7 where the exact value is 0 beside the load).
struct Worst {
    below_digits: f64,
    surface_digits: f64,
    surface_abs: f64,
    points: usize,
}

/// The absolute size of CONTACT's surface noise on this deck (loads of 1 MPa): 5e-7 of the corner
/// distances (up to 7.8 mm here) times the stress gradients next to the loaded element.
const SURFACE_NOISE: f64 = 1e-5;

/// Round-off of the corner sums (terms of order 1, their logarithms and arctangents): differences
/// below 1e-13 absolute are neither code's digits (e.g. σyz = 3.1276e-10 printed, 3.12769e-10 ours).
const ROUND_OFF: f64 = 1e-13;

fn compare(path: &str, ours: &dyn Fn(usize, [f64; 3]) -> [f64; 11]) -> Worst {
    let mut w = Worst { below_digits: 0.0, surface_digits: 0.0, surface_abs: 0.0, points: 0 };
    for (n, r) in rows(path).iter().enumerate() {
        let p = [r[0].value, r[1].value, r[2].value];
        for (k, (c, o)) in r[3..].iter().zip(ours(n, p)).enumerate() {
            let d = (o - c.value).abs();
            let digits = if d <= ROUND_OFF { 0.0 } else { d / c.unit };
            if std::env::var("SUBS_DEBUG").is_ok() && digits > 0.5 && (p[2] > 0.0 || d > SURFACE_NOISE) {
                eprintln!("{p:?} column {k}: ours {o:e} printed {:e}", c.value);
            }
            if p[2] > 0.0 {
                w.below_digits = w.below_digits.max(digits);
            } else {
                w.surface_abs = w.surface_abs.max(d);
                if d > SURFACE_NOISE {
                    w.surface_digits = w.surface_digits.max(digits);
                }
            }
        }
        w.points += 1;
    }
    w
}

fn check(path: &str, ours: &dyn Fn(usize, [f64; 3]) -> [f64; 11], label: &str) {
    let w = compare(path, ours);
    eprintln!(
        "{label}: {} points; below the surface worst {:.3} printed digits; on the surface worst |diff| {:.2e} ({:.3} digits beyond {SURFACE_NOISE:e})",
        w.points, w.below_digits, w.surface_abs, w.surface_digits
    );
    assert_eq!(w.points, 15 + 21 * 21 * 15);
    assert!(w.below_digits <= 0.5, "below the surface: {} units of the printed digit", w.below_digits);
    assert!(w.surface_digits <= 0.5, "on the surface: {} units of the printed digit", w.surface_digits);
}

#[test]
fn stress_matches_contact_subsurf_case_1_pressure() {
    check("reference/contact_subsurf/subsurf.0001.subs", &|_, p| ours(0.0, p), "subsurf case 1");
}

#[test]
fn stress_matches_contact_subsurf_case_2_pressure_and_traction() {
    check("reference/contact_subsurf/subsurf.ref_subs", &|_, p| ours(0.999, p), "subsurf case 2");
}

fn creepbench(dir: &std::path::Path, args: &[&str], threads: &str) {
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(dir)
        .env("RAYON_NUM_THREADS", threads)
        .args(args)
        .output()
        .unwrap();
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
}

/// The columns of CONTACT's `.subs` (from UX on) out of a row of `<solver>_stress.csv`.
fn subs_columns(line: &str) -> ([f64; 3], [f64; 11]) {
    let v: Vec<f64> = line.split(',').map(|s| s.parse().unwrap()).collect();
    // step, block, x, y, z, ux, uy, uz, sxx, syy, szz, sxy, syz, sxz, shyd, svm, ...
    let p = [v[2], v[3], v[4]];
    (p, [v[5], v[6], v[7], v[14], v[15], v[8], v[11], v[13], v[9], v[12], v[10]])
}

/// `import contact` of subsurf.inp writes `[stress]` (both blocks, the case's step); `simulate`
/// solves each case with the exact solver and writes `contact_stress.csv`, which matches CONTACT's
/// `.subs` files as the physics alone does (the solved tractions: pn = 1, px = 0.999 on body 1),
/// with the same bytes on one thread and two.
#[test]
fn stress_import_subsurf_and_simulate_matches_contact() {
    let dir = tempdir("stress_import_subsurf");
    let deck = root().join("reference/contact_subsurf/subsurf.inp");
    creepbench(&dir, &["import", "contact", deck.to_str().unwrap(), "--out", "deck"], "2");
    let scene2 = std::fs::read_to_string(dir.join("deck/subsurf_2.toml")).unwrap();
    assert!(scene2.contains("[stress]") && scene2.contains("[[stress.block]]"), "{scene2}");
    for (case, reference) in
        [(1, "reference/contact_subsurf/subsurf.0001.subs"), (2, "reference/contact_subsurf/subsurf.ref_subs")]
    {
        let scene = format!("deck/subsurf_{case}.toml");
        creepbench(&dir, &["simulate", &scene, "--out", "one"], "1");
        creepbench(&dir, &["simulate", &scene, "--out", "two"], "2");
        let file = format!("subsurf_{case}/contact_stress.csv");
        let text = std::fs::read_to_string(dir.join("one").join(&file)).unwrap();
        assert_eq!(
            text,
            std::fs::read_to_string(dir.join("two").join(&file)).unwrap(),
            "thread count changed the bytes"
        );
        let rows: Vec<([f64; 3], [f64; 11])> = text.lines().skip(1).map(subs_columns).collect();
        let ours = |n: usize, p: [f64; 3]| {
            assert_eq!(rows[n].0, p, "point {n}");
            rows[n].1
        };
        assert_eq!(rows.len(), 15 + 21 * 21 * 15);
        check(reference, &ours, &format!("simulate subsurf_{case}"));
    }
}

/// `export contact` writes the S digit (3 at the stress step, with MATFIL, OUTPUT and each block
/// as ISUBS = 9) and `import contact` of that deck gives back the same `[stress]`.
#[test]
fn stress_export_writes_the_points_back() {
    let dir = tempdir("stress_export_subsurf");
    let deck = root().join("reference/contact_subsurf/subsurf.inp");
    creepbench(&dir, &["import", "contact", deck.to_str().unwrap(), "--out", "deck"], "2");
    creepbench(&dir, &["export", "contact", "deck/subsurf_2.toml", "--out", "exp"], "2");
    let inp = std::fs::read_to_string(dir.join("exp/subsurf_2.inp")).unwrap();
    assert!(inp.lines().any(|l| l.trim_start().starts_with("203113 ")), "{inp}");
    assert_eq!(inp.matches("ISUBS").count(), 3, "{inp}");
    creepbench(&dir, &["import", "contact", "exp/subsurf_2.inp", "--out", "again"], "2");
    let stress = |path: &str| {
        let text = std::fs::read_to_string(dir.join(path)).unwrap();
        text[text.find("[stress]").unwrap()..].to_string()
    };
    assert_eq!(stress("deck/subsurf_2.toml"), stress("again/subsurf_2_1.toml"));
}
