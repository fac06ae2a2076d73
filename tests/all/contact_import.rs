//! Issue 32 items 1 and 5, `import contact`: CONTACT's module-3 input → scenes. Every shipped
//! scene survives `export contact` then `import contact` (the same resolved problem); CONTACT's own
//! public decks (tests/data/contact_decks, verbatim, see PROVENANCE.md) import with the
//! supported/refused split and the values their cases give.

use crate::common;
use common::root;
use creepbench::export::contact::module3_input;
use creepbench::import::contact::scene::{import_text, Imported};
use creepbench::problem::{Problem, ResolvedScene};
use creepbench::scene::InitialSlip;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Write an import's files into `dir` and load each scene with the project's reader.
fn load_all(imported: &Imported, dir: &Path) -> Vec<Problem> {
    for s in &imported.scenes {
        for (name, text) in &s.files {
            std::fs::write(dir.join(name), text).unwrap();
        }
    }
    imported.scenes.iter().map(|s| creepbench::pipeline::load(&dir.join(&s.files[0].0), &[]).unwrap()).collect()
}

/// Keys of scene.json a CONTACT deck does not carry: names and the models, metrics and solver
/// options of this project, and the form the history was given in (a sine, a step or a sweep's
/// `from`/`to`/`over` come back as the same rows of a table or a sweep's `at`), `origin`
/// (the deck a scene was imported from: the exported deck is another file) and `report_group`
/// (where the report shows the scene).
const OUTSIDE_A_DECK: &[&str] = &[
    "name",
    "origin",
    "report_group",
    "solvers",
    "metrics",
    "skipped_metrics",
    "model",
    "contact_solver",
    "suite",
    "studies",
    "warnings",
    "kind",
    "freq_hz",
    "sweep_direction",
];

/// Keys that follow from the scene's `[model]` options (Kalker's coefficients from the table or
/// the fit, the flexibilities, the simplified models' pressure): outside a deck where the scene
/// sets those options.
const MODEL_DEPENDENT: &[&str] = &["c11", "c22", "c23", "c33", "l1_mm3_n", "l2_mm3_n", "l3_mm3_n", "p_model_peak_mpa"];

/// Keys that follow from the nominal load (`contact.fn_n`): where the load changes within the
/// history a deck gives each case's FN and no nominal one (the import takes the first case's),
/// so the nominal ellipse and what follows from it are outside a deck.
const NOMINAL: &[&str] = &[
    "fn_n",
    "a_mm",
    "b_mm",
    "p0_mpa",
    "c11",
    "c22",
    "c23",
    "c33",
    "l1_mm3_n",
    "l2_mm3_n",
    "l3_mm3_n",
    "p_model_peak_mpa",
];

/// Keys of the contact's form: an ellipse under a load that changes within the history is
/// exported as its curvatures on a grid (IPOTCN = 1, IBASE = 1) and comes back as h per element
/// (the same undeformed distance on the same grid).
const SHAPE: &[&str] = &["geometry", "grid_scale", "grid_edges_mm", "undeformed_distance_mm"];

/// The keys of scene.json where the original and the imported scene differ (bitwise), minus those
/// outside a deck.
fn differences(original: &Problem, imported: &Problem, split: bool) -> Vec<String> {
    let a = serde_json::to_value(ResolvedScene::of(original, &original.solvers)).unwrap();
    let b = serde_json::to_value(ResolvedScene::of(imported, &imported.solvers)).unwrap();
    let model_set = original.model != creepbench::scene::ModelOptions::default()
        || !original.model_params.scene_json().0.is_empty();
    let load_varies = original.loading.rows().any(|s| s.fn_n != original.nominal.fn_n);
    let reshaped = original.geometry.elliptic() && load_varies;
    // A profile h = a1 x² + g(y) is exported element by element (IBASE = 9): a field comes back.
    let profile = a["geometry"] == "profile" && b["geometry"] == "field";
    // E given beside G (the thesis's 82000 / 210000 / 0.28): a deck carries G and ν only.
    let e_given = original.material.e_mpa != 2.0 * original.material.g_mpa * (1.0 + original.material.poisson);
    let mut out = Vec::new();
    for (key, va) in a.as_object().unwrap() {
        let skip = OUTSIDE_A_DECK.contains(&key.as_str())
            || (model_set && MODEL_DEPENDENT.contains(&key.as_str()))
            || (load_varies && NOMINAL.contains(&key.as_str()))
            || (reshaped && SHAPE.contains(&key.as_str()))
            || (profile && key == "geometry")
            || (e_given && key == "e_mpa")
            // The rows are compared on their own (the t = 0 state of a history that starts from
            // zero traction is not solved and not in a deck); a split sweep has one point each.
            || key == "loading"
            || (split && key == "n_steps");
        if !skip && Some(va) != b.get(key) {
            out.push(key.clone());
        }
    }
    out
}

/// A row's time, creepages (or the forces prescribed in their place), load (or approach), its
/// own undeformed distance (B1..B6) and friction, as bits, and μ.
fn row_bits(s: &creepbench::problem::Sample) -> (Vec<u64>, f64) {
    let opt = |f: Option<f64>| f.map_or(u64::MAX, f64::to_bits);
    let mut bits: Vec<u64> = [s.t_s, s.cx, s.cy, s.cs, s.fn_n].map(f64::to_bits).to_vec();
    bits.extend([opt(s.fx_target), opt(s.fy_target), opt(s.pen_mm)]);
    bits.extend(s.h_coefficients.map_or(vec![u64::MAX], |b| b.map(f64::to_bits).to_vec()));
    (bits, s.mu)
}

/// Rows equal: bit for bit, μ within the export's 1e-9 relative (a table's μ interpolated at a
/// printed time is read again only where it changed beyond rounding, `export::contact`).
fn same_row(a: &(Vec<u64>, f64), b: &(Vec<u64>, f64)) -> bool {
    a.0 == b.0 && (a.1 - b.1).abs() <= 1e-9 * a.1.abs()
}

#[test]
fn export_then_import_gives_back_every_shipped_scene() {
    // Every contact-patch suite (a wheel–rail scene's round trip: contact_wheelrail_import.rs).
    let mut suites: Vec<PathBuf> = std::fs::read_dir(root().join("scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir() && !p.ends_with("wheelrail"))
        .collect();
    suites.sort();
    let sources = creepbench::suite::scene_files(&suites, None).unwrap();
    assert!(sources.len() > 100, "{} scenes", sources.len());
    let dir = common::tempdir("contact_import_round_trip");
    let (mut failures, mut split, mut extra_slips) = (Vec::new(), 0, 0);
    for source in &sources {
        let original = creepbench::pipeline::load_source(source, &[]).unwrap();
        let deck = module3_input(&original);
        let imported = import_text(&format!("{}.inp", original.name), &original.name, &deck).unwrap();
        let refused: Vec<String> = imported
            .statuses
            .iter()
            .filter(|s| !s.supported())
            .take(2)
            .map(|s| format!("case {}: {}", s.case, s.refused.join("; ")))
            .collect();
        if !refused.is_empty() || imported.scenes.is_empty() {
            failures.push(format!("{}: refused {}", original.name, refused.join(" | ")));
            continue;
        }
        let backs = load_all(&imported, &dir);
        // A sweep along a direction its points do not give back exactly (the test table's
        // angles) comes back as one steady scene per point.
        if backs.len() > 1 {
            assert_eq!(original.loading.kind, creepbench::problem::LoadingKind::Sweep, "{}", original.name);
            split += 1;
        }
        // Every row bit for bit: time, creepages, load, friction (steps are numbered per scene).
        let ours: Vec<_> = original.loading.rows().map(row_bits).collect();
        let theirs: Vec<_> = backs.iter().flat_map(|b| b.loading.rows().map(row_bits)).collect();
        if ours.len() != theirs.len() || !ours.iter().zip(&theirs).all(|(a, b)| same_row(a, b)) {
            let k = ours.iter().zip(&theirs).position(|(a, b)| !same_row(a, b)).unwrap_or(ours.len().min(theirs.len()));
            failures.push(format!(
                "{}: rows differ from row {k} ({} vs {} rows)",
                original.name,
                ours.len(),
                theirs.len()
            ));
            continue;
        }
        for back in &backs {
            // The extra rigid slip per element (E = 9: EXRHS) comes back bit for bit, in place.
            extra_slips += usize::from(original.extra_slip.is_some());
            if back.extra_slip != original.extra_slip {
                failures.push(format!("{} ({}): extra_slip", original.name, back.name));
            }
            let diff = differences(&original, back, backs.len() > 1);
            if !diff.is_empty() {
                failures.push(format!("{} ({}): {}", original.name, back.name, diff.join(", ")));
            }
        }
    }
    assert!(failures.is_empty(), "{} of {} scenes differ:\n{}", failures.len(), sources.len(), failures.join("\n"));
    // Of the test table's 80 sweeps at ±30° and ±60° (two creepages move), 40 are not given back
    // bit for bit by any line through their points and split; every other scene comes back as one.
    assert_eq!(split, 40, "sweeps split into one scene per point");
    // conformal_4 and testbank_24 (CONTACT's conformal.inp case 4, testbank.inp case 24) carry one.
    assert_eq!(extra_slips, 2, "scenes with an extra rigid slip");
}

/// The import of a deck of tests/data/contact_decks.
fn import_deck(name: &str) -> Imported {
    creepbench::import::contact::import(&root().join("tests/data/contact_decks").join(name)).unwrap()
}

/// The cases of an import that became scenes, and those refused.
fn split(imported: &Imported) -> (Vec<usize>, Vec<usize>) {
    let (ok, no): (Vec<_>, Vec<_>) = imported.statuses.iter().partition(|s| s.supported());
    (ok.iter().map(|s| s.case).collect(), no.iter().map(|s| s.case).collect())
}

/// The scene of an import by name, loaded with the project's reader.
fn scene_of(imported: &Imported, name: &str) -> Problem {
    let dir = common::tempdir(&format!("contact_import_{name}"));
    let k = imported.scenes.iter().position(|s| s.name == name).expect("the scene");
    load_all(imported, &dir).remove(k)
}

#[test]
fn cattaneo_imports_its_normal_case_and_the_shift_by_force() {
    let imported = import_deck("cattaneo.inp");
    assert_eq!(split(&imported), (vec![1, 2], vec![]));
    let case2 = &imported.statuses[1].notes;
    assert!(case2.iter().any(|r| r.starts_with("T = 1: shifts")), "{case2:?}");
    assert!(case2.iter().any(|r| r.starts_with("F = 2: prescribed tangential forces")), "{case2:?}");
    // Case 2: FX = −0.875 (of FSTAT·FN on body 1), FY = 0 → Fx/FN = 0.875 · 0.4 on body 2, one
    // shift from rest with CONTACT's dummy time step of 1 s.
    let p = scene_of(&imported, "cattaneo_2");
    assert_eq!(p.rolling.motion, creepbench::scene::Motion::Shift);
    assert_eq!(p.rolling.dt_s, 1.0);
    let rows: Vec<_> = p.loading.rows().map(|s| (s.step, s.t_s, s.fx_target, s.fy_target, s.fn_n, s.mu)).collect();
    assert_eq!(rows, vec![(1, 1.0, Some(0.875 * 0.4), Some(-0.0), 9.1954, 0.4)]);
    // Case 1: T = 0 (frictionless compression) as a steady point at zero creepage.
    assert!(imported.statuses[0].notes.iter().any(|n| n.starts_with("T = 0: frictionless compression")));
    let p = scene_of(&imported, "cattaneo_1");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.a_mm, r.b_mm, r.fn_n, r.mu), (1.0, 1.0, 9.1954, 0.4));
    assert_eq!((r.mx, r.my, r.grid_scale, r.g_mpa, r.poisson), (19, 19, 1.26667, 200.0, 0.42));
    let rows = r.loading_rows().unwrap();
    assert_eq!(rows.iter().map(|s| [s.cx, s.cy, s.cs]).collect::<Vec<_>>(), vec![[0.0; 3]]);
    let text = &imported.scenes[0].files[0].1;
    assert!(text.contains("[origin]\ncases = [1, 1]\nfile = \"cattaneo.inp\""), "{text}");
}

/// fastsim.inp: case 1 the exact theory; cases 2, 3, 5, 6, 8 CONTACT's FASTSIM (M = 3, issue 46) on
/// Hertz's parabolic (B = 3) or elliptical (B = 2) pressure, case 8 rolling along -x; cases 4 and 7
/// its modified FaStrip (M = 5).
#[test]
fn fastsim_imports_the_exact_theory_and_contacts_fastsim_and_fastrip() {
    let imported = import_deck("fastsim.inp");
    assert_eq!(split(&imported), ((1..=8).collect(), vec![]));
    for k in [3, 6] {
        let s = &imported.statuses[k];
        assert!(s.notes.iter().any(|r| r.starts_with("M = 5, B = 2: CONTACT's modified FaStrip")), "{s:?}");
        let p = scene_of(&imported, &format!("fastsim_{}", k + 1));
        assert_eq!(p.solvers, ["fastrip_contact"]);
    }
    for k in [1, 2, 4, 5, 7] {
        let s = &imported.statuses[k];
        assert!(s.notes.iter().any(|r| r.starts_with("M = 3, B = ")), "{s:?}");
    }
    let p = scene_of(&imported, "fastsim_1");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.a_mm, r.b_mm, r.fn_n, r.mu, r.mx, r.my, r.grid_scale), (8.0, 4.0, 82000.0, 0.3, 44, 44, 1.1));
    assert_eq!((r.v_mm_s, r.dq_mm), (30000.0, 0.4));
    let s = &r.loading_rows().unwrap()[0];
    assert_eq!([s.cx, s.cy, s.cs], [0.0, -0.000625, 0.000625]);
    use creepbench::physics::PressureShape;
    for (name, shape, mx, chi) in [
        ("fastsim_2", PressureShape::Parabolic, 44, 0.0),
        ("fastsim_3", PressureShape::Ellipsoidal, 44, 0.0),
        ("fastsim_5", PressureShape::Parabolic, 220, 0.0),
        ("fastsim_6", PressureShape::Ellipsoidal, 220, 0.0),
        ("fastsim_8", PressureShape::Parabolic, 220, 180.0),
    ] {
        let p = scene_of(&imported, name);
        // The project's FASTSIM beside CONTACT's where it can roll (along +x).
        let beside: &[&str] = if chi == 0.0 { &["fastsim_contact", "fastsim"] } else { &["fastsim_contact"] };
        assert_eq!(p.solvers, beside, "{name}");
        assert_eq!((p.model.pressure, p.grid.mx, p.rolling.chi_deg), (shape, mx, chi), "{name}");
        assert_eq!(p.model.slope_reduction, None, "{name}: K0_MF = ALFAMF = BETAMF = 1 is no reduction");
    }
}

/// tractcurv.inp: the original FASTSIM (61-90) and the modified one with slope reduction and a
/// falling law (91-120) are two sweeps of CONTACT's FASTSIM, apart from the exact theory's.
#[test]
fn tractcurv_imports_contacts_fastsim_sweeps_with_their_slope_reduction() {
    let deck = root().join("reference/contact_public/examples/tractcurv.inp");
    let imported = creepbench::import::contact::import(&deck).unwrap();
    let cases: Vec<_> = imported.scenes.iter().map(|s| (s.name.as_str(), s.cases)).collect();
    assert!(cases.contains(&("tractcurv_61", [61, 90])) && cases.contains(&("tractcurv_91", [91, 120])), "{cases:?}");
    let p = scene_of(&imported, "tractcurv_91");
    assert_eq!(p.solvers, ["fastsim_contact", "fastsim"]);
    assert_eq!(p.model.slope_reduction, Some([0.54, 0.02, 0.62]));
    assert!(p.friction.is_falling());
    let p = scene_of(&imported, "tractcurv_61");
    assert_eq!((p.model.slope_reduction, p.friction.is_falling()), (None, false));
}

/// catt_to_cart.inp cases 1-57: a Cattaneo shift under FX (T = 1, P = 2) then 56 steps of
/// transient rolling (T = 2, P = 0) that continue its traction under the same FX: one scene, the
/// shift its step 0 (`[init] kind = "shift"`), the rolling at t = k DQ/VELOC.
#[test]
fn catt_to_cart_imports_the_shift_and_the_rolling_after_it_as_one_history() {
    let deck = root().join("reference/contact_public/examples/catt_to_cart.inp");
    let imported = creepbench::import::contact::import(&deck).unwrap();
    let first = &imported.scenes[0];
    assert_eq!((first.name.as_str(), first.cases), ("catt_to_cart_1", [1, 57]));
    let p = scene_of(&imported, "catt_to_cart_1");
    assert_eq!(p.rolling.motion, creepbench::scene::Motion::Rolling);
    assert_eq!(p.loading.init, creepbench::scene::InitKind::Shift);
    let rows: Vec<_> = p.loading.rows().collect();
    assert_eq!(rows.len(), 57);
    // FX = −0.657 of FSTAT·FN = 0.4013 on body 1 → Fx/FN = 0.657 · 0.4013 on body 2.
    assert!(rows.iter().all(|s| s.fx_target == Some(0.657 * 0.4013) && s.fy_target.is_none()));
    assert_eq!((rows[0].step, rows[0].t_s, rows[56].step), (0, 0.0, 56));
    assert_eq!(rows[56].t_s, 56.0 * (0.25 / 1000.0));
    // A shift that continues rolling (case 3 as T = 1, P = 0) is refused with its reason; the
    // cases before it are still one history.
    let mut text = std::fs::read_to_string(&deck).unwrap();
    let at = text.match_indices("  002110      P-B-T").nth(1).unwrap().0;
    text.replace_range(at..at + 8, "  001110");
    let again = import_text("c.inp", "c", &text).unwrap();
    let case3 = &again.statuses[2];
    assert!(case3.refused.iter().any(|r| r.starts_with("T = 1 with P = 0 after a rolling case")), "{case3:?}");
    assert_eq!(again.scenes[0].cases, [1, 2]);
}

/// catt_to_cart.inp cases 115-171: a Cattaneo shift on a 34 x 33 window, then 56 shifts under FX
/// with the approach prescribed, each on the window moved by one DX with its quadratic: one scene on
/// the union grid (90 x 33 from XL = -4.125), each moved case noting why that is exact. Where an
/// element outside a case's window would carry pressure (a deeper PEN), the case is refused naming
/// it and its XL, and its history stops before it.
#[test]
fn catt_to_cart_maps_the_moving_window_to_its_union_grid() {
    let deck = root().join("reference/contact_public/examples/catt_to_cart.inp");
    let imported = creepbench::import::contact::import(&deck).unwrap();
    let s = imported.scenes.iter().find(|s| s.name == "catt_to_cart_115").unwrap();
    assert_eq!(s.cases, [115, 171]);
    let p = scene_of(&imported, "catt_to_cart_115");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.mx, r.my), (90, 33));
    assert_eq!(p.grid_edges.map(|(x, _)| x[0]), Some(-4.125));
    assert_eq!(p.loading.rows().count(), 57);
    let note = |c: usize| imported.statuses[c - 1].notes.iter().find(|n| n.contains("union grid")).cloned();
    assert!((115..=171).all(|c| note(c).is_some() && imported.statuses[c - 1].scene.is_some()));
    assert!(note(116)
        .unwrap()
        .starts_with("XL = -3.875: the moving window (34 x 33) is mapped to the union grid (90 x 33 from XL = -4.125"));
    assert!(note(116).unwrap().contains("normal solution is zero outside the window"));
    // Case 170 pressed three times deeper: its contact reaches past its window.
    let mut text = std::fs::read_to_string(&deck).unwrap();
    // The PEN line: four lines after case 170's MODULE line.
    let at: usize = text.split_inclusive('\n').take(imported.statuses[169].line + 4).map(str::len).sum();
    assert!(text[at..].starts_with("  0.07258"), "{}", &text[at..at + 40]);
    text.replace_range(at..at + 9, "  0.21774");
    let again = import_text("c.inp", "c", &text).unwrap();
    let case170 = &again.statuses[169].refused;
    assert!(
        case170.iter().any(|r| r
            .starts_with("XL = 9.625: the grid moves by whole elements, but at PEN or FN = 0.21774 element (")
            && r.contains("outside case 170's window, carries pressure")),
        "{case170:?}"
    );
    assert_eq!(again.scenes.iter().find(|s| s.name == "c_115").unwrap().cases, [115, 169]);
}

#[test]
fn tractcurv_imports_the_coulomb_creep_curve_as_one_sweep() {
    let imported = import_deck("tractcurv.inp");
    let (ok, no) = split(&imported);
    // 31-60: the interface layer (M = 4, issue 46) with a falling law (L = 4, issue 33); 61-120:
    // CONTACT's FASTSIM (M = 3, issue 46); each series a sweep of its own.
    assert_eq!(ok, (1..=120).collect::<Vec<_>>());
    assert!(no.is_empty(), "{no:?}");
    let case31 = &imported.statuses[30].notes;
    assert!(
        case31.iter().any(|r| r.starts_with("M = 4, GG3 = 8200, LAYTHK = 1.25: an elastic interface layer")),
        "{case31:?}"
    );
    assert_eq!(imported.scenes.len(), 4);
    let p = scene_of(&imported, "tractcurv_31");
    let layer = creepbench::physics::material::Layer {
        g_mpa: 8200.0,
        thickness_mm: 1.25,
        yield_mpa: None,
        hardening_mpa_per_mm: 0.0,
    };
    assert_eq!((p.material.layer, p.material.g_mpa), (Some(layer), 82000.0));
    assert!(p.friction.is_falling());
    assert_eq!(p.loading.rows().count(), 30);
    assert_eq!(scene_of(&imported, "tractcurv_1").material.layer, None);
    let p = scene_of(&imported, "tractcurv_1");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.fn_n, r.mu, r.mx, r.my, r.grid_scale, r.v_mm_s), (106700.0, 0.33, 48, 44, 1.1, 10000.0));
    // IPOTCN = -2: A1 = 0.0008 and a/b = 0.5 give Hertz's ellipse of that ratio.
    assert!((r.a_mm / r.b_mm - 0.5).abs() < 1e-12, "a/b = {}", r.a_mm / r.b_mm);
    let cx: Vec<f64> = r.loading_rows().unwrap().iter().map(|s| s.cx).collect();
    assert_eq!(cx.len(), 30);
    assert_eq!((cx[0], cx[1], cx[29]), (0.00001, 0.0004, 0.25));
}

#[test]
fn carter2d_imports_the_strip_as_a_grid_with_its_quadratic_gap() {
    let imported = import_deck("carter2d.inp");
    assert_eq!(split(&imported), (vec![1], vec![]));
    let p = scene_of(&imported, "carter2d_1");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.mx, r.my, r.dx_mm, r.dy_mm, r.mu, r.geometry.as_str()), (55, 1, 0.04, 200.0, 0.3, "field"));
    assert_eq!(r.grid_edges_mm.unwrap()[0][0], -1.07);
    let s0 = r.loading_rows().unwrap()[0];
    assert_eq!([s0.cx, s0.fn_n], [-0.00024, 35780.0]);
    // IPOTCN = 3 with XC1 = -1.05: element 1 at x = -1.05, h = B1 x² = 0.001 · 1.05².
    let h = r.undeformed_distance_mm.unwrap();
    assert!((h[0] - 0.001 * 1.05 * 1.05).abs() < 1e-18, "{}", h[0]);
}

/// examples/veldep_fric (issue 32, falling friction of issue 33): the strip's gap IBASE = 2 (circular
/// in x, pointwise in y) as h per element, the steady case with its transient step (INISLP = 1)
/// and the steady case with its 50 steps from above (INISLP = −1) as two scenes carrying CONTACT's
/// slip-velocity iteration (OMGSLP = 1.1, its fixed stop at 1e-3).
#[test]
fn veldep_fric_imports_its_circular_gap_and_both_branches() {
    let deck = root().join("reference/contact_public/examples/veldep_fric.inp");
    let imported = creepbench::import::contact::import(&deck).unwrap();
    assert_eq!(split(&imported), ((1..=53).collect::<Vec<_>>(), vec![]));
    let spans: Vec<[usize; 2]> = imported.scenes.iter().map(|s| s.cases).collect();
    assert_eq!(spans, vec![[1, 2], [3, 53]]);
    assert!(imported.statuses[2].notes.iter().any(|n| n.starts_with("INISLP, OMGSLP = (1, 1.1): the steady start")));
    let solver = |name: &str| scene_of(&imported, name).contact_solver;
    let (below, above) = (solver("veldep_fric_1"), solver("veldep_fric_3"));
    assert_eq!((below.inislp, below.omgslp, below.veldep_tolerance), (InitialSlip::Below, 1.1, 1e-3));
    assert_eq!((above.inislp, above.omgslp, above.veldep_tolerance), (InitialSlip::Above, 1.1, 1e-3));
    let p = scene_of(&imported, "veldep_fric_3");
    let r = ResolvedScene::of(&p, &p.solvers);
    assert_eq!((r.mx, r.my, r.loading_rows().unwrap().len()), (92, 1, 51));
    // Element k at x = -4.6 + 0.1 (k - 1), y = 0: h = 0 (both heights) + (x - 0)²/(2 · 460).
    let h = r.undeformed_distance_mm.unwrap();
    for (k, x) in [(0, -4.6), (46, 0.0), (91, 4.5)] {
        assert!((h[k] - x * x / 920.0).abs() < 1e-16, "element {k}: {}", h[k]);
    }
}

#[test]
fn testbank_imports_two_cases_and_names_every_other_with_its_reason() {
    let imported = import_deck("testbank.inp");
    let (ok, no) = split(&imported);
    // 1: a Cattaneo shift with the approach prescribed (N = 0); 10: a Cattaneo shift under FX, FY
    // and 11 that continues it with the approach prescribed (N = 0, F = 2: one scene); 17:
    // transient rolling from rest under FX; 8: steady rolling with friction per grid row (V = 3); 2: case 1 with C = 3;
    // 13-16: a shift with B = 2 under FX, rolling under FX (14, 15), then with CKSI and DQ 0.8
    // on the Hertzian grid given again by A1, AOB (16); dissimilar bodies (issue 46): the normal
    // problems 3 and 5 (T = 0, on which K has no effect), steady rolling under FX (4), 9 and the
    // shifts 25, 26; 12: CONTACT's FASTSIM (M = 3, B = 3) under FX (F = 1), issue 46; 24: steady
    // rolling of dissimilar bodies with an extra rigid slip per element (E = 9, all zero).
    assert_eq!(ok, vec![1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 24, 25, 26]);
    assert_eq!(imported.statuses[10].scene.as_deref(), Some("testbank_10"), "{:?}", imported.statuses[10]);
    assert!(
        imported.statuses[10].notes.iter().any(|r| r.starts_with("N = 0: approach prescribed")),
        "{:?}",
        imported.statuses[10]
    );
    // 2: case 1 with the influence functions of bilinear tractions (C = 3).
    let s2 = imported.scenes.iter().find(|s| s.cases == [2, 2]).expect("case 2");
    assert!(s2.files[0].1.contains("[contact_solver]\ninfluence = \"bilinear\"\n"), "{}", s2.files[0].1);
    let s1 = imported.scenes.iter().find(|s| s.cases == [1, 1]).expect("case 1");
    assert!(!s1.files[0].1.contains("influence"), "{}", s1.files[0].1);
    // 5: C = 3 is carried, its dissimilar materials are not.
    assert!(imported.statuses[4].refused.iter().all(|r| !r.starts_with("C = ")), "{:?}", imported.statuses[4]);
    assert!(
        imported.statuses[12].notes.iter().any(|n| n.starts_with("B = 2: traction bound from Hertz")),
        "{:?}",
        imported.statuses[12]
    );
    assert!(
        imported.statuses[15].notes.iter().any(|n| n.starts_with("IPOTCN = -2 re-specifies")),
        "{:?}",
        imported.statuses[15]
    );
    // Case 12: CONTACT's FASTSIM on the parabolic pressure (B = 3) under FX: fastsim_contact alone
    // (the project's FASTSIM finds no creepage of a prescribed force).
    assert!(imported.statuses[11].notes.iter().any(|r| r.starts_with("M = 3, B = 3")), "{:?}", imported.statuses[11]);
    let p = scene_of(&imported, "testbank_12");
    assert_eq!(p.solvers, ["fastsim_contact"]);
    assert!(p.loading.rows().all(|s| s.fx_target.is_some_and(|f| (f + 0.6 * 0.3).abs() < 1e-15)));
    let p = scene_of(&imported, "testbank_13");
    assert_eq!(p.normal.pressure, creepbench::physics::NormalPressure::Solved);
    assert_eq!(p.normal.start_pressure, creepbench::physics::NormalPressure::Elliptical);
    let rows: Vec<_> = p.loading.rows().copied().collect();
    assert_eq!(rows.len(), 4);
    // F = 1 in 13-15 (Fx/FN = -FX FSTAT), CKSI in 16; DQ 0.2, 0.2, 0.2, 0.8 mm.
    assert!(rows[..3].iter().all(|s| s.fx_target == Some(-0.657 * 0.4013)));
    assert_eq!((rows[3].fx_target, rows[3].cx), (None, -0.002124));
    let dq: Vec<f64> = rows.iter().map(|s| s.courant.unwrap() * p.grid.dx_mm).collect();
    assert_eq!(dq, [0.2, 0.2, 0.2, 0.8]);
    let t: Vec<f64> = rows.iter().map(|s| s.t_s).collect();
    assert!((t[3] - 0.0012).abs() < 1e-15 && (t[1] - 0.0002).abs() < 1e-15, "{t:?}");
    assert_eq!(ok.len() + no.len(), imported.statuses.len());
    let module1: Vec<usize> = imported.statuses.iter().filter(|s| s.module == 1).map(|s| s.case).collect();
    assert!(!module1.is_empty());
    // Module 1: every case of the test bank is refused for what the wheel-rail scene lacks
    // (tests/all/contact_wheelrail_import.rs names each).
    for s in imported.statuses.iter().filter(|s| s.module == 1) {
        assert!(s.scene.is_none() && !s.refused.is_empty() && !s.refused[0].starts_with("MODULE = 1"), "{s:?}");
    }
    // Case 3 (T = 0): the normal problem of dissimilar bodies, written with the combined
    // constants; case 4 (steady rolling): the two bodies' own.
    let scene = |c: usize| &imported.scenes.iter().find(|s| s.cases == [c, c]).expect("imported").files[0].1;
    assert!(scene(3).contains("[material]\ng_mpa = ") && !scene(3).contains("g1_mpa"), "{}", scene(3));
    assert!(scene(4).contains("g1_mpa = 200.0") && scene(4).contains("g2_mpa = 1.0"), "{}", scene(4));
    let survey = creepbench::import::contact::survey(&root().join("tests/data/contact_decks/testbank.inp")).unwrap();
    assert_eq!(survey, imported.statuses);
}

fn creepbench(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).args(args).output().expect("runs")
}

#[test]
fn the_command_refuses_a_deck_with_unsupported_cases_whole_unless_asked() {
    let dir = common::tempdir("contact_import_cli");
    // cattaneo.inp with its second case's traction bound approximate (B = 2): refused.
    let text = std::fs::read_to_string(root().join("tests/data/contact_decks/cattaneo.inp")).unwrap();
    let deck = dir.join("cattaneo.inp");
    std::fs::write(&deck, text.replace("  201120     P-B-T", "  221120     P-B-T")).unwrap();
    let out = dir.join("scenes");
    let o = creepbench(&["import", "contact", deck.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("refused case 2 (line 34): not supported: B = 2"), "{err}");
    assert!(!out.exists(), "nothing written");
    let args = ["import", "contact", deck.to_str().unwrap(), "--out", out.to_str().unwrap(), "--supported-only"];
    let o = creepbench(&args);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("skipped case 2 (line 34)"));
    assert_eq!(String::from_utf8_lossy(&o.stdout).trim(), out.join("cattaneo_1.toml").to_str().unwrap());
    // The written scene runs as it is; a second import replaces nothing unless asked.
    let o = creepbench(&args);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--overwrite"));
    let mut again = args.to_vec();
    again.push("--overwrite");
    assert_eq!(creepbench(&again).status.code(), Some(0));
    creepbench::pipeline::load(&out.join("cattaneo_1.toml"), &[]).unwrap();
}

#[test]
fn bad_decks_are_refused_at_their_line_and_column() {
    let dir = common::tempdir("contact_import_bad");
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    let good = std::fs::read_to_string(root().join("tests/data/contact_decks/cattaneo.inp")).unwrap();
    // A word where MX, MY belong (line 29 of cattaneo.inp, case 1's grid line).
    let p = write("bad_mx.inp", &good.replace("   19   19     1.000", "   19   x9     1.000"));
    let e = creepbench::import::contact::import(&p).unwrap_err().to_string();
    assert!(e.contains("bad_mx.inp:29:9 (MX, MY and the potential contact)") && e.contains("a whole number"), "{e}");
    // A control digit out of range names the case, the word and the digit.
    let p = write("bad_digit.inp", &good.replace("  200100     P-B-T", "  200500     P-B-T"));
    let e = creepbench::import::contact::import(&p).unwrap_err().to_string();
    assert!(e.contains("bad_digit.inp, case 1, control word P-B-T-N-F-S, digit N") && e.contains("0, 1"), "{e}");
    // A deck cut short.
    let p = write("short.inp", &good[..good.find("IPOTCN").unwrap()]);
    let e = creepbench::import::contact::import(&p).unwrap_err().to_string();
    assert!(e.contains("short.inp:28` = the end of the file") && e.contains("MX, MY and the potential contact"), "{e}");
    let o = creepbench(&["import", "contact", p.to_str().unwrap(), "--out", dir.join("o").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!dir.join("o").exists());
}

/// Issue 33 item 1: CONTACT's own inputs of the falling-friction cases
/// (reference/contact_friction/<case>.inp: laws L = 2, 3, 4, friction memory, a speed changing per
/// case with C = 2; and the variants' inputs, reference/contact_friction_variants/<case>.inp: two
/// terms, other grids and ellipses, Courant 0.5 to 2, a load ramp) import as one scene each that
/// resolves to the problem of scenes/friction/<case> (scenes/friction_variants/<case>):
/// the same resolved scene, and every row's time, creepages, load, μ and speed equal to the
/// input's printed precision (relative 1e-9, absolute 1e-11, as `contact_export`).
#[test]
fn contacts_falling_friction_inputs_import_as_the_shipped_scenes() {
    let (mut failures, mut n) = (Vec::new(), 0);
    for (folder, suite, count) in
        [("contact_friction", "scenes/friction", 10), ("contact_friction_variants", "scenes/friction_variants", 30)]
    {
        let reference = root().join("reference").join(folder);
        let mut rdr = csv::Reader::from_path(reference.join("cases.csv")).unwrap();
        let names: Vec<String> = rdr.records().map(|r| r.unwrap()[0].to_string()).collect();
        assert_eq!(names.len(), count, "{folder}");
        n += count;
        failures.extend(import_as_scenes(&reference, suite, &names));
    }
    assert!(failures.is_empty(), "{} of {n} differ:\n{}", failures.len(), failures.join("\n"));
}

/// Each input `reference/<case>.inp` imported against the scene of that name in `suite`: the
/// differences found.
fn import_as_scenes(reference: &Path, suite: &str, names: &[String]) -> Vec<String> {
    let mut failures = Vec::new();
    for name in names {
        let imported = creepbench::import::contact::import(&reference.join(format!("{name}.inp"))).unwrap();
        assert!(imported.statuses.iter().all(|s| s.supported()), "{name}: {:?}", imported.statuses);
        let dir = common::tempdir(&format!("contact_friction_{name}"));
        let backs = load_all(&imported, &dir);
        assert_eq!(backs.len(), 1, "{name}: one scene");
        let source = creepbench::suite::find(&[root().join(suite)], name).unwrap();
        let original = creepbench::pipeline::load_source(&source, &[]).unwrap();
        // CONTACT's inputs print the scenes' values to 10-16 digits: equal to the printed precision.
        let values = |p: &Problem| -> Vec<[f64; 7]> {
            let v0 = p.rolling.v_mm_s;
            p.loading.rows().map(|s| [s.t_s, s.cx, s.cy, s.cs, s.fn_n, s.mu, s.speed_mm_s(v0)]).collect()
        };
        let (ours, theirs) = (values(&original), values(&backs[0]));
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs()) + 1e-11;
        let k = ours.iter().zip(&theirs).position(|(a, b)| !a.iter().zip(b).all(|(x, y)| close(*x, *y)));
        if ours.len() != theirs.len() || k.is_some() {
            let k = k.unwrap_or(0);
            failures.push(format!(
                "{name}: {} vs {} rows, row {k}: {:?} vs {:?}",
                ours.len(),
                theirs.len(),
                ours.get(k),
                theirs.get(k)
            ));
        }
        let diff = differences(&original, &backs[0], false);
        if !diff.is_empty() {
            failures.push(format!("{name}: {}", diff.join(", ")));
        }
    }
    failures
}

/// spence35.inp: its subsurface points (S = 3, ISUBS = 2) are two lines of three integers, as
/// CONTACT reads them (`m_subsurf.f90`); the deck is read and every one of its 35 cases is
/// refused for its real reason, the dissimilar bodies (POISS 0 and 0.5, GG 0.5 and 1e5 MPa).
#[test]
fn spence35_is_read_and_its_dissimilar_bodies_imported() {
    let deck = root().join("reference/contact_public/examples/spence35.inp");
    let imported = creepbench::import::contact::import(&deck).unwrap();
    assert_eq!(imported.statuses.len(), 35);
    assert!(imported.statuses.iter().all(|s| s.refused.is_empty()), "{:?}", imported.statuses);
    // One history of 35 shifts, the two bodies' constants as given (K = 0.49999 follows).
    assert_eq!(imported.scenes.len(), 1);
    assert_eq!(imported.scenes[0].cases, [1, 35]);
    let scene = &imported.scenes[0].files[0].1;
    for line in ["g1_mpa = 0.5", "g2_mpa = 100000.0", "poisson1 = 0.0", "poisson2 = 0.0"] {
        assert!(scene.contains(line), "{scene}");
    }
    assert!(!scene.contains("max_outer"), "MAXOUT = 10 is the default: {scene}");
}

/// A falling law's absent term (F < 1e-8) with SABSH = 0: CONTACT takes max(1e-4, SABSH) there
/// (`fric_input`, m_friclaw.f90) and runs the deck; the import writes that SABSH, so the deck
/// imports (it used to be refused: `friction.sabsh1_mm_s` = 0) and resolves to the same law.
#[test]
fn an_absent_falling_term_takes_contacts_smallest_sabsh() {
    let dir = common::tempdir("contact_import_absent_term");
    let text =
        std::fs::read_to_string(root().join("reference/contact_friction_variants/v07_exp_sine_mem.inp")).unwrap();
    let one_case: String = text.lines().take(17).map(|l| format!("{l}\n")).collect();
    let line = "  0.28   0.17   900.0   0.0   1000.0        FKIN, F1, SABSH1, F2, SABSH2";
    assert!(one_case.contains(line));
    for (values, law) in [
        ("0.3   0.0   0.0   0.0   0.0", [0.3, 0.0, 1e-4, 0.0]),
        ("0.3   0.1   100.0   1e-9   0.0", [0.3, 0.1, 100.0, 1e-9]),
    ] {
        let deck = dir.join("absent.inp");
        std::fs::write(&deck, one_case.replace(line, &format!("  {values}   FKIN, F1, SABSH1, F2, SABSH2"))).unwrap();
        let out = dir.join(format!("o_{}", law[3]));
        let o = creepbench(&["import", "contact", deck.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(0), "{values}: {}", String::from_utf8_lossy(&o.stderr));
        let p = creepbench::pipeline::load(&out.join("absent_1.toml"), &[]).unwrap();
        let creepbench::physics::FrictionLaw::Exponential(t) = p.friction else { panic!("{:?}", p.friction) };
        assert_eq!([t.fkin, t.f1, t.sabsh1_mm_s, t.f2], law, "{values}");
        assert!(t.f2 == 0.0 || t.sabsh2_mm_s == 1e-4, "{values}: {t:?}");
    }
}

/// The interface layer in the import: elastic, elasto-plastic and hardening in steady and
/// transient rolling, a hardening one refused in transient rolling at another CHI; a LAYTHK below
/// 1e-10 as no layer (CONTACT's `use_3bl`).
#[test]
fn the_interface_layer_imports_in_steady_and_transient_rolling() {
    let deck = |tang: &str, layer: &str| {
        format!(
            " 3 MODULE\n  20{tang}100  P-B-T-N-F-S\n  022420  L-D-C-M-Z-E\n 0000341  H-G-I-A-O-W-R\n   80 200 5 1 1e-6  MAXGS\n 106700. 0.001 0.0 0.0  FN, CKSI, CETA, CPHI\n   0.33 0.33  FSTAT, FKIN\n   0.0 0.5 10000.  CHI, DQ, VELOC\n   0.28 0.28 82000. 82000.  POISS, GG\n   {layer}  GG3, LAYTHK, TAU_C0, K_TAU\n   -2  IPOTCN\n   48 44 0.0008 0.5 1.1  MX, MY, A1, AOB, SCALE\n 0 MODULE\n"
        )
    };
    let import = |tang: &str, layer: &str| import_text("layer.inp", "layer", &deck(tang, layer)).unwrap();
    // Elastic-perfectly plastic (K_TAU = 0) imports as the layer's yield limit; a layer that
    // hardens (K_TAU != 0) imports in steady rolling (T = 3) and is refused in transient rolling.
    let plastic = import("3", "8200. 1.25 200. 0.");
    assert!(plastic.statuses[0].supported(), "{:?}", plastic.statuses[0]);
    assert!(plastic.scenes[0].files[0].1.contains("layer_yield_mpa = 200.0"), "{}", plastic.scenes[0].files[0].1);
    let hardening = import("3", "8200. 1.25 200. 435.");
    assert!(hardening.statuses[0].supported(), "{:?}", hardening.statuses[0]);
    let text = &hardening.scenes[0].files[0].1;
    assert!(text.contains("layer_hardening_mpa_per_mm = 435.0") && text.contains("kind = \"sweep\""), "{text}");
    // In transient rolling the layer imports (its previous displacement taken at the element's
    // own index, as CONTACT), hardening or not, on a layer or on the surface (LAYTHK = 0), the
    // limits moved with the material; at another CHI than 0 or 180 a moving limit is refused.
    for layer in ["8200. 1.25 200. 435.", "8200. 0. 200. 435.", "8200. 1.25 0. 0."] {
        let transient = import("2", layer);
        assert!(transient.statuses[0].supported(), "{layer}: {:?}", transient.statuses[0]);
    }
    let surface = import("2", "8200. 0. 200. 435.");
    let text = &surface.scenes[0].files[0].1;
    assert!(text.contains("layer_hardening_mpa_per_mm = 435.0") && text.contains("layer_thickness_mm = 0.0"), "{text}");
    let turned = import_text(
        "layer.inp",
        "layer",
        &deck("2", "8200. 1.25 200. 435.").replace("   0.0 0.5 10000.", "   30.0 0.5 10000."),
    )
    .unwrap();
    let why = &turned.statuses[0].refused;
    assert!(why.iter().any(|r| r.contains("hardens or softens in transient rolling at another CHI")), "{why:?}");
    let elastic = import("3", "8200. 1.25 0. 0.");
    assert!(elastic.statuses[0].supported(), "{:?}", elastic.statuses[0]);
    assert!(elastic.scenes[0].files[0].1.contains("layer_thickness_mm = 1.25"), "{}", elastic.scenes[0].files[0].1);
    let none = import("3", "8200. 1e-11 0. 0.");
    assert!(!none.scenes[0].files[0].1.contains("layer_g_mpa"), "{}", none.scenes[0].files[0].1);
}
