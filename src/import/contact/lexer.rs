//! The lines of a CONTACT input file as CONTACT's `readline` reads them (user guide, "Specification
//! of the input file"): `%` (and `!`) start a comment, empty lines are skipped, a group of values
//! may continue over newlines until its mandatory values are read, optional values must follow on
//! the same line, and the rest of a group's last line is ignored (text there is a comment).

use super::DeckError;

/// What a value must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A whole number (`22`, not `22.0`).
    Int,
    /// A real number (`0.35`, `3.5E-1`, `82000.`, Fortran's `1d-6`).
    Real,
    /// An angle: a real with an optional `d` (degrees) or `r` (radians, the default) suffix.
    Angle,
}

impl Kind {
    fn describe(self) -> &'static str {
        match self {
            Kind::Int => "a whole number",
            Kind::Real => "a real number",
            Kind::Angle => "an angle (a real number, optionally with the suffix d or r)",
        }
    }
}

/// One token and where it starts (1-based column).
#[derive(Debug, Clone)]
struct Token {
    text: String,
    column: usize,
}

/// A line with its comments cut off and at least one token.
#[derive(Debug, Clone)]
struct Line {
    number: usize,
    tokens: Vec<Token>,
}

/// Where a value came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Place {
    pub line: usize,
    pub column: usize,
}

/// The input file's lines and a reading position.
#[derive(Debug, Clone)]
pub struct Lexer {
    file: String,
    lines: Vec<Line>,
    next: usize,
}

/// Split a line into tokens (blanks and commas separate), comments cut off.
fn tokens(text: &str) -> Vec<Token> {
    let body = text.split(['%', '!']).next().unwrap_or("");
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    for (k, c) in body.char_indices().chain(std::iter::once((body.len(), ' '))) {
        let sep = c.is_whitespace() || c == ',';
        match (sep, start) {
            (true, Some(s)) => {
                out.push(Token { text: body[s..k].to_string(), column: body[..s].chars().count() + 1 });
                start = None;
            }
            (false, None) => start = Some(k),
            _ => {}
        }
    }
    out
}

/// A real number as CONTACT reads them: `d`/`D` exponents as `e`, and Fortran's exponent
/// without a letter (`.1-07` = 0.1e-7).
fn real(text: &str) -> Option<f64> {
    let mut t = text.replace(['d', 'D'], "e");
    if let Some(k) = t.rfind(['+', '-']).filter(|&k| k > 0 && !t[..k].ends_with(['e', 'E'])) {
        t.insert(k, 'e');
    }
    let plain = t.bytes().all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-'));
    t.parse::<f64>().ok().filter(|v| plain && v.is_finite())
}

/// An angle in radians: `180d`, `3.1416r` or `0.5` (radians).
fn angle(text: &str) -> Option<f64> {
    if let Some(deg) = text.strip_suffix(['d', 'D']).and_then(real) {
        return Some(deg.to_radians());
    }
    real(text.strip_suffix(['r', 'R']).unwrap_or(text))
}

fn value(kind: Kind, text: &str) -> Option<f64> {
    match kind {
        Kind::Int => text.parse::<i64>().ok().map(|v| v as f64),
        Kind::Real => real(text),
        Kind::Angle => angle(text),
    }
}

impl Lexer {
    pub fn new(file: &str, text: &str) -> Lexer {
        let lines = text
            .lines()
            .enumerate()
            .map(|(k, l)| Line { number: k + 1, tokens: tokens(l) })
            .filter(|l| !l.tokens.is_empty())
            .collect();
        Lexer { file: file.to_string(), lines, next: 0 }
    }

    /// The input file's name (for messages).
    pub fn file(&self) -> &str {
        &self.file
    }

    /// Whether every line has been read.
    pub fn at_end(&self) -> bool {
        self.next >= self.lines.len()
    }

    /// The line number the next read starts at (the last line's at the end).
    pub fn line_number(&self) -> usize {
        self.lines.get(self.next).or(self.lines.last()).map_or(0, |l| l.number)
    }

    /// Whether the next line starts with a module number (a whole number) followed by the word
    /// MODULE, as every CONTACT deck writes it (used to find the end of a skipped module-1 case).
    pub fn next_is_module_line(&self) -> bool {
        self.lines.get(self.next).is_some_and(|l| {
            l.tokens[0].text.parse::<i64>().is_ok()
                && l.tokens.get(1).is_some_and(|t| t.text.eq_ignore_ascii_case("module"))
        })
    }

    /// Skip one line.
    pub fn skip_line(&mut self) {
        self.next += 1;
    }

    /// Read a group: `mandatory` values (continuing over newlines), then up to `optional` more
    /// values of `optional_kind` on the same line; the rest of the last line is ignored.
    pub fn group(
        &mut self,
        what: &str,
        mandatory: &[Kind],
        optional: (usize, Kind),
    ) -> Result<(Vec<f64>, Place), DeckError> {
        let mut out = Vec::with_capacity(mandatory.len() + optional.0);
        let mut first = None;
        let mut last_line = None;
        let mut pos = 0;
        for &kind in mandatory {
            loop {
                let line = self.lines.get(self.next).ok_or_else(|| self.end_of_file(what))?;
                if let Some(tok) = line.tokens.get(pos) {
                    let place = Place { line: line.number, column: tok.column };
                    let v = value(kind, &tok.text).ok_or_else(|| self.bad(place, what, &tok.text, kind))?;
                    first.get_or_insert(place);
                    out.push(v);
                    pos += 1;
                    last_line = Some(self.next);
                    break;
                }
                // The line is used up: the group continues on the next line.
                self.next += 1;
                pos = 0;
            }
        }
        if let Some(k) = last_line {
            let line = &self.lines[k];
            for tok in line.tokens.iter().skip(pos).take(optional.0) {
                match value(optional.1, &tok.text) {
                    Some(v) => out.push(v),
                    None => break,
                }
            }
            self.next = k + 1;
        }
        Ok((out, first.unwrap_or(Place { line: self.line_number(), column: 1 })))
    }

    /// Read `n` reals that may span several lines (CONTACT's `read1darr`); the rest of the last
    /// line is ignored.
    pub fn array(&mut self, what: &str, n: usize) -> Result<Vec<f64>, DeckError> {
        let kinds = vec![Kind::Real; n];
        self.group(what, &kinds, (0, Kind::Real)).map(|(v, _)| v)
    }

    /// One quoted string (a file name): the line's first token.
    pub fn string(&mut self, what: &str) -> Result<(String, Place), DeckError> {
        let line = self.lines.get(self.next).ok_or_else(|| self.end_of_file(what))?;
        let tok = &line.tokens[0];
        let place = Place { line: line.number, column: tok.column };
        self.next += 1;
        Ok((tok.text.trim_matches('\'').to_string(), place))
    }

    fn end_of_file(&self, what: &str) -> DeckError {
        DeckError::EndOfFile { file: self.file.clone(), line: self.line_number(), what: what.to_string() }
    }

    fn bad(&self, place: Place, what: &str, text: &str, kind: Kind) -> DeckError {
        DeckError::Value {
            file: self.file.clone(),
            line: place.line,
            column: place.column,
            what: what.to_string(),
            value: crate::error::excerpt(text),
            allowed: kind.describe().to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_continue_over_newlines_and_ignore_trailing_text() {
        let mut lx = Lexer::new("t.inp", "% c\n 1.0  2d0 ! x\n\n 3.  4.  5.  6. FN, CKSI\n 7 8\n");
        let (v, p) = lx.group("four", &[Kind::Real; 3], (2, Kind::Real)).unwrap();
        assert_eq!(v, vec![1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_eq!((p.line, p.column), (2, 2));
        let (v, _) = lx.group("ints", &[Kind::Int, Kind::Int], (0, Kind::Real)).unwrap();
        assert_eq!(v, vec![7.0, 8.0]);
        assert!(lx.at_end());
    }

    #[test]
    fn a_word_where_a_number_belongs_names_line_and_column() {
        let mut lx = Lexer::new("t.inp", "\n  22  x2\n");
        let e = lx.group("MX, MY", &[Kind::Int, Kind::Int], (0, Kind::Real)).unwrap_err();
        assert_eq!(e.to_string(), "t.inp:2:7: MX, MY: \"x2\" is not allowed: a whole number");
        let mut lx = Lexer::new("t.inp", " 3.0\n");
        assert!(lx.group("MODULE", &[Kind::Int], (0, Kind::Real)).is_err());
    }

    #[test]
    fn angles_in_degrees_or_radians() {
        assert_eq!(angle("180d"), Some(std::f64::consts::PI));
        assert_eq!(angle("0.5r"), Some(0.5));
        assert_eq!(angle("0.5"), Some(0.5));
        assert_eq!(real("1e-6"), Some(1e-6));
        assert_eq!(real("nan"), None);
        assert_eq!(real(".1-07"), Some(0.1e-7));
        assert_eq!(real("-2.5"), Some(-2.5));
        assert_eq!(real("1-2-3"), None);
    }
}
