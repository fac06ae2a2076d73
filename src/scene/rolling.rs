//! `[rolling]` (optional): the rolling speed, the time step (Courant number), what moves the
//! bodies and the rolling direction; its keys declared once ([`KEYS`]) for the reader and
//! docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::Motion;
use crate::error::InputError;

/// `[rolling]`'s keys (`<!-- keys:rolling -->`).
pub const KEYS: Keys = Keys {
    id: "rolling",
    owner: file!(),
    keys: &[
        key(
            "v_mm_s",
            "mm/s",
            Allowed::Number(super::SPEED_LIMIT, "with a finite time step courant·dx/V"),
            Absent::Num(1000.0),
            r#"the rolling speed V: `v_mm_s = 1000.0`"#,
        ),
        key(
            "courant",
            "–",
            Allowed::Number(Range::new(0.0, false, 100.0, true), "at most 64 when the scene runs `uba`"),
            Absent::Num(1.0),
            r#"the rolling distance per step in elements: dq = courant·dx, dt = dq/V. The UBA's explicit step is stable up to 1; a larger courant number is split into ceil(courant) sub-steps: `courant = 0.5`"#,
        ),
        key(
            "chi_deg",
            "deg",
            Allowed::Number(Range::new(0.0, true, 360.0, false), ""),
            Absent::Num(0.0),
            r#"the rolling direction (CONTACT's CHI; the contact moves along (cos CHI, sin CHI) in CONTACT's coordinates, x along CONTACT's x): 0 rolls as every other scene, 180 the other way along x, the mirror image about x = 0 of the same scene with `cx` and `cs` of opposite sign (Fx and Mz change sign, Fy stays). Other angles in transient rolling only (no sweep, no steady `[init]`: CONTACT's steady solver rolls along ±x): the previous tractions are shifted by dq along CHI and the spin term is taken dq/6 along it, as CONTACT does; the creepages stay those of the x and y axes (a problem turned by CHI with its creepage vector turned by CHI gives the forces turned by CHI). Only the exact model (`contact`) takes a CHI other than 0, with Coulomb friction and `motion = "rolling"`: `chi_deg = 30.0`"#,
        ),
        key(
            "motion",
            "–",
            Allowed::Choice(&["rolling", "shift"], ""),
            Absent::Choice("rolling"),
            r#"what moves the bodies from step to step. `"shift"`: shifts without rolling (CONTACT's T = 1, Cattaneo's problem; Kalker 1990 §5.2.1): the traction of the last step stays in place, the slip of a step is its rigid shift plus the change of the elastic displacement; `c`, `cy` (and the table's `cx`, `cy`) are then the rigid shifts of the step in mm (CONTACT's CKSI, CETA) and `cs` the rotation of the step in rad (CPHI, about the origin), or the forces are prescribed with `fx_over_fn`, `fy_over_fn` as for rolling. Only the exact model (`contact`) solves shifts; a transient loading from rest only (no `sweep`, no steady `[init]`); `v_mm_s` and `courant` then only set the time axis: `motion = "shift"`"#,
        ),
    ],
};

/// `[rolling]` (optional): the speed [mm/s] (default 1000), the Courant number (default 1), the
/// motion (default rolling; `"shift"`: CONTACT's T = 1) and the rolling direction CHI [deg]
/// (default 0, in [0, 360); steady rolling at 0 or 180 only, CONTACT `m_sdis.f90`).
pub fn read(top: &mut Section) -> Result<(f64, f64, Motion, f64), InputError> {
    let empty = toml::Table::new();
    let mut r = match top.opt_table("rolling")? {
        Some(r) => r.declare(&KEYS),
        None => Section::new("rolling", &empty).declare(&KEYS),
    };
    let chi_deg = r.num_or_default("chi_deg")?;
    let v_mm_s = r.num_or_default("v_mm_s")?;
    let courant = r.num_or_default("courant")?;
    let motion = if r.pick_or_default("motion")? == "shift" { Motion::Shift } else { Motion::Rolling };
    r.finish()?;
    Ok((v_mm_s, courant, motion, chi_deg))
}
