//! The gate's verdict in the forms CI systems read (issue 15): JUnit XML (one test case per scene ×
//! solver × comparison, a failure carrying the worst gated point), the complete findings as JSON,
//! and a short Markdown summary (for `$GITHUB_STEP_SUMMARY`). Pure functions of the findings.

use crate::comparison::compare::Finding;
use crate::comparison::tolerance_file::Loosening;
use crate::error::{deviation, number};
use std::collections::BTreeMap;
use std::fmt::Write;

/// (scene, solver, comparison label).
type Key = (String, String, &'static str);
/// One scene × solver of a comparison: scene, solver, its findings.
type Case<'a> = (String, String, Vec<&'a Finding>);

/// The findings grouped by (scene, solver, comparison), in that order.
fn groups(all: &[Finding]) -> BTreeMap<Key, Vec<&Finding>> {
    let mut out: BTreeMap<Key, Vec<&Finding>> = BTreeMap::new();
    for f in all {
        out.entry((f.scene.clone(), f.solver.clone(), f.against.label())).or_default().push(f);
    }
    out
}

/// The worst finding of a group: a failed gated one first, then by severity.
fn worst<'a>(fs: &[&'a Finding]) -> &'a Finding {
    let failed = |f: &Finding| f.gated && !f.passed();
    fs.iter()
        .copied()
        .max_by(|a, b| failed(a).cmp(&failed(b)).then(a.severity().total_cmp(&b.severity())))
        .expect("a group holds at least one finding")
}

/// One line describing a finding's worst point.
pub fn describe(f: &Finding) -> String {
    let step = f.step.map_or("-".to_string(), |s| s.to_string());
    if f.diff.is_nan() && f.ours.is_nan() && f.theirs.is_nan() {
        return format!("{} step {step}: unmatched: {}", f.quantity, f.note);
    }
    let mut s = format!(
        "{} step {step}: ours {} vs {} {}, |diff| {}, allowed {}",
        f.quantity,
        number(f.ours),
        f.against.label(),
        number(f.theirs),
        deviation(f.diff),
        deviation(f.allowed)
    );
    if !f.note.is_empty() {
        let _ = write!(s, " ({})", f.note);
    }
    s
}

/// XML text and attribute escaping.
fn xml(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// JUnit XML (the common schema of Jenkins, GitLab and GitHub reporters): one `testsuite` per
/// comparison kind, one `testcase` per scene × solver; a test case fails when a gated quantity
/// misses its tolerance, its `failure` naming the worst point; reported-only comparisons pass and
/// carry their worst point in `system-out`.
pub fn junit(all: &[Finding], loosened: &[Loosening]) -> String {
    let mut suites: BTreeMap<&'static str, Vec<Case>> = BTreeMap::new();
    for ((scene, solver, against), fs) in groups(all) {
        suites.entry(against).or_default().push((scene, solver, fs));
    }
    let failed_case = |fs: &[&Finding]| fs.iter().any(|f| f.gated && !f.passed());
    let (tests, failures): (usize, usize) =
        suites.values().flatten().fold((0, 0), |(t, n), (_, _, fs)| (t + 1, n + usize::from(failed_case(fs))));
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let _ = writeln!(
        out,
        "<testsuites name=\"creepbench check\" tests=\"{tests}\" failures=\"{failures}\" errors=\"0\" time=\"0\">"
    );
    for (against, cases) in &suites {
        let n_fail = cases.iter().filter(|(_, _, fs)| failed_case(fs)).count();
        let _ = writeln!(
            out,
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{n_fail}\" errors=\"0\" skipped=\"0\" time=\"0\">",
            xml(&format!("against {against}")),
            cases.len()
        );
        let mine: Vec<&Loosening> = loosened.iter().filter(|l| l.against == *against).collect();
        if !mine.is_empty() {
            let _ = writeln!(out, "    <properties>");
            for l in mine {
                let _ = writeln!(out, "      <property name=\"loosened\" value=\"{}\"/>", xml(&l.to_string()));
            }
            let _ = writeln!(out, "    </properties>");
        }
        for (scene, solver, fs) in cases {
            let w = worst(fs);
            let _ = write!(
                out,
                "    <testcase name=\"{}\" classname=\"{}\" time=\"0\"",
                xml(&format!("{scene} {solver}")),
                xml(&format!("creepbench.{against}"))
            );
            if failed_case(fs) {
                let n = fs.iter().filter(|f| f.gated && !f.passed()).count();
                let _ = writeln!(out, ">");
                let _ = writeln!(
                    out,
                    "      <failure message=\"{}\" type=\"drift\">{} gated quantit{} out of tolerance; worst: {}</failure>",
                    xml(&describe(w)),
                    n,
                    if n == 1 { "y" } else { "ies" },
                    xml(&describe(w))
                );
                let _ = writeln!(out, "    </testcase>");
            } else {
                let _ = writeln!(out, ">");
                let _ = writeln!(out, "      <system-out>{}</system-out>", xml(&format!("worst: {}", describe(w))));
                let _ = writeln!(out, "    </testcase>");
            }
        }
        let _ = writeln!(out, "  </testsuite>");
    }
    out.push_str("</testsuites>\n");
    out
}

/// One finding as JSON (non-finite numbers become null).
#[derive(serde::Serialize)]
struct JsonFinding<'a> {
    scene: &'a str,
    solver: &'a str,
    against: &'static str,
    quantity: &'a str,
    step: Option<usize>,
    ours: Option<f64>,
    theirs: Option<f64>,
    diff: Option<f64>,
    allowed: Option<f64>,
    gated: bool,
    passed: bool,
    note: &'a str,
}

#[derive(serde::Serialize)]
struct JsonReport<'a> {
    passed: bool,
    gated: usize,
    failed: usize,
    /// The run's rules that loosen what the defaults gate.
    loosened: &'a [Loosening],
    findings: Vec<JsonFinding<'a>>,
}

/// Every finding, complete, with the verdict.
pub fn json(all: &[Finding], loosened: &[Loosening]) -> String {
    let finite = |v: f64| v.is_finite().then_some(v);
    let failed = all.iter().filter(|f| f.gated && !f.passed()).count();
    let report = JsonReport {
        passed: failed == 0,
        gated: all.iter().filter(|f| f.gated).count(),
        failed,
        loosened,
        findings: all
            .iter()
            .map(|f| JsonFinding {
                scene: &f.scene,
                solver: &f.solver,
                against: f.against.label(),
                quantity: &f.quantity,
                step: f.step,
                ours: finite(f.ours),
                theirs: finite(f.theirs),
                diff: finite(f.diff),
                allowed: finite(f.allowed),
                gated: f.gated,
                passed: f.passed(),
                note: &f.note,
            })
            .collect(),
    };
    serde_json::to_string_pretty(&report).expect("findings always serialise") + "\n"
}

/// Most failures listed in the summary.
const SUMMARY_FAILURES: usize = 30;

/// A short Markdown verdict: pass/fail, the counts per comparison, the failures (worst first).
pub fn summary(all: &[Finding], loosened: &[Loosening]) -> String {
    let failed: Vec<&Finding> = all.iter().filter(|f| f.gated && !f.passed()).collect();
    let mut out = format!("## creepbench check: {}\n\n", if failed.is_empty() { "passed" } else { "FAILED" });
    let _ = writeln!(out, "| comparison | scene × solver | gated quantities | failed |");
    let _ = writeln!(out, "|---|---|---|---|");
    let mut per: BTreeMap<&'static str, (usize, usize, usize)> = BTreeMap::new();
    for ((_, _, against), fs) in groups(all) {
        let e = per.entry(against).or_default();
        e.0 += 1;
        e.1 += fs.iter().filter(|f| f.gated).count();
        e.2 += fs.iter().filter(|f| f.gated && !f.passed()).count();
    }
    for (against, (cases, gated, fail)) in &per {
        let _ = writeln!(out, "| {against} | {cases} | {gated} | {fail} |");
    }
    if !loosened.is_empty() {
        let _ = writeln!(out, "\n{} rule(s) of the run's files loosen what the defaults gate:\n", loosened.len());
        for l in loosened {
            let _ = writeln!(out, "- {}", l.to_string().replace('|', "\\|"));
        }
    }
    if !failed.is_empty() {
        let mut worst: Vec<&Finding> = failed.clone();
        worst.sort_by(|a, b| b.severity().total_cmp(&a.severity()));
        let _ = writeln!(
            out,
            "\n{} failed (worst first{}):\n",
            failed.len(),
            if failed.len() > SUMMARY_FAILURES { format!(", first {SUMMARY_FAILURES}") } else { String::new() }
        );
        for f in worst.iter().take(SUMMARY_FAILURES) {
            let _ = writeln!(out, "- `{}` `{}`: {}", f.scene, f.solver, describe(f).replace('|', "\\|"));
        }
    }
    out
}
