//! Viscoelastic bodies in steady rolling (CONTACT's M = 1; Kalker 1990, appendix D; user guide
//! "Viscoelastic materials"): both bodies a standard linear solid, compliance
//! `C(t) = C_g + C_v (1 − e^(−t/τ))`. In steady rolling the tractions stand still in the contact
//! frame and the material passes under them at V, so the material now at `X` felt them at
//! `X − V t` a time `t` ago (grid coordinates: the material moves along +x). The Kelvin–Voigt
//! element's displacement is the elastic one of the past tractions weighted by `e^(−t/τ)/τ`:
//!
//! `A(X, Y) = A_g(X, Y) + f ∫_0^∞ e^(−s) A_g(X − d s, Y) ds`
//!
//! with `A_g` the elastic (glassy) coefficient, `f = C_v/C_g` (CONTACT's FG) and `d = V τ` the
//! relaxation distance (VT). `d → 0` gives `(1 + f) A_g`, the relaxed solid G/(1 + f); `d → ∞` or
//! `f = 0` gives `A_g`. A kernel shifted by `dq` is the same function at `X − dq`, so steady
//! rolling's `A − A_s` keeps its translation invariance. The integral is evaluated by adaptive
//! Gauss–Kronrod quadrature, split where the field point crosses an element's edge or centre.
//!
//! A row of offsets `X_k = k dx − shift` shares its memory: with `M(X) = ∫_0^∞ e^(−s) A_g(X − d s)
//! ds` and `h = X_k − X_(k−1)`, `M(X_k) = e^(−h/d) M(X_(k−1)) + ∫_0^(h/d) e^(−s) A_g(X_k − d s) ds`
//! (the material at `X_k` passed `X_(k−1)` a time `h/V` ago), so along a row each offset adds one
//! short integral over one element's length instead of the whole memory ([`Relaxation::apply_row`];
//! CONTACT's `visccf` in m_visc.f90 integrates each offset's whole memory, QUADPACK's `dqagi` to a
//! relative 1e-3).

/// The relaxation of both bodies: `ratio` = C_v/C_g (FG) ≥ 0 and the relaxation distance
/// `distance_mm` = V τ (VT) [mm] ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Relaxation {
    pub ratio: f64,
    pub distance_mm: f64,
}

/// The memory integral is cut at `s = END` (the weight `e^(−s)` is below 2e-22 beyond it, and the
/// coefficients grow at most logarithmically in the distance).
const END: f64 = 50.0;
/// Most panels of one integral.
const MAX_PANELS: usize = 400;

/// Gauss–Kronrod (7, 15) nodes on [−1, 1] (the non-negative half), Kronrod weights, and the
/// 7-point Gauss weights of the odd-numbered nodes (Piessens et al., QUADPACK, 1983, table of
/// `qk15`).
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
const WG: [f64; 4] =
    [0.129_484_966_168_869_7, 0.279_705_391_489_276_7, 0.381_830_050_505_118_9, 0.417_959_183_673_469_4];

/// Four coefficients at once (zz, xx, yy, xy).
type Four = [f64; 4];

fn axpy(acc: &mut Four, w: f64, v: Four) {
    for (a, b) in acc.iter_mut().zip(v) {
        *a += w * b;
    }
}

/// The Kronrod and Gauss sums of `g` over `[a, b]`.
fn gauss_kronrod(g: &impl Fn(f64) -> Four, a: f64, b: f64) -> (Four, Four) {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let mid = g(c);
    let (mut k, mut gs) = ([0.0; 4], [0.0; 4]);
    axpy(&mut k, WGK[7], mid);
    axpy(&mut gs, WG[3], mid);
    for j in 0..7 {
        let pair = [g(c - h * XGK[j]), g(c + h * XGK[j])];
        for v in pair {
            axpy(&mut k, WGK[j], v);
            if j % 2 == 1 {
                axpy(&mut gs, WG[j / 2], v);
            }
        }
    }
    (k.map(|v| v * h), gs.map(|v| v * h))
}

/// One panel of [`adaptive`]: its Kronrod sum and error estimate |Kronrod − Gauss| (the largest of
/// the four components).
struct Panel {
    lo: f64,
    hi: f64,
    sum: Four,
    err: f64,
}

impl Panel {
    fn new(g: &impl Fn(f64) -> Four, lo: f64, hi: f64) -> Panel {
        let (sum, gs) = gauss_kronrod(g, lo, hi);
        let err = sum.iter().zip(&gs).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        Panel { lo, hi, sum, err }
    }
}

/// `∫ g` over the consecutive panels between `edges` to the absolute tolerance `tol` (per
/// component): globally adaptive, the panel of the largest error estimate bisected until their
/// sum is below `tol`, at most [`MAX_PANELS`] panels (rounding bounds what any tolerance can get).
fn adaptive(g: &impl Fn(f64) -> Four, edges: &[f64], tol: f64) -> Four {
    let mut panels: Vec<Panel> = edges.windows(2).map(|w| Panel::new(g, w[0], w[1])).collect();
    while panels.len() < MAX_PANELS {
        let total: f64 = panels.iter().map(|p| p.err).sum();
        let Some((worst, _)) = panels.iter().enumerate().max_by(|a, b| a.1.err.total_cmp(&b.1.err)) else { break };
        if total <= tol {
            break;
        }
        let p = panels.swap_remove(worst);
        let mid = 0.5 * (p.lo + p.hi);
        if !(p.lo < mid && mid < p.hi) {
            panels.push(p);
            break;
        }
        panels.push(Panel::new(g, p.lo, mid));
        panels.push(Panel::new(g, mid, p.hi));
    }
    // Summed in the order of the panels along s: the same numbers whatever order they were split in.
    panels.sort_by(|a, b| a.lo.total_cmp(&b.lo));
    let mut total = [0.0; 4];
    for p in &panels {
        axpy(&mut total, 1.0, p.sum);
    }
    total
}

/// Offsets per chain of the row recursion left of the source element (see [`Relaxation::apply_row`]).
const CHAIN: isize = 32;

/// The first offset of the chain that carries offset `k`: 0 for `k ≥ 0`, else the start of `k`'s
/// block of [`CHAIN`] offsets (`−CHAIN..=−1`, `−2 CHAIN..=−CHAIN − 1`, ...). A coefficient thus
/// depends on its offset alone, not on the grid it serves: the same numbers in every grid.
fn chain_start(k: isize) -> isize {
    if k >= 0 {
        0
    } else {
        k.div_euclid(CHAIN) * CHAIN
    }
}

impl Relaxation {
    /// Whether the material is elastic (no viscous compliance).
    pub fn is_elastic(&self) -> bool {
        self.ratio == 0.0
    }

    /// `∫_0^s_end e^(−s) elastic(x_mm − d s) ds` to the absolute tolerance `tol`, split where
    /// `x − d s` crosses an edge or centre of an element (`±dx`, `±dx/2`, 0): the integrand's kinks.
    fn memory(&self, elastic: &impl Fn(f64) -> Four, x_mm: f64, dx_mm: f64, s_end: f64, tol: f64) -> Four {
        let d = self.distance_mm;
        let mut breaks: Vec<f64> = [-1.0, -0.5, 0.0, 0.5, 1.0]
            .iter()
            .map(|k| (x_mm - k * dx_mm) / d)
            .filter(|s| *s > 0.0 && *s < s_end)
            .collect();
        breaks.push(0.0);
        breaks.push(s_end);
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let g = |s: f64| elastic(x_mm - d * s).map(|v| (-s).exp() * v);
        adaptive(&g, &breaks, tol)
    }

    /// The viscoelastic coefficients at the field offset `x_mm` from an elastic coefficient
    /// function `elastic(x)` (its `y` fixed) of elements `dx_mm` long, to the absolute tolerance
    /// `tol` [mm/MPa] per component (the memory integrated whole, [`Relaxation::memory`]).
    pub fn apply(&self, elastic: impl Fn(f64) -> Four, x_mm: f64, dx_mm: f64, tol: f64) -> Four {
        let now = elastic(x_mm);
        if self.is_elastic() {
            return now;
        }
        if self.distance_mm == 0.0 {
            return now.map(|v| (1.0 + self.ratio) * v);
        }
        let memory = self.memory(&elastic, x_mm, dx_mm, END, tol);
        let mut out = now;
        axpy(&mut out, self.ratio, memory);
        out
    }

    /// [`Relaxation::apply`] at the offsets `x_k = k dx_mm − shift_mm` of a row, `k` in `ks`, to the
    /// same tolerance: the memory of each chain's first offset ([`chain_start`]) integrated whole
    /// to `tol/2`, each further one by the recursion of the module's doc, `M_k = q_k M_(k−1) + L_k`
    /// with `q_k = e^(−h_k/d)`, `L_k` the integral over `[0, h_k/d]` to `tol (1 − q_k)/2`: an error
    /// `e_j` of `L_j` reaches `M_k` damped by `q_(j+1)…q_k`, and `Σ_j q_(j+1)…q_k (1 − q_j)` =
    /// `1 − q_(first)…q_k` ≤ 1, so each coefficient is within `tol` as [`Relaxation::apply`]'s.
    pub fn apply_row(
        &self,
        elastic: impl Fn(f64) -> Four,
        ks: std::ops::RangeInclusive<isize>,
        dx_mm: f64,
        shift_mm: f64,
        tol: f64,
    ) -> Vec<Four> {
        let x_of = |k: isize| k as f64 * dx_mm - shift_mm;
        if self.is_elastic() || self.distance_mm == 0.0 {
            return ks.map(|k| self.apply(&elastic, x_of(k), dx_mm, tol)).collect();
        }
        let (lo, hi) = (*ks.start(), *ks.end());
        let mut out = Vec::with_capacity(ks.count());
        let mut k = lo;
        while k <= hi {
            let first = chain_start(k);
            let last = if first < 0 { hi.min(first + CHAIN - 1) } else { hi };
            let mut memory = self.memory(&elastic, x_of(first), dx_mm, END, 0.5 * tol);
            for j in first..=last {
                if j > first {
                    memory = self.step(&elastic, (x_of(j - 1), x_of(j)), dx_mm, memory, tol);
                }
                if j >= lo {
                    let mut v = elastic(x_of(j));
                    axpy(&mut v, self.ratio, memory);
                    out.push(v);
                }
            }
            k = last + 1;
        }
        out
    }

    /// One step of [`Relaxation::apply_row`]'s recursion: the memory at `x_mm.1` from the memory
    /// `before` at `x_mm.0 < x_mm.1`.
    fn step(&self, elastic: &impl Fn(f64) -> Four, x_mm: (f64, f64), dx_mm: f64, before: Four, tol: f64) -> Four {
        let h_over_d = (x_mm.1 - x_mm.0) / self.distance_mm;
        let q = (-h_over_d).exp();
        let local = self.memory(elastic, x_mm.1, dx_mm, h_over_d.min(END), 0.5 * tol * -(-h_over_d).exp_m1());
        let mut m = before.map(|v| q * v);
        axpy(&mut m, 1.0, local);
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_kronrod_integrates_polynomials_and_the_exponential() {
        // Kronrod (15 points) is exact to degree 22, Gauss (7) to degree 13.
        let (k, g) = gauss_kronrod(&|s: f64| [s.powi(13), s.powi(22), 1.0, s], 0.0, 2.0);
        for (got, want) in [(k[0], 2f64.powi(14) / 14.0), (g[0], 2f64.powi(14) / 14.0), (k[1], 2f64.powi(23) / 23.0)] {
            assert!((got - want).abs() <= 1e-13 * want, "{got} vs {want}");
        }
        assert!((k[2] - 2.0).abs() < 1e-15 && (k[3] - 2.0).abs() < 1e-15);
        let e = adaptive(&|s: f64| [(-s).exp(), s * (-s).exp(), 0.0, 0.0], &[0.0, END], 1e-15);
        assert!((e[0] - 1.0).abs() < 1e-14 && (e[1] - 1.0).abs() < 1e-14, "{e:?}");
    }

    #[test]
    fn memory_of_a_step_and_a_kink_is_exact() {
        // elastic(x) = 1 on |x| < dx/2 (a step at the edges): f ∫ e^{-s} 1[|x - d s| < dx/2] ds
        // = f (e^{-s0} - e^{-s1}) with s0, s1 where x − d s crosses dx/2 and −dx/2.
        let (dx, d, x) = (0.4, 3.0, 1.1);
        let step = |x: f64| [if x.abs() < 0.5 * dx { 1.0 } else { 0.0 }, x.abs(), 0.0, 0.0];
        let r = Relaxation { ratio: 0.7, distance_mm: d };
        let got = r.apply(step, x, dx, 1e-14);
        let (s0, s1) = ((x - 0.5 * dx) / d, (x + 0.5 * dx) / d);
        let want0 = 0.7 * ((-s0).exp() - (-s1).exp());
        assert!((got[0] - want0).abs() < 1e-13, "{} vs {want0}", got[0]);
        // |x − d s| with its kink at s = x/d: ∫ e^{-s} |x − d s| ds = x − d + 2 d e^{−x/d}.
        let want1 = x + 0.7 * (x - d + 2.0 * d * (-x / d).exp());
        assert!((got[1] - want1).abs() < 1e-12, "{} vs {want1}", got[1]);
    }

    /// A Boussinesq-like coefficient row of elements `dx` long: `I[1/r]` over `[x − dx/2, x + dx/2]`
    /// at a distance `y` (its kinks where `x ± dx/2` crosses 0 for `y → 0`).
    fn row_kernel(dx: f64, y: f64) -> impl Fn(f64) -> Four {
        move |x: f64| {
            let f = |u: f64| u * (y / u.abs().max(1e-300)).asinh() + y * (u / y).asinh();
            let v = f(x + 0.5 * dx) - f(x - 0.5 * dx);
            [v, 0.5 * v, x / (1.0 + x * x), 1.0]
        }
    }

    #[test]
    fn a_row_by_the_recursion_is_each_offset_integrated_whole() {
        // Short and long memories, glassy, a shifted row; both sides of the source element and
        // past several chains on its left.
        let dx = 0.16;
        for (d, shift, y) in
            [(0.05, 0.0, 0.3), (9.0, 0.0, 500.0), (45.0, 0.16, 0.08), (2000.0, 0.0, 500.0), (1e15, 0.1, 2.0)]
        {
            let r = Relaxation { ratio: 1.0, distance_mm: d };
            let el = row_kernel(dx, y);
            let tol = 1e-13 * el(0.0)[0];
            let row = r.apply_row(&el, -70..=40, dx, shift, tol);
            for (v, k) in row.iter().zip(-70isize..) {
                let whole = r.apply(&el, k as f64 * dx - shift, dx, 1e-3 * tol);
                for c in 0..4 {
                    assert!((v[c] - whole[c]).abs() <= tol, "d {d} k {k} c {c}: {} vs {}", v[c], whole[c]);
                }
            }
            // Any part of the row gives the same numbers (a coefficient depends on its offset alone).
            assert_eq!(r.apply_row(&el, -40..=-3, dx, shift, tol)[..], row[30..68]);
            assert_eq!(r.apply_row(&el, 5..=9, dx, shift, tol)[..], row[75..80]);
        }
        // Elastic and relaxed rows: the point values.
        let el = row_kernel(dx, 1.0);
        for r in [Relaxation { ratio: 0.0, distance_mm: 3.0 }, Relaxation { ratio: 0.5, distance_mm: 0.0 }] {
            let row = r.apply_row(&el, -2..=2, dx, 0.0, 1e-14);
            for (v, k) in row.iter().zip(-2isize..) {
                assert_eq!(*v, r.apply(&el, k as f64 * dx, dx, 1e-14));
            }
        }
    }

    #[test]
    fn limits_of_the_relaxation() {
        let el = |x: f64| [1.0 / (1.0 + x * x), x, 2.0, -x];
        // FG = 0: elastic; d = 0: relaxed (1 + FG) A_g; d huge: the glassy A_g.
        let x = 0.3;
        assert_eq!(Relaxation { ratio: 0.0, distance_mm: 5.0 }.apply(el, x, 0.2, 1e-14), el(x));
        let relaxed = Relaxation { ratio: 1.5, distance_mm: 0.0 }.apply(el, x, 0.2, 1e-14);
        assert_eq!(relaxed, el(x).map(|v| 2.5 * v));
        let glassy =
            Relaxation { ratio: 1.5, distance_mm: 1e16 }.apply(|x| [1.0 / (1.0 + x * x), 0.0, 0.0, 0.0], x, 0.2, 1e-16);
        assert!((glassy[0] - el(x)[0]).abs() < 1e-14, "{glassy:?}");
    }
}
