//! `creepbench simulate` end to end: the docs/scene-format.md contract, bad input, determinism.

use crate::common;
use common::*;
use std::path::Path;
use std::process::Command;

fn creepbench(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).args(args).output().expect("runs")
}

/// Every thesis scene (the scene files and every study's points) runs with uba and fastsim and
/// writes the files docs/scene-format.md promises; every CONTACT case of the thesis family is among them.
#[test]
fn simulate_every_thesis_scene() {
    let out = tempfile::tempdir().unwrap();
    let mut names = Vec::new();
    for entry in std::fs::read_dir(root().join("scenes/thesis")).unwrap() {
        let path = entry.unwrap().path();
        let o = creepbench(&[
            "simulate",
            path.to_str().unwrap(),
            "--solver",
            "uba",
            "--solver",
            "fastsim",
            "--out",
            out.path().to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}: {}", path.display(), String::from_utf8_lossy(&o.stderr));
        let dirs = String::from_utf8(o.stdout).unwrap();
        assert!(!dirs.trim().is_empty(), "{}: no result folder", path.display());
        for dir in dirs.lines().map(std::path::PathBuf::from) {
            let name = dir.file_name().unwrap().to_str().unwrap().to_string();
            let has_reference = root().join("reference/contact").join(format!("{name}.csv")).exists();
            for solver in ["uba", "fastsim"] {
                let text = std::fs::read_to_string(dir.join(format!("{solver}.csv"))).unwrap();
                assert!(text.starts_with("step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn"), "{name}/{solver}.csv header");
                if has_reference {
                    let rows = text.lines().count() - 1;
                    let reference_rows = reference(&name, "step").len();
                    assert_eq!(rows, reference_rows, "{name}/{solver}: {rows} rows, CONTACT has {reference_rows}");
                }
            }
            assert!(!dir.join("contact.csv").exists(), "contact was narrowed away");
            let json: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.join("scene.json")).unwrap()).unwrap();
            for key in ["a_mm", "b_mm", "p0_mpa", "c11", "c22", "c23", "dx_mm", "dy_mm", "dt_s", "n_steps"] {
                assert!(json[key].is_number(), "{name}: scene.json lacks {key}");
            }
            assert_eq!(json["solvers"], serde_json::json!(["uba", "fastsim"]));
            let metrics = std::fs::read_to_string(dir.join("metrics.csv")).unwrap();
            assert!(metrics.starts_with("solver,metric,value"));
            names.push(name);
        }
    }
    let mut cases = csv::Reader::from_path(root().join("reference/contact/cases.csv")).unwrap();
    let x_cases: Vec<String> =
        cases.records().map(Result::unwrap).filter(|r| &r[18] == "x").map(|r| r[0].to_string()).collect();
    assert_eq!(x_cases.len(), 41);
    for case in &x_cases {
        assert!(names.contains(case), "no thesis scene for CONTACT case {case}");
    }
}

/// The CSVs are byte-identical run to run.
#[test]
fn simulate_is_deterministic() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let scenes = tempfile::tempdir().unwrap();
    let scene = suite_scene_file("thesis", "sine_f30_mu10", scenes.path());
    for d in [&a, &b] {
        let o = creepbench(&[
            "simulate",
            scene.to_str().unwrap(),
            "--solver",
            "uba",
            "--solver",
            "fastsim",
            "--out",
            d.path().to_str().unwrap(),
        ]);
        assert!(o.status.success());
    }
    for f in ["uba.csv", "fastsim.csv", "metrics.csv", "scene.json"] {
        let read = |d: &Path| std::fs::read(d.join("sine_f30_mu10").join(f)).unwrap();
        assert_eq!(read(a.path()), read(b.path()), "{f} differs");
    }
}

fn base() -> String {
    scene_text("bad", "[\"uba\", \"fastsim\"]", 0.4, 22, "kind = \"step\"\nc = 0.005\nsteps = 10", "")
}

/// Bad input: exit 2, a message naming the field, the value and what is allowed, nothing written.
#[test]
fn bad_input_exits_2_and_writes_nothing() {
    let cases: Vec<(String, &str, &str)> = vec![
        (base().replace("fn_n = 100000.0", "fn_n = -5.0"), "contact.fn_n", "-5"),
        (base().replace("mu = 0.4", "mu = nan"), "contact.mu", "NaN"),
        (base().replace("mu = 0.4", "mu = inf"), "contact.mu", "inf"),
        (base().replace("[grid]", "[grid]\nmz = 3"), "grid.mz", "no such key"),
        (base().replace("mx = 22", "mx = \"22\""), "grid.mx", "whole number"),
        (base().replace("mx = 22", "mx = 0"), "grid.mx", "[1, 4096]"),
        (base().replace("mx = 22", "mx = 1024").replace("my = 22", "my = 1024"), "grid.my", "at most 524288 elements"),
        (base().replace("[\"uba\", \"fastsim\"]", "[\"uba\", \"brush\"]"), "solvers[1]", "\"brush\""),
        (base() + "[rolling]\ncourant = 80\n", "rolling.courant", "(0, 64]"),
        (
            base().replace("kind = \"step\"\nc = 0.005\nsteps = 10", "kind = \"table\"\nfile = \"missing.csv\""),
            "creepage.file",
            "missing.csv",
        ),
        (base().replace("kind = \"step\"", "kind = \"ramp\""), "creepage.kind", "step, sine, sweep, table"),
        (base().replace("poisson = 0.28", "poisson = 0.5"), "material.poisson", "[0, 0.5)"),
        (base().replace("name = \"bad\"", "name = \"Bad Name\""), "name", "[a-z0-9_]"),
        (base() + "[model]\npressure = \"hertzian\"\n", "model.pressure", "parabolic, ellipsoidal"),
        ("name = \"x\"\nsolvers = [\"uba\"\n".to_string(), "scene line 2, column 17", "malformed TOML"),
        (base().replace("[material]\ng_mpa = 82000.0\n", "[material]\n"), "material.g_mpa", "missing"),
        (base().replace("c = 0.005", "c = 2.0"), "creepage.c", "[-1, 1]"),
        (base().replace("steps = 10", "steps = 10.5"), "creepage.steps", "whole number"),
        (base() + "unknown_top = 1\n", "unknown_top", "no such key"),
        (base().replace("mx = 22", "mx = 22\nscale = 0.5"), "grid.scale", "[1, 10]"),
        (base().replace("steps = 10", "steps = 10\ncx = 0.001"), "creepage.cx", "only with kind = \"sweep\""),
        (
            base().replace(
                "kind = \"step\"\nc = 0.005\nsteps = 10",
                "kind = \"sweep\"\nfrom = 0\nto = 0.01\npoints = 3\nover = \"cq\"",
            ),
            "creepage.over",
            "cx, cy, cs",
        ),
    ];
    for (text, field, expect) in cases {
        let dir = tempfile::tempdir().unwrap();
        let scene = dir.path().join("scene.toml");
        std::fs::write(&scene, &text).unwrap();
        let out = dir.path().join("out");
        let o = creepbench(&["simulate", scene.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{field}: exit {:?}, stderr {err}", o.status.code());
        assert!(err.contains(field), "message must name {field}: {err}");
        assert!(err.contains(expect), "message must contain {expect:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        assert!(!out.exists() || std::fs::read_dir(&out).unwrap().next().is_none(), "{field}: output written");
    }
}

/// Malformed TOML is reported at its line and column (not a byte offset), with the line quoted:
/// a scene file through `simulate`, and any TOML file the one parser reads (tolerance and fit files).
#[test]
fn malformed_toml_names_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let text = base().replace("mu = 0.4", "mu = 0.4 0.3");
    let line = text.lines().position(|l| l == "mu = 0.4 0.3").unwrap() + 1;
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = simulate_in(dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains(&format!("s.toml: scene line {line}, column 6`")), "{err}");
    assert!(err.contains("malformed TOML in \"mu = 0.4 0.3\""), "{err}");
    assert!(!err.contains("byte"), "{err}");

    use creepbench::scene::reader::{parse_toml, LineColumn};
    let e = parse_toml("[[rule]]\nagainst = \"golden\"\nabs = 1e-9 x\n", "tol.toml").unwrap_err();
    assert_eq!(e.field, "tol.toml line 3, column 7");
    assert_eq!(e.value, "malformed TOML in \"abs = 1e-9 x\"");
    // Columns count characters, CRLF ends a line, an offset at the end is the last line's end,
    // and a long line is cut around the column.
    let at = |text: &str, offset| LineColumn::of(text, offset);
    assert_eq!((at("a = \"μμ\" x\r\nb = 1", 10).line, at("a = \"μμ\" x\r\nb = 1", 10).column), (1, 9));
    assert_eq!(at("a = \"μμ\" x\r\nb = 1", 10).excerpt, "a = \"μμ\" x");
    let end = at("a = 1\nb = [\n", 13);
    assert_eq!((end.line, end.column, end.excerpt.as_str()), (3, 1, ""));
    let long = format!("k = \"{}\" x", "y".repeat(100));
    let far = at(&long, 107);
    assert_eq!((far.line, far.column), (1, 108));
    assert_eq!(far.excerpt, format!("{}\" x", "y".repeat(18)));
}

/// Several scene files run in one process, each into its own folder with the numbers it has run
/// alone; two scenes of one name (one folder) are refused before any runs, nothing written.
#[test]
fn simulate_several_scenes_in_one_process() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.toml"));
    std::fs::write(&a, base().replace("name = \"bad\"", "name = \"first\"")).unwrap();
    std::fs::write(&b, base().replace("name = \"bad\"", "name = \"second\"").replace("mu = 0.4", "mu = 0.3")).unwrap();
    let path = |p: &Path| p.to_str().unwrap().to_string();
    let (both, alone) = (dir.path().join("both"), dir.path().join("alone"));
    let o = creepbench(&["simulate", &path(&a), &path(&b), "--out", &path(&both)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8(o.stdout).unwrap().lines().count(), 2);
    for (scene, name) in [(&b, "second"), (&a, "first")] {
        let o = creepbench(&["simulate", &path(scene), "--out", &path(&alone)]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        for solver in ["uba.csv", "fastsim.csv"] {
            let read = |d: &Path| std::fs::read_to_string(d.join(name).join(solver)).unwrap();
            assert_eq!(read(&both), read(&alone), "{name}/{solver}");
        }
    }
    let twice = dir.path().join("twice");
    let o = creepbench(&["simulate", &path(&a), &path(&a), "--out", &path(&twice)]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("first") && err.contains("distinct names"), "{err}");
    assert!(!twice.exists(), "nothing written");
}

/// `simulate DIR/s.toml --out DIR/o`.
fn simulate_in(dir: &Path) -> std::process::Output {
    creepbench(&["simulate", dir.join("s.toml").to_str().unwrap(), "--out", dir.join("o").to_str().unwrap()])
}

/// A table file with a bad cell names the file, line and column.
#[test]
fn bad_table_names_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("t.csv"), "t_s,cx,fn_n\n0,0,100000\n0.01,0.005,-3\n").unwrap();
    let text = base().replace("kind = \"step\"\nc = 0.005\nsteps = 10", "kind = \"table\"\nfile = \"t.csv\"");
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = simulate_in(dir.path());
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("line 3 column fn_n") && err.contains("-3"), "{err}");
}

/// A table may vary FN and μ in time; the history follows it.
#[test]
fn table_kind_varies_load_and_friction() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("t.csv"), "t_s,cx,fn_n,mu\n0,0.002,100000,0.4\n0.02,0.002,50000,0.2\n").unwrap();
    let text = base().replace("kind = \"step\"\nc = 0.005\nsteps = 10", "kind = \"table\"\nfile = \"t.csv\"");
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let o = simulate_in(dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let h = creepbench::history::History::from_csv(
        "uba",
        &std::fs::read_to_string(dir.path().join("o/bad/uba.csv")).unwrap(),
    )
    .unwrap();
    let dt: f64 = 2.0 * 8.56 / 22.0 / 1000.0;
    assert_eq!(h.rows.len(), (0.02 / dt).floor() as usize);
    let last = h.rows.last().unwrap();
    assert!(last.sample.fn_n < 52000.0 && last.sample.fn_n > 50000.0, "fn interpolated: {}", last.sample.fn_n);
    assert!(last.fx_over_fn <= 0.2 + 1e-12);
}

/// `run --fits` with a folder that is not there, or a bad fit file in it: exit 2 before any scene
/// runs, no result folder and no report.
#[test]
fn run_validates_fits_before_running() {
    let tmp = tempfile::tempdir().unwrap();
    let suite = tmp.path().join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    std::fs::write(suite.join("s.toml"), base()).unwrap();
    let bad_fits = tmp.path().join("fits");
    std::fs::create_dir_all(&bad_fits).unwrap();
    std::fs::write(bad_fits.join("f.toml"), "name = \"f\"\nmodel = 3\n").unwrap();
    for (fits, expect) in [(tmp.path().join("missing"), "--fits"), (bad_fits.clone(), "f.toml")] {
        let (res, rep) = (tmp.path().join("res"), tmp.path().join("rep"));
        let o = creepbench(&[
            "run",
            "--quiet",
            "--suite",
            suite.to_str().unwrap(),
            "--results",
            res.to_str().unwrap(),
            "--report",
            rep.to_str().unwrap(),
            "--fits",
            fits.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(expect), "{err}");
        assert!(!res.exists() && !rep.exists(), "{fits:?}: output written");
    }
}

/// --solver must name one of the scene's solvers.
#[test]
fn solver_flag_is_validated() {
    let scenes = tempfile::tempdir().unwrap();
    let scene = suite_scene_file("thesis", "step_mu04", scenes.path());
    let o = creepbench(&["simulate", scene.to_str().unwrap(), "--solver", "nope", "--out", "/nonexistent/x"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--solver"));
}

/// `run` gives byte-identical result CSVs with 1 and 2 rayon threads.
#[test]
fn run_is_identical_with_one_or_two_threads() {
    let tmp = tempfile::tempdir().unwrap();
    let suite = tmp.path().join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    for name in ["step_mu04", "sine_f60_mu10", "steady_fastsim_g22", "step_circle"] {
        suite_scene_file("thesis", name, &suite);
    }
    let mut outs = Vec::new();
    for threads in ["1", "2"] {
        let res = tmp.path().join(format!("res{threads}"));
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .args([
                "run",
                "--suite",
                suite.to_str().unwrap(),
                "--reference",
                root().join("reference").to_str().unwrap(),
                "--fits",
                root().join("fits").to_str().unwrap(),
            ])
            // The scenes' CSVs and the fits' outcomes are compared, not the wall times: no re-timing.
            .args([
                "--results",
                res.to_str().unwrap(),
                "--report",
                tmp.path().join(format!("rep{threads}")).to_str().unwrap(),
                "--timing-repeats",
                "0",
                "--quiet",
            ])
            .env("RAYON_NUM_THREADS", threads)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        outs.push(res);
    }
    for name in ["step_mu04", "sine_f60_mu10", "steady_fastsim_g22", "step_circle"] {
        for f in std::fs::read_dir(outs[0].join(name)).unwrap() {
            let f = f.unwrap().file_name();
            if f == "timing.csv" || f == "timing_repeats.csv" {
                continue; // wall times, kept apart for exactly this reason
            }
            let a = std::fs::read(outs[0].join(name).join(&f)).unwrap();
            let b = std::fs::read(outs[1].join(name).join(&f)).unwrap();
            assert_eq!(a, b, "{name}/{f:?} differs between 1 and 2 threads");
        }
    }
    // The fits of fits/ (asked for with --fits): their stored outcomes are the same bytes too.
    let fits: Vec<_> = std::fs::read_dir(outs[0].join("fits")).unwrap().map(|f| f.unwrap().file_name()).collect();
    assert_eq!(fits.len(), 6, "{fits:?}");
    for f in fits {
        let a = std::fs::read(outs[0].join("fits").join(&f)).unwrap();
        assert_eq!(
            a,
            std::fs::read(outs[1].join("fits").join(&f)).unwrap(),
            "fits/{f:?} differs between 1 and 2 threads"
        );
    }
}
