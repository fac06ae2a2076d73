//! `[origin]` (optional): the CONTACT deck and cases an imported scene came from; its keys
//! declared once ([`KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::Section;
use crate::error::InputError;

/// `[origin]`'s keys (`<!-- keys:origin -->`).
pub const KEYS: Keys = Keys {
    id: "origin",
    owner: file!(),
    keys: &[
        key(
            "file",
            "–",
            Allowed::Text("a string: the CONTACT input file's name"),
            Absent::Required,
            r#"the CONTACT input file the scene was imported from: `file = "cattaneo.inp"`"#,
        ),
        key(
            "cases",
            "–",
            Allowed::Text("two whole numbers `[first, last]`, 1 ≤ first ≤ last"),
            Absent::Required,
            r#"the deck's first and last case of the scene's history: `cases = [2, 57]`"#,
        ),
    ],
};

/// `[origin]`: the CONTACT input file (`file`) and its first and last case (`cases`) an imported
/// scene reproduces.
pub fn read(top: &mut Section) -> Result<Option<super::Origin>, InputError> {
    let Some(mut o) = top.opt_table("origin")?.map(|o| o.declare(&KEYS)) else {
        return Ok(None);
    };
    let file = o.text("file")?.to_string();
    let field = o.field("cases");
    let allowed = KEYS.get("cases").map(|k| k.allowed.message()).unwrap_or_default();
    let cases = match o.given("cases") {
        Some(toml::Value::Array(a)) => {
            let n: Vec<Option<usize>> =
                a.iter().map(|v| v.as_integer().and_then(|i| usize::try_from(i).ok())).collect();
            match n.as_slice() {
                [Some(first), Some(last)] if *first >= 1 && first <= last => [*first, *last],
                _ => return Err(InputError::new(field, toml::Value::Array(a.clone()), allowed)),
            }
        }
        Some(other) => return Err(InputError::new(field, other, allowed)),
        None => return Err(InputError::new(field, "missing", format!("required: {allowed}"))),
    };
    o.finish()?;
    Ok(Some(super::Origin { file, cases }))
}
