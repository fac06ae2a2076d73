//! Shifts that continue a sequence (CONTACT's T = 1 with P = 0, user guide "Tangential
//! quantities in case of a shift"; `m_wr_locatecp` `wr_connect_cps`, `wr_update_allcps`,
//! `m_hierarch_data` `gd_merge`, `m_wr_solvecp` `merge_prev_potcon`): each patch a case leaves
//! keeps its tractions on the material-fixed super-grid; a new patch takes those of the old
//! patches whose extents overlap its own (two or more merged onto one grid, one feeding two new
//! patches copied to both, old patches nothing connects to kept for later), and its grid is
//! widened to the contact of the time before.

use super::patch::{Extent, PatchGrid};

/// A box of super-grid element indices, `x` and `s` each `[first, last]` (inclusive).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct IndexBox {
    pub x: [i64; 2],
    pub s: [i64; 2],
}

impl IndexBox {
    /// The elements of `g` on the super-grid.
    pub fn of_grid(g: &PatchGrid) -> IndexBox {
        let [i, j] = g.first_index;
        IndexBox { x: [i, i + g.mx as i64 - 1], s: [j, j + g.ms as i64 - 1] }
    }

    /// The smallest box holding both (CONTACT's `potcon_merge`).
    pub fn union(self, o: IndexBox) -> IndexBox {
        IndexBox {
            x: [self.x[0].min(o.x[0]), self.x[1].max(o.x[1])],
            s: [self.s[0].min(o.s[0]), self.s[1].max(o.s[1])],
        }
    }

    /// The elements both hold, if any.
    pub fn intersect(self, o: IndexBox) -> Option<IndexBox> {
        let b = IndexBox {
            x: [self.x[0].max(o.x[0]), self.x[1].min(o.x[1])],
            s: [self.s[0].max(o.s[0]), self.s[1].min(o.s[1])],
        };
        (b.x[0] <= b.x[1] && b.s[0] <= b.s[1]).then_some(b)
    }

    /// The box's first element alone.
    fn first(self) -> IndexBox {
        IndexBox { x: [self.x[0]; 2], s: [self.s[0]; 2] }
    }

    fn mx(self) -> usize {
        (self.x[1] - self.x[0] + 1) as usize
    }

    fn ms(self) -> usize {
        (self.s[1] - self.s[0] + 1) as usize
    }

    fn contains(self, i: i64, j: i64) -> bool {
        (self.x[0]..=self.x[1]).contains(&i) && (self.s[0]..=self.s[1]).contains(&j)
    }

    /// The flat index (CONTACT's order: x fastest) of super-grid element (i, j) in this box.
    fn index(self, i: i64, j: i64) -> usize {
        (j - self.s[0]) as usize * self.mx() + (i - self.x[0]) as usize
    }
}

/// One patch a case leaves for the next (CONTACT's `allcps(icp)%cp` with its `gd`).
#[derive(Debug, Clone, PartialEq)]
pub struct OldPatch {
    /// The interpenetration's extent in track coordinates (what overlap connects).
    pub extent: Extent,
    /// Its grid on the super-grid.
    pub grid: IndexBox,
    /// Tractions per element of `grid` [MPa], CONTACT's element order, the exact solver's frame.
    pub px_mpa: Vec<f64>,
    pub py_mpa: Vec<f64>,
    /// The elements of `grid` in contact at its last step (CONTACT's `igs`; CONTACT's order).
    pub contact: Vec<bool>,
    /// Those in contact at the step before its last, where `grid` holds them (CONTACT's `igv`
    /// when the next step widens its grid: a field on the patch's grid, cut with it); `None`
    /// after a step from rest.
    pub contact_before: Option<Vec<bool>>,
}

impl OldPatch {
    /// The tractions of super-grid element (i, j), zero off its grid.
    fn at(&self, i: i64, j: i64) -> (f64, f64) {
        if !self.grid.contains(i, j) {
            return (0.0, 0.0);
        }
        let k = self.grid.index(i, j);
        (self.px_mpa[k], self.py_mpa[k])
    }

    /// Its contact on the elements of `b` (none off its grid).
    pub fn contact_on(&self, b: IndexBox) -> Vec<bool> {
        mask_on(self.grid, &self.contact, b)
    }

    /// The tractions on the elements of `b` (zero off this patch's grid).
    fn on_box(&self, b: IndexBox) -> (Vec<f64>, Vec<f64>) {
        let mut px = Vec::with_capacity(b.mx() * b.ms());
        let mut py = Vec::with_capacity(px.capacity());
        for j in b.s[0]..=b.s[1] {
            for i in b.x[0]..=b.x[1] {
                let (x, y) = self.at(i, j);
                px.push(x);
                py.push(y);
            }
        }
        (px, py)
    }
}

/// A mask on the elements of `from` on those of `to` (false where `from` does not reach).
fn mask_on(from: IndexBox, mask: &[bool], to: IndexBox) -> Vec<bool> {
    let mut out = Vec::with_capacity(to.mx() * to.ms());
    for j in to.s[0]..=to.s[1] {
        for i in to.x[0]..=to.x[1] {
            out.push(from.contains(i, j) && mask[from.index(i, j)]);
        }
    }
    out
}

/// The box of the elements of `b` a mask holds, if any.
fn mask_box(b: IndexBox, mask: &[bool]) -> Option<IndexBox> {
    let mut out: Option<IndexBox> = None;
    for (k, _) in mask.iter().enumerate().filter(|(_, &m)| m) {
        let (i, j) = (b.x[0] + (k % b.mx()) as i64, b.s[0] + (k / b.mx()) as i64);
        let e = IndexBox { x: [i; 2], s: [j; 2] };
        out = Some(out.map_or(e, |o| o.union(e)));
    }
    out
}

/// The patches of the case before (their order: the case's patches, then those kept for later).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Previous {
    pub patches: Vec<OldPatch>,
    /// Whether the case solves at several trial heights (FZ prescribed): CONTACT's `igv` then
    /// holds the previous time's contact once the first height is solved, and the final grid is
    /// widened to it ([`widened`]); with the height given, one solve, to the contact before it.
    pub iterated: bool,
}

/// Whether two extents overlap in x and in y (CONTACT's `patches_have_overlap`; the grid sizes
/// are the case's for every patch).
fn overlap(a: &Extent, b: &Extent) -> bool {
    !(a.x_mm[1] < b.x_mm[0] || a.x_mm[0] > b.x_mm[1] || a.y_mm[1] < b.y_mm[0] || a.y_mm[0] > b.y_mm[1])
}

/// For each new patch's extent, the old patches it connects to, in their order
/// (`wr_connect_cps`).
pub fn connections(new: &[Extent], previous: &Previous) -> Vec<Vec<usize>> {
    new.iter()
        .map(|e| previous.patches.iter().enumerate().filter(|(_, o)| overlap(&o.extent, e)).map(|(k, _)| k).collect())
        .collect()
}

/// What the one new patch of extent `extent` inherits from the time before: [`inherited`] of its
/// [`connections`] (`merge_prev_potcon` for a single patch).
pub fn inherited_by(extent: Extent, previous: &Previous) -> Option<OldPatch> {
    inherited(&connections(&[extent], previous)[0], previous)
}

/// What a new patch connected to the old patches `links` inherits: the first of them with the
/// others merged into it (`gd_merge`: the grids' union, each one's tractions on it — zero outside
/// each one's contact, whose boxes do not overlap —, the contact boxes united); `None` when it
/// connects to none.
pub fn inherited(links: &[usize], previous: &Previous) -> Option<OldPatch> {
    let (&first, rest) = links.split_first()?;
    let mut tot = previous.patches[first].clone();
    for &k in rest {
        let add = &previous.patches[k];
        let grid = tot.grid.union(add.grid);
        let (mut px, mut py) = tot.on_box(grid);
        let (ax, ay) = add.on_box(grid);
        for (p, a) in px.iter_mut().zip(&ax).chain(py.iter_mut().zip(&ay)) {
            *p += a;
        }
        let or = |a: Vec<bool>, b: Vec<bool>| a.iter().zip(&b).map(|(x, y)| *x || *y).collect::<Vec<bool>>();
        let before = |o: &OldPatch| o.contact_before.as_ref().map(|m| mask_on(o.grid, m, grid));
        let contact_before = match (before(&tot), before(add)) {
            (Some(a), Some(b)) => Some(or(a, b)),
            (a, b) => a.or(b),
        };
        tot = OldPatch {
            extent: tot.extent,
            grid,
            px_mpa: px,
            py_mpa: py,
            contact: or(tot.contact_on(grid), add.contact_on(grid)),
            contact_before,
        };
    }
    Some(tot)
}

/// `grid` widened to cover the contact of the time before (`merge_prev_potcon`): the bounding box
/// of the grid and of CONTACT's `igv`, `old`'s contact at the step before its last (with the
/// height given; at trial heights after the first, `iterated`, its last contact), or of `old`'s
/// grid's first element where that is empty (after a step from rest).
pub fn widened(grid: &PatchGrid, old: &OldPatch, iterated: bool) -> PatchGrid {
    let igv = if iterated { Some(&old.contact) } else { old.contact_before.as_ref() };
    let tight = igv.and_then(|m| mask_box(old.grid, m)).unwrap_or_else(|| old.grid.first());
    let b = IndexBox::of_grid(grid).union(tight);
    let [ax, as_] = grid.anchor_mm;
    PatchGrid {
        mx: b.mx(),
        ms: b.ms(),
        x0_mm: ax + (b.x[0] as f64 - 0.5) * grid.dx_mm,
        s0_mm: as_ + (b.s[0] as f64 - 0.5) * grid.ds_mm,
        first_index: [b.x[0], b.s[0]],
        ..*grid
    }
}

/// `old`'s tractions on the elements of `grid` (CONTACT's element order), zero where `old`'s grid
/// does not reach.
pub fn on_grid(old: &OldPatch, grid: &PatchGrid) -> (Vec<f64>, Vec<f64>) {
    old.on_box(IndexBox::of_grid(grid))
}

/// The elements in contact (`pn_mpa` positive, CONTACT's order on the patch's grid).
pub fn contact_of(pn_mpa: &[f64]) -> Vec<bool> {
    pn_mpa.iter().map(|&p| p > 0.0).collect()
}

/// `old`'s contact on the elements of `grid` (none where `old`'s grid does not reach): the
/// contact the patch that continues it keeps as CONTACT's `igv`.
pub fn contact_on_grid(old: &OldPatch, grid: &PatchGrid) -> Vec<bool> {
    old.contact_on(IndexBox::of_grid(grid))
}

/// The patches the next case connects to: `new` (this case's), then the old patches no new one
/// connected to, kept for later (`wr_update_allcps`).
pub fn next(new: Vec<OldPatch>, previous: &Previous, links: &[Vec<usize>]) -> Previous {
    let used = |k: usize| links.iter().any(|l| l.contains(&k));
    let kept = previous.patches.iter().enumerate().filter(|(k, _)| !used(*k)).map(|(_, o)| o.clone());
    Previous { patches: new.into_iter().chain(kept).collect(), iterated: previous.iterated }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(first: [i64; 2], mx: usize, ms: usize) -> PatchGrid {
        let anchor_mm = [-3.0, 2.0];
        PatchGrid {
            mx,
            ms,
            dx_mm: 0.4,
            ds_mm: 0.4,
            x0_mm: anchor_mm[0] + (first[0] as f64 - 0.5) * 0.4,
            s0_mm: anchor_mm[1] + (first[1] as f64 - 0.5) * 0.4,
            anchor_mm,
            first_index: first,
        }
    }

    fn old(first: [i64; 2], mx: usize, ms: usize, y_mm: [f64; 2], value: f64) -> OldPatch {
        let g = grid(first, mx, ms);
        OldPatch {
            extent: Extent { x_mm: [-5.0, 5.0], y_mm, z_mm: [0.0, 0.0] },
            grid: IndexBox::of_grid(&g),
            px_mpa: vec![value; mx * ms],
            py_mpa: vec![-value; mx * ms],
            contact: vec![true; mx * ms],
            contact_before: None,
        }
    }

    #[test]
    fn a_widened_grid_reaches_the_old_grids_first_element_after_a_step_from_rest() {
        // t1_split_cp case 2, patch 1 (docs/wheelrail.md): x [−11.8, 5.4] × s [−15.8, 17.0]
        // (43 × 82 elements) widened to the old grid's first element (−12.2, −32.2): 44 × 123.
        let o = old([-30, -80], 50, 30, [0.0, 1.0], 1.0);
        let new = grid([-29, -39], 43, 82);
        let w = widened(&new, &o, false);
        assert_eq!((w.mx, w.ms, w.first_index), (44, 123, [-30, -80]));
        assert!((w.centre(0, 0).0 - new.centre(0, 0).0 + 0.4).abs() < 1e-12);
        assert!((w.centre(0, 0).1 - new.centre(0, 0).1 + 41.0 * 0.4).abs() < 1e-12);
        // The old tractions land on the same super-grid elements.
        let (px, py) = on_grid(&o, &w);
        assert_eq!((px[0], py[0]), (1.0, -1.0));
        assert_eq!(px[w.mx - 1], 1.0);
        assert_eq!(px[40 * w.mx], 0.0, "s index −40 lies beyond the old grid's last, −51");
    }

    #[test]
    fn two_old_patches_merge_onto_their_grids_union_and_an_unconnected_one_is_kept() {
        let previous = Previous {
            iterated: false,
            patches: vec![
                old([0, 0], 2, 2, [0.0, 1.0], 1.0),
                old([5, 4], 1, 1, [2.0, 3.0], 2.0),
                old([9, 9], 1, 1, [9.0, 9.5], 3.0),
            ],
        };
        let new = [Extent { x_mm: [-1.0, 1.0], y_mm: [0.5, 2.5], z_mm: [0.0; 2] }];
        let links = connections(&new, &previous);
        assert_eq!(links, vec![vec![0, 1]]);
        let m = inherited(&links[0], &previous).unwrap();
        assert_eq!(m.grid, IndexBox { x: [0, 5], s: [0, 4] });
        let (px, _) = m.on_box(m.grid);
        assert_eq!((px[0], px[m.grid.index(5, 4)], px[m.grid.index(3, 2)]), (1.0, 2.0, 0.0));
        let kept = next(vec![m], &previous, &links);
        assert_eq!(kept.patches.len(), 2);
        assert_eq!(kept.patches[1], previous.patches[2]);
    }
}
