//! The rectangular grid, the potential contact: the ellipse's bounding box (thesis App. B,
//! Eq. B.1–B.2), or `[grid] scale` times it (CONTACT's SCALE).
//!
//! Element (i, j), i = 0..mx along x (rolling direction), j = 0..my along y, flat index
//! `k = j*mx + i`, centre `x_i = −hx + dx/2 + i dx`, `y_j = −hy + dy/2 + j dy` with the grid's
//! half-extents hx, hy (a, b at scale 1). Material enters at the leading edge x = −hx and moves
//! in +x (the thesis's and the UBA's orientation). CONTACT's x (and the spin convention of the
//! outputs) runs the other way: `x_C = −x`, material entering at `x_C = +hx`; the conversion
//! happens in the rigid slip ([`crate::physics::RigidSlip`]), the x–y coupling of the influence
//! coefficients and the spin moment, nowhere else.

/// Where a row's integration starts (`[model] leading_edge`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LeadingEdge {
    /// The grid's own edge: the element upstream of a row's first loaded element carries zero
    /// traction, so that element gets one full element length of slip. This is the fixed point
    /// of the UBA's upwind scheme and what CONTACT's FASTSIM does on a grid (it reproduces
    /// CONTACT's `steady_fastsim_g22` to 1e-4).
    Grid,
    /// The ellipse's exact leading edge `x = −a √(1 − y²/b²)` of each row (Kalker's strip
    /// integration). For the UBA: a ghost value upstream, the exact linear profile at x − dx.
    Exact,
}

/// A grid of `mx × my` piecewise-constant elements covering `[−hx, hx] × [−hy, hy]` (or the
/// given edges, [`Grid::from_edges`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    pub mx: usize,
    pub my: usize,
    /// Half-extent hx along x [mm] (not the ellipse's semi-axis: `scale · a`).
    pub half_x_mm: f64,
    /// Half-extent hy along y [mm] (`scale · b`).
    pub half_y_mm: f64,
    pub dx_mm: f64,
    pub dy_mm: f64,
    /// Element centres along x [mm], `mx` values.
    pub x_mm: Vec<f64>,
    /// Element centres along y [mm], `my` values.
    pub y_mm: Vec<f64>,
}

impl Grid {
    /// The grid of thesis App. B over half-extents hx, hy: `dx = 2hx/mx`, `dy = 2hy/my`, centres
    /// at `−hx + dx/2 + k dx` (hx = a, hy = b: the ellipse's bounding box).
    pub fn new(mx: usize, my: usize, half_x_mm: f64, half_y_mm: f64) -> Self {
        Self::from_edges(mx, my, [-half_x_mm, half_x_mm], [-half_y_mm, half_y_mm])
    }

    /// A grid over `[x_lo, x_hi] × [y_lo, y_hi]` in grid coordinates (an explicitly given
    /// potential contact, CONTACT's IPOTCN = 1 with x mirrored: `[x_lo, x_hi] = [−x1_C, −x0_C]`):
    /// `dx = (x_hi − x_lo)/mx`, centres at `x_lo + dx/2 + i dx`.
    pub fn from_edges(mx: usize, my: usize, [x_lo, x_hi]: [f64; 2], [y_lo, y_hi]: [f64; 2]) -> Self {
        let dx_mm = (x_hi - x_lo) / mx as f64;
        let dy_mm = (y_hi - y_lo) / my as f64;
        let x_mm = (0..mx).map(|i| x_lo + dx_mm * (i as f64 + 0.5)).collect();
        let y_mm = (0..my).map(|j| y_lo + dy_mm * (j as f64 + 0.5)).collect();
        let (half_x_mm, half_y_mm) = (0.5 * (x_hi - x_lo), 0.5 * (y_hi - y_lo));
        Self { mx, my, half_x_mm, half_y_mm, dx_mm, dy_mm, x_mm, y_mm }
    }

    /// Whether element (i, j) lies on the grid's boundary.
    pub fn on_edge(&self, k: usize) -> bool {
        let (i, j) = (k % self.mx, k / self.mx);
        i == 0 || j == 0 || i + 1 == self.mx || j + 1 == self.my
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.mx * self.my
    }

    /// Always false for a valid grid (mx, my ≥ 1).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Element area [mm²].
    pub fn element_area_mm2(&self) -> f64 {
        self.dx_mm * self.dy_mm
    }

    /// Element centres in flat order `k = j*mx + i`: (x [mm], y [mm]).
    pub fn centres(&self) -> (Vec<f64>, Vec<f64>) {
        let x = (0..self.len()).map(|k| self.x_mm[k % self.mx]).collect();
        let y = (0..self.len()).map(|k| self.y_mm[k / self.mx]).collect();
        (x, y)
    }

    /// Flat index of element (i, j).
    #[inline]
    pub fn index(&self, i: usize, j: usize) -> usize {
        j * self.mx + i
    }

    /// `1 − (x/a)² − (y/b)²` at the centre of element (i, j) for an ellipse with semi-axes
    /// `a_mm`, `b_mm` (may differ from the grid's when the load varies); > 0 inside.
    #[inline]
    pub fn ellipse_level(&self, i: usize, j: usize, a_mm: f64, b_mm: f64) -> f64 {
        let (x, y) = (self.x_mm[i] / a_mm, self.y_mm[j] / b_mm);
        1.0 - x * x - y * y
    }

    /// Half-length of the ellipse chord at row j: `a √(1 − (y_j/b)²)` [mm], 0 outside.
    pub fn chord_half_length_mm(&self, j: usize, a_mm: f64, b_mm: f64) -> f64 {
        let t = 1.0 - (self.y_mm[j] / b_mm).powi(2);
        if t > 0.0 {
            a_mm * t.sqrt()
        } else {
            0.0
        }
    }
}
