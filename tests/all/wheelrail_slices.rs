//! CONTACT's variable rail profiles (slices files of switches and crossings,
//! `reference/contact_wheelrail/testbank/profiles/*.slcs`) read and interpolated along the track
//! as CONTACT does:
//!
//! - against CONTACT's own routines (`profile_read_file` → `varprof_read_file`, then
//!   `varprof_intpol_xunif` at one position: the cross-section's points and arc length, printed to
//!   17 digits by a driver linked with a gfortran build of revision 2707; `tests/data/slices/`,
//!   its README), on the rails of the switches-and-crossings decks (interpolating spline) and the
//!   wheels of the wheel-flat decks (approximating spline, SMOOTH 0 and 5): every printed point
//!   within 1e-9 mm;
//! - against CONTACT's printed results of the decks `testbank/examples_s+c/*`: each contact
//!   patch's reference ZCP(R) is the rail's height on the cross-section at u = S_WS + XCP(TR),
//!   at y = YCP(R), to CONTACT's printed digits (half a unit of its last digit, widened by the
//!   rail's slopes times the half-units of the printed XCP and YCP).

use crate::common::root;
use creepbench::wheelrail::profile::slices::{read_slices, Slices};
use creepbench::wheelrail::profile::{ProfileKind, ProfileOptions};

/// A slices file of CONTACT's decks: its name, its folder, rail or wheel, the decks' SCALE and
/// SMOOTH (MIRRORZ = −1 in every deck).
struct File {
    name: &'static str,
    dir: &'static str,
    kind: ProfileKind,
    scale: f64,
    smooth: f64,
}

const RAIL: ProfileKind = ProfileKind::Rail;
const WHEEL: ProfileKind = ProfileKind::Wheel;
const TESTBANK: &str = "reference/contact_wheelrail/testbank/profiles";

const FILES: [File; 8] = [
    File { name: "uk_crossing.slcs", dir: TESTBANK, kind: RAIL, scale: 1000.0, smooth: 0.0 },
    File { name: "wing_rail.slcs", dir: TESTBANK, kind: RAIL, scale: 1.0, smooth: 0.0 },
    File { name: "cross_nose.slcs", dir: TESTBANK, kind: RAIL, scale: 1.0, smooth: 0.0 },
    File { name: "cross+wing.slcs", dir: TESTBANK, kind: RAIL, scale: 1.0, smooth: 0.0 },
    File { name: "uk_interrupt_v2.slcs", dir: TESTBANK, kind: RAIL, scale: 1000.0, smooth: 0.0 },
    File { name: "cross+wing_extd.slcs", dir: TESTBANK, kind: RAIL, scale: 1.0, smooth: 0.0 },
    File { name: "flat_d09.slcw", dir: TESTBANK, kind: WHEEL, scale: 1.0, smooth: 0.0 },
    File { name: "S1002_flat.slcw", dir: "reference/contact_wheelrail/examples", kind: WHEEL, scale: 1.0, smooth: 5.0 },
];

fn read(f: &File) -> Slices {
    let opts = ProfileOptions { scale: f.scale, smooth: f.smooth, mirror_z: -1, ..Default::default() };
    read_slices(&root().join(f.dir).join(f.name), f.kind, &opts).unwrap_or_else(|e| panic!("{}: {e}", f.name))
}

/// The rail slices file `name` of the testbank with SCALE `scale`.
fn slices(name: &'static str, scale: f64) -> Slices {
    read(&File { name, dir: TESTBANK, kind: RAIL, scale, smooth: 0.0 })
}

/// CONTACT's cross-sections: (u, n, [(j, y, z, s)]).
type Section = (f64, usize, Vec<(usize, f64, f64, f64)>);

fn contact_sections(name: &str) -> Vec<Section> {
    let text = std::fs::read_to_string(root().join("tests/data/slices").join(name)).unwrap();
    let mut out: Vec<Section> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('%')) {
        let v: Vec<&str> = line.split_whitespace().collect();
        if v[0] == "u" {
            out.push((v[1].parse().unwrap(), v[3].parse().unwrap(), Vec::new()));
        } else {
            let f = |k: usize| v[k].parse::<f64>().unwrap();
            out.last_mut().unwrap().2.push((v[0].parse().unwrap(), f(1), f(2), f(3)));
        }
    }
    out
}

/// The worst |Δ| [mm] of our cross-sections' points and arc lengths against CONTACT's.
fn worst_against_contact(f: &File) -> f64 {
    let s = read(f);
    let name = f.name;
    let mut worst = 0.0f64;
    let stem = name.rsplit_once('.').unwrap().0;
    for (u, n, points) in contact_sections(&format!("{stem}.txt")) {
        // The section's points: the interpolated samples, smoothed where SMOOTH > 0 (CONTACT
        // replaces them by the smoothing spline's values).
        let section = s.section_at(u).unwrap();
        let (y, z) = (section.y_mm(), section.z_mm());
        assert_eq!(y.len(), n, "{name} at u = {u}: points");
        assert_eq!(s.samples_at(u).0.len(), n);
        for &(j, yc, zc, sc) in &points {
            let d = (y[j - 1] - yc).abs().max((z[j - 1] - zc).abs()).max((section.s_mm()[j - 1] - sc).abs());
            assert!(
                d < 1e-9,
                "{name} at u = {u}, point {j}: ({}, {}, s {}) vs CONTACT ({yc}, {zc}, s {sc})",
                y[j - 1],
                z[j - 1],
                section.s_mm()[j - 1]
            );
            worst = worst.max(d);
        }
    }
    worst
}

#[test]
fn cross_sections_are_contacts_own() {
    for f in &FILES {
        let worst = worst_against_contact(f);
        eprintln!("{}: worst {worst:.2e} mm", f.name);
    }
}

/// The surface's height at (u, y) against CONTACT's `varprof_get_z_at_xy` (the driver's
/// `*_z.txt`: 999 where CONTACT finds no surface, beside the rail at u; u held to the first and
/// last slice's): the same points without a surface, and every height within 1e-9 mm plus
/// 1e-8 |dz/dy| (CONTACT's Newton solve for the lateral parameter stops at 1e-8 mm in y).
#[test]
fn surface_heights_are_contacts_own() {
    for f in FILES.iter().filter(|f| f.name != "S1002_flat.slcw") {
        let s = read(f);
        let stem = f.name.rsplit_once('.').unwrap().0;
        let text = std::fs::read_to_string(root().join(format!("tests/data/slices/{stem}_z.txt"))).unwrap();
        let (mut worst, mut count, mut outside) = (0.0f64, 0, 0);
        for line in text.lines().filter(|l| !l.starts_with('%')) {
            let v: Vec<f64> = line.split_whitespace().map(|x| x.parse().unwrap()).collect();
            let (u, y, zc) = (v[0], v[1], v[2]);
            let ours = s.surface_z_at(u, y);
            if zc == 999.0 {
                assert_eq!(ours, None, "{} at u = {u}, y = {y}: CONTACT finds no surface", f.name);
                outside += 1;
                continue;
            }
            let z = ours.unwrap_or_else(|| panic!("{} at u = {u}, y = {y}: no surface, CONTACT's z = {zc}", f.name));
            // CONTACT's Newton solve for v stops at |y(v) − y| < 1e-8 mm (`solve_cubic_newton`,
            // tol_f), which moves its z by up to 1e-8 |dz/dy|.
            let dz_dy = match (s.surface_z_at(u, y + 1e-3), s.surface_z_at(u, y - 1e-3)) {
                (Some(a), Some(b)) => (a - b) / 2e-3,
                _ => 0.0,
            };
            let scaled = (z - zc).abs() / (1e-9 + 1e-8 * dz_dy.abs());
            assert!(scaled <= 1.0, "{} at u = {u}, y = {y}: z {z} vs CONTACT {zc} (dz/dy {dz_dy})", f.name);
            worst = worst.max(scaled);
            count += 1;
        }
        eprintln!("{}: {count} heights, worst {worst:.2} of the bound; {outside} points without surface", f.name);
    }
}

/// Each patch's printed (S_WS, XCP(TR), YCP(R), ZCP(R)) with the printed texts of XCP, YCP, ZCP.
fn printed_references(deck: &str) -> Vec<(usize, f64, [f64; 3], [String; 3])> {
    let path = root().join("reference/contact_wheelrail/testbank/examples_s+c").join(deck);
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let (mut case, mut s_ws, mut out) = (0, f64::NAN, Vec::new());
    for (i, l) in lines.iter().enumerate() {
        let t = l.trim_start();
        if let Some(rest) = t.strip_prefix("Case") {
            case = rest.trim().parse().unwrap_or(case);
        }
        if l.contains("S_WS") && l.contains("Y_WS") {
            s_ws = lines[i + 1].split_whitespace().next().unwrap().parse().unwrap();
        }
        if l.contains("XCP(TR)") && l.contains("YCP(R)") {
            let v: Vec<&str> = lines[i + 1].split_whitespace().collect();
            let f = |k: usize| v[k].parse::<f64>().unwrap();
            out.push((case, s_ws, [f(0), f(4), f(5)], [v[0].into(), v[4].into(), v[5].into()]));
        }
    }
    out
}

/// Half a unit of a printed number's last digit.
fn half_unit(printed: &str) -> f64 {
    let decimals = printed.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    0.5 * 10f64.powi(-decimals)
}

/// The worst |ZCP(R) − CONTACT's| over each deck's patches in units of its bound.
#[test]
fn the_patches_reference_heights_are_contacts_printed_ones() {
    let decks: [(&str, &str, f64); 9] = [
        ("mbench_locus.ref_out", "uk_crossing.slcs", 1000.0),
        ("mbench_brute.ref_out", "uk_crossing.slcs", 1000.0),
        ("wing_locus.ref_out", "wing_rail.slcs", 1.0),
        ("wing_brute.ref_out", "wing_rail.slcs", 1.0),
        ("cross_locus.ref_out", "cross_nose.slcs", 1.0),
        ("cross_brute.ref_out", "cross_nose.slcs", 1.0),
        ("cross+wing.ref_out", "cross+wing.slcs", 1.0),
        ("mbench_intrup.ref_out", "uk_interrupt_v2.slcs", 1000.0),
        ("cw_interrupt.ref_out", "cross+wing_extd.slcs", 1.0),
    ];
    for (deck, file, scale) in decks {
        let s = slices(file, scale);
        let refs = printed_references(deck);
        assert!(!refs.is_empty(), "{deck}");
        let mut worst = 0.0f64;
        for (case, s_ws, [xcp, ycp, zcp], texts) in &refs {
            let u = s_ws + xcp;
            let at = |u: f64| s.section_at(u).unwrap().point_at_y(*ycp).unwrap();
            let p = at(u);
            let dz_dx = (at(u + 0.01).z_mm - at(u - 0.01).z_mm) / 0.02;
            let bound = half_unit(&texts[2])
                + dz_dx.abs() * half_unit(&texts[0])
                + p.slope_dz_dy().abs() * half_unit(&texts[1]);
            let ratio = (p.z_mm - zcp).abs() / bound;
            assert!(
                ratio <= 1.0,
                "{deck} case {case}: z {} at u = {u}, y = {ycp} vs CONTACT's ZCP(R) {} (bound {bound:.2e})",
                p.z_mm,
                texts[2]
            );
            worst = worst.max(ratio);
        }
        eprintln!("{deck}: {} patches, worst {worst:.2} of the bound", refs.len());
    }
}

/// Interruptions (slices whose parts are missing: a negative S_F at a slice's start or end):
/// the cross-sections hold only the points the surface has (255 of 558 on the UK crossing's
/// slices before the nose, 198 of 595 on the extended crossing before u = 0), as CONTACT's.
#[test]
fn interrupted_slices_hold_the_parts_present() {
    for (name, scale, before, after, n0, n1) in
        [("uk_interrupt_v2.slcs", 1000.0, 118.9, 118.94, 255, 558), ("cross+wing_extd.slcs", 1.0, -1.0, 0.0, 198, 595)]
    {
        let s = slices(name, scale);
        assert_eq!(s.section_at(before).unwrap().y_mm().len(), n0, "{name} at {before}");
        assert_eq!(s.section_at(after).unwrap().y_mm().len(), n1, "{name} at {after}");
    }
}
