//! One interval between two slices of a variable profile with the interpolating spline along the
//! track (CONTACT's `U_INTPOL = 1`): there the samples are cubics in t = u − u_k and so are the
//! lateral not-a-knot spline's second derivatives, so the surface's height at (t, y)
//! (`bspline_get_z_at_xy`: the first lateral segment that reaches y) costs a few cubics per
//! segment looked at. Each segment's reach in y over the whole interval is kept, and the reach of
//! each block of segments, so a query looks only at the segments that can hold y.

use super::notaknot::{Curve, NotAKnot};
use super::spline::bracketed_root;

/// Segments per block of the reach.
const BLOCK: usize = 16;

/// A bound's slack on y [mm], beyond the rounding of the cubics it bounds.
const SLACK_MM: f64 = 1e-6;

/// Band k: the cubics in t of the paths (`f`) and of the lateral spline's second derivatives
/// (`m`), for y and for z, and the y each lateral segment can reach.
#[derive(Debug, Clone)]
pub(super) struct Band {
    f_y: Vec<[f64; 4]>,
    m_y: Vec<[f64; 4]>,
    f_z: Vec<[f64; 4]>,
    m_z: Vec<[f64; 4]>,
    /// Per lateral segment the lowest and highest y it reaches for t in [0, h].
    reach: Vec<[f64; 2]>,
    /// Per block of [`BLOCK`] segments the union of their reaches.
    block: Vec<[f64; 2]>,
}

impl Band {
    /// Interval `k` of the paths (y paths, z paths), of length `h` [mm or rad].
    pub(super) fn new(across: &NotAKnot, (ys, zs): (&[Curve], &[Curve]), k: usize, h: f64) -> Band {
        let (f_y, m_y) = cubics(across, ys, k);
        let (f_z, m_z) = cubics(across, zs, k);
        let reach = segment_reach(&f_y, &m_y, h);
        let block = reach
            .chunks(BLOCK)
            .map(|c| c.iter().fold([f64::INFINITY, f64::NEG_INFINITY], |a, r| [a[0].min(r[0]), a[1].max(r[1])]))
            .collect();
        Band { f_y, m_y, f_z, m_z, reach, block }
    }

    /// The lateral spline's segment j (sites j, j + 1: length 1) at t, as a cubic in its local
    /// parameter (`notaknot::Curve::cubic`) from the values and second derivatives at its ends.
    fn segment(f: &[[f64; 4]], m: &[[f64; 4]], j: usize, t: f64) -> [f64; 4] {
        let (f0, f1, m0, m1) = (poly(f[j], t), poly(f[j + 1], t), poly(m[j], t), poly(m[j + 1], t));
        [f0, (f1 - f0) - (2.0 * m0 + m1) / 6.0, m0 / 2.0, (m1 - m0) / 6.0]
    }

    /// The surface's height at t in this band and lateral y: the first lateral segment that
    /// reaches y. A segment whose cubic cannot reach y (it lies within |M₀| + |M₁| times 0.0642 of
    /// its chord, s(1 − s)(2 − s)/6 ≤ 0.0642 on [0, 1]) is passed over without solving; so is a
    /// block of segments none of which reaches y anywhere in the band.
    pub(super) fn z_at(&self, t: f64, y: f64) -> Option<f64> {
        let slack = SLACK_MM + 1e-9 * (1.0 + y.abs());
        let outside = |r: &[f64; 2]| y < r[0] - slack || y > r[1] + slack;
        for (b, r) in self.block.iter().enumerate() {
            if outside(r) {
                continue;
            }
            for j in b * BLOCK..((b + 1) * BLOCK).min(self.reach.len()) {
                if outside(&self.reach[j]) {
                    continue;
                }
                if let Some(z) = self.z_on(j, t, y) {
                    return Some(z);
                }
            }
        }
        None
    }

    /// The height where segment j reaches y at t, if it does.
    fn z_on(&self, j: usize, t: f64, y: f64) -> Option<f64> {
        let (f0, f1) = (poly(self.f_y[j], t), poly(self.f_y[j + 1], t));
        let (m0, m1) = (poly(self.m_y[j], t), poly(self.m_y[j + 1], t));
        let bow = 0.065 * (m0.abs() + m1.abs()) + 1e-9 * (1.0 + y.abs());
        if y < f0.min(f1) - bow || y > f0.max(f1) + bow {
            return None;
        }
        let cy = Band::segment(&self.f_y, &self.m_y, j, t);
        let s = first_root((cy, 1.0), y)?;
        Some(poly(Band::segment(&self.f_z, &self.m_z, j, t), s))
    }
}

/// The cubics in t of interval `k` of the paths, and of the lateral not-a-knot spline's second
/// derivatives through them.
fn cubics(across: &NotAKnot, paths: &[Curve], k: usize) -> (Vec<[f64; 4]>, Vec<[f64; 4]>) {
    let f: Vec<[f64; 4]> = paths.iter().map(|c| c.cubic(k).0).collect();
    let mut m = vec![[0.0; 4]; f.len()];
    for p in 0..4 {
        let column: Vec<f64> = f.iter().map(|c| c[p]).collect();
        for (mj, v) in m.iter_mut().zip(across.curve(&column).second_derivatives()) {
            mj[p] = *v;
        }
    }
    (f, m)
}

/// Per lateral segment the y it reaches for some t in [0, h]: its ends' range with the largest
/// bow its second derivatives allow ([`Band::z_at`]'s test, over the whole band).
fn segment_reach(f: &[[f64; 4]], m: &[[f64; 4]], h: f64) -> Vec<[f64; 2]> {
    let f_range: Vec<[f64; 2]> = f.iter().map(|c| range(*c, h)).collect();
    let m_abs: Vec<f64> = m.iter().map(|c| range(*c, h)).map(|[lo, hi]| lo.abs().max(hi.abs())).collect();
    (0..f.len().saturating_sub(1))
        .map(|j| {
            let bow = 0.065 * (m_abs[j] + m_abs[j + 1]);
            let (lo, hi) = (f_range[j][0].min(f_range[j + 1][0]), f_range[j][1].max(f_range[j + 1][1]));
            let round = 1e-12 * (1.0 + lo.abs().max(hi.abs()) + bow);
            [lo - bow - round, hi + bow + round]
        })
        .collect()
}

/// The lowest and highest value of the cubic c0 + c1 t + c2 t² + c3 t³ on [0, h]: at the ends
/// and at its turning points inside.
fn range(c: [f64; 4], h: f64) -> [f64; 2] {
    let mut lo = poly(c, 0.0).min(poly(c, h));
    let mut hi = poly(c, 0.0).max(poly(c, h));
    for t in turning_points(c, h) {
        let v = poly(c, t);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    [lo, hi]
}

/// The cubic's turning points in (0, h), in increasing order: 3 c3 t² + 2 c2 t + c1 = 0.
fn turning_points([_, c1, c2, c3]: [f64; 4], h: f64) -> Vec<f64> {
    let (a, b, c) = (3.0 * c3, 2.0 * c2, c1);
    let mut ts = Vec::with_capacity(2);
    if a.abs() > 1e-300 {
        let disc = b * b - 4.0 * a * c;
        if disc > 0.0 {
            let r = disc.sqrt();
            let mut both = [(-b - r) / (2.0 * a), (-b + r) / (2.0 * a)];
            both.sort_by(f64::total_cmp);
            ts.extend(both.into_iter().filter(|&t| t > 0.0 && t < h));
        }
    } else if b.abs() > 1e-300 && -c / b > 0.0 && -c / b < h {
        ts.push(-c / b);
    }
    ts
}

/// c0 + c1 t + c2 t² + c3 t³.
fn poly([c0, c1, c2, c3]: [f64; 4], t: f64) -> f64 {
    ((c3 * t + c2) * t + c1) * t + c0
}

/// The smallest t in [0, h] where c0 + c1 t + c2 t² + c3 t³ = y: the first monotone piece
/// between the cubic's turning points that holds y, solved by bracketed Newton.
pub(super) fn first_root((c, h): ([f64; 4], f64), y: f64) -> Option<f64> {
    let [c0, c1, c2, c3] = c;
    let g = |t: f64| (((c3 * t + c2) * t + c1) * t + c0 - y, (3.0 * c3 * t + 2.0 * c2) * t + c1);
    let mut cuts = [0.0; 4];
    let inside = turning_points(c, h);
    cuts[1..=inside.len()].copy_from_slice(&inside);
    cuts[inside.len() + 1] = h;
    cuts[..inside.len() + 2].windows(2).find_map(|w| bracketed_root(&g, (w[0], g(w[0]).0), (w[1], g(w[1]).0)))
}
