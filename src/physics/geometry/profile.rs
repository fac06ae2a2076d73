//! A lateral gap profile g(y), linear between its points, and the undeformed distance
//! `h(x, y) = a1 x² + g(y)` it gives at the element centres (CONTACT's non-Hertzian reference
//! cases: a1 = 1/(2R) for a wheel of rolling radius R on a straight rail).

use crate::physics::Grid;

/// Points (y [mm], g [mm]) with strictly increasing y (checked where the profile is read).
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    pub y_mm: Vec<f64>,
    pub g_mm: Vec<f64>,
}

impl Profile {
    /// g at y, linear between the two points around it; `None` outside the profile.
    pub fn at(&self, y_mm: f64) -> Option<f64> {
        let (ys, gs) = (&self.y_mm, &self.g_mm);
        if !(ys.first()? <= &y_mm && &y_mm <= ys.last()?) {
            return None;
        }
        let k = ys.partition_point(|&v| v <= y_mm).clamp(1, ys.len() - 1);
        let t = (y_mm - ys[k - 1]) / (ys[k] - ys[k - 1]);
        Some(gs[k - 1] + t * (gs[k] - gs[k - 1]))
    }

    /// Whether the profile covers every element centre of the grid.
    pub fn covers(&self, grid: &Grid) -> bool {
        grid.y_mm.iter().all(|&y| self.at(y).is_some())
    }

    /// `a1 x² + g(y)` at every element centre, flat order (0 where the profile does not reach,
    /// which [`Profile::covers`] rules out first).
    pub fn undeformed_distance_mm(&self, grid: &Grid, a1_per_mm: f64) -> Vec<f64> {
        let (x, y) = grid.centres();
        x.iter().zip(&y).map(|(x, y)| a1_per_mm * x * x + self.at(*y).unwrap_or(0.0)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_between_points_and_none_outside() {
        let p = Profile { y_mm: vec![-2.0, 0.0, 4.0], g_mm: vec![1.0, 0.0, 2.0] };
        assert_eq!(p.at(-2.0), Some(1.0));
        assert_eq!(p.at(-1.0), Some(0.5));
        assert_eq!(p.at(1.0), Some(0.5));
        assert_eq!(p.at(4.0), Some(2.0));
        assert_eq!(p.at(4.5), None);
        assert_eq!(p.at(-2.1), None);
    }
}
