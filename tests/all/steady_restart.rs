//! Issue 12: the first transient step after a steady start where μ or FN changed there
//! (`[contact_solver] steady_restart`, `solvers::contact::restart`). The default reproduces
//! CONTACT's published envelope histories at every step (CONTACT's TangCG stops at the steady
//! state with its slip area on the new bound); `"converged"` reproduces CONTACT run with its steady
//! start solved to EPS 1e-10, where it converges (reference/contact_envelope_tight, this
//! project's CONTACT run). The two differ by 1.4e-3 (mu_ramp) and 1.4e-4 (fn_sine_f20) at step 1.
//! Where a friction rise turns the slip of the rescaled slip area, CONTACT converges and so does
//! the default (contact_envelope/mu_rise).

use crate::common;
use common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

/// Agreement asked of the exact solver: the envelope gate (1e-5) with margin for these cases.
const TOL: f64 = 1e-6;

fn history(case: &str, restart: Option<&str>) -> History {
    let mut text = suite_scene_text("envelope", case);
    if let Some(r) = restart {
        text = text.replace("[init]", &format!("[contact_solver]\nsteady_restart = \"{r}\"\n\n[init]"));
    }
    let scene = Scene::from_toml(&text, &root().join("scenes/envelope")).expect("valid scene");
    let p = creepbench::pipeline::resolve(&scene).expect("resolvable scene");
    run(&p, "contact")
}

/// Largest |Δ| of fx/FN and fy/FN over every step against a reference folder.
fn worst(h: &History, folder: &str, case: &str) -> (f64, usize) {
    let (fx, fy) = (h.column("fx_over_fn").unwrap(), h.column("fy_over_fn").unwrap());
    let (dx, kx) = max_abs_diff(&fx, &reference_in(folder, case, "fx_over_fn"));
    let (dy, ky) = max_abs_diff(&fy, &reference_in(folder, case, "fy_over_fn"));
    if dx >= dy {
        (dx, kx)
    } else {
        (dy, ky)
    }
}

#[test]
fn default_restart_matches_contacts_envelope_at_every_step() {
    for case in ["mu_ramp", "fn_sine_f20"] {
        let h = history(case, None);
        let (d, k) = worst(&h, "contact_envelope", case);
        println!("{case}: largest |df| {d:.2e} at row {k}");
        assert!(d < TOL, "{case}: {d:.2e} at row {k}");
        assert_eq!(h.column("n_adhesion").unwrap(), reference_in("contact_envelope", case, "n_adhesion"), "{case}");
    }
}

/// Friction that rises after the steady start (contact_envelope/mu_rise, this project's CONTACT
/// run): the rescaled slip area's slip turns against its traction next to the adhesion area,
/// CONTACT moves those elements to adhesion and converges, and so does the default here. Stopping
/// at the rescaled steady state instead was 4.3e-3 off at step 1 and 3.7e-3 still at step 5.
#[test]
fn default_restart_solves_the_step_when_a_friction_rise_turns_the_slip() {
    let h = history("mu_rise", None);
    let (d, k) = worst(&h, "contact_envelope", "mu_rise");
    println!("mu_rise: largest |df| {d:.2e} at row {k}");
    assert!(d < TOL, "mu_rise: {d:.2e} at row {k}");
    assert_eq!(h.column("n_adhesion").unwrap(), reference_in("contact_envelope", "mu_rise", "n_adhesion"));
    let iterations = h.column("iterations").unwrap();
    assert!(iterations[1] > 0.0, "step 1 solved, not restarted: {} iterations", iterations[1]);
}

#[test]
fn converged_restart_matches_contact_with_a_tight_steady_start() {
    for case in ["mu_ramp", "fn_sine_f20"] {
        let h = history(case, Some("converged"));
        let (d, k) = worst(&h, "contact_envelope_tight", case);
        println!("{case}: largest |df| {d:.2e} at row {k}");
        assert!(d < TOL, "{case}: {d:.2e} at row {k}");
        // The two restarts differ where CONTACT's published step 1 does.
        let published = reference_in("contact_envelope", case, "fx_over_fn");
        let fx = h.column("fx_over_fn").unwrap();
        assert!((fx[1] - published[1]).abs() > 1e-4, "{case}: step 1 {} vs {}", fx[1], published[1]);
    }
}

#[test]
fn unknown_restart_is_refused_naming_the_key() {
    let text = suite_scene_text("envelope", "mu_ramp")
        .replace("[init]", "[contact_solver]\nsteady_restart = \"project\"\n\n[init]");
    let err = Scene::from_toml(&text, &root().join("scenes/envelope")).unwrap_err().to_string();
    assert!(err.contains("contact_solver.steady_restart") && err.contains("converged"), "{err}");
}
