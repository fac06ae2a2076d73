//! FaStrip (B. Sichani, R. Enblom, M. Berg, "An alternative to FASTSIM for tangential solution of
//! the wheel–rail contact", Vehicle System Dynamics 54(6), 2016, 748–764): Kalker's strip theory
//! (Carter's 2-D solution per strip, extended to spin) on the grid's rows, its creepages scaled by
//! Kalker's coefficients so that small creepages give the linear theory, and FASTSIM's traction
//! direction in the slip area. Steady; on a transient scene the quasi-steady response (no memory).
//!
//! Per load, Hertz's ellipse a × b with peak pressure `p0 = 3 FN/(2π a b)`; per row j the strip's
//! half-length `a_j` (the planform's, `a √(1 − y_j²/b²)`) and Hertz's pressure `p = p0 √(a_j² − x²)/a`.
//! Normalised creepages (positive creepage, positive traction; CONTACT's spin sign, `wy = cy + cs x_C`):
//! `ξ' = 4(1−ν) C11 G cx / (2π² μ p0)`, `η' = 4(1−ν) C22 G cy / (2π² μ p0)`,
//! `φ' = 3 √(ab) C23 G cs / (2π μ p0)`. In strip j, with `u = ξ' − φ' y_j/a`, the slip area is the
//! trailing `[−a_j, −a_j + 2d]` of CONTACT's x (`x_C = −x` of the grid) with
//! `d = (√(η'² + (1 − φ'²) u²) + η' φ') / (1 − φ'²) · a/(1 − ν)`; in the adhesion area
//! `τx = μ κ (p − q)`, `τy = μ (λ p − (λ − φ') q)` with `q = p0 √((a_j − d)² − (x_C − d)²)/a` and
//! `(κ, λ) = (u, η' + φ' d/a)/|(u, η' + φ' d/a)|`; in the slip area μ p along FASTSIM's traction on
//! the same grid (its `[model]` options), a row whose leading element slips there taken from
//! FASTSIM with Kalker's single flexibility (as CONTACT's `original_fastrip`, m_solvpt.f90).
//! The adhesion traction is within μ p by construction: with `0 ≤ q ≤ p`,
//! `|τ|²/μ² = (p − q)² + 2λφ'(p − q) q + φ'² q² ≤ p²` for `|φ'| < 1`; where `|φ'| ≥ 1` the strip
//! solution has no such adhesion area and every strip slides (CONTACT's "full sliding
//! correction"). Hertzian contacts only: the strip solution is Carter's on Hertz's semi-elliptic
//! pressure, and the creepage scaling takes Kalker's coefficients of that ellipse; a geometry given
//! per element is refused (CONTACT's FaStrip likewise).

use super::brush::{self, Integration, RowMarch, Tractions};
use super::stepper::{FieldView, Step, Stepper};
use super::{grid_model, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::bound::scale_factor;
use crate::physics::lanes::sum4;
use crate::physics::{moment_sum, Planform, PressureShape};
use crate::problem::{LocalContact, Problem, Sample};
use crate::simd::with_avx2;
use crate::solvers::style::{muted, Dash, Marker};
use std::f64::consts::PI;

/// FaStrip.
pub const MODEL: ModelDef = grid_model(
    "fastrip",
    "FaStrip (Sichani, Enblom & Berg, VSD 54(6) 2016): Kalker's strip theory per grid row, creepages scaled by Kalker's coefficients, FASTSIM's direction in the slip area",
    check,
    build,
    muted(6, Dash::LongDash, Marker::Cross),
);

/// Hertz's ellipse only (see the module's doc).
fn check(p: &Problem) -> Result<(), InputError> {
    super::require_ellipse(p, "fastrip", "its strip solution is Carter's on Hertz's semi-elliptic pressure, so it needs Hertz's ellipse ([contact] a_mm, b_mm or the radii); on a contact given per element run fastsim, uba or contact")
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let n = p.grid.len();
    let fn_n = p.loading.first().fn_n;
    let (fastsim, single) = fastsim_contacts(p, fn_n);
    Ok(Box::new(Fastrip {
        p,
        hertz: p.geometry.planform(&p.grid, fn_n, PressureShape::Ellipsoidal),
        fastsim,
        single,
        dir: Tractions::zero(n),
        t: Tractions::zero(n),
    }))
}

/// FASTSIM's contact at `fn_n` as the scene sets it, and the same with Kalker's single flexibility
/// (`None` when the scene already uses it).
fn fastsim_contacts(p: &Problem, fn_n: f64) -> (LocalContact, Option<LocalContact>) {
    let local = p.local_contact(fn_n);
    let single = local.single_flexibility.is_none().then(|| {
        let e = &local.planform.ellipse;
        LocalContact { single_flexibility: Some((e.a_mm * e.b_mm).sqrt()), ..local.clone() }
    });
    (local, single)
}

struct Fastrip<'a> {
    p: &'a Problem,
    /// Hertz's ellipse at the current load, its ellipsoidal pressure and each row's half-length.
    hertz: Planform,
    /// FASTSIM's contact (the slip area's direction) and its single-flexibility twin.
    fastsim: LocalContact,
    single: Option<LocalContact>,
    /// FASTSIM's tractions (the single flexibility's in rows whose leading element slips).
    dir: Tractions,
    /// FaStrip's tractions.
    t: Tractions,
}

/// The strip theory's creepages ξ', η', φ' for peak pressure `p0_mpa` (see the module's doc).
fn normalised_creepages(p: &Problem, (a_mm, b_mm, p0_mpa): (f64, f64, f64), at: &Sample) -> [f64; 3] {
    let (c, g, nu) = (&p.coefficients, p.material.g_mpa, p.material.poisson);
    let s = g / (2.0 * at.mu * p0_mpa);
    let strip = 4.0 * (1.0 - nu) / (PI * PI);
    [s * strip * c.c11 * at.cx, s * strip * c.c22 * at.cy, s * 3.0 * (a_mm * b_mm).sqrt() * c.c23 / PI * at.cs]
}

/// One strip's solution: the half-length of its slip area and the direction (κ, λ).
struct Strip {
    /// Half-length d of the slip area [mm]; infinite where the strip slides.
    d_mm: f64,
    kappa: f64,
    lambda: f64,
}

impl Strip {
    /// Strip at `y_mm` of half-length `a_j_mm` on the ellipse's semi-axis `a_mm`.
    fn new([xi, eta, phi]: [f64; 3], y_mm: f64, a_j_mm: f64, a_mm: f64, nu: f64) -> Strip {
        let u = xi - phi * y_mm / a_mm;
        let d = if phi.abs() < 1.0 {
            ((eta * eta + (1.0 - phi * phi) * u * u).sqrt() + eta * phi) / (1.0 - phi * phi) * a_mm / (1.0 - nu)
        } else {
            f64::INFINITY
        };
        if d >= a_j_mm {
            // The slip area reaches the leading edge: the strip slides.
            return Strip { d_mm: f64::INFINITY, kappa: 0.0, lambda: 0.0 };
        }
        let v = eta + phi * d / a_mm;
        let norm = (u * u + v * v).sqrt();
        let (kappa, lambda) = if norm > 0.0 { (u / norm, v / norm) } else { (0.0, 0.0) };
        Strip { d_mm: d, kappa, lambda }
    }

    /// Elements 0..n of the row (grid x increasing) lie in its adhesion area, `x_C > 2d − a_j`.
    /// (The grid's x increases with i: the elements that satisfy it are a prefix, counted
    /// without branches.)
    fn adhesion_end(&self, x_mm: &[f64], a_j_mm: f64) -> usize {
        if self.d_mm.is_finite() {
            let edge = 2.0 * self.d_mm - a_j_mm;
            x_mm.iter().filter(|&&x| -x > edge).count()
        } else {
            0
        }
    }
}

/// What [`fill_row`] needs of a strip besides the row's arrays.
#[derive(Debug, Clone, Copy)]
struct RowConsts {
    /// Elements `..split` in adhesion, `split..` in slip.
    split: usize,
    a_j: f64,
    d: f64,
    /// p0/a [MPa/mm].
    c: f64,
    mu: f64,
    mu_kappa: f64,
    mu_lambda: f64,
    mu_phi: f64,
}

/// A row's pressure, the grid's x, FASTSIM's traction (x, y).
type RowInputs<'a> = (&'a [f64], &'a [f64], &'a [f64], &'a [f64]);

/// One row's tractions: the strip solution in the adhesion area, μ p along FASTSIM's traction in
/// the slip area; returns the number of loaded elements in slip. Branch-free loops (they
/// vectorise), compiled twice, plain and (when the CPU has it) with AVX2: the same IEEE
/// operations and no fused multiply-add, so both give bit-identical results.
fn fill_row(inputs: RowInputs, k: RowConsts, tx: &mut [f64], ty: &mut [f64]) -> usize {
    with_avx2(
        #[inline(always)]
        || fill_row_body(inputs, k, tx, ty),
    )
}

#[inline(always)]
fn fill_row_body((p_row, x_mm, dir_x, dir_y): RowInputs, k: RowConsts, tx: &mut [f64], ty: &mut [f64]) -> usize {
    let s = k.split;
    let (tx_a, tx_s) = tx.split_at_mut(s);
    let (ty_a, ty_s) = ty.split_at_mut(s);
    for (((tx, ty), &p), &x) in tx_a.iter_mut().zip(ty_a).zip(&p_row[..s]).zip(&x_mm[..s]) {
        let x_c = -x;
        let q = k.c * ((k.a_j - k.d) * (k.a_j - k.d) - (x_c - k.d) * (x_c - k.d)).max(0.0).sqrt();
        let t = (k.mu_kappa * (p - q), k.mu_lambda * p - (k.mu_lambda - k.mu_phi) * q);
        (*tx, *ty) = if p > 0.0 { t } else { (0.0, 0.0) };
    }
    let slip = tx_s.iter_mut().zip(ty_s).zip(&p_row[s..]).zip(&dir_x[s..]).zip(&dir_y[s..]);
    for ((((tx, ty), &p), &dx), &dy) in slip {
        let f = scale_factor(dx * dx + dy * dy, k.mu * p);
        (*tx, *ty) = (dx * f, dy * f);
    }
    p_row[s..].iter().filter(|&&p| p > 0.0).count()
}

impl Stepper for Fastrip<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        if at.fn_n != self.hertz.ellipse.fn_n {
            self.hertz = self.p.geometry.planform(&self.p.grid, at.fn_n, PressureShape::Ellipsoidal);
            (self.fastsim, self.single) = fastsim_contacts(self.p, at.fn_n);
        }
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let (grid, nu, mu) = (&self.p.grid, self.p.material.poisson, at.mu);
        let how = (self.p.model.leading_edge, Integration::Exact);
        let rates = brush::slip_rates(at, &self.fastsim);
        let single = self.single.as_ref().map(|s| (s, brush::slip_rates(at, s)));
        let e = self.hertz.ellipse;
        let (a, p0) = (e.a_mm, e.p0_mpa());
        let creepages = normalised_creepages(self.p, (a, e.b_mm, p0), at);
        let (pressure, mu_phi) = (&self.hertz.pressure_mpa, mu * creepages[2]);
        let mut n_slip = 0;
        // FASTSIM's traction along each row, the slip area's direction: with the single
        // flexibility where its leading element slips; two rows marched in step.
        let row = |j| match &single {
            Some((s, r)) if brush::leading_slips(grid, &self.fastsim, mu, &rates, how, j) => {
                RowMarch { j, local: s, rates: r }
            }
            _ => RowMarch { j, local: &self.fastsim, rates: &rates },
        };
        for j in (0..grid.my).step_by(2) {
            if j + 1 < grid.my {
                brush::march_rows(grid, mu, how, [row(j), row(j + 1)], &mut self.dir);
            } else {
                brush::march_rows(grid, mu, how, [row(j)], &mut self.dir);
            }
        }
        // Each strip's solution and tractions.
        for j in 0..grid.my {
            let a_j = self.hertz.half_length_mm[j];
            let strip = Strip::new(creepages, grid.y_mm[j], a_j, a, nu);
            let consts = RowConsts {
                split: strip.adhesion_end(&grid.x_mm, a_j),
                a_j,
                d: strip.d_mm,
                c: p0 / a,
                mu,
                mu_kappa: mu * strip.kappa,
                mu_lambda: mu * strip.lambda,
                mu_phi,
            };
            let row = grid.index(0, j)..grid.index(0, j) + grid.mx;
            let (tx, ty) = (&mut self.t.tx[row.clone()], &mut self.t.ty[row.clone()]);
            let inputs = (&pressure[row.clone()], grid.x_mm.as_slice(), &self.dir.tx[row.clone()], &self.dir.ty[row]);
            n_slip += fill_row(inputs, consts, tx, ty);
        }
        let sums = (sum4(&self.t.tx), sum4(&self.t.ty), moment_sum(grid, &self.t.tx, &self.t.ty));
        Ok(brush::step(&self.hertz, sums, self.hertz.loaded, n_slip))
    }

    /// No memory: the steady response at this step's creepage.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        Some(self.t.view(&self.p.grid, &self.hertz))
    }
}
