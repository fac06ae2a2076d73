//! The one table of CONTACT's module-3 features and whether the import carries them: a feature
//! the project's physics does not have is refused naming its control word and value, never
//! dropped; one that changes no result is accepted with a note. New physics (prescribed forces,
//! shifts, falling friction, …) is switched on here, in its row. Module 1 (wheel–rail) has its
//! own table, [`WHEELRAIL_FEATURES`], read by [`assess_wheelrail`]; what the wheel–rail scene
//! cannot say besides is in `scene::wheelrail::SCENE_LIMITS`, which gives the import's verdict.

use super::deck::{Case3, Potcon, SubsurfaceBlock};
use super::wheelrail_deck::{
    FrictionVariation, MaterialModel, ProfileFormat, ProfileSpec, RailPlacement, WheelRailCase,
};
use crate::physics::material::combine_bodies;

/// One feature of a case.
pub struct Feature {
    /// What it is.
    pub name: &'static str,
    /// The control digit or input line that asks for it.
    pub control: &'static str,
    /// Whether the import carries it (false: a case using it is refused).
    pub supported: bool,
    /// Why (refused: what is supported instead; accepted: what the import does with it).
    pub reason: &'static str,
    /// The value the case gives it, when the case uses it.
    pub used: fn(&Case3) -> Option<String>,
}

/// Surface temperatures the import carries: H ≥ 1 with the data of an H = 3, in steady rolling,
/// without a plastic layer.
fn heat_carried(c: &Case3) -> bool {
    let plastic = layer_in_force(c).is_some_and(|l| l[2] > 1e-10);
    c.state.heat_in_force().is_some() && c.digits.t == 3 && !plastic
}

/// Whether the case's friction is the temperature law (L = 6) as the import carries it: its
/// surface temperatures computed, a memory only with INISLP != 0.
fn temperature_law(c: &Case3) -> bool {
    let from_previous = c.state.memory[0] > 1e-9 && c.state.slip_start.is_none_or(|(i, _)| i == 0);
    c.state.friction_law == 6 && !from_previous && heat_carried(c)
}

/// Whether the case's subsurface points are all explicit (ISUBS = 9) in body 1 (Z ≥ 0), and some.
fn explicit_points(c: &Case3) -> bool {
    let b = &c.state.subsurface;
    !b.is_empty() && b.iter().all(|b| matches!(b, SubsurfaceBlock::Points([_, _, z]) if z.iter().all(|&z| z >= 0.0)))
}

fn digit(name: &str, v: u8, used: bool) -> Option<String> {
    used.then(|| format!("{name} = {v}"))
}

/// Every feature the import knows, in the order of the input.
pub const FEATURES: &[Feature] = &[
    Feature {
        name: "previous tractions of the normal part only or kept untouched",
        control: "P",
        supported: false,
        reason: "supported: P = 0 (next time step) and P = 2 (new sequence)",
        used: |c| digit("P", c.digits.p, matches!(c.digits.p, 1 | 3)),
    },
    Feature {
        name: "approximate normal problems (SDEC, KPEC, ANALYN)",
        control: "B",
        supported: false,
        reason: "supported: B = 0 (the full elastic normal problem), B = 1 (with a compressible sheet), B = 2, 3 (Hertz's elliptical or parabolic pressure) on a Hertzian geometry (IPOTCN < 0)",
        used: |c| {
            let hertz = matches!(c.state.potcon, Some(Potcon::Hertz { .. }));
            digit("B", c.digits.b, c.digits.b > 1 && !(matches!(c.digits.b, 2 | 3) && hertz))
        },
    },
    Feature {
        name: "a thin compressible elastic sheet",
        control: "B, FLXZ",
        supported: true,
        reason: "imported as [material] sheet_flexibility_mm3_per_n = FLXZ: u_z = FLXZ p_n added to the normal self-influence (docs/scene-format.md)",
        used: |c| digit("B", c.digits.b, c.digits.b == 1),
    },
    Feature {
        name: "traction bound from Hertz's pressure (elliptical or parabolic)",
        control: "B",
        supported: true,
        reason: "imported as `[normal] pressure = \"elliptical\"` (B = 2) or `\"parabolic\"` (B = 3): Hertz's pressure of the case's ellipse and FN at the element centres, the normal problem not solved (`m_sdis.f90`); `[normal] start_pressure` where only the case that starts a rolling history has it; with CONTACT's FASTSIM (M = 3) as `[model] pressure`",
        used: |c| {
            let hertz = matches!(c.state.potcon, Some(Potcon::Hertz { .. }));
            digit("B", c.digits.b, matches!(c.digits.b, 2 | 3) && hertz)
        },
    },
    Feature {
        name: "shifts and frictional compression",
        control: "T",
        supported: true,
        reason: "imported as `[rolling] motion = \"shift\"` (CKSI, CETA the shifts of a step [mm], CPHI its rotation), or as the shift that starts a rolling history (`[init] kind = \"shift\"`)",
        used: |c| digit("T", c.digits.t, c.digits.t == 1),
    },
    Feature {
        name: "frictionless compression",
        control: "T",
        supported: true,
        reason: "imported as a steady case at zero creepage (no tangential traction between quasi-identical bodies: the same normal solution)",
        used: |c| digit("T", c.digits.t, c.digits.t == 0),
    },
    Feature {
        name: "approach prescribed instead of the normal force",
        control: "N",
        supported: true,
        reason: "imported as the approach PEN: `[contact] pen_mm` in steady cases (T = 0, 3; one PEN per sweep), the creepage table's column pen_mm in shifts and transient rolling (T = 1, 2); the exact solver finds FN. On a Hertzian contact (IPOTCN = -1, -2, -3) CONTACT's `hzcalc3d` is followed: -3 keeps AA, BB and derives the curvatures from PEN, -1, -2 keep the curvatures and derive AA, BB (the grid) from PEN, so `contact.fn_n` is Hertz's load at PEN (FN = 2 pi E* PEN / (3 R_F(0, a^2, b^2))) and PEN stays one per Hertzian history",
        used: |c| digit("N", c.digits.n, c.digits.n == 0),
    },
    Feature {
        name: "prescribed tangential forces",
        control: "F",
        supported: true,
        reason: "imported as the table's fx_over_fn (F = 1) and fy_over_fn (F = 2): Fx/FN = −FX·FSTAT (scene::force_ratio)",
        used: |c| digit("F", c.digits.f, c.digits.f != 0 && matches!(c.digits.t, 1 | 2)),
    },
    Feature {
        name: "prescribed tangential forces in steady rolling",
        control: "F",
        supported: true,
        reason: "imported as a sweep's fx_over_fn (F = 1) and fy_over_fn (F = 2), or the step-0 row of a steady start: the exact solver finds CKSI (and CETA) by the same force iteration as in transient rolling",
        used: |c| digit("F", c.digits.f, c.digits.f != 0 && c.digits.t == 3),
    },
    Feature {
        name: "subsurface stresses",
        control: "S",
        supported: true,
        reason: "imported as [stress] (its ISUBS = 9 blocks as [[stress.block]], the case's row in its steps): the stresses in body 1 under the solved tractions, <solver>_stress.csv",
        used: |c| digit("S", c.digits.s, c.digits.s != 0 && explicit_points(c)),
    },
    Feature {
        name: "subsurface stresses at element centres, in body 2 or without points",
        control: "S, ISUBS",
        supported: true,
        reason: "read and not computed (they change no total): [stress] takes blocks of explicit points (ISUBS = 9) with Z >= 0 (body 1)",
        used: |c| {
            (c.digits.s != 0 && !explicit_points(c)).then(|| {
                let isubs: Vec<String> = c
                    .state
                    .subsurface
                    .iter()
                    .map(|b| match b {
                        SubsurfaceBlock::Points(_) => "9".to_string(),
                        SubsurfaceBlock::ElementCentres(i) => i.to_string(),
                    })
                    .collect();
                format!("S = {}, ISUBS = [{}]", c.digits.s, isubs.join(", "))
            })
        },
    },
    Feature {
        name: "friction varying per grid row with a law other than Coulomb's",
        control: "V, L",
        supported: false,
        reason: "supported: V = 3 with Coulomb friction (L = 0), V = 0 with every supported law",
        used: |c| (c.digits.v == 3 && c.state.friction_law != 0).then(|| format!("V = 3, L = {}", c.state.friction_law)),
    },
    Feature {
        name: "friction varying per grid row",
        control: "V",
        supported: true,
        reason: "imported as `[friction] law = \"coulomb\"` with `mu_rows`, the FSTAT of every row IY (CONTACT's one Coulomb coefficient), the nominal mu their largest; prescribed forces are over FN, not FSTAT FN (CONTACT's muscal = 1 with V = 3); the exact solver only",
        used: |c| digit("V", c.digits.v, c.digits.v == 3 && c.state.friction_law == 0),
    },
    Feature {
        name: "friction laws other than Coulomb's, the falling laws and the temperature law",
        control: "L",
        supported: false,
        reason: "supported: L = 0 (Coulomb), 2, 3, 4 (friction falling with the slip velocity, with its memory MEMDST, MEM_S0), 6 (friction of the surface temperature) or L = 1 keeping it",
        used: |c| digit("L (in force)", c.state.friction_law, !matches!(c.state.friction_law, 0 | 2..=4 | 6)),
    },
    Feature {
        name: "friction of the surface temperature",
        control: "L, FREF, TREF, DFHEAT, DTHEAT",
        supported: true,
        reason: "imported as [friction] law = \"temperature\", fref, tref_c, dfheat, dtheat_c (MEMDST, MEM_S0 as memory_mm, memory_s0_mm_s, relaxing at the rate of the start INISLP gives, [contact_solver] inislp): the exact model's fixed point between the tractions and the surface temperatures of their frictional heat (docs/models.md, \"Temperature-dependent friction\"), stopped at CONTACT's fixed 1e-4 ([contact_solver] tempdep_tolerance) or after CONTACT's max(1, MAXIN - 10) + 1 iterations (tempdep_max_iterations), damped by OMGSLP",
        used: |c| temperature_law(c).then(|| format!("L (in force) = 6: FREF, TREF, DFHEAT, DTHEAT = {:?}", c.state.friction)),
    },
    Feature {
        name: "friction of the surface temperature with a memory started from the previous case, or without surface temperatures",
        control: "L, MEMDST, INISLP, H",
        supported: false,
        reason: "supported: L = 6 with surface temperatures computed (H = 1, 3 in steady rolling) and MEMDST = 0, or a memory with INISLP != 0: CONTACT's memory with L = 6 relaxes at the rate of the slip velocity its iteration starts from, 0 (INISLP > 0) or VELOC (< 0); INISLP = 0 starts from the previous case's slip, which a steady case does not leave; without H the temperatures are never computed",
        used: |c| {
            let six = c.state.friction_law == 6;
            let from_previous = c.state.memory[0] > 1e-9 && c.state.slip_start.is_none_or(|(i, _)| i == 0);
            (six && (from_previous || !heat_carried(c))).then(|| {
                let inislp = c.state.slip_start.map_or(0, |(i, _)| i);
                format!("L = 6 with MEMDST = {}, INISLP = {inislp}, H = {}", c.state.memory[0], c.digits.h)
            })
        },
    },
    Feature {
        name: "static friction other than kinetic friction",
        control: "FSTAT, FKIN",
        supported: true,
        reason: "CONTACT's Coulomb law (L = 0) takes FSTAT as its one coefficient and overwrites FKIN with it (`fric_update` in m_friclaw.f90: fkin := fstat; the traction bound is FSTAT pn): mu = FSTAT",
        used: |c| {
            let f = &c.state.friction;
            (c.state.friction_law == 0 && f.len() == 2 && f[0] != f[1])
                .then(|| format!("FSTAT = {}, FKIN = {}", f[0], f[1]))
        },
    },
    Feature {
        name: "influence functions other than the half-space's with piecewise constant or bilinear tractions",
        control: "C",
        supported: false,
        reason: "supported: C = 2 (piecewise constant), 3 (bilinear) or 0, 1 keeping it; not the conformal (4) or numerical (9) ones",
        used: |c| digit("C", c.digits.c, matches!(c.digits.c, 4 | 9)),
    },
    Feature {
        name: "influence functions of the half-space with bilinear tractions",
        control: "C",
        supported: true,
        reason: "imported as `[contact_solver] influence = \"bilinear\"`: the exact solver's kernels of the bilinear hat per element centre (physics::halfspace::bilinear)",
        used: |c| digit("C", c.digits.c, c.digits.c == 3),
    },
    Feature {
        name: "material models other than elastic",
        control: "M",
        supported: false,
        reason: "supported: M = 0 (elastic half-spaces), M = 1 (viscoelastic bodies, its own rows), M = 4 (an elastic interface layer, its own rows), M = 3 (CONTACT's FASTSIM, also with FX prescribed, F = 1) and M = 5 (its modified FaStrip, with Coulomb friction rolling along +x) in steady rolling (T = 3) with the creepages given (F = 0), one friction coefficient (V = 0) and Hertz's pressure (B = 2, 3); the simplified theory with one flexibility (2) and the original FaStrip (6, 7) are not",
        used: |c| digit("M", c.digits.m, !matches!(c.digits.m, 0 | 1 | 4) && contact_simplified(c).is_none()),
    },
    Feature {
        name: "viscoelastic bodies",
        control: "M, FG, TC",
        supported: true,
        reason: "imported as [material] visco_ratio = FG, visco_time_s = TC (both bodies alike; none where FG = 0): the exact solver's influence coefficients carry the standard linear solid's memory over the relaxation distance VELOC·TC (docs/models.md, \"Viscoelastic bodies\")",
        used: |c| {
            let [fg, _, tc, _] = c.state.visco_in_force()?;
            Some(format!("M = 1, FG = {fg}, TC = {tc}"))
        },
    },
    Feature {
        name: "viscoelastic bodies of different constants",
        control: "M, FG, TC, POISS, GG",
        supported: false,
        reason: "supported: FG 1 = FG 2 and TC 1 = TC 2 with quasi-identical elastic constants (K = 0); where the two differ CONTACT couples the normal and tangential problems through the memory (`m_visc.f90`, one integral per body) or, with TC 1 = TC 2 and K = 0, takes FG 1 for both bodies, neither modelled",
        used: |c| {
            let [fg1, fg2, tc1, tc2] = c.state.visco_in_force()?;
            let k = crate::physics::material::combine_bodies(c.state.poiss, c.state.gg_mpa).k;
            (fg1 != fg2 || tc1 != tc2 || k != 0.0).then(|| format!("M = 1, FG = {fg1}, {fg2}, TC = {tc1}, {tc2}, K = {k}"))
        },
    },
    Feature {
        name: "viscoelastic bodies outside steady rolling along +x with piecewise constant tractions",
        control: "M, T, CHI, C",
        supported: false,
        reason: "supported: M = 1 in steady rolling (T = 3) at CHI = 0 with C = 2: CONTACT's memory integral holds for tractions that stand still in the contact frame, it sets CHI = 0 with M = 1 (`m_sdis.f90`), and with C = 3 it adds the memory of piecewise constant tractions to the bilinear elastic coefficients (`m_visc.f90`), none of which a scene says",
        used: |c| {
            c.state.visco_in_force()?;
            let chi_deg = c.state.chi_rad.to_degrees();
            let inflcf = c.state.inflcf;
            (c.digits.t != 3 || chi_deg.abs() > 1e-3 || inflcf == 3)
                .then(|| format!("M = 1, T = {}, CHI = {chi_deg} deg, C3 = {inflcf}", c.digits.t))
        },
    },
    Feature {
        name: "an elastic interface layer",
        control: "M, GG3, LAYTHK",
        supported: true,
        reason: "imported as [material] layer_g_mpa = GG3, layer_thickness_mm = LAYTHK (none where LAYTHK < 1e-10, as CONTACT): the exact solver adds the layer's flexibility LAYTHK/GG3 to the half-spaces' tangential self-influence, carried with the material in steady rolling and in place in transient rolling, as CONTACT (docs/models.md, \"Interface layer\")",
        used: |c| {
            let [gg3, laythk, ..] = layer_in_force(c)?;
            Some(format!("M = 4, GG3 = {gg3}, LAYTHK = {laythk}"))
        },
    },
    Feature {
        name: "an elasto-plastic interface layer",
        control: "M, TAU_C0, K_TAU",
        supported: true,
        reason: "imported as [material] layer_yield_mpa = TAU_C0 and layer_hardening_mpa_per_mm = K_TAU (where not 0), with layer_thickness_mm = 0 where LAYTHK = 0 (the bodies' surface yields): the traction bound min(mu pn, tau_c) per element, as CONTACT's `tangcg` and `gdsteady` set it, tau_c = TAU_C0 + K_TAU times the element's accumulated plastic slip, as its `plstrc` moves it; in steady rolling each element's tau_c taken from the element upstream, as its `stdygs` carries it; in transient rolling moved with the material by DQ before each step, as its `set_prev_data` shifts TAUCS (docs/models.md, \"Interface layer\")",
        used: |c| plastic_layer(c).map(|[_, _, tau_c0, k_tau]| format!("M = 4, TAU_C0 = {tau_c0}, K_TAU = {k_tau}")),
    },
    Feature {
        name: "an elasto-plastic interface layer that hardens or softens in transient rolling at another CHI, or with falling friction or dissimilar bodies",
        control: "M, TAU_C0, K_TAU, LAYTHK, T, CHI, L, GG 1, 2",
        supported: false,
        reason: "supported: TAU_C0 = 0 (an elastic layer), or TAU_C0 > 0 (on a layer, or LAYTHK = 0: the bodies' surface) with Coulomb friction (L = 0) and quasi-identical bodies, K_TAU != 0 in shifts (T = 1), steady rolling (T = 3, each limit carried from the element upstream as CONTACT's `stdygs`) and transient rolling along x (T = 2 at CHI = 0 or 180: each element's limit moved with the material by DQ before the step, as CONTACT's `set_prev_data` shifts TAUCS with `gf3_dq_shift`, TAU_C0 entering at the leading edge); transient rolling with a moving limit at another CHI and the combinations with falling friction or K != 0 are not modelled",
        used: |c| {
            let [_, laythk, tau_c0, k_tau] = layer_in_force(c)?;
            let other = plastic_layer(c).is_none();
            (tau_c0 > 1e-10 && other).then(|| {
                let (t, l) = (c.digits.t, c.state.friction_law);
                format!("M = 4, TAU_C0 = {tau_c0}, K_TAU = {k_tau}, LAYTHK = {laythk}, T = {t}, L = {l}")
            })
        },
    },
    Feature {
        name: "an interface layer in transient rolling",
        control: "M, LAYTHK, T",
        supported: true,
        reason: "imported as the layer (above): in transient rolling the exact solver takes the layer's previous displacement at the element's own index on the moved grid, as CONTACT does (`stang_rhs` in `m_stang.f90` forms the previous displacement from the previous tractions PV with the shifted coefficients CV, whose layer term, `gf3_aijpj` in `m_aijpj.f90`, adds FLX times PV of the element itself), not with the material as in steady rolling (docs/models.md, \"Interface layer\")",
        used: |c| {
            let flexible = layer_in_force(c).filter(|l| l[1] >= 1e-10 && c.digits.t == 2);
            flexible.map(|[_, laythk, ..]| format!("M = 4, LAYTHK = {laythk}, T = 2"))
        },
    },
    Feature {
        name: "CONTACT's modified FaStrip (strip theory with the simplified theory)",
        control: "M",
        supported: true,
        reason: "imported as solvers = [\"fastrip_contact\"] (CONTACT's modified FaStrip: its FASTSIM per row, then Kalker's strip theory's adhesion zone on the equivalent ellipse, docs/models.md) with `[model] pressure` as for M = 3",
        used: |c| contact_fastrip(c).then(|| format!("M = 5, B = {}", c.digits.b)),
    },
    Feature {
        name: "CONTACT's FASTSIM (the simplified theory with three flexibilities)",
        control: "M",
        supported: true,
        reason: "imported as solvers = [\"fastsim_contact\"] (CONTACT's FASTSIM: its coefficient table, blended flexibilities, rigid slip and totals, docs/models.md) with `[model] pressure` Hertz's parabolic (B = 3) or \"ellipsoidal\" (B = 2) pressure and `slope_reduction` = [K0_MF, ALFAMF, BETAMF] where they are not 1, 1, 1",
        used: |c| contact_fastsim(c).then(|| format!("M = 3, B = {}", c.digits.b)),
    },
    Feature {
        name: "damping",
        control: "M2",
        supported: false,
        reason: "supported: M2 = 0 or 1 (no damping)",
        used: |c| digit("M2", c.digits.m2, c.digits.m2 == 2),
    },
    Feature {
        name: "an extra term of the rigid slip",
        control: "E",
        supported: false,
        reason: "supported: E = 0 (no extra term) and E = 9 (an extra rigid slip per element, `[creepage] extra_slip`)",
        used: |c| (c.state.extra_rhs && c.state.exrhs.is_none()).then(|| format!("E = {}", c.digits.e)),
    },
    Feature {
        name: "surface temperatures",
        control: "H, BKTEMP, HEATCP, LAMBDA, DENS",
        supported: true,
        reason: "imported as [material] bulk1_c, heat_capacity1_j_per_kg_c, conductivity1_w_per_mm_c, density1_kg_per_mm3 and body 2's: the exact model computes both bodies' surface temperatures after the tractions, their largest over the contact in the columns temp1_max_c, temp2_max_c (docs/models.md, \"Surface temperatures\")",
        used: |c| heat_carried(c).then(|| format!("H = {}", c.digits.h)),
    },
    Feature {
        name: "surface temperatures outside steady rolling, with a plastic layer, or without their data",
        control: "H, T, M, TAU_C0",
        supported: false,
        reason: "supported: H = 1, 3 in steady rolling (T = 3, as CONTACT's `calc_temp`) on elastic bodies or an elastic layer, after H = 3 gave the data; the heat of a plastic layer's work (BETAPL) is not carried",
        used: |c| {
            let refused = c.digits.h != 0 && !heat_carried(c);
            refused.then(|| format!("H = {}, T = {}, M = {}", c.digits.h, c.digits.t, c.digits.m))
        },
    },
    Feature {
        name: "preprocessing only (the case is not solved)",
        control: "R",
        supported: false,
        reason: "supported: R = 0, 1 (the case is solved)",
        used: |c| digit("R", c.digits.r, c.digits.r >= 2),
    },
    Feature {
        name: "debug output and solver settings",
        control: "X, G, MAXGS..EPS",
        supported: true,
        reason: "read and not carried: this project's solver has its own stopping rule ([contact_solver]); with a falling law INISLP, OMGSLP are carried (their own row)",
        used: |c| digit("G", c.digits.g, c.digits.g != 1),
    },
    Feature {
        name: "the slip-velocity iteration of a falling law, the temperature iteration of L = 6",
        control: "INISLP, OMGSLP",
        supported: true,
        reason: "carried as [contact_solver] inislp (0: previous, > 0: below, < 0: above) and omgslp, stopped at CONTACT's fixed 1e-3 (veldep_tolerance); with L = 6 OMGSLP, and INISLP where a memory takes its rate from it, stopped at CONTACT's 1e-4 (tempdep_tolerance) or its MAXIN's iterations (tempdep_max_iterations); with L = 2, 3, 4 MAXIN is not carried (190 iterations at most)",
        used: |c| {
            let (inislp, omgslp) = c.state.slip_start.unwrap_or((0, crate::scene::OMGSLP));
            matches!(c.state.friction_law, 2..=4 | 6).then(|| format!("INISLP = {inislp}, OMGSLP = {omgslp}"))
        },
    },
    Feature {
        name: "a rolling direction other than +x with a falling friction law, or other than +x or -x in steady rolling",
        control: "CHI",
        supported: false,
        reason: "supported: CHI = 0 or 180 degrees (within 0.01 rad, as CONTACT) in steady rolling, any CHI in transient rolling (T = 2), with Coulomb friction where it is not 0 ([rolling] chi_deg)",
        used: |c| {
            let chi = c.state.chi_rad;
            let zero = super::scene::chi_deg(chi) == 0.0;
            let steady_oblique = c.digits.t == 3 && !super::scene::along_x(chi);
            // The temperature law (L = 6) is steady, where -x is the mirrored solve.
            let falling_turned = !zero && c.state.friction_law != 0 && c.state.friction_law != 6;
            (c.digits.t >= 2 && (steady_oblique || falling_turned)).then(|| format!("CHI = {chi} rad"))
        },
    },
    Feature {
        name: "a rolling direction other than +x or -x in transient rolling",
        control: "CHI",
        supported: true,
        reason: "imported as [rolling] chi_deg in degrees: the exact solver rolls along CHI (the previous tractions shifted by DQ along it, the spin term's offset DQ/6 along it, as CONTACT)",
        used: |c| {
            let chi = c.state.chi_rad;
            (c.digits.t == 2 && !super::scene::along_x(chi)).then(|| format!("CHI = {chi} rad"))
        },
    },
    Feature {
        name: "a spin centre away from the origin",
        control: "SPINXO, SPINYO",
        supported: false,
        reason: "supported: SPINXO = SPINYO = 0",
        used: |c| {
            let s = c.state.spin_centre_mm;
            (s != [0.0, 0.0]).then(|| format!("SPINXO = {}, SPINYO = {}", s[0], s[1]))
        },
    },
    Feature {
        name: "dissimilar materials (normal-tangential coupling)",
        control: "POISS 1, 2, GG 1, 2, MAXOUT",
        supported: true,
        reason: "imported as [material] g1_mpa, poisson1, g2_mpa, poisson2 (Kalker's K from them) and [contact_solver] max_outer = MAXOUT: the exact solver alternates the normal and tangential problems as CONTACT's Panagiotopoulos process",
        used: |c| {
            let m = combine_bodies(c.state.poiss, c.state.gg_mpa);
            (m.k != 0.0).then(|| format!("K = {:e}", m.k))
        },
    },
    Feature {
        name: "Hertzian options other than AA, BB, A1, B1 or A1, AOB",
        control: "IPOTCN",
        supported: false,
        reason: "supported: IPOTCN = -3 (AA, BB, SCALE), -1 (A1, B1, SCALE), -2 (A1, AOB, SCALE) or 1 to 4 (a grid)",
        used: |c| match &c.state.potcon {
            Some(Potcon::Hertz { ipotcn, .. }) if !(-3..=-1).contains(ipotcn) => Some(format!("IPOTCN = {ipotcn}")),
            _ => None,
        },
    },
    Feature {
        name: "undeformed distances other than quadratic, circular in x or per element",
        control: "IBASE",
        supported: false,
        reason: "supported: IBASE = 1 (B1..B6), 2 (circular in x, pointwise in y) or 9 (h per element)",
        used: |c| match (&c.state.potcon, &c.state.undeformed) {
            (Some(Potcon::Grid { .. }), Some(u)) if !matches!(u.ibase, 1 | 2 | 9) => {
                Some(format!("IBASE = {}", u.ibase))
            }
            (Some(Potcon::Grid { .. }), None) => Some("a grid without IBASE (Z = 2 never read)".into()),
            _ => None,
        },
    },
    Feature {
        name: "an undeformed distance circular in x, pointwise in y",
        control: "IBASE",
        supported: true,
        reason: "imported as h per element (IBASE = 9) as CONTACT evaluates it: the NN heights linear in y plus the parabola (x - XM)^2/(2 RX1) at the element centres",
        used: |c| match (&c.state.potcon, &c.state.undeformed) {
            (Some(Potcon::Grid { .. }), Some(u)) if u.ibase == 2 => Some("IBASE = 2".into()),
            _ => None,
        },
    },
    Feature {
        name: "a planform",
        control: "IPLAN",
        supported: false,
        reason: "supported: IPLAN = 1 (unrestricted)",
        used: |c| match (&c.state.potcon, &c.state.undeformed) {
            (Some(Potcon::Grid { .. }), Some(u)) if u.iplan != 1 => Some(format!("IPLAN = {}", u.iplan)),
            _ => None,
        },
    },
];

/// Whether a case is CONTACT's FASTSIM as the import carries it: M = 3 in steady rolling (T = 3)
/// with the creepages given (F = 0) or FX prescribed (F = 1), one friction coefficient (V = 0) and
/// Hertz's pressure imposed (B = 2, 3) on a Hertzian geometry (IPOTCN < 0).
pub fn contact_fastsim(c: &Case3) -> bool {
    c.digits.m == 3 && simplified_setting(c, 1)
}

/// Whether a case is CONTACT's modified FaStrip as the import carries it: M = 5 in the setting of
/// [`contact_fastsim`], with Coulomb friction (L = 0) rolling along +x (CHI = 0).
pub fn contact_fastrip(c: &Case3) -> bool {
    let along_x = super::scene::chi_deg(c.state.chi_rad) == 0.0;
    c.digits.m == 5 && simplified_setting(c, 0) && c.state.friction_law == 0 && along_x
}

/// GG3, LAYTHK, TAU_C0, K_TAU of an elasto-plastic layer the import carries: TAU_C0 > 0 (on a
/// layer, or LAYTHK = 0: the bodies' surface), K_TAU ≠ 0 in transient rolling (T = 2) only along
/// x (CHI = 0 or 180), Coulomb friction, K = 0.
pub fn plastic_layer(c: &Case3) -> Option<[f64; 4]> {
    let l = layer_in_force(c)?;
    let coupled = combine_bodies(c.state.poiss, c.state.gg_mpa).k != 0.0;
    let along_x = super::scene::along_x(c.state.chi_rad);
    let moving = l[3] != 0.0 && c.digits.t == 2 && !along_x;
    let carried = l[2] > 1e-10 && !moving && c.state.friction_law == 0 && !coupled;
    carried.then_some(l)
}

/// GG3, LAYTHK, TAU_C0, K_TAU of the case's interface layer: M = 4 with the values last read.
pub fn layer_in_force(c: &Case3) -> Option<[f64; 4]> {
    c.state.layer_in_force()
}

/// The model that runs a case of CONTACT's simplified theories, if the import carries it.
pub fn contact_simplified(c: &Case3) -> Option<&'static str> {
    if contact_fastsim(c) {
        Some(crate::solvers::fastsim_contact::NAME)
    } else if contact_fastrip(c) {
        Some(crate::solvers::fastrip_contact::NAME)
    } else {
        None
    }
}

/// Steady rolling (T = 3) with the creepages given (F = 0) or FX prescribed (F = 1, where `f_max`
/// allows it), one friction coefficient (V = 0) and Hertz's pressure imposed (B = 2, 3) on a
/// Hertzian geometry (IPOTCN < 0).
fn simplified_setting(c: &Case3, f_max: u8) -> bool {
    let hertz = matches!(c.state.potcon, Some(Potcon::Hertz { .. }));
    let d = c.digits;
    d.t == 3 && d.f <= f_max && d.v == 0 && matches!(d.b, 2 | 3) && hertz
}

/// The refusals (feature, value) and notes of a case.
pub fn assess(case: &Case3) -> (Vec<String>, Vec<String>) {
    let used = FEATURES
        .iter()
        .filter_map(|f| (f.used)(case).map(|v| (f.supported, format!("{v}: {} ({})", f.name, f.reason))));
    refused_and_notes(used)
}

/// Lines of (supported, text) split into the refusals and the notes, each in order.
pub fn refused_and_notes(lines: impl Iterator<Item = (bool, String)>) -> (Vec<String>, Vec<String>) {
    let (notes, refused): (Vec<_>, Vec<_>) = lines.partition(|(supported, _)| *supported);
    (refused.into_iter().map(|(_, l)| l).collect(), notes.into_iter().map(|(_, l)| l).collect())
}

/// A feature of CONTACT's module 1 (a row of [`WHEELRAIL_FEATURES`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WheelRailFeature {
    RollerRig,
    TransientContact,
    CompressibleLayer,
    ApproximateNormalProblem,
    PrescribedVerticalForce,
    PrescribedLongitudinalForce,
    MasslessRail,
    VaryingFriction,
    FrictionLaw,
    ContactApproach,
    ConformalInfluence,
    BilinearInfluence,
    MaterialModel,
    DissimilarMaterials,
    Damping,
    Temperatures,
    Subsurface,
    PreprocessingOnly,
    SolverSettings,
    VariableRailProfile,
    OutOfRoundWheel,
    ProfileSmoothing,
    RailDeviation,
    TrackCurvature,
    TapeCircle,
    WheelDeviation,
    PatchCombination,
}

/// "D (in force) = d" when the case's contact approach (CONTACT's D) is `d`.
fn approach_in_force(c: &WheelRailCase, d: u8) -> Option<String> {
    let m = c.state.discretisation.as_ref()?.method;
    (m == d).then(|| format!("D (in force) = {m}"))
}

/// One row of the module-1 table.
pub struct WheelRailRow {
    pub feature: WheelRailFeature,
    pub name: &'static str,
    pub control: &'static str,
    /// Whether the project's physics and its wheel–rail geometry are to carry it (false: a case
    /// using it is refused; the conversion to scenes does not exist yet).
    pub supported: bool,
    pub reason: &'static str,
    pub used: fn(&WheelRailCase) -> Option<String>,
}

/// A feature a module-1 case uses: its row and the value the case gives it.
#[derive(Debug, Clone, PartialEq)]
pub struct FeatureUse {
    pub feature: WheelRailFeature,
    pub name: &'static str,
    pub control: &'static str,
    pub supported: bool,
    pub reason: &'static str,
    pub value: String,
}

impl std::fmt::Display for FeatureUse {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {} ({})", self.value, self.name, self.reason)
    }
}

/// M = 3 (CONTACT's FASTSIM) without slope reduction (K0_MF = ALFAMF = BETAMF = 1).
pub fn plain_fastsim(c: &WheelRailCase) -> bool {
    let model = c.state.material.as_ref().map(|m| m.model);
    c.digits.m == 3
        && matches!(model, Some(MaterialModel::SlopeReduction { k0_mf, alfamf, betamf }) if [k0_mf, alfamf, betamf] == [1.0; 3])
}

/// KPEC or ANALYN (B = 5, 6) as the wheel–rail scene carries them: with CONTACT's FASTSIM without
/// slope reduction, or frictionless (T = 0: no tangential theory at all).
pub fn approximate_supported(c: &WheelRailCase) -> bool {
    plain_fastsim(c) || c.digits.t == 0
}

/// F = 1 as the wheel–rail scene carries it: with FZ prescribed (N = 1), in steady rolling
/// (T = 3) with the exact theory (B = 0, M = 0).
fn longitudinal_force_supported(c: &WheelRailCase) -> bool {
    let d = c.digits;
    d.n == 1 && d.t == 3 && d.b == 0 && d.m == 0
}

/// Whether a module-1 case's surface temperatures are carried: H = 1, 3 with their data, in
/// steady rolling (T = 3).
pub fn wr_heat_carried(c: &WheelRailCase) -> bool {
    matches!(c.digits.h, 1 | 3) && c.digits.t == 3 && c.state.heat.is_some()
}

/// Whether a module-1 case's friction of the temperature is carried: L = 6 with one set (V = 0)
/// or sets across the rail or along the track (V = 1, 2), no memory, its surface temperatures
/// carried.
pub fn wr_temperature_law_carried(c: &WheelRailCase) -> bool {
    let Some(f) = c.state.friction.as_ref().filter(|f| f.law == 6) else { return false };
    (f.variation != FrictionVariation::Uniform || f.sets.len() == 1)
        && f.memory.is_none_or(|m| m[0] == 0.0)
        && wr_heat_carried(c)
}

/// A roller rig as the wheel–rail scene carries it: steady rolling (T = 3) or frictionless
/// compression (T = 0) with VPITCH given (F = 0), the planar contact locus (D = 2, or 3 with the
/// rigid slip on the surfaces) or the grid search (D = 5), the rail placed absolutely, not a
/// slices file.
fn roller_supported(c: &WheelRailCase) -> bool {
    let d = c.digits;
    let planar = c.state.discretisation.as_ref().is_some_and(|disc| matches!(disc.method, 2 | 3 | 5));
    let absolute = c.state.track.is_some_and(|t| matches!(t.placement, RailPlacement::Absolute { .. }));
    let slices = c.state.rail_profile.as_ref().is_some_and(|p| p.format() == ProfileFormat::Slices);
    matches!(d.t, 0 | 3) && d.f == 0 && planar && absolute && !slices
}

fn wr_digit(name: &str, v: u8, used: bool) -> Option<String> {
    used.then(|| format!("{name} = {v}"))
}

/// Every module-1 feature a case can use, in the order of the input (user guide, control digits
/// of module 1, and `wr_input`).
pub const WHEELRAIL_FEATURES: &[WheelRailRow] = &[
    WheelRailRow {
        feature: WheelRailFeature::RollerRig,
        name: "a wheel on a roller rig",
        control: "C",
        supported: true,
        reason: "imported as [rail] roller_radius_mm = NOMRAD_R, roller_vpitch_rad_s = VPITCH_ROL, the cases' vs_mm_s 0: the rail profile revolved about the roller's axis (docs/wheelrail.md, \"A wheel on a roller rig\")",
        used: |c| wr_digit("C", c.digits.c, c.digits.roller_rig() && roller_supported(c)),
    },
    WheelRailRow {
        feature: WheelRailFeature::RollerRig,
        name: "a wheel on a roller rig beyond steady rolling on the planar contact locus",
        control: "C, T, F, D, GAUGHT",
        supported: false,
        reason: "supported on a roller rig: steady rolling (T = 3) or frictionless compression (T = 0) with VPITCH given (F = 0), the planar contact locus (D = 2, or 3 with the rigid slip on the actual surfaces) or the grid search (D = 5), the rail placed absolutely (GAUGHT ≤ 0) by a profile file",
        used: |c| {
            (c.digits.roller_rig() && !roller_supported(c)).then(|| {
                let d = c.state.discretisation.as_ref().map_or(0, |d| d.method);
                format!("C = {}, T = {}, F = {}, D = {d}", c.digits.c, c.digits.t, c.digits.f)
            })
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::TransientContact,
        name: "transient rolling",
        control: "T",
        supported: false,
        reason: "supported: T = 2 from rest (P = 2) or continuing a steady case (P = 0 after T = 3) or a transient one; after another run (P = 1, 3) it needs the state of a run before, not carried",
        used: |c| (c.digits.t == 2 && matches!(c.digits.p, 1 | 3)).then(|| format!("T = 2, P = {}", c.digits.p)),
    },
    WheelRailRow {
        feature: WheelRailFeature::TransientContact,
        name: "transient rolling continuing a sequence",
        control: "T, P",
        supported: true,
        reason: "imported as [wheelrail] motion = \"rolling_sequence\", dq_rel = DQREL with the steady case (T = 3) or the step from rest (P = 2, start = \"rest\") that starts it: each step the previous tractions on CONTACT's super-grid (fixed laterally in the rail's material, moving with the wheelset along the track), rolled by DQ, the exact theory (docs/wheelrail.md)",
        used: |c| (c.digits.t == 2 && matches!(c.digits.p, 0 | 2)).then(|| format!("T = 2, P = {}", c.digits.p)),
    },
    WheelRailRow {
        feature: WheelRailFeature::TransientContact,
        name: "a shift from rest",
        control: "T, P",
        supported: true,
        reason: "imported as [wheelrail] motion = \"shift\", s_mm = S_WS: one shift step from zero tractions (the velocities are the step's shifts, dt = 1) on CONTACT's material-fixed grid (x from -S_WS, s along the rail profile), the exact theory (docs/wheelrail.md)",
        used: |c| (c.digits.t == 1 && c.digits.p == 2).then(|| "T = 1, P = 2".to_string()),
    },
    WheelRailRow {
        feature: WheelRailFeature::TransientContact,
        name: "a shift continuing a sequence",
        control: "T, P",
        supported: true,
        reason: "imported as [wheelrail] motion = \"shift_sequence\" with the shift before it (or the steady case before it: start = \"steady\"): the previous case's tractions carried on CONTACT's material-fixed grid, its patches connected by overlap, split, merged or kept out of contact (docs/wheelrail.md)",
        used: |c| (c.digits.t == 1 && c.digits.p == 0).then(|| "T = 1, P = 0".to_string()),
    },
    WheelRailRow {
        feature: WheelRailFeature::TransientContact,
        name: "a shift after a case of another run",
        control: "T, P",
        supported: false,
        reason: "supported: T = 1 from rest (P = 2) or continuing the case before (P = 0); P = 1 (a new sequence keeping the state) and P = 3 (the steady state as the previous one) are not carried",
        used: |c| (c.digits.t == 1 && matches!(c.digits.p, 1 | 3)).then(|| format!("T = 1, P = {}", c.digits.p)),
    },
    WheelRailRow {
        feature: WheelRailFeature::CompressibleLayer,
        name: "a thin compressible elastic sheet",
        control: "B, FLXZ",
        supported: true,
        reason: "imported as [material] sheet_flexibility_mm3_per_n = FLXZ: u_z = FLXZ p_n added to the normal self-influence (docs/scene-format.md)",
        used: |c| wr_digit("B", c.digits.b, c.digits.b == 1),
    },
    WheelRailRow {
        feature: WheelRailFeature::ApproximateNormalProblem,
        name: "approximate normal problems (KPEC, ANALYN) with FASTSIM",
        control: "B, M",
        supported: true,
        reason: "imported as solvers = [\"kpec\"] (B = 5) or [\"analyn\"] (B = 6) with M = 3 (CONTACT's FASTSIM, no slope reduction) or in frictionless compression (T = 0, any M): each patch's pressure from the approximation at the approach the wheelset's height sets, the height balancing FZ with the approximation's own forces (docs/wheelrail.md)",
        used: |c| (matches!(c.digits.b, 5 | 6) && approximate_supported(c)).then(|| format!("B = {}, M = {}", c.digits.b, c.digits.m)),
    },
    WheelRailRow {
        feature: WheelRailFeature::ApproximateNormalProblem,
        name: "approximate normal problems (KPEC, ANALYN) without FASTSIM",
        control: "B, M",
        supported: false,
        reason: "supported: B = 5, 6 with M = 3 (FASTSIM, K0_MF = ALFAMF = BETAMF = 1) or T = 0 (frictionless), B = 0",
        used: |c| {
            (matches!(c.digits.b, 5 | 6) && !approximate_supported(c))
                .then(|| format!("B = {}, M = {}", c.digits.b, c.digits.m))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::PrescribedVerticalForce,
        name: "the vertical force prescribed instead of the wheelset height",
        control: "N, FZ",
        supported: true,
        reason: "the wheelset height Z_WS is found for FZ on the rail, as CONTACT's total-force iteration does",
        used: |c| wr_digit("N", c.digits.n, c.digits.n == 1),
    },
    WheelRailRow {
        feature: WheelRailFeature::PrescribedLongitudinalForce,
        name: "the longitudinal force prescribed instead of the pitch velocity",
        control: "F, FX_WS",
        supported: true,
        reason: "imported as [cases] longitudinal = \"force\" with the column fx_ws_n: the pitch velocity VPITCH found so that the exact theory's FX(WS) is FX_WS, with FZ prescribed (N = 1), as CONTACT's secant iteration does (docs/wheelrail.md)",
        used: |c| wr_digit("F", c.digits.f, c.digits.f == 1 && longitudinal_force_supported(c)),
    },
    WheelRailRow {
        feature: WheelRailFeature::PrescribedLongitudinalForce,
        name: "the longitudinal force prescribed with the height, frictionless, or with a simplified theory",
        control: "F, N, T, B, M",
        supported: false,
        reason: "supported: F = 1 with N = 1 (CONTACT refuses N = 0), steady rolling (T = 3) and the exact theory (B = 0, M = 0): CONTACT finds VPITCH with the case's own model, this project with the exact theory",
        used: |c| {
            (c.digits.f == 1 && !longitudinal_force_supported(c))
                .then(|| format!("F = 1 with N = {}, T = {}, B = {}, M = {}", c.digits.n, c.digits.t, c.digits.b, c.digits.m))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::PrescribedLongitudinalForce,
        name: "the longitudinal moment prescribed instead of the pitch velocity",
        control: "F, MY_WS",
        supported: false,
        reason: "supported: F = 0 (VPITCH given) and F = 1 (FX_WS given). CONTACT itself does not solve F = 2: its user guide lists the digit only in a comment, and its secant (wr_contact_fx_secant) then drives FX_WS to the last one an F = 1 case gave (zero if none), never MY_WS: its printed results are not those of a prescribed moment",
        used: |c| wr_digit("F", c.digits.f, c.digits.f == 2),
    },
    WheelRailRow {
        feature: WheelRailFeature::MasslessRail,
        name: "a massless rail deflecting under the contact forces",
        control: "F, KYRAIL..DYSTEP0",
        supported: true,
        reason: "carried as [massless_rail] ky_n_per_mm = KYRAIL, fy_n = FYRAIL, kz_n_per_mm = KZRAIL, fz_n = FZRAIL, dy_step_mm = DYSTEP0: the rail's deflections DY_DEFL, DZ_DEFL found so that its springs balance the contact forces (docs/wheelrail.md \"A massless rail\"), in steady rolling with VPITCH given",
        used: |c| wr_digit("F", c.digits.f, c.digits.f == 3),
    },
    WheelRailRow {
        feature: WheelRailFeature::VaryingFriction,
        name: "friction varying across the rail (contact angle) or along the track",
        control: "V, NVF, ALPHA/SVF",
        supported: true,
        reason: "carried as [wheelrail] mu_by = \"contact_angle\" (V = 1: each patch's mu at its contact angle on the wheel; with the conformal approach, D = 4, each grid row's mu at the row's inclination) or \"track_s\" (V = 2: mu at S_WS), mu_at, mu_values = FSTAT, as CONTACT takes them",
        used: |c| {
            let f = c.state.friction.as_ref()?;
            (f.variation != FrictionVariation::Uniform).then(|| format!("V = {} with NVF = {}", c.digits.v, f.sets.len()))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::FrictionLaw,
        name: "temperature-dependent friction",
        control: "L",
        supported: false,
        reason: "supported: L = 0 (Coulomb) and 2, 3, 4 (friction falling with the slip velocity, with its memory), or L = 1 keeping them",
        used: |c| c.state.friction.as_ref().filter(|f| f.law == 6).map(|_| "L (in force) = 6".to_string()),
    },
    WheelRailRow {
        feature: WheelRailFeature::ContactApproach,
        name: "contact approaches other than the planar one with the contact locus",
        control: "D",
        supported: false,
        reason: "supported: D = 2 (planar contact, contact locus, weighted reference), D = 3 (the same with the rigid slip on the actual surfaces), D = 4 (conformal), D = 5 (the planar one with the brute-force grid search, [wheelrail] contact_search = \"grid\"), D = 6 (that search on its finer mesh for steep slopes, \"grid_steep\") or D = 0, 1 keeping them; not 7 (the initial contact point as the reference) or 8 (oblique views on the contact locus), which stop CONTACT's own build with a segmentation fault (no result to match), nor 9 (the grid search in oblique views)",
        used: |c| {
            let m = c.state.discretisation.as_ref()?.method;
            (!matches!(m, 2..=6)).then(|| format!("D (in force) = {m}"))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::ContactApproach,
        name: "planar contact with the rigid slip on the actual surfaces",
        control: "D",
        supported: true,
        reason: "carried as [wheelrail] approach = \"planar_surface_slip\" (D = 3, docs/wheelrail.md \"Rigid slip on the actual surfaces\"): the planar patch's grid and gap, the rigid slip of the rail's (or roller's) and the wheel's material velocities at every element's points of both surfaces, its least-squares creepages printed, the rest an extra rigid slip per element (steady rolling, shifts and transient rolling); refused where a case also takes frictionless compression, dissimilar bodies or a simplified model (named by the scene's reader)",
        used: |c| approach_in_force(c, 3),
    },
    WheelRailRow {
        feature: WheelRailFeature::ContactApproach,
        name: "the conformal approach",
        control: "D",
        supported: true,
        reason: "carried as [wheelrail] approach = \"conformal\" (D = 4, docs/wheelrail.md \"The conformal approach\"): each patch on a curved reference midway between the surfaces (regions between D_COMB and D_SEP apart its blended sub-patches), its rigid slip on the actual surfaces, the tractions turned back to the tangent plane, in steady rolling, shifts and transient rolling (the previous tractions on the super-grid's curved rows); refused where a case also takes frictionless compression, dissimilar bodies or a simplified model (named by the scene's reader)",
        used: |c| approach_in_force(c, 4),
    },
    WheelRailRow {
        feature: WheelRailFeature::ContactApproach,
        name: "the brute-force grid search for the contact patches",
        control: "D",
        supported: true,
        reason: "carried as [wheelrail] contact_search = \"grid\" (D = 5): the round wheel revolved over x in +-R/8 (compute_round_whl), the gap on CONTACT's uniform mesh over it and the rail (a rail slices file: each mesh column's own cross-section), its local minima grown to their bounding boxes (wheelrail::brute, the search of out-of-round wheels); the patches then as with D = 2",
        used: |c| approach_in_force(c, 5),
    },
    WheelRailRow {
        feature: WheelRailFeature::ContactApproach,
        name: "the grid search for steep slopes",
        control: "D",
        supported: true,
        reason: "carried as [wheelrail] contact_search = \"grid_steep\" (D = 6, use_steep_slopes): the grid search of D = 5 with the gap mesh's lateral step 0.3 DS instead of 0.75 DS and a round wheel revolved over x in +-0.242 R (sin 14 deg) instead of +-R/8",
        used: |c| approach_in_force(c, 6),
    },
    WheelRailRow {
        feature: WheelRailFeature::ConformalInfluence,
        name: "influence functions corrected for conformal contact (Blanco), variants 1-4 on the conformal approach",
        control: "C3, IF_METH, VARIANT",
        supported: true,
        reason: "imported as [material] blanco_variant = VARIANT (1-4) and blanco_inclination = \"interpolated\" (IF_METH = 1) or \"linear\" (IF_METH = 0): the half-space's coefficients turned by the curved reference's row inclinations as the variant says (1 the traction turned, 2 the same with B_xn kept, 3 the displacement turned, 4 both by half the angle; physics::halfspace::blanco, CONTACT's influe_blanco1), each variant's product by FFT, the normal and tangential problems of each conformal patch iterated together (pipeline::wheelrail_blanco)",
        used: |c| blanco_used(c, true),
    },
    WheelRailRow {
        feature: WheelRailFeature::ConformalInfluence,
        name: "influence functions corrected for conformal contact (Blanco) on planar patches",
        control: "C3, IF_METH, VARIANT, D",
        supported: false,
        reason: "supported: C3 = 4 with VARIANT 1-4 and IF_METH 0 or 1 on the conformal approach (D = 4); a planar patch (D = 2, 3, 5) has no row inclinations (its rows are all in one tangent plane), and CONTACT has no result to match: its build (gfortran, d431cdb) stops with a segmentation fault in the first case of the Manchester deck `mbench_a22_left` with C3 = 4 (IF_METH 1, VARIANT 3) on D = 2, which it solves with C3 = 2; IF_METH or VARIANT outside CONTACT's ranges are refused by CONTACT itself",
        used: |c| blanco_used(c, false),
    },
    WheelRailRow {
        feature: WheelRailFeature::BilinearInfluence,
        name: "influence functions of the half-space with bilinear tractions",
        control: "C3",
        supported: true,
        reason: "the exact solver's kernels of the bilinear hat (physics::halfspace::bilinear), as module 3",
        used: |c| c.state.material.as_ref().filter(|m| m.influence == 3).map(|_| "C3 (in force) = 3".to_string()),
    },
    WheelRailRow {
        feature: WheelRailFeature::MaterialModel,
        name: "material models other than elastic",
        control: "M",
        supported: false,
        reason: "supported: M = 0 (elastic half-spaces), M = 3 without slope reduction (FASTSIM); viscoelastic (1), CONTACT's other simplified theories (2, 5-7), the modified FASTSIM's slope reduction and interface layers (4) are not",
        used: |c| wr_digit("M", c.digits.m, c.digits.m != 0 && !plain_fastsim(c)),
    },
    WheelRailRow {
        feature: WheelRailFeature::MaterialModel,
        name: "FASTSIM for the tangential problem",
        control: "M, K0_MF, ALFAMF, BETAMF",
        supported: true,
        reason: "imported as solvers = [\"fastsim\"] (B = 0), [\"kpec\"] (B = 5) or [\"analyn\"] (B = 6): Kalker's FASTSIM with his three flexibilities of the contact's equivalent ellipse",
        used: |c| plain_fastsim(c).then(|| "M = 3, K0_MF = ALFAMF = BETAMF = 1".to_string()),
    },
    WheelRailRow {
        feature: WheelRailFeature::DissimilarMaterials,
        name: "dissimilar materials (normal-tangential coupling)",
        control: "POISS 1, 2, GG 1, 2",
        supported: false,
        reason: "supported: quasi-identical rail and wheel, Kalker's K = 0",
        used: |c| {
            let m = c.state.material.as_ref()?;
            let k = combine_bodies(m.poiss, m.gg_mpa).k;
            (k != 0.0).then(|| format!("K = {k:e}"))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::Damping,
        name: "force-based proportional damping",
        control: "M2, CDAMPN..DFTMAX",
        supported: false,
        reason: "supported: M2 = 0, 1 without damping",
        used: |c| c.state.damping.filter(|d| d.iter().any(|&x| x != 0.0)).map(|_| format!("M2 = {}", c.digits.m2)),
    },
    WheelRailRow {
        feature: WheelRailFeature::Temperatures,
        name: "surface temperatures",
        control: "H, BKTEMP, HEATCP, LAMBDA, DENS",
        supported: true,
        reason: "imported as [material] bulk1_c … density2_kg_per_mm3: the exact theory computes both bodies' surface temperatures on each patch (its module-3 problem), their largest MAX(T1,T2) compared with CONTACT's",
        used: |c| wr_digit("H", c.digits.h, wr_heat_carried(c)),
    },
    WheelRailRow {
        feature: WheelRailFeature::Temperatures,
        name: "surface temperatures outside steady rolling, without friction or without their data",
        control: "H, T",
        supported: false,
        reason: "supported: H = 1, 3 in steady rolling (T = 3, as CONTACT's `calc_temp`) after H = 3 gave the data",
        used: |c| (c.digits.h != 0 && !wr_heat_carried(c)).then(|| format!("H = {}, T = {}", c.digits.h, c.digits.t)),
    },
    WheelRailRow {
        feature: WheelRailFeature::Subsurface,
        name: "subsurface stresses",
        control: "S",
        supported: true,
        reason: "S only prints stresses below the surface: the input is read and not computed",
        used: |c| wr_digit("S", c.digits.s, c.digits.s != 0),
    },
    WheelRailRow {
        feature: WheelRailFeature::PreprocessingOnly,
        name: "preprocessing only (the case is not solved)",
        control: "R",
        supported: false,
        reason: "supported: R = 0, 1 (the case is solved)",
        used: |c| wr_digit("R", c.digits.r, c.digits.r >= 2),
    },
    WheelRailRow {
        feature: WheelRailFeature::SolverSettings,
        name: "debug output and solver settings",
        control: "X, G, MAXGS..EPS, NPOT_MAX",
        supported: true,
        reason: "read and not carried: this project's solver has its own stopping rule ([contact_solver])",
        used: |c| wr_digit("G", c.digits.g, c.digits.g != 1 || c.digits.x == 1),
    },
    WheelRailRow {
        feature: WheelRailFeature::VariableRailProfile,
        name: "a variable rail profile (slices file, switches and crossings)",
        control: "RFNAME",
        supported: true,
        reason: "carried as [rail] profile (the .slcs file) with [wheelrail] s_mm (S_WS): the contact locus iterated on the rail's 3-D surface, each patch on the cross-section at its reference and each grid column on its own (wheelrail::varrail); slices whose parts are missing (interruptions) make CONTACT's masked surface (wheelrail::profile::masked); what CONTACT refuses in the file is refused when the scene reads it",
        used: |c| slices(c.state.rail_profile.as_ref()),
    },
    WheelRailRow {
        feature: WheelRailFeature::OutOfRoundWheel,
        name: "an out-of-round wheel (slices file)",
        control: "WFNAME",
        supported: true,
        reason: "carried as [wheel] profile (the .slcw file) with the cases' column pitch_rad (PITCH): CONTACT's grid-based search on its gap mesh (wheelrail::brute) and the undeformed distance to the wheel's surface at each element's angle (wheelrail::oorwheel)",
        used: |c| slices(c.state.wheel_profile.as_ref()),
    },
    WheelRailRow {
        feature: WheelRailFeature::ProfileSmoothing,
        name: "profile smoothing",
        control: "SMOOTH",
        supported: true,
        reason: "carried as [rail] and [wheel] smooth (CONTACT's smoothing spline with lambda = SMOOTH, or with ISMOOTH = 1 smooth_weighted and SMOOTH its filter length in mm)",
        used: |c| {
            let smooth = |p: Option<&ProfileSpec>| p.map_or(0.0, |p| p.smooth);
            let (r, w) = (smooth(c.state.rail_profile.as_ref()), smooth(c.state.wheel_profile.as_ref()));
            (r > 0.0 || w > 0.0).then(|| format!("SMOOTH = {r} (rail), {w} (wheel)"))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::RailDeviation,
        name: "rail deviations from the design position and their velocities",
        control: "Z, DYRAIL..VROLLR",
        supported: true,
        reason: "carried as [rail] deviation_y_mm, deviation_z_mm, deviation_roll_rad (the rail profile turned about its origin, then shifted) and deviation_vy_mm_s, deviation_vz_mm_s, deviation_vroll_rad_s (the rail's material velocity in the creepages)",
        used: |c| {
            let r = c.state.rail_deviation;
            let any = [r.dy_mm, r.dz_mm, r.droll_rad, r.vy_mm_s, r.vz_mm_s, r.vroll_rad_s].iter().any(|&x| x != 0.0);
            any.then(|| {
                format!(
                    "DYRAIL, DZRAIL, DROLLR, VYRAIL, VZRAIL, VROLLR = {}, {}, {}, {}, {}, {}",
                    r.dy_mm, r.dz_mm, r.droll_rad, r.vy_mm_s, r.vz_mm_s, r.vroll_rad_s
                )
            })
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::TrackCurvature,
        name: "track curvature in the creepages",
        control: "CURV",
        supported: false,
        reason: "supported: tangent track (CURV = 0)",
        used: |c| c.state.track.filter(|t| t.curv_per_mm != 0.0).map(|t| format!("CURV = {}", t.curv_per_mm)),
    },
    WheelRailRow {
        feature: WheelRailFeature::TapeCircle,
        name: "the wheel profile placed by its tape circle",
        control: "YTAPE",
        supported: false,
        reason: "supported: no YTAPE (or |YTAPE| >= 1000 mm): the profile origin at NOMRAD",
        used: |c| {
            let y = c.state.wheelset?.ytape_mm?;
            (y.abs() < 1000.0).then(|| format!("YTAPE = {y}"))
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::WheelDeviation,
        name: "flexible wheelset deviations",
        control: "E, DXWHL..VPITCHW",
        supported: true,
        reason: "carried as `[wheel] deviation_*`: the wheel's profile origin shifted and the wheel turned by DROLLW, DYAWW on the wheelset (DPITCHW kept, not moving a round wheel, as CONTACT), their rates in the wheel's material velocity and spin",
        used: |c| {
            let w = c.state.wheel_deviation?;
            let given = w.position.iter().chain(&w.velocity).any(|&x| x != 0.0);
            given.then(|| {
                format!("E = {} (in force: DXWHL .. DPITCHW = {:?}, VXWHL .. VPITCHW = {:?})", c.digits.e, w.position, w.velocity)
            })
        },
    },
    WheelRailRow {
        feature: WheelRailFeature::PatchCombination,
        name: "patch turning and near misses",
        control: "D_TURN, G_MISS",
        supported: true,
        reason: "the thresholds of the patch search, carried as given",
        used: |c| {
            let d = c.state.discretisation.as_ref()?;
            (d.d_turn_given_mm.is_some() || d.g_miss_mm >= 0.0)
                .then(|| format!("D_TURN = {}, G_MISS = {}", d.d_turn_mm(), d.g_miss_mm))
        },
    },
];

fn slices(p: Option<&ProfileSpec>) -> Option<String> {
    let p = p?;
    (p.format() == ProfileFormat::Slices).then(|| format!("{:?}", p.file))
}

/// Every row of [`WHEELRAIL_FEATURES`] a module-1 case uses, with its value.
pub fn assess_wheelrail(case: &WheelRailCase) -> Vec<FeatureUse> {
    WHEELRAIL_FEATURES
        .iter()
        .filter_map(|row| {
            (row.used)(case).map(|value| FeatureUse {
                feature: row.feature,
                name: row.name,
                control: row.control,
                supported: row.supported,
                reason: row.reason,
                value,
            })
        })
        .collect()
}

/// C3 = 4 in force: with `supported`, the combination imported (VARIANT 1-4, IF_METH 0 or 1, D = 4),
/// else any other.
fn blanco_used(c: &WheelRailCase, supported: bool) -> Option<String> {
    let m = c.state.material.as_ref().filter(|m| m.influence == 4)?;
    let d = c.state.discretisation.as_ref().map_or(0, |d| d.method);
    let [meth, var] = m.if_correction.unwrap_or([-1, -1]);
    let ok = d == 4 && (0..=1).contains(&meth) && (1..=4).contains(&var);
    (ok == supported).then(|| format!("C3 (in force) = 4, IF_METH = {meth}, VARIANT = {var}, D = {d}"))
}
