//! Step 1 of the pipeline: the scene file (docs/scene-format.md), parsed and validated.
//!
//! Every field is checked (type, range, NaN/inf, unknown keys); errors name the field, the value
//! and what is allowed, and become exit status 2.

pub mod geometry;
pub mod reader;
pub mod study;
pub mod table;

use crate::error::InputError;
use crate::physics::geometry::{Extent, GeometrySpec};
use crate::physics::{CoefficientSource, FlexibilityModel, LeadingEdge, PatchFlexibility, PressureShape, Radii};
use reader::{Range, Section};
use std::path::{Path, PathBuf};

/// Largest grid accepted along either axis.
pub const MAX_ELEMENTS_PER_AXIS: usize = 512;

/// Elastic constants as given.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialSpec {
    pub g_mpa: Option<f64>,
    pub e_mpa: Option<f64>,
    pub poisson: f64,
}

/// The creepage history kinds.
#[derive(Debug, Clone, PartialEq)]
pub enum Creepage {
    /// cx = `c_before` at t = 0, then `c` at every step k ≥ 1.
    Step { c: f64, steps: usize, c_before: f64 },
    /// cx(t_k) = c0 + cp sin(2π F t_k), k = 1..ceil(periods/(F dt)).
    Sine { c0: f64, cp: f64, freq_hz: f64, periods: f64 },
    /// Steady rolling at `points` evenly spaced t from `from` to `to` — or at the listed t of
    /// `at` (then `from`, `to` are its first and last) — at the creepage `[cx, cy, cs] +
    /// t·direction` (cy, cs the scene's constants; see [`Scene::sweep_point`]).
    Sweep { from: f64, to: f64, points: usize, direction: [f64; 3], cx: f64, at: Option<Vec<f64>> },
    /// A CSV table `t_s,cx[,cy,cs,fn_n,mu]`, interpolated at t_k = k dt up to its last time
    /// (within `problem::loading::TABLE_END_REL`).
    Table { file: PathBuf, rows: table::CreepageTable },
}

/// The initial tangential state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum InitKind {
    Zero,
    Steady,
}

/// Polach's parameters (`[model] polach_k_a, polach_k_s, polach_a, polach_b_s_per_m`; Wear 258
/// (2005) Eq. 1–8): the reductions of the adhesion and slip parts and the falling friction
/// `μ0 ((1 − A) e^(−B w) + A)`. Defaults: the unreduced curve with constant friction.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PolachParams {
    pub k_a: f64,
    pub k_s: f64,
    /// μ∞/μ0.
    pub a: f64,
    /// B [s/m].
    pub b_s_per_m: f64,
}

impl Default for PolachParams {
    fn default() -> Self {
        PolachParams { k_a: 1.0, k_s: 1.0, a: 1.0, b_s_per_m: 0.0 }
    }
}

impl PolachParams {
    pub fn is_default(&self) -> bool {
        *self == PolachParams::default()
    }
}

/// Model options of the simplified models (`[model]`).
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
    /// Polach's model's parameters.
    #[serde(default, skip_serializing_if = "PolachParams::is_default")]
    pub polach: PolachParams,
    /// The relaxation model's length [mm] for both components instead of the linear theory's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub relaxation_length_mm: Option<f64>,
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
            polach: PolachParams::default(),
            relaxation_length_mm: None,
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
        Self { tolerance: 1e-7, max_iterations: 1000, steady_restart: SteadyRestart::Contact }
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

/// An external model (`[external.NAME] command = [...]`): any executable that reads scene.json
/// and writes a history CSV in the `simulate` format.
#[derive(Debug, Clone, PartialEq)]
pub struct ExternalSolver {
    pub name: String,
    /// Program and arguments; a relative program path is resolved against the scene's folder.
    pub command: Vec<String>,
    /// Longest run on this scene [s] (`timeout_s`, default 600); then its process group is killed.
    pub timeout_s: f64,
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    pub name: String,
    pub solvers: Vec<String>,
    /// Metrics asked for; `None` = those that fit the creepage kind.
    pub metrics: Option<Vec<String>>,
    pub geometry: GeometrySpec,
    pub fn_n: f64,
    pub mu: f64,
    pub material: MaterialSpec,
    pub mx: usize,
    pub my: usize,
    /// The grid covers `grid_scale` times the nominal ellipse's bounding box (CONTACT's SCALE).
    pub grid_scale: f64,
    /// The potential contact: `Scale(grid_scale)`, or explicit edges for a geometry per element.
    pub extent: Extent,
    pub v_mm_s: f64,
    pub courant: f64,
    pub creepage: Creepage,
    pub cy: f64,
    pub cs_per_mm: f64,
    pub init: InitKind,
    pub model: ModelOptions,
    pub contact_solver: ContactSolverOptions,
    pub external: Vec<ExternalSolver>,
    pub limits: Limits,
    /// Folder of the scene file (relative paths in the scene are resolved against it).
    pub dir: PathBuf,
    /// The studies this scene is a point of (none for a scene file of its own).
    pub studies: Vec<study::StudyPoint>,
}

const CREEPAGE_LIMIT: Range = Range::new(-1.0, true, 1.0, true);
const SPIN_LIMIT: Range = Range::new(-10.0, true, 10.0, true);
/// Any finite number (a sweep's parameter and direction; the points are checked).
const FINITE: Range = Range::new(f64::NEG_INFINITY, false, f64::INFINITY, false);
/// `[grid] scale`: the grid's extent in nominal semi-axes.
const GRID_SCALE: Range = Range::new(1.0, true, 10.0, true);

/// A number for a message: plain, or in exponent form when very large or small.
fn compact(v: f64) -> String {
    if v != 0.0 && !(1e-6..1e9).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

fn is_valid_name(s: &str) -> bool {
    !s.is_empty() && s.len() <= 100 && s.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
}

impl Scene {
    /// Read and validate a scene file.
    pub fn from_file(path: &Path) -> Result<Scene, InputError> {
        let text = crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "scene file")
            .map_err(|e| InputError::new("scene", path.display(), format!("a readable scene file (TOML): {e}")))?;
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
        let mut top = Section::new("", doc);

        let name = top.str("name", "a name of [a-z0-9_]+")?;
        if !is_valid_name(name) {
            return Err(InputError::new("name", format!("{name:?}"), "1 to 100 characters of [a-z0-9_]"));
        }
        let mut external = Vec::new();
        if let Some(mut ext) = top.opt_table("external")? {
            for key in ext.keys() {
                if !is_valid_name(&key) || crate::solvers::builtin(&key).is_some() {
                    return Err(InputError::new(
                        ext.field(&key),
                        format!("{key:?}"),
                        format!(
                            "an external solver name of [a-z0-9_]+ other than the built-in {}",
                            crate::solvers::builtin_names().join(", ")
                        ),
                    ));
                }
                let mut t = ext.table(&key)?;
                let command = t
                    .opt_str_list("command", "program and its arguments")?
                    .filter(|c| !c.is_empty())
                    .ok_or_else(|| {
                        InputError::new(
                            t.field("command"),
                            "missing or empty",
                            "a non-empty array: program and arguments",
                        )
                    })?;
                let timeout_s = t
                    .opt_f64("timeout_s", Range::new(0.0, false, 86400.0, true))?
                    .unwrap_or(crate::safety::process::DEFAULT_TIMEOUT.as_secs_f64());
                t.finish()?;
                external.push(ExternalSolver { name: key, command, timeout_s });
            }
            ext.finish()?;
        }
        let solver_names: Vec<String> = crate::solvers::builtin_names()
            .into_iter()
            .map(String::from)
            .chain(external.iter().map(|e| e.name.clone()))
            .collect();
        let allowed_solvers = format!("a non-empty list of distinct names from {}", solver_names.join(", "));
        let solvers = top
            .opt_str_list("solvers", &allowed_solvers)?
            .ok_or_else(|| InputError::new("solvers", "missing", allowed_solvers.clone()))?;
        if solvers.is_empty() {
            return Err(InputError::new("solvers", "[]", allowed_solvers));
        }
        for (n, s) in solvers.iter().enumerate() {
            if !solver_names.contains(s) || solvers[..n].contains(s) {
                return Err(InputError::new(format!("solvers[{n}]"), format!("{s:?}"), allowed_solvers));
            }
        }
        let metric_names = crate::metrics::names().join(", ");
        let metrics = top.opt_str_list("metrics", &format!("names from {metric_names}"))?;
        if let Some(ms) = &metrics {
            for (n, m) in ms.iter().enumerate() {
                if crate::metrics::by_name(m).is_none() || ms[..n].contains(m) {
                    return Err(InputError::new(
                        format!("metrics[{n}]"),
                        format!("{m:?}"),
                        format!("distinct names from {metric_names}"),
                    ));
                }
            }
        }

        // [grid] (first: a geometry per element fills it)
        let mut g = top.table("grid")?;
        let mx = g.usize("mx", 1, MAX_ELEMENTS_PER_AXIS)?;
        let my = g.usize("my", 1, MAX_ELEMENTS_PER_AXIS)?;
        let grid_scale = g.opt_f64("scale", GRID_SCALE)?.unwrap_or(1.0);
        let edge = Range::new(-1e4, true, 1e4, true);
        let extent = match (g.opt_f64_array::<2>("x_mm", edge)?, g.opt_f64_array::<2>("y_mm", edge)?) {
            (None, None) => Extent::Scale(grid_scale),
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
                Extent::Edges { x_mm, y_mm }
            }
            (x, _) => {
                let missing = if x.is_none() { "x_mm" } else { "y_mm" };
                return Err(InputError::new(
                    g.field(missing),
                    "missing",
                    "both edges x_mm = [x0, x1] and y_mm = [y0, y1], or neither",
                ));
            }
        };
        g.finish()?;

        // [geometry]: a contact given per element
        let element_geometry = match top.opt_table("geometry")? {
            Some(section) => Some(geometry::read(section, dir, (mx, my))?),
            None => None,
        };

        // [contact]
        let mut c = top.table("contact")?;
        let len = Range::new(0.0, false, 1e4, true);
        let geometry = if let Some(spec) = element_geometry {
            for k in ["a_mm", "b_mm", "r_wx_mm", "r_wy_mm", "r_ry_mm"] {
                c.refuse(k, "not with a [geometry] given per element (its contact follows from the normal problem)")?;
            }
            spec
        } else if c.has("a_mm") || c.has("b_mm") || !c.has("r_wx_mm") {
            let a_mm = c.f64("a_mm", len)?;
            let b_mm = c.f64("b_mm", len)?;
            for k in ["r_wx_mm", "r_wy_mm", "r_ry_mm"] {
                if c.has(k) {
                    return Err(InputError::new(
                        c.field(k),
                        "given",
                        "either a_mm and b_mm, or the radii r_wx_mm, r_wy_mm, r_ry_mm, not both",
                    ));
                }
            }
            GeometrySpec::SemiAxes { a_mm, b_mm }
        } else {
            let radius = Range::new(0.0, false, f64::INFINITY, true);
            GeometrySpec::Radii(Radii {
                r_wx_mm: c.f64("r_wx_mm", Range::new(0.0, false, 1e9, true))?,
                r_wy_mm: c.f64("r_wy_mm", radius)?,
                r_ry_mm: c.f64("r_ry_mm", radius)?,
            })
        };
        let fn_n = c.f64("fn_n", Range::new(0.0, false, 1e9, true))?;
        let mu = c.f64("mu", Range::new(0.0, false, 1e3, true))?;
        c.finish()?;

        // [material]
        let mut m = top.table("material")?;
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

        // [rolling]
        let (mut v_mm_s, mut courant) = (1000.0, 1.0);
        if let Some(mut r) = top.opt_table("rolling")? {
            v_mm_s = r.opt_f64("v_mm_s", Range::new(0.0, false, 1e6, true))?.unwrap_or(v_mm_s);
            courant = r.opt_f64("courant", Range::new(0.0, false, 100.0, true))?.unwrap_or(courant);
            r.finish()?;
        }

        // [creepage]
        let mut cr = top.table("creepage")?;
        let kind = cr.choice("kind", &["step", "sine", "sweep", "table"])?;
        let creepage = match kind {
            "step" => Creepage::Step {
                c: cr.f64("c", CREEPAGE_LIMIT)?,
                steps: cr.usize("steps", 1, HARD_MAX_STEPS)?,
                c_before: cr.opt_f64("c_before", CREEPAGE_LIMIT)?.unwrap_or(0.0),
            },
            "sine" => Creepage::Sine {
                c0: cr.f64("c0", CREEPAGE_LIMIT)?,
                cp: cr.f64("cp", CREEPAGE_LIMIT)?,
                freq_hz: cr.f64("freq_hz", Range::new(0.0, false, 1e6, true))?,
                periods: cr.f64("periods", Range::new(0.0, false, 1e4, true))?,
            },
            "sweep" => {
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
                let over = cr.opt_choice("over", &["cx", "cy", "cs"])?;
                let direction = match (over, cr.opt_f64_array::<3>("direction", FINITE)?) {
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
                    (Some("cy"), None) => [0.0, 1.0, 0.0],
                    (Some("cs"), None) => [0.0, 0.0, 1.0],
                    _ => [1.0, 0.0, 0.0],
                };
                let cx = cr.opt_f64("cx", CREEPAGE_LIMIT)?.unwrap_or(0.0);
                Creepage::Sweep { from, to, points, direction, cx, at }
            }
            _ => {
                let file = cr.str("file", "a CSV path relative to the scene file")?;
                let path = dir.join(file);
                let rows = table::CreepageTable::from_file(&path, &cr.field("file"))?;
                Creepage::Table { file: path, rows }
            }
        };
        if kind != "sweep" {
            let only_sweep = format!("only with kind = \"sweep\" (kind {kind:?} sets cx itself)");
            for key in ["cx", "over", "direction"] {
                cr.refuse(key, &only_sweep)?;
            }
        }
        let cy = cr.opt_f64("cy", CREEPAGE_LIMIT)?.unwrap_or(0.0);
        let cs_per_mm = cr.opt_f64("cs", SPIN_LIMIT)?.unwrap_or(0.0);
        cr.finish()?;

        // [init]
        let mut init = InitKind::Zero;
        if let Some(mut i) = top.opt_table("init")? {
            init = match i.opt_choice("kind", &["zero", "steady"])? {
                Some("steady") => InitKind::Steady,
                _ => InitKind::Zero,
            };
            i.finish()?;
        }

        // [model]
        let mut model = ModelOptions::default();
        if let Some(mut md) = top.opt_table("model")? {
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
            if let Some([k0, alpha, beta]) =
                md.opt_f64_array::<3>("slope_reduction", Range::new(0.0, true, 1e3, true))?
            {
                if !(k0 > 0.0 && (0.0..=1.0).contains(&alpha)) {
                    return Err(InputError::new(
                        md.field("slope_reduction"),
                        format!("[{k0}, {alpha}, {beta}]"),
                        "[k0, alpha, beta] with k0 > 0, 0 <= alpha <= 1, beta >= 0",
                    ));
                }
                model.slope_reduction = Some([k0, alpha, beta]);
            }
            if let Some(n) = md.opt_choice("flexibilities", &["three", "one"])? {
                model.single_flexibility = n == "one";
            }
            let unit = Range::new(0.0, false, 1.0, true);
            if let Some(v) = md.opt_f64("polach_k_a", unit)? {
                model.polach.k_a = v;
            }
            if let Some(v) = md.opt_f64("polach_k_s", unit)? {
                model.polach.k_s = v;
            }
            if let Some(v) = md.opt_f64("polach_a", unit)? {
                model.polach.a = v;
            }
            if let Some(v) = md.opt_f64("polach_b_s_per_m", Range::new(0.0, true, 1e3, true))? {
                model.polach.b_s_per_m = v;
            }
            model.relaxation_length_mm = md.opt_f64("relaxation_length_mm", Range::new(0.0, false, 1e4, true))?;
            if let Some(f) = md.opt_choice("nonhertz_flexibility", &["strip", "equivalent_ellipse"])? {
                model.nonhertz_flexibility =
                    if f == "strip" { PatchFlexibility::Strip } else { PatchFlexibility::EquivalentEllipse };
            }
            md.finish()?;
        }

        // [contact_solver]
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
            cs.finish()?;
        }
        // [limits]
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
        top.finish()?;

        let scene = Scene {
            name: name.to_string(),
            solvers,
            metrics,
            geometry,
            fn_n,
            mu,
            material: MaterialSpec { g_mpa, e_mpa, poisson },
            mx,
            my,
            grid_scale,
            extent,
            v_mm_s,
            courant,
            creepage,
            cy,
            cs_per_mm,
            init,
            model,
            contact_solver,
            external,
            limits,
            dir: dir.to_path_buf(),
            studies: Vec::new(),
        };
        scene.check_sweep_points()?;
        Ok(scene)
    }

    /// Creepage `[cx, cy, cs]` of sweep point k = 1..=points: `[cx, cy, cs] + t·direction`, t from
    /// `from` to `to` evenly or the k-th of `at` (`None` for the other kinds). A zero direction component keeps its
    /// constant and a zero constant gives d·t, bit for bit: the cx sweep gives exactly the
    /// cx = from + (to − from)·(k − 1)/(points − 1) of scenes written before `over`/`direction`.
    pub fn sweep_point(&self, k: usize) -> Option<[f64; 3]> {
        let Creepage::Sweep { from, to, points, direction, cx, at } = &self.creepage else {
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
        Some([add(*cx, direction[0]), add(self.cy, direction[1]), add(self.cs_per_mm, direction[2])])
    }

    /// Every sweep point within the creepage ranges. Evenly spaced points are monotone in t, so
    /// the first and the last (computed as they are sampled) bound them all and the error names
    /// the end; a list `at` is checked point by point and the error names the entry.
    fn check_sweep_points(&self) -> Result<(), InputError> {
        let Creepage::Sweep { from, to, points, at, .. } = &self.creepage else {
            return Ok(());
        };
        let checked: Vec<(usize, String, f64)> = match at {
            Some(list) => list.iter().enumerate().map(|(n, &t)| (n + 1, format!("at[{n}]"), t)).collect(),
            None if *points == 1 => vec![(1, "from".into(), *from)],
            None => vec![(1, "from".into(), *from), (*points, "to".into(), *to)],
        };
        for (k, key, t) in checked.iter().map(|(k, key, t)| (*k, key, t)) {
            let point = self.sweep_point(k).unwrap_or_default();
            let limits = [("cx", CREEPAGE_LIMIT), ("cy", CREEPAGE_LIMIT), ("cs", SPIN_LIMIT)];
            for ((name, range), v) in limits.iter().zip(point) {
                if !range.contains(v) {
                    return Err(InputError::new(
                        format!("creepage.{key}"),
                        format!("{} (sweep point {k}: {name} = {})", compact(*t), compact(v)),
                        format!(
                            "a sweep whose every point [cx, cy, cs] + t·direction has cx and cy {}, cs {} [1/mm]",
                            CREEPAGE_LIMIT.describe(),
                            SPIN_LIMIT.describe()
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
