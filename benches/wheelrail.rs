//! Speed of the wheel–rail stage (issue 44 item 9) on the Manchester benchmark
//! (scenes/wheelrail/mbench_a22_{left,right}.toml, DX = DS = 0.2 mm, FZ = 10 kN prescribed):
//! `exact_case` — the exact solver on the left wheel's case 11 (lateral shift 5 mm, yaw 12 mrad),
//! the height search with the tangential forces' vertical part included (target: 1/25 of a
//! gfortran build of CONTACT on the same case); `geometry` — the contact search, the patches'
//! grids and the undeformed distance alone at that case's height, per wheel (target ≤ 1 ms), on
//! the rail placed beforehand; `rail_setup` — placing the rail by its gauge point and its gap
//! mesh, which depend on the track alone (made afresh: a scene's profile keeps it for its other
//! cases, once per scene);
//! `all_models_21_positions` — the 21 cases of both wheels with every model of the scenes;
//! `all_models_200_positions` — the benchmark's path at 200 positions of both wheels
//! (benches/scenes/mbench_200_{left,right}.toml) with every model (target: seconds). Issue 45 item 5, each scene with the exact solver alone (target: at most
//! 1/10 of CONTACT's time for the same deck): `crossing_35_positions/locus` (mbench_locus_1, the
//! S1002 wheel over the UK crossing's slices), `crossing_35_positions/grid` (mbench_brute_1, the
//! same with the grid search) and `wheel_flat_26_positions` (wheelflat_1, the Chalmers wheel
//! flat). docs/wheelrail.md "Speed" has the measured numbers.
//! Run: `cargo bench -p creepbench-benches --bench wheelrail`.

use creepbench::pipeline::wheelrail::solve;
use creepbench::pipeline::wheelrail_scene::{case_of, prepare, run_scene};
use creepbench::problem::material_of_spec;
use creepbench::scene::wheelrail::WheelRailScene;
use creepbench::wheelrail::{geometry_with, RailSetup};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

/// The Manchester case's case 11: the lateral shift 5 mm.
const CASE: u64 = 11;

fn scene(side: &str) -> WheelRailScene {
    shipped(&format!("mbench_a22_{side}"))
}

/// The shipped wheel–rail scene `name`.
fn shipped(name: &str) -> WheelRailScene {
    scene_file(&format!("scenes/wheelrail/{name}.toml"))
}

/// The wheel–rail scene at `path` (relative to the repository).
fn scene_file(path: &str) -> WheelRailScene {
    let path = Path::new(creepbench_benches::ROOT).join(path);
    let text = std::fs::read_to_string(&path).unwrap();
    WheelRailScene::from_toml(&text, path.parent().unwrap()).unwrap()
}

fn bench_case(c: &mut Criterion) {
    let mut g = c.benchmark_group("wheelrail");
    g.sample_size(10).measurement_time(Duration::from_secs(10));
    for side in ["left", "right"] {
        let s = scene(side);
        let (rail, wheel, _) = prepare(&s).unwrap();
        let material = material_of_spec(&s.material).unwrap();
        let row = s.cases.iter().find(|r| r.contact_case == CASE).unwrap();
        let case = case_of(&s, row, &rail, &wheel, material);
        let exact = vec!["contact".to_string()];
        let z_ws_mm = solve(&case, &exact, s.mu).unwrap().normal.z_ws_mm;
        if side == "left" {
            g.bench_function("exact_case/left_11", |b| b.iter(|| solve(black_box(&case), &exact, s.mu).unwrap()));
        }
        let setup = RailSetup::new(&case).unwrap();
        g.bench_function(format!("geometry/{side}_11"), |b| {
            b.iter(|| geometry_with(black_box(&case), &setup, z_ws_mm).unwrap())
        });
        g.bench_function(format!("rail_setup/{side}"), |b| b.iter(|| RailSetup::afresh(black_box(&case)).unwrap()));
    }
    g.finish();
}

fn bench_scenes(c: &mut Criterion) {
    let mut g = c.benchmark_group("wheelrail");
    g.sample_size(10).measurement_time(Duration::from_secs(30));
    let scenes = [scene("left"), scene("right")];
    g.bench_function("all_models_21_positions/both_wheels", |b| {
        b.iter(|| scenes.iter().map(|s| run_scene(black_box(s)).unwrap().cases.len()).sum::<usize>())
    });
    g.finish();
    // The path at 200 positions per wheel (benches/scenes/mbench_200_{left,right}.toml).
    let mut g = c.benchmark_group("wheelrail");
    g.sample_size(10).measurement_time(Duration::from_secs(150));
    let scenes = ["left", "right"].map(|side| scene_file(&format!("benches/scenes/mbench_200_{side}.toml")));
    g.bench_function("all_models_200_positions/both_wheels", |b| {
        b.iter(|| scenes.iter().map(|s| run_scene(black_box(s)).unwrap().cases.len()).sum::<usize>())
    });
    g.finish();
}

/// The crossing and the wheel flat, the exact solver alone on every position.
fn bench_in_shape(c: &mut Criterion) {
    let mut g = c.benchmark_group("wheelrail");
    g.sample_size(10).measurement_time(Duration::from_secs(60));
    for (label, name) in [
        ("crossing_35_positions/locus", "mbench_locus_1"),
        ("crossing_35_positions/grid", "mbench_brute_1"),
        ("wheel_flat_26_positions", "wheelflat_1"),
    ] {
        let mut s = shipped(name);
        s.solvers = vec!["contact".to_string()];
        g.bench_function(label, |b| b.iter(|| run_scene(black_box(&s)).unwrap().cases.len()));
    }
    g.finish();
}

criterion_group!(benches, bench_case, bench_scenes, bench_in_shape);
criterion_main!(benches);
