//! A strict reader over a TOML table: typed getters with range checks, and unknown-key errors.
//! Every error names the dotted field, the value given and what is allowed.

use super::keys::{bound, Absent, Allowed, KeySpec, Keys};
use crate::error::InputError;
use std::collections::BTreeSet;
use toml::{Table, Value};

/// Parse TOML text as a table; an error names `field` (a file, usually), the line and column
/// where the parser stopped, an excerpt of that line and the parser's message. The line is
/// quoted only if it looks like a line of this tool's own files ([`looks_like_own_toml`]): a file
/// that is not (`passwd.toml -> /etc/passwd`) is named by its path and position only.
pub fn parse_toml(text: &str, field: impl Into<String>) -> Result<Table, InputError> {
    text.parse().map_err(|e: toml::de::Error| {
        let field = field.into();
        let allowed = format!("valid TOML ({})", e.message());
        match e.span() {
            Some(span) => {
                let at = LineColumn::of(text, span.start);
                let line = text.lines().nth(at.line - 1).unwrap_or("");
                let value = match looks_like_own_toml(line) {
                    true => format!("malformed TOML in {:?}", at.excerpt),
                    false => "malformed TOML (not quoted: not this tool's TOML)".to_string(),
                };
                InputError::new(format!("{field} line {}, column {}", at.line, at.column), value, allowed)
            }
            None => InputError::new(field, "malformed TOML", allowed),
        }
    })
}

/// Whether a line may be quoted in a message, as [`crate::error::name_excerpt`] quotes a column
/// name only if it looks like one: a table header or a `key = value` line of names, numbers and
/// the punctuation of TOML (no `:`, `/`, `@`, `$`, …), as this tool's scene, study, fit and
/// tolerance files are written. Any other line — a password file's, a key's — is not quoted.
pub fn looks_like_own_toml(line: &str) -> bool {
    let t = line.trim();
    let key = |k: &str| !k.is_empty() && k.chars().all(|c| c.is_alphanumeric() || "_-.\"' ".contains(c));
    let shape = t.starts_with('[') || t.split_once('=').is_some_and(|(k, _)| key(k.trim()));
    shape && t.chars().all(|c| c.is_alphanumeric() || c.is_whitespace() || "_.-+=[]{},\"'#*".contains(c))
}

/// A byte offset of a text as a 1-based line and column (in characters) with an excerpt of
/// that line around the column.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LineColumn {
    pub line: usize,
    pub column: usize,
    pub excerpt: String,
}

impl LineColumn {
    /// Characters of the line shown at most (the excerpt starts up to 20 before the column).
    const EXCERPT_CHARS: usize = 40;

    /// Where byte `offset` of `text` lies (an offset past the end: the end of the last line).
    pub fn of(text: &str, offset: usize) -> LineColumn {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let before = &text[..offset];
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let line_end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
        let line_text = text[line_start..line_end].trim_end_matches('\r');
        let column0 = text[line_start..offset].chars().count();
        let skip = column0.saturating_sub(20);
        let excerpt: String = line_text.chars().skip(skip).take(Self::EXCERPT_CHARS).collect();
        LineColumn { line: before.matches('\n').count() + 1, column: column0 + 1, excerpt }
    }
}

/// One TOML table being read; keys not consumed are reported by [`Section::finish`].
pub struct Section<'a> {
    path: String,
    table: &'a Table,
    used: BTreeSet<String>,
    /// The declarations of this section's keys ([`Section::declare`]; none: keys read freely).
    declared: Vec<&'static Keys>,
    /// Keys read that no declaration names (a bug; [`Section::finish`] reports it).
    undeclared: BTreeSet<String>,
}

/// A section whose remaining keys a later stage reads (a model's own `[model]` keys): its table
/// and the keys read so far, so that the last reader's [`Section::finish`] names every known key.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Deferred {
    path: String,
    table: Table,
    used: BTreeSet<String>,
    declared: Vec<&'static Keys>,
}

impl Deferred {
    /// An absent section (no keys to read) whose keys `keys` declares.
    pub fn empty(path: impl Into<String>, keys: &'static Keys) -> Self {
        Deferred { path: path.into(), declared: vec![keys], ..Deferred::default() }
    }

    /// Read on where [`Section::defer`] stopped.
    pub fn resume(&self) -> Section<'_> {
        Section {
            path: self.path.clone(),
            table: &self.table,
            used: self.used.clone(),
            declared: self.declared.clone(),
            undeclared: BTreeSet::new(),
        }
    }
}

/// A numeric range with its wording.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    pub min: f64,
    pub min_inclusive: bool,
    pub max: f64,
    pub max_inclusive: bool,
}

impl Range {
    pub const fn new(min: f64, min_inclusive: bool, max: f64, max_inclusive: bool) -> Self {
        Self { min, min_inclusive, max, max_inclusive }
    }
    /// (0, max]
    pub const fn positive_to(max: f64) -> Self {
        Self::new(0.0, false, max, true)
    }
    pub fn contains(&self, v: f64) -> bool {
        v.is_finite()
            && (if self.min_inclusive { v >= self.min } else { v > self.min })
            && (if self.max_inclusive { v <= self.max } else { v < self.max })
    }
    /// The range as an interval (`(0, 1e4]`, `[0, ∞)`), or "any finite number".
    pub fn interval(&self) -> String {
        if self.min == f64::NEG_INFINITY && self.max == f64::INFINITY {
            return "any finite number".to_string();
        }
        let lo = if self.min_inclusive && self.min.is_finite() { '[' } else { '(' };
        let hi = if self.max_inclusive && self.max.is_finite() { ']' } else { ')' };
        let end = |v: f64| {
            if v.is_finite() {
                bound(v)
            } else if v > 0.0 {
                "∞".into()
            } else {
                "-∞".into()
            }
        };
        format!("{lo}{}, {}{hi}", end(self.min), end(self.max))
    }
    /// The range in words, as messages say what is allowed.
    pub fn describe(&self) -> String {
        match self.interval() {
            any if any.starts_with("any") => any,
            interval => format!("a finite number in {interval}"),
        }
    }
}

fn show(v: &Value) -> String {
    match v {
        Value::String(s) => format!("{s:?}"),
        other => other.to_string(),
    }
}

impl<'a> Section<'a> {
    pub fn new(path: impl Into<String>, table: &'a Table) -> Self {
        Self { path: path.into(), table, used: BTreeSet::new(), declared: Vec::new(), undeclared: BTreeSet::new() }
    }

    /// This section's keys are `keys` (and those of any other declaration added): the declared
    /// getters ([`Section::num`], …) check a value by its declaration, a key read that none
    /// declares fails [`Section::finish`], and an unknown key's message lists the declared keys.
    pub fn declare(mut self, keys: &'static Keys) -> Self {
        self.declared.push(keys);
        self
    }

    /// This section's dotted name (`study.axis[0]`).
    pub fn path(&self) -> &str {
        &self.path
    }

    /// Dotted name of `key` in this section.
    pub fn field(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{}", self.path, key)
        }
    }

    fn get(&mut self, key: &str) -> Option<&'a Value> {
        if !self.declared.is_empty() && self.declaration(key).is_none() {
            self.undeclared.insert(key.to_string());
        }
        self.used.insert(key.to_string());
        self.table.get(key)
    }

    fn declaration(&self, key: &str) -> Option<&'static KeySpec> {
        self.declared.iter().find_map(|keys| keys.get(key))
    }

    /// A key read as a kind its declaration does not give, or not declared: a bug of the reader.
    fn misdeclared(&self, key: &str) -> InputError {
        InputError::new(
            self.field(key),
            "read as a key of another kind than declared, or not declared",
            "a key as the reader declares it (a bug in creepbench: please report it)",
        )
    }

    /// The value of `key` as given, if any (read later by another stage, e.g. a list of names
    /// the pipeline checks against a registry).
    pub fn given(&mut self, key: &str) -> Option<&'a Value> {
        self.get(key)
    }

    pub fn has(&self, key: &str) -> bool {
        self.table.contains_key(key)
    }

    fn missing(&self, key: &str, allowed: &str) -> InputError {
        InputError::new(self.field(key), "missing", format!("required: {allowed}"))
    }

    /// An optional number (integer or float) within `range`.
    pub fn opt_f64(&mut self, key: &str, range: Range) -> Result<Option<f64>, InputError> {
        self.opt_f64_said(key, range, &range.describe())
    }

    /// [`Section::opt_f64`], an error saying `allowed`.
    fn opt_f64_said(&mut self, key: &str, range: Range, allowed: &str) -> Result<Option<f64>, InputError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let x = match v {
            Value::Float(f) => *f,
            Value::Integer(i) => *i as f64,
            other => return Err(InputError::new(self.field(key), show(other), allowed)),
        };
        if !range.contains(x) {
            return Err(InputError::new(self.field(key), x, allowed));
        }
        Ok(Some(x))
    }

    /// A required number within `range`.
    pub fn f64(&mut self, key: &str, range: Range) -> Result<f64, InputError> {
        self.opt_f64(key, range)?.ok_or_else(|| self.missing(key, &range.describe()))
    }

    /// An optional array of exactly `N` numbers (integer or float), each within `range`.
    pub fn opt_f64_array<const N: usize>(&mut self, key: &str, range: Range) -> Result<Option<[f64; N]>, InputError> {
        let allowed = format!("an array of {N} numbers, each {}", range.describe());
        let Some(v) = self.numbers(key, range, |n| n == N, &allowed)? else {
            return Ok(None);
        };
        let mut out = [0.0; N];
        out.copy_from_slice(&v);
        Ok(Some(out))
    }

    /// An optional non-empty array of numbers, each within `range`, at most `max_len` of them.
    pub fn opt_f64_list(&mut self, key: &str, range: Range, max_len: usize) -> Result<Option<Vec<f64>>, InputError> {
        let allowed = format!("an array of 1 to {max_len} numbers, each {}", range.describe());
        self.numbers(key, range, |n| (1..=max_len).contains(&n), &allowed)
    }

    /// An optional array of numbers whose length passes `len_ok`, each within `range`.
    fn numbers(
        &mut self,
        key: &str,
        range: Range,
        len_ok: impl Fn(usize) -> bool,
        allowed: &str,
    ) -> Result<Option<Vec<f64>>, InputError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let items = match v {
            Value::Array(items) if len_ok(items.len()) => items,
            other => return Err(InputError::new(self.field(key), show(other), allowed)),
        };
        let mut out = Vec::with_capacity(items.len());
        for (n, item) in items.iter().enumerate() {
            let x = match item {
                Value::Float(f) => *f,
                Value::Integer(i) => *i as f64,
                other => return Err(InputError::new(format!("{}[{n}]", self.field(key)), show(other), allowed)),
            };
            if !range.contains(x) {
                return Err(InputError::new(format!("{}[{n}]", self.field(key)), x, allowed));
            }
            out.push(x);
        }
        Ok(Some(out))
    }

    /// An optional whole number in `[min, max]`.
    pub fn opt_usize(&mut self, key: &str, min: usize, max: usize) -> Result<Option<usize>, InputError> {
        let allowed = format!("a whole number in [{min}, {max}]");
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        match v {
            Value::Integer(i) if *i >= min as i64 && *i <= max as i64 => Ok(Some(*i as usize)),
            other => Err(InputError::new(self.field(key), show(other), allowed)),
        }
    }

    /// A required whole number in `[min, max]`.
    pub fn usize(&mut self, key: &str, min: usize, max: usize) -> Result<usize, InputError> {
        self.opt_usize(key, min, max)?.ok_or_else(|| self.missing(key, &format!("a whole number in [{min}, {max}]")))
    }

    /// An optional boolean.
    pub fn opt_bool(&mut self, key: &str) -> Result<Option<bool>, InputError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Boolean(b)) => Ok(Some(*b)),
            Some(other) => Err(InputError::new(self.field(key), show(other), "true or false")),
        }
    }

    /// An optional string.
    pub fn opt_str(&mut self, key: &str, allowed: &str) -> Result<Option<&'a str>, InputError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::String(s)) => Ok(Some(s.as_str())),
            Some(other) => Err(InputError::new(self.field(key), show(other), allowed.to_string())),
        }
    }

    /// A required string.
    pub fn str(&mut self, key: &str, allowed: &str) -> Result<&'a str, InputError> {
        self.opt_str(key, allowed)?.ok_or_else(|| self.missing(key, allowed))
    }

    /// An optional string that must be one of `choices`.
    pub fn opt_choice(&mut self, key: &str, choices: &[&str]) -> Result<Option<&'a str>, InputError> {
        let allowed = format!("one of {}", choices.join(", "));
        match self.opt_str(key, &allowed)? {
            None => Ok(None),
            Some(s) if choices.contains(&s) => Ok(Some(s)),
            Some(s) => Err(InputError::new(self.field(key), format!("{s:?}"), allowed)),
        }
    }

    /// A required string that must be one of `choices`.
    pub fn choice(&mut self, key: &str, choices: &[&str]) -> Result<&'a str, InputError> {
        let allowed = format!("one of {}", choices.join(", "));
        self.opt_choice(key, choices)?.ok_or_else(|| self.missing(key, &allowed))
    }

    /// An optional array of strings, each checked by `check`.
    pub fn opt_str_list(&mut self, key: &str, allowed: &str) -> Result<Option<Vec<String>>, InputError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let Value::Array(items) = v else {
            return Err(InputError::new(self.field(key), show(v), format!("an array of strings: {allowed}")));
        };
        items
            .iter()
            .enumerate()
            .map(|(n, item)| match item {
                Value::String(s) => Ok(s.clone()),
                other => Err(InputError::new(format!("{}[{n}]", self.field(key)), show(other), allowed.to_string())),
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// Refuses `key` when present (a key this section allows only in other cases): the error
    /// names it, its value and `allowed`.
    pub fn refuse(&mut self, key: &str, allowed: &str) -> Result<(), InputError> {
        match self.get(key) {
            None => Ok(()),
            Some(v) => Err(InputError::new(self.field(key), show(v), allowed.to_string())),
        }
    }

    /// An optional array of tables (`[[key]]`), each read by the caller.
    pub fn opt_tables(&mut self, key: &str) -> Result<Option<Vec<Section<'a>>>, InputError> {
        let Some(v) = self.get(key) else {
            return Ok(None);
        };
        let field = self.field(key);
        let Value::Array(items) = v else {
            return Err(InputError::new(field, show(v), "an array of tables ([[section]])"));
        };
        items
            .iter()
            .enumerate()
            .map(|(n, item)| match item {
                Value::Table(t) => Ok(Section::new(format!("{field}[{n}]"), t)),
                other => Err(InputError::new(format!("{field}[{n}]"), show(other), "a table")),
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// The table itself (for sections whose keys are free, like a fit's `[set]`).
    pub fn raw(&self) -> &'a Table {
        self.table
    }

    /// An optional sub-table.
    pub fn opt_table(&mut self, key: &str) -> Result<Option<Section<'a>>, InputError> {
        match self.get(key) {
            None => Ok(None),
            Some(Value::Table(t)) => Ok(Some(Section::new(self.field(key), t))),
            Some(other) => Err(InputError::new(self.field(key), show(other), "a table ([section])")),
        }
    }

    /// A required sub-table.
    pub fn table(&mut self, key: &str) -> Result<Section<'a>, InputError> {
        self.opt_table(key)?.ok_or_else(|| self.missing(key, "a table ([section])"))
    }

    /// Keys of this table (for sections whose keys are names, like `[external]`).
    pub fn keys(&self) -> Vec<String> {
        self.table.keys().cloned().collect()
    }

    /// Leave the keys not read yet to a later stage ([`Deferred::resume`]); it calls `finish`.
    pub fn defer(self) -> Deferred {
        Deferred { path: self.path, table: self.table.clone(), used: self.used, declared: self.declared }
    }

    /// Fails on the first key that was never read (naming the declared keys, or those read), or
    /// on a key read that no declaration names.
    pub fn finish(self) -> Result<(), InputError> {
        if let Some(key) = self.undeclared.first() {
            return Err(self.misdeclared(key));
        }
        let mut known: BTreeSet<&str> = self.used.iter().map(String::as_str).collect();
        known.extend(self.declared.iter().flat_map(|k| k.keys).filter(|k| !k.is_family()).map(|k| k.key));
        let known: Vec<&str> = known.into_iter().collect();
        for (k, v) in self.table {
            if !self.used.contains(k) {
                return Err(InputError::new(
                    self.field(k),
                    show(v),
                    format!("no such key here; known keys: {}", known.join(", ")),
                ));
            }
        }
        Ok(())
    }
}

/// The declared getters: the range, choices, wording and default of a key come from its
/// declaration ([`Section::declare`]), so a message's "allowed" is the docs' text.
impl<'a> Section<'a> {
    fn spec(&self, key: &str) -> Result<&'static KeySpec, InputError> {
        self.declaration(key).ok_or_else(|| self.misdeclared(key))
    }

    /// An optional number, as declared ([`Allowed::Number`]).
    pub fn opt_num(&mut self, key: &str) -> Result<Option<f64>, InputError> {
        match self.spec(key)?.allowed {
            spec @ Allowed::Number(range, _) => self.opt_f64_said(key, range, &spec.message()),
            _ => Err(self.misdeclared(key)),
        }
    }

    /// A required number, as declared.
    pub fn num(&mut self, key: &str) -> Result<f64, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.opt_num(key)?.ok_or_else(|| self.missing(key, &allowed))
    }

    /// A number as declared, or its declared default ([`Absent::Num`]).
    pub fn num_or_default(&mut self, key: &str) -> Result<f64, InputError> {
        match self.spec(key)?.default {
            Absent::Num(v) => Ok(self.opt_num(key)?.unwrap_or(v)),
            _ => Err(self.misdeclared(key)),
        }
    }

    /// An optional array of exactly `N` numbers, as declared ([`Allowed::Numbers`]).
    pub fn opt_nums<const N: usize>(&mut self, key: &str) -> Result<Option<[f64; N]>, InputError> {
        let Some(v) = self.opt_num_list(key)? else {
            return Ok(None);
        };
        let mut out = [0.0; N];
        match v.len() == N {
            true => out.copy_from_slice(&v),
            false => return Err(self.misdeclared(key)),
        }
        Ok(Some(out))
    }

    /// An optional array of numbers, as declared ([`Allowed::Numbers`]).
    pub fn opt_num_list(&mut self, key: &str) -> Result<Option<Vec<f64>>, InputError> {
        match self.spec(key)?.allowed {
            spec @ Allowed::Numbers { range, min_len, max_len, .. } => {
                self.numbers(key, range, |n| (min_len..=max_len).contains(&n), &spec.message())
            }
            _ => Err(self.misdeclared(key)),
        }
    }

    /// An optional whole number, as declared ([`Allowed::Whole`]).
    pub fn opt_whole(&mut self, key: &str) -> Result<Option<usize>, InputError> {
        let spec = self.spec(key)?.allowed;
        let Allowed::Whole(min, max, _) = spec else {
            return Err(self.misdeclared(key));
        };
        match self.get(key) {
            None => Ok(None),
            Some(Value::Integer(i)) if *i >= min as i64 && *i <= max as i64 => Ok(Some(*i as usize)),
            Some(other) => Err(InputError::new(self.field(key), show(other), spec.message())),
        }
    }

    /// A required whole number, as declared.
    pub fn whole(&mut self, key: &str) -> Result<usize, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.opt_whole(key)?.ok_or_else(|| self.missing(key, &allowed))
    }

    /// A whole number as declared, or its declared default ([`Absent::Whole`]).
    pub fn whole_or_default(&mut self, key: &str) -> Result<usize, InputError> {
        match self.spec(key)?.default {
            Absent::Whole(n) => Ok(self.opt_whole(key)?.unwrap_or(n)),
            _ => Err(self.misdeclared(key)),
        }
    }

    /// An optional choice among the declared ones ([`Allowed::Choice`]).
    pub fn opt_pick(&mut self, key: &str) -> Result<Option<&'a str>, InputError> {
        match self.spec(key)?.allowed {
            Allowed::Choice(choices, _) => self.opt_choice(key, choices),
            _ => Err(self.misdeclared(key)),
        }
    }

    /// A required choice among the declared ones.
    pub fn pick(&mut self, key: &str) -> Result<&'a str, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.opt_pick(key)?.ok_or_else(|| self.missing(key, &allowed))
    }

    /// A choice, or its declared default ([`Absent::Choice`]).
    pub fn pick_or_default(&mut self, key: &str) -> Result<&'a str, InputError> {
        match self.spec(key)?.default {
            Absent::Choice(c) => Ok(self.opt_pick(key)?.unwrap_or(c)),
            _ => Err(self.misdeclared(key)),
        }
    }

    /// An optional string, its wording declared ([`Allowed::Text`]).
    pub fn opt_text(&mut self, key: &str) -> Result<Option<&'a str>, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.opt_str(key, &allowed)
    }

    /// A required string, its wording declared.
    pub fn text(&mut self, key: &str) -> Result<&'a str, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.str(key, &allowed)
    }

    /// An optional array of strings, its wording declared ([`Allowed::Text`]).
    pub fn opt_text_list(&mut self, key: &str) -> Result<Option<Vec<String>>, InputError> {
        let allowed = self.spec(key)?.allowed.message();
        self.opt_str_list(key, &allowed)
    }

    /// The entries no declared key names, marked read, in the table's order: the keys of a
    /// family (a study axis's dotted scene keys), each checked by the caller.
    pub fn family(&mut self) -> Vec<(&'a str, &'a Value)> {
        let table = self.table;
        let out: Vec<(&'a str, &'a Value)> =
            table.iter().filter(|(k, _)| self.declaration(k).is_none()).map(|(k, v)| (k.as_str(), v)).collect();
        self.used.extend(out.iter().map(|(k, _)| k.to_string()));
        out
    }
}

#[cfg(test)]
mod declared_tests {
    use super::*;
    use crate::scene::keys::key;

    const T: Keys = Keys {
        id: "t",
        owner: file!(),
        keys: &[
            key("a_mm", "mm", Allowed::Number(Range::new(0.0, false, 1e4, true), "below b_mm"), Absent::Num(2.0), ""),
            key("kind", "–", Allowed::Choice(&["x", "y"], ""), Absent::Choice("y"), ""),
        ],
    };

    fn table(text: &str) -> Table {
        text.parse().unwrap()
    }

    #[test]
    fn a_declared_getter_checks_and_words_by_the_declaration() {
        let t = table("a_mm = 2e4\nkind = \"x\"");
        let mut s = Section::new("c", &t).declare(&T);
        let e = s.num("a_mm").unwrap_err().to_string();
        assert!(e.contains("c.a_mm` = 20000: allowed: a finite number in (0, 1e4]; below b_mm"), "{e}");
        assert_eq!(s.pick_or_default("kind").unwrap(), "x");
        let empty = table("");
        let mut s = Section::new("c", &empty).declare(&T);
        assert_eq!((s.num_or_default("a_mm").unwrap(), s.pick_or_default("kind").unwrap()), (2.0, "y"));
    }

    #[test]
    fn an_unknown_key_names_the_declared_keys() {
        let t = table("a_mm = 1.0\nzz = 1");
        let mut s = Section::new("c", &t).declare(&T);
        s.num("a_mm").unwrap();
        let e = s.finish().unwrap_err().to_string();
        assert!(e.contains("c.zz` = 1: allowed: no such key here; known keys: a_mm, kind"), "{e}");
    }

    #[test]
    fn a_key_read_but_not_declared_fails() {
        let t = table("mu = 1.0");
        let mut s = Section::new("c", &t).declare(&T);
        assert!(s.num("mu").unwrap_err().to_string().contains("c.mu"));
        let mut s = Section::new("c", &t).declare(&T);
        assert_eq!(s.opt_f64("mu", Range::positive_to(2.0)).unwrap(), Some(1.0));
        assert!(s.finish().unwrap_err().to_string().contains("a bug in creepbench"));
        let mut s = Section::new("c", &t).declare(&T);
        assert!(s.num("kind").is_err(), "a choice read as a number");
    }
}
