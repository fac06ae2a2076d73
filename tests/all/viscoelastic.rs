//! Viscoelastic bodies (CONTACT's M = 1, issue 46) as a scene gives them: `[material]
//! visco_ratio`, `visco_time_s` together, the exact model in steady rolling only, `export
//! contact` as M = 1 and back. The physics against its closed-form limits (the standard linear
//! solid relaxes instantly: the elastic solid of G/(1 + FG); never: the elastic solid of G), and
//! against CONTACT's printed visc_cylindr.inp in the suite contact_public
//! (tests/all/contact_public.rs).

use crate::common::{root, tempdir};
use creepbench::problem::Problem;
use std::process::Command;

/// A non-Hertzian contact whose undeformed distance does not depend on the material (h = a1 x² +
/// g(y) on a fixed grid), rolling steadily under cx with a little cy and spin.
fn scene(material: &str) -> String {
    format!(
        r#"name = "visco"
solvers = ["contact"]
[contact]
fn_n = 40000.0
mu = 0.3
[geometry]
kind = "profile"
a1_per_mm = 0.001086956522
profile = "reference/contact_nonhertz/profile_flat.csv"
[material]
{material}
[grid]
mx = 16
my = 15
x_mm = [-7.0, 7.0]
y_mm = [-7.5, 7.5]
[rolling]
v_mm_s = 1000.0
[contact_solver]
tolerance = 1e-13
[creepage]
kind = "sweep"
over = "cx"
at = [0.0004, 0.0015, 0.004]
cy = 0.0003
cs = 0.0002
"#
    )
}

fn problem(material: &str) -> Problem {
    problem_of(&scene(material))
}

fn problem_of(text: &str) -> Problem {
    let s = creepbench::scene::Scene::from_toml(text, &root()).expect("valid scene");
    creepbench::pipeline::resolve(&s).expect("resolvable scene")
}

/// (fx/fn, fy/fn, mz) of every sweep point of the scene `text`.
fn forces_of(text: &str) -> Vec<[f64; 3]> {
    let h = crate::common::run(&problem_of(text), "contact");
    let (fx, fy, mz) = (h.column("fx_over_fn").unwrap(), h.column("fy_over_fn").unwrap(), h.column("mz_nmm").unwrap());
    (0..fx.len()).map(|k| [fx[k], fy[k], mz[k]]).collect()
}

fn forces(material: &str) -> Vec<[f64; 3]> {
    forces_of(&scene(material))
}

/// The thesis's ellipse with Hertz's pressure imposed (CONTACT B = 2): the tangential problem
/// alone, on the same contact whatever the material.
fn imposed(material: &str) -> Vec<[f64; 3]> {
    let text = crate::common::scene_text(
        "visco_hertz",
        "[\"contact\"]",
        0.3,
        12,
        "kind = \"sweep\"\nover = \"cx\"\nat = [0.0004, 0.0015, 0.004]\ncy = 0.0003\ncs = 0.0002",
        "[normal]\npressure = \"elliptical\"\n[contact_solver]\ntolerance = 1e-13",
    );
    forces_of(&text.replace("g_mpa = 82000.0\npoisson = 0.28", material))
}

/// The largest difference of two runs relative to the larger force (or moment) of the two.
fn worst_relative(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    let mut worst = 0.0f64;
    for (x, y) in a.iter().zip(b) {
        for q in 0..3 {
            let scale = if q < 2 { x[0].abs().max(x[1].abs()) } else { x[2].abs().max(y[2].abs()) };
            worst = worst.max((x[q] - y[q]).abs() / scale);
        }
    }
    worst
}

#[test]
fn instant_relaxation_is_the_relaxed_elastic_solid_and_none_the_glassy_one() {
    let (g, ratio) = (82000.0, 1.5);
    let visco =
        |time_s: f64| format!("g_mpa = {g:?}\npoisson = 0.28\nvisco_ratio = {ratio:?}\nvisco_time_s = {time_s:?}");
    let elastic = |g: f64| format!("g_mpa = {g:?}\npoisson = 0.28");
    // τ = 0: the Kelvin–Voigt element follows at once, compliance (1 + FG)/G; τ → ∞ (V τ = 1e15
    // mm, 1e14 grid lengths): the dashpot never yields, compliance 1/G. On one contact with
    // Hertz's pressure imposed, the tangential problem alone: the same forces to 1e-12.
    let relaxed = worst_relative(&imposed(&visco(0.0)), &imposed(&elastic(g / (1.0 + ratio))));
    let glassy = worst_relative(&imposed(&visco(1e12)), &imposed(&elastic(g)));
    println!("imposed pressure, relative difference of fx, fy, mz: relaxed {relaxed:e}, glassy {glassy:e}");
    assert!(relaxed <= 1e-12 && glassy <= 1e-12, "{relaxed:e} {glassy:e}");
    // With the normal problem solved (the contact found on an undeformed distance that does not
    // depend on G): equal to the normal solver's stopping test, a relative pressure change of
    // 1e-10 of the conjugate gradients (both limits' kernels are symmetric to 1e-12, so both runs
    // of each pair stop on that test; measured 5e-11 and 8e-11).
    let relaxed = worst_relative(&forces(&visco(0.0)), &forces(&elastic(g / (1.0 + ratio))));
    let glassy = worst_relative(&forces(&visco(1e12)), &forces(&elastic(g)));
    println!("solved pressure, relative difference of fx, fy, mz: relaxed {relaxed:e}, glassy {glassy:e}");
    assert!(relaxed <= 1e-10 && glassy <= 1e-10, "{relaxed:e} {glassy:e}");
}

/// `creepbench ARGS` in `dir` with `s.toml` holding `scene`: (exit code, stderr).
fn run(dir_name: &str, scene: &str, args: &[&str]) -> (Option<i32>, String, std::path::PathBuf) {
    let dir = tempdir(dir_name);
    std::fs::write(dir.join("s.toml"), scene.replace("reference/", &format!("{}/reference/", root().display())))
        .unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(&dir).args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stderr).to_string(), dir)
}

const VISCO: &str = "g_mpa = 1143.0\npoisson = 0.4\nvisco_ratio = 1.0\nvisco_time_s = 0.009";

#[test]
fn the_keys_go_together_with_the_exact_model_in_steady_rolling() {
    let p = problem(VISCO);
    let v = p.material.visco.expect("viscoelastic");
    assert_eq!((v.ratio, v.time_s), (1.0, 0.009));
    // FG = 0 is elastic bodies.
    assert_eq!(problem(&VISCO.replace("visco_ratio = 1.0", "visco_ratio = 0.0")).material.visco, None);
    let simulate = ["simulate", "s.toml", "--out", "out"];
    let cases = [
        ("visco_half", scene(&VISCO.replace("\nvisco_time_s = 0.009", "")), "material.visco_time_s"),
        ("visco_range", scene(&VISCO.replace("= 0.009", "= -1.0")), "material.visco_time_s"),
        (
            "visco_fastsim",
            scene(VISCO).replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\"]"),
            "viscoelastic bodies only with the exact model",
        ),
        (
            "visco_transient",
            scene(VISCO).replace(
                "kind = \"sweep\"\nover = \"cx\"\nat = [0.0004, 0.0015, 0.004]",
                "kind = \"step\"\nc = 0.001\nsteps = 2",
            ),
            "steady rolling only",
        ),
        (
            "visco_layer",
            scene(&format!("{VISCO}\nlayer_g_mpa = 8200.0\nlayer_thickness_mm = 1.25")),
            "either an interface layer or viscoelastic bodies",
        ),
    ];
    for (dir, text, what) in cases {
        let (code, err, dir) = run(dir, &text, &simulate);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains(what), "{what}: {err}");
        assert!(!dir.join("out").exists());
    }
}

#[test]
fn viscoelastic_bodies_export_as_m1_and_import_back() {
    let (code, err, dir) = run("visco_export", &scene(VISCO), &["export", "contact", "s.toml", "--out", "back"]);
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/visco.inp")).unwrap();
    assert!(deck.contains("  1.0   1.0   0.009   0.009    FG 1,2, TC 1,2"), "{deck}");
    assert!(deck.contains("  022120      L-D-C-M-Z-E") && deck.contains("  100100      L-D-C-M-Z-E"), "{deck}");
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(&dir)
        .args(["import", "contact", "back/visco.inp", "--out", "again"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let again = std::fs::read_to_string(dir.join("again/visco_1.toml")).unwrap();
    assert!(again.contains("visco_ratio = 1.0") && again.contains("visco_time_s = 0.009"), "{again}");
    // Rolling along −x: CONTACT rolls along +x with M = 1 whatever CHI.
    let backward = scene(VISCO).replace("[rolling]\n", "[rolling]\nchi_deg = 180.0\n");
    let (code, err, _) = run("visco_export_back", &backward, &["export", "contact", "s.toml", "--out", "back"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("rolling.chi_deg") && err.contains("M = 1"), "{err}");
}
