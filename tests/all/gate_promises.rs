//! The gate keeps its promises under concurrency, shards, odd paths and loosened rules (issue 30).

use crate::common;
use common::*;
use creepbench::suite::Shard;
use std::path::Path;
use std::process::{Command, Output};

fn creepbench(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(dir).args(args).output().expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

/// A quick scene called `name` (the UBA on an 8x8 grid, four steps) written as `dir/file`.
fn write_scene(dir: &Path, file: &str, name: &str) {
    std::fs::create_dir_all(dir).unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(dir.join(file), text).unwrap();
}

/// The scene folders of a blessed tree, sorted.
fn blessed(golden: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(golden)
        .map(|d| d.flatten().filter(|e| e.path().is_dir()).map(|e| e.file_name().to_string_lossy().into()).collect())
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn concurrent_blesses_of_two_suites_both_land() {
    let w = tempfile::tempdir().unwrap();
    for (suite, names) in [("sa", ["a_one", "a_two"]), ("sb", ["b_one", "b_two"])] {
        for n in names {
            write_scene(&w.path().join(suite), &format!("{n}.toml"), n);
        }
    }
    for round in 0..20 {
        let _ = std::fs::remove_dir_all(w.path().join("golden"));
        let spawn = |suite: &str| {
            Command::new(env!("CARGO_BIN_EXE_creepbench"))
                .current_dir(w.path())
                .args(["bless", "--quiet", "--suite", suite])
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        };
        let (a, b) = (spawn("sa"), spawn("sb"));
        for child in [a, b] {
            let o = child.wait_with_output().unwrap();
            assert_eq!(o.status.code(), Some(0), "round {round}: {}", stderr(&o));
        }
        assert_eq!(blessed(&w.path().join("golden")), ["a_one", "a_two", "b_one", "b_two"], "round {round}");
    }
}

#[test]
fn shards_and_bless_select_and_keep_scenes_by_their_name() {
    let w = tempfile::tempdir().unwrap();
    let names = ["n_alpha", "n_beta", "n_gamma", "n_delta", "n_eps", "n_zeta"];
    let stems = ["f1", "f2", "f3", "f4", "f5", "f6"];
    for (stem, name) in stems.iter().zip(names) {
        write_scene(&w.path().join("suite"), &format!("{stem}.toml"), name);
    }
    // The files' stems and the scenes' names fall into different shards for some scene.
    let s1 = Shard { index: 1, count: 2 };
    assert!(stems.iter().zip(names).any(|(st, n)| s1.takes(st) != s1.takes(n)));
    for shard in ["1/2", "2/2"] {
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite", "--shard", shard]);
        assert_eq!(o.status.code(), Some(0), "{shard}: {}", stderr(&o));
    }
    let mut want: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    want.sort();
    assert_eq!(blessed(&w.path().join("golden")), want);
    // Blessed twice more, shard by shard: nothing goes missing.
    for shard in ["2/2", "1/2"] {
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite", "--shard", shard]);
        assert_eq!(o.status.code(), Some(0), "{shard}: {}", stderr(&o));
        assert_eq!(blessed(&w.path().join("golden")), want);
    }
    // Two files of one name remain an error, sharded or not.
    write_scene(&w.path().join("suite"), "f7.toml", "n_alpha");
    for args in
        [vec!["bless", "--quiet", "--suite", "suite"], vec!["bless", "--quiet", "--suite", "suite", "--shard", "2/2"]]
    {
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("n_alpha") && stderr(&o).contains("f7.toml"), "{}", stderr(&o));
    }
}

/// A work folder with suite/ (two quick scenes), golden/ blessed from it, and a drift put into
/// golden/: a_one's UBA fx_over_fn at step 1 moved by about 5e-3.
fn drifted_workspace() -> tempfile::TempDir {
    let w = tempfile::tempdir().unwrap();
    for n in ["a_one", "a_two"] {
        write_scene(&w.path().join("suite"), &format!("{n}.toml"), n);
    }
    let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let csv = w.path().join("golden/a_one/uba.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut row: Vec<String> = lines[1].split(',').map(str::to_string).collect();
    row[6] = "0.2".into();
    lines[1] = row.join(",");
    std::fs::write(&csv, lines.join("\n") + "\n").unwrap();
    w
}

fn rule(body: &str) -> String {
    format!("[[rule]]\nagainst = \"golden\"\n{body}\nwhy = \"the test's reason\"\n")
}

#[test]
fn no_gate_is_disabled_in_silence() {
    let w = drifted_workspace();
    let check = |extra: &[&str]| {
        let mut args = vec!["check", "--quiet", "--suite", "suite", "--reference"];
        let refs = root().join("reference");
        args.push(refs.to_str().unwrap());
        args.extend_from_slice(extra);
        creepbench(w.path(), &args)
    };
    // Without a file the drift fails the gate.
    let o = check(&[]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    // Rules that make a gate unable to fail are refused unless they say so.
    let one = "scene = \"a_one\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"";
    for (body, field) in [
        (format!("{one}\nabs = 1e9"), "abs"),
        (format!("{one}\nabs = 1.7e308"), "abs"),
        (format!("{one}\nabs = 0.0\nrel = 1e12"), "rel"),
        (format!("{one}\ngated = false"), "gated = false"),
        ("abs = 0.5".to_string(), "\"*\""),
        ("scene = \"*\"\nabs = 0.5".to_string(), "\"*\""),
    ] {
        std::fs::write(w.path().join("t.toml"), rule(&body)).unwrap();
        let o = check(&["--tolerances", "t.toml"]);
        assert_eq!(o.status.code(), Some(2), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("t.toml rule[0]") && stderr(&o).contains(field), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("disable = true"), "{body}: {}", stderr(&o));
    }
    // Beyond f64, the file does not even parse.
    std::fs::write(w.path().join("t.toml"), rule(&format!("{one}\nabs = 1.8e308"))).unwrap();
    assert_eq!(check(&["--tolerances", "t.toml"]).status.code(), Some(2));
    // A suite's tolerances.toml is read the same way.
    std::fs::write(w.path().join("suite/tolerances.toml"), rule(&format!("{one}\nabs = 1e300"))).unwrap();
    let o = check(&[]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("tolerances.toml rule[0]"), "{}", stderr(&o));
    std::fs::remove_file(w.path().join("suite/tolerances.toml")).unwrap();
    // A loosening that passes the drift is listed in every verdict, with file, rule, why, count.
    for (body, decided) in [(format!("{one}\nabs = 0.01"), 1), (format!("{one}\ngated = false\ndisable = true"), 1)] {
        std::fs::write(w.path().join("t.toml"), rule(&body)).unwrap();
        let o = check(&["--tolerances", "t.toml", "--json", "v.json", "--junit", "v.xml", "--summary", "v.md"]);
        assert_eq!(o.status.code(), Some(0), "{body}: {}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout).to_string();
        let line =
            format!("decided {decided} comparison(s), loosened {decided} the defaults gate; why: the test's reason");
        assert!(out.contains("t.toml rule[0]: against golden") && out.contains(&line), "{body}: {out}");
        let j: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(w.path().join("v.json")).unwrap()).unwrap();
        let l = &j["loosened"][0];
        assert_eq!(
            (l["origin"].as_str(), l["decided"].as_u64(), l["why"].as_str()),
            (Some("t.toml rule[0]"), Some(decided), Some("the test's reason")),
            "{j}"
        );
        let xml = std::fs::read_to_string(w.path().join("v.xml")).unwrap();
        assert!(xml.contains("<property name=\"loosened\" value=\"t.toml rule[0]: against golden"), "{xml}");
        let md = std::fs::read_to_string(w.path().join("v.md")).unwrap();
        assert!(md.contains("t.toml rule[0]") && md.contains(&line), "{md}");
        // --strict refuses every loosening.
        let o = check(&["--tolerances", "t.toml", "--strict"]);
        assert_eq!(o.status.code(), Some(2), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("--strict") && stderr(&o).contains("t.toml rule[0]"), "{}", stderr(&o));
    }
    // A tightening is no loosening: --strict takes it, and nothing is listed.
    std::fs::write(
        w.path().join("t.toml"),
        rule("scene = \"a_two\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"\nabs = 0.0"),
    )
    .unwrap();
    let o = check(&["--tolerances", "t.toml", "--strict"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(!String::from_utf8_lossy(&o.stdout).contains("loosen"));
    // The report lists it too (merge of a run's results with the file).
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    let o = creepbench(
        w.path(),
        &["run", "--quiet", "--suite", "suite", "--results", "res", "--report", "rep", "--reference", refs],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    std::fs::write(w.path().join("t.toml"), rule(&format!("{one}\nabs = 0.01"))).unwrap();
    let o = creepbench(
        w.path(),
        &["merge", "res", "--suite", "suite", "--report", "rep2", "--tolerances", "t.toml", "--reference", refs],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let md = std::fs::read_to_string(w.path().join("rep2/validation.md")).unwrap();
    assert!(md.contains("Loosened gates") && md.contains("t.toml rule[0]") && md.contains("the test's reason"), "{md}");
    assert!(stderr(&o).contains("loosened: t.toml rule[0]"), "{}", stderr(&o));
}

/// A study over `axes` ("key = [values]" lines, one axis each) with a quick template.
fn study_text(axes: &[&str]) -> String {
    let mut t = String::from("[study]\nname = \"st\"\n");
    for (i, a) in axes.iter().enumerate() {
        t.push_str(&format!("[[study.axis]]\nname = \"a{i}\"\n{a}\n"));
    }
    let scene = scene_text("x", "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    let body: String = scene
        .lines()
        .skip(1)
        .map(|l| match l.strip_prefix('[') {
            Some(table) => format!("[scene.{table}\n"),
            None => format!("{l}\n"),
        })
        .collect();
    t + "[scene]\n" + &body
}

#[test]
fn study_values_are_finite_and_absurd_studies_are_refused_before_allocating() {
    let w = tempfile::tempdir().unwrap();
    for (axis, field) in [
        ("\"contact.mu\" = [0.3, 0.4]\nx_values = [nan, 1.0]", "x_values"),
        ("\"contact.mu\" = [0.3, 0.4]\nx_values = [1.0, inf]", "x_values"),
        ("\"contact.mu\" = [0.3, nan]", "contact.mu"),
        ("\"contact.mu\" = [-inf, 0.4]", "contact.mu"),
    ] {
        std::fs::write(w.path().join("s.toml"), study_text(&[axis])).unwrap();
        for cmd in ["expand", "simulate"] {
            let o = creepbench(w.path(), &[cmd, "s.toml", "--out", "o"]);
            assert_eq!(o.status.code(), Some(2), "{axis}: {}", stderr(&o));
            assert!(stderr(&o).contains(field) && stderr(&o).contains("finite"), "{axis}: {}", stderr(&o));
        }
        assert!(!w.path().join("o").exists(), "{axis}");
    }
    // 5 axes of 1e4 values: refused at once (it panicked with "capacity overflow", exit 101).
    let values: Vec<String> = (1..=10_000).map(|i| i.to_string()).collect();
    let axis = format!("\"grid.mx\" = [{}]", values.join(", "));
    std::fs::write(w.path().join("s.toml"), study_text(&[axis.as_str(); 5])).unwrap();
    let start = std::time::Instant::now();
    let o = creepbench(w.path(), &["expand", "s.toml", "--out", "o"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("at most 100000 points"), "{}", stderr(&o));
    assert!(start.elapsed().as_secs_f64() < 5.0, "{:?}", start.elapsed());
    // 1e4 points expand (and get their names checked) in linear time: it took 7.7 s.
    let doc: toml::Table = study_text(&[axis.as_str()]).parse().unwrap();
    let start = std::time::Instant::now();
    let points = creepbench::pipeline::expand_study(&doc).unwrap();
    assert_eq!(points.len(), 10_000);
    assert!(start.elapsed().as_secs_f64() < 2.0, "{:?}", start.elapsed());
}

#[test]
fn fit_patterns_that_match_nothing_are_errors() {
    use creepbench::calibration::fit::spec::wildcard;
    // `?` is one character, `*` any run (README).
    assert!(wildcard("sine_f?0_mu06", "sine_f10_mu06") && wildcard("sine_f??0_mu06", "sine_f100_mu06"));
    assert!(!wildcard("sine_f?0_mu06", "sine_f100_mu06") && wildcard("*_f*0_*", "sine_f100_mu06"));
    assert!(wildcard("a*b?c", "aXXbYc") && !wildcard("a*b?c", "aXXbc") && wildcard("*", "") && !wildcard("?", ""));
    let w = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root().join("fits/uba_sine.toml")).unwrap();
    let suite = root().join("scenes/thesis");
    let text = text.replace("\"../scenes/thesis\"", &format!("{:?}", suite.to_str().unwrap()));
    for (from, to, key) in [
        (
            "holdout = [\"sine_f*_mu10\", \"sine_f*_mu06\"]",
            "holdout = [\"sine_f*_mu10\", \"sine_f*_mu99\"]",
            "fit.holdout",
        ),
        ("holdout = [\"sine_f*_mu10\", \"sine_f*_mu06\"]", "holdout = [\"sine_f?0_mu9?\"]", "fit.holdout"),
        ("fit = [\"sine_f10_mu10\", \"sine_f30_mu10\"]", "fit = [\"sine_f10_mu10\", \"nothing\"]", "fit.fit"),
    ] {
        assert!(text.contains(from), "{from}");
        std::fs::write(w.path().join("f.toml"), text.replace(from, to)).unwrap();
        let start = std::time::Instant::now();
        let o = creepbench(
            w.path(),
            &["fit", "f.toml", "--out", "o.toml", "--reference", root().join("reference").to_str().unwrap()],
        );
        assert_eq!(o.status.code(), Some(2), "{to}: {}", stderr(&o));
        assert!(stderr(&o).contains(key) && stderr(&o).contains("matching a scene"), "{to}: {}", stderr(&o));
        assert!(start.elapsed().as_secs_f64() < 10.0 && !w.path().join("o.toml").exists());
    }
}

/// The reference data copied into `dir` with `edit` applied to one CONTACT history, its manifest
/// rewritten (as `creepbench manifest` would): the manifest guards change, not garbage.
fn edited_reference(dir: &Path, edit: impl Fn(&str) -> String) -> Result<(), String> {
    edited_reference_file(dir, "contact/sine_f10_c0_0000.csv", edit)
}

/// [`edited_reference`] with `edit` applied to the file `name` of the reference data.
fn edited_reference_file(dir: &Path, name: &str, edit: impl Fn(&str) -> String) -> Result<(), String> {
    let status = Command::new("cp").arg("-r").arg(root().join("reference")).arg(dir).status().unwrap();
    assert!(status.success());
    let file = dir.join(name);
    let text = std::fs::read_to_string(&file).unwrap();
    std::fs::write(&file, edit(&text)).unwrap();
    creepbench::safety::manifest::write(dir).unwrap();
    creepbench::comparison::references::References::load(dir).map(|_| ()).map_err(|e| e.to_string())
}

#[test]
fn reference_histories_with_garbage_steps_or_no_rows_are_refused_whatever_the_manifest_says() {
    let tmp = tempfile::tempdir().unwrap();
    edited_reference(&tmp.path().join("same"), |t| t.to_string()).unwrap();
    type Edit = fn(&str) -> String;
    let cases: [(&str, Edit); 4] = [
        ("a repeated step (a wrong row before the right one)", |t| {
            let mut lines: Vec<String> = t.lines().map(String::from).collect();
            let wrong = lines[2].replace("215.5133", "999.9");
            assert_ne!(wrong, lines[2]);
            lines.insert(2, wrong);
            lines.join("\n") + "\n"
        }),
        ("a negative step", |t| {
            let mut lines: Vec<String> = t.lines().map(String::from).collect();
            lines[1] = format!("-1{}", &lines[1][lines[1].find(',').unwrap()..]);
            lines.join("\n") + "\n"
        }),
        ("a fractional step", |t| {
            let mut lines: Vec<String> = t.lines().map(String::from).collect();
            lines[2] = format!("1.5{}", &lines[2][lines[2].find(',').unwrap()..]);
            lines.join("\n") + "\n"
        }),
        ("no rows", |t| t.lines().next().unwrap().to_string() + "\n"),
    ];
    for (i, (what, edit)) in cases.into_iter().enumerate() {
        let e = edited_reference(&tmp.path().join(format!("r{i}")), edit).unwrap_err();
        assert!(e.contains("sine_f10_c0_0000.csv") && e.contains("step"), "{what}: {e}");
    }
}

#[test]
fn a_case_given_twice_in_a_cases_file_is_refused_whatever_the_manifest_says() {
    let tmp = tempfile::tempdir().unwrap();
    // A second row of an existing case, with another note or method: it would replace the first.
    let repeat_last = |t: &str| {
        let last = t.lines().last().unwrap().to_string();
        format!("{t}{}\n", last.replace("yes", "no"))
    };
    for (i, file) in
        ["contact/cases.csv", "contact_envelope/cases.csv", "contact_friction/cases.csv"].iter().enumerate()
    {
        let e = edited_reference_file(&tmp.path().join(format!("d{i}")), file, repeat_last).unwrap_err();
        assert!(e.contains(file) && e.contains("column name") && e.contains("no earlier row"), "{file}: {e}");
    }
}

#[test]
fn a_traction_coefficient_beyond_its_bound_fails_the_gate_and_golden_data_pass() {
    use creepbench::comparison::against::Against;
    use creepbench::comparison::compare::{evaluate, traction_bound};
    use creepbench::suite::results::{read_scene, scene_names, StoredScene};
    // Every blessed history keeps |(Fx, Fy)|/FN within mu.
    let golden = root().join("golden");
    let names = scene_names(&golden);
    assert!(names.len() > 200, "{}", names.len());
    for n in &names {
        let s = read_scene(&golden, n).unwrap();
        assert!(traction_bound(&s, Against::Golden).is_empty(), "{n}: {:?}", traction_bound(&s, Against::Golden));
    }
    // A model writing 1.7e308, NaN, or mu·(1 + 1e-5) fails; mu·(1 + 1e-7) is rounding.
    let p = problem(&scene_text("b", "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", ""));
    let result = creepbench::pipeline::run(p).unwrap();
    let stored = StoredScene::from_result(&result);
    let refs = creepbench::comparison::references::References::load(&root().join("reference")).unwrap();
    for (fx, fails) in [(1.7e308, true), (f64::NAN, true), (0.4 * (1.0 + 1e-5), true), (0.4 * (1.0 + 1e-7), false)] {
        let mut s = stored.clone();
        s.histories.get_mut("uba").unwrap().rows[2].fx_over_fn = fx;
        let all = evaluate(&[s], &refs, None).unwrap();
        let bound: Vec<_> = all.iter().filter(|f| f.quantity == "traction_bound").collect();
        assert_eq!(bound.len(), usize::from(fails), "{fx}");
        if fails {
            assert!(bound[0].gated && !bound[0].passed() && bound[0].step == Some(3), "{fx}: {:?}", bound[0]);
        }
    }
}

#[test]
fn merge_checks_the_blessed_set_and_refuses_a_scene_of_no_model() {
    let w = tempfile::tempdir().unwrap();
    let names = ["m_alpha", "m_beta", "m_gamma", "m_delta", "m_eps", "m_zeta"];
    for n in names {
        write_scene(&w.path().join("suite"), &format!("{n}.toml"), n);
    }
    let s1 = Shard { index: 1, count: 2 };
    assert!(names.iter().any(|n| s1.takes(n)) && names.iter().any(|n| !s1.takes(n)));
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite", "--reference", refs]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for (shard, dir) in [("1/2", "r1"), ("2/2", "r2")] {
        let o = creepbench(
            w.path(),
            &["run", "--quiet", "--suite", "suite", "--shard", shard, "--results", dir, "--reference", refs],
        );
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    let o = creepbench(w.path(), &["merge", "r1", "r2", "--suite", "suite", "--report", "rep", "--reference", refs]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(std::fs::read_to_string(w.path().join("rep/validation.md")).unwrap().contains("All gates pass"));
    // One shard alone: the other's blessed scenes are missing, and the verdict says so.
    let o = creepbench(w.path(), &["merge", "r1", "--suite", "suite", "--report", "rep1", "--reference", refs]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let missing = names.iter().find(|n| !s1.takes(n)).unwrap();
    assert!(stderr(&o).contains(&format!("MISSING scene {missing}")), "{}", stderr(&o));
    let md = std::fs::read_to_string(w.path().join("rep1/validation.md")).unwrap();
    assert!(md.contains("GATES FAIL") && !md.contains("All gates pass"), "{md}");
    // A result folder listing no solvers is refused.
    let scene = names.iter().find(|n| s1.takes(n)).unwrap();
    let json_path = w.path().join("r1").join(scene).join("scene.json");
    let json = std::fs::read_to_string(&json_path).unwrap();
    let json = json.replace("\"solvers\": [\n    \"uba\"\n  ]", "\"solvers\": []");
    assert!(json.contains("\"solvers\": []"), "{json}");
    std::fs::write(&json_path, json).unwrap();
    std::fs::remove_file(w.path().join("r1").join(scene).join("uba.csv")).unwrap();
    let o = creepbench(w.path(), &["merge", "r1", "r2", "--suite", "suite", "--report", "rep2", "--reference", refs]);
    assert_ne!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("at least one solver"), "{}", stderr(&o));
    assert!(!w.path().join("rep2").exists());
}

#[test]
fn an_absurd_thread_count_is_capped_with_a_warning() {
    let w = tempfile::tempdir().unwrap();
    write_scene(w.path(), "s.toml", "threads");
    let start = std::time::Instant::now();
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(w.path())
        .args(["simulate", "s.toml", "--out", "o"])
        .env("RAYON_NUM_THREADS", "30000")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("RAYON_NUM_THREADS = 30000 capped at"), "{}", stderr(&o));
    assert!(start.elapsed().as_secs_f64() < 10.0);
}

/// Every file under `dir` with its contents (a protected tree before and after).
fn tree(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            if e.file_type().unwrap().is_dir() {
                stack.push(e.path());
            } else {
                out.push((e.path().display().to_string(), std::fs::read(e.path()).unwrap_or_default()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn nothing_is_written_when_a_command_will_fail() {
    let w = tempfile::tempdir().unwrap();
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    for n in ["fits", "tables", "plain"] {
        write_scene(&w.path().join(format!("s_{n}")), &format!("{n}.toml"), n);
    }
    std::fs::create_dir_all(w.path().join("myfits")).unwrap();
    std::fs::write(w.path().join("report.md"), "mine").unwrap();
    for (args, what) in [
        (vec!["run", "--suite", "s_plain", "--results", "res", "--report", "report.md"], "not a folder"),
        (vec!["run", "--suite", "s_fits", "--results", "res", "--report", "rep", "--fits", "myfits"], "\"fits\""),
        (vec!["run", "--suite", "s_tables", "--results", "res", "--report", "res"], "\"tables\""),
    ] {
        let mut args = args.clone();
        args.extend(["--quiet", "--reference", refs]);
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(what), "{args:?}: {}", stderr(&o));
        assert!(!w.path().join("res").exists() && !w.path().join("rep").exists(), "{args:?}");
        assert_eq!(std::fs::read_to_string(w.path().join("report.md")).unwrap(), "mine");
    }
    // merge --report X X: one folder twice, and a report over result folders named like its own.
    let o = creepbench(
        w.path(),
        &["run", "--quiet", "--suite", "s_tables", "--results", "res", "--report", "rep", "--reference", refs],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let before = tree(&w.path().join("res"));
    for args in [vec!["merge", "res", "res", "--report", "res2"], vec!["merge", "res", "--report", "res"]] {
        let mut args = args.clone();
        args.extend(["--suite", "s_tables", "--reference", refs]);
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_eq!(tree(&w.path().join("res")), before, "{args:?}");
        assert!(!w.path().join("res2").exists());
    }
    // A manifest that cannot be written leaves no temporary file behind.
    let d = w.path().join("data");
    std::fs::create_dir_all(d.join("MANIFEST.sha256/x")).unwrap();
    std::fs::write(d.join("a.csv"), "1\n").unwrap();
    assert!(creepbench::safety::manifest::write(&d).is_err());
    let mut left: Vec<String> =
        std::fs::read_dir(&d).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into()).collect();
    left.sort();
    assert_eq!(left, ["MANIFEST.sha256", "a.csv"]);
}

#[test]
fn protected_trees_are_recognised_by_what_they_are_and_outputs_are_plain_files() {
    let w = tempfile::tempdir().unwrap();
    let root_refs = root().join("reference");
    let refs = root_refs.to_str().unwrap();
    write_scene(&w.path().join("repo/suite"), "s.toml", "pt_scene");
    let repo = w.path().join("repo");
    let o = creepbench(&repo, &["bless", "--quiet", "--suite", "suite", "--reference", refs]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // A checksummed data tree of the user's.
    std::fs::create_dir_all(repo.join("data")).unwrap();
    std::fs::write(repo.join("data/a.csv"), "1\n").unwrap();
    creepbench::safety::manifest::write(&repo.join("data")).unwrap();
    let other = w.path().join("elsewhere");
    std::fs::create_dir_all(&other).unwrap();
    std::os::unix::fs::symlink(repo.join("golden"), other.join("link")).unwrap();
    let fifo = other.join("fifo");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let golden = repo.join("golden");
    let g = |rest: &str| format!("{}/{rest}", golden.display());
    let data = |rest: &str| format!("{}/data/{rest}", repo.display());
    let scene = repo.join("suite/s.toml");
    let scene = scene.to_str().unwrap();
    let fit_text = std::fs::read_to_string(root().join("fits/uba_sine.toml")).unwrap();
    std::fs::write(
        other.join("f.toml"),
        fit_text.replace("../scenes/thesis", root().join("scenes/thesis").to_str().unwrap()),
    )
    .unwrap();
    std::fs::write(other.join("st.toml"), study_text(&["\"contact.mu\" = [0.3, 0.4]"])).unwrap();
    let (before_golden, before_data) = (tree(&golden), tree(&repo.join("data")));
    let suite = repo.join("suite");
    let suite = suite.to_str().unwrap();
    let check = |extra: Vec<String>| {
        let mut v: Vec<String> = ["check", "--quiet", "--suite", suite, "--reference", refs].map(String::from).to_vec();
        v.extend(extra);
        v
    };
    let cases: Vec<Vec<String>> = vec![
        vec!["fit".into(), "f.toml".into(), "--out".into(), g("x.toml")],
        vec!["fit".into(), "f.toml".into(), "--out".into(), data("x.toml")],
        vec!["fit".into(), "f.toml".into(), "--out".into(), "link/x.toml".into()],
        vec!["manifest".into(), golden.display().to_string()],
        vec!["manifest".into(), g("pt_scene/../")],
        vec!["manifest".into(), "link".into()],
        vec!["expand".into(), "st.toml".into(), "--out".into(), "link/new".into()],
        vec!["simulate".into(), scene.into(), "--out".into(), g("../golden/new")],
        vec!["export".into(), "contact".into(), scene.into(), "--out".into(), data("")],
        check(vec!["--json".into(), g("v.json")]),
        check(vec!["--summary".into(), data("v.md")]),
        check(vec!["--junit".into(), "fifo".into()]),
        check(vec!["--junit".into(), "/dev/null".into()]),
        check(vec!["--json".into(), ".".into()]),
    ];
    for args in &cases {
        let start = std::time::Instant::now();
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(&other).args(args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("refusing"), "{args:?}: {}", stderr(&o));
        assert!(start.elapsed().as_secs_f64() < 10.0, "{args:?}");
    }
    // GITHUB_STEP_SUMMARY into golden/ or at a FIFO: refused at once, before the suite runs.
    for target in [g("s.md"), fifo.display().to_string(), data("s.md")] {
        let start = std::time::Instant::now();
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .current_dir(&other)
            .args(check(vec![]))
            .env("GITHUB_STEP_SUMMARY", &target)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{target}: {}", stderr(&o));
        assert!(start.elapsed().as_secs_f64() < 10.0, "{target}");
    }
    assert_eq!(tree(&golden), before_golden);
    assert_eq!(tree(&repo.join("data")), before_data);
    // export contact replaces no file of the user's, like fit and expand.
    std::fs::create_dir_all(other.join("ex")).unwrap();
    std::fs::write(other.join("ex/pt_scene.inp"), "mine").unwrap();
    let o = creepbench(&other, &["export", "contact", scene, "--out", "ex"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("replaces nothing"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(other.join("ex/pt_scene.inp")).unwrap(), "mine");
    // A plain new output is written.
    let o = creepbench(&other, &["export", "contact", scene, "--out", "ex2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}
