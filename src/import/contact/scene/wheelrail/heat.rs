//! A module-1 case's surface temperatures (H = 1, 3: BKTEMP, HEATCP, LAMBDA, DENS of both
//! bodies) and friction of the surface temperature (L = 6: FREF, TREF, DFHEAT, DTHEAT) as a
//! wheel–rail scene's `[material]` heat keys, `[friction]` and `[contact_solver]`, and those
//! sections written back (module 3's keys: scene/material.rs, friction.rs, contact_solver.rs).

use super::super::super::wheelrail_deck::{FrictionValues, FrictionVariation, WheelRailCase};
use crate::physics::temperature::Thermal;
use crate::physics::TemperatureLaw;
use crate::scene::wheelrail::WheelRailScene;
use crate::scene::wheelrail_tangential::Tangential;
use crate::scene::{ContactSolverOptions, VeldepSolves, OMGSLP};
use toml::Value;

/// CONTACT's fixed stop of the temperature iteration, rms(T_k − T_(k−1)) ≤ 1e-4 rms(T_k)
/// (`m_stang.f90`, its L = 6 branch), as module 3's import writes it.
const CONTACT_TEMPDEP_TOLERANCE: f64 = 1e-4;

/// Both bodies' thermal constants where the case computes the surface temperatures (H = 1, 3
/// after H = 3 gave them).
pub(super) fn thermal(c: &WheelRailCase) -> Option<[Thermal; 2]> {
    let h = c.state.heat.as_ref().filter(|_| matches!(c.digits.h, 1 | 3))?;
    Some(h.bodies.map(|[bulk_c, heat_capacity_j_per_kg_c, conductivity_w_per_mm_c, density_kg_per_mm3]| Thermal {
        bulk_c,
        heat_capacity_j_per_kg_c,
        conductivity_w_per_mm_c,
        density_kg_per_mm3,
    }))
}

/// The case's friction of the temperature (L = 6: its one law with V = 0) and, with it, CONTACT's
/// iteration as module 3's import carries it: stopped at 1e-4 or after max(1, MAXIN − 10) + 1
/// iterations, each tangential solve tight, damped by OMGSLP (the last G = 2, 3, 4 read; else its default).
pub(super) fn tangential(c: &WheelRailCase) -> Tangential {
    let Some(f) = c.state.friction.as_ref().filter(|f| f.law == 6) else { return Tangential::default() };
    let Some(FrictionValues::Temperature { fref, tref_c, dfheat, dtheat_c }) = f.sets.first().map(|s| s.values) else {
        return Tangential::default();
    };
    // Sets across the rail or along the track go to [wheelrail]'s control points (`mu_of`).
    let one_law = f.variation == FrictionVariation::Uniform;
    let solver = c.state.solver.as_ref();
    let maxin = solver.map_or(CONTACT_MAXIN, |s| s.maxin);
    // The parameters the last G = 2, 3 (OMEGAH, OMEGAS, INISLP, OMGSLP) or 4 (INISLP, OMGSLP) read.
    let omgslp = solver
        .and_then(|s| match s.extra.len() {
            4 => s.extra.get(3).copied(),
            2 => s.extra.get(1).copied(),
            _ => None,
        })
        .unwrap_or(OMGSLP);
    let contact_solver = ContactSolverOptions {
        tempdep_tolerance: CONTACT_TEMPDEP_TOLERANCE,
        tempdep_max_iterations: (maxin - 10).max(1) as usize + 1,
        veldep_solves: VeldepSolves::Tight,
        omgslp,
        ..ContactSolverOptions::default()
    };
    let law = one_law.then_some(TemperatureLaw { fref, tref_c, dfheat, dtheat_c });
    Tangential { temperature_law: law, contact_solver }
}

/// CONTACT's MAXIN before any is read (`m_hierarch_data.f90`).
const CONTACT_MAXIN: i64 = 20;

/// A section's keys and values in the order they are written.
type Pairs = Vec<(&'static str, Value)>;

/// `[material]`'s eight heat keys, where the scene has them.
pub(super) fn material_pairs(s: &WheelRailScene) -> Pairs {
    let Some(bodies) = s.material.heat else { return Vec::new() };
    let values = bodies
        .iter()
        .flat_map(|t| [t.bulk_c, t.heat_capacity_j_per_kg_c, t.conductivity_w_per_mm_c, t.density_kg_per_mm3]);
    let keys = crate::scene::material::HEAT_KEYS.keys.iter().map(|k| k.key);
    keys.zip(values).map(|(k, v)| (k, Value::Float(v))).collect()
}

/// `[friction]` of the temperature law, where the scene has it.
pub(super) fn friction_pairs(s: &WheelRailScene) -> Option<Pairs> {
    if s.mu_variation.as_ref().is_some_and(|v| v.temperature.is_some()) {
        // Its parameters per control point are [wheelrail]'s (`write::friction`).
        return Some(vec![("law", Value::String("temperature".into()))]);
    }
    let t = s.tangential.temperature_law?;
    Some(vec![
        ("law", Value::String("temperature".into())),
        ("fref", Value::Float(t.fref)),
        ("tref_c", Value::Float(t.tref_c)),
        ("dfheat", Value::Float(t.dfheat)),
        ("dtheat_c", Value::Float(t.dtheat_c)),
    ])
}

/// `[contact_solver]`: the options the import sets ([`tangential`]) where they differ from the
/// defaults (any other is found by the read-back's comparison).
pub(super) fn contact_solver_pairs(s: &WheelRailScene) -> Option<Pairs> {
    let (o, d) = (s.tangential.contact_solver, ContactSolverOptions::default());
    let mut out: Pairs = Vec::new();
    if o.tempdep_tolerance != d.tempdep_tolerance {
        out.push(("tempdep_tolerance", Value::Float(o.tempdep_tolerance)));
    }
    if o.tempdep_max_iterations != d.tempdep_max_iterations {
        out.push(("tempdep_max_iterations", Value::Integer(o.tempdep_max_iterations as i64)));
    }
    if o.veldep_solves == VeldepSolves::Tight {
        out.push(("veldep_solves", Value::String("tight".into())));
    }
    if o.omgslp != d.omgslp {
        out.push(("omgslp", Value::Float(o.omgslp)));
    }
    (!out.is_empty()).then_some(out)
}
