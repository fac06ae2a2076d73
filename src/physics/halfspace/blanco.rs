//! Blanco-Lorenzo's correction of the half-space influence coefficients for conformal contact
//! (CONTACT's C3 = 4, `m_inflcf.f90` `influe_blanco`; user guide, "conformal contact"): on a
//! curved reference whose rows j are inclined by α_j about the rolling direction x, the
//! displacement at element I of a traction at element J is the half-space's `A(I − J)` computed in
//! J's tangent plane, turned into I's (variant 3, `u_I = R(α_J − α_I) A p_J`: the lateral and
//! normal rows turned, the longitudinal one kept). Where every row has the same inclination the
//! coefficients are the half-space's. The turn couples the normal and the tangential problems
//! even for one material: a pressure displaces the surfaces laterally and a lateral traction
//! normally.
//!
//! The coefficients depend on the rows of I and J, not on their offset alone; with
//! `cos(α_J − α_I) = c_J c_I + s_J s_I` and `sin(α_J − α_I) = s_J c_I − c_J s_I` the product is
//! still four FFT convolutions of the tractions weighted by each source row's `c_J = cos α_J`,
//! `s_J = sin α_J` ([`BlancoProduct`]); [`direct_product`] sums every pair of elements for any
//! variant (CONTACT's `influe_blanco1`, one matrix per source row).

use super::convolution::Convolver;
use super::influence::Kernel;
use super::ContactError;

/// How each grid row's inclination is taken from the table `(y_i, α_i)` (CONTACT's IF_METH).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Inclination {
    /// IF_METH = 0: the least-squares line α = c0 + c1 y through the table, at each row's y.
    Linear,
    /// IF_METH = 1: the table interpolated linearly at each row's y (extrapolated beyond its ends).
    #[default]
    Interpolated,
}

impl Inclination {
    /// CONTACT's IF_METH of the method.
    pub fn if_meth(self) -> u8 {
        match self {
            Inclination::Linear => 0,
            Inclination::Interpolated => 1,
        }
    }
}

/// The variant of the correction this crate computes: CONTACT's VARIANT = 3 ("halfspace at J",
/// `u_I = R(α_J − α_I) A_IJ p_J`), the one CONTACT's public decks use.
pub const VARIANT: u8 = 3;

/// The correction as a scene asks for it (`[material] blanco_inclination`, `blanco_variant`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Blanco {
    pub inclination: Inclination,
    /// CONTACT's VARIANT (1–4; [`BlancoProduct`] computes [`VARIANT`]).
    pub variant: u8,
}

/// Each grid row's inclination α [rad] at the rows' lateral places `rows_y_mm` from the table
/// `table` of `(y_i [mm], α_i [rad])` in ascending y (CONTACT's `influe_blanco`: IF_METH 0 fits a
/// line, 1 interpolates, the end segments extended).
pub fn row_inclinations(method: Inclination, table: &[[f64; 2]], rows_y_mm: &[f64]) -> Result<Vec<f64>, ContactError> {
    if table.len() < 2 {
        return Err(ContactError::OutOfRange {
            name: "surface inclination table rows",
            value: table.len() as f64,
            requirement: ">= 2",
        });
    }
    if let Some(k) = table.iter().position(|r| !r[0].is_finite() || !r[1].is_finite()) {
        return Err(ContactError::NotFinite { name: "surface inclination table", index: k });
    }
    if table.windows(2).any(|w| w[1][0] <= w[0][0]) {
        return Err(ContactError::OutOfRange {
            name: "surface inclination table y",
            value: f64::NAN,
            requirement: "strictly ascending",
        });
    }
    Ok(match method {
        Inclination::Linear => {
            let (c0, c1) = least_squares_line(table);
            rows_y_mm.iter().map(|y| c0 + c1 * y).collect()
        }
        Inclination::Interpolated => rows_y_mm.iter().map(|&y| interpolated(table, y)).collect(),
    })
}

/// The least-squares line `α = c0 + c1 y` through the table (IF_METH = 0's normal equations).
fn least_squares_line(table: &[[f64; 2]]) -> (f64, f64) {
    let n = table.len() as f64;
    let (sy, syy) = (table.iter().map(|r| r[0]).sum::<f64>(), table.iter().map(|r| r[0] * r[0]).sum::<f64>());
    let (sa, sya) = (table.iter().map(|r| r[1]).sum::<f64>(), table.iter().map(|r| r[0] * r[1]).sum::<f64>());
    let det = n * syy - sy * sy;
    ((syy * sa - sy * sya) / det, (n * sya - sy * sa) / det)
}

/// The table interpolated linearly at `y`, its first and last segments extended beyond its ends.
fn interpolated(table: &[[f64; 2]], y: f64) -> f64 {
    let last = table.len() - 2;
    let j = table[1..=last].iter().take_while(|r| y >= r[0]).count().min(last);
    let ([y0, a0], [y1, a1]) = (table[j], table[j + 1]);
    a0 + (y - y0) * (a1 - a0) / (y1 - y0)
}

/// One pair's corrected 3 × 3 coefficients `B[i][j]` (i the displacement's, j the traction's
/// component: x, s, n) from the half-space's `a` for the turn `alpha_rad` = α_J − α_I of the
/// source row against the field row (CONTACT's `influe_blanco1`, VARIANT 1–4).
pub fn corrected_block(variant: u8, a: &[[f64; 3]; 3], alpha_rad: f64) -> Result<[[f64; 3]; 3], ContactError> {
    let (sn, cs) = alpha_rad.sin_cos();
    let (snb, csb) = (0.5 * alpha_rad).sin_cos();
    let (x, s, n) = (0, 1, 2);
    let mut b = *a;
    match variant {
        // 1: Blanco's formulas, the traction turned (columns s and n); 2: column n's x kept.
        1 | 2 => {
            for i in 0..3 {
                b[i][s] = a[i][s] * cs + a[i][n] * sn;
                b[i][n] = a[i][n] * cs - a[i][s] * sn;
            }
            if variant == 2 {
                b[x][n] = a[x][n];
            }
        }
        // 3: the half-space at J, its displacement turned into I's frame (rows s and n).
        3 => {
            for j in 0..3 {
                b[s][j] = a[s][j] * cs - a[n][j] * sn;
                b[n][j] = a[s][j] * sn + a[n][j] * cs;
            }
        }
        // 4: the split formula, turned by half the angle on either side.
        4 => {
            let (aspn, asmn) = (0.5 * (a[s][s] + a[n][n]), 0.5 * (a[s][s] - a[n][n]));
            b[x][s] = a[x][s] * csb + a[x][n] * snb;
            b[x][n] = a[x][n] * csb - a[x][s] * snb;
            b[s][x] = a[x][s] * csb + a[x][n] * snb;
            b[s][s] = asmn + aspn * cs + a[s][n] * sn;
            b[s][n] = a[s][n] * cs - aspn * sn;
            b[n][x] = a[x][s] * snb - a[x][n] * csb;
            b[n][s] = aspn * sn - a[s][n] * cs;
            b[n][n] = -asmn + aspn * cs + a[s][n] * sn;
        }
        v => {
            return Err(ContactError::OutOfRange {
                name: "Blanco variant",
                value: f64::from(v),
                requirement: "1, 2, 3 or 4",
            })
        }
    }
    Ok(b)
}

/// The half-space's 3 × 3 coefficients of `kernel` at offset `(di, dj)` (one material: no
/// normal–tangential coupling).
fn halfspace_block(kernel: &Kernel, di: isize, dj: isize) -> [[f64; 3]; 3] {
    let k = kernel.index(di, dj);
    [[kernel.xx[k], kernel.xy[k], 0.0], [kernel.xy[k], kernel.yy[k], 0.0], [0.0, 0.0, kernel.zz[k]]]
}

/// `u = B p` by the direct sum over every pair of elements (x, s, n components; grid order, row
/// `j` of element `k` = `k / mx` inclined by `alpha_rows[j]`), any variant: the reference of
/// [`BlancoProduct`].
pub fn direct_product(
    kernel: &Kernel,
    alpha_rows: &[f64],
    variant: u8,
    p: [&[f64]; 3],
) -> Result<[Vec<f64>; 3], ContactError> {
    let (mx, my) = (kernel.mx, kernel.my);
    check_rows(alpha_rows, my)?;
    let n = mx * my;
    for (name, f) in [("px", p[0]), ("ps", p[1]), ("pn", p[2])] {
        if f.len() != n {
            return Err(ContactError::SizeMismatch { name, len: f.len(), expected: n });
        }
    }
    let mut u = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    for field in 0..n {
        let (i, j) = ((field % mx) as isize, field / mx);
        let sources = p[0].iter().zip(p[1]).zip(p[2]).enumerate();
        for (source, ((&px, &ps), &pn)) in sources {
            let (ii, jj) = ((source % mx) as isize, source / mx);
            let a = halfspace_block(kernel, i - ii, j as isize - jj as isize);
            let b = corrected_block(variant, &a, alpha_rows[jj] - alpha_rows[j])?;
            for (c, uc) in u.iter_mut().enumerate() {
                uc[field] += b[c][0] * px + b[c][1] * ps + b[c][2] * pn;
            }
        }
    }
    Ok(u)
}

/// The rows' inclinations: one per grid row, finite.
fn check_rows(alpha_rows: &[f64], my: usize) -> Result<(), ContactError> {
    if alpha_rows.len() != my {
        return Err(ContactError::SizeMismatch { name: "row inclinations", len: alpha_rows.len(), expected: my });
    }
    match alpha_rows.iter().position(|a| !a.is_finite()) {
        Some(k) => Err(ContactError::NotFinite { name: "row inclinations", index: k }),
        None => Ok(()),
    }
}

/// `u = B p` of variant 3 on one grid by FFT: `u_x = (A p)_x`, and with `T = A_sx px + A_ss ps`,
/// `N = A_nn pn` convolved with the tractions weighted by the source row's cos and sin,
/// `u_s = c_I (T[c p] − N[s p]) + s_I (T[s p] + N[c p])`,
/// `u_n = c_I (T[s p] + N[c p]) + s_I (N[s p] − T[c p])`.
pub struct BlancoProduct {
    conv: Convolver,
    mx: usize,
    cos_rows: Vec<f64>,
    sin_rows: Vec<f64>,
    wx: Vec<f64>,
    ws: Vec<f64>,
    wn: Vec<f64>,
    tx: Vec<f64>,
    tc: Vec<f64>,
    ts: Vec<f64>,
    nc: Vec<f64>,
    ns: Vec<f64>,
}

impl BlancoProduct {
    /// The product of `kernel`'s grid with row `j` inclined by `alpha_rows[j]` [rad].
    pub fn new(kernel: &Kernel, alpha_rows: &[f64]) -> Result<BlancoProduct, ContactError> {
        check_rows(alpha_rows, kernel.my)?;
        let n = kernel.mx * kernel.my;
        let z = || vec![0.0; n];
        Ok(BlancoProduct {
            conv: Convolver::auto(kernel)?,
            mx: kernel.mx,
            cos_rows: alpha_rows.iter().map(|a| a.cos()).collect(),
            sin_rows: alpha_rows.iter().map(|a| a.sin()).collect(),
            wx: z(),
            ws: z(),
            wn: z(),
            tx: z(),
            tc: z(),
            ts: z(),
            nc: z(),
            ns: z(),
        })
    }

    /// The rows' inclinations changed to `alpha_rows` [rad] (the kernel kept).
    pub fn set_rows(&mut self, alpha_rows: &[f64]) -> Result<(), ContactError> {
        check_rows(alpha_rows, self.cos_rows.len())?;
        self.cos_rows = alpha_rows.iter().map(|a| a.cos()).collect();
        self.sin_rows = alpha_rows.iter().map(|a| a.sin()).collect();
        Ok(())
    }

    /// `u = B p` [mm] for the tractions `p = (px, ps, pn)` [MPa] (grid order).
    pub fn apply(&mut self, p: [&[f64]; 3], u: [&mut [f64]; 3]) -> Result<(), ContactError> {
        let [ux, us, un] = u;
        // u_x and the plain T are not needed apart: u_x from the unweighted tangential product.
        self.conv.tangential(p[0], p[1], None, ux, &mut self.tc)?;
        self.weighted(p, true)?;
        self.conv.tangential(&self.wx, &self.ws, None, &mut self.tx, &mut self.tc)?;
        self.conv.normal(&self.wn, None, &mut self.nc)?;
        self.weighted(p, false)?;
        self.conv.tangential(&self.wx, &self.ws, None, &mut self.tx, &mut self.ts)?;
        self.conv.normal(&self.wn, None, &mut self.ns)?;
        for k in 0..ux.len() {
            let (c, s) = (self.cos_rows[k / self.mx], self.sin_rows[k / self.mx]);
            us[k] = c * (self.tc[k] - self.ns[k]) + s * (self.ts[k] + self.nc[k]);
            un[k] = c * (self.ts[k] + self.nc[k]) + s * (self.ns[k] - self.tc[k]);
        }
        Ok(())
    }

    /// The tractions weighted by their row's cos (`cos`) or sin into `wx, ws, wn`.
    fn weighted(&mut self, p: [&[f64]; 3], cos: bool) -> Result<(), ContactError> {
        let n = self.wx.len();
        for (name, f) in [("px", p[0]), ("ps", p[1]), ("pn", p[2])] {
            if f.len() != n {
                return Err(ContactError::SizeMismatch { name, len: f.len(), expected: n });
            }
        }
        let rows = if cos { &self.cos_rows } else { &self.sin_rows };
        for k in 0..n {
            let w = rows[k / self.mx];
            (self.wx[k], self.ws[k], self.wn[k]) = (w * p[0][k], w * p[1][k], w * p[2][k]);
        }
        Ok(())
    }

    /// The correction `(B − A) p` [mm] of the half-space's displacements (x, s, n).
    pub fn correction(&mut self, p: [&[f64]; 3]) -> Result<[Vec<f64>; 3], ContactError> {
        let n = self.wx.len();
        let mut u = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        {
            let [ux, us, un] = &mut u;
            self.apply(p, [ux, us, un])?;
        }
        let (mut ax, mut as_, mut an) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        self.conv.tangential(p[0], p[1], None, &mut ax, &mut as_)?;
        self.conv.normal(p[2], None, &mut an)?;
        for k in 0..n {
            u[0][k] -= ax[k];
            u[1][k] -= as_[k];
            u[2][k] -= an[k];
        }
        Ok(u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fields(n: usize) -> [Vec<f64>; 3] {
        [
            (0..n).map(|k| ((k * 5 % 11) as f64) * 0.1 - 0.5).collect(),
            (0..n).map(|k| ((k * 3 % 7) as f64) * 0.1 - 0.3).collect(),
            (0..n).map(|k| ((k * 7 % 13) as f64) * 0.1).collect(),
        ]
    }

    fn kernel(mx: usize, my: usize) -> Kernel {
        Kernel::new(mx, my, 0.3, 0.25, 80000.0, 0.28, 0.0).unwrap()
    }

    #[test]
    fn a_flat_surface_has_the_half_space_coefficients_in_every_variant() {
        // α the same on every row (a flat surface, however inclined): B = A, the correction 0 (a
        // block of the half-space's form: A_sx = A_xs, A_nx = −A_xn, A_ns = −A_sn, as variant 4 takes).
        let a = [[1.0, 0.2, 0.05], [0.2, 0.9, -0.07], [-0.05, 0.07, 1.4]];
        for variant in 1..=4 {
            let b = corrected_block(variant, &a, 0.0).unwrap();
            let same = b.iter().flatten().zip(a.iter().flatten()).all(|(x, y)| (x - y).abs() <= 1e-15);
            assert!(same, "variant {variant}: {b:?}");
        }
        let (mx, my) = (9, 7);
        let k = kernel(mx, my);
        let p = fields(mx * my);
        let p = [p[0].as_slice(), p[1].as_slice(), p[2].as_slice()];
        let (mut ax, mut ay, mut an) = (vec![0.0; mx * my], vec![0.0; mx * my], vec![0.0; mx * my]);
        let mut c = Convolver::auto(&k).unwrap();
        c.tangential(p[0], p[1], None, &mut ax, &mut ay).unwrap();
        c.normal(p[2], None, &mut an).unwrap();
        let flat = vec![0.37; my];
        for variant in 1..=4 {
            let u = direct_product(&k, &flat, variant, p).unwrap();
            for (got, want) in u.iter().zip([&ax, &ay, &an]) {
                assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-12 * w.abs().max(1e-6)), "{variant}");
            }
        }
        let mut b = BlancoProduct::new(&k, &flat).unwrap();
        let d = b.correction(p).unwrap();
        let scale = an.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(d.iter().flatten().all(|v| v.abs() <= 1e-13 * scale), "{d:?}");
    }

    #[test]
    fn the_fft_product_is_the_direct_sum_of_variant_3_on_a_curved_surface() {
        let (mx, my) = (11, 9);
        let k = kernel(mx, my);
        let alpha: Vec<f64> = (0..my).map(|j| 0.45 - 0.11 * j as f64).collect();
        let p = fields(mx * my);
        let p = [p[0].as_slice(), p[1].as_slice(), p[2].as_slice()];
        let want = direct_product(&k, &alpha, VARIANT, p).unwrap();
        let n = mx * my;
        let (mut ux, mut us, mut un) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        BlancoProduct::new(&k, &alpha).unwrap().apply(p, [&mut ux, &mut us, &mut un]).unwrap();
        let scale = want[2].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for (got, want) in [&ux, &us, &un].into_iter().zip(&want) {
            assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-12 * scale));
        }
        // The turn couples the problems: a pressure alone displaces the surfaces laterally.
        let zero = vec![0.0; n];
        let u = direct_product(&k, &alpha, VARIANT, [&zero, &zero, p[2]]).unwrap();
        assert!(u[1].iter().any(|v| v.abs() > 1e-3 * scale) && u[0].iter().all(|v| *v == 0.0));
    }

    #[test]
    fn inclinations_of_the_rows_interpolated_or_fitted() {
        let table = [[-1.0, 0.2], [0.0, 0.0], [1.0, -0.1]];
        let rows = [-1.5, -0.5, 0.0, 0.5, 2.0];
        let a = row_inclinations(Inclination::Interpolated, &table, &rows).unwrap();
        let want = [0.3, 0.1, 0.0, -0.05, -0.2];
        assert!(a.iter().zip(want).all(|(a, w)| (a - w).abs() < 1e-15), "{a:?}");
        // The line through three points: slope -0.15, mean 0.1/3 at y = 0.
        let l = row_inclinations(Inclination::Linear, &table, &[0.0, 1.0]).unwrap();
        assert!((l[0] - 0.1 / 3.0).abs() < 1e-15 && (l[1] - (0.1 / 3.0 - 0.15)).abs() < 1e-15, "{l:?}");
        assert!(row_inclinations(Inclination::Linear, &table[..1], &rows).is_err());
        assert!(corrected_block(5, &[[0.0; 3]; 3], 0.1).is_err());
    }
}
