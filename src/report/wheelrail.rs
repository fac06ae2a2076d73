//! The section "Wheel–rail contact" (issue 44 item 8): the wheel–rail scenes that declare the
//! group `wheelrail`, drawn as the Manchester benchmark's users draw it — per wheel and patch the
//! contact position on the rail and on the wheel, the contact angle, FN, the creepages, FX, FS
//! and MN against the lateral shift (a shift's cases against the wheelset's position along the
//! track), every model beside CONTACT's printed points; the profiles
//! with the contact points and areas at the scene's `patch_cases`; the models' patch maps there;
//! and each model's error against the exact theory per patch and in the totals.

use crate::comparison::references::contact_output::printed::Printed;
use crate::comparison::references::contact_output::wheelrail::{Along, Patch, WheelRailCase as Printed1};
use crate::pipeline::wheelrail::CaseResult;
use crate::pipeline::wheelrail_view::{Outline, WheelRailView};
use crate::report::plot::{line_chart, patch_map, Axis, Series};
use crate::report::section::Section;
use crate::scene::wheelrail::{SideSpec, WheelRailFigures};
use crate::suite::wheelrail::{patch_numbers, PATCH_COLUMNS};
use std::fmt::Write;

/// The section's id and title.
pub const ID: &str = "wheelrail";
pub const TITLE: &str = "Wheel–rail contact";

/// The model every other is measured against (its normal solution is every model's).
const EXACT: &str = crate::solvers::contact::NAME;

/// A wheel–rail scene's results with CONTACT's printed cases (none: no `contact_output`).
pub struct Wheel<'a> {
    pub view: &'a WheelRailView,
    pub contact: &'a [Printed1],
}

/// A quantity of a patch drawn against the lateral shift: its column of `<model>_patches.csv`,
/// its axis title, whether the models differ in it, and CONTACT's printed value.
pub(super) struct Quantity {
    pub(super) column: &'static str,
    pub(super) title: &'static str,
    pub(super) per_model: bool,
    pub(super) printed: fn(&Patch) -> Option<Printed>,
}

pub(super) const QUANTITIES: [Quantity; 10] = [
    Quantity {
        column: "ycp_r_mm",
        title: "contact position on the rail y_r [mm]",
        per_model: false,
        printed: |p| p.reference.as_ref().map(|r| r.ycp_r_mm),
    },
    Quantity {
        column: "ycp_w_mm",
        title: "contact position on the wheel y_w [mm]",
        per_model: false,
        printed: |p| p.wheel_reference.as_ref().map(|r| r.ycp_w_mm),
    },
    Quantity {
        column: "deltcp_rad",
        title: "contact angle δ [rad]",
        per_model: false,
        printed: |p| p.reference.as_ref().map(|r| r.deltcp_tr_rad),
    },
    Quantity {
        column: "fn_n",
        title: "normal force FN [N]",
        per_model: false,
        printed: |p| p.totals.as_ref().map(|t| t.fn_n),
    },
    Quantity {
        column: "cksi",
        title: "longitudinal creepage ξ [–]",
        per_model: false,
        printed: |p| p.kinematics.as_ref().map(|k| k.cksi),
    },
    Quantity {
        column: "ceta",
        title: "lateral creepage η [–]",
        per_model: false,
        printed: |p| p.kinematics.as_ref().map(|k| k.ceta),
    },
    Quantity {
        column: "cphi_per_mm",
        title: "spin creepage φ [1/mm]",
        per_model: false,
        printed: |p| p.kinematics.as_ref().map(|k| k.cphi_per_mm),
    },
    Quantity {
        column: "fx_n",
        title: "longitudinal force FX [N]",
        per_model: true,
        printed: |p| p.totals.as_ref().map(|t| t.fx_n),
    },
    Quantity {
        column: "fs_n",
        title: "lateral force FS [N]",
        per_model: true,
        printed: |p| p.totals.as_ref().map(|t| t.fs_n),
    },
    Quantity {
        column: "mn_nmm",
        title: "spin moment MN [N·mm]",
        per_model: true,
        printed: |p| p.totals.as_ref().map(|t| t.mn_nmm),
    },
];

/// The lateral shift's axis.
const SHIFT: &str = "lateral shift y_ws [mm]";
/// A sequence of shifts' axis, or the cases' own positions (CONTACT's S_WS of each case).
const ALONG: &str = "wheelset position along the track S_WS [mm]";
/// An out-of-round wheel's axis: the distance the wheel rolled from PITCH = 0, −PITCH·NOMRAD.
const ROLLED: &str = "distance rolled s = −PITCH · NOMRAD [mm]";

/// What a scene's figures are drawn against: a wheel flat's (`[report] group = "wheel_flat"`)
/// against the distance the wheel rolled, −PITCH·NOMRAD (CONTACT's material angle θ = −PITCH at
/// the lowest point, user guide "Wheel-rail contact: out-of-round wheels"); cases that give their
/// own S_WS (a sequence of shifts, the Cattaneo → Carter transition of `m1_catt_shift`; the
/// crossing's cases of `mbench_intrup`) against S_WS; every other scene's against the lateral
/// shift; the axis title and each case's value.
pub(super) fn abscissa(view: &WheelRailView) -> (&'static str, Vec<f64>) {
    let s = &view.scene;
    if s.report.figures == WheelRailFigures::WheelFlat {
        return (ROLLED, s.cases.iter().map(|c| -c.pitch_rad * s.nominal_radius_mm).collect());
    }
    match s.case_positions_mm() {
        Some(positions) => (ALONG, positions),
        None => (SHIFT, s.cases.iter().map(|c| c.y_mm).collect()),
    }
}

/// A printed case's value on the scene's [`abscissa`]: −PITCH·NOMRAD of a wheel flat, its S_WS
/// where the cases give theirs, else its Y_WS.
fn printed_abscissa(view: &WheelRailView, c: &Printed1) -> Option<f64> {
    let pos = c.position.as_ref()?;
    if view.scene.report.figures == WheelRailFigures::WheelFlat {
        return Some(-pos.pitch_rad.value * view.scene.nominal_radius_mm);
    }
    match (view.scene.case_positions_mm(), pos.along) {
        (None, _) => Some(pos.y_mm.value),
        (Some(_), Along::TrackSMm(s)) => Some(s.value),
        (Some(_), Along::RollerXMm(_)) => None,
    }
}

/// A patch's value of `column` for model `k` of a case (`ycp_w_mm`: the view's).
fn value(view: &WheelRailView, case: usize, r: &CaseResult, k: usize, patch: usize, column: &str) -> Option<f64> {
    if column == "ycp_w_mm" {
        return view.ycp_w_mm.get(case)?.get(patch).copied();
    }
    let (name, forces, _) = r.models.get(k)?;
    let (p, f) = (r.normal_of(name).patches.get(patch)?, forces.get(patch)?);
    let at = PATCH_COLUMNS[2..].iter().position(|c| *c == column)?;
    Some(patch_numbers(r, p, f)[at])
}

/// The curves' group of a case: its yaw where the scene's cases repeat a value of the
/// [`abscissa`] (a crossed study of shift and yaw), else none.
fn grouping(view: &WheelRailView) -> impl Fn(f64) -> String {
    let xs = abscissa(view).1;
    let repeats = xs.iter().enumerate().any(|(i, x)| xs[..i].contains(x));
    move |yaw_rad: f64| if repeats { format!("yaw {:.4} rad", yaw_rad) } else { String::new() }
}

/// The series of one quantity of patch `patch`: one per model (or the exact theory's alone
/// where every model has the same), and CONTACT's printed points.
pub(super) fn series(w: &Wheel, q: &Quantity, patch: usize) -> Vec<Series> {
    let view = w.view;
    let group = grouping(view);
    let xs = abscissa(view).1;
    let mut out: Vec<Series> = Vec::new();
    for (k, model) in view.run.models.iter().enumerate() {
        if !q.per_model && model != EXACT && view.run.models.iter().any(|m| m == EXACT) {
            continue;
        }
        let mut by_group: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
        for (i, ((_, r), row)) in view.run.cases.iter().zip(&view.scene.cases).enumerate() {
            let Some(v) = value(view, i, r, k, patch, q.column) else { continue };
            let g = group(row.yaw_rad);
            match by_group.iter_mut().find(|(name, _)| *name == g) {
                Some((_, points)) => points.push((xs[i], v)),
                None => by_group.push((g, vec![(xs[i], v)])),
            }
        }
        out.extend(by_group.into_iter().map(|(g, points)| Series::model(model, points).in_group(g)));
    }
    let mut theirs: Vec<(String, Vec<(f64, f64)>)> = Vec::new();
    for c in w.contact {
        let (Some(pos), Some(p)) = (c.position.as_ref(), c.patches.get(patch)) else { continue };
        let (Some(v), Some(x)) = ((q.printed)(p), printed_abscissa(view, c)) else { continue };
        let g = group(pos.yaw_rad.value);
        match theirs.iter_mut().find(|(name, _)| *name == g) {
            Some((_, points)) => points.push((x, v.value)),
            None => theirs.push((g, vec![(x, v.value)])),
        }
    }
    out.extend(theirs.into_iter().map(|(g, points)| Series::reference("CONTACT", points).in_group(g)));
    out
}

/// The totals on the rail against the [`abscissa`]: FX(TR) and FY(TR) per model with CONTACT's.
fn totals_figures(w: &Wheel, name: &str, sec: &mut Section) {
    for (t, column, title) in
        [(0, "fx_tr", "total force on the rail FX(TR) [N]"), (1, "fy_tr", "total force on the rail FY(TR) [N]")]
    {
        let (along, xs) = abscissa(w.view);
        let mut series: Vec<Series> = Vec::new();
        for (k, model) in w.view.run.models.iter().enumerate() {
            let points = w.view.run.cases.iter().zip(&xs).map(|((_, r), &x)| (x, r.models[k].2.track_n[t]));
            series.push(Series::model(model, points.collect()));
        }
        let theirs = w.contact.iter().filter_map(|c| {
            let f = c.forces.as_ref()?;
            Some((printed_abscissa(w.view, c)?, if t == 0 { f.fx_tr_n.value } else { f.fy_tr_n.value }))
        });
        series.push(Series::reference("CONTACT", theirs.collect()));
        let file = format!("wheelrail_{name}_{column}.svg");
        let svg = line_chart(&format!("{name}: {title}"), &Axis::linear(along), &Axis::linear(title), &series);
        figure(sec, file, svg, &format!("{name} {column}"));
    }
}

pub(super) fn figure(sec: &mut Section, file: String, svg: String, alt: &str) {
    let _ = writeln!(sec.body, "![{alt}](figures/{file})");
    sec.figures.push((file, svg));
}

/// The profiles of one case with the contact areas (thick) and reference points, height up.
fn profiles_figure(name: &str, o: &Outline) -> String {
    let up = |v: &[(f64, f64)]| v.iter().map(|&(y, z)| (y, -z)).collect::<Vec<_>>();
    let mut series = vec![Series::model("rail", up(&o.rail_mm)), Series::model("wheel", up(&o.wheel_mm))];
    for (k, a) in o.areas_mm.iter().enumerate() {
        series.push(Series::model(format!("contact area, patch {}", k + 1), up(a)));
    }
    series.push(Series::reference("reference points", up(&o.points_mm)));
    line_chart(
        &format!("{name}, case {}: profiles and contact", o.contact_case),
        &Axis::linear("track y [mm]"),
        &Axis::linear("height −z [mm]"),
        &series,
    )
}

/// Per model and patch (and the totals), the largest difference from the exact theory over the
/// cases both solved.
pub(super) fn ladder(view: &WheelRailView, mu: f64) -> String {
    let Some(e) = view.run.models.iter().position(|m| m == EXACT) else {
        return format!("No `{EXACT}` among the models: no errors against the exact theory.\n");
    };
    let mut out = format!(
        "Each model against the exact theory (`{EXACT}`) on the same patches: the largest |ΔFX|, |ΔFS| [N] and |ΔMN| [N·mm] per patch over the cases that have it, the RMS of |Δ(FX, FS)| / (μ FN) (μ = {mu}), and the totals on the rail FX(TR), FY(TR).\n\n| model | patch | cases | max \\|ΔFX\\| [N] | max \\|ΔFS\\| or \\|ΔFY(TR)\\| [N] | max \\|ΔMN\\| [N·mm] | RMS \\|Δ(FX, FS)\\| / μFN |\n|---|---|---|---|---|---|---|\n"
    );
    let patches = view.run.cases.iter().map(|(_, r)| r.normal.patches.len()).max().unwrap_or(0);
    for (k, model) in view.run.models.iter().enumerate().filter(|(k, _)| *k != e) {
        for patch in 0..patches {
            let (mut n, mut fx, mut fs, mut mn, mut sq) = (0, 0.0f64, 0.0f64, 0.0f64, 0.0);
            for (_, r) in &view.run.cases {
                let (Some(a), Some(b)) = (r.models[k].1.get(patch), r.models[e].1.get(patch)) else { continue };
                n += 1;
                fx = fx.max((a.fx_n - b.fx_n).abs());
                fs = fs.max((a.fs_n - b.fs_n).abs());
                mn = mn.max((a.mn_nmm - b.mn_nmm).abs());
                sq += ((a.fx_n - b.fx_n).powi(2) + (a.fs_n - b.fs_n).powi(2)) / (mu * b.fn_n).powi(2);
            }
            if n > 0 {
                let rms = (sq / n as f64).sqrt();
                let _ = writeln!(out, "| {model} | {} | {n} | {fx:.1} | {fs:.1} | {mn:.0} | {rms:.4} |", patch + 1);
            }
        }
        let (mut fx, mut fy) = (0.0f64, 0.0f64);
        for (_, r) in &view.run.cases {
            fx = fx.max((r.models[k].2.track_n[0] - r.models[e].2.track_n[0]).abs());
            fy = fy.max((r.models[k].2.track_n[1] - r.models[e].2.track_n[1]).abs());
        }
        let _ = writeln!(out, "| {model} | totals | {} | {fx:.1} | {fy:.1} | — | — |", view.run.cases.len());
    }
    out
}

/// A wheel's heading: its name and side, its cases, models and CONTACT's printed cases.
pub(super) fn heading(w: &Wheel, sec: &mut Section) {
    let (view, name) = (w.view, w.view.scene.name.as_str());
    let side = if view.scene.side == SideSpec::Left { "left" } else { "right" };
    let _ = writeln!(
        sec.body,
        "### {name} ({side} wheel)\n\n{} cases, models {}; CONTACT's printed results: {}.\n",
        view.run.cases.len(),
        view.run.models.iter().map(|m| format!("`{m}`")).collect::<Vec<_>>().join(", "),
        if w.contact.is_empty() { "none declared".to_string() } else { format!("{} cases", w.contact.len()) }
    );
}

/// The most patches of a case of the wheel.
pub(super) fn patches(view: &WheelRailView) -> usize {
    view.run.cases.iter().map(|(_, r)| r.normal.patches.len()).max().unwrap_or(0)
}

/// One wheel: its text, figures, profiles, maps and ladder table.
fn wheel(w: &Wheel, sec: &mut Section) {
    let (view, name) = (w.view, w.view.scene.name.as_str());
    heading(w, sec);
    let patches = patches(view);
    for patch in 0..patches {
        let _ = writeln!(sec.body, "**Patch {}** (CONTACT's numbering: from the field side)\n", patch + 1);
        for q in &QUANTITIES {
            let series = series(w, q, patch);
            let title = format!("{name}, patch {}: {}", patch + 1, q.title);
            let file = format!("wheelrail_{name}_p{}_{}.svg", patch + 1, q.column);
            let along = Axis::linear(abscissa(view).0);
            figure(sec, file, line_chart(&title, &along, &Axis::linear(q.title), &series), &title);
        }
        sec.body.push('\n');
    }
    totals_figures(w, name, sec);
    let _ = writeln!(sec.body, "\n**Profiles and contact** (the cases of `patch_cases`)\n");
    for o in &view.outlines {
        let file = format!("wheelrail_{name}_profiles_{}.svg", o.contact_case);
        figure(sec, file, profiles_figure(name, o), &format!("{name} case {} profiles", o.contact_case));
    }
    let _ = writeln!(sec.body, "\n**Patch maps**: pressure (the normal solution the model's forces are on) with each model's slipping elements struck through, as its solve left them (in a sequence: the state its history reached); x along the track, s along the rail profile (y's sense)\n");
    for m in &view.maps {
        let title = format!("{name}, case {}, patch {}: {}", m.contact_case, m.patch, m.model);
        let file = format!("wheelrail_{name}_map_{}_{}_{}.svg", m.contact_case, m.patch, m.model);
        figure(sec, file, patch_map(&title, &m.cells, m.element_mm), &title);
    }
    let _ = writeln!(sec.body, "\n{}", ladder(view, view.scene.mu));
}

/// The section, if any wheel–rail scene declares the group `wheelrail`.
pub fn section(wheels: &[Wheel]) -> Option<Section> {
    let drawn: Vec<&Wheel> = wheels.iter().filter(|w| w.view.scene.report.in_section()).collect();
    if drawn.is_empty() {
        return None;
    }
    let mut sec = Section::new(
        TITLE,
        "Each wheel–rail scene of group `wheelrail` (docs/wheelrail.md), drawn as the Manchester benchmark (Shackleton & Iwnicki 2008) draws its results: against the wheelset's lateral shift (a sequence of shifts against the wheelset's position along the track), per contact patch. Every model solves the same patches, so the contact positions, angle, FN and creepages are the exact normal solution's (drawn once, as `contact`); FX, FS and MN are each model's. CONTACT's printed results are the black markers. Signs and frames are CONTACT's module-1 output's (forces on the rail, y to the right on both sides). A scene of group `wheel_flat` (an out-of-round wheel) draws FN, the approach, FX and FS per patch against the distance the wheel rolled; one of group `crossing` the contact position on the rail and FN per patch against S_WS (docs/report.md).\n\n".to_string(),
    );
    for w in drawn {
        match w.view.scene.report.figures {
            WheelRailFigures::WheelFlat => super::wheelrail_focus::wheel_flat(w, &mut sec),
            WheelRailFigures::Crossing => super::wheelrail_focus::crossing(w, &mut sec),
            _ => wheel(w, &mut sec),
        }
    }
    Some(sec)
}
