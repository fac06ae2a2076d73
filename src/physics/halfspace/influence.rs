//! Influence coefficients of a uniformly loaded `dx x dy` rectangle on the surface of an elastic
//! half-space, combined for two identical bodies (closed forms of Boussinesq and Cerruti
//! integrated over the rectangle; Kalker 1990, sec. 5.2; Johnson, "Contact Mechanics", eqs. 3.19
//! and 3.75). Units: coefficients in mm/MPa (displacement in mm per traction in MPa).
//!
//! With `X = x_field - x_source`, `Y = y_field - y_source`, `r = sqrt(X^2 + Y^2)` and `I[f]` the
//! integral of `f(X', Y')` over the source rectangle (`X' in [X - dx/2, X + dx/2]`, likewise `Y'`):
//!
//! * `Azz = (1-nu)/(pi G) I[1/r]`
//! * `Axx = 1/(pi G) (I[X^2/r^3] + (1-nu) I[Y^2/r^3])`
//! * `Ayy = 1/(pi G) (I[Y^2/r^3] + (1-nu) I[X^2/r^3])`
//! * `Axy = Ayx = nu/(pi G) I[XY/r^3]`
//!
//! `G` is the combined shear modulus [MPa] and `nu` Poisson's ratio of the (identical) bodies.
//!
//! The grid's x runs against CONTACT's (`x_C = −x`, [`crate::physics::Grid`]) while the tangential
//! components are CONTACT's flipped ones (the references' sign convention): of the formulas above,
//! written in CONTACT's frame, only `Axy` is odd in X, so in grid coordinates it changes sign.

use super::table;
use super::visco::Relaxation;
use super::ContactError;

/// Antiderivative of `X^2/r^3` (d^2/dXdY): `Y ln(X + r)`, written as `Y asinh(X/|Y|)`; the dropped
/// term `Y ln|Y|` depends on `Y` alone and cancels in the corner double difference. The asinh form
/// has no cancellation where `X + r -> 0` (X < 0, |Y| << |X|).
fn f_xx(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        0.0
    } else {
        y * (x / y.abs()).asinh()
    }
}

/// Antiderivative of `Y^2/r^3`: `X ln(Y + r)` in the asinh form `X asinh(Y/|X|)` (see [`f_xx`]).
fn f_yy(x: f64, y: f64) -> f64 {
    f_xx(y, x)
}

/// Antiderivative of `X Y / r^3`: `-r`.
fn f_xy(x: f64, y: f64) -> f64 {
    -x.hypot(y)
}

/// Antiderivative of `X/r^2` (d^2/dXdY): `Y ln r + X atan(Y/X)` (CONTACT's `j5`, memo m09002),
/// continuous through `X = 0` (`X atan(Y/X) -> 0`) and 0 at the origin.
fn f_xz(x: f64, y: f64) -> f64 {
    let r2 = x * x + y * y;
    if r2 == 0.0 {
        return 0.0;
    }
    let turn = if x == 0.0 { 0.0 } else { x * (y / x).atan() };
    0.5 * y * r2.ln() + turn
}

/// Antiderivative of `Y/r^2`: `X ln r + Y atan(X/Y)` (CONTACT's `j6`), [`f_xz`] with the axes swapped.
fn f_yz(x: f64, y: f64) -> f64 {
    f_xz(y, x)
}

/// Corner double difference `F(X+hx, Y+hy) - F(X-hx, Y+hy) - F(X+hx, Y-hy) + F(X-hx, Y-hy)`,
/// i.e. the integral over the rectangle of the mixed derivative of `F`.
fn double_diff(f: fn(f64, f64) -> f64, x: f64, y: f64, hx: f64, hy: f64) -> f64 {
    // Sum the terms with equal Y first: they are the closest in value.
    (f(x + hx, y + hy) - f(x - hx, y + hy)) - (f(x + hx, y - hy) - f(x - hx, y - hy))
}

/// Integrals of the four Boussinesq/Cerruti integrands over a `dx x dy` rectangle centred at
/// offset `(x, y)` [mm] from the field point; each in mm (they have the dimension of a length).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RectIntegrals {
    /// `I[1/r]` [mm]
    pub one_over_r: f64,
    /// `I[X^2/r^3]` [mm]
    pub xx: f64,
    /// `I[Y^2/r^3]` [mm]
    pub yy: f64,
    /// `I[XY/r^3]` [mm]
    pub xy: f64,
}

/// Closed-form rectangle integrals at offset `X = x`, `Y = y` [mm] for a `dx x dy` [mm] element
/// (Kalker 1990, eq. 5.20: corner double differences of the antiderivatives).
pub fn rect_integrals(x: f64, y: f64, dx: f64, dy: f64) -> RectIntegrals {
    let (hx, hy) = (0.5 * dx, 0.5 * dy);
    if y == 0.0 {
        return on_axis(x, hx, hy);
    }
    let xx = double_diff(f_xx, x, y, hx, hy);
    let yy = double_diff(f_yy, x, y, hx, hy);
    RectIntegrals { one_over_r: xx + yy, xx, yy, xy: double_diff(f_xy, x, y, hx, hy) }
}

/// [`rect_integrals`] at `Y = 0` (the row of a one-row grid, the viscoelastic memory's integrand):
/// at `Y − hy = −hy` the antiderivatives [`f_xx`] and [`f_yy`] are those at `+hy` negated (odd in
/// their `Y`; `asinh` is odd to the bit) and [`f_xy`] is equal, so each double difference is twice
/// one single difference (`D − (−D)`, exact) or zero: the same numbers at half the cost.
fn on_axis(x: f64, hx: f64, hy: f64) -> RectIntegrals {
    let single = |f: fn(f64, f64) -> f64| f(x + hx, hy) - f(x - hx, hy);
    let (xx, yy) = (single(f_xx), single(f_yy));
    let (xx, yy) = (xx + xx, yy + yy);
    RectIntegrals { one_over_r: xx + yy, xx, yy, xy: 0.0 }
}

/// Translation-invariant influence kernel over the grid offsets `di = i - I` in
/// `-(mx-1)..=(mx-1)`, `dj = j - J` in `-(my-1)..=(my-1)`, evaluated at
/// `X = di*dx - shift_mm`, `Y = dj*dy` (a rolling kernel at another direction: shifted in x and y,
/// [`Kernel::rolling`]). Storage index `(dj + my - 1)*(2mx - 1) + (di + mx - 1)`.
/// Coefficients in mm/MPa. `shift_mm = 0` is the ordinary kernel (u = A p); `shift_mm = dq` gives
/// the kernel of the displacement at the previous position of the material (u' = A_s p').
#[derive(Debug, Clone, PartialEq)]
pub struct Kernel {
    /// Elements along x of the grid the kernel serves.
    pub mx: usize,
    /// Elements along y of the grid the kernel serves.
    pub my: usize,
    /// Element size along x [mm].
    pub dx_mm: f64,
    /// Element size along y [mm].
    pub dy_mm: f64,
    /// Shift of the field point against the rolling direction [mm] (0 or dq).
    pub shift_mm: f64,
    /// Normal-normal coefficients `Azz` [mm/MPa].
    pub zz: Vec<f64>,
    /// Tangential `Axx` [mm/MPa].
    pub xx: Vec<f64>,
    /// Tangential `Ayy` [mm/MPa].
    pub yy: Vec<f64>,
    /// Tangential coupling `Axy = Ayx` [mm/MPa].
    pub xy: Vec<f64>,
}

/// How the traction varies over the grid, the influence functions' basis (CONTACT's C digit).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Basis {
    /// Uniform over each element (C = 2): [`rect_integrals`].
    #[default]
    Constant,
    /// Bilinear between the element centres (C = 3): [`super::bilinear::hat_integrals`].
    Bilinear,
}

impl Basis {
    pub fn is_default(&self) -> bool {
        *self == Basis::default()
    }

    /// The integrals of the basis function of the element at offset `(x, y)` [mm].
    fn integrals(self, x: f64, y: f64, dx: f64, dy: f64) -> RectIntegrals {
        match self {
            Basis::Constant => rect_integrals(x, y, dx, dy),
            Basis::Bilinear => super::bilinear::hat_integrals(x, y, dx, dy),
        }
    }
}

/// The cross-influence coefficients of two dissimilar bodies (Kalker's difference parameter
/// `K != 0`, Kalker 1990 eq. 1.44; CONTACT's `cf(:,:,1,3)`, `cf(:,:,2,3)` of `elascf_pcwcns`):
/// the tangential displacement difference per unit pressure,
/// `Axz = -K/(pi G) I[X/r^2]` and `Ayz = +K/(pi G) I[Y/r^2]` [mm/MPa] in grid coordinates (CONTACT's
/// `Axz` is odd in X and keeps its sign under the grid's mirrored x and flipped components, its
/// `Ayz` is even in X and changes sign), and the normal one per unit tangential traction
/// `Azx = -Axz`, `Azy = -Ayz` (Betti's reciprocity). Stored as [`Kernel`]: offsets and layout alike.
#[derive(Debug, Clone, PartialEq)]
pub struct CrossKernel {
    pub mx: usize,
    pub my: usize,
    /// `Axz` [mm/MPa] at each offset, storage as [`Kernel::index`].
    pub xz: Vec<f64>,
    /// `Ayz` [mm/MPa].
    pub yz: Vec<f64>,
}

impl CrossKernel {
    /// The cross coefficients of an `mx x my` grid of `dx x dy` [mm] elements for combined shear
    /// modulus `g_mpa` [MPa] and difference parameter `k` [-], the field point shifted by
    /// `offset_mm` [mm] (`[0, 0]`: the ordinary kernel; `dq towards`: the previous position of the
    /// material, as [`Kernel::rolling`]); uniform tractions over each element (CONTACT's C = 2).
    pub fn new(
        (mx, my): (usize, usize),
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, k): (f64, f64),
        offset_mm: [f64; 2],
    ) -> Result<CrossKernel, ContactError> {
        if mx == 0 || my == 0 {
            return Err(ContactError::EmptyGrid { mx, my });
        }
        for (name, value) in
            [("element size dx [mm]", dx_mm), ("element size dy [mm]", dy_mm), ("shear modulus G [MPa]", g_mpa)]
        {
            if !(value.is_finite() && value > 0.0) {
                return Err(ContactError::OutOfRange { name, value, requirement: "finite and > 0" });
            }
        }
        if !(k.is_finite() && (-0.5..=0.5).contains(&k)) {
            return Err(ContactError::OutOfRange {
                name: "difference parameter K",
                value: k,
                requirement: "in [-0.5, 0.5]",
            });
        }
        let (nkx, nky) = (2 * mx - 1, 2 * my - 1);
        let c = k / (std::f64::consts::PI * g_mpa);
        let (hx, hy) = (0.5 * dx_mm, 0.5 * dy_mm);
        let (mut xz, mut yz) = (Vec::with_capacity(nkx * nky), Vec::with_capacity(nkx * nky));
        for kj in 0..nky {
            let y = (kj as f64 - (my - 1) as f64) * dy_mm - offset_mm[1];
            for ki in 0..nkx {
                let x = (ki as f64 - (mx - 1) as f64) * dx_mm - offset_mm[0];
                xz.push(-c * double_diff(f_xz, x, y, hx, hy));
                yz.push(c * double_diff(f_yz, x, y, hx, hy));
            }
        }
        if xz.iter().chain(&yz).any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("cross-influence coefficients"));
        }
        Ok(CrossKernel { mx, my, xz, yz })
    }

    /// One component as the `zz` part of a [`Kernel`] of the same grid (the others zero), for a
    /// [`super::convolution::Convolver`]'s scalar product `u = A p`.
    pub fn as_scalar(&self, comp: &[f64], (dx_mm, dy_mm): (f64, f64)) -> Kernel {
        let zero = vec![0.0; comp.len()];
        Kernel {
            mx: self.mx,
            my: self.my,
            dx_mm,
            dy_mm,
            shift_mm: 0.0,
            zz: comp.to_vec(),
            xx: zero.clone(),
            yy: zero.clone(),
            xy: zero,
        }
    }
}

impl Kernel {
    /// Builds the kernel for an `mx x my` grid of `dx x dy` [mm] elements, combined shear modulus
    /// `g_mpa` [MPa], Poisson's ratio `nu`, field-point shift `shift_mm` [mm] (Kalker 1990, sec. 5.2).
    pub fn new(
        mx: usize,
        my: usize,
        dx_mm: f64,
        dy_mm: f64,
        g_mpa: f64,
        nu: f64,
        shift_mm: f64,
    ) -> Result<Kernel, ContactError> {
        Kernel::with_basis(mx, my, (dx_mm, dy_mm), (g_mpa, nu), shift_mm, Basis::Constant)
    }

    /// [`Kernel::new`] for tractions of the given [`Basis`] (the same combination of the four
    /// integrals, CONTACT's `elascf` for C = 2 and 3).
    pub fn with_basis(
        mx: usize,
        my: usize,
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, nu): (f64, f64),
        shift_mm: f64,
        basis: Basis,
    ) -> Result<Kernel, ContactError> {
        Kernel::shifted(mx, my, (dx_mm, dy_mm), (g_mpa, nu), shift_mm, [shift_mm, 0.0], (basis, None))
    }

    /// [`Kernel::with_basis`] of two viscoelastic bodies in steady rolling along the grid's +x
    /// (CONTACT's M = 1, [`Relaxation`]): `g_mpa` and `nu` the glassy (instantaneous) constants.
    pub fn viscoelastic(
        mx: usize,
        my: usize,
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, nu): (f64, f64),
        shift_mm: f64,
        (basis, relax): (Basis, Relaxation),
    ) -> Result<Kernel, ContactError> {
        for (name, value) in
            [("viscous compliance ratio FG", relax.ratio), ("relaxation distance V·TC [mm]", relax.distance_mm)]
        {
            if !(value.is_finite() && value >= 0.0) {
                return Err(ContactError::OutOfRange { name, value, requirement: "finite and >= 0" });
            }
        }
        let relax = (!relax.is_elastic()).then_some(relax);
        Kernel::shifted(mx, my, (dx_mm, dy_mm), (g_mpa, nu), shift_mm, [shift_mm, 0.0], (basis, relax))
    }

    /// The kernel of the displacement at the previous position of the material when the bodies
    /// roll `dq_mm` [mm] per step along the unit vector `towards` (grid coordinates: the material
    /// moves by `dq towards` against the contact; CONTACT's previous-traction grid offset
    /// `(xoffs, yoffs)` of `m_inflcf.f90`, any rolling direction CHI): coefficients at
    /// `X = di dx - dq towards_x`, `Y = dj dy - dq towards_y`; `shift_mm` = dq.
    pub fn rolling(
        mx: usize,
        my: usize,
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, nu): (f64, f64),
        (dq_mm, towards): (f64, [f64; 2]),
        basis: Basis,
    ) -> Result<Kernel, ContactError> {
        let offset = [dq_mm * towards[0], dq_mm * towards[1]];
        Kernel::shifted(mx, my, (dx_mm, dy_mm), (g_mpa, nu), dq_mm, offset, (basis, None))
    }

    /// [`Kernel::new`] with the field point shifted by `offset_mm` [mm] in x and y, recorded as
    /// the shift `shift_mm`; with a [`Relaxation`], of viscoelastic bodies.
    fn shifted(
        mx: usize,
        my: usize,
        (dx_mm, dy_mm): (f64, f64),
        (g_mpa, nu): (f64, f64),
        shift_mm: f64,
        offset_mm: [f64; 2],
        (basis, relax): (Basis, Option<Relaxation>),
    ) -> Result<Kernel, ContactError> {
        if mx == 0 || my == 0 {
            return Err(ContactError::EmptyGrid { mx, my });
        }
        let positive = "finite and > 0";
        for (name, value) in
            [("element size dx [mm]", dx_mm), ("element size dy [mm]", dy_mm), ("shear modulus G [MPa]", g_mpa)]
        {
            if !(value.is_finite() && value > 0.0) {
                return Err(ContactError::OutOfRange { name, value, requirement: positive });
            }
        }
        if !(nu.is_finite() && (-1.0..0.5).contains(&nu)) {
            return Err(ContactError::OutOfRange { name: "Poisson's ratio", value: nu, requirement: "in [-1, 0.5)" });
        }
        if let Some(&value) = [shift_mm, offset_mm[0], offset_mm[1]].iter().find(|v| !v.is_finite()) {
            return Err(ContactError::OutOfRange { name: "kernel shift [mm]", value, requirement: "finite" });
        }
        let c = 1.0 / (std::f64::consts::PI * g_mpa);
        let elastic = |x: f64, y: f64| {
            let r = basis.integrals(x, y, dx_mm, dy_mm);
            [
                c * (1.0 - nu) * r.one_over_r,
                c * (r.xx + (1.0 - nu) * r.yy),
                c * (r.yy + (1.0 - nu) * r.xx),
                -c * nu * r.xy,
            ]
        };
        // The viscoelastic memory to 1e-13 of the self-coefficient (Azz of the element itself).
        let tol = 1e-13 * elastic(0.0, 0.0)[0];
        // A row of offsets at once: a viscoelastic row shares its memory (`Relaxation::apply_row`).
        let row = |dj: isize, dis: table::Offsets| -> Vec<[f64; 4]> {
            let y = dj as f64 * dy_mm - offset_mm[1];
            match relax {
                None => dis.map(|di| elastic(di as f64 * dx_mm - offset_mm[0], y)).collect(),
                Some(r) => r.apply_row(|x| elastic(x, y), dis, dx_mm, offset_mm[0], tol),
            }
        };
        let key = table::Key {
            size_mm: [dx_mm.to_bits(), dy_mm.to_bits()],
            material: [g_mpa.to_bits(), nu.to_bits()],
            offset_mm: [offset_mm[0].to_bits(), offset_mm[1].to_bits()],
            basis: basis as u8,
            relax: relax.map_or([0, 0], |r| [r.ratio.to_bits(), r.distance_mm.to_bits()]),
        };
        let [zz, xx, yy, xy] = table::kernel_parts(mx, my, key, row);
        if zz.iter().chain(xx.iter()).chain(yy.iter()).chain(xy.iter()).any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("influence coefficients"));
        }
        Ok(Kernel { mx, my, dx_mm, dy_mm, shift_mm, zz, xx, yy, xy })
    }

    /// Row length of the kernel storage, `2mx - 1`.
    pub fn nkx(&self) -> usize {
        2 * self.mx - 1
    }

    /// Number of kernel rows, `2my - 1`.
    pub fn nky(&self) -> usize {
        2 * self.my - 1
    }

    /// Storage index of offset `(di, dj)`; `di` in `-(mx-1)..=(mx-1)`, `dj` in `-(my-1)..=(my-1)`.
    pub fn index(&self, di: isize, dj: isize) -> usize {
        (dj + self.my as isize - 1) as usize * self.nkx() + (di + self.mx as isize - 1) as usize
    }

    /// Coefficient set `(zz, xx, yy, xy)` [mm/MPa] for field element `(i, j)` and source `(ii, jj)`.
    pub fn coeffs(&self, i: usize, j: usize, ii: usize, jj: usize) -> (f64, f64, f64, f64) {
        let k = self.index(i as isize - ii as isize, j as isize - jj as isize);
        (self.zz[k], self.xx[k], self.yy[k], self.xy[k])
    }

    /// Element-wise difference `self - other` [mm/MPa] of two kernels of the same grid (the steady
    /// rolling operator `A - A_shift`, Kalker 1990, eq. 5.40); `shift_mm` of the result is the
    /// difference of the shifts.
    pub fn difference(&self, other: &Kernel) -> Result<Kernel, ContactError> {
        if self.mx != other.mx || self.my != other.my || self.zz.len() != other.zz.len() {
            return Err(ContactError::GridMismatch { expected: (self.mx, self.my), got: (other.mx, other.my) });
        }
        let sub = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x - y).collect();
        Ok(Kernel {
            mx: self.mx,
            my: self.my,
            dx_mm: self.dx_mm,
            dy_mm: self.dy_mm,
            shift_mm: self.shift_mm - other.shift_mm,
            zz: sub(&self.zz, &other.zz),
            xx: sub(&self.xx, &other.xx),
            yy: sub(&self.yy, &other.yy),
            xy: sub(&self.xy, &other.xy),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gauss-Legendre nodes/weights on [-1, 1] (8 points).
    const GL_X: [f64; 8] = [
        -0.960_289_856_497_536_3,
        -0.796_666_477_413_626_7,
        -0.525_532_409_916_329,
        -0.183_434_642_495_649_8,
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_3,
    ];
    const GL_W: [f64; 8] = [
        0.101_228_536_290_376_3,
        0.222_381_034_453_374_5,
        0.313_706_645_877_887_3,
        0.362_683_783_378_362,
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];

    /// Composite Gauss-Legendre integral of f over [x0,x1] x [y0,y1] with n x n panels.
    fn quad2(f: &dyn Fn(f64, f64) -> f64, x0: f64, x1: f64, y0: f64, y1: f64, n: usize) -> f64 {
        let (hx, hy) = ((x1 - x0) / n as f64, (y1 - y0) / n as f64);
        let mut s = 0.0;
        for pi in 0..n {
            for pj in 0..n {
                let cx = x0 + (pi as f64 + 0.5) * hx;
                let cy = y0 + (pj as f64 + 0.5) * hy;
                for a in 0..8 {
                    for b in 0..8 {
                        let x = cx + 0.5 * hx * GL_X[a];
                        let y = cy + 0.5 * hy * GL_X[b];
                        s += GL_W[a] * GL_W[b] * f(x, y);
                    }
                }
            }
        }
        s * 0.25 * hx * hy
    }

    #[test]
    fn antiderivatives_match_quadrature() {
        let (dx, dy) = (0.78, 0.37);
        // Offsets off the singularity, including X + r -> 0 regions (X << 0, Y ~ 0).
        let offsets = [
            (1.5, 0.9),
            (-2.3, 0.4),
            (-9.0 * dx, 0.0),
            (-30.0 * dx, 0.2 * dy),
            (4.0 * dx, -7.0 * dy),
            (0.0, 3.0 * dy),
            (-2.0 * dx, -2.0 * dy),
            (-100.0 * dx, 1e-3),
        ];
        for &(x, y) in &offsets {
            let r = rect_integrals(x, y, dx, dy);
            let q = |f: &dyn Fn(f64, f64) -> f64| quad2(f, x - dx / 2.0, x + dx / 2.0, y - dy / 2.0, y + dy / 2.0, 8);
            let r3 = |a: f64, b: f64| (a * a + b * b).powf(1.5);
            let e1 = q(&|a, b| 1.0 / a.hypot(b));
            let exx = q(&|a, b| a * a / r3(a, b));
            let eyy = q(&|a, b| b * b / r3(a, b));
            let exy = q(&|a, b| a * b / r3(a, b));
            let scale = e1.abs();
            for (got, want, what) in
                [(r.one_over_r, e1, "1/r"), (r.xx, exx, "X^2/r^3"), (r.yy, eyy, "Y^2/r^3"), (r.xy, exy, "XY/r^3")]
            {
                assert!(
                    (got - want).abs() <= 1e-11 * scale,
                    "{what} at ({x}, {y}): closed form {got}, quadrature {want}"
                );
            }
        }
    }

    #[test]
    fn on_the_axis_the_integrals_are_the_double_differences_to_the_bit() {
        // The shortcut at Y = 0 against the four-corner differences, across scales and signs.
        let (dx, dy) = (0.16, 1000.0);
        let (hx, hy) = (0.5 * dx, 0.5 * dy);
        for k in -400..=400 {
            for x in [k as f64 * dx, k as f64 * dx - 0.0731 * dx, k as f64 * 1.7e-3, k as f64 * 13.9] {
                let r = rect_integrals(x, 0.0, dx, dy);
                let full = RectIntegrals {
                    one_over_r: double_diff(f_xx, x, 0.0, hx, hy) + double_diff(f_yy, x, 0.0, hx, hy),
                    xx: double_diff(f_xx, x, 0.0, hx, hy),
                    yy: double_diff(f_yy, x, 0.0, hx, hy),
                    xy: double_diff(f_xy, x, 0.0, hx, hy),
                };
                for (a, b) in [(r.one_over_r, full.one_over_r), (r.xx, full.xx), (r.yy, full.yy), (r.xy, full.xy)] {
                    assert_eq!(a.to_bits(), b.to_bits(), "x = {x}: {a} vs {b}");
                }
                assert_eq!(rect_integrals(x, -0.0, dx, dy), r);
            }
        }
    }

    #[test]
    fn cross_coefficients_match_quadrature() {
        // Axz = -K/(pi G) I[X/r^2], Ayz = K/(pi G) I[Y/r^2] over the source element, against
        // Gauss-Legendre quadrature off the singular element, and the self term by symmetry.
        let (dx, dy, g, k) = (0.6, 0.45, 1.0, 0.5);
        let ck = CrossKernel::new((5, 4), (dx, dy), (g, k), [0.0, 0.0]).unwrap();
        let kernel = Kernel::new(5, 4, dx, dy, g, 0.0, 0.0).unwrap();
        let c = k / (std::f64::consts::PI * g);
        for dj in -3isize..=3 {
            for di in -4isize..=4 {
                let (x, y) = (di as f64 * dx, dj as f64 * dy);
                let idx = kernel.index(di, dj);
                if di == 0 && dj == 0 {
                    assert_eq!((ck.xz[idx], ck.yz[idx]), (0.0, 0.0), "odd integrands vanish on the self element");
                    continue;
                }
                let q =
                    |f: &dyn Fn(f64, f64) -> f64| quad2(f, x - dx / 2.0, x + dx / 2.0, y - dy / 2.0, y + dy / 2.0, 8);
                let want_xz = -c * q(&|a, b| a / (a * a + b * b));
                let want_yz = c * q(&|a, b| b / (a * a + b * b));
                assert!((ck.xz[idx] - want_xz).abs() < 1e-11, "xz at ({di}, {dj}): {} vs {want_xz}", ck.xz[idx]);
                assert!((ck.yz[idx] - want_yz).abs() < 1e-11, "yz at ({di}, {dj}): {} vs {want_yz}", ck.yz[idx]);
            }
        }
        // Odd in X (xz) and in Y (yz); xz < 0 at X > 0 for K > 0.
        assert!((ck.xz[kernel.index(2, 1)] + ck.xz[kernel.index(-2, 1)]).abs() < 1e-15);
        assert!((ck.yz[kernel.index(2, 1)] + ck.yz[kernel.index(2, -1)]).abs() < 1e-15);
        assert!(ck.xz[kernel.index(1, 0)] < 0.0);
        // A shift by one element along x is the kernel one column over.
        let cs = CrossKernel::new((5, 4), (dx, dy), (g, k), [dx, 0.0]).unwrap();
        assert!((cs.xz[kernel.index(1, 2)] - ck.xz[kernel.index(0, 2)]).abs() < 1e-15);
        assert!(CrossKernel::new((5, 4), (dx, dy), (g, 0.7), [0.0, 0.0]).is_err());
    }

    #[test]
    fn self_term_of_square_is_4h_asinh1() {
        // Integral of 1/r over a square of side h about its centre: 4 h asinh(1).
        let h = 0.7;
        let r = rect_integrals(0.0, 0.0, h, h);
        assert!((r.one_over_r - 4.0 * h * 1f64.asinh()).abs() < 1e-14);
        assert!((r.xx - r.yy).abs() < 1e-15);
        assert!(r.xy.abs() < 1e-15);
        // Singular self term also checked against polar integration: split the square into 8
        // triangles, each integral of 1/r over a right triangle with apex at the centre = h/2*asinh(1).
        assert!((r.one_over_r - 8.0 * 0.5 * h * 1f64.asinh()).abs() < 1e-14);
    }

    #[test]
    fn kernel_symmetry_and_shift() {
        let k = Kernel::new(5, 4, 0.8, 0.5, 82000.0, 0.28, 0.0).unwrap();
        for dj in -3isize..=3 {
            for di in -4isize..=4 {
                let a = k.index(di, dj);
                let b = k.index(-di, -dj);
                assert_eq!(k.zz[a], k.zz[b]);
                assert!((k.xy[a] - k.xy[b]).abs() < 1e-22);
                let c = k.index(-di, dj);
                assert!((k.xy[a] + k.xy[c]).abs() < 1e-20);
            }
        }
        assert!(k.xx[k.index(0, 0)] > 0.0 && k.yy[k.index(0, 0)] > 0.0);
        // Shift by a whole element reproduces the unshifted kernel one column over.
        let ks = Kernel::new(5, 4, 0.8, 0.5, 82000.0, 0.28, 0.8).unwrap();
        for dj in -3isize..=3 {
            for di in -3isize..=4 {
                let a = ks.index(di, dj);
                let b = k.index(di - 1, dj);
                assert!((ks.xx[a] - k.xx[b]).abs() < 1e-15 * k.xx[k.index(0, 0)]);
            }
        }
        assert!(Kernel::new(5, 4, 0.8, 0.5, -1.0, 0.28, 0.0).is_err());
        assert!(Kernel::new(5, 4, f64::NAN, 0.5, 1.0, 0.28, 0.0).is_err());
    }
}
