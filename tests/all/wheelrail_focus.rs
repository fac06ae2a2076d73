//! The focused figures of the section "Wheel–rail contact" (issue 45): the shipped wheel flats
//! (`[report] group = "wheel_flat"`: FN, the approach, FX and FS against the distance rolled
//! −PITCH·NOMRAD) and crossings (`group = "crossing"`: YCP(R) and FN per patch against S_WS, or
//! Y_WS at one S_WS), every model the scene runs beside CONTACT's printed points, end to end on a
//! few cases of each.

use crate::common;
use creepbench::scene::wheelrail::{WheelRailFigures, WheelRailScene};
use std::path::{Path, PathBuf};

/// The shipped scene `name` copied into `dir` with its cases cut to `cases` (its paths made
/// absolute).
fn cut(dir: &Path, name: &str, cases: &[u64]) -> PathBuf {
    let shipped = common::root().join("scenes/wheelrail");
    let text = std::fs::read_to_string(shipped.join(format!("{name}.toml"))).unwrap();
    let text = text.replace("\"../../reference/", &format!("\"{}/reference/", common::root().display()));
    let table = std::fs::read_to_string(shipped.join(format!("{name}_cases.csv"))).unwrap();
    let mut lines = table.lines();
    let mut csv = format!("{}\n", lines.next().unwrap());
    for l in lines.filter(|l| cases.iter().any(|c| l.starts_with(&format!("{c},")))) {
        csv += &format!("{l}\n");
    }
    std::fs::write(dir.join(format!("{name}_cases.csv")), csv).unwrap();
    let (first, last) = (cases[0], cases[cases.len() - 1]);
    let text =
        text.lines().map(|l| if l.starts_with("cases = [") { format!("cases = [{first}, {last}]") } else { l.into() });
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text.collect::<Vec<_>>().join("\n")).unwrap();
    path
}

/// The models drawn in a figure (its `data-model`s) and its axes' titles.
fn drawn(svg: &str) -> Vec<String> {
    let mut out: Vec<String> =
        svg.split("data-model=\"").skip(1).map(|s| s[..s.find('"').unwrap()].to_string()).collect();
    out.sort();
    out.dedup();
    out
}

#[test]
fn the_shipped_wheel_flats_and_crossings_declare_their_figures() {
    let shipped = common::root().join("scenes/wheelrail");
    for (name, figures) in [
        ("wheelflat_1", WheelRailFigures::WheelFlat),
        ("chalmers_flat_fz125_1", WheelRailFigures::WheelFlat),
        ("mbench_intrup_1", WheelRailFigures::Crossing),
        ("mbench_locus_1", WheelRailFigures::Crossing),
    ] {
        let s = WheelRailScene::from_file(&shipped.join(format!("{name}.toml"))).unwrap();
        assert_eq!(s.report.figures, figures, "{name}");
        assert!(s.report.contact_output.as_ref().is_some_and(|p| p.exists()), "{name}");
    }
}

#[test]
fn the_wheel_flat_and_crossing_figures_draw_every_model_beside_contact() {
    let dir = common::tempdir("wheelrail_focus");
    cut(&dir, "wheelflat_1", &[1, 11, 26]);
    cut(&dir, "mbench_intrup_1", &[1, 24, 43]);
    cut(&dir, "mbench_locus_1", &[1, 20, 35]);
    let args = [
        "simulate",
        "wheelflat_1.toml",
        "mbench_intrup_1.toml",
        "mbench_locus_1.toml",
        "--out",
        "res",
        "--report",
        "rep",
    ];
    let (code, err) = common::run_in(&dir, &args, "focus");
    assert_eq!(code, Some(0), "{err}");
    let md = std::fs::read_to_string(dir.join("rep/validation.md")).unwrap();
    for heading in
        ["### wheelflat_1 (right wheel)", "### mbench_intrup_1 (right wheel)", "### mbench_locus_1 (right wheel)"]
    {
        assert!(md.contains(heading), "{heading}: {md}");
    }
    let figure = |file: &str| std::fs::read_to_string(dir.join("rep/figures").join(file)).unwrap();
    // The wheel flat: the exact theory's FN and approach, every model's FX and FS, CONTACT's points,
    // against the distance rolled.
    for (q, models) in [
        ("fn_n", &["CONTACT", "contact"][..]),
        ("pen_mm", &["CONTACT", "contact"][..]),
        ("fx_n", &["CONTACT", "contact", "fastsim", "uba"][..]),
        ("fs_n", &["CONTACT", "contact", "fastsim", "uba"][..]),
    ] {
        let svg = figure(&format!("wheelrail_wheelflat_1_flat_p1_{q}.svg"));
        assert_eq!(drawn(&svg), models, "{q}");
        assert!(svg.contains("distance rolled s = −PITCH · NOMRAD [mm]"), "{q}");
    }
    // The crossing along the track (each case its own S_WS) and across it (two patches: the wing
    // rail and the nose, the load passing from one to the other).
    for q in ["ycp_r_mm", "fn_n"] {
        let svg = figure(&format!("wheelrail_mbench_intrup_1_crossing_p1_{q}.svg"));
        assert_eq!(drawn(&svg), ["CONTACT", "contact"], "{q}");
        assert!(svg.contains("wheelset position along the track S_WS [mm]"), "{q}");
        for patch in [1, 2] {
            let svg = figure(&format!("wheelrail_mbench_locus_1_crossing_p{patch}_{q}.svg"));
            assert_eq!(drawn(&svg), ["CONTACT", "contact"], "{q} {patch}");
            assert!(svg.contains("lateral shift y_ws [mm]"), "{q}");
        }
    }
    assert!(md.contains("Only `contact` runs on this scene"), "{md}");
    assert!(md.contains("| fastsim | 1 | 3 |") && md.contains("| uba | totals | 3 |"), "{md}");
}
