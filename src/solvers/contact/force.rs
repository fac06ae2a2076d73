//! Prescribed total tangential forces (CONTACT F = 1: Fx/FN given, cy given; F = 2: Fx/FN and
//! Fy/FN given): the creepages that give them, found by an outer iteration around the tangential
//! solve — Broyden's method (Broyden 1965; Dennis & Schnabel 1996 §8.1) started from Kalker's
//! linear theory (the creepage `f/slope` and the Jacobian `diag(G a b C11, G a b C22)/FN`), each
//! step halved until the force error shrinks. It stops when every prescribed ratio is met within
//! [`FORCE_TOL`] · μ, far below the 4 digits CONTACT prints.

use super::tangential::{StepResult, TangentialParams};
use super::ContactError;
use crate::problem::Sample;
use crate::solvers::Termination;

/// Stopping test: `|f_reached − f_prescribed| <= FORCE_TOL · μ` for each prescribed ratio.
pub const FORCE_TOL: f64 = 1e-8;

/// Most outer iterations (each one tangential solve, plus the halvings).
pub const MAX_OUTER: usize = 60;

/// Most halvings of one Broyden step.
const MAX_HALVINGS: usize = 4;

/// The largest change of a creepage in one Broyden step, in units of μ/slope (the creepage at
/// which Kalker's linear theory reaches full slip): near saturation the force hardly moves with
/// the creepage and a Newton step from there (or a Jacobian kept from such a point) would leap
/// far beyond any solution; a trust region of this size walks there instead, doubled after each
/// step it shortened that was taken whole (a far solution is reached in logarithmically many).
const STEP_CAP: f64 = 2.0;

/// The forces prescribed, per FN (`None`: that creepage is given).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Targets {
    pub fx: Option<f64>,
    pub fy: Option<f64>,
}

/// The outer iteration's result: the creepages found, the last solve's result (at them), the
/// force ratios it reached and whether they meet [`FORCE_TOL`].
#[derive(Debug)]
pub struct Found<R> {
    pub cx: f64,
    pub cy: f64,
    pub result: R,
    pub reached: [f64; 2],
    pub met: bool,
    /// Tangential solves made.
    pub solves: usize,
}

impl Targets {
    /// The sample's prescribed forces, if any.
    pub fn of(s: &Sample) -> Option<Targets> {
        s.prescribes_force().then_some(Targets { fx: s.fx_target, fy: s.fy_target })
    }
}

/// One tangential solve by `solve` at the sample's creepages, or, where the sample prescribes
/// forces, at the creepages that give them: then also the creepages found, and the result's
/// termination [`Termination::ForceNotReached`] when the force was not met. `pn_sum`: Σ pn, whose
/// ratio to Σ p is f.
pub fn solve_sample(
    at: &Sample,
    params: &TangentialParams,
    slope: [f64; 2],
    pn_sum: f64,
    memory: &mut Memory,
    mut solve: impl FnMut(&TangentialParams) -> Result<StepResult, ContactError>,
) -> Result<(StepResult, Option<[f64; 2]>), ContactError> {
    let Some(targets) = Targets::of(at) else {
        return Ok((solve(params)?, None));
    };
    let found = self::solve(targets, [params.cx, params.cy], slope, params.mu, memory, |cx, cy| {
        let r = solve(&TangentialParams { cx, cy, ..*params })?;
        let f = [r.px.iter().sum::<f64>() / pn_sum, r.py.iter().sum::<f64>() / pn_sum];
        Ok((r, f))
    })?;
    let mut r = found.result;
    if !found.met {
        r.termination = Termination::ForceNotReached;
    }
    Ok((r, Some([found.cx, found.cy])))
}

/// The prescribed ratios' indices (0 = x, 1 = y) and values.
fn unknowns(t: Targets) -> Vec<(usize, f64)> {
    [t.fx, t.fy].iter().enumerate().filter_map(|(i, f)| f.map(|f| (i, f))).collect()
}

/// What the iteration keeps from one sample to the next: the last creepages found and the
/// Jacobian at them (a history's next step starts there).
#[derive(Debug, Clone, Default)]
pub struct Memory {
    last: Option<(Vec<usize>, Vec<f64>, Vec<f64>)>,
}

impl Memory {
    /// The next sample starts from zero creepage, the last Jacobian kept: a shift's increment
    /// after the contact changed (a new load or undeformed distance: the last increment, which
    /// may have been the first shift from rest, is no guess of the next).
    pub fn from_rest(&mut self) {
        if let Some((_, u, _)) = self.last.as_mut() {
            u.iter_mut().for_each(|v| *v = 0.0);
        }
    }
}

/// Find the creepages giving `targets`. `given` holds the creepages (cx, cy) of the directions
/// not prescribed; `slope` Kalker's linear d(f)/d(c) per direction (> 0); `eval(cx, cy)` solves
/// the tangential problem and gives its result with the force ratios reached. Starts from the
/// last sample's creepages and Jacobian (`memory`), else from the linear theory's; each step is
/// kept within [`STEP_CAP`] μ/slope per creepage; a Broyden step that does not shrink the error
/// after a few halvings has its Jacobian remade by differences.
pub fn solve<R>(
    targets: Targets,
    given: [f64; 2],
    slope: [f64; 2],
    mu: f64,
    memory: &mut Memory,
    mut eval: impl FnMut(f64, f64) -> Result<(R, [f64; 2]), ContactError>,
) -> Result<Found<R>, ContactError> {
    let idx = unknowns(targets);
    let dirs: Vec<usize> = idx.iter().map(|&(i, _)| i).collect();
    let n = idx.len();
    let tol = FORCE_TOL * mu;
    let creepage = |u: &[f64]| {
        let mut c = given;
        for (k, &i) in dirs.iter().enumerate() {
            c[i] = u[k];
        }
        c
    };
    let residual = |f: [f64; 2]| idx.iter().map(|&(i, t)| f[i] - t).collect::<Vec<f64>>();
    let norm = |r: &[f64]| r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let (mut u, mut jac) = match memory.last.take() {
        Some((d, u, j)) if d == dirs => (u, j),
        _ => (
            idx.iter().map(|&(i, t)| t / slope[i]).collect(),
            diag(&dirs.iter().map(|&i| slope[i]).collect::<Vec<_>>()),
        ),
    };
    let mut solves = 0;
    let mut at = |u: &[f64], solves: &mut usize| {
        *solves += 1;
        let c = creepage(u);
        eval(c[0], c[1]).map(|(r, f)| (r, f, residual(f)))
    };
    let (mut result, mut f, mut r) = at(&u, &mut solves)?;
    let mut remade = false;
    let mut cap: Vec<f64> = dirs.iter().map(|&i| STEP_CAP * mu / slope[i]).collect();
    while norm(&r) > tol && solves < MAX_OUTER {
        // A singular Jacobian (the force flat in the creepage: Broyden's update after steps in
        // full slip) gives no step; a line search along it would solve the same creepages again
        // (up to MAX_HALVINGS + 1 times): it is left out and the Jacobian remade or the root
        // bracketed below.
        let mut best = None;
        if let Some(step) = solve_linear(&jac, &r, n) {
            // The whole step shortened to the trust region (its direction kept).
            let capped =
                step.iter().zip(&cap).fold(1.0f64, |l, (s, c)| if s.abs() > *c { l.min(c / s.abs()) } else { l });
            let mut lambda = capped;
            for _ in 0..=MAX_HALVINGS {
                let u_new: Vec<f64> = u.iter().zip(&step).map(|(a, s)| a - lambda * s).collect();
                let out = at(&u_new, &mut solves)?;
                // Broyden's update: J += (Δr − J Δu) Δuᵀ / (Δuᵀ Δu).
                broyden(&mut jac, &u_new, &u, &out.2, &r);
                if norm(&out.2) < norm(&r) {
                    best = Some((u_new, out, capped < 1.0 && lambda == capped));
                    break;
                }
                if solves >= MAX_OUTER {
                    break;
                }
                lambda *= 0.5;
            }
        }
        match best {
            Some((u_new, out, whole_capped_step)) => {
                (u, result, f, r) = (u_new, out.0, out.1, out.2);
                remade = false;
                if whole_capped_step {
                    cap.iter_mut().for_each(|c| *c *= 2.0);
                }
            }
            None if !remade && solves + n < MAX_OUTER => {
                jac = differences(&u, &r, &mut |v: &[f64]| at(v, &mut solves).map(|o| o.2))?;
                remade = true;
            }
            None if n == 1 => {
                // One creepage sought and the force does not move with it (full slip, e.g. a
                // small μ far from the creepage sought): bracket the target by doubling steps
                // along the linear theory's direction, then regula falsi inside the bracket.
                let sign = -r[0].signum();
                let budget = MAX_OUTER.saturating_sub(solves);
                let mut at1 = |v: f64| at(&[v], &mut solves).map(|(res, f, r)| (res, f, r[0]));
                if let Some((v, out)) = bracket(u[0], r[0], (sign * mu / slope[dirs[0]], budget), tol, &mut at1)? {
                    (u, result, f, r) = (vec![v], out.0, out.1, vec![out.2]);
                }
                break;
            }
            None => break,
        }
    }
    let c = creepage(&u);
    memory.last = Some((dirs, u, jac));
    Ok(Found { cx: c[0], cy: c[1], result, reached: f, met: norm(&r) <= tol, solves })
}

/// The root of a one-creepage residual `at(v)` (its result, forces and residual) from `u0`
/// (residual `r0`) where the residual is flat: steps `h`, `2h`, `4h` … from `u0` until the
/// residual changes sign (at most 60 doublings), then the Illinois regula falsi inside the
/// bracket until |residual| ≤ `tol`, at most `budget` evaluations (solves) in all; `None`: no
/// bracket found. The best point found is returned even if the tolerance was not met.
#[allow(clippy::type_complexity)]
fn bracket<R>(
    u0: f64,
    r0: f64,
    (h, budget): (f64, usize),
    tol: f64,
    at: &mut dyn FnMut(f64) -> Result<(R, [f64; 2], f64), ContactError>,
) -> Result<Option<(f64, (R, [f64; 2], f64))>, ContactError> {
    if !(h.is_finite() && h != 0.0) {
        return Ok(None);
    }
    let (mut a, mut ra) = (u0, r0);
    let mut step = h;
    let mut far = None;
    let mut evals = 0;
    for _ in 0..60.min(budget) {
        evals += 1;
        let v = u0 + step;
        let out = at(v)?;
        if out.2.signum() != r0.signum() || out.2.abs() <= tol {
            far = Some((v, out));
            break;
        }
        (a, ra) = (v, out.2);
        step *= 2.0;
    }
    let Some((b0, first)) = far else { return Ok(None) };
    let (mut b, mut rb) = (b0, first.2);
    let mut best = (b0, first);
    let mut side = 0;
    for _ in evals..budget {
        if best.1 .2.abs() <= tol || rb == ra {
            break;
        }
        let v = (a * rb - b * ra) / (rb - ra);
        let out = at(v)?;
        let rv = out.2;
        if rv.signum() == rb.signum() {
            (b, rb) = (v, rv);
            if side == -1 {
                ra *= 0.5;
            }
            side = -1;
        } else {
            (a, ra) = (v, rv);
            if side == 1 {
                rb *= 0.5;
            }
            side = 1;
        }
        if rv.abs() < best.1 .2.abs() {
            best = (v, out);
        }
    }
    Ok(Some(best))
}

/// Broyden's rank-one update of `jac` (row-major n×n) by the step u → u_new, r → r_new.
fn broyden(jac: &mut [f64], u_new: &[f64], u: &[f64], r_new: &[f64], r: &[f64]) {
    let n = u.len();
    let du: Vec<f64> = u_new.iter().zip(u).map(|(a, b)| a - b).collect();
    let dd: f64 = du.iter().map(|v| v * v).sum();
    if dd == 0.0 {
        return;
    }
    for a in 0..n {
        let jdu: f64 = (0..n).map(|b| jac[a * n + b] * du[b]).sum();
        for b in 0..n {
            jac[a * n + b] += (r_new[a] - r[a] - jdu) * du[b] / dd;
        }
    }
}

/// The residual of the prescribed forces at the creepages it is given.
type Residual<'a> = dyn FnMut(&[f64]) -> Result<Vec<f64>, ContactError> + 'a;

/// The Jacobian by forward differences at `u` (residual `r`), a step of 1e-4 of |u| (or 1e-8).
fn differences(u: &[f64], r: &[f64], at: &mut Residual<'_>) -> Result<Vec<f64>, ContactError> {
    let n = u.len();
    let mut jac = vec![0.0; n * n];
    for b in 0..n {
        let h = (1e-4 * u[b].abs()).max(1e-8);
        let mut v = u.to_vec();
        v[b] += h;
        let rv = at(&v)?;
        for a in 0..n {
            jac[a * n + b] = (rv[a] - r[a]) / h;
        }
    }
    Ok(jac)
}

/// A diagonal n×n matrix, row-major.
fn diag(d: &[f64]) -> Vec<f64> {
    let n = d.len();
    let mut m = vec![0.0; n * n];
    for (k, v) in d.iter().enumerate() {
        m[k * n + k] = *v;
    }
    m
}

/// `J⁻¹ r` for n = 1 or 2 (`None`: J singular).
fn solve_linear(j: &[f64], r: &[f64], n: usize) -> Option<Vec<f64>> {
    let finite = |v: Vec<f64>| v.iter().all(|x| x.is_finite()).then_some(v);
    match n {
        1 if j[0] != 0.0 => finite(vec![r[0] / j[0]]),
        2 => {
            let det = j[0] * j[3] - j[1] * j[2];
            if det == 0.0 {
                return None;
            }
            finite(vec![(j[3] * r[0] - j[1] * r[1]) / det, (j[0] * r[1] - j[2] * r[0]) / det])
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A saturating law with coupling: the iteration finds its inverse to the tolerance.
    #[test]
    fn finds_the_creepages_of_a_saturating_law() {
        let mu = 0.3;
        let law = |cx: f64, cy: f64| {
            let (lx, ly) = (100.0 * cx + 5.0 * cy, 120.0 * cy);
            let w = lx.hypot(ly);
            let s = if w == 0.0 { 0.0 } else { mu * (1.0 - (1.0 - (w / (3.0 * mu)).min(1.0)).powi(3)) / w };
            [lx * s, ly * s]
        };
        let targets = Targets { fx: Some(0.25), fy: Some(-0.1) };
        let found =
            solve(targets, [0.0, 0.0], [100.0, 120.0], mu, &mut Memory::default(), |cx, cy| Ok(((), law(cx, cy))))
                .unwrap();
        assert!(found.met, "{found:?}");
        let f = law(found.cx, found.cy);
        assert!((f[0] - 0.25).abs() <= FORCE_TOL * mu && (f[1] + 0.1).abs() <= FORCE_TOL * mu, "{f:?}");
        assert!(found.solves < 30, "{} solves", found.solves);
    }

    /// A force the law cannot give: the iteration stops and says so.
    #[test]
    fn says_when_the_force_is_not_reached() {
        let found = solve(
            Targets { fx: Some(0.2), fy: None },
            [0.0, 0.0],
            [100.0, 100.0],
            0.3,
            &mut Memory::default(),
            |cx, _| Ok(((), [(100.0 * cx).clamp(-0.1, 0.1), 0.0])),
        )
        .unwrap();
        assert!(!found.met);
        assert_eq!(found.reached[0], 0.1);
        assert!(found.solves <= MAX_OUTER);
    }

    /// Steady points in any order, each starting from the last one's creepage and Jacobian: a
    /// near-saturated point (slope ~1e-3 of the linear one) followed by a small force, the
    /// opposite saturation and back, on a law approaching μ as 1/c (as rolling contact does).
    #[test]
    fn far_targets_after_a_saturated_point_are_reached() {
        let (mu, slope) = (0.33, 200.0);
        let law = |cx: f64| {
            let w = slope * cx / mu;
            mu * w / (1.0 + w.abs())
        };
        let mut memory = Memory::default();
        for target in [0.98 * mu, 0.001, -0.99 * mu, 0.5 * mu, 0.999 * mu, 0.0] {
            let t = Targets { fx: Some(target), fy: None };
            let found =
                solve(t, [0.0, 0.0], [slope, slope], mu, &mut memory, |cx, _| Ok(((), [law(cx), 0.0]))).unwrap();
            assert!(found.met, "target {target}: {found:?}");
            assert!((law(found.cx) - target).abs() <= FORCE_TOL * mu, "target {target}: {found:?}");
        }
    }

    /// Full slip at the start, the force flat in the creepage for 5000 μ/slope (a small μ and a
    /// free-rolling creepage far from zero, as bentall.inp case 2): bracketed and found.
    #[test]
    fn a_flat_start_in_full_slip_is_bracketed() {
        let (mu, slope, c0) = (1e-4, 3000.0, 5.26e-4);
        let law = |cx: f64| mu * (slope * (cx - c0) / mu).tanh();
        let t = Targets { fx: Some(0.0), fy: None };
        let found =
            solve(t, [0.0, 0.0], [slope, slope], mu, &mut Memory::default(), |cx, _| Ok(((), [law(cx), 0.0]))).unwrap();
        assert!(found.met && law(found.cx).abs() <= FORCE_TOL * mu, "{found:?}");
        assert!((found.cx - c0).abs() < 1e-12 && found.solves <= MAX_OUTER, "{found:?}");
    }

    /// A Jacobian kept from full slip is zero (singular): no solve is repeated at the same
    /// creepages (before, the line search solved the start again MAX_HALVINGS + 1 times, as in
    /// bentall.inp case 6's second outer iteration); the Jacobian is remade and the force found.
    #[test]
    fn a_singular_jacobian_solves_no_creepage_twice() {
        let (mu, slope) = (0.05, 300.0);
        let law = |cx: f64| mu * (slope * (cx - 1e-4) / mu).tanh();
        let mut memory = Memory { last: Some((vec![0], vec![2e-4], vec![0.0])) };
        let mut seen: Vec<f64> = Vec::new();
        let t = Targets { fx: Some(0.01), fy: None };
        let found = solve(t, [0.0, 0.0], [slope, slope], mu, &mut memory, |cx, _| {
            seen.push(cx);
            Ok(((), [law(cx), 0.0]))
        })
        .unwrap();
        assert!(found.met && (law(found.cx) - 0.01).abs() <= FORCE_TOL * mu, "{found:?}");
        assert!(seen.windows(2).all(|w| w[0] != w[1]), "{seen:?}");
        assert_eq!(found.solves, seen.len());
    }

    /// F = 1: only cx is sought; cy stays as given.
    #[test]
    fn keeps_the_given_creepage() {
        let found = solve(
            Targets { fx: Some(0.01), fy: None },
            [0.0, 0.002],
            [100.0, 100.0],
            0.3,
            &mut Memory::default(),
            |cx, cy| Ok(((), [100.0 * cx + cy, 100.0 * cy])),
        )
        .unwrap();
        assert_eq!(found.cy, 0.002);
        assert!((found.cx - (0.01 - 0.002) / 100.0).abs() < 1e-12, "{}", found.cx);
    }
}
