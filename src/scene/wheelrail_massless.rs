//! `[massless_rail]` of a wheel–rail scene: a rail that deflects laterally and vertically under the
//! contact forces on springs (CONTACT's F = 3, user guide "Massless rail model": δy = (F_y(tr) +
//! F*_y) / k*_y, δz = (F_z(tr) + F*_z) / k*_z), every key declared once ([`KEYS`]).

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use crate::error::InputError;

/// A spring stiffness [N/mm].
const STIFFNESS: Range = Range::new(0.0, true, 1e12, true);
/// A prescribed force on the rail [N].
const FORCE: Range = Range::new(-1e9, true, 1e9, true);

/// `[massless_rail]`'s keys (`<!-- keys:wheelrail_massless -->`).
pub const KEYS: Keys = Keys {
    id: "wheelrail_massless",
    owner: file!(),
    keys: &[
        key(
            "ky_n_per_mm",
            "N/mm",
            Allowed::Number(Range::new(0.0, false, 1e12, true), ""),
            Absent::Required,
            r#"the rail's effective lateral stiffness k*_y (CONTACT's KYRAIL): the rail's lateral deflection along the side's own y (as `[rail] deviation_y_mm`) is (F_y + `fy_n`) / k*_y, F_y the contact force on the rail as CONTACT prints it, FY(TR) in track coordinates on either wheel (`get_f_toty`): `ky_n_per_mm = 10000.0`"#,
        ),
        key(
            "fy_n",
            "N",
            Allowed::Number(FORCE, ""),
            Absent::Num(0.0),
            r#"a prescribed lateral force F*_y on the rail along the side's own y (FYRAIL; a damper c_y over a time step dt: c_y δy_prev/dt, with c_y/dt added to `ky_n_per_mm`): `fy_n = -68230.0`"#,
        ),
        key(
            "kz_n_per_mm",
            "N/mm",
            Allowed::Number(STIFFNESS, "above 0 with `vertical = \"position\"`"),
            Absent::Num(0.0),
            r#"the rail's effective vertical stiffness k*_z (KZRAIL): its vertical deflection (z downwards) is (F_z(tr) + `fz_n`) / k*_z; 0 keeps the rail at its height (with `vertical = "force"` only): `kz_n_per_mm = 10000.0`"#,
        ),
        key(
            "fz_n",
            "N",
            Allowed::Number(FORCE, ""),
            Absent::Num(0.0),
            r#"a prescribed vertical force F*_z on the rail (FZRAIL): `fz_n = -30000.0`"#,
        ),
        key(
            "dy_step_mm",
            "mm",
            Allowed::Number(Range::new(0.0, false, 1e3, true), ""),
            Absent::Num(1.0),
            r#"the expected size of the lateral deflection, the first step of its search (DYSTEP0): `dy_step_mm = 0.75`"#,
        ),
    ],
};

/// The rail's springs and the forces prescribed on it (CONTACT's KYRAIL, FYRAIL, KZRAIL, FZRAIL,
/// DYSTEP0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MasslessRailSpec {
    pub ky_n_per_mm: f64,
    pub fy_n: f64,
    pub kz_n_per_mm: f64,
    pub fz_n: f64,
    pub dy_step_mm: f64,
}

/// `[massless_rail]`, if the scene has one; `position_given` (`vertical = "position"`) needs a
/// vertical spring (the rail's height is then found from it).
pub fn read(top: &mut Section, position_given: bool) -> Result<Option<MasslessRailSpec>, InputError> {
    let Some(s) = top.opt_table("massless_rail")? else { return Ok(None) };
    let mut s = s.declare(&KEYS);
    let spec = MasslessRailSpec {
        ky_n_per_mm: s.num("ky_n_per_mm")?,
        fy_n: s.num_or_default("fy_n")?,
        kz_n_per_mm: s.num_or_default("kz_n_per_mm")?,
        fz_n: s.num_or_default("fz_n")?,
        dy_step_mm: s.num_or_default("dy_step_mm")?,
    };
    if position_given && spec.kz_n_per_mm == 0.0 {
        return Err(InputError::new(
            s.field("kz_n_per_mm"),
            0,
            "a vertical stiffness above 0 with [cases] vertical = \"position\" (the wheelset's height given, the rail's found from its spring; CONTACT's F = 3 with N = 0)",
        ));
    }
    s.finish()?;
    Ok(Some(spec))
}
