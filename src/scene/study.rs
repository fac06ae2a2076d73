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
use super::reader::{Range, Section};
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
            Allowed::Numbers {
                range: Range::new(f64::NEG_INFINITY, false, f64::INFINITY, false),
                min_len: 1,
                max_len: MAX_STUDY_POINTS,
                note: "one per value",
            },
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

/// One `[[study.axis]]` table (`a`), checked in this order: its name, varied keys, their
/// common length, labels and x values.
fn read_axis(mut a: Section) -> Result<Axis, InputError> {
    let field = a.path().to_string();
    let name = axis_name(&mut a)?;
    let keys = a.family().into_iter().map(|(k, v)| axis_key(k, v, &field)).collect::<Result<Vec<_>, _>>()?;
    let len = axis_len(&keys, &field)?;
    let labels = match a.opt_text_list("labels")? {
        None => keys[0].1.iter().map(label_of).collect(),
        Some(l) if l.len() == len => l,
        Some(l) => {
            return Err(err(a.field("labels"), format!("{} strings", l.len()), format!("{len} strings, one per value")))
        }
    };
    let x_values = match a.opt_num_list("x_values")? {
        Some(x) if x.len() != len => {
            return Err(err(
                a.field("x_values"),
                format!("{} numbers", x.len()),
                format!("{len} numbers, one per value"),
            ))
        }
        x => x,
    };
    a.finish()?;
    Ok(Axis { name, keys, labels, x_values })
}

/// The axis's `name`: a name of [a-z0-9_]+.
fn axis_name(a: &mut Section) -> Result<String, InputError> {
    let name = a.text("name")?;
    match !name.is_empty() && name.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_') {
        true => Ok(name.to_string()),
        false => Err(err(a.field("name"), format!("{name:?}"), allowed(&AXIS_KEYS, "name"))),
    }
}

/// One varied key `k` and its values `v`: a non-empty array, a dotted scene key, finite numbers.
fn axis_key(k: &str, v: &Value, field: &str) -> Result<(String, Vec<Value>), InputError> {
    let values = v
        .as_array()
        .filter(|a| !a.is_empty())
        .ok_or_else(|| err(format!("{field}.\"{k}\""), v, "a non-empty array of values"))?;
    if k.split('.').any(str::is_empty) {
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
    let mut file = Section::new("", doc).declare(&FILE_KEYS);
    let study = file.table("study")?.raw();
    let template = file.table("scene")?.raw();
    file.finish()?;
    if template.contains_key("name") {
        return Err(err(
            "scene.name",
            "given",
            "no name in the template: the study names its scenes (study.scene_name)",
        ));
    }
    Ok((study, template))
}

/// Read the `[study]` table, checked in this order: its name and title, axes, x axis, metrics,
/// scene-name pattern and then its keys (none undeclared).
fn read_study(study: &Table, metric_names: &[&str]) -> Result<Study, InputError> {
    let mut s = Section::new("study", study).declare(&KEYS);
    let name = s.text("name")?.to_string();
    let title = s.opt_text("title")?.map_or_else(|| name.clone(), String::from);
    let axes = read_axes(&mut s)?;
    let x_axis = read_x_axis(s.opt_text("x")?, &axes)?;
    let metrics = read_metrics(&mut s, metric_names)?;
    let pattern = read_pattern(s.opt_text("scene_name")?, &name, &axes)?;
    s.finish()?;
    Ok(Study { name, title, axes, x_axis, metrics, pattern })
}

/// The `[[study.axis]]` tables, each as [`read_axis`] reads it, their names distinct.
fn read_axes(s: &mut Section) -> Result<Vec<Axis>, InputError> {
    let tables = match s.opt_tables("axis")? {
        Some(t) if !t.is_empty() => t,
        _ => return Err(err(s.field("axis"), "missing", allowed(&KEYS, "axis"))),
    };
    let axes: Vec<Axis> = tables.into_iter().map(|a| read_axis(a.declare(&AXIS_KEYS))).collect::<Result<_, _>>()?;
    for (i, a) in axes.iter().enumerate() {
        if axes[..i].iter().any(|b| b.name == a.name) {
            return Err(err(format!("study.axis[{i}].name"), format!("{:?}", a.name), "distinct axis names"));
        }
    }
    Ok(axes)
}

/// The index of the axis on the curves' x (`x`: `study.x`, default the first): its values
/// numbers, or its `x_values` given.
fn read_x_axis(x: Option<&str>, axes: &[Axis]) -> Result<usize, InputError> {
    let x_axis = match x {
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
fn read_metrics(s: &mut Section, metric_names: &[&str]) -> Result<Vec<String>, InputError> {
    let metrics = s.opt_text_list("metrics")?.unwrap_or_default();
    match metrics.iter().find(|m| !metric_names.contains(&m.as_str())) {
        Some(m) => Err(err(s.field("metrics"), format!("{m:?}"), format!("names from {}", metric_names.join(", ")))),
        None => Ok(metrics),
    }
}

/// `study.scene_name` (default `name_axis{axis}_…`): a pattern naming every axis.
fn read_pattern(scene_name: Option<&str>, name: &str, axes: &[Axis]) -> Result<String, InputError> {
    let pattern = match scene_name {
        Some(p) => p.to_string(),
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
