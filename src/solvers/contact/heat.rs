//! Surface temperatures after a steady solve (CONTACT's H = 3, `m_scontc.f90`: `calc_temp` after
//! the tangential problem): the frictional power density of each slipping element from its
//! traction and slip, handed to the shared physics ([`crate::physics::temperature`]).

use super::mirror;
use super::tangential::{ElementState, StepResult};
use crate::physics::temperature::{surface_temperatures, Heating, Temperatures, Thermal};
use crate::physics::Grid;

/// The history's columns of a run with surface temperatures: each body's largest over the
/// contact [°C].
pub const COLUMNS: [&str; 2] = ["temp1_max_c", "temp2_max_c"];

/// The frictional power density |τ| |s|/dt of each element [N/(mm s)]: zero where it does not
/// slip; `dt_s` the time of the slip `s` of the solve (steady: dx/V).
pub fn power_density(r: &StepResult, dt_s: f64) -> Vec<f64> {
    (0..r.px.len())
        .map(|k| match r.state[k] {
            ElementState::Slip => r.px[k].hypot(r.py[k]) * r.sx[k].hypot(r.sy[k]) / dt_s,
            _ => 0.0,
        })
        .collect()
}

/// Both bodies' surface temperatures of steady solve `r` on pressure `pn` (the solver's frame,
/// material moving towards +x), in the scene's frame: mirrored back where the solver works
/// mirrored (CHI = 180°).
pub fn temperatures(
    grid: &Grid,
    bodies: &[Thermal; 2],
    pn: &[f64],
    r: &StepResult,
    v_mm_s: f64,
    mirrored: bool,
) -> Temperatures {
    let contact: Vec<bool> = pn.iter().map(|&p| p > 0.0).collect();
    let q = power_density(r, grid.dx_mm / v_mm_s);
    let t = surface_temperatures(&Heating { grid, contact: &contact, power_density: &q, v_mm_s }, bodies);
    match mirrored {
        true => Temperatures { body: t.body.map(|b| mirror::field(grid.mx, &b)) },
        false => t,
    }
}

/// Body 1's surface temperature in the solver's frame without frictional heat (the bodies meet
/// at their effusivity mean in the contact, [`surface_temperatures`] with q = 0): the start of
/// the temperature law's fixed point ([`super::tempdep`]).
pub fn unheated(grid: &Grid, bodies: &[Thermal; 2], pn: &[f64], v_mm_s: f64) -> Vec<f64> {
    let contact: Vec<bool> = pn.iter().map(|&p| p > 0.0).collect();
    let q = vec![0.0; pn.len()];
    let [one, _] = surface_temperatures(&Heating { grid, contact: &contact, power_density: &q, v_mm_s }, bodies).body;
    one
}

/// The largest temperature of each body over the contact of pressure `pn` (the scene's frame).
pub fn maxima(t: &Temperatures, pn: &[f64]) -> [f64; 2] {
    let contact: Vec<bool> = pn.iter().map(|&p| p > 0.0).collect();
    [t.max_in_contact(0, &contact), t.max_in_contact(1, &contact)]
}
