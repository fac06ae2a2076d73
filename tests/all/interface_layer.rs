//! The interface layer (CONTACT's M = 4, issue 46) as a scene gives it: `[material]
//! layer_g_mpa`, `layer_thickness_mm` read together or not at all, the exact solver only, and
//! `export contact` both ways (M = 4 with GG3, LAYTHK, in transient rolling too, where both take
//! the layer's previous displacement in place: a closed form below). Its physics against closed
//! forms: `solvers/contact/tangential/tests_layer.rs`; against CONTACT's printed
//! tractcurv.inp 31-60: the suite contact_public (tests/all/contact_public.rs).

use crate::common::{run_scene, scene_text, tempdir};
use std::process::Command;

const LAYER: &str = "g_mpa = 82000.0\npoisson = 0.28\nlayer_g_mpa = 8200.0\nlayer_thickness_mm = 1.25";

fn text(material: &str, solvers: &str, creepage: &str) -> String {
    scene_text("layer", solvers, 0.3, 8, creepage, "").replace("g_mpa = 82000.0\npoisson = 0.28", material)
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
    let (code, err, dir) = run_scene("layer_half", &text(half, "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_thickness_mm") && err.contains("missing"), "{err}");
    assert!(!dir.join("out").exists());
    let (code, err, _) =
        run_scene("layer_range", &text(&LAYER.replace("8200.0", "-1.0"), "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_g_mpa"), "{err}");
    let (code, err, dir) = run_scene("layer_fastsim", &text(LAYER, "[\"contact\", \"fastsim\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("an interface layer only with the exact model"), "{err}");
    assert!(!dir.join("out").exists());
}

#[test]
fn the_layer_exports_as_m4_and_imports_back_in_steady_and_transient_rolling() {
    let steady = "kind = \"sweep\"\nover = \"cx\"\nat = [0.001, 0.002]";
    let (code, err, dir) = run_scene(
        "layer_export",
        &text(LAYER, "[\"contact\"]", steady),
        &["export", "contact", "s.toml", "--out", "back"],
    );
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/layer.inp")).unwrap();
    assert!(deck.contains("  8200.0   1.25   0.0   0.0    GG3, LAYTHK, TAU_C0, K_TAU"), "{deck}");
    // M = 4 in both cases: the first reads the material (C = 2), the second keeps it (C = 0).
    assert!(deck.contains("  022420      L-D-C-M-Z-E") && deck.contains("  100400      L-D-C-M-Z-E"), "{deck}");
    let again = imported_again(&dir);
    assert!(again.contains("layer_g_mpa = 8200.0") && again.contains("layer_thickness_mm = 1.25"), "{again}");
    // In transient rolling too (both programs take the layer's previous displacement at the
    // element's own index on the moved grid), and imported back.
    let transient = "kind = \"step\"\nc = 0.001\nsteps = 2";
    let (code, err, dir) = run_scene(
        "layer_transient",
        &text(LAYER, "[\"contact\"]", transient),
        &["export", "contact", "s.toml", "--out", "back"],
    );
    assert_eq!(code, Some(0), "{err}");
    let again = imported_again(&dir);
    assert!(again.contains("layer_thickness_mm = 1.25") && !again.contains("kind = \"sweep\""), "{again}");
}

/// The layer's yield limit (CONTACT's TAU_C0 with K_TAU = 0, issue 46): read with the layer only
/// (of thickness 0 too: the surface yields), refused with falling friction, and exported as
/// TAU_C0 and imported back.
#[test]
fn the_yield_limit_is_read_with_its_layer_and_exports_as_tau_c0() {
    let steady = "kind = \"sweep\"\nover = \"cx\"\nat = [0.001, 0.002]";
    let plastic = format!("{LAYER}\nlayer_yield_mpa = 560.0");
    let p = crate::common::problem(&text(&plastic, "[\"contact\"]", steady));
    assert_eq!(p.material.layer.and_then(|l| l.yield_mpa), Some(560.0));
    let simulate = ["simulate", "s.toml", "--out", "out"];
    let alone = "g_mpa = 82000.0\npoisson = 0.28\nlayer_yield_mpa = 560.0";
    let (code, err, dir) = run_scene("yield_alone", &text(alone, "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_yield_mpa") && err.contains("with its layer"), "{err}");
    assert!(!dir.join("out").exists());
    // A thickness of 0 with a yield limit: the bodies' surface yields (CONTACT's LAYTHK = 0,
    // testbank/examples_plast, tests/all/plastic_surface.rs), with no layer's flexibility; it
    // exports as LAYTHK = 0 and imports back.
    let thin = plastic.replace("1.25", "0.0");
    let p = crate::common::problem(&text(&thin, "[\"contact\"]", steady));
    let l = p.material.layer.expect("the surface's yield limit");
    assert_eq!((l.yield_mpa, l.flexibility_mm_per_mpa()), (Some(560.0), 0.0));
    let export = ["export", "contact", "s.toml", "--out", "back"];
    let (code, err, dir) = run_scene("yield_thin", &text(&thin, "[\"contact\"]", steady), &export);
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/layer.inp")).unwrap();
    assert!(deck.contains("  8200.0   0.0   560.0   0.0    GG3, LAYTHK, TAU_C0, K_TAU"), "{deck}");
    let again = imported_again(&dir);
    assert!(again.contains("layer_thickness_mm = 0.0") && again.contains("layer_yield_mpa = 560.0"), "{again}");
    let (code, err, _) =
        run_scene("yield_range", &text(&plastic.replace("560.0", "-1.0"), "[\"contact\"]", steady), &simulate);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("material.layer_yield_mpa"), "{err}");
    let (code, err, dir) = run_scene(
        "yield_export",
        &text(&plastic, "[\"contact\"]", steady),
        &["export", "contact", "s.toml", "--out", "back"],
    );
    assert_eq!(code, Some(0), "{err}");
    let deck = std::fs::read_to_string(dir.join("back/layer.inp")).unwrap();
    assert!(deck.contains("  8200.0   1.25   560.0   0.0    GG3, LAYTHK, TAU_C0, K_TAU"), "{deck}");
    let again = imported_again(&dir);
    assert!(again.contains("layer_yield_mpa = 560.0"), "{again}");
}

/// plastic_3bl.inp's magnetite series (cases 2-14, one element of 1 mm² under FN = 900 N, shifted
/// by -0.035, -0.035, -0.030 then -0.050 mm; GG3 = 176.63, LAYTHK = 0.020, TAU_C0 = 560, K_TAU = 0)
/// against the closed form of one element: the shifts taken up in series by the half-spaces
/// (their flexibility L from case 1: 0.001 mm at the printed FX = 84.97 N) and the layer
/// (h3/G3), |FX| = min(Σ shift / (L + h3/G3), τ_c0 · 1 mm²); and against CONTACT's printed FX.
#[test]
fn plastic_3bl_magnetite_yields_at_tau_c0() {
    let dir = tempdir("plastic_3bl");
    crate::layer_hardening::simulate_plastic_3bl(&dir, &["plastic_3bl_1", "plastic_3bl_2"]);
    let fx_n = |name: &str| -> Vec<f64> {
        crate::layer_hardening::column(&dir, name, "fx_over_fn").into_iter().map(|f| -f).collect()
    };
    let case1 = fx_n("plastic_3bl_1");
    // Case 1 (no layer): CONTACT prints FX = 84.97 N at 0.001 mm.
    assert!((case1[0] - 84.97).abs() <= 0.005, "{case1:?}");
    let l_mm_per_n = 0.001 / case1[0] + 0.020 / 176.63;
    let ours = fx_n("plastic_3bl_2");
    assert_eq!(ours.len(), 13);
    let shifts = [-0.035, -0.035, -0.030].into_iter().chain([-0.050; 10]);
    let (mut total, mut plastic) = (0.0, 0.0);
    for (k, (shift, fx)) in shifts.zip(&ours).enumerate() {
        total += -shift;
        // Elastic while the layer holds; past τ_c0 the excess flows plastically and stays.
        let closed = ((total - plastic) / l_mm_per_n).min(560.0);
        plastic = total - closed * l_mm_per_n;
        assert!((fx - closed).abs() <= 1e-9 * 560.0, "step {}: FX {fx} against {closed}", k + 1);
    }
    // CONTACT (plastic_3bl.ref_out): FX = 280.0 (case 2), then 560.0 (cases 3-14).
    assert!((ours[0] - 280.0).abs() <= 0.05 && ours[1..].iter().all(|f| (f - 560.0).abs() <= 0.05), "{ours:?}");
}

/// `back/layer.inp` of `dir` imported again (`import contact ... --out again`): its first scene file.
fn imported_again(dir: &std::path::Path) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(dir)
        .args(["import", "contact", "back/layer.inp", "--out", "again"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::read_to_string(dir.join("again/layer_1.toml")).unwrap()
}

/// A layer alone (half-spaces of G = 1e7 MPa beside a layer of G3 = 1 MPa) in transient rolling from rest, every element
/// adhering: CONTACT takes the layer's previous displacement at the element's own index on the
/// moved grid (`stang_rhs`, `gf3_aijpj`: FLX times the previous traction of the element itself),
/// so each element's traction grows by cx dq / FLX per step wherever its material came from:
/// fx/fn after n steps is n N cx dq A / (FLX FN) for N elements in contact of area A, to 1e-6.
/// Carried with the material the elements entering at the leading edge would start afresh.
#[test]
fn a_layer_alone_in_transient_rolling_takes_its_previous_displacement_in_place() {
    let creepage = "kind = \"step\"\nc = 1e-6\nsteps = 3";
    let stiff = LAYER.replace("g_mpa = 82000.0", "g_mpa = 1e7").replace("8200.0", "1.0");
    let p = crate::common::problem(&text(&stiff, "[\"contact\"]", creepage));
    let h = crate::common::run(&p, "contact");
    let fx = h.column("fx_over_fn").unwrap();
    let (adhesion, slip) = (h.column("n_adhesion").unwrap(), h.column("n_slip").unwrap());
    let flx = p.material.layer_flexibility_mm_per_mpa();
    let fn_n = h.column("fn_n").unwrap()[0];
    let per_step = adhesion[0] * 1e-6 * p.rolling.dq_mm * p.grid.element_area_mm2() / (flx * fn_n);
    for (n, f) in fx.iter().enumerate() {
        assert_eq!(slip[n], 0.0, "step {n}: every element adheres");
        let closed = (n + 1) as f64 * per_step;
        assert!((f.abs() - closed).abs() <= 1e-6 * closed, "step {}: {f} against {closed}", n + 1);
    }
}
