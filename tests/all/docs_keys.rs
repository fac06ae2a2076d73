//! The key tables of docs/scene-format.md are generated from the readers' declarations
//! (`creepbench::scene::keys`): the test fails showing the difference, and
//! `CREEPBENCH_BLESS_DOCS=1 cargo test --release --test all docs_keys` rewrites them. Every
//! declared key is read by the file that declares it, and every key that file reads is declared.

use crate::common;
use crate::docs::{files_under, generated_or_blessed, keys_read, read, regenerate};
use creepbench::scene::keys::{columns_markdown, markdown, Allowed, Keys};
use std::collections::{BTreeMap, BTreeSet};

/// Every declaration, in the order the docs show them.
fn tables() -> Vec<&'static Keys> {
    let mut all: Vec<&'static Keys> = creepbench::scene::KEY_TABLES.to_vec();
    all.extend(creepbench::solvers::MODEL_KEYS.iter().copied());
    use creepbench::scene::study;
    all.extend([&study::FILE_KEYS, &study::KEYS, &study::AXIS_KEYS]);
    use creepbench::calibration::fit::spec as fit;
    all.extend([&fit::FILE_KEYS, &fit::KEYS, &fit::PARAM_KEYS]);
    use creepbench::comparison::tolerance_file as tolerance;
    all.push(&tolerance::KEYS);
    all
}

/// The declarations of the columns of table files (`<!-- columns:ID -->`).
fn column_tables() -> Vec<&'static Keys> {
    creepbench::scene::COLUMN_TABLES.to_vec()
}

const OPEN: &str = "<!-- keys:";
const OPEN_COLUMNS: &str = "<!-- columns:";
const CLOSE: &str = "<!-- /keys -->";

/// `doc` with the text between each `<!-- keys:ID -->` (`<!-- columns:ID -->`) line and the next
/// `<!-- /keys -->` replaced by the Markdown of the key (column) declarations of ID; the IDs
/// found, in order.
fn generate(doc: &str, tables: &[&'static Keys], columns: &[&'static Keys]) -> (String, Vec<String>) {
    fn of(declared: &[&'static Keys], id: &str) -> Vec<&'static Keys> {
        let of_id: Vec<&Keys> = declared.iter().copied().filter(|t| t.id == id).collect();
        assert!(!of_id.is_empty(), "docs/scene-format.md has a marker of {id:?} but no reader declares it");
        of_id
    }
    let keys = |id: &str| markdown(&of(tables, id));
    let cols = |id: &str| columns_markdown(&of(columns, id));
    regenerate(doc, CLOSE, &[(OPEN, &keys), (OPEN_COLUMNS, &cols)])
}

#[test]
fn the_docs_key_tables_are_the_declarations() {
    let path = common::root().join("docs/scene-format.md");
    let doc = read(&path);
    let (tables, columns) = (tables(), column_tables());
    let (want, ids) = generate(&doc, &tables, &columns);
    for t in tables.iter().chain(&columns) {
        assert!(ids.contains(&t.id.to_string()), "no marker of {} in docs/scene-format.md", t.id);
    }
    generated_or_blessed(&path, &doc, &want, "docs_keys");
}

/// What is wrong between the declarations and the sources that read them: a declared key its
/// owner never reads, a key an owner reads that no declaration names (a table of its own, a
/// [`Allowed::Section`], may be read in any file of `readers`). A family row (a name in words)
/// is read through other declarations or by hand; the columns of a table file (`columns`) are
/// read by their declarations (each reader's tests check that its columns are the declared
/// ones), so they count as declared, not as read by name.
fn undeclared_or_unread(tables: &[&Keys], columns: &[&Keys], sources: &BTreeMap<String, String>) -> Vec<String> {
    let mut wrong = Vec::new();
    let read_in = |file: &str| keys_read(sources.get(file).map_or("", String::as_str));
    let anywhere: BTreeSet<String> = sources.keys().flat_map(|f| read_in(f)).collect();
    let sections: BTreeSet<&str> =
        tables.iter().flat_map(|t| t.keys).filter(|k| k.allowed == Allowed::Section).map(|k| k.key).collect();
    let owners: BTreeSet<&str> = tables.iter().map(|t| t.owner).collect();
    for owner in owners {
        let read = read_in(owner);
        let declared: BTreeSet<&str> =
            tables.iter().chain(columns).filter(|t| t.owner == owner).flat_map(|t| t.keys).map(|k| k.key).collect();
        for t in tables.iter().filter(|t| t.owner == owner) {
            for k in t.keys.iter().filter(|k| !k.is_family()) {
                let found = if k.allowed == Allowed::Section { anywhere.contains(k.key) } else { read.contains(k.key) };
                if !found {
                    wrong.push(format!("{owner}: [{}] {} is declared but never read", t.id, k.key));
                }
            }
        }
        for k in &read {
            if !declared.contains(k.as_str()) && !sections.contains(k.as_str()) {
                wrong.push(format!("{owner}: {k} is read but not declared"));
            }
        }
    }
    wrong
}

/// The sources of `src/`, by their path from the repository's root (as `file!()` gives it).
fn sources() -> BTreeMap<String, String> {
    let root = common::root();
    let mut files = Vec::new();
    files_under(&root.join("src"), "rs", &mut files);
    files.iter().map(|f| (f.strip_prefix(&root).unwrap().display().to_string(), read(f))).collect()
}

#[test]
fn every_declared_key_is_read_and_every_key_read_is_declared() {
    let tables = tables();
    assert!(tables.len() >= 2, "{} tables", tables.len());
    let wrong = undeclared_or_unread(&tables, &column_tables(), &sources());
    assert!(wrong.is_empty(), "declarations and readers disagree:\n{}", wrong.join("\n"));
}

/// The check fails on a key declared but not read, and on one read but not declared.
#[test]
fn a_key_declared_but_not_read_or_read_but_not_declared_fails() {
    use creepbench::scene::keys::{key, Absent};
    const T: Keys = Keys {
        id: "t",
        owner: "src/t.rs",
        keys: &[
            key("a_mm", "mm", Allowed::Text("x"), Absent::Required, "a"),
            key("b_mm", "mm", Allowed::Text("x"), Absent::Required, "b"),
        ],
    };
    let src = |text: &str| BTreeMap::from([("src/t.rs".to_string(), text.to_string())]);
    assert!(undeclared_or_unread(&[&T], &[], &src("s.num(\"a_mm\")?; s.opt_num(\"b_mm\")?;")).is_empty());
    assert_eq!(
        undeclared_or_unread(&[&T], &[], &src("s.num(\"a_mm\")?; s.opt_num(\"c_mm\")?;")),
        ["src/t.rs: [t] b_mm is declared but never read", "src/t.rs: c_mm is read but not declared"]
    );
}
