//! Issue 47 item 6, timings one can trust: the report's timing, work–precision and cost-per-step
//! sections give the median of the isolated repeats with its 95 % interval (columns and error
//! bars), computed here by hand from repeats given to golden scenes; `run --timing-repeats` stores
//! the repeats apart, and the result files stay the same bytes with or without them.

use crate::common::{root, tempdir};
use creepbench::comparison::references::References;
use creepbench::pipeline::Timing;
use creepbench::report::{sections, work_precision};
use creepbench::scene::report::ReportGroup;
use creepbench::suite::results::{self, StoredScene};
use std::process::Command;

const SCALING: [&str; 12] = [
    "report_scaling_contact_g22",
    "report_scaling_contact_g44",
    "report_scaling_contact_g88",
    "report_scaling_contact_g176",
    "report_scaling_fastsim_g22",
    "report_scaling_fastsim_g44",
    "report_scaling_fastsim_g88",
    "report_scaling_fastsim_g176",
    "report_scaling_uba_g22",
    "report_scaling_uba_g44",
    "report_scaling_uba_g88",
    "report_scaling_uba_g176",
];

/// The golden scenes of the work–precision grids and the cost-per-step study, each solver given
/// `n` repeats of 1, 2, …, n ms (in a shuffled order) with no set-up time.
fn scenes_with_repeats(n: usize) -> Vec<StoredScene> {
    let golden = root().join("golden");
    let names = work_precision::GRIDS.iter().map(|g| g.0).chain(SCALING);
    names
        .map(|name| {
            let mut s = results::read_scene(&golden, name).unwrap();
            // golden/'s scene.json predates `[report] group`: the scene file's group, as a run stores it.
            if SCALING.contains(&name) {
                s.scene.report_group = ReportGroup::Scaling;
            }
            assert!(creepbench::report::timed::wants_isolated(&s), "{name}");
            for solver in s.histories.keys() {
                let ms: Vec<usize> = (0..n).map(|k| (k * 7) % n + 1).collect();
                let runs = ms.iter().map(|&m| Timing { wall_s: m as f64 * 1e-3, setup_s: 0.0 }).collect();
                s.repeats.insert(solver.clone(), runs);
            }
            s
        })
        .collect()
}

fn references() -> References {
    References::load(&root().join("reference")).unwrap()
}

#[test]
fn timing_section_gives_each_re_timed_run_its_median_and_interval() {
    let scenes = scenes_with_repeats(9);
    let body = sections::timing(&scenes, &references()).body;
    assert!(body.contains("| scene | steps | solver | repeats | median wall | 95 % interval | coverage | median per step | CONTACT s |"), "{body}");
    // 1 … 9 ms: median 5 ms, [x(2), x(8)] = [2, 8] ms, coverage 1 − 2 (1 + 9)/2⁹ = 96.1 %.
    let row = "| sine_f30_mu10_g88 | 516 | contact | 9 | 5.000 ms | [2.000 ms, 8.000 ms] | 96.1 % | 9.69 µs | 87.40 |";
    assert!(body.contains(row), "{body}");
    assert!(
        body.contains(
            "| report_scaling_uba_g22 | 400 | uba | 9 | 5.000 ms | [2.000 ms, 8.000 ms] | 96.1 % | 12.50 µs |  |"
        ),
        "{body}"
    );
    assert!(body.contains("9 repeats") && body.contains("Single runs of the suite"), "{body}");
    // Five repeats give a median but no 95 % interval.
    let body = sections::timing(&scenes_with_repeats(5), &references()).body;
    assert!(body.contains("| sine_f30_mu10_g88 | 516 | contact | 5 | 3.000 ms | — | — |"), "{body}");
}

#[test]
fn work_precision_and_cost_carry_the_intervals_as_error_bars() {
    let scenes = scenes_with_repeats(6);
    let wp = work_precision::section(&scenes, &references()).expect("the three grids converge");
    // Six repeats: median (3 + 4)/2 = 3.5 ms, interval [x(1), x(6)] = [1, 6] ms, per simulated second.
    let g88 = scenes.iter().find(|s| s.name == "sine_f30_mu10_g88").unwrap();
    let sim_s = g88.scene.loading_rows().unwrap().last().unwrap().t_s;
    let cells = format!("| {:.2e} | [{:.2e}, {:.2e}] |", 3.5e-3 / sim_s, 1e-3 / sim_s, 6e-3 / sim_s);
    let row = wp.body.lines().find(|l| l.starts_with("| contact | 88 |")).unwrap();
    assert!(row.contains(&cells), "{row} lacks {cells}");
    let models: usize =
        work_precision::GRIDS.iter().map(|g| scenes.iter().find(|s| s.name == g.0).unwrap().histories.len()).sum();
    let (_, svg) = &wp.figures[0];
    assert_eq!(svg.matches(r#"class="error-bar""#).count(), models, "one bar per model point");

    let cost = sections::scaling(&scenes).unwrap();
    // UBA 22×22: 400 steps, per step 3.5 ms/400 = 8.75 µs in [2.50 µs, 15.00 µs].
    assert!(cost.body.contains("484: 8.75 µs [2.50 µs, 15.00 µs]"), "{}", cost.body);
    assert_eq!(cost.figures[0].1.matches(r#"class="error-bar""#).count(), SCALING.len());
}

/// A scene of the cost-per-step study run with and without re-timing: six repeats of each model
/// in timing_repeats.csv and the report's table; every other file the same bytes.
#[test]
fn run_re_times_alone_and_keeps_the_results_bit_identical() {
    let tmp = tempdir("timing_run");
    let suite = tmp.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    for s in ["report_scaling_uba_g22", "report_scaling_fastsim_g22"] {
        std::fs::copy(root().join("scenes/report").join(format!("{s}.toml")), suite.join(format!("{s}.toml"))).unwrap();
    }
    let run = |repeats: &str| {
        let (res, rep) = (tmp.join(format!("res{repeats}")), tmp.join(format!("rep{repeats}")));
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .args(["run", "--suite", suite.to_str().unwrap(), "--quiet", "--timing-repeats", repeats])
            .args(["--reference", root().join("reference").to_str().unwrap()])
            .args(["--golden", root().join("golden").to_str().unwrap()])
            .args(["--results", res.to_str().unwrap(), "--report", rep.to_str().unwrap()])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        (res, std::fs::read_to_string(rep.join("validation.md")).unwrap())
    };
    let (timed, md) = run("6");
    let (plain, md0) = run("0");
    let csv = std::fs::read_to_string(timed.join("report_scaling_uba_g22/timing_repeats.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "solver,repeat,wall_s,steps,setup_s");
    assert_eq!(lines.len(), 7, "{csv}");
    for (k, l) in lines[1..].iter().enumerate() {
        assert!(l.starts_with(&format!("uba,{},", k + 1)) && l.contains(",400,"), "{l}");
    }
    assert!(md.contains("| report_scaling_uba_g22 | 400 | uba | 6 |"), "{md}");
    assert!(md0.contains("No scene of this run was re-timed") && md0.contains("Not re-timed"), "{md0}");
    for scene in ["report_scaling_uba_g22", "report_scaling_fastsim_g22"] {
        assert!(!plain.join(scene).join("timing_repeats.csv").exists());
        for f in std::fs::read_dir(plain.join(scene)).unwrap() {
            let f = f.unwrap().file_name();
            if f == "timing.csv" {
                continue;
            }
            let (a, b) = (
                std::fs::read(plain.join(scene).join(&f)).unwrap(),
                std::fs::read(timed.join(scene).join(&f)).unwrap(),
            );
            assert_eq!(a, b, "{scene}/{f:?} differs with re-timing");
        }
    }
}
