//! The straight stack (issue 29): every `crate::` path in the code of `src/` (a `use crate::…`
//! line or a path written inline) may name only its own stage or one below it, and the modules of
//! one stage must not import each other in a cycle. The order is [`STAGES`], the same as the
//! code tour (docs/code.md), which this test checks too.

use crate::common;
use common::root;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The stages, bottom to top: the top-level modules of `src/` in each. A new stage is one line.
const STAGES: &[&[&str]] = &[
    &["error", "safety", "simd", "physics"], // the foundation
    &["scene"],
    &["wheelrail"],
    &["problem"],
    &["solvers"],
    &["history"],
    &["metrics"],
    &["pipeline"],
    &["suite"],
    &["comparison"],
    &["report"],
    &["calibration"],
    &["export", "import"],
    &["commands"],
    &["lib", "main"], // the crate roots
];

/// Imports that still run up the stack (the test fails once an entry is no longer needed, so the
/// list only shrinks).
const NOT_YET: &[(&str, &str)] = &[];

/// The stage index of a top-level module.
fn stage(module: &str) -> Option<usize> {
    STAGES.iter().position(|s| s.contains(&module))
}

/// The top-level module a file of `src/` belongs to (`src/solvers/uba/mod.rs` → `solvers`).
fn module_of(rel: &Path) -> String {
    let first = rel.components().nth(1).expect("a file under src/").as_os_str().to_string_lossy();
    first.trim_end_matches(".rs").to_string()
}

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

/// The code of a line: comments (`//`, doc comments included) cut off.
fn code(line: &str) -> &str {
    match line.find("//") {
        Some(k) => &line[..k],
        None => line,
    }
}

/// The top-level modules named by `crate::` paths in a line of code, including those inside
/// `use crate::{a::…, b::…}` groups (which may span lines: `group` carries the open group).
fn imported(line: &str, group: &mut bool) -> Vec<String> {
    let mut out = Vec::new();
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    let mut rest = line;
    while let Some(k) = rest.find("crate::") {
        let after = &rest[k + "crate::".len()..];
        if let Some(inner) = after.strip_prefix('{') {
            *group = true;
            rest = inner;
            continue;
        }
        out.push(ident(after));
        rest = after;
    }
    if *group {
        // Inside `use crate::{ … }`: each item's first segment names a module.
        for item in rest.split(',') {
            let item = item.trim().trim_start_matches('{');
            let name = ident(item);
            if !name.is_empty() && item[name.len()..].starts_with("::") {
                out.push(name);
            }
        }
        if rest.contains('}') {
            *group = false;
        }
    }
    out
}

/// An import that runs up the stack: file, line, the importing and the imported module.
struct Upward {
    file: String,
    line: usize,
    from: String,
    to: String,
}

#[test]
fn imports_run_only_down_the_stack() {
    let src = root().join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut upward: Vec<Upward> = Vec::new();
    let mut unknown: BTreeSet<String> = BTreeSet::new();
    // Imports between the modules of one stage, for the cycle check: module → (module, where).
    let mut sideways: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    for path in &files {
        let rel = path.strip_prefix(root()).unwrap();
        let file = rel.display().to_string();
        let from = module_of(rel);
        let Some(from_stage) = stage(&from) else {
            unknown.insert(format!("{file}: module `{from}` is in no stage of STAGES"));
            continue;
        };
        let text = std::fs::read_to_string(path).unwrap();
        let mut group = false;
        for (n, line) in text.lines().enumerate() {
            for to in imported(code(line), &mut group) {
                if to == from {
                    continue;
                }
                match stage(&to) {
                    None => {
                        unknown.insert(format!("{file}:{}: `crate::{to}` is in no stage of STAGES", n + 1));
                    }
                    Some(s) if s > from_stage => {
                        upward.push(Upward { file: file.clone(), line: n + 1, from: from.clone(), to });
                    }
                    Some(s) if s == from_stage => {
                        sideways.entry(from.clone()).or_default().entry(to).or_insert(format!("{file}:{}", n + 1));
                    }
                    Some(_) => {}
                }
            }
        }
    }
    assert!(unknown.is_empty(), "modules missing from STAGES:\n{}", unknown.into_iter().collect::<Vec<_>>().join("\n"));

    let allowed = |u: &Upward| NOT_YET.contains(&(u.file.as_str(), u.to.as_str()));
    let wrong: Vec<String> = upward
        .iter()
        .filter(|u| !allowed(u))
        .map(|u| format!("{}:{}: `{}` imports `crate::{}`, a stage above it", u.file, u.line, u.from, u.to))
        .collect();
    assert!(wrong.is_empty(), "imports up the stack (order: {}):\n{}", order(), wrong.join("\n"));
    let stale: Vec<String> = NOT_YET
        .iter()
        .filter(|(f, m)| !upward.iter().any(|u| u.file == *f && u.to == *m))
        .map(|(f, m)| format!("{f} → {m}"))
        .collect();
    assert!(stale.is_empty(), "NOT_YET entries no longer needed (remove them): {}", stale.join(", "));

    let cycles = cycles(&sideways);
    assert!(cycles.is_empty(), "import cycles within a stage:\n{}", cycles.join("\n"));
}

/// The cycles among the modules of a stage, each as `a (file:line) → b (file:line) → … → a`.
fn cycles(edges: &BTreeMap<String, BTreeMap<String, String>>) -> Vec<String> {
    let mut found = Vec::new();
    for start in edges.keys() {
        // Depth-first search for a path back to `start` (stages have a handful of modules).
        let mut stack: Vec<(String, Vec<String>)> = vec![(start.clone(), vec![start.clone()])];
        while let Some((at, path)) = stack.pop() {
            for (next, place) in edges.get(&at).into_iter().flatten() {
                let step = format!("{at} ({place}) → {next}");
                if next == start {
                    let mut p = path.clone();
                    p.push(step);
                    found.push(p[1..].join(", "));
                } else if !path.contains(next) {
                    let mut p = path.clone();
                    p.push(step);
                    stack.push((next.clone(), p));
                }
            }
        }
    }
    found
}

/// The stack written out: `a, b < c < …` (the code tour's form).
fn order() -> String {
    STAGES.iter().map(|s| s.join(", ")).collect::<Vec<_>>().join(" < ")
}

#[test]
fn the_readme_code_tour_gives_the_same_order() {
    let readme = std::fs::read_to_string(root().join("docs/code.md")).unwrap();
    let tour = &readme[readme.find("## The code").expect("the code tour")..];
    let want = order();
    assert!(tour.contains(&want), "the code tour (docs/code.md) must give the stack as `{want}`");
}

#[test]
fn the_reader_finds_every_form_of_path() {
    let mut g = false;
    assert_eq!(imported("use crate::solvers::{self, Termination};", &mut g), ["solvers"]);
    assert_eq!(imported("let x = crate::metrics::by_name(n); crate::error::excerpt(v)", &mut g), ["metrics", "error"]);
    assert_eq!(imported("use crate::{error::Error, history::Row};", &mut g), ["error", "history"]);
    assert!(!g);
    assert_eq!(imported("use crate::{", &mut g), Vec::<String>::new());
    assert!(g);
    assert_eq!(imported("    pipeline::run, scene::Scene,", &mut g), ["pipeline", "scene"]);
    assert_eq!(imported("};", &mut g), Vec::<String>::new());
    assert!(!g);
    assert_eq!(imported(code("/// see [`crate::harness::report`]"), &mut g), Vec::<String>::new());
    assert_eq!(module_of(Path::new("src/solvers/uba/mod.rs")), "solvers");
    assert_eq!(module_of(Path::new("src/pipeline.rs")), "pipeline");
}
