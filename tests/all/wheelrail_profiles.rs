//! The profile stage of CONTACT's module 1 on CONTACT's own profiles (tests/data/profiles, see its
//! README.md): the points CONTACT keeps after cleaning, its kinks, and its spline's z, slope and
//! curvature at given y, each against the numbers CONTACT's routines print for the same file
//! (a gfortran build of revision 2707 called from a small driver; `profile_read_file`,
//! `spline_get_xz_at_y` with `spline_add_topview`, `spline_eval`, `prw_determine_foldback`).
//! Tolerances: the points to the bit; z within 1e-6 mm (CONTACT's Newton solve for s at y stops at
//! |Δy| < 1e-8 mm, which moves z by up to 3e-7 mm on a steep flank); slope and curvature within
//! 1e-6 relative.
//!
//! CONTACT's numbers are written as it printed them, to 17 digits.
#![allow(clippy::excessive_precision)]

use crate::common::root;
use creepbench::wheelrail::profile::{read_profile, Profile, ProfileError, ProfileKind, ProfileOptions};
use std::path::PathBuf;

fn path(name: &str) -> PathBuf {
    root().join("tests/data/profiles").join(name)
}

fn read(name: &str, kind: ProfileKind, opts: &ProfileOptions) -> Profile {
    read_profile(&path(name), kind, opts).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn rail(name: &str) -> Profile {
    read(name, ProfileKind::Rail, &ProfileOptions::default())
}

fn wheel(name: &str) -> Profile {
    read(name, ProfileKind::Wheel, &ProfileOptions::default())
}

/// CONTACT's (y, s, z, dz/dy, curvature) at one y.
type Query = [f64; 5];

/// The profile's values at CONTACT's y agree with CONTACT's.
fn assert_queries(p: &Profile, expected: &[Query]) {
    for &[y, s, z, slope, curvature] in expected {
        let q = p.point_at_y(y).unwrap_or_else(|| panic!("{}: no point at y = {y}", p.file()));
        let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1e-3);
        assert!((q.z_mm - z).abs() < 1e-6, "{} y = {y}: z {} vs CONTACT {z}", p.file(), q.z_mm);
        assert!((q.s_mm - s).abs() < 1e-5, "{} y = {y}: s {} vs CONTACT {s}", p.file(), q.s_mm);
        assert!(rel(q.slope_dz_dy(), slope) < 1e-6, "{} y = {y}: slope {} vs {slope}", p.file(), q.slope_dz_dy());
        assert!(
            rel(q.curvature_per_mm, curvature) < 1e-6,
            "{} y = {y}: curvature {} vs {curvature}",
            p.file(),
            q.curvature_per_mm
        );
        assert_eq!(p.z_at(y), Some(q.z_mm));
    }
}

/// Point `i` (1-based, as CONTACT prints) is CONTACT's (y, z, s).
fn assert_point(p: &Profile, i: usize, y: f64, z: f64, s: f64) {
    assert_eq!((p.y_mm()[i - 1], p.z_mm()[i - 1]), (y, z), "{} point {i}", p.file());
    assert!((p.s_mm()[i - 1] - s).abs() < 1e-12, "{} point {i}: s {} vs {s}", p.file(), p.s_mm()[i - 1]);
}

#[test]
fn the_uic60_rail_is_contact_s() {
    let p = rail("MBench_UIC60_v3.prr");
    assert_eq!(p.len(), 495);
    assert_eq!(p.breaks(), [0, 494]);
    assert_point(&p, 1, -4.3704898000000000e1, 3.8510725999999998e1, -73.686782843549707);
    assert_point(&p, 495, 3.0595911999999995e1, 3.6653224999999999e1, 58.701841948690827);
    assert!(p.y_mm().windows(2).all(|w| w[1] > w[0]), "a rail's y ascends");
    assert_queries(
        &p,
        &[
            [0.0, -2.3108298330409838e-9, -1.4282718706813637e-8, -1.9841064579001098e-5, 3.3331664158804558e-3],
            [10.0, 10.012400599002738, 0.39133889529737248, 9.7857289226401661e-2, 1.2500289439446303e-2],
            [-20.0, -20.016179854286044, 0.68657885073904845, -8.5478333639405726e-2, 1.2502111454417226e-2],
        ],
    );
    // The crown: UIC60's 300 mm head radius.
    assert!((1.0 / p.curvature_at(0.0).unwrap() - 300.0).abs() < 0.1);
}

#[test]
fn the_uic60_rail_as_miniprof_is_contact_s() {
    let p = rail("MBench_UIC60_v3.ban");
    // 495 lines of points, 19 of them commented out with '"'.
    assert_eq!(p.len(), 476);
    assert_eq!(p.cleaning().read, 476);
    assert_point(&p, 1, -3.0595911999999998e1, 3.6653224999999999e1, -58.701841943084830);
    assert_point(&p, 476, 4.3704898000000000e1, 3.8510725999999998e1, 73.686782835645047);
    assert_queries(
        &p,
        &[
            [0.0, 2.3104423374498140e-9, -1.4282718715792186e-8, 1.9841064577769082e-5, 3.3331664158805503e-3],
            [10.0, 10.001855168694439, 0.16691165781074657, 3.3371752942509214e-2, 3.3334769675948052e-3],
        ],
    );
}

#[test]
fn the_s1002_wheel_is_contact_s() {
    let p = wheel("MBench_S1002_v3.prw");
    assert_eq!(p.len(), 399);
    assert_point(&p, 1, 6.0000000000000000e1, -2.6356763999999999, -60.075197737226070);
    assert_point(&p, 399, -6.9612628000000001e1, 1.3485642000000000e1, 89.313223279851854);
    assert!(p.y_mm().windows(2).all(|w| w[1] < w[0]), "this wheel's y descends throughout");
    assert_queries(
        &p,
        &[
            [0.0, -1.6240584543442127e-6, -3.2257694345533272e-11, -3.3585369648869767e-2, -3.1260727663320617e-3],
            [10.0, -10.002384905971622, -0.20840087935828630, -1.1270971318434011e-2, -1.1921869259643204e-3],
            [-20.0, 20.074090114787595, 1.5965630808845996, -0.14968666529067265, -1.0673776282242000e-2],
            [30.0, -30.009272426582804, -0.64622987564403023, -5.6586719655388952e-2, 4.9875411009828131e-3],
        ],
    );
    assert_eq!(p.uni_valued_range().unwrap(), 0..=398);
}

#[test]
fn a_measured_wheel_that_folds_back_is_viewed_from_below_and_trimmed_as_contact_does() {
    let p = wheel("Car7216_0001r.whl");
    assert_eq!(p.len(), 645);
    assert_point(&p, 1, 1.3132210000000001e2, -2.2105799999999999e1, -178.33173803910415);
    assert_point(&p, 645, -9.8599999999999993e-2, -2.2060300000000002e1, 22.179574347287542);
    assert!(!p.y_mm().windows(2).all(|w| w[1] < w[0]), "the flange's back folds back");
    assert_queries(
        &p,
        &[
            [0.0, -8.4797468180998479, 8.5627915582264276, 14.643923883485291, -1.1285802009446020e-2],
            [20.0, -41.459965324294750, 26.334971504958379, -0.34515225119208376, 4.9432510267190838e-2],
        ],
    );
    // CONTACT's prw_determine_foldback keeps points 23 to 432 (1-based).
    assert_eq!(p.uni_valued_range().unwrap(), 22..=431);
    let strict = read("Car7216_0001r.whl", ProfileKind::Wheel, &ProfileOptions { max_omit: 0.3, ..Default::default() });
    let e = strict.uni_valued_range().unwrap_err().to_string();
    assert!(e.contains("235 of 645") && e.contains("-2102"), "{e}");
}

#[test]
fn kinks_break_the_spline_where_contact_breaks_it() {
    let p = rail("groove_r1005.prr");
    assert_eq!(p.len(), 401);
    // CONTACT's profile_find_kinks: 1, 100, 302, 401 (1-based).
    assert_eq!(p.breaks(), [0, 99, 301, 400]);
    assert_queries(&p, &[[0.0, 0.0, 0.0, -8.6735823876627796e-19, -9.9825917721377250e-2]]);
    // A line with a note after its numbers (CONTACT ignores the note) and its kink.
    let p = rail("avg_low2.ban");
    assert_eq!(p.len(), 525);
    assert_eq!(p.breaks(), [0, 523, 524]);
    assert_point(&p, 525, 2.5591000000000001e1, 3.3799999999999997e1, 55.242099489970968);
    assert_queries(&p, &[[0.0, 0.0, 1.01, 7.3297638606132462e-2, -0.10358268860568412]]);
}

#[test]
fn smoothing_is_contact_s_for_both_methods() {
    let unweighted =
        read("MBench_UIC60_v3.prr", ProfileKind::Rail, &ProfileOptions { smooth: 5.0, ..Default::default() });
    assert_queries(
        &unweighted,
        &[
            [0.0, -2.1854216475158950e-5, -1.0800772015530837e-3, -7.9099504638885463e-4, 3.1763420758398999e-3],
            [5.0, 5.0005854426519427, 6.1496757805535061e-2, 3.4256448289563403e-2, 1.1995352294041639e-2],
        ],
    );
    let weighted = read(
        "MBench_UIC60_v3.prr",
        ProfileKind::Rail,
        &ProfileOptions { smooth: 3.0, ismooth: 1, ..Default::default() },
    );
    assert_queries(
        &weighted,
        &[
            [0.0, 1.9356854855101524e-7, 1.1778898128977318e-5, -6.9071432504936621e-6, 3.3182858754592631e-3],
            [5.0, 5.0006017480840477, 5.9750442942570293e-2, 3.4817776401584198e-2, 1.2737521904103002e-2],
        ],
    );
    // The smoothed points replace the read ones, as in CONTACT; s stays the chord length read.
    assert_ne!(unweighted.y_mm(), rail("MBench_UIC60_v3.prr").y_mm());
    assert_eq!(unweighted.s_mm(), rail("MBench_UIC60_v3.prr").s_mm());
}

/// circ_r100.prr: z = 100 − √(100² − y²) sampled every 0.1 mm to 6 decimals. The spline's z is
/// within 1e-6 mm of the circle; its curvature, a second derivative of data rounded to 1e-6 mm at
/// 0.1 mm spacing, within 4 % of 1/100 mm⁻¹ at every y with |y| ≤ 90 mm and within 1e-5 on
/// average.
#[test]
fn a_circular_rail_has_the_circle_s_curvature() {
    let p = rail("circ_r100.prr");
    assert_eq!(p.len(), 1999);
    let ys: Vec<f64> = (-900..=900).map(|i| f64::from(i) * 0.1 + 0.0137).collect();
    let mut sum = 0.0;
    for &y in &ys {
        let q = p.point_at_y(y).unwrap();
        assert!((q.z_mm - (100.0 - (1e4 - y * y).sqrt())).abs() < 1e-6, "y = {y}: z {}", q.z_mm);
        assert!((q.curvature_per_mm * 100.0 - 1.0).abs() < 0.04, "y = {y}: curvature {}", q.curvature_per_mm);
        sum += q.curvature_per_mm;
    }
    assert!((sum / ys.len() as f64 * 100.0 - 1.0).abs() < 1e-5, "mean curvature {}", sum / ys.len() as f64);
    // The tangent of a rail runs with y (material to its right, below in z-down coordinates).
    let t = p.point_at_s(0.0).unwrap().tangent();
    assert!((t[0] - 1.0).abs() < 1e-9 && t[1].abs() < 1e-6, "{t:?}");
}

#[test]
fn a_circular_wheel_is_convex_too() {
    let p = wheel("circ_r100.prw");
    assert_eq!(p.len(), 1001);
    // The file's two points next to y = 0 are off the circle by 5e-5 mm; away from them the
    // curvature is 1/100 as on the rail.
    let ys: Vec<f64> = (50..=450).flat_map(|i| [f64::from(i) * 0.1 + 0.0137, -(f64::from(i) * 0.1 + 0.0137)]).collect();
    let mean = ys.iter().map(|&y| p.curvature_at(y).unwrap()).sum::<f64>() / ys.len() as f64;
    assert!((mean * 100.0 - 1.0).abs() < 1e-4, "mean curvature {mean}");
    assert_eq!(p.kind(), ProfileKind::Wheel);
    let (lo, hi) = p.y_range();
    assert!((lo + 50.0).abs() < 1e-9 && (hi - 50.0).abs() < 1e-9, "{lo} {hi}");
    assert_eq!(p.z_at(50.5), None);
}

#[test]
fn mirroring_and_scaling_are_applied_as_contact_applies_them() {
    let plain = rail("MBench_UIC60_v3.prr");
    // The Miniprof file is the same rail mirrored, its points in the other order (19 of them
    // commented out): mirrored in y its y ascend and its points are the SIMPACK file's
    // (CONTACT: the same 476 points).
    let opts = ProfileOptions { mirror_y: 1, ..Default::default() };
    let mirrored = read("MBench_UIC60_v3.ban", ProfileKind::Rail, &opts);
    assert!(mirrored.cleaning().mirrored_y && !mirrored.cleaning().inverted && !mirrored.cleaning().mirrored_z);
    assert_eq!((mirrored.y_mm()[0], mirrored.z_mm()[0]), (plain.y_mm()[0], plain.z_mm()[0]));
    for i in 0..mirrored.len() {
        // Clamped: the last point's y is 3e-15 mm beyond the SIMPACK file's (its last digits).
        let (lo, hi) = plain.y_range();
        let (y, z) = (mirrored.y_mm()[i].clamp(lo, hi), mirrored.z_mm()[i]);
        assert!((plain.z_at(y).unwrap() - z).abs() < 1e-9, "mirrored point {i} ({y}, {z}) lies on the rail");
    }
    // SCALE multiplies every coordinate: a 1.01 scale is a rail 1 % larger.
    let scaled = read("MBench_UIC60_v3.prr", ProfileKind::Rail, &ProfileOptions { scale: 1.01, ..Default::default() });
    for i in [0, 200, 494] {
        assert!((scaled.y_mm()[i] - 1.01 * plain.y_mm()[i]).abs() < 1e-12);
        assert!((scaled.z_mm()[i] - 1.01 * plain.z_mm()[i]).abs() < 1e-12);
    }
}

#[test]
fn errors_name_the_file_the_line_and_what_is_allowed() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let opts = ProfileOptions::default();
    // A line that is not numbers.
    let p = write("r.txt", "% y z\n-10 1\n0 0\n10 one\n");
    let e = read_profile(&p, ProfileKind::Rail, &opts).unwrap_err();
    assert!(matches!(&e, ProfileError::Value { line: 4, column: 4, value, .. } if value == "one"), "{e}");
    assert!(e.to_string().contains("r.txt:4:4"), "{e}");
    // A non-finite value.
    let p = write("n.txt", "-10 1\n0 nan\n10 1\n");
    let e = read_profile(&p, ProfileKind::Rail, &opts).unwrap_err();
    assert!(matches!(&e, ProfileError::Value { line: 2, .. }), "{e}");
    // Too short a profile for its unit (a table in m read as mm).
    let p = write("m.txt", "-0.01 0.001\n0 0\n0.01 0.001\n");
    let e = read_profile(&p, ProfileKind::Rail, &opts).unwrap_err().to_string();
    assert!(e.contains("241") && e.contains("SCALEYZ"), "{e}");
    let ok = read_profile(&p, ProfileKind::Rail, &ProfileOptions { scale: 1000.0, ..Default::default() }).unwrap();
    assert_eq!(ok.len(), 3);
    // A loop.
    let p = write("loop.txt", "-20 5\n-5 0\n5 0\n10 2\n0 3\n-3 -1\n25 5\n");
    let e = read_profile(&p, ProfileKind::Rail, &opts).unwrap_err().to_string();
    assert!(e.contains("323") && e.contains("lines"), "{e}");
    // A wheel file read as a rail; an unsupported smoothing method.
    let e = read_profile(&path("MBench_S1002_v3.prw"), ProfileKind::Rail, &opts).unwrap_err().to_string();
    assert!(e.contains("301"), "{e}");
    let e =
        read_profile(&path("MBench_S1002_v3.prw"), ProfileKind::Wheel, &ProfileOptions { ismooth: 2, ..opts.clone() })
            .unwrap_err();
    assert!(matches!(&e, ProfileError::Option { field, .. } if field == "ismooth"), "{e}");
    // Into the crate's input error (exit status 2).
    let err: creepbench::Error = e.into();
    assert_eq!(err.exit_code(), 2);
}
