//! One declaration per key of an input section (key, unit, allowed values, default, meaning):
//! the reader checks a value by it ([`super::reader::Section::declare`]) and the key tables of
//! docs/scene-format.md are generated from it ([`markdown`]; `tests/all/docs.rs` compares them,
//! `CREEPBENCH_BLESS_DOCS=1` rewrites them), so the two cannot drift.

use super::reader::Range;

/// What a key allows: the reader's check and the docs' "allowed" cell, from one value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Allowed {
    /// A number within the range; the note (a condition checked elsewhere) follows it after `; `.
    Number(Range, &'static str),
    /// An array of `min_len` to `max_len` numbers, each within the range.
    Numbers { range: Range, min_len: usize, max_len: usize, note: &'static str },
    /// A whole number (a TOML integer) in `[min, max]`.
    Whole(usize, usize, &'static str),
    /// One of the strings.
    Choice(&'static [&'static str], &'static str),
    /// `true` or `false`.
    Bool,
    /// Anything else (a string, a list of names, an array of tables), in words.
    Text(&'static str),
    /// A table documented under its own heading (not a row of this section's table).
    Section,
}

/// A key's default: what the reader takes when the key is absent, and the docs' "default" cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Absent {
    /// The key must be given.
    Required,
    /// This number.
    Num(f64),
    /// This whole number.
    Whole(usize),
    /// This choice.
    Choice(&'static str),
    /// Described in words (required in some cases, derived from other keys, absent: …).
    Text(&'static str),
}

/// One key: its name, unit (`–` for none), allowed values, default and meaning with an example.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeySpec {
    pub key: &'static str,
    pub unit: &'static str,
    pub allowed: Allowed,
    pub default: Absent,
    pub meaning: &'static str,
}

/// A key (shorter to write in a table than the struct literal).
pub const fn key(
    key: &'static str,
    unit: &'static str,
    allowed: Allowed,
    default: Absent,
    meaning: &'static str,
) -> KeySpec {
    KeySpec { key, unit, allowed, default, meaning }
}

/// A section's keys: `id` names its table in docs/scene-format.md (`<!-- keys:ID -->`), `owner`
/// is the source file that reads them (`file!()`; a test checks that it reads every key).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Keys {
    pub id: &'static str,
    pub owner: &'static str,
    pub keys: &'static [KeySpec],
}

impl Keys {
    /// The declaration of `key`, if any (a family row never matches a key given).
    pub fn get(&self, key: &str) -> Option<&'static KeySpec> {
        self.keys.iter().find(|k| k.key == key && !k.is_family())
    }
}

impl KeySpec {
    /// Whether this row stands for a family of keys described in words (`a column's name`, a
    /// study axis's `` `"table.key"` ``), not one key: its name is not a key's (`a-z`, `0-9`,
    /// `_`); docs show it as written, and the reader reads its keys by another declaration or
    /// by hand.
    pub fn is_family(&self) -> bool {
        !self.key.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
    }
}

/// A bound as docs and messages write it: a simple multiple of π as such (`π/2`, `5π/6`, `2π`),
/// else plain, or with an exponent where that is at least two characters shorter (`1e4`,
/// `1e-14`, but `1000`, `86400`, `0.001`).
pub fn bound(v: f64) -> String {
    if let Some(pi) = of_pi(v) {
        return pi;
    }
    let plain = format!("{v}");
    let exp = format!("{v:e}");
    if exp.len() + 1 < plain.len() {
        exp
    } else {
        plain
    }
}

/// `v` as a multiple of π with a small denominator (angles in degrees that are whole: 150° =
/// `5π/6`, 6° = `π/30`), if it is one to 1e-15 relative.
fn of_pi(v: f64) -> Option<String> {
    const DENOMINATORS: [u32; 8] = [1, 2, 3, 4, 6, 12, 30, 180];
    if v == 0.0 || !v.is_finite() {
        return None;
    }
    DENOMINATORS.iter().find_map(|&den| {
        let num = v * f64::from(den) / std::f64::consts::PI;
        let whole = num.round();
        let exact = whole != 0.0 && whole.abs() <= 720.0 && (num - whole).abs() <= 1e-15 * num.abs().max(1.0);
        exact.then(|| {
            let sign = if whole < 0.0 { "-" } else { "" };
            let times = if whole.abs() == 1.0 { String::new() } else { format!("{}", whole.abs()) };
            let over = if den == 1 { String::new() } else { format!("/{den}") };
            format!("{sign}{times}π{over}")
        })
    })
}

/// `text` without Markdown's code marks and escapes (a message shows `"a"` for `` `"a"` ``,
/// `|x|` for `\\|x\\|`).
fn plain_text(text: &str) -> String {
    text.replace('`', "").replace("\\|", "|")
}

/// ` ; note` when there is a note.
fn with_note(text: String, note: &str) -> String {
    if note.is_empty() {
        text
    } else {
        format!("{text}; {note}")
    }
}

impl Allowed {
    /// The docs' "allowed" cell.
    pub fn cell(&self) -> String {
        match *self {
            Allowed::Number(range, note) => with_note(range.interval(), note),
            Allowed::Choice(choices, note) => {
                let quoted: Vec<String> = choices.iter().map(|c| format!("`\"{c}\"`")).collect();
                with_note(quoted.join(", "), note)
            }
            Allowed::Bool => "`true` or `false`".to_string(),
            Allowed::Text(text) => text.to_string(),
            Allowed::Section => "a table".to_string(),
            Allowed::Numbers { range, min_len, max_len, note } => {
                with_note(Allowed::Numbers { range, min_len, max_len, note: "" }.message(), note)
            }
            Allowed::Whole(min, max, note) => with_note(Allowed::Whole(min, max, "").message(), note),
        }
    }

    /// What an error message says is allowed (the docs' cell, said in words).
    pub fn message(&self) -> String {
        match *self {
            Allowed::Number(range, note) => with_note(range.describe(), &plain_text(note)),
            Allowed::Numbers { range, min_len, max_len, note } => {
                let count = match min_len == max_len {
                    true => format!("{min_len}"),
                    false => format!("{min_len} to {}", bound(max_len as f64)),
                };
                let each = match range.interval() {
                    any if any.starts_with("any") => format!("an array of {count} numbers, each a finite number"),
                    _ => format!("an array of {count} numbers, each {}", range.describe()),
                };
                with_note(each, &plain_text(note))
            }
            Allowed::Whole(min, max, note) => {
                with_note(format!("a whole number in [{min}, {}]", bound(max as f64)), &plain_text(note))
            }
            Allowed::Choice(choices, _) => format!("one of {}", choices.join(", ")),
            Allowed::Bool => "true or false".to_string(),
            Allowed::Text(text) => plain_text(text),
            Allowed::Section => "a table ([section])".to_string(),
        }
    }
}

impl Absent {
    /// The docs' "default" cell.
    pub fn cell(&self) -> String {
        match *self {
            Absent::Required => "required".to_string(),
            Absent::Num(v) => bound(v),
            Absent::Whole(n) => format!("{n}"),
            Absent::Choice(c) => format!("`\"{c}\"`"),
            Absent::Text(text) => text.to_string(),
        }
    }
}

impl KeySpec {
    /// The docs' "key" cell: `` `key` ``, or a family's words as written.
    pub fn cell(&self) -> String {
        match self.is_family() {
            true => self.key.to_string(),
            false => format!("`{}`", self.key),
        }
    }
}

/// The Markdown table of the columns of a table file (`tables`' keys as columns: column, unit,
/// allowed, meaning), as docs/scene-format.md shows it between `<!-- columns:ID -->` and
/// `<!-- /keys -->`.
pub fn columns_markdown(tables: &[&Keys]) -> String {
    let mut out = String::from("| column | unit | allowed | meaning |\n|---|---|---|---|\n");
    for k in tables.iter().flat_map(|t| t.keys) {
        out.push_str(&format!("| {} | {} | {} | {} |\n", k.cell(), k.unit, k.allowed.cell(), k.meaning));
    }
    out
}

/// The Markdown table of `tables`' keys (one header; sub-tables documented under their own
/// heading are left out), as docs/scene-format.md shows it between `<!-- keys:ID -->` and
/// `<!-- /keys -->`.
pub fn markdown(tables: &[&Keys]) -> String {
    let mut out = String::from("| key | unit | allowed | default | meaning, example |\n|---|---|---|---|---|\n");
    for k in tables.iter().flat_map(|t| t.keys) {
        if matches!(k.allowed, Allowed::Section) {
            continue;
        }
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} |\n",
            k.cell(),
            k.unit,
            k.allowed.cell(),
            k.default.cell(),
            k.meaning
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_written_short() {
        let got: Vec<String> =
            [1e4, 1e-14, 1000.0, 86400.0, 0.5, -1e4, 2e6, 1e-2, 1e-3].iter().map(|&v| bound(v)).collect();
        assert_eq!(got, ["1e4", "1e-14", "1000", "86400", "0.5", "-1e4", "2e6", "0.01", "0.001"]);
    }

    #[test]
    fn multiples_of_pi_are_written_as_such() {
        use std::f64::consts::PI;
        let got: Vec<String> =
            [PI, 2.0 * PI, -PI, PI / 2.0, 150.0 * PI / 180.0, 6.0 * PI / 180.0, 1.5, 3.5].map(bound).to_vec();
        assert_eq!(got, ["π", "2π", "-π", "π/2", "5π/6", "π/30", "1.5", "3.5"]);
    }

    #[test]
    fn a_row_shows_the_declaration() {
        const T: Keys = Keys {
            id: "t",
            owner: file!(),
            keys: &[
                key("a_mm", "mm", Allowed::Number(Range::new(0.0, false, 1e4, true), ""), Absent::Required, "a"),
                key("k", "–", Allowed::Choice(&["x", "y"], ""), Absent::Choice("x"), "k"),
                key("sub", "–", Allowed::Section, Absent::Text("–"), "not shown"),
            ],
        };
        let md = markdown(&[&T]);
        assert!(md.contains("| `a_mm` | mm | (0, 1e4] | required | a |\n"), "{md}");
        assert!(md.contains("| `k` | – | `\"x\"`, `\"y\"` | `\"x\"` | k |\n"), "{md}");
        assert!(!md.contains("sub"), "{md}");
        assert_eq!(T.get("a_mm").unwrap().allowed.message(), "a finite number in (0, 1e4]");
    }
}
