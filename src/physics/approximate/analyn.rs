//! ANALYN (B. A. Sichani, R. Enblom, M. Berg, "A novel method to model wheel–rail normal contact
//! in vehicle dynamics simulation", Vehicle System Dynamics 52(12), 2014), as CONTACT's modified
//! version computes it (`m_snorm`): per grid row the curvatures A(y) along x (least squares
//! parabola about the row's deepest point) and B(y) across (second difference), Hertz's ellipse
//! of those curvatures at the total interpenetration giving the shape factors α = δ/(A a²),
//! β = δ/(B b²); the row's local interpenetration `δ − β g(y)` (g the row's gap over the deepest
//! point), its half-length `√(δ_loc/(α A))` and Hertz's peak of the local ellipse, a
//! semi-elliptic pressure along x.

use super::{first_min, shape_of_curvatures, ApproximateError};
use crate::physics::{Grid, Material};
use std::f64::consts::PI;

/// Smallest curvature taken [1/mm] (a negative curvature becomes this).
const MIN_CURVATURE: f64 = 1e-4;
/// Widest half-span of the least-squares fit along x [elements].
const MAX_SPAN: usize = 10;
/// The fit's span ends where the gap rises above this share of the row's deepest value.
const SPAN_SHARE: f64 = 0.3;
/// Smallest local interpenetration or curvature counted as contact (CONTACT's `tiny`).
const TINY: f64 = 1e-20;

/// The ANALYN pressure [MPa] of the gap `gap` (grid order, negative where interpenetrating).
pub fn pressure(grid: &Grid, gap: &[f64], material: &Material) -> Result<Vec<f64>, ApproximateError> {
    let (mx, my) = (grid.mx, grid.my);
    let pentot = -gap[first_min(gap)];
    let mut p = vec![0.0; grid.len()];
    if mx < 3 || my < 3 {
        return Ok(p);
    }
    let at = |i: usize, j: usize| gap[j * mx + i];
    for j in 0..my {
        // The row's deepest point, kept off the grid's edge (CONTACT reports and clamps).
        let i_min = first_min(&gap[j * mx..(j + 1) * mx]).clamp(1, mx - 2);
        let g_y = at(i_min, j) + pentot;
        let a1 = curvature_x(&gap[j * mx..(j + 1) * mx], i_min, grid.dx_mm).max(MIN_CURVATURE);
        let (jm, jc, jp) = if j == 0 {
            (0, 1, 2)
        } else if j + 1 == my {
            (my - 3, my - 2, my - 1)
        } else {
            (j - 1, j, j + 1)
        };
        let b1 = (0.5 * (at(i_min, jp) - 2.0 * at(i_min, jc) + at(i_min, jm)) / grid.dy_mm.powi(2)).max(MIN_CURVATURE);
        let Some((shape, unit_mm)) = shape_of_curvatures(a1, b1, material) else { continue };
        let Ok(whole) = shape.at_unit_approach(pentot, unit_mm, material) else { continue };
        let alpha1 = pentot / (a1 * whole.a_mm * whole.a_mm);
        let beta1 = pentot / (b1 * whole.b_mm * whole.b_mm);
        let pen_loc = pentot - beta1 * g_y;
        if pen_loc <= TINY {
            continue;
        }
        let half = (pen_loc / (alpha1 * a1)).sqrt();
        let Ok(local) = shape.at_unit_approach(pen_loc, unit_mm, material) else { continue };
        let p_max = 1.5 * local.fn_n / (PI * local.a_mm * local.b_mm);
        let x_lc = grid.x_mm[i_min];
        for i in 0..mx {
            let r = (grid.x_mm[i] - x_lc) / half;
            if r.abs() < 1.0 {
                p[j * mx + i] = p_max * (1.0 - r * r).sqrt();
            }
        }
    }
    Ok(p)
}

/// Curvature A [1/mm] along x of a row's gap at `i_min`: the quadratic term of the least-squares
/// parabola over ±k elements, k grown from 1 while the row is interpenetrating there, up to
/// [`MAX_SPAN`], until the next point's gap exceeds [`SPAN_SHARE`] of the deepest (CONTACT's
/// `curvature_hx`).
fn curvature_x(row: &[f64], i_min: usize, dx_mm: f64) -> f64 {
    let mx = row.len();
    let mut k = 1;
    while k < MAX_SPAN
        && i_min > k
        && i_min + k + 1 < mx
        && row[i_min] < 0.0
        && row[i_min - k - 1].max(row[i_min + k + 1]) <= SPAN_SHARE * row[i_min]
    {
        k += 1;
    }
    let (mut s0, mut s2, mut s4, mut b0, mut b2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for d in -(k as isize)..=(k as isize) {
        let (t, h) = (d as f64, row[(i_min as isize + d) as usize]);
        s0 += 1.0;
        s2 += t * t;
        s4 += t.powi(4);
        b0 += h;
        b2 += h * t * t;
    }
    // Normal equations of h ≈ c0 + c1 t + c2 t² (the odd sums vanish): c2 = (s0 b2 − s2 b0)/(s0 s4 − s2²).
    (s0 * b2 - s2 * b0) / (s0 * s4 - s2 * s2) / (dx_mm * dx_mm)
}
