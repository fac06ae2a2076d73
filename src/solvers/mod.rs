//! Step 3 of the pipeline: the models, registered in one place. A built-in model is a
//! [`Stepper`] plus a [`ModelDef`] (name, source, extra columns, applicability, cost, its own
//! parameters, builder);
//! the history stage's `sample_loop` runs every one of them the same way. External models
//! (`[external.NAME]`) run as a process over the whole scene and give a history directly
//! (`history::external`).

pub mod brush;
pub mod brush_shift;
pub mod contact;
pub mod fastrip;
pub mod fastrip_contact;
pub mod fastsim;
pub mod fastsim_contact;
pub mod kpec;
pub mod linear;
pub mod polach;
pub mod relaxation;
pub mod she;
pub mod stepper;
pub mod style;
pub mod termination;
pub mod uba;

pub use stepper::{FieldView, Step, Stepper};
pub use termination::Termination;

use crate::error::InputError;
use crate::problem::{ModelParams, Problem};
use crate::scene::reader::Section;
use crate::scene::Motion;

/// Why a model could not produce a trustworthy result.
#[derive(Debug, thiserror::Error)]
pub enum SolveError {
    /// A traction coefficient came out NaN or infinite.
    #[error("non-finite traction coefficient at step {step}")]
    NonFinite { step: usize },
    /// The exact-theory solver failed.
    #[error(transparent)]
    Contact(#[from] contact::ContactRunError),
    /// An approximate normal problem (KPEC, ANALYN) has no answer.
    #[error(transparent)]
    Approximate(#[from] crate::physics::approximate::ApproximateError),
    /// A shift start asked of a model that solves no shifts (refused before a run).
    #[error("step {step}: this model solves no shifts")]
    NoShifts { step: usize },
}

/// The `[model]` keys the models read themselves, declared next to their readers (one line per
/// model with keys), shown in docs/scene-format.md after the scene's own `[model]` keys.
pub const MODEL_KEYS: &[&crate::scene::keys::Keys] = &[&polach::KEYS, &relaxation::KEYS];

/// A built-in model: everything the tool needs to know of it, in one record.
pub struct ModelDef {
    /// The name in scenes (`solvers = [...]`) and of `<name>.csv`.
    pub name: &'static str,
    /// What the model is, with its source, in one line (report, README).
    pub summary: &'static str,
    /// Columns of `<name>.csv` after the interface's (and `mu`), in order.
    pub extra_columns: &'static [&'static str],
    /// Whether its solves iterate: its history then ends with a `termination` column.
    pub iterative: bool,
    /// Whether it can find the creepages of prescribed total forces (CONTACT F = 1, 2:
    /// `fx_over_fn`, `fy_over_fn`); a model that cannot is refused on such a scene.
    pub prescribed_forces: bool,
    /// Whether it solves shifts without rolling (`[rolling] motion = "shift"`, CONTACT T = 1); a
    /// model that cannot is refused on such a scene.
    pub shifts: bool,
    /// Whether it solves each row's normal problem from what a table gives in place of FN or the
    /// geometry: the approach (`pen_mm`, CONTACT N = 0) and the undeformed distance (`b1_per_mm`
    /// … `b6_mm`, CONTACT's IBASE = 1 per case); a model that cannot is refused on such a scene.
    pub normal_rows: bool,
    /// The approximate normal problem the model solves itself (KPEC, ANALYN: CONTACT's B = 5, 6):
    /// on a wheel–rail case it takes its own patches at its own wheelset height, as CONTACT
    /// balances FZ with them; `None`: the exact normal solution every other model shares.
    pub own_normal: Option<crate::physics::approximate::Method>,
    /// Refuses a problem the model cannot run, naming the scene field.
    pub check: fn(&Problem) -> Result<(), InputError>,
    /// Relative cost of one history row, for scheduling a suite (longest first).
    pub cost_per_row: fn(&Problem) -> f64,
    /// Reads and validates the model's own `[model]` keys, once, before anything runs (`None`:
    /// it has none). The builder takes the result back from `Problem::model_params`.
    pub params: Option<ReadParams>,
    /// The stepper for this problem.
    pub build: for<'a> fn(&'a Problem) -> Result<Box<dyn Stepper + 'a>, SolveError>,
    /// How every figure draws it: a colour and marker no other built-in model has together.
    pub style: style::ModelStyle,
}

/// A model's parameter reader over the scene's `[model]` table.
pub type ReadParams = fn(&mut Section<'_>) -> Result<Box<dyn ModelParams>, InputError>;

/// Every built-in model. Adding one: its file and one line here.
pub const MODELS: &[&ModelDef] = &[
    &uba::MODEL,
    &fastsim::MODEL,
    &fastsim_contact::MODEL,
    &contact::MODEL,
    &linear::MODEL,
    &she::MODEL,
    &polach::MODEL,
    &fastrip::MODEL,
    &fastrip_contact::MODEL,
    &relaxation::MODEL,
    &kpec::KPEC,
    &kpec::ANALYN,
];

/// The built-in model of that name.
pub fn builtin(name: &str) -> Option<&'static ModelDef> {
    MODELS.iter().copied().find(|m| m.name == name)
}

/// Names of the built-in models, in registry order.
pub fn builtin_names() -> Vec<&'static str> {
    MODELS.iter().map(|m| m.name).collect()
}

/// Every built-in model the problem names must accept it (e.g. the UBA needs courant ≤ 1; only a
/// model that finds creepages can take prescribed forces).
pub fn check_applicable(problem: &Problem) -> Result<(), InputError> {
    let shifts = problem.rolling.motion == Motion::Shift || problem.loading.shift_start().is_some();
    check_falling_combinations(problem, shifts)?;
    check_external(problem)?;
    problem.solvers.iter().filter_map(|s| builtin(s)).try_for_each(|m| check_model(problem, m, shifts))
}

/// A falling friction law with what no model combines it with: shifts (`shifts`) or prescribed forces.
fn check_falling_combinations(problem: &Problem, shifts: bool) -> Result<(), InputError> {
    if problem.friction.is_falling() && shifts {
        return Err(InputError::new(
            "rolling.motion",
            "\"shift\" with a falling [friction] law",
            "shifts with Coulomb friction, or rolling with a falling law (the slip velocity of a shift is not modelled)",
        ));
    }
    if problem.friction.is_falling() && problem.loading.prescribes_force() {
        return Err(InputError::new(
            "creepage.fx_over_fn",
            "prescribed forces with a falling [friction] law",
            "prescribed forces with Coulomb friction, or creepages with a falling law (the two iterations are not combined)",
        ));
    }
    if problem.friction.temperature().is_some() && problem.loading.prescribes_force() {
        return Err(InputError::new(
            "creepage.fx_over_fn",
            "prescribed forces with law = \"temperature\"",
            "prescribed forces with Coulomb friction, or creepages with the temperature law (the two iterations are not combined)",
        ));
    }
    Ok(())
}

/// An external model is given FN, one μ and the scene's geometry: no normal problem per row, no
/// friction per grid row.
fn check_external(problem: &Problem) -> Result<(), InputError> {
    let external = problem.solvers.iter().find(|s| builtin(s).is_none());
    if let Some((name, what)) = external.zip(problem.loading.normal_rows()) {
        return Err(InputError::new(
            "solvers",
            format!("{name:?} (an external model) with {what}"),
            "built-in models that solve each row's normal problem (an external model is given FN and the scene's geometry)",
        ));
    }
    if let Some(name) = external.filter(|_| problem.material.coupled()) {
        return Err(InputError::new(
            "solvers",
            format!("{name:?} (an external model) with dissimilar bodies (K = {})", problem.material.k),
            format!("dissimilar bodies only with the exact model ({})", contact::NAME),
        ));
    }
    if let Some(name) = external.filter(|_| problem.friction_rows.is_some()) {
        return Err(InputError::new(
            "solvers",
            format!("{name:?} (an external model) with [friction] mu_rows"),
            format!(
                "models that take a friction per grid row: {} (an external model is given one mu)",
                FRICTION_ROWS.join(", ")
            ),
        ));
    }
    if let Some(name) = external.filter(|_| problem.material.heat.is_some()) {
        return Err(InputError::new(
            "solvers",
            format!("{name:?} (an external model) with [material]'s heat keys (bulk1_c ..)"),
            format!("surface temperatures only with the exact model ({})", contact::NAME),
        ));
    }
    if let Some(name) = external.filter(|_| problem.extra_slip.is_some()) {
        return Err(InputError::new(
            "solvers",
            format!("{name:?} (an external model) with [creepage] extra_slip"),
            format!("an extra rigid slip per element only with the exact model ({})", contact::NAME),
        ));
    }
    Ok(())
}

/// Built-in model `m` takes what the problem asks of it (friction per row, a falling law,
/// prescribed forces, normal rows, a courant column, `[normal]`, a direction, shifts when
/// `shifts`), then its own [`ModelDef::check`].
fn check_model(problem: &Problem, m: &ModelDef, shifts: bool) -> Result<(), InputError> {
    let rows_what = problem.loading.normal_rows();
    if problem.friction_rows.is_some() && !FRICTION_ROWS.contains(&m.name) {
        return Err(InputError::new(
            "solvers",
            format!("{:?} with [friction] mu_rows", m.name),
            format!("models that take a friction per grid row: {} (leave {} out of this scene: it takes one mu for the whole contact)", FRICTION_ROWS.join(", "), m.name),
        ));
    }
    if problem.material.heat.is_some() && m.name != contact::NAME {
        return Err(InputError::new(
            "solvers",
            format!("{:?} with [material]'s heat keys (bulk1_c ..)", m.name),
            format!(
                "surface temperatures only with the exact model ({}; leave {} out of this scene, or the heat keys)",
                contact::NAME,
                m.name
            ),
        ));
    }
    if problem.extra_slip.is_some() && m.name != contact::NAME {
        return Err(InputError::new(
            "solvers",
            format!("{:?} with [creepage] extra_slip", m.name),
            format!("an extra rigid slip per element only with the exact model ({}; leave {} out of this scene: it takes the creepages only)", contact::NAME, m.name),
        ));
    }
    if problem.friction.is_falling() && !FALLING_FRICTION.contains(&m.name) {
        return Err(InputError::new(
            "solvers",
            format!("{:?} with a falling [friction] law", m.name),
            format!("models that take a falling friction law: {}", FALLING_FRICTION.join(", ")),
        ));
    }
    if problem.loading.prescribes_force() && !m.prescribed_forces {
        let able: Vec<&str> = MODELS.iter().filter(|m| m.prescribed_forces).map(|m| m.name).collect();
        return Err(InputError::new(
            "solvers",
            format!("{:?} with prescribed forces (creepage.fx_over_fn or fy_over_fn)", m.name),
            format!("models that find the creepages of prescribed forces: {} (leave {} out of this scene: it takes creepages only)", able.join(", "), m.name),
        ));
    }
    if let Some(what) = rows_what.filter(|_| !m.normal_rows) {
        let able: Vec<&str> = MODELS.iter().filter(|m| m.normal_rows).map(|m| m.name).collect();
        return Err(InputError::new(
            "solvers",
            format!("{:?} with {what}", m.name),
            format!("models that solve each row's normal problem: {} (leave {} out of this scene: it takes FN and the scene's geometry only)", able.join(", "), m.name),
        ));
    }
    if problem.loading.rows().any(|s| s.courant.is_some()) && m.name != contact::NAME {
        return Err(InputError::new(
            "creepage.file column courant",
            format!("a rolling distance per row with {:?}", m.name),
            format!("a courant column only with the exact model ({}); [rolling] courant for every model (leave {} out of this scene)", contact::NAME, m.name),
        ));
    }
    if problem.material.coupled() && m.name != contact::NAME {
        return Err(InputError::new(
            "material.g1_mpa",
            format!("dissimilar bodies (K = {}) with {:?}", problem.material.k, m.name),
            format!("dissimilar bodies only with the exact model ({}), which couples the normal and tangential problems (leave {} out of this scene: it takes G and poisson only)", contact::NAME, m.name),
        ));
    }
    if problem.material.layer.is_some() && m.name != contact::NAME {
        return Err(InputError::new(
            "material.layer_g_mpa",
            format!("an interface layer with {:?}", m.name),
            format!("an interface layer only with the exact model ({}), which adds its flexibility to the half-spaces' influence (leave {} out of this scene)", contact::NAME, m.name),
        ));
    }
    if let Some(v) = problem.material.layer.and_then(|l| l.yield_mpa) {
        if problem.material.coupled() || problem.friction.is_falling() || problem.friction.temperature().is_some() {
            return Err(InputError::new(
                "material.layer_yield_mpa",
                format!("a yield limit {v} MPa with dissimilar bodies or falling friction"),
                "a layer's yield limit with quasi-identical bodies (K = 0) and one friction coefficient: the bound min(mu pn, tau_c0) is set with the pressure, which the outer iteration of dissimilar bodies and the falling law's fixed point set anew",
            ));
        }
    }
    if let Some(k) = problem.material.layer.filter(|l| l.hardens()).map(|l| l.hardening_mpa_per_mm) {
        let rolls = problem.rolling.motion != Motion::Shift && problem.loading.is_transient();
        // Along +x in the solver's frame: CHI = 0 on every row, or 180 for the whole history
        // (the solver's mirrored frame).
        let chi = problem.rolling.chi_deg;
        let mirrored = chi == 180.0 && problem.loading.rows().all(|s| s.chi_deg.is_none());
        let turned = problem.loading.rows().map(|s| s.chi_deg_or(chi)).find(|&c| c != 0.0 && !mirrored);
        if let Some(chi_deg) = turned.filter(|_| rolls) {
            return Err(InputError::new(
                "rolling.chi_deg",
                format!("a yield limit moving at {k} MPa/mm in transient rolling at CHI = {chi_deg} deg"),
                "a layer that hardens or softens in transient rolling along x (chi_deg = 0, or 180 for the whole history: each element's limit moved with the material by dq along the row, as CONTACT's set_prev_data shifts TAUCS); shifts and steady rolling take any layer that hardens or softens",
            ));
        }
    }
    if problem.material.visco.is_some() {
        check_visco(problem, m)?;
    }
    if !problem.normal.is_default() && m.name != contact::NAME {
        return Err(InputError::new(
            "normal.pressure",
            format!("{:?} with {:?}", problem.normal.pressure.name(), m.name),
            format!("[normal] only with the exact model ({}): the simplified models take their pressure from [model] pressure (leave {} out of this scene)", contact::NAME, m.name),
        ));
    }
    let turned = problem.loading.rows().map(|s| s.chi_deg_or(problem.rolling.chi_deg)).find(|&c| c != 0.0);
    if let Some(chi_deg) = turned.filter(|_| !OTHER_DIRECTIONS.contains(&m.name)) {
        return Err(InputError::new(
            "rolling.chi_deg",
            format!("{chi_deg} with {:?}", m.name),
            format!("models that roll along another direction than +x: {} (leave {} out of this scene: it rolls along +x only)", OTHER_DIRECTIONS.join(", "), m.name),
        ));
    }
    if shifts && !m.shifts {
        let able: Vec<&str> = MODELS.iter().filter(|m| m.shifts).map(|m| m.name).collect();
        return Err(InputError::new(
            "solvers",
            format!(
                "{:?} with {}",
                m.name,
                if problem.rolling.motion == Motion::Shift {
                    "rolling.motion = \"shift\""
                } else {
                    "init.kind = \"shift\""
                }
            ),
            format!(
                "models that solve shifts without rolling: {} (leave {} out of this scene: it models rolling only)",
                able.join(", "),
                m.name
            ),
        ));
    }
    (m.check)(problem)
}

/// The built-in models that take Coulomb's μ per grid row (`[friction] mu_rows`, CONTACT V = 3):
/// the exact solver's bound μ_j p per element. The simplified models take one μ (their
/// flexibilities, strips and closed forms are written for it).
const FRICTION_ROWS: [&str; 1] = [contact::NAME];

/// The built-in models that take a rolling direction CHI other than 0 (along -x, or any angle in
/// transient rolling; CONTACT `m_sdis.f90`).
const OTHER_DIRECTIONS: [&str; 2] = [contact::NAME, fastsim_contact::NAME];

/// The built-in models that take a falling friction law: the exact solver, FASTSIM and the UBA
/// (each element's bound μ(s) p, [`brush::Falling`]), the relaxation model (FASTSIM's falling
/// steady force, lagged) and Polach (its own falling law from the static value, Eq. 8). The
/// others refuse it: the linear theory and Shen-Hedrick-Elkins have no bound of their own to
/// make fall, FaStrip's strips take one μ per strip in closed form. CONTACT's FASTSIM takes the
/// law's μ at the rigid slip velocity, one for the contact.
const FALLING_FRICTION: [&str; 6] = [
    contact::NAME,
    fastsim::MODEL.name,
    uba::MODEL.name,
    relaxation::MODEL.name,
    polach::MODEL.name,
    fastsim_contact::NAME,
];

/// Relative cost of running the problem's models, for scheduling only.
pub fn estimated_cost(problem: &Problem) -> f64 {
    let rows = problem.loading.rows().count() as f64;
    problem.solvers.iter().filter_map(|s| builtin(s)).map(|m| rows * (m.cost_per_row)(problem)).sum()
}

/// Accepts every problem.
pub fn always(_: &Problem) -> Result<(), InputError> {
    Ok(())
}

/// A closed-form law (no grid, no field, no extra columns, any problem): the linear theory and
/// the creep-force laws beside it.
pub const fn closed_form(
    name: &'static str,
    summary: &'static str,
    build: for<'a> fn(&'a Problem) -> Result<Box<dyn Stepper + 'a>, SolveError>,
    style: style::ModelStyle,
) -> ModelDef {
    ModelDef { extra_columns: &[], cost_per_row: negligible, ..grid_model(name, summary, always, build, style) }
}

/// Refuses a contact other than Hertz's ellipse for the model `name`, whose method needs the
/// ellipse (`why`: what of it, and what to run instead).
pub fn require_ellipse(p: &Problem, name: &str, why: &str) -> Result<(), InputError> {
    if p.geometry.elliptic() {
        return Ok(());
    }
    Err(InputError::new(
        "geometry.kind",
        format!("{:?}", p.geometry.kind()),
        format!("no [geometry] section when the scene runs {name}: {why}"),
    ))
}

/// A model on the scene's grid that counts its adhesion and slip elements (`n_adhesion`,
/// `n_slip`), solves each row in one pass (no termination column), with the creepages given, in
/// rolling, at a cost linear in the elements; a model that does more says so over this default.
pub const fn grid_model(
    name: &'static str,
    summary: &'static str,
    check: fn(&Problem) -> Result<(), InputError>,
    build: for<'a> fn(&'a Problem) -> Result<Box<dyn Stepper + 'a>, SolveError>,
    style: style::ModelStyle,
) -> ModelDef {
    ModelDef {
        name,
        summary,
        extra_columns: &["n_adhesion", "n_slip"],
        iterative: false,
        prescribed_forces: false,
        shifts: false,
        normal_rows: false,
        own_normal: None,
        check,
        cost_per_row: linear_in_elements,
        params: None,
        build,
        style,
    }
}

/// Cost of a closed-form law per row (scheduling only).
fn negligible(_: &Problem) -> f64 {
    1e-3
}

/// Cost of a model that touches every grid element a constant number of times per row.
pub fn linear_in_elements(p: &Problem) -> f64 {
    0.01 * p.grid.len() as f64
}

/// Viscoelastic bodies (`[material] visco_ratio`, CONTACT's M = 1): the exact model in steady
/// rolling along ±x at one speed, the bodies' constants combined without coupling (the memory
/// integral of [`crate::physics::halfspace::visco`] assumes tractions that stand still in the
/// contact frame, which only steady rolling has).
fn check_visco(problem: &Problem, m: &ModelDef) -> Result<(), InputError> {
    let field = "material.visco_ratio";
    let refuse = |value: String, allowed: &str| Err(InputError::new(field, value, allowed.to_string()));
    if m.name != contact::NAME {
        return refuse(
            format!("viscoelastic bodies with {:?}", m.name),
            &format!("viscoelastic bodies only with the exact model ({}), whose influence coefficients carry the material's memory (leave {} out of this scene)", contact::NAME, m.name),
        );
    }
    if problem.loading.is_transient() || problem.rolling.motion != Motion::Rolling {
        return refuse(
            "viscoelastic bodies in a transient history or shifts".into(),
            "steady rolling only (creepage.kind = \"sweep\"): the viscoelastic influence coefficients hold where the tractions stand still in the contact frame (CONTACT's M = 1 likewise)",
        );
    }
    if problem.loading.rows().any(|s| s.v_mm_s.is_some() || s.chi_deg.is_some()) {
        return refuse(
            "viscoelastic bodies at a speed or direction that changes per row".into(),
            "one rolling speed and direction for the whole history (the relaxation distance V·visco_time_s is the kernel's)",
        );
    }
    if !matches!(problem.rolling.chi_deg, 0.0 | 180.0) {
        return refuse(
            format!("viscoelastic bodies rolling at chi_deg = {}", problem.rolling.chi_deg),
            "chi_deg = 0 or 180 (CONTACT's M = 1 rolls along x)",
        );
    }
    if problem.material.coupled() || problem.material.layer.is_some() {
        return refuse(
            "viscoelastic bodies with dissimilar constants (K != 0) or an interface layer".into(),
            "quasi-identical bodies (K = 0) without a layer: the viscoelastic normal-tangential coupling is not modelled, and CONTACT's M is one material model",
        );
    }
    Ok(())
}
