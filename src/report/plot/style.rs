//! The style registry: one colour, line style and marker per model, the same in every figure.
//! Colours: Paul Tol's "muted" scheme (colour-blind safe; Tol, "Colour schemes", SRON/EPS/TN/09-002,
//! 2021); reference data (CONTACT, the thesis) in black markers.

/// The dash pattern of a line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dash {
    Solid,
    Dashed,
    Dotted,
    DashDot,
    LongDash,
}

impl Dash {
    /// The SVG `stroke-dasharray` ("" for a solid line).
    pub fn dasharray(self) -> &'static str {
        match self {
            Dash::Solid => "",
            Dash::Dashed => "7 4",
            Dash::Dotted => "2 3",
            Dash::DashDot => "8 3 2 3",
            Dash::LongDash => "14 4",
        }
    }
}

/// The marker drawn at a model's points (a few along a line) and in its legend entry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Marker {
    Circle,
    Square,
    TriangleUp,
    Diamond,
    TriangleDown,
    Plus,
    Cross,
    Star,
    /// The two added with KPEC and ANALYN (outside [`Marker::ALL`], which the leftover styles of
    /// other models draw from).
    TriangleLeft,
    TriangleRight,
}

impl Marker {
    pub const ALL: [Marker; 8] = [
        Marker::Circle,
        Marker::Square,
        Marker::TriangleUp,
        Marker::Diamond,
        Marker::TriangleDown,
        Marker::Plus,
        Marker::Cross,
        Marker::Star,
    ];

    /// The name written into the SVG (`data-marker`).
    pub fn name(self) -> &'static str {
        match self {
            Marker::Circle => "circle",
            Marker::Square => "square",
            Marker::TriangleUp => "triangle-up",
            Marker::Diamond => "diamond",
            Marker::TriangleDown => "triangle-down",
            Marker::Plus => "plus",
            Marker::Cross => "cross",
            Marker::Star => "star",
            Marker::TriangleLeft => "triangle-left",
            Marker::TriangleRight => "triangle-right",
        }
    }
}

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

/// Tol's muted scheme: indigo, rose, green, cyan, wine, teal, olive, purple, sand.
pub const PALETTE: [&str; 9] =
    ["#332288", "#CC6677", "#117733", "#88CCEE", "#882255", "#44AA99", "#999933", "#AA4499", "#DDCC77"];

/// Reference data are drawn in this colour (markers only).
pub const REFERENCE_COLOR: &str = "#000000";

const fn style(color: usize, dash: Dash, marker: Marker) -> Style {
    Style { color: PALETTE[color], dash, marker, filled: true }
}

/// Two colours beyond the muted scheme for KPEC and ANALYN, from Tol's "light" scheme (orange,
/// light blue); the leftover styles keep to [`PALETTE`].
const EXTRA: [&str; 2] = ["#EE8866", "#77AADD"];

/// The built-in models (`crate::solvers::builtin_names`), each its own colour, dash and marker.
const BUILTIN: [(&str, Style); 10] = [
    ("contact", style(0, Dash::Solid, Marker::Circle)),
    ("uba", style(1, Dash::Solid, Marker::Square)),
    ("fastsim", style(2, Dash::Dashed, Marker::TriangleUp)),
    ("linear", style(3, Dash::Dashed, Marker::Diamond)),
    ("she", style(4, Dash::DashDot, Marker::TriangleDown)),
    ("polach", style(5, Dash::DashDot, Marker::Plus)),
    ("fastrip", style(6, Dash::LongDash, Marker::Cross)),
    ("relaxation", style(7, Dash::LongDash, Marker::Star)),
    ("kpec", Style { color: EXTRA[0], dash: Dash::Dashed, marker: Marker::TriangleLeft, filled: true }),
    ("analyn", Style { color: EXTRA[1], dash: Dash::DashDot, marker: Marker::TriangleRight, filled: true }),
];

/// Reference sets by label: CONTACT filled circles, the thesis open squares.
const REFERENCES: [(&str, Marker, bool); 2] = [("CONTACT", Marker::Circle, true), ("thesis", Marker::Square, false)];

/// 64-bit FNV-1a: a hash that stays the same across Rust versions and runs.
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// The styles no built-in model uses in colour and marker together, sand (the colour no built-in
/// has) first.
fn leftover() -> Vec<Style> {
    let dashes = [Dash::Solid, Dash::Dashed, Dash::DashDot, Dash::LongDash];
    let order = [8, 0, 1, 2, 3, 4, 5, 6, 7];
    let mut out = Vec::new();
    for (k, &c) in order.iter().enumerate() {
        for (m, &marker) in Marker::ALL.iter().enumerate() {
            let s = style(c, dashes[(k + m) % dashes.len()], marker);
            if !BUILTIN.iter().any(|(_, b)| b.color == s.color && b.marker == s.marker) {
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
    if let Some((_, s)) = BUILTIN.iter().find(|(n, _)| *n == name) {
        return *s;
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
        for (i, (a, sa)) in BUILTIN.iter().enumerate() {
            for (b, sb) in &BUILTIN[i + 1..] {
                assert_ne!(sa.color, sb.color, "{a} and {b}");
                assert_ne!(sa.marker, sb.marker, "{a} and {b}");
            }
            assert_ne!(sa.color, REFERENCE_COLOR, "{a}");
        }
        let mut names: Vec<&str> = BUILTIN.iter().map(|b| b.0).collect();
        let mut models = crate::solvers::builtin_names();
        names.sort();
        models.sort();
        assert_eq!(names, models, "every built-in model has a registered style");
    }

    #[test]
    fn an_external_model_gets_a_fixed_style_no_builtin_has() {
        for name in ["my_model", "python_uba", "ext", "UBA", "x"] {
            let s = model(name);
            assert_eq!(s, model(name), "{name}");
            assert!(!BUILTIN.iter().any(|(_, b)| b.color == s.color && b.marker == s.marker), "{name}: {s:?}");
        }
        assert_eq!(leftover().len(), 9 * 8 - 8);
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
