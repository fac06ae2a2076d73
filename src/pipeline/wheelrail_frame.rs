//! A wheel–rail patch's frame for the models and the exact solver: its own, or for a patch rolling
//! towards −x (CONTACT's CHI = 180°, `wr_creep_cref`) the problem mirrored about x = 0, as module 3
//! solves `chi_deg = 180` ([`mirror`]: CKSI, CPHI and the x parts of the tractions negated, each
//! row of a field reversed; the mirror undoes itself).

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

    /// An interval of x [mm] in this frame.
    pub fn extent_x(&self, x_mm: [f64; 2]) -> [f64; 2] {
        match self.mirrored {
            true => [-x_mm[1], -x_mm[0]],
            false => x_mm,
        }
    }

    /// A solution in this frame back in the patch's.
    pub fn back(&self, r: StepResult) -> StepResult {
        StepResult {
            px: self.field_x(r.px),
            py: self.field(r.py),
            sx: self.field_x(r.sx),
            sy: self.field(r.sy),
            state: self.field(r.state),
            ..r
        }
    }
}
