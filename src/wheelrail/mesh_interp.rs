//! CONTACT's interpolation of a curvilinear mesh's heights to the points of a uniform grid
//! (`interp_cartz2unif`: `interp_wgt_surf2unif` finds each point's cell and its logical (u, v)
//! there, `compute_logical_uv`; then `interp_aply_surf2unif_1d`, bilinear, or
//! `interp_aply_surf2unif_1d_bicubic`, bicubic with the derivatives by differences over the
//! nodes' indices, central inside the mesh and one-sided at its edges).

use super::wheel_mesh::logical_uv;

/// Points x0 + i dx (fastest), y0 + j dy.
#[derive(Debug, Clone, Copy)]
pub struct Uniform {
    pub x0: f64,
    pub dx: f64,
    pub nx: usize,
    pub y0: f64,
    pub dy: f64,
    pub ny: usize,
}

/// The interpolation inside a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    Bilinear,
    Bicubic,
}

/// A mesh of nodes (x, y, f): `n_u` along its first index (fastest), rows after.
#[derive(Debug, Clone, Copy)]
pub struct Mesh<'a> {
    pub nodes: &'a [[f64; 3]],
    pub n_u: usize,
}

impl Mesh<'_> {
    fn n_v(&self) -> usize {
        self.nodes.len() / self.n_u
    }
    fn f(&self, p: usize, q: usize) -> f64 {
        self.nodes[q * self.n_u + p][2]
    }
    /// The difference quotient along u at node (p, q) over its neighbours.
    fn f_u(&self, p: usize, q: usize) -> f64 {
        let (lo, hi) = (p.saturating_sub(1), (p + 1).min(self.n_u - 1));
        (self.f(hi, q) - self.f(lo, q)) / (hi - lo) as f64
    }
    fn f_v(&self, p: usize, q: usize) -> f64 {
        let (lo, hi) = (q.saturating_sub(1), (q + 1).min(self.n_v() - 1));
        (self.f(p, hi) - self.f(p, lo)) / (hi - lo) as f64
    }
    fn f_uv(&self, p: usize, q: usize) -> f64 {
        let (lo, hi) = (q.saturating_sub(1), (q + 1).min(self.n_v() - 1));
        (self.f_u(p, hi) - self.f_u(p, lo)) / (hi - lo) as f64
    }

    /// The bicubic of cell (i, r) at its logical (u, v) (`interp_aply_surf2unif_1d_bicubic`).
    fn bicubic(&self, i: usize, r: usize, u: f64, v: f64) -> f64 {
        let (p, q) = ([i, i + 1], [r, r + 1]);
        let mut f = [[0.0; 4]; 4];
        for a in 0..2 {
            for b in 0..2 {
                f[a][b] = self.f(p[a], q[b]);
                f[a + 2][b] = self.f_u(p[a], q[b]);
                f[a][b + 2] = self.f_v(p[a], q[b]);
                f[a + 2][b + 2] = self.f_uv(p[a], q[b]);
            }
        }
        // Hermite basis: h0 = 1 − 3t² + 2t³, h1 = 3t² − 2t³, g0 = t − 2t² + t³, g1 = −t² + t³.
        let basis = |t: f64| {
            let (t2, t3) = (t * t, t * t * t);
            [1.0 - 3.0 * t2 + 2.0 * t3, 3.0 * t2 - 2.0 * t3, t - 2.0 * t2 + t3, t3 - t2]
        };
        let (bu, bv) = (basis(u), basis(v));
        (0..4).map(|a| (0..4).map(|b| bu[a] * f[a][b] * bv[b]).sum::<f64>()).sum()
    }
}

/// Where each point of a uniform grid lies in a mesh (`interp_wgt_surf2unif`): the cell (index
/// along u, row) and the point's logical (u, v) in it; `None` off the mesh.
#[derive(Debug, Clone, Default)]
pub struct Located {
    cells: Vec<Option<(usize, usize, f64, f64)>>,
}

/// The mesh's f at every point of `out`, from the first cell (u fastest, then rows) that holds
/// it on or inside its edges; `None` off the mesh.
pub fn interpolate(m: Mesh, out: &Uniform, scheme: Scheme) -> Vec<Option<f64>> {
    apply(m, &locate(m, out), scheme)
}

/// The mesh's f at the located points: bilinear or bicubic in each one's cell
/// (`interp_aply_surf2unif_1d`, `_bicubic`). The mesh's x and y must be those it was located on.
pub fn apply(m: Mesh, located: &Located, scheme: Scheme) -> Vec<Option<f64>> {
    let n_u = m.n_u;
    located
        .cells
        .iter()
        .map(|cell| {
            cell.map(|(i, r, u, v)| match scheme {
                Scheme::Bilinear => {
                    let k = [r * n_u + i, r * n_u + i + 1, (r + 1) * n_u + i + 1, (r + 1) * n_u + i];
                    let f = k.map(|k| m.nodes[k][2]);
                    (1.0 - u) * (1.0 - v) * f[0] + u * (1.0 - v) * f[1] + u * v * f[2] + (1.0 - u) * v * f[3]
                }
                Scheme::Bicubic => m.bicubic(i, r, u, v),
            })
        })
        .collect()
}

/// Each point of `out` located in the first cell (u fastest, then rows) that holds it on or
/// inside its edges (cells with a non-finite node or no area skipped).
pub fn locate(m: Mesh, out: &Uniform) -> Located {
    let mut cells = vec![None; out.nx * out.ny];
    let n_v = m.n_v();
    let xy = |k: usize| [m.nodes[k][0], m.nodes[k][1]];
    for r in 0..n_v.saturating_sub(1) {
        for i in 0..m.n_u.saturating_sub(1) {
            let k = [r * m.n_u + i, r * m.n_u + i + 1, (r + 1) * m.n_u + i + 1, (r + 1) * m.n_u + i];
            if k.iter().any(|&k| !m.nodes[k].iter().all(|v| v.is_finite())) {
                continue;
            }
            let c = k.map(xy);
            let area: f64 = (0..4).map(|e| c[e][0] * c[(e + 1) % 4][1] - c[(e + 1) % 4][0] * c[e][1]).sum();
            if area == 0.0 {
                continue;
            }
            let inside = |p: [f64; 2]| {
                (0..4).all(|e| {
                    let (a, b) = (c[e], c[(e + 1) % 4]);
                    area.signum() * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) >= 0.0
                })
            };
            let min = |a: [f64; 4]| a.iter().copied().fold(f64::MAX, f64::min);
            let max = |a: [f64; 4]| a.iter().copied().fold(f64::MIN, f64::max);
            let first = |v: f64, v0: f64, d: f64| ((v - v0) / d).ceil().max(0.0) as i64;
            let last = |v: f64, v0: f64, d: f64, n: usize| (((v - v0) / d).floor() as i64).min(n as i64 - 1);
            let (bx, by) = (c.map(|p| p[0]), c.map(|p| p[1]));
            for jj in first(min(by), out.y0, out.dy)..=last(max(by), out.y0, out.dy, out.ny) {
                for ii in first(min(bx), out.x0, out.dx)..=last(max(bx), out.x0, out.dx, out.nx) {
                    let e = jj as usize * out.nx + ii as usize;
                    let p = [out.x0 + ii as f64 * out.dx, out.y0 + jj as f64 * out.dy];
                    if cells[e].is_some() || !inside(p) {
                        continue;
                    }
                    let (u, v) = logical_uv(c[0], c[1], c[2], c[3], p);
                    cells[e] = Some((i, r, u, v));
                }
            }
        }
    }
    Located { cells }
}
