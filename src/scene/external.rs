//! `[external.NAME]` (optional, one table per model): a model of the user's own, its command and
//! time limit; its keys declared once ([`KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::ExternalSolver;
use crate::error::InputError;

/// An `[external.NAME]` table's keys (`<!-- keys:external -->`).
pub const KEYS: Keys = Keys {
    id: "external",
    owner: file!(),
    keys: &[
        key(
            "command",
            "–",
            Allowed::Text("a non-empty array of strings: the program and its arguments"),
            Absent::Required,
            r#"run in the scene's folder as `COMMAND... SCENE_JSON OUT_CSV`; a relative program path is taken from the scene's folder: `command = ["python3", "../../scripts/example_model.py"]`"#,
        ),
        key(
            "timeout_s",
            "s",
            Allowed::Number(Range::new(0.0, false, 86400.0, true), ""),
            Absent::Num(crate::safety::process::DEFAULT_TIMEOUT.as_secs_f64()),
            r#"the longest run on one scene; then the model's process group is killed: `timeout_s = 60.0`"#,
        ),
    ],
};

/// `[external.NAME]`: each external model's command and time limit (the pipeline checks NAME).
pub fn read(top: &mut Section) -> Result<Vec<ExternalSolver>, InputError> {
    let mut external = Vec::new();
    if let Some(mut ext) = top.opt_table("external")? {
        for key in ext.keys() {
            let t = ext.table(&key)?.declare(&KEYS);
            external.push(external_one(key, t)?);
        }
        ext.finish()?;
    }
    Ok(external)
}

/// One `[external.NAME]` table.
fn external_one(name: String, mut t: Section) -> Result<ExternalSolver, InputError> {
    let command =
        t.opt_str_list("command", "the program and its arguments")?.filter(|c| !c.is_empty()).ok_or_else(|| {
            InputError::new(t.field("command"), "missing or empty", "a non-empty array: program and arguments")
        })?;
    let timeout_s = t.num_or_default("timeout_s")?;
    t.finish()?;
    Ok(ExternalSolver { name, command, timeout_s })
}
