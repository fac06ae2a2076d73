//! A wheel–rail scene's tangential problem beyond one Coulomb μ: friction of the surface
//! temperature (`[friction] law = "temperature"`, CONTACT's L = 6 in module 1), the surface
//! temperatures (`[material]`'s heat keys, H = 3) and the exact solver's options
//! (`[contact_solver]`), read with module 3's readers and keys (friction.rs, material.rs,
//! contact_solver.rs); each patch's exact solve takes them as its module-3 problem does.

use super::reader::Section;
use super::wheelrail::{MotionSpec, MuVariation};
use super::ContactSolverOptions;
use crate::error::InputError;
use crate::physics::{FrictionLaw, TemperatureLaw};

/// The scene's `[friction]` and `[contact_solver]`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Tangential {
    /// CONTACT's L = 6 (`[friction] law = "temperature"`), or Coulomb's `mu` (`None`).
    pub temperature_law: Option<TemperatureLaw>,
    /// The exact solver's options (`[contact_solver]`, its defaults when absent).
    pub contact_solver: ContactSolverOptions,
}

/// What the checks of [`read`] need from the rest of the scene.
pub struct Context<'a> {
    pub mu: f64,
    pub mu_variation: Option<&'a MuVariation>,
    pub heat: bool,
    pub solvers: &'a [String],
    pub motion: MotionSpec,
    pub frictionless: bool,
}

/// `[friction]` (Coulomb's law, the default, or the temperature law: one for every patch, or its
/// parameters per control point of `[wheelrail] mu_by`; without a memory, with the surface
/// temperatures) and `[contact_solver]`; the surface temperatures and the temperature law are the
/// exact theory's in steady rolling only (CONTACT's `calc_temp`, T = 3).
pub fn read(top: &mut Section, c: &Context) -> Result<Tangential, InputError> {
    let per_point = c.mu_variation.is_some_and(|v| v.temperature.is_some());
    let temperature_law = if per_point { law_alone(top).map(|()| None)? } else { one_law(top, c)? };
    let temperature = per_point || temperature_law.is_some();
    if temperature && !c.heat {
        return Err(InputError::new(
            "friction.law",
            "\"temperature\"",
            "with the surface temperatures ([material] bulk1_c … density2_kg_per_mm3)",
        ));
    }
    if c.heat || temperature {
        if c.solvers.iter().any(|m| m != "contact") {
            return Err(InputError::new(
                "solvers",
                format!("{:?}", c.solvers),
                "[\"contact\"] with the surface temperatures or [friction] law = \"temperature\" (the exact theory computes them)",
            ));
        }
        if c.motion != MotionSpec::Rolling || c.frictionless {
            return Err(InputError::new(
                "wheelrail.motion",
                format!("{:?}, frictionless = {}", c.motion, c.frictionless),
                "steady rolling with friction (motion = \"rolling\") with the surface temperatures (CONTACT computes them at T = 3 only)",
            ));
        }
    }
    let contact_solver = super::contact_solver::read(top)?;
    Ok(Tangential { temperature_law, contact_solver })
}

/// With the temperature law's parameters per control point (`[wheelrail] tref_c_values`, …):
/// `[friction]` gives `law = "temperature"` alone.
fn law_alone(top: &mut Section) -> Result<(), InputError> {
    let per_point = "[wheelrail] tref_c_values, dfheat_values and dtheat_c_values given (the law's parameters per control point, mu_values its FREF)";
    let field = top.field("friction.law");
    let Some(mut f) = top.opt_table("friction")?.map(|f| f.declare(&super::friction::KEYS)) else {
        return Err(InputError::new(field, "missing", format!("\"temperature\" with {per_point}")));
    };
    let law = f.pick("law")?;
    if law != "temperature" {
        return Err(InputError::new(f.field("law"), format!("{law:?}"), format!("\"temperature\" with {per_point}")));
    }
    for key in ["fref", "tref_c", "dfheat", "dtheat_c", "memory_mm", "memory_s0_mm_s"] {
        f.refuse(key, &format!("left out with {per_point}"))?;
    }
    f.finish()
}

/// `[friction]` with one law for every patch: Coulomb's (`None`) or the temperature's.
fn one_law(top: &mut Section, c: &Context) -> Result<Option<TemperatureLaw>, InputError> {
    // The law's μ check names module 3's `contact.mu`; here it is `[wheelrail] mu`.
    let spec = super::friction::read(top, Some(c.mu), 1).map_err(|e| match e.field.as_str() {
        "contact.mu" => InputError { field: "wheelrail.mu".into(), ..e },
        _ => e,
    })?;
    if spec.rows.is_some() {
        return Err(InputError::new(
            "friction.mu_rows",
            "given",
            "left out in a wheel–rail scene (each patch takes [wheelrail] mu or mu_by)",
        ));
    }
    if spec.memory.memory_mm != 0.0 {
        return Err(InputError::new(
            "friction.memory_mm",
            spec.memory.memory_mm,
            "left out in a wheel–rail scene (no friction memory)",
        ));
    }
    let temperature_law = match spec.law {
        FrictionLaw::Coulomb { .. } => None,
        FrictionLaw::Temperature(t) => Some(t),
        _ => {
            return Err(InputError::new(
                "friction.law",
                format!("{:?}", spec.law),
                "\"coulomb\" or \"temperature\" in a wheel–rail scene (the falling laws are module 3's)",
            ))
        }
    };
    if temperature_law.is_some() && c.mu_variation.is_some() {
        return Err(InputError::new(
            "wheelrail.mu_by",
            "given",
            "left out with one temperature law ([friction] fref, tref_c, dfheat, dtheat_c), or the law per control point: [wheelrail] mu_values (FREF), tref_c_values, dfheat_values, dtheat_c_values with [friction] law = \"temperature\" alone",
        ));
    }
    Ok(temperature_law)
}
