//! Friction of the surface temperature (CONTACT's L = 6, issue 46): `[friction] law =
//! "temperature"`, the exact model's fixed point between the tractions and the temperatures of
//! their frictional heat. Independent references: the law at its two limits is Coulomb's (DFHEAT
//! = 0: μ = FREF everywhere; every temperature above TREF + DTHEAT: μ = FREF + DFHEAT), and the
//! fixed point's own property (each slip element's traction at μ(T) of the temperatures its
//! tractions make). CONTACT's printed totals: tests/all/contact_public.rs (euro_tractcurv.inp
//! cases 32-60, 62-90, 92-120, m3_tempdep.inp 2-3, conv_temp.inp 1-5). Refusals and the
//! `export contact` round trip.

use crate::common::{problem, run, run_scene, scene_text};
use creepbench::comparison::references::contact_public::{TEMP1, TEMP2};
use std::process::Command;

const HEAT: &str = "bulk1_c = 0.0\nheat_capacity1_j_per_kg_c = 450.0\nconductivity1_w_per_mm_c = 0.05\ndensity1_kg_per_mm3 = 7.85e-6\nbulk2_c = 0.0\nheat_capacity2_j_per_kg_c = 450.0\nconductivity2_w_per_mm_c = 0.05\ndensity2_kg_per_mm3 = 7.85e-6";

/// Partial slip to full sliding at 30 m/s (hundreds of °C at the largest creepage).
const SWEEP: &str = "kind = \"sweep\"\nover = \"cx\"\nat = [-0.0005, -0.002, -0.03]";

/// A scene of `solvers` with Coulomb's `mu` (`friction` empty) or the `[friction]` table `friction`.
fn scene(solvers: &str, mu: f64, friction: &str) -> String {
    let text = scene_text("tempfric", solvers, mu, 20, SWEEP, friction)
        .replace("poisson = 0.28", &format!("poisson = 0.28\n{HEAT}"))
        .replace("[grid]", "[rolling]\nv_mm_s = 30000.0\n[grid]");
    if friction.is_empty() {
        text
    } else {
        text.replace(&format!("mu = {mu}\n"), "")
    }
}

fn law(fref: f64, tref_c: f64, dfheat: f64, dtheat_c: f64) -> String {
    format!("[friction]\nlaw = \"temperature\"\nfref = {fref:?}\ntref_c = {tref_c:?}\ndfheat = {dfheat:?}\ndtheat_c = {dtheat_c:?}\n[contact_solver]\ntempdep_tolerance = 1e-10\ntolerance = 1e-11")
}

fn columns(text: &str) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let h = run(&problem(text), "contact");
    let col = |c: &str| h.column(c).unwrap().to_vec();
    let hottest = col(TEMP1).iter().zip(col(TEMP2)).map(|(a, b)| a.max(b)).collect();
    (col("fx_over_fn"), hottest, col("n_slip"))
}

fn assert_close(what: &str, ours: &[f64], theirs: &[f64], rel: f64) {
    for (k, (a, b)) in ours.iter().zip(theirs).enumerate() {
        assert!((a - b).abs() <= rel * b.abs().max(1e-12), "{what} row {k}: {a} vs {b}");
    }
}

#[test]
fn the_temperature_law_at_its_limits_is_coulombs() {
    let coulomb = |mu: f64| {
        scene("[\"contact\"]", mu, "").replace("[creepage]", "[contact_solver]\ntolerance = 1e-11\n[creepage]")
    };
    // DFHEAT = 0: μ = FREF whatever the temperature.
    let (fx, t, slip) = columns(&scene("[\"contact\"]", 0.3, &law(0.3, 0.0, 0.0, 100.0)));
    let (fx_c, t_c, slip_c) = columns(&coulomb(0.3));
    println!("dfheat = 0: fx {fx:?} vs {fx_c:?}, max T {t:?} vs {t_c:?}");
    assert_eq!(slip, slip_c);
    assert_close("fx/fn", &fx, &fx_c, 1e-9);
    assert_close("max T", &t, &t_c, 1e-9);
    assert!(t[2] > 100.0, "full sliding heats: {t:?}");
    // TREF far below every temperature (the bulk is 0 °C): μ = FREF + DFHEAT on the whole contact.
    let (fx, t, slip) = columns(&scene("[\"contact\"]", 0.3, &law(0.3, -200.0, -0.12, 1.0)));
    let (fx_c, t_c, slip_c) = columns(&coulomb(0.18));
    println!("kinetic limit: fx {fx:?} vs {fx_c:?}");
    assert_eq!(slip, slip_c);
    assert_close("fx/fn", &fx, &fx_c, 1e-9);
    assert_close("max T", &t, &t_c, 1e-9);
    // Nearly full sliding at the limit: |fx/fn| just below μ (the leading row's elements adhere).
    assert!(fx[2].abs() < 0.18 && fx[2].abs() > 0.18 - 1e-5, "{fx:?}");
}

#[test]
fn falling_with_the_temperature_lowers_the_force_of_full_sliding() {
    // Between the limits: μ falls from 0.3 as the surface heats (TREF 0 °C, 0.18 lower at 400 °C).
    let (fx, t, _) = columns(&scene("[\"contact\"]", 0.3, &law(0.3, 0.0, -0.18, 400.0)));
    let h = run(&problem(&scene("[\"contact\"]", 0.3, &law(0.3, 0.0, -0.18, 400.0))), "contact");
    let (lo, hi) = (h.column("mu_min").unwrap()[2], h.column("mu_max").unwrap()[2]);
    println!("full sliding: fx/fn {}, max T {} C, mu in [{lo}, {hi}]", fx[2], t[2]);
    // The hottest element's μ is the law's at its temperature; the force lies between the limits.
    let mu_hot = 0.3 - 0.18 * (t[2] / 400.0).min(1.0);
    assert!((lo - mu_hot).abs() < 1e-6, "{lo} vs {mu_hot}");
    assert!(hi <= 0.3 && fx[2].abs() < 0.3 && fx[2].abs() > lo, "{fx:?} {lo} {hi}");
    assert!(h.column("tempdep_converged").unwrap().iter().all(|&c| c == 1.0));
}

#[test]
fn the_law_is_refused_without_heat_or_beside_other_models() {
    let simulate = ["simulate", "s.toml", "--out", "out"];
    let cases = [
        ("no_heat", scene("[\"contact\"]", 0.3, &law(0.3, 0.0, -0.1, 400.0)).replace(HEAT, ""), "friction.law"),
        ("negative", scene("[\"contact\"]", 0.3, &law(0.3, 0.0, -0.3, 400.0)), "friction.dfheat"),
        ("fastsim", scene("[\"contact\", \"fastsim\"]", 0.3, &law(0.3, 0.0, -0.1, 400.0)), "fastsim"),
        (
            "mu",
            scene("[\"contact\"]", 0.3, &law(0.3, 0.0, -0.1, 400.0))
                .replace("fn_n = 100000.0", "fn_n = 100000.0\nmu = 0.25"),
            "contact.mu",
        ),
    ];
    for (name, text, field) in cases {
        let (code, err, dir) = run_scene(&format!("tempfric_{name}"), &text, &simulate);
        println!("{name}: {err}");
        assert_eq!(code, Some(2), "{name}: {err}");
        assert!(err.contains(field), "{name}: {err}");
        assert!(!dir.join("out").exists());
    }
}

#[test]
fn export_writes_l_6_and_the_law_that_imports_back() {
    let text = scene("[\"contact\"]", 0.3, &law(0.3, 20.0, -0.18, 400.0));
    let (code, err, dir) = run_scene("tempfric_export", &text, &["export", "contact", "s.toml", "--out", "back"]);
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/tempfric.inp")).unwrap();
    assert!(deck.contains("  0.3   20.0   -0.18   400.0        FREF, TREF, DFHEAT, DTHEAT"), "{deck}");
    assert!(deck.contains("  622020      L-D-C-M-Z-E"), "{deck}");
    assert!(deck.contains(" 3402221    H-G-I-A-O-W-R") && deck.contains(" 1412221    H-G-I-A-O-W-R"), "{deck}");
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(&dir)
        .args(["import", "contact", "back/tempfric.inp", "--out", "again"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let again = std::fs::read_to_string(dir.join("again/tempfric_1.toml")).unwrap();
    for line in ["law = \"temperature\"", "fref = 0.3", "tref_c = 20.0", "dfheat = -0.18", "dtheat_c = 400.0"] {
        assert!(again.contains(line), "{line}: {again}");
    }
    // The imported scene computes the same history, to its fixed point's stop (CONTACT's 1e-4 of
    // the temperatures, `tempdep_tolerance` as imported, against 1e-10 here).
    let back = creepbench::scene::Scene::from_file(&dir.join("again/tempfric_1.toml")).unwrap();
    let h_back = run(&creepbench::pipeline::resolve(&back).unwrap(), "contact");
    let h = run(&problem(&text), "contact");
    let (a, b) = (h.column("fx_over_fn").unwrap(), h_back.column("fx_over_fn").unwrap());
    assert_close("fx/fn after the round trip", &a, &b, 1e-5);
}
