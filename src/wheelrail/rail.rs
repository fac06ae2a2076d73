//! The rail in the track (user guide, "Track and roller geometry"; CONTACT's m_wr_profiles): the
//! profile turned by its installation angle (−CANT for the right rail, whose track centre lies at
//! −y), then placed by the gauge point (GAUGHT > 0: the top on the track plane z = 0, the inner face
//! at depth GAUGHT at y = GAUGWD/2) or absolutely (its origin at RAILY0, RAILZ0), then displaced by
//! the rail's deviations. Everything here is the right side; the left is its mirror ([`super::side`]).

use super::curve::Curve;
use super::WheelRailError;

/// How the rail profile's origin is placed in the track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RailPlacement {
    /// The gauge-point computation (GAUGHT > 0, GAUGWD).
    Gauge { height_mm: f64, width_mm: f64 },
    /// The origin at (y, z) in track coordinates (GAUGHT ≤ 0: RAILY0, RAILZ0).
    Absolute { y_mm: f64, z_mm: f64 },
}

/// The track as one side sees it: placement, cant and the rail's deviation from its design place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Track {
    pub placement: RailPlacement,
    /// CANT: rotation from track vertical to rail vertical, positive towards the track centre.
    pub cant_rad: f64,
    /// DYRAIL, DZRAIL [mm], DROLLR [rad]: the rail's offsets from its design position.
    pub deviation_mm_rad: [f64; 3],
    /// VYRAIL, VZRAIL [mm/s], VROLLR [rad/s]: their rates (the creepages, [`super::creepage`]).
    pub deviation_velocity: [f64; 3],
}

/// Sampling step of the placement's scans [mm] (top and gauge face).
const SCAN_MM: f64 = 0.01;

/// The rail profile placed in the track: a profile point (y_r, z_r) lies at
/// `origin + R(angle) (y_r, z_r)` in track coordinates (y, z), R the rotation about x.
#[derive(Debug)]
pub struct PlacedRail<'a> {
    pub curve: &'a dyn Curve,
    /// The profile's origin in track coordinates (y, z) [mm].
    pub origin_mm: [f64; 2],
    /// The profile's rotation about x [rad] (−CANT + DROLLR on the right side).
    pub angle_rad: f64,
}

impl<'a> PlacedRail<'a> {
    /// The rail placed as `track` says.
    pub fn place(curve: &'a dyn Curve, track: &Track) -> Result<PlacedRail<'a>, WheelRailError> {
        let angle_rad = -track.cant_rad;
        let design = PlacedRail { curve, origin_mm: [0.0, 0.0], angle_rad };
        let origin = match track.placement {
            RailPlacement::Absolute { y_mm, z_mm } => [y_mm, z_mm],
            RailPlacement::Gauge { height_mm, width_mm } => {
                let (params, points) = design.sampled();
                let top = design.top_z_mm(&params, &points);
                let face = gauge_face_y(&points, top, height_mm)?;
                let face = design.refine_face_y(&params, &points, face, top + height_mm);
                [0.5 * width_mm - face, -top]
            }
        };
        let [dy, dz, droll] = track.deviation_mm_rad;
        Ok(PlacedRail { curve, origin_mm: [origin[0] + dy, origin[1] + dz], angle_rad: angle_rad + droll })
    }

    /// A profile point in track coordinates.
    fn to_track(&self, y_r: f64, z_r: f64) -> [f64; 2] {
        let (s, c) = self.angle_rad.sin_cos();
        [self.origin_mm[0] + c * y_r - s * z_r, self.origin_mm[1] + s * y_r + c * z_r]
    }

    /// The profile sampled every [`SCAN_MM`]: each sample's profile y and its point in track
    /// coordinates.
    fn sampled(&self) -> (Vec<f64>, Vec<[f64; 2]>) {
        let [lo, hi] = self.curve.y_range_mm();
        let n = ((hi - lo) / SCAN_MM).ceil().max(1.0) as usize;
        (0..=n)
            .filter_map(|k| {
                let y = (lo + (hi - lo) * k as f64 / n as f64).min(hi);
                self.curve.z_mm(y).map(|z| (y, self.to_track(y, z)))
            })
            .unzip()
    }

    /// The track point of the profile at profile y `y_r` (on the profile's range).
    fn track_at(&self, y_r: f64) -> Option<[f64; 2]> {
        self.curve.z_mm(y_r).map(|z| self.to_track(y_r, z))
    }

    /// The rail's top: the smallest track z of the curve (CONTACT's `spline_get_xyz_at_minz`),
    /// the lowest sample refined by golden-section search between its neighbours.
    fn top_z_mm(&self, params: &[f64], points: &[[f64; 2]]) -> f64 {
        let Some(k) = (0..points.len()).min_by(|&a, &b| points[a][1].total_cmp(&points[b][1])) else {
            return f64::INFINITY;
        };
        let (mut a, mut b) = (params[k.saturating_sub(1)], params[(k + 1).min(params.len() - 1)]);
        let z = |y: f64| self.track_at(y).map_or(f64::INFINITY, |p| p[1]);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if z(c) < z(d) {
                b = d;
            } else {
                a = c;
            }
        }
        z(0.5 * (a + b)).min(points[k][1])
    }

    /// The gauge face's track y at depth `z_mm` on the curve itself (CONTACT interpolates its
    /// spline, `spline_get_xy_at_z`): where `face` (the samples' linear estimate) lies between two
    /// consecutive samples that cross `z_mm`, bisection on the profile between them; else `face`.
    fn refine_face_y(&self, params: &[f64], points: &[[f64; 2]], face: f64, z_mm: f64) -> f64 {
        let crosses = |k: usize| {
            let (p, q) = (points[k], points[k + 1]);
            (p[1] - z_mm) * (q[1] - z_mm) <= 0.0 && (p[0].min(q[0])..=p[0].max(q[0])).contains(&face)
        };
        let Some(k) = (0..points.len().saturating_sub(1)).find(|&k| crosses(k)) else {
            return face;
        };
        let above = |y: f64| self.track_at(y).map_or(0.0, |p| p[1] - z_mm);
        let (mut a, mut b) = (params[k], params[k + 1]);
        let sa = above(a).signum();
        for _ in 0..80 {
            let m = 0.5 * (a + b);
            if above(m).signum() == sa {
                a = m;
            } else {
                b = m;
            }
        }
        self.track_at(0.5 * (a + b)).map_or(face, |p| p[0])
    }

    /// The track y range of the gap mesh: the lowest and highest track y of the profile's points
    /// (CONTACT's `grid_get_yrange` on the rail in track coordinates, so the mesh starts at a
    /// point, not at an extremum of the spline between points), or of the curve for a closed form.
    pub fn mesh_y_range_mm(&self) -> [f64; 2] {
        match self.curve.points_mm() {
            Some(points) if !points.is_empty() => points
                .iter()
                .map(|&[y, z]| self.to_track(y, z)[0])
                .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], y| [lo.min(y), hi.max(y)]),
            _ => self.y_range_mm(),
        }
    }

    /// The profile's y_r whose point lies at track y (Newton on `y(y_r) = y`), if on the profile.
    fn profile_y(&self, y_mm: f64) -> Option<f64> {
        let (s, c) = self.angle_rad.sin_cos();
        let mut y_r = (y_mm - self.origin_mm[0]) / c;
        for _ in 0..50 {
            let [lo, hi] = self.curve.y_range_mm();
            let y_r_in = y_r.clamp(lo, hi);
            let (z, dz) = self.curve.z_and_slope(y_r_in)?;
            let f = self.origin_mm[0] + c * y_r_in - s * z - y_mm;
            let step = f / (c - s * dz);
            y_r = y_r_in - step;
            if step.abs() < 1e-12 {
                return (lo..=hi).contains(&y_r).then_some(y_r);
            }
        }
        None
    }

    /// The rail profile's spline parameter s [mm] (CONTACT's `sr`) at track y, where the rail is
    /// a profile file.
    pub fn s_mm(&self, y_mm: f64) -> Option<f64> {
        let y_r = if self.angle_rad == 0.0 { y_mm - self.origin_mm[0] } else { self.profile_y(y_mm)? };
        self.curve.s_at_y(y_r)
    }

    /// The rail's point at its profile's spline parameter s (CONTACT's `sr`) in track coordinates
    /// (y, z) [mm], with its outward unit normal (n_y, n_z) there (the profile's (dz/ds, −dy/ds)
    /// turned into the track: CONTACT's `spline_get_nvec_at_s`), where the rail is a profile file.
    pub fn point_at_s(&self, s_mm: f64) -> Option<([f64; 2], [f64; 2])> {
        let p = self.curve.spline_point(s_mm)?;
        let [ty, tz] = p.tangent();
        let (s, c) = self.angle_rad.sin_cos();
        Some((self.to_track(p.y_mm, p.z_mm), [c * tz + s * ty, s * tz - c * ty]))
    }

    /// Height z [mm] of the rail surface at track y [mm].
    pub fn z_mm(&self, y_mm: f64) -> Option<f64> {
        if self.angle_rad == 0.0 {
            return Some(self.origin_mm[1] + self.curve.z_mm(y_mm - self.origin_mm[0])?);
        }
        let y_r = self.profile_y(y_mm)?;
        Some(self.to_track(y_r, self.curve.z_mm(y_r)?)[1])
    }

    /// Slope dz/dy of the rail surface at track y.
    pub fn dz_dy(&self, y_mm: f64) -> Option<f64> {
        let y_r = if self.angle_rad == 0.0 { y_mm - self.origin_mm[0] } else { self.profile_y(y_mm)? };
        let d = self.curve.dz_dy(y_r)?;
        let (s, c) = self.angle_rad.sin_cos();
        Some((s + c * d) / (c - s * d))
    }

    /// Height z and slope dz/dy of the rail surface at track y ([`Self::z_mm`], [`Self::dz_dy`]).
    pub fn z_and_slope(&self, y_mm: f64) -> Option<(f64, f64)> {
        let (s, c) = self.angle_rad.sin_cos();
        let slope = |d: f64| (s + c * d) / (c - s * d);
        if self.angle_rad == 0.0 {
            let (z, d) = self.curve.z_and_slope(y_mm - self.origin_mm[0])?;
            return Some((self.origin_mm[1] + z, slope(d)));
        }
        let y_r = self.profile_y(y_mm)?;
        let (z, d) = self.curve.z_and_slope(y_r)?;
        Some((self.to_track(y_r, z)[1], slope(d)))
    }

    /// The profile's two ends in track coordinates (y, z), each with a point 0.01 mm inside it
    /// (which side of the end the profile lies on).
    pub fn ends_mm(&self) -> Option<[([f64; 2], [f64; 2]); 2]> {
        let [lo, hi] = self.curve.y_range_mm();
        let inside = SCAN_MM.min(0.5 * (hi - lo));
        Some([(self.track_at(lo)?, self.track_at(lo + inside)?), (self.track_at(hi)?, self.track_at(hi - inside)?)])
    }

    /// Track y of the profile's lateral range ends (the rotated range's first and last points).
    pub fn y_range_mm(&self) -> [f64; 2] {
        let [lo, hi] = self.curve.y_range_mm();
        let a = self.curve.z_mm(lo).map(|z| self.to_track(lo, z)[0]).unwrap_or(f64::NAN);
        let b = self.curve.z_mm(hi).map(|z| self.to_track(hi, z)[0]).unwrap_or(f64::NAN);
        [a.min(b), a.max(b)]
    }

    /// The point of the rail at track y where the line `(y, z) + t (ny, nz)` meets it: the
    /// distance t [mm] along the unit direction, found by Newton from t = 0, or, where the line
    /// starts beside the profile's lateral range or Newton leaves it, from the line's point over
    /// the range's nearer end with each iterate held inside the range.
    pub fn along(&self, [y, z]: [f64; 2], [ny, nz]: [f64; 2]) -> Option<f64> {
        self.newton_along([y, z], [ny, nz], 0.0, None).or_else(|| {
            let [lo, hi] = self.y_range_mm();
            let ranged = lo < hi && ny.abs() >= 1e-12;
            if !ranged {
                return None;
            }
            let inside = [lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo)];
            let t0 = (y.clamp(inside[0], inside[1]) - y) / ny;
            self.newton_along([y, z], [ny, nz], t0, Some(inside))
        })
    }

    /// Newton's iteration of [`Self::along`] from `t0`; with `held`, each iterate's y kept in it.
    fn newton_along(&self, [y, z]: [f64; 2], [ny, nz]: [f64; 2], t0: f64, held: Option<[f64; 2]>) -> Option<f64> {
        let mut t = t0;
        for _ in 0..50 {
            if let Some([lo, hi]) = held {
                t = ((y + t * ny).clamp(lo, hi) - y) / ny;
            }
            let yt = y + t * ny;
            let (z_rail, dz_dy) = self.z_and_slope(yt)?;
            let g = z + t * nz - z_rail;
            let dg = nz - dz_dy * ny;
            let step = g / dg;
            t -= step;
            if step.abs() < 1e-12 {
                return Some(t);
            }
        }
        None
    }
}

/// The smallest y where the profile, scanned from its gauge-side (−y) end, first rises to the gauge
/// point's depth `height_mm` below its top `top_mm` (z downwards).
fn gauge_face_y(points: &[[f64; 2]], top_mm: f64, height_mm: f64) -> Result<f64, WheelRailError> {
    let z_mm = top_mm + height_mm;
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| a[0].total_cmp(&b[0]));
    match sorted.iter().position(|p| p[1] <= z_mm) {
        None => Err(WheelRailError::NoGaugeFace { height_mm }),
        Some(0) => {
            let [y_mm, z] = sorted[0];
            Err(WheelRailError::GaugeSideTooShallow { height_mm, y_mm, depth_mm: z - top_mm })
        }
        Some(k) => {
            let ([y0, z0], [y1, z1]) = (sorted[k - 1], sorted[k]);
            Ok(y0 + (y1 - y0) * (z_mm - z0) / (z1 - z0))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wheelrail::curve::Arc;

    fn crown() -> Arc {
        Arc { radius_mm: 300.0, centre_y_mm: 0.0, half_width_mm: 40.0, concave: false }
    }

    #[test]
    fn the_gauge_point_puts_the_top_on_the_plane_and_the_face_at_half_the_gauge() {
        let c = crown();
        let track = Track {
            placement: RailPlacement::Gauge { height_mm: 1.0, width_mm: 1435.0 },
            cant_rad: 0.0,
            deviation_mm_rad: [0.0; 3],
            deviation_velocity: [0.0; 3],
        };
        let r = PlacedRail::place(&c, &track).unwrap();
        // z = 300 − √(300² − u²) = 1 at u = −√(599): the face at y = 717.5.
        let u = (300.0f64 * 300.0 - 299.0 * 299.0).sqrt();
        // Found on the curve itself, not between its samples 0.01 mm apart (CONTACT's spline).
        assert!((r.origin_mm[0] - (717.5 + u)).abs() < 1e-9, "{:?}", r.origin_mm);
        assert!(r.origin_mm[1].abs() < 1e-12);
        assert!((r.z_mm(717.5).unwrap() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn a_gauge_side_shallower_than_the_gauge_point_is_named_with_its_depth() {
        // The crown's ends lie 300 − √(300² − 40²) = 2.6807 mm below its top: no face at 14 mm.
        let track = Track {
            placement: RailPlacement::Gauge { height_mm: 14.0, width_mm: 1435.0 },
            cant_rad: 0.0,
            deviation_mm_rad: [0.0; 3],
            deviation_velocity: [0.0; 3],
        };
        let e = PlacedRail::place(&crown(), &track).unwrap_err();
        let WheelRailError::GaugeSideTooShallow { height_mm, y_mm, depth_mm } = e else { panic!("{e:?}") };
        assert_eq!(height_mm, 14.0);
        assert!((y_mm + 40.0).abs() < 1e-9, "{y_mm}");
        assert!((depth_mm - (300.0 - (300.0f64 * 300.0 - 1600.0).sqrt())).abs() < 1e-9, "{depth_mm}");
        assert!(e.to_string().contains("mirror_y"), "{e}");
    }

    #[test]
    fn a_canted_rail_turns_its_slope() {
        let c = crown();
        let cant = 1.0f64 / 40.0;
        let track = Track {
            placement: RailPlacement::Absolute { y_mm: 0.0, z_mm: 0.0 },
            cant_rad: cant.atan(),
            deviation_mm_rad: [0.0; 3],
            deviation_velocity: [0.0; 3],
        };
        let r = PlacedRail::place(&c, &track).unwrap();
        // The crown's top (slope 0 on the profile) turns to slope tan(−cant) at its new place.
        let y_top = -(0.0f64 - 0.0) * 0.0; // the origin stays at the crown's top
        assert!((r.dz_dy(y_top).unwrap() - (-cant)).abs() < 1e-12);
        let t = r.along([5.0, -1.0], [0.0, 1.0]).unwrap();
        assert!((t - (r.z_mm(5.0).unwrap() + 1.0)).abs() < 1e-10);
    }

    #[test]
    fn a_line_starting_beside_the_profile_meets_it_inside() {
        // The crown spans y in [-40, 40]; a line from beside it (y = -45) running in at
        // 18 deg downwards meets it near y = -35 (testbank case 35's flange rows: their normals
        // start beside the gauge face).
        let track = Track {
            placement: RailPlacement::Absolute { y_mm: 0.0, z_mm: 0.0 },
            cant_rad: 0.0,
            deviation_mm_rad: [0.0; 3],
            deviation_velocity: [0.0; 3],
        };
        let c = crown();
        let r = PlacedRail::place(&c, &track).unwrap();
        let (y, z) = (-45.0, -1.0);
        let n = [18f64.to_radians().cos(), 18f64.to_radians().sin()];
        assert!(r.z_mm(y).is_none(), "the start lies beside the profile");
        let t = r.along([y, z], n).expect("the line meets the crown");
        let (yt, zt) = (y + t * n[0], z + t * n[1]);
        assert!((-40.0..=40.0).contains(&yt), "{yt}");
        assert!((zt - r.z_mm(yt).unwrap()).abs() < 1e-9, "{zt} against {:?}", r.z_mm(yt));
        // A line that runs away from the profile meets nothing.
        assert!(r.along([y, z], [-1.0, 0.0]).is_none());
    }
}
