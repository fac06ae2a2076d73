//! `<solver>_stress.csv`: the subsurface field ([`crate::physics::halfspace::stress`]) under a
//! model's traction field at the steps and points of the scene's `[stress]`, one row per step and
//! point (docs/scene-format.md). Points are computed in parallel and written in order: the bytes
//! do not depend on the thread count.

use crate::physics::halfspace::invariants::invariants;
use crate::physics::halfspace::stress::{elastic_field, LoadedRectangle};
use crate::physics::halfspace::ContactError;
use crate::physics::{Grid, Material};
use crate::scene::stress::StressPoints;
use crate::solvers::FieldView;
use rayon::prelude::*;

/// The columns of `<solver>_stress.csv`, in order (stresses tension positive, z into body 1).
pub const STRESS_COLUMNS: [&str; 20] = [
    "step",
    "block",
    "x_mm",
    "y_mm",
    "z_mm",
    "ux_mm",
    "uy_mm",
    "uz_mm",
    "sigxx_mpa",
    "sigyy_mpa",
    "sigzz_mpa",
    "sigxy_mpa",
    "sigyz_mpa",
    "sigxz_mpa",
    "sighyd_mpa",
    "sigvm_mpa",
    "sigma1_mpa",
    "sigma2_mpa",
    "sigma3_mpa",
    "sigtr_mpa",
];

/// The loaded rectangles of a field in CONTACT's coordinates (those of `[grid] x_mm` and of its
/// `.subs` files): element centre x_C = −x of the grid ([`crate::physics::grid`]), and CONTACT's
/// traction on body 1, (px, py) = −(tx, ty) (the solvers' tractions are CONTACT's with the sign
/// flipped: reference/README.md, `contact/`).
pub fn rectangles(grid: &Grid, pn_mpa: &[f64], tx_mpa: &[f64], ty_mpa: &[f64]) -> Vec<LoadedRectangle> {
    let (hx, hy) = (0.5 * grid.dx_mm, 0.5 * grid.dy_mm);
    (0..grid.len())
        .filter(|&k| pn_mpa[k] != 0.0 || tx_mpa[k] != 0.0 || ty_mpa[k] != 0.0)
        .map(|k| {
            let (x, y) = (-grid.x_mm[k % grid.mx], grid.y_mm[k / grid.mx]);
            LoadedRectangle {
                x_mm: [x - hx, x + hx],
                y_mm: [y - hy, y + hy],
                traction_mpa: [-tx_mpa[k], -ty_mpa[k], pn_mpa[k]],
            }
        })
        .collect()
}

/// Body 1's shear modulus and Poisson's ratio (the half-space z ≥ 0; CONTACT's GG(1), POISS(1)).
pub fn body_1(m: &Material) -> (f64, f64) {
    m.bodies.map_or((m.g_mpa, m.poisson), |b| (b.g_mpa[0], b.poisson[0]))
}

/// The CSV rows of one step: every point of every block of `at` (blocks numbered from 1), x fastest.
pub fn rows(step: usize, view: &FieldView, material: &Material, at: &StressPoints) -> Result<String, ContactError> {
    let rects = rectangles(view.grid, view.pressure_mpa, view.tx_mpa, view.ty_mpa);
    let (g, nu) = body_1(material);
    let points: Vec<(usize, [f64; 3])> = at
        .blocks
        .iter()
        .enumerate()
        .flat_map(|(b, block)| block.points().into_iter().map(move |p| (b + 1, p)))
        .collect();
    let lines: Vec<String> = points
        .par_iter()
        .map(|&(block, p)| {
            let f = elastic_field(&rects, g, nu, p)?;
            let s = f.sigma_mpa;
            let inv = invariants(&s);
            let [s1, s2, s3] = inv.principal_mpa;
            let values = [
                p[0],
                p[1],
                p[2],
                f.u_mm[0],
                f.u_mm[1],
                f.u_mm[2],
                s[0][0],
                s[1][1],
                s[2][2],
                s[0][1],
                s[1][2],
                s[0][2],
                inv.hydrostatic_mpa,
                inv.von_mises_mpa,
                s1,
                s2,
                s3,
                inv.tresca_mpa,
            ];
            let mut line = format!("{step},{block}");
            for v in values {
                line.push(',');
                line.push_str(&v.to_string());
            }
            line.push('\n');
            Ok(line)
        })
        .collect::<Result<_, ContactError>>()?;
    Ok(lines.concat())
}

/// The header line of `<solver>_stress.csv`.
pub fn header() -> String {
    format!("{}\n", STRESS_COLUMNS.join(","))
}
