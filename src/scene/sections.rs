//! The scene file's sections, one reader each ([`super::Scene::from_table`] calls them in the
//! file's order): every reader takes its section from the top-level table, checks each key and
//! refuses the keys it does not know.

use super::reader::{Deferred, Range, Section};
use super::{
    table, ContactSolverOptions, Creepage, ExternalSolver, InitKind, InitialSlip, Limits, MaterialSpec, ModelOptions,
    Motion, NormalOptions, SteadyRestart, CREEPAGE_LIMIT, FINITE, FORCE_RATIO, GRID_SCALE, HARD_MAX_STEPS,
    MAX_ELEMENTS_PER_AXIS, SPIN_LIMIT,
};
use crate::error::InputError;
use crate::physics::geometry::{Extent, GeometrySpec};
use crate::physics::{
    CoefficientSource, FallingTerms, FlexibilityModel, FrictionLaw, LeadingEdge, Memory, NormalPressure,
    PatchFlexibility, PressureShape, RowFriction,
};
use std::path::Path;

/// `[grid]`: its element counts, its scale and the potential contact's extent.
pub struct GridSpec {
    pub mx: usize,
    pub my: usize,
    pub scale: f64,
    pub extent: Extent,
}

/// The friction law (`[friction]`, optional: Coulomb with `contact.mu`) and μ's static value.
pub struct FrictionSpec {
    pub law: FrictionLaw,
    pub memory: Memory,
    pub mu_static: f64,
    /// Coulomb's μ per grid row (`[friction] mu_rows`, CONTACT V = 3); `mu_static` is their largest.
    pub rows: Option<RowFriction>,
}

/// The loading: the creepage history and the constant lateral and spin creepages.
pub struct CreepageSpec {
    pub creepage: Creepage,
    pub cy: f64,
    /// `fy_over_fn`: Fy/FN prescribed in place of `cy` (CONTACT F = 2).
    pub fy_over_fn: Option<f64>,
    pub cs_per_mm: f64,
}

/// `[external.NAME]`: each external model's command and time limit (the pipeline checks NAME).
pub fn external(top: &mut Section) -> Result<Vec<ExternalSolver>, InputError> {
    let mut external = Vec::new();
    if let Some(mut ext) = top.opt_table("external")? {
        for key in ext.keys() {
            let t = ext.table(&key)?;
            external.push(external_one(key, t)?);
        }
        ext.finish()?;
    }
    Ok(external)
}

/// One `[external.NAME]` table.
fn external_one(name: String, mut t: Section) -> Result<ExternalSolver, InputError> {
    let command =
        t.opt_str_list("command", "program and its arguments")?.filter(|c| !c.is_empty()).ok_or_else(|| {
            InputError::new(t.field("command"), "missing or empty", "a non-empty array: program and arguments")
        })?;
    let timeout_s = t
        .opt_f64("timeout_s", Range::new(0.0, false, 86400.0, true))?
        .unwrap_or(crate::safety::process::DEFAULT_TIMEOUT.as_secs_f64());
    t.finish()?;
    Ok(ExternalSolver { name, command, timeout_s })
}

/// `[grid]` (read first: a geometry per element fills it).
pub fn grid(top: &mut Section) -> Result<GridSpec, InputError> {
    let mut g = top.table("grid")?;
    let mx = g.usize("mx", 1, MAX_ELEMENTS_PER_AXIS)?;
    let my = g.usize("my", 1, MAX_ELEMENTS_PER_AXIS)?;
    let scale = g.opt_f64("scale", GRID_SCALE)?.unwrap_or(1.0);
    let extent = grid_extent(&mut g, scale)?;
    g.finish()?;
    Ok(GridSpec { mx, my, scale, extent })
}

/// `[grid] x_mm, y_mm` (both or neither): explicit edges, else `scale` times the ellipse's box.
fn grid_extent(g: &mut Section, scale: f64) -> Result<Extent, InputError> {
    let edge = Range::new(-1e4, true, 1e4, true);
    match (g.opt_f64_array::<2>("x_mm", edge)?, g.opt_f64_array::<2>("y_mm", edge)?) {
        (None, None) => Ok(Extent::Scale(scale)),
        (Some(x_mm), Some(y_mm)) => {
            for (key, [lo, hi]) in [("x_mm", x_mm), ("y_mm", y_mm)] {
                if hi <= lo {
                    return Err(InputError::new(
                        g.field(key),
                        format!("[{lo}, {hi}]"),
                        "edges [low, high] with low < high [mm]",
                    ));
                }
            }
            g.refuse("scale", "not with explicit edges x_mm, y_mm (scale sizes a grid from the ellipse)")?;
            Ok(Extent::Edges { x_mm, y_mm })
        }
        (x, _) => {
            let missing = if x.is_none() { "x_mm" } else { "y_mm" };
            Err(InputError::new(
                g.field(missing),
                "missing",
                "both edges x_mm = [x0, x1] and y_mm = [y0, y1], or neither",
            ))
        }
    }
}

/// Relative difference allowed between a given `contact.mu` and a falling law's FKIN + F1 + F2
/// (the sum is rounded in the last digit: 0.22 + 0.15 + 0.08 = 0.45000000000000007).
const MU_STATIC_REL: f64 = 1e-12;

/// `[friction]` (optional): the law and its parameters (CONTACT's names), the memory; `mu` is
/// `contact.mu` as given (required by Coulomb's law; a falling law's static value FKIN + F1 + F2);
/// Coulomb's law may give μ per grid row instead (`mu_rows`, `my` values).
pub fn friction(top: &mut Section, mu: Option<f64>, my: usize) -> Result<FrictionSpec, InputError> {
    let Some(mut f) = top.opt_table("friction")? else {
        return coulomb(mu, Memory::NONE);
    };
    let law = f.choice("law", &["coulomb", "linear", "rational", "exponential"])?;
    let coefficient = Range::new(0.0, true, 1e3, true);
    let speed = Range::new(0.0, true, 1e9, true);
    if law == "coulomb" {
        for key in ["fkin", "f1", "sabsh1_mm_s", "f2", "sabsh2_mm_s", "memory_mm", "memory_s0_mm_s"] {
            f.refuse(key, "only with a falling law (law = \"linear\", \"rational\" or \"exponential\")")?;
        }
        let rows = mu_rows(&mut f, mu, my)?;
        f.finish()?;
        return match rows {
            Some(rows) => {
                let mu_static = rows.mu_max();
                Ok(FrictionSpec {
                    law: FrictionLaw::Coulomb { mu: mu_static },
                    memory: Memory::NONE,
                    mu_static,
                    rows: Some(rows),
                })
            }
            None => coulomb(mu, Memory::NONE),
        };
    }
    f.refuse("mu_rows", "only with law = \"coulomb\" (a falling law is one for the whole contact)")?;
    let terms = FallingTerms {
        fkin: f.f64("fkin", coefficient)?,
        f1: f.f64("f1", coefficient)?,
        sabsh1_mm_s: f.f64("sabsh1_mm_s", Range::new(0.0, false, 1e9, true))?,
        f2: f.opt_f64("f2", coefficient)?.unwrap_or(0.0),
        sabsh2_mm_s: f.opt_f64("sabsh2_mm_s", speed)?.unwrap_or(0.0),
    };
    if terms.f2 > 0.0 && terms.sabsh2_mm_s <= 0.0 {
        let given = if f.has("sabsh2_mm_s") { terms.sabsh2_mm_s.to_string() } else { "missing".into() };
        return Err(InputError::new(f.field("sabsh2_mm_s"), given, "a slip velocity > 0 [mm/s] when f2 > 0"));
    }
    let law = match law {
        "linear" => FrictionLaw::Linear(terms),
        "rational" => FrictionLaw::Rational(terms),
        _ => FrictionLaw::Exponential(terms),
    };
    let memory = match f.opt_f64("memory_mm", Range::new(0.0, true, 1e4, true))? {
        Some(memory_mm) => Memory { memory_mm, s0_mm_s: f.opt_f64("memory_s0_mm_s", speed)?.unwrap_or(0.0) },
        None => {
            f.refuse("memory_s0_mm_s", "only with memory_mm (the memory's relaxation distance)")?;
            Memory::NONE
        }
    };
    let mu_static = law.mu_static();
    if !(mu_static > 0.0 && mu_static <= 1e3) {
        let given = format!("{} (fkin + f1 + f2 = {mu_static})", terms.fkin);
        return Err(InputError::new(f.field("fkin"), given, "a static value fkin + f1 + f2 in (0, 1000]"));
    }
    f.finish()?;
    if let Some(given) = mu {
        if (given - mu_static).abs() > MU_STATIC_REL * mu_static {
            return Err(InputError::new(
                "contact.mu",
                given,
                format!(
                    "left out with a falling friction law, or equal to its static value fkin + f1 + f2 = {mu_static}"
                ),
            ));
        }
    }
    Ok(FrictionSpec { law, memory, mu_static, rows: None })
}

/// `[friction] mu_rows` (Coulomb only): μ of every grid row, `my` values in (0, 1000], the first
/// at the lowest y (CONTACT's V = 3, FSTAT per row IY); `contact.mu` is then left out.
fn mu_rows(f: &mut Section, mu: Option<f64>, my: usize) -> Result<Option<RowFriction>, InputError> {
    let Some(list) = f.opt_f64_list("mu_rows", super::MU_LIMIT, MAX_ELEMENTS_PER_AXIS)? else {
        return Ok(None);
    };
    if list.len() != my {
        return Err(InputError::new(
            f.field("mu_rows"),
            format!("{} values", list.len()),
            format!("one coefficient per grid row: grid.my = {my} values, the first at the lowest y"),
        ));
    }
    if let Some(given) = mu {
        return Err(InputError::new(
            "contact.mu",
            given,
            "left out with [friction] mu_rows (the rows give the friction; the nominal mu is their largest)",
        ));
    }
    Ok(RowFriction::new(list))
}

/// Coulomb's law with `contact.mu` (required).
fn coulomb(mu: Option<f64>, memory: Memory) -> Result<FrictionSpec, InputError> {
    let mu = mu.ok_or_else(|| {
        InputError::new("contact.mu", "missing", "a coefficient of friction in (0, 1000] (or a falling [friction] law)")
    })?;
    Ok(FrictionSpec { law: FrictionLaw::Coulomb { mu }, memory, mu_static: mu, rows: None })
}

/// `[material]`: g_mpa or e_mpa (or both), and poisson; or the two bodies' g1_mpa, poisson1,
/// g2_mpa, poisson2 (dissimilar bodies, [`bodies`]).
pub fn material(top: &mut Section) -> Result<MaterialSpec, InputError> {
    let mut m = top.table("material")?;
    let layer = layer(&mut m)?;
    if let Some(spec) = bodies(&mut m)? {
        m.finish()?;
        return Ok(MaterialSpec { layer, ..spec });
    }
    let g_mpa = m.opt_f64("g_mpa", Range::new(0.0, false, 1e7, true))?;
    let e_mpa = m.opt_f64("e_mpa", Range::new(0.0, false, 1e7, true))?;
    let poisson = m.f64("poisson", Range::new(0.0, true, 0.5, false))?;
    if g_mpa.is_none() && e_mpa.is_none() {
        return Err(InputError::new(
            "material.g_mpa",
            "missing",
            "g_mpa (or e_mpa, from which g_mpa = e/(2(1+poisson)))",
        ));
    }
    m.finish()?;
    Ok(MaterialSpec { g_mpa, e_mpa, poisson, bodies: None, layer })
}

/// The keys of an interface layer, given together.
const LAYER_KEYS: [&str; 2] = ["layer_g_mpa", "layer_thickness_mm"];

/// An interface layer (CONTACT's M = 4: GG3, LAYTHK): both keys or neither. A thickness of 0 is
/// no layer, as CONTACT's (`use_3bl` needs LAYTHK >= 1e-10).
fn layer(m: &mut Section) -> Result<Option<crate::physics::material::Layer>, InputError> {
    let given: Vec<&str> = LAYER_KEYS.iter().copied().filter(|k| m.has(k)).collect();
    if given.is_empty() {
        return Ok(None);
    }
    if let Some(missing) = LAYER_KEYS.iter().find(|k| !given.contains(k)) {
        return Err(InputError::new(
            m.field(missing),
            "missing",
            format!("both of {} with {}", LAYER_KEYS.join(", "), given.join(", ")),
        ));
    }
    let g_mpa = m.f64("layer_g_mpa", Range::new(0.0, false, 1e12, true))?;
    let thickness_mm = m.f64("layer_thickness_mm", Range::new(0.0, true, 1e3, true))?;
    Ok((thickness_mm > 0.0).then_some(crate::physics::material::Layer { g_mpa, thickness_mm }))
}

/// The keys of the two bodies' constants, in the order they are named.
const BODY_KEYS: [&str; 4] = ["g1_mpa", "poisson1", "g2_mpa", "poisson2"];

/// `[material]` given per body (CONTACT's GG 1, 2 and POISS 1, 2): all four keys, none of
/// g_mpa, e_mpa, poisson; the combined constants and Kalker's K follow ([`crate::physics::Material::from_bodies`]).
fn bodies(m: &mut Section) -> Result<Option<MaterialSpec>, InputError> {
    // A body may be far stiffer than the pair (CONTACT's "rigid" body of G = 2e7 N/mm²).
    let modulus = Range::new(0.0, false, 1e12, true);
    let ratio = Range::new(0.0, true, 0.5, true);
    let given: Vec<&str> = BODY_KEYS.iter().copied().filter(|k| m.has(k)).collect();
    if given.is_empty() {
        return Ok(None);
    }
    if let Some(missing) = BODY_KEYS.iter().find(|k| !given.contains(k)) {
        return Err(InputError::new(
            m.field(missing),
            "missing",
            format!("all four of {} with {}", BODY_KEYS.join(", "), given.join(", ")),
        ));
    }
    if let Some(both) = ["g_mpa", "e_mpa", "poisson"].iter().find(|k| m.has(k)) {
        return Err(InputError::new(
            m.field(both),
            "given with the bodies' g1_mpa .. poisson2",
            "either the combined g_mpa (or e_mpa) and poisson, or the two bodies' constants",
        ));
    }
    let g = [m.f64("g1_mpa", modulus)?, m.f64("g2_mpa", modulus)?];
    let nu = [m.f64("poisson1", ratio)?, m.f64("poisson2", ratio)?];
    let bodies = crate::physics::material::Bodies { g_mpa: g, poisson: nu };
    let combined = crate::physics::Material::from_bodies(bodies);
    if combined.poisson >= 0.5 {
        return Err(InputError::new(
            m.field("poisson1"),
            nu[0],
            "bodies whose combined Poisson's ratio is below 0.5 (both at 0.5 is an incompressible pair: give g_mpa and poisson)",
        ));
    }
    Ok(Some(MaterialSpec { g_mpa: None, e_mpa: None, poisson: combined.poisson, bodies: Some(bodies), layer: None }))
}

/// `[rolling]` (optional): the speed [mm/s] (default 1000), the Courant number (default 1), the
/// motion (default rolling; `"shift"`: CONTACT's T = 1) and the rolling direction CHI [deg]
/// (default 0, in [0, 360); steady rolling at 0 or 180 only, CONTACT `m_sdis.f90`).
pub fn rolling(top: &mut Section) -> Result<(f64, f64, Motion, f64), InputError> {
    let (mut v_mm_s, mut courant, mut motion, mut chi_deg) = (1000.0, 1.0, Motion::Rolling, 0.0);
    if let Some(mut r) = top.opt_table("rolling")? {
        chi_deg = r.opt_f64("chi_deg", Range::new(0.0, true, 360.0, false))?.unwrap_or(chi_deg);
        v_mm_s = r.opt_f64("v_mm_s", super::SPEED_LIMIT)?.unwrap_or(v_mm_s);
        courant = r.opt_f64("courant", Range::new(0.0, false, 100.0, true))?.unwrap_or(courant);
        if r.opt_choice("motion", &["rolling", "shift"])? == Some("shift") {
            motion = Motion::Shift;
        }
        r.finish()?;
    }
    Ok((v_mm_s, courant, motion, chi_deg))
}

/// `[creepage]`: the kind's history, and the constant cy and cs.
pub fn creepage(top: &mut Section, dir: &Path) -> Result<CreepageSpec, InputError> {
    let mut cr = top.table("creepage")?;
    let kind = cr.choice("kind", &["step", "sine", "sweep", "table"])?;
    let creepage = match kind {
        "step" => match cr.opt_f64("fx_over_fn", FORCE_RATIO)? {
            Some(f) => {
                let instead = "only one of creepage.c (cx given) and creepage.fx_over_fn (Fx/FN prescribed; the state at t = 0 carries no force)";
                cr.refuse("c", instead)?;
                cr.refuse("c_before", instead)?;
                Creepage::Step {
                    c: f,
                    steps: cr.usize("steps", 1, HARD_MAX_STEPS)?,
                    c_before: 0.0,
                    fx_prescribed: true,
                }
            }
            None => Creepage::Step {
                c: cr.f64("c", CREEPAGE_LIMIT)?,
                steps: cr.usize("steps", 1, HARD_MAX_STEPS)?,
                c_before: cr.opt_f64("c_before", CREEPAGE_LIMIT)?.unwrap_or(0.0),
                fx_prescribed: false,
            },
        },
        "sine" => Creepage::Sine {
            c0: cr.f64("c0", CREEPAGE_LIMIT)?,
            cp: cr.f64("cp", CREEPAGE_LIMIT)?,
            freq_hz: cr.f64("freq_hz", Range::new(0.0, false, 1e6, true))?,
            periods: cr.f64("periods", Range::new(0.0, false, 1e4, true))?,
        },
        "sweep" => sweep(&mut cr)?,
        _ => {
            let file = cr.str("file", "a CSV path relative to the scene file")?;
            let path = dir.join(file);
            let rows = Box::new(table::CreepageTable::from_file(&path, &cr.field("file"))?);
            Creepage::Table { file: path, rows }
        }
    };
    if kind != "sweep" {
        let only_sweep = format!("only with kind = \"sweep\" (kind {kind:?} sets cx itself)");
        for key in ["cx", "over", "direction"] {
            cr.refuse(key, &only_sweep)?;
        }
    }
    if kind != "step" && kind != "sweep" {
        cr.refuse(
            "fx_over_fn",
            "only with kind = \"step\" or \"sweep\" (a table prescribes Fx/FN as its column fx_over_fn)",
        )?;
    }
    // A sweep over Fy/FN prescribes it at every point (its constant 0 where not given).
    let over_fy = kind == "sweep" && cr.opt_choice("over", SWEEP_OVER)? == Some("fy_over_fn");
    let fy_over_fn = cr.opt_f64("fy_over_fn", FORCE_RATIO)?.or(over_fy.then_some(0.0));
    if fy_over_fn.is_some() {
        cr.refuse("cy", "only one of creepage.cy (cy given) and creepage.fy_over_fn (Fy/FN prescribed)")?;
        if kind == "sweep" && cr.opt_choice("over", SWEEP_OVER)? == Some("cy") {
            cr.refuse("over", "over = \"fy_over_fn\" with fy_over_fn (Fy/FN prescribed in place of cy)")?;
        }
    }
    let cy = cr.opt_f64("cy", CREEPAGE_LIMIT)?.unwrap_or(0.0);
    let cs_per_mm = cr.opt_f64("cs", SPIN_LIMIT)?.unwrap_or(0.0);
    cr.finish()?;
    Ok(CreepageSpec { creepage, cy, fy_over_fn, cs_per_mm })
}

/// What a sweep's `over` may name: a creepage, a prescribed force ratio or the speed.
const SWEEP_OVER: &[&str] = &["cx", "cy", "cs", "v_mm_s", "fx_over_fn", "fy_over_fn"];

/// `[creepage] kind = "sweep"`: the parameter's points (`from, to, points` or the list `at`),
/// the direction (`over` or `direction`) and the constant cx, or Fx/FN prescribed in its place
/// (`fx_over_fn` or `over = "fx_over_fn"`, CONTACT's F = 1, 2 in steady rolling).
fn sweep(cr: &mut Section) -> Result<Creepage, InputError> {
    let at = cr.opt_f64_list("at", FINITE, HARD_MAX_STEPS)?;
    let (from, to, points) = match &at {
        Some(list) => {
            for key in ["from", "to", "points"] {
                cr.refuse(key, "either creepage.at (a list of t) or from, to, points, not both")?;
            }
            (list[0], list[list.len() - 1], list.len())
        }
        None => (cr.f64("from", FINITE)?, cr.f64("to", FINITE)?, cr.usize("points", 1, HARD_MAX_STEPS)?),
    };
    let over = cr.opt_choice("over", SWEEP_OVER)?;
    let speed = over == Some("v_mm_s");
    let direction = if speed {
        cr.refuse("direction", "not with over = \"v_mm_s\" (a speed sweep holds the creepages)")?;
        [0.0; 3]
    } else {
        sweep_direction(cr)?
    };
    let fx = cr.opt_f64("fx_over_fn", FORCE_RATIO)?;
    let fx_prescribed = fx.is_some() || over == Some("fx_over_fn");
    if fx_prescribed {
        let instead =
            "only one of creepage.cx (cx given) and creepage.fx_over_fn or over = \"fx_over_fn\" (Fx/FN prescribed)";
        cr.refuse("cx", instead)?;
        if over == Some("cx") {
            cr.refuse("over", "over = \"fx_over_fn\" with fx_over_fn (Fx/FN prescribed in place of cx)")?;
        }
    }
    let cx = match fx {
        Some(f) => f,
        None => cr.opt_f64("cx", CREEPAGE_LIMIT)?.unwrap_or(0.0),
    };
    Ok(Creepage::Sweep { from, to, points, direction, cx, at, speed, fx_prescribed })
}

/// A sweep's direction in (x, y, cs), x and y the creepages or the force ratios prescribed in
/// their place: `over` one of them, or `direction` (not both; default x).
fn sweep_direction(cr: &mut Section) -> Result<[f64; 3], InputError> {
    let over = cr.opt_choice("over", SWEEP_OVER)?;
    Ok(match (over, cr.opt_f64_array::<3>("direction", FINITE)?) {
        (Some(o), Some(d)) => {
            return Err(InputError::new(
                cr.field("direction"),
                format!("{d:?} with over = {o:?}"),
                "either creepage.over or creepage.direction, not both",
            ))
        }
        (None, Some(d)) if d.iter().all(|&x| x == 0.0) => {
            return Err(InputError::new(
                cr.field("direction"),
                format!("{d:?}"),
                "three finite numbers [dcx, dcy, dcs], not all zero",
            ))
        }
        (None, Some(d)) => d,
        (Some("cy" | "fy_over_fn"), None) => [0.0, 1.0, 0.0],
        (Some("cs"), None) => [0.0, 0.0, 1.0],
        _ => [1.0, 0.0, 0.0],
    })
}

/// `[init]` (optional): the initial tangential state (default zero). A shift start (`"shift"`)
/// needs a rolling time history: it is the shift before the rolling.
pub fn init(top: &mut Section, motion: Motion, creepage: &Creepage) -> Result<InitKind, InputError> {
    let mut init = InitKind::Zero;
    if let Some(mut i) = top.opt_table("init")? {
        init = match i.opt_choice("kind", &["zero", "steady", "shift"])? {
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

/// `[model]` (optional): the options the simplified models share; the keys left are the models'
/// own parameters, which the pipeline has each model read.
pub fn model(top: &mut Section) -> Result<(ModelOptions, Deferred), InputError> {
    let mut model = ModelOptions::default();
    let Some(mut md) = top.opt_table("model")? else {
        return Ok((model, Deferred::empty("model")));
    };
    if let Some(f) = md.opt_choice("flexibility", &["kalker", "thesis"])? {
        model.flexibility = if f == "thesis" { FlexibilityModel::Thesis } else { FlexibilityModel::Kalker };
    }
    if let Some(c) = md.opt_choice("coefficients", &["table", "fit"])? {
        model.coefficients = if c == "fit" { CoefficientSource::Fit } else { CoefficientSource::Table };
    }
    if let Some(p) = md.opt_choice("pressure", &["parabolic", "ellipsoidal"])? {
        model.pressure = if p == "ellipsoidal" { PressureShape::Ellipsoidal } else { PressureShape::Parabolic };
    }
    if let Some(e) = md.opt_choice("leading_edge", &["grid", "exact"])? {
        model.leading_edge = if e == "exact" { LeadingEdge::Exact } else { LeadingEdge::Grid };
    }
    model.slope_reduction = slope_reduction(&mut md)?;
    if let Some(n) = md.opt_choice("flexibilities", &["three", "one"])? {
        model.single_flexibility = n == "one";
    }
    if let Some(f) = md.opt_choice("nonhertz_flexibility", &["strip", "equivalent_ellipse"])? {
        model.nonhertz_flexibility =
            if f == "strip" { PatchFlexibility::Strip } else { PatchFlexibility::EquivalentEllipse };
    }
    Ok((model, md.defer()))
}

/// `[model] slope_reduction = [k0, alpha, beta]` (optional): k0 > 0, 0 ≤ α ≤ 1, β ≥ 0.
fn slope_reduction(md: &mut Section) -> Result<Option<[f64; 3]>, InputError> {
    let Some([k0, alpha, beta]) = md.opt_f64_array::<3>("slope_reduction", Range::new(0.0, true, 1e3, true))? else {
        return Ok(None);
    };
    if !(k0 > 0.0 && (0.0..=1.0).contains(&alpha)) {
        return Err(InputError::new(
            md.field("slope_reduction"),
            format!("[{k0}, {alpha}, {beta}]"),
            "[k0, alpha, beta] with k0 > 0, 0 <= alpha <= 1, beta >= 0",
        ));
    }
    Ok(Some([k0, alpha, beta]))
}

/// `[normal]` (optional): the exact solver's pressure, solved or Hertz's imposed (CONTACT's B = 0,
/// 2, 3), and the start row's. An imposed pressure needs Hertz's ellipse (CONTACT: IPOTCN < 0); a
/// start pressure needs a start (`[init] kind = "steady"` or `"shift"`).
pub fn normal(top: &mut Section, geometry: &GeometrySpec, init: InitKind) -> Result<NormalOptions, InputError> {
    let mut normal = NormalOptions::default();
    let Some(mut n) = top.opt_table("normal")? else {
        return Ok(normal);
    };
    let choices = ["solved", "elliptical", "parabolic"];
    let of = |name: &str| match name {
        "elliptical" => NormalPressure::Elliptical,
        "parabolic" => NormalPressure::Parabolic,
        _ => NormalPressure::Solved,
    };
    if let Some(p) = n.opt_choice("pressure", &choices)? {
        normal.pressure = of(p);
    }
    normal.start_pressure = normal.pressure;
    if let Some(p) = n.opt_choice("start_pressure", &choices)? {
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

/// `[contact_solver]` (optional): tolerance, iteration limit, steady restart.
pub fn contact_solver(top: &mut Section) -> Result<ContactSolverOptions, InputError> {
    let mut contact_solver = ContactSolverOptions::default();
    if let Some(mut cs) = top.opt_table("contact_solver")? {
        if let Some(t) = cs.opt_f64("tolerance", Range::new(1e-14, true, 1e-2, true))? {
            contact_solver.tolerance = t;
        }
        if let Some(n) = cs.opt_usize("max_iterations", 1, 1_000_000)? {
            contact_solver.max_iterations = n;
        }
        if let Some(r) = cs.opt_choice("steady_restart", &["contact", "converged"])? {
            contact_solver.steady_restart =
                if r == "contact" { SteadyRestart::Contact } else { SteadyRestart::Converged };
        }
        if let Some(t) = cs.opt_f64("veldep_tolerance", Range::new(1e-14, true, 1e-2, true))? {
            contact_solver.veldep_tolerance = t;
        }
        if let Some(start) = cs.opt_choice("inislp", &["previous", "below", "above", "extrapolated"])? {
            contact_solver.inislp = match start {
                "below" => InitialSlip::Below,
                "above" => InitialSlip::Above,
                "extrapolated" => InitialSlip::Extrapolated,
                _ => InitialSlip::Previous,
            };
        }
        if let Some(w) = cs.opt_f64("omgslp", Range::new(0.0, false, 2.0, true))? {
            contact_solver.omgslp = w;
        }
        if let Some(v) = cs.opt_choice("veldep_solves", &["adaptive", "tight"])? {
            contact_solver.veldep_solves =
                if v == "tight" { crate::scene::VeldepSolves::Tight } else { crate::scene::VeldepSolves::Adaptive };
        }
        if let Some(b) = cs.opt_choice("influence", &["constant", "bilinear"])? {
            use crate::physics::halfspace::influence::Basis;
            contact_solver.influence = if b == "bilinear" { Basis::Bilinear } else { Basis::Constant };
        }
        if let Some(n) = cs.opt_usize("max_outer", 1, 1000)? {
            contact_solver.max_outer = n;
        }
        cs.finish()?;
    }
    Ok(contact_solver)
}

/// `[limits]` (optional): the step limit and the estimated run time limit.
pub fn limits(top: &mut Section) -> Result<Limits, InputError> {
    let mut limits = Limits::default();
    if let Some(mut l) = top.opt_table("limits")? {
        if let Some(n) = l.opt_usize("max_steps", 1, HARD_MAX_STEPS)? {
            limits.max_steps = n;
        }
        if let Some(t) = l.opt_f64("max_estimated_s", Range::new(0.0, false, 1e7, true))? {
            limits.max_estimated_s = t;
        }
        l.finish()?;
    }
    Ok(limits)
}

/// `[origin]`: the CONTACT input file (`file`) and its first and last case (`cases`) an imported
/// scene reproduces.
pub fn origin(top: &mut Section) -> Result<Option<super::Origin>, InputError> {
    let Some(mut o) = top.opt_table("origin")? else {
        return Ok(None);
    };
    let file = o.str("file", "the CONTACT input file's name")?.to_string();
    let field = o.field("cases");
    let allowed = "two whole numbers [first, last], 1 <= first <= last";
    let cases = match o.given("cases") {
        Some(toml::Value::Array(a)) => {
            let n: Vec<Option<usize>> =
                a.iter().map(|v| v.as_integer().and_then(|i| usize::try_from(i).ok())).collect();
            match n.as_slice() {
                [Some(first), Some(last)] if *first >= 1 && first <= last => [*first, *last],
                _ => return Err(InputError::new(field, toml::Value::Array(a.clone()), allowed)),
            }
        }
        Some(other) => return Err(InputError::new(field, other, allowed)),
        None => return Err(InputError::new(field, "missing", format!("required: {allowed}"))),
    };
    o.finish()?;
    Ok(Some(super::Origin { file, cases }))
}
