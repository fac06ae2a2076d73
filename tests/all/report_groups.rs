//! Issue 47 item 2, scenes declare where they belong: a scene's `[report] group` (a study's
//! `[scene.report]` or an axis's `"report.group"`) decides its report section and figure group,
//! whatever its name; an unknown group is an input error naming the file, the key, the value and
//! every group (exit 2, nothing written).

use crate::common::{root, run_in, scene_text, tempdir};
use creepbench::scene::report::ReportGroup;
use std::path::Path;
use std::process::Command;

/// A step of the UBA on an 8x8 grid.
const STEP: &str = "kind = \"step\"\nc = 0.005\nsteps = 4";
/// Two periods of a sine of the UBA on an 8x8 grid.
const SINE: &str = "kind = \"sine\"\nc0 = 0.0\ncp = 0.002\nfreq_hz = 30.0\nperiods = 2.0";

/// A scene `name` of the UBA with `creepage`, declared in `group`, written to `suite/<name>.toml`.
fn write_scene(suite: &Path, name: &str, creepage: &str, group: &str) {
    std::fs::create_dir_all(suite).unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, creepage, &format!("[report]\ngroup = \"{group}\""));
    std::fs::write(suite.join(format!("{name}.toml")), text).unwrap();
}

/// A study `name` over μ whose `axis` lines (beside `"contact.mu" = [0.3, 0.4]`) may vary the
/// group, a step of the UBA as its template, written to `suite/<name>.toml`.
fn write_study(suite: &Path, name: &str, axis: &str) {
    std::fs::create_dir_all(suite).unwrap();
    let scene = scene_text("x", "[\"uba\"]", 0.4, 8, STEP, "");
    let template: String = scene
        .lines()
        .skip(1)
        .map(|l| match l.strip_prefix('[') {
            Some(table) => format!("[scene.{table}\n"),
            None => format!("{l}\n"),
        })
        .collect();
    let text = format!(
        "[study]\nname = \"{name}\"\nscene_name = \"{name}_mu{{mu}}\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3, 0.4]\nlabels = [\"03\", \"04\"]\n{axis}\n[scene]\n{template}"
    );
    std::fs::write(suite.join(format!("{name}.toml")), text).unwrap();
}

/// The lines of `md` under the heading `heading` (up to the next heading of its level or above).
fn under<'a>(md: &'a str, heading: &str) -> Vec<&'a str> {
    let level = heading.split(' ').next().unwrap();
    let mut lines = md.lines().skip_while(|l| *l != heading);
    assert!(lines.next().is_some(), "no {heading:?} in:\n{md}");
    lines.take_while(|l| !(l.starts_with('#') && l.split(' ').next().is_some_and(|h| h.len() <= level.len()))).collect()
}

#[test]
fn a_scene_lands_in_its_declared_group_whatever_its_name() {
    let dir = tempdir("report_groups_declared");
    let suite = dir.join("suite");
    // Names that no longer say where they belong (the report used to read `sine_f…_mu10`, `stab_`).
    write_scene(&suite, "renamed_sine", SINE, "sine_frequency_mu1");
    write_scene(&suite, "shaky", STEP, "stability");
    write_study(&suite, "mystudy", "\"report.group\" = [\"step_friction\", \"step_load\"]");
    let (res, rep) = (dir.join("res"), dir.join("rep"));
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["run", "--quiet", "--suite"])
        .args([suite.as_os_str(), "--results".as_ref(), res.as_os_str(), "--report".as_ref(), rep.as_os_str()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(rep.join("validation.md")).unwrap();
    let sines = under(&md, "### Sine: frequency at μ = 1").join("\n");
    assert!(sines.contains("figures/renamed_sine_history.svg") && sines.contains("renamed_sine_loop.svg"), "{sines}");
    assert!(under(&md, "### Stability and extreme cases").join("\n").contains("figures/shaky_history.svg"), "{md}");
    assert!(under(&md, "## Stability").iter().any(|l| l.starts_with("| shaky | uba |")), "{md}");
    assert!(under(&md, "### Step response: friction").join("\n").contains("mystudy_mu03_history.svg"), "{md}");
    assert!(under(&md, "### Step response: load, shape and creepage").join("\n").contains("mystudy_mu04_"), "{md}");
    assert!(!md.contains("### Other scenes"), "{md}");
    let json = std::fs::read_to_string(res.join("renamed_sine/scene.json")).unwrap();
    assert!(json.contains("\"report_group\": \"sine_frequency_mu1\""), "{json}");
}

#[test]
fn an_unknown_group_is_refused_naming_the_file_the_key_the_value_and_every_group() {
    let dir = tempdir("report_groups_unknown");
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    write_scene(&dir.join("suite"), "bad", STEP, "sines");
    write_study(&dir.join("studies"), "badstudy", "\"report.group\" = [\"steady\", \"stabilty\"]");
    let cases: [(&[&str], &str, &str); 4] = [
        (&["simulate", "suite/bad.toml", "--out", "out"], "bad.toml", "\"sines\""),
        (
            &["run", "--quiet", "--suite", "suite", "--results", "out/r", "--report", "out/p", "--reference", refs],
            "bad.toml",
            "\"sines\"",
        ),
        (&["expand", "studies/badstudy.toml", "--out", "out"], "badstudy.toml", "\"stabilty\""),
        (&["simulate", "studies/badstudy.toml", "--out", "out"], "badstudy.toml", "\"stabilty\""),
    ];
    for (args, file, value) in cases {
        let (code, err) = run_in(&dir, args, &args.join(" "));
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(file) && err.contains("report.group") && err.contains(value), "{args:?}: {err}");
        assert!(ReportGroup::ALL.iter().all(|g| err.contains(g.id())), "{args:?} lists every group: {err}");
    }
}
