//! Issue 46: CONTACT's module-1 frictional heating (H = 3) and friction of the surface
//! temperature (L = 6) as wheel–rail scenes: `testbank/examples_temp/m1_tempdep.inp` cases 1 and 2
//! import as two scenes (`[material]`'s heat keys, `[friction] law = "temperature"`,
//! `[contact_solver]` with CONTACT's stop), case 3 (L = 6 varying across the rail: two sets at
//! −10° and 20°) as a third, its law per control point (`[wheelrail] mu_values`, `tref_c_values`,
//! …); the scene refuses the temperature law where it cannot hold. The gate against CONTACT's
//! print is tests/all/wheelrail_mbench.rs's (scenes/wheelrail/m1_tempdep_*).

use crate::common::{self, root};
use creepbench::physics::TemperatureLaw;
use creepbench::scene::wheelrail::WheelRailScene;
use std::process::Command;

fn creepbench(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).args(args).output().expect("runs")
}

#[test]
fn m1_tempdep_imports_heat_and_the_temperature_law_one_or_across_the_rail() {
    let deck = root().join("reference/contact_wheelrail/testbank/examples_temp/m1_tempdep.inp");
    let out = common::tempdir("m1_tempdep_import");
    let o =
        creepbench(&["import", "contact", deck.to_str().unwrap(), "--out", out.to_str().unwrap(), "--supported-only"]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let scenes: Vec<_> = String::from_utf8_lossy(&o.stdout).lines().map(std::path::PathBuf::from).collect();
    assert_eq!(scenes.len(), 3, "{scenes:?}");
    let read = |k: usize| WheelRailScene::from_file(&scenes[k]).unwrap();
    let (one, two, three) = (read(0), read(1), read(2));
    // BKTEMP, HEATCP, LAMBDA, DENS of both bodies (the deck's 0, 450, 50e-3, 7.85e-6).
    for s in [&one, &two, &three] {
        let heat = s.material.heat.expect("heat");
        assert!(heat.iter().all(|t| t.bulk_c == 0.0 && t.heat_capacity_j_per_kg_c == 450.0));
        assert!(heat.iter().all(|t| t.conductivity_w_per_mm_c == 50e-3 && t.density_kg_per_mm3 == 7.85e-6));
    }
    assert_eq!(one.tangential, Default::default());
    let law = TemperatureLaw { fref: 0.3, tref_c: 0.0, dfheat: -0.18, dtheat_c: 400.0 };
    assert_eq!(two.tangential.temperature_law, Some(law));
    // CONTACT's stop: rms change 1e-4, max(1, MAXIN - 10) + 1 = 91 iterations at MAXIN = 100.
    assert_eq!(two.tangential.contact_solver.tempdep_tolerance, 1e-4);
    assert_eq!(two.tangential.contact_solver.tempdep_max_iterations, 91);
    // Case 3: ALPHA = -10°, 20° with FREF 0.2, 0.5, TREF 0, 0, DFHEAT -0.12, -0.3, DTHEAT 300, 600;
    // at the patch's contact angle 0 (a third of the way) each is case 2's.
    assert_eq!(three.tangential.temperature_law, None);
    assert_eq!(three.tangential.contact_solver, two.tangential.contact_solver);
    let v = three.mu_variation.as_ref().expect("friction across the rail");
    let deg = std::f64::consts::PI / 180.0;
    assert!((v.at[0] + 10.0 * deg).abs() < 1e-15 && (v.at[1] - 20.0 * deg).abs() < 1e-15, "{:?}", v.at);
    assert_eq!(v.values, [0.2, 0.5]);
    assert_eq!(v.temperature, Some([vec![0.0, 0.0], vec![-0.12, -0.3], vec![300.0, 600.0]]));
    let at_zero = v.law_at(0.0).unwrap();
    for (got, want) in [(at_zero.fref, 0.3), (at_zero.dfheat, -0.18), (at_zero.dtheat_c, 400.0)] {
        assert!((got - want).abs() < 1e-12 * want.abs(), "{at_zero:?}");
    }
}

/// The gated scene with its `[friction]` changed: each refusal names the key and what is allowed.
fn refusal(edit: impl Fn(&str) -> String) -> String {
    let path = root().join("scenes/wheelrail/m1_tempdep_2.toml");
    let text = edit(&std::fs::read_to_string(&path).unwrap());
    let err = WheelRailScene::from_toml(&text, path.parent().unwrap()).expect_err("refused");
    format!("{}: {} ({})", err.field, err.value, err.allowed)
}

#[test]
fn the_temperature_law_is_refused_where_a_wheel_rail_scene_cannot_hold_it() {
    let heat_keys = ["bulk", "heat_capacity", "conductivity", "density"];
    let without_heat =
        |t: &str| t.lines().filter(|l| !heat_keys.iter().any(|k| l.starts_with(k))).collect::<Vec<_>>().join("\n");
    let no_heat = refusal(without_heat);
    assert!(no_heat.starts_with("friction.law") && no_heat.contains("surface temperatures"), "{no_heat}");
    let fastsim = refusal(|t| t.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\"]"));
    assert!(fastsim.starts_with("solvers") && fastsim.contains("[\"contact\"]"), "{fastsim}");
    let mu = refusal(|t| t.replace("mu = 0.3", "mu = 0.4"));
    assert!(mu.starts_with("wheelrail.mu") && mu.contains("fref = 0.3"), "{mu}");
    let falling = refusal(|t| t.replace("law = \"temperature\"", "law = \"linear\""));
    assert!(falling.contains("friction"), "{falling}");
}

/// The law per control point (`m1_tempdep_3`) with its keys changed: each refusal names the key.
#[test]
fn the_temperature_law_per_control_point_is_refused_where_incomplete() {
    let path = root().join("scenes/wheelrail/m1_tempdep_3.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let refused = |t: String| {
        let err = WheelRailScene::from_toml(&t, path.parent().unwrap()).expect_err("refused");
        format!("{}: {} ({})", err.field, err.value, err.allowed)
    };
    let missing = refused(text.replace("dtheat_c_values = [300.0, 600.0]\n", ""));
    assert!(missing.starts_with("wheelrail.dtheat_c_values: missing"), "{missing}");
    let short = refused(text.replace("tref_c_values = [0.0, 0.0]", "tref_c_values = [0.0]"));
    assert!(short.starts_with("wheelrail.tref_c_values: 1 values") && short.contains("(2)"), "{short}");
    let both = refused(text.replace("law = \"temperature\"", "law = \"temperature\"\nfref = 0.3"));
    assert!(both.starts_with("friction.fref") && both.contains("per control point"), "{both}");
    let negative = refused(text.replace("dfheat_values = [-0.12, -0.3]", "dfheat_values = [-0.12, -0.5]"));
    assert!(negative.starts_with("wheelrail.dfheat_values[1]") && negative.contains("> 0"), "{negative}");
    let coulomb = refused(text.replace("law = \"temperature\"", "law = \"coulomb\""));
    assert!(coulomb.starts_with("friction.law") && coulomb.contains("\"temperature\" with"), "{coulomb}");
}

/// The gated scenes export as module-1 decks (H = 3 then 1, L = 6, MAXIN of the iterations) that
/// import again to the same scene (but the wheel surface, which a deck cannot choose).
#[test]
fn the_temperature_scenes_export_and_import_back() {
    for name in ["m1_tempdep_1", "m1_tempdep_2", "m1_tempdep_3"] {
        let dir = common::tempdir(&format!("{name}_round_trip"));
        let scene = root().join(format!("scenes/wheelrail/{name}.toml"));
        let deck_dir = dir.join("deck");
        let o = creepbench(&["export", "contact", scene.to_str().unwrap(), "--out", deck_dir.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
        let deck = deck_dir.join(format!("{name}.inp"));
        let text = std::fs::read_to_string(&deck).unwrap();
        assert_eq!(text.matches("BKTEMP, HEATCP, LAMBDA, DENS").count(), 2, "{text}");
        assert!(text.contains(" 3000321    H-G-I-A-O-W-R"), "{text}");
        // L = 6 (FREF, TREF, DFHEAT, DTHEAT; MAXIN = 91 + 9) in the second scene, per control
        // point across the rail (V = 1) in the third.
        let law = text.contains(" 0622033    V-L-D-C-M-Z-E") && text.contains("0.3   0.0   -0.18   400.0");
        assert_eq!(law, name == "m1_tempdep_2", "{text}");
        let across =
            text.contains(" 1622033    V-L-D-C-M-Z-E") && text.contains("0.5   0.0   -0.3   600.0     ALPHA, FREF");
        assert_eq!(across, name == "m1_tempdep_3", "{text}");
        assert!(text.contains("    999     100    30"), "{text}");
        let again = dir.join("again");
        let o = creepbench(&["import", "contact", deck.to_str().unwrap(), "--out", again.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
        let back_path = String::from_utf8_lossy(&o.stdout).lines().next().map(std::path::PathBuf::from).unwrap();
        let (original, back) =
            (WheelRailScene::from_file(&scene).unwrap(), WheelRailScene::from_file(&back_path).unwrap());
        assert_eq!(back.material, original.material);
        assert_eq!(back.tangential, original.tangential);
        assert_eq!(back.mu_variation, original.mu_variation);
        assert_eq!((back.mu, back.cases.len()), (original.mu, original.cases.len()));
    }
}
