//! `[limits]` (optional): how large a scene may be; its keys declared once ([`KEYS`], their
//! defaults those of [`Limits::default`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::{Limits, HARD_MAX_STEPS};
use crate::error::InputError;

/// `[limits]`'s keys (`<!-- keys:limits -->`).
pub const KEYS: Keys = Keys {
    id: "limits",
    owner: file!(),
    keys: &[
        key(
            "max_steps",
            "–",
            Allowed::Whole(1, HARD_MAX_STEPS, ""),
            Absent::Whole(2_000_000),
            r#"the most time steps or sweep points of any creepage kind; a longer history is refused (exit 2): `max_steps = 5000000`"#,
        ),
        key(
            "max_estimated_s",
            "s",
            Allowed::Number(Range::new(0.0, false, 1e7, true), ""),
            Absent::Num(600.0),
            r#"the exact solver's largest estimated run time on this scene; beyond it the scene is refused: `max_estimated_s = 3600.0`"#,
        ),
    ],
};

/// `[limits]` (optional): the step limit and the estimated run time limit.
pub fn read(top: &mut Section) -> Result<Limits, InputError> {
    let mut limits = Limits::default();
    if let Some(mut l) = top.opt_table("limits")?.map(|l| l.declare(&KEYS)) {
        if let Some(n) = l.opt_whole("max_steps")? {
            limits.max_steps = n;
        }
        if let Some(t) = l.opt_num("max_estimated_s")? {
            limits.max_estimated_s = t;
        }
        l.finish()?;
    }
    Ok(limits)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The declared defaults are those of the limits (an absent key keeps the default).
    #[test]
    fn the_declared_defaults_are_the_limits_defaults() {
        let d = Limits::default();
        assert_eq!(KEYS.get("max_steps").unwrap().default, Absent::Whole(d.max_steps));
        assert_eq!(KEYS.get("max_estimated_s").unwrap().default, Absent::Num(d.max_estimated_s));
    }
}
