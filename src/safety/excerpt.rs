//! Short, single-line excerpts of user values for error messages: a 10 MB bad value must not
//! become a 10 MB message, nor put control sequences on the user's terminal (issue 11).

/// Characters of a value shown in an error message before it is cut.
pub const EXCERPT_CHARS: usize = 60;

/// `value` quoted on one line, at most [`EXCERPT_CHARS`] characters of it, control and
/// bidirectional-formatting characters escaped, and `… (N bytes)` after the quote when cut.
pub fn excerpt(value: &str) -> String {
    excerpt_chars(value, EXCERPT_CHARS)
}

/// [`excerpt`] with another length: for whole messages of other parsers that may quote values.
pub fn excerpt_chars(value: &str, max_chars: usize) -> String {
    let mut out = String::from("\"");
    let mut shown = 0;
    let mut cut = false;
    for c in value.chars() {
        let piece = escaped(c);
        let n = piece.chars().count();
        if shown + n > max_chars {
            cut = true;
            break;
        }
        shown += n;
        out.push_str(&piece);
    }
    if cut {
        out.push_str(&format!("…\" ({} bytes)", value.len()));
    } else {
        out.push('"');
    }
    out
}

/// One character as shown: itself, or an escape that cannot act on a terminal.
fn escaped(c: char) -> String {
    match c {
        '\\' => "\\\\".into(),
        '"' => "\\\"".into(),
        '\n' => "\\n".into(),
        '\r' => "\\r".into(),
        '\t' => "\\t".into(),
        c if c.is_control() || is_invisible_format(c) => format!("\\u{{{:x}}}", c as u32),
        c => c.into(),
    }
}

/// Zero-width and bidirectional-override characters: they reorder or hide text on a terminal.
fn is_invisible_format(c: char) -> bool {
    matches!(c as u32, 0x200b..=0x200f | 0x202a..=0x202e | 0x2060..=0x2069 | 0xfeff)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_values_are_quoted_whole() {
        assert_eq!(excerpt("0.5"), "\"0.5\"");
        assert_eq!(excerpt(""), "\"\"");
    }

    #[test]
    fn long_values_are_cut_with_their_size() {
        let big = "x".repeat(10 << 20);
        let e = excerpt(&big);
        assert!(e.len() < 100, "{e}");
        assert!(e.ends_with(&format!("…\" ({} bytes)", 10 << 20)), "{e}");
        assert_eq!(e.matches('x').count(), EXCERPT_CHARS);
    }

    #[test]
    fn control_characters_are_escaped_and_the_excerpt_is_one_line() {
        let e = excerpt("a\nb\r\u{1b}[31mred\u{7}\u{202e}evil\0");
        assert!(!e.contains('\n') && !e.contains('\r') && !e.contains('\u{1b}') && !e.contains('\u{202e}'), "{e}");
        assert_eq!(e, "\"a\\nb\\r\\u{1b}[31mred\\u{7}\\u{202e}evil\\u{0}\"");
    }

    #[test]
    fn multibyte_characters_are_never_split() {
        let e = excerpt(&"é".repeat(100));
        assert_eq!(e.matches('é').count(), EXCERPT_CHARS);
        assert!(e.ends_with("(200 bytes)"), "{e}");
    }

    #[test]
    fn an_escape_is_never_cut_in_half() {
        let e = excerpt_chars("ab\u{1b}", 4);
        assert_eq!(e, "\"ab…\" (3 bytes)");
    }
}
