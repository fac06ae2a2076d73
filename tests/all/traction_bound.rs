//! Issue 32, CONTACT's B = 2, 3 (`[normal] pressure`): Hertz's pressure imposed in place of the
//! normal problem, the start row's pressure of its own (`start_pressure`), and the table's rows
//! that change F (cx and fx_over_fn per row) and DQ (courant per row) within a history.
//! References: Cattaneo–Mindlin's closed form on Hertz's own pressure (Johnson 1985, eqs. 7.28-29)
//! and full slip, whose force is μ times the imposed pressure's sum, over CONTACT's FN.

use crate::common::*;
use creepbench::history::History;
use creepbench::scene::Scene;

const G_MPA: f64 = 200.0;
const NU: f64 = 0.42;
const MU: f64 = 0.4;

/// Run the exact solver (or `solvers`) on a scene whose files sit in `dir`.
fn run_in(text: &str, dir: &std::path::Path) -> Result<History, String> {
    let scene = Scene::from_toml(text, dir).map_err(|e| e.to_string())?;
    let p = creepbench::pipeline::resolve(&scene).map_err(|e| e.to_string())?;
    Ok(run(&p, "contact"))
}

/// A Hertzian circle of radius 1 mm under 10 N on `n` × `n` elements over `scale` times it,
/// shifts (`motion`) or rolling, with `extra` tables.
fn circle(n: usize, scale: f64, motion: &str, creepage: &str, extra: &str) -> String {
    format!(
        "name = \"bound\"\nsolvers = [\"contact\"]\n[contact]\na_mm = 1.0\nb_mm = 1.0\nfn_n = 10.0\nmu = {MU}\n[material]\ng_mpa = {G_MPA:?}\npoisson = {NU}\n[grid]\nmx = {n}\nmy = {n}\nscale = {scale:?}\n[rolling]\nmotion = \"{motion}\"\n[creepage]\n{creepage}\n{extra}"
    )
}

/// On Hertz's own pressure the Cattaneo–Mindlin shift δ = 3μFN(2 − ν)/(8Ga)[1 − (1 − F/μFN)^(2/3)]
/// is met as on the solved pressure: the discretised edge costs O(dx) either way (and the pressure
/// sampled at the centres sums to slightly more than FN, to which the force is referred).
#[test]
fn cattaneo_mindlin_on_the_elliptical_pressure() {
    let ratio: f64 = 0.5;
    let delta_mm = 3.0 * MU * 10.0 * (2.0 - NU) / (8.0 * G_MPA) * (1.0 - (1.0f64 - ratio).powf(2.0 / 3.0));
    let creepage = format!("kind = \"step\"\nfx_over_fn = {:?}\nsteps = 1", ratio * MU);
    let mut errors = Vec::new();
    for pressure in ["solved", "elliptical"] {
        let dir = tempdir(&format!("bound_mindlin_{pressure}"));
        let text = circle(48, 1.0, "shift", &creepage, &format!("[normal]\npressure = \"{pressure}\"\n"));
        let h = run_in(&text, &dir).unwrap();
        let cx = h.column("cx").unwrap()[0];
        let pmax = h.column("pn_max_mpa").unwrap()[0];
        println!("{pressure}: shift {cx:.6e} vs Mindlin {delta_mm:.6e} ({:+.2e}), pmax {pmax}", cx / delta_mm - 1.0);
        errors.push((cx / delta_mm - 1.0).abs());
        if pressure == "elliptical" {
            // The element at the centre (48 even: at r = dx/√2) carries p0 √(1 − r²).
            let r2 = 2.0 * (1.0f64 / 48.0).powi(2);
            let p0 = 1.5 * 10.0 / std::f64::consts::PI;
            assert!((pmax - p0 * (1.0 - r2).sqrt()).abs() < 1e-12 * p0, "{pmax}");
        }
    }
    // Measured: solved −8.4e-4, elliptical −9.5e-4 (48 x 48 elements over the circle).
    assert!(errors[0] < 1e-3 && errors[1] < 1.1e-3, "{errors:?}");
}

/// Full slip (a shift 200 times Mindlin's, so that the elastic displacements barely turn the
/// slip away from x): every element at μ p; fx/fn is μ times the imposed
/// pressure's sum over FN, CONTACT's force over its prescribed FN (`m_soutpt.f90`), not μ. The
/// parabolic pressure likewise, with its own sum.
#[test]
fn full_slip_force_is_mu_times_the_sum_of_the_imposed_pressure_over_fn() {
    let grid = creepbench::physics::Grid::new(41, 41, 1.17143, 1.17143);
    for (pressure, shape) in [
        ("elliptical", creepbench::physics::PressureShape::Ellipsoidal),
        ("parabolic", creepbench::physics::PressureShape::Parabolic),
    ] {
        let dir = tempdir(&format!("bound_full_slip_{pressure}"));
        let text = circle(
            41,
            1.17143,
            "shift",
            "kind = \"step\"\nc = -0.9\nsteps = 1",
            &format!("[normal]\npressure = \"{pressure}\"\n"),
        );
        let h = run_in(&text, &dir).unwrap();
        let sum: f64 = shape.on_grid(&grid, 10.0, 1.0, 1.0).iter().sum::<f64>() * grid.element_area_mm2();
        let fx = h.column("fx_over_fn").unwrap()[0];
        println!("{pressure}: fx/fn {fx:.12} vs mu sum/FN {:.12}", MU * sum / 10.0);
        assert!(sum / 10.0 - 1.0 > 5e-5, "the sampled sum is not FN: {sum}");
        assert!((fx.abs() / (MU * sum / 10.0) - 1.0).abs() < 1e-7, "{fx}");
        assert_eq!(h.column("n_adhesion").unwrap()[0], 0.0);
    }
}

/// A shift start on the elliptical pressure, then rolling on the solved one: the start row is
/// solved on Hertz's pressure (its pn_max is p0 at the centre element, 41 odd), the steps on the
/// normal problem's.
#[test]
fn the_start_row_takes_its_own_pressure() {
    let dir = tempdir("bound_start_pressure");
    std::fs::write(dir.join("c.csv"), "t_s,fx_over_fn\n0,0.2\n0.0002,0.2\n").unwrap();
    let text = circle(
        41,
        1.2,
        "rolling",
        "kind = \"table\"\nfile = \"c.csv\"",
        "[init]\nkind = \"shift\"\n[normal]\nstart_pressure = \"elliptical\"\n",
    );
    let h = run_in(&text, &dir).unwrap();
    let pmax = h.column("pn_max_mpa").unwrap();
    let p0 = 1.5 * 10.0 / std::f64::consts::PI;
    assert_eq!(h.column("step").unwrap()[0], 0.0);
    assert!((pmax[0] - p0).abs() < 1e-12 * p0, "start {}", pmax[0]);
    assert!(pmax[1..].iter().all(|&p| p == pmax[1] && (p - p0).abs() > 1e-4 * p0), "{pmax:?}");
}

/// A table whose rows prescribe the force in some and the creepage in others, and change the
/// rolling distance (courant): each row is solved as it says, step k lasts courant_k dx / v.
#[test]
fn rows_change_the_force_and_the_step() {
    let dir = tempdir("bound_rows");
    let dx = 2.0 * 1.2 / 41.0;
    // t_1 = 0.5 dx/v, t_2 = t_1 + 2 dx/v with v = 1000 mm/s; each value held around its time.
    let (t1, t2) = (0.5 * dx / 1000.0, 2.5 * dx / 1000.0);
    let table = format!(
        "t_s,cx,fx_over_fn,courant\n0,,0.2,0.5\n{:?},,0.2,0.5\n{:?},0.001,,2.0\n{:?},0.001,,2.0\n",
        t1 + 0.1 * t1,
        t2 - 0.2 * (t2 - t1),
        t2 + 0.2 * (t2 - t1)
    );
    std::fs::write(dir.join("c.csv"), &table).unwrap();
    let h = run_in(&circle(41, 1.2, "rolling", "kind = \"table\"\nfile = \"c.csv\"", ""), &dir).unwrap();
    let (t, cx, fx) = (h.column("t_s").unwrap(), h.column("cx").unwrap(), h.column("fx_over_fn").unwrap());
    assert_eq!(t.len(), 2, "{t:?}");
    assert!((t[0] - t1).abs() < 1e-15 && (t[1] - t2).abs() < 1e-15, "{t:?}");
    assert!((fx[0] - 0.2).abs() < 1e-6, "row 1 prescribes the force: {}", fx[0]);
    assert_eq!(cx[1], 0.001, "row 2 gives the creepage");
    assert!(fx[1] > 0.0 && fx[1] < MU);
    // The step's own rolling distance is used: the same rows with courant 0.5 throughout roll
    // less in step 2 (and reach another force).
    let slow = table.replace(",2.0\n", ",0.5\n");
    std::fs::write(dir.join("c.csv"), &slow).unwrap();
    let h2 = run_in(&circle(41, 1.2, "rolling", "kind = \"table\"\nfile = \"c.csv\"", ""), &dir).unwrap();
    let fx2 = h2.column("fx_over_fn").unwrap();
    assert_eq!(fx2[0].to_bits(), fx[0].to_bits(), "the same first step");
    assert!((fx2[1] - fx[1]).abs() > 1e-3, "{} vs {}", fx2[1], fx[1]);
}

#[test]
fn refusals_name_the_key() {
    let dir = tempdir("bound_refusals");
    std::fs::write(dir.join("c.csv"), "t_s,cx,fx_over_fn\n0.001,0.001,0.1\n").unwrap();
    let table = "kind = \"table\"\nfile = \"c.csv\"";
    let err = |text: &str| run_in(text, &dir).unwrap_err();
    let e = err(&circle(20, 1.0, "rolling", table, ""));
    assert!(e.contains("columns cx, fx_over_fn") && e.contains("both given"), "{e}");
    let step = "kind = \"step\"\nc = 0.001\nsteps = 1";
    let e = err(&circle(20, 1.0, "rolling", step, "[normal]\nstart_pressure = \"elliptical\"\n"));
    assert!(e.contains("normal.start_pressure") && e.contains("without a start row"), "{e}");
    let e = err(&circle(20, 1.0, "rolling", step, "[normal]\npressure = \"hertz\"\n"));
    assert!(e.contains("normal.pressure"), "{e}");
    let uba =
        circle(20, 1.0, "rolling", step, "[normal]\npressure = \"elliptical\"\n").replace("[\"contact\"]", "[\"uba\"]");
    let e = err(&uba);
    assert!(e.contains("normal.pressure") && e.contains("only with the exact model"), "{e}");
    std::fs::write(dir.join("d.csv"), "t_s,cx,courant\n0.001,0.001,1.0\n").unwrap();
    let uba =
        circle(20, 1.0, "rolling", "kind = \"table\"\nfile = \"d.csv\"", "").replace("[\"contact\"]", "[\"fastsim\"]");
    let e = err(&uba);
    assert!(e.contains("column courant") && e.contains("only with the exact model"), "{e}");
}
