//! `[init]` (optional): the state before step 1; its key declared once ([`KEYS`]) for the
//! reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::Section;
use super::{Creepage, InitKind, Motion};
use crate::error::InputError;

/// `[init]`'s keys (`<!-- keys:init -->`).
pub const KEYS: Keys = Keys {
    id: "init",
    owner: file!(),
    keys: &[key(
        "kind",
        "–",
        Allowed::Choice(&["zero", "steady", "shift"], ""),
        Absent::Choice("zero"),
        r#"`zero`: no tangential traction before step 1; `steady`: the steady rolling state at the loading of t = 0: `kind = "steady"`; `shift`: a shift from rest at the loading of t = 0 (CONTACT's T = 1 with P = 2; its `cx`, `cy` the shift in mm and `cs` the rotation in rad, or the forces prescribed), whose traction the rolling steps then continue (CONTACT's T = 2 with P = 0, `examples/catt_to_cart.inp`); the history's row with step 0 is that shift. Only before a rolling time history (`rolling.motion = "rolling"`, not a sweep: refused naming `init.kind`), only the exact model (`contact`), Coulomb friction: `kind = "shift"`"#,
    )],
};

/// `[init]` (optional): the initial tangential state (default zero). A shift start (`"shift"`)
/// needs a rolling time history: it is the shift before the rolling.
pub fn read(top: &mut Section, motion: Motion, creepage: &Creepage) -> Result<InitKind, InputError> {
    let mut init = InitKind::Zero;
    if let Some(mut i) = top.opt_table("init")?.map(|i| i.declare(&KEYS)) {
        init = match i.opt_pick("kind")? {
            Some("steady") => InitKind::Steady,
            Some("shift") => InitKind::Shift,
            _ => InitKind::Zero,
        };
        let sweep = matches!(creepage, Creepage::Sweep { .. });
        if init == InitKind::Shift && (motion == Motion::Shift || sweep) {
            let got = if sweep { "with creepage.kind = \"sweep\"" } else { "with rolling.motion = \"shift\"" };
            return Err(InputError::new(
                i.field("kind"),
                format!("\"shift\" {got}"),
                "a shift start before a rolling time history (rolling.motion = \"rolling\", creepage.kind step, sine or table); shifts alone start from rest (kind = \"zero\")",
            ));
        }
        i.finish()?;
    }
    Ok(init)
}
