//! A wheel or rail profile as CONTACT's module 1 uses it (user guide, Section "Inputs regarding
//! wheel and rail profiles"; `m_varprof.f90` `profile_read_file`, `m_profile.f90`
//! `profile_finish_grid`, `profile_store_values`): read from a SIMPACK, Miniprof or plain file
//! ([`read_profile`]) or given as values ([`Profile::from_points`]), brought into CONTACT's
//! canonical form ([`canonical`]), cleaned ([`clean`]) and fitted with CONTACT's parametric spline
//! ([`spline`]). A [`Profile`] is read once per scene and shared: cloning it is cheap.
//!
//! Units are in the names: `_mm` for lengths, `_rad` for angles, `_per_mm` for curvatures.

mod approx;
mod band;
pub mod canonical;
pub mod clean;
pub mod error;
mod foldback;
mod index;
pub mod lines;
mod masked;
pub mod memo;
pub mod miniprof;
mod notaknot;
pub mod options;
pub mod read;
pub mod simpack;
pub mod slices;
pub mod spline;

pub use error::ProfileError;
pub use options::ProfileOptions;
pub use read::read_profile;

use canonical::Pt;
use spline::ParamSpline;
use std::sync::{Arc, OnceLock};

/// Which body a profile belongs to (CONTACT's `is_wheel` 0 or 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProfileKind {
    Rail,
    Wheel,
}

impl ProfileKind {
    /// "rail" or "wheel".
    pub fn name(self) -> &'static str {
        match self {
            ProfileKind::Rail => "rail",
            ProfileKind::Wheel => "wheel",
        }
    }
}

/// What reading and cleaning did to the points (CONTACT prints these as INFO and WARNING lines).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Cleaning {
    /// Points in the file (or given).
    pub read: usize,
    /// Dropped as too close to the previous point kept (`point.dist.min`, 1e-4 in the file's
    /// units for Miniprof and plain tables).
    pub too_close: usize,
    /// Dropped by replacing zig-zags with their mean (ZIGTHRS).
    pub zigzag: usize,
    /// Dropped outside SIMPACK's `bound.y.min`, `bound.y.max`.
    pub outside_bounds: usize,
    /// y was mirrored (MIRRORY, SIMPACK's `mirror.y`).
    pub mirrored_y: bool,
    /// z was mirrored (MIRRORZ, SIMPACK's `mirror.z`, or CONTACT's detection).
    pub mirrored_z: bool,
    /// The order of the points was reversed (SIMPACK's `inversion`, or CONTACT's detection).
    pub inverted: bool,
}

/// A point of the profile's spline with its derivatives in s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfilePoint {
    pub s_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    /// dy/ds: about a unit vector with `dz_ds` (s is the chord length of the points).
    pub dy_ds: f64,
    pub dz_ds: f64,
    /// Signed curvature (y′z″ − z′y″)/(y′² + z′²)^{3/2}, positive where the surface is convex
    /// (the top of a rail, the tread of a wheel); CONTACT's ±1e6 where the denominator is below
    /// 1e-6.
    pub curvature_per_mm: f64,
}

impl ProfilePoint {
    /// The unit tangent (dy/ds, dz/ds) normalised; the material lies to its right.
    pub fn tangent(&self) -> [f64; 2] {
        let n = self.dy_ds.hypot(self.dz_ds);
        [self.dy_ds / n, self.dz_ds / n]
    }

    /// The slope dz/dy; CONTACT's ±1e6 (the sign of dz/ds) where |dy/ds| < 1e-6 (a vertical
    /// flank).
    pub fn slope_dz_dy(&self) -> f64 {
        slope_dz_dy(self.dy_ds, self.dz_ds)
    }
}

/// dz/dy from the derivatives along the arc ([`ProfilePoint::slope_dz_dy`]).
fn slope_dz_dy(dy_ds: f64, dz_ds: f64) -> f64 {
    if dy_ds.abs() < 1e-6 {
        1e6_f64.copysign(dz_ds)
    } else {
        dz_ds / dy_ds
    }
}

/// A profile in CONTACT's canonical form with its spline.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile(Arc<Data>);

#[derive(PartialEq)]
struct Data {
    file: String,
    kind: ProfileKind,
    y_mm: Vec<f64>,
    z_mm: Vec<f64>,
    s_mm: Vec<f64>,
    spline: ParamSpline,
    breaks: Vec<usize>,
    cleaning: Cleaning,
    max_omit: f64,
    /// Each segment's y-range (interior extrema included), for the search by y.
    segment_y: Vec<(f64, f64)>,
    /// Each segment's pieces where y(s) is monotone ([`ParamSpline::monotone_pieces`]).
    pieces: Vec<spline::Pieces>,
    /// The contact locus's profile nodes, made at the first call (the profile's alone).
    locus_nodes: OnceLock<Option<Vec<super::locus::Node>>>,
    /// The profile's placements as a rail made so far ([`super::RailPlacements`]).
    placements: super::RailPlacements,
    /// The segments by y, and the whole y-range (`segment_y`'s hull).
    index: index::SegmentIndex,
    y_range: (f64, f64),
}

/// A summary: a profile has hundreds of points.
impl std::fmt::Debug for Data {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let n = self.s_mm.len();
        f.debug_struct("Profile")
            .field("file", &self.file)
            .field("kind", &self.kind)
            .field("points", &n)
            .field("first_mm", &(self.y_mm[0], self.z_mm[0]))
            .field("last_mm", &(self.y_mm[n - 1], self.z_mm[n - 1]))
            .field("s_mm", &(self.s_mm[0], self.s_mm[n - 1]))
            .field("breaks", &self.breaks)
            .field("cleaning", &self.cleaning)
            .finish_non_exhaustive()
    }
}

/// CONTACT's bounds on a profile's total length [mm] (`profile_finish_grid`, errors 241 and 242):
/// a profile outside them has its unit wrong.
pub const LENGTH_MIN_MM: f64 = 5.0;
pub const LENGTH_MAX_MM: f64 = 500.0;

/// Most points accepted (measured profiles have a few thousand; the loop check is quadratic).
pub const MAX_POINTS: usize = 20_000;

impl Profile {
    /// A profile given as values (CONTACT's `cntc_setprofileinputvalues`, `profile_store_values`):
    /// points closer than 1e-4 dropped, MIRRORY, MIRRORZ (0: detected), the order checked and
    /// reversed where needed, SCALEYZ, then cleaned and fitted as a file is. No zig-zag filter,
    /// as in CONTACT.
    pub fn from_points(
        y_mm: &[f64],
        z_mm: &[f64],
        kind: ProfileKind,
        opts: &ProfileOptions,
    ) -> Result<Profile, ProfileError> {
        let file = "<values>";
        let opts = opts.checked()?;
        if y_mm.len() != z_mm.len() {
            return Err(ProfileError::profile(
                file,
                "the number of y and z values",
                format!("{} and {}", y_mm.len(), z_mm.len()),
                "as many z values as y values",
            ));
        }
        if let Some(k) = y_mm.iter().chain(z_mm).position(|v| !v.is_finite()) {
            let i = k % y_mm.len().max(1);
            return Err(ProfileError::profile(
                file,
                format!("point {}", i + 1),
                format!("({}, {})", y_mm[i], z_mm[i]),
                "finite coordinates",
            ));
        }
        let mut pts: Vec<Pt> = y_mm.iter().zip(z_mm).map(|(&y, &z)| Pt::new(y, z, 0)).collect();
        let mut cleaning = Cleaning { read: pts.len(), ..Default::default() };
        check_count(&pts, file)?;
        cleaning.too_close = clean::drop_close_points(&mut pts, clean::POINT_DIST_MIN);
        check_count(&pts, file)?;
        if opts.mirror_y >= 1 {
            canonical::mirror_y(&mut pts);
            cleaning.mirrored_y = true;
        }
        let mirror_z = match opts.mirror_z {
            0 => canonical::z_mirror_needed(&pts, kind),
            m => m == 1,
        };
        if mirror_z {
            canonical::mirror_z(&mut pts);
            cleaning.mirrored_z = true;
        }
        if canonical::inversion_needed(&pts, kind).0 {
            canonical::invert(&mut pts);
            cleaning.inverted = true;
        }
        canonical::check_overall_order(&pts, kind, file)?;
        canonical::scale(&mut pts, opts.scale);
        Profile::finish(file, kind, pts, &opts, cleaning)
    }

    /// The canonical, cleaned points made into a profile (CONTACT's `profile_finish_grid`): no
    /// loop, the order at the top of the rail or bottom of the wheel, the arc length, the total
    /// length in [5, 500] mm, the kinks and the spline.
    pub(crate) fn finish(
        file: &str,
        kind: ProfileKind,
        pts: Vec<Pt>,
        opts: &ProfileOptions,
        cleaning: Cleaning,
    ) -> Result<Profile, ProfileError> {
        check_count(&pts, file)?;
        check_finite(&pts, file)?;
        check_distinct(&pts, file)?;
        clean::check_no_loop(&pts, file)?;
        canonical::check_inversion(&pts, kind, file)?;
        let s_mm = arc_length(&pts);
        check_length(&s_mm, file)?;
        let kinks = clean::KinkSettings {
            high_rad: opts.kink_high_rad,
            low_rad: opts.kink_low_rad,
            width_mm: opts.kink_wid_mm,
        };
        let breaks = clean::find_kinks(&pts, &kinks);
        let (lambda, use_spacing) = opts.lambda();
        Ok(Profile::fitted(file, kind, &pts, s_mm, breaks, (lambda, use_spacing), cleaning, opts.max_omit))
    }

    /// A profile through points as they are, without cleaning or kinks: one spline section,
    /// smoothing with λ = `lambda` unweighted (CONTACT's `grid_make_arclength` and
    /// `grid_make_ppspline` on a slices file's interpolated cross-section, `varprof_intpol_xunif`).
    /// `None` with fewer than four points or points that coincide.
    pub(crate) fn section(file: &str, kind: ProfileKind, y_mm: &[f64], z_mm: &[f64], lambda: f64) -> Option<Profile> {
        let pts: Vec<Pt> = y_mm.iter().zip(z_mm).map(|(&y, &z)| Pt::new(y, z, 0)).collect();
        let finite = pts.iter().all(|p| p.y.is_finite() && p.z.is_finite());
        if pts.len() < 4 || !finite {
            return None;
        }
        let s_mm = arc_length(&pts);
        if s_mm.windows(2).any(|w| w[1] <= w[0]) {
            return None;
        }
        let breaks = vec![0, pts.len() - 1];
        let cleaning = Cleaning { read: pts.len(), ..Default::default() };
        Some(Profile::fitted(file, kind, &pts, s_mm, breaks, (lambda, false), cleaning, 0.5))
    }

    /// The spline through `pts` at arc lengths `s_mm`, section by section between `breaks`.
    #[allow(clippy::too_many_arguments)]
    fn fitted(
        file: &str,
        kind: ProfileKind,
        pts: &[Pt],
        s_mm: Vec<f64>,
        breaks: Vec<usize>,
        (lambda, use_spacing): (f64, bool),
        cleaning: Cleaning,
        max_omit: f64,
    ) -> Profile {
        let wgt = spline::weights(&s_mm, &breaks, use_spacing);
        let ys: Vec<f64> = pts.iter().map(|p| p.y).collect();
        let zs: Vec<f64> = pts.iter().map(|p| p.z).collect();
        let y = spline::fit(&s_mm, &ys, &breaks, lambda, &wgt);
        let z = spline::fit(&s_mm, &zs, &breaks, lambda, &wgt);
        let spline = ParamSpline { s: s_mm.clone(), y, z };
        let pieces: Vec<spline::Pieces> = (0..s_mm.len() - 1).map(|i| spline.monotone_pieces(i)).collect();
        let segment_y: Vec<(f64, f64)> = pieces.iter().map(spline::Pieces::y_bounds).collect();
        let y_range =
            segment_y.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(a, b)| (lo.min(a), hi.max(b)));
        let index = index::SegmentIndex::new(&segment_y);
        Profile(Arc::new(Data {
            file: file.to_string(),
            kind,
            y_mm: spline.y.a0.clone(),
            z_mm: spline.z.a0.clone(),
            s_mm,
            spline,
            breaks,
            cleaning,
            max_omit,
            segment_y,
            pieces,
            locus_nodes: OnceLock::new(),
            placements: Default::default(),
            index,
            y_range,
        }))
    }

    /// The file the profile was read from (`<values>` for [`Self::from_points`]).
    pub fn file(&self) -> &str {
        &self.0.file
    }

    pub fn kind(&self) -> ProfileKind {
        self.0.kind
    }

    /// The points' y after cleaning [mm] (smoothed where SMOOTH > 0, as CONTACT replaces them).
    pub fn y_mm(&self) -> &[f64] {
        &self.0.y_mm
    }

    /// The points' z after cleaning [mm], positive down.
    pub fn z_mm(&self) -> &[f64] {
        &self.0.z_mm
    }

    /// The arc length at each point [mm]: the summed chord length, 0 where the profile crosses
    /// y = 0 (or at the point nearest the origin where y is not monotone), as CONTACT's
    /// `grid_make_arclength`.
    pub fn s_mm(&self) -> &[f64] {
        &self.0.s_mm
    }

    /// The number of points after cleaning.
    pub fn len(&self) -> usize {
        self.0.s_mm.len()
    }

    /// Never true: a profile has at least two points.
    pub fn is_empty(&self) -> bool {
        self.0.s_mm.is_empty()
    }

    /// The spline's section ends (0-based point indices): the first point, each kink, the last.
    pub fn breaks(&self) -> &[usize] {
        &self.0.breaks
    }

    /// What reading and cleaning did.
    pub fn cleaning(&self) -> &Cleaning {
        &self.0.cleaning
    }

    /// The spline (coefficients per segment).
    pub fn spline(&self) -> &ParamSpline {
        &self.0.spline
    }

    /// The range of s [mm].
    pub fn s_range(&self) -> (f64, f64) {
        (self.0.s_mm[0], self.0.s_mm[self.len() - 1])
    }

    /// The range of y the spline covers [mm] (min, max; bulges between points included).
    pub fn y_range(&self) -> (f64, f64) {
        self.0.y_range
    }

    /// The point of the spline at arc length `s_mm`, `None` outside [`Self::s_range`]. At a kink
    /// the derivatives are those of the section that starts there.
    pub fn point_at_s(&self, s_mm: f64) -> Option<ProfilePoint> {
        let i = self.0.spline.segment(s_mm)?;
        Some(self.point_on(i, s_mm))
    }

    fn point_on(&self, i: usize, s_mm: f64) -> ProfilePoint {
        let ([y, y1, y2], [z, z1, z2]) = self.0.spline.eval_on(i, s_mm);
        let numer = y1 * z2 - z1 * y2;
        let speed2 = y1 * y1 + z1 * z1;
        let denom = speed2 * speed2.sqrt();
        let curvature_per_mm = if denom.abs() < 1e-6 { 1e6_f64.copysign(numer) } else { numer / denom };
        ProfilePoint { s_mm, y_mm: y, z_mm: z, dy_ds: y1, dz_ds: z1, curvature_per_mm }
    }

    /// The visible point at lateral position `y_mm`: where the spline has several points at that
    /// y (a flange that folds back, a vertical flank) the one seen from above a rail (smallest z)
    /// or from below a wheel (largest z), as CONTACT's top view; the only one where y is
    /// monotone, as its `spline_get_xz_at_y`. `None` outside [`Self::y_range`].
    pub fn point_at_y(&self, y_mm: f64) -> Option<ProfilePoint> {
        self.visible_at_y(y_mm).map(|(i, s, _, _)| self.point_on(i, s))
    }

    /// [`Self::point_at_y`]'s segment, s, (y, y′, y″) and (z, z′, z″), without the curvature.
    fn visible_at_y(&self, y_mm: f64) -> Option<(usize, f64, [f64; 3], [f64; 3])> {
        if !y_mm.is_finite() {
            return None;
        }
        let mut best: Option<(usize, f64, [f64; 3], [f64; 3])> = None;
        for &i in self.0.index.candidates(y_mm) {
            let (lo, hi) = self.0.segment_y[i];
            if y_mm < lo || y_mm > hi {
                continue;
            }
            self.0.spline.each_s_at_y_in(i, &self.0.pieces[i], y_mm, |s| {
                let (y, z) = self.0.spline.eval_on(i, s);
                let better = match (best, self.0.kind) {
                    (None, _) => true,
                    (Some(b), ProfileKind::Rail) => z[0] < b.3[0],
                    (Some(b), ProfileKind::Wheel) => z[0] > b.3[0],
                };
                if better {
                    best = Some((i, s, y, z));
                }
            });
        }
        best
    }

    /// The contact locus's nodes ([`crate::wheelrail::curve::Curve::locus_nodes`]): `make`'s at
    /// the first call, kept with the profile.
    pub fn kept_locus_nodes(
        &self,
        make: impl FnOnce() -> Option<Vec<super::locus::Node>>,
    ) -> Option<Vec<super::locus::Node>> {
        self.0.locus_nodes.get_or_init(make).clone()
    }

    /// The profile's placements as a rail kept with it ([`super::RailPlacements`]).
    pub fn kept_placements(&self) -> &super::RailPlacements {
        &self.0.placements
    }

    /// z [mm] and the slope dz/dy at `y_mm` ([`Self::point_at_y`]'s, without its curvature).
    pub fn z_and_slope_at(&self, y_mm: f64) -> Option<(f64, f64)> {
        self.visible_at_y(y_mm).map(|(_, _, [_, y1, _], [z, z1, _])| (z, slope_dz_dy(y1, z1)))
    }

    /// z [mm] at `y_mm` ([`Self::point_at_y`]).
    pub fn z_at(&self, y_mm: f64) -> Option<f64> {
        self.visible_at_y(y_mm).map(|(_, _, _, z)| z[0])
    }

    /// The slope dz/dy at `y_mm` ([`ProfilePoint::slope_dz_dy`]).
    pub fn slope_at(&self, y_mm: f64) -> Option<f64> {
        self.z_and_slope_at(y_mm).map(|(_, d)| d)
    }

    /// The signed curvature [1/mm] at `y_mm` ([`ProfilePoint::curvature_per_mm`]).
    pub fn curvature_at(&self, y_mm: f64) -> Option<f64> {
        self.point_at_y(y_mm).map(|p| p.curvature_per_mm)
    }
}

/// At least two points, at most [`MAX_POINTS`] (CONTACT's error 190 for too few).
fn check_count(pts: &[Pt], file: &str) -> Result<(), ProfileError> {
    if pts.len() < 2 {
        return Err(ProfileError::profile(
            file,
            "the number of points",
            pts.len(),
            "at least 2 points (CONTACT's error 190)",
        ));
    }
    if pts.len() > MAX_POINTS {
        return Err(ProfileError::profile(
            file,
            "the number of points",
            pts.len(),
            format!("at most {MAX_POINTS} points"),
        ));
    }
    Ok(())
}

/// Coordinates still finite after the offsets and the unit (1e300 mm times SCALEYZ 1000 is not).
fn check_finite(pts: &[Pt], file: &str) -> Result<(), ProfileError> {
    if let Some(k) = pts.iter().position(|p| !(p.y.is_finite() && p.z.is_finite())) {
        let p = pts[k];
        let line = if p.line > 0 { format!(" (line {})", p.line) } else { String::new() };
        return Err(ProfileError::profile(
            file,
            format!("point {}{line} after its shift and unit", k + 1),
            format!("({}, {})", p.y, p.z),
            "finite coordinates in mm",
        ));
    }
    Ok(())
}

/// No two successive points at the same place (CONTACT stops with an internal error: its spline
/// needs s strictly increasing).
fn check_distinct(pts: &[Pt], file: &str) -> Result<(), ProfileError> {
    if let Some(k) = pts.windows(2).position(|w| w[0].y == w[1].y && w[0].z == w[1].z) {
        let (a, b) = (pts[k], pts[k + 1]);
        let lines = if a.line > 0 { format!(" (lines {} and {})", a.line, b.line) } else { String::new() };
        return Err(ProfileError::profile(
            file,
            format!("points {} and {}{lines} after cleaning", k + 1, k + 2),
            format!("both ({}, {})", a.y, a.z),
            "distinct successive points (the spline's arc length must increase)",
        ));
    }
    Ok(())
}

/// The summed chord length, shifted to 0 at y = 0 (linear interpolation, the end values beyond)
/// where y is strictly monotone, else at the point nearest the origin (the last of equals), as
/// CONTACT's `grid_make_arclength`.
fn arc_length(pts: &[Pt]) -> Vec<f64> {
    let mut s = vec![0.0; pts.len()];
    for i in 1..pts.len() {
        let (dy, dz) = (pts[i].y - pts[i - 1].y, pts[i].z - pts[i - 1].z);
        s[i] = s[i - 1] + (dy * dy + dz * dz).sqrt();
    }
    let y: Vec<f64> = pts.iter().map(|p| p.y).collect();
    let s0 = if strictly_monotone(&y) { interpolate_at_zero(&y, &s) } else { s[nearest_origin(pts)] };
    s.iter_mut().for_each(|v| *v -= s0);
    s
}

fn strictly_monotone(y: &[f64]) -> bool {
    y.windows(2).all(|w| w[1] > w[0]) || y.windows(2).all(|w| w[1] < w[0])
}

/// f at x = 0 by linear interpolation in the monotone x (CONTACT's `interp_1d_to_scalar`).
fn interpolate_at_zero(x: &[f64], f: &[f64]) -> f64 {
    let n = x.len();
    let ascending = x[n - 1] > x[0];
    let before = |v: f64, at: f64| if ascending { v < at } else { v > at };
    if before(0.0, x[0]) {
        return f[0];
    }
    if before(x[n - 1], 0.0) || 0.0 == x[n - 1] {
        return f[n - 1];
    }
    let i = (0..n - 1).find(|&i| !before(0.0, x[i]) && before(0.0, x[i + 1])).unwrap_or(n - 2);
    let dx = if ascending { (x[i + 1] - x[i]).max(1e-9) } else { (x[i + 1] - x[i]).min(-1e-9) };
    let fac = (0.0 - x[i]) / dx;
    (1.0 - fac) * f[i] + fac * f[i + 1]
}

/// The index of the point nearest (0, 0), the last of equals.
fn nearest_origin(pts: &[Pt]) -> usize {
    let mut best = 0;
    let mut dmin = 1e12;
    for (k, p) in pts.iter().enumerate() {
        let d = p.y * p.y + p.z * p.z;
        if d <= dmin {
            best = k;
            dmin = d;
        }
    }
    best
}

/// The total length within CONTACT's bounds (errors 241, 242).
fn check_length(s: &[f64], file: &str) -> Result<(), ProfileError> {
    let total = s[s.len() - 1] - s[0];
    if !(LENGTH_MIN_MM..=LENGTH_MAX_MM).contains(&total) {
        let code = if total < LENGTH_MIN_MM { 241 } else { 242 };
        return Err(ProfileError::profile(
            file,
            "the total length of the profile (summed chord length, mm)",
            crate::error::number(total),
            format!(
                "{LENGTH_MIN_MM} to {LENGTH_MAX_MM} mm (CONTACT's error {code}: a unit conversion amiss? SCALEYZ, SIMPACK's units.len.f)"
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rail crown z = R − √(R² − y²), z down, every `step_mm` over |y| ≤ `half_width_mm`.
    fn circle(r_mm: f64, half_width_mm: f64, step_mm: f64) -> (Vec<f64>, Vec<f64>) {
        let n = (2.0 * half_width_mm / step_mm).round() as usize;
        let y: Vec<f64> = (0..=n).map(|i| -half_width_mm + i as f64 * step_mm).collect();
        let z = y.iter().map(|y| r_mm - (r_mm * r_mm - y * y).sqrt()).collect();
        (y, z)
    }

    /// Closed form: a circle of radius 100 mm sampled exactly every 0.5 mm has curvature 1/100
    /// within 1e-6 relative away from the free ends, and z within 1e-9 mm of the circle.
    #[test]
    fn a_circle_has_curvature_one_over_its_radius() {
        let (y, z) = circle(100.0, 60.0, 0.5);
        let p = Profile::from_points(&y, &z, ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        assert_eq!(p.len(), y.len());
        for k in -40..=40 {
            let yq = f64::from(k) + 0.123;
            let q = p.point_at_y(yq).unwrap();
            assert!((q.curvature_per_mm * 100.0 - 1.0).abs() < 1e-6, "y = {yq}: {}", q.curvature_per_mm);
            assert!((q.z_mm - (100.0 - (1e4 - yq * yq).sqrt())).abs() < 1e-9, "y = {yq}");
            let slope = yq / (1e4 - yq * yq).sqrt();
            assert!((q.slope_dz_dy() - slope).abs() < 1e-7, "y = {yq}: slope {}", q.slope_dz_dy());
        }
        // s is 0 at y = 0 and runs with the arc length.
        let q = p.point_at_s(0.0).unwrap();
        assert!(q.y_mm.abs() < 1e-12 && q.z_mm.abs() < 1e-12);
        let a = p.point_at_s(100.0 * 0.5).unwrap();
        assert!((a.y_mm - 100.0 * 0.5f64.sin()).abs() < 1e-4, "{a:?}");
        assert_eq!(p.point_at_s(p.s_range().1 + 1e-9), None);
    }

    /// Closed form: a straight inclined line stays one (slope 0.1, curvature 0) and its tangent is
    /// the line's direction.
    #[test]
    fn a_straight_line_has_its_slope_and_no_curvature() {
        let y: Vec<f64> = (0..=20).map(|i| -10.0 + i as f64).collect();
        let z: Vec<f64> = y.iter().map(|y| 0.1 * y + 2.0).collect();
        let opts = ProfileOptions { mirror_z: -1, ..Default::default() };
        let p = Profile::from_points(&y, &z, ProfileKind::Rail, &opts).unwrap();
        for yq in [-9.5, -3.25, 0.0, 7.75] {
            let q = p.point_at_y(yq).unwrap();
            assert!((q.z_mm - (0.1 * yq + 2.0)).abs() < 1e-12 && (q.slope_dz_dy() - 0.1).abs() < 1e-12);
            assert!(q.curvature_per_mm.abs() < 1e-12);
            let t = q.tangent();
            assert!((t[0] - 1.0 / 1.01f64.sqrt()).abs() < 1e-12 && (t[1] - 0.1 / 1.01f64.sqrt()).abs() < 1e-12);
        }
        assert_eq!(p.y_range(), (-10.0, 10.0));
        assert_eq!(p.z_at(10.5), None);
        // s = 0 where y = 0, at the line's 10th point.
        assert!((p.s_mm()[10]).abs() < 1e-12 && (p.s_mm()[20] - 10.0 * 1.01f64.sqrt()).abs() < 1e-12);
    }

    /// MIRRORY gives the mirror image (in the canonical order) and SCALEYZ multiplies every
    /// coordinate, the curvature divided by it.
    #[test]
    fn mirroring_and_scaling() {
        // An asymmetric crown.
        let y: Vec<f64> = (0..=40).map(|i| -15.0 + i as f64 * 0.75).collect();
        let z: Vec<f64> = y.iter().map(|y| y * y / 80.0 + y * y * y / 4000.0).collect();
        let p = Profile::from_points(&y, &z, ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        let opts = ProfileOptions { mirror_y: 1, ..Default::default() };
        let m = Profile::from_points(&y, &z, ProfileKind::Rail, &opts).unwrap();
        assert!(m.cleaning().mirrored_y && m.cleaning().inverted && !m.cleaning().mirrored_z);
        assert!(m.y_mm().windows(2).all(|w| w[1] > w[0]));
        for yq in [-10.0, -2.5, 4.0, 12.0] {
            assert!((m.z_at(-yq).unwrap() - p.z_at(yq).unwrap()).abs() < 1e-12, "y = {yq}");
            assert!((m.slope_at(-yq).unwrap() + p.slope_at(yq).unwrap()).abs() < 1e-10);
        }
        let opts = ProfileOptions { scale: 2.0, ..Default::default() };
        let s = Profile::from_points(&y, &z, ProfileKind::Rail, &opts).unwrap();
        for yq in [-10.0, 0.0, 7.0] {
            assert!((s.z_at(2.0 * yq).unwrap() - 2.0 * p.z_at(yq).unwrap()).abs() < 1e-12);
            assert!((2.0 * s.curvature_at(2.0 * yq).unwrap() - p.curvature_at(yq).unwrap()).abs() < 1e-12);
        }
        // MIRRORZ = 1 on a crown already z-down makes a trough: CONTACT's checks look only at the
        // order near the smallest z (now the last point), so it is accepted, as by CONTACT.
        let opts = ProfileOptions { mirror_z: 1, ..Default::default() };
        let t = Profile::from_points(&y, &z, ProfileKind::Rail, &opts).unwrap();
        assert!(t.cleaning().mirrored_z && (t.z_at(4.0).unwrap() + p.z_at(4.0).unwrap()).abs() < 1e-12);
    }

    #[test]
    fn values_that_cannot_make_a_profile_are_refused() {
        let opts = ProfileOptions::default();
        let e = Profile::from_points(&[0.0, 1.0], &[0.0], ProfileKind::Rail, &opts).unwrap_err();
        assert!(e.to_string().contains("as many z values"), "{e}");
        let e = Profile::from_points(&[0.0, 1.0, 2.0], &[0.0, f64::NAN, 0.0], ProfileKind::Rail, &opts).unwrap_err();
        assert!(e.to_string().contains("point 2"), "{e}");
        let e = Profile::from_points(&[0.0], &[0.0], ProfileKind::Rail, &opts).unwrap_err();
        assert!(e.to_string().contains("190"), "{e}");
        // Two points 1e-5 apart are one (CONTACT's minimum distance 1e-4): too few.
        let e = Profile::from_points(&[0.0, 1e-5], &[0.0, 0.0], ProfileKind::Rail, &opts).unwrap_err();
        assert!(e.to_string().contains("at least 2"), "{e}");
    }

    #[test]
    fn a_profile_is_cheap_to_clone_and_equal_to_its_clone() {
        let (y, z) = circle(300.0, 30.0, 1.0);
        let p = Profile::from_points(&y, &z, ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        let q = p.clone();
        assert!(Arc::ptr_eq(&p.0, &q.0));
        assert_eq!(p, q);
    }
}
