//! A wheel–rail patch's frame for the models and the exact solver: its own, or for a patch rolling
//! towards −x (CONTACT's CHI = 180°, `wr_creep_cref`) the problem mirrored about x = 0, as module 3
//! solves `chi_deg = 180` ([`mirror`]: CKSI, CPHI and the x parts of the tractions negated, each
//! row of a field reversed; the mirror undoes itself). The exact solver, the models' patch scene
//! and the models that carry their history (`wheelrail_brush`) all take it: a history is kept in
//! the patch's own frame and mapped in on every step.

use crate::solvers::contact::mirror;
use crate::solvers::contact::tangential::StepResult;
use crate::wheelrail::NormalPatch;

/// Whether the patch's problem is solved mirrored, and its grid's row length.
#[derive(Debug, Clone, Copy)]
pub struct RollingFrame {
    mx: usize,
    mirrored: bool,
}

impl RollingFrame {
    /// The frame patch `p` is solved in.
    pub fn of(p: &NormalPatch) -> RollingFrame {
        RollingFrame { mx: p.geometry.grid.mx, mirrored: p.creepages.reversed }
    }

    /// The sign of x (and of CKSI, CPHI, FX and MZ) in this frame.
    pub fn sign(&self) -> f64 {
        if self.mirrored {
            -1.0
        } else {
            1.0
        }
    }

    /// A per-element field in this frame, and back.
    pub fn field<T: Copy>(&self, v: Vec<T>) -> Vec<T> {
        match self.mirrored {
            true => mirror::field(self.mx, &v),
            false => v,
        }
    }

    /// A per-element field of x components in this frame (mirrored and negated), and back.
    pub fn field_x(&self, v: Vec<f64>) -> Vec<f64> {
        match self.mirrored {
            true => mirror::field_x(self.mx, &v),
            false => v,
        }
    }

    /// A pair of per-element fields of (x, y) components (tractions, slips) in this frame, and back.
    pub fn pair(&self, (x, y): (Vec<f64>, Vec<f64>)) -> (Vec<f64>, Vec<f64>) {
        (self.field_x(x), self.field(y))
    }

    /// A module-3 solution's totals (Fx/FN, Fy/FN, MZ [N mm]) in this frame, and back: Fx and MZ
    /// change sign with x.
    pub fn totals(&self, (fx_over_fn, fy_over_fn, mz_nmm): (f64, f64, f64)) -> (f64, f64, f64) {
        (self.sign() * fx_over_fn, fy_over_fn, self.sign() * mz_nmm)
    }

    /// An interval of x [mm] in this frame.
    pub fn extent_x(&self, x_mm: [f64; 2]) -> [f64; 2] {
        match self.mirrored {
            true => [-x_mm[1], -x_mm[0]],
            false => x_mm,
        }
    }

    /// A solution in this frame back in the patch's.
    pub fn back(&self, r: StepResult) -> StepResult {
        let (px, py) = self.pair((r.px, r.py));
        let (sx, sy) = self.pair((r.sx, r.sy));
        StepResult { px, py, sx, sy, state: self.field(r.state), ..r }
    }
}
