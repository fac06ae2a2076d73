//! Issue 32 item 3: the rolling direction CHI (`[rolling] chi_deg`, CONTACT's CHI = 0 or 180°).
//! Reference: the mirror symmetry x → −x, a closed-form relation: rolling along −x with creepages
//! (cx, cy, cs) is the mirror image of rolling along +x with (−cx, cy, −cs), so
//! Fx(180°; cx, cy, cs) = −Fx(0°; −cx, cy, −cs), Fy the same, Mz = −Mz (CONTACT `m_sdis.f90`:
//! the shift `dq cos CHI`, the spin offset `cos CHI · dq/6`).

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

/// The thesis contact on a 22 × 22 grid, μ = 0.3, with `creepage` and `chi_deg`; the solver
/// stopped at 1e-12 (the two directions' round-off then stays far below the test's 1e-9).
fn scene(creepage: &str, chi_deg: f64) -> String {
    let extra = format!("[rolling]\nchi_deg = {chi_deg:?}\n[contact_solver]\ntolerance = 1e-12");
    scene_text("chi", "[\"contact\"]", 0.3, 22, creepage, &extra)
}

fn columns(h: &History) -> [Vec<f64>; 3] {
    ["fx_over_fn", "fy_over_fn", "mz_nmm"].map(|c| h.column(c).unwrap())
}

/// Asserts the mirror relation row by row, to 1e-9 of the largest |value| of the column.
fn assert_mirrored(back: &History, ahead: &History) -> [f64; 3] {
    let (b, a) = (columns(back), columns(ahead));
    let mut worst = [0.0; 3];
    for (c, sign) in [(0, -1.0), (1, 1.0), (2, -1.0)] {
        let scale = a[c].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(scale > 0.0 && b[c].len() == a[c].len());
        for (x, y) in b[c].iter().zip(&a[c]) {
            worst[c] = f64::max(worst[c], (x - sign * y).abs() / scale);
        }
        assert!(worst[c] < 1e-9, "column {c}: worst relative difference {:.2e}", worst[c]);
    }
    worst
}

/// Steady rolling along −x (a sweep over cx with cy and spin) against the mirrored +x sweep; the
/// direction matters: Fy with spin differs from the +x run with the same creepages.
#[test]
fn steady_rolling_at_180_deg_is_the_mirrored_0_deg_case() {
    let (cy, cs) = (0.0005, 0.0002);
    let sweep = |sign: f64| {
        format!("kind = \"sweep\"\nfrom = 0.0\nto = {:?}\npoints = 5\ncy = {cy:?}\ncs = {:?}", sign * 0.004, sign * cs)
    };
    let back = run(&problem(&scene(&sweep(1.0), 180.0)), "contact");
    let ahead = run(&problem(&scene(&sweep(-1.0), 0.0)), "contact");
    let worst = assert_mirrored(&back, &ahead);
    let same = run(&problem(&scene(&sweep(1.0), 0.0)), "contact");
    let (fy_back, fy_same) = (back.column("fy_over_fn").unwrap(), same.column("fy_over_fn").unwrap());
    println!("steady: worst relative differences {worst:?}; fy/fn at 180 deg {fy_back:?}, at 0 deg {fy_same:?}");
    assert!((fy_back[0] - fy_same[0]).abs() > 0.01, "the direction has no effect: {} vs {}", fy_back[0], fy_same[0]);
}

/// Transient rolling from rest and prescribed Fx along −x against the mirrored +x histories.
#[test]
fn transient_rolling_at_180_deg_is_the_mirrored_0_deg_case() {
    let step = |sign: f64| {
        format!("kind = \"step\"\nc = {:?}\nsteps = 12\ncy = 0.0005\ncs = {:?}", sign * 0.002, sign * 0.0002)
    };
    let worst = assert_mirrored(
        &run(&problem(&scene(&step(1.0), 180.0)), "contact"),
        &run(&problem(&scene(&step(-1.0), 0.0)), "contact"),
    );
    println!("transient: worst relative differences {worst:?}");
    let force =
        |sign: f64| format!("kind = \"step\"\nfx_over_fn = {:?}\nsteps = 3\ncs = {:?}", sign * 0.15, sign * 0.0002);
    let (back, ahead) =
        (run(&problem(&scene(&force(1.0), 180.0)), "contact"), run(&problem(&scene(&force(-1.0), 0.0)), "contact"));
    assert_mirrored(&back, &ahead);
    let (cx_back, cx_ahead) = (back.column("cx").unwrap(), ahead.column("cx").unwrap());
    for (b, a) in cx_back.iter().zip(&cx_ahead) {
        assert!((b + a).abs() <= 1e-9 * a.abs(), "creepage found {b} vs mirrored {a}");
    }
}

/// Other angles, and models other than the exact one, are refused naming the key.
#[test]
fn other_angles_and_models_are_refused() {
    let sweep = "kind = \"sweep\"\nfrom = 0.0\nto = 0.001\npoints = 2";
    let e = Scene::from_toml(&scene(sweep, 90.0), std::path::Path::new(".")).unwrap_err().to_string();
    assert!(e.contains("rolling.chi_deg") && e.contains("0 or 180"), "{e}");
    let text = scene_text("chi", "[\"fastsim\"]", 0.3, 22, sweep, "[rolling]\nchi_deg = 180.0");
    let scene = Scene::from_toml(&text, std::path::Path::new(".")).unwrap();
    let e = creepbench::pipeline::resolve(&scene).map(|_| ()).unwrap_err().to_string();
    assert!(e.contains("rolling.chi_deg") && e.contains("fastsim"), "{e}");
}

/// `export contact` writes CHI = 180d, `import contact` reads it back into `[rolling] chi_deg`
/// (the same resolved scene, the same rows); a deck at another angle is refused naming CHI.
#[test]
fn export_then_import_keeps_the_direction() {
    use creepbench::export::contact::module3_input;
    use creepbench::import::contact::scene::import_text;
    use creepbench::problem::ResolvedScene;
    for creepage in
        ["kind = \"sweep\"\nfrom = 0.0\nto = 0.002\npoints = 3\ncs = 0.0002", "kind = \"step\"\nc = 0.002\nsteps = 4"]
    {
        let original = problem(&scene(creepage, 180.0));
        let deck = module3_input(&original);
        assert!(deck.contains("  180d   "), "{deck}");
        let imported = import_text("chi.inp", "chi", &deck).unwrap();
        assert!(imported.statuses.iter().all(|s| s.supported()), "{:?}", imported.statuses);
        assert_eq!(imported.scenes.len(), 1);
        let dir = tempdir("rolling_direction_round_trip");
        for (name, text) in &imported.scenes[0].files {
            std::fs::write(dir.join(name), text).unwrap();
        }
        let back = creepbench::pipeline::load(&dir.join(&imported.scenes[0].files[0].0), &[]).unwrap();
        assert_eq!(back.rolling.chi_deg, 180.0);
        let (a, b) = (ResolvedScene::of(&original, &original.solvers), ResolvedScene::of(&back, &back.solvers));
        assert_eq!((a.chi_deg, a.dq_mm, a.v_mm_s), (b.chi_deg, b.dq_mm, b.v_mm_s));
        let rows = |p: &creepbench::problem::Problem| p.loading.rows().map(|s| [s.cx, s.cy, s.cs]).collect::<Vec<_>>();
        assert_eq!(rows(&original), rows(&back));
        let at_90 = deck.replace("  180d   ", "  90d   ");
        let refused = import_text("chi.inp", "chi", &at_90).unwrap();
        let reasons: Vec<String> = refused.statuses.iter().flat_map(|s| s.refused.clone()).collect();
        assert!(reasons.iter().any(|r| r.contains("CHI = 1.57")), "{reasons:?}");
    }
}
