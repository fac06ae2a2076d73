//! The influence coefficients of one element size, material, field-point offset and basis, kept
//! for the process by offset `(di, dj)`: a coefficient depends on its offset and not on the grid
//! it serves, so the table of the largest grid met holds every smaller grid's kernel (copied out
//! row by row, the same numbers as computed afresh). A wheel–rail deck meets tens of grid sizes
//! of one element size at its trial heights; each kernel is then a copy.

use std::sync::{Arc, Mutex};

/// What the coefficients depend on besides the offset (bit patterns: equal inputs, equal numbers).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Key {
    pub size_mm: [u64; 2],
    pub material: [u64; 2],
    pub offset_mm: [u64; 2],
    pub basis: u8,
    /// A viscoelastic relaxation's ratio and distance (`[0, 0]`: elastic).
    pub relax: [u64; 2],
}

/// Coefficients `[zz, xx, yy, xy]` at offsets `|di| ≤ hx`, `|dj| ≤ hy`, index
/// `(dj + hy)(2hx + 1) + di + hx`.
struct Table {
    key: Key,
    hx: usize,
    hy: usize,
    parts: [Vec<f64>; 4],
}

/// Tables kept (the oldest dropped first) and the largest kept [offsets]: a few MB in all.
const KEPT: usize = 8;
const LARGEST: usize = 1 << 17;

static TABLES: Mutex<Vec<Arc<Table>>> = Mutex::new(Vec::new());

impl Table {
    /// The table at offsets `|di| ≤ hx`, `|dj| ≤ hy`: the offsets `kept` (of the same key) holds
    /// copied from it, the others computed a row at a time by `row`.
    fn new(
        key: Key,
        hx: usize,
        hy: usize,
        kept: Option<&Table>,
        row: &impl Fn(isize, Offsets) -> Vec<[f64; 4]>,
    ) -> Table {
        let n = (2 * hx + 1) * (2 * hy + 1);
        let mut parts: [Vec<f64>; 4] = std::array::from_fn(|_| Vec::with_capacity(n));
        let (hx, hy) = (hx as isize, hy as isize);
        for dj in -hy..=hy {
            let held = kept.filter(|t| dj.unsigned_abs() <= t.hy).map_or(-1, |t| (t.hx as isize).min(hx));
            let mut values = Vec::with_capacity(2 * hx as usize + 1);
            if held < 0 {
                values = row(dj, -hx..=hx);
            } else if let Some(t) = kept {
                values.extend(row(dj, -hx..=-held - 1));
                let start = (dj + t.hy as isize) as usize * (2 * t.hx + 1) + (t.hx as isize - held) as usize;
                values.extend((start..=start + 2 * held as usize).map(|k| std::array::from_fn(|c| t.parts[c][k])));
                values.extend(row(dj, held + 1..=hx));
            }
            for v in values {
                for (part, v) in parts.iter_mut().zip(v) {
                    part.push(v);
                }
            }
        }
        Table { key, hx: hx as usize, hy: hy as usize, parts }
    }

    /// The kernel arrays of an `mx × my` grid (offsets `|di| < mx`, `|dj| < my`).
    fn cut(&self, mx: usize, my: usize) -> [Vec<f64>; 4] {
        let (row, nkx) = (2 * self.hx + 1, 2 * mx - 1);
        std::array::from_fn(|c| {
            let mut out = Vec::with_capacity(nkx * (2 * my - 1));
            for j in (self.hy + 1 - my)..=(self.hy + my - 1) {
                let start = j * row + self.hx + 1 - mx;
                out.extend_from_slice(&self.parts[c][start..start + nkx]);
            }
            out
        })
    }
}

/// The offsets `di` of one row of a table, ascending.
pub(super) type Offsets = std::ops::RangeInclusive<isize>;

/// The kernel arrays `[zz, xx, yy, xy]` of an `mx × my` grid, `row(dj, dis)` the coefficients of
/// the offsets `(di, dj)`, `di` in `dis` (each a function of its offset alone): from the kept table
/// of `key` where it covers the grid, else computed (and kept, grown to cover the grids met so
/// far, where it is not too large).
pub(super) fn kernel_parts(
    mx: usize,
    my: usize,
    key: Key,
    row: impl Fn(isize, Offsets) -> Vec<[f64; 4]>,
) -> [Vec<f64>; 4] {
    let kept = {
        let tables = TABLES.lock().unwrap_or_else(|e| e.into_inner());
        tables.iter().find(|t| t.key == key).cloned()
    };
    let (hx, hy) = (mx - 1, my - 1);
    if let Some(t) = kept.as_ref().filter(|t| t.hx >= hx && t.hy >= hy) {
        return t.cut(mx, my);
    }
    let (hx, hy) = kept.as_ref().map_or((hx, hy), |t| (t.hx.max(hx), t.hy.max(hy)));
    if (2 * hx + 1) * (2 * hy + 1) > LARGEST {
        return Table::new(key, mx - 1, my - 1, kept.as_deref(), &row).parts;
    }
    let table = Arc::new(Table::new(key, hx, hy, kept.as_deref(), &row));
    let parts = table.cut(mx, my);
    let mut tables = TABLES.lock().unwrap_or_else(|e| e.into_inner());
    tables.retain(|t| t.key != key);
    if tables.len() == KEPT {
        tables.remove(0);
    }
    tables.push(table);
    parts
}

#[cfg(test)]
mod tests {
    use super::super::influence::{rect_integrals, Kernel};

    #[test]
    fn a_kernel_cut_from_a_larger_grids_table_is_the_kernel_computed_afresh() {
        // An element size no other test uses: this test's tables alone.
        let (dx, dy, g, nu, shift) = (0.1237, 0.2411, 81000.0, 0.27, 0.1237);
        let small = Kernel::new(5, 7, dx, dy, g, nu, shift).unwrap();
        let large = Kernel::new(20, 30, dx, dy, g, nu, shift).unwrap();
        let again = Kernel::new(5, 7, dx, dy, g, nu, shift).unwrap();
        assert_eq!(small, again);
        // Each coefficient as the rectangle integrals give it, in both grids: the large grid's
        // rows partly copied from the small one's table, partly computed.
        let c = 1.0 / (std::f64::consts::PI * g);
        for (k, (mx, my)) in [(&small, (5isize, 7isize)), (&large, (20, 30))] {
            for dj in 1 - my..my {
                for di in 1 - mx..mx {
                    let r = rect_integrals(di as f64 * dx - shift, dj as f64 * dy, dx, dy);
                    let at = k.index(di, dj);
                    assert_eq!(k.zz[at], c * (1.0 - nu) * r.one_over_r, "{mx}x{my} ({di}, {dj})");
                    assert_eq!(k.xy[at], -c * nu * r.xy);
                }
            }
        }
    }
}
