//! `[creepage]`: the loading history (a step, a sine, a sweep or a table) and the constant
//! creepages or force ratios; its keys declared once ([`KEYS`]) for the reader and
//! docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::{table, Creepage, CREEPAGE_LIMIT, FINITE, FORCE_RATIO, HARD_MAX_STEPS, SPIN_LIMIT};
use crate::error::InputError;
use std::path::Path;

/// `[creepage]`'s keys (`<!-- keys:creepage -->`).
pub const KEYS: Keys = Keys {
    id: "creepage",
    owner: file!(),
    keys: &[
        key(
            "kind",
            "–",
            Allowed::Choice(&["step", "sine", "sweep", "table"], ""),
            Absent::Required,
            r#"the history's form"#,
        ),
        key(
            "cy",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Num(0.0),
            r#"the constant lateral creepage: `cy = 0.001`"#,
        ),
        key(
            "fy_over_fn",
            "–",
            Allowed::Number(FORCE_RATIO, "below μ together with `fx_over_fn`"),
            Absent::Text("absent: cy given"),
            r#"Fy/FN prescribed in place of `cy`, only together with Fx/FN (`fx_over_fn`, a sweep's `over = "fx_over_fn"` or the table's column: CONTACT's F = 2); not with `cy`; in a sweep the constant the direction's second component is added to (`over = "fy_over_fn"` prescribes Fy/FN from 0 without it): `fy_over_fn = -0.05`"#,
        ),
        key(
            "cs",
            "1/mm",
            Allowed::Number(SPIN_LIMIT, ""),
            Absent::Num(0.0),
            r#"the constant spin creepage: `cs = 0.0001`"#,
        ),
        key(
            "c",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Text("required for `step`"),
            r#"step: cx = c at every step k ≥ 1: `c = 0.005`"#,
        ),
        key(
            "steps",
            "–",
            Allowed::Whole(1, HARD_MAX_STEPS, "at most `[limits] max_steps`"),
            Absent::Text("required for `step`"),
            r#"step: the number of steps: `steps = 44`"#,
        ),
        key(
            "c_before",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Num(0.0),
            r#"step: cx at t = 0, before the step (the state `[init]` starts from): `c_before = -0.005`"#,
        ),
        key(
            "fx_over_fn",
            "–",
            Allowed::Number(FORCE_RATIO, "below μ"),
            Absent::Text("absent: cx given"),
            r#"step: Fx/FN prescribed at every step k ≥ 1 in place of `c` (not with `c`, `c_before`; t = 0 carries no force); sweep: Fx/FN prescribed in place of cx at every point, the constant the direction's first component is added to (not with `cx`; steady rolling under CONTACT's T = 3): CONTACT's F = 1 (F = 2 with `fy_over_fn`); sine and table refuse it (a table has the column): `fx_over_fn = 0.2`"#,
        ),
        key(
            "c0",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Text("required for `sine`"),
            r#"sine: the mean creepage, cx(t_k) = c0 + cp·sin(2π·F·t_k): `c0 = 0.001`"#,
        ),
        key(
            "cp",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Text("required for `sine`"),
            r#"sine: the amplitude: `cp = 0.002`"#,
        ),
        key(
            "freq_hz",
            "Hz",
            Allowed::Number(Range::new(0.0, false, 1e6, true), ""),
            Absent::Text("required for `sine`"),
            r#"sine: the frequency F (fewer than 3 steps per period warns: aliased): `freq_hz = 30.0`"#,
        ),
        key(
            "periods",
            "–",
            Allowed::Number(Range::new(0.0, false, 1e4, true), ""),
            Absent::Text("required for `sine`"),
            r#"sine: the length, k = 1 … ceil(periods/(F·dt)): `periods = 3.0`"#,
        ),
        key(
            "from",
            "–",
            Allowed::Number(FINITE, ""),
            Absent::Text("required for `sweep` without `at`"),
            r#"sweep: the first value of the sweep parameter t: `from = 0.0`"#,
        ),
        key(
            "to",
            "–",
            Allowed::Number(FINITE, ""),
            Absent::Text("required for `sweep` without `at`"),
            r#"sweep: the last value of t: `to = 0.01`"#,
        ),
        key(
            "points",
            "–",
            Allowed::Whole(1, HARD_MAX_STEPS, "at most `[limits] max_steps`"),
            Absent::Text("required for `sweep` without `at`"),
            r#"sweep: points evenly spaced from `from` to `to`: `points = 101`"#,
        ),
        key(
            "at",
            "–",
            Allowed::Numbers {
                range: FINITE,
                min_len: 1,
                max_len: HARD_MAX_STEPS,
                note: "at most `[limits] max_steps`, any order",
            },
            Absent::Text("–"),
            r#"sweep: the points at these t instead of `from`, `to`, `points` (not together with them); an error names the entry, `creepage.at[k]`: `at = [0.0, 0.001, 0.004]`"#,
        ),
        key(
            "over",
            "–",
            Allowed::Choice(SWEEP_OVER, ""),
            Absent::Choice("cx"),
            r#"sweep: the creepage the sweep moves, the direction [1, 0, 0], [0, 1, 0] or [0, 0, 1] (the default gives the cx sweep of scenes written before `over` existed, bit for bit); `"v_mm_s"`: t is the rolling speed [mm/s], in `[rolling] v_mm_s`'s range ((0, 1e6] with a finite time step courant·dx/t), and the creepages `cx`, `cy`, `cs` are held; `"fx_over_fn"`, `"fy_over_fn"`: t is the force ratio prescribed in place of cx (cy), as `fx_over_fn` (`fy_over_fn`) given, at every point (not with `cx` (`cy`), nor `over = "cx"` with `fx_over_fn`); not with `direction`: `over = "cy"`"#,
        ),
        key(
            "direction",
            "–",
            Allowed::Numbers { range: FINITE, min_len: 3, max_len: 3, note: "not all zero" },
            Absent::Text("`[1, 0, 0]`"),
            r#"sweep: point k is [cx, cy, cs] + t·direction (Fx/FN, Fy/FN in place of cx, cy where `fx_over_fn`, `fy_over_fn` prescribe them); not with `over`: `direction = [0.7071, 0.7071, 0.0]`"#,
        ),
        key(
            "cx",
            "–",
            Allowed::Number(CREEPAGE_LIMIT, ""),
            Absent::Num(0.0),
            r#"sweep: the constant cx the direction is added to (the other kinds set cx themselves and refuse it; not with `fx_over_fn`): `cx = 0.001`"#,
        ),
        key(
            "file",
            "–",
            Allowed::Text("a path to a CSV file, relative to the scene file"),
            Absent::Text("required for `table`"),
            r#"table: the history as a CSV (below): `file = "mu_ramp_table.csv"`"#,
        ),
        key(
            "extra_slip",
            "–",
            Allowed::Text("a path to a CSV file (columns `ix`, `iy`, `wx`, `wy`), relative to the scene file"),
            Absent::Text("absent: none"),
            r#"an extra rigid slip per element (CONTACT's EXRHS, E = 9) added to cx (`wx`) and cy (`wy`) of that element at every step, scaled by the rolling step as they are: 1-based element indices (ix along CONTACT's x from x0, as `[geometry] field`), every element of the grid exactly once; only the exact solver (`contact`), rolling along x (`chi_deg = 0`): `extra_slip = "w.csv"`"#,
        ),
    ],
};

/// The loading: the creepage history and the constant lateral and spin creepages.
pub struct CreepageSpec {
    pub creepage: Creepage,
    pub cy: f64,
    /// `fy_over_fn`: Fy/FN prescribed in place of `cy` (CONTACT F = 2).
    pub fy_over_fn: Option<f64>,
    pub cs_per_mm: f64,
    /// `extra_slip`: the extra rigid slip `[wx, wy]` per element in CONTACT's element order.
    pub extra_slip: Option<[Vec<f64>; 2]>,
}

/// `[creepage]`: the kind's history, and the constant cy and cs.
pub fn read(top: &mut Section, dir: &Path, grid: (usize, usize)) -> Result<CreepageSpec, InputError> {
    let mut cr = top.table("creepage")?.declare(&KEYS);
    let kind = cr.pick("kind")?;
    let creepage = match kind {
        "step" => match cr.opt_num("fx_over_fn")? {
            Some(f) => {
                let instead = "only one of creepage.c (cx given) and creepage.fx_over_fn (Fx/FN prescribed; the state at t = 0 carries no force)";
                cr.refuse("c", instead)?;
                cr.refuse("c_before", instead)?;
                Creepage::Step { c: f, steps: cr.whole("steps")?, c_before: 0.0, fx_prescribed: true }
            }
            None => Creepage::Step {
                c: cr.num("c")?,
                steps: cr.whole("steps")?,
                c_before: cr.num_or_default("c_before")?,
                fx_prescribed: false,
            },
        },
        "sine" => Creepage::Sine {
            c0: cr.num("c0")?,
            cp: cr.num("cp")?,
            freq_hz: cr.num("freq_hz")?,
            periods: cr.num("periods")?,
        },
        "sweep" => sweep(&mut cr)?,
        _ => {
            let file = cr.text("file")?;
            let path = dir.join(file);
            let rows = Box::new(table::CreepageTable::from_file(&path, &cr.field("file"))?);
            Creepage::Table { file: path, rows }
        }
    };
    if kind != "sweep" {
        let only_sweep = format!("only with kind = \"sweep\" (kind {kind:?} sets cx itself)");
        for key in ["cx", "over", "direction"] {
            cr.refuse(key, &only_sweep)?;
        }
    }
    if kind != "step" && kind != "sweep" {
        cr.refuse(
            "fx_over_fn",
            "only with kind = \"step\" or \"sweep\" (a table prescribes Fx/FN as its column fx_over_fn)",
        )?;
    }
    // A sweep over Fy/FN prescribes it at every point (its constant 0 where not given).
    let over_fy = kind == "sweep" && cr.opt_pick("over")? == Some("fy_over_fn");
    let fy_over_fn = cr.opt_num("fy_over_fn")?.or(over_fy.then_some(0.0));
    if fy_over_fn.is_some() {
        cr.refuse("cy", "only one of creepage.cy (cy given) and creepage.fy_over_fn (Fy/FN prescribed)")?;
        if kind == "sweep" && cr.opt_pick("over")? == Some("cy") {
            cr.refuse("over", "over = \"fy_over_fn\" with fy_over_fn (Fy/FN prescribed in place of cy)")?;
        }
    }
    let cy = cr.num_or_default("cy")?;
    let cs_per_mm = cr.num_or_default("cs")?;
    let extra_slip = extra_slip(&mut cr, dir, grid)?;
    cr.finish()?;
    Ok(CreepageSpec { creepage, cy, fy_over_fn, cs_per_mm, extra_slip })
}

/// `extra_slip`: the CSV `ix,iy,wx,wy` over every element of the `mx` x `my` grid.
fn extra_slip(cr: &mut Section, dir: &Path, grid: (usize, usize)) -> Result<Option<[Vec<f64>; 2]>, InputError> {
    let Some(file) = cr.opt_text("extra_slip")? else { return Ok(None) };
    let field = cr.field("extra_slip");
    let (cols, lines, origin) = super::geometry::read_columns(&dir.join(file), &field, &["ix", "iy", "wx", "wy"])?;
    let mut w = super::geometry::per_element(&cols, &lines, &origin, grid)?;
    let wy = w.pop().expect("two value columns");
    let wx = w.pop().expect("two value columns");
    Ok(Some([wx, wy]))
}

/// What a sweep's `over` may name: a creepage, a prescribed force ratio or the speed.
const SWEEP_OVER: &[&str] = &["cx", "cy", "cs", "v_mm_s", "fx_over_fn", "fy_over_fn"];

/// `[creepage] kind = "sweep"`: the parameter's points (`from, to, points` or the list `at`),
/// the direction (`over` or `direction`) and the constant cx, or Fx/FN prescribed in its place
/// (`fx_over_fn` or `over = "fx_over_fn"`, CONTACT's F = 1, 2 in steady rolling).
fn sweep(cr: &mut Section) -> Result<Creepage, InputError> {
    let at = cr.opt_num_list("at")?;
    let (from, to, points) = match &at {
        Some(list) => {
            for key in ["from", "to", "points"] {
                cr.refuse(key, "either creepage.at (a list of t) or from, to, points, not both")?;
            }
            (list[0], list[list.len() - 1], list.len())
        }
        None => (cr.num("from")?, cr.num("to")?, cr.whole("points")?),
    };
    let over = cr.opt_pick("over")?;
    let speed = over == Some("v_mm_s");
    let direction = if speed {
        cr.refuse("direction", "not with over = \"v_mm_s\" (a speed sweep holds the creepages)")?;
        [0.0; 3]
    } else {
        sweep_direction(cr)?
    };
    let fx = cr.opt_num("fx_over_fn")?;
    let fx_prescribed = fx.is_some() || over == Some("fx_over_fn");
    if fx_prescribed {
        let instead =
            "only one of creepage.cx (cx given) and creepage.fx_over_fn or over = \"fx_over_fn\" (Fx/FN prescribed)";
        cr.refuse("cx", instead)?;
        if over == Some("cx") {
            cr.refuse("over", "over = \"fx_over_fn\" with fx_over_fn (Fx/FN prescribed in place of cx)")?;
        }
    }
    let cx = match fx {
        Some(f) => f,
        None => cr.num_or_default("cx")?,
    };
    Ok(Creepage::Sweep { from, to, points, direction, cx, at, speed, fx_prescribed })
}

/// A sweep's direction in (x, y, cs), x and y the creepages or the force ratios prescribed in
/// their place: `over` one of them, or `direction` (not both; default x).
fn sweep_direction(cr: &mut Section) -> Result<[f64; 3], InputError> {
    let over = cr.opt_pick("over")?;
    Ok(match (over, cr.opt_nums::<3>("direction")?) {
        (Some(o), Some(d)) => {
            return Err(InputError::new(
                cr.field("direction"),
                format!("{d:?} with over = {o:?}"),
                "either creepage.over or creepage.direction, not both",
            ))
        }
        (None, Some(d)) if d.iter().all(|&x| x == 0.0) => {
            return Err(InputError::new(
                cr.field("direction"),
                format!("{d:?}"),
                "three finite numbers [dcx, dcy, dcs], not all zero",
            ))
        }
        (None, Some(d)) => d,
        (Some("cy" | "fy_over_fn"), None) => [0.0, 1.0, 0.0],
        (Some("cs"), None) => [0.0, 0.0, 1.0],
        _ => [1.0, 0.0, 0.0],
    })
}
