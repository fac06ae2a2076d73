//! Step 1 of the pipeline: the scene file (docs/scene-format.md), parsed and validated.
//!
//! Every field is checked (type, range, NaN/inf, unknown keys); errors name the field, the value
//! and what is allowed, and become exit status 2.

pub mod contact;
pub mod contact_solver;
pub mod creepage;
pub mod external;
pub mod friction;
pub mod geometry;
pub mod grid;
pub mod init;
pub mod keys;
pub mod limits;
pub mod material;
pub mod model;
pub mod normal;
pub mod origin;
pub mod reader;
pub mod report;
pub mod rolling;
pub mod source;
pub mod stress;
pub mod study;
pub mod table;
pub mod top;
pub mod wheelrail;
pub mod wheelrail_cases;
pub mod wheelrail_massless;
pub mod wheelrail_profile;
pub mod wheelrail_section;
pub mod wheelrail_tangential;

use crate::error::InputError;
use crate::physics::geometry::{Extent, GeometrySpec};
use crate::physics::{CoefficientSource, FlexibilityModel, LeadingEdge, PatchFlexibility, PressureShape};
use reader::{Deferred, Range, Section};
use std::path::{Path, PathBuf};

/// Largest grid accepted along either axis (CONTACT's 2-D decks run 841 × 1: `perfc_test/carter2d_800`).
pub const MAX_ELEMENTS_PER_AXIS: usize = 4096;

/// Largest grid accepted in all, `mx · my`: the exact solver's FFT products hold about a dozen
/// complex arrays of four times the grid (CONTACT's largest performance deck, `norm_problm_8p`,
/// runs 575 × 575).
pub const MAX_GRID_ELEMENTS: usize = 1 << 19;

/// Elastic constants as given.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialSpec {
    pub g_mpa: Option<f64>,
    pub e_mpa: Option<f64>,
    pub poisson: f64,
    /// The two bodies' own constants (`g1_mpa`, `poisson1`, `g2_mpa`, `poisson2`); then `g_mpa`,
    /// `e_mpa` and `poisson` are absent and follow from them (`poisson` holds the combined ν).
    pub bodies: Option<crate::physics::material::Bodies>,
    /// An interface layer between the bodies (`layer_g_mpa`, `layer_thickness_mm`; CONTACT's M = 4).
    pub layer: Option<crate::physics::material::Layer>,
    /// Viscoelastic bodies (`visco_ratio`, `visco_time_s`; CONTACT's M = 1).
    pub visco: Option<crate::physics::material::Visco>,
    /// Both bodies' thermal constants (`bulk1_c` … `density2_kg_per_mm3`; CONTACT's H = 3).
    pub heat: Option<[crate::physics::temperature::Thermal; 2]>,
    /// A thin compressible sheet's flexibility L_z [mm³/N] (`sheet_flexibility_mm3_per_n`;
    /// CONTACT's B = 1, FLXZ); 0: none.
    pub sheet_mm3_per_n: f64,
    /// Blanco-Lorenzo's conformal correction (`blanco_variant`, `blanco_inclination`; CONTACT's
    /// C3 = 4); `None`: the half-space's influence coefficients.
    pub blanco: Option<crate::physics::halfspace::blanco::Blanco>,
}

/// The creepage history kinds, as the scene declares them (scene.json's `loading.creepage`,
/// tagged by `kind`; a table by its rows, without its file's path).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
pub enum Creepage {
    /// cx = `c_before` at t = 0, then `c` at every step k ≥ 1; with `fx_prescribed`, `c` is the
    /// Fx/FN prescribed at every step k ≥ 1 (`fx_over_fn`, CONTACT F = 1) and t = 0 carries none.
    Step { c: f64, steps: usize, c_before: f64, fx_prescribed: bool },
    /// cx(t_k) = c0 + cp sin(2π F t_k), k = 1..ceil(periods/(F dt)).
    Sine { c0: f64, cp: f64, freq_hz: f64, periods: f64 },
    /// Steady rolling at `points` evenly spaced t from `from` to `to` — or at the listed t of
    /// `at` (then `from`, `to` are its first and last) — at the creepage `[cx, cy, cs] +
    /// t·direction` (cy, cs the scene's constants; see [`Scene::sweep_point`]).
    /// With `speed` (`over = "v_mm_s"`) t is the rolling speed [mm/s] and the creepages are held.
    /// With `fx_prescribed` (CONTACT's F = 1, 2 in steady rolling) the point's first component
    /// (and `cx`) is Fx/FN prescribed in place of cx; its second is Fy/FN where the scene's
    /// `fy_over_fn` is given.
    Sweep {
        from: f64,
        to: f64,
        points: usize,
        direction: [f64; 3],
        cx: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        at: Option<Vec<f64>>,
        speed: bool,
        fx_prescribed: bool,
    },
    /// A CSV table `t_s,cx[,cy,cs,fn_n,mu,v_mm_s]`, interpolated at t_k = k dt up to its last time
    /// (within `problem::loading::TABLE_END_REL`).
    Table {
        #[serde(skip)]
        file: PathBuf,
        #[serde(rename = "table")]
        rows: Box<table::CreepageTable>,
    },
}

impl Creepage {
    /// Sweep point k = 1..=points ([`Scene::sweep_point`]) with `y` the constant of the second
    /// component (cy, or Fy/FN where prescribed) and `cs` the spin's.
    pub fn sweep_point(&self, k: usize, y: f64, cs: f64) -> Option<[f64; 3]> {
        let Creepage::Sweep { from, to, points, direction, cx, at, .. } = self else {
            return None;
        };
        let f = if *points > 1 { (k - 1) as f64 / (*points - 1) as f64 } else { 0.0 };
        let t = match at {
            Some(list) => *list.get(k.checked_sub(1)?)?,
            None => from + (to - from) * f,
        };
        let add = |c: f64, d: f64| {
            if d == 0.0 {
                c
            } else if c == 0.0 {
                d * t
            } else {
                c + d * t
            }
        };
        Some([add(*cx, direction[0]), add(y, direction[1]), add(cs, direction[2])])
    }

    /// Rolling speed [mm/s] of sweep point k of a speed sweep (`over = "v_mm_s"`), else `None`.
    pub fn sweep_speed(&self, k: usize) -> Option<f64> {
        let Creepage::Sweep { from, to, points, at, speed: true, .. } = self else {
            return None;
        };
        let f = if *points > 1 { (k - 1) as f64 / (*points - 1) as f64 } else { 0.0 };
        match at {
            Some(list) => list.get(k.checked_sub(1)?).copied(),
            None => Some(from + (to - from) * f),
        }
    }
}

/// The initial tangential state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum InitKind {
    Zero,
    Steady,
    /// A shift from rest (CONTACT T = 1, P = 2) at the loading of t = 0, whose traction the
    /// rolling history then continues (CONTACT T = 2, P = 0: `examples/catt_to_cart.inp`).
    Shift,
}

/// Model options the simplified models share (`[model]`); a model's own parameters are its
/// file's (`ModelDef::params`), read from [`Scene::model_params`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ModelOptions {
    pub flexibility: FlexibilityModel,
    pub coefficients: CoefficientSource,
    pub pressure: PressureShape,
    /// Where the simplified models start each row (default: the grid's edge, as CONTACT's FASTSIM).
    pub leading_edge: LeadingEdge,
    /// Strip flexibilities on a contact that is not an ellipse (default: the equivalent ellipse's).
    #[serde(default, skip_serializing_if = "PatchFlexibility::is_default")]
    pub nonhertz_flexibility: PatchFlexibility,
    /// The modified FASTSIM's slope reduction `[k0, α, β]` (Spiryagin et al. 2013, as CONTACT's
    /// M = 2/3 options): flexibilities divided by `k = k0 (α + (1 − α)/(1 + β ε))`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slope_reduction: Option<[f64; 3]>,
    /// FASTSIM and the UBA with Kalker's single flexibility instead of three.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub single_flexibility: bool,
}

impl Default for ModelOptions {
    fn default() -> Self {
        Self {
            flexibility: FlexibilityModel::Kalker,
            coefficients: CoefficientSource::Table,
            pressure: PressureShape::Parabolic,
            leading_edge: LeadingEdge::Grid,
            nonhertz_flexibility: PatchFlexibility::EquivalentEllipse,
            single_flexibility: false,
            slope_reduction: None,
        }
    }
}

/// The exact solver's normal problem (`[normal]`, optional): solved, or Hertz's pressure imposed
/// (CONTACT's B = 2, 3); the start row's (step 0) may differ (the B of the case that starts a
/// history: `examples` of CONTACT shift with B = 2, then roll with B = 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub struct NormalOptions {
    /// The pressure of every row (`[normal] pressure`).
    pub pressure: crate::physics::NormalPressure,
    /// The start row's (`[normal] start_pressure`, default `pressure`).
    pub start_pressure: crate::physics::NormalPressure,
}

impl NormalOptions {
    /// Whether every row's normal problem is solved (the default; left out of `scene.json`).
    pub fn is_default(&self) -> bool {
        *self == NormalOptions::default()
    }

    /// The pressure of a row: the start row's (step 0 of a run with a steady or shift start) or
    /// every other row's.
    pub fn of_row(&self, start: bool) -> crate::physics::NormalPressure {
        if start {
            self.start_pressure
        } else {
            self.pressure
        }
    }
}

/// Options of the CONTACT-style solver (`[contact_solver]`, optional).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ContactSolverOptions {
    /// Stop when the largest traction change relative to max μ pn falls below this.
    pub tolerance: f64,
    /// Iteration limit per time step; reaching it flags the step as not converged.
    pub max_iterations: usize,
    /// The first transient step after a steady start where μ or FN changed there.
    #[serde(default, skip_serializing_if = "SteadyRestart::is_default")]
    pub steady_restart: SteadyRestart,
    /// Falling friction: stop the slip-velocity fixed point when rms(s_new − s) ≤ this · rms(s_new).
    #[serde(default = "veldep_tolerance", skip_serializing_if = "is_veldep_tolerance")]
    pub veldep_tolerance: f64,
    /// The temperature law: stop the temperature fixed point when rms(T_new − T) ≤ this · rms(T_new).
    #[serde(default = "tempdep_tolerance", skip_serializing_if = "is_tempdep_tolerance")]
    pub tempdep_tolerance: f64,
    /// The temperature law: the most iterations of its fixed point (CONTACT's max(1, MAXIN − 10) + 1).
    #[serde(default = "tempdep_max_iterations", skip_serializing_if = "is_tempdep_max_iterations")]
    pub tempdep_max_iterations: usize,
    /// Falling friction: where the slip-velocity fixed point starts (CONTACT's INISLP).
    #[serde(default, skip_serializing_if = "InitialSlip::is_default")]
    pub inislp: InitialSlip,
    /// Falling friction: the damping of the slip-velocity update (CONTACT's OMGSLP).
    #[serde(default = "omgslp", skip_serializing_if = "is_omgslp")]
    pub omgslp: f64,
    /// Falling friction: how tightly the fixed point's early tangential solves are made.
    #[serde(default, skip_serializing_if = "VeldepSolves::is_default")]
    pub veldep_solves: VeldepSolves,
    /// The influence functions' traction basis (`[contact_solver] influence`, CONTACT's C = 2, 3).
    #[serde(default, skip_serializing_if = "crate::physics::halfspace::influence::Basis::is_default")]
    pub influence: crate::physics::halfspace::influence::Basis,
    /// Dissimilar bodies (K ≠ 0): the most outer iterations between the normal and tangential
    /// problems per solve (CONTACT's MAXOUT, its Panagiotopoulos process).
    #[serde(default = "max_outer", skip_serializing_if = "is_max_outer")]
    pub max_outer: usize,
}

/// CONTACT's MAXOUT where the bodies are dissimilar and the input gives none (`contact_addon.f90`).
pub const MAX_OUTER: usize = 10;

fn max_outer() -> usize {
    MAX_OUTER
}

fn is_max_outer(v: &usize) -> bool {
    *v == MAX_OUTER
}

/// `[contact_solver] veldep_solves`: the tangential solves of the slip-velocity fixed point.
/// `Adaptive` solves early iterates loosely (1e-2 × the last relative change) and ends on a
/// tight solve, each solve started with the last one's slip area on the new bound; `Tight` solves
/// every iterate at the final tolerance from CONTACT's starts, as CONTACT does, so that CONTACT's
/// own loose stop (1e-3) is met at the same iterate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum VeldepSolves {
    #[default]
    Adaptive,
    Tight,
}

impl VeldepSolves {
    pub fn is_default(&self) -> bool {
        *self == VeldepSolves::default()
    }
}

/// Default `[contact_solver] veldep_tolerance`.
pub const VELDEP_TOLERANCE: f64 = 1e-6;

fn veldep_tolerance() -> f64 {
    VELDEP_TOLERANCE
}

fn is_veldep_tolerance(v: &f64) -> bool {
    *v == VELDEP_TOLERANCE
}

/// Default `[contact_solver] tempdep_tolerance`.
pub const TEMPDEP_TOLERANCE: f64 = 1e-6;

fn tempdep_tolerance() -> f64 {
    TEMPDEP_TOLERANCE
}

fn is_tempdep_tolerance(v: &f64) -> bool {
    *v == TEMPDEP_TOLERANCE
}

/// Default `[contact_solver] tempdep_max_iterations`: CONTACT's max(1, MAXIN − 10) + 1 at MAXIN = 200.
pub const TEMPDEP_MAX_ITERATIONS: usize = 191;

fn tempdep_max_iterations() -> usize {
    TEMPDEP_MAX_ITERATIONS
}

fn is_tempdep_max_iterations(v: &usize) -> bool {
    *v == TEMPDEP_MAX_ITERATIONS
}

/// Default `[contact_solver] omgslp`: CONTACT's default OMGSLP (`m_hierarch_data.f90` line 1749).
pub const OMGSLP: f64 = 0.5;

fn omgslp() -> f64 {
    OMGSLP
}

fn is_omgslp(v: &f64) -> bool {
    *v == OMGSLP
}

/// The start of the slip-velocity fixed point with falling friction (`[contact_solver] inislp`,
/// CONTACT's INISLP, `m_stang.f90` lines 258-264; its user guide states the signs the wrong way round).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum InitialSlip {
    /// INISLP = 0 (default): the previous step's slip velocity moved by dq; 0 in steady rolling
    /// and in the first step from zero.
    #[default]
    Previous,
    /// INISLP = +1: from s = 0 ("from below"): the low-slip solution where there are several.
    Below,
    /// INISLP = −1: from s = V ("from above"): the high-slip solution.
    Above,
    /// Not CONTACT's: as `Previous`, but a transient step after a transient step starts from the
    /// last two steps' slip velocity extrapolated in the contact's frame (at a stationary state
    /// the start is the solution, where the moved field is one element off it). The same fixed
    /// point where the step has one; where it has several, it may keep the last step's branch
    /// where CONTACT's start leaves it.
    Extrapolated,
}

impl InitialSlip {
    pub fn is_default(&self) -> bool {
        *self == InitialSlip::default()
    }
}

/// What the exact solver's first transient step after a steady start does where μ or FN changed
/// there (`[contact_solver] steady_restart`; `solvers::contact::restart`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SteadyRestart {
    /// CONTACT's result (default; its envelope data decide): the steady state with the slip area on
    /// the new bound, where the creepages and the loaded elements did not change, no adhesion
    /// element exceeds its new bound and no slip element's slip turns against its traction; else
    /// the converged step.
    #[default]
    Contact,
    /// The transient step solved to the tolerance from the steady state.
    Converged,
}

impl SteadyRestart {
    pub fn is_default(&self) -> bool {
        *self == SteadyRestart::default()
    }
}

impl Default for ContactSolverOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-7,
            max_iterations: 1000,
            steady_restart: SteadyRestart::Contact,
            veldep_tolerance: VELDEP_TOLERANCE,
            tempdep_tolerance: TEMPDEP_TOLERANCE,
            tempdep_max_iterations: TEMPDEP_MAX_ITERATIONS,
            inislp: InitialSlip::Previous,
            omgslp: OMGSLP,
            veldep_solves: VeldepSolves::Adaptive,
            influence: crate::physics::halfspace::influence::Basis::Constant,
            max_outer: MAX_OUTER,
        }
    }
}

/// Largest step or point count any scene may ask for, even with `[limits] max_steps`.
pub const HARD_MAX_STEPS: usize = 100_000_000;

/// How large a scene may be (`[limits]`): one step limit for every creepage kind and a limit on
/// the exact-theory solver's estimated run time; raising them is an explicit choice.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Limits {
    /// Time steps or sweep points (default 2 million).
    pub max_steps: usize,
    /// Estimated wall time of one model run [s] (default 600).
    pub max_estimated_s: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits { max_steps: 2_000_000, max_estimated_s: 600.0 }
    }
}

/// An external model (`[external.NAME] command = [...]`; the pipeline checks NAME): any executable that reads scene.json
/// and writes a history CSV in the `simulate` format.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalSolver {
    pub name: String,
    /// Program and arguments; a relative program path is resolved against the scene's folder.
    pub command: Vec<String>,
    /// Longest run on this scene [s] (`timeout_s`, default 600); then its process group is killed.
    pub timeout_s: f64,
}

/// Where an imported scene came from (`[origin]`, written by `import contact`): the CONTACT
/// input file and its first and last case (carried into scene.json: the reference set
/// `contact_public` finds the printed case of each row by it).
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Origin {
    pub file: String,
    pub cases: [usize; 2],
}

/// What moves the bodies from step to step (`[rolling] motion`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Motion {
    /// Rolling by dq per step: the creepages are dimensionless, the kernel shifts by dq.
    #[default]
    Rolling,
    /// Shifts without rolling (CONTACT T = 1, Cattaneo; Kalker 1990 §5.2.1): the creepage keys are
    /// rigid shifts per step [mm] (cs: rotation [rad]), the traction stays in place.
    Shift,
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub name: String,
    /// `solvers` as given: the pipeline checks it against the model registry and `external`.
    pub solvers: Option<toml::Value>,
    /// `metrics` as given (`None`: those that fit the creepage kind): the pipeline checks it
    /// against the metric registry.
    pub metrics: Option<toml::Value>,
    pub geometry: GeometrySpec,
    pub fn_n: f64,
    /// The approach [mm] prescribed at every step or sweep point in place of `fn_n` (`[contact]
    /// pen_mm`, CONTACT N = 0); `fn_n` then sizes the grid. `None`: FN prescribed.
    pub pen_mm: Option<f64>,
    /// Coulomb's μ, or a falling law's static value FKIN + F1 + F2.
    pub mu: f64,
    /// The friction law (`[friction]`; Coulomb with `mu` when absent).
    pub friction: crate::physics::FrictionLaw,
    /// The friction memory (`[friction] memory_mm`; none when absent).
    pub memory: crate::physics::Memory,
    /// Coulomb's μ per grid row (`[friction] mu_rows`; `mu` is their largest).
    pub friction_rows: Option<crate::physics::RowFriction>,
    pub material: MaterialSpec,
    pub mx: usize,
    pub my: usize,
    /// The grid covers `grid_scale` times the nominal ellipse's bounding box (CONTACT's SCALE).
    pub grid_scale: f64,
    /// The potential contact: `Scale(grid_scale)`, or explicit edges for a geometry per element.
    pub extent: Extent,
    pub v_mm_s: f64,
    pub courant: f64,
    /// Rolling, or shifts without rolling (CONTACT T = 1: the creepages are shifts per step).
    pub motion: Motion,
    /// The rolling direction CHI [deg] in [0, 360): 0 (+x), 180 (-x), any angle in transient
    /// rolling (`[rolling] chi_deg`).
    pub chi_deg: f64,
    pub creepage: Creepage,
    pub cy: f64,
    /// Fy/FN prescribed in place of `cy` (`[creepage] fy_over_fn`, CONTACT F = 2).
    pub fy_over_fn: Option<f64>,
    pub cs_per_mm: f64,
    /// The extra rigid slip `[wx, wy]` per element in CONTACT's element order (`[creepage]
    /// extra_slip`, CONTACT's EXRHS); `None`: none.
    pub extra_slip: Option<[Vec<f64>; 2]>,
    pub init: InitKind,
    pub model: ModelOptions,
    /// The `[model]` keys the models read themselves (their parameters; the pipeline has each
    /// model read and validate its own, then refuses a key no one read).
    pub model_params: Deferred,
    pub contact_solver: ContactSolverOptions,
    /// The exact solver's normal problem (`[normal]`).
    pub normal: NormalOptions,
    pub external: Vec<ExternalSolver>,
    pub limits: Limits,
    /// Folder of the scene file (relative paths in the scene are resolved against it).
    pub dir: PathBuf,
    /// The studies this scene is a point of (none for a scene file of its own).
    pub studies: Vec<study::StudyPoint>,
    /// The CONTACT deck and cases the scene was imported from (`[origin]`).
    pub origin: Option<Origin>,
    /// Where the report shows the scene (`[report] group`).
    pub report_group: report::ReportGroup,
    /// The subsurface points and steps of `[stress]` (CONTACT's S digit), if asked for.
    pub stress: Option<stress::StressPoints>,
}

/// The declared keys of a contact-patch scene's tables, in the order docs/scene-format.md
/// shows them ([`keys`]; the models declare their own `[model]` keys, `solvers::MODEL_KEYS`).
pub const KEY_TABLES: &[&keys::Keys] = &[
    &top::KEYS,
    &contact::KEYS,
    &geometry::KEYS,
    &friction::KEYS,
    &material::KEYS,
    &material::BODY_KEYS,
    &material::LAYER_KEYS,
    &material::PLASTIC_KEYS,
    &material::VISCO_KEYS,
    &material::HEAT_KEYS,
    &material::BLANCO_KEYS,
    &grid::KEYS,
    &rolling::KEYS,
    &creepage::KEYS,
    &init::KEYS,
    &model::KEYS,
    &contact_solver::KEYS,
    &normal::KEYS,
    &limits::KEYS,
    &origin::KEYS,
    &report::KEYS,
    &stress::KEYS,
    &external::KEYS,
    &wheelrail::TOP_KEYS,
    &wheelrail_section::KEYS,
    &wheelrail_profile::PROFILE_KEYS,
    &wheelrail_profile::RAIL_KEYS,
    &wheelrail_profile::WHEEL_KEYS,
    &wheelrail_cases::KEYS,
    &wheelrail_cases::AXIS_KEYS,
    &wheelrail_cases::STEP_KEYS,
    &wheelrail_massless::KEYS,
    &wheelrail::REPORT_KEYS,
];

/// The declarations of the columns of table files (column, unit, allowed, meaning): the reader
/// checks each value by its column's, and docs/scene-format.md's columns tables are generated
/// from them (`<!-- columns:ID -->`).
pub const COLUMN_TABLES: &[&keys::Keys] = &[&wheelrail_cases::COLUMNS];

const CREEPAGE_LIMIT: Range = Range::new(-1.0, true, 1.0, true);
/// A prescribed force ratio Fx/FN or Fy/FN: below 1 in size (and below μ, checked per sample).
pub(crate) const FORCE_RATIO: Range = Range::new(-1.0, false, 1.0, false);
const SPIN_LIMIT: Range = Range::new(-10.0, true, 10.0, true);
/// A rolling speed [mm/s] (`[rolling] v_mm_s`, a table's or a sweep's).
pub const SPEED_LIMIT: Range = Range::new(0.0, false, 1e6, true);
/// A coefficient of friction (`[contact] mu`, `[friction] mu_rows`, a table's column `mu`).
pub const MU_LIMIT: Range = Range::new(0.0, false, 1e3, true);
/// Any finite number (a sweep's parameter and direction; the points are checked).
const FINITE: Range = Range::new(f64::NEG_INFINITY, false, f64::INFINITY, false);
/// `[grid] scale`: the grid's extent in nominal semi-axes.
const GRID_SCALE: Range = Range::new(1.0, true, 10.0, true);

/// A number for a message: plain, or in exponent form when very large or small.
pub(crate) fn compact(v: f64) -> String {
    if v != 0.0 && !(1e-6..1e9).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// A speed sweep's speeds (`from`, `to` or each of `at`) within `[rolling] v_mm_s`'s range.
fn check_speeds(speeds: &[(String, f64)]) -> Result<(), InputError> {
    for (key, v) in speeds.iter().map(|(k, v)| (k, *v)) {
        if !SPEED_LIMIT.contains(v) {
            return Err(InputError::new(
                format!("creepage.{key}"),
                compact(v),
                format!("a speed sweep's speeds {} [mm/s] (from, to or each of at)", SPEED_LIMIT.describe()),
            ));
        }
    }
    Ok(())
}

/// A scene or external model name: 1 to 100 characters of `[a-z0-9_]`.
pub fn is_valid_name(s: &str) -> bool {
    !s.is_empty() && s.len() <= 100 && s.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
}

/// A scene file's text (any kind of scene), read within [`crate::safety::read::SCENE_LIMIT_BYTES`].
pub fn read_scene_text(path: &Path) -> Result<String, InputError> {
    crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "scene file")
        .map_err(|e| InputError::new("scene", path.display(), format!("a readable scene file (TOML): {e}")))
}

impl Scene {
    /// Read and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene, InputError> {
        let text = read_scene_text(path)?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Scene::from_toml(&text, &dir)
    }

    /// Parse and validate scene text; `dir` resolves relative paths.
    pub fn from_toml(text: &str, dir: &Path) -> Result<Scene, InputError> {
        let doc = reader::parse_toml(text, "scene")?;
        Scene::from_table(&doc, dir)
    }

    /// Validate a parsed scene table (a scene file's, or one point of a study); `dir` resolves
    /// relative paths.
    pub fn from_table(doc: &toml::Table, dir: &Path) -> Result<Scene, InputError> {
        if wheelrail::is_wheelrail(doc) {
            return Err(InputError::new(
                "wheelrail",
                "a wheel–rail scene",
                "a contact-patch scene here: a wheel–rail scene runs with `creepbench simulate`, in the suites of `run` and `check`, and from Python with `simulate_wheelrail`",
            ));
        }
        let mut top = Section::new("", doc).declare(&top::KEYS);
        let name = top::name(&mut top)?;
        let external = external::read(&mut top)?;
        let (solvers, metrics) = top::models_and_metrics(&mut top);
        let grid = grid::read(&mut top)?;
        let element_geometry = match top.opt_table("geometry")? {
            Some(section) => Some(geometry::read(section, dir, (grid.mx, grid.my))?),
            None => None,
        };
        let contact = contact::read(&mut top, element_geometry)?;
        let friction = friction::read(&mut top, contact.mu, grid.my)?;
        let material = material::read(&mut top)?;
        let (v_mm_s, courant, motion, chi_deg) = rolling::read(&mut top)?;
        let loading = creepage::read(&mut top, dir, (grid.mx, grid.my))?;
        let init = init::read(&mut top, motion, &loading.creepage)?;
        let (model, model_params) = model::read(&mut top)?;
        let contact_solver = contact_solver::read(&mut top)?;
        let normal = normal::read(&mut top, &contact.geometry, init)?;
        let limits = limits::read(&mut top)?;
        let origin = origin::read(&mut top)?;
        let report_group = report::read(&mut top)?;
        let stress = stress::read(&mut top)?;
        top.finish()?;
        let scene = Scene {
            name,
            solvers,
            metrics,
            geometry: contact.geometry,
            fn_n: contact.fn_n,
            pen_mm: contact.pen_mm,
            mu: friction.mu_static,
            friction: friction.law,
            memory: friction.memory,
            friction_rows: friction.rows,
            material,
            mx: grid.mx,
            my: grid.my,
            grid_scale: grid.scale,
            extent: grid.extent,
            v_mm_s,
            courant,
            motion,
            chi_deg,
            creepage: loading.creepage,
            cy: loading.cy,
            fy_over_fn: loading.fy_over_fn,
            cs_per_mm: loading.cs_per_mm,
            extra_slip: loading.extra_slip,
            init,
            model,
            model_params,
            contact_solver,
            normal,
            external,
            limits,
            dir: dir.to_path_buf(),
            studies: Vec::new(),
            origin,
            report_group,
            stress,
        };
        scene.check_sweep_points()?;
        scene.check_table_friction()?;
        scene.check_temperature_law()?;
        scene.check_table_geometry()?;
        Ok(scene)
    }

    /// Creepage `[cx, cy, cs]` of sweep point k = 1..=points: `[cx, cy, cs] + t·direction`, t from
    /// `from` to `to` evenly or the k-th of `at` (`None` for the other kinds). A zero direction component keeps its
    /// constant and a zero constant gives d·t, bit for bit: the cx sweep gives exactly the
    /// cx = from + (to − from)·(k − 1)/(points − 1) of scenes written before `over`/`direction`.
    pub fn sweep_point(&self, k: usize) -> Option<[f64; 3]> {
        self.creepage.sweep_point(k, self.fy_over_fn.unwrap_or(self.cy), self.cs_per_mm)
    }

    /// Rolling speed [mm/s] of sweep point k of a speed sweep (`over = "v_mm_s"`), else `None`.
    pub fn sweep_speed(&self, k: usize) -> Option<f64> {
        self.creepage.sweep_speed(k)
    }

    /// An undeformed distance per row (columns `b1_per_mm` … `b6_mm`) replaces a geometry given per
    /// element on an explicit grid: an ellipse sizes its grid from its load and has none to replace.
    fn check_table_geometry(&self) -> Result<(), InputError> {
        if let Creepage::Table { file, rows } = &self.creepage {
            if rows.h_coefficients.is_some() && !self.geometry.is_elementwise() {
                return Err(InputError::new(
                    format!("creepage.file ({})", file.display()),
                    "columns b1_per_mm to b6_mm with a Hertzian contact",
                    "an undeformed distance per row only with a [geometry] given per element on an explicit grid ([grid] x_mm, y_mm)",
                ));
            }
        }
        Ok(())
    }

    /// The temperature law (`[friction] law = "temperature"`) takes μ from the surface
    /// temperatures: `[material]`'s heat keys give them, and a table may not vary μ.
    fn check_temperature_law(&self) -> Result<(), InputError> {
        if self.friction.temperature().is_none() {
            return Ok(());
        }
        if self.material.heat.is_none() {
            return Err(InputError::new(
                "friction.law",
                "\"temperature\" without [material]'s heat keys",
                "the temperature law with the surface temperatures' data: [material] bulk1_c, heat_capacity1_j_per_kg_c, conductivity1_w_per_mm_c, density1_kg_per_mm3 and body 2's",
            ));
        }
        if let Creepage::Table { file, rows } = &self.creepage {
            if rows.mu.is_some() {
                return Err(InputError::new(
                    format!("creepage.file ({})", file.display()),
                    "a column mu",
                    "no mu column with law = \"temperature\" (the law gives mu)",
                ));
            }
        }
        Ok(())
    }

    /// A falling law gives μ itself: a table may not vary it (`mu` column).
    fn check_table_friction(&self) -> Result<(), InputError> {
        if let Creepage::Table { file, rows } = &self.creepage {
            if rows.mu.is_some() && self.friction.is_falling() {
                return Err(InputError::new(
                    format!("creepage.file ({})", file.display()),
                    "a column mu",
                    "no mu column with a falling [friction] law (the law gives mu)",
                ));
            }
            if rows.mu.is_some() && self.friction_rows.is_some() {
                return Err(InputError::new(
                    format!("creepage.file ({})", file.display()),
                    "a column mu",
                    "no mu column with [friction] mu_rows (the rows give mu)",
                ));
            }
        }
        Ok(())
    }

    /// Every sweep point within the creepage ranges. Evenly spaced points are monotone in t, so
    /// the first and the last (computed as they are sampled) bound them all and the error names
    /// the end; a list `at` is checked point by point and the error names the entry.
    fn check_sweep_points(&self) -> Result<(), InputError> {
        let Creepage::Sweep { from, to, points, at, speed, fx_prescribed, .. } = &self.creepage else {
            return Ok(());
        };
        if *speed {
            let named: Vec<(String, f64)> = match at {
                Some(list) => list.iter().enumerate().map(|(n, &v)| (format!("at[{n}]"), v)).collect(),
                None => vec![("from".into(), *from), ("to".into(), *to)],
            };
            return check_speeds(&named);
        }
        let checked: Vec<(usize, String, f64)> = match at {
            Some(list) => list.iter().enumerate().map(|(n, &t)| (n + 1, format!("at[{n}]"), t)).collect(),
            None if *points == 1 => vec![(1, "from".into(), *from)],
            None => vec![(1, "from".into(), *from), (*points, "to".into(), *to)],
        };
        for (k, key, t) in checked.iter().map(|(k, key, t)| (*k, key, t)) {
            let point = self.sweep_point(k).unwrap_or_default();
            let x = if *fx_prescribed { ("fx_over_fn", FORCE_RATIO) } else { ("cx", CREEPAGE_LIMIT) };
            let y = if self.fy_over_fn.is_some() { ("fy_over_fn", FORCE_RATIO) } else { ("cy", CREEPAGE_LIMIT) };
            let limits = [x, y, ("cs", SPIN_LIMIT)];
            for ((name, range), v) in limits.iter().zip(point) {
                if !range.contains(v) {
                    return Err(InputError::new(
                        format!("creepage.{key}"),
                        format!("{} (sweep point {k}: {name} = {})", compact(*t), compact(v)),
                        format!(
                            "a sweep whose every point [{}, {}, cs] + t·direction has cx and cy {}, Fx/FN and Fy/FN {}, cs {} [1/mm]",
                            x.0,
                            y.0,
                            CREEPAGE_LIMIT.describe(),
                            FORCE_RATIO.describe(),
                            SPIN_LIMIT.describe()
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
