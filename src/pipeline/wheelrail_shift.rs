//! A sequence of shifts (`[wheelrail] motion = "shift_sequence"`; CONTACT's T = 1, the first case
//! from rest, P = 0 after it) or of transient rolling steps after a steady case
//! (`"rolling_sequence"`, T = 3 then T = 2): the cases run in order, each taking the patches the one
//! before left ([`crate::wheelrail::shift`]: connected by overlap, merged, copied or kept, the grid widened
//! to the contact of the time before) and the exact theory's tractions on them.

use super::wheelrail::{solve_step, CaseResult, EXACT};
use crate::error::Error;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::shift::{self, IndexBox, OldPatch, Previous};
use crate::wheelrail::{Motion, Vertical, WheelRailCase};

/// Solve `cases` (each with its track position `s_ws_mm`) in order, each continuing the one
/// before; the first from rest, or with `steady_start` steady rolling (CONTACT's T = 3 before
/// T = 1 with P = 0), its tractions put on the material-fixed super-grid at its reference's
/// nearest element (`shift_grid_super`: S_WS plus the reference's track x, over DX).
pub fn solve_sequence<'a>(
    cases: impl IntoIterator<Item = (WheelRailCase<'a>, f64)>,
    steady_start: bool,
    models: &[String],
    friction: &Friction,
    on_error: impl FnMut(usize, Error) -> Error,
) -> Result<Vec<CaseResult>, Error> {
    let mut s_start_mm = 0.0;
    let cases = cases.into_iter().enumerate().map(|(k, (case, s_ws_mm))| {
        let motion = if k == 0 && steady_start { Motion::Rolling } else { Motion::Shift { s_ws_mm } };
        if k == 0 {
            s_start_mm = s_ws_mm;
        }
        WheelRailCase { motion, ..case }
    });
    let cases: Vec<_> = cases.collect();
    solve_in_order(cases, s_start_mm, models, friction, on_error)
}

/// Transient rolling (`[wheelrail] motion = "rolling_sequence"`; CONTACT's T = 3 then T = 2 with
/// P = 0): the first case steady rolling, its tractions put on the super-grid at its reference's
/// nearest element (`shift_grid_super`), or `from_rest` one transient step from zero tractions
/// (T = 2, P = 2); each later case one transient rolling step of `dq_mm` continuing the one before.
pub fn solve_rolling_sequence<'a>(
    cases: impl IntoIterator<Item = WheelRailCase<'a>>,
    (dq_mm, from_rest): (f64, bool),
    models: &[String],
    friction: &Friction,
    on_error: impl FnMut(usize, Error) -> Error,
) -> Result<Vec<CaseResult>, Error> {
    let cases = cases.into_iter().enumerate().map(|(k, case)| {
        let motion = if k == 0 && !from_rest { Motion::Rolling } else { Motion::Transient { dq_mm } };
        WheelRailCase { motion, ..case }
    });
    solve_in_order(cases, 0.0, models, friction, on_error)
}

/// Solve `cases` in order, each given the patches the one before left (a steady case given an
/// empty set, so that it keeps its tractions for the next, on the super-grid whose anchor is
/// `s_super_mm` along the track: S_WS before shifts, 0 before transient rolling).
fn solve_in_order<'a>(
    cases: impl IntoIterator<Item = WheelRailCase<'a>>,
    s_super_mm: f64,
    models: &[String],
    friction: &Friction,
    mut on_error: impl FnMut(usize, Error) -> Error,
) -> Result<Vec<CaseResult>, Error> {
    let mut previous: Option<Previous> = None;
    // The other models' own histories: the same patches with each one's tractions.
    let others: Vec<&String> = models.iter().filter(|m| m.as_str() != EXACT).collect();
    let mut histories: Vec<(String, Previous)> = Vec::new();
    let mut out = Vec::new();
    for (k, case) in cases.into_iter().enumerate() {
        let steady = case.motion == Motion::Rolling;
        if steady {
            previous = Some(Previous::default());
            histories.clear();
        }
        if let Some(p) = previous.as_mut() {
            p.iterated = matches!(case.vertical, Vertical::Force { .. });
        }
        for (_, h) in histories.iter_mut() {
            h.iterated = matches!(case.vertical, Vertical::Force { .. });
        }
        let case = WheelRailCase { previous: previous.as_ref(), ..case };
        let result = solve_step(&case, models, friction, &histories).map_err(|e| on_error(k, e))?;
        let mut left = left_for_next(&result, previous.as_ref(), EXACT);
        let mut next: Vec<(String, Previous)> = others
            .iter()
            .map(|m| {
                let before = histories.iter().find(|(h, _)| h == *m).map(|(_, h)| h).or(previous.as_ref());
                ((*m).clone(), left_for_next(&result, before, m))
            })
            .collect();
        if steady {
            on_super_grid(&mut left, &result, s_super_mm);
            for (_, h) in next.iter_mut() {
                on_super_grid(h, &result, s_super_mm);
            }
        }
        previous = Some(left);
        histories = next;
        out.push(result);
    }
    Ok(out)
}

/// A steady case's patches put on the super-grid of transient rolling that follows it: its grid
/// lies on multiples of DX, DS from its reference, which CONTACT snaps to the super-grid's nearest
/// element (`shift_grid_super`: the reference's track x and rail arc length over DX, DS, rounded);
/// its contact is the contact of the time before (`igv` of steady rolling). Before shifts the
/// super-grid is fixed in the material: the reference's x counts from −S_WS (`s_super_mm`).
fn on_super_grid(left: &mut Previous, result: &CaseResult, s_super_mm: f64) {
    for (old, p) in left.patches.iter_mut().zip(&result.normal.patches) {
        let g = &p.geometry.grid;
        let di = ((s_super_mm + p.geometry.frame.origin.x) / g.dx_mm).round() as i64;
        let dj = (p.geometry.rail_s_mm.unwrap_or(0.0) / g.ds_mm).round() as i64;
        old.grid =
            IndexBox { x: [old.grid.x[0] + di, old.grid.x[1] + di], s: [old.grid.s[0] + dj, old.grid.s[1] + dj] };
        old.contact_before = Some(old.contact.clone());
    }
}

/// The patches a solved case leaves for the next: each of its patches with `model`'s tractions
/// (zero where it keeps none), its contact and the contact of the old patches it continued; then
/// the old patches none of its patches connected to (`previous`: those `model` had, with its
/// tractions).
fn left_for_next(result: &CaseResult, previous: Option<&Previous>, model: &str) -> Previous {
    let empty = Previous::default();
    let previous = previous.unwrap_or(&empty);
    let extents: Vec<_> = result.normal.patches.iter().map(|p| p.geometry.extent).collect();
    let links = shift::connections(&extents, previous);
    let theirs = result.models.iter().find(|(m, _, _)| m == model).map(|(_, f, _)| f);
    let new = result
        .normal
        .patches
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let g = &p.geometry.grid;
            let (px_mpa, py_mpa) = theirs
                .and_then(|f| f[k].shift_tractions_mpa.clone())
                .unwrap_or_else(|| (vec![0.0; g.len()], vec![0.0; g.len()]));
            // CONTACT's igv, the contact the next case widens its grid to: the contact of the old
            // patch this one continued, on this one's grid (copied with the previous tractions
            // after this case's widening); none where it started from rest.
            let inherited = shift::inherited(&links[k], previous);
            OldPatch {
                extent: p.geometry.extent,
                grid: IndexBox::of_grid(g),
                px_mpa,
                py_mpa,
                contact: shift::contact_of(&p.pn_mpa),
                contact_before: inherited.map(|o| shift::contact_on_grid(&o, g)),
            }
        })
        .collect();
    shift::next(new, previous, &links)
}
