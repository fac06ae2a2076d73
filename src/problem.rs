//! Step 2 of the pipeline: the resolved problem. Hertz, Kalker's coefficients, the grid, the
//! time step and the sampled creepage history, computed once from a validated scene and handed
//! to every solver unchanged ("identical grids").

use crate::error::InputError;
use crate::physics::{Coefficients, Flexibilities, Grid, HertzContact, Material};
use crate::scene::{ContactSolverOptions, Creepage, ExternalSolver, Geometry, InitKind, ModelOptions, Scene};
use std::path::PathBuf;

/// Largest number of time steps (or sweep points) one scene may ask for.
pub const MAX_STEPS: usize = 2_000_000;

/// The loading at one instant (or one sweep point).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Sample {
    /// Step index: 0 = the initial state at t = 0, k ≥ 1 = after step k (sweeps: point index from 1).
    pub step: usize,
    pub t_s: f64,
    pub cx: f64,
    pub cy: f64,
    /// Spin creepage [1/mm].
    pub cs: f64,
    pub fn_n: f64,
    pub mu: f64,
}

/// Transient history or steady sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadingKind {
    Step,
    Sine,
    Table,
    Sweep,
}

/// Contact quantities at one load: the ellipse, its flexibilities and the simplified models'
/// pressure on the grid. Recomputed only when the load changes (table kind).
#[derive(Debug, Clone)]
pub struct LocalContact {
    pub hertz: HertzContact,
    pub flex: Flexibilities,
    /// Pressure of the simplified models [MPa] per element (`[model] pressure`).
    pub pressure_mpa: Vec<f64>,
}

/// Everything a solver needs, resolved once.
#[derive(Debug, Clone)]
pub struct Problem {
    pub name: String,
    pub solvers: Vec<String>,
    pub metrics: Vec<String>,
    /// Metrics the scene left out, with the reason (for the report).
    pub skipped_metrics: Vec<(String, String)>,
    /// The contact at the scene's nominal load.
    pub hertz: HertzContact,
    pub mu: f64,
    pub material: Material,
    pub grid: Grid,
    pub v_mm_s: f64,
    pub courant: f64,
    pub dt_s: f64,
    /// Rolling distance per step [mm] = courant·dx.
    pub dq_mm: f64,
    pub model: ModelOptions,
    pub coefficients: Coefficients,
    pub kind: LoadingKind,
    /// Sine frequency [Hz] (sine kind only).
    pub freq_hz: Option<f64>,
    /// The state at t = 0 (transient kinds), from which `init` starts.
    pub initial: Option<Sample>,
    /// Steps k = 1..N (transient) or sweep points.
    pub samples: Vec<Sample>,
    pub init: InitKind,
    pub contact_solver: ContactSolverOptions,
    pub external: Vec<ExternalSolver>,
    pub scene_dir: PathBuf,
    pub warnings: Vec<String>,
}

impl Problem {
    /// Resolve a validated scene.
    pub fn resolve(scene: &Scene) -> Result<Problem, InputError> {
        let material = match (scene.material.g_mpa, scene.material.e_mpa) {
            (Some(g), Some(e)) => Material { g_mpa: g, poisson: scene.material.poisson, e_mpa: e },
            (Some(g), None) => Material::from_g(g, scene.material.poisson),
            (None, Some(e)) => Material::from_e(e, scene.material.poisson),
            (None, None) => unreachable!("validated by the scene reader"),
        };
        let hertz = match &scene.geometry {
            Geometry::SemiAxes { a_mm, b_mm } => HertzContact { a_mm: *a_mm, b_mm: *b_mm, fn_n: scene.fn_n },
            Geometry::Radii(r) => HertzContact::from_radii(r, scene.fn_n, &material).map_err(|e| {
                InputError::new("contact.r_wx_mm", format!("{r:?}"), format!("radii of a convex contact ({e})"))
            })?,
        };
        let mut warnings = Vec::new();
        let ratio = hertz.b_mm / hertz.a_mm;
        if scene.model.coefficients == crate::physics::CoefficientSource::Fit {
            if !(1.0 / 25.0..=25.0).contains(&ratio) {
                return Err(InputError::new("model.coefficients", "\"fit\"", format!("the fit Eq. 2.36 holds for 1/25 <= b/a <= 25; this contact has b/a = {ratio:.4}: use \"table\"")));
            }
            if (scene.material.poisson - 0.27).abs() > 0.02 {
                warnings.push(format!(
                    "model.coefficients = fit was made for poisson 0.27, scene has {}",
                    scene.material.poisson
                ));
            }
        }
        if scene.model.coefficients == crate::physics::CoefficientSource::Table && !(0.1..=10.0).contains(&ratio) {
            warnings.push(format!(
                "b/a = {ratio:.4} is beyond Kalker's Table A1 (0.1 … 10): c11, c22, c23 are extrapolated"
            ));
        }
        let coefficients = Coefficients::new(scene.model.coefficients, hertz.a_mm, hertz.b_mm, material.poisson);
        let grid = Grid::new(scene.mx, scene.my, hertz.a_mm, hertz.b_mm);
        let dq_mm = scene.courant * grid.dx_mm;
        let dt_s = dq_mm / scene.v_mm_s;
        let base =
            Sample { step: 0, t_s: 0.0, cx: 0.0, cy: scene.cy, cs: scene.cs_per_mm, fn_n: scene.fn_n, mu: scene.mu };
        let too_many = |n: f64| {
            InputError::new("creepage", format!("{n:.0} steps"), format!("at most {MAX_STEPS} steps (dt = {dt_s:e} s)"))
        };
        let (kind, freq_hz, initial, samples) = match &scene.creepage {
            Creepage::Step { c, steps, c_before } => {
                let s: Vec<Sample> =
                    (1..=*steps).map(|k| Sample { step: k, t_s: k as f64 * dt_s, cx: *c, ..base }).collect();
                (LoadingKind::Step, None, Some(Sample { cx: *c_before, ..base }), s)
            }
            Creepage::Sine { c0, cp, freq_hz, periods } => {
                let n = (periods / (freq_hz * dt_s)).ceil();
                if n > MAX_STEPS as f64 {
                    return Err(too_many(n));
                }
                let w = 2.0 * std::f64::consts::PI * freq_hz;
                let s = (1..=n as usize)
                    .map(|k| {
                        let t = k as f64 * dt_s;
                        Sample { step: k, t_s: t, cx: c0 + cp * (w * t).sin(), ..base }
                    })
                    .collect();
                if 1.0 / (freq_hz * dt_s) < 3.0 {
                    warnings.push(format!(
                        "creepage.freq_hz = {freq_hz}: only {:.2} steps per period (dt = {dt_s:e} s); the history is aliased",
                        1.0 / (freq_hz * dt_s)
                    ));
                }
                (LoadingKind::Sine, Some(*freq_hz), Some(Sample { cx: *c0, ..base }), s)
            }
            Creepage::Sweep { from, to, points } => {
                let s = (1..=*points)
                    .map(|k| {
                        let f = if *points > 1 { (k - 1) as f64 / (*points - 1) as f64 } else { 0.0 };
                        Sample { step: k, t_s: 0.0, cx: from + (to - from) * f, ..base }
                    })
                    .collect();
                (LoadingKind::Sweep, None, None, s)
            }
            Creepage::Table { rows, .. } => {
                let n = (rows.end_s() / dt_s + 1e-9).floor();
                if n > MAX_STEPS as f64 {
                    return Err(too_many(n));
                }
                let at = |k: usize| {
                    let t = k as f64 * dt_s;
                    let get = |s: &Option<Vec<f64>>, d: f64| s.as_ref().map_or(d, |v| rows.interpolate(v, t));
                    Sample {
                        step: k,
                        t_s: t,
                        cx: rows.interpolate(&rows.cx, t),
                        cy: get(&rows.cy, scene.cy),
                        cs: get(&rows.cs, scene.cs_per_mm),
                        fn_n: get(&rows.fn_n, scene.fn_n),
                        mu: get(&rows.mu, scene.mu),
                    }
                };
                if n < 1.0 {
                    return Err(InputError::new(
                        "creepage.file",
                        format!("table ending at t = {} s", rows.end_s()),
                        format!("a table reaching at least one step, t >= dt = {dt_s:e} s"),
                    ));
                }
                if let Some(f) = &rows.fn_n {
                    if f.iter().any(|&x| x > scene.fn_n * (1.0 + 1e-12)) {
                        warnings.push(format!("creepage table: fn_n exceeds contact.fn_n = {} N; the grid covers the nominal ellipse only, so larger contacts are clipped to it", scene.fn_n));
                    }
                }
                (LoadingKind::Table, None, Some(at(0)), (1..=n as usize).map(at).collect())
            }
        };
        let (metrics, skipped_metrics) = select_metrics(scene, kind, freq_hz, samples.len(), dt_s);
        Ok(Problem {
            name: scene.name.clone(),
            solvers: scene.solvers.clone(),
            metrics,
            skipped_metrics,
            hertz,
            mu: scene.mu,
            material,
            grid,
            v_mm_s: scene.v_mm_s,
            courant: scene.courant,
            dt_s,
            dq_mm,
            model: scene.model,
            coefficients,
            kind,
            freq_hz,
            initial,
            samples,
            init: scene.init,
            contact_solver: scene.contact_solver,
            external: scene.external.clone(),
            scene_dir: scene.dir.clone(),
            warnings,
        })
    }

    /// The contact at load `fn_n` (the ellipse scales with FN^(1/3), coefficients do not change).
    pub fn local_contact(&self, fn_n: f64) -> LocalContact {
        let hertz = if fn_n == self.hertz.fn_n { self.hertz } else { self.hertz.at_load(fn_n) };
        let flex =
            Flexibilities::new(self.model.flexibility, &self.coefficients, hertz.a_mm, hertz.b_mm, &self.material);
        let pressure_mpa = self.model.pressure.on_grid(&self.grid, fn_n, hertz.a_mm, hertz.b_mm);
        LocalContact { hertz, flex, pressure_mpa }
    }

    /// Flexibilities at the nominal load.
    pub fn flexibilities(&self) -> Flexibilities {
        Flexibilities::new(self.model.flexibility, &self.coefficients, self.hertz.a_mm, self.hertz.b_mm, &self.material)
    }

    /// Peak of the simplified models' pressure at the nominal load [MPa].
    pub fn pressure_peak_mpa(&self) -> f64 {
        self.model.pressure.peak_mpa(self.hertz.fn_n, self.hertz.a_mm, self.hertz.b_mm)
    }

    /// Whether the creepage history is a transient (time-marching) one.
    pub fn is_transient(&self) -> bool {
        self.kind != LoadingKind::Sweep
    }

    /// Period of the sine creepage [s].
    pub fn period_s(&self) -> Option<f64> {
        self.freq_hz.map(|f| 1.0 / f)
    }
}

/// Metrics a scene gets: those it asks for that its kind supports, or by default those that fit.
fn select_metrics(
    scene: &Scene,
    kind: LoadingKind,
    freq: Option<f64>,
    n: usize,
    dt_s: f64,
) -> (Vec<String>, Vec<(String, String)>) {
    let fits = |m: &str| -> Result<(), String> {
        match m {
            "delay_ratio" | "loop_area" => {
                let Some(f) = freq else {
                    return Err("needs a sine creepage".into());
                };
                let periods = n as f64 * dt_s * f;
                let need = if m == "delay_ratio" { 2.0 } else { 1.0 };
                if periods + 1e-9 < need {
                    return Err(format!("needs at least {need} periods, the history has {periods:.2}"));
                }
                Ok(())
            }
            "settling_time_s" if kind != LoadingKind::Step => Err("step creepage only".into()),
            "oscillation_index" if kind == LoadingKind::Sweep => Err("time histories only".into()),
            _ => Ok(()),
        }
    };
    let (mut take, mut skip) = (Vec::new(), Vec::new());
    match &scene.metrics {
        Some(asked) => {
            for m in asked {
                match fits(m) {
                    Ok(()) => take.push(m.clone()),
                    Err(why) => skip.push((m.clone(), why)),
                }
            }
            for m in crate::scene::METRICS {
                if !asked.iter().any(|a| a == m) {
                    skip.push((m.to_string(), "not listed by the scene".into()));
                }
            }
        }
        None => {
            for m in crate::scene::METRICS {
                match fits(m) {
                    Ok(()) => take.push(m.to_string()),
                    Err(why) => skip.push((m.to_string(), why)),
                }
            }
        }
    }
    (take, skip)
}
