//! CONTACT's FASTSIM (`fastsim_contact`, issue 46): its totals are over the prescribed FN, as
//! CONTACT prints them, while Hertz's pressure imposed at the element centres carries Σ p dx dy;
//! at full slip |F|/FN is then μ times that load over FN, above μ, and the gate's traction check
//! takes the load the model reports (`fn_carried_n`) instead of failing a faithful result.

use crate::common::{root, tempdir};
use creepbench::comparison::compare::{traction_bound, Against};
use std::process::Command;

#[test]
fn full_slip_reaches_mu_times_the_carried_load_and_passes_the_traction_check() {
    let out = tempdir("fastsim_contact_bound");
    let scene = root().join("scenes/contact_public/tractcurv_61.toml");
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .args(["simulate", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut stored = creepbench::suite::results::read_scene(&out, "tractcurv_61").unwrap();
    let h = &stored.histories["fastsim_contact"];
    let carried = h.column("fn_carried_n").unwrap();
    let last = h.rows.len() - 1;
    let (row, share) = (&h.rows[last], carried[last] / h.rows[last].sample.fn_n);
    // tractcurv's 48 x 44 grid: the parabolic pressure at the element centres carries 1.00008 FN;
    // at cx = 0.25 every element slips and Fx/FN = 0.33 x 1.00008 (CONTACT prints 1.000 FSTAT).
    assert!((share - 1.0000797).abs() < 1e-6, "{share}");
    assert_eq!(row.extra[0], 0.0, "n_adhesion at full slip");
    assert!((row.fx_over_fn - 0.33 * share).abs() < 1e-12, "{}", row.fx_over_fn);
    assert!(traction_bound(&stored, Against::Golden).is_empty());
    // Without the carried load the same history is beyond μ: the check would fail it.
    for h in stored.histories.values_mut() {
        for c in h.extra_columns.iter_mut().filter(|c| *c == "fn_carried_n") {
            *c = "unknown".into();
        }
    }
    let found = traction_bound(&stored, Against::Golden);
    assert!(found.iter().any(|f| f.solver == "fastsim_contact" && f.quantity == "traction_bound"), "{found:?}");
}
