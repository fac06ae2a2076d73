//! The UBA's flat pass: every element's upwind update (corrected Eq. 3.9–3.10) and traction
//! bound (Eq. 2.29) in one pass over the grid, with the traction sums and the moment sum taken in
//! the same pass in the four-lane order of [`crate::physics::lanes`]. Written once per element
//! ([`element`]) and, where the CPU has AVX, four elements per register ([`avx`]): the same IEEE
//! operations in the same order and no fused multiply-add, so both paths give identical bits.

use super::{Prepared, StepSums};
use crate::physics::bound::bound_factor;
use crate::physics::lanes::combine;
use crate::physics::moment::moment_term;

/// Old tractions (x, y) in, new tractions (x, y) out.
pub(super) type Io<'a> = (&'a [f64], &'a [f64], &'a mut [f64], &'a mut [f64]);

/// The pass: `k` = [C, C·dx·kx0, C·dx·dkx/dy, C·dx·ky0, C·dx·dky/dx]
/// ([`crate::physics::RigidSlip::affine`]). `GHOST`: rows start from a ghost inflow value (exact
/// leading edge), else from zero; `SPIN`: the source varies with x and y, else it is constant.
pub(super) fn step<const GHOST: bool, const SPIN: bool>(p: &Prepared, io: Io, k: [f64; 5]) -> StepSums {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU supports AVX (checked just above).
        return unsafe { avx::step::<GHOST, SPIN>(p, io, k) };
    }
    let mut sums = Lanes::default();
    let n = io.0.len();
    elements::<GHOST, SPIN>(p, io, k, 0..n, &mut sums);
    sums.finish()
}

/// [`element`] for each element of `range`: the new tractions into `nx`, `ny` and the sums.
#[inline(always)]
fn elements<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (ox, oy, nx, ny): Io,
    k: [f64; 5],
    range: std::ops::Range<usize>,
    sums: &mut Lanes,
) {
    for m in range {
        let (tx, ty, slips) = element::<GHOST, SPIN>(p, (ox, oy), k, m);
        (nx[m], ny[m]) = (tx, ty);
        sums.add(p, m, ox.len(), (tx, ty, slips));
    }
}

/// The new traction of element `m` and whether it lies on the bound:
/// `v = τ + C (τ_up − τ) + gain · C dx k`, `τ_up` the upstream element's old traction (or the
/// ghost inflow at a run's start), then `v min(1, g/|v|)`.
#[inline(always)]
fn element<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (ox, oy): (&[f64], &[f64]),
    k: [f64; 5],
    m: usize,
) -> (f64, f64, bool) {
    let (vx, vy) = unbounded::<GHOST, SPIN>(p, (ox, oy), k, m);
    let n2 = vx * vx + vy * vy;
    let g = p.bound[m];
    // Direction-keeping projection: scale = min(1, g/|v|); unloaded (g = 0) → 0.
    let scale = bound_factor(n2, g);
    (vx * scale, vy * scale, (n2 > g * g) & (g > 0.0))
}

/// The traction of element `m` before the bound: `τ + C (τ_up − τ) + gain · C dx k`.
#[inline(always)]
pub(super) fn unbounded<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (ox, oy): (&[f64], &[f64]),
    [c, sx0, sx1, sy0, sy1]: [f64; 5],
    m: usize,
) -> (f64, f64) {
    let (px, py) = if m > 0 { (ox[m - 1], oy[m - 1]) } else { (0.0, 0.0) };
    let (inx, iny) = if GHOST { (p.ghost_x[m], p.ghost_y[m]) } else { (0.0, 0.0) };
    let ux = p.upstream[m] * px + inx;
    let uy = p.upstream[m] * py + iny;
    let (srcx, srcy) = if SPIN { (sx0 + sx1 * p.y_mm[m], sy0 + sy1 * p.x_mm[m]) } else { (sx0, sy0) };
    let (srcx, srcy) = (p.gain[m] * srcx, p.gain[m] * srcy);
    let vx = ox[m] + c * (ux - ox[m]) + srcx;
    let vy = oy[m] + c * (uy - oy[m]) + srcy;
    (vx, vy)
}

/// The sums of a pass: lane `m mod 4` for the elements of whole groups of four, in order for the
/// last `n mod 4` (from −0.0, as `Iterator::sum`).
pub(super) struct Lanes {
    x: [f64; 4],
    y: [f64; 4],
    moment: [f64; 4],
    tail: [f64; 3],
    slips: usize,
}

impl Default for Lanes {
    fn default() -> Self {
        Lanes { x: [0.0; 4], y: [0.0; 4], moment: [0.0; 4], tail: [-0.0; 3], slips: 0 }
    }
}

impl Lanes {
    #[inline(always)]
    pub(super) fn add(&mut self, p: &Prepared, m: usize, n: usize, (tx, ty, slips): (f64, f64, bool)) {
        let term = moment_term(p.x_mm[m], p.y_mm[m], tx, ty);
        if m < n - n % 4 {
            let l = m % 4;
            self.x[l] += tx;
            self.y[l] += ty;
            self.moment[l] += term;
        } else {
            self.tail[0] += tx;
            self.tail[1] += ty;
            self.tail[2] += term;
        }
        self.slips += usize::from(slips);
    }

    pub(super) fn finish(self) -> StepSums {
        StepSums {
            n_slip: self.slips,
            sum_tx: combine(self.x, self.tail[0]),
            sum_ty: combine(self.y, self.tail[1]),
            moment: combine(self.moment, self.tail[2]),
        }
    }
}

#[cfg(target_arch = "x86_64")]
mod avx {
    use super::{elements, Io, Lanes, Prepared, StepSums};
    use std::arch::x86_64::*;

    /// [`super::step`] four elements per register; the last `n mod 4` elements through
    /// [`super::element`].
    #[target_feature(enable = "avx")]
    pub(super) unsafe fn step<const GHOST: bool, const SPIN: bool>(
        p: &Prepared,
        (ox, oy, nx, ny): Io,
        k: [f64; 5],
    ) -> StepSums {
        let n = ox.len();
        let body = n - n % 4;
        let mut sums = Lanes::default();
        if body > 0 {
            let arrays = [&p.upstream, &p.ghost_x, &p.ghost_y, &p.gain, &p.bound, &p.x_mm, &p.y_mm];
            assert!(oy.len() == n && nx.len() == n && ny.len() == n && arrays.iter().all(|a| a.len() >= n));
            // SAFETY: every array holds at least n elements (asserted above) and the groups read
            // elements 0..body, body <= n.
            unsafe { groups::<GHOST, SPIN>(p, (ox, oy, nx, ny), k, body, &mut sums) };
        }
        elements::<GHOST, SPIN>(p, (ox, oy, nx, ny), k, body..n, &mut sums);
        sums.finish()
    }

    /// The groups of four of elements `0..body` (`body` a multiple of 4): the update of
    /// [`super::element`] on four lanes, the lane sums carried in registers.
    #[target_feature(enable = "avx")]
    unsafe fn groups<const GHOST: bool, const SPIN: bool>(
        p: &Prepared,
        (ox, oy, nx, ny): Io,
        [c, sx0, sx1, sy0, sy1]: [f64; 5],
        body: usize,
        sums: &mut Lanes,
    ) {
        let ld = |v: &[f64], m: usize| _mm256_loadu_pd(v.as_ptr().add(m));
        let (zero, one) = (_mm256_setzero_pd(), _mm256_set1_pd(1.0));
        let c = _mm256_set1_pd(c);
        let (sx0, sx1, sy0, sy1) = (_mm256_set1_pd(sx0), _mm256_set1_pd(sx1), _mm256_set1_pd(sy0), _mm256_set1_pd(sy1));
        let mut acc_x = _mm256_loadu_pd(sums.x.as_ptr());
        let mut acc_y = _mm256_loadu_pd(sums.y.as_ptr());
        let mut acc_m = _mm256_loadu_pd(sums.moment.as_ptr());
        let mut slips = 0u32;
        // The previous group's old tractions: the upstream elements are the last of them and
        // the first three of this group (no element before the first). Shifted in registers,
        // not loaded from one element back, so that no load overlaps the store just made to
        // the other buffer at the same offset modulo 4096 (4K aliasing).
        let (mut last_x, mut last_y) = (zero, zero);
        let shift =
            |last: __m256d, cur: __m256d| _mm256_shuffle_pd(_mm256_permute2f128_pd(last, cur, 0x21), cur, 0b0101);
        for m in (0..body).step_by(4) {
            let (o_x, o_y) = (ld(ox, m), ld(oy, m));
            let (pr_x, pr_y) = (shift(last_x, o_x), shift(last_y, o_y));
            (last_x, last_y) = (o_x, o_y);
            let up = ld(&p.upstream, m);
            let (inx, iny) = if GHOST { (ld(&p.ghost_x, m), ld(&p.ghost_y, m)) } else { (zero, zero) };
            let ux = _mm256_add_pd(_mm256_mul_pd(up, pr_x), inx);
            let uy = _mm256_add_pd(_mm256_mul_pd(up, pr_y), iny);
            let (x, y) = (ld(&p.x_mm, m), ld(&p.y_mm, m));
            let (srcx, srcy) = if SPIN {
                (_mm256_add_pd(sx0, _mm256_mul_pd(sx1, y)), _mm256_add_pd(sy0, _mm256_mul_pd(sy1, x)))
            } else {
                (sx0, sy0)
            };
            let gain = ld(&p.gain, m);
            let (srcx, srcy) = (_mm256_mul_pd(gain, srcx), _mm256_mul_pd(gain, srcy));
            let vx = _mm256_add_pd(_mm256_add_pd(o_x, _mm256_mul_pd(c, _mm256_sub_pd(ux, o_x))), srcx);
            let vy = _mm256_add_pd(_mm256_add_pd(o_y, _mm256_mul_pd(c, _mm256_sub_pd(uy, o_y))), srcy);
            let n2 = _mm256_add_pd(_mm256_mul_pd(vx, vx), _mm256_mul_pd(vy, vy));
            let g = ld(&p.bound, m);
            // min(g/|v|, 1) as f64::min: a NaN quotient (0/0) gives the second operand, 1.
            let scale = _mm256_min_pd(_mm256_div_pd(g, _mm256_sqrt_pd(n2)), one);
            let (tx, ty) = (_mm256_mul_pd(vx, scale), _mm256_mul_pd(vy, scale));
            _mm256_storeu_pd(nx.as_mut_ptr().add(m), tx);
            _mm256_storeu_pd(ny.as_mut_ptr().add(m), ty);
            let on_bound =
                _mm256_and_pd(_mm256_cmp_pd(n2, _mm256_mul_pd(g, g), _CMP_GT_OQ), _mm256_cmp_pd(g, zero, _CMP_GT_OQ));
            slips += (_mm256_movemask_pd(on_bound) as u32).count_ones();
            acc_x = _mm256_add_pd(acc_x, tx);
            acc_y = _mm256_add_pd(acc_y, ty);
            // The moment term (−x) τy − y τx, added as acc − (x τy + y τx): the same value to the
            // bit, as (−a) − b = −(a + b) and acc + (−s) = acc − s in IEEE arithmetic.
            acc_m = _mm256_sub_pd(acc_m, _mm256_add_pd(_mm256_mul_pd(x, ty), _mm256_mul_pd(y, tx)));
        }
        _mm256_storeu_pd(sums.x.as_mut_ptr(), acc_x);
        _mm256_storeu_pd(sums.y.as_mut_ptr(), acc_y);
        _mm256_storeu_pd(sums.moment.as_mut_ptr(), acc_m);
        sums.slips += slips as usize;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::Grid;

    /// A prepared step on an 11 × 7 grid (77 elements: groups of four and a tail of one) with
    /// every kind of element: unloaded, run starts with ghost inflow, sticking and slipping.
    fn prepared() -> (Prepared, Vec<f64>, Vec<f64>) {
        let grid = Grid::new(11, 7, 1.0, 1.0);
        let n = grid.len();
        let wave = |k: usize, f: f64| ((k as f64) * f).sin();
        let p = Prepared {
            runs: Vec::new(),
            bound: (0..n).map(|k| if k % 11 < 2 || k % 13 == 0 { 0.0 } else { 1.0 + wave(k, 0.7).abs() }).collect(),
            upstream: (0..n).map(|k| f64::from(u8::from(k % 11 > 2))).collect(),
            x_mm: (0..n).map(|k| grid.x_mm[k % 11]).collect(),
            y_mm: (0..n).map(|k| grid.y_mm[k / 11]).collect(),
            gain: (0..n).map(|k| 1.0 + 0.1 * wave(k, 0.3)).collect(),
            ghost_x: (0..n).map(|k| if k % 11 == 2 { 0.3 * wave(k, 1.1) } else { 0.0 }).collect(),
            ghost_y: (0..n).map(|k| if k % 11 == 2 { -0.2 * wave(k, 0.9) } else { 0.0 }).collect(),
        };
        let ox = (0..n).map(|k| if p.bound[k] > 0.0 { 1.5 * wave(k, 0.37) } else { 0.0 }).collect();
        let oy = (0..n).map(|k| if p.bound[k] > 0.0 { -0.8 * wave(k, 0.53) } else { 0.0 }).collect();
        (p, ox, oy)
    }

    /// The pass of whichever path this CPU takes against [`element`] and the lane order written
    /// out by hand, for the four combinations of inflow and spin: identical bits.
    #[test]
    fn the_pass_equals_the_element_update_and_the_lane_order() {
        let (p, ox, oy) = prepared();
        let n = ox.len();
        let k = [0.7, 0.05, -0.02, 0.03, 0.04];
        let expect = |ghost: bool, spin: bool| {
            let mut sums = Lanes::default();
            let mut out = (vec![0.0; n], vec![0.0; n]);
            for m in 0..n {
                let r = match (ghost, spin) {
                    (false, false) => element::<false, false>(&p, (&ox, &oy), k, m),
                    (false, true) => element::<false, true>(&p, (&ox, &oy), k, m),
                    (true, false) => element::<true, false>(&p, (&ox, &oy), k, m),
                    (true, true) => element::<true, true>(&p, (&ox, &oy), k, m),
                };
                (out.0[m], out.1[m]) = (r.0, r.1);
                sums.add(&p, m, n, r);
            }
            (out, sums.finish())
        };
        for (ghost, spin) in [(false, false), (false, true), (true, false), (true, true)] {
            let (mut nx, mut ny) = (vec![0.0; n], vec![0.0; n]);
            let io = (ox.as_slice(), oy.as_slice(), nx.as_mut_slice(), ny.as_mut_slice());
            let got = match (ghost, spin) {
                (false, false) => step::<false, false>(&p, io, k),
                (false, true) => step::<false, true>(&p, io, k),
                (true, false) => step::<true, false>(&p, io, k),
                (true, true) => step::<true, true>(&p, io, k),
            };
            let ((ex, ey), sums) = expect(ghost, spin);
            assert_eq!((nx, ny), (ex, ey), "ghost {ghost}, spin {spin}");
            assert_eq!(got, sums, "ghost {ghost}, spin {spin}");
            assert!(got.n_slip > 0 && got.n_slip < n / 2, "{} of {n} on the bound", got.n_slip);
        }
        // Lane order by hand for the x sum: elements 0..76 by m mod 4, then element 76.
        let (mut nx, mut ny) = (vec![0.0; n], vec![0.0; n]);
        let got = step::<true, true>(&p, (&ox, &oy, &mut nx, &mut ny), k);
        let mut lanes = [0.0f64; 4];
        for m in 0..76 {
            lanes[m % 4] += nx[m];
        }
        assert_eq!(got.sum_tx, (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) + nx[76]);
    }
}
