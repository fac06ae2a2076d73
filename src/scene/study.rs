//! Parameter studies (issue 14): one file holding a scene template and the values to vary,
//! expanded into ordinary scenes with deterministic names. Axes are crossed (the first outermost);
//! the keys of one axis vary together (e.g. a load with its semi-axes).
//!
//! ```toml
//! [study]
//! name = "sine_mu"                       # the study's id (report)
//! title = "Friction at 10 Hz (thesis Fig. 4.11)"
//! scene_name = "sine_f10_mu{mu}"         # {axis} = that axis's label (default: name_axislabel_…)
//! x = "mu"                               # the axis on the curves' x (default: the first)
//! metrics = ["delay_ratio", "loop_area"] # the curves drawn (default: every scalar metric)
//!
//! [[study.axis]]
//! name = "mu"
//! "contact.mu" = [0.1, 0.2, 1.0]         # a dotted scene key and its values
//! labels = ["01", "02", "10"]            # optional: name parts (default: the values, compact)
//! # x_values = [...]                     # optional: numbers on x where the values are not numbers
//!
//! [scene]                                # the template: a whole scene without `name`
//! solvers = ["uba", "contact"]
//! # ...
//! ```

use super::keys::{key, Absent, Allowed, Keys};
use crate::error::InputError;
use serde::{Deserialize, Serialize};
use toml::{Table, Value};

/// A study file's tables, each documented under its own heading (`<!-- keys:study -->`).
pub const FILE_KEYS: Keys = Keys {
    id: "study",
    owner: file!(),
    keys: &[
        key("study", "–", Allowed::Section, Absent::Required, "the study: its keys below"),
        key("scene", "–", Allowed::Section, Absent::Required, "the template: a whole scene without `name`"),
    ],
};

/// `[study]`'s keys (`<!-- keys:study -->`).
pub const KEYS: Keys = Keys {
    id: "study",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("a string"),
            Absent::Required,
            r#"the study's id (report, scene.json `studies`): `name = "sine_freq"`"#,
        ),
        key(
            "title",
            "–",
            Allowed::Text("a string"),
            Absent::Text("the name"),
            r#"the study's title in the report: `title = "Frequency at mu = 1"`"#,
        ),
        key(
            "scene_name",
            "–",
            Allowed::Text("a pattern naming every axis as `{axis}`"),
            Absent::Text("`<name>_<axis><label>_…`"),
            r#"the points' scene names; labels must make every name distinct: `scene_name = "sine_f{freq}_mu{mu}"`"#,
        ),
        key(
            "x",
            "–",
            Allowed::Text("one of the axes' names"),
            Absent::Text("the first axis"),
            r#"the axis on the report's x; its values must be numbers (or it has `x_values`): `x = "freq"`"#,
        ),
        key(
            "metrics",
            "–",
            Allowed::Text("metric names (as the scene's `metrics`)"),
            Absent::Text("every scalar metric"),
            r#"the curves the report draws against x: `metrics = ["delay_ratio"]`"#,
        ),
        key(
            "axis",
            "–",
            Allowed::Text("one or more `[[study.axis]]` tables"),
            Absent::Required,
            "the axes, crossed, the first outermost",
        ),
    ],
};

/// `[[study.axis]]`'s keys (`<!-- keys:study_axis -->`); the dotted scene keys are a family.
pub const AXIS_KEYS: Keys = Keys {
    id: "study_axis",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("a name of `a-z`, `0-9`, `_`, distinct among the axes"),
            Absent::Required,
            r#"the axis's name: `name = "mu"`"#,
        ),
        key(
            "`\"table.key\"`",
            "the key's",
            Allowed::Text("a non-empty array of values valid for that scene key"),
            Absent::Text("at least one"),
            r#"a dotted scene key (quoted) and its values; every key of one axis has as many values, and they vary together (a load with its semi-axes): `"contact.mu" = [1.0, 0.6]`"#,
        ),
        key(
            "labels",
            "–",
            Allowed::Text("one string per value"),
            Absent::Text("the values, `.` → `p`, `-` → `m`"),
            r#"the parts of the scene names: `labels = ["10", "06"]`"#,
        ),
        key(
            "x_values",
            "–",
            Allowed::Text("one number per value"),
            Absent::Text("–"),
            r#"the axis's numbers on the report's x where its values are not numbers: `x_values = [-90.0, 0.0, 90.0]`"#,
        ),
    ],
};

/// What `keys` declares `k` allows, as a message says it.
fn allowed(keys: &Keys, k: &str) -> String {
    keys.get(k).map_or_else(String::new, |spec| spec.allowed.message())
}

/// Where a scene sits in a study (scene.json `studies`, read by the report).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyPoint {
    /// The study's id and title.
    pub study: String,
    pub title: String,
    /// The varied key on the curves' x axis (e.g. `creepage.freq_hz`) and its value here.
    pub x_key: String,
    pub x: f64,
    /// The labels of the other axes at this point: one curve per model and series.
    pub series: String,
    /// The metrics the study draws against x.
    pub metrics: Vec<String>,
}

/// One scene of a study: its name, its scene table and its place in the study.
#[derive(Debug, Clone, PartialEq)]
pub struct Expanded {
    pub name: String,
    pub doc: Table,
    pub point: StudyPoint,
}

/// Whether a parsed TOML file is a study (it has a `[study]` table).
pub fn is_study(doc: &Table) -> bool {
    doc.contains_key("study")
}

/// The most scenes one study may expand into.
pub const MAX_STUDY_POINTS: usize = 100_000;

struct Axis {
    name: String,
    keys: Vec<(String, Vec<Value>)>,
    labels: Vec<String>,
    /// The axis's numbers on the curves' x where its keys are not numbers (`x_values`).
    x_values: Option<Vec<f64>>,
}

fn err(field: impl Into<String>, value: impl std::fmt::Display, allowed: impl Into<String>) -> InputError {
    InputError::new(field, value, allowed)
}

/// A value as part of a scene name: numbers compact (`0.5` → `0p5`, `-1` → `m1`), strings as given.
pub fn label_of(v: &Value) -> String {
    match v {
        Value::Integer(i) => i.to_string().replace('-', "m"),
        Value::Float(f) => format!("{f}").replace('-', "m").replace('.', "p"),
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

fn as_f64(v: &Value) -> Option<f64> {
    match v {
        Value::Integer(i) => Some(*i as f64),
        Value::Float(f) => Some(*f),
        _ => None,
    }
}

/// The `n`th `[[study.axis]]` table, checked in this order: its name, varied keys, their common
/// length, labels and x values.
fn read_axis(n: usize, t: &Value) -> Result<Axis, InputError> {
    let field = format!("study.axis[{n}]");
    let t = t.as_table().ok_or_else(|| err(&field, t, "a table: name, dotted scene keys with value lists, labels"))?;
    let name = axis_name(t, &field)?;
    let keys = axis_keys(t, &field)?;
    let len = axis_len(&keys, &field)?;
    let labels = axis_labels(t, &field, &keys[0].1, len)?;
    let x_values = axis_x_values(t, &field, len)?;
    Ok(Axis { name, keys, labels, x_values })
}

/// The axis's `name`: a name of [a-z0-9_]+.
fn axis_name(t: &Table, field: &str) -> Result<String, InputError> {
    match t.get("name") {
        Some(Value::String(s))
            if !s.is_empty() && s.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_') =>
        {
            Ok(s.clone())
        }
        Some(v) => Err(err(format!("{field}.name"), v, allowed(&AXIS_KEYS, "name"))),
        None => Err(err(format!("{field}.name"), "missing", format!("required: {}", allowed(&AXIS_KEYS, "name")))),
    }
}

/// The axis's varied keys, in the table's order: every entry but those [`AXIS_KEYS`] declares
/// (`name`, `labels`, `x_values`), each as [`axis_key`] reads it.
fn axis_keys(t: &Table, field: &str) -> Result<Vec<(String, Vec<Value>)>, InputError> {
    t.iter().filter(|(k, _)| AXIS_KEYS.get(k).is_none()).map(|(k, v)| axis_key(k, v, field)).collect()
}

/// One varied key `k` and its values `v`: a non-empty array, a dotted scene key, finite numbers.
fn axis_key(k: &str, v: &Value, field: &str) -> Result<(String, Vec<Value>), InputError> {
    let values = v
        .as_array()
        .filter(|a| !a.is_empty())
        .ok_or_else(|| err(format!("{field}.\"{k}\""), v, "a non-empty array of values"))?;
    if k.split('.').any(str::is_empty) || k == "name" {
        return Err(err(field, format!("{k:?}"), "dotted scene keys such as \"contact.mu\""));
    }
    if let Some(v) = values.iter().find(|v| v.as_float().is_some_and(|f| !f.is_finite())) {
        return Err(err(format!("{field}.\"{k}\""), v, "finite numbers (no nan or inf)"));
    }
    Ok((k.to_string(), values.clone()))
}

/// The axis's length: that of its first key, which every other key must share (at least one key).
fn axis_len(keys: &[(String, Vec<Value>)], field: &str) -> Result<usize, InputError> {
    let len = keys.first().map(|(_, v)| v.len()).ok_or_else(|| {
        err(
            field,
            "no varied key",
            "at least one dotted scene key with a list of values, e.g. \"contact.mu\" = [0.1, 0.2]",
        )
    })?;
    if let Some((k, v)) = keys.iter().find(|(_, v)| v.len() != len) {
        return Err(err(
            format!("{field}.\"{k}\""),
            format!("{} values", v.len()),
            format!("{len} values, as the axis's first key"),
        ));
    }
    Ok(len)
}

/// The axis's `labels`: `len` strings, or by default the `first` key's values, compact ([`label_of`]).
fn axis_labels(t: &Table, field: &str, first: &[Value], len: usize) -> Result<Vec<String>, InputError> {
    match t.get("labels") {
        None => Ok(first.iter().map(label_of).collect()),
        Some(Value::Array(a)) if a.len() == len && a.iter().all(Value::is_str) => {
            Ok(a.iter().filter_map(|v| v.as_str().map(String::from)).collect())
        }
        Some(v) => Err(err(format!("{field}.labels"), v, format!("{len} strings, one per value"))),
    }
}

/// The axis's `x_values` if given: `len` finite numbers, the axis's numbers on the curves' x.
fn axis_x_values(t: &Table, field: &str, len: usize) -> Result<Option<Vec<f64>>, InputError> {
    match t.get("x_values") {
        None => Ok(None),
        Some(Value::Array(a)) if a.len() == len && a.iter().all(|v| as_f64(v).is_some_and(f64::is_finite)) => {
            Ok(Some(a.iter().filter_map(as_f64).collect()))
        }
        Some(v) => Err(err(format!("{field}.x_values"), v, format!("{len} numbers, one per value (finite)"))),
    }
}

/// Set the dotted key `path` of `doc` to `value`, creating tables on the way.
pub fn set(doc: &mut Table, path: &str, value: Value, field: &str) -> Result<(), InputError> {
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop().unwrap_or(path);
    let mut t = doc;
    for p in parts {
        let entry = t.entry(p.to_string()).or_insert_with(|| Value::Table(Table::new()));
        t = entry
            .as_table_mut()
            .ok_or_else(|| err(field, format!("{path:?}"), format!("a key inside a table; {p:?} is a value")))?;
    }
    t.insert(last.to_string(), value);
    Ok(())
}

/// Expand a study file's table into its scenes, in axis order (the first axis outermost);
/// `study.metrics` must name metrics of `metric_names` (the registry's, given by the pipeline).
pub fn expand(doc: &Table, metric_names: &[&str]) -> Result<Vec<Expanded>, InputError> {
    let (study, template) = study_and_template(doc)?;
    let study = read_study(study, metric_names)?;
    let total = point_count(&study.axes)?;
    let mut out = Vec::with_capacity(total);
    let mut names = std::collections::HashSet::with_capacity(total);
    for n in 0..total {
        let scene = expand_point(template, &study, &axis_indices(n, &study.axes))?;
        if !names.insert(scene.name.clone()) {
            return Err(err(
                "study.scene_name",
                format!("{:?} twice", scene.name),
                "labels that make every scene name distinct",
            ));
        }
        out.push(scene);
    }
    Ok(out)
}

/// A study's `[study]` table read and checked: all its scenes need besides the template.
struct Study {
    name: String,
    title: String,
    axes: Vec<Axis>,
    /// The axis on the curves' x (its index in `axes`).
    x_axis: usize,
    metrics: Vec<String>,
    /// The scene names, `{axis}` standing for that axis's label.
    pattern: String,
}

/// The file's `[study]` and `[scene]` tables (nothing else), the template without `name`.
fn study_and_template(doc: &Table) -> Result<(&Table, &Table), InputError> {
    if let Some(k) = doc.keys().find(|k| *k != "study" && *k != "scene") {
        return Err(err(k.as_str(), "given", "a study file holds only [study] and [scene]"));
    }
    let study =
        doc.get("study").and_then(Value::as_table).ok_or_else(|| err("study", "not a table", "a [study] table"))?;
    let template = doc
        .get("scene")
        .and_then(Value::as_table)
        .ok_or_else(|| err("scene", "missing", "a [scene] table: the template scene without `name`"))?;
    if template.contains_key("name") {
        return Err(err(
            "scene.name",
            "given",
            "no name in the template: the study names its scenes (study.scene_name)",
        ));
    }
    Ok((study, template))
}

/// Read the `[study]` table, checked in this order: its keys, name and title, axes, x axis,
/// metrics and scene-name pattern.
fn read_study(study: &Table, metric_names: &[&str]) -> Result<Study, InputError> {
    check_study_keys(study)?;
    let name = text("name", study)?
        .ok_or_else(|| err("study.name", "missing", format!("required: {}", allowed(&KEYS, "name"))))?;
    let title = text("title", study)?.unwrap_or_else(|| name.clone());
    let axes = read_axes(study)?;
    let x_axis = read_x_axis(study, &axes)?;
    let metrics = read_metrics(study, metric_names)?;
    let pattern = read_pattern(study, &name, &axes)?;
    Ok(Study { name, title, axes, x_axis, metrics, pattern })
}

/// Refuse a `[study]` key [`KEYS`] does not declare.
fn check_study_keys(study: &Table) -> Result<(), InputError> {
    if let Some(k) = study.keys().find(|k| KEYS.get(k).is_none()) {
        let known: Vec<&str> = KEYS.keys.iter().map(|k| k.key).collect();
        return Err(err(format!("study.{k}"), "given", format!("one of {}", known.join(", "))));
    }
    Ok(())
}

/// The string `study.<k>` if given (`k` first, a literal: tests/all/docs.rs reads the keys from these calls).
fn text(k: &str, study: &Table) -> Result<Option<String>, InputError> {
    match study.get(k) {
        None => Ok(None),
        Some(Value::String(s)) => Ok(Some(s.clone())),
        Some(v) => Err(err(format!("study.{k}"), v, allowed(&KEYS, k))),
    }
}

/// The `[[study.axis]]` tables, each as [`read_axis`] reads it, their names distinct.
fn read_axes(study: &Table) -> Result<Vec<Axis>, InputError> {
    let axes: Vec<Axis> = match study.get("axis") {
        Some(Value::Array(a)) if !a.is_empty() => {
            a.iter().enumerate().map(|(n, t)| read_axis(n, t)).collect::<Result<_, _>>()?
        }
        other => {
            let v = other.map(|v| v.to_string()).unwrap_or_else(|| "missing".into());
            return Err(err("study.axis", v, "one or more [[study.axis]] tables"));
        }
    };
    for (i, a) in axes.iter().enumerate() {
        if axes[..i].iter().any(|b| b.name == a.name) {
            return Err(err(format!("study.axis[{i}].name"), format!("{:?}", a.name), "distinct axis names"));
        }
    }
    Ok(axes)
}

/// The index of the axis on the curves' x (`study.x`, default the first): its values numbers,
/// or its `x_values` given.
fn read_x_axis(study: &Table, axes: &[Axis]) -> Result<usize, InputError> {
    let x_axis = match text("x", study)? {
        None => 0,
        Some(x) => axes.iter().position(|a| a.name == x).ok_or_else(|| {
            let names: Vec<&str> = axes.iter().map(|a| a.name.as_str()).collect();
            err("study.x", format!("{x:?}"), format!("one of the axes: {}", names.join(", ")))
        })?,
    };
    if axes[x_axis].x_values.is_none() && axes[x_axis].keys[0].1.iter().any(|v| as_f64(v).is_none()) {
        return Err(err(
            format!("study.axis[{x_axis}]"),
            format!("{:?}", axes[x_axis].keys[0].0),
            "numbers on the x axis (or the axis's x_values)",
        ));
    }
    Ok(x_axis)
}

/// `study.metrics`: names from `metric_names` (none given: every scalar metric is drawn).
fn read_metrics(study: &Table, metric_names: &[&str]) -> Result<Vec<String>, InputError> {
    match study.get("metrics") {
        None => Ok(Vec::new()),
        Some(Value::Array(a)) => a
            .iter()
            .map(|m| match m.as_str() {
                Some(s) if metric_names.contains(&s) => Ok(s.to_string()),
                _ => Err(err("study.metrics", m, format!("names from {}", metric_names.join(", ")))),
            })
            .collect(),
        Some(v) => Err(err("study.metrics", v, "an array of metric names")),
    }
}

/// `study.scene_name` (default `name_axis{axis}_…`): a pattern naming every axis.
fn read_pattern(study: &Table, name: &str, axes: &[Axis]) -> Result<String, InputError> {
    let pattern = match text("scene_name", study)? {
        Some(p) => p,
        None => std::iter::once(name.to_string())
            .chain(axes.iter().map(|a| format!("{}{{{}}}", a.name, a.name)))
            .collect::<Vec<_>>()
            .join("_"),
    };
    for a in axes {
        if !pattern.contains(&format!("{{{}}}", a.name)) {
            return Err(err(
                "study.scene_name",
                format!("{pattern:?}"),
                format!("a pattern naming every axis, e.g. {{{}}}: distinct names per scene", a.name),
            ));
        }
    }
    Ok(pattern)
}

/// The number of points, the axes' lengths multiplied; refused before anything is allocated
/// beyond [`MAX_STUDY_POINTS`] (more points than any suite could run).
fn point_count(axes: &[Axis]) -> Result<usize, InputError> {
    let total = axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.labels.len()));
    total.filter(|&n| n <= MAX_STUDY_POINTS).ok_or_else(|| {
        let sizes: Vec<String> = axes.iter().map(|a| a.labels.len().to_string()).collect();
        err("study.axis", format!("{} points", sizes.join(" x ")), format!("at most {MAX_STUDY_POINTS} points"))
    })
}

/// Point `n`'s value index on each axis: mixed radix, the last axis fastest.
fn axis_indices(n: usize, axes: &[Axis]) -> Vec<usize> {
    let mut rest = n;
    let mut at = vec![0; axes.len()];
    for (i, a) in axes.iter().enumerate().rev() {
        at[i] = rest % a.labels.len();
        rest /= a.labels.len();
    }
    at
}

/// The scene at the value indices `at`: the template with the axes' keys set, named by the pattern.
fn expand_point(template: &Table, study: &Study, at: &[usize]) -> Result<Expanded, InputError> {
    let mut doc = scene_at(template, &study.axes, at)?;
    let name = scene_name_at(&study.pattern, &study.axes, at);
    doc.insert("name".into(), Value::String(name.clone()));
    Ok(Expanded { name, doc, point: study_point(study, at) })
}

/// The template with each axis's keys set to their values at `at`.
fn scene_at(template: &Table, axes: &[Axis], at: &[usize]) -> Result<Table, InputError> {
    let mut scene = template.clone();
    for (a, &k) in axes.iter().zip(at) {
        for (key, values) in &a.keys {
            set(&mut scene, key, values[k].clone(), &format!("study.axis {:?} key {key:?}", a.name))?;
        }
    }
    Ok(scene)
}

/// The scene name at `at`: the pattern with each `{axis}` replaced by that axis's label.
fn scene_name_at(pattern: &str, axes: &[Axis], at: &[usize]) -> String {
    let mut scene_name = pattern.to_string();
    for (a, &k) in axes.iter().zip(at) {
        scene_name = scene_name.replace(&format!("{{{}}}", a.name), &a.labels[k]);
    }
    scene_name
}

/// Where the point `at` sits in the study: its x (the x axis's value, or its `x_values`) and the
/// labels of the other axes (its series).
fn study_point(study: &Study, at: &[usize]) -> StudyPoint {
    let x_axis = &study.axes[study.x_axis];
    let series: Vec<String> = study
        .axes
        .iter()
        .zip(at)
        .enumerate()
        .filter(|(i, _)| *i != study.x_axis)
        .map(|(_, (a, &k))| format!("{} {}", a.name, a.labels[k]))
        .collect();
    StudyPoint {
        study: study.name.clone(),
        title: study.title.clone(),
        x_key: match &x_axis.x_values {
            Some(_) => x_axis.name.clone(),
            None => x_axis.keys[0].0.clone(),
        },
        x: match &x_axis.x_values {
            Some(v) => v[at[study.x_axis]],
            None => as_f64(&x_axis.keys[0].1[at[study.x_axis]]).unwrap_or(f64::NAN),
        },
        series: series.join(", "),
        metrics: study.metrics.clone(),
    }
}
