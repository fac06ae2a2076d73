//! A thin compressible sheet on the surface (CONTACT's B = 1, user guide "Compressible sheet"):
//! the normal part of Kalker's first-order theory, `u_z = L_z p_n` in the element that carries the
//! pressure, in series with the half-spaces, so `L_z` [mm³/N = mm/MPa] adds to the normal
//! self-influence `Azz` of every element (CONTACT `m_aijpj.f90`, `flx_z`); the tangential
//! directions and the cross terms are unchanged.

use super::influence::Kernel;
use super::ContactError;

impl Kernel {
    /// The kernel with a compressible sheet of flexibility `flx_mm3_per_n` = L_z added to `Azz`
    /// at offset (0, 0); 0 is no sheet.
    pub fn with_sheet(mut self, flx_mm3_per_n: f64) -> Result<Kernel, ContactError> {
        if !(flx_mm3_per_n.is_finite() && flx_mm3_per_n >= 0.0) {
            return Err(ContactError::OutOfRange {
                name: "compressible sheet flexibility L_z [mm^3/N]",
                value: flx_mm3_per_n,
                requirement: "finite and >= 0",
            });
        }
        let k = self.index(0, 0);
        self.zz[k] += flx_mm3_per_n;
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::super::normal::{NormalParams, NormalSolver};
    use super::*;

    #[test]
    fn the_sheet_adds_its_flexibility_to_the_normal_self_influence_alone() {
        let k0 = Kernel::new(5, 4, 0.5, 0.4, 82000.0, 0.28, 0.0).unwrap();
        let with = k0.clone().with_sheet(7.429e-5).unwrap();
        let c = k0.index(0, 0);
        assert_eq!(with.zz[c], k0.zz[c] + 7.429e-5);
        assert_eq!(with.zz.iter().zip(&k0.zz).filter(|(a, b)| a != b).count(), 1);
        assert_eq!((&with.xx, &with.yy, &with.xy), (&k0.xx, &k0.yy, &k0.xy));
        assert_eq!(k0.clone().with_sheet(0.0).unwrap(), k0);
        assert!(k0.clone().with_sheet(-1.0).is_err());
        assert!(k0.with_sheet(f64::NAN).is_err());
    }

    /// A sheet on a (nearly) rigid half-space is a Winkler foundation: p = (δ − h)/L_z where the
    /// bodies overlap, so a sphere of radius R pressed by δ carries FN = π R δ² / L_z (the
    /// integral of (δ − r²/2R)/L_z over r² < 2Rδ).
    #[test]
    fn a_sheet_on_a_rigid_half_space_carries_the_winkler_pressure() {
        let (m, d, r_mm, flx, delta_mm) = (81usize, 0.025, 50.0, 7.429e-5, 0.002);
        let kernel = Kernel::new(m, m, d, d, 1e9, 0.28, 0.0).unwrap().with_sheet(flx).unwrap();
        let centre = |i: usize| (i as f64 + 0.5 - m as f64 / 2.0) * d;
        let h_mm: Vec<f64> = (0..m * m)
            .map(|k| {
                let (x, y) = (centre(k % m), centre(k / m));
                (x * x + y * y) / (2.0 * r_mm)
            })
            .collect();
        let sol =
            NormalSolver::new(&kernel).unwrap().solve_approach(&h_mm, delta_mm, &NormalParams::default()).unwrap();
        // Element by element: the half-space's own compliance (1/(πG) scale, G = 1e9 MPa) is
        // below 1e-6 of the sheet's.
        for (k, p) in sol.pn_mpa.iter().enumerate() {
            let winkler = ((delta_mm - h_mm[k]) / flx).max(0.0);
            assert!((p - winkler).abs() <= 1e-4 * delta_mm / flx, "element {k}: {p} against {winkler}");
        }
        // The total against the closed form: the grid's sum of the exact pressure differs from
        // the integral by the discretisation of the rim (below 0.5 % on this grid).
        let fn_n: f64 = sol.pn_mpa.iter().sum::<f64>() * d * d;
        let closed = std::f64::consts::PI * r_mm * delta_mm * delta_mm / flx;
        assert!((fn_n / closed - 1.0).abs() < 5e-3, "FN {fn_n} N against {closed} N");
    }
}
