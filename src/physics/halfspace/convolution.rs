//! Discrete convolution `u = A p` of piecewise-constant grid tractions with a translation-invariant
//! influence [`Kernel`]: `u_(i,j) = sum_(I,J) A(i - I, j - J) p_(I,J)` for all `mx*my` output
//! elements, input taken as zero outside a given element set (Kalker 1990, eq. 5.22).
//! Units: p in MPa, A in mm/MPa, u in mm.
//!
//! Two paths with identical results (to round-off): direct summation, cost `O(n_active * mx*my)`,
//! and a zero-padded 2-D FFT (rustfft) with precomputed kernel spectra, cost `O(N log N)`
//! (Press et al., "Numerical Recipes", sec. 13.1, convolution by FFT with zero padding).
//! The tangential pair is transformed as one complex field `px + i py` (two real FFTs for one).

use super::direct;
use super::influence::Kernel;
use super::real_fft::RealFft2;
use super::ContactError;
use crate::simd::with_avx2;
use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};
use std::sync::Arc;

/// Which summation path a [`Convolver`] uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConvPath {
    /// Direct summation over the active sources.
    Direct,
    /// Zero-padded 2-D FFT.
    Fft,
}

/// Grid size (number of elements `mx*my`) from which the FFT path is chosen automatically: the
/// crossover of the direct sum's `O(n^2)` and the FFT's `O(N log N)` cost, near 10x10.
pub const FFT_CROSSOVER_ELEMENTS: usize = 10 * 10;

/// Automatic path choice by grid size (see [`FFT_CROSSOVER_ELEMENTS`]).
pub fn auto_path(mx: usize, my: usize) -> ConvPath {
    if mx * my >= FFT_CROSSOVER_ELEMENTS {
        ConvPath::Fft
    } else {
        ConvPath::Direct
    }
}

/// Smallest even integer `>= n` of the form `2^a 3^b` (the FFT length): rustfft's AVX kernels
/// are radix 2, 3, 4, 6, 8, 9, 12 and 16, and a length with a factor 5, 7 or 11 takes its slower
/// mixed-radix path (bench `fft_length`).
#[allow(clippy::manual_is_multiple_of)] // is_multiple_of needs Rust 1.87; MSRV is 1.82
fn fft_len(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        let mut r = m;
        for p in [2, 3] {
            while r % p == 0 {
                r /= p;
            }
        }
        if r == 1 && m % 2 == 0 {
            return m;
        }
        m += 1;
    }
}

/// Floating-point type of an FFT path: `f64` for products with `A`, `f32` for the preconditioner.
trait Real: rustfft::FftNum {
    fn of(v: f64) -> Self;
    fn get(self) -> f64;
}

impl Real for f64 {
    #[inline(always)]
    fn of(v: f64) -> f64 {
        v
    }
    #[inline(always)]
    fn get(self) -> f64 {
        self
    }
}

impl Real for f32 {
    #[inline(always)]
    fn of(v: f64) -> f32 {
        v as f32
    }
    #[inline(always)]
    fn get(self) -> f64 {
        f64::from(self)
    }
}

/// FFT plans, kernel spectra and work buffers of the FFT path.
#[derive(Clone)]
struct FftData<T: Real> {
    nx: usize,
    ny: usize,
    fwd_x: Arc<dyn Fft<T>>,
    inv_x: Arc<dyn Fft<T>>,
    fwd_y: Arc<dyn Fft<T>>,
    inv_y: Arc<dyn Fft<T>>,
    /// Kernel spectra in transposed layout `[kx][ky]`, scaled by `1/(nx*ny)`.
    szz: Vec<Complex<T>>,
    /// The normal kernel's inverse spectrum (the preconditioner's), made when first asked.
    szz_inv: Vec<Complex<T>>,
    sxx: Vec<Complex<T>>,
    syy: Vec<Complex<T>>,
    sxy: Vec<Complex<T>>,
    /// Packed tangential operator: `U(k) = alpha(k) Z(k) + beta(k) conj(Z(-k))` for
    /// `Z = FFT(px + i py)`, `U = FFT(ux + i uy)`: `alpha = (Sxx + Syy)/2`,
    /// `beta = (Sxx - Syy)/2 + i Sxy`.
    salpha: Vec<Complex<T>>,
    sbeta: Vec<Complex<T>>,
    /// Row-major `[y][x]` work buffer, `nx*ny`.
    buf: Vec<Complex<T>>,
    /// Transposed `[x][y]` work buffer, `nx*ny`.
    buft: Vec<Complex<T>>,
    /// Second transposed buffer for the tangential pair.
    buft2: Vec<Complex<T>>,
    scratch: Vec<Complex<T>>,
}

impl FftData<f64> {
    fn new(kernel: &Kernel, nx: usize, ny: usize) -> FftData<f64> {
        let mut d = FftData::<f64>::empty(nx, ny);
        let scale = 1.0 / (nx * ny) as f64;
        (d.sxx, d.syy) = d.kernel_spectra(kernel, (&kernel.xx, &kernel.yy), scale);
        (d.sxy, d.szz) = d.kernel_spectra(kernel, (&kernel.xy, &kernel.zz), scale);
        d.pack_pair();
        d
    }

    /// [`FftData::new`] with the tangential kernels' spectra alone (the normal one empty).
    fn new_tangential(kernel: &Kernel, nx: usize, ny: usize) -> FftData<f64> {
        let mut d = FftData::<f64>::empty(nx, ny);
        let scale = 1.0 / (nx * ny) as f64;
        (d.sxx, d.syy) = d.kernel_spectra(kernel, (&kernel.xx, &kernel.yy), scale);
        d.sxy = d.kernel_spectrum(kernel, &kernel.xy, scale);
        d.pack_pair();
        d
    }

    /// [`FftData::new_tangential`] of two kernels of one grid (`k0` and `ks`, checked by the
    /// caller to share `mx`, `my`), each component's pair in one complex transform: three
    /// transforms for the six real kernels.
    fn new_tangential_pair(k0: &Kernel, ks: &Kernel, nx: usize, ny: usize) -> (FftData<f64>, FftData<f64>) {
        let mut d0 = FftData::<f64>::empty(nx, ny);
        let mut ds = d0.sibling();
        let scale = 1.0 / (nx * ny) as f64;
        (d0.sxx, d0.syy) = d0.kernel_spectra(k0, (&k0.xx, &k0.yy), scale);
        (ds.sxx, ds.syy) = d0.kernel_spectra(k0, (&ks.xx, &ks.yy), scale);
        (d0.sxy, ds.sxy) = d0.kernel_spectra(k0, (&k0.xy, &ks.xy), scale);
        d0.pack_pair();
        ds.pack_pair();
        (d0, ds)
    }

    /// The spectra of the difference of this transform's kernel and `other`'s (the same lengths):
    /// the transform is linear, so they are the spectra's differences.
    fn minus(&self, other: &FftData<f64>) -> FftData<f64> {
        let sub = |a: &[Complex<f64>], b: &[Complex<f64>]| -> Vec<Complex<f64>> {
            if b.is_empty() {
                a.to_vec()
            } else {
                a.iter().zip(b).map(|(a, b)| a - b).collect()
            }
        };
        let mut d = self.clone();
        d.szz = sub(&self.szz, &other.szz);
        d.sxx = sub(&self.sxx, &other.sxx);
        d.syy = sub(&self.syy, &other.syy);
        d.sxy = sub(&self.sxy, &other.sxy);
        d.salpha = sub(&self.salpha, &other.salpha);
        d.sbeta = sub(&self.sbeta, &other.sbeta);
        d.szz_inv = Vec::new();
        d
    }

    /// [`FftData::new`] with the normal kernel's spectrum alone (the tangential ones empty).
    fn new_normal(kernel: &Kernel, nx: usize, ny: usize) -> FftData<f64> {
        let mut d = FftData::<f64>::empty(nx, ny);
        d.szz = d.kernel_spectrum(kernel, &kernel.zz, 1.0 / (nx * ny) as f64);
        d
    }

    /// Computes the packed tangential spectra `alpha`, `beta` from `Sxx`, `Syy`, `Sxy`.
    fn pack_pair(&mut self) {
        let i = Complex::new(0.0, 1.0);
        self.salpha = self.sxx.iter().zip(&self.syy).map(|(a, b)| (a + b) * 0.5).collect();
        self.sbeta = self.sxx.iter().zip(&self.syy).zip(&self.sxy).map(|((a, b), c)| (a - b) * 0.5 + i * c).collect();
    }

    /// Spectrum of one kernel component placed circularly (offset `d` added at index `d mod n`).
    fn kernel_spectrum(&mut self, kernel: &Kernel, comp: &[f64], scale: f64) -> Vec<Complex<f64>> {
        self.place(kernel, comp, None, scale);
        self.transform_placed();
        self.buft.clone()
    }

    /// The spectra of two real kernel components of `kernel`'s layout by one complex transform
    /// (Press et al., "Numerical Recipes", 3rd ed., sec. 12.3.1): `Z = F(a + i b)`, then
    /// `F(a)(k) = (Z(k) + conj Z(-k)) / 2` and `F(b)(k) = (Z(k) - conj Z(-k)) / (2i)`.
    fn kernel_spectra(
        &mut self,
        kernel: &Kernel,
        (a, b): (&[f64], &[f64]),
        scale: f64,
    ) -> (Vec<Complex<f64>>, Vec<Complex<f64>>) {
        self.place(kernel, a, Some(b), scale);
        self.transform_placed();
        split_pair(&self.buft, self.nx, self.ny)
    }

    /// Places the components `re` (and `im`, the imaginary part, where given) of `kernel`'s
    /// layout circularly into `buf`, scaled by `scale`.
    fn place(&mut self, kernel: &Kernel, re: &[f64], im: Option<&[f64]>, scale: f64) {
        let (mx, my, nx, ny) = (kernel.mx, kernel.my, self.nx, self.ny);
        let zero = Complex::new(0.0, 0.0);
        self.buf.iter_mut().for_each(|c| *c = zero);
        for dj in -(my as isize - 1)..=(my as isize - 1) {
            let row = dj.rem_euclid(ny as isize) as usize;
            for di in -(mx as isize - 1)..=(mx as isize - 1) {
                let col = di.rem_euclid(nx as isize) as usize;
                let k = kernel.index(di, dj);
                let v = Complex::new(re[k] * scale, im.map_or(0.0, |im| im[k] * scale));
                self.buf[row * nx + col] += v;
            }
        }
    }

    /// The forward 2-D transform of all of `buf` into `buft` (layout `[kx][ky]`).
    fn transform_placed(&mut self) {
        let (nx, ny) = (self.nx, self.ny);
        self.fwd_x.process_with_scratch(&mut self.buf, &mut self.scratch);
        transpose(&self.buf, &mut self.buft, nx, ny, ny);
        self.fwd_y.process_with_scratch(&mut self.buft, &mut self.scratch);
    }

    /// The field at every offset of the period, row-major `[y][x]`, from a spectrum stored like
    /// the kernel spectra (layout `[kx][ky]`, scaled by `1/(nx*ny)`): the unnormalised inverse
    /// 2-D transform, real part.
    fn real_space(&mut self, spectrum: &[Complex<f64>]) -> Vec<f64> {
        self.inverse_all(spectrum.iter().copied());
        self.buf.iter().map(|c| c.re).collect()
    }

    /// [`FftData::real_space`] of two spectra whose fields are real (`a`, `b` Hermitian) by one
    /// inverse transform of `a + i b`: the real part is `a`'s field, the imaginary part `b`'s.
    fn real_space_pair(&mut self, a: &[Complex<f64>], b: &[Complex<f64>]) -> (Vec<f64>, Vec<f64>) {
        let i = Complex::new(0.0, 1.0);
        self.inverse_all(a.iter().zip(b).map(|(a, b)| a + i * b));
        (self.buf.iter().map(|c| c.re).collect(), self.buf.iter().map(|c| c.im).collect())
    }

    /// The unnormalised inverse 2-D transform of `spectrum` (layout `[kx][ky]`) into `buf`.
    fn inverse_all(&mut self, spectrum: impl Iterator<Item = Complex<f64>>) {
        let (nx, ny) = (self.nx, self.ny);
        self.buft.iter_mut().zip(spectrum).for_each(|(c, s)| *c = s);
        self.inv_y.process_with_scratch(&mut self.buft, &mut self.scratch);
        transpose(&self.buft, &mut self.buf, ny, nx, nx);
        self.inv_x.process_with_scratch(&mut self.buf, &mut self.scratch);
    }

    /// The same operator in single precision (plans, spectra and buffers in `f32`).
    fn to_f32(&self) -> FftData<f32> {
        let down = |v: &[Complex<f64>]| v.iter().map(|c| Complex::new(c.re as f32, c.im as f32)).collect();
        let mut d = FftData::<f32>::empty(self.nx, self.ny);
        (d.szz, d.sxx, d.syy, d.sxy) = (down(&self.szz), down(&self.sxx), down(&self.syy), down(&self.sxy));
        (d.salpha, d.sbeta) = (down(&self.salpha), down(&self.sbeta));
        d
    }
}

/// The FFT length along y of an `my`-row grid: a single row (CONTACT's 2-D strips, `my = 1`)
/// has no offset along y, its period one row (the transform along y the identity, no padded row
/// transformed); more rows [`fft_len`] of `2my - 1`. (x keeps its even length: the real
/// transforms along x want it.)
fn fft_len_y(my: usize) -> usize {
    if my == 1 {
        1
    } else {
        fft_len(2 * my - 1)
    }
}

impl<T: Real> FftData<T> {
    /// An [`FftData::empty`] of the same lengths sharing this one's plans (not planned again).
    fn sibling(&self) -> FftData<T> {
        let plans = [&self.fwd_x, &self.inv_x, &self.fwd_y, &self.inv_y].map(Arc::clone);
        FftData::with_plans(self.nx, self.ny, plans, self.scratch.len())
    }

    /// Plans and zeroed work buffers for `nx x ny` transforms; no spectra yet.
    fn empty(nx: usize, ny: usize) -> FftData<T> {
        let mut planner = FftPlanner::<T>::new();
        let plans = [
            planner.plan_fft_forward(nx),
            planner.plan_fft_inverse(nx),
            planner.plan_fft_forward(ny),
            planner.plan_fft_inverse(ny),
        ];
        let scratch_len = plans.iter().map(|f| f.get_inplace_scratch_len()).max().unwrap_or(0);
        FftData::with_plans(nx, ny, plans, scratch_len)
    }

    /// Zeroed work buffers for `nx x ny` transforms by the plans `[fwd_x, inv_x, fwd_y, inv_y]`.
    fn with_plans(nx: usize, ny: usize, plans: [Arc<dyn Fft<T>>; 4], scratch_len: usize) -> FftData<T> {
        let [fwd_x, inv_x, fwd_y, inv_y] = plans;
        let zero = Complex::new(T::zero(), T::zero());
        FftData {
            nx,
            ny,
            fwd_x,
            inv_x,
            fwd_y,
            inv_y,
            szz: Vec::new(),
            szz_inv: Vec::new(),
            sxx: Vec::new(),
            syy: Vec::new(),
            sxy: Vec::new(),
            salpha: Vec::new(),
            sbeta: Vec::new(),
            buf: vec![zero; nx * ny],
            buft: vec![zero; nx * ny],
            buft2: vec![zero; nx * ny],
            scratch: vec![zero; scratch_len],
        }
    }

    /// Forward transform of the field in `buf` (only its first `my` rows may be non-zero, and of
    /// those only the rows `loaded`: the others, zero, are not transformed) into `buft` (layout
    /// `[kx][ky]`).
    fn forward(&mut self, my: usize, loaded: std::ops::Range<usize>) {
        let nx = self.nx;
        if !loaded.is_empty() {
            self.fwd_x.process_with_scratch(&mut self.buf[loaded.start * nx..loaded.end * nx], &mut self.scratch);
        }
        if self.ny == 1 {
            // One row: its transposed layout is itself, the transform along y the identity.
            self.buft.copy_from_slice(&self.buf);
            return;
        }
        transpose(&self.buf, &mut self.buft, nx, self.ny, my);
        self.fwd_y.process_with_scratch(&mut self.buft, &mut self.scratch);
    }

    /// Inverse transform of the spectrum in `buft` into the first `my` rows of `buf`.
    fn inverse(&mut self, my: usize) {
        let (nx, ny) = (self.nx, self.ny);
        if ny > 1 {
            self.inv_y.process_with_scratch(&mut self.buft, &mut self.scratch);
        }
        // Transpose back only the first my rows (x-major -> y-major).
        for j in 0..my {
            for i in 0..nx {
                self.buf[j * nx + i] = self.buft[i * ny + j];
            }
        }
        self.inv_x.process_with_scratch(&mut self.buf[..my * nx], &mut self.scratch);
    }
}

/// A kernel serves a non-empty grid and has `(2mx - 1)(2my - 1)` entries per component.
fn check_kernel(kernel: &Kernel) -> Result<(), ContactError> {
    let (mx, my) = (kernel.mx, kernel.my);
    if mx == 0 || my == 0 {
        return Err(ContactError::EmptyGrid { mx, my });
    }
    let nk = (2 * mx - 1) * (2 * my - 1);
    let lengths = [&kernel.zz, &kernel.xx, &kernel.yy, &kernel.xy].map(|v| v.len());
    match lengths.iter().find(|&&l| l != nk) {
        Some(&len) => Err(ContactError::SizeMismatch { name: "kernel array", len, expected: nk }),
        None => Ok(()),
    }
}

/// The kernel of the inverse of the tangential `A` periodised at `2mx x 2my` elements, at the
/// grid's offsets (its normal part zero): per frequency of that period the inverse of the 2x2
/// tangential symbol (symbols clamped to at least 1e-3 of their largest value, the coupling to
/// 0.99 of the geometric mean of the diagonal, so that `M` stays positive definite), transformed
/// back to real space. At the period
/// `2m` the periodised `A` holds every offset of the grid once (a circulant embedding of `A`);
/// between grid elements `M` is that circulant's inverse, whatever FFT length applies it.
fn periodic_inverse(kernel: &Kernel) -> Result<Kernel, ContactError> {
    let (mx, my) = (kernel.mx, kernel.my);
    check_kernel(kernel)?;
    let (px, py) = (2 * mx, 2 * my);
    let mut f = FftData::new_tangential(kernel, px, py);
    // Spectra are stored scaled by 1/(px py); the inverse's must carry the same scale.
    let scale = 1.0 / (px * py) as f64;
    let amax = f.sxx.iter().chain(&f.syy).fold(0.0f64, |m, v| m.max(v.re));
    let floor = 1e-3;
    for idx in 0..f.sxx.len() {
        let a = f.sxx[idx].re.max(floor * amax);
        let d = f.syy[idx].re.max(floor * amax);
        let lim = 0.99 * (a * d).sqrt();
        let b = f.sxy[idx].re.clamp(-lim, lim);
        let det = a * d - b * b;
        f.sxx[idx] = Complex::new(scale * scale * d / det, 0.0);
        f.syy[idx] = Complex::new(scale * scale * a / det, 0.0);
        f.sxy[idx] = Complex::new(-scale * scale * b / det, 0.0);
    }
    let (sxx, syy, sxy) = (std::mem::take(&mut f.sxx), std::mem::take(&mut f.syy), std::mem::take(&mut f.sxy));
    let (xx, yy) = f.real_space_pair(&sxx, &syy);
    let xy = f.real_space(&sxy);
    let at_offsets = |periodic: Vec<f64>| {
        let mut out = vec![0.0; (2 * mx - 1) * (2 * my - 1)];
        for dj in -(my as isize - 1)..=(my as isize - 1) {
            let row = dj.rem_euclid(py as isize) as usize;
            for di in -(mx as isize - 1)..=(mx as isize - 1) {
                out[kernel.index(di, dj)] = periodic[row * px + di.rem_euclid(px as isize) as usize];
            }
        }
        out
    };
    Ok(Kernel {
        mx,
        my,
        dx_mm: kernel.dx_mm,
        dy_mm: kernel.dy_mm,
        shift_mm: kernel.shift_mm,
        zz: vec![0.0; (2 * mx - 1) * (2 * my - 1)],
        xx: at_offsets(xx),
        yy: at_offsets(yy),
        xy: at_offsets(xy),
    })
}

/// The inverse of the stored spectrum `s` (scaled by `1/n`, `n` the transform's size) stored the
/// same way: `(1/n)² / s`, each `s` floored at 1e-3 of the largest (as [`periodic_inverse`]).
fn inverse_spectrum(s: &[Complex<f64>], n: usize) -> Vec<Complex<f64>> {
    let scale = 1.0 / n as f64;
    let floor = 1e-3 * s.iter().fold(0.0f64, |m, v| m.max(v.re));
    s.iter().map(|v| Complex::new(scale * scale / v.re.max(floor), 0.0)).collect()
}

/// The spectra `F(a)`, `F(b)` of two real fields from `Z = F(a + i b)` (layout `[kx][ky]`,
/// `nx x ny`): `F(a)(k) = (Z(k) + conj Z(-k)) / 2`, `F(b)(k) = -i (Z(k) - conj Z(-k)) / 2`.
fn split_pair(z: &[Complex<f64>], nx: usize, ny: usize) -> (Vec<Complex<f64>>, Vec<Complex<f64>>) {
    let (mut a, mut b) = (Vec::with_capacity(nx * ny), Vec::with_capacity(nx * ny));
    for kx in 0..nx {
        let mkx = (nx - kx) % nx;
        for ky in 0..ny {
            let zk = z[kx * ny + ky];
            let zm = z[mkx * ny + (ny - ky) % ny].conj();
            a.push((zk + zm) * 0.5);
            let d = (zk - zm) * 0.5;
            b.push(Complex::new(d.im, -d.re));
        }
    }
    (a, b)
}

/// Transposes the first `rows` rows of the row-major `[ny][nx]` array `src` into `dst` laid out
/// `[nx][ny]`; the other entries of `dst` are set to zero.
fn transpose<T: Real>(src: &[Complex<T>], dst: &mut [Complex<T>], nx: usize, ny: usize, rows: usize) {
    let zero = Complex::new(T::zero(), T::zero());
    for i in 0..nx {
        let d = &mut dst[i * ny..(i + 1) * ny];
        for (j, v) in d.iter_mut().enumerate().take(rows) {
            *v = src[j * nx + i];
        }
        for v in d.iter_mut().skip(rows) {
            *v = zero;
        }
    }
}

/// Evaluates `u = A p` on an `mx x my` grid for one kernel, by direct summation or FFT. Holds
/// every buffer it needs, so that [`Convolver::normal`] and [`Convolver::tangential`] do not
/// allocate.
#[derive(Clone)]
pub struct Convolver {
    mx: usize,
    my: usize,
    path: ConvPath,
    nkx: usize,
    kzz: Vec<f64>,
    kxx: Vec<f64>,
    kyy: Vec<f64>,
    kxy: Vec<f64>,
    /// Whether any `Axy` coefficient is nonzero (the direct path skips them otherwise).
    xy_coupled: bool,
    active: Vec<usize>,
    fft: Option<FftData<f64>>,
    /// Single-precision copy used instead of `fft` by [`Convolver::tangential`] (preconditioner).
    fft32: Option<FftData<f32>>,
    /// The real-input transforms of the normal products on the FFT path (made at the first).
    real: Option<RealFft2>,
}

impl Convolver {
    /// Convolver for `kernel` with an explicit path.
    pub fn new(kernel: &Kernel, path: ConvPath) -> Result<Convolver, ContactError> {
        check_kernel(kernel)?;
        let (mx, my) = (kernel.mx, kernel.my);
        let fft = match path {
            ConvPath::Fft => Some(FftData::new(kernel, fft_len(2 * mx - 1), fft_len_y(my))),
            ConvPath::Direct => None,
        };
        Ok(Convolver::holding(kernel, fft))
    }

    /// The convolver of `kernel` (checked) on the FFT path with the transforms `fft` where given,
    /// else on the direct path. The coefficients are kept for the direct path alone: the FFT
    /// path's products read the spectra (and a copy of the convolver copies no coefficients).
    fn holding(kernel: &Kernel, fft: Option<FftData<f64>>) -> Convolver {
        let (mx, my) = (kernel.mx, kernel.my);
        let direct = fft.is_none();
        let coefficients = |k: &Vec<f64>| if direct { k.clone() } else { Vec::new() };
        Convolver {
            mx,
            my,
            path: if direct { ConvPath::Direct } else { ConvPath::Fft },
            nkx: 2 * mx - 1,
            kzz: coefficients(&kernel.zz),
            kxx: coefficients(&kernel.xx),
            kyy: coefficients(&kernel.yy),
            kxy: coefficients(&kernel.xy),
            xy_coupled: kernel.xy.iter().any(|&v| v != 0.0),
            active: Vec::with_capacity(if direct { mx * my } else { 0 }),
            fft,
            fft32: None,
            real: None,
        }
    }

    /// FFT-path operator `M`, an approximate inverse of the tangential `A` used as preconditioner:
    /// the inverse of `A` periodised at twice the grid ([`periodic_inverse`]), applied like `A`
    /// itself, so that the FFT length does not change the operator. Its
    /// [`Convolver::tangential`] runs in single precision: a preconditioner changes only the path
    /// to the solution, not the solution; [`Convolver::normal`] is refused.
    pub fn inverse_of(kernel: &Kernel) -> Result<Convolver, ContactError> {
        let mut c = Convolver::with_spectra(&periodic_inverse(kernel)?, ConvPath::Fft, FftData::new_tangential)?;
        c.fft32 = c.fft.as_ref().map(FftData::to_f32);
        Ok(c)
    }

    /// Convolver with the path chosen by grid size ([`auto_path`]) whose
    /// [`Convolver::tangential`] runs in single precision on the FFT path: for the products inside
    /// an iteration whose residual is recomputed exactly every few steps (the CG's search
    /// directions), where an error of 1e-7 relative to the correction is harmless.
    pub fn single_precision(kernel: &Kernel) -> Result<Convolver, ContactError> {
        let mut c = Convolver::auto(kernel)?;
        c.fft32 = c.fft.as_ref().map(FftData::to_f32);
        Ok(c)
    }

    /// [`Convolver::single_precision`] of this convolver's kernel for its tangential products
    /// alone: on the FFT path its single-precision transforms made of this one's (not made
    /// again), which the copy does not keep (its normal products are refused); on the direct
    /// path a copy.
    pub fn to_single_precision(&self) -> Convolver {
        Convolver {
            mx: self.mx,
            my: self.my,
            path: self.path,
            nkx: self.nkx,
            kzz: self.kzz.clone(),
            kxx: self.kxx.clone(),
            kyy: self.kyy.clone(),
            kxy: self.kxy.clone(),
            xy_coupled: self.xy_coupled,
            active: self.active.clone(),
            fft: None,
            fft32: self.fft.as_ref().map(FftData::to_f32),
            real: None,
        }
    }

    /// Convolver with the path chosen by grid size ([`auto_path`]).
    pub fn auto(kernel: &Kernel) -> Result<Convolver, ContactError> {
        Convolver::new(kernel, auto_path(kernel.mx, kernel.my))
    }

    /// [`Convolver::auto`] for [`Convolver::normal`] alone: on the FFT path only the normal
    /// kernel is transformed ([`Convolver::tangential`] is refused).
    pub fn normal_only(kernel: &Kernel) -> Result<Convolver, ContactError> {
        Convolver::with_spectra(kernel, auto_path(kernel.mx, kernel.my), FftData::new_normal)
    }

    /// [`Convolver::auto`] for [`Convolver::tangential`] alone: on the FFT path only the
    /// tangential kernels are transformed ([`Convolver::normal`] is refused).
    pub fn tangential_only(kernel: &Kernel) -> Result<Convolver, ContactError> {
        Convolver::with_spectra(kernel, auto_path(kernel.mx, kernel.my), FftData::new_tangential)
    }

    /// [`Convolver::tangential_only`] of two kernels of one grid (the unshifted and the shifted
    /// kernel of the tangential problem): on the FFT path each component's pair transformed
    /// at once (three complex transforms for the six real kernels).
    pub fn tangential_pair(k0: &Kernel, ks: &Kernel) -> Result<(Convolver, Convolver), ContactError> {
        check_kernel(k0)?;
        check_kernel(ks)?;
        let (mx, my) = (k0.mx, k0.my);
        if (ks.mx, ks.my) != (mx, my) {
            return Err(ContactError::GridMismatch { expected: (mx, my), got: (ks.mx, ks.my) });
        }
        if auto_path(mx, my) == ConvPath::Direct {
            return Ok((Convolver::holding(k0, None), Convolver::holding(ks, None)));
        }
        let (f0, fs) = FftData::new_tangential_pair(k0, ks, fft_len(2 * mx - 1), fft_len_y(my));
        Ok((Convolver::holding(k0, Some(f0)), Convolver::holding(ks, Some(fs))))
    }

    /// Convolver for `kernel` on `path` whose FFT path holds the spectra `spectra` makes alone.
    fn with_spectra(
        kernel: &Kernel,
        path: ConvPath,
        spectra: fn(&Kernel, usize, usize) -> FftData<f64>,
    ) -> Result<Convolver, ContactError> {
        check_kernel(kernel)?;
        let fft = (path == ConvPath::Fft).then(|| spectra(kernel, fft_len(2 * kernel.mx - 1), fft_len_y(kernel.my)));
        Ok(Convolver::holding(kernel, fft))
    }

    /// The convolver of `difference`, the kernel of this convolver less `other`'s (both of the
    /// same grid): on the FFT path its spectra are the differences of theirs, no transform made.
    pub fn minus(&self, other: &Convolver, difference: &Kernel) -> Result<Convolver, ContactError> {
        check_kernel(difference)?;
        match (&self.fft, &other.fft) {
            (Some(a), Some(b)) => {
                let got = (difference.mx, difference.my);
                if (a.nx, a.ny) != (b.nx, b.ny) || got != (self.mx, self.my) {
                    return Err(ContactError::GridMismatch { expected: (self.mx, self.my), got });
                }
                Ok(Convolver::holding(difference, Some(a.minus(b))))
            }
            _ => Ok(Convolver::holding(difference, None)),
        }
    }

    /// The path in use.
    pub fn path(&self) -> ConvPath {
        self.path
    }

    /// The grid shape of the direct path's products.
    fn shape(&self) -> direct::Shape {
        direct::Shape { mx: self.mx, my: self.my, nkx: self.nkx }
    }

    /// Every array must have `mx*my` entries, and so must the mask if given.
    fn check(&self, arrays: &[(&'static str, &[f64])], mask: Option<&[bool]>) -> Result<(), ContactError> {
        let n = self.mx * self.my;
        for &(name, v) in arrays {
            if v.len() != n {
                return Err(ContactError::SizeMismatch { name, len: v.len(), expected: n });
            }
        }
        match mask {
            Some(m) if m.len() != n => Err(ContactError::SizeMismatch { name: "mask", len: m.len(), expected: n }),
            _ => Ok(()),
        }
    }

    /// The sources of the direct path: elements inside the mask where `nonzero` holds.
    fn collect_active(&mut self, mask: Option<&[bool]>, nonzero: impl Fn(usize) -> bool) {
        self.active.clear();
        let n = self.mx * self.my;
        self.active.extend((0..n).filter(|&k| mask.is_none_or(|m| m[k]) && nonzero(k)));
    }

    /// Normal displacement `u = Azz p` [mm] for pressure `p` [MPa] (zero where `mask` is false).
    pub fn normal(&mut self, p: &[f64], mask: Option<&[bool]>, u: &mut [f64]) -> Result<(), ContactError> {
        self.check(&[("p", p), ("u", u)], mask)?;
        match self.path {
            ConvPath::Direct => {
                self.collect_active(mask, |k| p[k] != 0.0);
                direct::normal(self.shape(), &self.kzz, &self.active, p, u);
            }
            ConvPath::Fft => self.fft_normal(p, mask, u, false)?,
        }
        Ok(())
    }

    /// `z ≈ Azz⁻¹ g` [MPa] for a gap `g` [mm]: the normal kernel's circulant on the FFT grid
    /// inverted per frequency (its spectrum floored at 1e-3 of its largest, as
    /// [`periodic_inverse`]), a preconditioner for the normal CG (Vollebregt 2014, J. Comput.
    /// Phys. 257, sec. 4). `false` (and `z` untouched) on the direct path, which has none.
    pub fn normal_inverse(&mut self, g: &[f64], z: &mut [f64]) -> Result<bool, ContactError> {
        self.check(&[("g", g), ("z", z)], None)?;
        if self.path != ConvPath::Fft {
            return Ok(false);
        }
        self.fft_normal(g, None, z, true)?;
        Ok(true)
    }

    /// `u = Azz p` on the FFT path, or with `inverse` its preconditioner ([`Convolver::normal_inverse`]).
    fn fft_normal(
        &mut self,
        p: &[f64],
        mask: Option<&[bool]>,
        u: &mut [f64],
        inverse: bool,
    ) -> Result<(), ContactError> {
        let (mx, my) = (self.mx, self.my);
        let f = self.fft.as_mut().filter(|f| !f.szz.is_empty()).ok_or(ContactError::MissingFft)?;
        if inverse && f.szz_inv.is_empty() {
            f.szz_inv = inverse_spectrum(&f.szz, f.nx * f.ny);
        }
        let real = self.real.get_or_insert_with(|| RealFft2::new(f.nx, f.ny));
        let spectrum = if inverse { &f.szz_inv } else { &f.szz };
        real.convolve((mx, my), p, |k| mask.is_none_or(|m| m[k]), &spectrum[..real.half_len()], u)
    }

    /// Tangential displacements `ux = Axx px + Axy py`, `uy = Axy px + Ayy py` [mm] for tractions
    /// `px`, `py` [MPa] (zero where `mask` is false).
    pub fn tangential(
        &mut self,
        px: &[f64],
        py: &[f64],
        mask: Option<&[bool]>,
        ux: &mut [f64],
        uy: &mut [f64],
    ) -> Result<(), ContactError> {
        self.check(&[("px", px), ("py", py), ("ux", ux), ("uy", uy)], mask)?;
        match self.path {
            ConvPath::Direct => {
                self.collect_active(mask, |k| px[k] != 0.0 || py[k] != 0.0);
                let kxy = self.xy_coupled.then_some(&self.kxy[..]);
                let pair = direct::Pair { kxx: &self.kxx, kyy: &self.kyy, kxy };
                direct::tangential(self.shape(), &pair, &self.active, (px, py), (ux, uy));
            }
            ConvPath::Fft => {
                let (mx, my) = (self.mx, self.my);
                let io = PairIo { mx, my, px, py, mask, ux, uy };
                // The single-precision transforms where there are any (a copy made by
                // `to_single_precision` keeps no others).
                match (self.fft32.as_mut(), self.fft.as_mut()) {
                    (Some(f32data), _) if !f32data.salpha.is_empty() => tangential_dispatch(f32data, io),
                    (None, Some(f)) if !f.salpha.is_empty() => tangential_dispatch(f, io),
                    _ => return Err(ContactError::MissingFft),
                }
            }
        }
        Ok(())
    }
}

/// Arguments of the tangential FFT path: grid size, input tractions and mask, output displacements.
struct PairIo<'a> {
    mx: usize,
    my: usize,
    px: &'a [f64],
    py: &'a [f64],
    mask: Option<&'a [bool]>,
    ux: &'a mut [f64],
    uy: &'a mut [f64],
}

/// FFT path of [`Convolver::tangential`] in its AVX2 build where the CPU has it ([`with_avx2`]:
/// the same operations, no reductions and no fused multiply-adds, so bit-identical results).
fn tangential_dispatch<T: Real>(f: &mut FftData<T>, io: PairIo) {
    with_avx2(
        #[inline(always)]
        || tangential_fft(f, io),
    )
}

/// FFT path of [`Convolver::tangential`] (see there).
#[inline(always)]
fn tangential_fft<T: Real>(f: &mut FftData<T>, io: PairIo) {
    let PairIo { mx, my, px, py, mask, ux, uy } = io;
    let (nx, ny) = (f.nx, f.ny);
    let zero = Complex::new(T::zero(), T::zero());
    for j in 0..my {
        let (head, tail) = f.buf[j * nx..(j + 1) * nx].split_at_mut(mx);
        let (rx, ry) = (&px[j * mx..(j + 1) * mx], &py[j * mx..(j + 1) * mx]);
        match mask {
            Some(m) => {
                for (((c, &x), &y), &on) in head.iter_mut().zip(rx).zip(ry).zip(&m[j * mx..(j + 1) * mx]) {
                    *c = if on { Complex::new(T::of(x), T::of(y)) } else { zero };
                }
            }
            None => {
                for ((c, &x), &y) in head.iter_mut().zip(rx).zip(ry) {
                    *c = Complex::new(T::of(x), T::of(y));
                }
            }
        }
        tail.fill(zero);
    }
    // The rows before the first load and after the last (outside the contact) transform to zero:
    // not transformed.
    let loaded = |k: &usize| mask.is_none_or(|m| m[*k]) && (px[*k] != 0.0 || py[*k] != 0.0);
    let first = (0..mx * my).find(loaded).map_or(my, |k| k / mx);
    let last = (0..mx * my).rev().find(loaded).map_or(first, |k| k / mx + 1);
    f.forward(my, first..last);
    // U(k) = alpha(k) Z(k) + beta(k) conj(Z(-k)) (see `salpha`, `sbeta`).
    for kx in 0..nx {
        let mkx = (nx - kx) % nx;
        let row = &f.buft[kx * ny..(kx + 1) * ny];
        let mrow = &f.buft[mkx * ny..(mkx + 1) * ny];
        let out = &mut f.buft2[kx * ny..(kx + 1) * ny];
        let al = &f.salpha[kx * ny..(kx + 1) * ny];
        let be = &f.sbeta[kx * ny..(kx + 1) * ny];
        out[0] = al[0] * row[0] + be[0] * mrow[0].conj();
        for ((((o, z), zm), a), b) in
            out[1..].iter_mut().zip(&row[1..]).zip(mrow[1..].iter().rev()).zip(&al[1..]).zip(&be[1..])
        {
            *o = *a * *z + *b * zm.conj();
        }
    }
    std::mem::swap(&mut f.buft, &mut f.buft2);
    f.inverse(my);
    for j in 0..my {
        let row = &f.buf[j * nx..j * nx + mx];
        for ((c, x), y) in row.iter().zip(&mut ux[j * mx..(j + 1) * mx]).zip(&mut uy[j * mx..(j + 1) * mx]) {
            *x = c.re.get();
            *y = c.im.get();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Small deterministic pseudo-random generator (xorshift64*), values in [-1, 1).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            let v = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d);
            (v >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    fn compare(mx: usize, my: usize, shift: f64) {
        let k = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, shift).unwrap();
        let mut d = Convolver::new(&k, ConvPath::Direct).unwrap();
        let mut f = Convolver::new(&k, ConvPath::Fft).unwrap();
        let n = mx * my;
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15 ^ (n as u64));
        let px: Vec<f64> = (0..n).map(|_| 500.0 * rng.next()).collect();
        let py: Vec<f64> = (0..n).map(|_| 500.0 * rng.next()).collect();
        let mask: Vec<bool> = (0..n).map(|_| rng.next() > -0.4).collect();
        for m in [None, Some(mask.as_slice())] {
            let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
            d.normal(&px, m, &mut a).unwrap();
            f.normal(&px, m, &mut b).unwrap();
            let scale = a.iter().fold(0.0f64, |s, v| s.max(v.abs()));
            let err = a.iter().zip(&b).fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
            assert!(err <= 1e-12 * scale, "normal {mx}x{my}: {err} vs {scale}");
            let (err, scale) = tangential_difference(&mut d, &mut f, (&px, &py), m);
            assert!(err <= 1e-12 * scale, "tangential {mx}x{my}: {err} vs {scale}");
        }
    }

    /// The largest difference of two convolvers' tangential products of `(px, py)` and the
    /// first's largest value.
    fn tangential_difference(
        a: &mut Convolver,
        b: &mut Convolver,
        p: (&[f64], &[f64]),
        m: Option<&[bool]>,
    ) -> (f64, f64) {
        let n = p.0.len();
        let (mut ax, mut ay, mut bx, mut by) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        a.tangential(p.0, p.1, m, &mut ax, &mut ay).unwrap();
        b.tangential(p.0, p.1, m, &mut bx, &mut by).unwrap();
        let scale = ax.iter().chain(&ay).fold(0.0f64, |s, v| s.max(v.abs()));
        let err = ax.iter().zip(&bx).chain(ay.iter().zip(&by)).fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
        (err, scale)
    }

    #[test]
    fn direct_and_fft_agree() {
        compare(22, 22, 0.0);
        compare(44, 44, 0.0);
        compare(30, 17, 0.0);
        compare(22, 22, 0.7);
        compare(13, 29, 0.35);
    }

    #[test]
    fn a_load_on_a_band_of_rows_convolves_as_on_the_direct_path() {
        // Rows before the first load and after the last are not transformed: the normal and
        // tangential products of a load on rows 7 to 15 of 24 (and of none) as the direct path's.
        let (mx, my) = (30, 24);
        let k = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let mut d = Convolver::new(&k, ConvPath::Direct).unwrap();
        let mut f = Convolver::new(&k, ConvPath::Fft).unwrap();
        let mut rng = Rng(11);
        let band: Vec<f64> =
            (0..mx * my).map(|k| if (7..16).contains(&(k / mx)) { 500.0 * rng.next().abs() } else { 0.0 }).collect();
        for p in [band, vec![0.0; mx * my]] {
            let (mut a, mut b) = (vec![0.0; mx * my], vec![0.0; mx * my]);
            d.normal(&p, None, &mut a).unwrap();
            f.normal(&p, None, &mut b).unwrap();
            let scale = a.iter().fold(0.0f64, |s, v| s.max(v.abs()));
            let err = a.iter().zip(&b).fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
            assert!(err <= 1e-12 * scale, "{err} vs {scale}");
            let py: Vec<f64> = p.iter().map(|v| -0.3 * v).collect();
            let (err, scale) = tangential_difference(&mut d, &mut f, (&p, &py), None);
            assert!(err <= 1e-12 * scale, "tangential: {err} vs {scale}");
        }
    }

    #[test]
    fn a_pair_of_kernels_transformed_at_once_is_each_transformed_alone() {
        for (mx, my) in [(22, 22), (30, 17), (13, 1)] {
            let k0 = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
            let ks = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, 0.35).unwrap();
            let (mut p0, mut ps) = Convolver::tangential_pair(&k0, &ks).unwrap();
            let n = mx * my;
            let mut rng = Rng(5 + n as u64);
            let px: Vec<f64> = (0..n).map(|_| 500.0 * rng.next()).collect();
            let py: Vec<f64> = (0..n).map(|_| 500.0 * rng.next()).collect();
            for (k, pair) in [(&k0, &mut p0), (&ks, &mut ps)] {
                let mut alone = Convolver::new(k, ConvPath::Direct).unwrap();
                let (err, scale) = tangential_difference(&mut alone, pair, (&px, &py), None);
                assert!(err <= 1e-12 * scale, "pair {mx}x{my}: {err} vs {scale}");
            }
        }
        let small = Kernel::new(3, 3, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let other = Kernel::new(4, 3, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
        assert!(Convolver::tangential_pair(&small, &other).is_err());
    }

    #[test]
    fn single_precision_preconditioner_matches_double() {
        // The preconditioner's f32 transforms against the same operator in f64: relative
        // difference at the level of f32 round-off.
        let (mx, my) = (30, 22);
        let k = Kernel::new(mx, my, 0.6, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let mut c32 = Convolver::inverse_of(&k).unwrap();
        let mut c64 = Convolver::inverse_of(&k).unwrap();
        c64.fft32 = None;
        let n = mx * my;
        let mut rng = Rng(11);
        let px: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        let py: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        let (mut ax, mut ay, mut bx, mut by) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        c32.tangential(&px, &py, None, &mut ax, &mut ay).unwrap();
        c64.tangential(&px, &py, None, &mut bx, &mut by).unwrap();
        let scale = bx.iter().chain(&by).fold(0.0f64, |s, v| s.max(v.abs()));
        let err = ax.iter().zip(&bx).chain(ay.iter().zip(&by)).fold(0.0f64, |s, (x, y)| s.max((x - y).abs()));
        assert!(scale > 0.0 && err <= 1e-5 * scale, "f32 vs f64: {err} vs {scale}");
        assert!(err > 0.0, "the f32 path was not used");
    }

    #[test]
    fn preconditioner_is_the_periodised_inverse_whatever_the_fft_length() {
        // M by its definition, with explicit DFT sums instead of rustfft: the symbols of the
        // tangential A at period (2 mx, 2 my), clamped (diagonal to 1e-3 of the largest, coupling
        // to 0.99 of the diagonal's geometric mean), their 2x2 inverses, back to the grid. M
        // itself is applied by FFTs of another length (2^a 3^b >= 2 m - 1).
        let (mx, my) = (5, 4);
        let k = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let (px, py) = (2 * mx, 2 * my);
        let tau = 2.0 * std::f64::consts::PI;
        let phase = |kx: usize, ky: usize, di: isize, dj: isize| {
            tau * (kx as f64 * di as f64 / px as f64 + ky as f64 * dj as f64 / py as f64)
        };
        let offsets: Vec<(isize, isize)> = (-(my as isize - 1)..my as isize)
            .flat_map(|dj| (-(mx as isize - 1)..mx as isize).map(move |di| (di, dj)))
            .collect();
        let symbol = |comp: &[f64], kx: usize, ky: usize| {
            offsets.iter().map(|&(di, dj)| comp[k.index(di, dj)] * phase(kx, ky, di, dj).cos()).sum::<f64>()
        };
        let freqs: Vec<(usize, usize)> = (0..py).flat_map(|ky| (0..px).map(move |kx| (kx, ky))).collect();
        let sym: Vec<[f64; 3]> = freqs
            .iter()
            .map(|&(kx, ky)| [symbol(&k.xx, kx, ky), symbol(&k.yy, kx, ky), symbol(&k.xy, kx, ky)])
            .collect();
        let amax = sym.iter().fold(0.0f64, |m, s| m.max(s[0]).max(s[1]));
        let inv: Vec<[f64; 3]> = sym
            .iter()
            .map(|s| {
                let (a, d) = (s[0].max(1e-3 * amax), s[1].max(1e-3 * amax));
                let lim = 0.99 * (a * d).sqrt();
                let b = s[2].clamp(-lim, lim);
                let det = a * d - b * b;
                [d / det, a / det, -b / det]
            })
            .collect();
        assert!(sym.iter().any(|s| s[0] < 1e-3 * amax), "the clamp is exercised");
        let mut m = Convolver::inverse_of(&k).unwrap();
        m.fft32 = None;
        let n = mx * my;
        let (mut worst, mut scale) = (0.0f64, 0.0f64);
        for src in 0..n {
            for comp in 0..2 {
                let (mut sx, mut sy) = (vec![0.0; n], vec![0.0; n]);
                [&mut sx, &mut sy][comp][src] = 1.0;
                let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
                m.tangential(&sx, &sy, None, &mut ux, &mut uy).unwrap();
                for dst in 0..n {
                    let di = (dst % mx) as isize - (src % mx) as isize;
                    let dj = (dst / mx) as isize - (src / mx) as isize;
                    let (mut ex, mut ey) = (0.0, 0.0);
                    for (&(kx, ky), s) in freqs.iter().zip(&inv) {
                        let c = phase(kx, ky, di, dj).cos() / (px * py) as f64;
                        let (xcol, ycol) = if comp == 0 { (s[0], s[2]) } else { (s[2], s[1]) };
                        ex += xcol * c;
                        ey += ycol * c;
                    }
                    worst = worst.max((ux[dst] - ex).abs()).max((uy[dst] - ey).abs());
                    scale = scale.max(ex.abs()).max(ey.abs());
                }
            }
        }
        assert!(scale > 0.0 && worst <= 1e-9 * scale, "M against its definition: {worst} (entries up to {scale})");
    }

    #[test]
    fn direct_matches_dense_matrix() {
        let (mx, my) = (6, 5);
        let k = Kernel::new(mx, my, 0.7, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let mut c = Convolver::new(&k, ConvPath::Direct).unwrap();
        let n = mx * my;
        let mut rng = Rng(7);
        let px: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        let py: Vec<f64> = (0..n).map(|_| rng.next()).collect();
        let (mut ux, mut uy) = (vec![0.0; n], vec![0.0; n]);
        c.tangential(&px, &py, None, &mut ux, &mut uy).unwrap();
        for j in 0..my {
            for i in 0..mx {
                let (mut sx, mut sy) = (0.0, 0.0);
                for jj in 0..my {
                    for ii in 0..mx {
                        let (_, xx, yy, xy) = k.coeffs(i, j, ii, jj);
                        let q = jj * mx + ii;
                        sx += xx * px[q] + xy * py[q];
                        sy += xy * px[q] + yy * py[q];
                    }
                }
                assert!((sx - ux[j * mx + i]).abs() < 1e-18);
                assert!((sy - uy[j * mx + i]).abs() < 1e-18);
            }
        }
        assert!(c.normal(&px[1..], None, &mut ux).is_err());
    }
}
