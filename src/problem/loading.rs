//! The loading of a scene sampled at its steps: step, sine, table (time histories) or sweep
//! (steady points), each sample carrying every loading quantity (creepages, FN, μ).

use crate::error::InputError;
use crate::physics::{ContactGeometry, Grid};
use crate::scene::table::{CreepageTable, Either, TableX};
use crate::scene::{compact, Creepage, InitKind, Scene};
use std::path::{Path, PathBuf};

/// A table covers step k when `k dt <= t_end (1 + TABLE_END_REL)`: its last time may be printed
/// rounded (10 significant digits are 5e-11 relative) and still cover the step it was written for.
pub const TABLE_END_REL: f64 = 1e-8;

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
    /// The rolling speed [mm/s] where it differs per row (a table's `v_mm_s`, a speed sweep);
    /// `None`: `[rolling] v_mm_s`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub v_mm_s: Option<f64>,
    /// The Courant number of this row's step where it differs per row (a table's `courant`:
    /// CONTACT's DQ changing within a history): the step rolls courant·dx; `None`: `[rolling] courant`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub courant: Option<f64>,
    /// Fx/FN prescribed (CONTACT F = 1, 2): the solver finds cx (which then holds 0, the start);
    /// `None`: cx is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fx_target: Option<f64>,
    /// Fy/FN prescribed (CONTACT F = 2): the solver finds cy; `None`: cy is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fy_target: Option<f64>,
    /// The approach [mm] prescribed (CONTACT N = 0, PEN): the solver finds FN (`fn_n` then holds
    /// the scene's nominal `contact.fn_n`); `None`: FN is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pen_mm: Option<f64>,
    /// The undeformed distance of this row, CONTACT's IBASE = 1 `h = b1 x² + b2 xy + b3 y² + b4 x
    /// + b5 y + b6` in CONTACT's coordinates, in place of the scene's geometry; `None`: the geometry's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub h_coefficients: Option<[f64; 6]>,
    /// The rolling direction CHI [deg] of this row where a table gives it (column `chi_deg`);
    /// `None`: `[rolling] chi_deg`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub chi_deg: Option<f64>,
}

impl Sample {
    /// A row with its creepages, FN and μ given and nothing prescribed in their place (the
    /// rolling speed the scene's).
    pub fn given(step: usize, t_s: f64, cx: f64, cy: f64, cs: f64, fn_n: f64, mu: f64) -> Sample {
        Sample {
            step,
            t_s,
            cx,
            cy,
            cs,
            fn_n,
            mu,
            v_mm_s: None,
            courant: None,
            fx_target: None,
            fy_target: None,
            pen_mm: None,
            h_coefficients: None,
            chi_deg: None,
        }
    }

    /// The rolling direction of this row [deg]: its own, else `rolling`'s.
    pub fn chi_deg_or(&self, rolling_chi_deg: f64) -> f64 {
        self.chi_deg.unwrap_or(rolling_chi_deg)
    }

    /// Whether a total force is prescribed in place of a creepage.
    pub fn prescribes_force(&self) -> bool {
        self.fx_target.is_some() || self.fy_target.is_some()
    }
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

/// The loading as the scene declares it (scene.json's `loading`): the creepage's kind and
/// parameters (a table by its rows) and the constants each row takes where the kind does not set
/// them. [`DeclaredLoading::sample`] gives its rows: the one sampling of a loading, for the models
/// and for whoever reads it back from scene.json.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DeclaredLoading {
    pub creepage: Creepage,
    /// `[creepage] cy`.
    pub cy: f64,
    /// `[creepage] fy_over_fn`: Fy/FN prescribed in place of cy.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fy_over_fn: Option<f64>,
    /// `[creepage] cs` [1/mm].
    pub cs_per_mm: f64,
    /// `[contact] fn_n` [N].
    pub fn_n: f64,
    /// `[contact] pen_mm`: the approach prescribed at every row [mm].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pen_mm: Option<f64>,
    /// `[contact] mu`.
    pub mu: f64,
    /// `[limits] max_steps`.
    pub max_steps: usize,
}

/// What sampling takes besides the declaration: the start, the time step and speed of
/// `[rolling]`, the grid's element length along x (a table's Courant column) and the table's
/// file (named in its errors).
#[derive(Debug, Clone, Copy)]
pub struct Stepping<'a> {
    pub init: InitKind,
    pub dt_s: f64,
    pub v_mm_s: f64,
    pub dx_mm: f64,
    pub file: &'a Path,
}

impl DeclaredLoading {
    /// The declaration of `scene` (a table without its file's path).
    pub fn of(scene: &Scene) -> DeclaredLoading {
        let mut creepage = scene.creepage.clone();
        if let Creepage::Table { file, .. } = &mut creepage {
            *file = PathBuf::new();
        }
        DeclaredLoading {
            creepage,
            cy: scene.cy,
            fy_over_fn: scene.fy_over_fn,
            cs_per_mm: scene.cs_per_mm,
            fn_n: scene.fn_n,
            pen_mm: scene.pen_mm,
            mu: scene.mu,
            max_steps: scene.limits.max_steps,
        }
    }

    /// The loading sampled at its steps: step, sine and table at t_k = k dt (a table with a
    /// speed or Courant column at its own steps), a sweep at its points.
    pub fn sample(&self, at: Stepping) -> Result<Loading, InputError> {
        let d = self;
        match &self.creepage {
            Creepage::Step { c, steps, c_before, fx_prescribed } => {
                step_history(d, at, *c, *c_before, *steps, *fx_prescribed)
            }
            Creepage::Sine { c0, cp, freq_hz, periods } => sine_history(d, at, *c0, *cp, *freq_hz, *periods),
            Creepage::Sweep { points, direction, fx_prescribed, .. } => {
                sweep_points(d, at, *points, *direction, *fx_prescribed)
            }
            Creepage::Table { rows, .. } if rows.v_mm_s.is_some() || rows.courant.is_some() => {
                speed_table_history(d, rows, at)
            }
            Creepage::Table { rows, .. } => table_history(d, rows, at),
        }
    }
}

/// The sampled loading of a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Loading {
    pub kind: LoadingKind,
    /// Sine frequency [Hz] (sine kind only).
    pub freq_hz: Option<f64>,
    /// The sweep's direction in (cx, cy, cs) (sweep kind only).
    pub sweep_direction: Option<[f64; 3]>,
    /// The state at t = 0 (transient kinds), from which `init` starts.
    pub initial: Option<Sample>,
    /// Steps k = 1..N (transient) or sweep points.
    pub samples: Vec<Sample>,
    pub init: InitKind,
}

impl Loading {
    /// Sample the scene's creepage history at `t_k = k dt`; warnings go to `warnings` (a table
    /// whose largest FN gives a contact beyond `grid`, `geometry`'s ellipse at that load).
    pub fn sample(
        scene: &Scene,
        dt_s: f64,
        geometry: &dyn ContactGeometry,
        grid: &Grid,
        warnings: &mut Vec<String>,
    ) -> Result<Loading, InputError> {
        check_approach_once(scene)?;
        let file = match &scene.creepage {
            Creepage::Table { file, .. } => file.as_path(),
            _ => Path::new(""),
        };
        let at = Stepping { init: scene.init, dt_s, v_mm_s: scene.v_mm_s, dx_mm: grid.dx_mm, file };
        let loading = DeclaredLoading::of(scene).sample(at)?;
        match &scene.creepage {
            Creepage::Sine { freq_hz, .. } => warn_aliased(*freq_hz, dt_s, warnings),
            Creepage::Table { rows, .. } if rows.v_mm_s.is_none() && rows.courant.is_none() => {
                warn_beyond_grid(scene, rows, geometry, grid, warnings)
            }
            _ => {}
        }
        loading.check_forces()?;
        Ok(loading)
    }

    /// A loading of `kind` with its rows, neither a sine's frequency nor a sweep's direction.
    fn of_rows(init: InitKind, kind: LoadingKind, initial: Option<Sample>, samples: Vec<Sample>) -> Loading {
        Loading { kind, freq_hz: None, sweep_direction: None, initial, samples, init }
    }

    /// Every row sampled, the initial state (when the loading has one) first.
    pub fn all_rows(self) -> Vec<Sample> {
        let mut rows = self.samples;
        if let Some(s0) = self.initial {
            rows.insert(0, s0);
        }
        rows
    }

    /// Whether any row prescribes a total force in place of a creepage (CONTACT F = 1, 2).
    pub fn prescribes_force(&self) -> bool {
        self.rows().any(Sample::prescribes_force)
    }

    /// What the rows give for the normal problem in place of FN or the scene's geometry, named
    /// for a model that cannot take it: the approach (CONTACT N = 0), the undeformed distance.
    pub fn normal_rows(&self) -> Option<&'static str> {
        if self.rows().any(|s| s.pen_mm.is_some()) {
            Some("the approach prescribed (creepage table column pen_mm)")
        } else if self.rows().any(|s| s.h_coefficients.is_some()) {
            Some("an undeformed distance per row (creepage table columns b1_per_mm to b6_mm)")
        } else {
            None
        }
    }

    /// Fy/FN is prescribed only with Fx/FN (CONTACT F = 2). A prescribed force must stay below μ·FN: at or above it the whole contact slides and no
    /// creepage gives it (Coulomb: |F| <= μ FN, reached only in full slip).
    fn check_forces(&self) -> Result<(), InputError> {
        if let Some(s) = self.rows().find(|s| s.fy_target.is_some() && s.fx_target.is_none()) {
            return Err(InputError::new(
                "creepage.fy_over_fn",
                format!("Fy/FN = {} with cx given (step {})", s.fy_target.unwrap_or_default(), s.step),
                "fy_over_fn only together with fx_over_fn (CONTACT F = 2; F = 1 prescribes Fx/FN with cy given)",
            ));
        }
        let Some(s) = self
            .rows()
            .find(|s| s.prescribes_force() && s.fx_target.unwrap_or(0.0).hypot(s.fy_target.unwrap_or(0.0)) >= s.mu)
        else {
            return Ok(());
        };
        let f = s.fx_target.unwrap_or(0.0).hypot(s.fy_target.unwrap_or(0.0));
        let field = if s.fx_target.is_some() { "creepage.fx_over_fn" } else { "creepage.fy_over_fn" };
        let at = match self.kind {
            LoadingKind::Sweep => format!("sweep point {}", s.step),
            _ => format!("step {} (t = {} s)", s.step, s.t_s),
        };
        Err(InputError::new(
            field,
            format!("|(Fx, Fy)|/FN = {f} at {at}"),
            format!("a prescribed force below mu = {} times FN: at or above it the whole contact slides and no creepage in partial slip gives it", s.mu),
        ))
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

    /// The initial state when the run starts from a shift (`[init] kind = "shift"`, a row with step 0).
    pub fn shift_start(&self) -> Option<&Sample> {
        self.initial.as_ref().filter(|_| self.init == InitKind::Shift && self.is_transient())
    }

    /// The initial state a run solves (steady or shift start; a row with step 0), if any.
    pub fn start(&self) -> Option<&Sample> {
        self.steady_start().or(self.shift_start())
    }

    /// Every row a run writes, in order: the start (if any), then the samples.
    pub fn rows(&self) -> impl Iterator<Item = &Sample> {
        self.start().into_iter().chain(&self.samples)
    }

    /// Largest μ over the rows (a table may vary it).
    pub fn mu_max(&self) -> f64 {
        self.rows().map(|s| s.mu).fold(0.0, f64::max)
    }
}

/// The error of a loading with `n` steps or points, more than `[limits] max_steps` (`max`).
fn too_many(n: f64, max: usize, dt_s: f64) -> InputError {
    InputError::new(
        "creepage",
        format!("{n:.0} steps"),
        format!("at most {max} steps or points (dt = {dt_s:e} s); [limits] max_steps raises the limit"),
    )
}

/// The approach `contact.pen_mm` is prescribed only where a creepage table gives neither fn_n nor pen_mm.
fn check_approach_once(scene: &Scene) -> Result<(), InputError> {
    if let (Some(pen_mm), Creepage::Table { rows, .. }) = (scene.pen_mm, &scene.creepage) {
        if rows.fn_n.is_some() || rows.pen_mm.is_some() {
            return Err(InputError::new(
                "contact.pen_mm",
                format!("{pen_mm} with a creepage table column fn_n or pen_mm"),
                "one of contact.pen_mm (the approach at every step) and the table's own fn_n or pen_mm column",
            ));
        }
    }
    Ok(())
}

/// A step: cx (or Fx/FN with `fx_prescribed`) = `c_before` at t = 0, then `c` at steps 1..=`steps`.
fn step_history(
    d: &DeclaredLoading,
    at: Stepping,
    c: f64,
    c_before: f64,
    steps: usize,
    fx_prescribed: bool,
) -> Result<Loading, InputError> {
    let (base, max, dt_s) = (Sample::nominal(d), d.max_steps, at.dt_s);
    if steps > max {
        return Err(too_many(steps as f64, max, dt_s));
    }
    let row = |k: usize, c: f64| match fx_prescribed {
        true => Sample { step: k, t_s: k as f64 * dt_s, fx_target: Some(c), ..base },
        false => Sample { step: k, t_s: k as f64 * dt_s, cx: c, ..base },
    };
    let s: Vec<Sample> = (1..=steps).map(|k| row(k, c)).collect();
    Ok(Loading::of_rows(at.init, LoadingKind::Step, Some(row(0, c_before)), s))
}

/// A sine: cx = c0 + cp sin(2π F t_k) over `periods` periods of F = `freq_hz`, c0 at t = 0.
fn sine_history(
    d: &DeclaredLoading,
    at: Stepping,
    c0: f64,
    cp: f64,
    freq_hz: f64,
    periods: f64,
) -> Result<Loading, InputError> {
    let (base, max, dt_s) = (Sample::nominal(d), d.max_steps, at.dt_s);
    let n = (periods / (freq_hz * dt_s)).ceil();
    if n > max as f64 {
        return Err(too_many(n, max, dt_s));
    }
    let w = 2.0 * std::f64::consts::PI * freq_hz;
    let s = (1..=n as usize)
        .map(|k| {
            let t = k as f64 * dt_s;
            Sample { step: k, t_s: t, cx: c0 + cp * (w * t).sin(), ..base }
        })
        .collect();
    let initial = Sample { cx: c0, ..base };
    Ok(Loading { freq_hz: Some(freq_hz), ..Loading::of_rows(at.init, LoadingKind::Sine, Some(initial), s) })
}

/// A warning where a sine's period has fewer than 3 steps.
fn warn_aliased(freq_hz: f64, dt_s: f64, warnings: &mut Vec<String>) {
    if 1.0 / (freq_hz * dt_s) < 3.0 {
        warnings.push(format!(
            "creepage.freq_hz = {freq_hz}: only {:.2} steps per period (dt = {dt_s:e} s); the history is aliased",
            1.0 / (freq_hz * dt_s)
        ));
    }
}

/// A sweep's `points` steady points along `direction` ([`Creepage::sweep_point`], [`Creepage::sweep_speed`]),
/// a force ratio prescribed in place of cx (`fx_prescribed`) or cy (the scene's `fy_over_fn`).
fn sweep_points(
    d: &DeclaredLoading,
    at: Stepping,
    points: usize,
    direction: [f64; 3],
    fx_prescribed: bool,
) -> Result<Loading, InputError> {
    let (base, max, dt_s) = (Sample::nominal(d), d.max_steps, at.dt_s);
    if points > max {
        return Err(too_many(points as f64, max, dt_s));
    }
    let s = (1..=points)
        .map(|k| {
            let [x, y, cs] = d.creepage.sweep_point(k, d.fy_over_fn.unwrap_or(d.cy), d.cs_per_mm).unwrap_or_default();
            // A force ratio prescribed in place of a creepage: the creepage starts at 0.
            let (cx, fx_target) = if fx_prescribed { (0.0, Some(x)) } else { (x, None) };
            let (cy, fy_target) = if d.fy_over_fn.is_some() { (0.0, Some(y)) } else { (y, None) };
            let v_mm_s = d.creepage.sweep_speed(k);
            Sample { step: k, t_s: 0.0, cx, cy, cs, v_mm_s, fx_target, fy_target, ..base }
        })
        .collect();
    Ok(Loading { sweep_direction: Some(direction), ..Loading::of_rows(at.init, LoadingKind::Sweep, None, s) })
}

/// A table with a speed or Courant column: its steps of [`speed_table`], its speed and Courant
/// number at t = 0 in the initial state.
fn speed_table_history(d: &DeclaredLoading, rows: &CreepageTable, at: Stepping) -> Result<Loading, InputError> {
    let samples = speed_table(d, rows, at)?;
    let initial = Sample {
        v_mm_s: rows.v_mm_s.as_ref().map(|v| rows.interpolate(v, 0.0)),
        courant: rows.courant.as_ref().map(|c| rows.interpolate(c, 0.0)),
        ..table_row(d, rows, 0, 0.0)
    };
    Ok(Loading::of_rows(at.init, LoadingKind::Table, Some(initial), samples))
}

/// A table at t_k = k dt up to its last time ([`table_steps`]).
fn table_history(d: &DeclaredLoading, rows: &CreepageTable, at: Stepping) -> Result<Loading, InputError> {
    let (max, dt_s) = (d.max_steps, at.dt_s);
    let n = table_steps(rows.end_s(), dt_s);
    if n > max as f64 {
        return Err(too_many(n, max, dt_s));
    }
    let row = |k: usize| table_row(d, rows, k, k as f64 * dt_s);
    if n < 1.0 {
        return Err(InputError::new(
            "creepage.file",
            format!("table ending at t = {} s", rows.end_s()),
            format!("a table reaching at least one step, t >= dt = {dt_s:e} s (within {TABLE_END_REL:e} relative)"),
        ));
    }
    Ok(Loading::of_rows(at.init, LoadingKind::Table, Some(row(0)), (1..=n as usize).map(row).collect()))
}

/// A warning where a table's largest FN gives an ellipse of `geometry` beyond the grid's
/// half-extents, with the smallest `[grid] scale` that covers it.
fn warn_beyond_grid(
    scene: &Scene,
    rows: &CreepageTable,
    geometry: &dyn ContactGeometry,
    grid: &Grid,
    warnings: &mut Vec<String>,
) {
    let Some(fn_max) =
        rows.fn_n.as_ref().filter(|_| geometry.elliptic()).map(|f| f.iter().fold(0.0, |a: f64, &b| a.max(b)))
    else {
        return;
    };
    let (e, nominal) = (geometry.ellipse_at(fn_max), geometry.nominal());
    let fits = |semi: f64, half: f64| semi <= half * (1.0 + 1e-12);
    if !(fits(e.a_mm, grid.half_x_mm) && fits(e.b_mm, grid.half_y_mm)) {
        // The smallest scale (rounded up to 0.001) whose grid holds that ellipse.
        let need = (e.a_mm / nominal.a_mm).max(e.b_mm / nominal.b_mm);
        let need = (need * 1000.0 * (1.0 + 1e-9)).ceil() / 1000.0;
        warnings.push(format!(
            "creepage table: fn_n up to {fn_max} N gives a contact of a = {:.4} mm, b = {:.4} mm, beyond the grid's half-extents {:.4} x {:.4} mm ([grid] scale = {} times the ellipse at contact.fn_n = {} N); the contact is clipped to the grid: [grid] scale = {need} or more covers it",
            e.a_mm, e.b_mm, grid.half_x_mm, grid.half_y_mm, scene.grid_scale, scene.fn_n
        ));
    }
}

/// The table's loading at step k, time `t` (columns it lacks: the scene's constants).
fn table_row(scene: &DeclaredLoading, rows: &CreepageTable, k: usize, t: f64) -> Sample {
    let get = |s: &Option<Vec<f64>>, d: f64| s.as_ref().map_or(d, |v| rows.interpolate(v, t));
    // Per row one of the creepage and the force: the row's ([`CreepageTable::either_at`]).
    let given_or_force = |c: &[f64], f: &[f64]| match rows.either_at(c, f, t) {
        Either::First(c) => (c, None),
        Either::Second(f) => (0.0, Some(f)),
    };
    let (cx, fx_target) = match &rows.cx {
        TableX::Creepage(cx) => (rows.interpolate(cx, t), None),
        TableX::Force(fx) => (0.0, Some(rows.interpolate(fx, t))),
        TableX::PerRow { cx, fx_over_fn } => given_or_force(cx, fx_over_fn),
    };
    // A column (cy or fy_over_fn) replaces the constant (cy or fy_over_fn).
    let (cy, fy_target) = match (&rows.cy, &rows.fy_over_fn) {
        (Some(cy), Some(fy)) => given_or_force(cy, fy),
        (Some(cy), _) => (rows.interpolate(cy, t), None),
        (None, Some(fy)) => (0.0, Some(rows.interpolate(fy, t))),
        (None, None) => (scene.cy, scene.fy_over_fn),
    };
    let (fn_n, pen_mm) = rows.normal_at(t, scene.fn_n);
    // A table without fn_n or pen_mm takes the scene's approach where it prescribes one.
    let pen_mm = pen_mm.or(scene.pen_mm);
    Sample {
        step: k,
        t_s: t,
        cx,
        cy,
        cs: get(&rows.cs, scene.cs_per_mm),
        fn_n,
        mu: get(&rows.mu, scene.mu),
        v_mm_s: None,
        courant: None,
        fx_target,
        fy_target,
        pen_mm,
        h_coefficients: rows.h_coefficients.as_ref().map(|b| b.each_ref().map(|v| rows.interpolate(v, t))),
        chi_deg: rows.chi_deg.as_ref().map(|v| rows.held(v, t)),
    }
}

/// Iterations allowed to find a step's speed in a table with `v_mm_s`.
const SPEED_ITERATIONS: usize = 200;

/// A table with a speed or Courant column: step k rolls dq_k (`[rolling]`'s dq, or the table's
/// courant_k·dx) and lasts dq_k/v_k, t_k = t_(k−1) + dq_k/v_k with v_k, dq_k the table's at t_k
/// (CONTACT's VELOC and DQ of the case, reference/contact_friction/README.md "How the histories
/// are formed"); (v_k, dq_k) is the fixed point of (v, dq) = (V, DQ)(t_(k−1) + dq/v), reached while
/// they change by less than themselves per step.
fn speed_table(scene: &DeclaredLoading, rows: &CreepageTable, at: Stepping) -> Result<Vec<Sample>, InputError> {
    let (dq_mm, dx_mm, max) = (at.dt_s * at.v_mm_s, at.dx_mm, scene.max_steps);
    let speed = |t: f64| rows.v_mm_s.as_ref().map_or(at.v_mm_s, |v| rows.interpolate(v, t));
    let step = |t: f64| rows.courant.as_ref().map_or(dq_mm, |c| rows.interpolate(c, t) * dx_mm);
    let end = rows.end_s() * (1.0 + TABLE_END_REL);
    let (mut t, mut samples) = (0.0, Vec::new());
    loop {
        let (mut v, mut dq) = (speed(t), step(t));
        let mut settled = false;
        for _ in 0..SPEED_ITERATIONS {
            let (next_v, next_dq) = (speed(t + dq / v), step(t + dq / v));
            settled = (next_v - v).abs() <= 1e-14 * v && (next_dq - dq).abs() <= 1e-14 * dq;
            (v, dq) = (next_v, next_dq);
            if settled {
                break;
            }
        }
        if !settled {
            return Err(unsettled_step(at.file, rows, t, (v, dq)));
        }
        let t_next = t + dq / v;
        if t_next > end {
            break;
        }
        if samples.len() >= max {
            return Err(InputError::new(
                "creepage",
                format!("more than {max} steps"),
                "at most [limits] max_steps steps; [limits] max_steps raises the limit",
            ));
        }
        t = t_next;
        samples.push(Sample {
            v_mm_s: rows.v_mm_s.is_some().then_some(v),
            courant: rows.courant.as_ref().map(|c| rows.interpolate(c, t)),
            ..table_row(scene, rows, samples.len() + 1, t)
        });
    }
    if samples.is_empty() {
        return Err(InputError::new(
            "creepage.file",
            format!("table ending at t = {} s", rows.end_s()),
            "a table reaching at least one step, t >= dq / v",
        ));
    }
    Ok(samples)
}

/// The step from `t` of a table with a speed or Courant column whose (v, dq) does not settle
/// ([`speed_table`]; `(v, dq)` the last iterate): names the table's file and those of its columns
/// it has, and the table's rows around `t` by their times.
fn unsettled_step(file: &Path, rows: &CreepageTable, t: f64, (v, dq): (f64, f64)) -> InputError {
    let file = file.display().to_string();
    let columns: Vec<&str> = [("v_mm_s", rows.v_mm_s.is_some()), ("courant", rows.courant.is_some())]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect();
    let ts = &rows.t_s;
    let next = ts.partition_point(|&x| x <= t).min(ts.len() - 1);
    let (lo, hi) = (ts[next.saturating_sub(1)], ts[next]);
    let near = if lo < hi {
        format!("the rows at t_s = {} and {} s", compact(lo), compact(hi))
    } else {
        format!("the row at t_s = {} s", compact(hi))
    };
    InputError::new(
        format!("creepage.file ({file}) column {}", columns.join(", ")),
        near,
        format!(
            "a speed and a Courant number that change by less than themselves within one step dq/v (the step from t = {} s does not settle: v = {} mm/s, dq = {} mm)",
            compact(t),
            compact(v),
            compact(dq)
        ),
    )
}

impl Sample {
    /// The scene's loading at t = 0: contact.fn_n (and the approach `contact.pen_mm` where
    /// prescribed), μ, the constant cy and cs, cx = 0.
    pub fn nominal(scene: &DeclaredLoading) -> Sample {
        Sample {
            fy_target: scene.fy_over_fn,
            pen_mm: scene.pen_mm,
            ..Sample::given(0, 0.0, 0.0, scene.cy, scene.cs_per_mm, scene.fn_n, scene.mu)
        }
    }

    /// The rolling speed of this row [mm/s]: its own, else `rolling`'s.
    pub fn speed_mm_s(&self, rolling_v_mm_s: f64) -> f64 {
        self.v_mm_s.unwrap_or(rolling_v_mm_s)
    }
}

/// Steps a table ending at `t_end_s` covers: the largest n with `n dt <= t_end (1 + TABLE_END_REL)`.
fn table_steps(t_end_s: f64, dt_s: f64) -> f64 {
    let end = t_end_s * (1.0 + TABLE_END_REL);
    let n = (end / dt_s).floor();
    // The division rounds (by less than one step): settle n on the times the samples use, k dt.
    if n >= 1.0 && n * dt_s > end {
        n - 1.0
    } else if (n + 1.0) * dt_s <= end {
        n + 1.0
    } else {
        n
    }
}

/// A column of the per-step loading as a file or a table gives it (an external model's
/// `loading.csv`, the Python package's `loading`): its name and a row's value (`None`: empty).
pub struct LoadingColumn {
    pub name: &'static str,
    pub value: fn(&Sample) -> Option<f64>,
    /// Written only where some row gives it.
    pub optional: bool,
}

/// The loading's columns: those of a history (step, t_s, cx, cy, cs, fn_n, mu), then what a row
/// prescribes or carries of its own (speed, Courant number, forces, approach, CHI, undeformed distance).
pub const LOADING_COLUMNS: [LoadingColumn; 19] = [
    LoadingColumn { name: "step", value: |s| Some(s.step as f64), optional: false },
    LoadingColumn { name: "t_s", value: |s| Some(s.t_s), optional: false },
    LoadingColumn { name: "cx", value: |s| Some(s.cx), optional: false },
    LoadingColumn { name: "cy", value: |s| Some(s.cy), optional: false },
    LoadingColumn { name: "cs", value: |s| Some(s.cs), optional: false },
    LoadingColumn { name: "fn_n", value: |s| Some(s.fn_n), optional: false },
    LoadingColumn { name: "mu", value: |s| Some(s.mu), optional: false },
    LoadingColumn { name: "v_mm_s", value: |s| s.v_mm_s, optional: true },
    LoadingColumn { name: "courant", value: |s| s.courant, optional: true },
    LoadingColumn { name: "fx_target", value: |s| s.fx_target, optional: true },
    LoadingColumn { name: "fy_target", value: |s| s.fy_target, optional: true },
    LoadingColumn { name: "pen_mm", value: |s| s.pen_mm, optional: true },
    LoadingColumn { name: "chi_deg", value: |s| s.chi_deg, optional: true },
    LoadingColumn { name: "b1_per_mm", value: |s| s.h_coefficients.map(|b| b[0]), optional: true },
    LoadingColumn { name: "b2_per_mm", value: |s| s.h_coefficients.map(|b| b[1]), optional: true },
    LoadingColumn { name: "b3_per_mm", value: |s| s.h_coefficients.map(|b| b[2]), optional: true },
    LoadingColumn { name: "b4", value: |s| s.h_coefficients.map(|b| b[3]), optional: true },
    LoadingColumn { name: "b5", value: |s| s.h_coefficients.map(|b| b[4]), optional: true },
    LoadingColumn { name: "b6_mm", value: |s| s.h_coefficients.map(|b| b[5]), optional: true },
];

/// The columns `rows` give: every history column, and each optional one some row has.
pub fn loading_columns(rows: &[Sample]) -> Vec<&'static LoadingColumn> {
    LOADING_COLUMNS.iter().filter(|c| !c.optional || rows.iter().any(|s| (c.value)(s).is_some())).collect()
}

/// `rows` as CSV: the header of [`loading_columns`], one line per row, each number in its shortest
/// form that reads back to the same value, an empty cell where a row leaves a column out.
pub fn write_loading_csv(rows: &[Sample], out: &mut dyn std::io::Write) -> std::io::Result<()> {
    let columns = loading_columns(rows);
    let names: Vec<&str> = columns.iter().map(|c| c.name).collect();
    writeln!(out, "{}", names.join(","))?;
    for s in rows {
        for (k, c) in columns.iter().enumerate() {
            if k > 0 {
                out.write_all(b",")?;
            }
            if let Some(v) = (c.value)(s) {
                write!(out, "{v}")?;
            }
        }
        out.write_all(b"\n")?;
    }
    Ok(())
}

#[cfg(test)]
mod loading_csv_tests {
    use super::*;

    /// The history's loading columns always, an optional one where some row gives it (an empty
    /// cell where a row does not), each number in its shortest round-trip form.
    #[test]
    fn loading_csv_has_the_history_columns_and_what_rows_give() {
        let a = Sample::given(0, 0.0, 0.1, -0.0, 1e-300, 1e5, 0.4);
        let b = Sample { v_mm_s: Some(2500.5), ..Sample::given(1, 0.004, 0.2, 0.0, 0.0, 1e5, 0.3) };
        let mut out = Vec::new();
        write_loading_csv(&[a, b], &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "step,t_s,cx,cy,cs,fn_n,mu,v_mm_s");
        assert_eq!(lines[2], "1,0.004,0.2,0,0,100000,0.3,2500.5");
        let cells: Vec<&str> = lines[1].split(',').collect();
        assert_eq!((cells[3], cells[7]), ("-0", ""));
        assert_eq!(cells[4].parse::<f64>().unwrap(), 1e-300);
    }
}
