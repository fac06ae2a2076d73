//! Short, single-line excerpts of user values for error messages: a 10 MB bad value must not
//! become a 10 MB message, nor put control sequences on the user's terminal (issue 11).

/// Characters of a value shown in an error message before it is cut.
pub const EXCERPT_CHARS: usize = 60;

/// `value` quoted on one line, at most [`EXCERPT_CHARS`] characters of it, control and
/// bidirectional-formatting characters escaped, and `… (N bytes)` after the quote when cut.
pub fn excerpt(value: &str) -> String {
    shorten(value, EXCERPT_CHARS, true)
}

/// `text` on one line, unquoted, at most `max_chars` characters, escaped and cut like
/// [`excerpt`]: for whole messages of other parsers, which may quote values of any length.
pub fn one_line(text: &str, max_chars: usize) -> String {
    shorten(text, max_chars, false)
}

fn shorten(value: &str, max_chars: usize, quoted: bool) -> String {
    let quote = if quoted { "\"" } else { "" };
    let mut out = String::from(quote);
    let mut shown = 0;
    let mut cut = false;
    for c in value.chars() {
        let piece = escaped(c, quoted);
        let n = piece.chars().count();
        if shown + n > max_chars {
            cut = true;
            break;
        }
        shown += n;
        out.push_str(&piece);
    }
    if cut {
        out.push_str(&format!("…{quote} ({} bytes)", value.len()));
    } else {
        out.push_str(quote);
    }
    out
}

/// One character as shown: itself, or an escape that cannot act on a terminal (and, inside
/// quotes, backslash and quote escaped).
fn escaped(c: char, quoted: bool) -> String {
    match c {
        '\\' if quoted => "\\\\".into(),
        '"' if quoted => "\\\"".into(),
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
    fn a_message_is_kept_on_one_line_without_quotes() {
        assert_eq!(one_line("line 3: \"x\"\nnext", 100), "line 3: \"x\"\\nnext");
        assert_eq!(one_line(&"y".repeat(500), 10), format!("{}… (500 bytes)", "y".repeat(10)));
    }

    #[test]
    fn multibyte_characters_are_never_split() {
        let e = excerpt(&"é".repeat(100));
        assert_eq!(e.matches('é').count(), EXCERPT_CHARS);
        assert!(e.ends_with("(200 bytes)"), "{e}");
    }

    #[test]
    fn an_escape_is_never_cut_in_half() {
        let e = shorten("ab\u{1b}", 4, true);
        assert_eq!(e, "\"ab…\" (3 bytes)");
    }
}
