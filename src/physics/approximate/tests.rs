//! Both approximations are exact on Hertz's geometry (KPEC by its ellipse correction, ANALYN by
//! its shape factors): on `h = A x² + B y²` they give Hertz's contact (Johnson 1985, §4.2).

use super::{at_load, Method};
use crate::physics::{Grid, HertzContact, Material, Radii};

/// Hertz's ellipse of radii 460 mm (rolling) and 300 mm (lateral) under 10 kN on a 0.1 mm grid,
/// and the approximation's contact on its undeformed distance.
fn hertzian(method: Method) -> (HertzContact, Grid, Vec<f64>, f64) {
    let m = Material::from_g(82000.0, 0.28);
    let radii = Radii { r_wx_mm: 460.0, r_wy_mm: 300.0, r_ry_mm: f64::INFINITY };
    let e = HertzContact::from_radii(&radii, 10_000.0, &m).unwrap();
    let grid = Grid::new(160, 120, 1.25 * e.a_mm, 1.25 * e.b_mm);
    let (a1, b1) = (0.5 / radii.r_wx_mm, 0.5 / radii.r_wy_mm);
    let (x, y) = grid.centres();
    let h: Vec<f64> = x.iter().zip(&y).map(|(x, y)| a1 * x * x + b1 * y * y).collect();
    let c = at_load(method, &grid, &h, e.fn_n, &m).unwrap();
    (e, grid, c.pn_mpa, c.pen_mm)
}

fn check(method: Method, area_tol: f64, peak_tol: f64, pen_tol: f64) {
    let (e, grid, p, pen) = hertzian(method);
    let m = Material::from_g(82000.0, 0.28);
    let area = p.iter().filter(|&&v| v > 0.0).count() as f64 * grid.element_area_mm2();
    let hertz_area = std::f64::consts::PI * e.a_mm * e.b_mm;
    let peak = p.iter().copied().fold(0.0, f64::max);
    let total: f64 = p.iter().sum::<f64>() * grid.element_area_mm2();
    println!(
        "{method:?}: area {area:.4} / {hertz_area:.4}, peak {peak:.2} / {:.2} MPa, approach {pen:.6} / {:.6} mm",
        e.p0_mpa(),
        e.approach_mm(&m)
    );
    assert!((total - e.fn_n).abs() <= 1e-9 * e.fn_n, "FN carried exactly: {total}");
    assert!((area / hertz_area - 1.0).abs() <= area_tol, "area {area} against Hertz's {hertz_area}");
    assert!((peak / e.p0_mpa() - 1.0).abs() <= peak_tol, "peak {peak} against Hertz's {}", e.p0_mpa());
    assert!((pen / e.approach_mm(&m) - 1.0).abs() <= pen_tol, "approach {pen} against Hertz's");
}

/// Measured on this 160 × 120 grid: KPEC's area 0.11 % short (whole elements on the ellipse's
/// edge), its peak 0.01 % and its approach 0.013 % low (the grid's piecewise-constant pressure).
#[test]
fn kpec_gives_hertz_on_hertz_geometry() {
    check(Method::Kpec, 2e-3, 2e-4, 3e-4);
}

/// Measured: ANALYN's area 0.05 % over, its peak 0.01 % and approach 0.013 % low.
#[test]
fn analyn_gives_hertz_on_hertz_geometry() {
    check(Method::Analyn, 1e-3, 2e-4, 3e-4);
}

/// KPEC's equivalent ellipse of `perfc_test/mbench_20kn_dx02_fz` case 128 (right wheel, on the
/// flange) as CONTACT's debug print gives it (PSFLCIN N = 3, its last height): A = 0.00035971,
/// B = 0.03879058 /mm, approach 0.05059746 mm → a = 10.40512318, b = 0.54757621 mm,
/// a/b = 19.00214611 (Hertz's exact ratio is 19.0084: the modulus is bisected to 1e-6).
#[test]
fn kpec_ellipse_is_contacts_hzcalc3d() {
    let (aa, bb) = super::hertz_of_curvatures_coarse(0.00035971, 0.03879058, 0.05059746).unwrap();
    assert!((aa / bb - 19.00214611).abs() < 5e-9, "a/b {}", aa / bb);
    assert!((aa - 10.40512318).abs() < 5e-6, "a {aa}");
    assert!((bb - 0.54757621).abs() < 5e-8, "b {bb}");
}

/// An element above its row's threshold between the row's first and last element in contact (a
/// gap that is not convex along x, as on a wheel flat) carries no pressure, and every other
/// element keeps the pressure of the same gap without it: CONTACT clears the exterior after KPEC
/// has set the scale with the whole row (`panprc`, m_scontc.f90; `perfc_test/chalmers_flat` at
/// θ = −29.4°: two such elements of 253 and 244 MPa).
#[test]
fn kpec_clears_an_element_above_its_rows_threshold_after_the_scale() {
    let m = Material::from_g(82000.0, 0.28);
    let grid = Grid::new(40, 30, 4.0, 3.0);
    let (x, y) = grid.centres();
    let smooth: Vec<f64> = x.iter().zip(&y).map(|(x, y)| 0.5 / 460.0 * x * x + 0.5 / 300.0 * y * y - 0.01).collect();
    let deepest = super::first_min(&smooth);
    // An element of the deepest row's neighbour, 4 elements from the centre, lifted out of contact.
    let hump = deepest + grid.mx + 4;
    let mut bumped = smooth.clone();
    bumped[hump] = 0.0;
    let p0 = super::kpec::pressure(&grid, &smooth, &m).unwrap();
    let p1 = super::kpec::pressure(&grid, &bumped, &m).unwrap();
    assert!(p0[hump] > 0.0 && p0[hump - 1] > 0.0 && p0[hump + 1] > 0.0, "the element is inside the row's contact");
    assert_eq!(p1[hump], 0.0, "cleared");
    for k in (0..grid.len()).filter(|&k| k != hump) {
        assert_eq!(p1[k], p0[k], "element {k}: the scale is set before the clearing");
    }
}
