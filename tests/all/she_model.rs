//! The Shen–Hedrick–Elkins law as a built-in model (issue 14, the model ladder): on a cx sweep its
//! coefficient is μ (ε − ε²/3 + ε³/27) of the linear theory's ε = |f_lin|/μ (taken from the
//! linear model where that is unsaturated), μ from ε = 3 on, and spin enters through Fy as in the
//! linear theory.

use crate::common;
use common::*;
use creepbench::solvers::she::law;

#[test]
fn she_saturates_the_linear_theory() {
    let mu = 0.4;
    let creepage = "kind = \"sweep\"\nfrom = 0.0\nto = 0.02\npoints = 41";
    let p = problem(&scene_text("she", "[\"linear\", \"she\"]", mu, 22, creepage, ""));
    let (lin, she) = (run(&p, "linear"), run(&p, "she"));
    let slope = lin.rows[1].fx_over_fn / lin.rows[1].sample.cx;
    let mut checked = 0;
    for (l, s) in lin.rows.iter().zip(&she.rows) {
        let eps = slope * l.sample.cx / mu;
        let expected = mu * law(eps);
        assert!((s.fx_over_fn - expected).abs() < 1e-12, "cx {}: {} vs {expected}", l.sample.cx, s.fx_over_fn);
        if eps < 1.0 {
            // The linear model is unsaturated here: the same ε from its own output.
            assert!((l.fx_over_fn / mu - eps).abs() < 1e-12);
        }
        if eps >= 3.0 {
            assert!((s.fx_over_fn - mu).abs() < 1e-15, "{}", s.fx_over_fn);
        }
        checked += 1;
    }
    assert_eq!(checked, 41);
    // Pure spin: Fy from C23 as in the linear theory, saturated along the resultant.
    let spin = problem(&scene_text(
        "she_cs",
        "[\"linear\", \"she\"]",
        mu,
        22,
        "kind = \"sweep\"\nover = \"cs\"\nfrom = 1e-5\nto = 1e-5\npoints = 1",
        "",
    ));
    let (l, s) = (run(&spin, "linear").rows[0].fy_over_fn, run(&spin, "she").rows[0].fy_over_fn);
    assert!(l > 0.0 && (s - mu * law(l / mu)).abs() < 1e-12, "linear {l}, she {s}");
}
