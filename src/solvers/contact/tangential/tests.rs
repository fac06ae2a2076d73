//! Tests of the tangential solver through its public API (and the warm-start bookkeeping).

use super::super::normal::{solve_normal, NormalParams};
use super::element::norm2;
use super::*;
use crate::physics::halfspace::influence::Basis;
use crate::physics::{Grid, HertzContact, Material};

/// A solver for the grid of `k0`, loaded with `pn`.
fn loaded(k0: &Kernel, ks: &Kernel, pn: &[f64], x: &[f64], y: &[f64]) -> TangentialSolver {
    let mut s = TangentialSolver::new(k0, ks, x, y).unwrap();
    s.set_pressure(pn).unwrap();
    s
}

/// Brush model: diagonal A = L I; the shifted kernel couples an element to its upstream
/// neighbour only (dq = dx).
fn brush(mx: usize, my: usize, l: f64) -> (Kernel, Kernel) {
    let n = (2 * mx - 1) * (2 * my - 1);
    let mut k0 = Kernel {
        mx,
        my,
        dx_mm: 1.0,
        dy_mm: 1.0,
        shift_mm: 0.0,
        zz: vec![0.0; n],
        xx: vec![0.0; n],
        yy: vec![0.0; n],
        xy: vec![0.0; n],
    };
    let c = k0.index(0, 0);
    k0.zz[c] = l;
    k0.xx[c] = l;
    k0.yy[c] = l;
    let mut ks = k0.clone();
    ks.shift_mm = 1.0;
    ks.zz[c] = 0.0;
    ks.xx[c] = 0.0;
    ks.yy[c] = 0.0;
    let u = ks.index(1, 0);
    ks.zz[u] = l;
    ks.xx[u] = l;
    ks.yy[u] = l;
    (k0, ks)
}

#[test]
fn brush_gives_explicit_transport_scheme() {
    let (mx, my, l) = (6, 3, 1e-5);
    let (k0, ks) = brush(mx, my, l);
    let grid = Grid::new(mx, my, 3.0, 1.5);
    let (x, y) = grid.centres();
    let pn = vec![100.0; mx * my];
    for method in [Method::GaussSeidel, Method::ConjugateGradient] {
        let mut s = loaded(&k0, &ks, &pn, &x, &y);
        let mut p = TangentialParams::new(1.0, 1e-4, 0.0, 0.0, 1.0);
        p.method = method;
        let (mut px, mut py) = (vec![0.0; mx * my], vec![0.0; mx * my]);
        for _step in 0..12 {
            let r = s.transient_step(&p, &px, &py, None).unwrap();
            assert!(r.termination.converged());
            for j in 0..my {
                for i in 0..mx {
                    let prev = if i == 0 { 0.0 } else { px[j * mx + i - 1] };
                    // p_k = p'_(k-1) + dx cx / L, capped at g = mu pn = 100 MPa.
                    let want = (prev + 1.0 * 1e-4 / l).min(100.0);
                    let got = r.px[j * mx + i];
                    assert!((got - want).abs() < 1e-6, "{method:?} ({i},{j}): {got} vs {want}");
                    assert!(r.py[j * mx + i].abs() < 1e-9);
                }
            }
            px.copy_from_slice(&r.px);
            py.copy_from_slice(&r.py);
        }
        // After enough steps the downstream part saturates: 10 MPa per element.
        assert!((px[5] - 60.0).abs() < 1e-6);
    }
}

fn hertz_setup(mx: usize, my: usize, courant: f64) -> (Kernel, Kernel, Vec<f64>, Grid) {
    let (a, b, fnn, g, nu) = (6.0, 3.5, 50_000.0, 82000.0, 0.28);
    let grid = Grid::new(mx, my, a, b);
    let h = crate::physics::ContactGeometry::undeformed_distance_mm(
        &crate::physics::HertzEllipse { nominal: HertzContact { a_mm: a, b_mm: b, fn_n: fnn } },
        &grid,
        fnn,
        &Material::from_g(g, nu),
    );
    let k0 = Kernel::new(mx, my, grid.dx_mm, grid.dy_mm, g, nu, 0.0).unwrap();
    let dq = courant * grid.dx_mm;
    let ks = Kernel::new(mx, my, grid.dx_mm, grid.dy_mm, g, nu, dq).unwrap();
    let pn = solve_normal(&h, &k0, fnn, &NormalParams::default()).unwrap().pn_mpa;
    (k0, ks, pn, grid)
}

#[test]
#[allow(clippy::needless_range_loop)]
fn cg_and_gauss_seidel_agree_with_spin_and_half_courant() {
    let (k0, ks, pn, grid) = hertz_setup(14, 12, 0.5);
    let (x, y) = grid.centres();
    let gmax = 0.3 * pn.iter().cloned().fold(0.0, f64::max);
    let mut sol = Vec::new();
    for method in [Method::GaussSeidel, Method::ConjugateGradient] {
        let mut s = loaded(&k0, &ks, &pn, &x, &y);
        let mut p = TangentialParams::new(0.3, 0.001, -0.0005, 0.003, ks.shift_mm);
        p.tol = 1e-10;
        p.method = method;
        let n = pn.len();
        let (mut px, mut py) = (vec![0.0; n], vec![0.0; n]);
        let mut last = None;
        for _ in 0..6 {
            let r = s.transient_step(&p, &px, &py, None).unwrap();
            assert_eq!(r.termination, Termination::Converged, "{method:?}");
            px.copy_from_slice(&r.px);
            py.copy_from_slice(&r.py);
            last = Some(r);
        }
        let r = last.unwrap();
        assert!(r.n_slip > 0 && r.n_adhesion > 0, "{} {}", r.n_slip, r.n_adhesion);
        sol.push(r);
    }
    let d = sol[0]
        .px
        .iter()
        .zip(&sol[1].px)
        .chain(sol[0].py.iter().zip(&sol[1].py))
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(d < 1e-7 * gmax, "GS vs CG differ by {d} MPa");
    assert_eq!(sol[0].state, sol[1].state);
    // Coulomb conditions hold in the solution.
    let r = &sol[1];
    for k in 0..pn.len() {
        let g = 0.3 * pn[k];
        let a = norm2(r.px[k], r.py[k]);
        assert!(a <= g * (1.0 + 1e-12));
        match r.state[k] {
            ElementState::Adhesion => {
                assert!(norm2(r.sx[k], r.sy[k]) < 1e-8 * 1e-3, "slip in adhesion")
            }
            ElementState::Slip => {
                assert!((a - g).abs() < 1e-9 * g);
                // slip parallel to the traction, same sense
                let cross = r.sx[k] * r.py[k] - r.sy[k] * r.px[k];
                let dot = r.sx[k] * r.px[k] + r.sy[k] * r.py[k];
                assert!(dot >= -1e-12 && cross.abs() <= 1e-6 * norm2(r.sx[k], r.sy[k]) * g + 1e-15);
            }
            ElementState::Exterior => assert_eq!(a, 0.0),
        }
    }
}

#[test]
fn extrapolated_warm_start_reaches_the_same_solution() {
    // A ramp of creepage, stepped with and without the extrapolated warm start: the same
    // tractions to the tolerance, the same element states, and no more iterations.
    let (k0, ks, pn, grid) = hertz_setup(16, 12, 1.0);
    let (x, y) = grid.centres();
    let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
    let n = pn.len();
    let mut runs = Vec::new();
    for extrapolate in [false, true] {
        let mut s = loaded(&k0, &ks, &pn, &x, &y);
        let (mut px, mut py) = (vec![0.0; n], vec![0.0; n]);
        let mut older: Option<(Vec<f64>, Vec<f64>)> = None;
        let mut iterations = 0;
        let mut last = None;
        for step in 0..12 {
            let mut p = TangentialParams::new(0.4, 0.0005 * step as f64, 0.0, 0.0, ks.shift_mm);
            p.tol = 1e-9;
            let o = if extrapolate { older.as_ref().map(|(a, b)| (a.as_slice(), b.as_slice())) } else { None };
            let r = s.transient_step(&p, &px, &py, o).unwrap();
            assert!(r.termination.converged());
            iterations += r.iterations;
            older = Some((px.clone(), py.clone()));
            px.copy_from_slice(&r.px);
            py.copy_from_slice(&r.py);
            last = Some(r);
        }
        runs.push((last.unwrap(), iterations));
    }
    let (a, b) = (&runs[0].0, &runs[1].0);
    let d = a.px.iter().zip(&b.px).chain(a.py.iter().zip(&b.py)).fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
    assert!(d < 1e-7 * gmax, "warm starts differ by {d} MPa");
    assert_eq!(a.state, b.state);
    assert!(runs[1].1 <= runs[0].1, "extrapolated {} vs previous {} iterations", runs[1].1, runs[0].1);
    // Mismatched lengths are an error, not a panic.
    let p = TangentialParams::new(0.4, 0.001, 0.0, 0.0, ks.shift_mm);
    let mut s = loaded(&k0, &ks, &pn, &x, &y);
    let short = vec![0.0; n - 1];
    assert!(s.transient_step(&p, &b.px, &b.py, Some((&short, &short))).is_err());
}

#[test]
fn extrapolation_factor_follows_the_creepage_line() {
    let point = |mu: f64, cx: f64, cy: f64| SteadyPoint { creep: [mu, cx, cy, 0.0], px: vec![], py: vec![] };
    let (o, l) = (point(0.3, 0.001, 0.0), point(0.3, 0.002, 0.0));
    let next = |mu: f64, cx: f64, cy: f64| TangentialParams::new(mu, cx, cy, 0.0, 0.1);
    assert!((extrapolation_factor(&o, &l, &next(0.3, 0.003, 0.0)) - 1.0).abs() < 1e-12);
    assert!((extrapolation_factor(&o, &l, &next(0.3, 0.0025, 0.0)) - 0.5).abs() < 1e-12);
    assert_eq!(extrapolation_factor(&o, &l, &next(0.3, 0.003, 0.001)), 0.0, "off the line");
    assert_eq!(extrapolation_factor(&o, &l, &next(0.4, 0.003, 0.0)), 0.0, "other mu");
    assert_eq!(extrapolation_factor(&l, &l, &next(0.3, 0.003, 0.0)), 0.0, "no direction");
}

#[test]
fn steady_state_is_fixed_point_of_transient_step() {
    let (k0, ks, pn, grid) = hertz_setup(16, 12, 1.0);
    let (x, y) = grid.centres();
    let mut s = loaded(&k0, &ks, &pn, &x, &y);
    let mut p = TangentialParams::new(0.4, 0.002, 0.0, 0.0, ks.shift_mm);
    p.tol = 1e-10;
    let st = s.steady(&p, None).unwrap();
    assert!(st.termination.converged() && st.n_slip > 0 && st.n_adhesion > 0);
    let tr = s.transient_step(&p, &st.px, &st.py, None).unwrap();
    assert!(tr.termination.converged());
    let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
    let d = st.px.iter().zip(&tr.px).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(d < 1e-6 * gmax, "steady vs transient from steady: {d}");
}

/// The accelerated steady solver reproduces the Gauss-Seidel steady state (creepage and spin,
/// Courant 1 and 2, cold and warm starts), bit for bit on a repeat; from a cold start in fewer
/// iterations.
#[test]
fn accelerated_steady_matches_gauss_seidel() {
    for courant in [1.0, 2.0] {
        let (k0, ks, pn, grid) = hertz_setup(16, 12, courant);
        let (x, y) = grid.centres();
        let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
        let mut solvers: Vec<TangentialSolver> = (0..3).map(|_| loaded(&k0, &ks, &pn, &x, &y)).collect();
        for (i, (cx, cy, cs)) in
            [(0.002, 0.0, 0.0), (0.001, -0.0005, 0.004), (0.0015, 0.0, 0.0)].into_iter().enumerate()
        {
            let mut p = TangentialParams::new(0.4, cx, cy, cs, ks.shift_mm);
            p.tol = 1e-10;
            p.steady_method = SteadyMethod::GaussSeidel;
            let gs = solvers[0].steady(&p, None).unwrap();
            p.steady_method = SteadyMethod::Accelerated;
            let aa = solvers[1].steady(&p, None).unwrap();
            let again = solvers[2].steady(&p, None).unwrap();
            assert_eq!(
                (gs.termination, aa.termination),
                (Termination::Converged, Termination::Converged),
                "courant {courant}"
            );
            assert!(aa.residual < p.tol && aa.n_slip > 0 && aa.n_adhesion > 0);
            if i == 0 {
                assert!(aa.iterations < gs.iterations, "{} vs {}", aa.iterations, gs.iterations);
            }
            let d = gs.px.iter().zip(&aa.px).chain(gs.py.iter().zip(&aa.py));
            let d = d.fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            assert!(d < 1e-7 * gmax, "courant {courant} ({cx}, {cy}, {cs}): {d} MPa");
            assert_eq!(aa, again);
        }
    }
}

#[test]
fn non_convergence_is_flagged_and_bad_input_is_an_error() {
    let (k0, ks, pn, grid) = hertz_setup(12, 10, 1.0);
    let (x, y) = grid.centres();
    let mut s = loaded(&k0, &ks, &pn, &x, &y);
    let n = pn.len();
    let mut p = TangentialParams::new(0.4, 0.004, 0.0, 0.0, ks.shift_mm);
    p.max_iter = 1;
    let zero = vec![0.0; n];
    for method in [Method::GaussSeidel, Method::ConjugateGradient] {
        p.method = method;
        let r = s.transient_step(&p, &zero, &zero, None).unwrap();
        assert!(r.termination == Termination::IterationLimit && r.residual > p.tol && r.residual.is_finite());
    }
    let r = s.steady(&p, None).unwrap();
    assert_eq!(r.termination, Termination::IterationLimit);
    p.max_iter = 1000;
    p.cx = f64::NAN;
    assert!(s.transient_step(&p, &zero, &zero, None).is_err());
    p.cx = 0.001;
    p.dq_mm *= 1.5;
    assert!(s.steady(&p, None).is_err());
    p.dq_mm = ks.shift_mm;
    assert!(s.transient_step(&p, &zero[1..], &zero, None).is_err());
    // No loaded element: an error when set, and the solver has no contact until set again.
    let mut empty = loaded(&k0, &ks, &pn, &x, &y);
    assert_eq!(empty.set_pressure(&zero), Err(ContactError::NoContact));
    assert_eq!(empty.transient_step(&p, &zero, &zero, None), Err(ContactError::NoContact));
    assert!(TangentialSolver::new(&k0, &ks, &x, &y).unwrap().steady(&p, None).is_err());
    // mu = 0: no traction at all, everything slips.
    p.mu = 0.0;
    let r = s.transient_step(&p, &zero, &zero, None).unwrap();
    assert!(r.termination.converged() && r.px.iter().all(|&v| v == 0.0) && r.n_adhesion == 0);
}

/// One solver built per grid and loaded again per load solves exactly as a solver built for that
/// load: a load change forgets the previous load's iterate, work arrays and steady warm start.
#[test]
fn reloading_a_solver_equals_building_a_new_one() {
    let (k0, ks, pn, grid) = hertz_setup(16, 12, 1.0);
    let (x, y) = grid.centres();
    // A second load: a smaller contact area (the outer elements unloaded, the rest scaled up).
    let cut = 0.3 * pn.iter().cloned().fold(0.0, f64::max);
    let pn2: Vec<f64> = pn.iter().map(|&v| if v > cut { 1.5 * v } else { 0.0 }).collect();
    let base = TangentialParams::new(0.4, 0.002, 0.0005, 0.001, ks.shift_mm);
    // Three steady points (each warm-started from the previous ones), then two transient steps
    // from the last, the second with the extrapolated warm start.
    let run = |s: &mut TangentialSolver| -> Vec<StepResult> {
        let mut p = base;
        let mut out = Vec::new();
        for cx in [0.001, 0.002, 0.003] {
            p.cx = cx;
            out.push(s.steady(&p, None).unwrap());
        }
        let (px, py) = (out[2].px.clone(), out[2].py.clone());
        p.cx = 0.0025;
        let r = s.transient_step(&p, &px, &py, None).unwrap();
        let r2 = s.transient_step(&p, &r.px, &r.py, Some((&px, &py))).unwrap();
        out.extend([r, r2]);
        out
    };
    let mut reused = loaded(&k0, &ks, &pn, &x, &y);
    run(&mut reused);
    let mut p = base;
    p.method = Method::GaussSeidel;
    let n = pn.len();
    reused.transient_step(&p, &vec![1.0; n], &vec![-0.5; n], None).unwrap();
    reused.set_pressure(&pn2).unwrap();
    let mut fresh = loaded(&k0, &ks, &pn2, &x, &y);
    assert!(fresh.n_contact() < loaded(&k0, &ks, &pn, &x, &y).n_contact());
    assert_eq!(run(&mut reused), run(&mut fresh));
}

/// Rolling along −x through the shifted kernel and spin offset of any direction
/// ([`TangentialSolver::rolling_towards`] with `[−1, 0]`) is the mirror image of rolling along +x
/// (the solver of CHI = 180°, [`super::super::mirror`]): tractions `(px, py)(x) = (−px', py')(−x)`
/// of the +x solve at `(−cx, cy, −cs)`, step by step to 1e-12 of the bound (dq ≤ dx: no
/// leading-edge correction, which CONTACT takes along +x for every CHI but 180°).
#[test]
fn rolling_towards_minus_x_is_the_mirrored_plus_x_solve() {
    use super::super::mirror;
    let (mx, my) = (14, 12);
    let (k0, ks, pn, grid) = hertz_setup(mx, my, 0.75);
    let (x, y) = grid.centres();
    let g = Material::from_g(82000.0, 0.28).g_mpa;
    let back =
        Kernel::rolling(mx, my, (grid.dx_mm, grid.dy_mm), (g, 0.28), (ks.shift_mm, [-1.0, 0.0]), Basis::Constant)
            .unwrap();
    let mut turned = TangentialSolver::rolling_towards(&k0, &back, [-1.0, 0.0], &x, &y).unwrap();
    turned.set_pressure(&pn).unwrap();
    let mut mirrored = loaded(&k0, &ks, &mirror::field(mx, &pn), &mirror::field_x(mx, &x), &y);
    let mut p = TangentialParams::new(0.3, 0.001, -0.0005, 0.003, ks.shift_mm);
    p.tol = 1e-13;
    let q = TangentialParams { cx: -p.cx, cs: -p.cs, ..p };
    let gmax = 0.3 * pn.iter().cloned().fold(0.0, f64::max);
    let n = mx * my;
    let (mut a, mut b) = ((vec![0.0; n], vec![0.0; n]), (vec![0.0; n], vec![0.0; n]));
    for _ in 0..8 {
        let ra = turned.transient_step(&p, &a.0, &a.1, None).unwrap();
        let rb = mirrored.transient_step(&q, &b.0, &b.1, None).unwrap();
        let (bx, by) = (mirror::field_x(mx, &rb.px), mirror::field(mx, &rb.py));
        let d = ra.px.iter().zip(&bx).chain(ra.py.iter().zip(&by)).fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
        assert!(d < 1e-12 * gmax, "differ by {d} MPa");
        assert!(ra.n_slip > 0 && ra.n_adhesion > 0);
        a = (ra.px, ra.py);
        b = (rb.px, rb.py);
    }
}
