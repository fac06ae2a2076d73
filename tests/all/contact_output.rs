//! Issue 32 items 2 and 4: the reader of CONTACT's printed output (`creepbench import
//! contact-output`, `creepbench::comparison::references::contact_output`) on every `.ref_out` shipped in
//! reference/contact_public/ (CONTACT's public examples, verbatim): one entry per `Case n` line,
//! module-1 cases kept with their numbers and not read, spot values against the printed text with
//! this project's signs (forces on body 2), each value's printed resolution, and the same numbers
//! as `scripts/contact_to_csv.py`'s reader of printed totals on every file (needs python3).

use crate::common::{root, tempdir};
use creepbench::comparison::references::contact_output::printed::{half_unit, Printed};
use creepbench::comparison::references::contact_output::{
    self, CaseBody, CaseOutput, Friction, Frictional, Prescribed, Stepping, Tangential, Totals,
};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Every `.ref_out` of reference/contact_public/, sorted.
fn shipped() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "ref_out") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join("reference/contact_public"), &mut out);
    out.sort();
    out
}

fn rel(p: &Path) -> String {
    p.strip_prefix(root().join("reference/contact_public")).unwrap().display().to_string()
}

/// The `Case n` lines of a file, counted independently of the reader.
fn case_headers(p: &Path) -> usize {
    let text = std::fs::read_to_string(p).unwrap();
    text.lines()
        .filter(|l| {
            let mut w = l.split_whitespace();
            w.next() == Some("Case") && w.next().is_some_and(|n| n.trim_end_matches(',').parse::<u32>().is_ok())
        })
        .count()
}

/// Per file: (cases, with module-3 totals, module 1, nothing printed).
const COUNTS: [(&str, usize, usize, usize, usize); 35] = [
    ("examples/bentall.ref_out", 6, 5, 0, 1),
    ("examples/carter2d.ref_out", 1, 1, 0, 0),
    ("examples/catt_to_cart.ref_out", 171, 171, 0, 0),
    ("examples/cattaneo.ref_out", 2, 2, 0, 0),
    ("examples/conformal.ref_out", 5, 5, 0, 0),
    ("examples/ertz_temperature.ref_out", 4, 4, 0, 0),
    ("examples/fastsim.ref_out", 8, 8, 0, 0),
    ("examples/plastic_3bl.ref_out", 57, 57, 0, 0),
    ("examples/spence35.ref_out", 35, 35, 0, 0),
    ("examples/tractcurv.ref_out", 120, 120, 0, 0),
    ("examples/veldep_fric.ref_out", 53, 53, 0, 0),
    ("examples/visc_cylindr.ref_out", 6, 6, 0, 0),
    ("testbank/examples_plast/carter_plast.ref_out", 12, 12, 0, 0),
    ("testbank/examples_plast/catt2d_plast.ref_out", 50, 50, 0, 0),
    ("testbank/examples_plast/catt3d_plast.ref_out", 63, 63, 0, 0),
    ("testbank/examples_plast/plastic_one_shift.ref_out", 27, 27, 0, 0),
    ("testbank/examples_plast/tractcurve_plast.ref_out", 240, 240, 0, 0),
    ("testbank/examples_temp/conv_temp.ref_out", 5, 5, 0, 0),
    ("testbank/examples_temp/euro_tractcurv.ref_out", 120, 120, 0, 0),
    ("testbank/examples_temp/m1_tempdep.ref_out", 3, 0, 3, 0),
    ("testbank/examples_temp/m3_tempdep.ref_out", 3, 3, 0, 0),
    ("testbank/examples_trans/force_site_b.ref_out", 4, 0, 4, 0),
    ("testbank/examples_trans/iestim_site_b.ref_out", 21, 0, 21, 0),
    ("testbank/examples_trans/m1_steady_roll.ref_out", 1, 0, 1, 0),
    ("testbank/examples_trans/m1_trans_dqrel.ref_out", 3, 0, 3, 0),
    ("testbank/examples_trans/t1_force_cp.ref_out", 2, 0, 2, 0),
    ("testbank/examples_trans/t1_merge_cp.ref_out", 2, 0, 2, 0),
    ("testbank/examples_trans/t1_npotmax.ref_out", 2, 0, 2, 0),
    ("testbank/examples_trans/t1_split_cp.ref_out", 2, 0, 2, 0),
    ("testbank/examples_trans/t1_zws.ref_out", 5, 0, 5, 0),
    ("testbank/examples_trans/t3_t1_conformal.ref_out", 16, 0, 16, 0),
    ("testbank/examples_trans/t3_t1_force.ref_out", 2, 0, 2, 0),
    ("testbank/examples_trans/t3_t2_conformal.ref_out", 6, 0, 6, 0),
    ("testbank/examples_trans/t3_t2_force.ref_out", 6, 0, 6, 0),
    ("testbank/testbank.ref_out", 39, 20, 19, 0),
];

fn read(rel_path: &str) -> Vec<CaseOutput> {
    contact_output::read(&root().join("reference/contact_public").join(rel_path)).unwrap()
}

fn totals(cases: &[CaseOutput], case: u32) -> &Totals {
    match &cases.iter().find(|c| c.case == case).unwrap_or_else(|| panic!("no case {case}")).body {
        CaseBody::Totals(t) => t,
        other => panic!("case {case}: {other:?}"),
    }
}

/// `p` is the printed `text`: the value (signs converted by the caller) and half a unit of its
/// last digit.
fn is(p: Printed, text: &str) {
    let want = Printed::parse(text).unwrap();
    assert_eq!(p, want, "{p:?} is not {text}");
}

#[test]
fn every_shipped_ref_out_one_entry_per_case_line_in_well_under_a_second() {
    let files = shipped();
    let names: Vec<String> = files.iter().map(|p| rel(p)).collect();
    assert_eq!(names, COUNTS.map(|c| c.0), "the .ref_out files of reference/contact_public");
    let started = std::time::Instant::now();
    let all: Vec<Vec<CaseOutput>> = files.iter().map(|p| contact_output::read(p).unwrap()).collect();
    let elapsed = started.elapsed();
    let bytes: u64 = files.iter().map(|p| std::fs::metadata(p).unwrap().len()).sum();
    eprintln!("parsed {} files, {} bytes, in {:.1} ms", files.len(), bytes, elapsed.as_secs_f64() * 1e3);
    assert!(elapsed.as_secs_f64() < 0.5, "parsing every shipped .ref_out took {elapsed:?}");
    for ((p, cases), (name, n, with_totals, module1, nothing)) in files.iter().zip(&all).zip(COUNTS) {
        assert_eq!(cases.len(), case_headers(p), "{name}: one entry per `Case n` line");
        let count = |f: fn(&CaseBody) -> bool| cases.iter().filter(|c| f(&c.body)).count();
        let got = (
            cases.len(),
            count(|b| matches!(b, CaseBody::Totals(_))),
            count(|b| matches!(b, CaseBody::Module1)),
            count(|b| matches!(b, CaseBody::Nothing)),
        );
        assert_eq!(got, (n, with_totals, module1, nothing), "{name}: cases, totals, module 1, nothing");
        // Case numbers as printed, in order (module-1 cases keep theirs).
        let numbers: Vec<u32> = cases.iter().map(|c| c.case).collect();
        assert_eq!(numbers, (1..=n as u32).collect::<Vec<_>>(), "{name}");
    }
}

#[test]
fn cattaneo_as_printed_with_the_signs_of_body_2() {
    let c = read("examples/cattaneo.ref_out");
    // Case 2: shift transient (T = 1) with FX/FSTAT/FN = -0.8750 prescribed (CONTACT's body 1):
    // 0.8750 on body 2; the shift solved for, SHIFT X = 8.155E-03, is printed with the totals.
    let t = totals(&c, 2);
    is(t.fn_n, "9.195");
    is(t.fx_n, "3.218");
    is(t.fy_n, "-0.000");
    is(t.mz_nmm, "-0.000");
    is(t.fx_over_fstat_fn().unwrap(), "0.8750");
    assert_eq!(t.fx_over_fstat_fn().unwrap().half_unit, 5e-5);
    assert!(matches!(t.x, Tangential::SolvedShiftMm(v) if v == Printed::parse("8.155E-03").unwrap()));
    assert!(matches!(t.y, Tangential::SolvedShiftMm(v) if v.value == 0.0));
    is(t.cx().unwrap(), "8.155E-03");
    let k = t.kinematics.unwrap();
    assert!(matches!(k.stepping, Stepping::Shift { dt_s } if dt_s.value == 1.0));
    assert!(matches!(k.x, Prescribed::ForceOverFstatFn(f) if f == Printed::parse("0.8750").unwrap()));
    is(t.approach_mm, "1.998E-02");
    assert!((t.approach_mm.half_unit - 5e-6).abs() < 1e-20);
    is(t.pn_max_mpa, "4.393");
    is(t.elastic_energy_nmm, "8.525E-05");
    assert_eq!(t.frictional, Frictional::WorkNmm(Printed::parse("-2.750E-06").unwrap()));
    let four_tenths = Printed::parse("0.4000").unwrap();
    assert_eq!(t.friction, Friction::Coulomb { fstat: four_tenths, fkin: four_tenths });
    let s = t.statistics.unwrap();
    assert_eq!((s.npot, s.ncon, s.nadh, s.nslip, s.inorm, s.itang), (361, 177, 45, 132, 1, 1));
    // Case 1: the normal problem alone, creepages prescribed (zero).
    let t = totals(&c, 1);
    assert!(matches!(t.x, Tangential::ForceOverFstatFn(v) if v.value == 0.0));
    assert!(matches!(t.kinematics.unwrap().x, Prescribed::Creepage(v) if v.value == 0.0));
    assert_eq!(t.statistics.unwrap().nadh, 177);
}

#[test]
fn rolling_cases_creepages_and_forces_as_printed() {
    // carter2d: CKSI = -2.400E-04 prescribed, FX = 6955. on body 1.
    let c = read("examples/carter2d.ref_out");
    let t = totals(&c, 1);
    let k = t.kinematics.unwrap();
    assert!(matches!(k.stepping, Stepping::Rolling { chi_deg, dq_mm } if chi_deg.value == 0.0 && dq_mm.value == 0.04));
    is(k.veloc_mm_s, "3.000E+04");
    is(t.cx().unwrap(), "-2.400E-04");
    is(t.fn_n, "3.578E+04");
    is(t.fx_n, "-6955.");
    assert_eq!(t.fx_n.half_unit, 0.5);
    assert_eq!(t.frictional, Frictional::PowerNmmPerS(Printed::parse("-47.62").unwrap()));
    let s = t.statistics.unwrap();
    assert_eq!((s.npot, s.ncon, s.nadh, s.nslip), (55, 50, 30, 20));
    // fastsim case 7: CETA and CPHI, FY = -1.585E+04, MZ = -4.757E+04, FY/FSTAT/FN = -0.6442.
    let c = read("examples/fastsim.ref_out");
    let t = totals(&c, 7);
    is(t.cy().unwrap(), "-6.250E-04");
    is(t.kinematics.unwrap().cphi_per_mm, "6.250E-04");
    is(t.fy_n, "1.585E+04");
    is(t.mz_nmm, "4.757E+04");
    is(t.fy_over_fstat_fn().unwrap(), "0.6442");
    assert_eq!(t.statistics.unwrap().nslip, 15562);
    // catt_to_cart case 10: FX prescribed, only the totals printed (OUTPUT 1): the creepage
    // solved for is CREEP X = 2.551E-03; no kinematic block, no statistics.
    let c = read("examples/catt_to_cart.ref_out");
    let t = totals(&c, 10);
    assert!(t.kinematics.is_none() && t.statistics.is_none());
    assert_eq!(t.friction, Friction::NotPrinted);
    assert!(matches!(t.x, Tangential::SolvedCreepage(v) if v == Printed::parse("2.551E-03").unwrap()));
    is(t.cx().unwrap(), "2.551E-03");
    is(t.fn_n, "0.4705");
    is(t.fx_n, "0.1240");
    assert_eq!(t.frictional, Frictional::PowerNmmPerS(Printed::parse("-2.385E-04").unwrap()));
}

#[test]
fn testbank_module_1_cases_keep_their_numbers() {
    let c = read("testbank/testbank.ref_out");
    assert!(matches!(c[17].body, CaseBody::Module1) && c[17].case == 18);
    assert!(matches!(c[38].body, CaseBody::Module1) && c[38].case == 39);
    // Case 10: shift with the force prescribed, FN 1722. (half a unit 0.5), SHIFT X = 3.042E-03.
    let t = totals(&c, 10);
    is(t.fn_n, "1722.");
    is(t.fx_n, "452.0");
    is(t.cx().unwrap(), "3.042E-03");
    // Case 8: friction per row (IY FSTAT FKIN 0.2 … 0.59), so FX/FN instead of FX/FSTAT/FN,
    // no one mu in the CSV (not the 0.4013 of the case before).
    let t = totals(&c, 8);
    assert_eq!(t.friction, Friction::Other);
    assert!(matches!(t.x, Tangential::ForceOverFn(v) if v == Printed::parse("-0.2563").unwrap()));
    let (csv, _) = contact_output::reference_csv::write(&c, Some("7-8".parse().unwrap()));
    let mu: Vec<&str> = csv.lines().skip(1).map(|l| l.split(',').nth(8).unwrap()).collect();
    assert_eq!(mu, ["0.4013", "NaN"]);
    // Case 25: the totals only, FN = 4.000E+05 (half a unit 50), APPROACH = 2.84688.
    let t = totals(&c, 25);
    assert_eq!(t.fn_n.half_unit, 50.0);
    is(t.approach_mm, "2.84688");
    assert_eq!(t.approach_mm.half_unit, 0.5e-5);
    assert!(matches!(c[24].body, CaseBody::Totals(_)) && c[24].line == 2664);
}

#[test]
fn half_a_unit_of_the_last_printed_digit() {
    assert_eq!(half_unit("0.8750"), Some(0.5 * 1e-4));
    assert_eq!(half_unit("1.998E-02"), Some(0.5 * 10f64.powi(-5)));
    assert_eq!(half_unit("1722."), Some(0.5));
    assert_eq!(half_unit("0.1000E-03"), Some(0.5 * 10f64.powi(-7)));
}

/// Runs `scripts/contact_to_csv.py`'s reader of printed totals (`out_cases`) on `files`: per
/// file, case → label → value.
fn python_out_cases(files: &[PathBuf]) -> Vec<BTreeMap<String, BTreeMap<String, f64>>> {
    let code = "import importlib.util, json, sys\n\
        spec = importlib.util.spec_from_file_location('contact_to_csv', sys.argv[1])\n\
        m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n\
        print(json.dumps([{str(k): v for k, v in m.out_cases(f).items()} for f in sys.argv[2:]]))\n";
    let script = root().join("scripts/contact_to_csv.py");
    let mut cmd = Command::new("python3");
    cmd.arg("-c").arg(code).arg(&script).args(files);
    let o = match cmd.output() {
        Ok(o) => o,
        Err(e) => panic!("python3 ({e}): this test compares with scripts/contact_to_csv.py and needs python3"),
    };
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn the_script_reads_the_same_numbers() {
    let files = shipped();
    let py = python_out_cases(&files);
    let mut compared = 0;
    for (p, py) in files.iter().zip(&py) {
        let cases = contact_output::read(p).unwrap();
        assert_eq!(py.len(), cases.len(), "{}: cases", rel(p));
        // The CSV's mu (FSTAT carried from case to case) is the script's FSTAT, NaN where it has none.
        let (csv, _) = contact_output::reference_csv::write(&cases, None);
        for line in csv.lines().skip(1) {
            let cells: Vec<&str> = line.split(',').collect();
            let mu: f64 = cells[8].parse().unwrap();
            let theirs = py[cells[0]].get("FSTAT");
            assert_eq!(theirs.copied().unwrap_or(f64::NAN).to_bits(), mu.to_bits(), "{} case {} mu", rel(p), cells[0]);
            compared += 1;
        }
        for c in &cases {
            let CaseBody::Totals(t) = &c.body else { continue };
            let v = &py[&c.case.to_string()];
            // CONTACT's signs: the reader's are body 2's.
            let mut want =
                vec![("FN", t.fn_n.value), ("FX", -t.fx_n.value), ("FY", -t.fy_n.value), ("MZ", -t.mz_nmm.value)];
            if let Some(s) = t.statistics {
                want.extend([("NADH", s.nadh as f64), ("NSLIP", s.nslip as f64)]);
            }
            if let Some(k) = t.kinematics {
                if let Prescribed::Creepage(x) = k.x {
                    want.push(("CKSI", x.value));
                }
                if let Prescribed::Creepage(y) = k.y {
                    want.push(("CETA", y.value));
                }
                want.push(("CPHI", k.cphi_per_mm.value));
            }
            if let Some(f) = t.friction.fstat() {
                want.push(("FSTAT", f.value));
            }
            for (label, ours) in want {
                let theirs =
                    v.get(label).unwrap_or_else(|| panic!("{} case {}: the script has no {label}", rel(p), c.case));
                assert_eq!(*theirs, ours, "{} case {} {label}", rel(p), c.case);
                compared += 1;
            }
            // Where this reader finds no statistics or creepages, the script finds none either.
            for label in ["NADH", "NSLIP"].iter().filter(|_| t.statistics.is_none()) {
                assert!(!v.contains_key(*label), "{} case {}: {label} only in the script", rel(p), c.case);
            }
        }
    }
    // 4939 before testbank/examples_plast (issue 46 item 2: 392 cases, 3643 numbers).
    assert_eq!(compared, 8582, "numbers compared");
}

fn creepbench(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(root()).args(args).output().expect("runs")
}

#[test]
fn import_contact_output_writes_a_reference_csv_the_harness_reads() {
    let dir = tempdir("import_contact_output");
    let out = dir.join("cattaneo.csv");
    let file = "reference/contact_public/examples/cattaneo.ref_out";
    let o = creepbench(&["import", "contact-output", file, "--out", out.to_str().unwrap(), "--cases", "2-2"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stderr).contains("2 case(s): 1 row(s) written"));
    let mut rdr = csv::Reader::from_path(&out).unwrap();
    let head: Vec<String> = rdr.headers().unwrap().iter().map(String::from).collect();
    let rows: Vec<csv::StringRecord> = rdr.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), 1);
    let get = |name: &str| -> f64 {
        let k = head.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
        rows[0][k].parse().unwrap()
    };
    assert_eq!((get("case"), get("step"), get("cx"), get("fn_n"), get("mu")), (2.0, 2.0, 8.155e-3, 9.195, 0.4));
    assert_eq!((get("fx_n"), get("fx_over_fstat_fn"), get("fx_over_fstat_fn_rounding")), (3.218, 0.875, 5e-5));
    assert_eq!(get("fx_over_fn"), 3.218 / 9.195);
    // Both roundings carried: (5e-4 + 0.35 · 5e-4) / 9.195.
    assert!((get("fx_over_fn_rounding") - (5e-4 + 3.218 / 9.195 * 5e-4) / 9.195).abs() < 1e-18);
    assert_eq!((get("n_adhesion"), get("n_slip"), get("approach_mm")), (45.0, 132.0, 1.998e-2));
    assert!(get("fric_power_nmm_per_s").is_nan() && get("fric_work_nmm") == -2.75e-6);
    // The harness's reader of reference histories takes it (its columns and the extras).
    let extra = ["approach_mm", "pn_max_mpa", "fx_over_fn_rounding"];
    let h = creepbench::comparison::references::contact::read_history(&out, 0, &extra).unwrap();
    assert_eq!(h.rows.len(), 1);
    assert_eq!((h.rows[0].sample.step, h.rows[0].fx_over_fn, h.rows[0].extra[1]), (2, 3.218 / 9.195, 132.0));
}

#[test]
fn import_contact_output_refuses_with_file_line_and_what_was_expected() {
    let dir = tempdir("import_contact_output_bad");
    // A values line cut short: exit 2, the file, the line and the labels named, nothing written.
    let text = std::fs::read_to_string(root().join("reference/contact_public/examples/cattaneo.ref_out")).unwrap();
    let cut = text.replacen("         9.195       0.000       0.000       0.000   7.350E-05", "         9.195", 1);
    assert_ne!(cut, text);
    let bad = dir.join("cut.out");
    std::fs::write(&bad, cut).unwrap();
    let out = dir.join("cut.csv");
    let o = creepbench(&["import", "contact-output", bad.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cut.out") && err.contains("line 42") && err.contains("FN FX FY MZ"), "{err}");
    assert!(!out.exists());
    // A file of module-1 cases only: nothing to write.
    let m1 = "reference/contact_public/testbank/examples_trans/t1_zws.ref_out";
    let o = creepbench(&["import", "contact-output", m1]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("t1_zws.ref_out") && err.contains("5 module-1 case(s)"), "{err}");
    // --cases that are no range, or hold no module-3 case.
    for cases in ["3-1", "x", "18-19"] {
        let o = creepbench(&[
            "import",
            "contact-output",
            "reference/contact_public/testbank/testbank.ref_out",
            "--cases",
            cases,
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{cases}: {err}");
        assert!(err.contains("--cases"), "{err}");
        assert!(o.stdout.is_empty());
    }
    // Not CONTACT's output at all.
    let o = creepbench(&["import", "contact-output", "reference/contact_public/examples/cattaneo.inp"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no line `Case n`"));
}
