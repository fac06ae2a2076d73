//! The lines of a CONTACT input file as CONTACT's `readline` reads them (user guide, "Specification
//! of the input file"): `%` (and `!`) start a comment, empty lines are skipped, a group of values
//! may continue over newlines until its mandatory values are read, optional values must follow on
//! the same line, and the rest of a group's last line is ignored (text there is a comment).

use super::DeckError;

/// What a value must be.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A whole number (`22`; `22.0` or `22.` too, as the Intel build of CONTACT that printed
    /// the reference outputs reads it: `testbank/examples_temp/conv_temp.inp` gives INISLP as
    /// `1.0`; gfortran's list-directed read refuses it; `22.5` is refused).
    Int,
    /// A real number (`0.35`, `3.5E-1`, `82000.`, Fortran's `1d-6`).
    Real,
    /// An angle: a real with an optional `d` (degrees) or `r` (radians, the default) suffix.
    Angle,
}

impl Kind {
    fn describe(self) -> &'static str {
        match self {
            Kind::Int => "a whole number (22 or 22.0)",
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
    /// Where each value of the last group came from (a quoted string first).
    places: Vec<Place>,
}

/// Split a line into tokens (blanks, commas and `=` separate), comments cut off; a quoted string
/// (`'My Documents\CONTACT'`) is one token, blanks and `%` inside it kept (CONTACT's
/// `splitlinetowords`).
fn tokens(text: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let mut start: Option<usize> = None;
    let mut quoted = false;
    let push = |s: usize, k: usize, out: &mut Vec<Token>| {
        out.push(Token { text: text[s..k].to_string(), column: text[..s].chars().count() + 1 });
    };
    for (k, c) in text.char_indices() {
        if quoted {
            quoted = c != '\'';
            continue;
        }
        let comment = c == '%' || c == '!';
        let sep = comment || c.is_whitespace() || c == ',' || c == '=';
        match (sep, start) {
            (true, Some(s)) => {
                push(s, k, &mut out);
                start = None;
            }
            (false, None) => {
                start = Some(k);
                quoted = c == '\'';
            }
            (false, Some(_)) => quoted = c == '\'',
            _ => {}
        }
        if comment {
            return out;
        }
    }
    if let Some(s) = start {
        push(s, text.len(), &mut out);
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

/// A real number that is a whole number (`1.0`, `-3.`, `2e1`) exactly, within ±2^53: CONTACT's
/// `readline` reads an integer by Fortran's list-directed read (`m_readline.f90`), which the Intel
/// build of the reference outputs gives the value of `1.0` (conv_temp.inp's INISLP, whose OMGSLP
/// on the same line took effect in its printed iterations).
fn whole_real(text: &str) -> Option<f64> {
    real(text).filter(|v| v.fract() == 0.0 && v.abs() <= 9_007_199_254_740_992.0)
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
        Kind::Int => text.parse::<i64>().ok().map(|v| v as f64).or_else(|| whole_real(text)),
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
        Lexer { file: file.to_string(), lines, next: 0, places: Vec::new() }
    }

    /// Where value `k` of the last group came from (a [`Lexer::quoted_group`]'s name is value 0).
    pub fn place(&self, k: usize) -> Place {
        let fallback = Place { line: self.line_number(), column: 1 };
        self.places.get(k).or(self.places.last()).copied().unwrap_or(fallback)
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

    /// Read a group: `mandatory` values (continuing over newlines), then up to `optional` more
    /// values of `optional_kind` on the same line; the rest of the last line is ignored.
    pub fn group(
        &mut self,
        what: &str,
        mandatory: &[Kind],
        optional: (usize, Kind),
    ) -> Result<(Vec<f64>, Place), DeckError> {
        self.group_with(what, mandatory, &vec![optional.1; optional.0])
    }

    /// Read a group as CONTACT's `readline` does: `mandatory` values (continuing over newlines),
    /// then the `optional` values, one of each kind in turn, found on the same line (the first
    /// that is missing or not of its kind ends the group); the rest of the last line is ignored.
    pub fn group_with(
        &mut self,
        what: &str,
        mandatory: &[Kind],
        optional: &[Kind],
    ) -> Result<(Vec<f64>, Place), DeckError> {
        self.values_from(what, 0, mandatory, optional)
    }

    /// A group whose first value is a quoted string (a file name: `'MBench_UIC60_v3.prr'`), then
    /// `mandatory` and `optional` values as [`Lexer::group_with`] (`readline` type `s` first).
    pub fn quoted_group(
        &mut self,
        what: &str,
        mandatory: &[Kind],
        optional: &[Kind],
    ) -> Result<(String, Vec<f64>, Place), DeckError> {
        let line = self.lines.get(self.next).ok_or_else(|| self.end_of_file(what))?;
        let tok = &line.tokens[0];
        let place = Place { line: line.number, column: tok.column };
        let name = tok.text.strip_prefix('\'').and_then(|t| t.strip_suffix('\'')).filter(|_| tok.text.len() >= 2);
        let Some(name) = name.map(str::to_string) else {
            return Err(DeckError::Value {
                file: self.file.clone(),
                line: place.line,
                column: place.column,
                what: what.to_string(),
                value: crate::error::excerpt(&tok.text),
                allowed: "a file name in single quotes".into(),
            });
        };
        let (v, _) = self.values_from(what, 1, mandatory, optional)?;
        self.places.insert(0, place);
        Ok((name, v, place))
    }

    /// The values of a group from token `start` of the next line on.
    fn values_from(
        &mut self,
        what: &str,
        start: usize,
        mandatory: &[Kind],
        optional: &[Kind],
    ) -> Result<(Vec<f64>, Place), DeckError> {
        let mut out = Vec::with_capacity(mandatory.len() + optional.len());
        self.places.clear();
        let mut first = None;
        let mut last_line = (start > 0).then_some(self.next);
        let mut pos = start;
        for &kind in mandatory {
            loop {
                let line = self.lines.get(self.next).ok_or_else(|| self.end_of_file(what))?;
                if let Some(tok) = line.tokens.get(pos) {
                    let place = Place { line: line.number, column: tok.column };
                    let v = value(kind, &tok.text).ok_or_else(|| self.bad(place, what, &tok.text, kind))?;
                    first.get_or_insert(place);
                    self.places.push(place);
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
            for (tok, &kind) in line.tokens.iter().skip(pos).zip(optional) {
                match value(kind, &tok.text) {
                    Some(v) => {
                        out.push(v);
                        self.places.push(Place { line: line.number, column: tok.column });
                    }
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
        assert_eq!(e.to_string(), "t.inp:2:7: MX, MY: \"x2\" is not allowed: a whole number (22 or 22.0)");
        let mut lx = Lexer::new("t.inp", " 3.5\n");
        assert!(lx.group("MODULE", &[Kind::Int], (0, Kind::Real)).is_err());
        // A real that is a whole number reads as it (CONTACT's Intel build: conv_temp.inp's INISLP 1.0).
        let mut lx = Lexer::new("t.inp", " 1.0   0.5   INISLP, OMGSLP\n -1.  2e1\n");
        assert_eq!(lx.group("INISLP, OMGSLP", &[Kind::Int, Kind::Real], (0, Kind::Real)).unwrap().0, vec![1.0, 0.5]);
        assert_eq!(lx.group("two", &[Kind::Int, Kind::Int], (0, Kind::Real)).unwrap().0, vec![-1.0, 20.0]);
    }

    #[test]
    fn quoted_file_names_keep_their_blanks_and_percent_signs() {
        let t: Vec<String> = tokens(" 'My Docs/a%b.prr'  0  1.0, 0.0 % RFNAME").into_iter().map(|t| t.text).collect();
        assert_eq!(t, ["'My Docs/a%b.prr'", "0", "1.0", "0.0"]);
        let mut lx = Lexer::new("t.inp", " 'r.prr' 0 1.0 0.0 1 RFNAME\n 'w.prw' 0\n 2.0 0.0\n");
        let (name, v, p) =
            lx.quoted_group("RFNAME", &[Kind::Int, Kind::Real, Kind::Real], &[Kind::Int, Kind::Int]).unwrap();
        assert_eq!((name.as_str(), v, p.column), ("r.prr", vec![0.0, 1.0, 0.0, 1.0], 2));
        let (name, v, _) = lx.quoted_group("WFNAME", &[Kind::Int, Kind::Real, Kind::Real], &[Kind::Int]).unwrap();
        assert_eq!((name.as_str(), v), ("w.prw", vec![0.0, 2.0, 0.0]));
        let mut lx = Lexer::new("t.inp", " r.prr 0 1.0 0.0\n");
        let e = lx.quoted_group("RFNAME", &[Kind::Int], &[]).unwrap_err();
        assert_eq!(e.to_string(), "t.inp:1:2: RFNAME: \"r.prr\" is not allowed: a file name in single quotes");
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
