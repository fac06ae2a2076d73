//! A sequence of shifts (`[wheelrail] motion = "shift_sequence"`; CONTACT's T = 1, the first case
//! from rest, P = 0 after it): the cases run in order, each taking the patches the one before
//! left ([`crate::wheelrail::shift`]: connected by overlap, merged, copied or kept, the grid widened
//! to the contact of the time before) and the exact theory's tractions on them.

use super::wheelrail::{solve_with, CaseResult, EXACT};
use crate::error::Error;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::shift::{self, IndexBox, OldPatch, Previous};
use crate::wheelrail::{Motion, Vertical, WheelRailCase};

/// Solve `cases` (each with its track position `s_ws_mm`) in order, each continuing the one
/// before; the first from rest.
pub fn solve_sequence<'a>(
    cases: impl IntoIterator<Item = (WheelRailCase<'a>, f64)>,
    models: &[String],
    friction: &Friction,
    mut on_error: impl FnMut(usize, Error) -> Error,
) -> Result<Vec<CaseResult>, Error> {
    let mut previous: Option<Previous> = None;
    let mut out = Vec::new();
    for (k, (case, s_ws_mm)) in cases.into_iter().enumerate() {
        if let Some(p) = previous.as_mut() {
            p.iterated = matches!(case.vertical, Vertical::Force { .. });
        }
        let case = WheelRailCase { motion: Motion::Shift { s_ws_mm }, previous: previous.as_ref(), ..case };
        let result = solve_with(&case, models, friction).map_err(|e| on_error(k, e))?;
        previous = Some(left_for_next(&result, previous.as_ref()));
        out.push(result);
    }
    Ok(out)
}

/// The patches a solved case leaves for the next: each of its patches with the exact theory's
/// tractions, its contact and the contact of the old patches it continued; then the old patches
/// none of its patches connected to.
fn left_for_next(result: &CaseResult, previous: Option<&Previous>) -> Previous {
    let empty = Previous::default();
    let previous = previous.unwrap_or(&empty);
    let extents: Vec<_> = result.normal.patches.iter().map(|p| p.geometry.extent).collect();
    let links = shift::connections(&extents, previous);
    let exact = result.models.iter().find(|(m, _, _)| m == EXACT).map(|(_, f, _)| f);
    let new = result
        .normal
        .patches
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let g = &p.geometry.grid;
            let (px_mpa, py_mpa) = exact
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
