//! The direct-summation path of [`Convolver`](super::convolution::Convolver) (Kalker 1990,
//! eq. 5.22: `u_(i,j) = sum_(I,J) A(i - I, j - J) p_(I,J)` over the active sources), compiled for
//! AVX2 where the CPU has it ([`with_avx2`]: the same IEEE operations in the same order, no fused
//! multiply-adds). The kernel arrays are laid out as the convolver keeps them: offset
//! `(i - I + mx - 1) + (j - J + my - 1) * nkx`, `nkx = 2 mx - 1`. Units: p in MPa, A in mm/MPa,
//! u in mm.
//!
//! A source's term that is a signed zero (a zero traction component, or a zero coupling `Axy`) is
//! left out: the sums start at +0 and an added ±0 changes no partial sum (x + ±0 = x for x ≠ 0,
//! +0 + ±0 = +0), so that the results are bit for bit those of the full sum.

use crate::simd::with_avx2;

/// Grid shape of a direct product: `mx × my` elements, kernel rows of `nkx = 2 mx - 1` offsets.
#[derive(Debug, Clone, Copy)]
pub(super) struct Shape {
    pub mx: usize,
    pub my: usize,
    pub nkx: usize,
}

impl Shape {
    /// Start of the kernel row seen by output row `j` from the source at grid index `k`.
    #[inline(always)]
    fn base(&self, k: usize, j: usize) -> usize {
        let (ii, jj) = (k % self.mx, k / self.mx);
        (j + self.my - 1 - jj) * self.nkx + (self.mx - 1 - ii)
    }
}

/// `u = Azz p` [mm] over the `active` sources of pressure `p_mpa` (`u` overwritten).
pub(super) fn normal(shape: Shape, kzz: &[f64], active: &[usize], p_mpa: &[f64], u_mm: &mut [f64]) {
    with_avx2(
        #[inline(always)]
        || {
            u_mm.fill(0.0);
            let mx = shape.mx;
            for &k in active {
                let pk = p_mpa[k];
                for j in 0..shape.my {
                    let base = shape.base(k, j);
                    axpy(&kzz[base..base + mx], pk, &mut u_mm[j * mx..(j + 1) * mx]);
                }
            }
        },
    )
}

/// Tangential coefficients of a direct product: `Axx`, `Ayy`, and `Axy` where any is nonzero
/// (`None`: the two directions uncoupled, as on a one-row grid, whose `Axy` is odd in y).
pub(super) struct Pair<'a> {
    pub kxx: &'a [f64],
    pub kyy: &'a [f64],
    pub kxy: Option<&'a [f64]>,
}

/// `ux = Axx px + Axy py`, `uy = Axy px + Ayy py` [mm] over the `active` sources of tractions
/// `px`, `py` [MPa] (`ux`, `uy` overwritten).
pub(super) fn tangential(
    shape: Shape,
    a: &Pair,
    active: &[usize],
    (px_mpa, py_mpa): (&[f64], &[f64]),
    (ux_mm, uy_mm): (&mut [f64], &mut [f64]),
) {
    with_avx2(
        #[inline(always)]
        || {
            ux_mm.fill(0.0);
            uy_mm.fill(0.0);
            let mx = shape.mx;
            for &k in active {
                let (sx, sy) = (px_mpa[k], py_mpa[k]);
                for j in 0..shape.my {
                    let base = shape.base(k, j);
                    let row = j * mx..(j + 1) * mx;
                    let (kxx, kyy) = (&a.kxx[base..base + mx], &a.kyy[base..base + mx]);
                    match a.kxy {
                        Some(kxy) => {
                            let kxy = &kxy[base..base + mx];
                            let (uxr, uyr) = (&mut ux_mm[row.clone()], &mut uy_mm[row]);
                            for i in 0..mx {
                                uxr[i] += kxx[i] * sx + kxy[i] * sy;
                                uyr[i] += kxy[i] * sx + kyy[i] * sy;
                            }
                        }
                        None => {
                            if sx != 0.0 {
                                axpy(kxx, sx, &mut ux_mm[row.clone()]);
                            }
                            if sy != 0.0 {
                                axpy(kyy, sy, &mut uy_mm[row]);
                            }
                        }
                    }
                }
            }
        },
    )
}

/// `u += k s` element by element.
#[inline(always)]
fn axpy(k: &[f64], s: f64, u: &mut [f64]) {
    for (uv, kv) in u.iter_mut().zip(k) {
        *uv += kv * s;
    }
}
