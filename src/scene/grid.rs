//! `[grid]`: the potential contact's elements, its scale or its explicit edges; its keys
//! declared once ([`KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::{MAX_ELEMENTS_PER_AXIS, MAX_GRID_ELEMENTS};
use crate::error::InputError;
use crate::physics::geometry::Extent;

/// An edge of the potential contact [mm].
const EDGE: Range = Range::new(-1e4, true, 1e4, true);

/// `[grid]`'s keys (`<!-- keys:grid -->`).
pub const KEYS: Keys = Keys {
    id: "grid",
    owner: file!(),
    keys: &[
        key(
            "mx",
            "–",
            Allowed::Whole(1, MAX_ELEMENTS_PER_AXIS, "mx · my at most 524288"),
            Absent::Required,
            r#"elements along x; on an ellipse dx = 2·scale·a/mx and element centres at −scale·a + dx/2 + k·dx: `mx = 22`"#,
        ),
        key(
            "my",
            "–",
            Allowed::Whole(1, MAX_ELEMENTS_PER_AXIS, "mx · my at most 524288"),
            Absent::Required,
            r#"elements along y, dy = 2·scale·b/my: `my = 22`"#,
        ),
        key(
            "scale",
            "–",
            Allowed::Number(super::GRID_SCALE, ""),
            Absent::Num(1.0),
            r#"the potential contact as CONTACT's SCALE: the grid covers `scale` times the nominal ellipse's bounding box, x in [−scale·a, scale·a]; the contact stays the ellipse (whose size grows as FN^(1/3)). A creepage table whose largest `fn_n` gives an ellipse beyond the grid warns and names the scale that covers it: `scale = 1.5714285714285714`"#,
        ),
        key(
            "x_mm",
            "mm",
            Allowed::Numbers { range: EDGE, min_len: 2, max_len: 2, note: "low < high" },
            Absent::Text("–"),
            r#"the edges `[x0, x1]` of the potential contact in CONTACT's coordinates, for a `[geometry]` given per element, or for an ellipse whose grid is a window of its own (with `y_mm`; not with `scale`): the contact is cut at the window's edge, as CONTACT's grid kept by D = 0 when the load changes; element (ix, iy) has its centre at x0 + (ix − ½)·dx: `x_mm = [-10.0, 10.0]`"#,
        ),
        key(
            "y_mm",
            "mm",
            Allowed::Numbers { range: EDGE, min_len: 2, max_len: 2, note: "low < high" },
            Absent::Text("–"),
            r#"the edges `[y0, y1]` along y: `y_mm = [-8.0, 8.0]`"#,
        ),
    ],
};

/// `[grid]`: its element counts, its scale and the potential contact's extent.
pub struct GridSpec {
    pub mx: usize,
    pub my: usize,
    pub scale: f64,
    pub extent: Extent,
}

/// `[grid]` (read first: a geometry per element fills it).
pub fn read(top: &mut Section) -> Result<GridSpec, InputError> {
    let mut g = top.table("grid")?.declare(&KEYS);
    let mx = g.whole("mx")?;
    let my = g.whole("my")?;
    if mx * my > MAX_GRID_ELEMENTS {
        return Err(InputError::new(
            g.field("my"),
            format!("{my} with mx = {mx} ({} elements)", mx * my),
            format!("mx · my at most {MAX_GRID_ELEMENTS} elements"),
        ));
    }
    let scale = g.num_or_default("scale")?;
    let extent = grid_extent(&mut g, scale)?;
    g.finish()?;
    Ok(GridSpec { mx, my, scale, extent })
}

/// `[grid] x_mm, y_mm` (both or neither): explicit edges, else `scale` times the ellipse's box.
fn grid_extent(g: &mut Section, scale: f64) -> Result<Extent, InputError> {
    match (g.opt_nums::<2>("x_mm")?, g.opt_nums::<2>("y_mm")?) {
        (None, None) => Ok(Extent::Scale(scale)),
        (Some(x_mm), Some(y_mm)) => {
            for (key, [lo, hi]) in [("x_mm", x_mm), ("y_mm", y_mm)] {
                if hi <= lo {
                    return Err(InputError::new(
                        g.field(key),
                        format!("[{lo}, {hi}]"),
                        "edges [low, high] with low < high [mm]",
                    ));
                }
            }
            g.refuse("scale", "not with explicit edges x_mm, y_mm (scale sizes a grid from the ellipse)")?;
            Ok(Extent::Edges { x_mm, y_mm })
        }
        (x, _) => {
            let missing = if x.is_none() { "x_mm" } else { "y_mm" };
            Err(InputError::new(
                g.field(missing),
                "missing",
                "both edges x_mm = [x0, x1] and y_mm = [y0, y1], or neither",
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The keys' table says the total the reader checks (a note is text, the limit a constant).
    #[test]
    fn the_documented_total_is_the_one_checked() {
        for k in KEYS.keys.iter().filter(|k| k.key == "mx" || k.key == "my") {
            assert!(k.allowed.cell().contains(&MAX_GRID_ELEMENTS.to_string()), "{}: {}", k.key, k.allowed.cell());
        }
    }
}
