//! Tangential rolling-contact problem with Coulomb friction for one transient time step or for
//! steady rolling (Kalker 1990, sec. 5.4; Vollebregt & Kalker, CONTACT user guide, "ConvexGS").
//!
//! Per contact element `k` (pn_k > 0), traction bound `g_k = mu pn_k` [MPa]:
//! * rigid slip of the step `w_k = dq (cx - cs y_k, cy + cs x_k)` [mm];
//! * transient: previous displacement `u'_k = (A_s p')_k`, kernel shifted by `dq` (material that is
//!   at `x_k` now was at `x_k - dq`), slip `s_k = w_k + u'_k - (A p)_k` [mm];
//! * steady rolling: the fixed point `p' = p`, `s = w - (A - A_s) p`;
//! * adhesion `s_k = 0, |p_k| <= g_k`; slip `|p_k| = g_k, s_k = lambda p_k/|p_k|`, `lambda >= 0`.
//!
//! Three solvers (select with [`TangentialParams::method`] and [`TangentialParams::steady_method`]):
//!
//! * **Projected Gauss-Seidel** (CONTACT's ConvexGS family): element by element, with the other
//!   tractions fixed, the local 2x2 problem `s_k = t_k - D p_k` (`D = diag` of the operator at
//!   offset 0) is solved exactly: stick `p = D^-1 t` if `|D^-1 t| <= g`, else
//!   `(D + lambda/g I) p = t`, `|p| = g`, by a safeguarded 1-D Newton iteration. The slip field is
//!   kept exact by incremental updates of every contact element's slip when one traction changes
//!   (cost O(n_contact^2) per sweep). For steady rolling it sweeps each grid row from the
//!   trailing edge to the leading edge (the other order diverges for `A - A_s`); there it verifies
//!   and finishes the accelerated solution below, and is the fallback if that stalls.
//! * **Conjugate gradients** (TangCG type, Vollebregt, CONTACT user guide): preconditioned CG on
//!   the adhesion tractions and on the directions of the slip tractions (kept on the bound, with
//!   the circle's curvature `lambda/g` added to their stiffness), element sets updated every 4
//!   iterations (CG restarted on a change), products `A v` by FFT, preconditioner = inverse of the
//!   periodised `A`, blended on the slip elements with their diagonal by how fast they slip
//!   (see `apply_prec`), warm start = the previous traction extrapolated in time; the products of
//!   the search directions and the preconditioner run in single precision (the slip is recomputed
//!   exactly in double precision every 4 iterations and for the stopping test, so the solution
//!   meets the same test: iterative refinement). Falls back to Gauss-Seidel if it does not
//!   converge. This is the default for transient steps ([`Method::Auto`]): it needs about 10-20
//!   iterations of O(N log N) per step where Gauss-Seidel needs about 50 sweeps of O(n_contact^2).
//!   Measured on sine_f30_mu10_g88 (516 steps, release, alone): 21.4 s before these choices
//!   (35 iterations per step, FFT length 175, previous traction moved with the material as start),
//!   6.8 s after (16.9 per step); max |f - f_CONTACT| unchanged at 1.6e-7.
//! * **Accelerated steady rolling** (default, [`SteadyMethod::Accelerated`]): Anderson acceleration
//!   (Walker & Ni 2011, "Anderson acceleration for fixed-point iterations", SIAM J. Numer. Anal.
//!   49(4), 1715-1735; history depth 16, QR-updated least squares) of a preconditioned projected
//!   Jacobi map whose fixed points are the steady solutions: local Gauss-Seidel solves on the slip
//!   elements, and on the adhesion elements the correction `(I - S)^-1 M s`, with `M` the CG
//!   preconditioner (FFT inverse of the periodised `A`) and `(I - S)^-1` the inverse of the shift
//!   by `dq` along the rows (`A - A_s = A (I - S)` for the translation-invariant kernel), so that
//!   the transport that makes plain iterations slow is inverted exactly; every mixed iterate is
//!   projected onto the traction bound. Two FFT products per evaluation. It stops when the largest
//!   local change (every element's local solve at the exact slip of the iterate) is below `tol`,
//!   the test of the CG solver. (A verifying Gauss-Seidel sweep after that, O(n_contact^2), took
//!   more than half the time at 88x88 and changed f by < 1e-9; it was dropped.) A sweep's warm
//!   start is the previous point's solution extrapolated along the creepage line. If the iteration
//!   stalls, diverges or produces non-finite values, Gauss-Seidel continues from the best iterate
//!   with its full sweep budget. Measured (release, 2-core Xeon) against Gauss-Seidel alone:
//!   steady_exact_g22 5.3 -> 1.5 ms per point, steady_exact_g44 143 -> 9 ms per point,
//!   steady_exact_g88 48 ms per point; max |f - f_CONTACT| 1.2e-7 (g22), 9.0e-8 (g44).
//!   (Anderson on the transient map `p' -> p`, each evaluation a warm-started CG solve, was tried
//!   first: about 26 evaluations of about 20 CG iterations per point at 44x44, no faster than
//!   Gauss-Seidel.)
//!
//! All stop when the largest traction change a local solve would make, relative to `max(g)`, is
//! below `tol` (Gauss-Seidel: `max|delta p|` of the last sweep; CG: the preconditioned residual at
//! an exact slip re-evaluation; accelerated steady: as Gauss-Seidel, by its final sweeps).

use super::convolution::Convolver;
use super::influence::Kernel;
use super::ContactError;

/// Parameters of one tangential solve. Creepages are dimensionless (`cs` in 1/mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TangentialParams {
    /// Coulomb friction coefficient (>= 0).
    pub mu: f64,
    /// Longitudinal creepage [-].
    pub cx: f64,
    /// Lateral creepage [-].
    pub cy: f64,
    /// Spin creepage [1/mm].
    pub cs: f64,
    /// Rolling distance per time step `dq` [mm]; must equal the shift of the shifted kernel.
    pub dq_mm: f64,
    /// Stop when the largest traction change a local solve would make, `max|delta p| / max(g)`,
    /// is below `tol` (default 1e-7; Gauss-Seidel: over the last sweep).
    pub tol: f64,
    /// Maximum Gauss-Seidel sweeps or CG iterations (default 1000); a CG that does not converge
    /// continues with up to as many Gauss-Seidel sweeps. The accelerated steady solver makes at
    /// most `min(max_iter, 400)` map evaluations before up to `max_iter` Gauss-Seidel sweeps.
    pub max_iter: usize,
    /// Gauss-Seidel relaxation factor for adhesion elements of transient steps (1 = plain
    /// Gauss-Seidel; see [`DEFAULT_OMEGA`]). Steady rolling always uses 1.
    pub omega: f64,
    /// Element order of the sweeps for transient steps.
    pub sweep_transient: SweepOrder,
    /// Element order of the sweeps for steady rolling.
    pub sweep_steady: SweepOrder,
    /// Solver for transient steps.
    pub method: Method,
    /// Solver for steady rolling (default [`SteadyMethod::Accelerated`]).
    pub steady_method: SteadyMethod,
}

/// Solver choice for steady rolling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SteadyMethod {
    /// Anderson-accelerated preconditioned projected fixed-point iteration (Walker & Ni 2011; see
    /// the module docs), verified and finished by Gauss-Seidel sweeps, which also take over if
    /// the acceleration stalls.
    Accelerated,
    /// Projected Gauss-Seidel only (trailing edge first).
    GaussSeidel,
}

/// Solver choice for transient steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Conjugate gradients for transient steps (measured faster than Gauss-Seidel at every grid
    /// size tried, 22x22 to 88x88).
    Auto,
    /// Projected Gauss-Seidel with exact incremental slip updates (ConvexGS).
    GaussSeidel,
    /// FFT-based nonlinear conjugate gradients on the adhesion set and the slip directions
    /// (TangCG type), falling back to Gauss-Seidel if it does not converge.
    ConjugateGradient,
}

/// Order in which a Gauss-Seidel sweep visits the elements of a grid row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepOrder {
    /// Leading edge first (`i` ascending, with the material flow).
    LeadingFirst,
    /// Trailing edge first (`i` descending, against the material flow; CONTACT's ConvexGS order).
    TrailingFirst,
}

/// Default relaxation factor: 1 (no SOR). Measured on the 22x22 CONTACT cases: omega = 1.2 / 1.4 /
/// 1.6 raised the transient sweeps per step (step_mu04: 46 -> 55 -> 67 -> 96 on average) and made
/// the steady sweeps fail to converge, so over-relaxation is off by default and never used for
/// steady rolling.
pub const DEFAULT_OMEGA: f64 = 1.0;

/// History depth of the accelerated steady solver. Measured on steady_exact_g44 (map
/// evaluations over the 101 points): depth 4 / 8 / 10 / 16 / 24: 6330 / 3143 / 2988 / 2826 / 2680
/// with little change in time beyond 10 (each extra column costs O(n_contact) per evaluation).
const STEADY_DEPTH: usize = 16;
/// At most this many map evaluations (and at most `max_iter`) before Gauss-Seidel takes over.
const STEADY_MAX_EVALS: usize = 400;
/// The accelerated iteration ends (Gauss-Seidel takes over) when the best residual has not halved
/// within this many evaluations.
const STEADY_STALL: usize = 40;
/// A residual above this multiple of the best one restarts the Anderson history from the best
/// map value.
const STEADY_BLOWUP: f64 = 1e3;
/// Restarts allowed before Gauss-Seidel takes over.
const STEADY_MAX_RESTARTS: usize = 3;

impl TangentialParams {
    /// Parameters with the default tolerance 1e-7, 1000 sweeps and [`DEFAULT_OMEGA`].
    pub fn new(mu: f64, cx: f64, cy: f64, cs: f64, dq_mm: f64) -> TangentialParams {
        TangentialParams {
            mu,
            cx,
            cy,
            cs,
            dq_mm,
            tol: 1e-7,
            max_iter: 1000,
            omega: DEFAULT_OMEGA,
            sweep_transient: SweepOrder::LeadingFirst,
            sweep_steady: SweepOrder::TrailingFirst,
            method: Method::Auto,
            steady_method: SteadyMethod::Accelerated,
        }
    }

    fn validate(&self) -> Result<(), ContactError> {
        let fin = [self.mu, self.cx, self.cy, self.cs, self.dq_mm, self.tol, self.omega];
        if fin.iter().any(|v| !v.is_finite()) {
            return Err(ContactError::InvalidInput("tangential parameters must be finite".into()));
        }
        if self.mu < 0.0 {
            return Err(ContactError::InvalidInput(format!("friction coefficient must be >= 0 (got {})", self.mu)));
        }
        if self.dq_mm <= 0.0 {
            return Err(ContactError::InvalidInput(format!("rolling step dq must be > 0 (got {} mm)", self.dq_mm)));
        }
        if self.tol <= 0.0 || self.max_iter == 0 {
            return Err(ContactError::InvalidInput("tangential solver needs tol > 0 and max_iter >= 1".into()));
        }
        if !(self.omega > 0.0 && self.omega < 2.0) {
            return Err(ContactError::InvalidInput(format!(
                "relaxation factor must lie in (0, 2) (got {})",
                self.omega
            )));
        }
        Ok(())
    }
}

/// State of one grid element after a solve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementState {
    /// Outside the contact area (pn = 0).
    Exterior,
    /// Adhesion: zero slip, `|p| <= g`.
    Adhesion,
    /// Slip: `|p| = g`.
    Slip,
}

/// Result of one tangential solve.
#[derive(Debug, Clone, PartialEq)]
pub struct StepResult {
    /// Longitudinal traction per element [MPa] (flat index `k = j*mx + i`).
    pub px: Vec<f64>,
    /// Lateral traction per element [MPa].
    pub py: Vec<f64>,
    /// Slip of the step per element, x [mm] (steady: slip over a distance dq).
    pub sx: Vec<f64>,
    /// Slip of the step per element, y [mm].
    pub sy: Vec<f64>,
    /// Element states.
    pub state: Vec<ElementState>,
    /// Gauss-Seidel sweeps, CG iterations or, for accelerated steady rolling, map evaluations
    /// plus the Gauss-Seidel sweeps that verified (or took over from) them.
    pub iterations: usize,
    /// Final relative change `max|delta p| / max(g)` of the last sweep.
    pub residual: f64,
    /// Whether `residual < tol` was reached within `max_iter` sweeps.
    pub converged: bool,
    /// Number of elements in adhesion.
    pub n_adhesion: usize,
    /// Number of elements in slip.
    pub n_slip: usize,
}

impl StepResult {
    /// Total tangential force `(Fx, Fy)` [N] for element area `dxdy` [mm^2].
    pub fn force_n(&self, dxdy_mm2: f64) -> (f64, f64) {
        (self.px.iter().sum::<f64>() * dxdy_mm2, self.py.iter().sum::<f64>() * dxdy_mm2)
    }
}

/// Euclidean norm of `(a, b)` (no overflow guard needed at traction magnitudes).
#[inline(always)]
fn norm2(a: f64, b: f64) -> f64 {
    (a * a + b * b).sqrt()
}

/// Solves `(D + m I) p = t`, `|p| = g` for `m >= 0` with `D = diag(dx, dy)`, `dx, dy > 0`, given
/// `|D^-1 t| > g > 0`: returns `p`. Newton on `phi(m) = 1/|p(m)| - 1/g` (exactly linear when
/// `dx = dy`), safeguarded by bisection on the bracket `[max(0, |t|/g - max d), |t|/g - min d]`
/// (from `|t|/(max d + m) <= |p(m)| <= |t|/(min d + m)`), started at `|t|/g - d_eff` with the
/// weighted mean `d_eff = (tx^2 dx + ty^2 dy)/|t|^2`.
fn slip_solve(tx: f64, ty: f64, dx: f64, dy: f64, g: f64) -> (f64, f64) {
    let tn = norm2(tx, ty);
    let (dmin, dmax) = (dx.min(dy), dx.max(dy));
    let lo0 = (tn / g - dmax).max(0.0);
    let (mut lo, mut hi) = (lo0, (tn / g - dmin).max(lo0));
    let d_eff = if tn > 0.0 { (tx * tx * dx + ty * ty * dy) / (tn * tn) } else { dmin };
    let mut m = (tn / g - d_eff).clamp(lo, hi);
    for _ in 0..60 {
        let (ax, ay) = (dx + m, dy + m);
        let (px, py) = (tx / ax, ty / ay);
        let pn2 = px * px + py * py;
        let pn = pn2.sqrt();
        let phi = 1.0 / pn - 1.0 / g;
        if phi.abs() <= 1e-15 / g {
            break;
        }
        if phi < 0.0 {
            lo = m;
        } else {
            hi = m;
        }
        // d|p|/dm = -(px^2/ax + py^2/ay)/|p|; dphi/dm = -(1/|p|^2) d|p|/dm.
        let dphi = (px * px / ax + py * py / ay) / (pn2 * pn);
        let mut next = m - phi / dphi;
        if !(next > lo && next < hi && next.is_finite()) {
            next = 0.5 * (lo + hi);
        }
        if (next - m).abs() <= 1e-16 * (1.0 + m) {
            m = next;
            break;
        }
        m = next;
    }
    let (px, py) = (tx / (dx + m), ty / (dy + m));
    let s = g / norm2(px, py);
    (px * s, py * s)
}

/// `sx -= kxx dpx + kxy dpy`, `sy -= kxy dpx + kyy dpy` over equal-length slices.
#[inline(always)]
fn axpy2(sx: &mut [f64], sy: &mut [f64], kxx: &[f64], kxy: &[f64], kyy: &[f64], dpx: f64, dpy: f64) {
    let n = sx.len();
    let (sy, kxx, kxy, kyy) = (&mut sy[..n], &kxx[..n], &kxy[..n], &kyy[..n]);
    for i in 0..n {
        sx[i] -= kxx[i] * dpx + kxy[i] * dpy;
        sy[i] -= kxy[i] * dpx + kyy[i] * dpy;
    }
}

/// Geometry of the incremental slip update: contact spans per grid row.
struct Spans {
    mx: usize,
    my: usize,
    nkx: usize,
    /// Rows with contact: `(j, lo, hi)`, elements `lo..hi` of row `j` (covers all contact elements).
    rows: Vec<(usize, usize, usize)>,
}

/// Applies the slip change caused by a traction change `dp` at element `k` to all contact rows:
/// `s_m -= K(m - k) dp`.
#[inline(always)]
fn update_slip_generic(sp: &Spans, op: &Operator, sx: &mut [f64], sy: &mut [f64], k: usize, dp: (f64, f64)) {
    let (ii, jj) = (k % sp.mx, k / sp.mx);
    for &(j, lo, hi) in &sp.rows {
        let base = (j + sp.my - 1 - jj) * sp.nkx + (sp.mx - 1 - ii);
        let (kb, ke) = (base + lo, base + hi);
        let (eb, ee) = (j * sp.mx + lo, j * sp.mx + hi);
        axpy2(&mut sx[eb..ee], &mut sy[eb..ee], &op.xx[kb..ke], &op.xy[kb..ke], &op.yy[kb..ke], dp.0, dp.1);
    }
}

/// [`update_slip_generic`] compiled for AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn update_slip_avx2(sp: &Spans, op: &Operator, sx: &mut [f64], sy: &mut [f64], k: usize, dp: (f64, f64)) {
    update_slip_generic(sp, op, sx, sy, k, dp)
}

/// Work arrays of the conjugate-gradient solver.
struct CgWork {
    vx: Vec<f64>,
    vy: Vec<f64>,
    qx: Vec<f64>,
    qy: Vec<f64>,
    qpx: Vec<f64>,
    qpy: Vec<f64>,
    rx: Vec<f64>,
    ry: Vec<f64>,
    zx: Vec<f64>,
    zy: Vec<f64>,
    zrx: Vec<f64>,
    zry: Vec<f64>,
    /// Weight of the FFT part of the preconditioner: 1 on adhesion elements, on slip elements
    /// `sqrt((d - lambda/g) / d)` (0 if degenerate); set by `cg_residual`.
    wt: Vec<f64>,
    /// Slip elements, set by `cg_residual`: unit tangent `t` of the bound circle at `p`, the
    /// curvature term `lambda/g` and the tangential stiffness `t.D t + lambda/g`.
    tx: Vec<f64>,
    ty: Vec<f64>,
    curv: Vec<f64>,
    stiff: Vec<f64>,
}

impl CgWork {
    fn new(n: usize) -> CgWork {
        CgWork {
            vx: vec![0.0; n],
            vy: vec![0.0; n],
            qx: vec![0.0; n],
            qy: vec![0.0; n],
            qpx: vec![0.0; n],
            qpy: vec![0.0; n],
            rx: vec![0.0; n],
            ry: vec![0.0; n],
            zx: vec![0.0; n],
            zy: vec![0.0; n],
            zrx: vec![0.0; n],
            zry: vec![0.0; n],
            wt: vec![0.0; n],
            tx: vec![0.0; n],
            ty: vec![0.0; n],
            curv: vec![0.0; n],
            stiff: vec![0.0; n],
        }
    }
}

/// Dot product with four interleaved partial sums (vectorisable; fixed summation order, so the
/// result is deterministic).
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut acc = [0.0f64; 4];
    let (ca, cb) = (a.chunks_exact(4), b.chunks_exact(4));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for l in 0..4 {
            acc[l] += x[l] * y[l];
        }
    }
    let mut tail = 0.0;
    for (x, y) in ra.iter().zip(rb) {
        tail += x * y;
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// Anderson acceleration (Walker & Ni 2011, "Anderson acceleration for fixed-point iterations",
/// SIAM J. Numer. Anal. 49(4), type II with a QR factorisation updated by column append and
/// Givens deletion of the oldest column) for a fixed-point map `x -> g(x)` on vectors of length
/// `len`. The vectors of the steady solver are packed over the contact elements as
/// `[px of each contact element..., py of each...]`.
struct Anderson {
    len: usize,
    depth: usize,
    /// Columns in use.
    m: usize,
    /// Orthonormal `Q` of the residual differences `dF = Q R`, column `c` at `q[c*len..]`.
    q: Vec<f64>,
    /// Upper triangular `R`, `depth x depth`, row-major.
    r: Vec<f64>,
    /// Differences of the map values, oldest first (same column order as `Q`).
    dg: std::collections::VecDeque<Vec<f64>>,
    spare: Vec<Vec<f64>>,
    f_prev: Vec<f64>,
    g_prev: Vec<f64>,
    have_prev: bool,
    work: Vec<f64>,
    gamma: Vec<f64>,
}

impl Anderson {
    /// Columns whose orthogonal part is below this fraction of their norm are not added.
    const DEPENDENT: f64 = 1e-10;
    /// The oldest columns are dropped while `max|R_ii| / min|R_ii|` exceeds this (a cheap
    /// condition estimate of `R`; Walker & Ni's `droptol` safeguard).
    const MAX_COND: f64 = 1e10;

    fn new(len: usize, depth: usize) -> Anderson {
        Anderson {
            len,
            depth,
            m: 0,
            q: vec![0.0; len * depth],
            r: vec![0.0; depth * depth],
            dg: Default::default(),
            spare: Vec::new(),
            f_prev: vec![0.0; len],
            g_prev: vec![0.0; len],
            have_prev: false,
            work: vec![0.0; len],
            gamma: vec![0.0; depth],
        }
    }

    /// Forgets the history (the next step is the plain fixed-point step).
    fn restart(&mut self) {
        while let Some(v) = self.dg.pop_front() {
            self.spare.push(v);
        }
        self.m = 0;
        self.have_prev = false;
    }

    /// Removes the oldest column: `R` without its first column is upper Hessenberg; Givens
    /// rotations of rows `(i, i+1)` make it triangular again and are applied to the columns of `Q`.
    #[inline(always)]
    fn delete_oldest(&mut self) {
        let (m, d, len) = (self.m, self.depth, self.len);
        if m == 0 {
            return;
        }
        for row in 0..m {
            for c in 0..m - 1 {
                self.r[row * d + c] = self.r[row * d + c + 1];
            }
            self.r[row * d + m - 1] = 0.0;
        }
        for i in 0..m - 1 {
            let (a, b) = (self.r[i * d + i], self.r[(i + 1) * d + i]);
            let h = a.hypot(b);
            if h == 0.0 {
                continue;
            }
            let (c, s) = (a / h, b / h);
            for col in i..m - 1 {
                let (x, y) = (self.r[i * d + col], self.r[(i + 1) * d + col]);
                self.r[i * d + col] = c * x + s * y;
                self.r[(i + 1) * d + col] = -s * x + c * y;
            }
            let (qi, qn) = self.q[i * len..(i + 2) * len].split_at_mut(len);
            for (x, y) in qi.iter_mut().zip(qn.iter_mut()) {
                let (u, v) = (*x, *y);
                *x = c * u + s * v;
                *y = -s * u + c * v;
            }
        }
        for c in 0..d {
            self.r[(m - 1) * d + c] = 0.0;
        }
        self.m -= 1;
        if let Some(v) = self.dg.pop_front() {
            self.spare.push(v);
        }
    }

    /// One Anderson step: given the iterate `x`, its map value `g` and residual `f = g - x`,
    /// appends the differences to the history and overwrites `x` with
    /// `g - dG gamma`, `gamma = argmin |f - dF gamma|`.
    fn step(&mut self, x: &mut [f64], g: &[f64], f: &[f64]) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: AVX2 is available (checked above). Same operations in the same order (no
            // fused multiply-adds; `dot` keeps its four partial sums), so bit-identical results.
            unsafe { self.step_avx2(x, g, f) };
            return;
        }
        self.step_impl(x, g, f)
    }

    /// [`Anderson::step_impl`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn step_avx2(&mut self, x: &mut [f64], g: &[f64], f: &[f64]) {
        self.step_impl(x, g, f)
    }

    #[inline(always)]
    fn step_impl(&mut self, x: &mut [f64], g: &[f64], f: &[f64]) {
        let (d, len) = (self.depth, self.len);
        if self.have_prev && d > 0 {
            if self.m == d {
                self.delete_oldest();
            }
            let m = self.m;
            // Modified Gram-Schmidt of df = f - f_prev against Q.
            let mut v = std::mem::take(&mut self.work);
            for i in 0..len {
                v[i] = f[i] - self.f_prev[i];
            }
            let norm0 = dot(&v, &v).sqrt();
            for c in 0..m {
                let qc = &self.q[c * len..(c + 1) * len];
                let h = dot(qc, &v);
                self.r[c * d + m] = h;
                for (a, b) in v.iter_mut().zip(qc) {
                    *a -= h * b;
                }
            }
            let nrm = dot(&v, &v).sqrt();
            if nrm > Self::DEPENDENT * norm0 && nrm.is_finite() {
                self.r[m * d + m] = nrm;
                for (a, b) in self.q[m * len..(m + 1) * len].iter_mut().zip(&v) {
                    *a = b / nrm;
                }
                let mut dgv = self.spare.pop().unwrap_or_else(|| vec![0.0; len]);
                for i in 0..len {
                    dgv[i] = g[i] - self.g_prev[i];
                }
                self.dg.push_back(dgv);
                self.m += 1;
            } else {
                for c in 0..m {
                    self.r[c * d + m] = 0.0;
                }
            }
            self.work = v;
            while self.m > 1 {
                let diag = (0..self.m).map(|i| self.r[i * d + i].abs());
                let (lo, hi) = diag.fold((f64::INFINITY, 0.0f64), |(lo, hi), a| (lo.min(a), hi.max(a)));
                if hi <= Self::MAX_COND * lo {
                    break;
                }
                self.delete_oldest();
            }
        }
        self.f_prev.copy_from_slice(f);
        self.g_prev.copy_from_slice(g);
        self.have_prev = true;
        let m = self.m;
        for c in 0..m {
            self.gamma[c] = dot(&self.q[c * len..(c + 1) * len], f);
        }
        for i in (0..m).rev() {
            let mut t = self.gamma[i];
            for l in i + 1..m {
                t -= self.r[i * d + l] * self.gamma[l];
            }
            self.gamma[i] = t / self.r[i * d + i];
        }
        x.copy_from_slice(g);
        if self.gamma[..m].iter().all(|v| v.is_finite()) {
            for (gc, col) in self.gamma[..m].iter().zip(&self.dg) {
                for (a, b) in x.iter_mut().zip(col) {
                    *a -= gc * b;
                }
            }
        }
    }
}

/// Work arrays of the accelerated steady solver.
struct SteadyWork {
    /// Iterate on the grid (input of the convolutions).
    ax: Vec<f64>,
    ay: Vec<f64>,
    /// Iterate, map value, residual and best map value so far (packed).
    x: Vec<f64>,
    g: Vec<f64>,
    f: Vec<f64>,
    best: Vec<f64>,
    anderson: Anderson,
}

impl SteadyWork {
    fn new(n: usize, nc: usize, depth: usize) -> SteadyWork {
        SteadyWork {
            ax: vec![0.0; n],
            ay: vec![0.0; n],
            x: vec![0.0; 2 * nc],
            g: vec![0.0; 2 * nc],
            f: vec![0.0; 2 * nc],
            best: vec![0.0; 2 * nc],
            anderson: Anderson::new(2 * nc, depth),
        }
    }
}

/// Operator coefficients used by the Gauss-Seidel sweep (transient: `A`; steady: `A - A_s`).
struct Operator {
    xx: Vec<f64>,
    xy: Vec<f64>,
    yy: Vec<f64>,
    /// Diagonal `(D_xx, D_yy)` at offset 0.
    dxx: f64,
    dyy: f64,
}

impl Operator {
    fn from_kernel(k: &Kernel) -> Operator {
        let c = k.index(0, 0);
        Operator { xx: k.xx.clone(), xy: k.xy.clone(), yy: k.yy.clone(), dxx: k.xx[c], dyy: k.yy[c] }
    }
}

/// A converged steady solution and its parameters `[mu, cx, cy, cs]` (warm start of the next
/// point of a sweep).
struct SteadyPoint {
    creep: [f64; 4],
    px: Vec<f64>,
    py: Vec<f64>,
}

/// Linear extrapolation factor `r` for the warm start `p_n + r (p_n - p_(n-1))` of the next steady
/// point: `r = (c - c_n).(c_n - c_(n-1)) / |c_n - c_(n-1)|^2` when the next creepage vector `c`
/// continues the line through the last two (same `mu`, collinear within 1e-9), else 0.
fn extrapolation_factor(older: &SteadyPoint, last: &SteadyPoint, next: &TangentialParams) -> f64 {
    let c = [next.mu, next.cx, next.cy, next.cs];
    if c[0] != last.creep[0] || last.creep[0] != older.creep[0] {
        return 0.0;
    }
    let d1: [f64; 3] = std::array::from_fn(|i| last.creep[i + 1] - older.creep[i + 1]);
    let d2: [f64; 3] = std::array::from_fn(|i| c[i + 1] - last.creep[i + 1]);
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let n1 = dot(&d1, &d1);
    if n1 <= 0.0 {
        return 0.0;
    }
    let r = dot(&d1, &d2) / n1;
    let off: [f64; 3] = std::array::from_fn(|i| d2[i] - r * d1[i]);
    if dot(&off, &off) <= 1e-18 * n1.max(dot(&d2, &d2)) && r.is_finite() {
        r
    } else {
        0.0
    }
}

/// Transient / steady tangential solver for a fixed grid, kernels and contact area (pressure).
/// Construct once per normal solution; call [`TangentialSolver::transient_step`] per time step or
/// [`TangentialSolver::steady`] per creepage point. Buffers are reused between calls.
pub struct TangentialSolver {
    mx: usize,
    my: usize,
    dx_mm: f64,
    shift_mm: f64,
    x_mm: Vec<f64>,
    y_mm: Vec<f64>,
    pn: Vec<f64>,
    contact: Vec<usize>,
    /// Contact elements row by row, `i` descending within a row (trailing edge first).
    contact_down: Vec<usize>,
    spans: Spans,
    op_transient: Operator,
    op_steady: Operator,
    conv0: Convolver,
    /// `A` in single precision for the CG's search directions.
    conv0_f32: Convolver,
    convs: Convolver,
    /// Steady rolling operator `A - A_s`.
    convd: Convolver,
    /// FFT preconditioner for the CG solver (inverse of the periodised `A`).
    prec: Convolver,
    use_avx2: bool,
    // work arrays over the grid
    px: Vec<f64>,
    py: Vec<f64>,
    sx: Vec<f64>,
    sy: Vec<f64>,
    ux: Vec<f64>,
    uy: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    cg: CgWork,
    slip: Vec<bool>,
    /// Last steady solution (warm start of the next steady point).
    steady_prev: Vec<SteadyPoint>,
    mask: Vec<bool>,
    /// Work arrays of the accelerated steady solver (allocated on first use).
    aa: Option<SteadyWork>,
}

impl TangentialSolver {
    /// Sets up the solver. `k0`: unshifted kernel; `ks`: kernel shifted by `dq` [mm]
    /// (`ks.shift_mm = dq`); `pn_mpa`: pressure per element (contact = `pn > 0`); `x_mm`, `y_mm`:
    /// element centres [mm] (flat index `k = j*mx + i`).
    pub fn new(
        k0: &Kernel,
        ks: &Kernel,
        pn_mpa: &[f64],
        x_mm: &[f64],
        y_mm: &[f64],
    ) -> Result<TangentialSolver, ContactError> {
        let (mx, my) = (k0.mx, k0.my);
        let n = mx * my;
        if ks.mx != mx || ks.my != my || ks.dx_mm != k0.dx_mm || ks.dy_mm != k0.dy_mm {
            return Err(ContactError::SizeMismatch(
                "shifted kernel must belong to the same grid as the unshifted kernel".into(),
            ));
        }
        if k0.shift_mm != 0.0 {
            return Err(ContactError::InvalidInput(format!("the unshifted kernel has shift {} mm", k0.shift_mm)));
        }
        if ks.shift_mm.is_nan() || ks.shift_mm <= 0.0 {
            return Err(ContactError::InvalidInput(format!(
                "the shifted kernel needs shift dq > 0 (got {} mm)",
                ks.shift_mm
            )));
        }
        for (name, v) in [("pn", pn_mpa), ("x", x_mm), ("y", y_mm)] {
            if v.len() != n {
                return Err(ContactError::SizeMismatch(format!("{name} has {} entries, grid has {n}", v.len())));
            }
            if v.iter().any(|z| !z.is_finite()) {
                return Err(ContactError::InvalidInput(format!("{name} is not finite")));
            }
        }
        if pn_mpa.iter().any(|&v| v < 0.0) {
            return Err(ContactError::InvalidInput("negative pressure".into()));
        }
        let contact: Vec<usize> = (0..n).filter(|&k| pn_mpa[k] > 0.0).collect();
        if contact.is_empty() {
            return Err(ContactError::NoContact("no element has pn > 0; tangential problem undefined".into()));
        }
        let mut rows = Vec::new();
        for j in 0..my {
            let row = &pn_mpa[j * mx..(j + 1) * mx];
            if let (Some(lo), Some(hi)) = (row.iter().position(|&v| v > 0.0), row.iter().rposition(|&v| v > 0.0)) {
                rows.push((j, lo, hi + 1));
            }
        }
        let mut contact_down = Vec::with_capacity(contact.len());
        for j in 0..my {
            for i in (0..mx).rev() {
                if pn_mpa[j * mx + i] > 0.0 {
                    contact_down.push(j * mx + i);
                }
            }
        }
        let op_transient = Operator::from_kernel(k0);
        let kd = k0.difference(ks)?;
        let op_steady = Operator::from_kernel(&kd);
        if !(op_transient.dxx > 0.0 && op_transient.dyy > 0.0 && op_steady.dxx > 0.0 && op_steady.dyy > 0.0) {
            return Err(ContactError::InvalidInput("influence kernels have non-positive diagonal".into()));
        }
        #[cfg(target_arch = "x86_64")]
        let use_avx2 = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
        #[cfg(not(target_arch = "x86_64"))]
        let use_avx2 = false;
        let mask: Vec<bool> = pn_mpa.iter().map(|&v| v > 0.0).collect();
        Ok(TangentialSolver {
            mx,
            my,
            dx_mm: k0.dx_mm,
            shift_mm: ks.shift_mm,
            x_mm: x_mm.to_vec(),
            y_mm: y_mm.to_vec(),
            pn: pn_mpa.to_vec(),
            contact,
            contact_down,
            spans: Spans { mx, my, nkx: 2 * mx - 1, rows },
            op_transient,
            op_steady,
            conv0: Convolver::auto(k0)?,
            conv0_f32: Convolver::single_precision(k0)?,
            prec: Convolver::inverse_of(k0)?,
            convs: Convolver::auto(ks)?,
            convd: Convolver::auto(&kd)?,
            use_avx2,
            px: vec![0.0; n],
            py: vec![0.0; n],
            sx: vec![0.0; n],
            sy: vec![0.0; n],
            ux: vec![0.0; n],
            uy: vec![0.0; n],
            vx: vec![0.0; n],
            vy: vec![0.0; n],
            cg: CgWork::new(n),
            slip: vec![false; n],
            steady_prev: Vec::with_capacity(2),
            mask,
            aa: None,
        })
    }

    /// Number of contact elements.
    pub fn n_contact(&self) -> usize {
        self.contact.len()
    }

    /// Courant number `dq/dx`.
    pub fn courant(&self) -> f64 {
        self.shift_mm / self.dx_mm
    }

    fn check_params(&self, p: &TangentialParams) -> Result<(), ContactError> {
        p.validate()?;
        if (p.dq_mm - self.shift_mm).abs() > 1e-9 * self.shift_mm {
            return Err(ContactError::InvalidInput(format!(
                "dq = {} mm differs from the shifted kernel's shift {} mm",
                p.dq_mm, self.shift_mm
            )));
        }
        Ok(())
    }

    /// Rigid slip of the step `w_k = dq (cx - cs y_k, cy + cs x_k)` [mm] added into `(bx, by)`.
    fn add_rigid_slip(&mut self, p: &TangentialParams, steady_target: bool) {
        let dq = p.dq_mm;
        let (bx, by) = if steady_target { (&mut self.sx, &mut self.sy) } else { (&mut self.vx, &mut self.vy) };
        for &k in &self.contact {
            bx[k] += dq * (p.cx - p.cs * self.y_mm[k]);
            by[k] += dq * (p.cy + p.cs * self.x_mm[k]);
        }
    }

    /// One transient rolling step: previous tractions `prev_px`, `prev_py` [MPa] (on the grid, at
    /// the previous time, contact-fixed coordinates). Warm start: the previous traction shifted one
    /// element downstream when `dq = dx` (courant 1), else the previous traction; clipped to the
    /// traction bound.
    pub fn transient_step(
        &mut self,
        params: &TangentialParams,
        prev_px: &[f64],
        prev_py: &[f64],
        older: Option<(&[f64], &[f64])>,
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        let n = self.mx * self.my;
        let older_ok = older.is_none_or(|(ox, oy)| ox.len() == n && oy.len() == n);
        if prev_px.len() != n || prev_py.len() != n || !older_ok {
            return Err(ContactError::SizeMismatch(format!("previous traction must have {n} entries")));
        }
        let older_finite = older.is_none_or(|(ox, oy)| ox.iter().chain(oy).all(|v| v.is_finite()));
        if prev_px.iter().chain(prev_py).any(|v| !v.is_finite()) || !older_finite {
            return Err(ContactError::InvalidInput("previous traction is not finite".into()));
        }
        // u' = A_s p' (previous displacement at the previous position of the material).
        self.convs.tangential(prev_px, prev_py, None, &mut self.vx, &mut self.vy)?;
        // b = w + u' (stored in vx, vy).
        self.add_rigid_slip(params, false);
        // Warm start in the contact frame: the previous traction, or its linear extrapolation
        // `2 p_n - p_(n-1)` when the step before is given (measured, release, CG iterations per
        // step: step_mu04 25.9 (previous traction moved with the material, the former start) ->
        // 16.2 (previous) -> 14.4 (extrapolated); sine_f10_mu04 23.0 -> 15.1 -> 14.1;
        // sine_f30_mu10_g44 26.5 -> 22.9 -> 21.3).
        self.px.iter_mut().for_each(|v| *v = 0.0);
        self.py.iter_mut().for_each(|v| *v = 0.0);
        for &k in &self.contact {
            (self.px[k], self.py[k]) = match older {
                Some((ox, oy)) => (2.0 * prev_px[k] - ox[k], 2.0 * prev_py[k] - oy[k]),
                None => (prev_px[k], prev_py[k]),
            };
        }
        self.clip_to_bound(params.mu);
        // s = b - A p.
        self.conv0.tangential(&self.px, &self.py, Some(&self.mask), &mut self.ux, &mut self.uy)?;
        for &k in &self.contact {
            self.sx[k] = self.vx[k] - self.ux[k];
            self.sy[k] = self.vy[k] - self.uy[k];
        }
        let use_cg = match params.method {
            Method::GaussSeidel => false,
            Method::ConjugateGradient => true,
            Method::Auto => true,
        };
        if use_cg {
            self.tang_cg(params)
        } else {
            self.gauss_seidel(params, false)
        }
    }

    /// Steady rolling at the given creepages: `s = w - (A - A_s) p`. Warm start from `start`
    /// (tractions [MPa]) if given, else from the previous steady solution of this solver (linearly
    /// extrapolated from the last two when the creepage continues their line), else zero.
    /// Solver per [`TangentialParams::steady_method`]; if the accelerated iteration fails its test,
    /// Gauss-Seidel sweeps continue, and `converged: false` reports that they failed too.
    pub fn steady(
        &mut self,
        params: &TangentialParams,
        start: Option<(&[f64], &[f64])>,
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        let n = self.mx * self.my;
        self.px.iter_mut().for_each(|v| *v = 0.0);
        self.py.iter_mut().for_each(|v| *v = 0.0);
        match start {
            Some((sx0, sy0)) => {
                if sx0.len() != n || sy0.len() != n {
                    return Err(ContactError::SizeMismatch(format!("start traction must have {n} entries")));
                }
                if sx0.iter().chain(sy0).any(|v| !v.is_finite()) {
                    return Err(ContactError::InvalidInput("start traction is not finite".into()));
                }
                for &k in &self.contact {
                    self.px[k] = sx0[k];
                    self.py[k] = sy0[k];
                }
            }
            None if !self.steady_prev.is_empty() => {
                // With one point only, older = last and r = 0: the previous solution itself.
                let (older, last) = (&self.steady_prev[0], &self.steady_prev[self.steady_prev.len() - 1]);
                let r = if self.steady_prev.len() == 2 { extrapolation_factor(older, last, params) } else { 0.0 };
                for &k in &self.contact {
                    self.px[k] = last.px[k] + r * (last.px[k] - older.px[k]);
                    self.py[k] = last.py[k] + r * (last.py[k] - older.py[k]);
                }
            }
            None => {}
        }
        self.clip_to_bound(params.mu);
        let gmax = self.contact.iter().map(|&k| params.mu * self.pn[k]).fold(0.0, f64::max);
        let (mut evals, mut converged) = (0, None);
        if params.steady_method == SteadyMethod::Accelerated && gmax > 0.0 {
            (evals, converged) = self.steady_anderson(params)?;
        }
        // s = w - (A - A_s) p.
        self.conv0.tangential(&self.px, &self.py, Some(&self.mask), &mut self.ux, &mut self.uy)?;
        self.convs.tangential(&self.px, &self.py, Some(&self.mask), &mut self.vx, &mut self.vy)?;
        for &k in &self.contact {
            self.sx[k] = -(self.ux[k] - self.vx[k]);
            self.sy[k] = -(self.uy[k] - self.vy[k]);
        }
        self.add_rigid_slip(params, true);
        let res = match converged {
            Some(residual) => self.finish(evals, residual, true)?,
            None => {
                let mut r = self.gauss_seidel(params, true)?;
                r.iterations += evals;
                r
            }
        };
        let mut point = if self.steady_prev.len() == 2 {
            self.steady_prev.remove(0)
        } else {
            SteadyPoint { creep: [0.0; 4], px: vec![0.0; n], py: vec![0.0; n] }
        };
        point.creep = [params.mu, params.cx, params.cy, params.cs];
        point.px.copy_from_slice(&res.px);
        point.py.copy_from_slice(&res.py);
        self.steady_prev.push(point);
        Ok(res)
    }

    /// Anderson-accelerated fixed-point iteration for steady rolling (see
    /// [`SteadyMethod::Accelerated`]): `x <- P(x_AA)`, `x_AA` the Anderson mix of the map values
    /// `G(x)` of [`TangentialSolver::steady_map`], `P` the projection onto the traction bound.
    /// Starts from `(px, py)` (on or inside the bound) and leaves there the last iterate if it met
    /// the stopping test, else the best map value seen (or the start, if none was finite).
    /// Safeguards: a residual above [`STEADY_BLOWUP`] times the best one (or non-finite) restarts
    /// the history from the best map value, at most [`STEADY_MAX_RESTARTS`] times; no halving of
    /// the best residual within [`STEADY_STALL`] evaluations ends the iteration. Returns
    /// `(map evaluations, Some(final residual) if it met the test)`; if not, the caller continues
    /// with Gauss-Seidel.
    fn steady_anderson(&mut self, params: &TangentialParams) -> Result<(usize, Option<f64>), ContactError> {
        let stop_tol = params.tol;
        let max_evals = params.max_iter.min(STEADY_MAX_EVALS);
        let mu = params.mu;
        let n = self.mx * self.my;
        let nc = self.contact.len();
        let mut aa = self.aa.take().unwrap_or_else(|| SteadyWork::new(n, nc, STEADY_DEPTH));
        aa.anderson.restart();
        for (i, &k) in self.contact.iter().enumerate() {
            aa.x[i] = self.px[k];
            aa.x[nc + i] = self.py[k];
        }
        let mut best_res = f64::INFINITY;
        let mut progress_res = f64::INFINITY;
        let mut progress_eval = 0;
        let mut restarts = 0;
        let mut evals = 0;
        let mut converged = None;
        while evals < max_evals {
            let res = self.steady_map(params, &mut aa)?;
            evals += 1;
            if res < stop_tol {
                converged = Some(res);
                break;
            }
            if res < best_res {
                best_res = res;
                aa.best.copy_from_slice(&aa.g);
            }
            if best_res <= 0.5 * progress_res {
                progress_res = best_res;
                progress_eval = evals;
            } else if evals - progress_eval >= STEADY_STALL {
                break;
            }
            if !res.is_finite() || res > STEADY_BLOWUP * best_res {
                // Diverging or non-finite: restart from the best map value.
                restarts += 1;
                if restarts > STEADY_MAX_RESTARTS || !best_res.is_finite() {
                    break;
                }
                aa.anderson.restart();
                aa.x.copy_from_slice(&aa.best);
                continue;
            }
            for i in 0..2 * nc {
                aa.f[i] = aa.g[i] - aa.x[i];
            }
            aa.anderson.step(&mut aa.x, &aa.g, &aa.f);
            // Project the mixed iterate onto the traction bound.
            for (i, &k) in self.contact.iter().enumerate() {
                let g = mu * self.pn[k];
                let (x, y) = (aa.x[i], aa.x[nc + i]);
                let a = norm2(x, y);
                if a.is_nan() || a > g {
                    let f = if a > 0.0 && a.is_finite() { g / a } else { 0.0 };
                    (aa.x[i], aa.x[nc + i]) = if f > 0.0 { (x * f, y * f) } else { (0.0, 0.0) };
                }
            }
        }
        let result = if converged.is_some() {
            Some(&aa.x)
        } else if best_res.is_finite() {
            Some(&aa.best)
        } else {
            None
        };
        if let Some(v) = result {
            for (i, &k) in self.contact.iter().enumerate() {
                self.px[k] = v[i];
                self.py[k] = v[nc + i];
            }
        }
        self.aa = Some(aa);
        Ok((evals, converged))
    }

    /// The fixed-point map of the accelerated steady solver at the iterate `aa.x` (packed; on or
    /// inside the bound): `aa.g = G(x)`. With the exact steady slip `s = w - (A - A_s) x` (one FFT
    /// product):
    /// * every element's local Gauss-Seidel problem is solved with the others fixed (as in
    ///   [`TangentialSolver::gauss_seidel`], diagonal of `A - A_s`); elements whose local solution
    ///   lies on the bound are slip elements and take it as their map value;
    /// * the adhesion elements take `x + (I - S)^-1 M s`, `M` the FFT inverse of the periodised `A`
    ///   applied to the adhesion slip (the CG preconditioner) and `(I - S)^-1` the exact inverse of
    ///   the shift by the rolling distance along each run of adhesion elements of a grid row (zero
    ///   inflow at the run's upstream end), since `A - A_s = A (I - S)` for the translation-invariant
    ///   kernel; the result is clipped to the bound.
    ///
    /// Returns the largest local change `max|p_local - x| / max(g)` (infinite if anything is not
    /// finite): the quantity whose maximum over a sweep is the Gauss-Seidel stopping test.
    fn steady_map(&mut self, params: &TangentialParams, aa: &mut SteadyWork) -> Result<f64, ContactError> {
        let mu = params.mu;
        let nc = self.contact.len();
        let mx = self.mx;
        let (dxx, dyy) = (self.op_steady.dxx, self.op_steady.dyy);
        let gmax = self.contact.iter().map(|&k| mu * self.pn[k]).fold(0.0, f64::max);
        for (i, &k) in self.contact.iter().enumerate() {
            aa.ax[k] = aa.x[i];
            aa.ay[k] = aa.x[nc + i];
        }
        // s = w - (A - A_s) x.
        self.convd.tangential(&aa.ax, &aa.ay, Some(&self.mask), &mut self.ux, &mut self.uy)?;
        for &k in &self.contact {
            self.sx[k] = -self.ux[k];
            self.sy[k] = -self.uy[k];
        }
        self.add_rigid_slip(params, true);
        // Local solves; the adhesion slip goes into cg.q for the preconditioner.
        let mut res = 0.0f64;
        let mut finite = true;
        for (i, &k) in self.contact.iter().enumerate() {
            let g = mu * self.pn[k];
            let (p0x, p0y) = (aa.x[i], aa.x[nc + i]);
            let tx = self.sx[k] + dxx * p0x;
            let ty = self.sy[k] + dyy * p0y;
            let (qx, qy) = (tx / dxx, ty / dyy);
            let (nx, ny);
            if qx * qx + qy * qy <= g * g {
                (nx, ny) = (qx, qy);
                self.slip[k] = false;
                self.cg.qx[k] = self.sx[k];
                self.cg.qy[k] = self.sy[k];
            } else {
                (nx, ny) = if g > 0.0 { slip_solve(tx, ty, dxx, dyy, g) } else { (0.0, 0.0) };
                self.slip[k] = true;
                self.cg.qx[k] = 0.0;
                self.cg.qy[k] = 0.0;
            }
            aa.g[i] = nx;
            aa.g[nc + i] = ny;
            let d = (nx - p0x).abs().max((ny - p0y).abs());
            finite &= d.is_finite();
            res = res.max(d);
        }
        if !finite {
            return Ok(f64::INFINITY);
        }
        self.prec.tangential(&self.cg.qx, &self.cg.qy, Some(&self.mask), &mut self.cg.zrx, &mut self.cg.zry)?;
        // e = (I - S)^-1 z into cg.z along each run of adhesion elements of a grid row: S shifts by
        // theta = n + f elements downstream (linear interpolation; e_i - (1-f) e_(i-n) - f e_(i-n-1)
        // = z_i), zero inflow at the run's start.
        let theta = self.courant();
        let n_shift = theta.floor() as usize;
        let frac = theta - n_shift as f64;
        let mut run_lo = 0;
        for (i, &k) in self.contact.iter().enumerate() {
            if self.slip[k] {
                continue;
            }
            let cont = i > 0 && k % mx != 0 && self.contact[i - 1] == k - 1 && !self.slip[k - 1];
            if !cont {
                run_lo = k;
            }
            let prev = |e: &[f64], back: usize| if k >= run_lo + back { e[k - back] } else { 0.0 };
            let (ex, ey) = if n_shift == 0 {
                (prev(&self.cg.zx, 1) + self.cg.zrx[k] / frac, prev(&self.cg.zy, 1) + self.cg.zry[k] / frac)
            } else {
                let (a, b) = (1.0 - frac, frac);
                (
                    self.cg.zrx[k] + a * prev(&self.cg.zx, n_shift) + b * prev(&self.cg.zx, n_shift + 1),
                    self.cg.zry[k] + a * prev(&self.cg.zy, n_shift) + b * prev(&self.cg.zy, n_shift + 1),
                )
            };
            self.cg.zx[k] = ex;
            self.cg.zy[k] = ey;
            let g = mu * self.pn[k];
            let (mut gx, mut gy) = (aa.x[i] + ex, aa.x[nc + i] + ey);
            let a = norm2(gx, gy);
            if a.is_nan() || a > g {
                let f = if a > 0.0 && a.is_finite() { g / a } else { 0.0 };
                (gx, gy) = if f > 0.0 { (gx * f, gy * f) } else { (0.0, 0.0) };
            }
            aa.g[i] = gx;
            aa.g[nc + i] = gy;
        }
        Ok(res / gmax)
    }

    /// Exact slip `s = b - A p` with `b` in `(vx, vy)` (transient steps).
    fn recompute_slip(&mut self) -> Result<(), ContactError> {
        self.conv0.tangential(&self.px, &self.py, Some(&self.mask), &mut self.ux, &mut self.uy)?;
        for &k in &self.contact {
            self.sx[k] = self.vx[k] - self.ux[k];
            self.sy[k] = self.vy[k] - self.uy[k];
        }
        Ok(())
    }

    /// Residual and diagonally preconditioned residual of the reduced problem (adhesion: the slip
    /// itself; slip: its component along the bound circle), into `cg.r`, `cg.z`, and the slip
    /// elements' tangent, curvature, stiffness and preconditioner weight (see `apply_prec`). Returns
    /// `max |z|` (the change a local Gauss-Seidel solve would make, to first order) [MPa].
    fn cg_residual(&mut self, dxx: f64, dyy: f64, mu: f64) -> f64 {
        let mut zmax = 0.0f64;
        let w = &mut self.cg;
        for &k in &self.contact {
            let (sx, sy) = (self.sx[k], self.sy[k]);
            if self.slip[k] {
                let g = mu * self.pn[k];
                let a = norm2(self.px[k], self.py[k]);
                if g <= 0.0 || a <= 0.0 {
                    w.rx[k] = 0.0;
                    w.ry[k] = 0.0;
                    w.zx[k] = 0.0;
                    w.zy[k] = 0.0;
                    (w.tx[k], w.ty[k], w.curv[k], w.stiff[k], w.wt[k]) = (0.0, 0.0, 0.0, 0.0, 0.0);
                    continue;
                }
                let (nx, ny) = (self.px[k] / a, self.py[k] / a);
                let (tx, ty) = (-ny, nx);
                let st = tx * sx + ty * sy;
                let lam = (nx * sx + ny * sy).max(0.0);
                w.rx[k] = st * tx;
                w.ry[k] = st * ty;
                let d = dxx * tx * tx + dyy * ty * ty + lam / g;
                let curv = lam / g;
                (w.tx[k], w.ty[k], w.curv[k], w.stiff[k]) = (tx, ty, curv, d);
                w.wt[k] = (1.0 - curv / d).sqrt();
                let zt = st / d;
                w.zx[k] = zt * tx;
                w.zy[k] = zt * ty;
                zmax = zmax.max(zt.abs());
            } else {
                w.wt[k] = 1.0;
                w.rx[k] = sx;
                w.ry[k] = sy;
                w.zx[k] = sx / dxx;
                w.zy[k] = sy / dyy;
                zmax = zmax.max(w.zx[k].abs()).max(w.zy[k].abs());
            }
        }
        zmax
    }

    /// Preconditioned residual `z = S M S r + (I - S^2) D_c^-1 r` into `cg.z` (needs `cg.r` and
    /// the weights `S` from [`TangentialSolver::cg_residual`]): `M` the FFT inverse of the periodised `A`,
    /// `D_c` the diagonal stiffness (slip elements: `t.D t + lambda/g` along the tangent `t`), `S = I`
    /// on adhesion elements and `sqrt(t.D t / (t.D t + lambda/g))` on slip elements, whose part is
    /// projected onto `t`. Symmetric positive definite; the FFT part for slip elements that barely
    /// slip (`lambda` small), the diagonal for those that slip fast. Measured (release, CG
    /// iterations per step) against the FFT part on adhesion elements only and the diagonal on all
    /// slip elements, the former choice: sine_f30_mu10_g88 26.9 -> 16.9, sine_f30_mu10_g44
    /// 21.1 -> 14.8, sine_f10_mu04 13.7 -> 12.4, sine_f10_mu01 9.0 -> 9.4; the FFT part alone on
    /// the slip elements (`S = I`) needs 2-3 times as many on the large-slip cases.
    fn apply_prec(&mut self) -> Result<(), ContactError> {
        let w = &mut self.cg;
        for &k in &self.contact {
            w.qx[k] = w.wt[k] * w.rx[k];
            w.qy[k] = w.wt[k] * w.ry[k];
        }
        self.prec.tangential(&w.qx, &w.qy, Some(&self.mask), &mut w.zrx, &mut w.zry)?;
        for &k in &self.contact {
            if !self.slip[k] {
                w.zx[k] = w.zrx[k];
                w.zy[k] = w.zry[k];
            } else if w.stiff[k] > 0.0 {
                let (tx, ty, s) = (w.tx[k], w.ty[k], w.wt[k]);
                let zt =
                    s * (tx * w.zrx[k] + ty * w.zry[k]) + (1.0 - s * s) * (tx * w.rx[k] + ty * w.ry[k]) / w.stiff[k];
                w.zx[k] = zt * tx;
                w.zy[k] = zt * ty;
            }
        }
        Ok(())
    }

    /// Moves elements between adhesion and slip: adhesion elements above the bound go to slip
    /// (clipped onto it); slip elements whose local solution lies inside the bound, or whose slip
    /// opposes the traction, go to adhesion. Returns whether anything changed.
    fn cg_update_sets(&mut self, dxx: f64, dyy: f64, mu: f64) -> bool {
        let mut changed = false;
        for &k in &self.contact {
            let g = mu * self.pn[k];
            let (px, py) = (self.px[k], self.py[k]);
            let a = norm2(px, py);
            if !self.slip[k] {
                if a > g {
                    let f = if a > 0.0 { g / a } else { 0.0 };
                    self.px[k] = px * f;
                    self.py[k] = py * f;
                    self.slip[k] = true;
                    changed = true;
                }
            } else {
                let tx = self.sx[k] + dxx * px;
                let ty = self.sy[k] + dyy * py;
                let (qx, qy) = (tx / dxx, ty / dyy);
                if qx * qx + qy * qy <= g * g {
                    self.slip[k] = false;
                    changed = true;
                }
            }
        }
        changed
    }

    /// Transient step by nonlinear preconditioned conjugate gradients (TangCG type, Vollebregt,
    /// CONTACT user guide sec. "TangCG"): CG on the adhesion tractions and on the directions of
    /// the slip tractions (kept on the bound), the circle's curvature `lambda/g` added to the slip
    /// elements' stiffness; element sets updated every few iterations with a restart. Matrix-vector
    /// products by FFT. Falls back to Gauss-Seidel if the CG does not converge. Expects `(px, py)`
    /// on or inside the bound and `(sx, sy)` the exact slip for them.
    fn tang_cg(&mut self, params: &TangentialParams) -> Result<StepResult, ContactError> {
        const INNER: usize = 4;
        let (dxx, dyy) = (self.op_transient.dxx, self.op_transient.dyy);
        let mu = params.mu;
        let gmax = self.contact.iter().map(|&k| mu * self.pn[k]).fold(0.0, f64::max);
        if gmax <= 0.0 {
            return self.gauss_seidel(params, false);
        }
        // Initial element division from the warm start: elements on the traction bound slip. (The
        // local problems are no guide here: the residual of a warm start is smooth, and a single
        // element's stiffness is far below the collective one.)
        for &k in &self.contact {
            let g = mu * self.pn[k];
            self.slip[k] = g <= 0.0 || norm2(self.px[k], self.py[k]) >= g * (1.0 - 1e-12);
        }
        // The slip is exact for the current tractions (the caller computed it).
        let mut restart = true;
        let mut since_check = 0;
        let mut iterations = 0;
        let mut residual = f64::INFINITY;
        let mut cg_ok = false;
        while iterations < params.max_iter {
            iterations += 1;
            self.cg_residual(dxx, dyy, mu);
            self.apply_prec()?;
            // Search direction, conjugate to the previous one (beta = -(z, q_old)/(v, q_old)).
            {
                let w = &mut self.cg;
                let beta = if restart {
                    0.0
                } else {
                    let (mut zq, mut vq) = (0.0, 0.0);
                    for &k in &self.contact {
                        zq += w.zx[k] * w.qpx[k] + w.zy[k] * w.qpy[k];
                        vq += w.vx[k] * w.qpx[k] + w.vy[k] * w.qpy[k];
                    }
                    if vq.abs() > 1e-300 {
                        -zq / vq
                    } else {
                        0.0
                    }
                };
                restart = false;
                for &k in &self.contact {
                    w.vx[k] = w.zx[k] + beta * w.vx[k];
                    w.vy[k] = w.zy[k] + beta * w.vy[k];
                }
            }
            // Search-direction product in single precision: the slip is recomputed exactly (f64)
            // every INNER iterations and for the stopping test.
            self.conv0_f32.tangential(&self.cg.vx, &self.cg.vy, Some(&self.mask), &mut self.cg.qx, &mut self.cg.qy)?;
            let w = &mut self.cg;
            let (mut rv, mut vq) = (0.0, 0.0);
            let mut vmax = 0.0f64;
            for &k in &self.contact {
                let (qx, qy) = (w.qx[k], w.qy[k]);
                let (qpx, qpy) = if self.slip[k] {
                    // Tangent and curvature from `cg_residual` (p has not moved since).
                    let (tx, ty, c) = (w.tx[k], w.ty[k], w.curv[k]);
                    let qt = tx * qx + ty * qy;
                    (qt * tx + c * w.vx[k], qt * ty + c * w.vy[k])
                } else {
                    (qx, qy)
                };
                w.qpx[k] = qpx;
                w.qpy[k] = qpy;
                rv += w.rx[k] * w.vx[k] + w.ry[k] * w.vy[k];
                vq += w.vx[k] * qpx + w.vy[k] * qpy;
                vmax = vmax.max(w.vx[k].abs()).max(w.vy[k].abs());
            }
            let alpha = if vq > 0.0 && rv.is_finite() { rv / vq } else { 0.0 };
            if !alpha.is_finite() {
                break;
            }
            for &k in &self.contact {
                self.px[k] += alpha * w.vx[k];
                self.py[k] += alpha * w.vy[k];
                self.sx[k] -= alpha * w.qx[k];
                self.sy[k] -= alpha * w.qy[k];
                if self.slip[k] {
                    let g = mu * self.pn[k];
                    let a = norm2(self.px[k], self.py[k]);
                    if a > 0.0 {
                        self.px[k] *= g / a;
                        self.py[k] *= g / a;
                    }
                }
            }
            let dif = (alpha * vmax).abs() / gmax;
            since_check += 1;
            if since_check >= INNER || dif < params.tol || alpha == 0.0 {
                since_check = 0;
                self.recompute_slip()?;
                if self.cg_update_sets(dxx, dyy, mu) {
                    self.recompute_slip()?;
                    restart = true;
                    continue;
                }
                residual = self.cg_residual(dxx, dyy, mu) / gmax;
                if residual < params.tol {
                    cg_ok = true;
                    break;
                }
                if alpha == 0.0 {
                    break;
                }
            }
        }
        if !cg_ok {
            // Fall back to Gauss-Seidel from the current iterate (slip exact).
            self.recompute_slip()?;
            let mut r = self.gauss_seidel(params, false)?;
            r.iterations += iterations;
            return Ok(r);
        }
        self.finish(iterations, residual, true)
    }

    /// Packs the current tractions, slip and element division into a [`StepResult`].
    fn finish(&self, iterations: usize, residual: f64, converged: bool) -> Result<StepResult, ContactError> {
        let n = self.mx * self.my;
        let mut state = vec![ElementState::Exterior; n];
        let (mut n_adhesion, mut n_slip) = (0, 0);
        let mut sx = vec![0.0; n];
        let mut sy = vec![0.0; n];
        for &k in &self.contact {
            if self.slip[k] {
                state[k] = ElementState::Slip;
                n_slip += 1;
            } else {
                state[k] = ElementState::Adhesion;
                n_adhesion += 1;
            }
            sx[k] = self.sx[k];
            sy[k] = self.sy[k];
        }
        let mut px = vec![0.0; n];
        let mut py = vec![0.0; n];
        for &k in &self.contact {
            px[k] = self.px[k];
            py[k] = self.py[k];
        }
        if px.iter().chain(&py).any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("tangential traction".into()));
        }
        Ok(StepResult { px, py, sx, sy, state, iterations, residual, converged, n_adhesion, n_slip })
    }

    fn clip_to_bound(&mut self, mu: f64) {
        for &k in &self.contact {
            let g = mu * self.pn[k];
            let a = norm2(self.px[k], self.py[k]);
            if a > g {
                let s = if a > 0.0 { g / a } else { 0.0 };
                self.px[k] *= s;
                self.py[k] *= s;
            }
        }
    }

    /// Projected Gauss-Seidel sweeps on the current `(px, py)`, slip `(sx, sy)` (exact for the
    /// current tractions). `steady` selects the operator `A - A_s` instead of `A`.
    fn gauss_seidel(&mut self, params: &TangentialParams, steady: bool) -> Result<StepResult, ContactError> {
        let op = if steady { &self.op_steady } else { &self.op_transient };
        let (dxx, dyy) = (op.dxx, op.dyy);
        let omega = if steady { 1.0 } else { params.omega };
        let mu = params.mu;
        let gmax = self.contact.iter().map(|&k| mu * self.pn[k]).fold(0.0, f64::max);
        let mut iterations = 0;
        let mut residual = f64::INFINITY;
        let mut converged = false;
        if gmax <= 0.0 {
            // mu = 0: no traction possible, everything slips.
            for &k in &self.contact {
                self.px[k] = 0.0;
                self.py[k] = 0.0;
                self.slip[k] = true;
            }
            residual = 0.0;
            converged = true;
        }
        // Traction changes below this are not applied (they are far below the stopping level).
        let skip = 1e-3 * params.tol * gmax;
        let down = if steady {
            params.sweep_steady == SweepOrder::TrailingFirst
        } else {
            params.sweep_transient == SweepOrder::TrailingFirst
        };
        while !converged && iterations < params.max_iter {
            iterations += 1;
            let mut dmax = 0.0f64;
            for idx in 0..self.contact.len() {
                let k = if down { self.contact_down[idx] } else { self.contact[idx] };
                let g = mu * self.pn[k];
                let (p0x, p0y) = (self.px[k], self.py[k]);
                let tx = self.sx[k] + dxx * p0x;
                let ty = self.sy[k] + dyy * p0y;
                let (qx, qy) = (tx / dxx, ty / dyy);
                let (mut nx, mut ny);
                let is_slip;
                if qx * qx + qy * qy <= g * g {
                    // Adhesion, optionally over-relaxed and projected back onto the disc.
                    nx = p0x + omega * (qx - p0x);
                    ny = p0y + omega * (qy - p0y);
                    let a = norm2(nx, ny);
                    if a > g {
                        nx *= g / a;
                        ny *= g / a;
                    }
                    is_slip = false;
                } else if g > 0.0 {
                    let (sx, sy) = slip_solve(tx, ty, dxx, dyy, g);
                    nx = sx;
                    ny = sy;
                    is_slip = true;
                } else {
                    nx = 0.0;
                    ny = 0.0;
                    is_slip = true;
                }
                self.slip[k] = is_slip;
                let (dpx, dpy) = (nx - p0x, ny - p0y);
                let d = dpx.abs().max(dpy.abs());
                if d > dmax {
                    dmax = d;
                }
                if d <= skip {
                    continue;
                }
                self.px[k] = nx;
                self.py[k] = ny;
                #[cfg(target_arch = "x86_64")]
                if self.use_avx2 {
                    // SAFETY: the CPU supports AVX2 and FMA (checked at construction).
                    unsafe { update_slip_avx2(&self.spans, op, &mut self.sx, &mut self.sy, k, (dpx, dpy)) };
                    continue;
                }
                update_slip_generic(&self.spans, op, &mut self.sx, &mut self.sy, k, (dpx, dpy));
            }
            if !dmax.is_finite() {
                return Err(ContactError::NonFinite("tangential Gauss-Seidel diverged".into()));
            }
            residual = dmax / gmax;
            if residual < params.tol {
                converged = true;
            }
        }
        self.finish(iterations, residual, converged)
    }
}

#[cfg(test)]
mod tests {
    use super::super::normal::{solve_normal, NormalParams};
    use super::*;
    use crate::physics::Grid;

    #[test]
    fn slip_solve_hits_bound_and_direction() {
        let (tx, ty, dx, dy, g) = (3.0, -1.0, 0.7, 0.9, 1.5);
        let (px, py) = slip_solve(tx, ty, dx, dy, g);
        assert!((norm2(px, py) - g).abs() < 1e-13);
        // (D + m I) p = t for one m >= 0 in both components.
        let mx = tx / px - dx;
        let my = ty / py - dy;
        assert!(mx >= 0.0 && (mx - my).abs() < 1e-10, "{mx} {my}");
    }

    /// Brush model: diagonal A = L I; the shifted kernel couples an element to its upstream
    /// neighbour only (dq = dx).
    fn brush(mx: usize, my: usize, l: f64) -> (Kernel, Kernel) {
        let n = (2 * mx - 1) * (2 * my - 1);
        let mut k0 = Kernel {
            mx,
            my,
            dx_mm: 1.0,
            dy_mm: 1.0,
            shift_mm: 0.0,
            zz: vec![0.0; n],
            xx: vec![0.0; n],
            yy: vec![0.0; n],
            xy: vec![0.0; n],
        };
        let c = k0.index(0, 0);
        k0.zz[c] = l;
        k0.xx[c] = l;
        k0.yy[c] = l;
        let mut ks = k0.clone();
        ks.shift_mm = 1.0;
        ks.zz[c] = 0.0;
        ks.xx[c] = 0.0;
        ks.yy[c] = 0.0;
        let u = ks.index(1, 0);
        ks.zz[u] = l;
        ks.xx[u] = l;
        ks.yy[u] = l;
        (k0, ks)
    }

    #[test]
    fn brush_gives_explicit_transport_scheme() {
        let (mx, my, l) = (6, 3, 1e-5);
        let (k0, ks) = brush(mx, my, l);
        let grid = Grid::new(mx, my, 3.0, 1.5);
        let (x, y) = grid.centres();
        let pn = vec![100.0; mx * my];
        for method in [Method::GaussSeidel, Method::ConjugateGradient] {
            let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
            let mut p = TangentialParams::new(1.0, 1e-4, 0.0, 0.0, 1.0);
            p.method = method;
            let (mut px, mut py) = (vec![0.0; mx * my], vec![0.0; mx * my]);
            for _step in 0..12 {
                let r = s.transient_step(&p, &px, &py, None).unwrap();
                assert!(r.converged);
                for j in 0..my {
                    for i in 0..mx {
                        let prev = if i == 0 { 0.0 } else { px[j * mx + i - 1] };
                        // p_k = p'_(k-1) + dx cx / L, capped at g = mu pn = 100 MPa.
                        let want = (prev + 1.0 * 1e-4 / l).min(100.0);
                        let got = r.px[j * mx + i];
                        assert!((got - want).abs() < 1e-6, "{method:?} ({i},{j}): {got} vs {want}");
                        assert!(r.py[j * mx + i].abs() < 1e-9);
                    }
                }
                px.copy_from_slice(&r.px);
                py.copy_from_slice(&r.py);
            }
            // After enough steps the downstream part saturates: 10 MPa per element.
            assert!((px[5] - 60.0).abs() < 1e-6);
        }
    }

    fn hertz_setup(mx: usize, my: usize, courant: f64) -> (Kernel, Kernel, Vec<f64>, Grid) {
        let (a, b, fnn, g, nu) = (6.0, 3.5, 50_000.0, 82000.0, 0.28);
        let grid = Grid::new(mx, my, a, b);
        let h = crate::physics::ContactGeometry::undeformed_distance_mm(
            &crate::physics::HertzEllipse { nominal: crate::physics::HertzContact { a_mm: a, b_mm: b, fn_n: fnn } },
            &grid,
            fnn,
            &crate::physics::Material::from_g(g, nu),
        );
        let k0 = Kernel::new(mx, my, grid.dx_mm, grid.dy_mm, g, nu, 0.0).unwrap();
        let dq = courant * grid.dx_mm;
        let ks = Kernel::new(mx, my, grid.dx_mm, grid.dy_mm, g, nu, dq).unwrap();
        let pn = solve_normal(&h, &k0, fnn, &NormalParams::default()).unwrap().pn_mpa;
        (k0, ks, pn, grid)
    }

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn cg_and_gauss_seidel_agree_with_spin_and_half_courant() {
        let (k0, ks, pn, grid) = hertz_setup(14, 12, 0.5);
        let (x, y) = grid.centres();
        let gmax = 0.3 * pn.iter().cloned().fold(0.0, f64::max);
        let mut sol = Vec::new();
        for method in [Method::GaussSeidel, Method::ConjugateGradient] {
            let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
            let mut p = TangentialParams::new(0.3, 0.001, -0.0005, 0.003, ks.shift_mm);
            p.tol = 1e-10;
            p.method = method;
            let n = pn.len();
            let (mut px, mut py) = (vec![0.0; n], vec![0.0; n]);
            let mut last = None;
            for _ in 0..6 {
                let r = s.transient_step(&p, &px, &py, None).unwrap();
                assert!(r.converged, "{method:?}");
                px.copy_from_slice(&r.px);
                py.copy_from_slice(&r.py);
                last = Some(r);
            }
            let r = last.unwrap();
            assert!(r.n_slip > 0 && r.n_adhesion > 0, "{} {}", r.n_slip, r.n_adhesion);
            sol.push(r);
        }
        let d = sol[0]
            .px
            .iter()
            .zip(&sol[1].px)
            .chain(sol[0].py.iter().zip(&sol[1].py))
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(d < 1e-7 * gmax, "GS vs CG differ by {d} MPa");
        assert_eq!(sol[0].state, sol[1].state);
        // Coulomb conditions hold in the solution.
        let r = &sol[1];
        for k in 0..pn.len() {
            let g = 0.3 * pn[k];
            let a = norm2(r.px[k], r.py[k]);
            assert!(a <= g * (1.0 + 1e-12));
            match r.state[k] {
                ElementState::Adhesion => {
                    assert!(norm2(r.sx[k], r.sy[k]) < 1e-8 * 1e-3, "slip in adhesion")
                }
                ElementState::Slip => {
                    assert!((a - g).abs() < 1e-9 * g);
                    // slip parallel to the traction, same sense
                    let cross = r.sx[k] * r.py[k] - r.sy[k] * r.px[k];
                    let dot = r.sx[k] * r.px[k] + r.sy[k] * r.py[k];
                    assert!(dot >= -1e-12 && cross.abs() <= 1e-6 * norm2(r.sx[k], r.sy[k]) * g + 1e-15);
                }
                ElementState::Exterior => assert_eq!(a, 0.0),
            }
        }
    }

    #[test]
    fn extrapolated_warm_start_reaches_the_same_solution() {
        // A ramp of creepage, stepped with and without the extrapolated warm start: the same
        // tractions to the tolerance, the same element states, and no more iterations.
        let (k0, ks, pn, grid) = hertz_setup(16, 12, 1.0);
        let (x, y) = grid.centres();
        let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
        let n = pn.len();
        let mut runs = Vec::new();
        for extrapolate in [false, true] {
            let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
            let (mut px, mut py) = (vec![0.0; n], vec![0.0; n]);
            let mut older: Option<(Vec<f64>, Vec<f64>)> = None;
            let mut iterations = 0;
            let mut last = None;
            for step in 0..12 {
                let mut p = TangentialParams::new(0.4, 0.0005 * step as f64, 0.0, 0.0, ks.shift_mm);
                p.tol = 1e-9;
                let o = if extrapolate { older.as_ref().map(|(a, b)| (a.as_slice(), b.as_slice())) } else { None };
                let r = s.transient_step(&p, &px, &py, o).unwrap();
                assert!(r.converged);
                iterations += r.iterations;
                older = Some((px.clone(), py.clone()));
                px.copy_from_slice(&r.px);
                py.copy_from_slice(&r.py);
                last = Some(r);
            }
            runs.push((last.unwrap(), iterations));
        }
        let (a, b) = (&runs[0].0, &runs[1].0);
        let d = a.px.iter().zip(&b.px).chain(a.py.iter().zip(&b.py)).fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
        assert!(d < 1e-7 * gmax, "warm starts differ by {d} MPa");
        assert_eq!(a.state, b.state);
        assert!(runs[1].1 <= runs[0].1, "extrapolated {} vs previous {} iterations", runs[1].1, runs[0].1);
        // Mismatched lengths are an error, not a panic.
        let p = TangentialParams::new(0.4, 0.001, 0.0, 0.0, ks.shift_mm);
        let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
        let short = vec![0.0; n - 1];
        assert!(s.transient_step(&p, &b.px, &b.py, Some((&short, &short))).is_err());
    }

    #[test]
    fn extrapolation_factor_follows_the_creepage_line() {
        let point = |mu: f64, cx: f64, cy: f64| SteadyPoint { creep: [mu, cx, cy, 0.0], px: vec![], py: vec![] };
        let (o, l) = (point(0.3, 0.001, 0.0), point(0.3, 0.002, 0.0));
        let next = |mu: f64, cx: f64, cy: f64| TangentialParams::new(mu, cx, cy, 0.0, 0.1);
        assert!((extrapolation_factor(&o, &l, &next(0.3, 0.003, 0.0)) - 1.0).abs() < 1e-12);
        assert!((extrapolation_factor(&o, &l, &next(0.3, 0.0025, 0.0)) - 0.5).abs() < 1e-12);
        assert_eq!(extrapolation_factor(&o, &l, &next(0.3, 0.003, 0.001)), 0.0, "off the line");
        assert_eq!(extrapolation_factor(&o, &l, &next(0.4, 0.003, 0.0)), 0.0, "other mu");
        assert_eq!(extrapolation_factor(&l, &l, &next(0.3, 0.003, 0.0)), 0.0, "no direction");
    }

    #[test]
    fn steady_state_is_fixed_point_of_transient_step() {
        let (k0, ks, pn, grid) = hertz_setup(16, 12, 1.0);
        let (x, y) = grid.centres();
        let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
        let mut p = TangentialParams::new(0.4, 0.002, 0.0, 0.0, ks.shift_mm);
        p.tol = 1e-10;
        let st = s.steady(&p, None).unwrap();
        assert!(st.converged && st.n_slip > 0 && st.n_adhesion > 0);
        let tr = s.transient_step(&p, &st.px, &st.py, None).unwrap();
        assert!(tr.converged);
        let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
        let d = st.px.iter().zip(&tr.px).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(d < 1e-6 * gmax, "steady vs transient from steady: {d}");
    }

    /// The accelerated steady solver reproduces the Gauss-Seidel steady state (creepage and spin,
    /// Courant 1 and 2, cold and warm starts), bit for bit on a repeat; from a cold start in fewer
    /// iterations.
    #[test]
    fn accelerated_steady_matches_gauss_seidel() {
        for courant in [1.0, 2.0] {
            let (k0, ks, pn, grid) = hertz_setup(16, 12, courant);
            let (x, y) = grid.centres();
            let gmax = 0.4 * pn.iter().cloned().fold(0.0, f64::max);
            let mut solvers: Vec<TangentialSolver> =
                (0..3).map(|_| TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap()).collect();
            for (i, (cx, cy, cs)) in
                [(0.002, 0.0, 0.0), (0.001, -0.0005, 0.004), (0.0015, 0.0, 0.0)].into_iter().enumerate()
            {
                let mut p = TangentialParams::new(0.4, cx, cy, cs, ks.shift_mm);
                p.tol = 1e-10;
                p.steady_method = SteadyMethod::GaussSeidel;
                let gs = solvers[0].steady(&p, None).unwrap();
                p.steady_method = SteadyMethod::Accelerated;
                let aa = solvers[1].steady(&p, None).unwrap();
                let again = solvers[2].steady(&p, None).unwrap();
                assert!(gs.converged && aa.converged, "courant {courant}: {} {}", gs.residual, aa.residual);
                assert!(aa.residual < p.tol && aa.n_slip > 0 && aa.n_adhesion > 0);
                if i == 0 {
                    assert!(aa.iterations < gs.iterations, "{} vs {}", aa.iterations, gs.iterations);
                }
                let d = gs.px.iter().zip(&aa.px).chain(gs.py.iter().zip(&aa.py));
                let d = d.fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
                assert!(d < 1e-7 * gmax, "courant {courant} ({cx}, {cy}, {cs}): {d} MPa");
                assert_eq!(aa, again);
            }
        }
    }

    #[test]
    fn non_convergence_is_flagged_and_bad_input_is_an_error() {
        let (k0, ks, pn, grid) = hertz_setup(12, 10, 1.0);
        let (x, y) = grid.centres();
        let mut s = TangentialSolver::new(&k0, &ks, &pn, &x, &y).unwrap();
        let n = pn.len();
        let mut p = TangentialParams::new(0.4, 0.004, 0.0, 0.0, ks.shift_mm);
        p.max_iter = 1;
        let zero = vec![0.0; n];
        for method in [Method::GaussSeidel, Method::ConjugateGradient] {
            p.method = method;
            let r = s.transient_step(&p, &zero, &zero, None).unwrap();
            assert!(!r.converged && r.residual > p.tol && r.residual.is_finite());
        }
        let r = s.steady(&p, None).unwrap();
        assert!(!r.converged);
        p.max_iter = 1000;
        p.cx = f64::NAN;
        assert!(s.transient_step(&p, &zero, &zero, None).is_err());
        p.cx = 0.001;
        p.dq_mm *= 1.5;
        assert!(s.steady(&p, None).is_err());
        p.dq_mm = ks.shift_mm;
        assert!(s.transient_step(&p, &zero[1..], &zero, None).is_err());
        assert!(TangentialSolver::new(&k0, &ks, &vec![0.0; n], &x, &y).is_err());
        // mu = 0: no traction at all, everything slips.
        p.mu = 0.0;
        let r = s.transient_step(&p, &zero, &zero, None).unwrap();
        assert!(r.converged && r.px.iter().all(|&v| v == 0.0) && r.n_adhesion == 0);
    }
}
