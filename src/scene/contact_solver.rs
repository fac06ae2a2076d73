//! `[contact_solver]` (optional): the exact solver's stopping rule and options; its keys declared
//! once ([`KEYS`], their defaults those of [`ContactSolverOptions::default`]) for the reader and
//! docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::{ContactSolverOptions, InitialSlip, SteadyRestart};
use crate::error::InputError;

/// `[contact_solver]`'s keys (`<!-- keys:contact_solver -->`).
pub const KEYS: Keys = Keys {
    id: "contact_solver",
    owner: file!(),
    keys: &[
        key(
            "tolerance",
            "–",
            Allowed::Number(Range::new(1e-14, true, 1e-2, true), ""),
            Absent::Num(1e-7),
            r#"stop a step when the largest traction change relative to max μ·pn falls below this: `tolerance = 1e-9`"#,
        ),
        key(
            "max_iterations",
            "–",
            Allowed::Whole(1, 1_000_000, ""),
            Absent::Whole(1000),
            r#"the iteration limit per step; reaching it is a warning and `termination = 2` in the history: `max_iterations = 5000`"#,
        ),
        key(
            "veldep_tolerance",
            "–",
            Allowed::Number(Range::new(1e-14, true, 1e-2, true), ""),
            Absent::Num(super::VELDEP_TOLERANCE),
            r#"with a falling `[friction]` law: stop the fixed point on the slip velocity s when rms(s_new − s) ≤ this·rms(s_new) over the contact, or when no element slips (CONTACT stops at a fixed 1e-3, which leaves up to 7e-5 in f/FN; 1e-6 leaves at most 1.4e-7 against CONTACT run to 1e-7 on the reference cases); it ends only on a tangential solve stopped at the smaller of `tolerance` and a tenth of this, the earlier ones at 1e-2 × the fixed point's last relative change (at most 1e-2, the first at 1e-2; never tighter than the last; a solve that reached the final tolerance anyway counts as final), each warm started from the previous iterate (its slip elements moved onto the new bound); at most 190 iterations, each a tangential solve with the bound μ(s)·pn, damped as CONTACT (by `omgslp` in slip elements whose μ rises, × 0.8 every 20 iterations while the element division changes): `veldep_tolerance = 1e-8`; `creepbench import contact` writes CONTACT's own 1e-3"#,
        ),
        key(
            "tempdep_tolerance",
            "–",
            Allowed::Number(Range::new(1e-14, true, 1e-2, true), ""),
            Absent::Num(super::TEMPDEP_TOLERANCE),
            r#"with `[friction] law = "temperature"`: stop the fixed point on the surface temperature T [°C] when rms(T_new − T) ≤ this·rms(T_new) over the contact, or when no element slips (CONTACT stops at a fixed 1e-4 of the temperatures in °C); it ends only on a tangential solve stopped at the smaller of `tolerance` and a tenth of this, the earlier ones loosened as with `veldep_solves = "adaptive"`; at most `tempdep_max_iterations`, each a tangential solve with the bound μ(T)·pn, damped as CONTACT (by `omgslp` in slip elements whose μ exceeds the upstream element's, × 0.8 every 15 iterations while the element division changes): `tempdep_tolerance = 1e-4`; `creepbench import contact` writes CONTACT's own 1e-4"#,
        ),
        key(
            "tempdep_max_iterations",
            "–",
            Allowed::Whole(1, 100_000, ""),
            Absent::Whole(super::TEMPDEP_MAX_ITERATIONS),
            r#"with `[friction] law = "temperature"`: the most iterations of the fixed point on the surface temperature (CONTACT's max(1, MAXIN − 10) + 1: its loop runs while its count is at most max(1, MAXIN − 10)); stopping there unconverged is `tempdep_converged = 0`, `termination = 2` and a warning, and the row is that last iterate, as CONTACT prints it: `tempdep_max_iterations = 91`; `creepbench import contact` writes the deck's (MAXIN = 100: 91)"#,
        ),
        key(
            "inislp",
            "–",
            Allowed::Choice(&["previous", "below", "above", "extrapolated"], ""),
            Absent::Choice("previous"),
            r#"with a falling law, where the fixed point starts (CONTACT's INISLP 0, +1, −1): the previous step's slip velocity moved by dq (0 in steady rolling and in the first step from zero), s = 0, or s = V (with `veldep_solves = "adaptive"`, once two iterates from the previous step's start hold that step's element division, the iteration goes on from the last two steps extrapolated: the same path's branch in about a third of the iterations at a stationary state). Where a case has several solutions, `below` finds the low-slip one (more adhesion, the higher force) and `above` the high-slip one (CONTACT's code and its `examples/veldep_fric`; its user guide states it the other way round), and `previous` the one CONTACT's INISLP 0 finds, step by step. `extrapolated` (not CONTACT's) starts a transient step after a transient step from the last two steps' slip velocities extrapolated in the contact's frame, max(0, 2 s_(k−1) − s_(k−2)): at a stationary state the start is the solution, where the moved field is one element off it, so a transient history takes about a third of the time; the same fixed point where a step has one, but where it has several it keeps the last step's branch where CONTACT's start may leave it (a steep law without memory, `reference/contact_friction_variants/`): `inislp = "above"`"#,
        ),
        key(
            "omgslp",
            "–",
            Allowed::Number(Range::new(0.0, false, 2.0, true), ""),
            Absent::Num(super::OMGSLP),
            r#"with a falling law, the damping of the slip-velocity update: s := omgslp·s_new + (1 − omgslp)·s in slip elements whose μ rises (CONTACT's OMGSLP, default 0.5; `examples/veldep_fric` uses 1.1); with `law = "temperature"` the same of the temperature update, T := T + omgslp·(T_new − T) in slip elements whose μ exceeds the upstream element's. It changes the path of the fixed point, not the point it converges to: `omgslp = 1.1`"#,
        ),
        key(
            "veldep_solves",
            "–",
            Allowed::Choice(&["adaptive", "tight"], ""),
            Absent::Choice("adaptive"),
            r#"with a falling law (or `law = "temperature"`), how the fixed point's tangential solves are made: `adaptive` solves the early iterates at 1e-2 × the last relative change (at most 1e-2) and ends on a solve at the final tolerance, starts each solve with the slip elements of the last one (or of the last step) on the new bound: the same fixed point to the tolerance, from the same start, with less work; `tight` solves every iterate at the final tolerance from CONTACT's starts, as CONTACT does, so that with CONTACT's own loose stop (`veldep_tolerance = 1e-3`) the iteration stops at CONTACT's iterate; `creepbench import contact` writes `tight`: `veldep_solves = "tight"`"#,
        ),
        key(
            "influence",
            "–",
            Allowed::Choice(&["constant", "bilinear"], ""),
            Absent::Choice("constant"),
            r#"the influence functions of the half-space (CONTACT's C digit): `constant` the tractions uniform over each element (C = 2, `physics::halfspace::influence`), `bilinear` the tractions bilinear between the element centres, each centre's the hat (1 − \|ξ\|/dx)(1 − \|η\|/dy) (C = 3, `physics::halfspace::bilinear`); for the normal and the tangential problem alike; the forces stay Σ p·dx·dy: `influence = "bilinear"`"#,
        ),
        key(
            "max_outer",
            "–",
            Allowed::Whole(1, 1000, ""),
            Absent::Whole(super::MAX_OUTER),
            r#"with dissimilar bodies (`[material] g1_mpa` … `poisson2`, K ≠ 0): the most outer iterations of a solve between the normal problem (on the undeformed distance plus the normal displacement of the tangential traction) and the tangential one (its slip plus the tangential displacement of the pressure), CONTACT's MAXOUT (its Panagiotopoulos process); they stop when rms of the change of (pn, px, py) over the grid falls to 5 × `tolerance` × rms(pn, px, py) (CONTACT's 5 EPS: each solve leaves an error of the order of its tolerance) after a tangential solve at `tolerance` (the earlier ones at 1e-2 × the smallest relative change so far, at most 1e-3, each warm started from the last iterate; the last allowed one at `tolerance`); 1 solves the normal problem once without the traction's share (CONTACT's MAXOUT = 1); reaching the limit unconverged is `termination = 2`; ignored for K = 0: `max_outer = 30`"#,
        ),
        key(
            "steady_restart",
            "–",
            Allowed::Choice(&["contact", "converged"], ""),
            Absent::Choice("contact"),
            r#"the first transient step after a steady start where μ or FN changed: as CONTACT returns it (the steady state with its slip area rescaled onto the new bound) or solved to the tolerance ([models.md](models.md), "Sign convention: CONTACT's"): `steady_restart = "converged"`"#,
        ),
    ],
};

/// `[contact_solver]` (optional): tolerance, iteration limit, steady restart.
pub fn read(top: &mut Section) -> Result<ContactSolverOptions, InputError> {
    let mut contact_solver = ContactSolverOptions::default();
    if let Some(mut cs) = top.opt_table("contact_solver")?.map(|c| c.declare(&KEYS)) {
        if let Some(t) = cs.opt_num("tolerance")? {
            contact_solver.tolerance = t;
        }
        if let Some(n) = cs.opt_whole("max_iterations")? {
            contact_solver.max_iterations = n;
        }
        if let Some(r) = cs.opt_pick("steady_restart")? {
            contact_solver.steady_restart =
                if r == "contact" { SteadyRestart::Contact } else { SteadyRestart::Converged };
        }
        if let Some(t) = cs.opt_num("veldep_tolerance")? {
            contact_solver.veldep_tolerance = t;
        }
        if let Some(t) = cs.opt_num("tempdep_tolerance")? {
            contact_solver.tempdep_tolerance = t;
        }
        if let Some(n) = cs.opt_whole("tempdep_max_iterations")? {
            contact_solver.tempdep_max_iterations = n;
        }
        if let Some(start) = cs.opt_pick("inislp")? {
            contact_solver.inislp = match start {
                "below" => InitialSlip::Below,
                "above" => InitialSlip::Above,
                "extrapolated" => InitialSlip::Extrapolated,
                _ => InitialSlip::Previous,
            };
        }
        if let Some(w) = cs.opt_num("omgslp")? {
            contact_solver.omgslp = w;
        }
        if let Some(v) = cs.opt_pick("veldep_solves")? {
            contact_solver.veldep_solves =
                if v == "tight" { crate::scene::VeldepSolves::Tight } else { crate::scene::VeldepSolves::Adaptive };
        }
        if let Some(b) = cs.opt_pick("influence")? {
            use crate::physics::halfspace::influence::Basis;
            contact_solver.influence = if b == "bilinear" { Basis::Bilinear } else { Basis::Constant };
        }
        if let Some(n) = cs.opt_whole("max_outer")? {
            contact_solver.max_outer = n;
        }
        cs.finish()?;
    }
    Ok(contact_solver)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The declared defaults are those of the options (an absent key keeps the default).
    #[test]
    fn the_declared_defaults_are_the_options_defaults() {
        let d = ContactSolverOptions::default();
        let of = |k: &str| KEYS.get(k).unwrap().default;
        assert_eq!(of("tolerance"), Absent::Num(d.tolerance));
        assert_eq!(of("max_iterations"), Absent::Whole(d.max_iterations));
        assert_eq!(of("veldep_tolerance"), Absent::Num(d.veldep_tolerance));
        assert_eq!(of("tempdep_tolerance"), Absent::Num(d.tempdep_tolerance));
        assert_eq!(of("tempdep_max_iterations"), Absent::Whole(d.tempdep_max_iterations));
        assert_eq!(of("omgslp"), Absent::Num(d.omgslp));
        assert_eq!(of("max_outer"), Absent::Whole(d.max_outer));
    }
}
