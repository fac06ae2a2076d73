//! `[normal]` (optional): the exact solver's normal problem, solved or Hertz's pressure imposed
//! (CONTACT's B = 0, 2, 3); its keys declared once ([`KEYS`]) for the reader and
//! docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::Section;
use super::{InitKind, NormalOptions};
use crate::error::InputError;
use crate::physics::geometry::GeometrySpec;
use crate::physics::NormalPressure;

/// A row's pressure.
const PRESSURES: &[&str] = &["solved", "elliptical", "parabolic"];

/// `[normal]`'s keys (`<!-- keys:normal -->`).
pub const KEYS: Keys = Keys {
    id: "normal",
    owner: file!(),
    keys: &[
        key(
            "pressure",
            "–",
            Allowed::Choice(PRESSURES, ""),
            Absent::Choice("solved"),
            r#"every row's pressure: the normal problem solved (B = 0), Hertz's 3FN/(2πab)·√(1 − x²/a² − y²/b²) (B = 2) or 2FN/(πab)·(1 − x²/a² − y²/b²) (B = 3): `pressure = "elliptical"`"#,
        ),
        key(
            "start_pressure",
            "–",
            Allowed::Choice(PRESSURES, "as `pressure`"),
            Absent::Text("`pressure`"),
            r#"the start row's (step 0 of `[init] kind = "steady"` or `"shift"`; refused without one), where the case that starts a CONTACT history has another B than its steps (`testbank.inp` 13-16: a shift with B = 2, then rolling with B = 0): `start_pressure = "elliptical"`"#,
        ),
    ],
};

/// `[normal]` (optional): the exact solver's pressure, solved or Hertz's imposed (CONTACT's B = 0,
/// 2, 3), and the start row's. An imposed pressure needs Hertz's ellipse (CONTACT: IPOTCN < 0); a
/// start pressure needs a start (`[init] kind = "steady"` or `"shift"`).
pub fn read(top: &mut Section, geometry: &GeometrySpec, init: InitKind) -> Result<NormalOptions, InputError> {
    let mut normal = NormalOptions::default();
    let Some(mut n) = top.opt_table("normal")?.map(|n| n.declare(&KEYS)) else {
        return Ok(normal);
    };
    let of = |name: &str| match name {
        "elliptical" => NormalPressure::Elliptical,
        "parabolic" => NormalPressure::Parabolic,
        _ => NormalPressure::Solved,
    };
    if let Some(p) = n.opt_pick("pressure")? {
        normal.pressure = of(p);
    }
    normal.start_pressure = normal.pressure;
    if let Some(p) = n.opt_pick("start_pressure")? {
        if init == InitKind::Zero {
            return Err(InputError::new(
                n.field("start_pressure"),
                format!("{p:?} without a start row"),
                "a start pressure only with [init] kind = \"steady\" or \"shift\" (the row of step 0)",
            ));
        }
        normal.start_pressure = of(p);
    }
    let hertz = matches!(geometry, GeometrySpec::SemiAxes { .. } | GeometrySpec::Radii(_));
    if !hertz && normal != NormalOptions::default() {
        let key = if normal.pressure != NormalPressure::Solved { "pressure" } else { "start_pressure" };
        return Err(InputError::new(
            n.field(key),
            "an imposed pressure with a [geometry] table",
            "\"solved\" with a [geometry] table: the elliptical and parabolic pressures are Hertz's ellipse (contact.a_mm, b_mm or the radii; CONTACT's IPOTCN < 0)",
        ));
    }
    n.finish()?;
    Ok(normal)
}
