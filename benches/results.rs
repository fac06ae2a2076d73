//! Writing result folders (issue 48 item 6): `write_scenes/<N>_into_<M>` writes N scene folders
//! (golden/step_mu04's results, nine histories, under new names) into a results folder that
//! already holds M scene folders, under the folder's lock as `run` and `simulate` write. The time
//! per scene must not grow with M (each write once listed the whole folder for leftovers of killed
//! runs: N folders into M cost N·M). docs/performance.md has the measured numbers.
//! Run: `cargo bench -p creepbench-benches --bench results`.

use creepbench::safety::{folder, lock};
use creepbench::suite::results::{self, StoredScene};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use std::path::Path;
use std::time::Duration;

/// Scene folders written per iteration.
const N: usize = 50;
/// Sizes of the results folder before the writes.
const SIZES: [usize; 3] = [0, 2_000, 10_000];

/// N copies of a blessed scene under the names `w_<k>`.
fn scenes() -> Vec<StoredScene> {
    let golden = Path::new(creepbench_benches::ROOT).join("golden");
    let stored = results::read_scene(&golden, "step_mu04").unwrap();
    (0..N).map(|k| StoredScene { name: format!("w_{k}"), ..stored.clone() }).collect()
}

/// A results folder holding `m` scene folders (a marker and a scene.json each).
fn folder_of(m: usize) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for k in 0..m {
        let d = dir.path().join(format!("old_{k}"));
        std::fs::create_dir(&d).unwrap();
        std::fs::write(d.join(folder::MARKER), "x").unwrap();
        std::fs::write(d.join("scene.json"), "{}\n").unwrap();
    }
    dir
}

fn bench_write(c: &mut Criterion) {
    let scenes = scenes();
    let mut g = c.benchmark_group("write_scenes");
    g.sample_size(10).measurement_time(Duration::from_secs(5)).throughput(Throughput::Elements(N as u64));
    for m in SIZES {
        let dir = folder_of(m);
        g.bench_with_input(BenchmarkId::new(format!("{N}_into"), m), &m, |b, _| {
            b.iter(|| {
                let _lock = lock::lock_folder(dir.path(), lock::DEFAULT_LOCK_WAIT).unwrap();
                results::write_scenes(dir.path(), &scenes, false).unwrap().len()
            })
        });
        // The write before issue 48: each folder lists the results folder for leftovers
        // (`folder::write_result_folder`, still what a writer without the folder's lock does).
        g.bench_with_input(BenchmarkId::new(format!("{N}_listing_into"), m), &m, |b, _| {
            b.iter(|| {
                let _lock = lock::lock_folder(dir.path(), lock::DEFAULT_LOCK_WAIT).unwrap();
                let write = |s: &StoredScene| folder::write_result_folder(dir.path(), &s.name, s.files(false));
                scenes.iter().map(write).collect::<Result<Vec<_>, _>>().unwrap().len()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench_write);
criterion_main!(benches);
