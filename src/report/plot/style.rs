//! How a series is drawn, the same in every figure: a built-in model in its registry entry's
//! colour, dash and marker (`crate::solvers::style`), any other model in a style no built-in has,
//! chosen by a hash of its name; reference data (CONTACT, the thesis) in black markers.

pub use crate::solvers::style::{Dash, Marker};
use crate::solvers::style::{ModelStyle, MUTED};

/// How one model or reference is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Style {
    /// `#rrggbb`.
    pub color: &'static str,
    pub dash: Dash,
    pub marker: Marker,
    /// Filled marker (else outlined).
    pub filled: bool,
}

/// Reference data are drawn in this colour (markers only).
pub const REFERENCE_COLOR: &str = "#000000";

/// A model's style as drawn (filled markers).
const fn drawn(s: ModelStyle) -> Style {
    Style { color: s.colour, dash: s.dash, marker: s.marker, filled: true }
}

/// The built-in models' styles, each its registry entry's ([`crate::solvers::ModelDef::style`]).
fn builtin() -> impl Iterator<Item = (&'static str, Style)> {
    crate::solvers::MODELS.iter().map(|m| (m.name, drawn(m.style)))
}

/// Reference sets by label: CONTACT filled circles, the thesis open squares.
const REFERENCES: [(&str, Marker, bool); 2] = [("CONTACT", Marker::Circle, true), ("thesis", Marker::Square, false)];

/// 64-bit FNV-1a: a hash that stays the same across Rust versions and runs.
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// The styles no built-in model uses in colour and marker together, sand (the muted colour a
/// built-in uses least) first; muted colours only.
fn leftover() -> Vec<Style> {
    let dashes = [Dash::Solid, Dash::Dashed, Dash::DashDot, Dash::LongDash];
    let order = [8, 0, 1, 2, 3, 4, 5, 6, 7];
    let mut out = Vec::new();
    for (k, &c) in order.iter().enumerate() {
        for (m, &marker) in Marker::ALL.iter().enumerate() {
            let s = drawn(ModelStyle { colour: MUTED[c], dash: dashes[(k + m) % dashes.len()], marker });
            if !builtin().any(|(_, b)| b.color == s.color && b.marker == s.marker) {
                out.push(s);
            }
        }
    }
    out
}

/// The suffix of a fitted variant's name (`polach (fitted)`, the calibration's figures).
pub const FITTED: &str = " (fitted)";

/// A model's style: the registry's for a built-in model, else one of the leftover styles chosen
/// by a hash of the name (the same name always gets the same style). A fitted variant
/// (`<model>` + [`FITTED`]) is drawn in its model's colour and marker, outlined, dotted (a dash
/// no model has).
pub fn model(name: &str) -> Style {
    if let Some(base) = name.strip_suffix(FITTED) {
        return Style { dash: Dash::Dotted, filled: false, ..model(base) };
    }
    if let Some((_, s)) = builtin().find(|(n, _)| *n == name) {
        return s;
    }
    let rest = leftover();
    rest[(fnv1a(name) % rest.len() as u64) as usize]
}

/// A reference set's style: black markers (CONTACT filled circles, the thesis open squares, any
/// other set a marker chosen by a hash of its label).
pub fn reference(label: &str) -> Style {
    let (marker, filled) =
        REFERENCES.iter().find(|(l, _, _)| *l == label).map(|&(_, m, f)| (m, f)).unwrap_or_else(|| {
            let others = [Marker::TriangleUp, Marker::Diamond, Marker::TriangleDown, Marker::Cross];
            (others[(fnv1a(label) % others.len() as u64) as usize], false)
        });
    Style { color: REFERENCE_COLOR, dash: Dash::Solid, marker, filled }
}

/// A series' style: a reference's when it is drawn as markers, else its model's.
pub fn of(name: &str, is_reference: bool) -> Style {
    if is_reference {
        reference(name)
    } else {
        model(name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_models_differ_in_colour_dash_and_marker() {
        let all: Vec<(&str, Style)> = builtin().collect();
        for (i, (a, sa)) in all.iter().enumerate() {
            for (b, sb) in &all[i + 1..] {
                assert_ne!(sa.color, sb.color, "{a} and {b}");
                assert_ne!((sa.marker, sa.dash), (sb.marker, sb.dash), "{a} and {b}");
            }
            assert_ne!(sa.color, REFERENCE_COLOR, "{a}");
        }
    }

    #[test]
    fn an_external_model_gets_a_fixed_style_no_builtin_has() {
        for name in ["my_model", "python_uba", "ext", "UBA", "x"] {
            let s = model(name);
            assert_eq!(s, model(name), "{name}");
            assert!(!builtin().any(|(_, b)| b.color == s.color && b.marker == s.marker), "{name}: {s:?}");
        }
        let muted_builtins = builtin().filter(|(_, b)| MUTED.contains(&b.color)).count();
        assert_eq!(leftover().len(), 9 * 8 - muted_builtins);
        assert_eq!(model("uba").color, "#CC6677");
    }

    #[test]
    fn a_fitted_variant_is_its_model_outlined_and_dotted() {
        for name in ["polach", "uba", "relaxation", "my_model"] {
            let (m, f) = (model(name), model(&format!("{name}{FITTED}")));
            assert_eq!((f.color, f.marker), (m.color, m.marker), "{name}");
            assert_eq!((f.dash, f.filled), (Dash::Dotted, false), "{name}");
            assert_ne!(m.dash, Dash::Dotted, "{name}: no model is dotted");
        }
    }

    #[test]
    fn references_are_black_markers() {
        assert_eq!(
            reference("CONTACT"),
            Style { color: "#000000", dash: Dash::Solid, marker: Marker::Circle, filled: true }
        );
        assert_eq!(reference("thesis").marker, Marker::Square);
        assert!(!reference("thesis").filled);
        assert_eq!(reference("other set").color, REFERENCE_COLOR);
    }
}
