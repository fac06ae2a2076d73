//! One section of the report as rendered: title, Markdown body, figures and linked tables.

/// A section of the report: title, Markdown body, figures (file name, SVG) and long tables moved
/// to linked files (file name, Markdown; [`crate::report::linked_table`]).
#[derive(Debug, Clone, Default)]
pub struct Section {
    /// Its id in the section registry (`registry.rs`, which sets it).
    pub id: &'static str,
    pub title: String,
    pub body: String,
    pub figures: Vec<(String, String)>,
    pub tables: Vec<(String, String)>,
}

impl Section {
    /// A section of text only.
    pub fn new(title: &str, body: String) -> Section {
        Section { title: title.into(), body, ..Section::default() }
    }
}
