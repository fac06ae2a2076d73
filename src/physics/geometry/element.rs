//! A non-Hertzian contact: the undeformed distance given per element on an explicit grid
//! (CONTACT's IPOTCN = 1 with IBASE = 9), the normal pressure from the normal problem on it
//! ([`crate::physics::halfspace::normal`]), so the contact may be any shape and split into
//! several patches that merge or part as the load changes.
//!
//! The simplified models need an ellipse for Kalker's coefficients and flexibilities: the
//! equivalent ellipse of Kik & Piotrowski (2008), which keeps the contact's area and the ratio of
//! its length to its width (as CONTACT's `equiv_ellipse`, m_hertz.f90).

use super::{ContactGeometry, Planform};
use crate::physics::halfspace::blend::Blend;
use crate::physics::halfspace::influence::Kernel;
use crate::physics::halfspace::normal::{NormalParams, NormalSolver};
use crate::physics::halfspace::ContactError;
use crate::physics::{Grid, HertzContact, Material, PressureShape};
use std::f64::consts::PI;
use std::fmt;
use std::sync::{Arc, Mutex};

/// The normal contact at one load.
#[derive(Debug, Clone, PartialEq)]
pub struct NormalContact {
    pub fn_n: f64,
    /// Pressure per element [MPa], flat order.
    pub pn_mpa: Vec<f64>,
    /// Kik–Piotrowski's equivalent ellipse of the loaded elements.
    pub ellipse: HertzContact,
    /// Share of the load carried by elements on the grid's boundary (0 when the grid holds it).
    pub edge_load_share: f64,
}

/// An undeformed distance per element on its own grid.
pub struct ElementGeometry {
    kind: &'static str,
    h_mm: Vec<f64>,
    grid: Grid,
    nominal: NormalContact,
    /// The normal solver, made at the first load solved here (none while the nominal load's
    /// pressure was handed in solved).
    solver: Mutex<Option<NormalSolver>>,
    material: Material,
    blend: Option<Blend>,
    /// Whether the nominal load's pressure was handed in solved.
    given: bool,
    /// Normal contacts solved so far (a history revisits its loads), by load.
    cache: Mutex<Vec<Arc<NormalContact>>>,
}

impl fmt::Debug for ElementGeometry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ElementGeometry").field("kind", &self.kind).field("grid", &self.grid).finish_non_exhaustive()
    }
}

impl ElementGeometry {
    /// The geometry `kind` ("profile", "field") with undeformed distance `h_mm` per element of
    /// `grid` (flat order), loaded by `fn_n` [N] nominally; with `blend`, its sub-patches'
    /// cross-influence attenuated in the normal problem (CONTACT's blending approach).
    pub fn new(
        kind: &'static str,
        h_mm: Vec<f64>,
        grid: Grid,
        material: &Material,
        fn_n: f64,
        blend: Option<Blend>,
    ) -> Result<ElementGeometry, ContactError> {
        Self::with_pressure(kind, h_mm, grid, material, fn_n, blend, None)
    }

    /// [`Self::new`], with `solved` the normal pressure at `fn_n` already solved elsewhere (grid
    /// order: a wheel–rail patch's) taken instead of solving it again.
    pub fn with_pressure(
        kind: &'static str,
        h_mm: Vec<f64>,
        grid: Grid,
        material: &Material,
        fn_n: f64,
        blend: Option<Blend>,
        solved: Option<Vec<f64>>,
    ) -> Result<ElementGeometry, ContactError> {
        let (mut solver, given) = (None, solved.is_some());
        let nominal = match solved {
            Some(pn_mpa) => contact_of(&grid, fn_n, pn_mpa)?,
            None if blend.is_none() => match Kept::find(&grid, material, &h_mm, fn_n) {
                Some(nominal) => nominal,
                None => {
                    let mut s = normal_solver(&grid, material, None)?;
                    let nominal = solve(&mut s, &grid, &h_mm, fn_n)?;
                    Kept::keep(&grid, material, &h_mm, nominal.clone());
                    solver = Some(s);
                    nominal
                }
            },
            None => {
                let mut s = normal_solver(&grid, material, blend.clone())?;
                let nominal = solve(&mut s, &grid, &h_mm, fn_n)?;
                solver = Some(s);
                nominal
            }
        };
        let cache = Mutex::new(vec![Arc::new(nominal.clone())]);
        let (solver, material) = (Mutex::new(solver), *material);
        Ok(ElementGeometry { kind, h_mm, grid, nominal, solver, material, blend, given, cache })
    }

    /// The normal contact at load `fn_n` [N] (solved once per load).
    pub fn normal_at(&self, fn_n: f64) -> Result<Arc<NormalContact>, ContactError> {
        let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(c) = cache.iter().find(|c| c.fn_n == fn_n) {
            return Ok(Arc::clone(c));
        }
        let mut solver = self.solver.lock().unwrap_or_else(|e| e.into_inner());
        if solver.is_none() {
            *solver = Some(normal_solver(&self.grid, &self.material, self.blend.clone())?);
        }
        let solver = solver.as_mut().expect("made above");
        let c = Arc::new(solve(solver, &self.grid, &self.h_mm, fn_n)?);
        cache.push(Arc::clone(&c));
        Ok(c)
    }

    /// The normal contact at the nominal load.
    pub fn nominal_contact(&self) -> &NormalContact {
        &self.nominal
    }

    /// The normal contact at `fn_n`, or, if it cannot be solved (the problem checks every load
    /// of a history before any run), an empty contact that carries nothing.
    fn contact_or_empty(&self, fn_n: f64) -> Arc<NormalContact> {
        self.normal_at(fn_n).unwrap_or_else(|_| {
            Arc::new(NormalContact {
                fn_n,
                pn_mpa: vec![0.0; self.grid.len()],
                ellipse: HertzContact { fn_n, ..self.nominal.ellipse },
                edge_load_share: 0.0,
            })
        })
    }
}

/// A nominal normal contact kept for the process with what it was solved of (grid, the
/// material's elastic constants and sheet, the undeformed distance, the load; no blending): the
/// scenes of one deck run in one process (`creepbench simulate SCENE...`) often share their
/// geometry and load (ertz_temperature.inp's four cases), whose normal problem is then solved
/// once; the same inputs bit for bit, the same pressure.
struct Kept {
    grid: Grid,
    material_bits: [u64; 3],
    h_mm: Vec<f64>,
    contact: NormalContact,
}

/// The contacts [`Kept`] (the newest last) and how many.
static KEPT: Mutex<Vec<Arc<Kept>>> = Mutex::new(Vec::new());
const KEPT_CONTACTS: usize = 4;

impl Kept {
    /// The bits of the material's constants the normal problem reads.
    fn material_bits(m: &Material) -> [u64; 3] {
        [m.g_mpa, m.poisson, m.sheet_mm3_per_n].map(f64::to_bits)
    }

    /// Whether this contact was solved of these inputs, bit for bit.
    fn is_of(&self, grid: &Grid, material: &Material, h_mm: &[f64], fn_n: f64) -> bool {
        self.contact.fn_n.to_bits() == fn_n.to_bits()
            && self.material_bits == Self::material_bits(material)
            && self.grid == *grid
            && self.h_mm.len() == h_mm.len()
            && self.h_mm.iter().zip(h_mm).all(|(a, b)| a.to_bits() == b.to_bits())
    }

    /// The kept contact of these inputs, if any.
    fn find(grid: &Grid, material: &Material, h_mm: &[f64], fn_n: f64) -> Option<NormalContact> {
        let kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
        kept.iter().rev().find(|k| k.is_of(grid, material, h_mm, fn_n)).map(|k| k.contact.clone())
    }

    /// Keep `contact`, solved of these inputs (the oldest dropped beyond [`KEPT_CONTACTS`]).
    fn keep(grid: &Grid, material: &Material, h_mm: &[f64], contact: NormalContact) {
        let k = Kept { grid: grid.clone(), material_bits: Self::material_bits(material), h_mm: h_mm.to_vec(), contact };
        let mut kept = KEPT.lock().unwrap_or_else(|e| e.into_inner());
        if kept.len() == KEPT_CONTACTS {
            kept.remove(0);
        }
        kept.push(Arc::new(k));
    }
}

/// The normal solver of `grid`'s elements of `material`, with `blend`.
fn normal_solver(grid: &Grid, material: &Material, blend: Option<Blend>) -> Result<NormalSolver, ContactError> {
    let kernel = Kernel::new(grid.mx, grid.my, grid.dx_mm, grid.dy_mm, material.g_mpa, material.poisson, 0.0)?
        .with_sheet(material.sheet_mm3_per_n)?;
    let mut solver = NormalSolver::new(&kernel)?;
    solver.set_blend(blend)?;
    Ok(solver)
}

/// The normal problem at `fn_n`, converged, with its equivalent ellipse.
fn solve(solver: &mut NormalSolver, grid: &Grid, h_mm: &[f64], fn_n: f64) -> Result<NormalContact, ContactError> {
    let pn_mpa = solver.solve(h_mm, fn_n, &NormalParams::default())?.converged_pn_mpa()?;
    contact_of(grid, fn_n, pn_mpa)
}

/// The normal contact of pressure `pn_mpa` (grid order) at `fn_n`: its equivalent ellipse and
/// the share of the load on the grid's edge.
fn contact_of(grid: &Grid, fn_n: f64, pn_mpa: Vec<f64>) -> Result<NormalContact, ContactError> {
    let total: f64 = pn_mpa.iter().sum();
    let edge: f64 = pn_mpa.iter().enumerate().filter(|(k, _)| grid.on_edge(*k)).map(|(_, p)| p).sum();
    let ellipse = equivalent_ellipse(grid, &pn_mpa, fn_n).ok_or(ContactError::NoContact)?;
    Ok(NormalContact { fn_n, pn_mpa, ellipse, edge_load_share: edge / total })
}

/// Kik & Piotrowski's equivalent ellipse of the loaded elements: the contact's area A and the
/// ratio of its extents (length L along x, width W along y, in whole elements) kept,
/// `a = √(A/π) √(L/W)`, `b = √(A/π) √(W/L)` (CONTACT's `equiv_ellipse`).
pub fn equivalent_ellipse(grid: &Grid, pn_mpa: &[f64], fn_n: f64) -> Option<HertzContact> {
    let loaded: Vec<usize> = (0..grid.len()).filter(|&k| pn_mpa[k] > 0.0).collect();
    if loaded.is_empty() {
        return None;
    }
    let span = |f: &dyn Fn(usize) -> usize| {
        let (lo, hi) = loaded.iter().fold((usize::MAX, 0), |(lo, hi), &k| (lo.min(f(k)), hi.max(f(k))));
        (hi - lo + 1) as f64
    };
    let length = grid.dx_mm * span(&|k| k % grid.mx);
    let width = grid.dy_mm * span(&|k| k / grid.mx);
    let area = grid.element_area_mm2() * loaded.len() as f64;
    let r = (area / PI).sqrt();
    Some(HertzContact { a_mm: r * (length / width).sqrt(), b_mm: r * (width / length).sqrt(), fn_n })
}

impl ContactGeometry for ElementGeometry {
    fn kind(&self) -> &'static str {
        self.kind
    }

    fn elliptic(&self) -> bool {
        false
    }

    fn nominal(&self) -> HertzContact {
        self.nominal.ellipse
    }

    fn ellipse_at(&self, fn_n: f64) -> HertzContact {
        self.contact_or_empty(fn_n).ellipse
    }

    fn undeformed_distance_mm(&self, _grid: &Grid, _fn_n: f64, _material: &Material) -> Vec<f64> {
        self.h_mm.clone()
    }

    /// The exact normal pressure (the pressure shape of `[model] pressure` is Hertzian and does
    /// not apply); each row's leading edge is the upstream face of its first loaded element.
    fn planform(&self, grid: &Grid, fn_n: f64, _shape: PressureShape) -> Planform {
        let c = self.contact_or_empty(fn_n);
        Planform::of_pressure(grid, c.ellipse, c.pn_mpa.clone())
    }

    fn edge_load_share(&self, fn_n: f64) -> f64 {
        self.contact_or_empty(fn_n).edge_load_share
    }

    fn normal_pressure_mpa(&self, fn_n: f64) -> Option<Vec<f64>> {
        self.normal_at(fn_n).ok().map(|c| c.pn_mpa.clone())
    }

    fn given_pressure_mpa(&self, fn_n: f64) -> Option<&[f64]> {
        (self.given && fn_n == self.nominal.fn_n).then_some(&self.nominal.pn_mpa)
    }

    fn planform_error(&self, fn_n: f64) -> Option<ContactError> {
        self.normal_at(fn_n).err()
    }
}
