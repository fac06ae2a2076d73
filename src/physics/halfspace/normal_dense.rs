//! The normal problem on a kernel that is not symmetric (viscoelastic bodies in steady rolling,
//! [`super::visco`]: the pressure at an element acts differently up- and downstream), where the
//! conjugate gradients of [`super::normal`] need not converge: an active-set method with direct
//! solves. On the contact set `C` the pressure solves `A_CC p_C = δ − h_C` (δ the approach: given,
//! or found with `Σ p dx dy = FN`); elements of negative pressure leave `C`, then elements that
//! overlap (`h + A p − δ < 0`) enter it, until neither happens (Kalker 1990, sec. 5.3, the
//! contact-area iteration of NORM, each step solved exactly).

use super::influence::Kernel;
use super::ContactError;
use crate::simd::with_avx2;

/// Most changes of the contact set.
const MAX_SETS: usize = 500;
/// A kernel whose `A(d)` and `A(−d)` differ by more than this fraction of its largest coefficient
/// is not symmetric (an elastic kernel's differ by rounding, ~1e-16; a viscoelastic one's by its
/// memory, 1e-3 and more where the relaxation distance is within a few hundred grid lengths).
const ASYMMETRY: f64 = 1e-12;

/// The `zz` part of a kernel that is not symmetric, kept for direct solves.
pub(super) struct Dense {
    mx: usize,
    zz: Kernel,
}

impl Dense {
    /// The dense solver of `kernel`'s `zz`, or `None` when it is symmetric (`A(d) = A(−d)` for every
    /// offset `d` to [`ASYMMETRY`] of its largest coefficient, the rounding of an elastic kernel's
    /// evaluation: the conjugate gradients serve).
    pub(super) fn of(kernel: &Kernel) -> Option<Dense> {
        let (hx, hy) = (kernel.mx as isize - 1, kernel.my as isize - 1);
        let largest = kernel.zz.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let bound = ASYMMETRY * largest;
        let symmetric = (-hy..=hy).all(|dj| {
            (-hx..=hx).all(|di| (kernel.zz[kernel.index(di, dj)] - kernel.zz[kernel.index(-di, -dj)]).abs() <= bound)
        });
        (!symmetric).then(|| Dense { mx: kernel.mx, zz: kernel.clone() })
    }

    /// The position of flat element `k` in the kernel's rows of `2 mx − 1` offsets: `A[a][b]` between
    /// field `a` and source `b` is `zz[self.place(a) + self.centre() − self.place(b)]`.
    fn place(&self, k: usize) -> usize {
        (k / self.mx) * self.zz.nkx() + k % self.mx
    }

    /// The index of offset (0, 0) in the kernel.
    fn centre(&self) -> usize {
        self.zz.index(0, 0)
    }

    /// The row of `A` of field element `a` over the sources whose places ([`Dense::place`]) are `sources`.
    fn row<'a>(&'a self, a: usize, sources: &'a [usize]) -> impl Iterator<Item = f64> + 'a {
        let base = self.place(a) + self.centre();
        sources.iter().map(move |&s| self.zz.zz[base - s])
    }

    /// The pressure [MPa] for the undeformed distance `h_mm` with the total force `fn_n` [N] on
    /// elements of `area_mm2` (the approach found), or, without it, `h_mm` already `h − approach`;
    /// returns (pressure, contact-set changes, largest violation, converged).
    pub(super) fn solve(
        &self,
        h_mm: &[f64],
        force: Option<(f64, f64)>,
    ) -> Result<(Vec<f64>, usize, f64, bool), ContactError> {
        let n = h_mm.len();
        let hscale = h_mm.iter().fold(0.0f64, |m, h| m.max(h.abs())).max(f64::MIN_POSITIVE);
        // Start: every element with a force prescribed, the overlap for an approach.
        let mut set: Vec<bool> = match force {
            Some(_) => vec![true; n],
            None => h_mm.iter().map(|h| *h < 0.0).collect(),
        };
        let mut p = vec![0.0; n];
        for changes in 0..MAX_SETS {
            let idx: Vec<usize> = (0..n).filter(|&k| set[k]).collect();
            if idx.is_empty() {
                return Err(ContactError::NoContact);
            }
            let delta = self.on_set(&idx, h_mm, force, &mut p)?;
            let negative: Vec<usize> = idx.iter().copied().filter(|&k| p[k] < 0.0).collect();
            if !negative.is_empty() {
                negative.iter().for_each(|&k| set[k] = false);
                continue;
            }
            // Overlap outside the set, relative to the undeformed distance's scale.
            let tol = 1e-12 * hscale.max(delta.abs());
            let mut worst = 0.0f64;
            let places: Vec<usize> = idx.iter().map(|&b| self.place(b)).collect();
            for k in 0..n {
                if set[k] {
                    continue;
                }
                let e = h_mm[k] - delta + self.row(k, &places).zip(&idx).map(|(a, &b)| a * p[b]).sum::<f64>();
                if e < -tol {
                    set[k] = true;
                }
                worst = worst.max(-e);
            }
            if worst <= tol {
                return Ok((p, changes + 1, worst.max(0.0), true));
            }
        }
        Ok((p, MAX_SETS, f64::INFINITY, false))
    }

    /// The pressure on the set `idx` (zero elsewhere), written into `p`, and the approach δ.
    fn on_set(
        &self,
        idx: &[usize],
        h_mm: &[f64],
        force: Option<(f64, f64)>,
        p: &mut [f64],
    ) -> Result<f64, ContactError> {
        let m = idx.len();
        let places: Vec<usize> = idx.iter().map(|&c| self.place(c)).collect();
        let mut a: Vec<f64> = Vec::with_capacity(m * m);
        for &r in idx {
            a.extend(self.row(r, &places));
        }
        let lu = Lu::factor(&mut a, m).ok_or(ContactError::NonFinite("normal problem: singular influence matrix"))?;
        // p = v + δ u with A u = 1, A v = −h.
        let mut v: Vec<f64> = idx.iter().map(|&k| -h_mm[k]).collect();
        lu.solve(&a, &mut v);
        let delta = match force {
            Some((fn_n, area_mm2)) => {
                let mut u = vec![1.0; m];
                lu.solve(&a, &mut u);
                let (su, sv): (f64, f64) = (u.iter().sum(), v.iter().sum());
                let delta = (fn_n / area_mm2 - sv) / su;
                v.iter_mut().zip(&u).for_each(|(v, u)| *v += delta * u);
                delta
            }
            None => 0.0,
        };
        p.iter_mut().for_each(|x| *x = 0.0);
        for (&k, &val) in idx.iter().zip(&v) {
            if !val.is_finite() {
                return Err(ContactError::NonFinite("normal pressure"));
            }
            p[k] = val;
        }
        Ok(delta)
    }
}

/// LU factors with partial pivoting of an `m × m` row-major matrix, in place.
struct Lu {
    m: usize,
    pivot: Vec<usize>,
}

impl Lu {
    /// The factors of `a` (overwritten), or `None` if a pivot is zero or not finite; compiled for
    /// AVX2 where the CPU has it ([`with_avx2`]: the same operations in the same order, bit for bit
    /// the same factors).
    fn factor(a: &mut [f64], m: usize) -> Option<Lu> {
        with_avx2(
            #[inline(always)]
            || Lu::factor_in_place(a, m),
        )
    }

    /// [`Lu::factor`]'s elimination (Doolittle, partial pivoting by rows).
    #[inline(always)]
    fn factor_in_place(a: &mut [f64], m: usize) -> Option<Lu> {
        let mut pivot = vec![0; m];
        for c in 0..m {
            let r = (c..m).max_by(|&x, &y| a[x * m + c].abs().total_cmp(&a[y * m + c].abs()))?;
            if a[r * m + c] == 0.0 || !a[r * m + c].is_finite() {
                return None;
            }
            pivot[c] = r;
            if r != c {
                for j in 0..m {
                    a.swap(r * m + j, c * m + j);
                }
            }
            let d = a[c * m + c];
            let (upper, lower) = a.split_at_mut((c + 1) * m);
            let pivot_row = &upper[c * m + c + 1..(c + 1) * m];
            for row in lower.chunks_exact_mut(m) {
                let f = row[c] / d;
                row[c] = f;
                if f != 0.0 {
                    for (x, p) in row[c + 1..].iter_mut().zip(pivot_row) {
                        *x -= f * p;
                    }
                }
            }
        }
        Some(Lu { m, pivot })
    }

    /// Solve `A x = b` in place with the factors in `a`.
    fn solve(&self, a: &[f64], b: &mut [f64]) {
        let m = self.m;
        for c in 0..m {
            b.swap(c, self.pivot[c]);
        }
        for r in 0..m {
            let s: f64 = (0..r).map(|j| a[r * m + j] * b[j]).sum();
            b[r] -= s;
        }
        for r in (0..m).rev() {
            let s: f64 = (r + 1..m).map(|j| a[r * m + j] * b[j]).sum();
            b[r] = (b[r] - s) / a[r * m + r];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lu_solves_a_non_symmetric_system() {
        let mut a = vec![2.0, 1.0, 0.0, 4.0, 3.0, 1.0, 0.0, 5.0, 7.0];
        let x = [1.0, -2.0, 3.0];
        let b0: Vec<f64> = (0..3).map(|r| (0..3).map(|c| a[r * 3 + c] * x[c]).sum()).collect();
        let lu = Lu::factor(&mut a, 3).unwrap();
        let mut b = b0.clone();
        lu.solve(&a, &mut b);
        for (got, want) in b.iter().zip(x) {
            assert!((got - want).abs() < 1e-14, "{b:?}");
        }
    }
}
