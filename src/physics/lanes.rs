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

/// Σ term(k) over `k` in `0..n` in the four-lane order (the terms computed on the fly).
#[inline(always)]
pub fn sum_by(n: usize, term: impl Fn(usize) -> f64) -> f64 {
    sums2_by(n, |k| (term(k), 0.0)).0
}

/// Two sums over `k` in `0..n` of the pairs `term(k)`, each in the four-lane order, in one pass.
#[inline(always)]
pub fn sums2_by(n: usize, term: impl Fn(usize) -> (f64, f64)) -> (f64, f64) {
    let (mut a, mut b) = ([0.0f64; 4], [0.0f64; 4]);
    let body = n - n % 4;
    for c in (0..body).step_by(4) {
        for l in 0..4 {
            let (x, y) = term(c + l);
            a[l] += x;
            b[l] += y;
        }
    }
    let (mut ta, mut tb) = (0.0, 0.0);
    for k in body..n {
        let (x, y) = term(k);
        ta += x;
        tb += y;
    }
    (combine(a, ta), combine(b, tb))
}

/// The largest of non-negative values (0 for none), in four lanes: a maximum is exact in any
/// order, and the lanes vectorise where a running maximum would wait on every comparison.
#[inline(always)]
pub fn max4(v: &[f64]) -> f64 {
    let larger = |a: f64, b: f64| if b > a { b } else { a };
    let mut m = [0.0f64; 4];
    let chunks = v.chunks_exact(4);
    let tail = chunks.remainder().iter().fold(0.0f64, |a, &b| larger(a, b));
    for c in chunks {
        for l in 0..4 {
            m[l] = larger(m[l], c[l]);
        }
    }
    m.iter().fold(tail, |a, &b| larger(a, b))
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
        let w: Vec<f64> = v.iter().map(|x| 0.5 * x).collect();
        let (a, b) = sums2_by(v.len(), |m| (v[m], w[m]));
        assert_eq!(a, sum4(&v));
        assert_eq!(b, sum4(&w));
        assert_eq!(sum_by(v.len(), |m| v[m]), sum4(&v));
        let abs: Vec<f64> = v.iter().map(|x| x.abs()).collect();
        assert_eq!(max4(&abs), abs.iter().fold(0.0f64, |m, &x| m.max(x)));
        assert_eq!(max4(&[]), 0.0);
    }
}
