//! The `[report]` table (optional): where the validation report shows the scene. A scene (or a
//! study's `[scene]` template, or one of its axes as `"report.group"`) declares its group; the
//! report's sections and figure groups select scenes by it, never by their names.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::Section;
use crate::error::InputError;
use serde::{Deserialize, Serialize};

/// The report group a scene declares (`[report] group`; scene.json `report_group`). What each
/// group shows is the report's (`report::groups`, the sections): this is the vocabulary the
/// scene reader checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ReportGroup {
    /// A creepage step at several μ.
    StepFriction,
    /// A creepage step under other loads, shapes and creepages.
    StepLoad,
    /// A sine over frequency at μ = 1 (drawn with its time history).
    SineFrequencyMu1,
    /// A sine over frequency at μ = 0.6.
    SineFrequencyMu06,
    /// A sine at 10 Hz over μ.
    SineFriction,
    /// A sine over the normal load.
    SineLoad,
    /// A sine over the mean creepage C0.
    SineMeanCreepage,
    /// A sine on refined grids (drawn with its time history).
    GridRefinement,
    /// A steady sweep.
    Steady,
    /// A case of the stability table.
    Stability,
    /// A falling-friction case of the stability table, also in the falling-friction section's.
    StabilityFalling,
    /// A case of the falling-friction section.
    FallingFriction,
    /// A run of the cost-per-step study (not drawn).
    Scaling,
    /// A study behind "The thesis's figures beside ours" (not drawn).
    ThesisFigures,
    /// Any other scene (the default).
    #[default]
    Other,
}

impl ReportGroup {
    /// Every group, in the order the report draws them.
    pub const ALL: [ReportGroup; 15] = [
        ReportGroup::StepFriction,
        ReportGroup::StepLoad,
        ReportGroup::SineFrequencyMu1,
        ReportGroup::SineFrequencyMu06,
        ReportGroup::SineFriction,
        ReportGroup::SineLoad,
        ReportGroup::SineMeanCreepage,
        ReportGroup::GridRefinement,
        ReportGroup::Steady,
        ReportGroup::Stability,
        ReportGroup::StabilityFalling,
        ReportGroup::FallingFriction,
        ReportGroup::Scaling,
        ReportGroup::ThesisFigures,
        ReportGroup::Other,
    ];

    /// The group's name in a scene file and in scene.json.
    pub fn id(self) -> &'static str {
        match self {
            ReportGroup::StepFriction => "step_friction",
            ReportGroup::StepLoad => "step_load",
            ReportGroup::SineFrequencyMu1 => "sine_frequency_mu1",
            ReportGroup::SineFrequencyMu06 => "sine_frequency_mu06",
            ReportGroup::SineFriction => "sine_friction",
            ReportGroup::SineLoad => "sine_load",
            ReportGroup::SineMeanCreepage => "sine_mean_creepage",
            ReportGroup::GridRefinement => "grid_refinement",
            ReportGroup::Steady => "steady",
            ReportGroup::Stability => "stability",
            ReportGroup::StabilityFalling => "stability_falling",
            ReportGroup::FallingFriction => "falling_friction",
            ReportGroup::Scaling => "scaling",
            ReportGroup::ThesisFigures => "thesis_figures",
            ReportGroup::Other => "other",
        }
    }

    /// The group named `id`, if there is one.
    pub fn of_id(id: &str) -> Option<ReportGroup> {
        ReportGroup::ALL.into_iter().find(|g| g.id() == id)
    }

    /// Whether this is the default group (left out of scene.json).
    pub fn is_default(&self) -> bool {
        *self == ReportGroup::default()
    }

    /// Whether the group is one of the stability table's.
    pub fn is_stability(self) -> bool {
        matches!(self, ReportGroup::Stability | ReportGroup::StabilityFalling)
    }
}

/// `[report]`'s keys (`<!-- keys:report -->`).
pub const KEYS: Keys = Keys {
    id: "report",
    owner: file!(),
    keys: &[key(
        "group",
        "–",
        Allowed::Text("one of the groups below"),
        Absent::Choice("other"),
        r#"the scene's report group: `group = "stability"`"#,
    )],
};

/// `[report]`: the scene's `group` (the default group without the table or the key); an
/// unknown group is refused naming the field, the value and every group.
pub fn read(top: &mut Section) -> Result<ReportGroup, InputError> {
    let Some(mut t) = top.opt_table("report")?.map(|t| t.declare(&KEYS)) else {
        return Ok(ReportGroup::default());
    };
    let ids = ReportGroup::ALL.map(ReportGroup::id);
    let group = t.opt_choice("group", &ids)?.and_then(ReportGroup::of_id).unwrap_or_default();
    t.finish()?;
    Ok(group)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_group_reads_back_from_its_id_and_its_json() {
        for g in ReportGroup::ALL {
            assert_eq!(ReportGroup::of_id(g.id()), Some(g));
            assert_eq!(serde_json::to_string(&g).unwrap(), format!("\"{}\"", g.id()));
        }
        assert_eq!(ReportGroup::of_id("sine"), None);
    }

    #[test]
    fn an_unknown_group_names_the_field_the_value_and_every_group() {
        let doc: toml::Table = "[report]\ngroup = \"sines\"".parse().unwrap();
        let err = read(&mut Section::new("", &doc)).unwrap_err().to_string();
        assert!(err.contains("report.group") && err.contains("\"sines\""), "{err}");
        assert!(ReportGroup::ALL.iter().all(|g| err.contains(g.id())), "{err}");
        let doc: toml::Table = "[report]\ngroupe = \"steady\"".parse().unwrap();
        assert!(read(&mut Section::new("", &doc)).unwrap_err().to_string().contains("report.groupe"));
    }
}
