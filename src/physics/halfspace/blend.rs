//! Sub-patches with attenuated cross-influence (CONTACT's blending approach for contact patches
//! between D_COMB and D_SEP apart, its IPLAN = 4; user guide, "Module 1", and Vollebregt 2020,
//! "wheel–rail geometry"): every element belongs to one sub-patch (or to none: it cannot touch);
//! the displacement at an element of sub-patch j from pressure in sub-patch i is scaled by
//! `f(i, j)` (1 on the diagonal).

use super::convolution::Convolver;
use super::ContactError;

/// The sub-patch of every element (0: none, outside every sub-patch's rectangle) and the
/// symmetric factors between sub-patches.
#[derive(Debug, Clone, PartialEq)]
pub struct Blend {
    /// Sub-patch number per element (1 to n; 0 outside), in the grid's element order.
    pub part: Vec<u16>,
    /// `n × n` factors, row-major: `factor[(i − 1) n + (j − 1)]` scales the influence of
    /// sub-patch i's pressure on sub-patch j's elements.
    pub factor: Vec<f64>,
    pub n: usize,
}

impl Blend {
    /// The factor between sub-patches `i` and `j` (1-based).
    pub fn factor(&self, i: u16, j: u16) -> f64 {
        self.factor[(i as usize - 1) * self.n + (j as usize - 1)]
    }

    /// Whether element `k` may carry pressure.
    pub fn allows(&self, k: usize) -> bool {
        self.part[k] > 0
    }

    /// The same blend with its elements reordered: element `k` of the result is element
    /// `order[k]` of this one.
    pub fn reordered(&self, order: &[usize]) -> Blend {
        Blend { part: order.iter().map(|&k| self.part[k]).collect(), factor: self.factor.clone(), n: self.n }
    }

    /// `u = A_blend p`: per sub-patch i, the displacements of its pressure alone, scaled on
    /// every other sub-patch j by `f(i, j)` (CONTACT's `normcg_matvec` with IPLAN = 4).
    pub fn normal(&self, conv: &mut Convolver, p: &[f64], u: &mut [f64]) -> Result<(), ContactError> {
        u.iter_mut().for_each(|v| *v = 0.0);
        let mut own = vec![0.0; p.len()];
        let mut part_u = vec![0.0; p.len()];
        for i in 1..=self.n as u16 {
            let mut any = false;
            for (k, o) in own.iter_mut().enumerate() {
                *o = if self.part[k] == i { p[k] } else { 0.0 };
                any |= *o != 0.0;
            }
            if !any {
                continue;
            }
            conv.normal(&own, None, &mut part_u)?;
            for k in 0..p.len() {
                let j = self.part[k];
                let f = if j == 0 || j == i { 1.0 } else { self.factor(i, j) };
                u[k] += f * part_u[k];
            }
        }
        Ok(())
    }
}
