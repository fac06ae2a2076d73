//! `creepbench fit` (issue 14, calibration): a known parameter is recovered, the shipped fits of
//! the relaxation model and the UBA give the stated before/after errors against the exact solver,
//! the output is the same bytes run to run, and bad fit files are refused (exit 2, nothing written).

use crate::common;
use common::*;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn fit(file: &Path, out: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["fit", file.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap()
}

/// The value of `key = value` in the fitted block.
fn fitted(text: &str, key: &str) -> f64 {
    let doc: toml::Table = text.parse().unwrap();
    doc["model"][key].as_float().unwrap()
}

/// A row "| set | n | rows | norm | before | after |" of the before/after table: (before, after).
fn row(text: &str, set: &str, norm: &str) -> (f64, f64) {
    let line = text
        .lines()
        .map(|l| l.trim_start_matches("# "))
        .find(|l| l.starts_with(&format!("| {set} |")) && l.contains(&format!("| {norm}")))
        .unwrap_or_else(|| panic!("no row {set} {norm} in\n{text}"));
    let cells: Vec<&str> = line.split('|').map(str::trim).collect();
    (cells[5].parse().unwrap(), cells[6].parse().unwrap())
}

/// A fit of the relaxation length (start 10 mm, bounds [1, 60] mm) on the scenes `fit` of `suite`.
fn relaxation_fit(name: &str, against: &str, suite: &str, fit: &str) -> String {
    format!(
        r#"[fit]
name = "{name}"
model = "relaxation"
against = "{against}"
norm = "rms_df"
suites = ["{suite}"]
fit = ["{fit}"]

[[fit.param]]
name = "l"
start = 10.0
bounds = [1.0, 60.0]

[set]
"model.relaxation_length_mm" = "{{l}}"
"#
    )
}

/// A suite of one thesis sine scene running the relaxation model with a given length, and a fit
/// of that length against the same model as written: the fit must find it.
#[test]
fn recovers_a_known_relaxation_length_and_is_deterministic() {
    let dir = tempdir("fit_recover");
    let suite = dir.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    let mut scene: toml::Table = suite_scene_text("thesis", "sine_f30_mu10").parse().unwrap();
    scene.insert("solvers".into(), toml::Value::Array(vec!["relaxation".into()]));
    let model = scene.entry("model").or_insert_with(|| toml::Value::Table(Default::default()));
    model.as_table_mut().unwrap().insert("relaxation_length_mm".into(), 21.5.into());
    std::fs::write(suite.join("sine_f30_mu10.toml"), scene.to_string()).unwrap();
    let spec = dir.join("recover.toml");
    std::fs::write(&spec, relaxation_fit("recover", "solver:relaxation", "suite", "sine_*")).unwrap();
    let (a, b) = (dir.join("a.toml"), dir.join("b.toml"));
    for out in [&a, &b] {
        let o = fit(&spec, out);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let text = std::fs::read_to_string(&a).unwrap();
    let l = fitted(&text, "relaxation_length_mm");
    println!("{text}");
    assert!((l - 21.5).abs() < 1e-3, "fitted length {l} mm, written 21.5 mm");
    let (before, after) = row(&text, "fitted", "rms_df");
    assert!(before > 1e-2 && after < 1e-5, "rms |df| {before} -> {after}");
    assert_eq!(text, std::fs::read_to_string(&b).unwrap(), "two runs of one fit differ");
}

/// The shipped calibration of the relaxation model (fits/relaxation_sine.toml) against the exact
/// solver at 10 and 30 Hz: the fitted length and the errors it leaves, on the fitted scenes and
/// on the 14 held-out sine scenes (other frequencies, mu = 0.6). Measured when written:
/// L = 8.4664 mm (linear theory 13.44), held-out RMS |df| 0.03967 -> 0.02596, loop-area error
/// 44.5 % -> 11.2 %: the fitted lag generalises.
#[test]
fn relaxation_calibration_closes_most_of_the_loop_gap_on_held_out_scenes() {
    let dir = tempdir("fit_relaxation");
    let out = dir.join("relaxation.toml");
    let o = fit(&root().join("fits/relaxation_sine.toml"), &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&out).unwrap();
    println!("{text}");
    let l = fitted(&text, "relaxation_length_mm");
    assert!((l - 8.4664).abs() < 0.01, "fitted length {l} mm");
    let held = |norm| row(&text, "held out", norm);
    let (b, a) = held("rms_df");
    assert!((b - 0.03967).abs() < 2e-5 && (a - 0.02596).abs() < 2e-4, "held-out rms {b} -> {a}");
    let (b, a) = held("loop_area");
    assert!((b - 0.44517).abs() < 2e-4 && (a - 0.11214).abs() < 2e-3, "held-out loop error {b} -> {a}");
    let (b, a) = row(&text, "fitted", "rms_df");
    assert!((b - 0.07551).abs() < 2e-5 && (a - 0.04052).abs() < 2e-4, "fitted rms {b} -> {a}");
}

/// The same fit against CONTACT's own histories (`against = "reference"`) instead of the exact
/// solver's: CONTACT and the exact solver agree to 1e-7 on these scenes, so the fitted length must
/// agree with the shipped fit's to well within its own tolerance.
#[test]
fn fitting_against_contacts_histories_gives_the_same_length() {
    let dir = tempdir("fit_reference");
    let text = std::fs::read_to_string(root().join("fits/relaxation_sine.toml"))
        .unwrap()
        .replace("against = \"solver:contact\"", "against = \"reference\"")
        .replace("\"../scenes/thesis\"", &format!("{:?}", root().join("scenes/thesis").display().to_string()))
        .replace("holdout = [\"sine_f*_mu10\", \"sine_f*_mu06\"]", "holdout = [\"sine_f60_mu10\"]");
    let spec = dir.join("relaxation_reference.toml");
    std::fs::write(&spec, text).unwrap();
    let out = dir.join("out.toml");
    let o = fit(&spec, &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&out).unwrap();
    println!("{text}");
    let l = fitted(&text, "relaxation_length_mm");
    assert!((l - 8.4664).abs() < 0.01, "fitted length against CONTACT {l} mm");
    assert!(text.contains("against reference"), "{text}");
}

/// The shipped calibration of the UBA (fits/uba_sine.toml: the modified FASTSIM's slope reduction
/// on the UBA's flexibilities): it lowers the fitted scenes' RMS |df| only from 0.0846 to 0.0746
/// and raises the held-out scenes' from 0.0387 to 0.0456 — the UBA's gap is in its form, which
/// no flexibility reduction closes. The test pins that finding.
#[test]
fn uba_calibration_does_not_generalise() {
    let dir = tempdir("fit_uba");
    let out = dir.join("uba.toml");
    let o = fit(&root().join("fits/uba_sine.toml"), &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(&out).unwrap();
    println!("{text}");
    let (b, a) = row(&text, "fitted", "rms_df");
    assert!((b - 0.08457).abs() < 2e-5 && a < b && a > 0.07, "fitted rms {b} -> {a}");
    let (b, a) = row(&text, "held out", "rms_df");
    assert!((b - 0.03866).abs() < 2e-5 && a > b, "held-out rms {b} -> {a}");
}

/// Bad fit files: exit 2, the message names the field and the value, nothing is written.
#[test]
fn bad_fit_files_are_refused() {
    let dir = tempdir("fit_bad");
    let good =
        relaxation_fit("bad", "solver:contact", &root().join("scenes/thesis").display().to_string(), "sine_f10_mu10");
    let cases: [(&str, &str, &str, &str); 11] = [
        ("norm = \"rms_df\"", "norm = \"l2\"", "fit.norm", "\"l2\""),
        ("against = \"solver:contact\"", "against = \"contact\"", "fit.against", "\"contact\""),
        ("\"{l}\"", "\"{m}\"", "model.relaxation_length_mm", "{m}"),
        ("bounds = [1.0, 60.0]", "bounds = [60.0, 1.0]", "fit.param[0].bounds", "[60, 1]"),
        ("start = 10.0", "start = 100.0", "fit.param[0].start", "100"),
        ("fit = [\"sine_f10_mu10\"]", "fit = [\"nosuch*\"]", "fit.fit", "nosuch*"),
        ("norm = \"rms_df\"", "norm = \"rms_df\"\nlearning_rate = 1", "fit.learning_rate", "1"),
        ("bounds = [1.0, 60.0]", "bounds = [-5.0, 60.0]", "relaxation_length_mm", "-5"),
        ("\"model.relaxation_length_mm\" = \"{l}\"", "\"model.relaxation_length_mm\" = 3.0", "fit.param l", "not used"),
        ("norm = \"rms_df\"", "norm = \"delay_ratio\"", "fit.norm", "delay_ratio"),
        // A parameter the model ignores (the UBA has no relaxation length): refused, not 0 iterations.
        ("model = \"relaxation\"", "model = \"uba\"", "fit.param l", "ignores"),
    ];
    for (n, (from, to, field, value)) in cases.iter().enumerate() {
        let spec = dir.join(format!("bad{n}.toml"));
        let mut text = good.replace(from, to);
        if n == 9 {
            // delay_ratio on a steady scene: no scene has the norm.
            text = text.replace("sine_f10_mu10", "steady_exact_g22");
        }
        std::fs::write(&spec, text).unwrap();
        let out = dir.join(format!("out{n}.toml"));
        let o = fit(&spec, &out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "case {n}: {err}");
        assert!(err.contains(field) && err.contains(value), "case {n}: {err}");
        assert!(err.contains(&spec.display().to_string()), "case {n} does not name the file: {err}");
        assert!(!out.exists(), "case {n} wrote {}", out.display());
    }
    // An existing output is never replaced.
    let spec = dir.join("good.toml");
    std::fs::write(&spec, &good).unwrap();
    let out = dir.join("existing.toml");
    std::fs::write(&out, "keep me").unwrap();
    let o = fit(&spec, &out);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--out"));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "keep me");
}

/// `creepbench run` runs the fits of fits/ and puts each fitted variant beside its published model
/// over the suites it ran: on three thesis sine scenes the fitted relaxation length lowers the RMS
/// |df| against the exact theory, and the published column is the model ladder's own number.
#[test]
fn run_puts_the_fitted_variant_beside_the_published_model() {
    let dir = tempdir("fit_run");
    let suite = dir.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    for name in ["sine_f10_mu10", "sine_f60_mu10", "sine_f100_mu06"] {
        suite_scene_file("thesis", name, &suite);
    }
    // The shipped relaxation fit alone (its suite named from where it now lies), no re-timing.
    let fits = dir.join("fits");
    std::fs::create_dir_all(&fits).unwrap();
    let shipped = std::fs::read_to_string(root().join("fits/relaxation_sine.toml")).unwrap();
    let thesis = root().join("scenes/thesis");
    let fit = shipped.replace("\"../scenes/thesis\"", &format!("{:?}", thesis.to_str().unwrap()));
    assert_ne!(fit, shipped, "the fit names its suite relative to fits/");
    std::fs::write(fits.join("relaxation_sine.toml"), fit).unwrap();
    let (res, rep) = (dir.join("res"), dir.join("rep"));
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["run", "--quiet", "--timing-repeats", "0", "--fits"])
        .args([&fits, &PathBuf::from("--suite")])
        .args([&suite, &PathBuf::from("--results"), &res, &PathBuf::from("--report"), &rep])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let record: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(res.join("fits/relaxation_sine.json")).unwrap()).unwrap();
    let s = &record["suites"][0];
    assert_eq!((s["suite"].as_str(), s["scenes"].as_u64()), (Some("suite"), Some(3)), "{s}");
    let (published, fitted) = (s["published"][1].as_f64().unwrap(), s["fitted"][1].as_f64().unwrap());
    println!("RMS |df| published {published}, fitted {fitted}");
    assert!(fitted < 0.8 * published, "{published} -> {fitted}");
    let report = std::fs::read_to_string(rep.join("validation.md")).unwrap();
    let ladder_row = report.lines().find(|l| l.starts_with("| relaxation | suite |")).expect("the ladder's row");
    let ladder_rms: f64 = ladder_row.split('|').nth(6).unwrap().trim().parse().unwrap();
    assert_eq!(format!("{ladder_rms:.4}"), format!("{published:.4}"), "{ladder_row}");
    assert!(report.contains("The fitted variant beside the published `relaxation`"));
    // The before/after curves: the two fitted scenes, then the held-out one the fitted length
    // carries worst; on the fitted scenes the fitted curve is the closer to the exact theory.
    let curves = record["curves"].as_array().unwrap();
    let sets: Vec<(&str, &str)> =
        curves.iter().map(|c| (c["scene"].as_str().unwrap(), c["set"].as_str().unwrap())).collect();
    assert_eq!(sets[..2], [("sine_f10_mu10", "fitted"), ("sine_f30_mu10", "fitted")], "{sets:?}");
    assert_eq!(sets.len(), 3, "{sets:?}");
    assert_eq!(sets[2].1, "held out");
    let ys = |c: &serde_json::Value, k: &str| -> Vec<f64> {
        c[k].as_array().unwrap().iter().map(|p| p[1].as_f64().unwrap()).collect()
    };
    let rms =
        |a: &[f64], b: &[f64]| (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>() / a.len() as f64).sqrt();
    for c in &curves[..2] {
        let (target, before, after) = (ys(c, "target"), ys(c, "before"), ys(c, "after"));
        assert!(target.len() > 50 && before.len() == target.len() && after.len() == target.len(), "{}", c["scene"]);
        let (b, a) = (rms(&before, &target), rms(&after, &target));
        println!("{}: RMS |dfx| before {b:.4}, after {a:.4}", c["scene"]);
        assert!(a < 0.8 * b, "{}: {b} -> {a}", c["scene"]);
    }
    for (scene, _) in &sets {
        let svg = std::fs::read_to_string(rep.join(format!("figures/fit_relaxation_sine_{scene}.svg"))).unwrap();
        for model in ["contact", "relaxation", "relaxation (fitted)"] {
            assert!(svg.contains(&format!("data-model=\"{model}\"")), "{scene}: {model}");
        }
        assert!(report.contains(&format!("figures/fit_relaxation_sine_{scene}.svg")), "{scene}");
    }
}
