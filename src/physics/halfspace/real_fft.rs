//! A real field's zero-padded 2-D convolution by real-input transforms (realfft): along x a
//! real-to-complex transform keeps the `nx/2 + 1` columns a real field's spectrum needs (the rest
//! are their conjugates), along y a complex transform of those columns alone; half the work of the
//! complex transforms of the same field (Press et al., "Numerical Recipes", 3rd ed., sec. 12.3).

use super::ContactError;
use realfft::{ComplexToReal, FftError, RealFftPlanner, RealToComplex};
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Plans and buffers for `nx x ny` real transforms (`nx` even).
#[derive(Clone)]
pub(super) struct RealFft2 {
    nx: usize,
    ny: usize,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    fwd_y: Arc<dyn Fft<f64>>,
    inv_y: Arc<dyn Fft<f64>>,
    /// One real row, `nx`.
    row: Vec<f64>,
    /// One row's half spectrum, `nx/2 + 1`.
    half: Vec<Complex<f64>>,
    /// The half spectrum, layout `[kx][ky]`, `(nx/2 + 1) ny`.
    cols: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl RealFft2 {
    /// The transforms of an `nx x ny` period.
    pub(super) fn new(nx: usize, ny: usize) -> RealFft2 {
        let mut real = RealFftPlanner::<f64>::new();
        let (r2c, c2r) = (real.plan_fft_forward(nx), real.plan_fft_inverse(nx));
        let mut complex = FftPlanner::<f64>::new();
        let (fwd_y, inv_y) = (complex.plan_fft_forward(ny), complex.plan_fft_inverse(ny));
        let scratch_len = [
            r2c.get_scratch_len(),
            c2r.get_scratch_len(),
            fwd_y.get_inplace_scratch_len(),
            inv_y.get_inplace_scratch_len(),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        let zero = Complex::new(0.0, 0.0);
        let nh = nx / 2 + 1;
        RealFft2 {
            nx,
            ny,
            r2c,
            c2r,
            fwd_y,
            inv_y,
            row: vec![0.0; nx],
            half: vec![zero; nh],
            cols: vec![zero; nh * ny],
            scratch: vec![zero; scratch_len],
        }
    }

    /// The number of spectrum entries [`RealFft2::convolve`] reads: columns `kx = 0 ..= nx/2` of a
    /// spectrum laid out `[kx][ky]`.
    pub(super) fn half_len(&self) -> usize {
        (self.nx / 2 + 1) * self.ny
    }

    /// `u = F⁻¹(s · F(p))` on the first `my` rows and `mx` columns of the period for the real
    /// `mx x my` field `p` (zero where `keep` is false, and outside it), `s` the half spectrum
    /// ([`RealFft2::half_len`]) of a real kernel, scaled by `1/(nx ny)` (unnormalised transforms).
    pub(super) fn convolve(
        &mut self,
        (mx, my): (usize, usize),
        p: &[f64],
        keep: impl Fn(usize) -> bool,
        s: &[Complex<f64>],
        u: &mut [f64],
    ) -> Result<(), ContactError> {
        let (ny, nh) = (self.ny, self.nx / 2 + 1);
        let zero = Complex::new(0.0, 0.0);
        // The rows before the first load and after the last (outside the contact) transform to
        // zero: not transformed.
        let n = mx * my;
        let loaded = |k: &usize| keep(*k) && p[*k] != 0.0;
        let first = (0..n).find(loaded).map_or(my, |k| k / mx);
        let last = (0..n).rev().find(loaded).map_or(0, |k| k / mx + 1);
        for j in (0..first).chain(last.max(first)..my) {
            for kx in 0..nh {
                self.cols[kx * ny + j] = zero;
            }
        }
        for j in first..last {
            for (i, v) in self.row.iter_mut().enumerate() {
                let k = j * mx + i;
                *v = if i < mx && keep(k) { p[k] } else { 0.0 };
            }
            self.r2c.process_with_scratch(&mut self.row, &mut self.half, &mut self.scratch).map_err(fft_error)?;
            for (kx, c) in self.half.iter().enumerate() {
                self.cols[kx * ny + j] = *c;
            }
        }
        for kx in 0..nh {
            self.cols[kx * ny + my..(kx + 1) * ny].iter_mut().for_each(|c| *c = zero);
        }
        // One row (ny = 1): the transforms along y are the identity.
        if ny > 1 {
            self.fwd_y.process_with_scratch(&mut self.cols, &mut self.scratch);
        }
        for (c, s) in self.cols.iter_mut().zip(s) {
            *c *= s;
        }
        if ny > 1 {
            self.inv_y.process_with_scratch(&mut self.cols, &mut self.scratch);
        }
        for j in 0..my {
            for (kx, c) in self.half.iter_mut().enumerate() {
                *c = self.cols[kx * ny + j];
            }
            // A real field's spectrum is real at kx = 0 and nx/2: what is left there is round-off.
            self.half[0].im = 0.0;
            self.half[nh - 1].im = 0.0;
            self.c2r.process_with_scratch(&mut self.half, &mut self.row, &mut self.scratch).map_err(fft_error)?;
            u[j * mx..(j + 1) * mx].copy_from_slice(&self.row[..mx]);
        }
        Ok(())
    }
}

/// A real transform's refusal (buffers of the wrong length: an internal inconsistency).
fn fft_error(e: FftError) -> ContactError {
    match e {
        FftError::InputBuffer(expected, len) => ContactError::SizeMismatch { name: "real FFT input", len, expected },
        FftError::OutputBuffer(expected, len) => ContactError::SizeMismatch { name: "real FFT output", len, expected },
        FftError::ScratchBuffer(expected, len) => {
            ContactError::SizeMismatch { name: "real FFT scratch", len, expected }
        }
        FftError::InputValues(..) => ContactError::NonFinite("real FFT input's imaginary part"),
    }
}
