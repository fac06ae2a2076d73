//! Step 2 of the pipeline: the resolved problem. The contact geometry, Kalker's coefficients,
//! the grid, the rolling step and the sampled loading, computed once from a validated scene and
//! handed to every solver unchanged ("identical grids"). Grouped by concern as CONTACT's problem
//! data: material, geometry, grid, rolling, loading, model options, solver options.

pub mod loading;
pub mod params;
pub mod resolved;

pub use loading::{DeclaredLoading, Loading, LoadingKind, Sample, Stepping};
pub use params::{ModelParamSet, ModelParams};
pub use resolved::ResolvedScene;

use crate::error::InputError;
use crate::physics::geometry::Extent;
use crate::physics::{
    CoefficientSource, Coefficients, ContactGeometry, Flexibilities, FrictionLaw, Grid, HertzContact, Material, Memory,
    PatchFlexibility, Planform,
};
use crate::scene::{
    ContactSolverOptions, Creepage, ExternalSolver, Limits, ModelOptions, Motion, NormalOptions, Scene,
};
use std::path::PathBuf;
use std::sync::Arc;

/// Largest relative difference between a given E and 2 G (1 + ν) when both are given.
pub const E_G_TOLERANCE: f64 = 1e-3;

/// The simplified models' contact at one load: planform and flexibilities.
#[derive(Debug, Clone)]
pub struct LocalContact {
    pub planform: Planform,
    pub flex: Flexibilities,
    /// Per grid row, the rigid slip's factor over `flex` (`L/L(y)`; 1 on an ellipse and with
    /// uniform flexibilities, [`crate::physics::PatchFlexibility`]).
    pub row_gain: Vec<f64>,
    /// `Some(√(ab))` [mm] when the simplified models use Kalker's single flexibility
    /// ([`Flexibilities::single_mm3_n`]).
    pub single_flexibility: Option<f64>,
    /// The modified FASTSIM's slope reduction at this load, if the scene asks for it.
    pub slope: Option<crate::physics::SlopeReduction>,
}

/// Rolling: speed and the rolling distance per time step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    pub v_mm_s: f64,
    /// Courant number V dt / dx.
    pub courant: f64,
    pub dt_s: f64,
    /// Rolling distance per step [mm] = courant·dx.
    pub dq_mm: f64,
    /// Rolling, or shifts without rolling (the creepages then shifts per step).
    pub motion: Motion,
    /// The rolling direction CHI [deg] in [0, 360): 0 (+x), 180 (-x, CONTACT's CHI = 180°), any
    /// angle in transient rolling.
    pub chi_deg: f64,
}

impl Rolling {
    /// Whether the bodies roll along -x (CHI = 180°).
    pub fn backward(&self) -> bool {
        self.chi_deg == 180.0
    }
}

/// A contact given per element: every load of the history gives a normal contact (else an input
/// error naming the load), and a contact that reaches the grid's edge is cut by it (a warning
/// with the share of the load there).
fn check_loads(
    geometry: &dyn ContactGeometry,
    loading: &Loading,
    warnings: &mut Vec<String>,
) -> Result<(), InputError> {
    let mut loads: Vec<f64> = loading.rows().map(|s| s.fn_n).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup();
    let mut worst = (0.0, 0.0);
    for fn_n in loads {
        let share = geometry.edge_load_share(fn_n);
        if !share.is_finite() || geometry.planform_error(fn_n).is_some() {
            let why = geometry.planform_error(fn_n).map_or_else(|| "a non-finite pressure".into(), |e| e.to_string());
            return Err(InputError::new(
                "contact.fn_n",
                fn_n,
                format!("a load the geometry's normal problem can carry on this grid ({why})"),
            ));
        }
        if share > worst.1 {
            worst = (fn_n, share);
        }
    }
    if worst.1 > 0.0 {
        warnings.push(format!(
            "the contact reaches the grid's edge: at FN = {} N, {:.3} % of the load sits on boundary elements; widen [grid] x_mm, y_mm so the grid holds the contact",
            worst.0,
            100.0 * worst.1
        ));
    }
    Ok(())
}

/// The parts of a problem computed from the scene (not copied): material, contact, grid,
/// coefficients, rolling step, sampled loading, and the warnings met on the way.
struct Physics {
    material: Material,
    geometry: Arc<dyn ContactGeometry>,
    coefficients: Coefficients,
    grid: Grid,
    rolling: Rolling,
    loading: Loading,
    warnings: Vec<String>,
}

impl Physics {
    /// Compute a scene's physics in order: material, geometry and grid, coefficients, rolling
    /// step, loading, and (a contact given per element) the loads checked against the grid.
    fn resolve(scene: &Scene) -> Result<Physics, InputError> {
        let material = material_of(scene)?;
        let (geometry, grid) = scene.geometry.build(scene.fn_n, &material, (scene.mx, scene.my), scene.extent)?;
        let mut warnings = Vec::new();
        let coefficients = coefficients_of(scene, &geometry.nominal(), &material, &mut warnings)?;
        let rolling = rolling_of(scene, grid.dx_mm);
        let loading = Loading::sample(scene, rolling.dt_s, geometry.as_ref(), &grid, &mut warnings)?;
        if !geometry.elliptic() {
            check_loads(geometry.as_ref(), &loading, &mut warnings)?;
        }
        Ok(Physics { material, geometry, coefficients, grid, rolling, loading, warnings })
    }
}

/// The scene's material from G or E (or both, consistent within [`E_G_TOLERANCE`]) and ν.
fn material_of(scene: &Scene) -> Result<Material, InputError> {
    if let Some(b) = scene.material.blanco {
        return Err(InputError::new(
            "material.blanco_variant",
            b.variant,
            "absent in a contact-patch scene: Blanco's correction takes a wheel–rail scene's conformal rows (their inclinations)",
        ));
    }
    material_of_spec(&scene.material)
}

/// A `[material]` table's material from G or E (or both, consistent within [`E_G_TOLERANCE`]) and ν.
pub fn material_of_spec(m: &crate::scene::MaterialSpec) -> Result<Material, InputError> {
    let elastic = if let Some(bodies) = m.bodies {
        Material::from_bodies(bodies)
    } else {
        match (m.g_mpa, m.e_mpa) {
            (Some(g), Some(e)) => material_of_g_and_e(g, e, m.poisson)?,
            (Some(g), None) => Material::from_g(g, m.poisson),
            (None, Some(e)) => Material::from_e(e, m.poisson),
            (None, None) => return Err(InputError::new("material.g_mpa", "missing", "g_mpa or e_mpa")),
        }
    };
    Ok(Material {
        layer: m.layer,
        visco: m.visco,
        heat: m.heat,
        sheet_mm3_per_n: m.sheet_mm3_per_n,
        blanco: m.blanco,
        ..elastic
    })
}

/// A material given both G and E: they must agree, E = 2G(1 + ν) within [`E_G_TOLERANCE`].
fn material_of_g_and_e(g_mpa: f64, e_mpa: f64, poisson: f64) -> Result<Material, InputError> {
    // E = 2G(1 + ν) for an isotropic material; the thesis's own Table 4.1 pair
    // (G 82000, E 210000, ν 0.28) is 4e-4 off, a rounding of the printed values.
    let from_g_mpa = 2.0 * g_mpa * (1.0 + poisson);
    if ((e_mpa - from_g_mpa) / from_g_mpa).abs() > E_G_TOLERANCE {
        return Err(InputError::new(
            "material.e_mpa",
            e_mpa,
            format!(
                "E = 2 G (1 + poisson) = {from_g_mpa} within {E_G_TOLERANCE:e} relative, or only one of g_mpa and e_mpa"
            ),
        ));
    }
    Ok(Material { e_mpa, ..Material::from_g(g_mpa, poisson) })
}

/// Kalker's coefficients at the nominal contact `hertz`, from the source the scene names; its
/// range checked (the fit's b/a an error, its ν and the table's extrapolation warnings).
fn coefficients_of(
    scene: &Scene,
    hertz: &HertzContact,
    material: &Material,
    warnings: &mut Vec<String>,
) -> Result<Coefficients, InputError> {
    let ratio = hertz.b_mm / hertz.a_mm;
    if scene.model.coefficients == CoefficientSource::Fit {
        check_fit(ratio, scene.material.poisson, warnings)?;
    }
    if scene.model.coefficients == CoefficientSource::Table && !(0.1..=10.0).contains(&ratio) {
        warnings
            .push(format!("b/a = {ratio:.4} is beyond Kalker's Table A1 (0.1 … 10): c11, c22, c23 are extrapolated"));
    }
    Ok(Coefficients::new(scene.model.coefficients, hertz.a_mm, hertz.b_mm, material.poisson))
}

/// The fit Eq. 2.36's range: b/a within 1/25 … 25 (else an error), ν near 0.27 (else a warning).
fn check_fit(ratio: f64, poisson: f64, warnings: &mut Vec<String>) -> Result<(), InputError> {
    if !(1.0 / 25.0..=25.0).contains(&ratio) {
        return Err(InputError::new(
            "model.coefficients",
            "\"fit\"",
            format!("the fit Eq. 2.36 holds for 1/25 <= b/a <= 25; this contact has b/a = {ratio:.4}: use \"table\""),
        ));
    }
    if (poisson - 0.27).abs() > 0.02 {
        warnings.push(format!("model.coefficients = fit was made for poisson 0.27, scene has {poisson}"));
    }
    Ok(())
}

/// The rolling step on a grid of element length `dx_mm`: dq = courant·dx, dt = dq / V.
fn rolling_of(scene: &Scene, dx_mm: f64) -> Rolling {
    let dq_mm = scene.courant * dx_mm;
    let dt_s = dq_mm / scene.v_mm_s;
    Rolling { v_mm_s: scene.v_mm_s, courant: scene.courant, dt_s, dq_mm, motion: scene.motion, chi_deg: scene.chi_deg }
}

/// The grid's edges [mm] when the scene gives them (`[grid] x_mm, y_mm`), else `None`.
fn grid_edges_mm(extent: Extent) -> Option<([f64; 2], [f64; 2])> {
    match extent {
        Extent::Edges { x_mm, y_mm } => Some((x_mm, y_mm)),
        Extent::Scale(_) => None,
    }
}

/// Everything a solver needs, resolved once.
#[derive(Debug, Clone)]
pub struct Problem {
    pub name: String,
    pub solvers: Vec<String>,
    /// The metrics computed (chosen by the pipeline from the scene's and the loading).
    pub metrics: Vec<String>,
    /// Metrics the scene left out, with the reason (for the report).
    pub skipped_metrics: Vec<(String, String)>,
    pub material: Material,
    pub geometry: Arc<dyn ContactGeometry>,
    pub coefficients: Coefficients,
    pub grid: Grid,
    /// The grid's extent in nominal semi-axes (`[grid] scale`, default 1).
    pub grid_scale: f64,
    /// The grid's edges in CONTACT's coordinates when the scene gives them (`[grid] x_mm, y_mm`).
    pub grid_edges: Option<([f64; 2], [f64; 2])>,
    pub rolling: Rolling,
    /// The friction law every model takes its bound from (`[friction]`; Coulomb by default).
    pub friction: FrictionLaw,
    /// The friction memory (none by default).
    pub memory: Memory,
    /// Coulomb's μ per grid row (`[friction] mu_rows`, CONTACT V = 3); `None`: one μ.
    pub friction_rows: Option<crate::physics::RowFriction>,
    /// The extra rigid slip `(wx, wy)` per element in the grid's order (`[creepage] extra_slip`,
    /// CONTACT's EXRHS); `None`: none.
    pub extra_slip: Option<(Vec<f64>, Vec<f64>)>,
    /// The scene's nominal loading (contact.fn_n, contact.mu, the constant cy and cs).
    pub nominal: Sample,
    /// The loading as the scene declared it (scene.json's `loading`), of which `loading` is the sampling.
    pub declared: DeclaredLoading,
    pub loading: Loading,
    pub model: ModelOptions,
    /// Each model's own parameters, read and validated once ([`params`]).
    pub model_params: ModelParamSet,
    pub contact_solver: ContactSolverOptions,
    /// The exact solver's normal problem: solved or Hertz's pressure imposed (`[normal]`).
    pub normal: NormalOptions,
    pub external: Vec<ExternalSolver>,
    pub limits: Limits,
    pub scene_dir: PathBuf,
    /// The studies the scene is a point of ([`crate::scene::study`]).
    pub studies: Vec<crate::scene::study::StudyPoint>,
    /// The CONTACT deck and cases the scene was imported from (the scene's `[origin]`).
    pub origin: Option<crate::scene::Origin>,
    /// Where the report shows the scene (the scene's `[report] group`).
    pub report_group: crate::scene::report::ReportGroup,
    /// The subsurface points and steps of the scene's `[stress]`, if any.
    pub stress: Option<crate::scene::stress::StressPoints>,
    pub warnings: Vec<String>,
}

impl Problem {
    /// Resolve a validated scene whose model names (`solvers`, checked against the registry) and
    /// models' parameters are given; its metrics are chosen after (the pipeline wires the three).
    pub fn resolve(scene: &Scene, solvers: Vec<String>, model_params: ModelParamSet) -> Result<Problem, InputError> {
        let physics = Physics::resolve(scene)?;
        let problem = Problem::assemble(scene, solvers, model_params, physics);
        problem.check_derived()?;
        problem.check_sweep_speeds(scene)?;
        Ok(problem)
    }

    /// A speed sweep's speeds (`over = "v_mm_s"`) within `[rolling] v_mm_s`'s range, its lower
    /// bound included: a time step courant dx / v that is finite ([`Self::check_derived`]). The
    /// error names the entry of `at` or the end (`from`, `to`).
    fn check_sweep_speeds(&self, scene: &Scene) -> Result<(), InputError> {
        let Creepage::Sweep { at, speed: true, .. } = &scene.creepage else {
            return Ok(());
        };
        for (k, v) in self.loading.samples.iter().filter_map(|s| Some((s.step, s.v_mm_s?))) {
            let dt_s = self.rolling.dq_mm / v;
            if dt_s.is_finite() && dt_s > 0.0 {
                continue;
            }
            let key = match at {
                Some(_) => format!("at[{}]", k - 1),
                None if k == 1 => "from".into(),
                None => "to".into(),
            };
            return Err(InputError::new(
                format!("creepage.{key}"),
                format!("{v:e} (sweep point {k}: dt = {dt_s:e} s)"),
                "a speed sweep's speeds as [rolling] v_mm_s: in (0, 1e6] mm/s with a finite time step courant dx / v",
            ));
        }
        Ok(())
    }

    /// The problem of `scene` from its resolved physics and the scene's settings, copied as given;
    /// no metrics yet.
    fn assemble(scene: &Scene, solvers: Vec<String>, model_params: ModelParamSet, physics: Physics) -> Problem {
        let declared = DeclaredLoading::of(scene);
        let order = |w: &[f64]| crate::physics::geometry::field_in_grid_order(&physics.grid, w);
        let extra_slip = scene.extra_slip.as_ref().map(|[wx, wy]| (order(wx), order(wy)));
        Problem {
            name: scene.name.clone(),
            solvers,
            metrics: Vec::new(),
            skipped_metrics: Vec::new(),
            material: physics.material,
            geometry: physics.geometry,
            coefficients: physics.coefficients,
            grid: physics.grid,
            grid_scale: scene.grid_scale,
            grid_edges: grid_edges_mm(scene.extent),
            rolling: physics.rolling,
            friction: scene.friction,
            memory: scene.memory,
            friction_rows: scene.friction_rows.clone(),
            extra_slip,
            nominal: Sample::nominal(&declared),
            declared,
            loading: physics.loading,
            model: scene.model,
            model_params,
            contact_solver: scene.contact_solver,
            normal: scene.normal,
            external: scene.external.clone(),
            limits: scene.limits,
            scene_dir: scene.dir.clone(),
            studies: scene.studies.clone(),
            origin: scene.origin.clone(),
            report_group: scene.report_group,
            stress: scene.stress.clone(),
            warnings: physics.warnings,
        }
    }

    /// Quantities derived from valid inputs can still be absurd (an axis ratio of 1e-20, a speed
    /// of 5e-324 mm/s): refuse them here, naming the input, before anything is computed.
    fn check_derived(&self) -> Result<(), InputError> {
        let h = self.hertz();
        let c = &self.coefficients;
        let f = self.flexibilities();
        let positive = |v: &[f64]| v.iter().all(|x| x.is_finite() && *x > 0.0);
        if !positive(&[h.a_mm, h.b_mm, h.p0_mpa(), self.grid.dx_mm, self.grid.dy_mm]) {
            return Err(InputError::new(
                "contact",
                format!("a = {} mm, b = {} mm, p0 = {} MPa", h.a_mm, h.b_mm, h.p0_mpa()),
                "a contact whose semi-axes, element sizes and peak pressure are finite and positive",
            ));
        }
        if !positive(&[c.c11, c.c22, c.c23, f.l1_mm3_n, f.l2_mm3_n, f.l3_mm3_n]) {
            return Err(InputError::new("contact.b_mm", format!("b/a = {:e}", h.b_mm / h.a_mm), format!("an axis ratio for which Kalker's coefficients and the flexibilities are finite and positive (c11 {}, c22 {}, c23 {})", c.c11, c.c22, c.c23)));
        }
        let t_end = self.loading.samples.last().map_or(0.0, |s| s.t_s);
        if !(positive(&[self.rolling.dt_s, self.rolling.dq_mm]) && t_end.is_finite()) {
            return Err(InputError::new(
                "rolling.v_mm_s",
                format!("{:e}", self.rolling.v_mm_s),
                format!(
                    "a speed for which the time step courant dx / v and the history's times are finite (dt = {:e} s)",
                    self.rolling.dt_s
                ),
            ));
        }
        self.check_shift()
    }

    /// Shifts without rolling have no steady state (the traction of a shift stays where it is):
    /// a transient history from rest only.
    fn check_shift(&self) -> Result<(), InputError> {
        if self.rolling.motion != Motion::Shift {
            return Ok(());
        }
        if !self.loading.is_transient() {
            return Err(InputError::new(
                "rolling.motion",
                "\"shift\"",
                "a transient loading (creepage.kind step, sine or table): shifts have no steady state, so no sweep",
            ));
        }
        if self.loading.steady_start().is_some() {
            return Err(InputError::new(
                "rolling.motion",
                "\"shift\" with init.kind = \"steady\"",
                "shifts from rest: leave init.kind at its default (zero traction)",
            ));
        }
        Ok(())
    }

    /// The contact ellipse at the nominal load.
    pub fn hertz(&self) -> HertzContact {
        self.geometry.nominal()
    }

    /// The simplified models' contact at load `fn_n`.
    pub fn local_contact(&self, fn_n: f64) -> LocalContact {
        self.local_contact_of(self.geometry.planform(&self.grid, fn_n, self.model.pressure))
    }

    /// `local` made for load `fn_n` if it was made for another load; whether it was remade.
    pub fn reload_local(&self, local: &mut LocalContact, fn_n: f64) -> bool {
        let stale = fn_n != local.planform.ellipse.fn_n;
        if stale {
            *local = self.local_contact(fn_n);
        }
        stale
    }

    /// The simplified models' contact on a planform found otherwise (an approximate normal
    /// problem's, [`crate::physics::approximate`]).
    pub fn local_contact_of(&self, planform: Planform) -> LocalContact {
        let flex = self.flexibilities_of(&planform.ellipse);
        let strips = !self.geometry.elliptic() && self.model.nonhertz_flexibility == PatchFlexibility::Strip;
        let a_mm = planform.ellipse.a_mm;
        let row_gain =
            planform.half_length_mm.iter().map(|&h| if strips && h > 0.0 { a_mm / h } else { 1.0 }).collect();
        let e = &planform.ellipse;
        let single_flexibility = self.model.single_flexibility.then(|| (e.a_mm * e.b_mm).sqrt());
        let slope = self.model.slope_reduction.map(|[k0, alpha, beta]| crate::physics::SlopeReduction {
            k0,
            alpha,
            beta,
            eps_scale: self.material.g_mpa * std::f64::consts::PI * e.a_mm * e.b_mm * k0 * self.coefficients.c11
                / (4.0 * e.fn_n),
            a_mm: e.a_mm,
        });
        LocalContact { planform, flex, row_gain, single_flexibility, slope }
    }

    /// Flexibilities of the simplified models for an ellipse (thesis Eq. 2.35 or 3.5).
    pub fn flexibilities_of(&self, e: &HertzContact) -> Flexibilities {
        Flexibilities::new(self.model.flexibility, &self.coefficients, e.a_mm, e.b_mm, &self.material)
    }

    /// Flexibilities at the nominal load.
    pub fn flexibilities(&self) -> Flexibilities {
        self.flexibilities_of(&self.hertz())
    }
}
