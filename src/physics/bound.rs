//! The traction bound |τ| ≤ g = μ p (thesis Eq. 2.27, 3.11) and its direction-keeping
//! projections, written once for every solver.
//!
//! One policy for degenerate input, in every routine here: a traction is inside the bound only if
//! `τx² + τy² ≤ g²` holds (so a NaN traction or a NaN bound is outside; `g` is `μ p ≥ 0`), and a
//! traction that is outside is projected to zero when the bound is not positive (`g ≤ 0` or NaN)
//! or the traction's modulus is not finite (NaN, or an overflowing square).

/// Whether the traction (τx, τy) lies on or inside the disk of radius `g` (`τx² + τy² ≤ g²`).
#[inline(always)]
pub fn within_bound(tx: f64, ty: f64, g: f64) -> bool {
    tx * tx + ty * ty <= g * g
}

/// How close to the bound a traction counts as on it, relative: a projection onto the bound
/// leaves |τ| = g to a few roundings.
pub const ON_BOUND_REL: f64 = 1e-9;

/// Whether the traction (τx, τy) sits on the bound `g > 0` (an element that slips in a model that
/// projects onto the bound: |τ| ≥ (1 − [`ON_BOUND_REL`]) g).
#[inline]
pub fn on_bound(tx: f64, ty: f64, g: f64) -> bool {
    g > 0.0 && !within_bound(tx, ty, g * (1.0 - ON_BOUND_REL))
}

/// Project the traction (τx, τy) onto the disk of radius `g = μ p` keeping its direction
/// (thesis Eq. 2.29, written without the quadrant cases: τ ← g τ/|τ| when |τ| > g).
/// Returns the projected traction and whether the bound was active (the element slips).
#[inline]
pub fn project_to_bound(tx: f64, ty: f64, g: f64) -> (f64, f64, bool) {
    if within_bound(tx, ty, g) {
        (tx, ty, false)
    } else {
        let (x, y) = scale_to_bound(tx, ty, g);
        (x, y, true)
    }
}

/// Scale the traction (τx, τy) onto the circle `|τ| = g` keeping its direction: `g τ/|τ|`
/// (thesis Eq. 2.29 for an element known to slip). The zero traction has no direction and stays
/// zero; otherwise the module policy applies (zero for `g ≤ 0`, NaN `g` or a non-finite `|τ|`).
#[inline]
pub fn scale_to_bound(tx: f64, ty: f64, g: f64) -> (f64, f64) {
    let a = (tx * tx + ty * ty).sqrt();
    scale_by_factor(tx, ty, a, g, g / a)
}

/// [`scale_to_bound`] of a traction whose modulus `a` = |τ| and its reciprocal `inv_a` = 1/a
/// are known (where the caller has them): the factor g · inv_a in place of a division, its cases
/// as selects (lanes of elements vectorise: [`crate::solvers::brush`]'s falling bound).
#[inline(always)]
pub fn scale_with_reciprocal(tx: f64, ty: f64, (a, inv_a): (f64, f64), g: f64) -> (f64, f64) {
    scale_by_factor(tx, ty, a, g, g * inv_a)
}

/// The cases of [`scale_to_bound`] around its factor `s` = g/a: the zero traction stays, and
/// the result is zero for `g ≤ 0`, NaN `g` or a non-finite `a`.
#[inline(always)]
fn scale_by_factor(tx: f64, ty: f64, a: f64, g: f64, s: f64) -> (f64, f64) {
    let (x, y) = if a > 0.0 { (tx * s, ty * s) } else { (tx, ty) };
    if (g > 0.0) & a.is_finite() {
        (x, y)
    } else {
        (0.0, 0.0)
    }
}

/// The factor `min(1, g/|τ|)` that [`project_to_bound`] applies, written branch-free from
/// `|τ|² = n2` so that a grid-wide pass vectorises (the UBA's step). For finite tractions it gives
/// the same numbers as [`project_to_bound`] to the last bit; an unloaded element (g = 0) gets 0.
#[inline(always)]
pub fn bound_factor(n2: f64, g: f64) -> f64 {
    (g / n2.sqrt()).min(1.0)
}

/// The factor `g/|τ|` that [`scale_to_bound`] applies, written branch-free from `|τ|² = n2` (a
/// grid-wide pass vectorises; FaStrip's slip area): the zero traction gets 0. For finite
/// tractions and `g ≥ 0` it gives the same numbers as [`scale_to_bound`] to the last bit.
#[inline(always)]
pub fn scale_factor(n2: f64, g: f64) -> f64 {
    // Divided unconditionally, then selected: no branch in a vectorised loop.
    let f = g / n2.sqrt();
    if n2 > 0.0 {
        f
    } else {
        0.0
    }
}

/// Relative tolerance of [`falling_bound`]: iterations stop when a step changes g by at most
/// `FALLING_TOL · a` (a = |τ| of the unbounded traction).
pub const FALLING_TOL: f64 = 1e-12;

/// Iterations [`falling_bound`] may take (Newton, quadratic near the root; a bisection of the
/// bracket where a Newton step leaves it: 100 bisections narrow any bracket below `FALLING_TOL`).
const FALLING_MAX_ITER: usize = 100;

/// The friction coefficient at an iterate as a ratio, as the law and its memory give it without
/// dividing ([`crate::physics::law_kernel::LawKernel::update_ratio`]): μ = n/d and dμ/ds = m/d²,
/// d > 0 (d = 1 without memory).
pub type MuRatio = (f64, f64, f64);

/// The bound g of a slipping element whose coefficient falls with its own slip velocity: the
/// root in (0, a) of `h(g) = g − p μ(c (a − g))`, where a = |τ| of the unbounded traction, the
/// slip velocity of the projected traction is `s = c (a − g)` [mm/s] and `mu(s)` gives the
/// friction law's μ and dμ/ds ([`MuRatio`], with the memory's weight when there is one). The
/// element slips, so `h(a) = a − p μ(0) > 0`, and `h(0) = −p μ(c a) < 0`: a root exists and the
/// bracket keeps it. Newton from `g0` (h' = 1 + p c dμ/ds), a bisection where a step leaves the
/// bracket; it stops at an iterate whose Newton step would be at most `FALLING_TOL · a` (that
/// iterate is the result: the test needs no division), or after a step of at most that. With
/// several roots (a law steeper than 1/(p c)) it settles on one of them; the history's
/// oscillation flag watches the result. Returns g and the slip velocity c (a − g).
pub fn falling_bound(a: f64, p: f64, c: f64, g0: f64, mu: impl Fn(f64) -> MuRatio) -> (f64, f64) {
    let mut state = falling_start(a, g0);
    for _ in 0..FALLING_MAX_ITER {
        let at = mu(c * (a - state.2));
        let (residual, settled) = falling_test(state.2, (a, p, c), at);
        if settled {
            break;
        }
        let (next, done) = falling_step(state, a, (residual, at.1));
        state = next;
        if done {
            break;
        }
    }
    (state.2, c * (a - state.2))
}

/// [`falling_bound`] of L elements in step (lanes whose `active` is false are left alone and
/// return their start): each lane takes the iterates, the evaluations of `mu` and the result of
/// [`falling_bound`] on its own, bit for bit; `mu` evaluates L slip velocities at once. The
/// state is held per quantity (lo, hi, g of the lanes) and every choice of [`falling_step`] is a
/// select, so that the iteration compiles to vector instructions; an iteration in which every
/// lane settles ([`falling_test`]) divides nothing.
#[inline(always)]
pub fn falling_bound_lanes<const L: usize>(
    (a, p, c): ([f64; L], [f64; L], [f64; L]),
    g0: [f64; L],
    active: [bool; L],
    mu: impl Fn([f64; L]) -> ([f64; L], [f64; L], [f64; L]),
) -> [f64; L] {
    let (mut lo, mut hi, mut g) = ([0.0; L], a, [0.0; L]);
    let mut done = [false; L];
    for l in 0..L {
        g[l] = falling_start(a[l], g0[l]).2;
        done[l] = !active[l];
    }
    for _ in 0..FALLING_MAX_ITER {
        if done == [true; L] {
            break;
        }
        let s: [f64; L] = std::array::from_fn(|l| c[l] * (a[l] - g[l]));
        let (n, d, m) = mu(s);
        let mut residual = [(0.0, 0.0); L];
        for l in 0..L {
            let settled;
            (residual[l], settled) = falling_test(g[l], (a[l], p[l], c[l]), (n[l], d[l], m[l]));
            done[l] |= settled;
        }
        if done == [true; L] {
            break;
        }
        for l in 0..L {
            let ((lo_n, hi_n, g_n), stop) = falling_step((lo[l], hi[l], g[l]), a[l], (residual[l], d[l]));
            let keep = done[l];
            (lo[l], hi[l], g[l]) =
                (if keep { lo[l] } else { lo_n }, if keep { hi[l] } else { hi_n }, if keep { g[l] } else { g_n });
            done[l] = keep || stop;
        }
    }
    g
}

/// The bracket (0, a) and the start of [`falling_bound`]: `g0` where it lies inside, else a/2.
#[inline(always)]
fn falling_start(a: f64, g0: f64) -> (f64, f64, f64) {
    (0.0, a, if g0 > 0.0 && g0 < a { g0 } else { 0.5 * a })
}

/// At iterate g with the law's ratio (n, d, m) ([`MuRatio`]): h d = g d − p n and h' d² =
/// d² + p c m (the residual and the slope times d > 0 and d²: no division), and whether g is
/// settled: a root (h = 0), or a Newton step h/h' = (h d) d/(h' d²) of at most `FALLING_TOL · a`.
#[inline(always)]
fn falling_test(g: f64, (a, p, c): (f64, f64, f64), (n, d, m): MuRatio) -> ((f64, f64), bool) {
    let (hd, slope) = (g * d - p * n, d * d + p * c * m);
    let small = (slope > 0.0) & ((hd * d).abs() <= FALLING_TOL * a * slope);
    ((hd, slope), (hd == 0.0) | small)
}

/// One iteration of [`falling_bound`] from the bracket and iterate (lo, hi, g) with the
/// residual and slope of [`falling_test`] and the ratio's d: the next (lo, hi, g) and whether
/// the step taken was at most `FALLING_TOL · a`. Every choice is a select (no early return), so
/// that [`falling_bound_lanes`] compiles it to vector instructions.
#[inline(always)]
fn falling_step((lo, hi, g): (f64, f64, f64), a: f64, ((hd, slope), d): ((f64, f64), f64)) -> ((f64, f64, f64), bool) {
    let below = hd < 0.0;
    let (lo_n, hi_n) = (if below { g } else { lo }, if below { hi } else { g });
    let newton = g - hd * d / slope;
    let take = slope > 0.0 && newton > lo_n && newton < hi_n;
    let next = if take { newton } else { 0.5 * (lo_n + hi_n) };
    ((lo_n, hi_n, next), (next - g).abs() <= FALLING_TOL * a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_direction_and_clips_modulus() {
        let (x, y, slip) = project_to_bound(3.0, -4.0, 2.5);
        assert!(slip);
        assert!(((x * x + y * y).sqrt() - 2.5).abs() < 1e-12);
        assert!((y / x - (-4.0 / 3.0)).abs() < 1e-12);
        assert_eq!(project_to_bound(0.3, 0.4, 1.0), (0.3, 0.4, false));
        assert_eq!(project_to_bound(1.0, 0.0, 0.0), (0.0, 0.0, true));
    }

    #[test]
    fn branch_free_factor_matches_the_projection() {
        let mut x = 0.3f64;
        for _ in 0..1000 {
            // A simple deterministic sequence of tractions and bounds over many magnitudes.
            x = (x * 3.7 + 0.11).fract();
            let (tx, ty, g) = ((x - 0.5) * 1e3, (0.5 - x * x) * 7e2, x * 400.0);
            let f = bound_factor(tx * tx + ty * ty, g);
            let (px, py, _) = project_to_bound(tx, ty, g);
            assert_eq!((tx * f, ty * f), (px, py), "{tx} {ty} {g}");
        }
        assert_eq!(bound_factor(4.0, 0.0), 0.0);
    }

    #[test]
    fn branch_free_scale_matches_scale_to_bound() {
        let mut x = 0.7f64;
        for _ in 0..1000 {
            x = (x * 3.7 + 0.13).fract();
            let (tx, ty, g) = ((x - 0.5) * 1e3, (0.5 - x * x) * 7e2, x * 400.0);
            let f = scale_factor(tx * tx + ty * ty, g);
            assert_eq!((tx * f, ty * f), scale_to_bound(tx, ty, g), "{tx} {ty} {g}");
        }
        assert_eq!(scale_factor(0.0, 2.0), 0.0);
        assert_eq!(scale_factor(4.0, 0.0), 0.0);
    }

    #[test]
    fn one_policy_for_degenerate_input() {
        assert_eq!(project_to_bound(0.0, 0.0, 0.0), (0.0, 0.0, false));
        assert_eq!(project_to_bound(f64::NAN, 1.0, 2.0), (0.0, 0.0, true));
        assert_eq!(project_to_bound(1.0, 1.0, f64::NAN), (0.0, 0.0, true));
        assert_eq!(project_to_bound(1e300, -1e300, 2.0), (0.0, 0.0, true));
        assert_eq!(project_to_bound(2.0, 0.0, -1.0), (0.0, 0.0, true));
        assert_eq!(scale_to_bound(0.0, 0.0, 2.0), (0.0, 0.0));
        assert_eq!(scale_to_bound(0.5, 0.0, 2.0), (2.0, 0.0));
        assert_eq!(scale_to_bound(0.5, 0.0, 0.0), (0.0, 0.0));
        assert_eq!(scale_to_bound(f64::NAN, 0.0, 1.0), (0.0, 0.0));
    }

    /// The projection scales by `g / sqrt(τx² + τy²)`: the arithmetic every solver used before.
    #[test]
    fn scale_factor_is_g_over_the_modulus() {
        let (tx, ty, g): (f64, f64, f64) = (0.7310, -1.913, 0.3127);
        let s = g / (tx * tx + ty * ty).sqrt();
        assert_eq!(project_to_bound(tx, ty, g), (tx * s, ty * s, true));
        assert_eq!(scale_to_bound(0.1 * tx, 0.1 * ty, g), {
            let s = g / ((0.1 * tx) * (0.1 * tx) + (0.1 * ty) * (0.1 * ty)).sqrt();
            (0.1 * tx * s, 0.1 * ty * s)
        });
    }
    /// The falling bound solves g = p μ(c (a − g)): a linear law by hand, and the residual of an
    /// exponential one below the tolerance.
    #[test]
    fn falling_bound_is_the_fixed_point() {
        // μ(s) = 0.4 − 1e-4 s, p = 1, c = 1000, a = 1: g = 0.4 − 0.1 (1 − g) → g = 0.3/0.9.
        let (g, s) = falling_bound(1.0, 1.0, 1000.0, 0.0, |s| (0.4 - 1e-4 * s, 1.0, -1e-4));
        assert!((g - 1.0 / 3.0).abs() < 1e-12, "{g}");
        assert!((s - 2000.0 / 3.0).abs() < 1e-8, "{s}");
        let k = std::f64::consts::LN_2 / 600.0;
        let mu = |s: f64| 0.25 + 0.2 * (-k * s).exp();
        let (a, p, c) = (900.0, 1500.0, 3.0);
        let (g, s) = falling_bound(a, p, c, 0.0, |s| (mu(s), 1.0, -k * 0.2 * (-k * s).exp()));
        assert!(g > 0.0 && g < a);
        assert!((g - p * mu(s)).abs() <= 1e-9 * a, "residual {}", g - p * mu(s));
        assert!((s - c * (a - g)).abs() < 1e-9);
    }

    /// Four lanes in step give each lane's [`falling_bound`] bit for bit (lanes that converge
    /// after different numbers of iterations, one that starts outside the bracket, one inactive).
    #[test]
    fn four_lanes_are_four_falling_bounds() {
        let k = std::f64::consts::LN_2 / 600.0;
        // With a memory's denominator d ≠ 1: μ = n/d, dμ/ds = m/d².
        let law = |s: f64| {
            let d = 1.0 + 1e-3 * s;
            (d * (0.25 + 0.2 * (-k * s).exp()), d, d * d * (-k * 0.2 * (-k * s).exp()))
        };
        let a = [900.0, 450.0, 1200.0, 700.0];
        let p = [1500.0, 800.0, 1900.0, 1000.0];
        let c = [3.0, 0.5, 40.0, 2.0];
        let g0 = [600.0, 0.0, 1190.0, 300.0];
        let got = falling_bound_lanes((a, p, c), g0, [true, true, true, false], |s| {
            let r = s.map(law);
            (r.map(|x| x.0), r.map(|x| x.1), r.map(|x| x.2))
        });
        for l in 0..3 {
            assert_eq!(got[l], falling_bound(a[l], p[l], c[l], g0[l], law).0, "lane {l}");
        }
        assert_eq!(got[3], 300.0);
    }
}
