//! FASTSIM and the UBA against CONTACT's FASTSIM, Kalker's linear theory and each other.

use crate::common;
use common::*;
use creepbench::physics::project_to_bound;
use creepbench::solvers::brush::Tractions;
use creepbench::solvers::uba;

const SWEEP: &str = "kind = \"sweep\"\nfrom = 0.0\nto = 0.01\npoints = 101";

/// FASTSIM at 22×22 with Table A1 coefficients against CONTACT's FASTSIM (parabolic bound B = 3):
/// |Δf| ≤ 0.0015 at every creepage (measured 9.1e-5).
#[test]
fn fastsim_matches_contact_fastsim() {
    let p = problem(&scene_text("fs", "[\"fastsim\"]", 0.4, 22, SWEEP, ""));
    let ours = f(&run(&p, "fastsim"));
    let theirs = reference("steady_fastsim_g22", "fx_over_fn");
    let (err, k) = max_abs_diff(&ours, &theirs);
    println!("FASTSIM vs CONTACT FASTSIM: max |df| = {err:.3e} at cx = {:.4}", k as f64 * 1e-4);
    let rule = creepbench::comparison::tolerances::rule(
        creepbench::comparison::references::contact::FASTSIM,
        "steady_fastsim_g22",
        "fastsim",
        "fx_over_fn",
    );
    assert!(err <= rule.abs, "max |df| = {err} at point {k}");
}

/// Small-creepage slope of FASTSIM = Kalker's linear theory f = G a b c11 cx / FN within 1 %:
/// at 22×22 integrating from the exact leading edge, and with the grid edge on a fine grid
/// (the grid edge adds half an element per row: +5 % at 22, first order in dx).
#[test]
fn fastsim_slope_is_linear_theory() {
    let mut bias = Vec::new();
    for (grid, edge) in [(22, "exact"), (200, "grid"), (22, "grid"), (88, "grid")] {
        let extra = format!("[model]\nleading_edge = \"{edge}\"");
        let p = problem(&scene_text(
            "slope",
            "[\"fastsim\"]",
            0.4,
            grid,
            "kind = \"sweep\"\nfrom = 1e-7\nto = 1e-7\npoints = 1",
            &extra,
        ));
        let f0 = f(&run(&p, "fastsim"))[0];
        let c11 = p.coefficients.c11;
        let linear = p.material.g_mpa * p.hertz().a_mm * p.hertz().b_mm * c11 * 1e-7 / p.hertz().fn_n;
        let ratio = f0 / linear;
        println!("grid {grid} edge {edge}: slope / linear theory = {ratio:.5} (c11 = {c11:.4})");
        if edge == "exact" || grid == 200 {
            assert!((ratio - 1.0).abs() < 0.01, "grid {grid} {edge}: {f0} vs {linear}");
        } else {
            bias.push(ratio - 1.0);
        }
    }
    // The grid edge's bias is positive and first order in dx: 22 → 88 divides it by about 4.
    assert!(bias[0] > 0.0 && bias[1] > 0.0 && (3.0..5.0).contains(&(bias[0] / bias[1])), "{bias:?}");
}

/// The steady UBA converges to FASTSIM with refinement (first order in dx) when FASTSIM starts
/// at the exact leading edge, and equals it to round-off when both share the grid's edge.
#[test]
fn steady_uba_converges_to_fastsim() {
    let mut errs = Vec::new();
    for grid in [22, 88] {
        let uba_p = problem(&scene_text("u", "[\"uba\"]", 0.4, grid, SWEEP, ""));
        let fs_exact =
            problem(&scene_text("f", "[\"fastsim\"]", 0.4, grid, SWEEP, "[model]\nleading_edge = \"exact\""));
        let fs_grid = problem(&scene_text("f", "[\"fastsim\"]", 0.4, grid, SWEEP, ""));
        let u = f(&run(&uba_p, "uba"));
        let (e_exact, _) = max_abs_diff(&u, &f(&run(&fs_exact, "fastsim")));
        let (e_grid, _) = max_abs_diff(&u, &f(&run(&fs_grid, "fastsim")));
        println!("grid {grid}: |UBA - FASTSIM(exact edge)| = {e_exact:.5}, shared grid edge: {e_grid:.1e}");
        assert!(e_grid < 1e-12, "shared discretisation must agree to round-off: {e_grid}");
        errs.push(e_exact);
    }
    assert!(errs[0] <= 0.012, "22x22: {}", errs[0]);
    assert!(errs[1] <= 0.0035, "88x88: {}", errs[1]);
    // First order: a 4x finer grid divides the gap by about 4.
    let order = (errs[0] / errs[1]).ln() / 4f64.ln();
    assert!((0.8..1.3).contains(&order), "observed order {order}");
}

/// f is odd in the creepage, for the UBA (transient, sine with sign changes) and FASTSIM.
#[test]
fn traction_is_odd_in_creepage() {
    for solver in ["uba", "fastsim"] {
        let sine = |c0: f64, cp: f64| {
            format!(
                "kind = \"sine\"\nc0 = {c0}\ncp = {cp}\nfreq_hz = 30.0\nperiods = 2.0\ncy = {}\ncs = {}",
                c0 * 0.3,
                c0 * 0.01
            )
        };
        let s = format!("[\"{solver}\"]");
        let pos =
            f(&run(&problem(&scene_text("o", &s, 0.4, 22, &sine(0.002, 0.004), "[init]\nkind = \"steady\"")), solver));
        let neg = f(&run(
            &problem(&scene_text("o", &s, 0.4, 22, &sine(-0.002, -0.004), "[init]\nkind = \"steady\"")),
            solver,
        ));
        let worst = pos.iter().zip(&neg).map(|(a, b)| (a + b).abs()).fold(0.0, f64::max);
        assert!(worst < 1e-14, "{solver}: f(c) + f(-c) up to {worst}");
        assert!(pos.iter().any(|&x| x < 0.0) && pos.iter().any(|&x| x > 0.0), "history must change sign");
    }
}

/// |τ| ≤ μ p at every element after every step, also with spin and lateral creepage.
#[test]
fn uba_respects_the_traction_bound() {
    let p = problem(&scene_text(
        "b",
        "[\"uba\"]",
        0.3,
        22,
        "kind = \"step\"\nc = 0.02\nsteps = 50\ncy = -0.01\ncs = 0.002",
        "",
    ));
    let local = p.local_contact(p.hertz().fn_n);
    let (mut t, mut u) = (Tractions::zero(p.grid.len()), Tractions::zero(p.grid.len()));
    let rates = creepbench::solvers::brush::rates(0.02, -0.01, 0.002, &local.flex);
    let mut prep = uba::Prepared::new(&p.grid, &local, 0.3);
    for _ in 0..50 {
        uba::step((&p.grid, &local.planform), &mut prep, &rates, (1.0, p.model.leading_edge), &u, &mut t);
        std::mem::swap(&mut t, &mut u);
        let t = &u;
        for k in 0..p.grid.len() {
            let g = 0.3 * local.planform.pressure_mpa[k];
            let m = (t.tx[k].powi(2) + t.ty[k].powi(2)).sqrt();
            assert!(m <= g * (1.0 + 1e-12), "element {k}: |tau| {m} > mu p {g}");
            if local.planform.pressure_mpa[k] == 0.0 {
                assert_eq!((t.tx[k], t.ty[k]), (0.0, 0.0));
            }
        }
    }
    // Full slip without spin: the whole patch on the bound in one direction, |f| = μ.
    let p = problem(&scene_text("b", "[\"uba\"]", 0.3, 22, "kind = \"step\"\nc = 0.4\nsteps = 30\ncy = -0.3", ""));
    let h = run(&p, "uba");
    let last = f(&h).last().copied().unwrap();
    let fy = h.column("fy_over_fn").unwrap().last().copied().unwrap();
    assert!(((last * last + fy * fy).sqrt() - 0.3).abs() < 1e-12, "|f| at full slip {last}, {fy}");
    assert!(
        (fy / last + 0.75 * p.flexibilities().l1_mm3_n / p.flexibilities().l2_mm3_n).abs() < 1e-9,
        "slip direction"
    );
    assert_eq!(project_to_bound(2.0, 0.0, 1.0).0, 1.0);
}

/// At courant 1 a step response reaches its steady state within one transit (mx steps), to round-off.
#[test]
fn uba_step_settles_in_one_transit() {
    for (c, mu) in [(0.005, 0.4), (0.0002, 1.0), (0.01, 0.4)] {
        let step = format!("kind = \"step\"\nc = {c}\nsteps = 30");
        let hist = f(&run(&problem(&scene_text("s", "[\"uba\"]", mu, 22, &step, "")), "uba"));
        let sweep = format!("kind = \"sweep\"\nfrom = {c}\nto = {c}\npoints = 1");
        let steady = f(&run(&problem(&scene_text("s", "[\"uba\"]", mu, 22, &sweep, "")), "uba"))[0];
        let settled = hist.iter().position(|x| (x - steady).abs() < 1e-14).unwrap();
        println!("c {c} mu {mu}: steady {steady:.6} reached at step {}", settled + 1);
        assert!(settled < 22, "after mx = 22 steps: {} vs steady {steady}", hist[21]);
        assert!(hist[settled..].iter().all(|x| (x - steady).abs() < 1e-14), "stays there");
        // Thesis Table 4.3: the 29th and 30th steps agree (0.399757… there, see docs).
        assert_eq!(hist[28], hist[29]);
    }
    // In full adhesion the longest row (22 loaded elements) needs exactly one transit.
    let hist =
        f(&run(&problem(&scene_text("s", "[\"uba\"]", 1.0, 22, "kind = \"step\"\nc = 0.0002\nsteps = 30", "")), "uba"));
    assert!((hist[20] - hist[29]).abs() > 1e-9 && (hist[21] - hist[29]).abs() < 1e-14);
}

/// With courant < 1 the scheme converges to the same steady state (the march is its fixed point).
#[test]
fn uba_small_courant_converges_to_the_same_steady_state() {
    let extra = "[rolling]\nv_mm_s = 1000.0\ncourant = 0.5";
    let p = problem(&scene_text("c", "[\"uba\"]", 0.4, 22, "kind = \"step\"\nc = 0.003\nsteps = 400", extra));
    let hist = f(&run(&p, "uba"));
    let sw =
        problem(&scene_text("c", "[\"uba\"]", 0.4, 22, "kind = \"sweep\"\nfrom = 0.003\nto = 0.003\npoints = 1", ""));
    let steady = f(&run(&sw, "uba"))[0];
    assert!((hist.last().unwrap() - steady).abs() < 1e-10, "{} vs {steady}", hist.last().unwrap());
}

/// Thesis 4.2.2: a larger μ takes longer to settle (UBA, step 0.005, μ 0.1 … 0.6).
#[test]
fn larger_mu_settles_later() {
    let mut last = 0.0;
    for mu in [0.1, 0.2, 0.3, 0.4, 0.5, 0.6] {
        let text = scene_text("m", "[\"uba\"]", mu, 22, "kind = \"step\"\nc = 0.005\nsteps = 44", "");
        let p = problem(&format!("metrics = [\"settling_time_s\"]\n{text}"));
        let m = creepbench::metrics::compute(&p.metrics, &p.loading, &run(&p, "uba"), &[]);
        let ts = m.iter().find(|m| m.name == "settling_time_s").unwrap().value;
        println!("mu {mu}: settling {ts:.5} s");
        assert!(ts > last, "mu {mu}: {ts} s not later than {last} s");
        last = ts;
    }
}

/// The steady initial state is the steady march at the creepage of t = 0.
#[test]
fn steady_initial_state() {
    let p = problem(&scene_text(
        "i",
        "[\"uba\", \"fastsim\"]",
        1.0,
        22,
        "kind = \"sine\"\nc0 = 0.005\ncp = 0.005\nfreq_hz = 10.0\nperiods = 1.0",
        "[init]\nkind = \"steady\"",
    ));
    let (u, fs) = (run(&p, "uba"), run(&p, "fastsim"));
    assert_eq!(u.rows[0].sample.step, 0);
    assert!((u.rows[0].fx_over_fn - fs.rows[0].fx_over_fn).abs() < 1e-14);
    // CONTACT's steady state at cx = 0.005, mu = 1 (sine_f10_mu10 step 0) for scale: 0.6082.
    let contact0 = reference("sine_f10_mu10", "fx_over_fn")[0];
    assert!((u.rows[0].fx_over_fn - contact0).abs() < 0.02, "{} vs CONTACT {contact0}", u.rows[0].fx_over_fn);
}

/// FASTSIM with Kalker's single flexibility (Kalker 1982, `[model] flexibilities = "one"`):
/// L = (|cx| L1 + |cy| L2 + c |cs| L3)/√(cx² + cy² + c² cs²), so one creepage alone gives that
/// component's own flexibility (the three-flexibility result), and in the linear range (no slip)
/// each force scales by L_i / L exactly.
#[test]
fn fastsim_with_one_flexibility() {
    let sweep = |over: &str, extra: &str| {
        let creepage = format!("kind = \"sweep\"\nover = \"{over}\"\nfrom = 1e-6\nto = 1e-6\npoints = 1");
        let p = problem(&scene_text("one", "[\"fastsim\"]", 0.3, 22, &creepage, extra));
        let h = run(&p, "fastsim");
        (h.rows[0].fx_over_fn, h.rows[0].fy_over_fn, p)
    };
    let one = "[model]\nflexibilities = \"one\"";
    for over in ["cx", "cy", "cs"] {
        let ((x3, y3, _), (x1, y1, _)) = (sweep(over, ""), sweep(over, one));
        let scale = x3.abs().max(y3.abs());
        assert!(
            (x1 - x3).abs() <= 1e-12 * scale && (y1 - y3).abs() <= 1e-12 * scale,
            "{over}: ({x1}, {y1}) vs ({x3}, {y3})"
        );
    }
    // cx = cy: L = (L1 + L2)/√2.
    let creepage = "kind = \"sweep\"\ndirection = [1.0, 1.0, 0.0]\nfrom = 1e-6\nto = 1e-6\npoints = 1";
    let p3 = problem(&scene_text("three", "[\"fastsim\"]", 0.3, 22, creepage, ""));
    let p1 = problem(&scene_text("one", "[\"fastsim\"]", 0.3, 22, creepage, one));
    let (h3, h1) = (run(&p3, "fastsim"), run(&p1, "fastsim"));
    let f = p3.flexibilities();
    let l = (f.l1_mm3_n + f.l2_mm3_n) / 2f64.sqrt();
    let (rx, ry) = (h1.rows[0].fx_over_fn / h3.rows[0].fx_over_fn, h1.rows[0].fy_over_fn / h3.rows[0].fy_over_fn);
    assert!((rx - f.l1_mm3_n / l).abs() < 1e-9 && (ry - f.l2_mm3_n / l).abs() < 1e-9, "{rx} {ry}");
}

/// The modified FASTSIM (`[model] slope_reduction = [k0, α, β]`, Spiryagin et al. 2013 as in
/// CONTACT): with α = 1 the flexibilities are divided by k0, so in the linear range the forces
/// scale by k0 exactly; the factor follows k0 (α + (1 − α)/(1 + β ε)); bad triples are refused.
#[test]
fn modified_fastsim_slope_reduction() {
    let creepage = "kind = \"sweep\"\ndirection = [1.0, 0.5, 0.0]\nfrom = 1e-6\nto = 1e-6\npoints = 1";
    let plain = problem(&scene_text("p", "[\"fastsim\"]", 0.3, 22, creepage, ""));
    let reduced =
        problem(&scene_text("r", "[\"fastsim\"]", 0.3, 22, creepage, "[model]\nslope_reduction = [0.6, 1.0, 5.0]"));
    let (h0, h1) = (run(&plain, "fastsim"), run(&reduced, "fastsim"));
    for (a, b) in [(h0.rows[0].fx_over_fn, h1.rows[0].fx_over_fn), (h0.rows[0].fy_over_fn, h1.rows[0].fy_over_fn)] {
        assert!((b / a - 0.6).abs() < 1e-12, "{b} / {a}");
    }
    // The factor against the formula, by hand: ε = G π a b k0 C11 w / (4 μ FN).
    let p = problem(&scene_text("r", "[\"fastsim\"]", 0.3, 22, creepage, "[model]\nslope_reduction = [0.8, 0.4, 2.0]"));
    let local = p.local_contact(p.hertz().fn_n);
    let slope = local.slope.expect("asked for");
    let (h, c11, g) = (p.hertz(), p.coefficients.c11, p.material.g_mpa);
    let (cx, cy, cs) = (0.002, 0.001, 0.0001);
    let w = (cx * cx + (cy + h.a_mm * cs).powi(2)).sqrt();
    let eps = g * std::f64::consts::PI * h.a_mm * h.b_mm * 0.8 * c11 * w / (4.0 * 0.3 * h.fn_n);
    let k = 0.8 * (0.4 + 0.6 / (1.0 + 2.0 * eps));
    assert!((slope.factor((cx, cy, cs), 0.3) - k).abs() < 1e-14, "{} vs {k}", slope.factor((cx, cy, cs), 0.3));
    // Spin against the lateral creepage: ν = cy where |cy + a cs| < |cy|.
    assert_eq!(slope.factor((0.0, 0.001, -1e-5), 0.3), slope.factor((0.0, 0.001, 0.0), 0.3));
    for bad in ["[0.0, 0.5, 1.0]", "[1.0, 1.5, 1.0]", "[1.0, 0.5, -1.0]"] {
        let text = scene_text("r", "[\"fastsim\"]", 0.3, 22, creepage, &format!("[model]\nslope_reduction = {bad}"));
        let e = creepbench::scene::Scene::from_toml(&text, std::path::Path::new(".")).unwrap_err().to_string();
        assert!(e.contains("model.slope_reduction"), "{bad}: {e}");
    }
}
