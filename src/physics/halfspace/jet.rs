//! A second-order jet in three variables: a value with its gradient and Hessian, carried exactly
//! through +, −, ×, ÷, ln, atan and sqrt (forward-mode differentiation, the chain rule to second
//! order). The subsurface stresses ([`super::stress`]) differentiate the rectangle primitives of
//! Love's potentials with it.

use std::ops::{Add, Mul, Neg, Sub};

/// f, ∂f/∂x_i and ∂²f/∂x_i∂x_j (symmetric) at one point of (x, y, z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet {
    pub v: f64,
    pub g: [f64; 3],
    pub h: [[f64; 3]; 3],
}

impl Jet {
    /// A constant.
    pub fn constant(v: f64) -> Self {
        Self { v, g: [0.0; 3], h: [[0.0; 3]; 3] }
    }

    /// The coordinate `axis` (0, 1, 2) with value `v`.
    pub fn variable(v: f64, axis: usize) -> Self {
        let mut j = Self::constant(v);
        j.g[axis] = 1.0;
        j
    }

    /// φ(f) from φ(f), φ'(f), φ''(f): the chain rule to second order.
    fn compose(self, phi: f64, d1: f64, d2: f64) -> Self {
        let mut out = Self::constant(phi);
        for i in 0..3 {
            out.g[i] = d1 * self.g[i];
            for j in 0..3 {
                out.h[i][j] = d2 * self.g[i] * self.g[j] + d1 * self.h[i][j];
            }
        }
        out
    }

    /// 1/f.
    pub fn recip(self) -> Self {
        let r = 1.0 / self.v;
        self.compose(r, -r * r, 2.0 * r * r * r)
    }

    /// ln f (f > 0).
    pub fn ln(self) -> Self {
        let r = 1.0 / self.v;
        self.compose(self.v.ln(), r, -r * r)
    }

    /// atan f.
    pub fn atan(self) -> Self {
        let q = 1.0 / (1.0 + self.v * self.v);
        self.compose(self.v.atan(), q, -2.0 * self.v * q * q)
    }

    /// √f (f > 0).
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.compose(s, 0.5 / s, -0.25 / (s * s * s))
    }

    /// f · c for a constant c.
    pub fn scale(self, c: f64) -> Self {
        self.compose(self.v * c, c, 0.0)
    }
}

impl Add for Jet {
    type Output = Jet;
    fn add(self, o: Jet) -> Jet {
        let mut out = self;
        out.v += o.v;
        for i in 0..3 {
            out.g[i] += o.g[i];
            for j in 0..3 {
                out.h[i][j] += o.h[i][j];
            }
        }
        out
    }
}

impl Neg for Jet {
    type Output = Jet;
    fn neg(self) -> Jet {
        self.scale(-1.0)
    }
}

impl Sub for Jet {
    type Output = Jet;
    fn sub(self, o: Jet) -> Jet {
        self + (-o)
    }
}

impl Mul for Jet {
    type Output = Jet;
    fn mul(self, o: Jet) -> Jet {
        let mut out = Self::constant(self.v * o.v);
        for i in 0..3 {
            out.g[i] = self.g[i] * o.v + self.v * o.g[i];
            for j in 0..3 {
                out.h[i][j] = self.h[i][j] * o.v + self.g[i] * o.g[j] + self.g[j] * o.g[i] + self.v * o.h[i][j];
            }
        }
        out
    }
}

impl std::ops::Div for Jet {
    type Output = Jet;
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn div(self, o: Jet) -> Jet {
        self * o.recip()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = atan(x y / (z √(x²+y²+z²))) against central differences of its closed form.
    #[test]
    fn stress_jet_matches_finite_differences() {
        let f = |p: [f64; 3]| {
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            (p[0] * p[1] / (p[2] * r)).atan() + (r + p[2]).ln() * p[0]
        };
        let p = [0.3, -0.7, 0.45];
        let [x, y, z] = [0, 1, 2].map(|a| Jet::variable(p[a], a));
        let r = (x * x + y * y + z * z).sqrt();
        let j = (x * y / (z * r)).atan() + (r + z).ln() * x;
        assert!((j.v - f(p)).abs() < 1e-15);
        let h = 1e-4;
        for a in 0..3 {
            for b in 0..3 {
                let at = |da: f64, db: f64| {
                    let mut q = p;
                    q[a] += da;
                    q[b] += db;
                    f(q)
                };
                let fd = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4.0 * h * h);
                assert!((j.h[a][b] - fd).abs() < 1e-6, "h[{a}][{b}] = {} vs {fd}", j.h[a][b]);
            }
            let fd1 = {
                let (mut q, mut s) = (p, p);
                q[a] += 1e-5;
                s[a] -= 1e-5;
                (f(q) - f(s)) / 2e-5
            };
            assert!((j.g[a] - fd1).abs() < 1e-8);
        }
    }
}
