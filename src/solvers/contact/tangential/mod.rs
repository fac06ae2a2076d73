//! Tangential rolling-contact problem with Coulomb friction for one transient time step or for
//! steady rolling (Kalker 1990, sec. 5.4; Vollebregt & Kalker, CONTACT user guide), organised as
//! CONTACT's tangential solvers: one file per method around one element solver and one set of
//! operators.
//!
//! Per contact element `k` (pn_k > 0), traction bound `g_k = mu pn_k` [MPa]:
//! * rigid slip of the step `w_k = dq (cx - cs y_k, cy - cs (x_k - dq/6))` [mm] ([`RigidSlip`] in
//!   grid coordinates, spin evaluated `dq/6` downstream of the centre as CONTACT does; rolling
//!   at another angle: `dq/6` against the material's motion `t`, at `x_k - t dq/6`);
//! * transient: previous displacement `u'_k = (A_s p')_k`, kernel shifted by `dq` (material that is
//!   at `x_k` now was at `x_k - dq`; at another angle at `x_k - t dq`, [`Kernel::rolling`]), slip `s_k = w_k + u'_k - (A p)_k` [mm]; for `dq > dx`
//!   material that entered the contact during the step slips only from the leading edge on:
//!   `s_k = facdt_k w_k + u_edge - (A p)_k` ([`Entering`]);
//! * steady rolling: the fixed point `p' = p`, `s = w - (A - A_s) p`;
//! * adhesion `s_k = 0, |p_k| <= g_k`; slip `|p_k| = g_k, s_k = lambda p_k/|p_k|`, `lambda >= 0`.
//!
//! The modules:
//! * `element`: the local 2x2 problem of one element with the others fixed (stick, or slip on
//!   the bound by a safeguarded Newton iteration), shared by every method;
//! * `operator`: the FFT products and coefficient operators, built once per grid, and the
//!   incremental slip update;
//! * `gauss_seidel`: projected Gauss–Seidel with exact incremental slip updates (CONTACT's
//!   ConvexGS); transient steps sweep each row leading edge first, steady rolling trailing edge
//!   first (the other order diverges for `A - A_s`); the fallback of the two methods below;
//! * `cg`: transient steps by a preconditioned projected conjugate-gradient method on the
//!   adhesion tractions and the slip directions (CONTACT's TangCG type), FFT products;
//! * `steady`: steady rolling by an Anderson-accelerated (Walker & Ni 2011) preconditioned
//!   projected fixed-point map that inverts the shift along the adhesion rows.
//!
//! All stop when the largest traction change a local solve would make, relative to `max(g)`, is
//! below `tol` (Gauss–Seidel: `max|delta p|` of the last sweep; CG: the preconditioned residual at
//! an exact slip re-evaluation; accelerated steady: every element's local solve at the exact slip
//! of the iterate). The bound is enforced by the crate's one projection, [`crate::physics::bound`].

mod cg;
mod element;
mod gauss_seidel;
mod operator;
mod steady;

use super::convolution::Convolver;
use super::influence::Kernel;
use super::ContactError;
use crate::physics::bound::project_to_bound;
use crate::physics::RigidSlip;
use crate::solvers::termination::Termination;
use cg::CgWork;
use operator::{Plans, Spans};
use steady::SteadyWork;

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
    /// is below `tol` (default 1e-7; Gauss–Seidel: over the last sweep).
    pub tol: f64,
    /// Maximum Gauss–Seidel sweeps or CG iterations (default 1000); a CG that does not converge
    /// continues with up to as many Gauss–Seidel sweeps. The accelerated steady solver makes at
    /// most `min(max_iter, 400)` map evaluations before up to `max_iter` Gauss–Seidel sweeps.
    pub max_iter: usize,
    /// Solver for transient steps (default [`Method::ConjugateGradient`]).
    pub method: Method,
    /// Solver for steady rolling (default [`SteadyMethod::Accelerated`]).
    pub steady_method: SteadyMethod,
}

/// Solver choice for steady rolling.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SteadyMethod {
    /// Anderson-accelerated preconditioned projected fixed-point iteration (`steady`),
    /// Gauss–Seidel sweeps taking over if the acceleration stalls.
    #[default]
    Accelerated,
    /// Projected Gauss–Seidel only (trailing edge first).
    GaussSeidel,
}

/// Solver choice for transient steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// FFT-based projected conjugate gradients on the adhesion set and the slip directions
    /// (TangCG type, `cg`), falling back to Gauss–Seidel if it does not converge.
    #[default]
    ConjugateGradient,
    /// Projected Gauss–Seidel with exact incremental slip updates (ConvexGS, `gauss_seidel`).
    GaussSeidel,
}

impl TangentialParams {
    /// Parameters with the default tolerance 1e-7, 1000 iterations and the default methods.
    pub fn new(mu: f64, cx: f64, cy: f64, cs: f64, dq_mm: f64) -> TangentialParams {
        TangentialParams {
            mu,
            cx,
            cy,
            cs,
            dq_mm,
            tol: 1e-7,
            max_iter: 1000,
            method: Method::default(),
            steady_method: SteadyMethod::default(),
        }
    }

    fn validate(&self) -> Result<(), ContactError> {
        let values =
            [("mu", self.mu), ("cx", self.cx), ("cy", self.cy), ("cs", self.cs), ("dq", self.dq_mm), ("tol", self.tol)];
        if let Some(&(name, value)) = values.iter().find(|(_, v)| !v.is_finite()) {
            return Err(ContactError::OutOfRange { name, value, requirement: "finite" });
        }
        if self.mu < 0.0 {
            return Err(ContactError::OutOfRange { name: "friction coefficient", value: self.mu, requirement: ">= 0" });
        }
        if self.dq_mm <= 0.0 {
            return Err(ContactError::OutOfRange {
                name: "rolling step dq [mm]",
                value: self.dq_mm,
                requirement: "> 0",
            });
        }
        if self.tol <= 0.0 {
            return Err(ContactError::OutOfRange { name: "tol", value: self.tol, requirement: "> 0" });
        }
        if self.max_iter == 0 {
            return Err(ContactError::OutOfRange { name: "max_iter", value: 0.0, requirement: ">= 1" });
        }
        Ok(())
    }

    /// The rigid slip per unit rolling distance (Kalker 1990, Eq. 1.6).
    fn rigid_slip(&self) -> RigidSlip {
        RigidSlip::new(self.cx, self.cy, self.cs)
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
    /// Gauss–Seidel sweeps, CG iterations or, for accelerated steady rolling, map evaluations,
    /// plus the Gauss–Seidel sweeps that took over from them.
    pub iterations: usize,
    /// Final relative change `max|delta p| / max(g)`.
    pub residual: f64,
    /// How the solve ended: converged, converged by the Gauss–Seidel fallback after the CG or the
    /// accelerated steady iteration stalled, or at the iteration limit.
    pub termination: Termination,
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

/// CONTACT's default offset of the spin term, as a fraction of `dq` (m_sdis.f90, `set_tang_rhs`:
/// `w_y = CETA + CPHI (x_C + FACPHI dq)`, FACPHI = 1/6 for rolling): the spin slip accumulated
/// over a step is evaluated between the element centre and its upstream position.
const FACPHI: f64 = 1.0 / 6.0;

/// Elements whose centre is closer than `dq` to a leading edge (only when `dq > dx`): their
/// material was outside the contact at the previous time. CONTACT's leading-edge correction
/// (m_leadedge.f90 `sxbnd`/`subnd`, m_stang.f90 eq. 1b): the rigid slip counts only over the
/// fraction `facdt = min(1, (i - i0 + 1) dx / dq)` of the step spent inside (the edge taken at the
/// exterior element `i0 - 1` upstream of the segment's first element `i0`), and the previous
/// displacement is that of the unshifted kernel at the edge element, `(A p')_(i0-1)`. No
/// correction for `i < 2` (the potential contact must hold an exterior element upstream), and
/// `u_edge = 0` for segments starting at `i0 < 2`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entering {
    k: usize,
    facdt: f64,
    edge: Option<usize>,
}

/// The grid and the contact area of the current load.
struct Layout {
    mx: usize,
    my: usize,
    dx_mm: f64,
    /// Rolling distance per step `dq` [mm], the shift of the shifted kernel; 1 for shifts without
    /// rolling (the creepages are then the shifts per step in mm).
    shift_mm: f64,
    /// Whether the bodies roll (else shifts without rolling: the kernel does not shift, no
    /// steady state, no entering material, the spin term at the centre).
    rolls: bool,
    /// Unit vector the material moves along against the contact (grid coordinates; `[1, 0]`:
    /// CHI = 0, [`super::direction`]): the spin term's offset `FACPHI dq` points against it.
    towards: [f64; 2],
    /// Element centres [mm].
    x_mm: Vec<f64>,
    y_mm: Vec<f64>,
    /// Pressure of the current load [MPa].
    pn: Vec<f64>,
    /// Contact elements (`pn > 0`) row by row, `i` ascending (leading edge first).
    contact: Vec<usize>,
    /// Contact elements row by row, `i` descending within a row (trailing edge first).
    contact_down: Vec<usize>,
    /// `pn > 0` per grid element.
    mask: Vec<bool>,
    /// Contact spans per row, for the incremental slip update.
    spans: Spans,
    /// Elements that enter the contact during a transient step (`dq > dx` only).
    entering: Vec<Entering>,
    /// Dissimilar bodies: the slip of the pressure's tangential displacements `u'_tz − u_tz` [mm]
    /// added to the rigid slip of every contact element ([`TangentialSolver::set_coupled_slip`]).
    coupled: Option<(Vec<f64>, Vec<f64>)>,
    /// An extra rigid slip per element [-] added to the creepages (CONTACT's EXRHS, E = 9,
    /// `m_sdis.f90` `set_tang_rhs`; [`TangentialSolver::set_extra_slip`]).
    extra: Option<(Vec<f64>, Vec<f64>)>,
}

impl Layout {
    fn n(&self) -> usize {
        self.mx * self.my
    }

    /// Courant number `dq/dx`.
    fn courant(&self) -> f64 {
        self.shift_mm / self.dx_mm
    }

    /// The largest traction bound `max(mu pn)` [MPa].
    fn gmax(&self, mu: f64) -> f64 {
        self.contact.iter().map(|&k| mu * self.pn[k]).fold(0.0, f64::max)
    }

    /// Replaces the contact area by the elements with `pn > 0` of a new pressure.
    fn set_pressure(&mut self, pn_mpa: &[f64]) -> Result<(), ContactError> {
        let (mx, my, n) = (self.mx, self.my, self.n());
        check_grid_array("pn", pn_mpa, n)?;
        if let Some(&value) = pn_mpa.iter().find(|&&v| v < 0.0) {
            return Err(ContactError::OutOfRange { name: "pressure [MPa]", value, requirement: ">= 0" });
        }
        self.pn.clear();
        self.pn.extend_from_slice(pn_mpa);
        self.contact.clear();
        self.contact.extend((0..n).filter(|&k| pn_mpa[k] > 0.0));
        if self.contact.is_empty() {
            return Err(ContactError::NoContact);
        }
        self.contact_down.clear();
        for j in 0..my {
            self.contact_down.extend((0..mx).rev().map(|i| j * mx + i).filter(|&k| pn_mpa[k] > 0.0));
        }
        self.mask.clear();
        self.mask.extend(pn_mpa.iter().map(|&v| v > 0.0));
        self.spans = Spans::new(mx, my, pn_mpa);
        self.entering = self.find_entering();
        Ok(())
    }

    /// The [`Entering`] elements of the current contact area.
    fn find_entering(&self) -> Vec<Entering> {
        let mut out = Vec::new();
        if !self.rolls || self.shift_mm <= self.dx_mm {
            return out;
        }
        for j in 0..self.my {
            let mut i0 = 0;
            for i in 0..self.mx {
                let k = j * self.mx + i;
                if !self.mask[k] {
                    continue;
                }
                if i == 0 || !self.mask[k - 1] {
                    i0 = i;
                }
                let facdt = ((i - i0 + 1) as f64 * self.dx_mm / self.shift_mm).min(1.0);
                if i >= 2 && facdt < 0.9999 {
                    out.push(Entering { k, facdt, edge: (i0 >= 2).then(|| j * self.mx + i0 - 1) });
                }
            }
        }
        out
    }

    /// Rigid slip of the step `dq w_k` [mm] added into `(bx, by)`, the spin term at the offset
    /// [`FACPHI`]. With `edge_u = A p'` (transient steps), the [`Entering`] elements get
    /// `facdt dq w_k + (A p')_edge` instead of `dq w_k + u'_k`.
    fn add_rigid_slip(&self, p: &TangentialParams, edge_u: Option<(&[f64], &[f64])>, bx: &mut [f64], by: &mut [f64]) {
        let (dq, w) = (p.dq_mm, p.rigid_slip());
        // Shifts: the rotation about the origin, no offset (CONTACT's FACPHI = 0 for T = 1).
        let (ox, oy) =
            if self.rolls { (FACPHI * dq * self.towards[0], FACPHI * dq * self.towards[1]) } else { (0.0, 0.0) };
        let at = |k: usize| {
            let (wx, wy) = w.at(self.x_mm[k] - ox, self.y_mm[k] - oy);
            self.extra.as_ref().map_or((wx, wy), |(ex, ey)| (wx + ex[k], wy + ey[k]))
        };
        for &k in &self.contact {
            let (wx, wy) = at(k);
            bx[k] += dq * wx;
            by[k] += dq * wy;
        }
        if let Some((cx, cy)) = &self.coupled {
            for &k in &self.contact {
                bx[k] += cx[k];
                by[k] += cy[k];
            }
        }
        let Some((ux, uy)) = edge_u else { return };
        for e in &self.entering {
            let (wx, wy) = at(e.k);
            let (ex, ey) = e.edge.map_or((0.0, 0.0), |m| (ux[m], uy[m]));
            bx[e.k] = e.facdt * dq * wx + ex;
            by[e.k] = e.facdt * dq * wy + ey;
        }
    }
}

/// A grid array must have `n` finite entries.
fn check_grid_array(name: &'static str, v: &[f64], n: usize) -> Result<(), ContactError> {
    if v.len() != n {
        return Err(ContactError::SizeMismatch { name, len: v.len(), expected: n });
    }
    match v.iter().position(|z| !z.is_finite()) {
        Some(index) => Err(ContactError::NotFinite { name, index }),
        None => Ok(()),
    }
}

/// The iterate every method works on: tractions, slip and element division over the grid, and
/// two grid buffers for products (`v` holds `b = w + u'` during a transient step).
struct State {
    px: Vec<f64>,
    py: Vec<f64>,
    sx: Vec<f64>,
    sy: Vec<f64>,
    ux: Vec<f64>,
    uy: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
    slip: Vec<bool>,
}

impl State {
    fn new(n: usize) -> State {
        State {
            px: vec![0.0; n],
            py: vec![0.0; n],
            sx: vec![0.0; n],
            sy: vec![0.0; n],
            ux: vec![0.0; n],
            uy: vec![0.0; n],
            vx: vec![0.0; n],
            vy: vec![0.0; n],
            slip: vec![false; n],
        }
    }

    /// Projects the tractions of the contact elements onto their bounds `mu pn`.
    fn clip_to_bound(&mut self, lay: &Layout, mu: f64) {
        for &k in &lay.contact {
            (self.px[k], self.py[k], _) = project_to_bound(self.px[k], self.py[k], mu * lay.pn[k]);
        }
    }

    /// Exact slip `s = b - A p` with `b` in `(vx, vy)` (transient steps).
    fn recompute_slip(&mut self, lay: &Layout, conv0: &mut Convolver) -> Result<(), ContactError> {
        conv0.tangential(&self.px, &self.py, Some(&lay.mask), &mut self.ux, &mut self.uy)?;
        for &k in &lay.contact {
            self.sx[k] = self.vx[k] - self.ux[k];
            self.sy[k] = self.vy[k] - self.uy[k];
        }
        Ok(())
    }

    /// Packs the current tractions, slip and element division into a [`StepResult`].
    fn finish(
        &self,
        lay: &Layout,
        iterations: usize,
        residual: f64,
        termination: Termination,
    ) -> Result<StepResult, ContactError> {
        let n = lay.n();
        let mut state = vec![ElementState::Exterior; n];
        let (mut n_adhesion, mut n_slip) = (0, 0);
        let (mut px, mut py, mut sx, mut sy) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for &k in &lay.contact {
            if self.slip[k] {
                state[k] = ElementState::Slip;
                n_slip += 1;
            } else {
                state[k] = ElementState::Adhesion;
                n_adhesion += 1;
            }
            (sx[k], sy[k]) = (self.sx[k], self.sy[k]);
            (px[k], py[k]) = (self.px[k], self.py[k]);
        }
        if px.iter().chain(&py).any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("tangential traction"));
        }
        Ok(StepResult { px, py, sx, sy, state, iterations, residual, termination, n_adhesion, n_slip })
    }
}

/// How one method's iteration ended.
#[derive(Debug, Clone, Copy)]
struct Outcome {
    iterations: usize,
    residual: f64,
    converged: bool,
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

/// Transient / steady tangential solver for a fixed grid and kernels. Build once per grid
/// ([`TangentialSolver::new`]: kernels, FFT plans, operators), give it the pressure of each load
/// ([`TangentialSolver::set_pressure`]: contact area, spans, masks), then call
/// [`TangentialSolver::transient_step`] per time step or [`TangentialSolver::steady`] per creepage
/// point. Buffers are reused between calls.
pub struct TangentialSolver {
    layout: Layout,
    plans: Plans,
    state: State,
    cg: CgWork,
    /// Work of the accelerated steady solver (allocated on first use per load).
    steady: Option<SteadyWork>,
    /// The last two steady solutions (warm start of the next steady point).
    steady_prev: Vec<SteadyPoint>,
    /// Whether the state holds the right-hand side of the last [`TangentialSolver::transient_step`]
    /// (what [`TangentialSolver::transient_resolve_from`] solves again).
    rhs_kept: bool,
}

impl TangentialSolver {
    /// Sets up the solver for a grid. `k0`: unshifted kernel; `ks`: kernel shifted by `dq` [mm]
    /// (`ks.shift_mm = dq`); `x_mm`, `y_mm`: element centres [mm] (flat index `k = j*mx + i`).
    /// No load yet: call [`TangentialSolver::set_pressure`] before solving.
    pub fn new(k0: &Kernel, ks: &Kernel, x_mm: &[f64], y_mm: &[f64]) -> Result<TangentialSolver, ContactError> {
        Self::rolling_towards(k0, ks, [1.0, 0.0], x_mm, y_mm)
    }

    /// [`TangentialSolver::new`] for rolling at another direction: the material moves along the
    /// unit vector `towards` (grid coordinates, [`super::direction::towards`]), `ks` the kernel
    /// shifted along it ([`Kernel::rolling`]). The leading-edge correction for `dq > dx` stays
    /// along x, as CONTACT's (`m_leadedge.f90`: rolling assumed along ±x).
    pub fn rolling_towards(
        k0: &Kernel,
        ks: &Kernel,
        towards: [f64; 2],
        x_mm: &[f64],
        y_mm: &[f64],
    ) -> Result<TangentialSolver, ContactError> {
        if ks.shift_mm.is_nan() || ks.shift_mm <= 0.0 {
            return Err(ContactError::OutOfRange {
                name: "shift dq of the shifted kernel [mm]",
                value: ks.shift_mm,
                requirement: "> 0",
            });
        }
        if let Some(&value) = towards.iter().find(|v| !v.is_finite()) {
            return Err(ContactError::OutOfRange { name: "rolling direction", value, requirement: "finite" });
        }
        let mut s = Self::build(k0, ks, x_mm, y_mm, true)?;
        s.layout.towards = towards;
        Ok(s)
    }

    /// Sets up the solver for shifts without rolling (CONTACT T = 1; Kalker 1990 §5.2.1): the
    /// previous displacement is `A p'` in place (`A_s = A`), a step's rigid slip is the shift
    /// itself (the creepages as shifts [mm], `dq` = 1); transient steps only.
    pub fn for_shifts(k0: &Kernel, x_mm: &[f64], y_mm: &[f64]) -> Result<TangentialSolver, ContactError> {
        Self::build(k0, k0, x_mm, y_mm, false)
    }

    fn build(
        k0: &Kernel,
        ks: &Kernel,
        x_mm: &[f64],
        y_mm: &[f64],
        rolls: bool,
    ) -> Result<TangentialSolver, ContactError> {
        let (mx, my) = (k0.mx, k0.my);
        let n = mx * my;
        if ks.mx != mx || ks.my != my || ks.dx_mm != k0.dx_mm || ks.dy_mm != k0.dy_mm {
            return Err(ContactError::GridMismatch { expected: (mx, my), got: (ks.mx, ks.my) });
        }
        if k0.shift_mm != 0.0 {
            return Err(ContactError::OutOfRange {
                name: "shift of the unshifted kernel [mm]",
                value: k0.shift_mm,
                requirement: "= 0",
            });
        }
        check_grid_array("x", x_mm, n)?;
        check_grid_array("y", y_mm, n)?;
        let plans = Plans::of(k0, ks)?;
        let layout = Layout {
            mx,
            my,
            dx_mm: k0.dx_mm,
            shift_mm: if rolls { ks.shift_mm } else { 1.0 },
            rolls,
            towards: [1.0, 0.0],
            x_mm: x_mm.to_vec(),
            y_mm: y_mm.to_vec(),
            pn: vec![0.0; n],
            contact: Vec::with_capacity(n),
            contact_down: Vec::with_capacity(n),
            mask: vec![false; n],
            spans: Spans::new(mx, my, &vec![0.0; n]),
            entering: Vec::new(),
            coupled: None,
            extra: None,
        };
        Ok(TangentialSolver {
            layout,
            plans,
            state: State::new(n),
            cg: CgWork::new(n),
            steady: None,
            steady_prev: Vec::with_capacity(2),
            rhs_kept: false,
        })
    }

    /// Moves the grid to new element centres `x_mm`, `y_mm` (same size and kernels: a patch of
    /// the same size elsewhere); the next [`TangentialSolver::set_pressure`] sets its load.
    pub fn set_centres(&mut self, x_mm: &[f64], y_mm: &[f64]) -> Result<(), ContactError> {
        let n = self.layout.n();
        check_grid_array("x", x_mm, n)?;
        check_grid_array("y", y_mm, n)?;
        self.layout.x_mm.copy_from_slice(x_mm);
        self.layout.y_mm.copy_from_slice(y_mm);
        Ok(())
    }

    /// Sets the load: pressure per element [MPa] (contact = `pn > 0`). Forgets everything of the
    /// previous load (work arrays, steady warm start), so that the next solve is the one a newly
    /// built solver would make.
    pub fn set_pressure(&mut self, pn_mpa: &[f64]) -> Result<(), ContactError> {
        let n = self.layout.n();
        self.layout.contact.clear();
        self.layout.set_pressure(pn_mpa)?;
        self.state = State::new(n);
        self.cg = CgWork::new(n);
        self.steady = None;
        self.steady_prev.clear();
        self.rhs_kept = false;
        Ok(())
    }

    /// Sets the traction bound per element, `g_k = μ_k pn_k` [MPa], for a friction coefficient
    /// that varies per element (solve with `mu = 1`): replaces the bound's pressure only, keeping
    /// the contact area, the work arrays and the warm start. `g` must be positive exactly on the
    /// contact area set by [`TangentialSolver::set_pressure`].
    pub fn set_bound(&mut self, g_mpa: &[f64]) -> Result<(), ContactError> {
        let lay = &mut self.layout;
        check_grid_array("traction bound", g_mpa, lay.n())?;
        if let Some(k) = (0..lay.n()).find(|&k| (g_mpa[k] > 0.0) != lay.mask[k]) {
            return Err(ContactError::OutOfRange {
                name: "traction bound [MPa]",
                value: g_mpa[k],
                requirement: "> 0 exactly on the contact area",
            });
        }
        lay.pn.copy_from_slice(g_mpa);
        Ok(())
    }

    /// Dissimilar bodies (Kalker's K ≠ 0): the slip `(sx, sy)` [mm] the pressures add to every
    /// contact element's rigid slip, `u'_tz − u_tz` with `u_tz = A_tz pn` now and `u'_tz` at the
    /// material's previous position (CONTACT's `uvn − usn` of `stang_rhs`); `None`: none (K = 0).
    /// Kept until set again, through [`TangentialSolver::set_pressure`].
    pub fn set_coupled_slip(&mut self, slip: Option<(&[f64], &[f64])>) -> Result<(), ContactError> {
        let n = self.layout.n();
        self.layout.coupled = match slip {
            Some((sx, sy)) => {
                check_grid_array("coupled slip x", sx, n)?;
                check_grid_array("coupled slip y", sy, n)?;
                Some((sx.to_vec(), sy.to_vec()))
            }
            None => None,
        };
        Ok(())
    }

    /// An extra rigid slip per element `(wx, wy)` [-] (grid order) added to the creepages of every
    /// solve, scaled by dq as they are (CONTACT's EXRHS, E = 9, `m_sdis.f90` `set_tang_rhs`);
    /// `None`: none.
    pub fn set_extra_slip(&mut self, slip: Option<(&[f64], &[f64])>) -> Result<(), ContactError> {
        let n = self.layout.n();
        self.layout.extra = match slip {
            Some((wx, wy)) => {
                check_grid_array("extra slip x", wx, n)?;
                check_grid_array("extra slip y", wy, n)?;
                Some((wx.to_vec(), wy.to_vec()))
            }
            None => None,
        };
        Ok(())
    }

    /// Number of contact elements.
    pub fn n_contact(&self) -> usize {
        self.layout.contact.len()
    }

    /// Courant number `dq/dx`.
    pub fn courant(&self) -> f64 {
        self.layout.courant()
    }

    /// The steady operator's self-flexibility [mm/MPa]: the mean of A − A_s's diagonal
    /// (x and y), an element's slip per MPa of its own traction in steady rolling.
    pub fn steady_self_flexibility_mm_per_mpa(&self) -> f64 {
        0.5 * (self.plans.steady.diag.xx + self.plans.steady.diag.yy)
    }

    fn check_params(&self, p: &TangentialParams) -> Result<(), ContactError> {
        p.validate()?;
        let shift = self.layout.shift_mm;
        if (p.dq_mm - shift).abs() > 1e-9 * shift {
            return Err(ContactError::ShiftMismatch { dq_mm: p.dq_mm, shift_mm: shift });
        }
        if self.layout.contact.is_empty() {
            return Err(ContactError::NoContact);
        }
        Ok(())
    }

    /// One transient rolling step: previous tractions `prev_px`, `prev_py` [MPa] (on the grid, at
    /// the previous time, contact-fixed coordinates) and, if given, those of the step before.
    /// Warm start: the previous traction, or its linear extrapolation `2 p_n - p_(n-1)` in time
    /// when the step before is given; clipped to the traction bound.
    pub fn transient_step(
        &mut self,
        params: &TangentialParams,
        prev_px: &[f64],
        prev_py: &[f64],
        older: Option<(&[f64], &[f64])>,
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        let n = self.layout.n();
        if let Some((ox, oy)) = older {
            check_grid_array("older traction px", ox, n)?;
            check_grid_array("older traction py", oy, n)?;
        }
        self.transient_rhs(params, prev_px, prev_py)?;
        self.rhs_kept = true;
        let (lay, st) = (&self.layout, &mut self.state);
        st.px.fill(0.0);
        st.py.fill(0.0);
        for &k in &lay.contact {
            (st.px[k], st.py[k]) = match older {
                Some((ox, oy)) => (2.0 * prev_px[k] - ox[k], 2.0 * prev_py[k] - oy[k]),
                None => (prev_px[k], prev_py[k]),
            };
        }
        self.transient_solve(params)
    }

    /// One transient rolling step after the previous tractions `prev_px`, `prev_py` [MPa], as
    /// [`TangentialSolver::transient_step`], warm started from the tractions `start` [MPa] (clipped
    /// to the bound) in place of the previous tractions' extrapolation.
    pub fn transient_step_from(
        &mut self,
        params: &TangentialParams,
        prev_px: &[f64],
        prev_py: &[f64],
        start: (&[f64], &[f64]),
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        self.transient_rhs(params, prev_px, prev_py)?;
        self.rhs_kept = true;
        self.transient_resolve_from(params, start)
    }

    /// The step of the last [`TangentialSolver::transient_step`] again (the same creepages in
    /// `params` and previous tractions: its right-hand side b = w + u' is kept, one convolution
    /// less) with the bound changed since ([`TangentialSolver::set_bound`]), warm started from the
    /// tractions `start` [MPa] (an earlier solve of the same step with another bound).
    pub fn transient_resolve_from(
        &mut self,
        params: &TangentialParams,
        start: (&[f64], &[f64]),
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        if !self.rhs_kept {
            return Err(ContactError::OutOfRange {
                name: "transient re-solve without a transient step of this load before it",
                value: 0.0,
                requirement: "after transient_step",
            });
        }
        let n = self.layout.n();
        check_grid_array("start traction px", start.0, n)?;
        check_grid_array("start traction py", start.1, n)?;
        let (lay, st) = (&self.layout, &mut self.state);
        st.px.fill(0.0);
        st.py.fill(0.0);
        for &k in &lay.contact {
            (st.px[k], st.py[k]) = (start.0[k], start.1[k]);
        }
        self.transient_solve(params)
    }

    /// The transient step from the warm start in the state's tractions (the right-hand side set).
    fn transient_solve(&mut self, params: &TangentialParams) -> Result<StepResult, ContactError> {
        let (lay, st) = (&self.layout, &mut self.state);
        st.clip_to_bound(lay, params.mu);
        // s = b - A p.
        st.recompute_slip(lay, &mut self.plans.conv0)?;
        let op = &self.plans.transient;
        if params.method == Method::GaussSeidel || lay.gmax(params.mu) <= 0.0 {
            let o = gauss_seidel::solve(lay, op, &lay.contact, st, params)?;
            return st.finish(lay, o.iterations, o.residual, primary(o.converged));
        }
        let o = cg::solve(lay, &mut self.plans, st, &mut self.cg, params)?;
        if o.converged {
            return st.finish(lay, o.iterations, o.residual, Termination::Converged);
        }
        // Fall back to Gauss–Seidel from the current iterate (slip exact).
        st.recompute_slip(lay, &mut self.plans.conv0)?;
        let gs = gauss_seidel::solve(lay, &self.plans.transient, &lay.contact, st, params)?;
        st.finish(lay, o.iterations + gs.iterations, gs.residual, fallback(gs.converged))
    }

    /// The right-hand side `b = w + u'` of a transient step into `(vx, vy)`: `u' = A_s p'`, the
    /// previous displacement at the previous position of the material, and for material that
    /// entered during the step (`dq > dx`) the leading-edge form ([`Layout::add_rigid_slip`]).
    fn transient_rhs(
        &mut self,
        params: &TangentialParams,
        prev_px: &[f64],
        prev_py: &[f64],
    ) -> Result<(), ContactError> {
        let (lay, st) = (&self.layout, &mut self.state);
        check_grid_array("previous traction px", prev_px, lay.n())?;
        check_grid_array("previous traction py", prev_py, lay.n())?;
        self.plans.convs.tangential(prev_px, prev_py, None, &mut st.vx, &mut st.vy)?;
        if !lay.entering.is_empty() {
            self.plans.conv0.tangential(prev_px, prev_py, None, &mut st.ux, &mut st.uy)?;
        }
        lay.add_rigid_slip(params, Some((&st.ux, &st.uy)), &mut st.vx, &mut st.vy);
        Ok(())
    }

    /// The slip of a transient step at the tractions `p` [MPa] after the previous tractions
    /// `prev`, `s = w + u' - A p` [mm] on the contact elements (zero elsewhere), as
    /// [`TangentialSolver::transient_step`] forms it; no solve.
    pub fn transient_slip(
        &mut self,
        params: &TangentialParams,
        prev: (&[f64], &[f64]),
        p: (&[f64], &[f64]),
    ) -> Result<(Vec<f64>, Vec<f64>), ContactError> {
        self.check_params(params)?;
        let n = self.layout.n();
        check_grid_array("px", p.0, n)?;
        check_grid_array("py", p.1, n)?;
        self.transient_rhs(params, prev.0, prev.1)?;
        self.rhs_kept = false;
        let (lay, st) = (&self.layout, &mut self.state);
        st.px.copy_from_slice(p.0);
        st.py.copy_from_slice(p.1);
        st.recompute_slip(lay, &mut self.plans.conv0)?;
        let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
        for &k in &lay.contact {
            (sx[k], sy[k]) = (st.sx[k], st.sy[k]);
        }
        Ok((sx, sy))
    }

    /// Steady rolling at the given creepages: `s = w - (A - A_s) p`. Warm start from `start`
    /// (tractions [MPa]) if given, else from the previous steady solution of this solver (linearly
    /// extrapolated from the last two when the creepage continues their line), else zero.
    /// Solver per [`TangentialParams::steady_method`]; if the accelerated iteration fails its test,
    /// Gauss–Seidel sweeps continue from its best iterate.
    pub fn steady(
        &mut self,
        params: &TangentialParams,
        start: Option<(&[f64], &[f64])>,
    ) -> Result<StepResult, ContactError> {
        self.check_params(params)?;
        if !self.layout.rolls {
            return Err(ContactError::OutOfRange {
                name: "steady solve of shifts without rolling (no steady state)",
                value: params.dq_mm,
                requirement: "rolling",
            });
        }
        let n = self.layout.n();
        if let Some((sx0, sy0)) = start {
            check_grid_array("start traction px", sx0, n)?;
            check_grid_array("start traction py", sy0, n)?;
        }
        self.warm_start(params, start);
        self.rhs_kept = false;
        let (lay, st) = (&self.layout, &mut self.state);
        st.clip_to_bound(lay, params.mu);
        let gmax = lay.gmax(params.mu);
        let accelerate = params.steady_method == SteadyMethod::Accelerated && gmax > 0.0;
        let (mut evals, mut converged) = (0, None);
        if accelerate {
            let work = self.steady.get_or_insert_with(|| SteadyWork::new(n, lay.contact.len()));
            (evals, converged) = steady::solve(lay, &mut self.plans, st, work, params)?;
        }
        // s = w - (A - A_s) p.
        self.plans.conv0.tangential(&st.px, &st.py, Some(&lay.mask), &mut st.ux, &mut st.uy)?;
        self.plans.convs.tangential(&st.px, &st.py, Some(&lay.mask), &mut st.vx, &mut st.vy)?;
        for &k in &lay.contact {
            st.sx[k] = -(st.ux[k] - st.vx[k]);
            st.sy[k] = -(st.uy[k] - st.vy[k]);
        }
        lay.add_rigid_slip(params, None, &mut st.sx, &mut st.sy);
        let res = match converged {
            Some(residual) => st.finish(lay, evals, residual, Termination::Converged)?,
            None => {
                let gs = gauss_seidel::solve(lay, &self.plans.steady, &lay.contact_down, st, params)?;
                let termination = if accelerate { fallback(gs.converged) } else { primary(gs.converged) };
                st.finish(lay, gs.iterations + evals, gs.residual, termination)?
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

    /// The start of a steady solve into `(px, py)`: `start` if given, else the previous steady
    /// solution (extrapolated along the creepage line from the last two), else zero.
    fn warm_start(&mut self, params: &TangentialParams, start: Option<(&[f64], &[f64])>) {
        let (lay, st) = (&self.layout, &mut self.state);
        st.px.fill(0.0);
        st.py.fill(0.0);
        match start {
            Some((sx0, sy0)) => {
                for &k in &lay.contact {
                    st.px[k] = sx0[k];
                    st.py[k] = sy0[k];
                }
            }
            None if !self.steady_prev.is_empty() => {
                // With one point only, older = last and r = 0: the previous solution itself.
                let (older, last) = (&self.steady_prev[0], &self.steady_prev[self.steady_prev.len() - 1]);
                let r = if self.steady_prev.len() == 2 { extrapolation_factor(older, last, params) } else { 0.0 };
                for &k in &lay.contact {
                    st.px[k] = last.px[k] + r * (last.px[k] - older.px[k]);
                    st.py[k] = last.py[k] + r * (last.py[k] - older.py[k]);
                }
            }
            None => {}
        }
    }
}

/// The termination of a method that ran alone.
fn primary(converged: bool) -> Termination {
    if converged {
        Termination::Converged
    } else {
        Termination::IterationLimit
    }
}

/// The termination of the Gauss–Seidel fallback after a method stalled.
fn fallback(converged: bool) -> Termination {
    if converged {
        Termination::FallbackConverged
    } else {
        Termination::IterationLimit
    }
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_layer;
