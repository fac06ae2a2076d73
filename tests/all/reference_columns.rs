//! Issue 29, item 5: a reference file that lacks a column the reader uses is an error naming the
//! file and the column (not an empty string, NaN or 0); a required value that is not a number
//! names its line and column; an optional one (loop area, frequency) may be empty.

use crate::common;
use common::*;
use creepbench::comparison::references::contact::ContactCases;
use std::path::Path;

/// A reference folder whose contact/cases.csv is `cases` (with the first case's history copied).
fn folder(name: &str, cases: &str) -> std::path::PathBuf {
    let d = tempdir(name);
    std::fs::create_dir_all(d.join("contact")).unwrap();
    std::fs::write(d.join("contact/cases.csv"), cases).unwrap();
    let from = root().join("reference/contact/step_mu01.csv");
    std::fs::copy(from, d.join("contact/step_mu01.csv")).unwrap();
    d
}

/// The shipped header and its first case (step_mu01), with `drop` removed from both.
fn cases_without(drop: Option<&str>) -> String {
    let text = std::fs::read_to_string(root().join("reference/contact/cases.csv")).unwrap();
    let mut lines = text.lines();
    let (head, first) = (lines.next().unwrap(), lines.next().unwrap());
    let keep: Vec<usize> = head.split(',').enumerate().filter(|(_, h)| Some(*h) != drop).map(|(i, _)| i).collect();
    let pick = |l: &str| keep.iter().map(|&i| l.split(',').nth(i).unwrap()).collect::<Vec<_>>().join(",");
    format!("{}\n{}\n", pick(head), pick(first))
}

fn load_error(dir: &Path) -> String {
    ContactCases::load(dir).expect_err("an error").to_string()
}

#[test]
fn the_shipped_columns_load() {
    let d = folder("refcols_ok", &cases_without(None));
    let c = ContactCases::load(&d).unwrap();
    let case = &c.cases["step_mu01"];
    assert_eq!((case.mx, case.n_steps, case.kind.as_str(), case.method.as_str()), (22, 44, "step", "exact"));
    assert_eq!((case.contact_wall_s, case.pn_max_mpa, case.loop_area, case.freq_hz), (0.18, 1364.60, None, None));
}

#[test]
fn a_missing_column_names_the_file_and_the_column() {
    for column in ["name", "kind", "method", "mx", "n_steps", "contact_wall_s", "loop_area", "pn_max_mpa", "freq_hz"] {
        let d = folder(&format!("refcols_{column}"), &cases_without(Some(column)));
        let e = load_error(&d);
        assert!(e.contains("contact/cases.csv") && e.contains(&format!("lacks column {column}")), "{column}: {e}");
    }
}

#[test]
fn a_required_value_that_is_not_a_number_names_line_and_column() {
    let bad = cases_without(None).replacen(",44,0.18,", ",44,fast,", 1);
    let e = load_error(&folder("refcols_value", &bad));
    assert!(e.contains("cases.csv") && e.contains("line 2 column contact_wall_s") && e.contains("\"fast\""), "{e}");
    let empty = cases_without(None).replacen(",44,0.18,", ",44,,", 1);
    let e = load_error(&folder("refcols_empty", &empty));
    assert!(e.contains("line 2 column contact_wall_s") && e.contains("is not a number"), "{e}");
}
