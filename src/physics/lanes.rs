//! Sums in four lanes: element `m` of a flat array goes into partial sum `m mod 4`, the lanes are
//! combined as `(s0 + s1) + (s2 + s3)` and the last `len mod 4` elements are added in order. A
//! fixed order (deterministic, independent of the CPU), yet one vector addition per four elements
//! where a single running sum would wait on every addition (the UBA's pass keeps its lanes in
//! one register, `solvers/uba/flat.rs`).

/// Σ v in the four-lane order.
#[inline]
pub fn sum4(v: &[f64]) -> f64 {
    let mut acc = [0.0f64; 4];
    let chunks = v.chunks_exact(4);
    let tail: f64 = chunks.remainder().iter().sum();
    for c in chunks {
        for l in 0..4 {
            acc[l] += c[l];
        }
    }
    combine(acc, tail)
}

/// The lanes combined with the in-order sum of the tail: `(s0 + s1) + (s2 + s3) + tail`.
#[inline(always)]
pub fn combine(acc: [f64; 4], tail: f64) -> f64 {
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_follow_the_element_order() {
        // Magnitudes far apart, so that another order of the additions would give other bits.
        let v: Vec<f64> = (0..4 * 9 + 3).map(|m| (m as f64 * 0.7).sin() * 10f64.powi(m % 7 - 3)).collect();
        let mut lanes = [0.0f64; 4];
        for m in 0..36 {
            lanes[m % 4] += v[m];
        }
        let tail = (v[36] + v[37]) + v[38];
        assert_eq!(sum4(&v), (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]) + tail);
        assert_ne!(sum4(&v), v.iter().sum::<f64>(), "a data set where the order shows");
    }
}
