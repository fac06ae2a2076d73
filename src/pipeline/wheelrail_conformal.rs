//! The forces of a conformal patch (CONTACT's D = 4, `m_wr_solvecp` `aggregate_forces`): the
//! tractions the tangential solver found on the curved grid, each in its row's frame (along x,
//! along the row's tangent, along its inward normal), turned back to the tangent plane
//! (`gf3_curv2cart`) and summed: BAR_FX, BAR_FS, BAR_FN; the moment about the plane's normal
//! from each element's place on the curve (x_i, sp_j): MN. TILDE_FN is the pressure's sum
//! unturned.

use super::wheelrail::PatchForces;
use crate::wheelrail::conformal_grid::ConformalPatch;
use crate::wheelrail::patch::PatchGeometry;

/// A conformal patch's forces on the rail in its tangent plane (right-side frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConformalForces {
    /// BAR_FX, BAR_FS, BAR_FN [N].
    pub bar_n: [f64; 3],
    /// MN about the reference's normal [N mm].
    pub mn_nmm: f64,
    /// TILDE_FN: the pressure summed in the rows' own frames [N].
    pub tilde_fn_n: f64,
}

/// The forces of tractions `(px, py)` and pressure `pn` [MPa] on the rail (CONTACT's element
/// order and signs: px along x, py along each row's tangent) over conformal patch `g`.
pub fn aggregate(g: &PatchGeometry, c: &ConformalPatch, px: &[f64], py: &[f64], pn: &[f64]) -> ConformalForces {
    let grid = &g.grid;
    let (e_s, n) = (g.frame.e_s(), g.frame.n());
    let (mut bar, mut mn, mut tilde) = ([0.0; 3], 0.0, 0.0);
    for j in 0..grid.ms {
        let [cy, cz] = c.reference.normal_yz(j);
        // The row's outward normal in the plane's (s, n).
        let (c_s, c_n) = (cy * e_s.y + cz * e_s.z, cy * n.y + cz * n.z);
        let sp = c.sp_mm[j];
        for i in 0..grid.mx {
            let k = j * grid.mx + i;
            let fs = -c_n * py[k] - c_s * pn[k];
            bar[0] += px[k];
            bar[1] += fs;
            bar[2] += c_s * py[k] - c_n * pn[k];
            mn += grid.centre(i, j).0 * fs - sp * px[k];
            tilde += pn[k];
        }
    }
    let da = grid.dx_mm * grid.ds_mm;
    ConformalForces { bar_n: bar.map(|f| f * da), mn_nmm: mn * da, tilde_fn_n: tilde * da }
}

impl ConformalForces {
    /// The patch's forces in CONTACT's module-1 signs, the side's frame (`m` its sign).
    pub fn on_rail(&self, m: f64) -> PatchForces {
        let [fx_n, fs_n, fn_n] = self.bar_n;
        PatchForces {
            fn_n,
            fx_n,
            fs_n: m * fs_n,
            mn_nmm: m * self.mn_nmm,
            n_adhesion: None,
            n_slip: None,
            shift_tractions_mpa: None,
            slip: None,
            temp_max_c: None,
            blanco_un_mm: None,
        }
    }
}
