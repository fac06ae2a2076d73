//! `[stress]` of a history whose cases ask for subsurface stresses (S ≥ 1): the blocks of
//! explicit points (ISUBS = 9) as `[[stress.block]]`, sorted and without repeats as CONTACT
//! computes them (user guide, "Input for the subsurface stress calculation"), and the rows of
//! those cases as its `steps`.

use super::{case3, floats, table, Source};
use crate::error::InputError;
use crate::import::contact::deck::SubsurfaceBlock;
use crate::problem::Problem;
use toml::Value;

/// The history's `[stress]`, or `None` when no case asks for stresses. Every case that does must
/// use the same points (one set per scene).
pub(super) fn section(src: &Source, problem: &Problem) -> Result<Option<Value>, InputError> {
    let mut steps = Vec::new();
    let mut blocks: Option<&[SubsurfaceBlock]> = None;
    for (&k, row) in src.h.cases.iter().zip(problem.loading.rows()) {
        let c = case3(src.cases, k);
        if c.digits.s == 0 {
            continue;
        }
        match blocks {
            Some(b) if b != c.state.subsurface.as_slice() => {
                return Err(InputError::new(
                    format!("{}, case {}", src.file, src.cases[k].number),
                    "subsurface points that differ from an earlier case's of its history",
                    "one set of subsurface points per history (S = 3 before its first case with S >= 1)",
                ))
            }
            _ => blocks = Some(&c.state.subsurface),
        }
        steps.push(Value::Integer(row.step as i64));
    }
    let Some(blocks) = blocks else {
        return Ok(None);
    };
    let mut out = Vec::new();
    for b in blocks {
        // element centres or body 2: read and not computed (features.rs)
        let SubsurfaceBlock::Points(axes) = b else {
            return Ok(None);
        };
        if axes[2].iter().any(|&z| z < 0.0) {
            return Ok(None);
        }
        let [x, y, z] = axes.clone().map(sorted_unique);
        out.push(table(vec![("x_mm", floats(&x)), ("y_mm", floats(&y)), ("z_mm", floats(&z))]));
    }
    Ok(Some(table(vec![("block", Value::Array(out)), ("steps", Value::Array(steps))])))
}

/// Ascending, each value once.
fn sorted_unique(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}
