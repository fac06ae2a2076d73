//! What a history is drawn against: time for a history in time; for a steady sweep the creepage
//! its direction moves most, or the rolling speed for a sweep over the speed (the report's
//! traction curves and histories, the calibration's before/after).

use super::History;
use crate::problem::{LoadingKind, Problem, ResolvedScene};

/// What decides a history's abscissa: the loading's kind, a sweep's direction in (cx, cy, cs)
/// (zero for a sweep over the rolling speed) and the scene's rolling speed [mm/s] (a row without
/// its own speed has it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drawn {
    pub kind: LoadingKind,
    pub direction: [f64; 3],
    pub v_mm_s: f64,
}

impl Drawn {
    /// A stored scene's (scene.json: a sweep written without a direction is the cx sweep).
    pub fn of_scene(scene: &ResolvedScene) -> Drawn {
        Drawn { kind: scene.kind, direction: scene.sweep_direction.unwrap_or([1.0, 0.0, 0.0]), v_mm_s: scene.v_mm_s }
    }

    /// A resolved problem's.
    pub fn of_problem(p: &Problem) -> Drawn {
        let direction = p.loading.sweep_direction.unwrap_or([1.0, 0.0, 0.0]);
        Drawn { kind: p.loading.kind, direction, v_mm_s: p.rolling.v_mm_s }
    }
}

/// The x of each row of `h` and its column name: `t_s` unless the loading is a sweep; a sweep's
/// the component of its direction largest in magnitude (cx, cy, cs in that order on ties), or
/// `v_mm_s` (each row's rolling speed) when the direction is zero (`over = "v_mm_s"`).
pub fn abscissa(h: &History, drawn: Drawn) -> (&'static str, Vec<f64>) {
    if drawn.kind != LoadingKind::Sweep {
        return ("t_s", h.rows.iter().map(|r| r.sample.t_s).collect());
    }
    let d = drawn.direction;
    if d == [0.0; 3] {
        return ("v_mm_s", h.rows.iter().map(|r| r.sample.speed_mm_s(drawn.v_mm_s)).collect());
    }
    let k = (1..3).fold(0, |k, i| if d[i].abs() > d[k].abs() { i } else { k });
    let pick = [|r: &super::Row| r.sample.cx, |r: &super::Row| r.sample.cy, |r: &super::Row| r.sample.cs][k];
    (["cx", "cy", "cs"][k], h.rows.iter().map(pick).collect())
}
