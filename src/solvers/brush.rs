//! The brush (simplified-theory) machinery shared by FASTSIM and the UBA (and FaStrip, for its
//! slip area's direction): slip rates per unit rolling distance over the flexibilities, the steady
//! march along each row from the leading edge with the traction bound, and the traction field.
//! FASTSIM and the UBA differ only in how they march.

use crate::physics::bound::{falling_bound, falling_bound_lanes, scale_with_reciprocal, within_bound};
use crate::physics::law_kernel::LawKernel;
pub use crate::physics::LeadingEdge;
use crate::physics::{moment_sum, project_to_bound, Flexibilities, Grid, Planform, RigidSlip};
use crate::problem::{LocalContact, Problem, Sample};
use crate::simd::with_avx2;
use crate::solvers::{FieldView, Step, Termination};

/// The rigid slip over the flexibilities [MPa/mm] (the left side of thesis Eq. 3.4/3.6):
/// `kx = cx/L1 − cs y/L3`, `ky = cy/L2 − cs x/L3` (grid x; CONTACT's spin sign, [`RigidSlip`]).
/// With Kalker's single flexibility ([`LocalContact::single_flexibility`]) every component is
/// divided by the same L of this sample's creepages.
/// With the modified FASTSIM's slope reduction ([`LocalContact::slope`]) the flexibilities are
/// divided by its factor k.
pub fn slip_rates(s: &Sample, local: &LocalContact) -> RigidSlip {
    let (l1, l2, l3) = flexibilities(s, local);
    RigidSlip::new(s.cx, s.cy, s.cs).over_flexibilities(l1, l2, l3)
}

/// The flexibilities L1, L2, L3 [mm³/N] the brush marches with at this sample: Kalker's three,
/// or the single one, divided by the slope reduction's factor k (k = 1 without one).
pub fn flexibilities(s: &Sample, local: &LocalContact) -> (f64, f64, f64) {
    let c = (s.cx, s.cy, s.cs);
    let (l1, l2, l3) = match local.single_flexibility {
        None => (local.flex.l1_mm3_n, local.flex.l2_mm3_n, local.flex.l3_mm3_n),
        Some(c_mm) => {
            let l = local.flex.single_mm3_n(c, c_mm);
            (l, l, l)
        }
    };
    // k = 1 without a slope reduction: l / 1 is l exactly.
    let k = local.slope.map_or(1.0, |r| r.factor(c, s.mu));
    (l1 / k, l2 / k, l3 / k)
}

/// [`slip_rates`] of creepages (cx, cy, cs [1/mm]).
pub fn rates(cx: f64, cy: f64, cs_per_mm: f64, flex: &Flexibilities) -> RigidSlip {
    RigidSlip::new(cx, cy, cs_per_mm).over_flexibilities(flex.l1_mm3_n, flex.l2_mm3_n, flex.l3_mm3_n)
}

/// How a solver integrates the slip rate over one element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Integration {
    /// Rate at the element centre times dx (the UBA's source term, Eq. 3.9–3.10).
    Centre,
    /// Exact integral over [x − dx, x] (FASTSIM, Eq. 2.34).
    Exact,
    /// CONTACT's FASTSIM: the rate at the element centre, its spin term taken dx/6 upstream
    /// (CONTACT's FACPHI = 1/6 of DQ = DX, `set_tang_rhs` in m_sdis.f90), times dx.
    SpinUpstream,
}

impl Integration {
    #[inline]
    fn increment(self, rates: &RigidSlip, x: f64, y: f64, dx: f64) -> (f64, f64) {
        match self {
            Integration::Centre => {
                let (kx, ky) = rates.at(x, y);
                (kx * dx, ky * dx)
            }
            Integration::Exact => rates.between(x - dx, x, y),
            Integration::SpinUpstream => {
                let (kx, ky) = rates.at(x - dx / 6.0, y);
                (kx * dx, ky * dx)
            }
        }
    }
}

/// The traction upstream of a row's first loaded element at column i, row j.
#[inline]
pub fn ghost(grid: &Grid, planform: &Planform, edge: LeadingEdge, rates: &RigidSlip, i: usize, j: usize) -> (f64, f64) {
    match edge {
        LeadingEdge::Grid => (0.0, 0.0),
        LeadingEdge::Exact => {
            let x = grid.x_mm[i];
            let x_le = planform.leading_edge_mm[j].clamp(x - grid.dx_mm, x);
            rates.between(x_le, x - grid.dx_mm, grid.y_mm[j])
        }
    }
}

/// Traction field on the grid [MPa], flat order.
#[derive(Debug, Clone, PartialEq)]
pub struct Tractions {
    pub tx: Vec<f64>,
    pub ty: Vec<f64>,
}

impl Tractions {
    pub fn zero(n: usize) -> Self {
        Tractions { tx: vec![0.0; n], ty: vec![0.0; n] }
    }

    /// Per element (flat order) whether it slips: its traction on the bound μ p
    /// ([`crate::physics::bound::on_bound`]), `pressure_mpa` the planform's.
    pub fn slipping(&self, pressure_mpa: &[f64], mu: f64) -> Vec<bool> {
        let on = |k: usize| crate::physics::bound::on_bound(self.tx[k], self.ty[k], mu * pressure_mpa[k]);
        (0..self.tx.len()).map(on).collect()
    }

    /// The field view of these tractions on the planform's pressure.
    pub fn view<'a>(&'a self, grid: &'a Grid, planform: &'a Planform) -> FieldView<'a> {
        FieldView {
            grid,
            pressure_mpa: &planform.pressure_mpa,
            tx_mpa: &self.tx,
            ty_mpa: &self.ty,
            state: None,
            temperature_c: None,
        }
    }

    /// Σ τx, Σ τy (one running sum each, flat order) and the moment sum [`moment_sum`].
    pub fn sums(&self, grid: &Grid) -> (f64, f64, f64) {
        (self.tx.iter().sum(), self.ty.iter().sum(), moment_sum(grid, &self.tx, &self.ty))
    }
}

/// A brush model's solve: the coefficients from the traction sums over the planform, the spin
/// moment from the moment sum [`moment_sum`] scaled the same way (`FN Σ m / Σ p`, so that it is
/// consistent with f = Σ τ / Σ p),
/// and the adhesion and slip counts (the extra columns `n_adhesion, n_slip`).
pub fn step(planform: &Planform, (sum_tx, sum_ty, moment): (f64, f64, f64), n_loaded: usize, n_slip: usize) -> Step {
    let (fx, fy) = planform.coefficients(sum_tx, sum_ty);
    let mz_nmm =
        if planform.pressure_sum_mpa > 0.0 { planform.ellipse.fn_n * moment / planform.pressure_sum_mpa } else { 0.0 };
    Step {
        fx_over_fn: fx,
        fy_over_fn: fy,
        mz_nmm,
        extra: vec![(n_loaded - n_slip) as f64, n_slip as f64],
        termination: Termination::Direct,
    }
}

/// The traction bound of one element of a march: what the element's unbounded traction becomes.
pub trait ElementBound {
    /// The friction coefficient carried into a row's first loaded element (the memory's state
    /// of fresh material).
    fn inflow_mu(&self) -> f64;
    /// The bounded traction of an element of pressure `p` > 0 and row gain `gain` from its
    /// unbounded traction (ux, uy), the coefficient `mu_up` its material carried in from
    /// upstream and `mu_start` a guess of its own (where an iteration starts; it changes no
    /// result beyond the iteration's tolerance): (τx, τy, whether it slips, the coefficient it
    /// carries downstream).
    fn apply(&self, u: (f64, f64), p: f64, gain: f64, mu: (f64, f64)) -> (f64, f64, bool, f64);
    /// Whether [`steady_march_with`] marches [`BOUND_GROUP`] rows in step through
    /// [`ElementBound::apply_lanes`] (a bound whose grouped form is faster than single ones).
    const GROUPED: bool = false;
    /// [`ElementBound::apply`] of L elements (lanes with `p ≤ 0` are the caller's to
    /// overwrite), the same bits per lane.
    #[inline(always)]
    fn apply_lanes<const L: usize>(&self, e: &Group<L>) -> [(f64, f64, bool, f64); L] {
        std::array::from_fn(|l| self.apply((e.ux[l], e.uy[l]), e.p[l], e.gain[l], (e.mu_up[l], e.mu_start[l])))
    }
}

/// Coulomb's bound μ p ([`project_to_bound`], thesis Eq. 2.29).
#[derive(Debug, Clone, Copy)]
pub struct Coulomb(pub f64);

impl ElementBound for Coulomb {
    #[inline(always)]
    fn inflow_mu(&self) -> f64 {
        self.0
    }

    #[inline(always)]
    fn apply(&self, (ux, uy): (f64, f64), p: f64, _gain: f64, _mu: (f64, f64)) -> (f64, f64, bool, f64) {
        let (px, py, slip) = project_to_bound(ux, uy, self.0 * p);
        (px, py, slip, self.0)
    }
}

/// A falling law's bound μ(s) p at the element's own slip velocity s [mm/s] (physics::friction).
/// The slip of the projected traction τ = g u/|u| per unit rolling distance is
/// `w = (L1 (ux − τx), L2 (uy − τy)) / (gain dx)` (the brush's displacement L τ against the rigid
/// slip over one element, Kalker 1990 Eq. 3.36), and its slip velocity `s = V |w|`
/// = `(|u| − g) V |(L1 ux, L2 uy)| / (|u| gain dx)`. g solves g = p μ(s(g)) ([`falling_bound`]);
/// with a memory μ = θ μ_up + (1 − θ) μ_s(s), θ of the time `dt_s` the material takes to cross
/// the element (backward Euler, [`crate::physics::Memory::update`]), μ_up carried along the row
/// from the leading edge (fresh material: the static value).
#[derive(Debug, Clone, Copy)]
pub struct Falling {
    /// The law and its memory over the time `dt_s` the material takes to cross one element
    /// (constants made once, [`LawKernel`]).
    pub kernel: LawKernel,
    /// The static coefficient μ_s(0): fresh material's.
    pub mu_static: f64,
    /// V L1 / dx and V L2 / dx [mm/s per MPa]: slip velocity per unit of u − τ.
    pub c_mm_s: (f64, f64),
    /// The memory's weight θ and the law's μ_s at s = 0 (the stick test's coefficient, made once).
    stick: (f64, f64),
}

impl Falling {
    /// The falling bound of the problem's law at this sample, the material moving `dq_mm` per
    /// element or step (dx for a steady march, C dx for a UBA sub-step); `None` with Coulomb.
    pub fn of(p: &Problem, at: &Sample, local: &LocalContact, dq_mm: f64) -> Option<Falling> {
        if !p.friction.is_falling() {
            return None;
        }
        let v_mm_s = at.speed_mm_s(p.rolling.v_mm_s);
        let (l1, l2, _) = flexibilities(at, local);
        let kernel = LawKernel::new(&p.friction, &p.memory, dq_mm / v_mm_s);
        Some(Falling {
            kernel,
            mu_static: p.friction.mu_static(),
            c_mm_s: (v_mm_s * l1 / dq_mm, v_mm_s * l2 / dq_mm),
            stick: kernel.stick(),
        })
    }

    /// μ at s = 0 from the constants made once: the same arithmetic as
    /// [`crate::physics::Memory::update`] at s = 0.
    #[inline(always)]
    fn mu_stick(&self, mu_up: f64) -> f64 {
        let (theta, mu_s) = self.stick;
        if theta == 0.0 {
            mu_s
        } else {
            theta * mu_up + (1.0 - theta) * mu_s
        }
    }
}

impl ElementBound for Falling {
    const GROUPED: bool = true;

    fn inflow_mu(&self) -> f64 {
        self.mu_static
    }

    #[inline(always)]
    fn apply_lanes<const L: usize>(&self, e: &Group<L>) -> [(f64, f64, bool, f64); L] {
        self.group_bounds(e)
    }

    /// The Newton on the element's bound starts from `mu_start` (the element's own coefficient
    /// of the previous sample or sub-step: the root moves little from one to the next).
    #[inline(always)]
    fn apply(&self, (ux, uy): (f64, f64), p: f64, gain: f64, (mu_up, mu_start): (f64, f64)) -> (f64, f64, bool, f64) {
        let mu_stick = self.mu_stick(mu_up);
        if within_bound(ux, uy, mu_stick * p) {
            return (ux, uy, false, mu_stick);
        }
        let (a, inv_p) = ((ux * ux + uy * uy).sqrt(), 1.0 / p);
        let inv = 1.0 / (a * gain);
        let (cx, cy) = (self.c_mm_s.0 * ux, self.c_mm_s.1 * uy);
        let c = (cx * cx + cy * cy).sqrt() * inv;
        let (g, _) = falling_bound(a, p, c, mu_start * p, |s| self.kernel.update_ratio(mu_up, s));
        let (px, py) = scale_with_reciprocal(ux, uy, (a, gain * inv), g);
        (px, py, true, g * inv_p)
    }
}

/// L elements' unbounded tractions, pressures (> 0), row gains and coefficients (carried in,
/// start) for [`ElementBound::apply_lanes`].
pub struct Group<const L: usize> {
    pub ux: [f64; L],
    pub uy: [f64; L],
    pub p: [f64; L],
    /// 1/p ([`Planform::inv_pressure_per_mpa`]).
    pub inv_p: [f64; L],
    pub gain: [f64; L],
    pub mu_up: [f64; L],
    pub mu_start: [f64; L],
}

impl<const L: usize> Group<L> {
    /// Every lane unloaded (p = 0), carrying `fresh` material's coefficient.
    #[inline(always)]
    pub fn unloaded(fresh: f64) -> Self {
        Group {
            ux: [0.0; L],
            uy: [0.0; L],
            p: [0.0; L],
            inv_p: [0.0; L],
            gain: [1.0; L],
            mu_up: [fresh; L],
            mu_start: [fresh; L],
        }
    }
}

impl Falling {
    /// [`ElementBound::apply_lanes`]: the stick test, then the slipping lanes' bounds in step
    /// ([`falling_bound_lanes`], one vectorised evaluation of the law for the lanes).
    #[inline(always)]
    fn group_bounds<const L: usize>(&self, e: &Group<L>) -> [(f64, f64, bool, f64); L] {
        // Every lane's arithmetic unconditionally and every choice a select (`&`, not `&&`), so
        // that the lanes compile to vector instructions; the selected values are those of
        // `within_bound` and `scale_with_reciprocal` to the bit.
        let (mut stick, mut a, mut c, mut g0) = ([0.0; L], [0.0; L], [0.0; L], [0.0; L]);
        let mut inv = [0.0; L];
        let mut slips = [false; L];
        for l in 0..L {
            let (ux, uy, p) = (e.ux[l], e.uy[l], e.p[l]);
            stick[l] = self.mu_stick(e.mu_up[l]);
            slips[l] = (p > 0.0) & !within_bound(ux, uy, stick[l] * p);
            // The reciprocal 1/(a gain) once, off the chain of dependent bounds (1/p made per load).
            a[l] = (ux * ux + uy * uy).sqrt();
            inv[l] = 1.0 / (a[l] * e.gain[l]);
            let (cx, cy) = (self.c_mm_s.0 * ux, self.c_mm_s.1 * uy);
            c[l] = (cx * cx + cy * cy).sqrt() * inv[l];
            g0[l] = e.mu_start[l] * p;
        }
        let g = if slips.iter().any(|s| *s) {
            falling_bound_lanes(
                (a, e.p, c),
                g0,
                slips,
                #[inline(always)]
                |s| self.kernel.update_ratio_lanes(e.mu_up, s),
            )
        } else {
            g0
        };
        let mut out = [(0.0, 0.0, false, 0.0); L];
        for l in 0..L {
            let (ux, uy) = (e.ux[l], e.uy[l]);
            let (px, py) = scale_with_reciprocal(ux, uy, (a[l], e.gain[l] * inv[l]), g[l]);
            let mu = g[l] * e.inv_p[l];
            out[l] = if slips[l] { (px, py, true, mu) } else { (ux, uy, false, stick[l]) };
        }
        out
    }
}

/// Steady rolling by marching each row from its leading edge, with the traction bound `μ p`
/// after every element (thesis 2.3.6 and Eq. 2.29), the slip of row j times `row_gain[j]`.
/// Returns the number of slipping elements.
pub fn steady_march(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    rates: &RigidSlip,
    how: (LeadingEdge, Integration),
    out: &mut Tractions,
) -> usize {
    steady_march_with(grid, local, &Coulomb(mu), rates, how, (out, &mut []))
}

/// [`steady_march`] with any element bound (a falling law's, [`Falling`]); each element's
/// coefficient into `mu_out` unless it is empty (its values before: the bound's starts).
pub fn steady_march_with<B: ElementBound>(
    grid: &Grid,
    local: &LocalContact,
    bound: &B,
    rates: &RigidSlip,
    how: (LeadingEdge, Integration),
    (out, mu_out): (&mut Tractions, &mut [f64]),
) -> usize {
    let row = |j| RowMarch { j, local, rates };
    let mut n_slip = 0;
    if B::GROUPED {
        return with_avx2(
            #[inline(always)]
            || {
                // A plain loop: an iterator adapter's fold would be compiled outside the AVX2
                // function (not inlined into it), and the rows' arithmetic with it.
                let mut n_slip = 0;
                let mut j0 = 0;
                while j0 < grid.my {
                    let mut rows = [row(j0); BOUND_GROUP];
                    let len = BOUND_GROUP.min(grid.my - j0);
                    for (r, slot) in rows.iter_mut().enumerate().take(len) {
                        *slot = row(j0 + r);
                    }
                    n_slip += march_row_group(grid, bound, how, &rows[..len], (&mut *out, &mut *mu_out));
                    j0 += BOUND_GROUP;
                }
                n_slip
            },
        );
    }
    for j in (0..grid.my).step_by(2) {
        n_slip += if j + 1 < grid.my {
            march_rows_with(grid, bound, how, [row(j), row(j + 1)], (&mut *out, &mut *mu_out)).iter().sum::<usize>()
        } else {
            march_rows_with(grid, bound, how, [row(j)], (&mut *out, &mut *mu_out))[0]
        };
    }
    n_slip
}

/// A row to march: its index, and the contact and slip rates it is marched with.
#[derive(Clone, Copy)]
pub struct RowMarch<'a> {
    pub j: usize,
    pub local: &'a LocalContact,
    pub rates: &'a RigidSlip,
}

/// [`steady_march`] of N rows (their elements of `out` are overwritten), element by element in
/// step so that their independent chains of bounds overlap; each row's arithmetic is the same as
/// marched alone. Returns the number of slipping elements per row.
pub fn march_rows<const N: usize>(
    grid: &Grid,
    mu: f64,
    how: (LeadingEdge, Integration),
    rows: [RowMarch; N],
    out: &mut Tractions,
) -> [usize; N] {
    march_rows_with(grid, &Coulomb(mu), how, rows, (out, &mut []))
}

/// [`march_rows`] with any element bound.
#[inline(always)]
fn march_rows_with<const N: usize, B: ElementBound>(
    grid: &Grid,
    bound: &B,
    how: (LeadingEdge, Integration),
    rows: [RowMarch; N],
    (out, mu_out): (&mut Tractions, &mut [f64]),
) -> [usize; N] {
    let mut n_slip = [0; N];
    // (τx, τy) of the last element, whether it was loaded, and the coefficient its material
    // carries, per row.
    let mut upstream = [(0.0, 0.0, false, bound.inflow_mu()); N];
    for i in 0..grid.mx {
        for (r, row) in rows.iter().enumerate() {
            let k = grid.index(i, row.j);
            let p = row.local.planform.pressure_mpa[k];
            let (tx, ty, loaded, mu_up) = upstream[r];
            if p <= 0.0 {
                out.tx[k] = 0.0;
                out.ty[k] = 0.0;
                upstream[r] = (tx, ty, false, bound.inflow_mu());
                continue;
            }
            let (ux, uy) = unbounded(grid, row.local, row.rates, how, (i, row.j), loaded.then_some((tx, ty)));
            // The element's coefficient of the previous solve where there is one (a start).
            let mu_start = if mu_out.is_empty() { mu_up } else { mu_out[k] };
            let (px, py, slip, mu) = bound.apply((ux, uy), p, row.local.row_gain[row.j], (mu_up, mu_start));
            out.tx[k] = px;
            out.ty[k] = py;
            n_slip[r] += slip as usize;
            upstream[r] = (px, py, true, mu);
            if !mu_out.is_empty() {
                mu_out[k] = mu;
            }
        }
    }
    n_slip
}

/// Falling bounds solved in step ([`ElementBound::apply_lanes`]): three vector registers of
/// four lanes, so that their Newtons overlap, the rows' chains of dependent bounds of a grouped
/// march (each element waits for its upstream neighbour's) and a UBA step's independent elements
/// alike (benches/solvers.rs `falling_friction`).
pub const BOUND_GROUP: usize = 12;

/// [`march_rows_with`] of up to [`BOUND_GROUP`] rows through [`ElementBound::apply_lanes`]: the
/// rows' elements of one column as the lanes (missing rows as unloaded lanes). Returns the number of
/// slipping elements.
#[inline(always)]
fn march_row_group<B: ElementBound>(
    grid: &Grid,
    bound: &B,
    how: (LeadingEdge, Integration),
    rows: &[RowMarch],
    (out, mu_out): (&mut Tractions, &mut [f64]),
) -> usize {
    let mut n_slip = 0;
    let fresh = bound.inflow_mu();
    let mut upstream = [(0.0, 0.0, false, fresh); BOUND_GROUP];
    for i in 0..grid.mx {
        let mut e = Group::<BOUND_GROUP>::unloaded(fresh);
        for (r, row) in rows.iter().enumerate() {
            let k = grid.index(i, row.j);
            let p = row.local.planform.pressure_mpa[k];
            if p <= 0.0 {
                continue;
            }
            let (tx, ty, loaded, mu_up) = upstream[r];
            (e.ux[r], e.uy[r]) = unbounded(grid, row.local, row.rates, how, (i, row.j), loaded.then_some((tx, ty)));
            (e.p[r], e.gain[r], e.mu_up[r]) = (p, row.local.row_gain[row.j], mu_up);
            e.inv_p[r] = row.local.planform.inv_pressure_per_mpa[k];
            // The element's coefficient of the previous solve where there is one (a start).
            e.mu_start[r] = if mu_out.is_empty() { mu_up } else { mu_out[k] };
        }
        let bounded = bound.apply_lanes(&e);
        for (r, row) in rows.iter().enumerate() {
            let k = grid.index(i, row.j);
            if e.p[r] <= 0.0 {
                (out.tx[k], out.ty[k]) = (0.0, 0.0);
                upstream[r] = (upstream[r].0, upstream[r].1, false, fresh);
                continue;
            }
            let (px, py, slip, mu) = bounded[r];
            (out.tx[k], out.ty[k]) = (px, py);
            n_slip += usize::from(slip);
            upstream[r] = (px, py, true, mu);
            if !mu_out.is_empty() {
                mu_out[k] = mu;
            }
        }
    }
    n_slip
}

/// Whether the first loaded element of row j slips in [`march_rows`] (without marching the row).
pub fn leading_slips(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    rates: &RigidSlip,
    how: (LeadingEdge, Integration),
    j: usize,
) -> bool {
    let pressure = &local.planform.pressure_mpa;
    (0..grid.mx).find(|&i| pressure[grid.index(i, j)] > 0.0).is_some_and(|i| {
        let (ux, uy) = unbounded(grid, local, rates, how, (i, j), None);
        !within_bound(ux, uy, mu * pressure[grid.index(i, j)])
    })
}

/// The traction of loaded element (i, j) before the bound: the upstream element's traction (or,
/// at the start of a loaded run, the inflow) plus the element's slip times the row's gain.
#[inline(always)]
fn unbounded(
    grid: &Grid,
    local: &LocalContact,
    rates: &RigidSlip,
    (edge, integration): (LeadingEdge, Integration),
    (i, j): (usize, usize),
    upstream: Option<(f64, f64)>,
) -> (f64, f64) {
    let gain = local.row_gain[j];
    let (tx, ty) = upstream.unwrap_or_else(|| {
        let (gx, gy) = ghost(grid, &local.planform, edge, rates, i, j);
        (gain * gx, gain * gy)
    });
    let (dtx, dty) = integration.increment(rates, grid.x_mm[i], grid.y_mm[j], grid.dx_mm);
    (tx + gain * dtx, ty + gain * dty)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::{FallingTerms, FrictionLaw, Memory};

    /// Four elements through [`ElementBound::apply_lanes`] give what [`ElementBound::apply`] gives each
    /// of them, bit for bit (one sticking, three slipping with different iteration counts), for
    /// every falling law with and without memory; and a slipping element's bound is the fixed
    /// point g = p μ(s(g)).
    #[test]
    fn four_elements_are_four_bounds() {
        let t = |fkin, f1, s1, f2, s2| FallingTerms { fkin, f1, sabsh1_mm_s: s1, f2, sabsh2_mm_s: s2 };
        let laws = [
            FrictionLaw::Exponential(t(0.25, 0.2, 600.0, 0.0, 0.0)),
            FrictionLaw::Linear(t(0.2, 0.25, 800.0, 0.05, 100.0)),
            FrictionLaw::Rational(t(0.22, 0.15, 400.0, 0.08, 2500.0)),
        ];
        let e = Group::<4> {
            ux: [100.0, 900.0, 2000.0, -700.0],
            uy: [50.0, 10.0, -300.0, 400.0],
            p: [1200.0, 1500.0, 1800.0, 900.0],
            inv_p: [1.0 / 1200.0, 1.0 / 1500.0, 1.0 / 1800.0, 1.0 / 900.0],
            gain: [1.0, 1.0, 0.9, 1.1],
            mu_up: [0.45, 0.4, 0.3, 0.45],
            mu_start: [0.45, 0.41, 0.1, 0.35],
        };
        for law in laws {
            for memory in [Memory::NONE, Memory { memory_mm: 0.01, s0_mm_s: 10.0 }] {
                let kernel = LawKernel::new(&law, &memory, 2.6e-5);
                let bound =
                    Falling { kernel, mu_static: law.mu_static(), c_mm_s: (3.0e3, 2.8e3), stick: kernel.stick() };
                let four = bound.apply_lanes(&e);
                for (l, four) in four.iter().enumerate() {
                    let one = bound.apply((e.ux[l], e.uy[l]), e.p[l], e.gain[l], (e.mu_up[l], e.mu_start[l]));
                    assert_eq!(*four, one, "{law:?} {memory:?} lane {l}");
                    assert_eq!(one.2, l > 0, "lane {l} slips");
                }
                let (tx, ty, _, mu) = four[2];
                let (a, g) = (e.ux[2].hypot(e.uy[2]), tx.hypot(ty));
                let (cx, cy) = (3.0e3 * e.ux[2], 2.8e3 * e.uy[2]);
                let s = cx.hypot(cy) / (a * e.gain[2]) * (a - g);
                let (want, _) = memory.update_and_slope(&law, e.mu_up[2], 2.6e-5, s);
                assert!((mu - want).abs() < 1e-12, "{law:?} {memory:?}: {mu} vs {want}");
            }
        }
    }
}
