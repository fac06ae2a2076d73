//! Friction falling with the slip velocity in the exact solver: CONTACT's fixed point on the slip
//! velocity around the tangential solve (`m_stang.f90`, `stang`, lines 240-620;
//! reference/contact_friction/README.md "How CONTACT solves it"), solved to a stated tolerance.
//!
//! Per iteration: μ per element from the slip velocity s by the law and the memory recursion
//! along each row from the leading edge; the tangential problem with the fixed bound μ_k pn_k;
//! s_new = |S|/dt (0 outside the contact); stop when rms(s_new − s) ≤ tol·rms(s_new) over the
//! contact or when no element slips; else s := s_new, damped by OMGSLP in slip elements whose μ
//! exceeds μ_prev, OMGSLP × 0.8 every 20 iterations while the element division changes.
//! Adaptive solves (the default) reach the same fixed point with less work: loose early solves,
//! warm starts with the slip area on the new bound, and in a transient step, once CONTACT's path
//! holds the last step's element division, the last steps' field extrapolated as the next
//! iterate. `inislp = "extrapolated"` starts a transient step from the last two steps' slip
//! velocity extrapolated in the contact's frame (stationary fields: one solve), at the price of
//! CONTACT's branch where a step has several solutions.
//! Axes as the solver's: leading edge at ix = 0, material moving to +x.

use super::tangential::{ElementState, StepResult};
use super::ContactError;
use crate::physics::bound::scale_to_bound;
use crate::physics::{FrictionLaw, Memory};
use crate::scene::InitialSlip;

/// The fixed point's options (`[contact_solver]`: `veldep_tolerance`, `inislp`; the limit and
/// OMGSLP are CONTACT's, `stepper`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelDepOptions {
    /// Stop when rms(s_new − s) ≤ tolerance · rms(s_new) (CONTACT: a fixed 1e-3).
    pub tolerance: f64,
    /// Iteration limit (CONTACT: max(1, MAXIN − 10) = 190).
    pub max_iterations: usize,
    /// The start of s (CONTACT's INISLP).
    pub initial: InitialSlip,
    /// The damping OMGSLP (CONTACT's default 0.5).
    pub omgslp: f64,
    /// The tolerance of the tangential solve the fixed point ends on ([`inner_tolerance`]).
    pub solve_tolerance: f64,
    /// Early iterates solved loosely ([`inner_tolerance`]), each solve started with the last
    /// one's slip area on the new bound ([`onto_bound`]); false: CONTACT's path, every iterate at
    /// `solve_tolerance` from CONTACT's starts.
    pub adaptive_solves: bool,
}

/// The tangential tolerance per unit of the fixed point's last relative change: an iterate still
/// far from the fixed point is solved only as tightly as the next change can use.
const INNER_PER_CHANGE: f64 = 1e-2;

/// The loosest tangential tolerance of an early iterate (the first one's too: its change is unknown).
const INNER_LOOSEST: f64 = 1e-2;

/// The tangential tolerance of the next solve after a relative change `change` (None: the
/// first): `INNER_PER_CHANGE · change` within [`solve`, `INNER_LOOSEST`], `solve` the final one's.
pub(super) fn inner_tolerance(solve: f64, change: Option<f64>) -> f64 {
    adaptive_tolerance(solve, change, INNER_LOOSEST)
}

/// The rule of [`inner_tolerance`] with the loosest tolerance `loosest` (the coupled K ≠ 0
/// iteration's is tighter): `INNER_PER_CHANGE · change` within [`solve`, `loosest`].
pub(super) fn adaptive_tolerance(solve: f64, change: Option<f64>, loosest: f64) -> f64 {
    let loose = change.map_or(loosest, |c| (INNER_PER_CHANGE * c).min(loosest));
    loose.max(solve)
}

/// How the fixed point of one step or steady point ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelDepOutcome {
    pub iterations: usize,
    pub converged: bool,
    /// The last relative change rms(s_new − s)/rms(s_new) (0 when no element slips).
    pub change: f64,
    /// Tangential iterations summed over the fixed point's solves.
    pub inner_iterations: usize,
}

/// One rolling step as the law sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Steady rolling (μ_prev: the upstream element of the same solution) or a transient step
    /// (μ_prev: the previous step's field moved by dq).
    pub steady: bool,
    /// The time of the step [s]: s = |S|/dt (steady rolling: dx/V).
    pub dt_s: f64,
    pub v_mm_s: f64,
    /// The rolling distance per step in elements (transient: how far the previous fields move).
    pub shift_elements: f64,
}

/// The law, the memory and the fields the next step starts from.
pub struct VelDep {
    law: FrictionLaw,
    memory: Memory,
    options: VelDepOptions,
    mx: usize,
    /// μ of the last solve per element (all elements; exterior ones relax towards FSTAT).
    mu: Vec<f64>,
    /// |S| [mm] of the last solve per element (0 outside the contact).
    shift_mm: Vec<f64>,
    /// Whether `mu`, `shift_mm` hold a previous step (else: a start from zero, FSTAT and s = 0).
    has_previous: bool,
    /// The converged slip velocity [mm/s] of the last two transient steps in the contact's frame
    /// (last first; emptied by a steady solve): the extrapolated start ([`VelDep::initial_slip`]).
    recent_mm_s: Vec<Vec<f64>>,
    /// The element division of the last converged transient step (empty after a steady solve).
    recent_state: Vec<ElementState>,
}

impl VelDep {
    pub fn new(law: FrictionLaw, memory: Memory, options: VelDepOptions, mx: usize, n: usize) -> VelDep {
        VelDep {
            law,
            memory,
            options,
            mx,
            mu: vec![law.mu_static(); n],
            shift_mm: vec![0.0; n],
            has_previous: false,
            recent_mm_s: Vec::new(),
            recent_state: Vec::new(),
        }
    }

    /// The μ field of the last solve.
    pub fn mu(&self) -> &[f64] {
        &self.mu
    }

    /// Solve one step (or steady point) on pressure `pn`: `solve(bound, start, tol)` solves the
    /// tangential problem with the bound μ_k pn_k [MPa] to the tolerance `tol`, warm started from
    /// `start` (the last iterate's tractions) when given. Early iterates are solved loosely
    /// ([`inner_tolerance`]); the fixed point ends only on a solve at `solve_tolerance`.
    pub fn step(
        &mut self,
        pn: &[f64],
        motion: Motion,
        mut solve: impl FnMut(&[f64], Option<(&[f64], &[f64])>, f64) -> Result<StepResult, ContactError>,
    ) -> Result<(StepResult, VelDepOutcome), ContactError> {
        let n = pn.len();
        let fstat = self.law.mu_static();
        // μ_prev of a transient step: the previous step's μ moved by dq (FSTAT entering, and
        // everywhere after a start from zero; m_sdis.f90 line 303, m_stang.f90 line 309).
        let moved_mu = match (motion.steady, self.has_previous) {
            (false, true) => shift_rows(&self.mu, self.mx, motion.shift_elements, fstat),
            _ => vec![fstat; n],
        };
        let mut s = self.initial_slip(pn, motion);
        // The last steps' field extrapolated, taken over once CONTACT's path holds their branch.
        let mut settle = self.settle_target(pn, motion);
        let (mut mu, mut mu_prev, mut bound) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut omgslp = self.options.omgslp;
        let mut last: Option<StepResult> = None;
        let mut inner = 0;
        let mut s_new = vec![0.0; n];
        let mut last_change = None;
        // The next solve starts as the step's first (`start` None), not from the last iterate.
        let mut settled_now = false;
        for it in 1..=self.options.max_iterations {
            self.friction_field(&s, &moved_mu, motion, &mut mu, &mut mu_prev);
            for k in 0..n {
                bound[k] = mu[k] * pn[k];
            }
            // Adaptive: the last iterate's slip area on the new bound.
            let from = if std::mem::take(&mut settled_now) { None } else { last.as_ref() };
            let on_bound =
                from.filter(|_| self.options.adaptive_solves).map(|r| onto_bound(&r.px, &r.py, &r.state, &bound));
            let start = match (&on_bound, from) {
                (Some((x, y)), _) => Some((x.as_slice(), y.as_slice())),
                (None, Some(r)) => Some((r.px.as_slice(), r.py.as_slice())),
                (None, None) => None,
            };
            let tol = if self.options.adaptive_solves {
                inner_tolerance(self.options.solve_tolerance, last_change)
            } else {
                self.options.solve_tolerance
            };
            let r = solve(&bound, start, tol)?;
            inner += r.iterations;
            for k in 0..n {
                s_new[k] = if pn[k] > 0.0 { r.sx[k].hypot(r.sy[k]) / motion.dt_s } else { 0.0 };
            }
            let (dif, size) = rms_pair(pn, &s_new, &s);
            let change = if size > 0.0 { dif / size } else { 0.0 };
            // A loose solve that happened to get as tight as the final one counts as final.
            let tight = tol <= self.options.solve_tolerance || r.residual <= self.options.solve_tolerance;
            let converged = tight && (dif <= self.options.tolerance * size || r.n_slip == 0);
            let changed = last.as_ref().is_some_and(|l| l.state != r.state);
            if converged || it == self.options.max_iterations {
                let outcome = VelDepOutcome { iterations: it, converged, change, inner_iterations: inner };
                self.keep(&r, &mu, &s_new, motion.steady);
                return Ok((r, outcome));
            }
            for k in 0..n {
                let damp = it > 1 && r.state[k] == ElementState::Slip && mu[k] > mu_prev[k];
                s[k] = if damp { (omgslp * s_new[k] + (1.0 - omgslp) * s[k]).max(0.0) } else { s_new[k] };
            }
            last_change = Some(change);
            let held = !changed && last.is_some() && r.state == self.recent_state;
            if let Some(target) = settle.take_if(|_| held) {
                // Two iterates of CONTACT's path in the last step's element division: go on from
                // that step's branch extrapolated, solved tightly from here, the next solve started
                // as the step's first (the last steps' tractions extrapolated, on the new bound).
                s = target;
                last_change = Some(0.0);
                settled_now = true;
            }
            if changed && it % 20 == 0 {
                omgslp *= 0.8;
            }
            last = Some(r);
        }
        unreachable!("the loop returns at its last iteration (max_iterations >= 1)")
    }

    /// The start of s (m_stang.f90 lines 258-264): the previous step's |S|/dt moved by dq
    /// (`Previous` in a transient step; 0 in steady rolling and from zero), 0, or V everywhere;
    /// `Extrapolated` after a transient step: the last two extrapolated ([`extrapolated_slip`]).
    fn initial_slip(&self, pn: &[f64], motion: Motion) -> Vec<f64> {
        let n = pn.len();
        match self.options.initial {
            InitialSlip::Below => vec![0.0; n],
            InitialSlip::Above => vec![motion.v_mm_s; n],
            InitialSlip::Previous | InitialSlip::Extrapolated if motion.steady || !self.has_previous => vec![0.0; n],
            InitialSlip::Extrapolated if !self.recent_mm_s.is_empty() => extrapolated_slip(&self.recent_mm_s, pn),
            InitialSlip::Previous | InitialSlip::Extrapolated => {
                let moved = shift_rows(&self.shift_mm, self.mx, motion.shift_elements, 0.0);
                moved.iter().zip(pn).map(|(&s, &p)| if p > 0.0 { s / motion.dt_s } else { 0.0 }).collect()
            }
        }
    }

    /// With adaptive solves, CONTACT's start (`Previous`) in a transient step after a transient
    /// step: the last two steps' slip velocity extrapolated ([`extrapolated_slip`]), which the
    /// iteration takes over once two of its iterates have the last step's element division (at a
    /// stationary state the extrapolated field is the solution, where CONTACT's moved start is
    /// one element off it and needs about ten iterations to come back).
    fn settle_target(&self, pn: &[f64], motion: Motion) -> Option<Vec<f64>> {
        let contacts = self.options.adaptive_solves && self.options.initial == InitialSlip::Previous;
        let after_step = !motion.steady && self.has_previous && !self.recent_mm_s.is_empty();
        (contacts && after_step && self.recent_state.len() == pn.len())
            .then(|| extrapolated_slip(&self.recent_mm_s, pn))
    }

    /// μ per element from s: the law and the memory recursion along each row from the leading
    /// edge (m_stang.f90 lines 296-335); `mu_prev` receives each element's μ_prev.
    fn friction_field(&self, s: &[f64], moved_mu: &[f64], motion: Motion, mu: &mut [f64], mu_prev: &mut [f64]) {
        let (mx, fstat) = (self.mx, self.law.mu_static());
        for (row, (mu_row, prev_row)) in mu.chunks_mut(mx).zip(mu_prev.chunks_mut(mx)).enumerate() {
            let base = row * mx;
            let mut upstream = fstat;
            for i in 0..mx {
                let before = if motion.steady { upstream } else { moved_mu[base + i] };
                prev_row[i] = before;
                mu_row[i] = self.memory.update(&self.law, before, motion.dt_s, s[base + i]);
                upstream = mu_row[i];
            }
        }
    }

    /// Keep the converged step's μ, |S| and slip velocity `s_mm_s` for the next step.
    fn keep(&mut self, r: &StepResult, mu: &[f64], s_mm_s: &[f64], steady: bool) {
        self.mu.copy_from_slice(mu);
        for (k, s) in self.shift_mm.iter_mut().enumerate() {
            *s = r.sx[k].hypot(r.sy[k]);
        }
        self.has_previous = true;
        if steady {
            self.recent_mm_s.clear();
            self.recent_state.clear();
        } else {
            self.recent_state.clone_from(&r.state);
            self.recent_mm_s.truncate(1);
            self.recent_mm_s.insert(0, s_mm_s.to_vec());
        }
    }
}

/// A warm start for the bound `bound` [MPa] from the tractions `px`, `py` [MPa] of a solve whose
/// element division was `state`: its slip elements moved onto the new bound along their
/// direction (else, inside a bound that grew, they would start as adhesion and the solve would
/// first have to find the slip area again), the others as they are.
pub fn onto_bound(px: &[f64], py: &[f64], state: &[ElementState], bound: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let (mut x, mut y) = (px.to_vec(), py.to_vec());
    for k in 0..x.len() {
        if state[k] == ElementState::Slip {
            (x[k], y[k]) = scale_to_bound(px[k], py[k], bound[k]);
        }
    }
    (x, y)
}

/// The adaptive start of a transient step's slip velocity [mm/s] from the last two steps'
/// (`recent`, last first) in the contact's frame: `max(0, 2 s_(k−1) − s_(k−2))`, or `s_(k−1)`
/// after one step; 0 outside the contact. A stationary field is its own prediction, where the
/// previous field moved by dq (CONTACT's start) is one element off it.
fn extrapolated_slip(recent: &[Vec<f64>], pn: &[f64]) -> Vec<f64> {
    let last = &recent[0];
    let older = recent.get(1).unwrap_or(last);
    (0..pn.len()).map(|k| if pn[k] > 0.0 { (2.0 * last[k] - older[k]).max(0.0) } else { 0.0 }).collect()
}

/// The warm start of a transient step's first solve on the bound `bound` [MPa]: the last two
/// steps' tractions extrapolated in time, `2 p_n − p_(n−1)` (`p_n` without `older`; as
/// [`super::tangential::TangentialSolver::transient_step`] makes it), the last step's slip area
/// `state` on the new bound ([`onto_bound`]).
pub fn step_start(
    px: &[f64],
    py: &[f64],
    older: Option<(&[f64], &[f64])>,
    state: &[ElementState],
    bound: &[f64],
) -> (Vec<f64>, Vec<f64>) {
    let (x, y): (Vec<f64>, Vec<f64>) = match older {
        Some((ox, oy)) => (
            px.iter().zip(ox).map(|(&p, &o)| 2.0 * p - o).collect(),
            py.iter().zip(oy).map(|(&p, &o)| 2.0 * p - o).collect(),
        ),
        None => (px.to_vec(), py.to_vec()),
    };
    onto_bound(&x, &y, state, bound)
}

/// rms over the contact elements (pn > 0) of `a − b` and of `a` (CONTACT's gf3_rms over AllInt).
pub(super) fn rms_pair(pn: &[f64], a: &[f64], b: &[f64]) -> (f64, f64) {
    let (mut d2, mut a2, mut n) = (0.0, 0.0, 0usize);
    for k in 0..pn.len() {
        if pn[k] > 0.0 {
            d2 += (a[k] - b[k]) * (a[k] - b[k]);
            a2 += a[k] * a[k];
            n += 1;
        }
    }
    let n = n.max(1) as f64;
    ((d2 / n).sqrt(), (a2 / n).sqrt())
}

/// A field moved with the material by `shift` elements along +x (linear between elements for a
/// fractional shift), `fill` entering at the leading edge (CONTACT's `gf3_dq_shift`).
fn shift_rows(field: &[f64], mx: usize, shift: f64, fill: f64) -> Vec<f64> {
    let whole = shift.floor();
    let frac = shift - whole;
    let whole = whole as isize;
    let at = |row: &[f64], i: isize| if i >= 0 && (i as usize) < row.len() { row[i as usize] } else { fill };
    let mut out = Vec::with_capacity(field.len());
    for row in field.chunks(mx) {
        for i in 0..mx as isize {
            let near = at(row, i - whole);
            out.push(if frac == 0.0 { near } else { (1.0 - frac) * near + frac * at(row, i - whole - 1) });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_move_downstream_with_fill_at_the_leading_edge() {
        let f = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(shift_rows(&f, 3, 1.0, 0.5), vec![0.5, 1.0, 2.0, 0.5, 4.0, 5.0]);
        assert_eq!(shift_rows(&f, 3, 0.5, 0.0), vec![0.5, 1.5, 2.5, 2.0, 4.5, 5.5]);
    }

    #[test]
    fn slip_elements_start_on_the_new_bound_others_as_they_were() {
        use ElementState::{Adhesion, Exterior, Slip};
        let state = [Slip, Adhesion, Slip, Exterior];
        let (x, y) = onto_bound(&[3.0, 1.0, -2.0, 0.0], &[4.0, 0.5, 0.0, 0.0], &state, &[10.0, 10.0, 1.0, 0.0]);
        assert_eq!(x, vec![6.0, 1.0, -1.0, 0.0]);
        assert_eq!(y, vec![8.0, 0.5, 0.0, 0.0]);
    }

    #[test]
    fn a_step_starts_from_the_extrapolated_tractions_on_the_new_bound() {
        let state = [ElementState::Slip, ElementState::Adhesion];
        let (x, y) = step_start(&[2.0, 1.0], &[0.0, 1.0], Some((&[1.0, 0.5], &[0.0, 0.0])), &state, &[5.0, 9.0]);
        assert_eq!((x, y), (vec![5.0, 1.5], vec![0.0, 2.0]));
        let (x, _) = step_start(&[2.0, 1.0], &[0.0, 1.0], None, &state, &[5.0, 9.0]);
        assert_eq!(x, vec![5.0, 1.0]);
    }

    #[test]
    fn slip_velocity_extrapolates_in_the_contact_frame_not_below_zero() {
        let pn = [1.0, 1.0, 0.0];
        let recent = vec![vec![3.0, 1.0, 7.0], vec![2.0, 4.0, 7.0]];
        assert_eq!(extrapolated_slip(&recent, &pn), vec![4.0, 0.0, 0.0]);
        assert_eq!(extrapolated_slip(&recent[..1], &pn), vec![3.0, 1.0, 0.0]);
    }

    #[test]
    fn rms_over_contact_only() {
        let (d, a) = rms_pair(&[1.0, 0.0, 1.0], &[3.0, 100.0, 4.0], &[0.0, 0.0, 4.0]);
        assert!((d - (4.5f64).sqrt()).abs() < 1e-15);
        assert!((a - (12.5f64).sqrt()).abs() < 1e-15);
    }
}
