//! Rolling the other way along x (`[rolling] chi_deg = 180`, CONTACT's CHI = 180°): the problem
//! mirrored about x = 0 is the default direction's (CONTACT `m_sdis.f90`: the shift by
//! `dq cos CHI`, the spin offset `cos CHI · dq/6`). Under x → −x the tractions and slips map
//! `(px, py) → (−px, py)`, the rigid slip `(cx − cs y, cy + cs x)` maps to creepages `(−cx, cy, −cs)`,
//! the totals `(Fx, Fy, Mz) → (−Fx, Fy, −Mz)`; the solver works in the mirrored frame, these
//! helpers carry samples and fields across.

use crate::problem::Sample;

/// Element `k` of the mirror of an `mx`-wide grid (`i → mx − 1 − i` in each row).
fn mirrored_index(mx: usize, k: usize) -> usize {
    let (j, i) = (k / mx, k % mx);
    j * mx + (mx - 1 - i)
}

/// A per-element field seen in the mirrored frame (the same map undoes itself).
pub fn field<T: Copy>(mx: usize, v: &[T]) -> Vec<T> {
    (0..v.len()).map(|k| v[mirrored_index(mx, k)]).collect()
}

/// A per-element field of x components in the mirrored frame (mirrored and negated).
pub fn field_x(mx: usize, v: &[f64]) -> Vec<f64> {
    (0..v.len()).map(|k| -v[mirrored_index(mx, k)]).collect()
}

/// The sample in the mirrored frame: cx, cs and a prescribed Fx/FN change sign.
pub fn sample(s: &Sample) -> Sample {
    Sample { cx: -s.cx, cs: -s.cs, fx_target: s.fx_target.map(|f| -f), ..*s }
}

/// Creepages found under prescribed forces, back from the mirrored frame.
pub fn found(c: [f64; 2]) -> [f64; 2] {
    [-c[0], c[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mirror_reverses_each_row_and_undoes_itself() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(field(3, &v), vec![3.0, 2.0, 1.0, 6.0, 5.0, 4.0]);
        assert_eq!(field_x(3, &v), vec![-3.0, -2.0, -1.0, -6.0, -5.0, -4.0]);
        assert_eq!(field(3, &field(3, &v)), v.to_vec());
    }
}
