//! The section "CONTACT's wheel–rail decks" (issue 44 item 7): every module-1 case of every deck
//! of reference/contact_wheelrail/ and of the library's prints — reproduced (its worst
//! comparison over the patches and totals, in half-units of the printed digit, against the
//! bound of `tolerances.toml`), a declared gap with its missing feature, or not supported with
//! the feature the importer refuses (the survey, attached by the command).

use crate::comparison::references::contact_public::Survey;
use crate::comparison::references::wheelrail_cases::{WheelRailCases, AGAINST, LIBRARY};
use crate::comparison::references::References;
use crate::report::section::Section;
use crate::suite::results::StoredScene;
use std::collections::BTreeSet;
use std::fmt::Write;

/// The section's id and title.
pub const ID: &str = "contact_wheelrail";
pub const TITLE: &str = "CONTACT's wheel–rail decks";

/// Whether the run gated any wheel–rail scene.
pub fn applies(refs: &References) -> bool {
    refs.get::<WheelRailCases>(AGAINST).is_some_and(|s| !s.results.is_empty())
}

/// The status of one case of a deck.
pub fn status(set: &WheelRailCases, deck: &str, case: u64) -> String {
    if let Some(w) = set.results.get(&(deck.to_string(), case)) {
        let d = &w.deviation;
        let at = if d.patch == 0 { "totals".to_string() } else { format!("patch {}", d.patch) };
        let what = format!("{:.2} half-units ({} {at}, {})", w.measure, d.quantity, w.scene);
        return match (w.gap, w.passed) {
            (Some(g), true) => format!("declared gap, within its bound: {g}; worst gated {what}"),
            (Some(g), false) => format!("**declared gap, beyond its bound**: {g}; {what}"),
            (None, true) => format!("reproduced: worst {what}"),
            (None, false) => format!("**differs**: {what}"),
        };
    }
    match set.survey.get(deck) {
        Some(Survey::Cases(c)) => match c.get(&(case as usize)) {
            Some(r) if !r.refused.is_empty() => format!("not supported: {}", r.refused.join("; ").replace('|', "/")),
            Some(_) => "supported, not among these results".into(),
            None => "not a module-1 case".into(),
        },
        Some(Survey::Unread(why)) => format!("the deck is not read: {}", why.replace('|', "/")),
        None => "not surveyed".into(),
    }
}

/// The section.
pub fn section(_scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let set = refs.get::<WheelRailCases>(AGAINST)?;
    let mut per_deck =
        String::from("| deck | module-1 cases | reproduced | declared gap | not supported |\n|---|---|---|---|---|\n");
    let mut rows = String::from("| deck | case | status |\n|---|---|---|\n");
    let mut decks: Vec<(String, Vec<u64>)> = Vec::new();
    for deck in set.inputs.keys() {
        let mut cases: BTreeSet<u64> = BTreeSet::new();
        if let Some(Survey::Cases(c)) = set.survey.get(deck) {
            cases.extend(c.keys().map(|&k| k as u64));
        }
        decks.push((deck.clone(), cases.into_iter().collect()));
    }
    for (deck, cases) in &decks {
        let (mut ok, mut gap, mut refused) = (0, 0, 0);
        for &case in cases {
            let s = status(set, deck, case);
            ok += usize::from(s.starts_with("reproduced"));
            gap += usize::from(s.starts_with("declared gap"));
            refused += usize::from(s.starts_with("not supported") || s.starts_with("the deck"));
            let _ = writeln!(rows, "| {deck} | {case} | {s} |");
        }
        let _ = writeln!(per_deck, "| {deck} | {} | {ok} | {gap} | {refused} |", cases.len());
    }
    // The library's prints: the cases of a deck through CONTACT's library, compared beside it.
    let mut library = String::new();
    for (file, element, deck) in LIBRARY {
        let n = set.prints.get(file).map_or(0, |c| c.iter().filter(|c| c.result_element == Some(element)).count());
        let _ = writeln!(
            library,
            "- `{file}`, result element {element}: {n} cases printed by CONTACT's library for the cases of `{deck}`, compared with the same scene's results (its rows above count both)."
        );
    }
    let body = format!(
        "Every module-1 case of the decks of `reference/contact_wheelrail/`: the exact solver's worst comparison with CONTACT's printed output, over the totals on the rail and every patch's reference, creepages, forces and element counts, in half-units of the printed value's last digit against the bound `tolerances.toml` gives it (label \"CONTACT wheel-rail\"; FX and MN floored, see docs/wheelrail.md), a declared gap with the feature it lacks, or not supported with the feature the importer refuses.\n\n{per_deck}\n{library}\n{rows}"
    );
    Some(Section::new(TITLE, body))
}
