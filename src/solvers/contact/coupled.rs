//! Dissimilar bodies (Kalker's difference parameter K ≠ 0): the exact solver's outer iteration
//! between the normal and the tangential problem (Kalker 1990 sec. 5.3; CONTACT's
//! Panagiotopoulos process, `m_scontc.f90` `panprc`). A pressure displaces the surfaces
//! tangentially, `u_tz = A_tz pn`, which the tangential problem takes as a slip
//! `u'_tz − u_tz` (shifts: `A_tz (pn' − pn)`, pn' the pressure of the previous case;
//! transient rolling: `A_tz,s pn' − A_tz pn` with the kernel at the material's previous position;
//! steady rolling: `−(A_tz − A_tz,s) pn`); the tangential traction displaces them normally,
//! `u_n = A_zt p_t`, which the normal problem adds to the undeformed distance. Each outer
//! iteration solves the normal problem with the last traction, then the tangential one with the
//! new pressure, until rms of the change of (pn, px, py) falls to [`OUTER_FACTOR`] times the
//! tolerance times rms(pn, px, py), at most `[contact_solver] max_outer` times.

use super::coupling::Coupling;
use super::ContactError;

/// The outer iteration stops at this many times the tangential solves' own tolerance, as CONTACT
/// stops it at 5 EPS (`panprc`): each solve leaves an error of the order of its tolerance, which
/// an outer change cannot go below.
pub const OUTER_FACTOR: f64 = 5.0;

/// The tolerance of an outer iteration's tangential solve: the falling-friction fixed point's
/// adaptive rule ([`super::veldep::adaptive_tolerance`]: 1e-2 × the smallest relative change of
/// the iterates so far, never below `tol`) at most [`FIRST_INNER_TOLERANCE`], that the first
/// solve takes: the early iterates are far from the fixed point by more than a tight solve's
/// error; the iteration ends only on a solve at `tol`, so that its fixed point and stop are those
/// of solves at `tol` throughout.
pub fn inner_tolerance(tol: f64, relative_change: Option<f64>) -> f64 {
    super::veldep::adaptive_tolerance(tol, relative_change, FIRST_INNER_TOLERANCE)
}

/// The tolerance of an outer iteration's first tangential solve.
pub const FIRST_INNER_TOLERANCE: f64 = 1e-3;

/// Which kind of solve the slip is made for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Steady rolling (the solve rolls the steady distance).
    Steady,
    /// A transient rolling step after the previous pressure.
    Rolling,
    /// A shift without rolling after the previous pressure.
    Shift,
}

/// The coupling products of one grid and the pressure of the last solve.
pub struct Couplings {
    now: Coupling,
    /// The kernel at the material's previous position after a transient step (rolling only).
    rolled: Option<Coupling>,
    /// The kernel at the previous position of the steady solve's step (rolling only).
    steady: Option<Coupling>,
    /// The pressure of the last solve [MPa] (the solver's frame); zero from rest.
    pub previous_pn: Vec<f64>,
    /// The most outer iterations per solve (CONTACT's MAXOUT).
    pub max_outer: usize,
    ux: Vec<f64>,
    uy: Vec<f64>,
    vx: Vec<f64>,
    vy: Vec<f64>,
}

/// The grid, material and motion the couplings are built for.
pub struct Setup {
    pub mx: usize,
    pub my: usize,
    pub dx_mm: f64,
    pub dy_mm: f64,
    pub g_mpa: f64,
    pub k: f64,
    /// Rolling: the unit vector the material moves along (solver frame) and the distances of a
    /// transient step and of the steady solve [mm]; `None`: shifts.
    pub rolling: Option<([f64; 2], f64, f64)>,
    pub max_outer: usize,
}

impl Couplings {
    pub fn new(s: &Setup) -> Result<Couplings, ContactError> {
        let make = |offset: [f64; 2]| Coupling::new((s.mx, s.my), (s.dx_mm, s.dy_mm), (s.g_mpa, s.k), offset);
        let at = |t: [f64; 2], d: f64| [d * t[0], d * t[1]];
        let (rolled, steady) = match s.rolling {
            Some((t, dq, dq_steady)) => (Some(make(at(t, dq))?), Some(make(at(t, dq_steady))?)),
            None => (None, None),
        };
        let n = s.mx * s.my;
        Ok(Couplings {
            now: make([0.0, 0.0])?,
            rolled,
            steady,
            previous_pn: vec![0.0; n],
            max_outer: s.max_outer,
            ux: vec![0.0; n],
            uy: vec![0.0; n],
            vx: vec![0.0; n],
            vy: vec![0.0; n],
        })
    }

    /// The slip `u'_tz − u_tz` [mm] of the pressure `pn` [MPa] for a solve of `kind`.
    pub fn slip(&mut self, kind: Kind, pn: &[f64]) -> Result<(&[f64], &[f64]), ContactError> {
        self.now.of_pressure(pn, &mut self.ux, &mut self.uy)?;
        let (before, of) = match kind {
            Kind::Steady => (self.steady.as_mut(), pn),
            Kind::Rolling => (self.rolled.as_mut(), self.previous_pn.as_slice()),
            Kind::Shift => (Some(&mut self.now), self.previous_pn.as_slice()),
        };
        let before = before.ok_or(ContactError::OutOfRange {
            name: "a rolling solve of a coupling built for shifts",
            value: 0.0,
            requirement: "rolling",
        })?;
        before.of_pressure(of, &mut self.vx, &mut self.vy)?;
        for k in 0..self.ux.len() {
            self.vx[k] -= self.ux[k];
            self.vy[k] -= self.uy[k];
        }
        Ok((&self.vx, &self.vy))
    }

    /// The normal displacement `A_zt p_t` [mm] of the traction `(px, py)` [MPa].
    pub fn normal_of(&mut self, px: &[f64], py: &[f64]) -> Result<Vec<f64>, ContactError> {
        let mut un = vec![0.0; px.len()];
        self.now.of_traction(px, py, &mut un)?;
        Ok(un)
    }
}

/// The traction the next normal solve takes: the last iterate, from the third on moved along
/// its last change by Aitken's Δ² for a linear fixed-point iteration, `t + λ/(1 − λ) Δt` with
/// `λ = Δt·Δt' / Δt'·Δt'` the contraction of the last two changes (kept in [0, 0.8]; Irons &
/// Tuck 1969). The fixed point is unchanged (at it Δt = 0); each tangential solve stays exact,
/// only the normal problem's input is extrapolated.
#[derive(Default)]
pub struct Extrapolation {
    /// The last iterate (px then py) and the change that led to it.
    last: Option<(Vec<f64>, Option<Vec<f64>>)>,
}

impl Extrapolation {
    pub fn next(&mut self, px: &[f64], py: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let t: Vec<f64> = px.iter().chain(py).copied().collect();
        let delta = self.last.as_ref().map(|(prev, _)| t.iter().zip(prev).map(|(a, b)| a - b).collect::<Vec<f64>>());
        let lambda = match (&delta, self.last.as_ref().and_then(|(_, d)| d.as_ref())) {
            (Some(d), Some(d_prev)) => {
                let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
                let den = dot(d_prev, d_prev);
                if den > 0.0 {
                    (dot(d, d_prev) / den).clamp(0.0, 0.8)
                } else {
                    0.0
                }
            }
            _ => 0.0,
        };
        let out: Vec<f64> = match &delta {
            Some(d) if lambda > 0.0 => t.iter().zip(d).map(|(v, dv)| v + lambda / (1.0 - lambda) * dv).collect(),
            _ => t.clone(),
        };
        self.last = Some((t, delta));
        let n = px.len();
        (out[..n].to_vec(), out[n..].to_vec())
    }
}

/// rms of the change from `before` to `now` of the three traction components over the grid,
/// and rms of `now` (CONTACT's `gf3_rms` of `panprc`; the element count cancels in their ratio).
pub fn change(before: [&[f64]; 3], now: [&[f64]; 3]) -> (f64, f64) {
    let (mut d, mut s) = (0.0, 0.0);
    for c in 0..3 {
        for (a, b) in before[c].iter().zip(now[c]) {
            d += (b - a) * (b - a);
            s += b * b;
        }
    }
    (d.sqrt(), s.sqrt())
}
