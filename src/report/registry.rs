//! The section registry: one entry per section of the report — its id, whether it applies to the
//! stored scenes and reference data present, and its render function — in the report's order.
//! Adding a section: its function (a file of its own or one in `sections.rs`) and a line here.

use crate::comparison::references::{References, ENVELOPE_SECTION, NONHERTZ_SECTION};
use crate::report::contact_public;
use crate::report::contact_wheelrail;
use crate::report::envelope;
use crate::report::falling;
use crate::report::ladder;
use crate::report::section::Section;
use crate::report::sections;
use crate::report::studies;
use crate::report::work_precision;
use crate::suite::results::StoredScene;

/// One section of the report.
pub struct SectionDef {
    /// Its id: what other sections are placed by ([`insert_after`]) and reference sets name
    /// ([`crate::comparison::references::SetDef::section`]).
    pub id: &'static str,
    /// Whether it applies to the scenes and reference data present.
    pub applies: fn(&[StoredScene], &References) -> bool,
    /// The section (`None`: the data it needs do not come together, e.g. no convergence).
    pub render: fn(&[StoredScene], &References) -> Option<Section>,
}

/// Every section, in the report's order.
pub const SECTIONS: [SectionDef; 13] = [
    SectionDef {
        id: "thesis",
        applies: |s, _| sections::thesis_applies(s),
        render: |s, r| Some(sections::thesis_beside_ours(s, r)),
    },
    SectionDef { id: ladder::ID, applies: |s, _| ladder::applies(s), render: |s, _| ladder::section(s) },
    SectionDef {
        id: "studies",
        applies: |s, _| s.iter().any(|s| !s.scene.studies.is_empty()),
        render: studies::section,
    },
    SectionDef { id: ENVELOPE_SECTION, applies: |s, r| in_section(s, r, ENVELOPE_SECTION), render: envelope::section },
    SectionDef {
        id: NONHERTZ_SECTION,
        applies: |s, r| in_section(s, r, NONHERTZ_SECTION),
        render: envelope::nonhertz_section,
    },
    SectionDef { id: falling::ID, applies: |s, _| falling::applies(s), render: falling::section },
    SectionDef { id: contact_public::ID, applies: |s, _| contact_public::applies(s), render: contact_public::section },
    SectionDef {
        id: contact_wheelrail::ID,
        applies: |_, r| contact_wheelrail::applies(r),
        render: contact_wheelrail::section,
    },
    SectionDef { id: "work_precision", applies: |s, _| work_precision::applies(s), render: work_precision::section },
    SectionDef {
        id: "grid_convergence",
        applies: |s, _| sections::grid_convergence_applies(s),
        render: sections::grid_convergence,
    },
    SectionDef {
        id: "stability",
        applies: |s, _| sections::stability_applies(s),
        render: |s, _| Some(sections::stability(s)),
    },
    SectionDef { id: "timing", applies: |_, _| true, render: |s, r| Some(sections::timing(s, r)) },
    SectionDef { id: "scaling", applies: |s, _| sections::scaling_applies(s), render: |s, _| sections::scaling(s) },
];

/// Whether a stored scene is a case of the reference set drawn in the section `id`.
fn in_section(scenes: &[StoredScene], refs: &References, id: &str) -> bool {
    scenes.iter().any(|s| refs.section_of(&s.name) == Some(id))
}

/// Every section that applies, in the registry's order, each with its id.
pub fn all(scenes: &[StoredScene], refs: &References) -> Vec<Section> {
    SECTIONS
        .iter()
        .filter(|def| (def.applies)(scenes, refs))
        .filter_map(|def| Some(Section { id: def.id, ..(def.render)(scenes, refs)? }))
        .collect()
}

/// Place `section` right after the section `id` (at the end without one).
pub fn insert_after(all: &mut Vec<Section>, id: &str, section: Section) {
    let at = all.iter().position(|s| s.id == id).map_or(all.len(), |i| i + 1);
    all.insert(at, section);
}
