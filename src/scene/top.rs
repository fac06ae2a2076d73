//! A scene file's top level: its name, the models and metrics it asks for, and its tables
//! (each read by its own reader; [`super::Scene::from_table`] calls them in the file's order).

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::Section;
use crate::error::InputError;

/// A table of its own (its keys in its own declaration).
pub(super) const fn table(name: &'static str) -> super::keys::KeySpec {
    key(name, "–", Allowed::Section, Absent::Text("absent"), "")
}

/// The top level's keys (`<!-- keys:top -->` in docs/scene-format.md).
pub const KEYS: Keys = Keys {
    id: "top",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("1 to 100 characters of `[a-z0-9_]`"),
            Absent::Required,
            r#"the scene's id and its result folder: `name = "step_cx001"`"#,
        ),
        key(
            "solvers",
            "–",
            Allowed::Text("a non-empty list of distinct names: the built-in models `uba`, `fastsim`, `fastsim_contact`, `fastrip_contact`, `contact`, `linear`, `she`, `polach`, `fastrip`, `relaxation`, `kpec`, `analyn`, or a name of this scene's `[external.NAME]` tables"),
            Absent::Required,
            r#"the models run on the scene: `solvers = ["uba", "contact"]` ([models.md](models.md))"#,
        ),
        key(
            "metrics",
            "–",
            Allowed::Text("distinct names from `delay_ratio`, `loop_area`, `steady_value`, `settling_time_s`, `oscillation_index`, `sawtooth_index`"),
            Absent::Text("every default metric that fits the loading"),
            r#"the metrics computed (see "metrics.csv" below); `oscillation_index` and `sawtooth_index` are computed only when listed; a listed metric that does not fit the loading is a warning: `metrics = ["steady_value", "sawtooth_index"]`"#,
        ),
        table("external"),
        table("grid"),
        table("geometry"),
        table("contact"),
        table("friction"),
        table("material"),
        table("rolling"),
        table("creepage"),
        table("init"),
        table("model"),
        table("contact_solver"),
        table("normal"),
        table("limits"),
        table("origin"),
        table("report"),
        table("stress"),
    ],
};

/// `name`: 1 to 100 characters of `[a-z0-9_]`.
pub fn name(top: &mut Section) -> Result<String, InputError> {
    let name = top.text("name")?;
    if !super::is_valid_name(name) {
        let allowed = KEYS.get("name").map(|k| k.allowed.message()).unwrap_or_default();
        return Err(InputError::new("name", format!("{name:?}"), allowed));
    }
    Ok(name.to_string())
}

/// `solvers` and `metrics` as given (the pipeline checks them against its registries).
pub fn models_and_metrics(top: &mut Section) -> (Option<toml::Value>, Option<toml::Value>) {
    (top.given("solvers").cloned(), top.given("metrics").cloned())
}
