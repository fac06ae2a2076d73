//! The section "CONTACT's public examples" (issue 32 item 4): every case of every deck of
//! reference/contact_public/ — reproduced, with its worst difference in half-units of the
//! printed rounding (the gate's measure, `tolerances.toml` rules "CONTACT public"), or not
//! supported with the missing feature (the importer's survey, attached by the command).

use crate::comparison::references::contact_output::CaseBody;
use crate::comparison::references::contact_public::{PublicCases, RowDiff, Survey, AGAINST, FX, FY};
use crate::comparison::references::wheelrail_cases::{WheelRailCases, AGAINST as WHEELRAIL};
use crate::comparison::references::References;
use crate::report::linked_table::{self, Table};
use crate::report::section::Section;
use crate::suite::results::StoredScene;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;

/// The section's id and title.
pub const ID: &str = "contact_public";
pub const TITLE: &str = "CONTACT's public examples";

/// One unit of the last printed digit, in half-units: the bound of the gate's rules (k = 2).
const ONE_PRINTED_UNIT: f64 = 2.0;

/// The models compared case by case: CONTACT's exact theory, CONTACT's FASTSIM for its M = 3 cases
/// and its modified FaStrip for M = 5 (each imported scene runs the one that computes what its deck
/// asks).
const SOLVERS: [&str; 3] = ["contact", crate::solvers::fastsim_contact::NAME, crate::solvers::fastrip_contact::NAME];

/// Whether any stored scene was imported from a CONTACT deck.
pub fn applies(scenes: &[StoredScene]) -> bool {
    scenes.iter().any(|s| s.scene.origin.is_some())
}

/// The worst gated comparison of each (deck, case) over the stored scenes' rows of the
/// [`SOLVERS`], with the model (a quantity that a rule of `tolerances.toml` only reports is left out
/// of the verdict, as the gate leaves it).
fn worst_by_case(scenes: &[StoredScene], public: &PublicCases) -> BTreeMap<(String, usize), (RowDiff, &'static str)> {
    let mut out: BTreeMap<(String, usize), (RowDiff, &'static str)> = BTreeMap::new();
    for sc in scenes {
        let Some(origin) = &sc.scene.origin else { continue };
        for solver in SOLVERS {
            let Some(h) = sc.histories.get(solver) else { continue };
            for d in public.row_diffs(sc, h).unwrap_or_default() {
                if !crate::comparison::tolerances::rule(AGAINST, &sc.name, solver, d.quantity).gated {
                    continue;
                }
                let key = (origin.file.clone(), d.case);
                if out.get(&key).is_none_or(|(w, _)| d.half_units() > w.half_units()) {
                    out.insert(key, (d, solver));
                }
            }
        }
    }
    out
}

/// One case of a deck as the list shows it: its worst comparison with the model that made it
/// (none: not run), the importer's verdict, the set of CONTACT's wheel–rail decks (a module-1
/// case's verdict is that gate's, when it holds the deck) and whether CONTACT printed totals for it.
struct CaseRow<'a> {
    deck: &'a str,
    case: usize,
    worst: Option<&'a (RowDiff, &'a str)>,
    survey: Option<&'a Survey>,
    wheelrail: Option<&'a WheelRailCases>,
    printed: bool,
}

/// The case's status.
fn status(row: &CaseRow) -> String {
    let CaseRow { deck, case, worst, survey, wheelrail, printed } = *row;
    if let Some((d, solver)) = worst {
        let verdict = if d.half_units() <= ONE_PRINTED_UNIT { "reproduced" } else { "**differs**" };
        // A value CONTACT prints at its noise level is measured against the noise floor.
        let unit = if d.quantity.ends_with("_at_noise_floor") { "the noise floor" } else { "the printed rounding" };
        // The exact solver's rows as before; another model named.
        let by = if *solver == SOLVERS[0] { String::new() } else { format!(", {solver}") };
        return format!("{verdict}: worst {:.2} half-units of {unit} ({}{by})", d.half_units(), d.quantity);
    }
    let verdict = match survey {
        Some(Survey::Cases(cases)) => cases.get(&case),
        Some(Survey::Unread(why)) => return format!("not supported: the deck is not read: {}", why.replace('|', "/")),
        None => None,
    };
    // The wheel–rail gate's own copy of the deck has its profiles beside it.
    let gate = wheelrail.filter(|w| w.inputs.contains_key(deck));
    match (verdict, gate) {
        (Some(v), Some(w)) if v.module == 1 => {
            format!("{MODULE_1} {}", super::contact_wheelrail::status(w, deck, case as u64))
        }
        (Some(v), _) if v.module == 1 && v.refused.is_empty() => {
            format!("{MODULE_1} supported, not in the wheel–rail gate (import {deck} to run it)")
        }
        (Some(v), _) if !v.refused.is_empty() => {
            let head = if v.module == 1 { format!("{MODULE_1} not supported") } else { "not supported".into() };
            format!("{head}: {}", v.refused.join("; ").replace('|', "/"))
        }
        (Some(_), _) if printed => format!("supported, not among these results (import {deck} to compare it)"),
        (Some(_), _) => "supported; CONTACT printed no totals for it".into(),
        (None, _) => "not surveyed".into(),
    }
}

/// How a module-1 case's status starts (its verdict is the wheel–rail gate's, section
/// "CONTACT's wheel–rail decks").
const MODULE_1: &str = "wheel–rail (module 1):";

/// The section.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let public = refs.get::<PublicCases>(AGAINST)?;
    let wheelrail = refs.get::<WheelRailCases>(WHEELRAIL);
    let worst = worst_by_case(scenes, public);
    let mut table = Table::new(&["deck", "case", "status"]);
    let mut per_deck = String::from(
        "| deck | cases | reproduced | not supported | of them wheel–rail (module 1) |\n|---|---|---|---|---|\n",
    );
    let (mut keep, mut keys, mut reproduced_all) = (Vec::new(), Vec::new(), 0);
    for (deck, printed) in &public.decks {
        let survey = public.survey.get(deck);
        let mut cases: BTreeSet<usize> = printed.iter().map(|c| c.case as usize).collect();
        if let Some(Survey::Cases(c)) = survey {
            cases.extend(c.keys());
        }
        let (mut reproduced, mut refused, mut module1) = (0, 0, 0);
        for &case in &cases {
            let has_totals = printed.iter().any(|c| c.case as usize == case && matches!(c.body, CaseBody::Totals(_)));
            let w = worst.get(&(deck.clone(), case));
            let row = CaseRow { deck, case, worst: w, survey, wheelrail, printed: has_totals };
            let s = status(&row);
            let verdict = s.strip_prefix(MODULE_1).map_or(s.as_str(), str::trim_start);
            module1 += usize::from(s.starts_with(MODULE_1));
            reproduced += usize::from(verdict.starts_with("reproduced"));
            refused += usize::from(verdict.starts_with("not supported") || verdict.starts_with("not surveyed"));
            if let Some(w) = w {
                keep.push(table.rows.len());
                keys.push(w.0.half_units());
            }
            table.rows.push(format!("| {deck} | {case} | {s} |"));
        }
        let _ = writeln!(per_deck, "| {deck} | {} | {reproduced} | {refused} | {module1} |", cases.len());
        reproduced_all += reproduced;
    }
    let order = linked_table::largest(&keys, keys.len());
    let keep: Vec<usize> = order.into_iter().map(|i| keep[i]).collect();
    let summary = format!(
        "Every case of every deck of `reference/contact_public/` (CONTACT's `examples/` and `testbank/`, read from its printed `.ref_out`): reproduced by the exact solver, or for CONTACT's FASTSIM (M = 3) and modified FaStrip (M = 5) by `fastsim_contact` and `fastrip_contact` (its worst difference from the printed fx/fn, fy/fn and MZ in half-units of the printed value's last digit; the gate allows {ONE_PRINTED_UNIT}, one printed unit) or not supported, with the feature the importer refuses. A wheel–rail case (CONTACT's module 1) has the wheel–rail gate's verdict (section \"CONTACT's wheel–rail decks\": every case and patch in half-units of CONTACT's printed digits) where that gate holds its deck. {} of {} cases reproduced.",
        reproduced_all,
        table.rows.len()
    );
    let placed = linked_table::place(ID, TITLE, &table, &summary, &keep, "The compared cases, worst first");
    let body = format!("{per_deck}\n{}{}", placed.inline, fastsim_beside(scenes, public));
    Some(Section { tables: placed.file.into_iter().collect(), ..Section::new(TITLE, body) })
}

/// The project's FASTSIM beside CONTACT's (issue 46): every scene that runs both, row by row, the
/// traction coefficient (its larger printed component) as CONTACT printed it and as
/// `fastsim_contact` and `fastsim` give it, with the exact theory's case at the same creepages
/// where a scene of the same deck runs it (tractcurv.inp's cases 1-30 beside 61-90 and 91-120).
fn fastsim_beside(scenes: &[StoredScene], public: &PublicCases) -> String {
    let mut out = String::new();
    for sc in scenes {
        let (Some(origin), Some(theirs), Some(ours)) =
            (&sc.scene.origin, sc.histories.get(SOLVERS[1]), sc.histories.get("fastsim"))
        else {
            continue;
        };
        let (Ok(c), Ok(p)) = (public.row_diffs(sc, theirs), public.row_diffs(sc, ours)) else { continue };
        let largest = |q| c.iter().filter(|d| d.quantity == q).map(|d| d.printed.value.abs()).fold(0.0, f64::max);
        let q = if largest(FX) >= largest(FY) { FX } else { FY };
        let creep = |h: &crate::history::History| {
            h.rows.iter().map(|r| [r.sample.cx, r.sample.cy, r.sample.cs]).collect::<Vec<_>>()
        };
        let exact = scenes.iter().find_map(|e| {
            let h = e.histories.get(SOLVERS[0])?;
            let same = e.scene.origin.as_ref().is_some_and(|o| o.file == origin.file) && creep(h) == creep(theirs);
            same.then(|| public.row_diffs(e, h).ok()).flatten()
        });
        let pick = |d: &[RowDiff]| d.iter().filter(|d| d.quantity == q).cloned().collect::<Vec<_>>();
        let (c, p, e) = (pick(&c), pick(&p), exact.as_deref().map(pick).unwrap_or_default());
        let name = q.trim_end_matches("_in_rounding").replace("_over_", "/");
        let [first, last] = origin.cases;
        let cases = if first == last { format!("case {first}") } else { format!("cases {first}-{last}") };
        let _ = write!(
            out,
            "\n### CONTACT's FASTSIM beside the project's: {} {cases} ({name})\n\n| case | cx | cy | cs [1/mm] | exact, CONTACT | contact | FASTSIM, CONTACT | fastsim_contact | fastsim |\n|---|---|---|---|---|---|---|---|---|\n",
            origin.file
        );
        for (k, (dc, dp)) in c.iter().zip(&p).enumerate() {
            let [cx, cy, cs] = creep(theirs)[k];
            let (ep, eo) = e.get(k).map_or(("—".into(), "—".into()), |d| {
                (format!("{:.6} (case {})", d.printed.value, d.case), format!("{:.6}", d.ours))
            });
            let _ = writeln!(
                out,
                "| {} | {cx} | {cy} | {cs} | {ep} | {eo} | {:.6} | {:.6} | {:.6} |",
                dc.case, dc.printed.value, dc.ours, dp.ours
            );
        }
    }
    out
}
