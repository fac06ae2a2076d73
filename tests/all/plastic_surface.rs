//! CONTACT's testbank/examples_plast (issue 46 item 2): the plasticity of the bodies' surface
//! (M = 4 with LAYTHK = 0 and TAU_C0 > 0, `[material] layer_thickness_mm = 0` with
//! `layer_yield_mpa`): each deck's supported scene of `scenes/contact_public` simulated and
//! compared with the totals CONTACT printed in its `.ref_out` (fx/fn, fy/fn and, under a
//! prescribed force, the shift found), in half-units of the printed value's last digit; every
//! case is imported, the hardening surface in transient rolling too (its limits moved with the
//! material before each step).

use crate::common::{root, tempdir};
use creepbench::comparison::references::contact_output::printed::Printed;
use creepbench::comparison::references::contact_public::{PublicCases, RowDiff, CX, FX, FX_NOISE, FY, MZ_Q};
use std::path::Path;
use std::process::Command;

/// The scene `name` of scenes/contact_public simulated into `out`, and every comparison of its
/// rows with the printed cases of its deck.
fn diffs(out: &Path, name: &str) -> Vec<RowDiff> {
    let scene = root().join(format!("scenes/contact_public/{name}.toml"));
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .args(["simulate", scene.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{name}: {}", String::from_utf8_lossy(&o.stderr));
    let stored = creepbench::suite::results::read_scene(out, name).unwrap();
    let public = PublicCases::load(&root().join("reference")).unwrap();
    public.row_diffs(&stored, &stored.histories["contact"]).unwrap()
}

/// The worst difference in half-units of the cases `cases` of `d`, each case compared at least
/// for fx/fn and fy/fn.
fn worst(d: &[RowDiff], cases: impl Iterator<Item = usize>) -> f64 {
    let mut worst = 0.0f64;
    for case in cases {
        let of_case: Vec<&RowDiff> = d.iter().filter(|r| r.case == case).collect();
        assert!(of_case.iter().any(|r| r.quantity == FX || r.quantity == FX_NOISE), "case {case}: {of_case:?}");
        assert!(of_case.iter().any(|r| r.quantity == FY), "case {case}: {of_case:?}");
        worst = of_case.iter().map(|r| r.half_units()).fold(worst, f64::max);
    }
    worst
}

/// carter_plast.inp's elastic-perfectly plastic cases (K_TAU = 0, TAU_C0 = 35 < μ pmax ≈ 57):
/// Carter's 2-D steady rolling at cx = −4e-4 on grids of DX = 0.08, 0.04, 0.02 mm (cases 3, 7,
/// 11). Measured worst 0.98 half-units (case 11, FX/FSTAT/FN = 0.5864 printed).
#[test]
fn carter_plast_elastic_perfectly_plastic_2d_rolling_at_printed_digits() {
    let out = tempdir("plastic_surface_carter");
    for (name, case) in [("carter_plast_3", 3), ("carter_plast_7", 7), ("carter_plast_11", 11)] {
        let d = diffs(&out, name);
        let w = worst(&d, [case].into_iter());
        assert!(w <= 1.0, "{name}: worst {w} half-units: {d:?}");
        // The yield limit bites: FX/FSTAT/FN printed 0.5959, 0.5896, 0.5864, where case 1 (K_TAU
        // = 4018000: the limit moves up almost at once, nearly elastic) printed 0.6562.
        let fx = d.iter().find(|r| r.quantity == FX).unwrap();
        assert!(fx.ours.abs() < 0.6 * 0.5, "{name}: fx/fn {}", fx.ours);
    }
}

/// tractcurve_plast.inp: Polach's Eurosprinter traction curve (FN = 106.7 kN, a/b = 0.5, cx up
/// to 0.25 in 30 steps) with Coulomb friction (cases 1-30) and with the surface yielding at
/// TAU_C0 = 150 MPa, K_TAU = 0 (cases 181-210, its seventh series): every case within one
/// half-unit of its printed digits (measured worst 0.90 half-units, cases 14 and 183). The
/// yield limit takes the curve below Coulomb's at large creepage (case 210 against 30).
#[test]
fn tractcurve_plast_coulomb_and_yielding_curves_at_printed_digits() {
    let out = tempdir("plastic_surface_tractcurve");
    let coulomb = diffs(&out, "tractcurve_plast_1");
    let yielding = diffs(&out, "tractcurve_plast_181");
    let (wc, wy) = (worst(&coulomb, 1..=30), worst(&yielding, 181..=210));
    assert!(wc <= 1.0 && wy <= 1.0, "worst {wc}, {wy} half-units");
    let fx = |d: &[RowDiff], case: usize| d.iter().find(|r| r.case == case && r.quantity == FX).unwrap().printed.value;
    // FX/FSTAT/FN printed 1.000 at cx = 0.25 with Coulomb friction, 0.8852 with the yield limit.
    assert!((fx(&coulomb, 30).abs() - 0.33).abs() < 1e-3, "{}", fx(&coulomb, 30));
    assert!(fx(&yielding, 210).abs() < 0.9 * 0.33, "{}", fx(&yielding, 210));
}

/// catt2d_plast.inp case 1: Cattaneo's 2-D shift (T = 1) under FX/FSTAT/FN = 0.6 prescribed with
/// a hardening surface (TAU_C0 = 35, K_TAU = 123000): the force reached and the SHIFT X found
/// within one half-unit of the printed digits (measured worst 0.62).
#[test]
fn catt2d_plast_hardening_shift_under_a_force_at_printed_digits() {
    let out = tempdir("plastic_surface_catt2d");
    let d = diffs(&out, "catt2d_plast_1");
    assert!(d.iter().any(|r| r.quantity == CX), "the shift found is compared: {d:?}");
    let w = worst(&d, [1].into_iter());
    assert!(w <= 1.0, "worst {w} half-units: {d:?}");
}

/// plastic_one_shift.inp: one element (FN = 5, μ = 1, TAU_C0 = 3, K_TAU = 0.42857) shifted
/// forth (1-5), held (6), back (7-9), held (10), forth (11-16), round a corner from x to y
/// (17-23) and along y (24-27): all 27 cases within one half-unit of the printed digits
/// (measured worst 1.00, case 3, FX/FSTAT/FN = −0.6063). In cases 23-27 the x-traction left as
/// the element turns to y is printed 1.005E-05 to 6.129E-06: the gate measures it at its noise
/// floor, and here at its printed digits too.
#[test]
fn plastic_one_shift_hardens_round_a_corner_at_printed_digits() {
    let out = tempdir("plastic_surface_one_shift");
    let d = diffs(&out, "plastic_one_shift_1");
    let w = worst(&d, 1..=27);
    // Case 3 sits on the printed rounding's boundary (ours −0.606349997, printed −0.6063: 0.9994
    // half-units), so the bound is the gate's, one printed unit; every other case is within 0.97.
    assert!(w <= 2.0, "worst {w} half-units");
    let others = worst(&d, (1..=27).filter(|&c| c != 3));
    assert!(others <= 1.0, "worst {others} half-units without case 3");
    for case in 23..=27 {
        let r = d.iter().find(|r| r.case == case && r.quantity == FX_NOISE).expect("floored x-traction");
        let printed = Printed::parse(&format!("{:.3e}", r.printed.value)).unwrap();
        let at_digits = (r.ours - printed.value).abs() / printed.half_unit;
        assert!(at_digits <= 1.0, "case {case}: ours {} printed {} ({at_digits} half-units)", r.ours, r.printed.value);
    }
}

/// A yield limit that moves (K_TAU ≠ 0) in steady rolling, each element's limit carried from the
/// element upstream as CONTACT's SteadyGS (`stdygs`) carries it: carter_plast.inp's 2-D rolling at
/// cx = −4e-4 with K_TAU = 123000 (case 2: FX/FSTAT/FN printed 0.6420) and −20500 (case 4:
/// 0.5509), where the K_TAU = 0 case of the same grid printed 0.5959; tractcurve_plast.inp's
/// traction curve hardening at K_TAU = 35143 (cases 31-60) and softening at −81.918 (211-240, to
/// the floor 0.1 τ_c0 from cx = 0.175 on: FX/FSTAT/FN printed 0.5121 at cx = 0.25 against 0.8852
/// at K_TAU = 0). Every case within one half-unit of its printed digits (measured worst 0.77,
/// 0.02, 0.98, 0.95). Past the floor a flowing element's own bound is τc' + K_TAU |Δu_pl|, below
/// 15 MPa, as CONTACT's `plstrc` leaves its traction (only the limit carried on is floored): with
/// the bound floored too, cases 237-240 were 24 to 177 half-units off.
#[test]
fn moving_yield_limit_in_steady_rolling_at_printed_digits() {
    let out = tempdir("plastic_surface_steady_hardening");
    for (name, cases) in [
        ("carter_plast_2", 2..=2),
        ("carter_plast_4", 4..=4),
        ("tractcurve_plast_31", 31..=60),
        ("tractcurve_plast_211", 211..=240),
    ] {
        let d = diffs(&out, name);
        let w = worst(&d, cases);
        assert!(w <= 1.0, "{name}: worst {w} half-units");
    }
    let d = diffs(&out, "carter_plast_4");
    let fx = d.iter().find(|r| r.quantity == FX).unwrap();
    // Softening takes FX below the elastic-perfectly plastic 0.5959·μ (case 3).
    assert!((fx.ours.abs() - 0.5509 * 0.5).abs() <= 0.5e-4 * 0.5 * 1.5, "fx/fn {}", fx.ours);
    let stored = creepbench::suite::results::read_scene(&out, "tractcurve_plast_211").unwrap();
    let h = &stored.histories["contact"];
    let tau_min = h.column("tau_c_min_mpa").unwrap();
    // The softened elements flow below the floor 0.1 τ_c0 = 15 MPa at the largest creepages.
    let last = tau_min.last().copied().unwrap();
    assert!(last > 0.0 && last < 15.0, "{tau_min:?}");
    assert!(h.column("hardening_converged").unwrap().iter().all(|&c| c == 1.0));
}

/// The import takes every case of these decks: carter_plast 1 and tractcurve_plast 31 (a yield
/// limit that moves in steady rolling), catt2d_plast 2 and catt3d_plast 4 (the surface hardening
/// in transient rolling); a layer with a thickness in transient rolling stays refused
/// (tests/all/contact_import.rs).
#[test]
fn every_case_of_the_plasticity_decks_is_imported() {
    let dir = tempdir("plastic_surface_refused");
    let deck = |name: &str| root().join(format!("reference/contact_public/testbank/examples_plast/{name}.inp"));
    let import = |name: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .args([
                "import",
                "contact",
                deck(name).to_str().unwrap(),
                "--out",
                dir.to_str().unwrap(),
                "--supported-only",
            ])
            .output()
            .unwrap();
        String::from_utf8_lossy(&o.stderr).to_string() + &String::from_utf8_lossy(&o.stdout)
    };
    for name in ["carter_plast", "tractcurve_plast", "catt2d_plast", "catt3d_plast", "plastic_one_shift"] {
        let text = import(name);
        assert!(!text.lines().any(|l| l.starts_with("skipped case ")), "{name}: {text}");
    }
}

/// The scene `name`'s stored history column `column` (simulated into `out` by [`diffs`]).
fn column(out: &Path, name: &str, column: &str) -> Vec<f64> {
    let stored = creepbench::suite::results::read_scene(out, name).unwrap();
    stored.histories["contact"].column(column).unwrap()
}

/// catt2d_plast.inp cases 1-50: the hardening surface (TAU_C0 = 35, K_TAU = 123000) shifted under
/// FX/FSTAT/FN = 0.6 (case 1), then rolled at cx = -4e-4 for 49 steps of dq = dx (T = 2, P = 0),
/// each element's yield limit moved with the material before the step (CONTACT's set_prev_data):
/// every case within the gate's 2 half-units (measured worst 1.01, case 29). Case 2 as CONTACT
/// prints it: FX/FSTAT/FN = 0.6051, 17 elements in adhesion and 4 + 5 slipping or flowing
/// (NADH, NSLIP, NPLAST); case 50: 0.6379, 11 and 8 + 7. The limits rose above TAU_C0.
#[test]
fn catt2d_plast_hardening_in_transient_rolling_at_printed_digits() {
    let out = tempdir("plastic_surface_catt2d_rolling");
    let d = diffs(&out, "catt2d_plast_1");
    let w = worst(&d, 1..=50);
    assert!(w <= 2.0, "worst {w} half-units: {d:?}");
    for (case, printed, adhesion, slip) in [(2, 0.6051, 17.0, 4.0 + 5.0), (50, 0.6379, 11.0, 8.0 + 7.0)] {
        let fx = d.iter().find(|r| r.case == case && r.quantity == FX).unwrap();
        assert!((fx.printed.value.abs() - 0.5 * printed).abs() < 1e-9, "case {case}: {fx:?}");
        assert!(fx.half_units() <= 1.0, "case {case}: {fx:?}");
        let row = case - 1;
        assert_eq!(column(&out, "catt2d_plast_1", "n_adhesion")[row], adhesion, "case {case}");
        assert_eq!(column(&out, "catt2d_plast_1", "n_slip")[row], slip, "case {case}");
    }
    let tau_max = column(&out, "catt2d_plast_1", "tau_c_max_mpa");
    assert!(tau_max.last().is_some_and(|&t| t > 50.0), "{tau_max:?}");
    assert!(column(&out, "catt2d_plast_1", "hardening_converged").iter().all(|&c| c == 1.0));
}

/// catt3d_plast.inp: the 3-D circle (34 x 33 elements, TAU_C0 = 0.005, K_TAU = 0.42857) rolled
/// from rest under FX/FSTAT/FN = 0.6918 (case 3, CREEP X found), then at cx = -0.0034 for 56
/// steps (4-59), and the elastic-perfectly plastic surface (K_TAU = 0) rolled from rest and one
/// step on (60-61; 62-63 the same by CONTACT's other solver): every case within the gate's 2
/// half-units (measured worst 1.02, case 9); case 59 with CONTACT's 282 elements in adhesion.
#[test]
fn catt3d_plast_transient_rolling_at_printed_digits() {
    let out = tempdir("plastic_surface_catt3d_rolling");
    let d = diffs(&out, "catt3d_plast_3");
    assert!(d.iter().any(|r| r.quantity == CX && r.case == 3), "the creepage found is compared: {d:?}");
    // MZ = 0 by symmetry; CONTACT prints its iteration's noise (up to 1.05e-6 N mm, cases 43-46
    // and 54-56; tolerances.toml reports it, not gated): ours stays below 1e-9 N mm.
    let (mz, d): (Vec<RowDiff>, Vec<RowDiff>) = d.into_iter().partition(|r| r.quantity == MZ_Q);
    assert!(mz.iter().all(|r| r.ours.abs() < 1e-9 && r.printed.value.abs() < 1.1e-6), "{mz:?}");
    let w = worst(&d, 3..=59);
    assert!(w <= 2.0, "worst {w} half-units");
    assert_eq!(column(&out, "catt3d_plast_3", "n_adhesion").last(), Some(&282.0));
    for (name, cases) in [("catt3d_plast_60", 60..=61), ("catt3d_plast_62", 62..=63)] {
        let d = diffs(&out, name);
        let w = worst(&d, cases);
        assert!(w <= 1.0, "{name}: worst {w} half-units: {d:?}");
    }
}
