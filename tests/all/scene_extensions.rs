//! Scene-interface extensions of issue 12: the sweep's direction (`over`, `direction`, the `cx`
//! constant), the grid's scale (`[grid] scale`, CONTACT's SCALE) and a table that covers its last
//! row when its times were printed rounded. Good and bad input, scene.json, and runs.

use crate::common;
use common::*;
use creepbench::error::InputError;
use creepbench::problem::{LoadingKind, Problem, ResolvedScene};
use creepbench::scene::table::CreepageTable;
use creepbench::scene::Scene;
use std::path::Path;
use std::process::Command;

fn scene_on(grid: usize, creepage: &str) -> String {
    scene_text("ext", "[\"uba\", \"fastsim\", \"contact\", \"linear\"]", 0.4, grid, creepage, "")
}

fn scene(creepage: &str, extra: &str) -> String {
    scene_text("ext", "[\"uba\", \"fastsim\", \"contact\", \"linear\"]", 0.4, 10, creepage, extra)
}

/// A sweep from 0 to 0.01 in 11 points, `keys` added or replacing those.
fn sweep(keys: &str) -> String {
    let mut creepage = String::from("kind = \"sweep\"\n");
    for (key, default) in [("from", "0.0"), ("to", "0.01"), ("points", "11")] {
        if !keys.lines().any(|l| l.starts_with(&format!("{key} ="))) {
            creepage += &format!("{key} = {default}\n");
        }
    }
    scene(&(creepage + keys), "")
}

/// The error of scene text that must be refused, parsing or resolving it (never a panic).
fn refused(text: &str) -> InputError {
    match Scene::from_toml(text, Path::new(".")) {
        Err(e) => e,
        Ok(s) => creepbench::pipeline::resolve(&s).expect_err("the scene must be refused"),
    }
}

/// The error names the field, the value and what is allowed.
fn assert_refused(text: &str, field: &str, value: &str, allowed: &str) {
    let e = refused(text);
    assert_eq!(e.field, field, "{e}");
    assert!(e.value.contains(value), "value {value:?} in: {e}");
    assert!(e.allowed.contains(allowed), "allowed {allowed:?} in: {e}");
}

fn creepages(p: &Problem) -> Vec<[f64; 3]> {
    p.loading.samples.iter().map(|s| [s.cx, s.cy, s.cs]).collect()
}

// ---- 1. Sweep direction -------------------------------------------------------------------------

/// Without `over`/`direction` a sweep is the cx sweep, bit for bit the old cx = from + (to − from) f.
#[test]
fn default_sweep_is_the_cx_sweep_bit_for_bit() {
    let (from, to, n) = (-0.003, 0.0071, 37usize);
    let text = scene(&format!("kind = \"sweep\"\nfrom = {from}\nto = {to}\npoints = {n}\ncy = 0.002\ncs = 0.05"), "");
    let p = problem(&text);
    let over = problem(&text.replace("points = 37", "points = 37\nover = \"cx\""));
    let dir = problem(&text.replace("points = 37", "points = 37\ndirection = [1, 0, 0]"));
    for (k, s) in p.loading.samples.iter().enumerate() {
        let old = from + (to - from) * (k as f64 / (n - 1) as f64);
        assert_eq!(s.cx.to_bits(), old.to_bits(), "point {}", k + 1);
        assert_eq!((s.cy.to_bits(), s.cs.to_bits()), (0.002f64.to_bits(), 0.05f64.to_bits()));
    }
    assert_eq!(creepages(&p), creepages(&over));
    assert_eq!(creepages(&p), creepages(&dir));
    assert_eq!(p.loading.sweep_direction, Some([1.0, 0.0, 0.0]));
}

/// `over = "cy"` / `"cs"` sweep that creepage from the constants; `direction` any combination.
#[test]
fn sweep_over_cy_cs_and_a_direction() {
    let p = problem(&sweep("over = \"cy\"\ncx = 0.001\ncy = 0.002\ncs = 0.03"));
    for (k, c) in creepages(&p).iter().enumerate() {
        let t = 0.0 + (0.01 - 0.0) * (k as f64 / 10.0);
        assert_eq!(c[0], 0.001);
        assert_eq!(c[1], 0.002 + t, "cy at t = {t}");
        assert_eq!(c[2], 0.03);
    }
    // A spin sweep may go beyond the creepage range: cs is checked against the spin range.
    let p = problem(&scene("kind = \"sweep\"\nfrom = -4.0\nto = 6.0\npoints = 3\nover = \"cs\"", ""));
    assert_eq!(creepages(&p), vec![[0.0, 0.0, -4.0], [0.0, 0.0, 1.0], [0.0, 0.0, 6.0]]);
    let p = problem(&sweep("direction = [0.5, -0.25, 2.0]\ncx = 0.001\ncy = 0.002\ncs = 0.1"));
    let last = creepages(&p)[10];
    assert_eq!(last, [0.001 + 0.5 * 0.01, 0.002 - 0.25 * 0.01, 0.1 + 2.0 * 0.01]);
    assert_eq!(p.loading.sweep_direction, Some([0.5, -0.25, 2.0]));
}

/// A cy sweep runs through every built-in model: fy grows with cy, fx stays (nearly) zero.
#[test]
fn cy_sweep_runs_every_model() {
    let p = problem(&sweep("over = \"cy\"\nto = 0.002\npoints = 5"));
    for solver in ["uba", "fastsim", "contact", "linear"] {
        let h = run(&p, solver);
        let fy = h.column("fy_over_fn").unwrap();
        assert_eq!(fy.len(), 5, "{solver}");
        assert!(fy.windows(2).all(|w| w[1] > w[0]), "{solver}: fy increasing in cy: {fy:?}");
        assert!(h.column("fx_over_fn").unwrap().iter().all(|f| f.abs() < 1e-6), "{solver}: fx ~ 0");
    }
}

/// scene.json records the direction and reads back equal; result folders written before it
/// (tests/fixtures: scene.json of golden/steady_exact_g22 and step_mu01 at f95dd0c) read as the cx
/// sweep and a time history without one, both at grid scale 1 and c33 absent (0).
#[test]
fn scene_json_records_direction_and_reads_old_files() {
    let p = problem(&sweep("direction = [0.0, 1.0, 0.5]"));
    let json = ResolvedScene::of(&p, &p.solvers).to_json();
    let back = ResolvedScene::from_json(&json).unwrap();
    assert_eq!(back.sweep_direction, Some([0.0, 1.0, 0.5]));
    assert_eq!(back, ResolvedScene::of(&p, &p.solvers));
    let old = |name: &str| {
        let text = std::fs::read_to_string(root().join("tests/fixtures").join(name)).unwrap();
        assert!(!text.contains("sweep_direction") && !text.contains("grid_scale"), "{name}: written before both");
        ResolvedScene::from_json(&text).unwrap()
    };
    let s = old("scene_v1_sweep.json");
    assert_eq!((s.kind, s.sweep_direction, s.grid_scale), (LoadingKind::Sweep, Some([1.0, 0.0, 0.0]), 1.0));
    let s = old("scene_v1_step.json");
    assert_eq!((s.sweep_direction, s.grid_scale), (None, 1.0));
}

#[test]
fn bad_sweep_keys_are_refused_naming_field_value_and_allowed() {
    let r = assert_refused;
    r(&sweep("over = \"cz\""), "creepage.over", "\"cz\"", "one of cx, cy, cs");
    r(&sweep("over = 1"), "creepage.over", "1", "one of cx, cy, cs");
    r(&sweep("direction = [0, 0, 0]"), "creepage.direction", "[0.0, 0.0, 0.0]", "not all zero");
    r(&sweep("direction = [1, 0]"), "creepage.direction", "[1, 0]", "an array of 3 numbers");
    r(&sweep("direction = 1.0"), "creepage.direction", "1.0", "an array of 3 numbers");
    r(&sweep("direction = [1, \"a\", 0]"), "creepage.direction[1]", "\"a\"", "finite number");
    r(&sweep("direction = [1, nan, 0]"), "creepage.direction[1]", "NaN", "finite number");
    r(&sweep("direction = [1, 0, -inf]"), "creepage.direction[2]", "-inf", "finite number");
    r(&sweep("over = \"cy\"\ndirection = [0, 1, 0]"), "creepage.direction", "over = \"cy\"", "not both");
    r(&sweep("cx = 1.5"), "creepage.cx", "1.5", "[-1, 1]");
    r(&sweep("cx = nan"), "creepage.cx", "NaN", "[-1, 1]");
    // cx belongs to the sweep: step and sine set cx themselves, a table gives it as a column.
    let step = scene("kind = \"step\"\nc = 0.005\nsteps = 10\ncx = 0.001", "");
    r(&step, "creepage.cx", "0.001", "only with kind = \"sweep\"");
    let sine = scene("kind = \"sine\"\nc0 = 0.0\ncp = 0.005\nfreq_hz = 10.0\nperiods = 1.0\nover = \"cy\"", "");
    r(&sine, "creepage.over", "\"cy\"", "only with kind = \"sweep\"");
    let step = scene("kind = \"step\"\nc = 0.005\nsteps = 10\ndirection = [1, 0, 0]", "");
    r(&step, "creepage.direction", "[1, 0, 0]", "only with kind = \"sweep\"");
    // Every point in range, naming the end that leaves it and the creepage.
    r(&sweep("to = 2.0"), "creepage.to", "cx = 2", "cx and cy a finite number in [-1, 1]");
    r(&sweep("from = -1.5"), "creepage.from", "cx = -1.5", "[-1, 1]");
    r(&sweep("over = \"cy\"\ncy = 0.995"), "creepage.to", "cy = 1.005", "[-1, 1]");
    r(&sweep("over = \"cs\"\nto = 10.5"), "creepage.to", "cs = 10.5", "cs a finite number in [-10, 10]");
    r(&sweep("direction = [0, 0, -1e308]\nto = 1e10"), "creepage.to", "cs = -inf", "[-10, 10]");
    r(&sweep("from = 1e308\nto = -1e308"), "creepage.from", "1e308 (sweep point 1: cx = NaN)", "[-1, 1]");
    r(&sweep("from = inf"), "creepage.from", "inf", "finite number");
    // One point: only `from` is swept to.
    let one = scene("kind = \"sweep\"\nfrom = 0.5\nto = 7.0\npoints = 1", "");
    assert_eq!(creepages(&problem(&one)), vec![[0.5, 0.0, 0.0]]);
}

// ---- 2. Grid scale ------------------------------------------------------------------------------

#[test]
fn grid_scale_parses_and_sizes_the_grid() {
    let text =
        |extra: &str| scene("kind = \"step\"\nc = 0.005\nsteps = 4", "").replace("my = 10", &format!("my = 10{extra}"));
    let p1 = problem(&text(""));
    let explicit = problem(&text("\nscale = 1.0"));
    assert_eq!((p1.grid_scale, &p1.grid), (1.0, &explicit.grid), "scale 1 is the default grid, bit for bit");
    assert_eq!((p1.grid.half_x_mm, p1.grid.half_y_mm), (8.56, 4.08), "scale 1: the ellipse's bounding box");
    let p = problem(&text("\nscale = 1.5"));
    assert_eq!((p.grid.half_x_mm, p.grid.half_y_mm), (1.5 * 8.56, 1.5 * 4.08));
    assert_eq!((p.grid.dx_mm, p.grid.dy_mm), (2.0 * 1.5 * 8.56 / 10.0, 2.0 * 1.5 * 4.08 / 10.0));
    assert_eq!((p.hertz().a_mm, p.hertz().b_mm), (8.56, 4.08), "the contact is the scene's, not the grid's");
    assert_eq!(ResolvedScene::of(&p, &p.solvers).grid_scale, 1.5);
    let r = assert_refused;
    r(&text("\nscale = 0.5"), "grid.scale", "0.5", "[1, 10]");
    r(&text("\nscale = 10.5"), "grid.scale", "10.5", "[1, 10]");
    r(&text("\nscale = nan"), "grid.scale", "NaN", "[1, 10]");
    r(&text("\nscale = \"2\""), "grid.scale", "\"2\"", "[1, 10]");
}

/// `creepbench simulate` of a scene with scale 1.5 runs all its models and agrees with scale 1 on
/// grids of the same element size whose centres coincide (20 and 30 elements: the 1.5 grid adds
/// 5 elements on each side). Observed: contact 6.5e-10 (the iterative solves on differently sized
/// FFTs stop at their tolerance 1e-7 at different points), UBA and FASTSIM 1e-16 (the element
/// centres are computed from different extents), linear identical. 22 against 33 elements would
/// shift the centres by half an element: 1e-4, a discretisation difference, not a check.
#[test]
fn scaled_grid_agrees_with_the_nominal_grid_of_equal_elements() {
    let tmp = tempfile::tempdir().unwrap();
    let mut runs = Vec::new();
    for (name, m, scale) in [("s10", 20, 1.0), ("s15", 30, 1.5)] {
        let text = scene_text(
            name,
            "[\"uba\", \"fastsim\", \"contact\", \"linear\"]",
            0.4,
            m,
            "kind = \"step\"\nc = 0.002\nsteps = 40\ncy = 0.001\ncs = 0.01",
            "",
        )
        .replace(&format!("my = {m}"), &format!("my = {m}\nscale = {scale}"));
        let path = tmp.path().join(format!("{name}.toml"));
        std::fs::write(&path, text).unwrap();
        let out = tmp.path().join("out");
        let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .args(["simulate", path.to_str().unwrap(), "--out", out.to_str().unwrap()])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let json =
            ResolvedScene::from_json(&std::fs::read_to_string(out.join(name).join("scene.json")).unwrap()).unwrap();
        assert_eq!(json.grid_scale, scale);
        runs.push(out.join(name));
    }
    for (solver, tol) in [("contact", 1e-8), ("uba", 1e-14), ("fastsim", 1e-14), ("linear", 0.0)] {
        let read = |d: &Path| {
            creepbench::history::History::from_csv(
                solver,
                &std::fs::read_to_string(d.join(format!("{solver}.csv"))).unwrap(),
            )
            .unwrap()
        };
        let (a, b) = (read(&runs[0]), read(&runs[1]));
        assert_eq!(a.rows.len(), 40, "{solver}");
        for col in ["fx_over_fn", "fy_over_fn"] {
            let (d, k) = max_abs_diff(&a.column(col).unwrap(), &b.column(col).unwrap());
            println!("{solver} {col}: max |scale 1.5 − scale 1| = {d:.3e} at step {}", k + 1);
            assert!(d <= tol, "{solver} {col}: {d:e} at step {} (tolerance {tol:e})", k + 1);
        }
    }
}

/// The table's clipping warning fires only when the contact at its largest FN leaves the grid, and
/// then points to `[grid] scale`.
#[test]
fn clipping_warning_only_beyond_the_scaled_grid() {
    let tmp = tempfile::tempdir().unwrap();
    let warnings = |fn_max: f64, scale: f64| {
        let csv = tmp.path().join("t.csv");
        std::fs::write(&csv, format!("t_s,cx,fn_n\n0,0.001,100000\n0.01,0.001,{fn_max}\n")).unwrap();
        let text =
            scene("kind = \"table\"\nfile = \"t.csv\"", "").replace("my = 10", &format!("my = 10\nscale = {scale}"));
        let s = Scene::from_toml(&text, tmp.path()).unwrap();
        creepbench::pipeline::resolve(&s).unwrap().warnings
    };
    assert!(warnings(100000.0, 1.0).is_empty());
    assert!(warnings(80000.0, 1.0).is_empty());
    let w = warnings(150000.0, 1.0);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("clipped") && w[0].contains("[grid] scale = 1.145"), "{}", w[0]);
    // (1.5)^(1/3) = 1.1447: scale 1.2 holds the contact at 1.5 FN, 1.1 does not.
    assert!(warnings(150000.0, 1.2).is_empty());
    assert_eq!(warnings(150000.0, 1.1).len(), 1);
}

// ---- 3. A table covers its last row -------------------------------------------------------------

/// A table printed as CONTACT-style output does: t_k = k dt to 10 significant digits. Row 48's
/// time rounds down (0.03735272727 < 48 dt), which the old count floor(t_end/dt + 1e-9) lost.
#[test]
fn table_with_rounded_times_covers_every_row() {
    let tmp = tempfile::tempdir().unwrap();
    let dt = problem(&scene_on(22, "kind = \"step\"\nc = 0.005\nsteps = 1")).rolling.dt_s;
    let n = 48;
    let rows: Vec<(f64, f64, f64)> = (0..=n)
        .map(|k| {
            let t: f64 = format!("{:.9e}", k as f64 * dt).parse().unwrap();
            (t, 0.004 * (k as f64 / 5.0).sin(), 0.4 + 0.001 * k as f64)
        })
        .collect();
    assert!((rows[n].0 / dt + 1e-9).floor() < n as f64, "the old rule loses the last row");
    let csv: String = rows.iter().map(|(t, cx, mu)| format!("{t:.9e},{cx},{mu}\n")).collect();
    std::fs::write(tmp.path().join("t.csv"), format!("t_s,cx,mu\n{csv}")).unwrap();
    let text = scene_on(22, "kind = \"table\"\nfile = \"t.csv\"");
    let p = creepbench::pipeline::resolve(&Scene::from_toml(&text, tmp.path()).unwrap()).unwrap();
    assert_eq!(p.rolling.dt_s, dt);
    assert_eq!(p.loading.samples.len(), n, "every row's step");
    // At step k the time differs from row k's by its rounding (<= 5e-11 relative, 2e-12 s here);
    // with |dcx/dt| < 1.1 /s the interpolated value is within 3e-12 of the row.
    for s in &p.loading.samples {
        let (_, cx, mu) = rows[s.step];
        assert!((s.cx - cx).abs() < 1e-11 && (s.mu - mu).abs() < 1e-11, "step {}: {} vs {cx}", s.step, s.cx);
    }
    let last = p.loading.samples.last().unwrap();
    assert!(last.t_s > rows[n].0, "step 48 lies just beyond the last row");
    assert_eq!((last.cx, last.mu), (rows[n].1, rows[n].2), "there the last row holds exactly");
}

/// Within 1e-8 relative of the last time a step counts; beyond it, not.
#[test]
fn table_end_tolerance_is_relative_1e_8() {
    let tmp = tempfile::tempdir().unwrap();
    let dt = problem(&scene("kind = \"step\"\nc = 0.005\nsteps = 1", "")).rolling.dt_s;
    let steps = |t_end: f64| {
        std::fs::write(tmp.path().join("t.csv"), format!("t_s,cx\n0,0.001\n{t_end:e},0.002\n")).unwrap();
        let text = scene("kind = \"table\"\nfile = \"t.csv\"", "");
        Scene::from_toml(&text, tmp.path())
            .and_then(|s| creepbench::pipeline::resolve(&s))
            .map(|p| p.loading.samples.len())
    };
    assert_eq!(steps(20.0 * dt).unwrap(), 20);
    assert_eq!(steps(20.0 * dt * (1.0 - 0.5e-8)).unwrap(), 20);
    assert_eq!(steps(20.0 * dt * (1.0 - 2e-8)).unwrap(), 19);
    assert_eq!(steps(dt * (1.0 - 0.5e-8)).unwrap(), 1);
    let e = steps(dt * (1.0 - 2e-8)).unwrap_err();
    assert!(e.field == "creepage.file" && e.allowed.contains("at least one step"), "{e}");
}

/// Interpolation holds the first row before it and the last row beyond it.
#[test]
fn interpolation_clamps_to_the_first_and_last_rows() {
    let t = CreepageTable::from_csv("t_s,cx\n0.1,0.001\n0.2,0.003\n", "t").unwrap();
    assert_eq!(t.interpolate(t.cx.values(), 0.0), 0.001);
    assert!((t.interpolate(t.cx.values(), 0.15) - 0.002).abs() < 1e-15);
    assert_eq!(t.interpolate(t.cx.values(), 0.2), 0.003);
    assert_eq!(t.interpolate(t.cx.values(), 0.2 * (1.0 + 1e-9)), 0.003);
    assert_eq!(t.interpolate(t.cx.values(), 1.0), 0.003);
}

/// A table's `mu` column has `[contact] mu`'s range (0, 1000]: 1e300 was accepted. The error
/// names the table's file, the line and the column.
#[test]
fn a_tables_mu_has_the_range_of_contact_mu() {
    let e = CreepageTable::from_csv("t_s,cx,mu\n0,0.001,0.4\n0.001,0.001,1e300\n", "t.csv").unwrap_err();
    assert_eq!(e.field, "t.csv line 3 column mu", "{e}");
    // The value with its exponent (error::number), not 60 of its 301 digits.
    assert_eq!(e.value, "1e300", "{e}");
    assert!(e.allowed.contains("a coefficient of friction in (0, 1000]"), "{e}");
    assert!(CreepageTable::from_csv("t_s,cx,mu\n0,0.001,0.4\n0.001,0.001,1000\n", "t.csv").is_ok());
    let dir = tempdir("table_mu_range");
    let text = scene("kind = \"table\"\nfile = \"t.csv\"", "");
    std::fs::write(dir.join("s.toml"), text).unwrap();
    std::fs::write(dir.join("t.csv"), "t_s,cx,mu\n0,0.001,0.4\n0.001,0.001,1000.5\n").unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(&dir)
        .args(["simulate", "s.toml", "--out", "out"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("s.toml: creepage.file (t.csv) line 3 column mu` = 1000.5: allowed: a coefficient"), "{err}");
    assert!(!dir.join("out").exists());
}

/// A speed sweep's speeds have `[rolling] v_mm_s`'s range, its lower bound included: a speed
/// whose time step courant dx / v overflows (5e-324 mm/s) is refused as `rolling.v_mm_s` refuses
/// it, naming the entry of `at` or the end; 1e-300 mm/s (a finite step) passes.
#[test]
fn a_speed_sweep_has_the_speed_range_of_rolling() {
    let allowed = "a speed sweep's speeds as [rolling] v_mm_s: in (0, 1e6] mm/s with a finite time step";
    let at = "kind = \"sweep\"\nover = \"v_mm_s\"\nat = [1000.0, 5e-324]";
    assert_refused(&scene(at, ""), "creepage.at[1]", "5e-324 (sweep point 2: dt = inf s)", allowed);
    let ends = "kind = \"sweep\"\nover = \"v_mm_s\"\nfrom = 5e-324\nto = 1e-300\npoints = 3";
    assert_refused(&scene(ends, ""), "creepage.from", "5e-324 (sweep point 1", allowed);
    let rolling = "[rolling]\nv_mm_s = 5e-324\n";
    assert_refused(&scene("kind = \"step\"\nc = 0.001\nsteps = 4", rolling), "rolling.v_mm_s", "5e-324", "finite");
    let fine = scene("kind = \"sweep\"\nover = \"v_mm_s\"\nat = [1000.0, 1e-300]", "");
    problem(&fine);
}

/// A table row right after empty lines is named by its own line: the CSV reader gives it the
/// position of the first empty line (c6081a0 named line 3 for a row on line 5).
#[test]
fn a_table_row_right_after_empty_lines_names_its_line() {
    let e = CreepageTable::from_csv("t_s,cx,mu\n0,0.001,0.4\n\n\n0.001,0.001,1e300\n", "t.csv").unwrap_err();
    assert_eq!(e.field, "t.csv line 5 column mu", "{e}");
    let e = CreepageTable::from_csv("\r\nt_s,cx\r\n\r\n0.1,0.001\r\n\r\n0.1,0.003\r\n", "t.csv").unwrap_err();
    assert_eq!(e.field, "t.csv line 6 column t_s", "{e}");
}
