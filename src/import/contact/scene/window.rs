//! The potential contact across a history: a Hertzian grid re-specified as the same grid, a grid
//! that moves by whole elements (a moving window, written on the union grid of its windows), and
//! the undeformed distance and nominal load of a grid geometry (`m_sdis.f90`).

use super::super::deck::{Case, Potcon, State};
use super::super::CaseStatus;
use super::case3;
use super::history::History;
use crate::physics::material::combine_bodies;

/// Largest relative difference of the semi-axes of two Hertzian potential contacts taken as one
/// grid: CONTACT's printed curvature A1 = 0.2963e-2 of `testbank.inp` case 16 gives a = 4.09992
/// mm where case 13's AA = 4.1 (2e-5).
pub(super) const HERTZ_GRID_REL: f64 = 1e-4;

/// The semi-axes [mm] of a case's Hertzian potential contact (IPOTCN = -3: AA, BB; -1: Hertz's of
/// A1, B1 at its FN; -2: of A1 and AOB), with MX, MY and SCALE; `None`: not Hertzian or N = 0.
pub(super) fn hertz_axes(s: &State) -> Option<(usize, usize, f64, [f64; 2])> {
    let Some(Potcon::Hertz { ipotcn, mx, my, params }) = &s.potcon else {
        return None;
    };
    let axes = match ipotcn {
        -3 => [params[0], params[1]],
        -1 | -2 => {
            let b1 = if *ipotcn == -2 { params[0] * curvature_ratio(params[1], s) } else { params[1] };
            let radii = crate::physics::Radii { r_wx_mm: 0.5 / params[0], r_wy_mm: 1.0 / b1, r_ry_mm: 1.0 / b1 };
            let m = combine_bodies(s.poiss, s.gg_mpa);
            let material = crate::physics::Material::from_g(m.g_mpa, m.poisson);
            let e = crate::physics::HertzContact::from_radii(&radii, s.pen_or_fn, &material).ok()?;
            [e.a_mm, e.b_mm]
        }
        _ => return None,
    };
    Some((*mx, *my, params[2], axes))
}

/// Whether a case re-specifies its history's Hertzian grid as the same grid: MX, MY and SCALE
/// equal, the semi-axes within [`HERTZ_GRID_REL`] (the history keeps the first case's).
pub(super) fn same_hertz_grid(a: &State, b: &State) -> bool {
    match (hertz_axes(a), hertz_axes(b)) {
        (Some((mx, my, scale, [aa, ab])), Some((nx, ny, sc, [ba, bb]))) => {
            (mx, my, scale) == (nx, ny, sc)
                && ((aa - ba) / aa).abs() <= HERTZ_GRID_REL
                && ((ab - bb) / ab).abs() <= HERTZ_GRID_REL
        }
        _ => false,
    }
}

/// Whether both cases give a quadratic undeformed distance (IBASE = 1, IPLAN alike) on one grid:
/// new B(1..6) per case are the table's columns `b1_per_mm` … `b6_mm`.
pub(super) fn quadratics(a: &State, b: &State) -> bool {
    let q = |s: &State| s.undeformed.as_ref().filter(|u| u.ibase == 1).map(|u| u.iplan);
    matches!(a.potcon, Some(Potcon::Grid { .. })) && q(a).is_some() && q(a) == q(b)
}

/// The whole elements (x, y) by which `b`'s grid is `a`'s moved (same IPOTCN, MX, MY, DX, DY;
/// XL, YL shifted by integer multiples of DX, DY), if it is.
pub(super) fn window_shift(a: &State, b: &State) -> Option<(i64, i64)> {
    let (
        Some(Potcon::Grid { ipotcn: ia, mx: ma, my: na, xl_mm: xa, yl_mm: ya, dx_mm: dxa, dy_mm: dya }),
        Some(Potcon::Grid { ipotcn: ib, mx: mb, my: nb, xl_mm: xb, yl_mm: yb, dx_mm: dxb, dy_mm: dyb }),
    ) = (&a.potcon, &b.potcon)
    else {
        return None;
    };
    let whole = |from: f64, to: f64, d: f64| {
        let k = ((to - from) / d).round();
        ((from + k * d - to).abs() <= 1e-9 * d).then_some(k as i64)
    };
    let same = (ia, ma, na, dxa, dya) == (ib, mb, nb, dxb, dyb);
    same.then_some(())?;
    Some((whole(*xa, *xb, *dxa)?, whole(*ya, *yb, *dya)?))
}

/// The quadratic undeformed distance B(1..6) at (x, y) (IBASE = 1).
pub(super) fn quadratic(b: &[f64], (x, y): (f64, f64)) -> f64 {
    b[0] * x * x + b[1] * x * y + b[2] * y * y + b[3] * x + b[4] * y + b[5]
}

/// The union grid of a history whose cases move one grid by whole elements (`None` where the grid
/// does not move): the lowest XL, YL and the extent of every window.
pub(super) fn union_grid(cases: &[Case], h: &History) -> Option<Potcon> {
    let first = &case3(cases, h.cases[0]).state;
    let shifts: Vec<(i64, i64)> =
        h.cases.iter().map(|&k| window_shift(first, &case3(cases, k).state)).collect::<Option<_>>()?;
    if shifts.iter().all(|&s| s == (0, 0)) {
        return None;
    }
    let Some(Potcon::Grid { ipotcn, mx, my, xl_mm, yl_mm, dx_mm, dy_mm }) = first.potcon.clone() else {
        return None;
    };
    let lo = |f: fn(&(i64, i64)) -> i64| shifts.iter().map(f).min().unwrap_or(0);
    let hi = |f: fn(&(i64, i64)) -> i64| shifts.iter().map(f).max().unwrap_or(0);
    let (x0, y0) = (lo(|s| s.0), lo(|s| s.1));
    Some(Potcon::Grid {
        ipotcn,
        mx: mx + (hi(|s| s.0) - x0) as usize,
        my: my + (hi(|s| s.1) - y0) as usize,
        xl_mm: xl_mm + x0 as f64 * dx_mm,
        yl_mm: yl_mm + y0 as f64 * dy_mm,
        dx_mm,
        dy_mm,
    })
}

/// A moving window (its grid moved by whole elements per case) is written on the union grid of
/// its history, exact where no element outside a case's window can touch: with the approach
/// prescribed (N = 0), the undeformed distance exceeds PEN at every such element, so its gap stays
/// open and its traction zero, as CONTACT's, which has no element there. Each case is refused
/// where this fails, or noted where it holds.
pub(super) fn check_union(cases: &[Case], h: &History, statuses: &mut [CaseStatus]) {
    let Some(Potcon::Grid { mx, my, xl_mm, yl_mm, dx_mm, dy_mm, .. }) = union_grid(cases, h) else {
        return;
    };
    for &k in &h.cases {
        let c = case3(cases, k);
        let Some(Potcon::Grid { mx: wx, my: wy, xl_mm: xl, yl_mm: yl, .. }) = &c.state.potcon else { continue };
        let (ox, oy) = (((xl - xl_mm) / dx_mm).round() as usize, ((yl - yl_mm) / dy_mm).round() as usize);
        let b = c.state.undeformed.as_ref().map(|u| u.values.clone()).unwrap_or_default();
        let pen = c.state.pen_or_fn;
        let h_mm: Vec<f64> = (0..mx * my)
            .map(|e| quadratic(&b, (xl_mm + ((e % mx) as f64 + 0.5) * dx_mm, yl_mm + ((e / mx) as f64 + 0.5) * dy_mm)))
            .collect();
        let m = combine_bodies(c.state.poiss, c.state.gg_mpa);
        let by_pen = c.digits.n == 0;
        let pn = pressure_on(&h_mm, (mx, my, dx_mm, dy_mm), (m.g_mpa, m.poisson), pen, by_pen).unwrap_or_default();
        let touching = (0..mx * my).map(|e| (e % mx, e / mx)).find(|&(ix, iy)| {
            let inside = (ox..ox + wx).contains(&ix) && (oy..oy + wy).contains(&iy);
            !inside && pn.get(iy * mx + ix).is_none_or(|p| *p != 0.0)
        });
        match touching {
            Some((ix, iy)) => statuses[k].refused.push(format!(
                "XL = {xl}: the grid moves by whole elements, but at PEN or FN = {pen} element ({}, {}) of the union grid ({mx} x {my} from XL = {xl_mm}), outside case {}'s window, carries pressure {:?} MPa: it touches where CONTACT has no element (supported: a moving window outside which the union grid's normal solution is zero)",
                ix + 1,
                iy + 1,
                cases[k].number,
                pn.get(iy * mx + ix)
            )),
            None => statuses[k].notes.push(format!(
                "XL = {xl}: the moving window ({wx} x {wy}) is mapped to the union grid ({mx} x {my} from XL = {xl_mm}, YL = {yl_mm}) of its history; exact: at {} = {pen} the union grid's normal solution is zero outside the window, so it is the window's (the normal problem's solution is unique; no normal-tangential coupling) and the tangential traction, bounded by mu times it, is zero there too, as where CONTACT has no element",
                if by_pen { "PEN" } else { "FN" }
            )),
        }
    }
}

/// The B(1..6) of each case where they change within the history (IBASE = 1), else `None`.
pub(super) fn quadratic_rows(cases: &[Case], h: &History) -> Option<Vec<[f64; 6]>> {
    let b = |k: usize| {
        let u = case3(cases, k).state.undeformed.as_ref()?;
        <[f64; 6]>::try_from(u.values.as_slice()).ok().filter(|_| u.ibase == 1)
    };
    let rows: Vec<[f64; 6]> = h.cases.iter().map(|&k| b(k)).collect::<Option<_>>()?;
    rows.iter().any(|r| r != &rows[0]).then_some(rows)
}

/// The load of approach `pen_mm` on undeformed distance `h_mm` (CONTACT's element order) of a
/// `mx × my` grid of `dx × dy` elements: the nominal `contact.fn_n` of a case with N = 0 (`None`
/// where the normal solver fails or does not converge).
pub(super) fn load_of_approach(
    h_mm: &[f64],
    (mx, my, dx, dy): (usize, usize, f64, f64),
    (g, nu): (f64, f64),
    pen_mm: f64,
) -> Option<f64> {
    use crate::physics::halfspace::{influence::Kernel, normal};
    let kernel = Kernel::new(mx, my, dx, dy, g, nu, 0.0).ok()?;
    let s = normal::NormalSolver::new(&kernel).ok()?.solve_approach(h_mm, pen_mm, &Default::default()).ok()?;
    Some(s.converged_pn_mpa().ok()?.iter().sum::<f64>() * dx * dy).filter(|f| f.is_finite() && *f > 0.0)
}

/// The pressure on undeformed distance `h_mm` (CONTACT's element order) of a `mx × my` grid of
/// `dx × dy` elements at approach `pen_or_fn` (`by_pen`, N = 0) or load (N = 1), or `None` where
/// the normal solver fails.
fn pressure_on(
    h_mm: &[f64],
    (mx, my, dx, dy): (usize, usize, f64, f64),
    (g, nu): (f64, f64),
    pen_or_fn: f64,
    by_pen: bool,
) -> Option<Vec<f64>> {
    use crate::physics::halfspace::{influence::Kernel, normal};
    let kernel = Kernel::new(mx, my, dx, dy, g, nu, 0.0).ok()?;
    let mut solver = normal::NormalSolver::new(&kernel).ok()?;
    let s = if by_pen {
        solver.solve_approach(h_mm, pen_or_fn, &Default::default()).ok()?
    } else {
        solver.solve(h_mm, pen_or_fn, &Default::default()).ok()?
    };
    s.converged_pn_mpa().ok()
}

/// IBASE = 2 at an element centre (x, y): the NN heights linear in y between Y1 + (k−1) DY1
/// (extrapolated beyond), plus the circle in x as CONTACT evaluates it, its parabola
/// (x − XM)²/(2 RX1) (`m_sdis.f90` lines 358-405); `b` = NN, XM, RX1, Y1, DY1, heights.
pub(super) fn circular_in_x(b: &[f64], (x, y): (f64, f64)) -> f64 {
    let (nn, xm, rx, y1, dy1) = (b[0] as usize, b[1], b[2], b[3], b[4]);
    let yn = y1 + (nn - 1) as f64 * dy1;
    let (left, y_left) = if y < y1 {
        (0, y1)
    } else if y >= yn {
        (nn - 2, yn - dy1)
    } else {
        let k = ((y - y1) / dy1) as usize;
        (k, y1 + k as f64 * dy1)
    };
    let heights = &b[5..];
    let slope = (heights[left + 1] - heights[left]) / dy1;
    heights[left] + slope * (y - y_left) + (x - xm) * (x - xm) / (2.0 * rx)
}

/// Hertz's curvature ratio B/A of an ellipse with semi-axis ratio `a_over_b` (it depends on the
/// ratio alone: any load and material give it).
pub(super) fn curvature_ratio(a_over_b: f64, s: &State) -> f64 {
    let m = combine_bodies(s.poiss, s.gg_mpa);
    let material = crate::physics::Material::from_g(m.g_mpa, m.poisson);
    let e = crate::physics::HertzContact { a_mm: a_over_b, b_mm: 1.0, fn_n: 1.0 };
    let (a, b) = e.undeformed_curvatures(&material);
    b / a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ibase_2_is_linear_in_y_through_its_heights_and_a_parabola_in_x() {
        // NN = 3 heights 1, 3, 2 at y = -1, 1, 3; circle of radius 5 around XM = 2.
        let b = [3.0, 2.0, 5.0, -1.0, 2.0, 1.0, 3.0, 2.0];
        let at = |x: f64, y: f64| circular_in_x(&b, (x, y));
        assert_eq!(at(2.0, -1.0), 1.0);
        assert_eq!(at(2.0, 0.0), 2.0);
        assert_eq!(at(2.0, 2.0), 2.5);
        // Beyond the points: the first and last segments extended (CONTACT extrapolates).
        assert_eq!(at(2.0, -3.0), -1.0);
        assert_eq!(at(2.0, 5.0), 1.0);
        // (x - XM)²/(2 RX1): the parabola CONTACT uses, not the circle.
        assert_eq!(at(4.0, 1.0), 3.0 + 0.4);
    }
}
