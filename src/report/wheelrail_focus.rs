//! The focused figures of the section "Wheel–rail contact" (issue 45): a wheel flat (`[report]
//! group = "wheel_flat"`: FN, the approach, FX and FS per patch against the distance the wheel
//! rolled) and a crossing (`group = "crossing"`: the contact position on the rail YCP(R) and FN
//! per patch against S_WS, or Y_WS where the cases stand at one S_WS: the contact moving from the
//! wing rail to the nose and the load passing between them), every model beside
//! CONTACT's printed points, as the section's full figures draw them ([`super::wheelrail`]).

use super::wheelrail::{abscissa, figure, heading, ladder, patches, series, Quantity, Wheel, QUANTITIES};
use crate::report::plot::{line_chart, Axis};
use crate::report::section::Section;
use std::fmt::Write;

/// The approach of a patch (CONTACT's APPROACH: the interpenetration of the undeformed
/// surfaces), the vertical response where FZ is prescribed.
const APPROACH: Quantity = Quantity {
    column: "pen_mm",
    title: "approach (undeformed interpenetration) [mm]",
    per_model: false,
    printed: |p| p.totals.as_ref().map(|t| t.approach_mm),
};

/// The section's quantity of `column` (one of [`QUANTITIES`]).
fn quantity(column: &str) -> &'static Quantity {
    QUANTITIES.iter().find(|q| q.column == column).expect("a quantity of the section")
}

/// Per patch, one figure of each of `quantities` against the scene's abscissa.
fn figures(w: &Wheel, quantities: &[&Quantity], what: &str, sec: &mut Section) {
    let (view, name) = (w.view, w.view.scene.name.as_str());
    for patch in 0..patches(view) {
        let _ = writeln!(sec.body, "**Patch {}** (CONTACT's numbering: from the field side)\n", patch + 1);
        for q in quantities {
            let title = format!("{name}, patch {}: {}", patch + 1, q.title);
            let file = format!("wheelrail_{name}_{what}_p{}_{}.svg", patch + 1, q.column);
            let along = Axis::linear(abscissa(view).0);
            figure(sec, file, line_chart(&title, &along, &Axis::linear(q.title), &series(w, q, patch)), &title);
        }
        sec.body.push('\n');
    }
}

/// The models the figures leave out, if the scene runs the exact theory alone.
fn left_out(w: &Wheel, why: &str, sec: &mut Section) {
    if w.view.run.models.len() == 1 {
        let _ = writeln!(sec.body, "Only `{}` runs on this scene: {why}\n", w.view.run.models[0]);
    }
}

/// A wheel flat: FN (the vertical force), the approach, FX and FS per patch against the distance
/// rolled −PITCH·NOMRAD, as the flat turns under the contact; each model's error against the
/// exact theory.
pub(super) fn wheel_flat(w: &Wheel, sec: &mut Section) {
    heading(w, sec);
    let _ = writeln!(
        sec.body,
        "The wheel flat turning under the contact (FZ prescribed): the vertical force FN, the approach, and the traction FX, FS per patch against the distance the wheel rolled, s = −PITCH · NOMRAD (NOMRAD = {} mm).\n",
        w.view.scene.nominal_radius_mm
    );
    let quantities = [quantity("fn_n"), &APPROACH, quantity("fx_n"), quantity("fs_n")];
    figures(w, &quantities, "flat", sec);
    let _ = writeln!(sec.body, "{}", ladder(w.view, w.view.scene.mu));
}

/// A crossing: the contact position on the rail YCP(R) and FN per patch against S_WS (or Y_WS),
/// the contact moving from the wing rail to the nose and the load passing between them.
pub(super) fn crossing(w: &Wheel, sec: &mut Section) {
    heading(w, sec);
    let _ = writeln!(
        sec.body,
        "The wheel on the crossing: the contact position on the rail y_r and the normal force FN per patch against {}, the contact moving from the wing rail to the nose and the load passing between them.\n",
        abscissa(w.view).0
    );
    left_out(w, "the contact position and FN are the exact normal solution's, the same for every model.", sec);
    figures(w, &[quantity("ycp_r_mm"), quantity("fn_n")], "crossing", sec);
}
