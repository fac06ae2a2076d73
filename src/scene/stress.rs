//! The `[stress]` table (optional): the points below the surface where the subsurface stresses
//! are asked for (CONTACT's S digit, its blocks of X, Y, Z points), and at which steps.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use crate::error::InputError;
use serde::{Deserialize, Serialize};

/// At most this many coordinates per axis (CONTACT's blocks are grids of NX · NY · NZ points).
pub const MAX_AXIS: usize = 1000;
/// At most this many points in all (the field is computed per point and element).
pub const MAX_POINTS: usize = 1_000_000;
/// A coordinate on the surface [mm].
const SURFACE: Range = Range::new(-1e4, true, 1e4, true);
/// A depth below the surface [mm], into body 1 (the lower body; CONTACT's z ≥ 0).
const DEPTH: Range = Range::new(0.0, true, 1e4, true);

/// A coordinate axis on the surface.
const SURFACE_AXIS: Allowed = Allowed::Numbers { range: SURFACE, min_len: 1, max_len: MAX_AXIS, note: "" };

/// `[stress]`'s keys (`<!-- keys:stress -->`).
pub const KEYS: Keys = Keys {
    id: "stress",
    owner: file!(),
    keys: &[
        key("x_mm", "mm", SURFACE_AXIS, Absent::Required, r#"the points' x: `x_mm = [-1.0, -0.5, 0.0, 0.5, 1.0]`"#),
        key("y_mm", "mm", SURFACE_AXIS, Absent::Required, r#"the points' y: `y_mm = [0.0]`"#),
        key(
            "z_mm",
            "mm",
            Allowed::Numbers { range: DEPTH, min_len: 1, max_len: MAX_AXIS, note: "" },
            Absent::Required,
            r#"the depths below the surface: `z_mm = [0.0, 0.1, 0.2, 0.5, 1.0]`"#,
        ),
        key(
            "block",
            "–",
            Allowed::Text("an array of tables `[[stress.block]]`, each with `x_mm`, `y_mm`, `z_mm` as here"),
            Absent::Text("–"),
            r#"several blocks of points instead of `[stress]`'s own `x_mm`, `y_mm`, `z_mm` (below)"#,
        ),
        key(
            "steps",
            "–",
            Allowed::Text("an array of 1 to 1000 whole numbers ≥ 0"),
            Absent::Text("the last row"),
            r#"the rows (the history's `step`) whose tractions load the half-space: `steps = [0, 10]`; a step no row has gives no rows"#,
        ),
    ],
};

/// One block of points, the grid x × y × z (CONTACT's ISUBS = 9 block).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// Along x [mm] in CONTACT's coordinates (as `[grid] x_mm`).
    pub x_mm: Vec<f64>,
    pub y_mm: Vec<f64>,
    /// Depth below the surface [mm], ≥ 0.
    pub z_mm: Vec<f64>,
}

impl Block {
    /// Every point, x fastest, then y, then z (CONTACT's order in its `.subs` file).
    pub fn points(&self) -> Vec<[f64; 3]> {
        let mut out = Vec::with_capacity(self.x_mm.len() * self.y_mm.len() * self.z_mm.len());
        for &z in &self.z_mm {
            for &y in &self.y_mm {
                out.extend(self.x_mm.iter().map(|&x| [x, y, z]));
            }
        }
        out
    }
}

/// The blocks of points and the steps whose tractions load the half-space.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StressPoints {
    pub blocks: Vec<Block>,
    /// The steps (a history's `step` column) whose field is used; `None`: the last row.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub steps: Option<Vec<usize>>,
}

/// One block's `x_mm`, `y_mm`, `z_mm` (each 1 to 1000 numbers).
fn block(t: &mut Section) -> Result<Block, InputError> {
    let missing = |t: &Section, key: &str| {
        InputError::new(t.field(key), "missing", KEYS.get(key).map(|k| k.allowed.message()).unwrap_or_default())
    };
    let x_mm = t.opt_num_list("x_mm")?.ok_or_else(|| missing(t, "x_mm"))?;
    let y_mm = t.opt_num_list("y_mm")?.ok_or_else(|| missing(t, "y_mm"))?;
    let z_mm = t.opt_num_list("z_mm")?.ok_or_else(|| missing(t, "z_mm"))?;
    Ok(Block { x_mm, y_mm, z_mm })
}

/// `[stress]`: one block (`x_mm`, `y_mm`, `z_mm`) or several (`[[stress.block]]`, each its
/// own), and `steps` (optional).
pub fn read(top: &mut Section) -> Result<Option<StressPoints>, InputError> {
    let Some(mut t) = top.opt_table("stress")?.map(|t| t.declare(&KEYS)) else {
        return Ok(None);
    };
    let blocks = match t.opt_tables("block")? {
        Some(sections) if !sections.is_empty() => {
            let mut out = Vec::with_capacity(sections.len());
            for b in sections {
                let mut b = b.declare(&KEYS);
                out.push(block(&mut b)?);
                b.finish()?;
            }
            out
        }
        Some(_) => return Err(InputError::new(t.field("block"), "[]", "one or more [[stress.block]] tables")),
        None => vec![block(&mut t)?],
    };
    let n: usize = blocks.iter().map(|b| b.x_mm.len() * b.y_mm.len() * b.z_mm.len()).sum();
    if n > MAX_POINTS {
        return Err(InputError::new(
            t.field("z_mm"),
            format!("{n} points"),
            format!("at most {MAX_POINTS} points in all"),
        ));
    }
    let steps = match t.given("steps") {
        None => None,
        Some(toml::Value::Array(items)) if !items.is_empty() && items.len() <= MAX_AXIS => {
            let mut out = Vec::with_capacity(items.len());
            for (k, item) in items.iter().enumerate() {
                match item {
                    toml::Value::Integer(i) if *i >= 0 => out.push(*i as usize),
                    other => {
                        return Err(InputError::new(
                            format!("{}[{k}]", t.field("steps")),
                            other,
                            "a step number (a whole number >= 0)",
                        ))
                    }
                }
            }
            Some(out)
        }
        Some(other) => {
            return Err(InputError::new(t.field("steps"), other, format!("an array of 1 to {MAX_AXIS} step numbers")))
        }
    };
    t.finish()?;
    Ok(Some(StressPoints { blocks, steps }))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_str(text: &str) -> Result<Option<StressPoints>, InputError> {
        let doc: toml::Table = text.parse().unwrap();
        read(&mut Section::new("", &doc))
    }

    #[test]
    fn stress_points_read_in_contact_order() {
        let p = read_str("[stress]\nx_mm = [-1, 1]\ny_mm = [0]\nz_mm = [0, 0.5]\nsteps = [3]").unwrap().unwrap();
        assert_eq!(p.blocks[0].points(), vec![[-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [-1.0, 0.0, 0.5], [1.0, 0.0, 0.5]]);
        assert_eq!(p.steps, Some(vec![3]));
        let two = "[stress]\n[[stress.block]]\nx_mm = [0]\ny_mm = [0]\nz_mm = [1]\n[[stress.block]]\nx_mm = [1, 2]\ny_mm = [0]\nz_mm = [0]";
        let p = read_str(two).unwrap().unwrap();
        assert_eq!(p.blocks.len(), 2);
        assert_eq!(p.blocks[1].points(), vec![[1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]);
        assert_eq!(p.steps, None);
        assert_eq!(read_str("name = 'a'").unwrap(), None);
    }

    #[test]
    fn stress_points_refuse_bad_input_naming_the_field() {
        let err = read_str("[stress]\nx_mm = [0]\ny_mm = [0]\nz_mm = [-0.1]").unwrap_err().to_string();
        assert!(err.contains("stress.z_mm[0]") && err.contains("-0.1"), "{err}");
        let err = read_str("[stress]\nx_mm = [0]\ny_mm = [0]").unwrap_err().to_string();
        assert!(err.contains("stress.z_mm"), "{err}");
        let err = read_str("[stress]\nx_mm = [0]\ny_mm = [0]\nz_mm = [1]\nsteps = [-1]").unwrap_err().to_string();
        assert!(err.contains("stress.steps[0]"), "{err}");
        let err =
            read_str("[stress]\n[[stress.block]]\nx_mm = [0]\ny_mm = [0]\nz_mm = [1]\nw = 1").unwrap_err().to_string();
        assert!(err.contains("stress.block[0].w"), "{err}");
        let err = read_str("[stress]\nx_mm = [0]\ny_mm = [0]\nz_mm = [1]\ndepth = 2").unwrap_err().to_string();
        assert!(err.contains("stress.depth"), "{err}");
    }
}
