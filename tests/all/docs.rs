//! The documentation stays complete and inside the repository: every key the readers of scene,
//! study, fit and tolerance files accept, and every key of the shipped files, is documented in
//! docs/scene-format.md; no document or source names a file outside the repository.

use crate::common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

pub(crate) fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

pub(crate) fn files_under(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files_under(&path, ext, out);
        } else if path.extension().is_some_and(|e| e == ext) {
            out.push(path);
        }
    }
}

/// A kind of marker (`<!-- KIND:`) and the generated text of each of its IDs.
pub(crate) type Marker<'a> = (&'a str, &'a dyn Fn(&str) -> String);

/// `doc` with the text between each marker line (`<!-- KIND:ID -->`, a kind of `kinds`) and the
/// next `close` line replaced by that kind's text of ID; the IDs found, in order.
pub(crate) fn regenerate(doc: &str, close: &str, kinds: &[Marker]) -> (String, Vec<String>) {
    let (mut out, mut ids, mut rest) = (String::new(), Vec::new(), doc);
    while let Some((at, open, text)) =
        kinds.iter().filter_map(|&(open, text)| rest.find(open).map(|at| (at, open, text))).min_by_key(|m| m.0)
    {
        let line_end = at + rest[at..].find('\n').expect("a marker line ends");
        let id = rest[at + open.len()..line_end].trim_end_matches("-->").trim().to_string();
        let end = line_end + rest[line_end..].find(close).unwrap_or_else(|| panic!("{open}{id} is not closed"));
        out.push_str(&rest[..=line_end]);
        out.push_str(&text(&id));
        ids.push(id);
        rest = &rest[end..];
    }
    out.push_str(rest);
    (out, ids)
}

/// The lines of `got` and `want` that differ, as `-` (in the docs) and `+` (generated).
fn diff(got: &str, want: &str) -> String {
    let (g, w): (BTreeSet<&str>, BTreeSet<&str>) = (got.lines().collect(), want.lines().collect());
    let gone = got.lines().filter(|l| !w.contains(l)).map(|l| format!("- {l}"));
    let new = want.lines().filter(|l| !g.contains(l)).map(|l| format!("+ {l}"));
    gone.chain(new).take(60).collect::<Vec<_>>().join("\n")
}

/// Passes when the document at `path` is `want`; with `CREEPBENCH_BLESS_DOCS=1` writes `want`
/// there, else fails showing the difference and the command (`test`) that rewrites it.
pub(crate) fn generated_or_blessed(path: &Path, doc: &str, want: &str, test: &str) {
    if want == doc {
        return;
    }
    if std::env::var("CREEPBENCH_BLESS_DOCS").is_ok_and(|v| v == "1") {
        std::fs::write(path, want).unwrap();
        return;
    }
    panic!(
        "{}'s generated tables differ from their sources (rewrite them with CREEPBENCH_BLESS_DOCS=1 \
         cargo test --release --test all {test}):\n{}",
        path.display(),
        diff(doc, want)
    );
}

fn scene_format() -> String {
    read(&common::root().join("docs/scene-format.md"))
}

/// `key` appears in the reference as a key (`` `key` ``) or as a table (`` `[key]` ``,
/// `` `[key.NAME]` ``, `` `[[key]]` ``, `` `[[fit.key]]` ``).
fn documented(doc: &str, key: &str) -> bool {
    [format!("`{key}`"), format!("`[{key}]`"), format!("`[{key}."), format!("`[[{key}]]`"), format!("`[[fit.{key}]]`")]
        .iter()
        .any(|form| doc.contains(form.as_str()))
}

/// The reader methods of `scene::reader::Section` that take a key as their first argument.
const KEY_METHODS: [&str; 32] = [
    "given",
    "num",
    "opt_num",
    "num_or_default",
    "opt_nums",
    "opt_num_list",
    "whole",
    "opt_whole",
    "whole_or_default",
    "pick",
    "opt_pick",
    "pick_or_default",
    "text",
    "opt_text",
    "f64",
    "opt_f64",
    "usize",
    "opt_usize",
    "str",
    "opt_str",
    "choice",
    "opt_choice",
    "opt_bool",
    "opt_f64_array",
    "opt_f64_list",
    "opt_str_list",
    "opt_text_list",
    "refuse",
    "table",
    "opt_table",
    "opt_tables",
    "has",
];

/// The string literal starting at byte `at` (just after its opening quote), if it is a key.
fn key_at(text: &str, at: usize) -> Option<String> {
    let end = text[at..].find('"')?;
    let key = &text[at..at + end];
    (!key.is_empty() && key.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_'))
        .then(|| key.to_string())
}

/// The keys a source file reads: `.METHOD("key"` of the strict reader (`opt_f64_array::<3>`
/// included) and a helper taking the section first (`pattern(&mut s, "scene")`).
pub(crate) fn keys_read(text: &str) -> BTreeSet<String> {
    let mut keys = BTreeSet::new();
    for (i, _) in text.match_indices("(\"") {
        let before = &text[..i];
        let name_start =
            before.rfind(|c: char| !(c.is_ascii_alphanumeric() || "_:<>".contains(c))).map_or(0, |p| p + 1);
        let method = before[name_start..].split("::").next().unwrap_or("");
        let is_method = before[..name_start].ends_with('.') && KEY_METHODS.contains(&method);
        if is_method {
            keys.extend(key_at(text, i + 2));
        }
    }
    for (i, _) in text.match_indices("(&mut ") {
        let rest = &text[i + 6..];
        let Some(comma) = rest.find(", \"") else { continue };
        if rest[..comma].bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
            keys.extend(key_at(text, i + 6 + comma + 3));
        }
    }
    keys
}

/// Every key any reader of an input file accepts, from the source of `src/`.
fn keys_of_the_readers() -> BTreeSet<String> {
    let mut files = Vec::new();
    files_under(&common::root().join("src"), "rs", &mut files);
    let mut keys = BTreeSet::new();
    for f in &files {
        keys.extend(keys_read(&read(f)));
    }
    keys
}

/// The scan finds the keys of every file kind (so that a change of the readers' form fails
/// here, not silently), and each of them is documented.
#[test]
fn every_key_the_readers_accept_is_documented() {
    let keys = keys_of_the_readers();
    // Scene (each table), geometry, study, fit and tolerance keys: the scan sees them all.
    for anchor in [
        "name",
        "solvers",
        "metrics",
        "a_mm",
        "r_ry_mm",
        "g_mpa",
        "mx",
        "scale",
        "x_mm",
        "a1_per_mm",
        "field",
        "v_mm_s",
        "courant",
        "c_before",
        "freq_hz",
        "at",
        "direction",
        "file",
        "flexibility",
        "slope_reduction",
        "polach_b_s_per_m",
        "relaxation_length_mm",
        "nonhertz_flexibility",
        "steady_restart",
        "max_estimated_s",
        "command",
        "timeout_s",
        "scene_name",
        "x_values",
        "labels",
        "holdout",
        "bounds",
        "norm",
        "against",
        "quantity",
        "gated",
        "why",
    ] {
        assert!(keys.contains(anchor), "the scan of src/ no longer finds the key {anchor}: {keys:?}");
    }
    assert!(keys.len() >= 90, "{} keys found: {keys:?}", keys.len());
    let doc = scene_format();
    let missing: Vec<&String> = keys.iter().filter(|k| !documented(&doc, k)).collect();
    assert!(missing.is_empty(), "keys read by src/ but not in docs/scene-format.md: {missing:?}");
}

/// The keys of a parsed file, dotted, with `[]` for an array of tables; a quoted dotted key (a
/// study axis's or a fit's `[set]` scene key) is split into its parts.
fn keys_of(table: &toml::Table, path: &str, out: &mut BTreeSet<(String, String)>) {
    for (k, v) in table {
        let full = if path.is_empty() { k.clone() } else { format!("{path}.{k}") };
        for part in k.split('.') {
            out.insert((full.clone(), part.to_string()));
        }
        match v {
            // [external.NAME]: NAME is the user's; its keys are documented.
            toml::Value::Table(t) if k == "external" => {
                for (name, inner) in t {
                    if let toml::Value::Table(inner) = inner {
                        keys_of(inner, &format!("{full}.{name}"), out);
                    }
                }
            }
            toml::Value::Table(t) => keys_of(t, &full, out),
            toml::Value::Array(items) => {
                for item in items {
                    if let toml::Value::Table(t) = item {
                        keys_of(t, &format!("{full}[]"), out);
                    }
                }
            }
            _ => {}
        }
    }
}

/// Every key of every shipped scene, study, fit and tolerance file is documented.
#[test]
fn every_key_of_the_shipped_files_is_documented() {
    let root = common::root();
    let mut files = vec![root.join("tolerances.toml")];
    files_under(&root.join("scenes"), "toml", &mut files);
    files_under(&root.join("fits"), "toml", &mut files);
    assert!(files.len() >= 70, "{} files", files.len());
    let doc = scene_format();
    let mut missing = Vec::new();
    let mut seen = 0;
    for f in &files {
        let table: toml::Table = read(f).parse().unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let mut keys = BTreeSet::new();
        keys_of(&table, "", &mut keys);
        seen += keys.len();
        for (full, part) in keys {
            if !documented(&doc, &part) {
                missing.push(format!("{}: {full} ({part})", f.display()));
            }
        }
    }
    assert!(seen > 1000, "{seen} keys in the shipped files");
    assert!(missing.is_empty(), "keys of shipped files not in docs/scene-format.md:\n{}", missing.join("\n"));
}

/// `documented` is strict: a key the reference does not name fails.
#[test]
fn an_undocumented_key_is_found() {
    let doc = scene_format();
    assert!(documented(&doc, "relaxation_length_mm") && documented(&doc, "external"));
    assert!(!documented(&doc, "relaxation_len") && !documented(&doc, "no_such_key"));
    let keys =
        keys_read("let x = t.opt_f64(\"alpha_mm\", r)?; s.opt_f64_array::<3>(\"beta\", r); f(&mut s, \"gamma\")");
    assert_eq!(keys.into_iter().collect::<Vec<_>>(), ["alpha_mm", "beta", "gamma"]);
}

/// The repository is self-contained: no document, source, script or test names a file of the
/// folder above it (the scene format once lived in such a file).
#[test]
fn nothing_points_outside_the_repository() {
    let root = common::root();
    let mut files = vec![root.join("README.md"), root.join("reference/README.md")];
    for (dir, ext) in [("docs", "md"), ("src", "rs"), ("scripts", "py"), ("scripts", "sh"), ("tests", "rs")] {
        if root.join(dir).is_dir() {
            files_under(&root.join(dir), ext, &mut files);
        }
    }
    let outside = ["../", "shared", "/"].concat();
    let old_contract = ["interface", ".md"].concat();
    for f in &files {
        let text = read(f);
        for (n, line) in text.lines().enumerate() {
            assert!(
                !line.contains(&outside) && !line.contains(&old_contract),
                "{}:{}: names a file outside the repository: {line}",
                f.display(),
                n + 1
            );
        }
    }
}

/// Every relative link of the README and docs/ reaches a file of the repository.
#[test]
fn links_of_the_documents_resolve() {
    let root = common::root();
    let mut files = vec![root.join("README.md")];
    files_under(&root.join("docs"), "md", &mut files);
    for f in &files {
        let text = read(f);
        for (i, _) in text.match_indices("](") {
            let rest = &text[i + 2..];
            let target = &rest[..rest.find(')').unwrap_or(0)];
            let target = target.split('#').next().unwrap_or("");
            if target.is_empty() || target.contains("://") {
                continue;
            }
            let path = f.parent().unwrap().join(target);
            assert!(path.exists(), "{}: link {target} does not resolve", f.display());
        }
    }
}

/// `run --help` says what `run` does and where the report goes, as the README does; `.ci/run`
/// runs the README's test command.
#[test]
fn help_and_ci_agree_with_the_readme() {
    let root = common::root();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench")).args(["run", "--help"]).output().unwrap();
    let help = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{help}");
    for suite in creepbench::suite::DEFAULT_SUITES {
        assert!(help.contains(suite), "run --help does not name {suite}: {help}");
    }
    assert!(help.contains("the ten shipped suites") && help.contains("[default: out/report]"), "{help}");
    let readme = read(&root.join("README.md"));
    for promise in [
        "cargo run --release -- run",
        "cargo test --release",
        "out/report/validation.md",
        "Measured from a fresh clone",
    ] {
        assert!(readme.contains(promise), "README lacks {promise:?}");
    }
    let ci = read(&root.join(".ci/run"));
    assert!(ci.lines().any(|l| l.trim() == "cargo test --release --locked"), "{ci}");
    let words = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(words.contains("`.ci/run` runs exactly `cargo test --release --locked`"), "README and .ci/run disagree");
}
