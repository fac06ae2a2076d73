//! The loading of a scene sampled at its steps: step, sine, table (time histories) or sweep
//! (steady points), each sample carrying every loading quantity (creepages, FN, μ).

use crate::error::InputError;
use crate::scene::{Creepage, InitKind, Scene};

/// The loading at one instant (or one sweep point).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
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
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadingKind {
    Step,
    Sine,
    Table,
    Sweep,
}

/// The sampled loading of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Loading {
    pub kind: LoadingKind,
    /// Sine frequency [Hz] (sine kind only).
    pub freq_hz: Option<f64>,
    /// The state at t = 0 (transient kinds), from which `init` starts.
    pub initial: Option<Sample>,
    /// Steps k = 1..N (transient) or sweep points.
    pub samples: Vec<Sample>,
    pub init: InitKind,
}

impl Loading {
    /// Sample the scene's creepage history at `t_k = k dt`; warnings go to `warnings`.
    pub fn sample(scene: &Scene, dt_s: f64, warnings: &mut Vec<String>) -> Result<Loading, InputError> {
        let base =
            Sample { step: 0, t_s: 0.0, cx: 0.0, cy: scene.cy, cs: scene.cs_per_mm, fn_n: scene.fn_n, mu: scene.mu };
        let max = scene.limits.max_steps;
        let too_many = |n: f64| {
            InputError::new(
                "creepage",
                format!("{n:.0} steps"),
                format!("at most {max} steps or points (dt = {dt_s:e} s); [limits] max_steps raises the limit"),
            )
        };
        let (kind, freq_hz, initial, samples) = match &scene.creepage {
            Creepage::Step { c, steps, c_before } => {
                if *steps > max {
                    return Err(too_many(*steps as f64));
                }
                let s: Vec<Sample> =
                    (1..=*steps).map(|k| Sample { step: k, t_s: k as f64 * dt_s, cx: *c, ..base }).collect();
                (LoadingKind::Step, None, Some(Sample { cx: *c_before, ..base }), s)
            }
            Creepage::Sine { c0, cp, freq_hz, periods } => {
                let n = (periods / (freq_hz * dt_s)).ceil();
                if n > max as f64 {
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
                if *points > max {
                    return Err(too_many(*points as f64));
                }
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
                if n > max as f64 {
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
        Ok(Loading { kind, freq_hz, initial, samples, init: scene.init })
    }

    /// Whether the loading is a time history (not a steady sweep).
    pub fn is_transient(&self) -> bool {
        self.kind != LoadingKind::Sweep
    }

    /// Period of the sine creepage [s].
    pub fn period_s(&self) -> Option<f64> {
        self.freq_hz.map(|f| 1.0 / f)
    }

    /// The state a run starts from: the initial state, or the first sample of a sweep.
    pub fn first(&self) -> &Sample {
        self.initial.as_ref().unwrap_or(&self.samples[0])
    }

    /// The initial state when the run starts from steady rolling (a row with step 0).
    pub fn steady_start(&self) -> Option<&Sample> {
        self.initial.as_ref().filter(|_| self.init == InitKind::Steady && self.is_transient())
    }

    /// Every row a run writes, in order: the steady start (if any), then the samples.
    pub fn rows(&self) -> impl Iterator<Item = &Sample> {
        self.steady_start().into_iter().chain(&self.samples)
    }

    /// Largest μ over the rows (a table may vary it).
    pub fn mu_max(&self) -> f64 {
        self.rows().map(|s| s.mu).fold(0.0, f64::max)
    }
}
