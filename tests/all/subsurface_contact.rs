//! The subsurface stresses (src/physics/halfspace/stress.rs) against CONTACT's printed `.subs`
//! files of its example `subsurf` (reference/contact_public/examples/subsurf.ref_subs: case 2,
//! pn = 1 and px = 0.999 on the unit square; reference/contact_subsurf/subsurf.0001.subs: case 1,
//! pn = 1 alone, this project's run of the same deck): every printed number of all 6633 points,
//! in units of its last printed digit.

use crate::common::root;
use creepbench::physics::halfspace::invariants::invariants;
use creepbench::physics::halfspace::stress::{elastic_field, LoadedRectangle};

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

fn compare(path: &str, px: f64) -> Worst {
    let mut w = Worst { below_digits: 0.0, surface_digits: 0.0, surface_abs: 0.0, points: 0 };
    for r in rows(path) {
        let p = [r[0].value, r[1].value, r[2].value];
        for (k, (c, o)) in r[3..].iter().zip(ours(px, p)).enumerate() {
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

fn check(path: &str, px: f64, label: &str) {
    let w = compare(path, px);
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
    check("reference/contact_subsurf/subsurf.0001.subs", 0.0, "subsurf case 1");
}

#[test]
fn stress_matches_contact_subsurf_case_2_pressure_and_traction() {
    check("reference/contact_public/examples/subsurf.ref_subs", 0.999, "subsurf case 2");
}
