//! KPEC and ANALYN with FASTSIM (CONTACT's B = 5, 6 with M = 3): the pressure from an
//! approximate normal problem on the scene's undeformed distance ([`crate::physics::approximate`]:
//! Kik–Piotrowski with CONTACT's ellipse correction, or ANALYN) at the approach that carries the
//! row's FN, the tangential problem by Kalker's FASTSIM on that pressure, its flexibilities from
//! the equivalent ellipse of the approximate contact (Kik & Piotrowski: its area and
//! length-to-width ratio kept).

use super::fastsim_contact;
use super::{grid_model, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::approximate::{self, ApproximateContact, ApproximateError, Method};
use crate::physics::geometry::element::equivalent_ellipse;
use crate::physics::{Grid, HertzContact, Material, Planform};
use crate::problem::{LocalContact, Problem};
use crate::solvers::style::{Dash, Marker, ModelStyle, LIGHT};
use std::cell::RefCell;

/// KPEC with FASTSIM.
pub const KPEC: ModelDef = ModelDef {
    name: "kpec",
    summary: "KPEC (Kik–Piotrowski's virtual interpenetration with CONTACT's ellipse correction, B = 5) for the pressure, FASTSIM on it",
    check: check::<KPEC_METHOD>,
    build: |p| fastsim_contact::with_contact(p, contact::<KPEC_METHOD>),
    style: ModelStyle { colour: LIGHT[0], dash: Dash::Dashed, marker: Marker::TriangleLeft },
    own_normal: Some(Method::Kpec),
    extra_columns: fastsim_contact::MODEL.extra_columns,
    ..MODEL
};

/// ANALYN with FASTSIM.
pub const ANALYN: ModelDef = ModelDef {
    name: "analyn",
    summary: "ANALYN (Sichani, Enblom & Berg, VSD 52(12) 2014; CONTACT's B = 6) for the pressure, FASTSIM on it",
    check: check::<ANALYN_METHOD>,
    build: |p| fastsim_contact::with_contact(p, contact::<ANALYN_METHOD>),
    style: ModelStyle { colour: LIGHT[1], dash: Dash::DashDot, marker: Marker::TriangleRight },
    own_normal: Some(Method::Analyn),
    extra_columns: fastsim_contact::MODEL.extra_columns,
    ..MODEL
};

const KPEC_METHOD: u8 = 0;
const ANALYN_METHOD: u8 = 1;

/// What the two share.
const MODEL: ModelDef = grid_model(
    "",
    "",
    check::<KPEC_METHOD>,
    |p| fastsim_contact::with_contact(p, contact::<KPEC_METHOD>),
    ModelStyle { colour: LIGHT[0], dash: Dash::Dashed, marker: Marker::TriangleLeft },
);

fn method<const M: u8>() -> Method {
    if M == KPEC_METHOD {
        Method::Kpec
    } else {
        Method::Analyn
    }
}

/// The approximate contact at `fn_n` as FASTSIM's contact: the pressure handed in with the
/// geometry at that load (a wheel–rail patch's, this model's own normal problem solved once), else
/// the approximate normal problem solved here.
fn contact<const M: u8>(p: &Problem, fn_n: f64) -> Result<LocalContact, SolveError> {
    let pn_mpa = match p.geometry.given_pressure_mpa(fn_n) {
        Some(given) => given.to_vec(),
        None => {
            let h = p.geometry.undeformed_distance_mm(&p.grid, fn_n, &p.material);
            at_load(method::<M>(), p, &h, fn_n)?.pn_mpa
        }
    };
    let ellipse = equivalent_ellipse(&p.grid, &pn_mpa, fn_n).unwrap_or(HertzContact { fn_n, ..p.hertz() });
    Ok(p.local_contact_of(Planform::of_pressure(&p.grid, ellipse, pn_mpa)))
}

/// Any geometry (on Hertz's ellipse the undeformed distance on the grid gives Hertz's contact)
/// whose normal problem the approximation solves at every load of the scene (a load whose
/// pressure was handed in solved is carried).
fn check<const M: u8>(p: &Problem) -> Result<(), InputError> {
    let mut loads: Vec<f64> = p.loading.rows().map(|s| s.fn_n).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup();
    for fn_n in loads.into_iter().filter(|&f| p.geometry.given_pressure_mpa(f).is_none()) {
        let h = p.geometry.undeformed_distance_mm(&p.grid, fn_n, &p.material);
        at_load(method::<M>(), p, &h, fn_n).map_err(|e| {
            InputError::new(
                "contact.fn_n",
                fn_n,
                format!("a load the approximate normal problem carries on this grid ({e})"),
            )
        })?;
    }
    Ok(())
}

/// What [`approximate::at_load`] found last on this thread, with its inputs.
struct Found {
    method: Method,
    grid: Grid,
    material: Material,
    h_mm: Vec<u64>,
    fn_n: u64,
    contact: ApproximateContact,
}

thread_local! {
    static LAST: RefCell<Option<Found>> = const { RefCell::new(None) };
}

/// [`approximate::at_load`] on `p`'s grid and material, the last answer kept: the check and the
/// model's contact ask for the same load of one scene in turn (the inputs compared bit for bit,
/// so the answer is the one computed afresh).
fn at_load(method: Method, p: &Problem, h_mm: &[f64], fn_n: f64) -> Result<ApproximateContact, ApproximateError> {
    let bits: Vec<u64> = h_mm.iter().map(|h| h.to_bits()).collect();
    let same = |f: &Found| {
        f.method == method && f.fn_n == fn_n.to_bits() && f.h_mm == bits && f.grid == p.grid && f.material == p.material
    };
    if let Some(c) = LAST.with_borrow(|last| last.as_ref().filter(|f| same(f)).map(|f| f.contact.clone())) {
        return Ok(c);
    }
    let contact = approximate::at_load(method, &p.grid, h_mm, fn_n, &p.material)?;
    let found = Found { method, grid: p.grid.clone(), material: p.material, h_mm: bits, fn_n: fn_n.to_bits(), contact };
    let c = found.contact.clone();
    LAST.set(Some(found));
    Ok(c)
}
