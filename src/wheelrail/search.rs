//! The contact search (user guide, "Identification of contact patches"; CONTACT's
//! m_wr_locatecp, `compute_wr_locus` and `locate_interpen_1d`): the gap function on a uniform
//! lateral mesh over the rail (step 0.3 DS), the wheel's contact locus above each mesh point and
//! the rail below it, and the interpenetration regions where the wheel reaches below the rail.

use super::rail::PlacedRail;
use super::wheel::PlacedWheel;

/// The gap mesh's step over DS (CONTACT's `fac_dyds`).
pub const MESH_STEP_OVER_DS: f64 = 0.3;

/// One mesh point: the locus point and the rail below it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocusSample {
    /// The locus point in track coordinates [mm].
    pub x_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    /// The rail surface's height there [mm].
    pub z_rail_mm: f64,
    /// The wheel's reach below the rail surface [mm] (positive: interpenetration; minus the gap).
    pub pen_mm: f64,
    /// The rail's inclination atan(dz/dy) there [rad].
    pub rail_angle_rad: f64,
}

/// The rail under the gap mesh `y_k = y_min + k dy` over the rail points' lateral range
/// ([`PlacedRail::mesh_y_range_mm`]): its height and inclination at each mesh point where it has
/// one. It depends on the track alone: made once per case, read at every trial height.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RailMesh {
    /// (track y, rail z [mm], rail inclination [rad]) per mesh point, ascending in y.
    points: Vec<(f64, f64, f64)>,
}

impl RailMesh {
    /// The mesh of step [`MESH_STEP_OVER_DS`] × `ds_mm` under `rail`.
    pub fn new(rail: &PlacedRail, ds_mm: f64) -> RailMesh {
        let [lo, hi] = rail.mesh_y_range_mm();
        let dy = MESH_STEP_OVER_DS * ds_mm;
        let n = ((hi - lo) / dy).ceil() as usize + 1;
        let points = (0..n)
            .filter_map(|k| {
                let y = lo + dy * k as f64;
                Some((y, rail.z_mm(y)?, rail.dz_dy(y)?.atan()))
            })
            .collect();
        RailMesh { points }
    }
}

/// The gap function on the rail's mesh ([`RailMesh`]), where the wheel's locus covers it.
pub fn scan(wheel: &PlacedWheel, rail: &RailMesh) -> Vec<LocusSample> {
    rail.points
        .iter()
        .filter_map(|&(y, z_rail_mm, rail_angle_rad)| {
            let p = wheel.locus_at_track_y(y)?;
            Some(LocusSample { x_mm: p.x, y_mm: y, z_mm: p.z, z_rail_mm, pen_mm: p.z - z_rail_mm, rail_angle_rad })
        })
        .collect()
}

/// The gap function on a rail whose profile varies along the track (CONTACT's `compute_wr_locus`
/// on a variable profile): the mesh's y and the rail's inclination from the rail at the wheelset
/// ([`RailMesh`] of the cross-section at S_WS: `prr_rgn`, `make_surfc_inclination`), the wheel's
/// locus and the rail's height from the loci iterated on the surface ([`super::varrail::loci`]).
pub fn scan_varying(loci: &super::varrail::Loci, rail: &RailMesh) -> Vec<LocusSample> {
    rail.points
        .iter()
        .filter_map(|&(y, _, rail_angle_rad)| {
            let p = loci.wheel.at_y(y)?;
            let z_rail_mm = loci.rail.at_y(y)?.z;
            Some(LocusSample { x_mm: p.x, y_mm: y, z_mm: p.z, z_rail_mm, pen_mm: p.z - z_rail_mm, rail_angle_rad })
        })
        .collect()
}

/// The deepest reach of the wheel below the rail [mm] (negative: the smallest gap).
pub fn deepest_mm(samples: &[LocusSample]) -> Option<f64> {
    samples.iter().map(|s| s.pen_mm).reduce(f64::max)
}

/// The interpenetration regions: each maximal run of mesh points with pen ≥ 0, with one guard
/// point on each side where the mesh has it (CONTACT's bounding box with `nguard = 1`); a point
/// whose pen is not a number interpenetrates nowhere.
pub fn regions(samples: &[LocusSample]) -> Vec<&[LocusSample]> {
    let mut out = Vec::new();
    let mut k = 0;
    while k < samples.len() {
        if samples[k].pen_mm.is_nan() || samples[k].pen_mm < 0.0 {
            k += 1;
            continue;
        }
        let start = k;
        while k < samples.len() && samples[k].pen_mm >= 0.0 {
            k += 1;
        }
        out.push(&samples[start.saturating_sub(1)..(k + 1).min(samples.len())]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(y_mm: f64, pen_mm: f64) -> LocusSample {
        LocusSample { x_mm: 0.0, y_mm, z_mm: 0.0, z_rail_mm: 0.0, pen_mm, rail_angle_rad: 0.0 }
    }

    #[test]
    fn a_point_whose_pen_is_not_a_number_interpenetrates_nowhere() {
        // A NaN height once made every pen NaN and this scan push the same region forever.
        let samples = [at(0.0, -1.0), at(1.0, f64::NAN), at(2.0, 0.5), at(3.0, f64::NAN), at(4.0, -1.0)];
        let found = regions(&samples);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].iter().map(|s| s.y_mm).collect::<Vec<_>>(), [1.0, 2.0, 3.0]);
        assert!(regions(&[at(0.0, f64::NAN); 3]).is_empty());
    }
}
