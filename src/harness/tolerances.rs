//! Every tolerance of the gates, in one reviewed place. A comparison passes when
//! `|ours − theirs| ≤ abs + rel·|theirs|`. Changing a number here is a reviewed decision: say why.

use super::against::Against;
use super::tolerance_file::glob;

/// One rule: which comparison it covers, its tolerance, and whether a miss fails the gate.
#[derive(Debug, Clone, Copy)]
pub struct Rule {
    pub against: Against,
    /// Scene name or `*` pattern ([`glob`], as in tolerance files).
    pub scene: &'static str,
    /// Solver name, or "*" for any.
    pub solver: &'static str,
    /// Column (`fx_over_fn`, `fy_over_fn`, `iterations`) or metric name, or "*" for any.
    pub quantity: &'static str,
    pub abs: f64,
    pub rel: f64,
    /// A miss fails `creepbench check` (exit 1); otherwise it is only reported.
    pub gated: bool,
    pub why: &'static str,
}

impl Rule {
    /// Allowed |difference| for a reference value.
    pub fn allowed(&self, theirs: f64) -> f64 {
        self.abs + self.rel * theirs.abs()
    }
}

const INF: f64 = f64::INFINITY;

/// The rules, first match wins.
pub const RULES: &[Rule] = &[
    // Regression against this project's own blessed results (and `check --against DIR`).
    Rule { scene: "*", against: Against::Golden, solver: "*", quantity: "iterations", abs: 2.0, rel: 0.05, gated: true, why: "iteration counts are a drift signal of the CONTACT-style solver; a few iterations of slack for floating-point differences between CPUs" },
    Rule { scene: "*", against: Against::Golden, solver: "*", quantity: "residual", abs: INF, rel: 0.0, gated: false, why: "final residuals are reported, not gated" },
    Rule { scene: "*", against: Against::Golden, solver: "*", quantity: "*", abs: 1e-9, rel: 1e-7, gated: true, why: "results are deterministic; the slack only absorbs floating-point differences between CPUs and libm versions" },
    // CONTACT's exact theory on identical grids (issue 3).
    Rule { scene: "*", against: Against::Reference("CONTACT"), solver: "contact", quantity: "fx_over_fn", abs: 1e-5, rel: 0.0, gated: true, why: "issue 12: the exact solver within 1e-5 of CONTACT at every step (issue 3 asked for 0.002; the solver reproduces CONTACT to 4e-7)" },
    Rule { scene: "*", against: Against::Reference("CONTACT"), solver: "contact", quantity: "delay_ratio", abs: 0.005, rel: 0.0, gated: true, why: "issue 3: delay ratios within 0.005 of CONTACT's" },
    Rule { scene: "*", against: Against::Reference("CONTACT"), solver: "contact", quantity: "loop_area", abs: 0.0, rel: 0.02, gated: true, why: "issue 3: loop areas within 2 %" },
    Rule { scene: "*", against: Against::Reference("CONTACT"), solver: "contact", quantity: "steady_value", abs: 1e-5, rel: 0.0, gated: true, why: "same bound as every step" },
    // Known gaps, measured and open (issue 12): the first step after a steady start at which the
    // friction or the load changes is off by these amounts (the error decays over one contact
    // length; every other step of these cases is within 1e-6). Each rule names its scene; delete it
    // when the gap closes.
    Rule { scene: "mu_ramp", against: Against::Reference("CONTACT envelope"), solver: "contact", quantity: "fx_over_fn", abs: 1.5e-3, rel: 0.0, gated: true, why: "KNOWN GAP (issue 12): 1.39e-3 at step 1, mu 0.4 -> 0.394 right after the steady start; target 1e-5" },
    Rule { scene: "fn_sine_f20", against: Against::Reference("CONTACT envelope"), solver: "contact", quantity: "fx_over_fn", abs: 1.5e-4, rel: 0.0, gated: true, why: "KNOWN GAP (issue 12): 1.36e-4 at step 1, FN 100 -> 99.88 kN right after the steady start; target 1e-5" },
    // CONTACT's exact theory beyond the thesis family (issue 12): every step, both components and
    // the spin moment made dimensionless by FN a.
    Rule { scene: "*", against: Against::Reference("CONTACT envelope"), solver: "contact", quantity: "fx_over_fn", abs: 1e-5, rel: 0.0, gated: true, why: "issue 12: the exact solver within 1e-5 of CONTACT in fx/fn at every step of every envelope case" },
    Rule { scene: "*", against: Against::Reference("CONTACT envelope"), solver: "contact", quantity: "fy_over_fn", abs: 1e-5, rel: 0.0, gated: true, why: "issue 12: fy/fn likewise" },
    Rule { scene: "*", against: Against::Reference("CONTACT envelope"), solver: "contact", quantity: "mz_over_fn_a", abs: 1e-5, rel: 0.0, gated: true, why: "issue 12: the spin moment gated like f, as mz/(FN a)" },
    Rule { scene: "*", against: Against::Reference("CONTACT envelope"), solver: "*", quantity: "*", abs: INF, rel: 0.0, gated: false, why: "the fast models against the exact theory on the envelope: reported per case, not gated (issue 12)" },
    // CONTACT's exact theory on non-Hertzian contacts (issue 13): as the envelope.
    Rule { scene: "*", against: Against::Reference("CONTACT non-Hertzian"), solver: "contact", quantity: "fx_over_fn", abs: 1e-5, rel: 0.0, gated: true, why: "issue 13: the exact solver within 1e-5 of CONTACT in fx/fn at every step of every non-Hertzian case" },
    Rule { scene: "*", against: Against::Reference("CONTACT non-Hertzian"), solver: "contact", quantity: "fy_over_fn", abs: 1e-5, rel: 0.0, gated: true, why: "issue 13: fy/fn likewise" },
    Rule { scene: "*", against: Against::Reference("CONTACT non-Hertzian"), solver: "contact", quantity: "mz_over_fn_a", abs: 1e-5, rel: 0.0, gated: true, why: "issue 13: the spin moment as mz/(FN a), a the equivalent ellipse's" },
    Rule { scene: "*", against: Against::Reference("CONTACT non-Hertzian"), solver: "*", quantity: "*", abs: INF, rel: 0.0, gated: false, why: "the fast models on non-Hertzian contacts: reported per case, not gated (issue 13)" },
    // CONTACT's FASTSIM with the parabolic bound (issue 2).
    Rule { scene: "*", against: Against::Reference("CONTACT FASTSIM"), solver: "fastsim", quantity: "fx_over_fn", abs: 0.0015, rel: 0.0, gated: true, why: "issue 2: FASTSIM within 0.0015 of CONTACT's FASTSIM at every creepage" },
    Rule { scene: "*", against: Against::Reference("CONTACT FASTSIM"), solver: "uba", quantity: "fx_over_fn", abs: 0.0015, rel: 0.0, gated: true, why: "the steady UBA is FASTSIM's grid march (same discretisation)" },
    // The simplified models against the exact theory, and the thesis's figures: reported, not gated.
    Rule { scene: "*", against: Against::Reference("CONTACT"), solver: "*", quantity: "*", abs: INF, rel: 0.0, gated: false, why: "simplified models differ from the exact theory by design; the report shows by how much" },
    Rule { scene: "*", against: Against::Reference("CONTACT FASTSIM"), solver: "*", quantity: "*", abs: INF, rel: 0.0, gated: false, why: "reported" },
    Rule { scene: "*", against: Against::Reference("thesis"), solver: "*", quantity: "*", abs: INF, rel: 0.0, gated: false, why: "the thesis's figures were read off its plots and used another grid treatment; reported beside ours" },
];

/// The first rule covering this comparison.
pub fn rule(against: Against, scene: &str, solver: &str, quantity: &str) -> Rule {
    let against_key = if against == Against::Previous { Against::Golden } else { against };
    *RULES
        .iter()
        .find(|r| {
            r.against == against_key && glob(r.scene, scene) && glob(r.solver, solver) && glob(r.quantity, quantity)
        })
        .unwrap_or(&Rule {
            scene: "*",
            against,
            solver: "*",
            quantity: "*",
            abs: INF,
            rel: 0.0,
            gated: false,
            why: "no rule",
        })
}
