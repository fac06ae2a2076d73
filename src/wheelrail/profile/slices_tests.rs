use super::*;
use std::fs;

/// A rail-like plain table: y from −30 to 30 mm, z = 0.002 y² + dz (z down).
fn table(dz: f64, dy: f64) -> String {
    (0..=60).map(|k| k as f64 - 30.0).map(|y| format!("{} {}\n", y + dy, 0.002 * y * y + dz)).collect()
}

fn opts() -> ProfileOptions {
    ProfileOptions { mirror_z: -1, ..Default::default() }
}

/// Slices at `u` with z shifted by `dz(u)`, written with `header` and `tail` (the features).
fn write(dir: &Path, u: &[f64], dz: impl Fn(f64) -> f64, header: &str, tail: &str) -> std::path::PathBuf {
    let mut text = format!("% test\n{header}");
    for (i, &x) in u.iter().enumerate() {
        fs::write(dir.join(format!("s{i}.txt")), table(dz(x), 0.0)).unwrap();
        text += &format!("  {x}  's{i}.txt'\n");
    }
    text += tail;
    let path = dir.join("rail.slcs");
    fs::write(&path, text).unwrap();
    path
}

const HEADER: &str = "0.0 1.0  U_OFFSET, U_SCALE\n 6   NSLC\n 0 0 0  NFEAT\n 1  U_INTPOL\n";
const U: [f64; 6] = [-40.0, -10.0, 0.0, 5.0, 30.0, 100.0];

/// The height shift along the track of [`cubic_rail`]: a cubic in u.
fn dz(u: f64) -> f64 {
    0.5 + 0.01 * u - 2e-4 * u * u + 1e-6 * u * u * u
}

/// The slices at [`U`] of the plain table shifted by [`dz`] (read, then their files removed).
fn cubic_rail() -> Slices {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), &U, dz, HEADER, "");
    read_slices(&path, ProfileKind::Rail, &opts()).unwrap()
}

/// A rail whose height changes as a cubic along the track is interpolated exactly between its
/// slices (not-a-knot ends reproduce cubics), and held beyond the first and last slice.
#[test]
fn a_height_cubic_along_the_track_is_interpolated_exactly() {
    let s = cubic_rail();
    assert_eq!(s.positions(), &U);
    // One part of 60 mm: 1 + 120 segments.
    assert_eq!(s.samples(), 122);
    let (y0, z0) = s.samples_at(U[0]);
    for u in [-40.0, -33.3, -10.0, 2.5, 17.0, 99.0] {
        let (y, z) = s.samples_at(u);
        for j in 0..y.len() {
            assert!((y[j] - y0[j]).abs() < 1e-12);
            assert!((z[j] - z0[j] - (dz(u) - dz(U[0]))).abs() < 1e-11, "u {u} j {j}");
        }
        let section = s.section_at(u).unwrap();
        let want = 0.002 * 7.3 * 7.3 + dz(u);
        assert!((section.z_at(7.3).unwrap() - want).abs() < 1e-5, "u {u}: {:?} vs {want}", section.z_at(7.3));
    }
    assert_eq!(s.samples_at(-100.0), s.samples_at(-40.0));
    assert_eq!(s.samples_at(150.0), s.samples_at(100.0));
}

/// Features divide the slices into parts, each resampled at its longest length's count.
#[test]
fn features_set_the_parts_and_their_samples() {
    let dir = tempfile::tempdir().unwrap();
    let header = "0.0 1.0\n 6\n 3 0 0\n 1\n";
    let feats: String = U.iter().map(|u| format!("{u} 0.0 {} 999\n", 20.0 + u / 100.0)).collect();
    let path = write(dir.path(), &U, |_| 0.0, header, &feats);
    let s = read_slices(&path, ProfileKind::Rail, &opts()).unwrap();
    let total = s.slice(0).s_range().1 - s.slice(0).s_range().0;
    let first = 1 + ((21.0 + 1e-6) / 0.5) as usize;
    let second = 1 + ((total - 19.6 + 1e-6) / 0.5) as usize;
    assert_eq!(s.samples(), first + second + 1);
}

fn refusal(header: &str, tail: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), &U, |_| 0.0, header, tail);
    read_slices(&path, ProfileKind::Rail, &opts()).unwrap_err().to_string()
}

/// What CONTACT refuses (its error numbers) and what is not supported, each naming the file, the
/// line and the value.
#[test]
fn bad_slices_files_are_refused_naming_line_and_value() {
    let e = refusal("0.0 1.0\n 3\n 0 0 0\n 1\n", "");
    assert!(e.contains("rail.slcs:3:1") && e.contains("404"), "{e}");
    let e = refusal("0.0 1.0\n 6\n 0 0 0\n 3\n", "");
    assert!(e.contains("rail.slcs:5:1") && e.contains("2 (approximating spline)"), "{e}");
    let e = refusal("0.0 1.0\n 6\n 0 0 0\n 1 1\n", "");
    assert!(e.contains("PERTURB") && e.contains("not supported"), "{e}");
    let e = refusal("0.0 -1.0\n 6\n 0 0 0\n 1\n", "");
    assert!(e.contains("rail.slcs:2:1") && e.contains("U_SCALE"), "{e}");
    let e = refusal("0.0 1.0\n 7\n 0 0 0\n 1\n", "");
    assert!(e.contains("the end of the file before slice 7"), "{e}");
    let e = refusal(HEADER, "  1 2\n");
    assert!(e.contains("rail.slcs:12") && e.contains("perturbations are not supported"), "{e}");
    let feats: String = U.iter().map(|u| format!("{u} 0.0 10 999\n")).collect();
    let e = refusal("0.0 1.0\n 6\n 3 2 0\n 1\n", &feats);
    assert!(e.contains("NKINK") && e.contains("151"), "{e}");
    let bad = feats.replacen("5 0.0", "5.5 0.0", 1);
    let e = refusal("0.0 1.0\n 6\n 3 0 0\n 1\n", &bad);
    assert!(e.contains("rail.slcs:15:1") && e.contains("155"), "{e}");
    let gap = feats.replacen("0 0.0 10", "0 -1 10", 1);
    // One slice lacking a part: the part's path is inactive over one slice at its start.
    let e = refusal("0.0 1.0\n 6\n 3 0 0\n 1\n", &gap);
    assert!(e.contains("path of sample 1") && e.contains("171"), "{e}");
    let e = refusal("0.0 1.0\n 6\n 3 0 0\n 2\n", &gap);
    assert!(e.contains("interruptions") && e.contains("U_INTPOL = 2"), "{e}");
    let none = feats.replacen("0 0.0 10 999", "0 -1 -1 999", 1);
    let e = refusal("0.0 1.0\n 6\n 3 0 0\n 1\n", &none);
    assert!(e.contains("161"), "{e}");
    let down = feats.replacen("0 0.0 10", "0 12 10", 1);
    let e = refusal("0.0 1.0\n 6\n 3 0 0\n 1\n", &down);
    assert!(e.contains("slice 1: S_F 1 and 2") && e.contains("162"), "{e}");

    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), &[0.0, 1.0, 1.0005, 3.0, 4.0, 5.0], |_| 0.0, HEADER, "");
    let e = read_slices(&path, ProfileKind::Rail, &opts()).unwrap_err().to_string();
    assert!(e.contains("rail.slcs:8:1") && e.contains("152"), "{e}");
    let path = write(dir.path(), &U, |_| 0.0, HEADER, "");
    fs::write(dir.path().join("s3.txt"), "1 2\n3 x\n").unwrap();
    let e = read_slices(&path, ProfileKind::Rail, &opts()).unwrap_err().to_string();
    assert!(e.contains("rail.slcs, slice 4:") && e.contains("s3.txt:2:3"), "{e}");
    let e = read_slices(&path, ProfileKind::Wheel, &opts()).unwrap_err().to_string();
    assert!(e.contains("slcw"), "{e}");
    let err: crate::error::Error = read_slices(&path, ProfileKind::Rail, &opts()).unwrap_err().into();
    assert_eq!(err.exit_code(), 2);
}

/// A wheel's slices must lie within [−1.5π, 1.5π] and cover [−π, π] or lie inside it.
#[test]
fn a_wheels_slices_cover_its_circumference_as_contact_requires() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("0 1\n4\n0 0 0\n1\n");
    for (i, th) in [-3.0, -1.0, 1.0, 3.5].iter().enumerate() {
        fs::write(dir.path().join(format!("w{i}.txt")), table(0.0, 0.0)).unwrap();
        text += &format!("{th} w{i}.txt\n");
    }
    let path = dir.path().join("w.slcw");
    fs::write(&path, text).unwrap();
    let e = read_slices(&path, ProfileKind::Wheel, &opts()).unwrap_err().to_string();
    assert!(e.contains("153") && e.contains("[-3, 3.5]"), "{e}");
}

/// The surface's height at (u, y) (the bands with their reach) is the closed form's, and a
/// cross-section cut to a lateral range ([`Slices::section_near`]) is the whole one inside it.
#[test]
fn the_surface_and_a_cut_cross_section_are_the_closed_forms() {
    let s = cubic_rail();
    for u in [-40.0, -33.3, -10.0, 2.5, 17.0, 99.0, 100.0] {
        // Inside the ends, where each slice's profile spline (in arc length) holds the parabola.
        for k in 0..=100 {
            let y = -25.0 + 0.5 * k as f64;
            let want = 0.002 * y * y + dz(u);
            let got = s.surface_z_at(u, y).unwrap();
            assert!((got - want).abs() < 1e-5, "u {u} y {y}: {got} vs {want}");
        }
        assert_eq!(s.surface_z_at(u, 31.0), None, "beyond the profile at u {u}");
        let whole = s.section_at(u).unwrap();
        let cut = s.section_near(u, [-2.0, 4.0]).unwrap();
        assert!(cut.y_mm().len() < whole.y_mm().len(), "{} of {}", cut.y_mm().len(), whole.y_mm().len());
        for y in [-2.0, -0.7, 0.0, 1.3, 4.0] {
            let (a, b) = (whole.z_at(y).unwrap(), cut.z_at(y).unwrap());
            assert!((a - b).abs() <= 1e-12 * (1.0 + a.abs()), "u {u} y {y}: {a} vs {b}");
        }
    }
}
