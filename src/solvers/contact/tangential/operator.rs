//! The operators of the tangential problem, built once per grid from the unshifted kernel `A` and
//! the kernel `A_s` shifted by the rolling distance (Kalker 1990, eq. 5.40): the FFT products
//! (`A`, `A_s`, the steady operator `A - A_s`, `A` in single precision and the preconditioner),
//! the coefficients of `A` and `A - A_s` for the incremental slip update of Gauss–Seidel, and the
//! contact spans of the rows that update visits.

use super::super::convolution::Convolver;
use super::super::influence::Kernel;
use super::super::ContactError;
use super::element::Diag;
use std::sync::{Arc, Mutex};

/// Coefficients of one operator in kernel storage (transient: `A`; steady: `A - A_s`), with
/// its diagonal, for the incremental slip update.
#[derive(Clone)]
pub(super) struct Operator {
    xx: Vec<f64>,
    xy: Vec<f64>,
    yy: Vec<f64>,
    /// Diagonal `(D_xx, D_yy)` at offset 0.
    pub diag: Diag,
    /// Whether the update runs in its AVX2 + FMA build (the CPU has both).
    avx2: bool,
}

impl Operator {
    fn from_kernel(k: &Kernel, avx2: bool) -> Operator {
        let c = k.index(0, 0);
        let diag = Diag { xx: k.xx[c], yy: k.yy[c] };
        Operator { xx: k.xx.clone(), xy: k.xy.clone(), yy: k.yy.clone(), diag, avx2 }
    }

    /// Applies the slip change caused by a traction change `dp` at element `k` to all contact
    /// rows: `s_m -= K(m - k) dp`.
    #[inline(always)]
    pub(super) fn update_slip(&self, spans: &Spans, sx: &mut [f64], sy: &mut [f64], k: usize, dp: (f64, f64)) {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: the CPU supports AVX2 and FMA (checked when the operator was built).
            unsafe { update_slip_avx2(self, spans, sx, sy, k, dp) };
            return;
        }
        update_slip_generic(self, spans, sx, sy, k, dp)
    }
}

/// Contact spans per grid row, the part of each row the slip update visits.
pub(super) struct Spans {
    mx: usize,
    my: usize,
    nkx: usize,
    /// Rows with contact: `(j, lo, hi)`, elements `lo..hi` of row `j` (covers all contact elements).
    rows: Vec<(usize, usize, usize)>,
}

impl Spans {
    /// The spans of the elements with `pn > 0` on an `mx x my` grid.
    pub(super) fn new(mx: usize, my: usize, pn: &[f64]) -> Spans {
        let mut rows = Vec::new();
        for j in 0..my {
            let row = &pn[j * mx..(j + 1) * mx];
            if let (Some(lo), Some(hi)) = (row.iter().position(|&v| v > 0.0), row.iter().rposition(|&v| v > 0.0)) {
                rows.push((j, lo, hi + 1));
            }
        }
        Spans { mx, my, nkx: 2 * mx - 1, rows }
    }
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

/// [`Operator::update_slip`], portable build.
#[inline(always)]
fn update_slip_generic(op: &Operator, sp: &Spans, sx: &mut [f64], sy: &mut [f64], k: usize, dp: (f64, f64)) {
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
unsafe fn update_slip_avx2(op: &Operator, sp: &Spans, sx: &mut [f64], sy: &mut [f64], k: usize, dp: (f64, f64)) {
    update_slip_generic(op, sp, sx, sy, k, dp)
}

/// Everything built from the kernels, once per grid: the FFT products and the coefficient
/// operators. Independent of the load.
#[derive(Clone)]
pub(super) struct Plans {
    /// `A`.
    pub conv0: Convolver,
    /// `A` in single precision, for the CG's search directions.
    pub conv0_f32: Convolver,
    /// `A_s`, the kernel shifted by the rolling distance.
    pub convs: Convolver,
    /// The steady rolling operator `A - A_s`.
    pub convd: Convolver,
    /// The FFT preconditioner (inverse of `A` periodised at twice the grid).
    pub prec: Convolver,
    /// Coefficients of `A` (transient steps).
    pub transient: Operator,
    /// Coefficients of `A - A_s` (steady rolling).
    pub steady: Operator,
}

/// Plans kept for the process with the kernels they were built of (the newest last): the scenes
/// of one deck run in one process (`creepbench simulate SCENE...`) and the cases of one scene
/// often share their grid and kernels, whose plans are then copied, not transformed again.
static KEPT: Mutex<Vec<Arc<(Kernel, Kernel, Plans)>>> = Mutex::new(Vec::new());

/// How many plans [`KEPT`] holds (a few MB each on CONTACT's grids).
const KEPT_PLANS: usize = 2;

/// The largest grid whose plans are kept (elements): a kept plan is copied for each solver, so
/// that a large grid's would hold its memory twice (a dozen arrays of four times the grid), where
/// building it is a small part of the solve.
const KEPT_MAX_ELEMENTS: usize = 1 << 16;

/// Whether two kernels are the same bit for bit (equal inputs, equal plans).
fn same_bits(a: &Kernel, b: &Kernel) -> bool {
    let bits = |x: &[f64], y: &[f64]| x.len() == y.len() && x.iter().zip(y).all(|(u, v)| u.to_bits() == v.to_bits());
    (a.mx, a.my) == (b.mx, b.my)
        && [a.dx_mm, a.dy_mm, a.shift_mm].map(f64::to_bits) == [b.dx_mm, b.dy_mm, b.shift_mm].map(f64::to_bits)
        && bits(&a.zz, &b.zz)
        && bits(&a.xx, &b.xx)
        && bits(&a.yy, &b.yy)
        && bits(&a.xy, &b.xy)
}

impl Plans {
    /// [`Plans::new`] of `k0` and `ks`, a copy of the kept plans where they were built of the
    /// same kernels (the same numbers as built afresh), else built and kept.
    pub(super) fn of(k0: &Kernel, ks: &Kernel) -> Result<Plans, ContactError> {
        if k0.mx * k0.my > KEPT_MAX_ELEMENTS {
            return Plans::new(k0, ks);
        }
        let kept = KEPT
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .iter()
            .rev()
            .find(|e| same_bits(&e.0, k0) && same_bits(&e.1, ks))
            .cloned();
        if let Some(e) = kept {
            return Ok(e.2.clone());
        }
        let plans = Plans::new(k0, ks)?;
        let mut kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
        if kept.len() == KEPT_PLANS {
            kept.remove(0);
        }
        kept.push(Arc::new((k0.clone(), ks.clone(), plans.clone())));
        Ok(plans)
    }

    /// The plans for the unshifted kernel `k0` and the shifted kernel `ks`.
    fn new(k0: &Kernel, ks: &Kernel) -> Result<Plans, ContactError> {
        #[cfg(target_arch = "x86_64")]
        let avx2 = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
        #[cfg(not(target_arch = "x86_64"))]
        let avx2 = false;
        let transient = Operator::from_kernel(k0, avx2);
        let kd = k0.difference(ks)?;
        let steady = Operator::from_kernel(&kd, avx2);
        // Without a shift (shifts without rolling) the steady operator A − A_s vanishes, unused.
        let steady_diag = if ks.shift_mm > 0.0 { vec![steady.diag.xx, steady.diag.yy] } else { Vec::new() };
        for d in [transient.diag.xx, transient.diag.yy].into_iter().chain(steady_diag) {
            if d.is_nan() || d <= 0.0 {
                return Err(ContactError::OutOfRange {
                    name: "influence kernel diagonal",
                    value: d,
                    requirement: "> 0",
                });
            }
        }
        let (conv0, convs) = Convolver::tangential_pair(k0, ks)?;
        Ok(Plans {
            conv0_f32: conv0.to_single_precision(),
            convd: conv0.minus(&convs, &kd)?,
            conv0,
            prec: Convolver::inverse_of(k0)?,
            convs,
            transient,
            steady,
        })
    }
}
