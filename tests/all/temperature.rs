//! Surface temperatures of frictional heating (CONTACT's H = 3 and 1, issue 46): `[material]`'s
//! heat keys, read all eight or none, steady rolling and the exact model only; CONTACT's
//! examples/ertz_temperature.inp reproduced (its four printed MAX(T1,T2) and forces at their
//! digits), `export contact` writing H = 3 and the temperature lines that import back. The
//! closed form of a uniform source (the 1-D flash temperature): physics/temperature.rs's tests.

use crate::common::{root, run_scene, scene_text, suite_problem};
use creepbench::comparison::references::contact_output::{self, CaseBody, Tangential};
use creepbench::comparison::references::contact_public::{TEMP1, TEMP2};
use std::process::Command;

const HEAT: &str = "bulk1_c = 0.0\nheat_capacity1_j_per_kg_c = 450.0\nconductivity1_w_per_mm_c = 0.05\ndensity1_kg_per_mm3 = 7.85e-6\nbulk2_c = 150.0\nheat_capacity2_j_per_kg_c = 450.0\nconductivity2_w_per_mm_c = 0.05\ndensity2_kg_per_mm3 = 7.85e-6";

fn scene(solvers: &str, creepage: &str, heat: &str) -> String {
    scene_text("heat", solvers, 0.3, 16, creepage, "")
        .replace("poisson = 0.28", &format!("poisson = 0.28\n{heat}"))
        .replace("[grid]", "[rolling]\nv_mm_s = 30000.0\n[grid]")
}

const SWEEP: &str = "kind = \"sweep\"\nover = \"cx\"\nat = [0.0, -0.001, -0.03]";

/// CONTACT's four cases: each scene's row against the printed MAX(T1,T2) in half-units of its
/// last digit (and fx/fn, as the public gate does).
#[test]
fn ertz_temperature_reproduces_contacts_printed_maximum_temperatures() {
    let path = root().join("reference/contact_public/examples/ertz_temperature.ref_out");
    let printed = contact_output::read(&path).unwrap();
    for case in 1..=4u32 {
        let name = format!("ertz_temperature_{case}");
        let p = suite_problem("contact_public", &name, &[]);
        let h = crate::common::run(&p, "contact");
        let col = |c: &str| h.column(c).unwrap()[0];
        let ours = col(TEMP1).max(col(TEMP2));
        let CaseBody::Totals(t) = &printed.iter().find(|c| c.case == case).unwrap().body else { panic!("totals") };
        let theirs = t.temperature_max_c.expect("MAX(T1,T2) printed");
        let half_units = (ours - theirs.value).abs() / theirs.half_unit;
        let Tangential::ForceOverFstatFn(fx) = t.x else { panic!("case {case}: FX/FSTAT/FN printed") };
        let fx = fx.times(0.3);
        let fx_half = (col("fx_over_fn") - fx.value).abs() / fx.half_unit;
        println!(
            "case {case}: max T ours {ours:.4} C, printed {} C: {half_units:.3} half-units; fx/fn {:.6} vs {}: {fx_half:.3}",
            theirs.value,
            col("fx_over_fn"),
            fx.value
        );
        assert!(half_units <= 2.0, "case {case}: {ours} vs {theirs:?}");
        assert!(fx_half <= 2.0, "case {case}");
    }
}

#[test]
fn the_heat_keys_are_read_together_for_the_exact_model_in_steady_rolling() {
    let p = crate::common::problem(&scene("[\"contact\"]", SWEEP, HEAT));
    let heat = p.material.heat.expect("heat");
    assert_eq!((heat[0].bulk_c, heat[1].bulk_c, heat[1].density_kg_per_mm3), (0.0, 150.0, 7.85e-6));
    let h = crate::common::run(&p, "contact");
    let (t1, t2) = (h.column(TEMP1).unwrap(), h.column(TEMP2).unwrap());
    // No slip: the bodies meet at the mean 75 °C; more slip, more heat.
    assert_eq!((t1[0], t2[0]), (75.0, 75.0));
    assert!(t1[1] > 75.0 && t1[2] > t1[1], "{t1:?}");
    let simulate = ["simulate", "s.toml", "--out", "out"];
    let partial = HEAT.replace("density2_kg_per_mm3 = 7.85e-6", "");
    let (code, err, dir) = run_scene("heat_partial", &scene("[\"contact\"]", SWEEP, &partial), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.density2_kg_per_mm3") && err.contains("all eight"), "{err}");
    assert!(!dir.join("out").exists());
    let (code, err, _) = run_scene("heat_fastsim", &scene("[\"contact\", \"fastsim\"]", SWEEP, HEAT), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("surface temperatures only with the exact model"), "{err}");
    let transient = "kind = \"step\"\nc = -0.001\nsteps = 3";
    let (code, err, _) = run_scene("heat_transient", &scene("[\"contact\"]", transient, HEAT), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.bulk1_c") && err.contains("transient rolling"), "{err}");
    let cold = HEAT.replace("conductivity1_w_per_mm_c = 0.05", "conductivity1_w_per_mm_c = 0.0");
    let (code, err, _) = run_scene("heat_range", &scene("[\"contact\"]", SWEEP, &cold), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.conductivity1_w_per_mm_c"), "{err}");
}

#[test]
fn export_writes_h_3_and_the_temperature_lines_that_import_back() {
    let (code, err, dir) = run_scene(
        "heat_export",
        &scene("[\"contact\"]", SWEEP, HEAT),
        &["export", "contact", "s.toml", "--out", "back"],
    );
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/heat.inp")).unwrap();
    assert!(deck.contains("  0.0   450.0   0.05   7.85e-6    BKTEMP1, HEATCP1, LAMBDA1, DENS1"), "{deck}");
    assert!(deck.contains("  150.0   450.0   0.05   7.85e-6    BKTEMP2, HEATCP2, LAMBDA2, DENS2"), "{deck}");
    assert!(deck.contains(" 3002211    H-G-I-A-O-W-R") && deck.contains(" 1012211    H-G-I-A-O-W-R"), "{deck}");
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(&dir)
        .args(["import", "contact", "back/heat.inp", "--out", "again"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let again = std::fs::read_to_string(dir.join("again/heat_1.toml")).unwrap();
    for line in HEAT.lines() {
        let (key, value) = line.split_once(" = ").unwrap();
        let value: f64 = value.parse().unwrap();
        let read = again.lines().find_map(|l| l.strip_prefix(&format!("{key} = "))).expect(key);
        assert_eq!(read.parse::<f64>().unwrap(), value, "{key}");
    }
}
