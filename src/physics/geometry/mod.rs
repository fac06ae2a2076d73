//! The geometry seam: what every solver needs of the contact's shape, behind one trait. The
//! exact-theory solver takes the undeformed distance per element; the simplified models take a
//! planform (their pressure on the grid, each row's leading edge, the ellipse that sets their
//! flexibilities). Hertz's ellipse is one geometry ([`hertz::HertzEllipse`]); an undeformed
//! distance per element on an explicit grid is the other ([`element::ElementGeometry`]), made
//! from a lateral profile ([`profile::Profile`]) or given element by element.

pub mod element;
pub mod hertz;
pub mod profile;

use super::halfspace::blend::Blend;
use super::halfspace::ContactError;
use super::{Grid, HertzContact, Material, PressureShape, Radii};
use crate::error::InputError;
use std::fmt::Debug;
use std::sync::Arc;

pub use element::ElementGeometry;
pub use hertz::HertzEllipse;
pub use profile::Profile;

/// The geometry as a scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum GeometrySpec {
    /// Hertz's ellipse by its semi-axes (`contact.a_mm`, `contact.b_mm`).
    SemiAxes { a_mm: f64, b_mm: f64 },
    /// Hertz's ellipse from the principal radii (`contact.r_wx_mm`, …) and the load.
    Radii(Radii),
    /// `h = a1 x² + g(y)`, g linear between the rows of a profile (`[geometry] kind = "profile"`).
    Profile { a1_per_mm: f64, profile: Profile },
    /// h per element (`[geometry] kind = "field"`), in CONTACT's element order: index
    /// `(iy − 1) mx + (ix − 1)`, ix along CONTACT's x; with the sub-patches of CONTACT's blending
    /// approach (same order) where a wheel–rail patch has them (never from a scene's keys); with
    /// the normal pressure [MPa] at the scene's FN (same order) where a wheel–rail patch has
    /// solved it: the exact theory's, or the model's own approximate one's (KPEC, ANALYN); never
    /// from a scene's keys: the geometry takes it instead of solving again.
    Field { h_mm: Vec<f64>, blend: Option<Blend>, pn_mpa: Option<Vec<f64>> },
}

/// The potential contact as a scene gives it (`[grid]`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Extent {
    /// `scale` times the bounding box of the nominal ellipse (CONTACT's SCALE).
    Scale(f64),
    /// Explicit edges in CONTACT's coordinates (`x_mm = [x0, x1]`, `y_mm = [y0, y1]`).
    Edges { x_mm: [f64; 2], y_mm: [f64; 2] },
}

impl GeometrySpec {
    /// Whether this geometry is given per element (on an explicit grid) rather than as an ellipse.
    pub fn is_elementwise(&self) -> bool {
        matches!(self, GeometrySpec::Profile { .. } | GeometrySpec::Field { .. })
    }

    /// Hertz's ellipse of an elliptic geometry at `fn_n` [N] (semi-axes as given, or from radii).
    fn nominal(&self, fn_n: f64, material: &Material) -> Result<HertzContact, InputError> {
        match self {
            GeometrySpec::SemiAxes { a_mm, b_mm } => Ok(HertzContact { a_mm: *a_mm, b_mm: *b_mm, fn_n }),
            GeometrySpec::Radii(r) => HertzContact::from_radii(r, fn_n, material).map_err(|e| {
                InputError::new("contact.r_wx_mm", format!("{r:?}"), format!("radii of a convex contact ({e})"))
            }),
            _ => unreachable!("called for an elliptic geometry"),
        }
    }

    /// The contact geometry at the nominal load `fn_n` [N] and its grid of `mx × my` elements
    /// over `extent`; errors name the scene field.
    pub fn build(
        &self,
        fn_n: f64,
        material: &Material,
        (mx, my): (usize, usize),
        extent: Extent,
    ) -> Result<(Arc<dyn ContactGeometry>, Grid), InputError> {
        let nominal = match (self, extent) {
            (GeometrySpec::SemiAxes { .. } | GeometrySpec::Radii(_), Extent::Scale(_)) => {
                Self::nominal(self, fn_n, material)?
            }
            (_, Extent::Edges { x_mm: [x0, x1], y_mm }) if self.is_elementwise() => {
                let grid = Grid::from_edges(mx, my, [-x1, -x0], y_mm);
                let (mut blend_in_grid, mut solved) = (None, None);
                let (kind, h_mm) = match self {
                    GeometrySpec::Profile { a1_per_mm, profile } => {
                        if !profile.covers(&grid) {
                            let (lo, hi) = (profile.y_mm[0], profile.y_mm[profile.y_mm.len() - 1]);
                            return Err(InputError::new(
                                "geometry.profile",
                                format!("y_mm from {lo} to {hi}"),
                                format!(
                                    "a profile covering every element centre of the grid, y from {} to {} mm",
                                    grid.y_mm[0],
                                    grid.y_mm[grid.my - 1]
                                ),
                            ));
                        }
                        ("profile", profile.undeformed_distance_mm(&grid, *a1_per_mm))
                    }
                    GeometrySpec::Field { h_mm, blend, pn_mpa } => {
                        blend_in_grid = blend.as_ref().map(|b| b.reordered(&contact_order(&grid)));
                        solved = pn_mpa.as_ref().map(|p| field_in_grid_order(&grid, p));
                        ("field", field_in_grid_order(&grid, h_mm))
                    }
                    _ => unreachable!("is_elementwise"),
                };
                let geometry =
                    ElementGeometry::with_pressure(kind, h_mm, grid.clone(), material, fn_n, blend_in_grid, solved)
                        .map_err(|e| {
                            InputError::new(
                                "contact.fn_n",
                                fn_n,
                                format!("a load the {kind} geometry's normal problem can carry on this grid ({e})"),
                            )
                        })?;
                return Ok((Arc::new(geometry), grid));
            }
            (GeometrySpec::SemiAxes { .. } | GeometrySpec::Radii(_), Extent::Edges { x_mm: [x0, x1], y_mm }) => {
                // An ellipse on a window of its own (CONTACT's grid kept by D = 0 while the load
                // changes): the contact may reach beyond it and is cut there, as CONTACT's.
                let nominal = Self::nominal(self, fn_n, material)?;
                return Ok((Arc::new(HertzEllipse { nominal }), Grid::from_edges(mx, my, [-x1, -x0], y_mm)));
            }
            (_, Extent::Edges { .. }) => {
                return Err(InputError::new(
                    "grid.x_mm",
                    "given",
                    "grid edges with a [geometry] given per element or an ellipse (a_mm, b_mm or radii)",
                ))
            }
            (_, Extent::Scale(_)) => {
                return Err(InputError::new(
                    "grid.x_mm",
                    "missing",
                    "the grid's edges x_mm = [x0, x1], y_mm = [y0, y1] for a [geometry] given per element",
                ))
            }
        };
        let Extent::Scale(scale) = extent else { unreachable!("matched above") };
        let grid = Grid::new(mx, my, scale * nominal.a_mm, scale * nominal.b_mm);
        Ok((Arc::new(HertzEllipse { nominal }), grid))
    }
}

/// A field in CONTACT's element order (ix along CONTACT's x) in this grid's flat order
/// (i along the grid's x = −x_C: i = mx − ix).
pub fn field_in_grid_order(grid: &Grid, h_contact: &[f64]) -> Vec<f64> {
    contact_order(grid).into_iter().map(|k| h_contact[k]).collect()
}

/// For each element of this grid's flat order, its index in CONTACT's element order.
fn contact_order(grid: &Grid) -> Vec<usize> {
    let mut order = vec![0; grid.len()];
    for j in 0..grid.my {
        for i in 0..grid.mx {
            order[grid.index(i, j)] = j * grid.mx + (grid.mx - 1 - i);
        }
    }
    order
}

/// The simplified models' contact at one load.
#[derive(Debug, Clone, PartialEq)]
pub struct Planform {
    /// The ellipse at this load: its semi-axes set the flexibilities (thesis Eq. 2.35).
    pub ellipse: HertzContact,
    /// Pressure per element [MPa], flat order; zero outside the contact.
    pub pressure_mpa: Vec<f64>,
    /// 1/p per element [1/MPa] where it is loaded, 0 elsewhere: made once per load for the
    /// falling bound's μ = g/p (solvers::brush `Falling`).
    pub inv_pressure_per_mpa: Vec<f64>,
    /// Σ pressure over the grid [MPa], the denominator of the traction coefficients (Eq. 3.12).
    pub pressure_sum_mpa: f64,
    /// Number of loaded elements (p > 0).
    pub loaded: usize,
    /// x of each grid row's leading edge [mm] (`[model] leading_edge = "exact"`; the ellipse's
    /// `−a √(1 − y²/b²)`, or the upstream face of the row's first loaded element).
    pub leading_edge_mm: Vec<f64>,
    /// Half-length of each grid row's contact [mm] (0 where the row has no contact): a strip's
    /// flexibility scales with it on non-Hertzian contacts.
    pub half_length_mm: Vec<f64>,
}

impl Planform {
    /// A planform from its pressure, summing it once in flat order.
    pub fn new(
        ellipse: HertzContact,
        pressure_mpa: Vec<f64>,
        leading_edge_mm: Vec<f64>,
        half_length_mm: Vec<f64>,
    ) -> Self {
        let pressure_sum_mpa = pressure_mpa.iter().sum();
        let loaded = pressure_mpa.iter().filter(|&&p| p > 0.0).count();
        let inv_pressure_per_mpa = pressure_mpa.iter().map(|&p| if p > 0.0 { 1.0 / p } else { 0.0 }).collect();
        Planform {
            ellipse,
            pressure_mpa,
            inv_pressure_per_mpa,
            pressure_sum_mpa,
            loaded,
            leading_edge_mm,
            half_length_mm,
        }
    }

    /// The planform of a pressure given per element (grid order): each row's leading edge the
    /// upstream face of its first loaded element, its half-length over its loaded span.
    pub fn of_pressure(grid: &Grid, ellipse: HertzContact, pressure_mpa: Vec<f64>) -> Self {
        let (mut leading_edge, mut half_length) = (vec![0.0; grid.my], vec![0.0; grid.my]);
        for j in 0..grid.my {
            let row = &pressure_mpa[grid.index(0, j)..grid.index(0, j) + grid.mx];
            if let (Some(first), Some(last)) = (row.iter().position(|&p| p > 0.0), row.iter().rposition(|&p| p > 0.0)) {
                leading_edge[j] = grid.x_mm[first] - 0.5 * grid.dx_mm;
                half_length[j] = 0.5 * (grid.x_mm[last] - grid.x_mm[first] + grid.dx_mm);
            }
        }
        Planform::new(ellipse, pressure_mpa, leading_edge, half_length)
    }

    /// Traction coefficients `(Σ τx / Σ p, Σ τy / Σ p)` from the traction sums (thesis Eq. 3.12).
    pub fn coefficients(&self, sum_tx: f64, sum_ty: f64) -> (f64, f64) {
        if self.pressure_sum_mpa <= 0.0 {
            return (0.0, 0.0);
        }
        (sum_tx / self.pressure_sum_mpa, sum_ty / self.pressure_sum_mpa)
    }
}

/// A contact geometry: the undeformed distance and the planform at any load.
pub trait ContactGeometry: Send + Sync + Debug {
    /// Name written to scene.json (`geometry`).
    fn kind(&self) -> &'static str;
    /// Whether the contact is Hertz's ellipse (the simplified models' flexibilities are then
    /// the ellipse's, uniform over the contact).
    fn elliptic(&self) -> bool {
        true
    }
    /// Share of the load at `fn_n` carried by elements on the grid's boundary: the grid cuts the
    /// contact when it is not zero.
    fn edge_load_share(&self, _fn_n: f64) -> f64 {
        0.0
    }
    /// The normal pressure [MPa] per element at `fn_n` if this geometry has already solved the
    /// normal problem for it (a geometry given per element does, once per load): the exact solver
    /// then takes it instead of solving again. `None`: solve it.
    fn normal_pressure_mpa(&self, _fn_n: f64) -> Option<Vec<f64>> {
        None
    }
    /// The normal pressure [MPa] per element at `fn_n` if it was handed in solved with the
    /// geometry at that load (a wheel–rail patch's: the pressure of the normal problem of the
    /// model the patch is made for, [`GeometrySpec::Field`]); a model with its own normal problem
    /// (KPEC, ANALYN) takes it instead of solving that problem again.
    fn given_pressure_mpa(&self, _fn_n: f64) -> Option<&[f64]> {
        None
    }
    /// Why the contact at `fn_n` cannot be formed (a normal problem that fails), if it cannot.
    fn planform_error(&self, _fn_n: f64) -> Option<ContactError> {
        None
    }
    /// The ellipse at the scene's nominal load: it sizes the grid (times `[grid] scale`) and
    /// gives Kalker's coefficients (Table A1 is tabulated by the axis ratio).
    fn nominal(&self) -> HertzContact;
    /// The ellipse at load `fn_n` [N].
    fn ellipse_at(&self, fn_n: f64) -> HertzContact;
    /// Undeformed distance [mm] at every element centre at load `fn_n`, flat order.
    fn undeformed_distance_mm(&self, grid: &Grid, fn_n: f64, material: &Material) -> Vec<f64>;
    /// The simplified models' planform at load `fn_n` with pressure shape `shape`.
    fn planform(&self, grid: &Grid, fn_n: f64, shape: PressureShape) -> Planform;
}
