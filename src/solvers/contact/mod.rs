//! The compact non-steady CONTACT-style solver: Kalker's exact theory for quasi-identical
//! elastic half-spaces on the scene's grid (Kalker 1990, ch. 5; Vollebregt & Kalker, CONTACT),
//! one module per sub-problem as in CONTACT:
//!
//! - [`influence`]: influence coefficients of uniformly loaded rectangles (Boussinesq, Cerruti),
//!   kept as translation-invariant kernels, once unshifted and once shifted by the rolling
//!   distance per step;
//! - [`convolution`]: u = A p by direct sums (small grids) or zero-padded 2-D FFT;
//! - [`normal`]: the normal problem for the prescribed FN (bound-constrained CG, as NormCG);
//! - [`tangential`]: steady and transient rolling with Coulomb friction per time step:
//!   transient steps by a projected CG with FFT products (as CONTACT's TangCG, falling back to
//!   projected Gauss–Seidel as ConvexGS); steady rolling by an Anderson-accelerated projected
//!   iteration (Walker & Ni 2011) that undoes the one-element shift along adhesion rows, stopped
//!   by the same local-change test, Gauss–Seidel sweeps taking over if it stalls. Each transient
//!   step starts from the last two steps' tractions extrapolated in time.
//!
//! This file maps a resolved [`Problem`] onto them and writes the history. The undeformed
//! distance comes from the shared Hertz module, the grid from the shared physics.
//! Axes: leading edge at x = −a, material moving in +x (CONTACT rolls the other way: mirror x
//! when comparing fields).

pub mod convolution;
pub mod influence;
pub mod normal;
pub mod tangential;

use super::Solver;
use crate::error::Error;
use crate::history::{History, Row};
use crate::physics::{Grid, HertzContact, Material};
use crate::problem::{Problem, Sample};
use crate::scene::InitKind;
use influence::Kernel;
use normal::{solve_normal, NormalParams};
use std::fmt;
use tangential::{ElementState, StepResult, TangentialParams, TangentialSolver};

/// Errors of the contact core; no function of these modules panics on bad numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactError {
    /// An input value is out of range or not finite (which, and why).
    InvalidInput(String),
    /// Array lengths do not match the grid (what was expected).
    SizeMismatch(String),
    /// No grid element can carry load (e.g. the grid is too coarse to hold any contact).
    NoContact(String),
    /// A computation produced a non-finite number (where).
    NonFinite(String),
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ContactError::InvalidInput(s) => write!(f, "invalid input: {s}"),
            ContactError::SizeMismatch(s) => write!(f, "size mismatch: {s}"),
            ContactError::NoContact(s) => write!(f, "no contact: {s}"),
            ContactError::NonFinite(s) => write!(f, "non-finite result: {s}"),
        }
    }
}

impl std::error::Error for ContactError {}

/// Hertzian undeformed distance `h = A x² + B y²` [mm] at the element centres, with the
/// curvatures that give the ellipse `hertz` under its load (shared Hertz module).
pub fn undeformed_distance(grid: &Grid, hertz: &HertzContact, material: &Material) -> Vec<f64> {
    let (ca, cb) = hertz.undeformed_curvatures(material);
    let (x, y) = grid.centres();
    x.iter().zip(&y).map(|(x, y)| ca * x * x + cb * y * y).collect()
}

/// Kalker's exact theory for quasi-identical half-spaces (CONTACT-style).
pub struct ContactSolver;

/// Extra columns of `contact.csv`: per step the adhesion/slip counts, the iterations and final
/// residual of the tangential solve (a change in the counts is a drift signal), whether it
/// converged (1/0), and the largest element pressure of the normal solution [MPa].
pub const EXTRA: [&str; 6] = ["n_adhesion", "n_slip", "iterations", "residual", "converged", "pn_max_mpa"];

/// The traction field of one step, for field comparisons (tests, reports).
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub step: usize,
    pub pn_mpa: Vec<f64>,
    pub px_mpa: Vec<f64>,
    pub py_mpa: Vec<f64>,
    pub state: Vec<ElementState>,
}

/// The normal solution and the tangential solver for one load.
struct Loaded {
    fn_n: f64,
    pn: Vec<f64>,
    pn_sum: f64,
    pn_max: f64,
    solver: TangentialSolver,
}

fn fail(problem: &Problem, e: impl fmt::Display) -> Error {
    super::fail(problem, "contact", e.to_string())
}

fn load(problem: &Problem, k0: &Kernel, ks: &Kernel, fn_n: f64) -> Result<Loaded, Error> {
    let hertz = if fn_n == problem.hertz.fn_n { problem.hertz } else { problem.hertz.at_load(fn_n) };
    let h = undeformed_distance(&problem.grid, &hertz, &problem.material);
    let normal = solve_normal(&h, k0, fn_n, &NormalParams::default())
        .map_err(|e| fail(problem, format!("normal problem at FN = {fn_n} N: {e}")))?;
    if !normal.converged {
        return Err(fail(
            problem,
            format!(
                "normal problem at FN = {fn_n} N did not converge in {} iterations (residual {:.2e})",
                normal.iterations, normal.residual
            ),
        ));
    }
    let pn_sum: f64 = normal.pn_mpa.iter().sum();
    if pn_sum <= 0.0 {
        return Err(fail(
            problem,
            format!("no element of the {}x{} grid carries load", problem.grid.mx, problem.grid.my),
        ));
    }
    let (x, y) = problem.grid.centres();
    let solver = TangentialSolver::new(k0, ks, &normal.pn_mpa, &x, &y).map_err(|e| fail(problem, e))?;
    let pn_max = normal.pn_mpa.iter().fold(0.0f64, |a, &b| a.max(b));
    Ok(Loaded { fn_n, pn: normal.pn_mpa, pn_sum, pn_max, solver })
}

impl ContactSolver {
    /// Run the problem, keeping the traction fields of the steps `keep` selects.
    pub fn run_with_fields(problem: &Problem, keep: &dyn Fn(usize) -> bool) -> Result<(History, Vec<Field>), Error> {
        let g = &problem.grid;
        let mat = &problem.material;
        let kernel = |shift: f64| {
            Kernel::new(g.mx, g.my, g.dx_mm, g.dy_mm, mat.g_mpa, mat.poisson, shift).map_err(|e| fail(problem, e))
        };
        let (k0, ks) = (kernel(0.0)?, kernel(problem.dq_mm)?);
        let params = |s: &Sample| {
            let mut p = TangentialParams::new(s.mu, s.cx, s.cy, s.cs, problem.dq_mm);
            p.tol = problem.contact_solver.tolerance;
            p.max_iter = problem.contact_solver.max_iterations;
            p
        };
        let mut h = History::new("contact", &EXTRA);
        let mut fields = Vec::new();
        let mut record = |h: &mut History, s: &Sample, l: &Loaded, r: &StepResult| {
            let fx = r.px.iter().sum::<f64>() / l.pn_sum;
            let fy = r.py.iter().sum::<f64>() / l.pn_sum;
            let extra = vec![
                r.n_adhesion as f64,
                r.n_slip as f64,
                r.iterations as f64,
                r.residual,
                f64::from(u8::from(r.converged)),
                l.pn_max,
            ];
            h.rows.push(Row::new(s, fx, fy, extra));
            if keep(s.step) {
                fields.push(Field {
                    step: s.step,
                    pn_mpa: l.pn.clone(),
                    px_mpa: r.px.clone(),
                    py_mpa: r.py.clone(),
                    state: r.state.clone(),
                });
            }
        };
        let first = problem.initial.unwrap_or(problem.samples[0]);
        let mut l = load(problem, &k0, &ks, first.fn_n)?;
        if !problem.is_transient() {
            for s in &problem.samples {
                if s.fn_n != l.fn_n {
                    l = load(problem, &k0, &ks, s.fn_n)?;
                }
                let r =
                    l.solver.steady(&params(s), None).map_err(|e| fail(problem, format!("step {}: {e}", s.step)))?;
                record(&mut h, s, &l, &r);
            }
            return Ok((h, fields));
        }
        let n = g.len();
        let (mut prev_x, mut prev_y) = (vec![0.0; n], vec![0.0; n]);
        if let (InitKind::Steady, Some(s0)) = (problem.init, problem.initial) {
            let r =
                l.solver.steady(&params(&s0), None).map_err(|e| fail(problem, format!("initial steady state: {e}")))?;
            record(&mut h, &s0, &l, &r);
            (prev_x, prev_y) = (r.px, r.py);
        }
        let mut older: Option<(Vec<f64>, Vec<f64>)> = None;
        for s in &problem.samples {
            if s.fn_n != l.fn_n {
                l = load(problem, &k0, &ks, s.fn_n)?;
                older = None;
            }
            let r = l
                .solver
                .transient_step(&params(s), &prev_x, &prev_y, older.as_ref().map(|(a, b)| (a.as_slice(), b.as_slice())))
                .map_err(|e| fail(problem, format!("step {}: {e}", s.step)))?;
            if r.px.iter().chain(&r.py).any(|v| !v.is_finite()) {
                return Err(fail(problem, format!("non-finite traction at step {}", s.step)));
            }
            record(&mut h, s, &l, &r);
            older = Some((std::mem::take(&mut prev_x), std::mem::take(&mut prev_y)));
            (prev_x, prev_y) = (r.px, r.py);
        }
        Ok((h, fields))
    }
}

impl Solver for ContactSolver {
    fn name(&self) -> &str {
        "contact"
    }

    fn run(&self, problem: &Problem) -> Result<History, Error> {
        Ok(Self::run_with_fields(problem, &|_| false)?.0)
    }
}
