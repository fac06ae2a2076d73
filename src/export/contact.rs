//! A resolved scene as CONTACT module-3 input (issue 15), so that a user with CONTACT can make
//! reference data for a scene of their own: one CONTACT case per history row, with the control
//! digits and case structure of `reference/contact/README.contact.md` ("How the time histories are
//! formed"): a steady sweep is one steady case (T = 3) per point; a transient history starts a
//! sequence (P = 2) with its steady start (T = 3, step 0) or its first step (T = 2), then one
//! transient case (P = 0, T = 2) per step. Exact theory, Coulomb friction FSTAT = FKIN = μ (read
//! again, L = 0, in a case whose μ changed), FN prescribed (N = 1), both bodies of the scene's
//! material, rolling in CONTACT's +x (CHI = 0) with DQ = courant·dx (CONTACT solves a steady case
//! with DQ = DX and keeps it: after a steady start at another DQ the first transient case gives DQ
//! again).
//!
//! Geometry (first case): Hertz's ellipse as IPOTCN = −3 (AA, BB, SCALE) when the load is constant;
//! when the load changes within the history, the ellipse's fixed curvatures h = A1 x² + B1 y² on the
//! fixed grid (IPOTCN = 1, IBASE = 1), as this project's solvers keep the geometry; a geometry given
//! per element as IPOTCN = 1 with its grid and IBASE = 9, h per element in CONTACT's order.
//! Signs: cx, cy, cs are CKSI, CETA, CPHI as they are (this project uses CONTACT's convention).

use crate::problem::{LoadingKind, Problem, Sample};
use std::fmt::Write;

/// Values per line of an element-wise undeformed distance.
const PER_LINE: usize = 6;
/// A relative change of μ below this between two cases is rounding, not a new friction.
const MU_CHANGE_REL: f64 = 1e-9;

/// The CONTACT input that computes the problem's history, one case per row.
pub fn module3_input(p: &Problem) -> String {
    let rows: Vec<&Sample> = p.loading.rows().collect();
    let steady_start = p.loading.steady_start().is_some();
    let sweep = p.loading.kind == LoadingKind::Sweep;
    let load_varies = rows.iter().any(|s| s.fn_n != rows[0].fn_n);
    let mut out = format!(
        "%\n% CONTACT input written by creepbench for scene \"{}\" ({} cases, one per history row).\n%\n",
        p.name,
        rows.len()
    );
    let mut prev_mu = f64::NAN;
    for (n, s) in rows.iter().enumerate() {
        let first = n == 0;
        let steady = sweep || (steady_start && first);
        let new_sequence = sweep || first;
        // A table's μ interpolated at a row's printed time may differ from the row by rounding:
        // read again only a μ that changed beyond that.
        let read_mu = first || (s.mu - prev_mu).abs() > MU_CHANGE_REL * prev_mu.abs();
        if read_mu {
            prev_mu = s.mu;
        }
        let _ = writeln!(out, "\n 3  MODULE      % step {}, t={} s", s.step, s.t_s);
        let (pv, t) = (if new_sequence { 2 } else { 0 }, if steady { 3 } else { 2 });
        // F = 1: Fx prescribed with CETA given, F = 2: Fx and Fy (the scene refuses Fy alone).
        let f = usize::from(s.fx_target.is_some()) + usize::from(s.fy_target.is_some());
        let _ = writeln!(out, "  {pv}0{t}1{f}0      P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS");
        // CONTACT solves the steady start with DQ = DX and keeps that DQ for the cases that follow
        // (`m_sdis.f90`): where the scene's DQ is another, the first transient case gives it again
        // (C = 2: kinematics and material read again, influence coefficients recomputed).
        let dq_again = steady_start && n == 1 && p.rolling.dq_mm != p.grid.dx_mm;
        let ldc = match (first, dq_again) {
            (true, _) => "022020".to_string(),
            (false, again) => format!("{}0{}000", if read_mu { 0 } else { 1 }, if again { 2 } else { 0 }),
        };
        let _ = writeln!(out, "  {ldc}      L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS");
        let _ = writeln!(
            out,
            " 00{}2211    H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN",
            if first { 0 } else { 1 }
        );
        let _ = writeln!(out, "   999   200    30     1   1e-08          MAXGS, MAXIN, MAXNR, MAXOUT, EPS");
        // CONTACT's FXREL, FYREL: the force over FSTAT·FN, its sign flipped (fx = −FX/FN here).
        let (x, y) = (s.fx_target.map_or(s.cx, |f| -f / s.mu), s.fy_target.map_or(s.cy, |f| -f / s.mu));
        let names = [
            "FN",
            if s.fx_target.is_some() { "FXREL" } else { "CKSI" },
            if s.fy_target.is_some() { "FYREL" } else { "CETA" },
        ];
        let _ = writeln!(out, "  {:?}   {x:?}   {y:?}   {:?}        {}, CPHI", s.fn_n, s.cs, names.join(", "));
        if read_mu {
            let _ = writeln!(out, "  {:?}   {:?}                            FSTAT, FKIN", s.mu, s.mu);
        }
        if first {
            geometry(p, load_varies, &mut out);
        } else if dq_again {
            kinematics_and_material(p, &mut out);
        }
    }
    out.push_str("\n 0  MODULE\n");
    out
}

/// The kinematics (CHI, DQ, VELOC) and material lines of a case with C = 2.
fn kinematics_and_material(p: &Problem, out: &mut String) {
    let m = &p.material;
    let _ = writeln!(out, "  0.0   {:?}   {:?}                 CHI, DQ, VELOC", p.rolling.dq_mm, p.rolling.v_mm_s);
    let _ = writeln!(out, "  {:?}   {:?}   {:?}   {:?}    POISS 1,2,  GG 1,2", m.poisson, m.poisson, m.g_mpa, m.g_mpa);
}

/// The first case's kinematics, material and geometry lines.
fn geometry(p: &Problem, load_varies: bool, out: &mut String) {
    let (m, g) = (&p.material, &p.grid);
    kinematics_and_material(p, out);
    if p.geometry.elliptic() && !load_varies {
        let e = p.hertz();
        let _ = writeln!(out, "  -3                                          IPOTCN");
        let _ = writeln!(
            out,
            "  {}   {}   {:?}   {:?}   {:?}       MX, MY, AA, BB, SCALE",
            g.mx, g.my, e.a_mm, e.b_mm, p.grid_scale
        );
        return;
    }
    // The grid's lower-left corner in CONTACT's coordinates (x_C = −x).
    let (xl, yl) = match p.grid_edges {
        Some(([x0, _], [y0, _])) => (x0, y0),
        None => (-(g.x_mm[g.mx - 1] + 0.5 * g.dx_mm), g.y_mm[0] - 0.5 * g.dy_mm),
    };
    let _ = writeln!(out, "  1                                           IPOTCN");
    let _ = writeln!(
        out,
        "  {}   {}   {:?}   {:?}   {:?}   {:?}       MX, MY, XL, YL, DX, DY",
        g.mx, g.my, xl, yl, g.dx_mm, g.dy_mm
    );
    if p.geometry.elliptic() {
        let (a1, b1) = p.hertz().undeformed_curvatures(m);
        let _ = writeln!(out, "  1    1                                      IBASE, IPLAN");
        let _ = writeln!(out, "  {a1:?}   0.0   {b1:?}   0.0   0.0   0.0     B1..B6");
        return;
    }
    let h = p.geometry.undeformed_distance_mm(g, p.hertz().fn_n, m);
    let _ = writeln!(out, "  9    1                                      IBASE, IPLAN");
    let contact_order: Vec<f64> = (0..g.len()).map(|k| h[g.index(g.mx - 1 - k % g.mx, k / g.mx)]).collect();
    for chunk in contact_order.chunks(PER_LINE) {
        let line: Vec<String> = chunk.iter().map(|v| format!("{v:?}")).collect();
        let _ = writeln!(out, "  {}", line.join("  "));
    }
}
