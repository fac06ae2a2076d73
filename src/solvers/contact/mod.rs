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

pub mod anderson;
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
use normal::{NormalParams, NormalSolver};
use std::fmt;
use tangential::{ElementState, StepResult, TangentialParams, TangentialSolver};

/// Errors of the contact core; no function of these modules panics on bad numbers.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// An input value is out of range or not finite.
    #[error("invalid input: {name} = {value} (must be {requirement})")]
    OutOfRange { name: &'static str, value: f64, requirement: &'static str },
    /// An input array holds a non-finite value.
    #[error("invalid input: {name} is not finite at element {index}")]
    NotFinite { name: &'static str, index: usize },
    /// A grid needs at least one element along each axis.
    #[error("invalid input: a grid of {mx} x {my} elements (needs mx, my >= 1)")]
    EmptyGrid { mx: usize, my: usize },
    /// An array's length does not match the grid.
    #[error("size mismatch: {name} has {len} entries, expected {expected}")]
    SizeMismatch { name: &'static str, len: usize, expected: usize },
    /// Two kernels belong to different grids (elements along x and y).
    #[error("size mismatch: kernels of a {}x{} and a {}x{} grid (or of different element sizes)", expected.0, expected.1, got.0, got.1)]
    GridMismatch { expected: (usize, usize), got: (usize, usize) },
    /// The rolling step of a solve differs from the shift of the solver's shifted kernel.
    #[error("invalid input: dq = {dq_mm} mm differs from the shifted kernel's shift {shift_mm} mm")]
    ShiftMismatch { dq_mm: f64, shift_mm: f64 },
    /// No grid element can carry load (e.g. the grid is too coarse to hold any contact).
    #[error("no contact: no grid element carries load")]
    NoContact,
    /// A computation produced a non-finite number (where).
    #[error("non-finite result: {0}")]
    NonFinite(&'static str),
    /// A convolver on the FFT path has no FFT data (an internal inconsistency).
    #[error("internal: FFT data missing for the FFT path")]
    MissingFft,
}

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

/// The normal solution of one load (set into the tangential solver by [`load`]).
struct Loaded {
    fn_n: f64,
    pn: Vec<f64>,
    pn_sum: f64,
    pn_max: f64,
}

fn fail(problem: &Problem, e: impl fmt::Display) -> Error {
    super::fail(problem, "contact", e.to_string())
}

/// Solves the normal problem at `fn_n` and sets its pressure into the tangential solver; the
/// kernels and plans of both solvers are built once per run.
fn load(
    problem: &Problem,
    normal: &mut NormalSolver,
    solver: &mut TangentialSolver,
    fn_n: f64,
) -> Result<Loaded, Error> {
    let hertz = if fn_n == problem.hertz.fn_n { problem.hertz } else { problem.hertz.at_load(fn_n) };
    let h = undeformed_distance(&problem.grid, &hertz, &problem.material);
    let normal = normal
        .solve(&h, fn_n, &NormalParams::default())
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
    solver.set_pressure(&normal.pn_mpa).map_err(|e| fail(problem, e))?;
    let pn_max = normal.pn_mpa.iter().fold(0.0f64, |a, &b| a.max(b));
    Ok(Loaded { fn_n, pn: normal.pn_mpa, pn_sum, pn_max })
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
        let (x, y) = g.centres();
        let mut solver = TangentialSolver::new(&k0, &ks, &x, &y).map_err(|e| fail(problem, e))?;
        let mut normal = NormalSolver::new(&k0).map_err(|e| fail(problem, e))?;
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
                f64::from(u8::from(r.termination.converged())),
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
        let mut l = load(problem, &mut normal, &mut solver, first.fn_n)?;
        if !problem.is_transient() {
            for s in &problem.samples {
                if s.fn_n != l.fn_n {
                    l = load(problem, &mut normal, &mut solver, s.fn_n)?;
                }
                let r = solver.steady(&params(s), None).map_err(|e| fail(problem, format!("step {}: {e}", s.step)))?;
                record(&mut h, s, &l, &r);
            }
            return Ok((h, fields));
        }
        let n = g.len();
        let (mut prev_x, mut prev_y) = (vec![0.0; n], vec![0.0; n]);
        if let (InitKind::Steady, Some(s0)) = (problem.init, problem.initial) {
            let r =
                solver.steady(&params(&s0), None).map_err(|e| fail(problem, format!("initial steady state: {e}")))?;
            record(&mut h, &s0, &l, &r);
            (prev_x, prev_y) = (r.px, r.py);
        }
        let mut older: Option<(Vec<f64>, Vec<f64>)> = None;
        for s in &problem.samples {
            if s.fn_n != l.fn_n {
                l = load(problem, &mut normal, &mut solver, s.fn_n)?;
                older = None;
            }
            let r = solver
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
