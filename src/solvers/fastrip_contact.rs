//! CONTACT's modified FaStrip (its M = 5: `modif_fastrip` in m_solvpt.f90; user guide
//! §"Flexibilities of the simplified theory"), beside the project's `fastrip`: CONTACT's FASTSIM
//! ([`super::fastsim_contact`]: its flexibilities, rigid slip and slope reduction) marched over each
//! grid row, then per row Kalker's strip theory on the equivalent ellipse of the loaded elements
//! (a, b; pmax = 3FN/(2πab)): the adhesion zone's length from the row's normalised creepages
//! ξ' = −G 4(1−ν) C11 cx/(2μ pmax π²), η' likewise with C22, φ' = −3G √(ab) C23 cs/(2μ pmax π)
//! (CONTACT's `linrol` coefficients), its tractions μ pmax (κ s_c − κ s_a, λ s_c − (λ − φ') s_a)
//! where the row's largest stays within μ pmax, the rest of the row at μ p along FASTSIM's
//! traction; a row whose strip tractions exceed the bound keeps FASTSIM's. Totals as CONTACT's
//! (over FN). Coulomb friction, steady rolling along +x on Hertz's ellipse.

use super::brush::{self, Integration, Tractions};
use super::fastsim_contact::{blended, equivalent_ellipse, slope_factor, CARRIED_LOAD};
use super::stepper::{FieldView, Step, Stepper};
use super::termination::Termination;
use super::{grid_model, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::{Coefficients, Grid, LeadingEdge, RigidSlip};
use crate::problem::{LocalContact, Problem, Sample};
use crate::solvers::style::{Dash, Marker, ModelStyle, LIGHT};
use std::f64::consts::PI;

/// The model's name in scenes.
pub const NAME: &str = "fastrip_contact";

/// CONTACT's modified FaStrip on the scene's grid.
pub const MODEL: ModelDef = ModelDef {
    extra_columns: &["n_adhesion", "n_slip", CARRIED_LOAD],
    ..grid_model(
        NAME,
        "CONTACT's modified FaStrip (its M = 5, m_solvpt.f90): CONTACT's FASTSIM per grid row, then Kalker's strip theory's adhesion zone on the equivalent ellipse where its tractions stay within the bound, totals over FN",
        check,
        build,
        ModelStyle { colour: LIGHT[2], dash: Dash::Dashed, marker: Marker::Square },
    )
};

/// Hertz's ellipse only.
fn check(p: &Problem) -> Result<(), InputError> {
    super::require_ellipse(p, NAME, "its strips are those of Hertz's ellipse (CONTACT's IPOTCN < 0)")
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let local = p.local_contact(p.loading.first().fn_n);
    Ok(Box::new(FastripContact { p, local, t: Tractions::zero(p.grid.len()) }))
}

struct FastripContact<'a> {
    p: &'a Problem,
    local: LocalContact,
    t: Tractions,
}

impl Stepper for FastripContact<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        self.p.reload_local(&mut self.local, at.fn_n);
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let c = (at.cx, at.cy, at.cs);
        let (planform, grid) = (&self.local.planform, &self.p.grid);
        let flex = blended(self.p, planform, c, at.mu, at.fx_target.is_some() || at.fy_target.is_some());
        let k = slope_factor(self.p, planform, c, at.mu);
        let rates =
            RigidSlip::new(c.0, c.1, c.2).over_flexibilities(flex.l1_mm3_n / k, flex.l2_mm3_n / k, flex.l3_mm3_n / k);
        let how = (LeadingEdge::Grid, Integration::SpinUpstream);
        brush::steady_march(grid, &self.local, at.mu, &rates, how, &mut self.t);
        let strip = Strip::new(self.p, &self.local, c, at.mu);
        let mut n_slip = 0;
        for j in 0..grid.my {
            n_slip += match strip.row(grid, &self.local, j, &mut self.t) {
                Some(slipping) => slipping,
                // FASTSIM's row: its elements at the bound μ p (to rounding) slip.
                None => (0..grid.mx)
                    .map(|i| grid.index(i, j))
                    .filter(|&k| {
                        let pk = planform.pressure_mpa[k];
                        pk > 0.0 && self.t.tx[k].hypot(self.t.ty[k]) >= at.mu * pk * (1.0 - 1e-9)
                    })
                    .count(),
            };
        }
        let (sx, sy, m) = self.t.sums(grid);
        let per = grid.element_area_mm2() / planform.ellipse.fn_n;
        Ok(Step {
            fx_over_fn: sx * per,
            fy_over_fn: sy * per,
            mz_nmm: m * grid.element_area_mm2(),
            extra: vec![
                (planform.loaded - n_slip) as f64,
                n_slip as f64,
                planform.pressure_sum_mpa * grid.element_area_mm2(),
            ],
            termination: Termination::Direct,
        })
    }

    /// No memory: the steady response at this step's creepage.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        Some(self.t.view(&self.p.grid, &self.local.planform))
    }
}

/// The strip theory's constants of a solve: the equivalent ellipse's a [mm], μ pmax [MPa], the
/// normalised creepages ξ', η', φ' and ν.
struct Strip {
    a_mm: f64,
    mu_pmax: f64,
    mu: f64,
    creep: (f64, f64, f64),
    nu: f64,
}

impl Strip {
    fn new(p: &Problem, local: &LocalContact, (cx, cy, cs): (f64, f64, f64), mu: f64) -> Strip {
        let (a, b) = equivalent_ellipse(&p.grid, &local.planform);
        let (g, nu) = (p.material.g_mpa, p.material.poisson);
        let pmax = 1.5 * local.planform.ellipse.fn_n / (PI * a * b);
        let c = Coefficients::from_contact(a, b, nu);
        let lin = |cij: f64, creep: f64| -g * 4.0 * (1.0 - nu) * cij * creep / (2.0 * mu * pmax * PI * PI);
        let phi = -g * 3.0 * (a * b).sqrt() * c.c23 * cs / (2.0 * mu * pmax * PI);
        Strip { a_mm: a, mu_pmax: mu * pmax, mu, creep: (lin(c.c11, cx), lin(c.c22, cy), phi), nu }
    }

    /// Row j after FASTSIM: the strip's adhesion zone where its tractions stay within the bound,
    /// the rest at μ p along FASTSIM's traction. CONTACT's coordinates: x_C = −x, its tractions
    /// the negatives of ours. Returns the row's slipping elements where the strip applies
    /// (`None`: the row keeps FASTSIM's tractions).
    fn row(&self, grid: &Grid, local: &LocalContact, j: usize, t: &mut Tractions) -> Option<usize> {
        let p = &local.planform.pressure_mpa;
        let loaded: Vec<usize> = (0..grid.mx).filter(|&i| p[grid.index(i, j)] > 0.0).collect();
        if loaded.is_empty() {
            return Some(0);
        }
        let half = 0.5 * grid.dx_mm;
        let x_c = |i: usize| -grid.x_mm[i];
        let lo = loaded.iter().map(|&i| x_c(i) - half).fold(f64::INFINITY, f64::min);
        let hi = loaded.iter().map(|&i| x_c(i) + half).fold(f64::NEG_INFINITY, f64::max);
        let aj = (0.5 * (hi - lo)).max(1e-10);
        let (a, y) = (self.a_mm, grid.y_mm[j]);
        let (xi, eta, phi) = self.creep;
        let d = self.adhesion_offset(aj, y);
        let (ux, uy) = (xi - phi * y / a, eta + phi * d / a);
        let norm = (ux * ux + uy * uy).max(1e-20).sqrt();
        let (kappa, lambda) = (ux / norm, uy / norm);
        let lambda_p = lambda - phi;
        let strip = |x: f64| {
            let s_c = (aj * aj - x * x).max(0.0).sqrt() / a;
            let s_a = ((aj - d).powi(2) - (x - d).powi(2)).max(0.0).sqrt() / a;
            (kappa * s_c - kappa * s_a, lambda * s_c - lambda_p * s_a)
        };
        let in_adhesion = |i: usize| x_c(i) > -aj + 2.0 * d;
        let ft_max = loaded
            .iter()
            .filter(|&&i| in_adhesion(i))
            .map(|&i| strip(x_c(i)))
            .fold(0.0, |m, (fx, fy)| f64::max(m, fx * fx + fy * fy));
        if ft_max > 1.0 {
            return None;
        }
        let mut slipping = 0;
        for &i in &loaded {
            let k = grid.index(i, j);
            if in_adhesion(i) {
                let (fx, fy) = strip(x_c(i));
                (t.tx[k], t.ty[k]) = (-self.mu_pmax * fx, -self.mu_pmax * fy);
            } else {
                let g = self.mu * p[k] / t.tx[k].hypot(t.ty[k]).max(1e-10);
                (t.tx[k], t.ty[k]) = (t.tx[k] * g, t.ty[k] * g);
                slipping += 1;
            }
        }
        Some(slipping)
    }

    /// The adhesion zone's offset d of a row of half-length aj at y (its zone x_C > −aj + 2d):
    /// Kalker's strip theory, full sliding (aj + 1) where φ' = 1 or it has no zone.
    fn adhesion_offset(&self, aj: f64, y: f64) -> f64 {
        let (xi, eta, phi) = self.creep;
        if (phi - 1.0).abs() <= 1e-6 {
            return aj + 1.0;
        }
        let u = xi - phi * y / self.a_mm;
        let discr = eta * eta + (1.0 - phi * phi) * u * u;
        if discr < 0.0 {
            return aj + 1.0;
        }
        let d = (discr.sqrt() + eta * phi) / (1.0 - phi * phi) * self.a_mm / (1.0 - self.nu);
        if d < 0.0 {
            aj + 1.0
        } else {
            d
        }
    }
}
