//! The normal–tangential coupling of two dissimilar bodies (Kalker's difference parameter
//! `K != 0`; Kalker 1990 sec. 1.5, 5.2): the tangential displacement difference of a pressure,
//! `u_t = A_tz pn`, and the normal one of a tangential traction, `u_n = A_zt p_t = -(Axz px + Ayz py)`,
//! by FFT ([`Convolver`]) with the [`CrossKernel`] coefficients, at the current position of the
//! material and at its previous one (rolling: the kernel shifted by `dq` along the motion).

use super::convolution::Convolver;
use super::influence::CrossKernel;
use super::ContactError;

/// The products of one grid's cross kernel (unshifted, or shifted to the material's previous
/// position) with a pressure or a tangential traction.
pub struct Coupling {
    xz: Convolver,
    yz: Convolver,
    n: usize,
    buf: Vec<f64>,
}

impl Coupling {
    /// The coupling of an `mx x my` grid of `dx x dy` [mm] elements, combined shear modulus
    /// `g_mpa` [MPa], difference parameter `k`, field point shifted by `offset_mm` [mm].
    pub fn new(
        (mx, my): (usize, usize),
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, k): (f64, f64),
        offset_mm: [f64; 2],
    ) -> Result<Coupling, ContactError> {
        let ck = CrossKernel::new((mx, my), (dx_mm, dy_mm), (g_mpa, k), offset_mm)?;
        let xz = Convolver::auto(&ck.as_scalar(&ck.xz, (dx_mm, dy_mm)))?;
        let yz = Convolver::auto(&ck.as_scalar(&ck.yz, (dx_mm, dy_mm)))?;
        Ok(Coupling { xz, yz, n: mx * my, buf: vec![0.0; mx * my] })
    }

    /// `(ux, uy) = A_tz pn` [mm] for the pressure `pn` [MPa] on every element.
    pub fn of_pressure(&mut self, pn: &[f64], ux: &mut [f64], uy: &mut [f64]) -> Result<(), ContactError> {
        self.xz.normal(pn, None, ux)?;
        self.yz.normal(pn, None, uy)
    }

    /// `un = A_zt p_t = -(Axz px + Ayz py)` [mm] for the tangential traction `(px, py)` [MPa].
    pub fn of_traction(&mut self, px: &[f64], py: &[f64], un: &mut [f64]) -> Result<(), ContactError> {
        if un.len() != self.n {
            return Err(ContactError::SizeMismatch { name: "un", len: un.len(), expected: self.n });
        }
        self.xz.normal(px, None, un)?;
        self.yz.normal(py, None, &mut self.buf)?;
        for (u, b) in un.iter_mut().zip(&self.buf) {
            *u = -(*u + b);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::halfspace::influence::Kernel;

    #[test]
    fn products_are_the_direct_sums() {
        // Against the direct double sum over the cross kernel; and Betti's reciprocity: the work of
        // the pressure on the traction's normal displacement equals the traction's on the
        // pressure's tangential one, pn . u_n(p_t) = p_t . u_t(pn).
        let (mx, my, dx, dy) = (12, 11, 0.3, 0.4);
        let mut c = Coupling::new((mx, my), (dx, dy), (1.0, 0.3), [0.0, 0.0]).unwrap();
        let ck = CrossKernel::new((mx, my), (dx, dy), (1.0, 0.3), [0.0, 0.0]).unwrap();
        let index = Kernel::new(mx, my, dx, dy, 1.0, 0.0, 0.0).unwrap();
        let n = mx * my;
        let pn: Vec<f64> = (0..n).map(|k| ((k * 7 % 13) as f64) * 0.1).collect();
        let px: Vec<f64> = (0..n).map(|k| ((k * 5 % 11) as f64) * 0.1 - 0.5).collect();
        let py: Vec<f64> = (0..n).map(|k| ((k * 3 % 7) as f64) * 0.1 - 0.3).collect();
        let (mut ux, mut uy, mut un) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        c.of_pressure(&pn, &mut ux, &mut uy).unwrap();
        c.of_traction(&px, &py, &mut un).unwrap();
        for f in 0..n {
            let (i, j) = ((f % mx) as isize, (f / mx) as isize);
            let (mut sx, mut sy, mut sn) = (0.0, 0.0, 0.0);
            for s in 0..n {
                let (ii, jj) = ((s % mx) as isize, (s / mx) as isize);
                let q = index.index(i - ii, j - jj);
                sx += ck.xz[q] * pn[s];
                sy += ck.yz[q] * pn[s];
                sn -= ck.xz[q] * px[s] + ck.yz[q] * py[s];
            }
            assert!((ux[f] - sx).abs() < 1e-13 && (uy[f] - sy).abs() < 1e-13 && (un[f] - sn).abs() < 1e-13);
        }
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let (w_n, w_t) = (dot(&un, &pn), dot(&ux, &px) + dot(&uy, &py));
        assert!(w_t.abs() > 1e-3 && (w_n - w_t).abs() < 1e-12 * w_t.abs(), "{w_n} {w_t}");
    }
}
