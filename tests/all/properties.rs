//! proptest properties of the physics (issue 4): odd symmetry, |τ| ≤ μp, the linear-theory
//! slope, the sign of the frictional dissipation.

use crate::common;
use common::*;
use creepbench::physics::{project_to_bound, Coefficients, HertzContact, Material, Radii};
use creepbench::solvers::brush::{self, Integration, LeadingEdge, Tractions};
use proptest::prelude::*;

fn contact_problem(mu: f64, b_over_a: f64, grid: usize) -> creepbench::problem::Problem {
    let text = scene_text("p", "[\"uba\"]", mu, grid, "kind = \"step\"\nc = 0.001\nsteps = 1", "")
        .replace("b_mm = 4.08", &format!("b_mm = {}", 8.56 * b_over_a));
    problem(&text)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// The projection keeps the direction and never exceeds the bound.
    #[test]
    fn projection_keeps_direction(tx in -1e4f64..1e4, ty in -1e4f64..1e4, g in 0.0f64..1e4) {
        let (px, py, slip) = project_to_bound(tx, ty, g);
        prop_assert!((px * px + py * py).sqrt() <= g * (1.0 + 1e-12) || !slip);
        prop_assert!(px * tx >= 0.0 && py * ty >= 0.0);
        if slip && g > 0.0 { prop_assert!((px * ty - py * tx).abs() <= 1e-9 * (tx.abs() + ty.abs()) * g); }
    }

    /// f(−c) = −f(c) for the steady march, both integrations, with cy and spin.
    #[test]
    fn steady_march_is_odd(cx in -0.02f64..0.02, cy in -0.02f64..0.02, cs in -0.01f64..0.01, mu in 0.05f64..2.0) {
        let p = contact_problem(mu, 0.48, 12);
        let local = p.local_contact(p.hertz().fn_n);
        let (mut t1, mut t2) = (Tractions::zero(p.grid.len()), Tractions::zero(p.grid.len()));
        for (edge, integ) in [(LeadingEdge::Grid, Integration::Centre), (LeadingEdge::Exact, Integration::Exact)] {
            brush::steady_march(&p.grid, &local, mu, &brush::rates(cx, cy, cs, &local.flex), (edge, integ), &mut t1);
            brush::steady_march(&p.grid, &local, mu, &brush::rates(-cx, -cy, -cs, &local.flex), (edge, integ), &mut t2);
            for k in 0..p.grid.len() {
                prop_assert!((t1.tx[k] + t2.tx[k]).abs() < 1e-9 && (t1.ty[k] + t2.ty[k]).abs() < 1e-9);
                let g = mu * local.planform.pressure_mpa[k];
                prop_assert!((t1.tx[k].powi(2) + t1.ty[k].powi(2)).sqrt() <= g * (1.0 + 1e-12) + 1e-300);
            }
        }
    }

    /// The UBA history keeps |τ| ≤ μp at every step and element whatever the creepage history.
    #[test]
    fn uba_bound_holds(steps in proptest::collection::vec((-0.02f64..0.02, -0.01f64..0.01, -0.005f64..0.005), 1..30), mu in 0.05f64..1.0, courant in 0.1f64..1.0) {
        let p = contact_problem(mu, 0.48, 10);
        let local = p.local_contact(p.hertz().fn_n);
        let mut prep = creepbench::solvers::uba::Prepared::new(&p.grid, &local, mu);
        let (mut t, mut u) = (Tractions::zero(p.grid.len()), Tractions::zero(p.grid.len()));
        for (cx, cy, cs) in steps {
            let rates = brush::rates(cx, cy, cs, &local.flex);
            creepbench::solvers::uba::step((&p.grid, &local.planform), &mut prep, &rates, (courant, LeadingEdge::Grid), &t, &mut u);
            std::mem::swap(&mut t, &mut u);
            for k in 0..p.grid.len() {
                let g = mu * local.planform.pressure_mpa[k];
                prop_assert!((t.tx[k].powi(2) + t.ty[k].powi(2)).sqrt() <= g * (1.0 + 1e-12) + 1e-300);
            }
        }
    }

    /// Linear theory: in full adhesion (tiny creepage) the steady FASTSIM force from the exact
    /// edge is G a b c11 cx on a 40×40 grid within 1.5 %, for any axis ratio in the table.
    #[test]
    fn linear_theory_slope(b_over_a in 0.15f64..6.0) {
        let text = scene_text("s", "[\"fastsim\"]", 0.4, 40, "kind = \"sweep\"\nfrom = 1e-7\nto = 1e-7\npoints = 1", "[model]\nleading_edge = \"exact\"")
            .replace("b_mm = 4.08", &format!("b_mm = {}", 8.56 * b_over_a));
        let p = problem(&text);
        let f0 = f(&run(&p, "fastsim"))[0];
        let lin = p.material.g_mpa * p.hertz().a_mm * p.hertz().b_mm * p.coefficients.c11 * 1e-7 / p.hertz().fn_n;
        prop_assert!((f0 / lin - 1.0).abs() < 0.015, "b/a {}: ratio {}", b_over_a, f0 / lin);
    }

    /// Frictional dissipation is never negative: in every slipping element the traction and the
    /// slip it resists point the same way (sign convention of this project), so the power
    /// f·c summed over a steady state is ≥ 0: f cx + fy cy ≥ 0.
    #[test]
    fn dissipation_is_non_negative(cx in -0.02f64..0.02, cy in -0.02f64..0.02, mu in 0.05f64..1.0) {
        let text = scene_text("d", "[\"fastsim\", \"uba\"]", mu, 16, &format!("kind = \"step\"\nc = {cx}\nsteps = 40\ncy = {cy}"), "");
        let p = problem(&text);
        for s in ["fastsim", "uba"] {
            let h = run(&p, s);
            let r = h.rows.last().unwrap();
            prop_assert!(r.fx_over_fn * cx + r.fy_over_fn * cy >= -1e-15, "{}: {} {}", s, r.fx_over_fn, r.fy_over_fn);
        }
    }

    /// Hertz: the semi-axes scale with FN^(1/3) and their ratio depends only on the curvatures.
    #[test]
    fn hertz_scaling(fn_n in 1.0f64..1e7, r in 200.0f64..2000.0) {
        let mat = Material::from_g(82000.0, 0.28);
        let radii = Radii { r_wx_mm: r, r_wy_mm: 500.0, r_ry_mm: 300.0 };
        let (h1, h2) = (HertzContact::from_radii(&radii, fn_n, &mat).unwrap(), HertzContact::from_radii(&radii, 8.0 * fn_n, &mat).unwrap());
        prop_assert!((h2.a_mm / h1.a_mm - 2.0).abs() < 1e-9 && (h2.b_mm / h1.b_mm - 2.0).abs() < 1e-9);
        let c = Coefficients::from_table(h1.a_mm, h1.b_mm, 0.28);
        prop_assert!(c.c11 > 0.0 && c.c22 > 0.0 && c.c23 > 0.0);
    }
}
