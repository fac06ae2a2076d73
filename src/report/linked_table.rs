//! Long per-scene tables of the report in linked files (issue 15, report navigation): a table of
//! more than [`MAX_INLINE_ROWS`] rows is written whole to `tables/<name>.md`, and its section
//! keeps a one-line summary, the link and the rows that matter most (the worst), so that
//! validation.md reads on a few screens. Tables up to that length stay inline.

/// The longest table kept inline whole.
pub const MAX_INLINE_ROWS: usize = 40;
/// The report's folder of linked tables.
pub const DIR: &str = "tables";

/// A Markdown table: its header and separator lines, then one line per row.
#[derive(Debug, Clone, Default)]
pub struct Table {
    pub head: String,
    pub rows: Vec<String>,
}

impl Table {
    /// A table whose header names `columns`.
    pub fn new(columns: &[&str]) -> Table {
        Table { head: format!("| {} |\n|{}\n", columns.join(" | "), "---|".repeat(columns.len())), rows: Vec::new() }
    }

    fn markdown<'a>(&'a self, rows: impl Iterator<Item = &'a String>) -> String {
        let mut s = self.head.clone();
        for r in rows {
            s.push_str(r);
            s.push('\n');
        }
        s
    }
}

/// A table placed in the report: the Markdown its section shows and, when it moved, the linked
/// file (name within [`DIR`], contents).
#[derive(Debug, Clone, PartialEq)]
pub struct Placed {
    pub inline: String,
    pub file: Option<(String, String)>,
}

/// The anchor GitHub gives a heading with this title.
pub fn anchor(title: &str) -> String {
    title
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            '-' | '_' => Some(c),
            c if c.is_alphanumeric() => Some(c.to_lowercase().next().unwrap_or(c)),
            _ => None,
        })
        .collect()
}

/// Place `table` of the section `section` (its title, for the file's heading and the link back):
/// whole when it is short; else `tables/<name>.md` with every row, and inline `summary`, the
/// link and the rows `keep` (indices, in the order given, each once; `kept` says what they are).
pub fn place(name: &str, section: &str, table: &Table, summary: &str, keep: &[usize], kept: &str) -> Placed {
    if table.rows.len() <= MAX_INLINE_ROWS {
        return Placed { inline: table.markdown(table.rows.iter()), file: None };
    }
    let file = format!("{name}.md");
    let contents = format!(
        "# {section}: all {} rows\n\nFrom the report [validation.md](../validation.md#{}). {summary}\n\n{}",
        table.rows.len(),
        anchor(section),
        table.markdown(table.rows.iter())
    );
    let mut shown: Vec<usize> = Vec::new();
    for &i in keep {
        if i < table.rows.len() && !shown.contains(&i) {
            shown.push(i);
        }
    }
    let mut inline = format!("{summary} All {} rows: [{DIR}/{file}]({DIR}/{file}).", table.rows.len());
    if !shown.is_empty() {
        inline.push_str(&format!(" {kept}:\n\n{}", table.markdown(shown.iter().map(|&i| &table.rows[i]))));
    } else {
        inline.push('\n');
    }
    Placed { inline, file: Some((file, contents)) }
}

/// The indices of the `n` largest `key`s (ties: the earlier row), for [`place`]'s `keep`.
pub fn largest(keys: &[f64], n: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by(|&a, &b| keys[b].total_cmp(&keys[a]).then(a.cmp(&b)));
    order.truncate(n);
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(n: usize) -> Table {
        let mut t = Table::new(&["scene", "value"]);
        t.rows = (0..n).map(|i| format!("| r{i} | {i} |")).collect();
        t
    }

    #[test]
    fn short_tables_stay_inline_long_ones_move_with_their_worst_rows_kept() {
        let short = place("t", "Timing", &table(MAX_INLINE_ROWS), "sum", &[3], "slowest");
        assert_eq!(short.file, None);
        assert_eq!(short.inline.lines().count(), 2 + MAX_INLINE_ROWS);
        let long = place("t", "Timing", &table(MAX_INLINE_ROWS + 1), "41 runs.", &[7, 2, 7], "The slowest");
        let (name, contents) = long.file.expect("moved");
        assert_eq!(name, "t.md");
        assert_eq!(contents.lines().filter(|l| l.starts_with("| r")).count(), MAX_INLINE_ROWS + 1);
        assert!(contents.contains("(../validation.md#timing)"), "{contents}");
        assert!(long.inline.starts_with("41 runs. All 41 rows: [tables/t.md](tables/t.md). The slowest:\n\n| scene"));
        let kept: Vec<&str> = long.inline.lines().filter(|l| l.starts_with("| r")).collect();
        assert_eq!(kept, ["| r7 | 7 |", "| r2 | 2 |"]);
        assert_eq!(largest(&[1.0, 5.0, 3.0, 5.0], 3), [1, 3, 2]);
    }
}
