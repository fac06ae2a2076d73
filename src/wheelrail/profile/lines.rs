//! CONTACT's line rules for profile files (`m_readline.f90`: `getNonemptyLine`,
//! `readKeywordValues`, `readPlainValues`): comment characters, blank lines, `key = value` lines,
//! plain keywords and lines of numbers (Fortran list-directed: blanks, tabs and commas separate,
//! `1.5d3` is a number).
//!
//! Where CONTACT reads a line of numbers leniently (it keeps the leading numbers and drops the
//! rest, or skips the line with a message), [`numbers`] refuses the line, naming its column: a
//! profile read here never silently differs from the file.

use super::error::ProfileError;

/// One line that is not empty once its comment is cut (CONTACT's `getNonemptyLine`).
#[derive(Debug, Clone, PartialEq)]
pub struct Line<'a> {
    /// 1-based line number in the file.
    pub number: usize,
    /// The whole line as in the file (comments included).
    pub text: &'a str,
    /// Blank lines (nothing but blanks, no comment) skipped just before this one: Miniprof's data
    /// start after one.
    pub blank_before: usize,
}

/// The lines of `text` that are not empty or comments only, `comment` the comment characters
/// (`!%` for SIMPACK, `!"%#` for Miniprof and plain tables). A line is a comment when nothing but
/// blanks stands before its first comment character (quotes are not honoured here, as in
/// CONTACT).
pub fn non_empty_lines<'a>(text: &'a str, comment: &'static str) -> Vec<Line<'a>> {
    let mut out = Vec::new();
    let mut blank = 0;
    for (k, raw) in text.lines().enumerate() {
        let raw = raw.strip_suffix('\r').unwrap_or(raw);
        match raw.find(|c| comment.contains(c)) {
            None if raw.trim().is_empty() => blank += 1,
            Some(p) if raw[..p].trim().is_empty() => {}
            _ => {
                out.push(Line { number: k + 1, text: raw, blank_before: blank });
                blank = 0;
            }
        }
    }
    out
}

/// The line before its first comment character outside quotes (`'` or `"` toggle a string, as in
/// CONTACT's `readKeywordValues`).
pub fn cut_comment_outside_quotes<'a>(text: &'a str, comment: &str) -> &'a str {
    let mut in_string = false;
    for (k, c) in text.char_indices() {
        if c == '\'' || c == '"' {
            in_string = !in_string;
        }
        if !in_string && comment.contains(c) {
            return &text[..k];
        }
    }
    text
}

/// The line before its first comment character (quotes disregarded: CONTACT's `readPlainValues`).
pub fn cut_comment<'a>(text: &'a str, comment: &str) -> &'a str {
    match text.find(|c| comment.contains(c)) {
        Some(p) => &text[..p],
        None => text,
    }
}

/// What a header or section line is (CONTACT's `readKeywordValues`).
#[derive(Debug, Clone, PartialEq)]
pub enum Entry<'a> {
    /// `key = value`: the value as written (trimmed, possibly empty).
    KeyValue { key: &'a str, value: &'a str },
    /// A line without `=` whose first item is not a number: a plain keyword (SIMPACK's section
    /// names, Miniprof's old-style header lines).
    Keyword(&'a str),
    /// A line without `=` that starts with a number.
    Numbers,
}

/// Split a line whose comment is cut: at the first `=` outside quotes into key and value;
/// otherwise a plain keyword or a line of numbers.
pub fn entry(code: &str) -> Entry<'_> {
    let mut in_string = false;
    for (k, c) in code.char_indices() {
        if c == '\'' || c == '"' {
            in_string = !in_string;
        }
        if !in_string && c == '=' {
            return Entry::KeyValue { key: code[..k].trim(), value: code[k + 1..].trim() };
        }
    }
    if leading_numbers(code).is_empty() {
        Entry::Keyword(code.trim())
    } else {
        Entry::Numbers
    }
}

/// The items of a line and their 1-based columns, split at blanks, tabs and commas.
fn items(code: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for (k, c) in code.char_indices().chain(std::iter::once((code.len(), ' '))) {
        let separator = c.is_whitespace() || c == ',';
        match (separator, start) {
            (true, Some(s)) => {
                out.push((code[..s].chars().count() + 1, &code[s..k]));
                start = None;
            }
            (false, None) => start = Some(k),
            _ => {}
        }
    }
    out
}

/// A Fortran real: `1`, `-2.5`, `.5`, `1e3`, `1.5d-3`, `1.5D+3`. `None` if `item` is not one;
/// infinite and NaN values come back as they are (the caller refuses them).
pub fn fortran_real(item: &str) -> Option<f64> {
    let ok = |c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E' | 'd' | 'D');
    if item.is_empty() || !item.chars().all(ok) || !item.chars().any(|c| c.is_ascii_digit()) {
        return None;
    }
    item.replace(['d', 'D'], "e").parse::<f64>().ok()
}

/// The numbers at the start of a value, as CONTACT counts them (it stops at the first item that
/// is not a number and reads none when the value has a `/`, Miniprof's dates).
pub fn leading_numbers(value: &str) -> Vec<f64> {
    if value.contains('/') {
        return Vec::new();
    }
    items(value).into_iter().map_while(|(_, item)| fortran_real(item)).collect()
}

/// Where a line comes from, for its errors.
#[derive(Debug, Clone, Copy)]
pub struct At<'a> {
    pub file: &'a str,
    pub line: usize,
}

impl At<'_> {
    /// A value error at `column` of this line.
    pub fn value(&self, column: usize, what: &str, value: &str, allowed: &str) -> ProfileError {
        ProfileError::Value {
            file: self.file.into(),
            line: self.line,
            column,
            what: what.into(),
            value: crate::error::excerpt(value),
            allowed: allowed.into(),
        }
    }

    /// A structure error at this line.
    pub fn structure(&self, what: impl Into<String>, allowed: impl Into<String>) -> ProfileError {
        ProfileError::Structure { file: self.file.into(), line: self.line, what: what.into(), allowed: allowed.into() }
    }
}

/// The numbers a line of points starts with (comment cut), as CONTACT reads them: the first
/// `needed` items must be finite numbers, and the numbers after them are read up to the first item
/// that is not one (CONTACT ignores the rest of the line, such as a note). `what` names the
/// line's role in errors.
pub fn numbers(code: &str, at: At<'_>, what: &str, needed: usize) -> Result<Vec<f64>, ProfileError> {
    let items = items(code);
    let mut out = Vec::new();
    for (k, &(column, item)) in items.iter().enumerate() {
        match fortran_real(item) {
            Some(v) if v.is_finite() => out.push(v),
            Some(_) if k < needed => return Err(at.value(column, what, item, "a finite number")),
            None if k < needed => {
                return Err(at.value(
                    column,
                    what,
                    item,
                    &format!("a number: the line's first {needed} items are numbers"),
                ))
            }
            _ => break,
        }
    }
    if out.len() < needed {
        let column = code.trim_end().chars().count() + 1;
        return Err(at.value(column, what, code.trim(), &format!("{needed} numbers on the line")));
    }
    Ok(out)
}

/// The one number a `key = value` line must give (CONTACT reads the first).
pub fn key_number(key: &str, value: &str, at: At<'_>) -> Result<f64, ProfileError> {
    let column = 1;
    match leading_numbers(value).first() {
        Some(v) if v.is_finite() => Ok(*v),
        Some(_) => Err(at.value(column, key, value, "a finite number")),
        None => Err(at.value(column, key, value, "a number")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comment_lines_and_blank_lines_are_skipped_and_blanks_counted() {
        let text = "a=1\n\n  \n! c\nb=2 ! x\n   % only\n1 2\n";
        let lines = non_empty_lines(text, "!%");
        let got: Vec<_> = lines.iter().map(|l| (l.number, l.text, l.blank_before)).collect();
        assert_eq!(got, [(1, "a=1", 0), (5, "b=2 ! x", 2), (7, "1 2", 0)]);
    }

    #[test]
    fn key_values_keywords_and_numbers_are_told_apart() {
        assert_eq!(entry(" version = 1 "), Entry::KeyValue { key: "version", value: "1" });
        assert_eq!(entry("comment = 'a = b'"), Entry::KeyValue { key: "comment", value: "'a = b'" });
        assert_eq!(entry("  header.begin "), Entry::Keyword("header.begin"));
        assert_eq!(entry(" -1.5  2"), Entry::Numbers);
        assert_eq!(cut_comment_outside_quotes("c = 'x ! y' ! z", "!%"), "c = 'x ! y' ");
        assert_eq!(cut_comment("1 2 \" 3", "!\"%#"), "1 2 ");
    }

    #[test]
    fn fortran_reals_are_read_with_their_d_exponent() {
        assert_eq!(fortran_real("1.5d3"), Some(1500.0));
        assert_eq!(fortran_real("-2.5E-1"), Some(-0.25));
        assert_eq!(fortran_real(".5"), Some(0.5));
        assert_eq!(fortran_real("abc"), None);
        assert_eq!(fortran_real("nan"), None);
        assert_eq!(leading_numbers("1.0, 2.0 abc 3"), [1.0, 2.0]);
        assert!(leading_numbers("2020/01/02").is_empty());
    }

    #[test]
    fn a_line_that_is_not_numbers_is_refused_naming_the_column() {
        let at = At { file: "p.txt", line: 4 };
        assert_eq!(numbers("1.0,\t2.0", at, "a point", 2).unwrap(), [1.0, 2.0]);
        assert_eq!(numbers("1.0 2.0 3 note 4", at, "a point", 2).unwrap(), [1.0, 2.0, 3.0]);
        let e = numbers("1.0  2.x", at, "a point", 2).unwrap_err();
        assert!(matches!(&e, ProfileError::Value { line: 4, column: 6, value, .. } if value == "2.x"), "{e}");
        let e = numbers("1.0 1e999", at, "a point", 2).unwrap_err();
        assert!(e.to_string().contains("finite"), "{e}");
        let e = numbers("1.0", at, "a point", 2).unwrap_err();
        assert!(e.to_string().contains("2 numbers"), "{e}");
    }
}
