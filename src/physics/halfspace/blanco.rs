//! Blanco-Lorenzo's correction of the half-space influence coefficients for conformal contact
//! (CONTACT's C3 = 4, `m_inflcf.f90` `influe_blanco`; user guide, "conformal contact"): on a
//! curved reference whose rows j are inclined by α_j about the rolling direction x, the
//! displacement at element I of a traction at element J is the half-space's `A(I − J)` with the
//! turn `R(α)`, α = α_J − α_I, of the source row against the field row (about x: the lateral and
//! normal components mixed, the longitudinal one kept), as CONTACT's VARIANT says
//! (`influe_blanco1`): 1 Blanco's formulas, the traction turned, `B = A R(α)`; 2 the same with
//! `B_xn = A_xn` kept; 3 the half-space at J, its displacement turned into I's frame,
//! `B = R(α) A`; 4 the split formula, `B = R(α/2) A R(α/2)`. Where every row has the same
//! inclination the coefficients are the half-space's. The turn couples the normal and the
//! tangential problems even for one material: a pressure displaces the surfaces laterally and a
//! lateral traction normally.
//!
//! The coefficients depend on the rows of I and J, not on their offset alone; with
//! `cos θ(α_J − α_I) = c_J c_I + s_J s_I` and `sin θ(α_J − α_I) = s_J c_I − c_J s_I`
//! (`c_J = cos θα_J`, `s_J = sin θα_J`, θ = 1 or ½) every variant's product is still a sum of FFT
//! convolutions of the tractions weighted by each source row's `c_J`, `s_J`, times the field row's
//! ([`BlancoProduct`]: variant 3 four convolutions, the others up to nine, [`variant_terms`]);
//! [`direct_product`] sums every pair of elements for any variant (CONTACT's `influe_blanco1`,
//! one matrix per source row), their reference.

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

/// CONTACT's VARIANT = 3 ("halfspace at J", `u_I = R(α_J − α_I) A_IJ p_J`), the one CONTACT's
/// public decks use (its product [`BlancoProduct`] takes four convolutions).
pub const VARIANT: u8 = 3;

/// CONTACT's VARIANTs this crate computes (`influe_blanco1`'s 1–4).
pub const VARIANTS: [u8; 4] = [1, 2, 3, 4];

/// The correction as a scene asks for it (`[material] blanco_inclination`, `blanco_variant`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Blanco {
    pub inclination: Inclination,
    /// CONTACT's VARIANT (1–4, [`VARIANTS`]).
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

/// The half-space kernel a term of a variant takes (one material: `A_sx = A_xs`, no
/// normal–tangential coupling).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    Xx,
    Xs,
    Ss,
    Nn,
}

/// The function of the turn α = α_J − α_I a term is weighted by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Turn {
    One,
    Cos,
    Sin,
    /// cos(α/2), variant 4's split turn.
    CosHalf,
    /// sin(α/2).
    SinHalf,
}

/// One term of a variant's block: `B[out][inp] += coef · turn(α_J − α_I) · A_part` (components
/// 0 x, 1 s, 2 n).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Term {
    pub out: usize,
    pub inp: usize,
    pub part: Part,
    pub turn: Turn,
    pub coef: f64,
}

const fn term(out: usize, inp: usize, part: Part, turn: Turn, coef: f64) -> Term {
    Term { out, inp, part, turn, coef }
}

use Part::{Nn, Ss, Xs, Xx};
use Turn::{Cos, CosHalf, One, Sin, SinHalf};

/// Variant 1 (`influe_blanco1`: the traction turned, `B = A R(α)`) for one material.
const TERMS_1: [Term; 8] = [
    term(0, 0, Xx, One, 1.0),
    term(0, 1, Xs, Cos, 1.0),
    term(0, 2, Xs, Sin, -1.0),
    term(1, 0, Xs, One, 1.0),
    term(1, 1, Ss, Cos, 1.0),
    term(1, 2, Ss, Sin, -1.0),
    term(2, 1, Nn, Sin, 1.0),
    term(2, 2, Nn, Cos, 1.0),
];

/// Variant 2: variant 1 with `B_xn = A_xn` (0 for one material).
const TERMS_2: [Term; 7] = [
    term(0, 0, Xx, One, 1.0),
    term(0, 1, Xs, Cos, 1.0),
    term(1, 0, Xs, One, 1.0),
    term(1, 1, Ss, Cos, 1.0),
    term(1, 2, Ss, Sin, -1.0),
    term(2, 1, Nn, Sin, 1.0),
    term(2, 2, Nn, Cos, 1.0),
];

/// Variant 3: the displacement turned, `B = R(α) A`.
const TERMS_3: [Term; 8] = [
    term(0, 0, Xx, One, 1.0),
    term(0, 1, Xs, One, 1.0),
    term(1, 0, Xs, Cos, 1.0),
    term(1, 1, Ss, Cos, 1.0),
    term(1, 2, Nn, Sin, -1.0),
    term(2, 0, Xs, Sin, 1.0),
    term(2, 1, Ss, Sin, 1.0),
    term(2, 2, Nn, Cos, 1.0),
];

/// Variant 4: the split turn, `B = R(α/2) A R(α/2)`: with `A_ss`, `A_nn` split into their half
/// sum and half difference, `B_ss = ½(A_ss − A_nn) + ½(A_ss + A_nn) cos α`.
const TERMS_4: [Term; 17] = [
    term(0, 0, Xx, One, 1.0),
    term(0, 1, Xs, CosHalf, 1.0),
    term(0, 2, Xs, SinHalf, -1.0),
    term(1, 0, Xs, CosHalf, 1.0),
    term(1, 1, Ss, One, 0.5),
    term(1, 1, Nn, One, -0.5),
    term(1, 1, Ss, Cos, 0.5),
    term(1, 1, Nn, Cos, 0.5),
    term(1, 2, Ss, Sin, -0.5),
    term(1, 2, Nn, Sin, -0.5),
    term(2, 0, Xs, SinHalf, 1.0),
    term(2, 1, Ss, Sin, 0.5),
    term(2, 1, Nn, Sin, 0.5),
    term(2, 2, Ss, One, -0.5),
    term(2, 2, Nn, One, 0.5),
    term(2, 2, Ss, Cos, 0.5),
    term(2, 2, Nn, Cos, 0.5),
];

/// The terms of `variant`'s corrected block for one material (CONTACT's `influe_blanco1` with
/// `A_xn = A_sn = 0`): the FFT product's recipe.
pub fn variant_terms(variant: u8) -> Result<&'static [Term], ContactError> {
    match variant {
        1 => Ok(&TERMS_1),
        2 => Ok(&TERMS_2),
        3 => Ok(&TERMS_3),
        4 => Ok(&TERMS_4),
        v => Err(ContactError::OutOfRange { name: "Blanco variant", value: f64::from(v), requirement: "1, 2, 3 or 4" }),
    }
}

/// `u = B p` of one variant on one grid by FFT. Variant 3: `u_x = (A p)_x`, and with
/// `T = A_sx px + A_ss ps`, `N = A_nn pn` convolved with the tractions weighted by the source
/// row's cos and sin, `u_s = c_I (T[c p] − N[s p]) + s_I (T[s p] + N[c p])`,
/// `u_n = c_I (T[s p] + N[c p]) + s_I (N[s p] − T[c p])`. Variants 1, 2, 4: each term of
/// [`variant_terms`] one convolution of its kernel with the traction weighted by 1, or by the
/// source row's cos and sin (of α or α/2) and combined with the field row's.
pub struct BlancoProduct {
    conv: Convolver,
    mx: usize,
    variant: u8,
    cos_rows: Vec<f64>,
    sin_rows: Vec<f64>,
    cos_half_rows: Vec<f64>,
    sin_half_rows: Vec<f64>,
    wx: Vec<f64>,
    ws: Vec<f64>,
    wn: Vec<f64>,
    tx: Vec<f64>,
    tc: Vec<f64>,
    ts: Vec<f64>,
    nc: Vec<f64>,
    ns: Vec<f64>,
}

/// The weight of a traction in one convolution of the terms' product.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Weight {
    One,
    Cos,
    Sin,
    CosHalf,
    SinHalf,
}

/// The convolution a kernel takes: `tangential(q, 0)` gives `A_xx q` and `A_sx q`,
/// `tangential(0, q)` gives `A_ss q`, `normal(q)` `A_nn q`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Call {
    TangentialX,
    TangentialS,
    Normal,
}

/// The convolutions one product computed: by (call, traction component, weight), the call's
/// outputs end to end.
type Done = Vec<((Call, usize, Weight), Vec<f64>)>;

impl BlancoProduct {
    /// The product of `variant` ([`VARIANTS`]) on `kernel`'s grid with row `j` inclined by
    /// `alpha_rows[j]` [rad].
    pub fn new(kernel: &Kernel, alpha_rows: &[f64], variant: u8) -> Result<BlancoProduct, ContactError> {
        check_rows(alpha_rows, kernel.my)?;
        variant_terms(variant)?;
        let n = kernel.mx * kernel.my;
        let z = || vec![0.0; n];
        let mut b = BlancoProduct {
            conv: Convolver::auto(kernel)?,
            mx: kernel.mx,
            variant,
            cos_rows: Vec::new(),
            sin_rows: Vec::new(),
            cos_half_rows: Vec::new(),
            sin_half_rows: Vec::new(),
            wx: z(),
            ws: z(),
            wn: z(),
            tx: z(),
            tc: z(),
            ts: z(),
            nc: z(),
            ns: z(),
        };
        b.set_rows(alpha_rows)?;
        Ok(b)
    }

    /// The rows' inclinations changed to `alpha_rows` [rad] (the kernel kept).
    pub fn set_rows(&mut self, alpha_rows: &[f64]) -> Result<(), ContactError> {
        check_rows(alpha_rows, self.wx.len() / self.mx)?;
        self.cos_rows = alpha_rows.iter().map(|a| a.cos()).collect();
        self.sin_rows = alpha_rows.iter().map(|a| a.sin()).collect();
        self.cos_half_rows = alpha_rows.iter().map(|a| (0.5 * a).cos()).collect();
        self.sin_half_rows = alpha_rows.iter().map(|a| (0.5 * a).sin()).collect();
        Ok(())
    }

    /// `u = B p` [mm] for the tractions `p = (px, ps, pn)` [MPa] (grid order).
    pub fn apply(&mut self, p: [&[f64]; 3], u: [&mut [f64]; 3]) -> Result<(), ContactError> {
        if self.variant == VARIANT {
            return self.apply_turned(p, u);
        }
        self.apply_terms(p, u)
    }

    /// Variant 3's product: four convolutions of the weighted tractions.
    fn apply_turned(&mut self, p: [&[f64]; 3], u: [&mut [f64]; 3]) -> Result<(), ContactError> {
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

    /// Any variant's product from its [`variant_terms`]: each convolution (kernel call, traction,
    /// weight) computed once, a traction that is zero everywhere skipped.
    fn apply_terms(&mut self, p: [&[f64]; 3], u: [&mut [f64]; 3]) -> Result<(), ContactError> {
        let n = self.wx.len();
        for (name, f) in [("px", p[0]), ("ps", p[1]), ("pn", p[2])] {
            if f.len() != n {
                return Err(ContactError::SizeMismatch { name, len: f.len(), expected: n });
            }
        }
        let mut u = u;
        for c in u.iter_mut() {
            c.iter_mut().for_each(|v| *v = 0.0);
        }
        let zero: [bool; 3] = std::array::from_fn(|c| p[c].iter().all(|v| *v == 0.0));
        let mut done: Done = Vec::new();
        for t in variant_terms(self.variant)? {
            if zero[t.inp] {
                continue;
            }
            let weights = match t.turn {
                Turn::One => [Weight::One, Weight::One],
                Turn::Cos | Turn::Sin => [Weight::Cos, Weight::Sin],
                Turn::CosHalf | Turn::SinHalf => [Weight::CosHalf, Weight::SinHalf],
            };
            let mut parts = [Vec::new(), Vec::new()];
            for (part, w) in parts.iter_mut().zip(weights) {
                *part = self.convolved(&mut done, t.part, t.inp, w, p[t.inp])?;
            }
            let (rc, rs) = match t.turn {
                Turn::One => (None, None),
                Turn::Cos | Turn::Sin => (Some(&self.cos_rows), Some(&self.sin_rows)),
                Turn::CosHalf | Turn::SinHalf => (Some(&self.cos_half_rows), Some(&self.sin_half_rows)),
            };
            let out = &mut u[t.out];
            for k in 0..n {
                let row = k / self.mx;
                out[k] += t.coef
                    * match (t.turn, rc, rs) {
                        (Turn::Cos | Turn::CosHalf, Some(c), Some(s)) => c[row] * parts[0][k] + s[row] * parts[1][k],
                        (Turn::Sin | Turn::SinHalf, Some(c), Some(s)) => c[row] * parts[1][k] - s[row] * parts[0][k],
                        _ => parts[0][k],
                    };
            }
        }
        Ok(())
    }

    /// `A_part (w q)` [mm]: the kernel `part` convolved with the traction `q` (component `inp`)
    /// weighted by its row's `w`, taken from `done` or computed and kept there.
    fn convolved(
        &mut self,
        done: &mut Done,
        part: Part,
        inp: usize,
        w: Weight,
        q: &[f64],
    ) -> Result<Vec<f64>, ContactError> {
        let (call, second) = match part {
            Part::Xx => (Call::TangentialX, false),
            Part::Xs => (Call::TangentialX, true),
            Part::Ss => (Call::TangentialS, true),
            Part::Nn => (Call::Normal, false),
        };
        let key = (call, inp, w);
        let n = q.len();
        let k = match done.iter().position(|(k, _)| *k == key) {
            Some(k) => k,
            None => {
                let rows = match w {
                    Weight::One => None,
                    Weight::Cos => Some(&self.cos_rows),
                    Weight::Sin => Some(&self.sin_rows),
                    Weight::CosHalf => Some(&self.cos_half_rows),
                    Weight::SinHalf => Some(&self.sin_half_rows),
                };
                let wq: Vec<f64> = match rows {
                    None => q.to_vec(),
                    Some(r) => q.iter().enumerate().map(|(k, v)| r[k / self.mx] * v).collect(),
                };
                let (zero, mut a, mut b) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
                match call {
                    Call::TangentialX => self.conv.tangential(&wq, &zero, None, &mut a, &mut b)?,
                    Call::TangentialS => self.conv.tangential(&zero, &wq, None, &mut a, &mut b)?,
                    Call::Normal => self.conv.normal(&wq, None, &mut a)?,
                }
                // Both outputs of a tangential call kept: x's first, then s's.
                a.extend_from_slice(&b);
                done.push((key, a));
                done.len() - 1
            }
        };
        let v = &done[k].1;
        Ok(if second { v[n..].to_vec() } else { v[..n].to_vec() })
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
        let scale = an.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for variant in VARIANTS {
            let mut b = BlancoProduct::new(&k, &flat, variant).unwrap();
            let d = b.correction(p).unwrap();
            assert!(d.iter().flatten().all(|v| v.abs() <= 1e-13 * scale), "{variant}: {d:?}");
        }
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
        BlancoProduct::new(&k, &alpha, VARIANT).unwrap().apply(p, [&mut ux, &mut us, &mut un]).unwrap();
        let scale = want[2].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for (got, want) in [&ux, &us, &un].into_iter().zip(&want) {
            assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1e-12 * scale));
        }
        // The turn couples the problems: a pressure alone displaces the surfaces laterally.
        let zero = vec![0.0; n];
        let u = direct_product(&k, &alpha, VARIANT, [&zero, &zero, p[2]]).unwrap();
        assert!(u[1].iter().any(|v| v.abs() > 1e-3 * scale) && u[0].iter().all(|v| *v == 0.0));
    }

    /// The turn about x by `a` [rad]: `(x, s, n)` to `(x, s cos a − n sin a, s sin a + n cos a)`.
    fn turn(a: f64) -> [[f64; 3]; 3] {
        let (s, c) = a.sin_cos();
        [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]
    }

    fn times(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    }

    #[test]
    fn each_variant_is_its_turn_of_the_half_space_block() {
        // A block of the half-space's form (A_sx = A_xs, A_nx = −A_xn, A_ns = −A_sn) and the
        // variants' closed forms (user guide, "conformal contact"): 1 A R(α), 2 the same with
        // B_xn = A_xn, 3 R(α) A, 4 R(α/2) A R(α/2).
        let a = [[1.0, 0.2, 0.05], [0.2, 0.9, -0.07], [-0.05, 0.07, 1.4]];
        for alpha in [0.31, -0.74, 1.2] {
            let mut two = times(&a, &turn(alpha));
            two[0][2] = a[0][2];
            let want = [
                (1, times(&a, &turn(alpha))),
                (2, two),
                (3, times(&turn(alpha), &a)),
                (4, times(&times(&turn(0.5 * alpha), &a), &turn(0.5 * alpha))),
            ];
            for (variant, w) in want {
                let b = corrected_block(variant, &a, alpha).unwrap();
                let same = b.iter().flatten().zip(w.iter().flatten()).all(|(x, y)| (x - y).abs() <= 1e-15);
                assert!(same, "variant {variant}, α {alpha}: {b:?} against {w:?}");
            }
        }
    }

    #[test]
    fn the_fft_product_is_the_direct_sum_of_every_variant_on_a_curved_surface() {
        let (mx, my) = (11, 9);
        let k = kernel(mx, my);
        let alpha: Vec<f64> = (0..my).map(|j| 0.45 - 0.11 * j as f64 + 0.02 * (j * j) as f64).collect();
        let p = fields(mx * my);
        let p = [p[0].as_slice(), p[1].as_slice(), p[2].as_slice()];
        let n = mx * my;
        for variant in VARIANTS {
            let want = direct_product(&k, &alpha, variant, p).unwrap();
            let scale = want[2].iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let mut b = BlancoProduct::new(&k, &alpha, variant).unwrap();
            let (mut ux, mut us, mut un) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            b.apply(p, [&mut ux, &mut us, &mut un]).unwrap();
            // The terms' product as well (variant 3's own product takes its four convolutions).
            let (mut tx, mut ts, mut tn) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            b.apply_terms(p, [&mut tx, &mut ts, &mut tn]).unwrap();
            for got in [[&ux, &us, &un], [&tx, &ts, &tn]] {
                for (c, (got, want)) in got.into_iter().zip(&want).enumerate() {
                    let worst = got.iter().zip(want).map(|(g, w)| (g - w).abs()).fold(0.0, f64::max);
                    assert!(worst <= 1e-12 * scale, "variant {variant}, component {c}: {worst:e} of {scale:e}");
                }
            }
        }
        // Variant 1 turns the traction: a pressure alone displaces longitudinally (B_xn = −A_xs
        // sin α); variant 2 keeps B_xn = A_xn = 0, its x displacement of a pressure is zero.
        let zero = vec![0.0; n];
        let one = direct_product(&k, &alpha, 1, [&zero, &zero, p[2]]).unwrap();
        let two = direct_product(&k, &alpha, 2, [&zero, &zero, p[2]]).unwrap();
        assert!(one[0].iter().any(|v| v.abs() > 0.0) && two[0].iter().all(|v| *v == 0.0));
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
