//! Falling friction on held-out cases: reference/contact_friction_hidden (19 CONTACT cases whose
//! laws, memories, speeds, loadings, ellipses and grids differ from every case of
//! contact_friction and contact_friction_variants; its README gives the runs and the findings).
//! The exact solver with its default settings on scenes/friction_hidden against CONTACT's tightly
//! converged values (every case, fx/fn and fy/fn within 1e-5, the same adhesion count in every
//! row, every step converged) and its published values (fx/fn, fy/fn, mz/(FN a) within 2e-4 on
//! the 17 cases whose `gate` is `yes`). On the two `gate = tight` cases the published values are
//! further than that from CONTACT's own tight ones; there the solver's miss must be CONTACT's own
//! iteration error, and with CONTACT's 1e-3 stop the solver gives the published values.

use crate::common;
use common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

const FOLDER: &str = "contact_friction_hidden";
const TIGHT_TOL: f64 = 1e-5;
const PUBLISHED_TOL: f64 = 2e-4;

/// (name, gate, a_mm) of every case of cases.csv.
fn cases() -> Vec<(String, String, f64)> {
    let path = root().join("reference").join(FOLDER).join("cases.csv");
    let mut rdr = csv::Reader::from_path(&path).unwrap();
    let head = rdr.headers().unwrap().clone();
    let col = |name: &str| head.iter().position(|h| h == name).expect(name);
    let (name, gate, a) = (col("name"), col("gate"), col("a_mm"));
    rdr.records()
        .map(|r| r.unwrap())
        .map(|r| (r[name].to_string(), r[gate].to_string(), r[a].parse().unwrap()))
        .collect()
}

/// The scene scenes/friction_hidden/<case>.toml, with `solver_lines` added as its
/// `[contact_solver]` table when given, run by the exact solver.
fn run_case(case: &str, solver_lines: Option<&str>) -> History {
    let path = root().join(format!("scenes/friction_hidden/{case}.toml"));
    let mut text = std::fs::read_to_string(&path).unwrap();
    if let Some(lines) = solver_lines {
        let with = text.replace("[contact]\n", &format!("[contact_solver]\n{lines}\n\n[contact]\n"));
        assert_ne!(with, text);
        text = with;
    }
    let scene = Scene::from_toml(&text, path.parent().unwrap()).unwrap();
    run(&creepbench::pipeline::resolve(&scene).unwrap(), "contact")
}

fn column(h: &History, name: &str) -> Vec<f64> {
    h.column(name).unwrap_or_else(|| panic!("column {name}"))
}

/// Row by row: |ours − theirs| and the largest with its row.
fn diffs(ours: &[f64], theirs: &[f64]) -> Vec<f64> {
    assert_eq!(ours.len(), theirs.len());
    ours.iter().zip(theirs).map(|(a, b)| (a - b).abs()).collect()
}

fn worst(d: &[f64]) -> (f64, usize) {
    d.iter().enumerate().fold((0.0, 0), |m, (k, &v)| if v > m.0 { (v, k) } else { m })
}

/// Every case against CONTACT's tight and published values (the module's doc); prints the table
/// of the largest differences per case.
#[test]
fn exact_solver_matches_contact_on_held_out_falling_friction_cases() {
    let all = cases();
    assert_eq!(all.len(), 19);
    let mut gates = (0, 0);
    println!("case | tight fx/fn, fy/fn | published fx/fn, fy/fn, mz/(FN a) | gate");
    for (case, gate, a_mm) in &all {
        let h = run_case(case, None);
        let reference = |c: &str| reference_in(FOLDER, case, c);
        assert_eq!(column(&h, "step"), reference("step"), "{case}: steps");
        let (fx, fy) = (column(&h, "fx_over_fn"), column(&h, "fy_over_fn"));
        // The tightly converged fixed point: every case (gate yes and tight).
        let tight = [diffs(&fx, &reference("fx_over_fn_tight")), diffs(&fy, &reference("fy_over_fn_tight"))];
        for (d, what) in tight.iter().zip(["fx/fn", "fy/fn"]) {
            let (w, k) = worst(d);
            assert!(w <= TIGHT_TOL, "{case} row {k}: {what} {w:.3e} off the tight value");
        }
        assert_eq!(column(&h, "n_adhesion"), reference("n_adhesion_tight"), "{case}: adhesion counts");
        assert!(column(&h, "veldep_converged").iter().all(|&c| c == 1.0), "{case}: a step not converged");
        assert!(column(&h, "termination").iter().all(|&t| t == 0.0), "{case}: a step not terminated normally");
        // The published values.
        let fn_n = reference("fn_n");
        let scale = |v: Vec<f64>| -> Vec<f64> { v.iter().zip(&fn_n).map(|(m, f)| m / (f * a_mm)).collect() };
        let published = [
            diffs(&fx, &reference("fx_over_fn")),
            diffs(&fy, &reference("fy_over_fn")),
            diffs(&scale(column(&h, "mz_nmm")), &scale(reference("mz_nmm"))),
        ];
        let w = |k: usize, d: &[Vec<f64>]| worst(&d[k]).0;
        println!(
            "{case} | {:.2e}, {:.2e} | {:.2e}, {:.2e}, {:.2e} | {gate}",
            w(0, &tight),
            w(1, &tight),
            w(0, &published),
            w(1, &published),
            w(2, &published)
        );
        match gate.as_str() {
            "yes" => {
                gates.0 += 1;
                for (d, what) in published.iter().zip(["fx/fn", "fy/fn", "mz/(FN a)"]) {
                    let (w, k) = worst(d);
                    assert!(w <= PUBLISHED_TOL, "{case} row {k}: {what} {w:.3e} off the published value");
                }
            }
            "tight" => {
                gates.1 += 1;
                // The miss is CONTACT's own: in every row the solver is no further from the
                // published values than CONTACT's tight run is (to 1e-6), and it does miss.
                let contact_own = [
                    diffs(&reference("fx_over_fn"), &reference("fx_over_fn_tight")),
                    diffs(&reference("fy_over_fn"), &reference("fy_over_fn_tight")),
                ];
                for k in 0..2 {
                    for (row, (ours, theirs)) in published[k].iter().zip(&contact_own[k]).enumerate() {
                        assert!(ours <= &(theirs + 1e-6), "{case} row {row}: {ours:.3e} vs CONTACT's own {theirs:.3e}");
                    }
                }
                assert!(w(0, &published) > PUBLISHED_TOL, "{case}: within the published tolerance: gate yes?");
            }
            other => panic!("{case}: gate {other}"),
        }
    }
    assert_eq!(gates, (17, 2));
}

/// The two `gate = tight` cases with CONTACT's own stop (`veldep_solves = "tight"`: its path,
/// `veldep_tolerance = 0.001`: its 1e-3 criterion; what `creepbench import contact` writes): the
/// solver then gives CONTACT's published values, 1.8e-3 (h16) and 2.4e-4 (h19) off the tight ones,
/// within 1e-6 in fx/fn and fy/fn (measured 6.5e-8 and 7.1e-8).
#[test]
fn contacts_own_stop_gives_the_published_values_it_leaves_off_the_tight_ones() {
    let lines = "veldep_solves = \"tight\"\nveldep_tolerance = 0.001";
    for case in ["h16_exp_fine_grid_step_mem", "h19_exp_fine_grid_step_mem_dc008"] {
        let h = run_case(case, Some(lines));
        for (ours, theirs, tight) in
            [("fx_over_fn", "fx_over_fn", "fx_over_fn_tight"), ("fy_over_fn", "fy_over_fn", "fy_over_fn_tight")]
        {
            let published = reference_in(FOLDER, case, theirs);
            let (d, k) = worst(&diffs(&column(&h, ours), &published));
            let (own, _) = worst(&diffs(&published, &reference_in(FOLDER, case, tight)));
            println!("{case} {ours}: CONTACT's stop {d:.2e} off the published values (row {k}); published vs tight {own:.2e}");
            assert!(d < 1e-6, "{case} row {k}: {ours} {d:.3e}");
        }
    }
}

/// h16 is a period-2 oscillation in time, not a step with several solutions: CONTACT's tight
/// values alternate over the last 20 steps (every difference of successive steps changes sign
/// and exceeds 0.01 in size) and the tight runs from INISLP 0, +1 and −1 agree (`spread_tight`
/// of cases.csv at most 1e-7, the sums' last digit); h19, the same with twice the memory, settles
/// (its last 10 steps within 1e-5 of each other).
#[test]
fn h16_oscillates_with_period_two_and_h19_settles() {
    let tight = reference_in(FOLDER, "h16_exp_fine_grid_step_mem", "fx_over_fn_tight");
    let steps: Vec<f64> = tight[tight.len() - 21..].windows(2).map(|w| w[1] - w[0]).collect();
    assert!(steps.iter().all(|d| d.abs() > 0.01), "{steps:?}");
    assert!(steps.windows(2).all(|w| w[0] * w[1] < 0.0), "{steps:?}");
    let settled = reference_in(FOLDER, "h19_exp_fine_grid_step_mem_dc008", "fx_over_fn_tight");
    let last = &settled[settled.len() - 10..];
    let (lo, hi) = last.iter().fold((f64::MAX, f64::MIN), |(l, h), &v| (l.min(v), h.max(v)));
    assert!(hi - lo < 1e-5, "{last:?}");
    let mut rdr = csv::Reader::from_path(root().join("reference").join(FOLDER).join("cases.csv")).unwrap();
    let head = rdr.headers().unwrap().clone();
    let (name, spread) =
        (head.iter().position(|h| h == "name").unwrap(), head.iter().position(|h| h == "spread_tight").unwrap());
    for r in rdr.records().map(Result::unwrap) {
        let s: f64 = r[spread].parse().unwrap();
        assert!(s <= 1.01e-7, "{}: spread_tight {s}", &r[name]);
    }
}
