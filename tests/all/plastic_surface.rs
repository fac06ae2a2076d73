//! CONTACT's testbank/examples_plast (issue 46 item 2): the plasticity of the bodies' surface
//! (M = 4 with LAYTHK = 0 and TAU_C0 > 0, `[material] layer_thickness_mm = 0` with
//! `layer_yield_mpa`): each deck's supported scene of `scenes/contact_public` simulated and
//! compared with the totals CONTACT printed in its `.ref_out` (fx/fn, fy/fn and, under a
//! prescribed force, the shift found), in half-units of the printed value's last digit; the
//! cases the import refuses name what is missing (a yield limit that moves in rolling).

use crate::common::{root, tempdir};
use creepbench::comparison::references::contact_output::printed::Printed;
use creepbench::comparison::references::contact_public::{PublicCases, RowDiff, CX, FX, FX_NOISE, FY};
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

/// The cases of these decks the import refuses name the feature: a yield limit that moves (K_TAU
/// ≠ 0) in steady rolling (carter_plast 1, tractcurve_plast 31) and the surface's plasticity in
/// transient rolling (catt2d_plast 2, catt3d_plast 4).
#[test]
fn the_refused_cases_name_what_is_missing() {
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
    let line = |text: &str, case: usize| {
        let head = format!("skipped case {case} (");
        text.lines().find(|l| l.starts_with(&head)).unwrap_or_else(|| panic!("case {case}: {text}")).to_string()
    };
    let moving = "a yield limit that moves in steady rolling";
    let carter = import("carter_plast");
    assert!(line(&carter, 1).contains("K_TAU = 4018000") && line(&carter, 1).contains(moving));
    let tract = import("tractcurve_plast");
    assert!(line(&tract, 31).contains("K_TAU = 35143") && line(&tract, 31).contains(moving));
    let transient = "M = 4, T = 2: an interface layer in transient rolling";
    assert!(line(&import("catt2d_plast"), 2).contains(transient));
    let catt3d = import("catt3d_plast");
    assert!(line(&catt3d, 4).contains(transient), "{}", line(&catt3d, 4));
    assert!(catt3d.contains("none of 63 case(s) supported"), "{catt3d}");
}
