//! A rail slices file with interruptions (parts missing on some slices: negative features S_F at
//! a slice's start or end) as CONTACT builds and evaluates its surface (`m_bspline_make.f90`,
//! `bspline_make_2d_bspline` with its mask; `bspline_check_mask`; `m_bspline_get.f90`,
//! `bspline_eval2d_prod`, `bspline_eval2d_inverse`, `bspline_get_z_at_xy`; user guide, "3D
//! surface building"): the tensor cubic B-spline's coefficients over the slices (knots at the
//! slices' positions, three more at each end spaced as the end interval) and the samples
//! (knots at their indices), each with a flag whether it is set.
//!
//! 1. Across the track, each slice's active samples are the not-a-knot spline over their
//!    indices, its coefficients set on the slice's row from its first sample's to two past its
//!    last.
//! 2. Along the track, the coefficient columns are taken in groups of samples whose slices are
//!    active alike, and each run of active slices of a group separately: each column of the run
//!    the not-a-knot spline through its coefficients over the run's slices, which sets the
//!    coefficients of the rows from the run's first slice to two past its last. A group keeps
//!    the two columns past its last sample only where the slices beside the run lack the next
//!    sample (its own neighbour then supplies them), and likewise before its first.
//! 3. A point (u, v) exists where all sixteen coefficients it uses are set (u held to the first
//!    and last slice's); the height at (u, y) is found as CONTACT finds it: v where the spline's
//!    y at u is y on the first lateral segment that reaches it, the unset coefficients taken at
//!    CONTACT's fill value −999 in that search, then the point at (u, v), absent where the mask
//!    says so.
//!
//! The not-a-knot splines are those of [`super::notaknot`]; their B-spline coefficients on the
//! knots are the blossoms of their cubic pieces (the same spline as CONTACT's collocation solve
//! with the two not-a-knot knots inserted afterwards).

use super::approx::basis;
use super::notaknot::{Curve, NotAKnot};

/// CONTACT's value of a coefficient that no spline sets (`cij = -999`).
const UNSET: f64 = -999.0;

/// The requirements of `bspline_check_mask`: an inactive part at a start or end at least 2
/// points long (or none), active regions at least 4 points long, at least 4 points between
/// active regions, at most 9 regions.
const MIN_BOUND: usize = 2;
const MIN_POINTS: usize = 4;
const MIN_SEPARATION: usize = 4;
const MAX_REGIONS: usize = 9;

/// The surface of a slices file with interruptions.
#[derive(Debug, Clone)]
pub struct Masked {
    /// The slices' positions.
    u: Vec<f64>,
    /// The knots along the track: n + 6.
    tu: Vec<f64>,
    /// The number of samples per slice (m) and of coefficient columns (m + 2).
    m: usize,
    /// The coefficients and their flags, (n + 2) rows × (m + 2) columns, row by row.
    cy: Vec<f64>,
    cz: Vec<f64>,
    set: Vec<bool>,
}

/// Why a masked surface cannot be built: CONTACT's error and its words.
#[derive(Debug, Clone, PartialEq)]
pub struct MaskError {
    pub what: String,
    pub value: String,
    pub allowed: String,
}

impl Masked {
    /// The surface through the resampled slices `y[i][j]`, `z[i][j]` at positions `u`, slice i
    /// holding samples `active[i].0 ..= active[i].1`.
    pub fn new(u: &[f64], y: &[Vec<f64>], z: &[Vec<f64>], active: &[(usize, usize)]) -> Result<Masked, MaskError> {
        let (n, m) = (u.len(), y[0].len());
        let mask: Vec<Vec<bool>> = active.iter().map(|&(a, b)| (0..m).map(|j| j >= a && j <= b).collect()).collect();
        check_mask(&mask)?;
        let tu = knots(u);
        let tv: Vec<f64> = (0..m + 6).map(|k| k as f64 - 3.0).collect();
        let sites: Vec<f64> = (0..m).map(|j| j as f64).collect();
        // Phase 1: each slice's lateral coefficients (NaN: not set).
        let mut ci = (vec![vec![f64::NAN; m + 2]; n], vec![vec![f64::NAN; m + 2]; n]);
        for (i, &(a, b)) in active.iter().enumerate() {
            let s = NotAKnot::new(&sites[a..=b]).ok_or_else(|| too_few(&format!("slice {}", i + 1), b + 1 - a))?;
            for (dst, src) in [(&mut ci.0[i], &y[i]), (&mut ci.1[i], &z[i])] {
                let c = coefficients(&s.curve(&src[a..=b]), &sites[a..=b], &tv, a);
                dst[a..a + c.len()].copy_from_slice(&c);
            }
        }
        let mut out = Masked {
            u: u.to_vec(),
            tu,
            m,
            cy: vec![UNSET; (n + 2) * (m + 2)],
            cz: vec![UNSET; (n + 2) * (m + 2)],
            set: vec![false; (n + 2) * (m + 2)],
        };
        // Phase 2: along the track, per group of alike columns and run of active slices.
        for (a0, a1) in groups(&mask) {
            for (i0, i1) in runs(&mask, a0) {
                let (k0, k1) = guard_columns(&mask, (a0, a1), (i0, i1));
                let s =
                    NotAKnot::new(&u[i0..=i1]).ok_or_else(|| too_few(&format!("sample {}", a0 + 1), i1 + 1 - i0))?;
                for k in k0..=k1.min(m + 1) {
                    for (dst, src) in [(&mut out.cy, &ci.0), (&mut out.cz, &ci.1)] {
                        let path: Vec<f64> = (i0..=i1).map(|i| src[i][k]).collect();
                        if let Some(i) = path.iter().position(|v| v.is_nan()) {
                            return Err(MaskError {
                                what: format!("the lateral coefficient {} of slice {}", k + 1, i0 + i + 1),
                                value: "not set by the slice's active samples".into(),
                                allowed: "interruptions whose neighbouring runs of slices supply every coefficient a run uses".into(),
                            });
                        }
                        let c = coefficients(&s.curve(&path), &u[i0..=i1], &out.tu, i0);
                        for (r, v) in (i0..).zip(c) {
                            dst[r * (m + 2) + k] = v;
                        }
                    }
                    for r in i0..=i1 + 2 {
                        out.set[r * (m + 2) + k] = true;
                    }
                }
            }
        }
        Ok(out)
    }

    /// The rows used at u (held to the first and last slice) and their B-splines' values.
    fn rows_at(&self, u: f64) -> (usize, [f64; 4]) {
        let n = self.u.len();
        let x = u.clamp(self.u[0], self.u[n - 1]);
        let s = self.u.partition_point(|&v| v <= x).saturating_sub(1).min(n - 2);
        (s, basis(&self.tu, s + 3, x))
    }

    /// The coefficient columns at u: Σ_r B_r(u) c_rk for y and z (unset ones at −999), and
    /// whether all four rows of column k are set.
    fn columns_at(&self, u: f64) -> (Vec<f64>, Vec<f64>, Vec<bool>) {
        let w = self.m + 2;
        let (s, b) = self.rows_at(u);
        let (mut cy, mut cz, mut set) = (vec![0.0; w], vec![0.0; w], vec![true; w]);
        for (q, &bq) in b.iter().enumerate() {
            let row = (s + q) * w..(s + q + 1) * w;
            for (c, v) in cy.iter_mut().zip(&self.cy[row.clone()]) {
                *c += bq * v;
            }
            for (c, v) in cz.iter_mut().zip(&self.cz[row.clone()]) {
                *c += bq * v;
            }
            for (f, v) in set.iter_mut().zip(&self.set[row]) {
                *f &= v;
            }
        }
        (cy, cz, set)
    }

    /// The surface's samples at u (v at each sample's index), `None` where not all of the
    /// coefficients they use are set (CONTACT's 999 there: `varprof_intpol_xunif`).
    pub fn samples_at(&self, u: f64) -> Vec<Option<(f64, f64)>> {
        let (cy, cz, set) = self.columns_at(u);
        (0..self.m).map(|j| lateral(&cy, &cz, &set, j as f64, self.m)).collect()
    }

    /// The height at (u, y) (`bspline_get_z_at_xy`): the first lateral segment whose
    /// coefficients' range holds y and whose cubic reaches it gives v (unset coefficients at
    /// −999); `None` where none does or where the point at (u, v) is not set.
    pub fn z_at(&self, u: f64, y: f64, first_root: impl Fn([f64; 4], f64) -> Option<f64>) -> Option<f64> {
        let (cy, cz, set) = self.columns_at(u);
        for s in 0..self.m - 1 {
            let c = &cy[s..s + 4];
            let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            if !(lo <= y && y <= hi) {
                continue;
            }
            if let Some(t) = first_root(uniform_cubic(c), y) {
                return lateral(&cy, &cz, &set, s as f64 + t, self.m).map(|(_, z)| z);
            }
        }
        None
    }
}

/// The point at lateral parameter v of the columns at u: the segment holding v (the last one
/// closed), `None` unless its four columns are set.
fn lateral(cy: &[f64], cz: &[f64], set: &[bool], v: f64, m: usize) -> Option<(f64, f64)> {
    let s = (v.floor().max(0.0) as usize).min(m - 2);
    if !set[s..s + 4].iter().all(|&b| b) {
        return None;
    }
    let t = v - s as f64;
    let b = uniform_basis(t);
    let dot = |c: &[f64]| c[s..s + 4].iter().zip(b).map(|(c, b)| c * b).sum::<f64>();
    Some((dot(cy), dot(cz)))
}

/// The four uniform cubic B-splines on a segment at t ∈ [0, 1].
fn uniform_basis(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [
        s * s * s / 6.0,
        (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
        (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0,
        t * t * t / 6.0,
    ]
}

/// The segment's cubic a₀ + a₁t + a₂t² + a₃t³ from its four uniform B-spline coefficients.
fn uniform_cubic(c: &[f64]) -> [f64; 4] {
    [
        (c[0] + 4.0 * c[1] + c[2]) / 6.0,
        (c[2] - c[0]) / 2.0,
        (c[0] - 2.0 * c[1] + c[2]) / 2.0,
        (c[3] - c[0] + 3.0 * (c[1] - c[2])) / 6.0,
    ]
}

/// CONTACT's knots at the sites `x` (`bspline_make_knot_vector_atmeas` with the inserted knots,
/// no replication): three before the first spaced as the first interval, the sites, three after.
fn knots(x: &[f64]) -> Vec<f64> {
    let n = x.len();
    let (d0, d1) = (x[1] - x[0], x[n - 1] - x[n - 2]);
    let mut t = vec![x[0] - 3.0 * d0, x[0] - 2.0 * d0, x[0] - d0];
    t.extend_from_slice(x);
    t.extend([x[n - 1] + d1, x[n - 1] + 2.0 * d1, x[n - 1] + 3.0 * d1]);
    t
}

/// The B-spline coefficients of the spline `curve` through the sites `x` (p of them) on the
/// knots `t`, where `x[q] = t[first + 3 + q]`: B_r for r = first ..= first + p + 1, each the
/// blossom of a cubic piece on its support at its three inner knots.
fn coefficients(curve: &Curve, x: &[f64], t: &[f64], first: usize) -> Vec<f64> {
    let p = x.len();
    (0..p + 2)
        .map(|q| {
            let seg = (q as isize - 1).clamp(0, p as isize - 2) as usize;
            let ([c0, c1, c2, c3], _) = curve.cubic(seg);
            let r = first + q;
            let [a, b, c] = [t[r + 1] - x[seg], t[r + 2] - x[seg], t[r + 3] - x[seg]];
            c0 + c1 * (a + b + c) / 3.0 + c2 * (a * b + a * c + b * c) / 3.0 + c3 * a * b * c
        })
        .collect()
}

fn too_few(what: &str, count: usize) -> MaskError {
    MaskError {
        what: format!("the active points of {what}"),
        value: count.to_string(),
        allowed: "at least 4 (CONTACT's error 172)".into(),
    }
}

/// The groups of consecutive samples whose columns of the mask are alike.
fn groups(mask: &[Vec<bool>]) -> Vec<(usize, usize)> {
    let m = mask[0].len();
    let column = |j: usize| mask.iter().map(move |row| row[j]);
    let mut out = Vec::new();
    let mut a0 = 0;
    for j in 1..=m {
        if j == m || !column(j).eq(column(a0)) {
            out.push((a0, j - 1));
            a0 = j;
        }
    }
    out
}

/// The runs of slices active at sample `j`.
fn runs(mask: &[Vec<bool>], j: usize) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, row) in mask.iter().enumerate() {
        match (row[j], start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                out.push((s, i - 1));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, mask.len() - 1));
    }
    out
}

/// The coefficient columns a group (samples a0 ..= a1) sets on a run (slices i0 ..= i1): from
/// a0 or a0 + 2 to a1 + 2 or a1, the guard columns kept where the slices just before and after
/// the run lack the neighbouring sample.
fn guard_columns(mask: &[Vec<bool>], (a0, a1): (usize, usize), (i0, i1): (usize, usize)) -> (usize, usize) {
    let (n, m) = (mask.len(), mask[0].len());
    let beside_lack = |j: usize| (i0 == 0 || !mask[i0 - 1][j]) && (i1 + 1 >= n || !mask[i1 + 1][j]);
    let left = a0 == 0 || beside_lack(a0 - 1);
    let right = a1 + 1 >= m || beside_lack(a1 + 1);
    (if left { a0 } else { a0 + 2 }, if right { a1 + 2 } else { a1 })
}

/// `bspline_check_mask`: along each slice and each sample's path, an inactive start or end of
/// at least 2 points (or none), active regions of at least 4, at least 4 points between
/// regions, at most 9 regions (CONTACT's errors 171, 172, 173).
fn check_mask(mask: &[Vec<bool>]) -> Result<(), MaskError> {
    for (i, row) in mask.iter().enumerate() {
        check_line(row, &format!("slice {}", i + 1))?;
    }
    for j in 0..mask[0].len() {
        let path: Vec<bool> = mask.iter().map(|row| row[j]).collect();
        check_line(&path, &format!("the path of sample {}", j + 1))?;
    }
    Ok(())
}

fn check_line(line: &[bool], name: &str) -> Result<(), MaskError> {
    let err = |what: &str, count: usize, allowed: &str| MaskError {
        what: format!("{name}: {what}"),
        value: count.to_string(),
        allowed: allowed.into(),
    };
    let mut regions = 0;
    let mut k = 0;
    while k < line.len() {
        let len = line[k..].iter().take_while(|&&b| b == line[k]).count();
        let (first, last) = (k == 0, k + len == line.len());
        if line[k] {
            regions += 1;
            if len < MIN_POINTS {
                return Err(err("an active region's points", len, "at least 4 (CONTACT's error 172)"));
            }
        } else if (first || last) && len < MIN_BOUND {
            return Err(err("the inactive points at its start or end", len, "0 or at least 2 (CONTACT's error 171)"));
        } else if !(first || last) && len < MIN_SEPARATION {
            return Err(err("the inactive points between active regions", len, "at least 4 (CONTACT's error 171)"));
        }
        k += len;
    }
    if regions > MAX_REGIONS {
        return Err(err("the regions of active points", regions, "at most 9 (CONTACT's error 173)"));
    }
    Ok(())
}

#[cfg(test)]
#[path = "masked_tests.rs"]
mod tests;
