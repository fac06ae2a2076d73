//! The interface layer (CONTACT's M = 4, issue 46) as a scene gives it: `[material]
//! layer_g_mpa`, `layer_thickness_mm` read together or not at all, the exact solver only, and
//! `export contact` both ways (M = 4 with GG3, LAYTHK; refused in transient rolling). Its physics
//! against closed forms: `solvers/contact/tangential/tests_layer.rs`; against CONTACT's printed
//! tractcurv.inp 31-60: the suite contact_public (tests/all/contact_public.rs).

use crate::common::{scene_text, tempdir};
use std::process::Command;

const LAYER: &str = "g_mpa = 82000.0\npoisson = 0.28\nlayer_g_mpa = 8200.0\nlayer_thickness_mm = 1.25";

fn text(material: &str, solvers: &str, creepage: &str) -> String {
    scene_text("layer", solvers, 0.3, 8, creepage, "").replace("g_mpa = 82000.0\npoisson = 0.28", material)
}

/// `creepbench ARGS` in `dir` with `s.toml` holding `scene`: (exit code, stderr).
fn run(dir_name: &str, scene: &str, args: &[&str]) -> (Option<i32>, String, std::path::PathBuf) {
    let dir = tempdir(dir_name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(&dir).args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stderr).to_string(), dir)
}

#[test]
fn the_layer_is_read_with_both_keys_and_the_exact_model_only() {
    let steady = "kind = \"sweep\"\nover = \"cx\"\nat = [0.001, 0.002]";
    let p = crate::common::problem(&text(LAYER, "[\"contact\"]", steady));
    let layer = p.material.layer.expect("a layer");
    assert_eq!((layer.g_mpa, layer.thickness_mm), (8200.0, 1.25));
    assert_eq!(p.material.layer_flexibility_mm_per_mpa(), 1.25 / 8200.0);
    // A thickness of 0 is no layer (CONTACT's LAYTHK < 1e-10).
    let none = crate::common::problem(&text(&LAYER.replace("1.25", "0.0"), "[\"contact\"]", steady));
    assert_eq!(none.material.layer, None);
    let simulate = ["simulate", "s.toml", "--out", "out"];
    let half = "g_mpa = 82000.0\npoisson = 0.28\nlayer_g_mpa = 8200.0";
    let (code, err, dir) = run("layer_half", &text(half, "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_thickness_mm") && err.contains("missing"), "{err}");
    assert!(!dir.join("out").exists());
    let (code, err, _) =
        run("layer_range", &text(&LAYER.replace("8200.0", "-1.0"), "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_g_mpa"), "{err}");
    let (code, err, dir) = run("layer_fastsim", &text(LAYER, "[\"contact\", \"fastsim\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("an interface layer only with the exact model"), "{err}");
    assert!(!dir.join("out").exists());
}

#[test]
fn the_layer_exports_as_m4_and_imports_back_and_transient_rolling_is_refused() {
    let steady = "kind = \"sweep\"\nover = \"cx\"\nat = [0.001, 0.002]";
    let (code, err, dir) =
        run("layer_export", &text(LAYER, "[\"contact\"]", steady), &["export", "contact", "s.toml", "--out", "back"]);
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/layer.inp")).unwrap();
    assert!(deck.contains("  8200.0   1.25   0.0   0.0    GG3, LAYTHK, TAU_C0, K_TAU"), "{deck}");
    // M = 4 in both cases: the first reads the material (C = 2), the second keeps it (C = 0).
    assert!(deck.contains("  022420      L-D-C-M-Z-E") && deck.contains("  100400      L-D-C-M-Z-E"), "{deck}");
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(&dir)
        .args(["import", "contact", "back/layer.inp", "--out", "again"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let again = std::fs::read_to_string(dir.join("again/layer_1.toml")).unwrap();
    assert!(again.contains("layer_g_mpa = 8200.0") && again.contains("layer_thickness_mm = 1.25"), "{again}");
    let transient = "kind = \"step\"\nc = 0.001\nsteps = 2";
    let (code, err, dir) = run(
        "layer_transient",
        &text(LAYER, "[\"contact\"]", transient),
        &["export", "contact", "s.toml", "--out", "back"],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_g_mpa") && err.contains("transient rolling"), "{err}");
    assert!(!dir.join("back").exists());
}
