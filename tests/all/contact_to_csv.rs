//! Issue 15, the round trip's last leg: `scripts/contact_to_csv.py` turns CONTACT's results of a
//! run into a reference CSV (reference/contact_envelope's format), with the reference READMEs'
//! sign flips (fx, fy, px, py; mz = −MZ).
//!
//! - From CONTACT's printed totals: its own example output (tests/fixtures/contact_output/, see
//!   the README there) — every total equals the number printed, sign-flipped, and the traction
//!   coefficients agree with the printed FX/FSTAT/FN, FY/FSTAT/FN to their printed precision.
//! - From per-element `.mat` files: CONTACT's example outputs ship none, so the test writes them
//!   in CONTACT's layout (writmt, src/m_soutpt.f90) from CONTACT's own per-element values in
//!   reference/ (6 significant digits, as the .mat files they were converted from) for the input
//!   `creepbench export contact` writes; the integrated totals equal those the reference data
//!   were integrated to from the original .mat files.
//!
//! Needs python3 (CI has it): where it is missing every test here fails, saying so.

use crate::common;
use common::{root, suite_scene, tempdir};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs python3; a missing python3 fails the test (it would otherwise test nothing).
fn python(args: &[&str], cwd: &Path) -> Output {
    match Command::new("python3").args(args).current_dir(cwd).output() {
        Ok(o) => o,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            panic!("python3 not found: these tests run scripts/contact_to_csv.py and need python3 on PATH")
        }
        Err(e) => panic!("python3: {e}"),
    }
}

fn script() -> String {
    root().join("scripts/contact_to_csv.py").display().to_string()
}

/// A CSV as a header and rows of numbers (an empty cell, a value the script could not form, as NaN).
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut rdr = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let head = rdr.headers().unwrap().iter().map(String::from).collect();
    let cell = |v: &str| if v.is_empty() { f64::NAN } else { v.parse::<f64>().unwrap() };
    let rows = rdr.records().map(|r| r.unwrap().iter().map(cell).collect()).collect();
    (head, rows)
}

fn col(head: &[String], name: &str) -> usize {
    head.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name} in {head:?}"))
}

/// Half a unit in the 4th significant digit of a value CONTACT printed.
fn half_unit(printed: f64) -> f64 {
    0.5 * 10f64.powf(printed.abs().log10().floor() - 3.0)
}

/// One case as CONTACT printed it: CKSI, CETA, CPHI, FSTAT; FN, FX, FY, MZ; FX/FSTAT/FN,
/// FY/FSTAT/FN; NADH, NSLIP.
type Printed = ([f64; 4], [f64; 4], [f64; 2], [f64; 2]);

/// CONTACT's example `conformal` (5 steady cases, all of fx, fy, mz non-zero), as printed.
const CONFORMAL: [Printed; 5] = [
    ([-4.000e-3, -9.900e-3, -1.537e-3, 0.3], [1.000e5, 9144.0, 2.592e4, 3.860e4], [0.3048, 0.8639], [0.0, 1027.0]),
    ([-4.000e-3, -9.900e-3, -1.537e-3, 0.3], [9.184e4, 8959.0, 2.417e4, 2.676e4], [0.3252, 0.8774], [0.0, 871.0]),
    ([-4.000e-3, -9.900e-3, -1.537e-3, 0.3], [9.932e4, 1.086e4, 2.578e4, 3.292e4], [0.3646, 0.8651], [0.0, 901.0]),
    ([0.0, 0.0, 0.0, 0.3], [9.184e4, 1.050e4, 2.251e4, 3.227e4], [0.3812, 0.8172], [0.0, 871.0]),
    ([0.0, 0.0, 0.0, 0.3], [9.983e4, 1.270e4, 2.383e4, 4.039e4], [0.4239, 0.7955], [0.0, 905.0]),
];

#[test]
fn printed_totals_of_contacts_own_output_with_the_sign_flips() {
    let dir = tempdir("contact_to_csv_out");
    let csv_path = dir.join("conformal.csv");
    let fixture = root().join("tests/fixtures/contact_output/conformal.ref_out");
    let o = python(&[&script(), "--out", fixture.to_str().unwrap(), "--csv", csv_path.to_str().unwrap()], &root());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (head, rows) = read_csv(&csv_path);
    assert_eq!(head.join(","), "step,t_s,cx,cy,cs,fn_n,mu,fx_n,fy_n,mz_nmm,fx_over_fn,fy_over_fn,n_adhesion,n_slip");
    assert_eq!(rows.len(), CONFORMAL.len());
    let c = |n: &str| col(&head, n);
    for (k, (row, (kin, tot, rel, counts))) in rows.iter().zip(CONFORMAL).enumerate() {
        let same = |got: f64, want: f64, what: &str| {
            assert!((got - want).abs() <= 1e-12 * want.abs(), "case {}: {what} {got} vs printed {want}", k + 1)
        };
        same(row[c("step")], (k + 1) as f64, "step (the case number)");
        for (name, want) in ["cx", "cy", "cs", "mu"].iter().zip(kin) {
            same(row[c(name)], want, name);
        }
        // The flips: fx = −FX, fy = −FY, mz = −MZ (forces on body 2); FN as printed.
        same(row[c("fn_n")], tot[0], "fn_n");
        same(row[c("fx_n")], -tot[1], "fx_n");
        same(row[c("fy_n")], -tot[2], "fy_n");
        same(row[c("mz_nmm")], -tot[3], "mz_nmm");
        same(row[c("n_adhesion")], counts[0], "n_adhesion");
        same(row[c("n_slip")], counts[1], "n_slip");
        // The coefficients against CONTACT's own printed ratios: |Δ| within the ratio's print
        // rounding (times μ) plus the rounding of the printed FX (or FY) and FN it is made of.
        for (name, total, printed) in [("fx_over_fn", tot[1], rel[0]), ("fy_over_fn", tot[2], rel[1])] {
            let ours = row[c(name)];
            let theirs = -printed * kin[3];
            let slack =
                kin[3] * half_unit(printed) + ours.abs() * (half_unit(total) / total + half_unit(tot[0]) / tot[0]);
            assert!((ours - theirs).abs() <= slack, "case {}: {name} {ours} vs −{printed}·μ = {theirs}", k + 1);
        }
    }
}

/// CONTACT's element state letters in reference/ as its .mat codes (m_gridfunc.f90).
fn igs(state: &str) -> u8 {
    match state {
        "E" => 0,
        "A" => 1,
        "S" => 2,
        other => panic!("state {other}"),
    }
}

/// Write `path` as CONTACT's writmt writes a module-3 .mat file (MATFIL = 2: every element of
/// the potential contact; g14.6 numbers): meta, grid, material and friction lines under their
/// `%` headers, then one line per element `I IGS H MU PN PX PY UN UX UY SREL` with CONTACT's
/// signs (tractions on body 1: the reference files' flipped px, py flipped back).
fn write_mat(path: &Path, grid: (usize, usize, f64, f64, f64, f64), mu: f64, cells: &[Vec<String>]) {
    let (mx, my, xl, yl, dx, dy) = grid;
    let g = |v: f64| format!("{v:>14.5e}");
    let mut s = String::new();
    s.push_str("%  TIM           S_WS(FC)      TH_WS(FC)     Y_R(TR)       Z_R(TR)       ROLL_R(TR)    RNOM_ROL        -           -           -           FMT\n");
    s.push_str(&format!(
        "{}{}{}{}{}{}{}     0             0             0          2410\n",
        g(0.0),
        g(0.0),
        g(0.0),
        g(0.0),
        g(0.0),
        g(0.0),
        g(0.0)
    ));
    s.push_str("%   MX    MY     XL            YL            DX            DY            CHI           DQ            C1            D             YNOM_WHL\n");
    s.push_str(&format!(
        "{mx:>7} {my:>4}  {}{}{}{}{}{}     0             2         {}\n",
        g(xl),
        g(yl),
        g(dx),
        g(dy),
        g(0.0),
        g(dx),
        g(0.0)
    ));
    s.push_str("%    T    M      GG1           GG2           POISS1        POISS2\n");
    s.push_str(&format!("      2    0  {}{}{}{}\n", g(82000.0), g(82000.0), g(0.28), g(0.28)));
    s.push_str("%    L    H      VELOC         FSTAT         FKIN\n");
    s.push_str(&format!("      0    0  {}{}{}\n", g(1000.0), g(mu), g(mu)));
    s.push_str("%    I    IGS    H             MU            PN            PX            PY            UN            UX            UY            SREL\n");
    // Field rows: step,ix,iy,x_mm,y_mm,pn_mpa,px_mpa,py_mpa,state (px, py flipped in reference/).
    for c in cells {
        let (ix, iy): (usize, usize) = (c[1].parse().unwrap(), c[2].parse().unwrap());
        let v = |i: usize| c[i].parse::<f64>().unwrap();
        s.push_str(&format!(
            "{:>7} {:>4}  {}{}{}{}{}{}{}{}{}\n",
            ix + mx * (iy - 1),
            igs(&c[8]),
            g(0.0),
            g(mu),
            g(v(5)),
            g(-v(6)),
            g(-v(7)),
            g(0.0),
            g(0.0),
            g(0.0),
            g(0.0)
        ));
    }
    assert!(cells.len() == mx * my, "{}: {} elements", path.display(), cells.len());
    std::fs::write(path, s).unwrap();
}

/// The field file's rows by step.
fn field_by_step(path: &Path) -> std::collections::BTreeMap<usize, Vec<Vec<String>>> {
    let mut rdr = csv::Reader::from_path(path).unwrap();
    let mut out: std::collections::BTreeMap<usize, Vec<Vec<String>>> = Default::default();
    for r in rdr.records() {
        let r: Vec<String> = r.unwrap().iter().map(String::from).collect();
        out.entry(r[0].parse().unwrap()).or_default().push(r);
    }
    out
}

/// `mat_totals` of the script for each .mat file: `[totals, error bounds]` per file.
fn mat_totals(files: &[String], dir: &Path) -> Vec<serde_json::Value> {
    let code = "import sys, json; sys.path.insert(0, sys.argv[1]); import contact_to_csv as c; \
                print(json.dumps([c.mat_totals(p) for p in sys.argv[2:]]))";
    let scripts = root().join("scripts").display().to_string();
    let mut args = vec!["-c", code, &scripts];
    args.extend(files.iter().map(String::as_str));
    let o = python(&args, dir);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

/// The default contact's grid (a 8.56, b 4.08 mm, 22 × 22, SCALE 1) as a .mat prints it.
fn default_grid() -> (usize, usize, f64, f64, f64, f64) {
    (22, 22, -8.56, -4.08, 2.0 * 8.56 / 22.0, 2.0 * 4.08 / 22.0)
}

/// step_mu04: the exported input and one .mat file per case, made from CONTACT's per-element
/// values of every step; the script's history equals reference/contact/step_mu04.csv.
#[test]
fn per_element_files_of_an_exported_run_integrate_to_the_reference_history() {
    let dir = tempdir("contact_to_csv_mat");
    // step_mu04 is a point of the thesis's step_mu study: the study file exports every point.
    let study = suite_scene("thesis", "step_mu04").path;
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["export", "contact"])
        .arg(&study)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let printed = String::from_utf8_lossy(&o.stdout);
    assert!(printed.lines().count() > 1 && printed.contains("step_mu04.inp"), "{printed}");
    let inp: PathBuf = dir.join("step_mu04.inp");
    let fields = field_by_step(&root().join("reference/contact/step_mu04_field.csv"));
    assert_eq!(fields.len(), 44);
    for (step, cells) in &fields {
        write_mat(&dir.join(format!("step_mu04.{step:04}.mat")), default_grid(), 0.4, cells);
    }
    let out_csv = dir.join("step_mu04.csv");
    let o = python(&[&script(), inp.to_str().unwrap(), "--csv", out_csv.to_str().unwrap()], &root());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("44 cases: 44 from .mat files"), "{err}");
    let (head, ours) = read_csv(&out_csv);
    let (rhead, theirs) = read_csv(&root().join("reference/contact/step_mu04.csv"));
    assert_eq!(ours.len(), theirs.len());
    let mut worst = [0.0f64; 3];
    for (a, b) in ours.iter().zip(&theirs) {
        let (x, y) = (|n: &str| a[col(&head, n)], |n: &str| b[col(&rhead, n)]);
        for n in ["step", "cx", "cy", "n_adhesion", "n_slip"] {
            assert_eq!(x(n), y(n), "step {}: {n}", y("step"));
        }
        assert!((x("t_s") - y("t_s")).abs() <= 1e-9 * y("t_s"), "step {}: t_s", y("step"));
        assert_eq!((x("cs"), x("mu")), (0.0, 0.4));
        // The reference totals carry 7 significant digits; the elements 6 and the grid line's
        // dx, dy 6: relative 1e-6 of FN covers both roundings.
        for (i, n) in ["fn_n", "fx_n", "fy_n"].iter().enumerate() {
            let d = (x(n) - y(n)).abs() / y("fn_n");
            worst[i] = worst[i].max(d);
            assert!(d <= 1e-6, "step {}: {n} {} vs {}", y("step"), x(n), y(n));
        }
        assert!((x("fx_over_fn") - y("fx_over_fn")).abs() <= 1e-6, "step {}: fx_over_fn", y("step"));
    }
    println!("step_mu04, worst |Δ|/FN over 44 steps: fn {:.1e}, fx {:.1e}, fy {:.1e}", worst[0], worst[1], worst[2]);
}

/// The spin moment from the elements, mz = Σ (x py − y px) dx dy of the flipped tractions: equal
/// to reference/contact_envelope/step_combined.csv's mz_nmm (−MZ of CONTACT) at the two steps
/// whose fields the reference ships (cx, cy and spin together).
#[test]
fn the_moment_from_the_elements_is_the_references() {
    let dir = tempdir("contact_to_csv_mz");
    let fields = field_by_step(&root().join("reference/contact_envelope/step_combined_field.csv"));
    let (head, rows) = read_csv(&root().join("reference/contact_envelope/step_combined.csv"));
    let mut mats = Vec::new();
    for (step, cells) in &fields {
        let p = dir.join(format!("step_combined.{step:04}.mat"));
        write_mat(&p, default_grid(), 0.4, cells);
        mats.push((*step, p.display().to_string()));
    }
    assert_eq!(mats.iter().map(|m| m.0).collect::<Vec<_>>(), [23, 44]);
    let totals = mat_totals(&mats.iter().map(|m| m.1.clone()).collect::<Vec<_>>(), &dir);
    for ((step, _), t) in mats.iter().zip(&totals) {
        let r = rows.iter().find(|r| r[col(&head, "step")] == *step as f64).unwrap();
        let want = |n: &str| r[col(&head, n)];
        let got = |n: &str| t[0][n].as_f64().unwrap();
        // Moments are about 3e4 N mm: 1e-6 relative of FN·a (8.56e5 N mm) covers the roundings.
        let scale = want("fn_n") * 8.56;
        for n in ["mz_nmm", "fx_n", "fy_n"] {
            assert!((got(n) - want(n)).abs() <= 1e-6 * scale, "step {step}: {n} {} vs {}", got(n), want(n));
        }
        assert!(want("mz_nmm").abs() > 1e4, "a moment that tests the convention");
        assert_eq!((got("n_adhesion"), got("n_slip")), (want("n_adhesion"), want("n_slip")));
    }
}

/// The error bound of the integrated totals from the elements' 6 printed digits: in a case
/// without lateral creepage or spin (step_mu04, 44 steps) the true moment is zero by symmetry and
/// the integrated one is rounding noise, within the bound, which is itself about 1e-7 of FN·a;
/// for the combined case the bound is far below the moment. This is why a moment integrated
/// from a .mat file can differ from the MZ CONTACT printed from its unrounded tractions where
/// the moment is small (0.026 against −0.00015 N mm in the envelope's mu_ramp): the script
/// compares within this bound.
#[test]
fn the_digits_bound_the_integrated_totals() {
    let dir = tempdir("contact_to_csv_noise");
    let mut mats = Vec::new();
    for (case, folder) in [("step_mu04", "contact"), ("step_combined", "contact_envelope")] {
        for (step, cells) in field_by_step(&root().join(format!("reference/{folder}/{case}_field.csv"))) {
            let p = dir.join(format!("{case}.{step:04}.mat"));
            write_mat(&p, default_grid(), 0.4, &cells);
            mats.push((case, p.display().to_string()));
        }
    }
    let totals = mat_totals(&mats.iter().map(|m| m.1.clone()).collect::<Vec<_>>(), &dir);
    let fn_a = 1e5 * 8.56;
    let (mut longitudinal, mut worst, mut max_bound) = (0, 0.0f64, 0.0f64);
    for ((case, _), t) in mats.iter().zip(&totals) {
        let (mz, bound) = (t[0]["mz_nmm"].as_f64().unwrap(), t[1]["mz_nmm"].as_f64().unwrap());
        assert!(bound > 0.0 && bound < 1e-6 * fn_a, "{case}: bound {bound} N mm");
        if *case == "step_mu04" {
            assert!(mz.abs() <= bound, "{case}: mz {mz} beyond the digits' bound {bound}");
            longitudinal += 1;
            worst = worst.max(mz.abs());
            max_bound = max_bound.max(bound);
        } else {
            assert!(mz.abs() > 1e4 * bound, "{case}: mz {mz}, bound {bound}");
        }
    }
    assert_eq!(longitudinal, 44);
    assert!(worst > 0.0, "the rounding shows in the longitudinal moment");
    println!("step_mu04: |mz| from the elements at most {worst:.4} N mm, within the digits' bound (at most {max_bound:.4} N mm)");
}

/// Bad input is exit 2 with a message naming the problem, no CSV written.
#[test]
fn missing_results_are_an_input_error() {
    let dir = tempdir("contact_to_csv_bad");
    let inp = dir.join("x.inp");
    std::fs::write(&inp, "\n 3  MODULE      % step 1, t=0.001 s\n  2.0   0.001   0.0   0.0    FN, CKSI, CETA, CPHI\n  0.4   0.4   FSTAT, FKIN\n\n 0  MODULE\n").unwrap();
    let out_csv = dir.join("x.csv");
    let o = python(&[&script(), inp.to_str().unwrap(), "--csv", out_csv.to_str().unwrap()], &dir);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("case 1") && err.contains("x.0001.mat"), "{err}");
    assert!(!out_csv.exists());
    // An input creepbench did not write (no step comments) is refused with the way out.
    std::fs::write(&inp, "\n 3  MODULE\n  2.0   0.001   0.0   0.0    FN, CKSI, CETA, CPHI\n").unwrap();
    let o = python(&[&script(), inp.to_str().unwrap()], &dir);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--out only"));
}

/// A falling friction law (L = 2, 3, 4): the input gives FKIN, F1, SABSH1, F2, SABSH2 and no FSTAT
/// line; CONTACT's FSTAT is FKIN + F1 + F2. The variant x05 (rational law FKIN 0.24, F1 0.2, a
/// steady speed sweep 10 … 50 m/s with C = 2 and VELOC per case) from its shipped input and
/// CONTACT's output of that run (tests/fixtures/contact_output/, no .mat files: the printed
/// totals): every row equals reference/contact_friction_variants/x05_…csv, which was integrated
/// from the run's .mat files, to CONTACT's 4 printed digits; the speed, the slip-velocity
/// iterations and their convergence exactly.
#[test]
fn a_falling_friction_input_gives_the_variants_history() {
    let name = "x05_rat_speed_sweep_tinymem_spin";
    let dir = tempdir("contact_to_csv_falling");
    let inp = dir.join(format!("{name}.inp"));
    std::fs::copy(root().join(format!("reference/contact_friction_variants/{name}.inp")), &inp).unwrap();
    let out = root().join(format!("tests/fixtures/contact_output/{name}.out"));
    let out_csv = dir.join(format!("{name}.csv"));
    let o = python(
        &[&script(), inp.to_str().unwrap(), "--out", out.to_str().unwrap(), "--csv", out_csv.to_str().unwrap()],
        &root(),
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("5 cases: 0 from .mat files, 5 from the printed totals"), "{err}");
    let (head, ours) = read_csv(&out_csv);
    assert!(head.join(",").ends_with(",v_mm_s,mu_min,mu_max,s_max_mm_s,veldep_its,converged"), "{head:?}");
    let (rhead, theirs) = read_csv(&root().join(format!("reference/contact_friction_variants/{name}.csv")));
    assert_eq!(ours.len(), theirs.len());
    assert_eq!(ours.len(), 5);
    for (a, b) in ours.iter().zip(&theirs) {
        let (x, y) = (|n: &str| a[col(&head, n)], |n: &str| b[col(&rhead, n)]);
        let step = y("step");
        for n in ["step", "t_s", "cx", "cy", "cs", "v_mm_s", "n_adhesion", "n_slip", "veldep_its", "converged"] {
            assert_eq!(x(n), y(n), "step {step}: {n}");
        }
        // Over the elements of a .mat file: empty where the case came from the printed totals.
        for n in ["mu_min", "mu_max", "s_max_mm_s"] {
            assert!(x(n).is_nan() && y(n) > 0.0, "step {step}: {n}");
        }
        // FSTAT = FKIN + F1 + F2 = 0.24 + 0.2 + 0.
        assert!((x("mu") - 0.44).abs() < 1e-15, "step {step}: mu {}", x("mu"));
        for n in ["fn_n", "fx_n", "fy_n", "mz_nmm"] {
            assert!((x(n) - y(n)).abs() <= 1.01 * half_unit(x(n)), "step {step}: {n} printed {} vs {}", x(n), y(n));
        }
        let slack = x("fx_over_fn").abs() * (half_unit(x("fx_n")) / x("fx_n") + half_unit(x("fn_n")) / x("fn_n"));
        assert!((x("fx_over_fn") - y("fx_over_fn")).abs() <= 1.01 * slack, "step {step}: fx_over_fn");
    }
    // The speed changes from case to case (C = 2 with VELOC in every case).
    assert_eq!(ours.iter().map(|r| r[col(&head, "v_mm_s")]).collect::<Vec<_>>(), [1e4, 2e4, 3e4, 4e4, 5e4]);
}
