//! CONTACT's contact locus of a wheel made of profile points (user guide, "Identification of
//! contact patches"; `m_wr_locatecp`: `compute_wr_locus`, `locus_prismatic`): the locus point is
//! computed at each point of the wheel profile's uni-valued part, taken to the track, and an
//! interpolating spline x(s), y(s), z(s) in the profile's arc length is fitted through them, in
//! sections between the locus's kinks in its top view (y, x) (`profile_find_kinks` with 18°, x
//! scaled by 0.1); the gap mesh reads x and z at y from that spline (`spline_get_xz_at_y`).
//!
//! With yaw the locus's x is −ρ z′ tan ψ: on a flange it moves by millimetres between profile
//! points, and the spline through the points, broken at the kinks, is not the exact locus (on the
//! Manchester benchmark's coarse profiles at y = 6.2 mm, yaw 14.9 mrad, the flange contact's
//! reference 0.16 mm higher on the exact locus). Closed-form curves keep the exact locus.

use super::curve::Curve;
use super::profile::canonical::Pt;
use super::profile::clean::{find_kinks, KinkSettings};
use super::profile::spline::{fit, Cubic};
use nalgebra::{Point3, Rotation3, Vector3};

/// CONTACT's kink thresholds for the locus (`compute_wr_locus`: π/10 high and low, 0.01 mm).
const KINKS: KinkSettings =
    KinkSettings { high_rad: std::f64::consts::PI / 10.0, low_rad: std::f64::consts::PI / 10.0, width_mm: 0.01 };
/// The factor on x in the locus's kink detection (CONTACT's `scale_z` for the locus).
const X_SCALE: f64 = 0.1;

/// A wheel profile point as the locus needs it: arc length s, y, z and the slope dz/dy
/// (CONTACT's `dz_ds / min(−1e-6, dy_ds)`) [mm].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Node {
    pub s_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    pub dz_dy: f64,
}

/// The locus spline in track coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct LocusSpline {
    s: Vec<f64>,
    x: Cubic,
    y: Cubic,
    z: Cubic,
}

/// The track point of profile position y_w at (x, depth) in the wheelset frame.
pub type ToTrack<'a> = &'a dyn Fn(Vector3<f64>) -> Point3<f64>;

impl LocusSpline {
    /// The locus of the profile's nodes for a wheel turned by `rotation` (wheelset → track) with its
    /// profile origin `y_offset_mm` from the centre (`locus_prismatic`: x clamped to ±R/2).
    pub fn build(
        curve: &dyn Curve,
        rotation: &Rotation3<f64>,
        y_offset_mm: f64,
        radius_mm: f64,
        to_track: ToTrack,
    ) -> Option<LocusSpline> {
        let nodes = curve.locus_nodes()?;
        if nodes.len() < 2 {
            return None;
        }
        let r = rotation.matrix();
        let (r11, r12, r13) = (r[(0, 0)], r[(0, 1)], r[(0, 2)]);
        let mut pts = Vec::with_capacity(nodes.len());
        for n in &nodes {
            let rho = radius_mm + n.z_mm;
            let x = ((rho * n.dz_dy * r12 - radius_mm * r13) / r11).clamp(-0.5 * radius_mm, 0.5 * radius_mm);
            // CONTACT's z = −999 where the circle has no point at x (a radius below R/2).
            let depth = if rho * rho > x * x { (rho * rho - x * x).sqrt() } else { radius_mm - 999.0 };
            pts.push(to_track(Vector3::new(x, y_offset_mm + n.y_mm, depth)));
        }
        let s: Vec<f64> = nodes.iter().map(|n| n.s_mm).collect();
        Some(LocusSpline::through(s, &pts))
    }

    /// The interpolating spline x(s), y(s), z(s) through track points `pts` at parameters `s`, in
    /// sections between the kinks of their top view (y, 0.1 x) (`compute_wr_locus`:
    /// `profile_find_kinks`, `grid_make_ppspline`).
    pub fn through(s: Vec<f64>, pts: &[Point3<f64>]) -> LocusSpline {
        let top: Vec<Pt> = pts.iter().map(|p| Pt { y: p.y, z: X_SCALE * p.x, line: 0 }).collect();
        let breaks = find_kinks(&top, &KINKS);
        let ones = vec![1.0; s.len()];
        let column = |f: &dyn Fn(&Point3<f64>) -> f64| -> Vec<f64> { pts.iter().map(f).collect() };
        LocusSpline {
            x: fit(&s, &column(&|p| p.x), &breaks, 0.0, &ones),
            y: fit(&s, &column(&|p| p.y), &breaks, 0.0, &ones),
            z: fit(&s, &column(&|p| p.z), &breaks, 0.0, &ones),
            s,
        }
    }

    /// The locus point at track y: the segment whose nodes hold y (bisection on the nodes' y, as
    /// CONTACT's `locate_segment`), y(s) = y solved on it, x and z there; `None` beyond the
    /// first or last node (CONTACT's value −888: no contact).
    pub fn at_y(&self, y_mm: f64) -> Option<Point3<f64>> {
        let ys = &self.y.a0;
        let n = ys.len();
        let ascending = ys[n - 1] >= ys[0];
        let below = |v: f64| if ascending { v <= y_mm } else { v >= y_mm };
        if !below(ys[0]) || below(ys[n - 1]) && ys[n - 1] != y_mm {
            return None;
        }
        // The last node at or before y in the nodes' order.
        let (mut lo, mut hi) = (0, n - 1);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if below(ys[mid]) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let i = lo.min(n - 2);
        let h = self.s[i + 1] - self.s[i];
        let t = root_on(&self.y, i, h, y_mm)?;
        Some(Point3::new(self.x.eval(i, t)[0], y_mm, self.z.eval(i, t)[0]))
    }
}

/// The local t in [0, h] where f(t) = v on segment i (Newton's steps kept in the bracket of the
/// nodes' values, bisection where a step leaves it).
fn root_on(c: &Cubic, i: usize, h: f64, v: f64) -> Option<f64> {
    let g = |t: f64| {
        let [f, df, _] = c.eval(i, t);
        (f - v, df)
    };
    let (g0, gh) = (g(0.0).0, g(h).0);
    if g0 == 0.0 {
        return Some(0.0);
    }
    if gh == 0.0 {
        return Some(h);
    }
    if g0.signum() == gh.signum() {
        return None;
    }
    let (mut neg, mut pos) = if g0 < 0.0 { (0.0, h) } else { (h, 0.0) };
    let mut t = -g0 * h / (gh - g0);
    for _ in 0..100 {
        let (gt, dg) = g(t);
        if gt == 0.0 {
            break;
        }
        if gt < 0.0 {
            neg = t;
        } else {
            pos = t;
        }
        let step = if dg != 0.0 { t - gt / dg } else { f64::NAN };
        let (lo, hi) = if neg < pos { (neg, pos) } else { (pos, neg) };
        let next = if step > lo && step < hi { step } else { 0.5 * (neg + pos) };
        if (next - t).abs() <= 4.0 * f64::EPSILON * h.max(1.0) {
            t = next;
            break;
        }
        t = next;
    }
    Some(t)
}

#[cfg(test)]
mod tests {
    use super::super::rail::PlacedRail;
    use super::super::search;
    use super::super::test_fixtures as fixtures;
    use super::super::wheel::{PlacedWheel, Pose};

    /// CONTACT's gap function (its `dump_gap1d.m`, debug level L = 5 of module 1) for the right
    /// wheel of `perfc_test/mbench_20kn_coarseprf` case 126 (y = 6.2 mm, yaw 14.9 mrad, on the
    /// coarse profiles): x of the locus, y, the wheel's and the rail's z [mm] at the mesh points
    /// of the flange contact (printed to 6 decimals).
    const CONTACT_GAP: [[f64; 4]; 6] = [
        [8.822104, 717.930107, 11.906594, 11.906530],
        [8.953887, 718.080107, 11.493133, 11.429848],
        [8.270197, 718.230107, 11.082432, 11.008072],
        [7.521292, 718.380107, 10.671951, 10.626582],
        [5.968612, 718.530107, 10.303896, 10.276653],
        [4.542551, 718.680107, 9.960019, 9.952473],
    ];

    #[test]
    fn the_gap_mesh_on_a_yawed_flange_is_contacts() {
        let (wheel, rail) = fixtures::profiles("MBench_S1002_coars.prw", "MBench_UIC60_coars.prr");
        let rail = PlacedRail::place(&rail, &fixtures::track()).unwrap();
        let g = fixtures::wheelset();
        let pose = Pose { y_mm: 6.2, z_mm: -0.2617, roll_rad: -0.00071622, yaw_rad: 0.0149 };
        let mut wheel = PlacedWheel::place(&wheel, &g, &pose);
        let samples = search::scan(&wheel, &search::RailMesh::new(&rail, 0.5));
        for [x, y, zw, zr] in CONTACT_GAP {
            let s = samples.iter().find(|s| (s.y_mm - y).abs() < 1e-6).expect("mesh point");
            for (ours, theirs) in [(s.x_mm, x), (s.z_mm, zw), (s.z_rail_mm, zr)] {
                assert!((ours - theirs).abs() <= 5e-7 + 1e-9, "y {y}: ours {ours}, CONTACT {theirs}");
            }
        }
        // The exact locus between the profile's points is not CONTACT's.
        wheel.locus_spline = None;
        let exact = wheel.locus_at_track_y(718.230107).unwrap();
        assert!((exact.z - 11.082432).abs() > 1e-3, "{exact:?}");
    }
}
