//! CONTACT's printed module-1 results against a wheel–rail scene's: per case the totals on the
//! rail, per patch the reference location, the creepages, the forces and the element counts, each
//! difference measured in half-units of CONTACT's last printed digit (a difference of at most 1
//! is the printed value reproduced).

use super::contact_output::printed::Printed;
use super::contact_output::wheelrail::{Patch, WheelRailCase};
use crate::pipeline::wheelrail::{CaseResult, Pitch};

/// CONTACT's FSTAT, from the largest patch's printed FX and FX/FSTAT/FN.
fn mu_of(theirs: &WheelRailCase) -> Option<f64> {
    use super::contact_output::wheelrail::Ratio;
    let t =
        theirs.patches.iter().filter_map(|p| p.totals.as_ref()).max_by(|a, b| a.fn_n.value.total_cmp(&b.fn_n.value))?;
    let Ratio::OverFstatFn(r) = t.fx_ratio else { return None };
    (r.value != 0.0).then(|| t.fx_n.value / (r.value * t.fn_n.value))
}

/// One compared quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Deviation {
    pub contact_case: u64,
    /// The patch (from 1), or 0 for the case's totals.
    pub patch: usize,
    pub quantity: &'static str,
    pub ours: f64,
    pub contact: f64,
    /// Half a unit of CONTACT's last printed digit (its rounding bound).
    pub half_unit: f64,
    /// |ours − contact| over half a unit of CONTACT's last printed digit.
    pub half_units: f64,
    /// How far CONTACT's value may lie from its converged one, where its iteration stops short
    /// of its printed digits (VPITCH found for FX_WS: [`vpitch_tolerance`]); else 0.
    pub tolerance: f64,
}

/// CONTACT's solver tolerance EPS in the decks with FX_WS prescribed (`mbench_fx_ws_*`, as
/// `export contact` writes it).
pub const CONTACT_EPS: f64 = 1e-5;

/// How far CONTACT's VPITCH may lie from the one that gives FX_WS exactly: its secant stops
/// when |FX(WS) − FX_WS| < EPS·μ·FZ (`wr_contact_fx_secant`, relative to FZ), which moves VPITCH
/// by EPS·μ·FZ·|dVPITCH/dFX(WS)|, twice that for FZ's own iteration inside it (stopped at
/// the same EPS relative to FZ).
pub fn vpitch_tolerance(mu: f64, fz_n: f64, per_fx_rad_s_n: f64) -> f64 {
    2.0 * CONTACT_EPS * mu * fz_n * per_fx_rad_s_n
}

fn deviation(case: u64, patch: usize, quantity: &'static str, ours: f64, p: &Printed) -> Deviation {
    let half_units = (ours - p.value).abs() / p.half_unit.max(f64::MIN_POSITIVE);
    Deviation {
        contact_case: case,
        patch,
        quantity,
        ours,
        contact: p.value,
        half_unit: p.half_unit,
        half_units,
        tolerance: 0.0,
    }
}

/// Every compared quantity of one case of the model at index `model` of the run's models: the
/// number of patches (`n_patches`, a count: any difference is 2 half-units or more), the totals
/// on the rail, the pitch velocity where the case found it, a massless rail's deflections and, patch by patch in CONTACT's order, the patches both have.
pub fn compare_case(case: u64, ours: &CaseResult, model: usize, theirs: &WheelRailCase) -> Vec<Deviation> {
    let mut out = Vec::new();
    let count = Printed { value: theirs.patches.len() as f64, half_unit: 0.5 };
    let (name, forces, totals) = &ours.models[model];
    let normal = ours.normal_of(name);
    out.push(deviation(case, 0, "n_patches", normal.patches.len() as f64, &count));
    if let Some(f) = &theirs.forces {
        let names = ["fx_tr_n", "fy_tr_n", "fz_tr_n", "fx_ws_n", "fy_ws_n", "fz_ws_n"];
        let printed = [&f.fx_tr_n, &f.fy_tr_n, &f.fz_tr_n, &f.fx_ws_n, &f.fy_ws_n, &f.fz_ws_n];
        let values = totals.track_n.iter().chain(&totals.wheelset_n);
        out.extend(names.iter().zip(printed).zip(values).map(|((n, p), v)| deviation(case, 0, n, *v, p)));
    }
    // VPITCH where the case found it (FX_WS prescribed, CONTACT's F = 1), beyond CONTACT's
    // stopping tolerance.
    // μ as CONTACT prints it, or where it prints FX = 0 (free rolling) the case's own.
    if let (Pitch::Found { rad_s, per_fx_rad_s_n, mu }, Some(v)) = (ours.pitch, &theirs.velocity) {
        let mu = mu_of(theirs).unwrap_or(mu);
        let fz = totals.track_n[2];
        // No slope (found at the first estimate): no tolerance.
        let tolerance = vpitch_tolerance(mu, fz, per_fx_rad_s_n).max(0.0);
        out.push(Deviation { tolerance, ..deviation(case, 0, "vpitch_rad_s", rad_s, &v.vpitch_rad_s) });
    }
    // The massless rail's deflections found (CONTACT's F = 3).
    if let (Some([dy, dz]), Some(d)) = (ours.rail_deflection_mm, &theirs.rail_deflection) {
        out.push(deviation(case, 0, "dy_defl_mm", dy, &d.dy_defl_mm));
        out.push(deviation(case, 0, "dz_defl_mm", dz, &d.dz_defl_mm));
    }
    let m = normal.side.sign();
    for (k, (p, f)) in normal.patches.iter().zip(forces).enumerate() {
        let Some(t) = theirs.patches.get(k) else { continue };
        out.extend(patch_deviations(case, k + 1, m, ours, p, f, t));
    }
    out
}

fn patch_deviations(
    case: u64,
    patch: usize,
    m: f64,
    ours: &CaseResult,
    p: &crate::wheelrail::NormalPatch,
    f: &crate::pipeline::wheelrail::PatchForces,
    t: &Patch,
) -> Vec<Deviation> {
    let mut out = Vec::new();
    let mut add = |q: &'static str, v: f64, pr: &Printed| out.push(deviation(case, patch, q, v, pr));
    let o = &p.geometry.frame.origin;
    if let Some(r) = &t.reference {
        let [y_r, z_r] = ours.normal.in_rail_mm(o.y, o.z);
        add("xcp_tr_mm", o.x, &r.xcp_tr_mm);
        add("ycp_tr_mm", m * o.y, &r.ycp_tr_mm);
        add("zcp_tr_mm", o.z, &r.zcp_tr_mm);
        add("deltcp_rad", m * p.geometry.frame.delta_rad, &r.deltcp_tr_rad);
        add("ycp_r_mm", m * y_r, &r.ycp_r_mm);
        add("zcp_r_mm", z_r, &r.zcp_r_mm);
    }
    if let Some(k) = &t.kinematics {
        add("chi_rad", p.creepages.chi_rad(), &k.chi_rad);
        add("veloc_mm_s", p.creepages.veloc_mm_s, &k.veloc_mm_s);
        add("cksi", p.creepages.cksi, &k.cksi);
        add("ceta", m * p.creepages.ceta, &k.ceta);
        add("cphi_per_mm", m * p.creepages.cphi_per_mm, &k.cphi_per_mm);
    }
    if let Some(tt) = &t.totals {
        add("fn_n", f.fn_n, &tt.fn_n);
        add("fx_n", f.fx_n, &tt.fx_n);
        add("fs_n", f.fs_n, &tt.fs_n);
        add("mn_nmm", f.mn_nmm, &tt.mn_nmm);
        add("pen_mm", p.pen_mm, &tt.approach_mm);
        // MAX(T1,T2), or each body's where CONTACT prints them apart: against our largest of both.
        use super::contact_output::wheelrail::MaxTemperature;
        match (f.temp_max_c, &tt.max_temperature) {
            (Some(t), Some(MaxTemperature::Both(pr))) => add("temp_max_c", t, pr),
            (Some(t), Some(MaxTemperature::Each(a, b))) => add("temp_max_c", t, if a.value >= b.value { a } else { b }),
            _ => {}
        }
    }
    if let Some(s) = &t.statistics {
        let count = |n: u32| Printed { value: n as f64, half_unit: 0.5 };
        let ncon = p.pn_mpa.iter().filter(|&&v| v > 0.0).count() as f64;
        add("npot", p.geometry.grid.len() as f64, &count(s.npot));
        add("ncon", ncon, &count(s.ncon));
        if let (Some(a), Some(sl)) = (f.n_adhesion, f.n_slip) {
            add("nadh", a as f64, &count(s.nadh));
            add("nslip", sl as f64, &count(s.nslip));
        }
    }
    out
}
