//! A falling law and its memory prepared once per sample for the simplified models' per-element
//! bound (issue 33 item 6, speed): μ(s) and dμ/ds of [`FrictionLaw::mu_steady_and_slope`] and
//! [`Memory::update_and_slope`] with every constant divided out beforehand (ln2/S, 1/(2S), 1/S),
//! so that an evaluation costs the law's exponentials and at most one division per term (the
//! rational law's), and the memory's weight θ = d_c/(d_c + dt max(s, s0)) none: μ is given as a
//! ratio ([`crate::physics::bound::MuRatio`]) whose denominator the bound's Newton multiplies
//! through. The exponential is [`exp`], branch-free, so that several elements' evaluations
//! ([`LawKernel::update_ratio_lanes`]) compile to vector instructions with the same bits as one
//! element's.

use super::bound::MuRatio;
use super::friction::{FallingTerms, FrictionLaw, Memory};

/// ln 2, the exponential law's half-value scale (`m_friclaw.f90` line 436).
const LN_2: f64 = std::f64::consts::LN_2;

/// e^x, branch-free (it vectorises), to within two units in the last place for x in
/// [−700, 700] (clamped there: e^−700 ≈ 1e-304 stands for anything smaller): x = n ln2 + r with
/// |r| ≤ ln2/2 (Cody and Waite's two-part ln2), e^r by its Taylor series to degree 13 (remainder
/// below 4e-18) in Estrin's scheme, times 2^n made in the exponent bits.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    // fdlibm's ln2 split: LN2_HI has 32 significant bits, so n · LN2_HI is exact for |n| < 2^21.
    const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
    const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);
    // 1.5 · 2^52: x log2(e) + SHIFT is an integer in its last bits (round to nearest).
    const SHIFT: f64 = 6_755_399_441_055_744.0;
    const C: [f64; 14] = [
        1.0,
        1.0,
        1.0 / 2.0,
        1.0 / 6.0,
        1.0 / 24.0,
        1.0 / 120.0,
        1.0 / 720.0,
        1.0 / 5040.0,
        1.0 / 40320.0,
        1.0 / 362_880.0,
        1.0 / 3_628_800.0,
        1.0 / 39_916_800.0,
        1.0 / 479_001_600.0,
        1.0 / 6_227_020_800.0,
    ];
    let x = x.clamp(-700.0, 700.0);
    let t = x * std::f64::consts::LOG2_E + SHIFT;
    let n = t - SHIFT;
    let r = (x - n * LN2_HI) - n * LN2_LO;
    let (r2, pair) = (r * r, |k: usize| C[k] + C[k + 1] * r);
    let r4 = r2 * r2;
    let q0 = pair(0) + r2 * pair(2);
    let q1 = pair(4) + r2 * pair(6);
    let q2 = pair(8) + r2 * pair(10);
    let poly = (q0 + r4 * q1) + (r4 * r4) * (q2 + r4 * pair(12));
    // t's low mantissa bits hold 2^51 + n: adding the bias and shifting leaves (n + 1023) << 52.
    poly * f64::from_bits(t.to_bits().wrapping_add(1023) << 52)
}

/// The shape of a prepared law with its constants per term (F, and the reciprocal scale).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Shape {
    /// Coulomb: μ.
    Constant(f64),
    /// L = 2: per term (F/(2S), 2S): F − s F/(2S) below s = 2S, 0 above.
    Linear([(f64, f64); 2]),
    /// L = 3: (1/S1, 1/S2): F1/(1 + s/S1) + F2/(1 + (s/S2)²).
    Rational([f64; 2]),
    /// L = 4: per term (F, ln2/S), terms with F = 0 dropped: F exp(−s ln2/S).
    Exponential([(f64, f64); 2], usize),
}

/// [`FrictionLaw`] and [`Memory`] with their constants made once for a time step `dt_s`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawKernel {
    fkin: f64,
    f: [f64; 2],
    shape: Shape,
    /// d_c [mm], dt [s], s0 [mm/s]; d_c = 0 without memory.
    memory: (f64, f64, f64),
}

impl LawKernel {
    /// The kernel of `law` with `memory` over steps of `dt_s`.
    pub fn new(law: &FrictionLaw, memory: &Memory, dt_s: f64) -> Self {
        let scale = FallingTerms::scale;
        let (fkin, f, shape) = match law {
            FrictionLaw::Coulomb { mu } => (*mu, [0.0; 2], Shape::Constant(*mu)),
            FrictionLaw::Temperature(t) => (t.fref, [0.0; 2], Shape::Constant(t.fref)),
            FrictionLaw::Linear(t) => {
                let term = |f: f64, sh: f64| {
                    let w = 2.0 * scale(f, sh);
                    (f / w, w)
                };
                (t.fkin, [t.f1, t.f2], Shape::Linear([term(t.f1, t.sabsh1_mm_s), term(t.f2, t.sabsh2_mm_s)]))
            }
            FrictionLaw::Rational(t) => {
                let inv = [1.0 / scale(t.f1, t.sabsh1_mm_s), 1.0 / scale(t.f2, t.sabsh2_mm_s)];
                (t.fkin, [t.f1, t.f2], Shape::Rational(inv))
            }
            FrictionLaw::Exponential(t) => {
                let mut terms = [(0.0, 0.0); 2];
                let mut n = 0;
                for (f, sh) in [(t.f1, t.sabsh1_mm_s), (t.f2, t.sabsh2_mm_s)] {
                    // An absent term adds 0 without its exponential (see `FrictionLaw::mu_steady`).
                    if f != 0.0 {
                        terms[n] = (f, LN_2 / scale(f, sh));
                        n += 1;
                    }
                }
                (t.fkin, [t.f1, t.f2], Shape::Exponential(terms, n))
            }
        };
        let d_c = if memory.is_active() { memory.memory_mm } else { 0.0 };
        LawKernel { fkin, f, shape, memory: (d_c, dt_s, memory.s0_mm_s) }
    }

    /// (μ_s(s), dμ_s/ds) at `s_mm_s` ≥ 0 ([`FrictionLaw::mu_steady_and_slope`]).
    #[inline(always)]
    pub fn steady_and_slope(&self, s_mm_s: f64) -> (f64, f64) {
        let (mu, d) = self.steady_lanes([s_mm_s]);
        (mu[0], d[0])
    }

    /// [`LawKernel::steady_and_slope`] of L slip velocities: the law's shape chosen once, each
    /// lane's arithmetic that of one (so that the lanes vectorise, with the same bits).
    #[inline(always)]
    fn steady_lanes<const L: usize>(&self, s: [f64; L]) -> ([f64; L], [f64; L]) {
        let (mut mu, mut d) = ([self.fkin; L], [0.0; L]);
        match self.shape {
            Shape::Constant(m) => mu = [m; L],
            Shape::Linear(terms) => {
                for (k, (slope, end)) in terms.into_iter().enumerate() {
                    for l in 0..L {
                        // Below its end the term adds F − s F/(2S) and falls by F/(2S).
                        let below = s[l] < end;
                        mu[l] += if below { self.f[k] - s[l] * slope } else { 0.0 };
                        d[l] -= if below { slope } else { 0.0 };
                    }
                }
            }
            Shape::Rational([i1, i2]) => {
                for l in 0..L {
                    let q1 = 1.0 + s[l] * i1;
                    let r = s[l] * i2;
                    let q2 = 1.0 + r * r;
                    // One division for both quotients: 1/q1 = q2/(q1 q2), 1/q2 = q1/(q1 q2).
                    let inv = 1.0 / (q1 * q2);
                    let (v1, v2) = (self.f[0] * q2 * inv, self.f[1] * q1 * inv);
                    mu[l] = self.fkin + v1 + v2;
                    d[l] = -v1 * i1 * q2 * inv - 2.0 * v2 * r * i2 * q1 * inv;
                }
            }
            Shape::Exponential(terms, n) => {
                for &(f, k) in &terms[..n] {
                    for l in 0..L {
                        let e = f * exp(-k * s[l]);
                        mu[l] += e;
                        d[l] -= k * e;
                    }
                }
            }
        }
        (mu, d)
    }

    /// The memory's weight θ at s = 0 and μ_s(0): the stick test's constants.
    pub fn stick(&self) -> (f64, f64) {
        let (d_c, dt, s0) = self.memory;
        let theta = if d_c > 0.0 { d_c / (d_c + dt * s0.max(0.0)) } else { 0.0 };
        (theta, self.steady_and_slope(0.0).0)
    }

    /// μ after one step of material that carried `mu_prev` in, at slip velocity `s_mm_s`, and
    /// its slope, as the ratio ([`MuRatio`]) of [`Memory::update_and_slope`] without its division.
    #[inline(always)]
    pub fn update_ratio(&self, mu_prev: f64, s_mm_s: f64) -> MuRatio {
        let (n, d, m) = self.update_ratio_lanes([mu_prev], [s_mm_s]);
        (n[0], d[0], m[0])
    }

    /// [`LawKernel::update_ratio`] of L elements (the same bits per lane): with s' = max(s, s0)
    /// and d = d_c + dt s', μ = (d_c μ_prev + dt s' μ_s)/d (θ = d_c/d, backward Euler) and
    /// d² dμ/ds = d dt s' dμ_s/ds − d_c dt (μ_prev − μ_s) above s0 (the second term: θ's slope);
    /// without memory (μ_s, 1, dμ_s/ds).
    #[inline(always)]
    pub fn update_ratio_lanes<const L: usize>(&self, mu_prev: [f64; L], s: [f64; L]) -> ([f64; L], [f64; L], [f64; L]) {
        let (mu, slope) = self.steady_lanes(s);
        let (d_c, dt, s0) = self.memory;
        if d_c == 0.0 {
            return (mu, [1.0; L], slope);
        }
        let (mut n, mut d, mut m) = ([0.0; L], [0.0; L], [0.0; L]);
        for l in 0..L {
            let w = dt * s[l].max(s0);
            d[l] = d_c + w;
            n[l] = d_c * mu_prev[l] + w * mu[l];
            let theta_slope = if s[l] > s0 { d_c * dt * (mu_prev[l] - mu[l]) } else { 0.0 };
            m[l] = d[l] * w * slope[l] - theta_slope;
        }
        (n, d, m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`exp`] against libm's over the range the laws use and beyond: within two units in the
    /// last place; clamped at −700; exact at 0.
    #[test]
    fn exp_is_the_exponential() {
        assert_eq!(exp(0.0), 1.0);
        let mut x = -745.0f64;
        while x < 709.0 {
            let (got, want) = (exp(x), x.clamp(-700.0, 700.0).exp());
            assert!((got - want).abs() <= 2.0 * f64::EPSILON * want, "{x}: {got} vs {want}");
            x += 0.0137;
        }
        for x in [-1e-300, -1e-17, -0.3465, 0.3466, -1.0, -37.5, -699.9] {
            assert!((exp(x) - x.exp()).abs() <= 2.0 * f64::EPSILON * x.exp(), "{x}");
        }
        assert_eq!(exp(-1e9), exp(-700.0));
    }

    fn laws() -> [FrictionLaw; 5] {
        let t = |fkin, f1, s1, f2, s2| FallingTerms { fkin, f1, sabsh1_mm_s: s1, f2, sabsh2_mm_s: s2 };
        [
            FrictionLaw::Coulomb { mu: 0.3 },
            FrictionLaw::Exponential(t(0.25, 0.2, 600.0, 0.0, 0.0)),
            FrictionLaw::Exponential(t(0.2, 0.15, 300.0, 0.1, 2000.0)),
            FrictionLaw::Linear(t(0.2, 0.25, 800.0, 0.05, 100.0)),
            FrictionLaw::Rational(t(0.22, 0.15, 400.0, 0.08, 2500.0)),
        ]
    }

    /// The kernel gives the law's and the memory's values and slopes (to rounding), with and
    /// without memory, below and above s0 and past the linear law's ends.
    #[test]
    fn kernel_is_the_law_and_the_memory() {
        let memories = [Memory::NONE, Memory { memory_mm: 0.01, s0_mm_s: 10.0 }];
        for law in laws() {
            for memory in memories {
                let k = LawKernel::new(&law, &memory, 2.6e-5);
                for s in [0.0, 5.0, 150.0, 199.0, 700.0, 1700.0, 3000.0, 9000.0] {
                    let (mu, d) = memory.update_and_slope(&law, 0.41, 2.6e-5, s);
                    let (n, den, m) = k.update_ratio(0.41, s);
                    // The ratio's quotients as the test forms them (their roundings: a few ulps).
                    let (km, kd) = (n / den, m / (den * den));
                    assert!((km - mu).abs() <= 4e-16, "{law:?} {memory:?} at {s}: {km} vs {mu}");
                    assert!((kd - d).abs() <= 4e-15 * d.abs().max(1e-6), "{law:?} {memory:?} at {s}: {kd} vs {d}");
                }
                let (theta, mu0) = k.stick();
                assert_eq!(theta, memory.theta(2.6e-5, 0.0), "{law:?}");
                assert_eq!(mu0, law.mu_steady(0.0), "{law:?}");
            }
        }
    }
}
