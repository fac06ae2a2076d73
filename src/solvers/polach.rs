//! Polach's creep-force model (O. Polach, "Creep forces in simulations of traction vehicles
//! running on adhesion limit", Wear 258 (2005) 992–1000, Eq. 1–8): the resultant creep force
//! `F = 2 Q μ / π · (kA ε / (1 + (kA ε)²) + arctan(kS ε))` of the gradient of the tangential stress
//! in the adhesion area `ε = (2/3) C π a² b / (Q μ) · s`, with the contact shear stiffness from
//! Kalker's coefficients `C = 3 G / (8 a) · √((c11 sx/s)² + (c22 sy/s)²)` and the resultant
//! creepage `s = √(sx² + sy²)`; the components along the creepage, `Fx = F sx/s`, `Fy = F sy/s`.
//! Falling friction with the slip velocity `w = s V`: `μ = μ0 ((1 − A) e^(−B w) + A)`.
//! Spin enters through Kalker's lateral term as in the linear theory (`sy = cy + (ab)^½ c23/c22 cs`,
//! the equivalent lateral creepage), as multibody codes commonly do; Polach's own spin correction
//! is not applied. With kA = kS = 1 the curve has the linear theory's slope at s = 0 and tends to
//! μ as s grows. Steady, no memory. The model gives no spin moment: its `mz_nmm` is 0.

use super::stepper::{FieldView, Step, Stepper};
use super::termination::Termination;
use super::{closed_form, ModelDef, SolveError};
use crate::error::InputError;
use crate::problem::params::ParamValue;
use crate::problem::{ModelParams, Problem, Sample};
use crate::scene::keys::{key, Absent, Allowed, Keys};
use crate::scene::reader::{Range, Section};
use crate::solvers::style::{muted, Dash, Marker};
use std::f64::consts::PI;

/// Polach's model.
pub const MODEL: ModelDef = ModelDef {
    params: Some(read_params),
    ..closed_form(
        "polach",
        "Polach (Wear 258, 2005): resultant creep force 2Qμ/π (kA ε/(1+(kA ε)²) + atan(kS ε)), falling friction μ0((1−A)e^(−Bw)+A)",
        build,
        muted(5, Dash::DashDot, Marker::Plus),
    )
};

/// A reduction or ratio in (0, 1].
const UNIT: Allowed = Allowed::Number(Range::new(0.0, false, 1.0, true), "");

/// Polach's `[model]` keys (`<!-- keys:model -->`, after the scene's), their defaults
/// [`PolachParams::DEFAULT`].
pub const KEYS: Keys = Keys {
    id: "model",
    owner: file!(),
    keys: &[
        key(
            "polach_k_a",
            "–",
            UNIT,
            Absent::Num(PolachParams::DEFAULT.k_a),
            r#"Polach's reduction kA of the adhesion part: `polach_k_a = 0.6`"#,
        ),
        key(
            "polach_k_s",
            "–",
            UNIT,
            Absent::Num(PolachParams::DEFAULT.k_s),
            r#"Polach's reduction kS of the slip part: `polach_k_s = 0.4`"#,
        ),
        key(
            "polach_a",
            "–",
            UNIT,
            Absent::Num(PolachParams::DEFAULT.a),
            r#"Polach's falling friction, A = μ∞/μ0 in μ = μ0·((1 − A)·e^(−B·w) + A): `polach_a = 0.4`"#,
        ),
        key(
            "polach_b_s_per_m",
            "s/m",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Num(PolachParams::DEFAULT.b_s_per_m),
            r#"Polach's B, w = s·V the slip velocity: `polach_b_s_per_m = 0.6`"#,
        ),
    ],
};

/// Polach's parameters (`[model] polach_k_a, polach_k_s, polach_a, polach_b_s_per_m`; Wear 258
/// (2005) Eq. 1–8): the reductions of the adhesion and slip parts and the falling friction
/// `μ0 ((1 − A) e^(−B w) + A)`. Defaults: the unreduced curve with constant friction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PolachParams {
    pub k_a: f64,
    pub k_s: f64,
    /// μ∞/μ0.
    pub a: f64,
    /// B [s/m].
    pub b_s_per_m: f64,
}

impl PolachParams {
    /// The unreduced curve with constant friction.
    pub const DEFAULT: PolachParams = PolachParams { k_a: 1.0, k_s: 1.0, a: 1.0, b_s_per_m: 0.0 };

    /// Read and validate the scene's `[model] polach_*` keys (each optional: its default).
    pub fn read(md: &mut Section<'_>) -> Result<PolachParams, InputError> {
        Ok(PolachParams {
            k_a: md.num_or_default("polach_k_a")?,
            k_s: md.num_or_default("polach_k_s")?,
            a: md.num_or_default("polach_a")?,
            b_s_per_m: md.num_or_default("polach_b_s_per_m")?,
        })
    }
}

impl ModelParams for PolachParams {
    /// scene.json `model.polach = {k_a, k_s, a, b_s_per_m}`, left out at the defaults.
    fn scene_json(&self) -> Vec<(&'static str, ParamValue)> {
        if *self == PolachParams::DEFAULT {
            return Vec::new();
        }
        let fields = [("k_a", self.k_a), ("k_s", self.k_s), ("a", self.a), ("b_s_per_m", self.b_s_per_m)];
        vec![("polach", ParamValue::Record(fields.iter().map(|&(k, v)| (k.to_string(), v)).collect()))]
    }
}

fn read_params(md: &mut Section<'_>) -> Result<Box<dyn ModelParams>, InputError> {
    Ok(Box::new(PolachParams::read(md)?))
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let q = *p.model_params.get::<PolachParams>().unwrap_or(&PolachParams::DEFAULT);
    Ok(Box::new(Polach { p, q, a_mm: 0.0, b_mm: 0.0 }))
}

/// Polach's resultant force over μ Q for the stiffness ratio `eps` (Eq. 1) and reductions kA, kS.
/// An infinite `eps` (μ FN so small that the ratio overflows, a subnormal μ) takes the limit of
/// Eq. 1, full sliding: the adhesion term kA ε/(1 + (kA ε)²) → 0 (∞/∞ would be NaN).
pub fn resultant(eps: f64, k_a: f64, k_s: f64) -> f64 {
    let e = k_a * eps;
    let adhesion = if e.is_finite() { e / (1.0 + e * e) } else { 0.0 };
    2.0 / PI * (adhesion + (k_s * eps).atan())
}

/// The friction coefficient at slip velocity `w_m_s` [m/s] (Eq. 8): `μ0 ((1 − A) e^(−B w) + A)`.
pub fn falling_friction(mu0: f64, w_m_s: f64, q: &PolachParams) -> f64 {
    mu0 * ((1.0 - q.a) * (-q.b_s_per_m * w_m_s).exp() + q.a)
}

struct Polach<'a> {
    p: &'a Problem,
    q: PolachParams,
    /// The contact's semi-axes at the current load [mm].
    a_mm: f64,
    b_mm: f64,
}

impl Stepper for Polach<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        let e = self.p.geometry.ellipse_at(at.fn_n);
        (self.a_mm, self.b_mm) = (e.a_mm, e.b_mm);
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let (c, q, g) = (&self.p.coefficients, &self.q, self.p.material.g_mpa);
        let (a, b) = (self.a_mm, self.b_mm);
        let sx = at.cx;
        let sy = at.cy + (a * b).sqrt() * c.c23 / c.c22 * at.cs;
        let s = sx.hypot(sy);
        let (mut fx, mut fy) = (0.0, 0.0);
        if s > 0.0 {
            let mu = falling_friction(at.mu, s * at.speed_mm_s(self.p.rolling.v_mm_s) * 1e-3, q);
            let stiffness = 3.0 * g / (8.0 * a) * ((c.c11 * sx / s).powi(2) + (c.c22 * sy / s).powi(2)).sqrt();
            let eps = 2.0 / 3.0 * stiffness * PI * a * a * b / (at.fn_n * mu) * s;
            let f = mu * resultant(eps, q.k_a, q.k_s);
            (fx, fy) = (f * sx / s, f * sy / s);
        }
        Ok(Step { fx_over_fn: fx, fy_over_fn: fy, mz_nmm: 0.0, extra: Vec::new(), termination: Termination::Direct })
    }

    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Polach's curve: the slope 4/π at zero (kA = kS = 1: with ε's definition, the linear
    /// theory's), 1 as ε grows; kS < 1 lowers the slip part; falling friction A at w → ∞.
    #[test]
    fn polach_curve() {
        assert!((resultant(1e-8, 1.0, 1.0) / 1e-8 - 4.0 / PI).abs() < 1e-6);
        assert!((resultant(1e9, 1.0, 1.0) - 1.0).abs() < 1e-8);
        assert!(resultant(2.0, 1.0, 0.4) < resultant(2.0, 1.0, 1.0));
        let q = PolachParams { k_a: 1.0, k_s: 1.0, a: 0.4, b_s_per_m: 0.6 };
        assert_eq!(falling_friction(0.5, 0.0, &q), 0.5);
        assert!((falling_friction(0.5, 1e6, &q) - 0.2).abs() < 1e-12);
    }
}
