//! `[contact]`: the contact's ellipse (semi-axes or radii), its load and Coulomb's μ; its keys
//! declared once ([`KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use crate::error::InputError;
use crate::physics::geometry::GeometrySpec;
use crate::physics::Radii;

/// A semi-axis [mm].
const SEMI_AXIS: Allowed = Allowed::Number(Range::new(0.0, false, 1e4, true), "");
/// A transverse radius [mm].
const RADIUS: Allowed = Allowed::Number(Range::new(0.0, false, f64::INFINITY, true), "");

/// `[contact]`'s keys (`<!-- keys:contact -->`).
pub const KEYS: Keys = Keys {
    id: "contact",
    owner: file!(),
    keys: &[
        key(
            "a_mm",
            "mm",
            SEMI_AXIS,
            Absent::Text("required with `b_mm`"),
            r#"semi-axis of the contact ellipse along the rolling direction x: `a_mm = 8.56`"#,
        ),
        key("b_mm", "mm", SEMI_AXIS, Absent::Text("required with `a_mm`"), r#"semi-axis along y: `b_mm = 4.08`"#),
        key(
            "r_wx_mm",
            "mm",
            Allowed::Number(Range::new(0.0, false, 1e9, true), ""),
            Absent::Text("–"),
            r#"the wheel's rolling radius (instead of `a_mm`, `b_mm`): `r_wx_mm = 460.0`"#,
        ),
        key(
            "r_wy_mm",
            "mm",
            RADIUS,
            Absent::Text("required with `r_wx_mm`"),
            r#"the wheel's transverse radius: `r_wy_mm = 300.0`"#,
        ),
        key(
            "r_ry_mm",
            "mm",
            RADIUS,
            Absent::Text("required with `r_wx_mm`"),
            r#"the rail's transverse radius (the rail straight along x): `r_ry_mm = 300.0`"#,
        ),
        key(
            "fn_n",
            "N",
            Allowed::Number(Range::new(0.0, false, 1e9, true), ""),
            Absent::Required,
            r#"the normal load (a creepage table may vary it per step, or prescribe the approach `pen_mm` in its place: then the nominal load that sizes the grid): `fn_n = 100000.0`"#,
        ),
        key(
            "pen_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, super::table::PEN_MAX_MM, true), ""),
            Absent::Text("–"),
            r#"the **approach prescribed** at every step or sweep point in place of the load (CONTACT's N = 0, PEN), as a table's `pen_mm` column (below): FN is an outcome, `fn_n` then only sizes the grid and sets the nominal ellipse; not with a table that has its own `fn_n` or `pen_mm` column; only the exact model takes it: `pen_mm = 0.05`"#,
        ),
        key(
            "mu",
            "–",
            Allowed::Number(super::MU_LIMIT, ""),
            Absent::Text("required with Coulomb's law"),
            r#"Coulomb's coefficient of friction (a table may vary it); with a falling `[friction]` law left out, or equal to its static value fkin + f1 + f2 (within 1e-12 relative); left out with `[friction] mu_rows`: `mu = 0.4`"#,
        ),
    ],
};

/// The contact: its geometry, load and friction (`[contact]`, or `[geometry]` per element).
pub struct ContactSpec {
    pub geometry: GeometrySpec,
    pub fn_n: f64,
    /// `contact.mu` as given (required with Coulomb's law, optional with a falling one).
    pub mu: Option<f64>,
    /// `contact.pen_mm`: the approach prescribed at every step or sweep point (CONTACT N = 0).
    pub pen_mm: Option<f64>,
}

/// `[contact]`: load and friction, and the ellipse (semi-axes or radii) unless `element_geometry`
/// (`[geometry]`, a contact given per element) gives the contact.
pub fn read(top: &mut Section, element_geometry: Option<GeometrySpec>) -> Result<ContactSpec, InputError> {
    let mut c = top.table("contact")?.declare(&KEYS);
    let geometry = match element_geometry {
        Some(spec) => {
            for k in ["a_mm", "b_mm", "r_wx_mm", "r_wy_mm", "r_ry_mm"] {
                c.refuse(k, "not with a [geometry] given per element (its contact follows from the normal problem)")?;
            }
            spec
        }
        None => ellipse(&mut c)?,
    };
    let fn_n = c.num("fn_n")?;
    let mu = c.opt_num("mu")?;
    let pen_mm = c.opt_num("pen_mm")?;
    c.finish()?;
    Ok(ContactSpec { geometry, fn_n, mu, pen_mm })
}

/// `[contact]` semi-axes `a_mm, b_mm`, or the radii `r_wx_mm, r_wy_mm, r_ry_mm` (not both).
fn ellipse(c: &mut Section) -> Result<GeometrySpec, InputError> {
    if c.has("a_mm") || c.has("b_mm") || !c.has("r_wx_mm") {
        let a_mm = c.num("a_mm")?;
        let b_mm = c.num("b_mm")?;
        for k in ["r_wx_mm", "r_wy_mm", "r_ry_mm"] {
            if c.has(k) {
                return Err(InputError::new(
                    c.field(k),
                    "given",
                    "either a_mm and b_mm, or the radii r_wx_mm, r_wy_mm, r_ry_mm, not both",
                ));
            }
        }
        return Ok(GeometrySpec::SemiAxes { a_mm, b_mm });
    }
    Ok(GeometrySpec::Radii(Radii {
        r_wx_mm: c.num("r_wx_mm")?,
        r_wy_mm: c.num("r_wy_mm")?,
        r_ry_mm: c.num("r_ry_mm")?,
    }))
}
