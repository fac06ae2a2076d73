//! Which spline segments can hold a lateral position y: the profile's y-range cut into equal
//! buckets, each listing (ascending) the segments whose y-range meets it, so that a search by y
//! visits a few segments, in the same order as a scan over all of them.

/// The segments per bucket of y, stored flat (`starts[k]..starts[k + 1]` into `items`).
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentIndex {
    y0_mm: f64,
    width_mm: f64,
    starts: Vec<usize>,
    items: Vec<usize>,
}

impl SegmentIndex {
    /// The index of the segments' y-ranges `(lo, hi)`, one bucket per segment.
    pub fn new(segment_y: &[(f64, f64)]) -> SegmentIndex {
        let (lo, hi) =
            segment_y.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &(a, b)| (l.min(a), h.max(b)));
        let buckets = segment_y.len().max(1);
        let width_mm = if hi > lo { (hi - lo) / buckets as f64 } else { 1.0 };
        let mut index = SegmentIndex { y0_mm: lo, width_mm, starts: vec![0; buckets + 1], items: Vec::new() };
        // One bucket more on each side than the ends' own: a margin against rounding.
        let span = |&(a, b): &(f64, f64)| (index.bucket(a).saturating_sub(1), (index.bucket(b) + 1).min(buckets - 1));
        let spans: Vec<(usize, usize)> = segment_y.iter().map(span).collect();
        // Counted first, then filled in segment order: each bucket's list ascending.
        for &(first, last) in &spans {
            for k in first..=last {
                index.starts[k + 1] += 1;
            }
        }
        for k in 0..buckets {
            index.starts[k + 1] += index.starts[k];
        }
        let mut next = index.starts[..buckets].to_vec();
        index.items = vec![0; index.starts[buckets]];
        for (i, &(first, last)) in spans.iter().enumerate() {
            for slot in &mut next[first..=last] {
                index.items[*slot] = i;
                *slot += 1;
            }
        }
        index
    }

    /// The bucket of `y_mm` (the nearest end one outside the range).
    fn bucket(&self, y_mm: f64) -> usize {
        let k = ((y_mm - self.y0_mm) / self.width_mm).floor();
        if k >= 0.0 {
            (k as usize).min(self.starts.len() - 2)
        } else {
            0
        }
    }

    /// The segments whose y-range may hold `y_mm`, ascending (a superset of those that do).
    pub fn candidates(&self, y_mm: f64) -> &[usize] {
        let k = self.bucket(y_mm);
        &self.items[self.starts[k]..self.starts[k + 1]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_segment_holding_y_is_a_candidate_in_order() {
        // Overlapping ranges, one folding back over the others.
        let ranges = [(0.0, 1.0), (1.0, 2.5), (2.5, 2.6), (0.5, 2.55), (2.6, 4.0)];
        let index = SegmentIndex::new(&ranges);
        for k in 0..=400 {
            let y = -0.5 + 5.0 * k as f64 / 400.0;
            let holding: Vec<usize> = (0..ranges.len()).filter(|&i| ranges[i].0 <= y && y <= ranges[i].1).collect();
            let c = index.candidates(y);
            assert!(c.windows(2).all(|w| w[0] < w[1]), "ascending at {y}");
            assert!(holding.iter().all(|i| c.contains(i)), "y = {y}: {holding:?} in {c:?}");
        }
    }
}
