//! A first-order relaxation (lag) of the steady creep force, the usual way multibody codes add
//! unsteadiness: `dF/dq = (F_ss(c) − F)/L` per component along the rolling distance q (`dq = V dt`),
//! with the relaxation length of the linear theory, creep coefficient over tangential contact
//! stiffness (the spring of the contact in series with Kalker's creep "damper"):
//! `Lx = G a b C11 / kx`, `Ly = G a b C22 / ky`, k Mindlin's full-adhesion stiffness of the ellipse
//! ([`crate::physics::HertzContact::tangential_stiffness_n_mm`]; Johnson 1985, ch. 7), or
//! `[model] relaxation_length_mm` for both. The steady law F_ss is FASTSIM on the scene's grid: its
//! slope is the linear theory's (Kalker's flexibilities), so the lag is the only difference from the
//! steady model that the transient brush (UBA) extends.
//! A transient step integrates the lag exactly with F_ss held at the step's creepage (its value at
//! the end of the step): `F_k = F_ss,k + (F_{k−1} − F_ss,k) e^(−V dt/L)`; from zero traction a
//! constant creepage gives `F_ss (1 − e^(−V t/L))` at every step. The steady start and sweep
//! points give F_ss (no memory). The state is the force vector [N]: it is carried across a change
//! of FN (the coefficient is F/FN at the new load, L follows the new ellipse) and, like the steady
//! law, kept within μ FN (physics/bound.rs) after every step and every change of FN or μ.
//! The source gives no relaxation length for the spin moment: mz_nmm is FASTSIM's at the step's
//! creepage, not lagged.
//! With a falling friction law the steady law is FASTSIM's with the falling bound (physics::friction)
//! and the force is kept within the static value μ_s(0) FN: the lag acts on the steady force of the
//! creepage, with no feedback of the slip velocity into the lag, so this model cannot show the
//! falling branch's instability in time (the UBA and the exact solver can).

use super::stepper::{FieldView, Step, Stepper};
use super::termination::Termination;
use super::{always, fastsim, linear_in_elements, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::{project_to_bound, LinearTheory};
use crate::problem::params::ParamValue;
use crate::problem::{ModelParams, Problem, Sample};
use crate::scene::keys::{key, Absent, Allowed, Keys};
use crate::scene::reader::{Range, Section};

/// The relaxation model's `[model]` key (`<!-- keys:model -->`, after the scene's).
pub const KEYS: Keys = Keys {
    id: "model",
    owner: file!(),
    keys: &[key(
        "relaxation_length_mm",
        "mm",
        Allowed::Number(Range::new(0.0, false, 1e4, true), ""),
        Absent::Text("the linear theory's"),
        r#"the relaxation model's length for both components instead of Lx = G·a·b·C11/kx, Ly = G·a·b·C22/ky (Mindlin's tangential stiffness), fixed whatever the load: `relaxation_length_mm = 8.466`"#,
    )],
};
use crate::solvers::style::{muted, Dash, Marker};

/// The relaxation (lag) model.
pub const MODEL: ModelDef = ModelDef {
    name: "relaxation",
    summary: "First-order relaxation of FASTSIM's steady force, dF/dq = (F_ss − F)/L, L = creep coefficient / Mindlin's tangential stiffness (Lx = G ab C11/kx, Ly = G ab C22/ky)",
    extra_columns: &[],
    iterative: false,
    prescribed_forces: false,
    shifts: false,
    normal_rows: false,
    own_normal: None,
    check: always,
    cost_per_row: linear_in_elements,
    params: Some(read_params),
    build,
    style: muted(7, Dash::LongDash, Marker::Star),
};

/// The relaxation model's parameter: `[model] relaxation_length_mm`, one length [mm] for both
/// components instead of the linear theory's (`None`: the linear theory's).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RelaxationParams {
    pub length_mm: Option<f64>,
}

impl RelaxationParams {
    /// Read and validate `[model] relaxation_length_mm` (optional).
    pub fn read(md: &mut Section<'_>) -> Result<RelaxationParams, InputError> {
        Ok(RelaxationParams { length_mm: md.opt_num("relaxation_length_mm")? })
    }
}

impl ModelParams for RelaxationParams {
    /// scene.json `model.relaxation_length_mm`, left out when not given.
    fn scene_json(&self) -> Vec<(&'static str, ParamValue)> {
        self.length_mm.map(|l| ("relaxation_length_mm", ParamValue::Number(l))).into_iter().collect()
    }
}

fn read_params(md: &mut Section<'_>) -> Result<Box<dyn ModelParams>, InputError> {
    Ok(Box::new(RelaxationParams::read(md)?))
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let first = p.loading.first();
    Ok(Box::new(Relaxation {
        p,
        steady_law: (fastsim::MODEL.build)(p)?,
        lengths_mm: relaxation_lengths_mm(p, first.fn_n),
        force_n: (0.0, 0.0),
        fn_n: first.fn_n,
    }))
}

/// Relaxation lengths (Lx, Ly) [mm] at load `fn_n`: `[model] relaxation_length_mm` for both, else
/// the linear theory's, `G a b C11 / kx` and `G a b C22 / ky` of the contact's ellipse at that load
/// (the equivalent ellipse on a contact given per element).
pub fn relaxation_lengths_mm(p: &Problem, fn_n: f64) -> (f64, f64) {
    if let Some(l) = p.model_params.get::<RelaxationParams>().and_then(|r| r.length_mm) {
        return (l, l);
    }
    let e = p.geometry.ellipse_at(fn_n);
    // The linear forces at unit creepages [N]: G a b C11 and G a b C22.
    let (fx_n, fy_n, _) =
        LinearTheory::new(p.material.g_mpa, e.a_mm, e.b_mm, 1.0).forces(&p.coefficients, (1.0, 1.0, 0.0));
    let (kx, ky) = e.tangential_stiffness_n_mm(&p.material);
    (fx_n / kx, fy_n / ky)
}

struct Relaxation<'a> {
    p: &'a Problem,
    steady_law: Box<dyn Stepper + 'a>,
    /// (Lx, Ly) at the current load [mm].
    lengths_mm: (f64, f64),
    /// The lagged tangential force (Fx, Fy) [N].
    force_n: (f64, f64),
    /// The current load [N].
    fn_n: f64,
}

impl Relaxation<'_> {
    fn step(&self, mz_nmm: f64) -> Step {
        Step {
            fx_over_fn: self.force_n.0 / self.fn_n,
            fy_over_fn: self.force_n.1 / self.fn_n,
            mz_nmm,
            extra: Vec::new(),
            termination: Termination::Direct,
        }
    }

    /// Keep the force within μ FN.
    fn bound(&mut self, mu: f64) {
        let (x, y, _) = project_to_bound(self.force_n.0, self.force_n.1, mu * self.fn_n);
        self.force_n = (x, y);
    }
}

impl Stepper for Relaxation<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        self.steady_law.load(at)?;
        if at.fn_n != self.fn_n {
            self.lengths_mm = relaxation_lengths_mm(self.p, at.fn_n);
            self.fn_n = at.fn_n;
        }
        self.bound(at.mu);
        Ok(())
    }

    /// The steady law's value itself (no memory); the state becomes its force.
    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let s = self.steady_law.steady(at)?;
        self.force_n = (s.fx_over_fn * self.fn_n, s.fy_over_fn * self.fn_n);
        Ok(Step { extra: Vec::new(), ..s })
    }

    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let s = self.steady_law.steady(at)?;
        let dq = self.p.rolling.dq_mm;
        let (rx, ry) = ((-dq / self.lengths_mm.0).exp(), (-dq / self.lengths_mm.1).exp());
        let (sx, sy) = (s.fx_over_fn * self.fn_n, s.fy_over_fn * self.fn_n);
        self.force_n = (sx + (self.force_n.0 - sx) * rx, sy + (self.force_n.1 - sy) * ry);
        self.bound(at.mu);
        Ok(self.step(s.mz_nmm))
    }

    /// The lag acts on the total force: there is no traction field.
    fn field(&self) -> Option<FieldView<'_>> {
        None
    }
}
