//! An interface (third-body) layer between the bodies, in series with the half-spaces (CONTACT's
//! M = 4, user guide "Interfacial layer of contaminants"): the layer shears elastically,
//! `u = p h3/G3`, where the traction acts, so its flexibility `h3/G3` [mm/MPa] adds to the
//! tangential self-influence `Axx`, `Ayy` of every element (CONTACT `m_aijpj.f90`, `flx_3bl`); the
//! normal direction and the cross terms are unchanged. The layer is carried by the material: in
//! the kernel of the displacement at the material's previous position (shifted by `dq` along the
//! rolling direction, [`Kernel::rolling`]) it adds to the element that held that material, so
//! that steady rolling's `A - A_s` differences the layer's displacement along the rows as
//! CONTACT's SteadyGS does (`m_solvpt.f90`: `coef = ... + flx` on `dp = p(ix) - p(ix - 1)`).

use super::influence::Kernel;
use super::ContactError;

/// A material position on an element's edge, within this fraction of an element, is shared
/// half and half by the two elements (a shift of an odd number of half elements).
const EDGE: f64 = 1e-9;

/// The elements (offsets along one axis) holding a position `t` elements away, with their weights:
/// the nearest one, or the two an edge separates.
fn holders(t: f64) -> [(isize, f64); 2] {
    let lo = t.floor();
    let frac = t - lo;
    if (frac - 0.5).abs() < EDGE {
        [(lo as isize, 0.5), (lo as isize + 1, 0.5)]
    } else {
        [(t.round() as isize, 1.0), (0, 0.0)]
    }
}

impl Kernel {
    /// The kernel with an interface layer of flexibility `flx_mm_per_mpa` = h3/G3 [mm/MPa] added:
    /// on `Axx`, `Ayy` at the element holding the field point moved by `offset_mm` (the kernel's
    /// own offset: 0 for `A`, `dq` along the rolling direction for `A_s`). A point beyond the grid
    /// (material that entered the grid during the step) gets nothing: it carried no traction.
    pub fn with_layer(mut self, flx_mm_per_mpa: f64, offset_mm: [f64; 2]) -> Result<Kernel, ContactError> {
        if !(flx_mm_per_mpa.is_finite() && flx_mm_per_mpa >= 0.0) {
            return Err(ContactError::OutOfRange {
                name: "interface layer flexibility h3/G3 [mm/MPa]",
                value: flx_mm_per_mpa,
                requirement: "finite and >= 0",
            });
        }
        if let Some(&value) = offset_mm.iter().find(|v| !v.is_finite()) {
            return Err(ContactError::OutOfRange { name: "layer offset [mm]", value, requirement: "finite" });
        }
        if flx_mm_per_mpa == 0.0 {
            return Ok(self);
        }
        let (mx, my) = (self.mx as isize, self.my as isize);
        for (di, wx) in holders(offset_mm[0] / self.dx_mm) {
            for (dj, wy) in holders(offset_mm[1] / self.dy_mm) {
                let w = wx * wy;
                if w == 0.0 || di.abs() >= mx || dj.abs() >= my {
                    continue;
                }
                let k = self.index(di, dj);
                self.xx[k] += w * flx_mm_per_mpa;
                self.yy[k] += w * flx_mm_per_mpa;
            }
        }
        Ok(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_layer_adds_its_flexibility_where_the_material_was() {
        let (dx, dy, flx) = (0.5, 0.4, 1.25 / 8200.0);
        let k0 = Kernel::new(5, 4, dx, dy, 82000.0, 0.28, 0.0).unwrap();
        let with = k0.clone().with_layer(flx, [0.0, 0.0]).unwrap();
        let c = k0.index(0, 0);
        assert_eq!(with.xx[c], k0.xx[c] + flx);
        assert_eq!(with.yy[c], k0.yy[c] + flx);
        // Nothing else changes: the normal direction, the coupling, the other elements.
        assert_eq!((&with.zz, &with.xy), (&k0.zz, &k0.xy));
        let changed = with.xx.iter().zip(&k0.xx).filter(|(a, b)| a != b).count();
        assert_eq!(changed, 1);
        // Shifted by one element (steady rolling, dq = dx): the upstream neighbour's entry.
        let ks = Kernel::new(5, 4, dx, dy, 82000.0, 0.28, dx).unwrap();
        let with_s = ks.clone().with_layer(flx, [dx, 0.0]).unwrap();
        let u = ks.index(1, 0);
        assert_eq!(with_s.xx[u], ks.xx[u] + flx);
        assert_eq!(with_s.xx[ks.index(0, 0)], ks.xx[ks.index(0, 0)]);
        // Half an element: shared by the two elements the edge separates.
        let half = ks.clone().with_layer(flx, [0.5 * dx, 0.0]).unwrap();
        assert_eq!(half.yy[ks.index(0, 0)], ks.yy[ks.index(0, 0)] + 0.5 * flx);
        assert_eq!(half.yy[u], ks.yy[u] + 0.5 * flx);
        // Beyond the grid: nothing.
        assert_eq!(ks.clone().with_layer(flx, [5.0 * dx, 0.0]).unwrap(), ks);
        assert!(k0.clone().with_layer(-1.0, [0.0, 0.0]).is_err());
        assert!(k0.with_layer(flx, [f64::NAN, 0.0]).is_err());
    }
}
