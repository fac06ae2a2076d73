//! Issue 32 item 3: strips of one row (CONTACT MY = 1, Carter's 2-D problem): an explicit grid of
//! mx × 1 elements, each `dy` wide, with h given per element. References: CONTACT's printed output
//! of examples/carter2d.inp and Carter's closed form for a rolling cylinder.

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

/// Last value of a history's column.
fn last(h: &History, column: &str) -> f64 {
    *h.column(column).unwrap().last().unwrap()
}

/// CONTACT's examples/carter2d.inp (eve70a/CONTACT d431cdb): steady rolling, FN 35780 N, CKSI
/// −0.00024, FSTAT = FKIN = 0.3, G 82000 MPa, ν 0.28, 55 × 1 elements of 0.04 × 200 mm from
/// XC1 = −1.05 mm (first centre), h = 0.001 x² (B1, IBASE 1). CONTACT solves steady rolling with
/// DQ = DX (its DQ 0.0401 is not used), as this solver does.
fn carter() -> History {
    let dir = tempdir("strip_carter2d");
    let (x0, dx) = (-1.07, 0.04);
    let mut csv = String::from("ix,iy,h_mm\n");
    for ix in 1..=55 {
        let x = x0 + (ix as f64 - 0.5) * dx;
        csv.push_str(&format!("{ix},1,{:?}\n", 0.001 * x * x));
    }
    std::fs::write(dir.join("h.csv"), csv).unwrap();
    let x1 = x0 + 55.0 * dx;
    let text = format!(
        "name = \"carter2d\"\nsolvers = [\"contact\"]\n[contact]\nfn_n = 35780.0\nmu = 0.3\n[geometry]\nkind = \"field\"\nfield = \"h.csv\"\n[material]\ng_mpa = 82000.0\npoisson = 0.28\n[grid]\nmx = 55\nmy = 1\nx_mm = [{x0:?}, {x1:?}]\ny_mm = [-100.0, 100.0]\n[creepage]\nkind = \"sweep\"\nover = \"cx\"\nfrom = -0.00024\nto = -0.00024\npoints = 1\n"
    );
    let scene = Scene::from_toml(&text, &dir).unwrap();
    run(&creepbench::pipeline::resolve(&scene).unwrap(), "contact")
}

/// carter2d.ref_out's totals: FX/FSTAT/FN 0.6480 (this project's fx = −FX), PMAX 113.9 MPa,
/// NCON 50, NADH 30, NSLIP 20, each to its printed digits.
#[test]
fn contact_carter2d_totals() {
    let h = carter();
    let (fx, pmax) = (last(&h, "fx_over_fn"), last(&h, "pn_max_mpa"));
    let (n_adh, n_slip) = (last(&h, "n_adhesion"), last(&h, "n_slip"));
    println!("FX/FSTAT/FN {:.6} (printed 0.6480), PMAX {pmax:.4} (113.9), NADH {n_adh} NSLIP {n_slip}", -fx / 0.3);
    assert!((-fx / 0.3 - 0.6480).abs() <= 0.5e-4, "{fx}");
    assert!((pmax - 113.9).abs() <= 0.05, "{pmax}");
    assert_eq!((n_adh, n_slip), (30.0, 20.0));
}

/// Carter's closed form (Carter 1926; Johnson 1985, Contact Mechanics §8.2), a cylinder of radius
/// R rolling on a plane of the same material, load P per unit length: half-width
/// a = √(4 P R/(π E*)), E* = E/(2(1 − ν²)); under creepage ξ the adhesion zone is the leading
/// a′ = a √(1 − |Q|/μP) and |ξ| = (μ a/R)(1 − √(1 − |Q|/μP)). Here R = 500 mm, P = 178.9 N/mm:
/// a = 1.000 mm, a′ = 0.6 mm, |Q|/μP = 0.64. The grid: 2a = 50 elements, 2a′ = 30 elements;
/// the force of the discretised strip (200 mm wide, elements of 0.04 mm) within 0.01 of 0.64
/// (CONTACT's own is 0.6480).
#[test]
fn carter_closed_form() {
    let (g, nu, mu, r_mm, p_n_mm, xi) = (82000.0, 0.28, 0.3, 500.0, 35780.0 / 200.0, 0.00024);
    let e_star = 2.0 * g * (1.0 + nu) / (2.0 * (1.0 - nu * nu));
    let a_mm = (4.0 * p_n_mm * r_mm / (std::f64::consts::PI * e_star)).sqrt();
    let root = 1.0 - xi * r_mm / (mu * a_mm);
    let (q, a_adh_mm) = (1.0 - root * root, a_mm * root);
    let h = carter();
    let fx = last(&h, "fx_over_fn");
    let (n_adh, n_slip) = (last(&h, "n_adhesion"), last(&h, "n_slip"));
    println!("a {a_mm:.5} mm, a' {a_adh_mm:.5} mm, Q/muP {q:.5} vs {:.5}", -fx / mu);
    assert_eq!(n_adh + n_slip, (2.0 * a_mm / 0.04).round());
    assert_eq!(n_adh, (2.0 * a_adh_mm / 0.04).round());
    assert!((-fx / mu - q).abs() < 0.01, "{} vs {q}", -fx / mu);
}
