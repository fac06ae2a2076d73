//! FASTSIM and the UBA on a wheel–rail patch that moves in time: the patch's module-3 problem (the
//! exact theory's grid and pressure, the bound μ p), the model's own tractions the case before left
//! on the material-fixed grid as its start (carried, merged and split as the exact theory's,
//! [`crate::wheelrail::shift`]), then in a shift (CONTACT's T = 1) one brush shift per element
//! ([`brush_shift::shift_step`], the step's rigid shift from the exact path's kinematics), in
//! transient rolling (T = 2) one UBA time step of Courant number DQ / DX ([`uba::continuing`],
//! sub-stepped above 1), and in the steady case that starts a sequence the model's steady
//! solution, kept for the next. A patch rolling towards −x (CHI = 180°) is solved mirrored about
//! x = 0 as the exact solver solves it ([`RollingFrame`]), its history kept in its own frame.

use super::wheelrail::{on_bound_counted, patch_problem, PatchForces};
use super::wheelrail_exact::{about_anchor, in_contact_order, previous_tractions};
use super::wheelrail_frame::RollingFrame;
use crate::error::{Error, InputError};
use crate::physics::geometry::field_in_grid_order;
use crate::problem::{Problem, Sample};
use crate::solvers::brush::{self, Tractions};
use crate::solvers::stepper::{Step, Stepper};
use crate::solvers::{self, brush_shift, uba, SolveError};
use crate::wheelrail::shift::Previous;
use crate::wheelrail::{Motion, NormalPatch, WheelRailCase};

/// `model`'s forces on patch `p` of `case`, continuing its own `history` (the patches the case
/// before left with this model's tractions; `None` from rest), its tractions kept for the next case.
pub fn patch_forces(
    p: &NormalPatch,
    model: &str,
    mu: f64,
    case: &WheelRailCase,
    history: Option<&Previous>,
) -> Result<PatchForces, Error> {
    // The problem is in the patch's rolling frame (mirrored for a patch rolling towards −x, as
    // the exact solver's): the history, kept in the patch's own frame, is mapped in, the
    // solution back.
    let frame = RollingFrame::of(p);
    let mut problem = patch_problem(p, model, mu, case)?;
    let (px0, py0) = previous_tractions(p, &WheelRailCase { previous: history, ..*case });
    let in_grid = |f: &[f64]| field_in_grid_order(&problem.grid, f);
    let (tx, ty) = frame.pair((in_grid(&px0), in_grid(&py0)));
    let start = Tractions { tx, ty };
    let failed = |e: SolveError| Error::Solve { scene: "patch".into(), solver: model.into(), source: Box::new(e) };
    let (step, t, pressure_mpa) = match case.motion {
        Motion::Shift { .. } => shift(&problem, &start),
        Motion::Transient { dq_mm } => {
            problem.rolling.courant = courant(dq_mm, problem.grid.dx_mm)?;
            solved(&problem, uba::continuing(&problem, start), Stepper::transient).map_err(failed)?
        }
        Motion::Rolling => {
            let def = solvers::builtin(model).ok_or_else(|| InputError::new("solvers", model, "a built-in model"))?;
            let stepper = (def.build)(&problem).map_err(failed)?;
            solved(&problem, stepper, Stepper::steady).map_err(failed)?
        }
    };
    let count = |k: usize| step.extra.get(k).map(|v| *v as usize);
    let mu = problem.loading.first().mu;
    let slip = count(1).and_then(|n| on_bound_counted(&t, &pressure_mpa, mu, n));
    let in_patch = |f: &[f64]| in_contact_order(&problem.grid, f);
    let (fx_over_fn, fy_over_fn, mz_nmm) = frame.totals((step.fx_over_fn, step.fy_over_fn, step.mz_nmm));
    let forces = PatchForces {
        n_adhesion: count(0),
        n_slip: count(1),
        shift_tractions_mpa: Some(frame.pair((in_patch(&t.tx), in_patch(&t.ty)))),
        slip: slip.map(|s| frame.field(in_contact_order(&problem.grid, &s))),
        ..PatchForces::on_rail(p, case, fx_over_fn, fy_over_fn, mz_nmm)
    };
    Ok(if case.motion.super_grid_s_mm().is_some() { about_anchor(forces, p, case) } else { forces })
}

/// One brush shift of the problem's patch from `start`: the shifts are the sample's creepages
/// (CONTACT's T = 1: dt = 1, the velocities one step's shifts).
fn shift(problem: &Problem, start: &Tractions) -> (Step, Tractions, Vec<f64>) {
    let at = problem.loading.first();
    let local = problem.local_contact(at.fn_n);
    let shift = brush::slip_rates(at, &local);
    let mut t = Tractions::zero(problem.grid.len());
    let n_slip = brush_shift::shift_step(&problem.grid, &local, at.mu, &shift, start, &mut t);
    let loaded = local.planform.pressure_mpa.iter().filter(|&&p| p > 0.0).count();
    (brush::step(&local.planform, t.sums(&problem.grid), loaded, n_slip), t, local.planform.pressure_mpa)
}

/// `stepper` (on `problem`) through one solve `solve` (a transient step or steady rolling) of the
/// problem's one sample: its result, tractions and the pressure that bounds them.
fn solved<'a>(
    problem: &'a Problem,
    mut stepper: Box<dyn Stepper + 'a>,
    solve: impl FnOnce(&mut (dyn Stepper + 'a), &Sample) -> Result<Step, SolveError>,
) -> Result<(Step, Tractions, Vec<f64>), SolveError> {
    let at = problem.loading.first();
    stepper.load(at)?;
    let step = solve(stepper.as_mut(), at)?;
    let f = stepper.field().expect("FASTSIM and the UBA have a traction field");
    Ok((step, Tractions { tx: f.tx_mpa.to_vec(), ty: f.ty_mpa.to_vec() }, f.pressure_mpa.to_vec()))
}

/// The UBA's Courant number of a transient rolling step DQ on elements DX, within its limit
/// ([`uba::MAX_COURANT`]: sub-steps of Courant number ≤ 1 each, the explicit step's stability).
fn courant(dq_mm: f64, dx_mm: f64) -> Result<f64, Error> {
    let c = dq_mm / dx_mm;
    if c > 0.0 && c <= uba::MAX_COURANT {
        return Ok(c);
    }
    let allowed = format!(
        "a transient rolling step DQ = dq_rel DX of at most {} DX for the uba (its explicit step is split into ceil(DQ / DX) sub-steps of Courant number <= 1)",
        uba::MAX_COURANT
    );
    Err(InputError::new("wheelrail.dq_rel", c, allowed).into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::RigidSlip;
    use crate::pipeline::wheelrail::{patch_solve, CaseResult, EXACT};
    use crate::pipeline::wheelrail_scene::{case_of, prepare, run_scene};
    use crate::problem::material_of_spec;
    use crate::scene::wheelrail::WheelRailScene;
    use std::path::Path;

    /// `scenes/wheelrail/NAME.toml` with `edit` applied to its text.
    fn scene(name: &str, edit: impl Fn(String) -> String) -> WheelRailScene {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/wheelrail");
        let text = std::fs::read_to_string(dir.join(format!("{name}.toml"))).unwrap();
        WheelRailScene::from_toml(&edit(text), &dir).unwrap()
    }

    /// A model's forces on patch `k` of a solved case.
    fn of<'a>(r: &'a CaseResult, model: &str, k: usize) -> &'a PatchForces {
        &r.models.iter().find(|(m, _, _)| m == model).unwrap().1[k]
    }

    #[test]
    fn a_shift_from_rest_is_the_brush_closed_form_per_element() {
        // m1_catt_shift case 1: Cattaneo's shift from rest, one patch (1279 elements in contact).
        let s = scene("m1_catt_shift_1", |t| t);
        let run = run_scene(&s).unwrap();
        let (rail, wheel, _) = prepare(&s).unwrap();
        let case = case_of(&s, &s.cases[0], &rail, &wheel, material_of_spec(&s.material).unwrap());
        let case = WheelRailCase { motion: Motion::Shift { s_ws_mm: 0.0 }, ..case };
        let r = &run.cases[0].1;
        let p = &r.normal.patches[0];
        // Per element: τ = w/L bounded to μ p along w (w the element's rigid shift), on the
        // exact theory's grid and pressure.
        let problem = patch_problem(p, "fastsim", s.mu, &case).unwrap();
        let at = problem.loading.first();
        let local = problem.local_contact(at.fn_n);
        let (l1, l2, l3) = brush::flexibilities(at, &local);
        let c = &p.creepages;
        let w = RigidSlip::new(c.cksi, c.ceta, c.cphi_per_mm).over_flexibilities(l1, l2, l3);
        let g = &problem.grid;
        let (mut sx, mut sy, mut sp, mut slipping) = (0.0, 0.0, 0.0, 0);
        for j in 0..g.my {
            for i in 0..g.mx {
                let pk = local.planform.pressure_mpa[g.index(i, j)];
                if pk <= 0.0 {
                    continue;
                }
                let (wx, wy) = w.at(g.x_mm[i], g.y_mm[j]);
                let size = (wx * wx + wy * wy).sqrt();
                let f = (s.mu * pk / size).min(1.0);
                slipping += usize::from(f < 1.0);
                (sx, sy, sp) = (sx + f * wx, sy + f * wy, sp + pk);
            }
        }
        let want = PatchForces::on_rail(p, &case, sx / sp, sy / sp, 0.0);
        for model in ["fastsim", "uba"] {
            let got = of(r, model, 0);
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * p.fn_n;
            assert!(close(got.fx_n, want.fx_n) && close(got.fs_n, want.fs_n), "{model}: {got:?} vs {want:?}");
            assert_eq!(got.n_slip, Some(slipping), "{model}");
        }
        // FASTSIM and the UBA share the shift (they differ only in how they march rolling).
        assert_eq!(of(r, "fastsim", 0), of(r, "uba", 0));
        // The exact theory's Cattaneo shift pulls the same way, about half as hard (the
        // simplified theory's flexibility is steady rolling's, Kalker 1990 §3.3).
        let exact = of(r, "contact", 0);
        assert!(exact.fx_n * want.fx_n > 0.0 && exact.fs_n * want.fs_n > 0.0, "{exact:?}");
        assert!((want.fx_n / exact.fx_n - 1.98).abs() < 0.01, "FX {} vs {}", want.fx_n, exact.fx_n);
    }

    #[test]
    fn enough_shifts_one_way_reach_each_models_own_steady_state() {
        // m1_catt_shift: after Cattaneo's shift from rest, 80 shifts of 0.2 mm = DX each roll the
        // contact over the material-fixed grid; from case 41 on the brush forces stand still.
        let s = scene("m1_catt_shift_1", |t| t);
        let run = run_scene(&s).unwrap();
        let (rail, wheel, _) = prepare(&s).unwrap();
        let last = run.cases.len() - 1;
        let case = case_of(&s, &s.cases[last], &rail, &wheel, material_of_spec(&s.material).unwrap());
        let r = &run.cases[last].1;
        // The same patch in steady rolling, its creepages the shifts over the 0.2 mm rolled.
        let mut p = r.normal.patches[0].clone();
        let c = p.creepages;
        let dq_mm = s.dx_mm;
        p.creepages = crate::wheelrail::creepage::Creepages {
            cksi: c.cksi / dq_mm,
            ceta: c.ceta / dq_mm,
            cphi_per_mm: c.cphi_per_mm / dq_mm,
            veloc_mm_s: 1.0,
            reversed: false,
        };
        // Every patch solve starts from rest on the same grid: the brush's steady march.
        let steady = |model: &str| patch_solve(&p, model, s.mu, &case).unwrap();
        let gap = |a: &PatchForces, b: &PatchForces| (a.fx_n - b.fx_n).abs().max((a.fs_n - b.fs_n).abs());
        for model in ["fastsim", "uba"] {
            let got = of(r, model, 0);
            // The cases' pressure and shifts vary in their 8th digit (the exact normal solve).
            let early = of(&run.cases[last - 40].1, model, 0);
            assert!(gap(got, early) < 1e-6 * p.fn_n, "{model}: not yet steady at case 41 ({} N)", gap(got, early));
            // The shift's rigid slip taken at the element's centre is the UBA's steady march
            // (Integration::Centre): FX −40.2414 N, FS −25.4254 N both ways.
            let uba = steady("uba");
            assert!(gap(got, &uba) < 1e-6 * p.fn_n, "{model}: {got:?} vs the UBA's steady {uba:?}");
        }
        // FASTSIM's own steady march integrates the rigid slip along each element's path (its
        // spin term half an element upstream, Kalker's Eq. 2.34): FX −40.381 N, FS −24.336 N, a
        // shift has no path and takes the centre's. The gap is that half element's spin.
        let (fastsim, uba) = (steady("fastsim"), steady("uba"));
        assert!((fastsim.fx_n / uba.fx_n - 1.0).abs() < 0.005, "{fastsim:?} vs {uba:?}");
        assert!((fastsim.fs_n / uba.fs_n - 1.0).abs() < 0.05, "{fastsim:?} vs {uba:?}");
        // The exact theory reaches its own steady rolling too (0.7 % of its force here; the gate
        // compares its forces with CONTACT's digits).
        let (exact, exact_steady) = (of(r, EXACT, 0), steady(EXACT));
        assert!(gap(exact, &exact_steady) < 0.015 * exact_steady.fx_n.hypot(exact_steady.fs_n), "{exact:?}");
    }

    /// The largest |τ| / (μ p) over a solved case's patches for `model` (1 on the bound).
    fn bound_ratio(r: &CaseResult, model: &str, mu: f64) -> f64 {
        let forces = &r.models.iter().find(|(m, _, _)| m == model).unwrap().1;
        let mut worst = 0.0f64;
        for (p, f) in r.normal.patches.iter().zip(forces) {
            let (px, py) = f.shift_tractions_mpa.as_ref().unwrap();
            for (k, &pn) in p.pn_mpa.iter().enumerate() {
                let t = px[k].hypot(py[k]);
                assert!(pn > 0.0 || t == 0.0, "{model}: traction {t} MPa off the contact");
                if pn > 0.0 {
                    worst = worst.max(t / (mu * pn));
                }
            }
        }
        worst
    }

    #[test]
    fn the_ubas_step_on_a_patch_that_changes_is_stable_sub_stepped_or_refused() {
        // Transient rolling: the UBA's upwind step of Courant number DQ/DX ≤ 1 is a convex
        // combination of the old tractions plus the source, then bounded: |τ| never exceeds μ p,
        // and its forces rise to steady rolling without an overshoot or a step-to-step swing.
        // m1_trans_roll (DQ = DX, 81 steps from rest), m1_trans_dqrel (DQ = 4 DX: 4 sub-steps of
        // C = 1), t3_t2_force (three patches, FZ prescribed: the height and every patch's shape
        // change from step to step).
        let uba = |t: String| t.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"uba\"]");
        // t3_t2_force's μ varies with the contact angle, 0.2 to 0.9: its bound is taken at 0.9.
        for (name, mu_max) in [("m1_trans_roll_1", None), ("m1_trans_dqrel_1", None), ("t3_t2_force_1", Some(0.9))] {
            let s = scene(name, uba);
            let run = run_scene(&s).unwrap();
            let fx: Vec<f64> = run.cases.iter().map(|(_, r)| of(r, "uba", 0).fx_n).collect();
            for (c, r) in &run.cases {
                let ratio = bound_ratio(r, "uba", mu_max.unwrap_or(s.mu));
                assert!(ratio <= 1.0 + 1e-12, "{name} case {c}: |τ| / μp up to {ratio}");
            }
            if name == "m1_trans_roll_1" {
                // From rest the force grows step by step to its steady value, monotonically.
                assert!(fx.windows(2).all(|w| w[1] <= w[0] + 1e-9 * w[0].abs()), "{name}: {fx:?}");
                assert!((fx[80] / fx[40] - 1.0).abs() < 1e-6, "{name}: {fx:?}");
            }
        }
        // A step is at most 10 DX (the scene's dq_rel), 10 sub-steps, within the UBA's limit.
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/wheelrail");
        let text = uba(std::fs::read_to_string(dir.join("m1_trans_dqrel_1.toml")).unwrap());
        let e = WheelRailScene::from_toml(&text.replace("dq_rel = 4.0", "dq_rel = 100.0"), &dir).unwrap_err();
        assert!(e.field.contains("dq_rel") && e.allowed.contains("10]"), "{e:?}");
        assert!(courant(100.0 * 0.2, 0.2).is_err() && courant(10.0 * 0.2, 0.2).is_ok());
        // Shifts: no transport (each element keeps its own traction), so no step limit; patches
        // that split and merge (t1_split_cp, t1_merge_cp) keep every traction within μ p.
        let brush = |t: String| t.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\", \"uba\"]");
        for name in ["t1_split_cp_1", "t1_merge_cp_1"] {
            let s = scene(name, brush);
            let run = run_scene(&s).unwrap();
            for (_, r) in &run.cases {
                // μ by the contact angle, 0.2 to 0.35: the bound taken at 0.35.
                assert!(bound_ratio(r, "uba", 0.35) <= 1.0 + 1e-12, "{name}");
                assert!(bound_ratio(r, "fastsim", 0.35) <= 1.0 + 1e-12, "{name}");
            }
        }
    }

    /// The Manchester right deck's scene and the patches of its case 14 (a flange contact, not
    /// symmetric in x).
    fn manchester_14() -> (WheelRailScene, Vec<NormalPatch>) {
        let s = scene("mbench_a22_right", |t| t);
        let (rail, wheel, _) = prepare(&s).unwrap();
        let row = s.cases.iter().find(|r| r.contact_case == 14).unwrap();
        let case = case_of(&s, row, &rail, &wheel, material_of_spec(&s.material).unwrap());
        let normal = crate::wheelrail::normal_contact(&case, None).unwrap();
        assert!(!normal.patches.is_empty());
        (s, normal.patches)
    }

    /// Patch `p` mirrored about x = 0 and rolling the other way: its fields' rows reversed, its
    /// grid and anchor at −x, CKSI and CPHI negated (the mirror image of the same problem).
    fn mirrored(p: &NormalPatch) -> NormalPatch {
        let mut q = p.clone();
        let g = &mut q.geometry.grid;
        let mirror = |v: &[f64]| crate::solvers::contact::mirror::field(g.mx, v);
        q.geometry.h_mm = mirror(&p.geometry.h_mm);
        q.pn_mpa = mirror(&p.pn_mpa);
        if let Some(b) = &mut q.geometry.blend {
            b.part = crate::solvers::contact::mirror::field(g.mx, &b.part);
        }
        g.x0_mm = -(g.x0_mm + g.dx_mm * g.mx as f64);
        g.anchor_mm[0] = -g.anchor_mm[0];
        let c = &mut q.creepages;
        (c.cksi, c.cphi_per_mm, c.reversed) = (-c.cksi, -c.cphi_per_mm, !c.reversed);
        q
    }

    /// A model's forces on a patch, without its fields.
    fn brief(f: &PatchForces) -> String {
        format!("FX {} FS {} MN {} N ({:?} adhering, {:?} slipping)", f.fx_n, f.fs_n, f.mn_nmm, f.n_adhesion, f.n_slip)
    }

    /// `f` on patch `p` mirrored: FX and MN negated, the tractions' x parts negated and each row of
    /// every field reversed (what `g` on the mirrored patch must equal).
    fn assert_mirrored(f: &PatchForces, g: &PatchForces, p: &NormalPatch, what: &str) {
        let frame = RollingFrame::of(p);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-9 * p.fn_n);
        assert!(
            close(f.fx_n, -g.fx_n) && close(f.fs_n, g.fs_n) && close(f.mn_nmm, -g.mn_nmm),
            "{what}: {f:?} vs {g:?}"
        );
        assert_eq!((f.fn_n, f.n_adhesion, f.n_slip), (g.fn_n, g.n_adhesion, g.n_slip), "{what}");
        assert_eq!(f.slip, g.slip.clone().map(|s| frame.field(s)), "{what}: slip");
        let (fx, fy) = f.shift_tractions_mpa.clone().unwrap();
        let (gx, gy) = frame.pair(g.shift_tractions_mpa.clone().unwrap());
        let scale = fx.iter().chain(&fy).fold(0.0f64, |m, v| m.max(v.abs()));
        for (k, (a, b)) in fx.iter().zip(&gx).chain(fy.iter().zip(&gy)).enumerate() {
            assert!((a - b).abs() <= 1e-12 * scale, "{what}: element {k}: {a} vs {b} MPa");
        }
    }

    /// The patch `p` left with the model's tractions `f` (what the case after it continues).
    fn left_by(p: &NormalPatch, f: &PatchForces) -> Previous {
        let (px_mpa, py_mpa) = f.shift_tractions_mpa.clone().unwrap();
        let old = crate::wheelrail::shift::OldPatch {
            extent: p.geometry.extent,
            grid: crate::wheelrail::shift::IndexBox::of_grid(&p.geometry.grid),
            px_mpa,
            py_mpa,
            contact: crate::wheelrail::shift::contact_of(&p.pn_mpa),
            contact_before: None,
        };
        Previous { patches: vec![old], iterated: false }
    }

    #[test]
    fn a_patch_rolling_backwards_is_the_mirror_of_the_mirrored_patch_for_the_brush_models() {
        // Right case 14's patches rolling towards −x (CHI = 180°): each model, in a steady start,
        // a shift and a transient step, from rest and continuing a history, equals the mirror
        // image of the same model on the mirrored patch rolling along +x.
        let (s, patches) = manchester_14();
        let (rail, wheel, _) = prepare(&s).unwrap();
        let row = s.cases.iter().find(|r| r.contact_case == 14).unwrap();
        let case = case_of(&s, row, &rail, &wheel, material_of_spec(&s.material).unwrap());
        let motions = [
            ("uba", Motion::Rolling),
            ("fastsim", Motion::Shift { s_ws_mm: 0.0 }),
            ("uba", Motion::Transient { dq_mm: 0.4 }),
        ];
        for forward in &patches {
            let mut p = forward.clone();
            p.creepages.reversed = true;
            let q = mirrored(&p);
            assert!(!q.creepages.reversed);
            for (model, motion) in motions {
                let case = WheelRailCase { motion, ..case };
                let what = format!("{model} {motion:?} FN {:.0} N", p.fn_n);
                let (f, g) = (
                    patch_forces(&p, model, s.mu, &case, None).unwrap(),
                    patch_forces(&q, model, s.mu, &case, None).unwrap(),
                );
                assert_mirrored(&f, &g, &p, &format!("{what} from rest"));
                // Rolling backwards matters (a shift has no direction): the same patch rolling
                // along +x pulls otherwise.
                let ahead = patch_forces(forward, model, s.mu, &case, None).unwrap();
                let moved = (f.fx_n - ahead.fx_n).abs().max((f.mn_nmm - ahead.mn_nmm).abs());
                let rolls = !matches!(motion, Motion::Shift { .. });
                assert!(!rolls || moved > 1e-3 * p.fn_n, "{what}: rolling backwards changed nothing ({moved})");
                // Continuing: each patch's history in its own frame, the mirror's mirrored.
                let (hf, hg) = (left_by(&p, &f), left_by(&q, &g));
                let (f2, g2) = (
                    patch_forces(&p, model, s.mu, &case, Some(&hf)).unwrap(),
                    patch_forces(&q, model, s.mu, &case, Some(&hg)).unwrap(),
                );
                assert_mirrored(&f2, &g2, &p, &format!("{what} continued"));
            }
        }
    }

    #[test]
    fn a_patch_rolling_backwards_carries_its_history_through_transient_rolling() {
        // The UBA rolling right case 14's patches towards −x step by step (DQ = 2 DX): each step
        // continues the tractions the step before left (in the patch's own frame), so the second
        // step differs from a step from rest, and the sequence is the mirror image of the
        // mirrored patches' sequence along +x step for step.
        let (s, patches) = manchester_14();
        let (rail, wheel, _) = prepare(&s).unwrap();
        let row = s.cases.iter().find(|r| r.contact_case == 14).unwrap();
        let case = case_of(&s, row, &rail, &wheel, material_of_spec(&s.material).unwrap());
        let case = WheelRailCase { motion: Motion::Transient { dq_mm: 2.0 * s.dx_mm }, ..case };
        for forward in &patches {
            let mut p = forward.clone();
            p.creepages.reversed = true;
            let q = mirrored(&p);
            let (mut hp, mut hq) = (None, None);
            let mut steps = Vec::new();
            for step in 0..3 {
                let f = patch_forces(&p, "uba", s.mu, &case, hp.as_ref()).unwrap();
                let g = patch_forces(&q, "uba", s.mu, &case, hq.as_ref()).unwrap();
                assert_mirrored(&f, &g, &p, &format!("step {step}, FN {:.0} N", p.fn_n));
                (hp, hq) = (Some(left_by(&p, &f)), Some(left_by(&q, &g)));
                steps.push(f);
            }
            // From rest the same patch gives the first step's forces again; continued it does not.
            let rest = patch_forces(&p, "uba", s.mu, &case, None).unwrap();
            assert_eq!(rest, steps[0]);
            let moved = (steps[1].fx_n - rest.fx_n).abs().max((steps[1].fs_n - rest.fs_n).abs());
            assert!(moved > 1e-4 * p.fn_n, "FN {:.0} N: the history carried nothing ({moved} N)", p.fn_n);
            println!("FN {:.1} N: FX {:.3} {:.3} {:.3} N", p.fn_n, steps[0].fx_n, steps[1].fx_n, steps[2].fx_n);
        }
    }

    #[test]
    fn a_steady_start_rolling_backwards_is_the_models_steady_solve() {
        // The steady case that starts a sequence (the brush models' own march) and the models'
        // steady path (the patch's module-3 scene) take a patch rolling towards −x through the
        // same frame: the same forces and slip.
        let (s, patches) = manchester_14();
        let (rail, wheel, _) = prepare(&s).unwrap();
        let row = s.cases.iter().find(|r| r.contact_case == 14).unwrap();
        let case = case_of(&s, row, &rail, &wheel, material_of_spec(&s.material).unwrap());
        for forward in &patches {
            let mut p = forward.clone();
            p.creepages.reversed = true;
            for model in ["fastsim", "uba"] {
                let (f, g) =
                    (patch_forces(&p, model, s.mu, &case, None).unwrap(), patch_solve(&p, model, s.mu, &case).unwrap());
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * p.fn_n;
                assert!(
                    close(f.fx_n, g.fx_n) && close(f.fs_n, g.fs_n) && close(f.mn_nmm, g.mn_nmm),
                    "{model}: {f:?} vs {g:?}"
                );
                assert_eq!((f.n_adhesion, f.n_slip, &f.slip), (g.n_adhesion, g.n_slip, &g.slip), "{model}");
            }
        }
    }

    #[test]
    fn a_wheel_rolling_backwards_carries_the_ubas_history_as_the_exact_theorys() {
        // m1_trans_roll's first steps (transient rolling from rest, DQ = DX) and the same wheel
        // rolling backwards on the mirrored track (VS, VPITCH and the yaw negated): its patch
        // rolls towards −x (CHI = 180°), and the UBA, as the exact theory, carries its tractions
        // from step to step and gives the mirror image of the forward run.
        let uba = |t: String| t.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"uba\"]");
        let mut ahead = scene("m1_trans_roll_1", uba);
        ahead.cases.truncate(6);
        let mut back = ahead.clone();
        for row in &mut back.cases {
            row.yaw_rad = -row.yaw_rad;
            for k in [0, 4, 5] {
                row.velocity[k] = -row.velocity[k];
            }
        }
        let (ahead, back) = (run_scene(&ahead).unwrap(), run_scene(&back).unwrap());
        let mut worst = 0.0f64;
        for ((c, a), (_, b)) in ahead.cases.iter().zip(&back.cases) {
            assert!(b.normal.patches.iter().all(|p| p.creepages.reversed), "case {c}");
            assert!(a.normal.patches.iter().all(|p| !p.creepages.reversed), "case {c}");
            for model in [EXACT, "uba"] {
                let (f, g) = (of(a, model, 0), of(b, model, 0));
                let gap = (f.fx_n + g.fx_n).abs().max((f.fs_n - g.fs_n).abs()).max((f.mn_nmm + g.mn_nmm).abs() / 100.0);
                worst = worst.max(gap / f.fn_n);
                assert!(gap <= 1e-12 * f.fn_n, "case {c} {model}: {} vs {}", brief(f), brief(g));
            }
        }
        println!("worst mirror gap {worst:.2e} FN");
        // The UBA's history carries: from rest on an unchanging patch each step would repeat the
        // first; the force grows step by step instead.
        let fx: Vec<f64> = back.cases.iter().map(|(_, r)| of(r, "uba", 0).fx_n).collect();
        println!("UBA FX backwards {fx:?}");
        assert!((fx[1] - fx[0]).abs() > 1e-3 * fx[0].abs(), "{fx:?}");
    }
}
