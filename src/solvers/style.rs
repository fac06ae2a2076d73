//! How a model is drawn in every figure — one colour, dash and marker per model — as a field of
//! its registry entry ([`super::ModelDef::style`]). Colours: Paul Tol's "muted" scheme (colour-blind
//! safe; Tol, "Colour schemes", SRON/EPS/TN/09-002, 2021) and two of his "light" scheme.

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
    /// Two more for KPEC and ANALYN (outside [`Marker::ALL`], which the leftover styles of other
    /// models draw from).
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

/// A model's colour, dash and marker.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ModelStyle {
    /// `#rrggbb`.
    pub colour: &'static str,
    pub dash: Dash,
    pub marker: Marker,
}

/// Tol's muted scheme: indigo, rose, green, cyan, wine, teal, olive, purple, sand.
pub const MUTED: [&str; 9] =
    ["#332288", "#CC6677", "#117733", "#88CCEE", "#882255", "#44AA99", "#999933", "#AA4499", "#DDCC77"];

/// Three of Tol's "light" scheme (orange, light blue, pink), for the models beyond the muted nine.
pub const LIGHT: [&str; 3] = ["#EE8866", "#77AADD", "#FFAABB"];

/// A style from the muted scheme's colour `k`.
pub const fn muted(k: usize, dash: Dash, marker: Marker) -> ModelStyle {
    ModelStyle { colour: MUTED[k], dash, marker }
}
