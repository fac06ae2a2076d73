//! CONTACT's FASTSIM (its M = 3: `modif_fastsim`, `fastsim_params` in m_solvpt.f90, `simpflex` and
//! `linrol` in m_hertz.f90, the rigid slip of `set_tang_rhs` in m_sdis.f90; user guide §"Flexibilities
//! of the simplified theory"), beside the project's `fastsim`. Where they differ CONTACT's choices
//! are taken (docs/models.md, "CONTACT's FASTSIM"): Kalker's three flexibilities from CONTACT's own
//! interpolation of his table ([`Coefficients::from_contact`]), blended towards one flexibility as
//! the creepage grows (creepages given; not under prescribed forces); the rigid slip at the element
//! centre with its spin term dx/6 upstream ([`Integration::SpinUpstream`]) instead of its exact
//! integral; a falling law's μ one value, μ(V √(cx² + cy²)), instead of a bound per element; the
//! slope reduction's ε on the equivalent ellipse of the loaded elements; totals as CONTACT sums them,
//! Σ τ dx dy / FN and MZ = Σ (x τy − y τx) dx dy, instead of Σ τ / Σ p. It rolls along +x or −x
//! (CHI = 0, 180°: the mirror image in x of +x). Steady rolling only: quasi-steady on a time history.

use super::brush::{self, Integration, Tractions};
use super::fastsim::ContactAt;
use super::stepper::{FieldView, Step, Stepper};
use super::termination::Termination;
use super::{grid_model, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::{Coefficients, Flexibilities, Grid, LeadingEdge, Planform, RigidSlip};
use crate::problem::{LocalContact, Problem, Sample};
use crate::solvers::style::{muted, Dash, Marker};
use std::f64::consts::PI;

/// The model's name in scenes.
pub const NAME: &str = "fastsim_contact";

/// The column of the load the imposed pressure carries, Σ p dx dy [N]: CONTACT's totals are over
/// the prescribed FN (its `soutpt`), so at full slip |F|/FN is μ times this load over FN (1.00076
/// on fastsim.inp case 3's 44 × 44 elliptical pressure), the bound the gate's traction check takes.
pub const CARRIED_LOAD: &str = "fn_carried_n";

/// CONTACT's FASTSIM on the scene's grid.
pub const MODEL: ModelDef = ModelDef {
    extra_columns: &["n_adhesion", "n_slip", CARRIED_LOAD],
    prescribed_forces: true,
    ..grid_model(
        NAME,
        "CONTACT's FASTSIM (its M = 3, m_solvpt.f90): Kalker's three flexibilities of CONTACT's coefficient table blended towards one at large creepage, the rigid slip at the element centre (spin dx/6 upstream), totals over FN",
        check,
        build,
        muted(8, Dash::LongDash, Marker::Circle),
    )
};

/// Hertz's ellipse only (CONTACT's equivalent ellipse of a non-Hertzian contact is not taken here),
/// rolling along +x or −x.
fn check(p: &Problem) -> Result<(), InputError> {
    super::require_ellipse(
        p,
        NAME,
        "its flexibilities are those of Hertz's ellipse (CONTACT's IPOTCN < 0); on a contact given per element run fastsim",
    )?;
    if p.loading.rows().any(|s| s.fy_target.is_some()) {
        return Err(InputError::new(
            "creepage.fy_over_fn",
            format!("Fy/FN prescribed with {NAME:?}"),
            "Fx/FN prescribed (CONTACT's F = 1) or the creepages given: CONTACT's FASTSIM finds cx only",
        ));
    }
    let turned = p.loading.rows().map(|s| s.chi_deg_or(p.rolling.chi_deg)).find(|&c| c != 0.0 && c != 180.0);
    if let Some(chi) = turned {
        return Err(InputError::new(
            "rolling.chi_deg",
            format!("{chi} with {NAME:?}"),
            "0 or 180 (CONTACT's FASTSIM rolls along +x or -x in steady rolling)",
        ));
    }
    Ok(())
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let local = p.local_contact(p.loading.first().fn_n);
    Ok(Box::new(FastsimContact { p, contact: None, local, t: Tractions::zero(p.grid.len()), solved: None }))
}

/// CONTACT's FASTSIM on the contact `contact` gives at each load (an approximate normal problem's:
/// KPEC, ANALYN), its flexibilities from the equivalent ellipse of the loaded elements as CONTACT
/// takes them on a non-Hertzian contact (`panprc` in m_scontc.f90: `equiv_ellipse`, `simpflex`).
pub fn with_contact(p: &Problem, contact: ContactAt) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let local = contact(p, p.loading.first().fn_n)?;
    Ok(Box::new(FastsimContact { p, contact: Some(contact), local, t: Tractions::zero(p.grid.len()), solved: None }))
}

struct FastsimContact<'a> {
    p: &'a Problem,
    /// The contact at a load where it is not the problem's own (then the flexibilities are the
    /// equivalent ellipse's).
    contact: Option<ContactAt>,
    local: LocalContact,
    t: Tractions,
    /// The creepages found under a prescribed Fx/FN.
    solved: Option<[f64; 2]>,
}

impl Stepper for FastsimContact<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        match self.contact {
            Some(contact) if at.fn_n != self.local.planform.ellipse.fn_n => self.local = contact(self.p, at.fn_n)?,
            Some(_) => {}
            None => {
                self.p.reload_local(&mut self.local, at.fn_n);
            }
        }
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let Some(target) = at.fx_target else {
            self.solved = None;
            return Ok(self.solve(at, at.cx));
        };
        // Fx/FN prescribed (CONTACT F = 1): cx found by bisection (Fx/FN rises with cx), to the
        // last bit of cx, without blending (CONTACT's `simpflex` blends only given creepages).
        let mut half = 1e-4;
        let (mut lo, mut hi) = (-half, half);
        while self.solve(at, lo).fx_over_fn > target || self.solve(at, hi).fx_over_fn < target {
            half *= 2.0;
            (lo, hi) = (-half, half);
            if half > 1.0 {
                return Err(SolveError::NonFinite { step: at.step });
            }
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if self.solve(at, mid).fx_over_fn < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let cx = 0.5 * (lo + hi);
        self.solved = Some([cx, at.cy]);
        Ok(self.solve(at, cx))
    }

    fn solved_creepage(&self) -> Option<[f64; 2]> {
        self.solved
    }

    /// No memory: the steady response at this step's creepage.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        Some(self.t.view(&self.p.grid, &self.local.planform))
    }
}

impl FastsimContact<'_> {
    /// The march at longitudinal creepage `cx` (the sample's other creepages).
    fn solve(&mut self, at: &Sample, cx: f64) -> Step {
        let backward = at.chi_deg_or(self.p.rolling.chi_deg) == 180.0;
        // Rolling along −x is the mirror image in x of rolling along +x with cx and cs reversed.
        let sign = if backward { -1.0 } else { 1.0 };
        let c = (sign * cx, at.cy, sign * at.cs);
        let (planform, grid) = (&self.local.planform, &self.p.grid);
        let mu = self.mu(at);
        // CONTACT's characteristic creepages take FSTAT (the static coefficient of a falling law).
        let fstat = if self.p.friction.is_falling() { self.p.friction.mu_static() } else { at.mu };
        let prescribed = at.fy_target.is_some() || at.fx_target.is_some();
        let flex = if self.contact.is_some() {
            let (a_mm, b_mm) = equivalent_ellipse(grid, planform);
            let m = &self.p.material;
            let contact = Blending { a_mm, b_mm, g_mpa: m.g_mpa, poisson: m.poisson };
            contact.flexibilities(c, fstat * planform.ellipse.fn_n, prescribed)
        } else {
            blended(self.p, planform, c, fstat, prescribed)
        };
        let k = slope_factor(self.p, &self.local.planform, c, mu);
        let rates =
            RigidSlip::new(c.0, c.1, c.2).over_flexibilities(flex.l1_mm3_n / k, flex.l2_mm3_n / k, flex.l3_mm3_n / k);
        let how = (LeadingEdge::Grid, Integration::SpinUpstream);
        let n_slip = brush::steady_march(grid, &self.local, mu, &rates, how, &mut self.t);
        let (sx, sy, m) = self.t.sums(grid);
        let per = grid.element_area_mm2() / planform.ellipse.fn_n;
        Step {
            fx_over_fn: sign * sx * per,
            fy_over_fn: sy * per,
            mz_nmm: sign * m * grid.element_area_mm2(),
            extra: vec![
                (planform.loaded - n_slip) as f64,
                n_slip as f64,
                planform.pressure_sum_mpa * grid.element_area_mm2(),
            ],
            termination: Termination::Direct,
        }
    }

    /// The coefficient of friction: the sample's with Coulomb's law; with a falling law its
    /// value at the rigid slip velocity V √(cx² + cy²), one for the whole contact (CONTACT's
    /// `fastsim_params` after Spiryagin et al. 2013).
    fn mu(&self, at: &Sample) -> f64 {
        if !self.p.friction.is_falling() {
            return at.mu;
        }
        self.p.friction.mu_steady(at.speed_mm_s(self.p.rolling.v_mm_s) * at.cx.hypot(at.cy))
    }
}

/// The slope reduction's k at creepages c and friction μ (`[model] slope_reduction`, 1 without),
/// CONTACT's ε on the equivalent ellipse of the loaded elements ([`equivalent_ellipse`],
/// `fastsim_params` in m_solvpt.f90).
pub fn slope_factor(p: &Problem, planform: &Planform, (cx, cy, cs): (f64, f64, f64), mu: f64) -> f64 {
    let Some([k0, alpha, beta]) = p.model.slope_reduction else { return 1.0 };
    let (a, b) = equivalent_ellipse(&p.grid, planform);
    let c11 = Coefficients::from_contact(a, b, p.material.poisson).c11;
    let nu = cy + cs * a;
    let nu = if nu.abs() < cy.abs() { cy } else { nu };
    let eps = p.material.g_mpa * PI * a * b * k0 * c11 * cx.hypot(nu) / (4.0 * mu * planform.ellipse.fn_n);
    k0 * (alpha + (1.0 - alpha) / (1.0 + beta * eps))
}

/// Kik and Piotrowski's equivalent ellipse of the loaded elements as CONTACT takes it
/// (`equiv_ellipse`, m_hertz.f90): the area n dx dy and the ratio of the extents of the
/// loaded columns and rows kept: a = √(A/π) √(len/wid), b = √(A/π) √(wid/len) [mm].
pub fn equivalent_ellipse(grid: &Grid, planform: &Planform) -> (f64, f64) {
    let (mut n, mut cols, mut rows) = (0usize, (usize::MAX, 0), (usize::MAX, 0));
    for j in 0..grid.my {
        for i in 0..grid.mx {
            if planform.pressure_mpa[grid.index(i, j)] > 0.0 {
                n += 1;
                cols = (cols.0.min(i), cols.1.max(i));
                rows = (rows.0.min(j), rows.1.max(j));
            }
        }
    }
    if n == 0 {
        return (0.0, 0.0);
    }
    let len = grid.dx_mm * (cols.1 - cols.0 + 1) as f64;
    let wid = grid.dy_mm * (rows.1 - rows.0 + 1) as f64;
    let r = (n as f64 * grid.element_area_mm2() / PI).sqrt();
    (r * (len / wid).sqrt(), r * (wid / len).sqrt())
}

/// CONTACT's flexibilities at creepages c (`simpflex`): Kalker's L1, L2, L3 of Hertz's ellipse with
/// CONTACT's coefficients, and where the creepages are given (`forces_prescribed` false) blended
/// towards the one flexibility `L = (cx² + cy² + (cs f)²)/(cx²/L1 + cy²/L2 + (cs f)²/L3)`,
/// f = 3πa/32, by the weight min(1, |(cx, cy)| / (3 |(ξ*, η*)|)), ξ* = μ FN/(G ab C11) and
/// η* = μ FN/(G ab C22) the creepages at which the linear theory reaches μ FN.
pub fn blended(
    p: &Problem,
    planform: &Planform,
    c: (f64, f64, f64),
    mu: f64,
    forces_prescribed: bool,
) -> Flexibilities {
    let e = &planform.ellipse;
    let contact = Blending { a_mm: e.a_mm, b_mm: e.b_mm, g_mpa: p.material.g_mpa, poisson: p.material.poisson };
    contact.flexibilities(c, mu * e.fn_n, forces_prescribed)
}

/// The contact [`blended`] takes its flexibilities of: Hertz's semi-axes and the material.
#[derive(Debug, Clone, Copy)]
pub struct Blending {
    pub a_mm: f64,
    pub b_mm: f64,
    pub g_mpa: f64,
    pub poisson: f64,
}

impl Blending {
    /// [`blended`] with μ FN = `mu_fn_n` [N].
    pub fn flexibilities(&self, (cx, cy, cs): (f64, f64, f64), mu_fn_n: f64, forces_prescribed: bool) -> Flexibilities {
        let (a, b, g) = (self.a_mm, self.b_mm, self.g_mpa);
        let c = Coefficients::from_contact(a, b, self.poisson);
        let (l1, l2, l3) =
            (8.0 * a / (3.0 * c.c11 * g), 8.0 * a / (3.0 * c.c22 * g), PI * a * (a / b).sqrt() / (4.0 * c.c23 * g));
        if forces_prescribed {
            return Flexibilities { l1_mm3_n: l1, l2_mm3_n: l2, l3_mm3_n: l3 };
        }
        let s = cs * (PI * a * a / 4.0) / (8.0 * a / 3.0);
        let numer = cx * cx + cy * cy + s * s;
        let denom = (cx * cx / l1 + cy * cy / l2 + s * s / l3).max(1e-14);
        let l_one = numer / denom;
        let scale = mu_fn_n / (a * b * g);
        let (ch_x, ch_y) = (scale / c.c11, scale / c.c22);
        let f_crp = ((cx * cx + cy * cy) / (ch_x * ch_x + ch_y * ch_y)).sqrt().max(1e-10);
        let w = (f_crp / 3.0).clamp(0.0, 1.0);
        let mix = |l: f64| (1.0 - w) * l + w * l_one;
        Flexibilities { l1_mm3_n: mix(l1), l2_mm3_n: mix(l2), l3_mm3_n: mix(l3) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flexibilities CONTACT printed (FLX1, FLX2, FLX3 [mm³/N], to four digits) for its
    /// FASTSIM cases: fastsim.inp case 2 (a = 8, b = 4 mm, FN 82000 N, μ 0.3, cy = −cs = −0.000625,
    /// blended by about a fifth) and tractcurv.inp case 61 (a, b of its Hertzian A1 = 0.0008/mm,
    /// a/b = 0.5, printed 6.304, 12.61 mm; FN 106700 N, μ 0.33, cx = 1e-5: L2 and L3 moved towards
    /// L1 in their fourth digit). Kalker's
    /// unblended three do not give case 2's.
    #[test]
    fn blending_gives_contacts_printed_flexibilities() {
        let steel = |a_mm, b_mm| Blending { a_mm, b_mm, g_mpa: 82000.0, poisson: 0.28 };
        let cases = [
            (steel(8.0, 4.0), (0.0, -0.000625, 0.000625), 0.3 * 82000.0, [0.4937e-4, 0.5152e-4, 0.4090e-4]),
            (
                steel(6.303597245517766, 12.607194491035537),
                (1e-5, 0.0, 0.0),
                0.33 * 106700.0,
                [0.5491e-4, 0.6773e-4, 0.4526e-4],
            ),
        ];
        for (contact, c, mu_fn, printed) in cases {
            let f = contact.flexibilities(c, mu_fn, false);
            let ours = [f.l1_mm3_n, f.l2_mm3_n, f.l3_mm3_n];
            for (o, p) in ours.iter().zip(printed) {
                // Half a unit of the fourth digit.
                assert!((o - p).abs() <= 0.5e-8, "{ours:?} against {printed:?}");
            }
        }
        let kalker = steel(8.0, 4.0).flexibilities((0.0, -0.000625, 0.000625), 0.3 * 82000.0, true);
        assert!((kalker.l2_mm3_n - 0.5152e-4).abs() > 1e-7, "{kalker:?}");
    }
}
