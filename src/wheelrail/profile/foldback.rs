//! The part of a wheel profile that is a function of y (CONTACT's `prw_determine_foldback` in
//! `m_wr_locatecp.f90`, with MAXOMIT): from the point nearest the middle of the y-range, the
//! points are kept outwards while y keeps falling (towards the flange) or rising (towards the field
//! side) and the spline runs with dy/ds < 0; the rest (the back of the flange, a folded field side)
//! is left out, and more than MAXOMIT of the points left out is an error. CONTACT does this in the
//! contact search's view coordinates (the wheel rolled with the wheelset); here it is done in the
//! profile's own coordinates, the same for a wheelset without roll.

use super::{Profile, ProfileError, ProfileKind};
use std::ops::RangeInclusive;

impl Profile {
    /// The 0-based range of points CONTACT keeps of a wheel profile where it folds back (a rail is
    /// kept whole: CONTACT views it from above instead, as [`Profile::point_at_y`] does). Refused
    /// when more than MAXOMIT of the points would be left out (CONTACT's error -2102).
    pub fn uni_valued_range(&self) -> Result<RangeInclusive<usize>, ProfileError> {
        let (y, n) = (self.y_mm(), self.len());
        if self.kind() == ProfileKind::Rail {
            return Ok(0..=n - 1);
        }
        // dy/ds at each point, as CONTACT's spline_eval gives it: the slope of the segment
        // starting there (the last point: the end of the last segment).
        let dy_ds = &self.spline().y.a1;
        let (iymin, iymax) = (first_extreme(y, true), first_extreme(y, false));
        let ymid = (y[iymin] + y[iymax]) * 0.5;
        let mut imid = 0;
        for i in 1..n {
            if (y[i] - ymid).abs() < (y[imid] - ymid).abs() {
                imid = i;
            }
        }
        let mut end = imid;
        while end + 1 < n && y[end + 1] < y[end] && dy_ds[end + 1] < 0.0 {
            end += 1;
        }
        let mut start = imid;
        while start > 0 && y[start - 1] > y[start] && dy_ds[start - 1] < 0.0 {
            start -= 1;
        }
        let left_out = n - (end - start + 1);
        let allowed = (self.0.max_omit * n as f64).round() as usize;
        if left_out > allowed {
            return Err(ProfileError::profile(
                self.file(),
                "the points left out where the wheel profile folds back (y not descending)",
                format!("{left_out} of {n} (kept points {} to {})", start + 1, end + 1),
                format!("at most MAXOMIT = {} of the points, {allowed} (CONTACT's error -2102)", self.0.max_omit),
            ));
        }
        Ok(start..=end)
    }
}

/// The index of the first smallest (`pick_min`) or largest value.
fn first_extreme(v: &[f64], pick_min: bool) -> usize {
    let mut best = 0;
    for (k, &x) in v.iter().enumerate() {
        if (pick_min && x < v[best]) || (!pick_min && x > v[best]) {
            best = k;
        }
    }
    best
}
