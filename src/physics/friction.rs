//! The friction law every model takes its traction bound from: Coulomb's constant μ, CONTACT's
//! friction falling with the local slip velocity s [mm/s] (laws L = 2, 3, 4 of `m_friclaw.f90`),
//! with an optional friction memory (`m_stang.f90` lines 310-335; reference/contact_friction/README.md),
//! or its friction varying with the surface temperature (L = 6, [`TemperatureLaw`]).

use serde::{Deserialize, Serialize};

/// ln 2, the exponential law's half-value scale (`m_friclaw.f90` line 436).
const LN_2: f64 = std::f64::consts::LN_2;

/// A friction law μ_s(s): the coefficient of steady sliding at slip velocity s [mm/s].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "lowercase")]
pub enum FrictionLaw {
    /// Coulomb: μ_s(s) = μ for every s (CONTACT L = 0 with FSTAT = FKIN).
    Coulomb { mu: f64 },
    /// L = 2: FKIN + F1 max(0, 1 − s/(2 S1)) + F2 max(0, 1 − s/(2 S2)).
    Linear(FallingTerms),
    /// L = 3: FKIN + F1/(1 + s/S1) + F2/(1 + (s/S2)²).
    Rational(FallingTerms),
    /// L = 4: FKIN + F1 exp(−ln2 s/S1) + F2 exp(−ln2 s/S2).
    Exponential(FallingTerms),
    /// L = 6: μ of the surface temperature ([`TemperatureLaw`]); in the slip velocity it is
    /// constant, FREF (`fric_veldep_mu_steady`, `m_friclaw.f90` line 442).
    Temperature(TemperatureLaw),
}

/// CONTACT's friction of the surface temperature T [°C] (L = 6, user guide sec. "Temperature
/// dependent friction", eq. mu_T): FREF up to TREF, linear by DFHEAT over DTHEAT, FREF + DFHEAT above.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TemperatureLaw {
    /// μ at low temperatures, μ_ref (FREF).
    pub fref: f64,
    /// The temperature where μ starts changing, T_ref [°C] (TREF).
    pub tref_c: f64,
    /// The change of μ from T_ref to T_ref + ΔT_heat, Δμ_heat (DFHEAT; < 0: friction falling).
    pub dfheat: f64,
    /// The temperature span of the change, ΔT_heat > 0 [°C] (DTHEAT).
    pub dtheat_c: f64,
}

impl TemperatureLaw {
    /// μ(T) = FREF + DFHEAT · clamp(T − TREF, 0, DTHEAT)/DTHEAT (`fric_tempdep_mu_temp`,
    /// `m_friclaw.f90` lines 475-478).
    #[inline]
    pub fn mu_at(&self, t_c: f64) -> f64 {
        let dt = (t_c - self.tref_c).min(self.dtheat_c).max(0.0);
        self.fref + dt * self.dfheat / self.dtheat_c
    }
}

/// CONTACT's parameters of a falling law: FKIN, and two terms (F, SABSH [mm/s]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FallingTerms {
    pub fkin: f64,
    pub f1: f64,
    pub sabsh1_mm_s: f64,
    pub f2: f64,
    pub sabsh2_mm_s: f64,
}

impl FallingTerms {
    /// A term's SABSH as CONTACT uses it: max(1e-4, SABSH) when its F < 1e-8 (`m_friclaw.f90` 833-846).
    pub(crate) fn scale(f: f64, sabsh: f64) -> f64 {
        if f < 1e-8 {
            sabsh.max(1e-4)
        } else {
            sabsh
        }
    }
}

impl FrictionLaw {
    /// The static coefficient μ_s(0) = FKIN + F1 + F2 (FSTAT, `m_friclaw.f90` lines 303-305).
    pub fn mu_static(&self) -> f64 {
        match self {
            FrictionLaw::Coulomb { mu } => *mu,
            FrictionLaw::Linear(t) | FrictionLaw::Rational(t) | FrictionLaw::Exponential(t) => t.fkin + t.f1 + t.f2,
            // FSTAT := FREF (`fric_update`, m_friclaw.f90 line 307)
            FrictionLaw::Temperature(t) => t.fref,
        }
    }

    /// The largest μ the law gives, the bound of |(Fx, Fy)|/FN: FSTAT for Coulomb's law and the
    /// falling ones (μ_s falls from μ_s(0); the memory keeps μ between μ_prev and μ_s), and
    /// max(FREF, FREF + DFHEAT) for the temperature law.
    pub fn mu_max(&self) -> f64 {
        match self {
            FrictionLaw::Temperature(t) => t.fref.max(t.fref + t.dfheat),
            _ => self.mu_static(),
        }
    }

    /// Whether μ depends on the slip velocity (L = 2, 3, 4; not Coulomb's nor the temperature law).
    pub fn is_falling(&self) -> bool {
        matches!(self, FrictionLaw::Linear(_) | FrictionLaw::Rational(_) | FrictionLaw::Exponential(_))
    }

    /// The temperature law (L = 6), where μ follows the surface temperature.
    pub fn temperature(&self) -> Option<&TemperatureLaw> {
        match self {
            FrictionLaw::Temperature(t) => Some(t),
            _ => None,
        }
    }

    /// μ_s(s), the steady-sliding coefficient at slip velocity `s_mm_s` ≥ 0
    /// (`fric_veldep_mu_steady`, `m_friclaw.f90` lines 397-450).
    #[inline]
    pub fn mu_steady(&self, s_mm_s: f64) -> f64 {
        match self {
            FrictionLaw::Coulomb { mu } => *mu,
            FrictionLaw::Temperature(t) => t.fref,
            // m_friclaw.f90 lines 422-426
            FrictionLaw::Linear(t) => {
                let term = |f: f64, sh: f64| f * (1.0 - s_mm_s / (2.0 * FallingTerms::scale(f, sh))).max(0.0);
                t.fkin + term(t.f1, t.sabsh1_mm_s) + term(t.f2, t.sabsh2_mm_s)
            }
            // m_friclaw.f90 lines 428-432
            FrictionLaw::Rational(t) => {
                let r2 = s_mm_s / FallingTerms::scale(t.f2, t.sabsh2_mm_s);
                t.fkin + t.f1 / (1.0 + s_mm_s / FallingTerms::scale(t.f1, t.sabsh1_mm_s)) + t.f2 / (1.0 + r2 * r2)
            }
            // m_friclaw.f90 lines 434-438
            FrictionLaw::Exponential(t) => {
                // An absent term (F = 0) adds 0 without its exponential: exp(−ln2 s/1e-4)
                // underflows, and libm's underflow path costs ten ordinary exponentials.
                let term = |f: f64, sh: f64| {
                    if f == 0.0 {
                        0.0
                    } else {
                        f * (-LN_2 * s_mm_s / FallingTerms::scale(f, sh)).exp()
                    }
                };
                t.fkin + term(t.f1, t.sabsh1_mm_s) + term(t.f2, t.sabsh2_mm_s)
            }
        }
    }
}

impl FrictionLaw {
    /// (μ_s(s), dμ_s/ds): the steady coefficient and its slope [1/(mm/s)] at `s_mm_s` ≥ 0
    /// (derivatives of `m_friclaw.f90` 422-438; one exponential per term).
    #[inline]
    pub fn mu_steady_and_slope(&self, s_mm_s: f64) -> (f64, f64) {
        let sc = FallingTerms::scale;
        match self {
            FrictionLaw::Coulomb { mu } => (*mu, 0.0),
            FrictionLaw::Temperature(t) => (t.fref, 0.0),
            FrictionLaw::Linear(t) => {
                let term = |f: f64, sh: f64| {
                    let h = sc(f, sh);
                    if s_mm_s < 2.0 * h {
                        (f * (1.0 - s_mm_s / (2.0 * h)), -f / (2.0 * h))
                    } else {
                        (0.0, 0.0)
                    }
                };
                let ((v1, d1), (v2, d2)) = (term(t.f1, t.sabsh1_mm_s), term(t.f2, t.sabsh2_mm_s));
                (t.fkin + v1 + v2, d1 + d2)
            }
            FrictionLaw::Rational(t) => {
                let (h1, h2) = (sc(t.f1, t.sabsh1_mm_s), sc(t.f2, t.sabsh2_mm_s));
                let q1 = 1.0 + s_mm_s / h1;
                let r = s_mm_s / h2;
                let q2 = 1.0 + r * r;
                (t.fkin + t.f1 / q1 + t.f2 / q2, -t.f1 / (h1 * q1 * q1) - t.f2 * 2.0 * r / (h2 * q2 * q2))
            }
            FrictionLaw::Exponential(t) => {
                let term = |f: f64, sh: f64| {
                    if f == 0.0 {
                        // 0 · exp(…) without the exponential (see `mu_steady`).
                        return (0.0, 0.0);
                    }
                    let h = sc(f, sh);
                    let e = f * (-LN_2 * s_mm_s / h).exp();
                    (e, -LN_2 / h * e)
                };
                let ((v1, d1), (v2, d2)) = (term(t.f1, t.sabsh1_mm_s), term(t.f2, t.sabsh2_mm_s));
                (t.fkin + v1 + v2, d1 + d2)
            }
        }
    }

    /// The steepest fall max_s |dμ_s/ds| [1/(mm/s)], the sum of each term's steepest: linear
    /// F/(2 S) and exponential ln2 F/S (at s = 0), rational F1/S1 (at s = 0) and
    /// F2 (9/8)/(√3 S2) (at s = S2/√3); 0 for Coulomb. Derivatives of `m_friclaw.f90` 422-438.
    pub fn steepest_fall_per_mm_s(&self) -> f64 {
        let s = FallingTerms::scale;
        match self {
            FrictionLaw::Coulomb { .. } | FrictionLaw::Temperature(_) => 0.0,
            FrictionLaw::Linear(t) => t.f1 / (2.0 * s(t.f1, t.sabsh1_mm_s)) + t.f2 / (2.0 * s(t.f2, t.sabsh2_mm_s)),
            FrictionLaw::Rational(t) => {
                t.f1 / s(t.f1, t.sabsh1_mm_s) + t.f2 * 9.0 / 8.0 / (3f64.sqrt() * s(t.f2, t.sabsh2_mm_s))
            }
            FrictionLaw::Exponential(t) => LN_2 * (t.f1 / s(t.f1, t.sabsh1_mm_s) + t.f2 / s(t.f2, t.sabsh2_mm_s)),
        }
    }
}

/// Friction memory: the relaxation distance d_c [mm] and the slip velocity floor s0 [mm/s]
/// (CONTACT's MEMDST, MEM_S0; user guide "Friction memory").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Memory {
    pub memory_mm: f64,
    pub s0_mm_s: f64,
}

impl Memory {
    /// No memory: μ = μ_s(s) at once (CONTACT's MEMDST ≤ 1e-9).
    pub const NONE: Memory = Memory { memory_mm: 0.0, s0_mm_s: 0.0 };

    /// The weight θ of the previous μ in one backward-Euler step of dμ/dt = −(max(s, s0)/d_c)(μ − μ_s(s)):
    /// θ = d_c/(d_c + dt max(s, s0)), 0 without memory (`m_stang.f90` lines 318-330).
    #[inline]
    pub fn theta(&self, dt_s: f64, s_mm_s: f64) -> f64 {
        if self.memory_mm <= 1e-9 {
            0.0
        } else {
            self.memory_mm / (self.memory_mm + dt_s * s_mm_s.max(self.s0_mm_s))
        }
    }

    /// μ after one step: θ μ_prev + (1 − θ) μ_s(s) (`m_stang.f90` lines 318-335).
    #[inline]
    pub fn update(&self, law: &FrictionLaw, mu_prev: f64, dt_s: f64, s_mm_s: f64) -> f64 {
        let theta = self.theta(dt_s, s_mm_s);
        let mu_s = law.mu_steady(s_mm_s);
        if theta == 0.0 {
            mu_s
        } else {
            theta * mu_prev + (1.0 - theta) * mu_s
        }
    }

    /// [`Memory::update`] and its derivative in s: μ = θ μ_prev + (1 − θ) μ_s(s),
    /// dμ/ds = θ'(s) (μ_prev − μ_s) + (1 − θ) μ_s'(s), θ' = −d_c dt/(d_c + dt s)² above s0 (0 below).
    #[inline]
    pub fn update_and_slope(&self, law: &FrictionLaw, mu_prev: f64, dt_s: f64, s_mm_s: f64) -> (f64, f64) {
        let theta = self.theta(dt_s, s_mm_s);
        let (mu_s, d_s) = law.mu_steady_and_slope(s_mm_s);
        if theta == 0.0 {
            return (mu_s, d_s);
        }
        let q = self.memory_mm + dt_s * s_mm_s.max(self.s0_mm_s);
        let d_theta = if s_mm_s > self.s0_mm_s { -self.memory_mm * dt_s / (q * q) } else { 0.0 };
        (theta * mu_prev + (1.0 - theta) * mu_s, d_theta * (mu_prev - mu_s) + (1.0 - theta) * d_s)
    }

    /// Whether there is a memory (d_c > 1e-9 mm).
    pub fn is_active(&self) -> bool {
        self.memory_mm > 1e-9
    }
}

impl Default for Memory {
    fn default() -> Self {
        Memory::NONE
    }
}

/// Coulomb friction that varies per grid row (CONTACT's V = 3: one FSTAT per row IY, rows in
/// increasing y; user guide sec. "Friction variation"): the bound of an element of row j is
/// μ_j p. Solvers take it as the one coefficient μ_max on the bound pressure p μ_j/μ_max.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RowFriction {
    mu: Vec<f64>,
}

impl RowFriction {
    /// The coefficients of the rows, the first at the lowest y; `None` unless every one is
    /// finite and positive and there is at least one.
    pub fn new(mu: Vec<f64>) -> Option<RowFriction> {
        (!mu.is_empty() && mu.iter().all(|m| m.is_finite() && *m > 0.0)).then_some(RowFriction { mu })
    }

    /// μ_j of every row, the first at the lowest y.
    pub fn rows(&self) -> &[f64] {
        &self.mu
    }

    /// The largest coefficient: the nominal μ (|F| ≤ Σ μ_j p ≤ μ_max FN).
    pub fn mu_max(&self) -> f64 {
        self.mu.iter().copied().fold(0.0, f64::max)
    }

    /// The bound pressure p_k μ_j/μ_max per element (flat order `k = j mx + i`) [MPa]: times
    /// μ_max it is the row's bound μ_j p_k; where μ_j = μ_max it is p_k itself, bit for bit.
    pub fn bound_pressure(&self, mx: usize, pn_mpa: &[f64]) -> Vec<f64> {
        let top = self.mu_max();
        pn_mpa
            .iter()
            .enumerate()
            .map(|(k, &p)| {
                let mu = self.mu[k / mx];
                if mu == top {
                    p
                } else {
                    p * (mu / top)
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exp() -> FrictionLaw {
        FrictionLaw::Exponential(FallingTerms { fkin: 0.25, f1: 0.2, sabsh1_mm_s: 600.0, f2: 0.0, sabsh2_mm_s: 0.0 })
    }

    /// The rational law of reference/contact_friction (RAT: FSTAT 0.45).
    fn rat() -> FrictionLaw {
        FrictionLaw::Rational(FallingTerms { fkin: 0.22, f1: 0.15, sabsh1_mm_s: 400.0, f2: 0.08, sabsh2_mm_s: 2500.0 })
    }

    #[test]
    fn row_friction_scales_the_bound_pressure_per_row() {
        assert!(RowFriction::new(vec![]).is_none());
        assert!(RowFriction::new(vec![0.3, 0.0]).is_none());
        assert!(RowFriction::new(vec![0.3, f64::NAN]).is_none());
        let rows = RowFriction::new(vec![0.2, 0.4]).expect("positive");
        assert_eq!(rows.mu_max(), 0.4);
        // Two rows of two elements: row 0 at half the bound of row 1.
        let pn = [1.0, 3.0, 5.0, 0.7];
        assert_eq!(rows.bound_pressure(2, &pn), vec![0.5, 1.5, 5.0, 0.7]);
        // All rows equal: the pressure itself, bit for bit.
        let same = RowFriction::new(vec![0.3; 2]).expect("positive");
        let pn = [0.1234567, 2.0 / 3.0, 0.0, 1e-300];
        assert_eq!(same.bound_pressure(2, &pn), pn.to_vec());
    }

    #[test]
    fn the_temperature_law_is_linear_between_its_two_plateaus() {
        // User guide eq. mu_T: FREF up to TREF, FREF + DFHEAT beyond TREF + DTHEAT, linear between.
        let t = TemperatureLaw { fref: 0.33, tref_c: 100.0, dfheat: -0.19, dtheat_c: 400.0 };
        assert_eq!(t.mu_at(-50.0), 0.33);
        assert_eq!(t.mu_at(100.0), 0.33);
        assert!((t.mu_at(300.0) - (0.33 - 0.095)).abs() < 1e-15);
        assert!((t.mu_at(500.0) - 0.14).abs() < 1e-15);
        assert!((t.mu_at(5000.0) - 0.14).abs() < 1e-15);
        let law = FrictionLaw::Temperature(t);
        // FSTAT = FREF (`fric_update`); constant in the slip velocity; its largest μ is FREF.
        assert_eq!((law.mu_static(), law.mu_steady(800.0), law.mu_max()), (0.33, 0.33, 0.33));
        assert!(!law.is_falling() && law.temperature().is_some());
        let rising = FrictionLaw::Temperature(TemperatureLaw { dfheat: 0.19, ..t });
        assert!((rising.mu_max() - 0.52).abs() < 1e-15);
    }

    #[test]
    fn static_values_are_fkin_plus_terms() {
        assert_eq!(exp().mu_static(), 0.45);
        assert_eq!(FrictionLaw::Coulomb { mu: 0.3 }.mu_static(), 0.3);
        let rat = rat();
        assert!((rat.mu_static() - 0.45).abs() < 1e-15);
        assert!((rat.mu_steady(0.0) - 0.45).abs() < 1e-15);
    }

    #[test]
    fn exponential_halves_the_term_at_sabsh() {
        // 0.25 + 0.2 · 2^-1 = 0.35 at s = 600; 0.25 + 0.2 · 2^-2 = 0.30 at s = 1200.
        assert!((exp().mu_steady(600.0) - 0.35).abs() < 1e-15);
        assert!((exp().mu_steady(1200.0) - 0.30).abs() < 1e-15);
    }

    #[test]
    fn linear_reaches_fkin_at_twice_sabsh() {
        let lin =
            FrictionLaw::Linear(FallingTerms { fkin: 0.2, f1: 0.25, sabsh1_mm_s: 800.0, f2: 0.0, sabsh2_mm_s: 0.0 });
        // 0.2 + 0.25 (1 − 400/1600) = 0.3875; beyond 1600 mm/s FKIN.
        assert!((lin.mu_steady(400.0) - 0.3875).abs() < 1e-15);
        assert_eq!(lin.mu_steady(1600.0), 0.2);
        assert_eq!(lin.mu_steady(5000.0), 0.2);
    }

    #[test]
    fn rational_by_hand() {
        let rat = rat();
        // s = 400: 0.22 + 0.15/2 + 0.08/(1 + 0.0256) = 0.295 + 0.078003120124805
        assert!((rat.mu_steady(400.0) - (0.295 + 0.08 / 1.0256)).abs() < 1e-15);
        // s = 2500: 0.22 + 0.15/7.25 + 0.08/2
        assert!((rat.mu_steady(2500.0) - (0.26 + 0.15 / 7.25)).abs() < 1e-15);
    }

    #[test]
    fn memory_is_a_backward_euler_step() {
        let m = Memory { memory_mm: 0.01, s0_mm_s: 10.0 };
        // dt = 1e-4 s, s = 600 mm/s: θ = 0.01/(0.01 + 0.06) = 1/7.
        let theta = m.theta(1e-4, 600.0);
        assert!((theta - 1.0 / 7.0).abs() < 1e-15);
        let mu = m.update(&exp(), 0.45, 1e-4, 600.0);
        assert!((mu - (0.45 / 7.0 + 6.0 / 7.0 * 0.35)).abs() < 1e-15);
        // Below s0 the floor sets the rate: θ = 0.01/(0.01 + 1e-4 · 10) = 10/11.
        assert!((m.theta(1e-4, 0.0) - 10.0 / 11.0).abs() < 1e-15);
        // Without memory μ = μ_s(s).
        assert_eq!(Memory::NONE.update(&exp(), 0.45, 1e-4, 600.0), exp().mu_steady(600.0));
    }
    #[test]
    fn steepest_fall_is_the_slope_at_its_steepest() {
        // Exponential at s = 0: ln2 · 0.2/600; numerically the same.
        let d = exp().steepest_fall_per_mm_s();
        assert!((d - LN_2 * 0.2 / 600.0).abs() < 1e-18);
        assert!(((exp().mu_steady(0.0) - exp().mu_steady(1e-3)) / 1e-3 - d).abs() < 1e-9);
        // Rational with only F2: steepest at s = S2/√3, slope F2 (9/8)/(√3 S2).
        let rat =
            FrictionLaw::Rational(FallingTerms { fkin: 0.2, f1: 0.0, sabsh1_mm_s: 1.0, f2: 0.1, sabsh2_mm_s: 100.0 });
        let s0 = 100.0 / 3f64.sqrt();
        let numeric = (rat.mu_steady(s0 - 1e-4) - rat.mu_steady(s0 + 1e-4)) / 2e-4;
        assert!((rat.steepest_fall_per_mm_s() - numeric).abs() < 1e-10, "{numeric}");
        assert_eq!(FrictionLaw::Coulomb { mu: 0.3 }.steepest_fall_per_mm_s(), 0.0);
    }
    #[test]
    fn slope_is_the_derivative() {
        let laws = [
            exp(),
            FrictionLaw::Linear(FallingTerms { fkin: 0.2, f1: 0.25, sabsh1_mm_s: 800.0, f2: 0.05, sabsh2_mm_s: 100.0 }),
            FrictionLaw::Rational(FallingTerms {
                fkin: 0.22,
                f1: 0.15,
                sabsh1_mm_s: 400.0,
                f2: 0.08,
                sabsh2_mm_s: 2500.0,
            }),
        ];
        for law in laws {
            for s in [10.0, 150.0, 700.0, 3000.0] {
                let (mu, d) = law.mu_steady_and_slope(s);
                assert!((mu - law.mu_steady(s)).abs() < 1e-15, "{law:?} {s}");
                let numeric = (law.mu_steady(s + 1e-3) - law.mu_steady(s - 1e-3)) / 2e-3;
                assert!((d - numeric).abs() < 1e-9, "{law:?} at {s}: {d} vs {numeric}");
            }
        }
    }
}
