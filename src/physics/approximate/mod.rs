//! Approximate non-Hertzian normal contact on a grid of undeformed distances (CONTACT's B = 5, 6;
//! user guide §"Fast or detailed solution", `m_snorm`): Kik–Piotrowski's virtual interpenetration
//! with CONTACT's ellipse correction (KPEC, [`kpec`]) and Sichani's ANALYN ([`analyn`]). Both
//! give the pressure at a prescribed approach; [`at_load`] finds the approach that carries a
//! prescribed FN (CONTACT solves them at the approach its module 1 sets: N = 0 per patch).

pub mod analyn;
pub mod kpec;

use super::{Grid, HertzContact, HertzShape, Material, Radii};

/// Which approximation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Kik–Piotrowski with CONTACT's ellipse correction (B = 5).
    Kpec,
    /// ANALYN (Sichani, Enblom & Berg 2014; B = 6).
    Analyn,
}

/// Why an approximate normal problem has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ApproximateError {
    /// The deepest interpenetration lies on the grid's edge: no curvature along x there.
    #[error("{method:?}: the deepest interpenetration is on the grid's edge (row {row}, element {element}): the grid does not hold the contact")]
    OnEdge { method: Method, row: usize, element: usize },
    /// The interpenetration's curvatures give no Hertzian ellipse.
    #[error("{method:?}: the interpenetration is not convex (curvatures A = {a_per_mm} /mm, B = {b_per_mm} /mm)")]
    NotConvex { method: Method, a_per_mm: f64, b_per_mm: f64 },
    /// No approach up to `pen_mm` carries the load.
    #[error("{method:?}: no approach up to {pen_mm} mm carries FN = {fn_n} N")]
    NoLoad { method: Method, fn_n: f64, pen_mm: f64 },
}

/// The approximate contact at one load: pressure per element [MPa] (grid order) and its approach.
#[derive(Debug, Clone, PartialEq)]
pub struct ApproximateContact {
    pub pn_mpa: Vec<f64>,
    pub pen_mm: f64,
}

/// Hertz's semi-axes (a, b) [mm] and load [N] of curvatures `a1`, `b1` [1/mm] at approach
/// `pen_mm` (CONTACT's `hzcalc3d` with IPOTCN = −1, N = 0): radii 1/(2A), 1/(2B).
pub fn hertz_of_curvatures(a1: f64, b1: f64, pen_mm: f64, material: &Material) -> Option<HertzContact> {
    HertzContact::from_radii_and_approach(&radii_of_curvatures(a1, b1), pen_mm, material).ok()
}

/// Bisection tolerance on the elliptic modulus k in CONTACT's equivalent ellipses (`EPSHZ`).
const EPS_MODULUS: f64 = 1e-6;

/// Hertz's semi-axes (a, b) [mm] of curvatures `a1`, `b1` [1/mm] at approach `pen_mm` as
/// CONTACT's `hzcalc3d` gives them with EPSHZ = 1e-6 (IPOTCN = −1, N = 0; user guide §Hertz):
/// the modulus k found by bisection on [0, 1] until the bracket is within 1e-6, its last
/// midpoint taken (on slender ellipses b/a is then up to a few 1e-4 off Hertz's), then
/// `c = √(δ ρ E/(2 K g))`, ρ = 2/(A + B), g = √(1 − k²), the axes `c √g` and `c/√g`.
pub fn hertz_of_curvatures_coarse(a1: f64, b1: f64, pen_mm: f64) -> Option<(f64, f64)> {
    if !(a1 > 0.0 && b1 > 0.0 && pen_mm >= 0.0) {
        return None;
    }
    let ratio = a1.min(b1) / a1.max(b1);
    // min/max curvature of modulus k: (K − E)/(E/(1 − m) − K), m = k².
    let curvature_ratio = |k: f64| {
        let m = k * k;
        let (k_int, e_int) = ellip::ellipke(m).ok()?;
        Some((k_int - e_int) / (e_int / (1.0 - m) - k_int))
    };
    let (mut lo, mut hi, mut k) = (0.0_f64, 1.0_f64, 0.5_f64);
    while hi - lo > EPS_MODULUS {
        k = 0.5 * (lo + hi);
        if curvature_ratio(k)? >= ratio {
            lo = k;
        } else {
            hi = k;
        }
    }
    let m = k * k;
    let (k_int, e_int) = ellip::ellipke(m).ok()?;
    let g = (1.0 - m).max(1e-40).sqrt();
    let rho = 2.0 / (a1 + b1);
    let c = (pen_mm * rho * e_int / (2.0 * k_int * g)).sqrt();
    let (short, long) = (c * g.sqrt(), c / g.sqrt());
    Some(if b1 <= a1 { (short, long) } else { (long, short) })
}

/// Hertz's shape of curvatures `a1`, `b1` [1/mm] and its approach under 1 N [mm]
/// ([`hertz_of_curvatures`] at any approach from them: the eccentricity found once).
pub fn shape_of_curvatures(a1: f64, b1: f64, material: &Material) -> Option<(HertzShape, f64)> {
    let key = [a1, b1, material.g_mpa, material.poisson, material.e_mpa].map(f64::to_bits);
    SHAPES.with_borrow_mut(|kept| {
        if let Some(found) = kept.get(&key) {
            return *found;
        }
        if kept.len() >= KEPT_SHAPES {
            kept.clear();
        }
        let shape = HertzShape::of(&radii_of_curvatures(a1, b1)).ok();
        let found = shape.and_then(|s| Some((s, s.unit_approach_mm(material).ok()?)));
        kept.insert(key, found);
        found
    })
}

/// Shapes kept per thread before they are dropped: ANALYN's pressure asks for every row's shape
/// at every approach of its bisection, and a row's curvatures do not depend on the approach.
const KEPT_SHAPES: usize = 1 << 14;

type ShapeKey = [u64; 5];

thread_local! {
    /// [`shape_of_curvatures`]'s results by their inputs' bits (the same numbers as computed afresh).
    static SHAPES: std::cell::RefCell<std::collections::HashMap<ShapeKey, Option<(HertzShape, f64)>>> =
        std::cell::RefCell::new(std::collections::HashMap::new());
}

/// Radii 1/(2A), 1/(2B), the rail straight across.
fn radii_of_curvatures(a1: f64, b1: f64) -> Radii {
    Radii { r_wx_mm: 0.5 / a1, r_wy_mm: 0.5 / b1, r_ry_mm: f64::INFINITY }
}

/// The pressure of `method` at approach `pen_mm` on the undeformed distance `h_mm` (grid order).
pub fn at_approach(
    method: Method,
    grid: &Grid,
    h_mm: &[f64],
    pen_mm: f64,
    material: &Material,
) -> Result<Vec<f64>, ApproximateError> {
    let gap: Vec<f64> = h_mm.iter().map(|h| h - pen_mm).collect();
    if gap.iter().all(|&g| g >= 0.0) {
        return Ok(vec![0.0; grid.len()]);
    }
    match method {
        Method::Kpec => kpec::pressure(grid, &gap, material),
        Method::Analyn => analyn::pressure(grid, &gap, material),
    }
}

/// Bisection steps on the approach (2⁻⁶⁰ of the bracket).
const BISECTIONS: usize = 60;

/// The contact carrying `fn_n` [N]: the approach found by bisection on the total force (which
/// jumps where an element enters the contact), the pressure at the bracket's upper end scaled to
/// carry exactly `fn_n` (a module-3 problem prescribes FN).
pub fn at_load(
    method: Method,
    grid: &Grid,
    h_mm: &[f64],
    fn_n: f64,
    material: &Material,
) -> Result<ApproximateContact, ApproximateError> {
    let area = grid.element_area_mm2();
    let force = |pen: f64| -> Result<(f64, Vec<f64>), ApproximateError> {
        let p = at_approach(method, grid, h_mm, pen, material)?;
        Ok((p.iter().sum::<f64>() * area, p))
    };
    let h_min = h_mm.iter().copied().fold(f64::INFINITY, f64::min);
    let (mut lo, mut step) = (h_min, 1e-3);
    let mut hi = lo + step;
    let mut upper = force(hi)?;
    while upper.0 < fn_n {
        if step > 1e3 {
            return Err(ApproximateError::NoLoad { method, fn_n, pen_mm: hi - h_min });
        }
        lo = hi;
        step *= 2.0;
        hi = lo + step;
        upper = force(hi)?;
    }
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let at = force(mid)?;
        if at.0 < fn_n {
            lo = mid;
        } else {
            (hi, upper) = (mid, at);
        }
    }
    let scale = fn_n / upper.0;
    Ok(ApproximateContact { pn_mpa: upper.1.iter().map(|p| p * scale).collect(), pen_mm: hi - h_min })
}

/// Index of the first smallest value of `v`.
fn first_min(v: &[f64]) -> usize {
    let mut k = 0;
    for (i, &x) in v.iter().enumerate() {
        if x < v[k] {
            k = i;
        }
    }
    k
}

#[cfg(test)]
mod tests;
