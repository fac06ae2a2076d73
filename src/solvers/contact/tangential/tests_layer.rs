//! The interface layer (CONTACT's M = 4) against closed forms: a layer alone (half-spaces far
//! stiffer) sheared by a shift carries p = G3/h3 · shift, rolls steadily as the brush model of
//! flexibility h3/G3 (the traction grows by dx·cx·G3/h3 per element from the leading edge), and a
//! layer of vanishing thickness gives the half-space's solution.

use super::*;
use crate::physics::Grid;

/// G [MPa] of half-spaces so stiff that their flexibility (~1e-13 mm/MPa) is ~1e-9 of the layer's.
const RIGID_MPA: f64 = 1e12;
/// The layer of tractcurv.inp's second series: GG3 = 8200 MPa, LAYTHK = 1.25 mm.
const FLX: f64 = 1.25 / 8200.0;

fn kernels(mx: usize, my: usize, dx: f64, dy: f64, g: f64, flx: f64) -> (Kernel, Kernel) {
    let k0 = Kernel::new(mx, my, dx, dy, g, 0.28, 0.0).unwrap().with_layer(flx, [0.0, 0.0]).unwrap();
    let ks = Kernel::new(mx, my, dx, dy, g, 0.28, dx).unwrap().with_layer(flx, [dx, 0.0]).unwrap();
    (k0, ks)
}

#[test]
fn a_layer_alone_sheared_by_a_shift_carries_g3_over_h3_times_the_shift() {
    let (mx, my) = (6, 5);
    let grid = Grid::new(mx, my, 3.0, 2.5);
    let (x, y) = grid.centres();
    let (k0, _) = kernels(mx, my, grid.dx_mm, grid.dy_mm, RIGID_MPA, FLX);
    let mut s = TangentialSolver::for_shifts(&k0, &x, &y).unwrap();
    s.set_pressure(&vec![100.0; mx * my]).unwrap();
    let shift_mm = 2e-4;
    // Shifts: the creepages are the shifts [mm] over a unit "dq"; μ large: all stuck.
    let mut p = TangentialParams::new(10.0, shift_mm, -0.5 * shift_mm, 0.0, 1.0);
    p.tol = 1e-12;
    let zero = vec![0.0; mx * my];
    let r = s.transient_step(&p, &zero, &zero, None).unwrap();
    assert!(r.termination.converged() && r.n_slip == 0);
    let (want_x, want_y) = (shift_mm / FLX, -0.5 * shift_mm / FLX);
    for k in 0..mx * my {
        assert!((r.px[k] - want_x).abs() < 1e-6 * want_x, "{k}: {} vs {want_x}", r.px[k]);
        assert!((r.py[k] - want_y).abs() < 1e-6 * want_x, "{k}: {} vs {want_y}", r.py[k]);
    }
}

#[test]
fn steady_rolling_on_a_layer_alone_is_the_brush_model() {
    let (mx, my) = (8, 3);
    let grid = Grid::new(mx, my, 4.0, 1.5);
    let (x, y) = grid.centres();
    let dx = grid.dx_mm;
    let (k0, ks) = kernels(mx, my, dx, grid.dy_mm, RIGID_MPA, FLX);
    let mut s = TangentialSolver::new(&k0, &ks, &x, &y).unwrap();
    let g = 5.0;
    s.set_pressure(&vec![g; mx * my]).unwrap();
    let cx = 2e-4;
    let mut p = TangentialParams::new(1.0, cx, 0.0, 0.0, dx);
    p.tol = 1e-12;
    let r = s.steady(&p, None).unwrap();
    assert!(r.termination.converged());
    // The material enters at the leading edge (the grid's first column: grid x runs along the
    // material's motion, against CONTACT's) free of traction and gains dx·cx/FLX per element, up
    // to the bound g = μ pn.
    for j in 0..my {
        for i in 0..mx {
            let from_leading_edge = (i + 1) as f64;
            let want = (from_leading_edge * dx * cx / FLX).min(g);
            let got = r.px[j * mx + i];
            assert!((got - want).abs() < 1e-6 * g, "({i},{j}): {got} vs {want}");
        }
    }
    assert!(r.n_slip > 0 && r.n_adhesion > 0, "the bound is reached within the grid");
}

#[test]
fn a_vanishing_layer_gives_the_half_space_and_a_layer_softens_the_creep_force() {
    let (mx, my) = (14, 12);
    let grid = Grid::new(mx, my, 6.0, 3.5);
    let (x, y) = grid.centres();
    // Hertz's pressure on the ellipse a = 6, b = 3.5 (max 1000 MPa).
    let pn: Vec<f64> =
        x.iter().zip(&y).map(|(x, y)| 1000.0 * (1.0 - (x / 6.0).powi(2) - (y / 3.5).powi(2)).max(0.0).sqrt()).collect();
    let fx = |flx: f64| {
        let (k0, ks) = kernels(mx, my, grid.dx_mm, grid.dy_mm, 82000.0, flx);
        let mut s = TangentialSolver::new(&k0, &ks, &x, &y).unwrap();
        s.set_pressure(&pn).unwrap();
        let mut p = TangentialParams::new(0.3, 0.001, 0.0, 0.0, grid.dx_mm);
        p.tol = 1e-11;
        let r = s.steady(&p, None).unwrap();
        assert!(r.termination.converged());
        r.px.iter().sum::<f64>()
    };
    let (bare, thin, layer) = (fx(0.0), fx(1e-9 / 8200.0), fx(FLX));
    assert!((thin - bare).abs() < 1e-7 * bare.abs(), "{thin} vs {bare}");
    assert!(layer < 0.9 * bare && layer > 0.0, "{layer} vs {bare}");
}
