//! docs/contact-import.md's tables of what `import contact` carries are generated from the
//! importer's own tables (`import::contact::features::FEATURES`, `WHEELRAIL_FEATURES` and
//! `scene::wheelrail::SCENE_LIMITS`): the test fails showing the difference, and
//! `CREEPBENCH_BLESS_DOCS=1 cargo test --release --test all docs_features` rewrites them.

use crate::common;
use crate::docs::{generated_or_blessed, read, regenerate};
use creepbench::import::contact::features::{FEATURES, WHEELRAIL_FEATURES};
use creepbench::import::contact::scene::wheelrail::SCENE_LIMITS;

/// A table cell: pipes escaped, on one line.
fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// The Markdown table of rows (name, control, carried, reason).
fn table(rows: impl Iterator<Item = (&'static str, &'static str, bool, &'static str)>, carried: [&str; 2]) -> String {
    let mut out = String::from("| feature | control | imported | why |\n|---|---|---|---|\n");
    for (name, control, ok, reason) in rows {
        let verdict = if ok { carried[0] } else { carried[1] };
        out.push_str(&format!("| {} | {} | {verdict} | {} |\n", cell(name), cell(control), cell(reason)));
    }
    out
}

/// The generated text of the table named `id`.
fn generated(id: &str) -> String {
    match id {
        "module3" => table(FEATURES.iter().map(|f| (f.name, f.control, f.supported, f.reason)), ["yes", "refused"]),
        "module1" => {
            table(WHEELRAIL_FEATURES.iter().map(|f| (f.name, f.control, f.supported, f.reason)), ["yes", "refused"])
        }
        "scene_limits" => table(
            SCENE_LIMITS.iter().map(|f| (f.name, f.control, f.accepted, f.reason)),
            ["yes, with a note", "refused"],
        ),
        _ => panic!("docs/contact-import.md names a table {id:?}: module3, module1 or scene_limits"),
    }
}

const OPEN: &str = "<!-- features:";
const CLOSE: &str = "<!-- /features -->";

#[test]
fn the_import_feature_tables_are_the_importers() {
    let path = common::root().join("docs/contact-import.md");
    let doc = read(&path);
    let (want, ids) = regenerate(&doc, CLOSE, &[(OPEN, &generated)]);
    assert_eq!(ids, ["module3", "module1", "scene_limits"], "docs/contact-import.md's tables");
    generated_or_blessed(&path, &doc, &want, "docs_features");
}
