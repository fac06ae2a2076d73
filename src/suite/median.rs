//! The median of repeated measurements with a distribution-free confidence interval from order
//! statistics (Conover, Practical Nonparametric Statistics, 3rd ed., 1999, §3.2; David &
//! Nagaraja, Order Statistics, 3rd ed., 2003, §7.1): for n independent samples of any
//! continuous distribution, [x₍k₎, x₍n+1−k₎] holds the median with probability
//! P(k ≤ B ≤ n − k), B ~ Binomial(n, ½).

use statrs::distribution::{Binomial, DiscreteCDF};

/// The confidence the interval is asked for.
pub const CONFIDENCE: f64 = 0.95;

/// Fewest samples for which [`CONFIDENCE`] is reachable ([x₍₁₎, x₍₆₎] covers 1 − 2/2⁶ = 0.969;
/// with five, [x₍₁₎, x₍₅₎] covers only 0.9375).
pub const MIN_SAMPLES: usize = 6;

/// The median of some samples with its interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MedianInterval {
    pub n: usize,
    pub median: f64,
    /// [x₍k₎, x₍n+1−k₎] and its coverage; None with fewer than [`MIN_SAMPLES`] samples.
    pub interval: Option<(f64, f64)>,
    pub coverage: Option<f64>,
}

/// P(x₍k₎ ≤ median ≤ x₍n+1−k₎) for n samples = P(k ≤ B ≤ n − k), B ~ Binomial(n, ½) (1-based k).
pub fn coverage(n: usize, k: usize) -> f64 {
    if k == 0 || 2 * k > n {
        return 0.0;
    }
    let b = Binomial::new(0.5, n as u64).expect("p = 0.5 is a probability");
    b.cdf((n - k) as u64) - b.cdf((k - 1) as u64)
}

/// The largest k whose interval [x₍k₎, x₍n+1−k₎] covers the median with at least `confidence`
/// (the narrowest symmetric one), with its coverage.
pub fn order_statistic(n: usize, confidence: f64) -> Option<(usize, f64)> {
    (1..=n / 2).rev().map(|k| (k, coverage(n, k))).find(|&(_, c)| c >= confidence)
}

/// The median of the finite `samples` and its [`CONFIDENCE`] interval (None when none is finite).
pub fn median_interval(samples: &[f64]) -> Option<MedianInterval> {
    let mut x: Vec<f64> = samples.iter().copied().filter(|v| v.is_finite()).collect();
    if x.is_empty() {
        return None;
    }
    x.sort_by(f64::total_cmp);
    let n = x.len();
    let median = if n % 2 == 1 { x[n / 2] } else { 0.5 * (x[n / 2 - 1] + x[n / 2]) };
    let found = order_statistic(n, CONFIDENCE);
    Some(MedianInterval {
        n,
        median,
        interval: found.map(|(k, _)| (x[k - 1], x[n - k])),
        coverage: found.map(|(_, c)| c),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coverage against the closed form Σ C(n, i) / 2ⁿ over k ≤ i ≤ n − k, counted by hand.
    #[test]
    fn coverage_is_the_binomial_sum() {
        assert!((coverage(6, 1) - (1.0 - 2.0 / 64.0)).abs() < 1e-12);
        assert!((coverage(5, 1) - (1.0 - 2.0 / 32.0)).abs() < 1e-12);
        // n = 9, k = 2: 1 − 2 (1 + 9) / 512.
        assert!((coverage(9, 2) - (1.0 - 20.0 / 512.0)).abs() < 1e-12);
        // n = 20, k = 6: 1 − 2 (1 + 20 + 190 + 1140 + 4845 + 15504) / 2²⁰.
        assert!((coverage(20, 6) - (1.0 - 2.0 * 21700.0 / 1048576.0)).abs() < 1e-12);
        assert_eq!(coverage(4, 3), 0.0);
    }

    #[test]
    fn the_narrowest_interval_of_at_least_95_percent() {
        assert_eq!(order_statistic(5, CONFIDENCE), None);
        assert_eq!(order_statistic(6, CONFIDENCE).map(|f| f.0), Some(1));
        assert_eq!(order_statistic(8, CONFIDENCE).map(|f| f.0), Some(1)); // k = 2: 1 − 18/256 = 0.93
        assert_eq!(order_statistic(9, CONFIDENCE).map(|f| f.0), Some(2));
        // n = 20: k = 7 covers 1 − 2·60460/2²⁰ = 0.885, too little; k = 6 covers 0.959.
        assert_eq!(order_statistic(20, CONFIDENCE).map(|f| f.0), Some(6));
    }

    #[test]
    fn median_and_interval_of_samples() {
        let m = median_interval(&[5.0, 1.0, 4.0, 2.0, 3.0, 9.0, 8.0, 7.0, 6.0]).unwrap();
        assert_eq!((m.n, m.median, m.interval), (9, 5.0, Some((2.0, 8.0))));
        let m = median_interval(&[4.0, 1.0, 3.0, 2.0, f64::NAN, 6.0, 5.0]).unwrap();
        assert_eq!((m.n, m.median, m.interval), (6, 3.5, Some((1.0, 6.0))));
        let few = median_interval(&[3.0, 1.0, 2.0]).unwrap();
        assert_eq!((few.median, few.interval, few.coverage), (2.0, None, None));
        assert_eq!(median_interval(&[f64::NAN]), None);
    }

    /// The stated coverage is what sampling gives: 20 000 sets of 9 uniform samples (a fixed
    /// linear congruential sequence), the median ½ inside [x₍₂₎, x₍₈₎] in 96.1 % ± 0.4 % of them.
    #[test]
    fn stated_coverage_holds_by_sampling() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let trials = 20_000;
        let mut hit = 0;
        for _ in 0..trials {
            let x: Vec<f64> = (0..9).map(|_| next()).collect();
            let (lo, hi) = median_interval(&x).unwrap().interval.unwrap();
            hit += usize::from(lo <= 0.5 && 0.5 <= hi);
        }
        let rate = hit as f64 / trials as f64;
        assert!((rate - coverage(9, 2)).abs() < 0.004, "{rate}");
    }
}
