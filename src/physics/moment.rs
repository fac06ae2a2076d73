//! The moment about z of a tangential traction field, in the references' sign convention
//! (reference READMEs: `mz = Σ (x_C py − y px) dx dy` of the flipped tractions, `= −MZ` of CONTACT),
//! with CONTACT's `x_C = −x` of the grid ([`crate::physics::Grid`]).

use super::Grid;

/// One element's term `x_C ty − y tx` of [`moment_sum`] from the grid's `x` (`x_C = −x`) [MPa·mm].
#[inline(always)]
pub fn moment_term(x_mm: f64, y_mm: f64, tx: f64, ty: f64) -> f64 {
    -x_mm * ty - y_mm * tx
}

/// `Σ_k (x_C,k ty_k − y_k tx_k)` over the grid [MPa·mm]; times the element area it is the moment
/// in N·mm. Each row is summed in four interleaved partial sums (element i into sum i mod 4, so the
/// additions do not wait on each other), the rows in order: deterministic.
pub fn moment_sum(grid: &Grid, tx: &[f64], ty: &[f64]) -> f64 {
    let mut total = 0.0;
    for (j, &y) in grid.y_mm.iter().enumerate() {
        let row = j * grid.mx..(j + 1) * grid.mx;
        let (rx, ry) = (&tx[row.clone()], &ty[row]);
        let mut acc = [0.0f64; 4];
        let (xs, px, py) = (grid.x_mm.chunks_exact(4), rx.chunks_exact(4), ry.chunks_exact(4));
        let mut tail = 0.0;
        for ((&x, &px), &py) in xs.remainder().iter().zip(px.remainder()).zip(py.remainder()) {
            tail += moment_term(x, y, px, py);
        }
        for ((x, px), py) in xs.zip(px).zip(py) {
            for l in 0..4 {
                acc[l] += moment_term(x[l], y, px[l], py[l]);
            }
        }
        total += (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lateral_traction_ahead_of_the_centre_turns_positive() {
        // One element at grid x = −1.5 (x_C = +1.5, upstream half), y = 0.5 with ty = 2, tx = 3:
        // x_C ty − y tx = 3 − 1.5.
        let grid = Grid::new(2, 2, 3.0, 1.0);
        let k = grid.index(0, 1);
        let (mut tx, mut ty) = (vec![0.0; 4], vec![0.0; 4]);
        tx[k] = 3.0;
        ty[k] = 2.0;
        assert_eq!(moment_sum(&grid, &tx, &ty), 1.5 * 2.0 - 0.5 * 3.0);
    }
}
