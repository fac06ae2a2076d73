//! Patch combination against CONTACT's rules and its printed numbers: the blending factor of two
//! sub-patches and the turning of two separate patches' angles.

use super::*;

const SEP: Separation =
    Separation { angle_rad: std::f64::consts::FRAC_PI_2, distance_mm: 8.0, combine_mm: 4.0, turn_mm: 12.0 };

/// A region spanning `y_mm` laterally (x from −1 to 1 mm, the rail flat at z = 0).
fn region(y_mm: [f64; 2], angle_rad: f64, weight: f64) -> Candidate {
    Candidate {
        x_mm: [-1.0, 1.0],
        y_mm,
        z_mm: [0.0, 0.0],
        wgt_x_mm: 0.0,
        wgt_y_mm: 0.5 * (y_mm[0] + y_mm[1]),
        wgt_angle_rad: angle_rad,
        total_weight: weight,
        pen_max_mm: 0.01,
        parts: Vec::new(),
    }
}

/// CONTACT (right case 11 of the Manchester benchmark, its debug output: the regions' y and z
/// ranges) prints the factor 0.391 for sub-patches 6.763 mm apart at D_SEP = 8, D_COMB = 4.
#[test]
fn the_blending_factor_is_contacts() {
    let mut tread = region([734.630, 738.693], 0.0, 1.0);
    let mut root = region([725.536, 728.005], 0.0, 1.0);
    (tread.z_mm, root.z_mm) = ([1.413, 0.865], [3.519, 2.769]);
    let parts = [tread, root].map(|c| c.extent());
    let f = sub_patch_factors(&parts, &SEP);
    assert_eq!((f[0], f[3]), (1.0, 1.0));
    assert_eq!(f[1], f[2]);
    assert!((f[1] - 0.391).abs() < 5e-4, "{f:?}");
    // Beyond D_SEP nothing couples.
    let far = [region([0.0, 1.0], 0.0, 1.0), region([9.5, 10.0], 0.0, 1.0)].map(|c| c.extent());
    assert_eq!(sub_patch_factors(&far, &SEP)[1], 0.0);
}

/// Two regions 6 mm apart are one patch with two sub-patches; 10 mm apart two patches whose
/// angles move half-way ((12 − 10) / (12 − 8)) to their weighted mean; 13 mm apart untouched.
#[test]
fn regions_are_blended_or_turned_by_their_distance() {
    let blended = combine(vec![region([0.0, 1.0], -0.1, 1.0), region([7.0, 8.0], -0.3, 3.0)], &SEP);
    assert_eq!(blended.len(), 1);
    assert_eq!(blended[0].parts.len(), 2);
    assert!((blended[0].wgt_angle_rad - (-0.3 * 3.0 - 0.1) / 4.0).abs() < 1e-15);
    let turned = combine(vec![region([0.0, 1.0], -0.1, 1.0), region([11.0, 12.0], -0.3, 3.0)], &SEP);
    let mean = (-0.1 - 0.9) / 4.0;
    assert_eq!(turned.len(), 2);
    // Sorted from the field side (y descending): the region at y = 11 first.
    assert!((turned[0].wgt_angle_rad - (-0.3 + 0.5 * (mean + 0.3))).abs() < 1e-15, "{turned:?}");
    assert!((turned[1].wgt_angle_rad - (-0.1 + 0.5 * (mean + 0.1))).abs() < 1e-15, "{turned:?}");
    let apart = combine(vec![region([0.0, 1.0], -0.1, 1.0), region([14.0, 15.0], -0.3, 3.0)], &SEP);
    assert_eq!((apart[0].wgt_angle_rad, apart[1].wgt_angle_rad), (-0.3, -0.1));
}

/// Past its profile's end the rail keeps the end's n in the patch's plane (CONTACT's
/// `spline_get_loc_xz_at_y` with `spline_eval`'s constant extrapolation, testbank case 29): a
/// flat rail on y ∈ [0, 10], the plane turned by δ = 0.3 rad about its point (5, 0).
#[test]
fn past_its_end_the_rail_keeps_the_ends_n() {
    let line = crate::wheelrail::curve::Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [0.0, 10.0] };
    let rail = PlacedRail { curve: &line, origin_mm: [0.0, 0.0], angle_rad: 0.0 };
    let frame = PatchFrame { origin: Point3::new(0.0, 5.0, 0.0), delta_rad: 0.3 };
    let (s, c) = 0.3f64.sin_cos();
    // The end y = 10 lies at plane s = 5 cos δ, n = −5 sin δ; the end y = 0 at −5 cos δ, 5 sin δ.
    let past_hi = rail_n_past_end(&frame, &rail, 5.0 * c + 0.7).unwrap();
    assert!((past_hi + 5.0 * s).abs() < 1e-12, "{past_hi}");
    let past_lo = rail_n_past_end(&frame, &rail, -5.0 * c - 2.0).unwrap();
    assert!((past_lo - 5.0 * s).abs() < 1e-12, "{past_lo}");
    assert_eq!(rail_n_past_end(&frame, &rail, 1.0), None);
}

/// A conformal patch's sub-patches on its curved rows (CONTACT's `compute_sc_for_yz`): each
/// sub-patch's lateral range runs between the rows whose reference points lie nearest its ends
/// (in y, z), widened by 0.4 D_COMB; where the reference bends away from the tangent plane this
/// differs from the planar rule's s = (y − y_ref) / cos δ.
#[test]
fn sub_patches_on_curved_rows_take_the_rows_nearest_their_ends() {
    use super::super::conformal_reference::CurvedReference;
    let frame = PatchFrame { origin: Point3::new(0.0, 0.0, 0.0), delta_rad: 0.0 };
    // Eleven rows 1 mm apart along a circle of radius 5 mm touching the plane at the reference:
    // row j at arc length j − 5, angle θ = (j − 5) / 5, point (y, z) = (5 sin θ, 5 (1 − cos θ)).
    let rows = 11;
    let at = |theta: f64| [5.0 * theta.sin(), 5.0 * (1.0 - theta.cos())];
    let point_mm: Vec<[f64; 2]> = (0..rows).map(|j| at((j as f64 - 5.0) / 5.0)).collect();
    let reference = CurvedReference { first_row: -5, point_mm, normal: vec![[0.0, 0.0, -1.0]; rows] };
    let grid = PatchGrid {
        mx: 3,
        ms: rows,
        dx_mm: 1.0,
        ds_mm: 1.0,
        x0_mm: -1.5,
        s0_mm: -5.5,
        anchor_mm: [0.0, 0.0],
        first_index: [-1, -5],
    };
    let sep = Separation { combine_mm: 0.5, ..SEP };
    // Sub-patch 1 between the points of rows 1 and 2 (arc length −4, −3), sub-patch 2 at row 9's
    // (arc length 4, y = 3.59 mm).
    let extent = |a: [f64; 2], b: [f64; 2]| Extent { x_mm: [-1.0, 1.0], y_mm: [a[0], b[0]], z_mm: [a[1], b[1]] };
    let parts = [extent(at(-0.8), at(-0.6)), extent(at(0.8), at(0.8))];
    let by_row = |part: &[u16]| (0..rows).map(|j| part[j * grid.mx + 1]).collect::<Vec<u16>>();
    let curved = curved_sub_patch_of_elements(&parts, &frame, &grid, &reference, &sep);
    // Widened by 0.2 mm: rows 1–2, and row 9 alone.
    assert_eq!(by_row(&curved), [0, 1, 1, 0, 0, 0, 0, 0, 0, 2, 0]);
    // The planar rule takes sub-patch 2 at s = y = 3.59 ± 0.2 mm: rows 8 and 9.
    let planar = sub_patch_of_elements(&parts, &frame, &grid, &sep);
    assert_eq!(by_row(&planar), [0, 1, 1, 0, 0, 0, 0, 0, 2, 2, 0]);
}
