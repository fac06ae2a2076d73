//! The contact's sections of a history's scene: `[friction]` (or `contact.mu`), `[contact]`,
//! `[geometry]`, `[normal]`, `[material]` and `[grid]`, from the first case's potential contact
//! (IPOTCN and its line), undeformed distance, friction and material.

use super::super::deck::{Case, Potcon, State};
use super::history::{History, Run};
use super::rows::{row_mu, upper_edge};
use super::window::{circular_in_x, curvature_ratio, load_of_approach, quadratic, union_grid};
use super::{case3, floats, material_of, table, Draft, Source};
use crate::error::InputError;
use crate::physics::material::combine_bodies;
use crate::physics::FallingTerms;
use std::fmt::Write;
use toml::Value;

/// A section's keys in the order they are written.
type Pairs = Vec<(&'static str, Value)>;

/// Every section of the contact, into `draft`.
pub(super) fn write(src: &Source, draft: &mut Draft) -> Result<(), InputError> {
    let s = &src.first.state;
    let mut contact: Pairs = vec![("fn_n", Value::Float(src.rows[0][3]))];
    match (friction_table(s), row_mu(s)) {
        (Some(f), _) => draft.insert("friction", f),
        (None, Some(per_row)) => draft
            .insert("friction", table(vec![("law", Value::String("coulomb".into())), ("mu_rows", floats(&per_row))])),
        (None, None) => contact.push(("mu", Value::Float(src.rows[0][4]))),
    }
    let potcon = union_grid(src.cases, src.h).or_else(|| s.potcon.clone());
    let (mx, my) = potcon.as_ref().map_or((0, 0), Potcon::mx_my);
    let mut grid: Pairs = vec![("mx", Value::Integer(mx as i64)), ("my", Value::Integer(my as i64))];
    // N = 0: the nominal load is the one at the first case's PEN.
    let pen = (src.first.digits.n == 0).then_some(src.rows[0][3]);
    let fn_n = match &potcon {
        Some(Potcon::Hertz { ipotcn: -3, params, .. }) => given_axes(params, pen, s, (&mut contact, &mut grid)),
        Some(Potcon::Hertz { ipotcn, params, .. }) => {
            given_curvatures(src, (*ipotcn, params), pen, (&mut contact, &mut grid))?
        }
        Some(Potcon::Grid { xl_mm, yl_mm, dx_mm, dy_mm, .. }) => {
            grid_geometry(src, (mx, my), (*xl_mm, *yl_mm, *dx_mm, *dy_mm), pen, (draft, &mut grid))?
        }
        None => {
            return Err(InputError::new(src.first_place(), "no IPOTCN", "a potential contact (D = 2 in a case before)"))
        }
    };
    if let Some(fn_n) = fn_n {
        contact[0] = ("fn_n", Value::Float(fn_n));
    }
    if src.h.run == Run::Sweep && pen.is_some() {
        // Steady cases (T = 0, 3) with N = 0: one PEN for the sweep (a setup of its own).
        contact.push(("pen_mm", Value::Float(src.rows[0][3])));
    }
    draft.insert("contact", table(contact));
    let fastsim = super::super::features::contact_simplified(src.first).is_some();
    if let Some(normal) = normal_table(src.cases, src.h).filter(|_| !fastsim) {
        draft.insert("normal", normal);
    }
    let m = combine_bodies(s.poiss, s.gg_mpa);
    let material = match m.k != 0.0 && !normal_only(src) {
        // Dissimilar bodies: each body's own constants (the combination and K follow from them).
        // T = 0 solves the normal problem alone, on which K has no effect: the combined constants.
        true => vec![
            ("g1_mpa", Value::Float(s.gg_mpa[0])),
            ("poisson1", Value::Float(s.poiss[0])),
            ("g2_mpa", Value::Float(s.gg_mpa[1])),
            ("poisson2", Value::Float(s.poiss[1])),
        ],
        false => vec![("g_mpa", Value::Float(m.g_mpa)), ("poisson", Value::Float(m.poisson))],
    };
    let mut material = material;
    // M = 4: the elastic interface layer (none where LAYTHK < 1e-10: CONTACT's `use_3bl`), or
    // with TAU_C0 > 0 and LAYTHK = 0 the plasticity of the bodies' surface (thickness 0).
    if let Some([gg3, laythk, tau_c0, k_tau]) = s.layer_in_force().filter(|l| l[1] >= 1e-10 || l[2] > 1e-10) {
        let laythk = if laythk >= 1e-10 { laythk } else { 0.0 };
        material.extend([("layer_g_mpa", Value::Float(gg3)), ("layer_thickness_mm", Value::Float(laythk))]);
        // Its yield limit (TAU_C0 > 0) and the rate it moves at (K_TAU; features.rs takes it in
        // shifts and steady rolling).
        if tau_c0 > 1e-10 {
            material.push(("layer_yield_mpa", Value::Float(tau_c0)));
            if k_tau != 0.0 {
                material.push(("layer_hardening_mpa_per_mm", Value::Float(k_tau)));
            }
        }
    }
    // M = 1: viscoelastic bodies alike (features.rs refuses bodies that differ); FG = 0 is elastic.
    if let Some([fg, _, tc, _]) = s.visco_in_force().filter(|v| v[0] > 0.0) {
        material.extend([("visco_ratio", Value::Float(fg)), ("visco_time_s", Value::Float(tc))]);
    }
    // B = 1: the compressible sheet's flexibility.
    if let Some(flxz) = s.sheet_in_force() {
        material.push(("sheet_flexibility_mm3_per_n", Value::Float(flxz)));
    }
    // H = 1, 3: both bodies' thermal constants (features.rs takes them in steady rolling).
    if let Some(h) = s.heat_in_force() {
        let keys = crate::scene::material::HEAT_KEYS.keys.iter().map(|k| k.key);
        material.extend(keys.zip(h).map(|(k, v)| (k, Value::Float(v))));
    }
    draft.insert("material", table(material));
    draft.insert("grid", table(grid));
    Ok(())
}

/// Whether every case of the history solves the normal problem only (T = 0: no tangential
/// problem, so no traction for K to couple; CONTACT's `panprc` stops after the normal solve).
fn normal_only(src: &Source) -> bool {
    src.h
        .cases
        .iter()
        .all(|&k| matches!(&src.cases[k].kind, super::super::deck::CaseKind::Module3(c) if c.digits.t == 0))
}

/// IPOTCN = −3: the semi-axes AA, BB and the grid's SCALE. With N = 0 CONTACT (`hzcalc3d`) keeps
/// AA, BB and the curvatures follow from PEN: the load is Hertz's of that ellipse at PEN.
fn given_axes(params: &[f64], pen: Option<f64>, s: &State, (contact, grid): (&mut Pairs, &mut Pairs)) -> Option<f64> {
    contact.extend([("a_mm", Value::Float(params[0])), ("b_mm", Value::Float(params[1]))]);
    grid.push(("scale", Value::Float(params[2])));
    pen.map(|pen| crate::physics::HertzContact::with_approach(params[0], params[1], pen, &material_of(s)).fn_n)
}

/// IPOTCN = −1: h = A1 x² + B1 y², as the radii R_wx = 1/(2 A1), R_wy = R_ry = 1/B1; −2: A1 and
/// a/b, B1 = A1 · (B/A of Hertz's ellipse of that a/b); and the grid's SCALE. With N = 0 CONTACT
/// (`hzcalc3d`) keeps the curvatures and AA, BB (so the grid) follow from PEN: the load is
/// Hertz's at that approach.
fn given_curvatures(
    src: &Source,
    (ipotcn, params): (i64, &[f64]),
    pen: Option<f64>,
    (contact, grid): (&mut Pairs, &mut Pairs),
) -> Result<Option<f64>, InputError> {
    let s = &src.first.state;
    let b1 = if ipotcn == -2 { params[0] * curvature_ratio(params[1], s) } else { params[1] };
    let (rx, ry) = (0.5 / params[0], 1.0 / b1);
    contact.extend([("r_wx_mm", Value::Float(rx)), ("r_wy_mm", Value::Float(ry)), ("r_ry_mm", Value::Float(ry))]);
    let radii = crate::physics::Radii { r_wx_mm: rx, r_wy_mm: ry, r_ry_mm: ry };
    let hertz = |n: u8, load: f64| {
        let m = material_of(s);
        match n {
            0 => crate::physics::HertzContact::from_radii_and_approach(&radii, load, &m),
            _ => crate::physics::HertzContact::from_radii(&radii, load, &m),
        }
        .map_err(|e| {
            InputError::new(src.first_place(), format!("{} = {load}", if n == 0 { "PEN" } else { "FN" }), e.to_string())
        })
    };
    // D = 0 after another load: CONTACT keeps the grid its last D >= 1 case sized (SCALE times
    // that case's ellipse) while the ellipse follows the curvatures to the new load.
    match s.grid_load {
        Some((n, load)) if (n, load) != (src.first.digits.n, s.pen_or_fn) => {
            let w = hertz(n, load)?;
            let (x, y) = (params[2] * w.a_mm, params[2] * w.b_mm);
            grid.extend([("x_mm", floats(&[-x, x])), ("y_mm", floats(&[-y, y]))]);
        }
        _ => grid.push(("scale", Value::Float(params[2]))),
    }
    pen.map(|pen| hertz(0, pen).map(|e| e.fn_n)).transpose()
}

/// IPOTCN > 0: the grid's extent and the undeformed distance h per element (IBASE = 9 as given,
/// 2 [`circular_in_x`], else [`quadratic`]) as `[geometry] kind = "field"` with its file
/// `<name>_h.csv`. With N = 0 the load is the one that PEN makes on that grid (it forms the
/// nominal contact).
fn grid_geometry(
    src: &Source,
    (mx, my): (usize, usize),
    (xl_mm, yl_mm, dx_mm, dy_mm): (f64, f64, f64, f64),
    pen: Option<f64>,
    (draft, grid): (&mut Draft, &mut Pairs),
) -> Result<Option<f64>, InputError> {
    let s = &src.first.state;
    let (x1, y1) = (upper_edge(xl_mm, mx, dx_mm), upper_edge(yl_mm, my, dy_mm));
    grid.extend([("x_mm", floats(&[xl_mm, x1])), ("y_mm", floats(&[yl_mm, y1]))]);
    let u = s.undeformed.as_ref().expect("a grid's undeformed distance (checked by the feature table)");
    let b = &u.values;
    let centre = |e: usize| (xl_mm + (((e % mx) as f64) + 0.5) * dx_mm, yl_mm + (((e / mx) as f64) + 0.5) * dy_mm);
    let h_mm: Vec<f64> = match u.ibase {
        9 => b.clone(),
        2 => (0..mx * my).map(|e| circular_in_x(b, centre(e))).collect(),
        _ => (0..mx * my).map(|e| quadratic(b, centre(e))).collect(),
    };
    let fn_n = match pen {
        Some(pen) => {
            let m = combine_bodies(s.poiss, s.gg_mpa);
            let fn_n = load_of_approach(&h_mm, (mx, my, dx_mm, dy_mm), (m.g_mpa, m.poisson), pen).ok_or_else(|| {
                InputError::new(
                    src.first_place(),
                    format!("PEN = {pen}"),
                    "an approach at which the undeformed distance makes contact on the grid",
                )
            })?;
            Some(fn_n)
        }
        None => None,
    };
    let mut csv = String::from("ix,iy,h_mm\n");
    for (e, v) in h_mm.iter().enumerate() {
        let _ = writeln!(csv, "{},{},{v:?}", e % mx + 1, e / mx + 1);
    }
    let field = format!("{}_h.csv", src.name);
    draft.insert(
        "geometry",
        table(vec![("kind", Value::String("field".into())), ("field", Value::String(field.clone()))]),
    );
    draft.files.push((field, csv));
    Ok(fn_n)
}

/// `[friction]` of a falling law (L = 2, 3, 4) with its memory, or of the temperature law (L = 6:
/// FREF, TREF, DFHEAT, DTHEAT; its memory is refused, features.rs); `None`: Coulomb (`contact.mu`).
/// An absent second term (F2 = 0) and an absent memory (MEMDST = 0) are left out: they change no μ.
/// Each term's SABSH is the one CONTACT uses, max(1e-4, SABSH) where its F < 1e-8 (`fric_input`,
/// `m_friclaw.f90` lines 833-846: [`FallingTerms::scale`]), so that a deck CONTACT accepts with
/// SABSH = 0 in such a term gives the same law.
fn friction_table(s: &State) -> Option<Value> {
    let law = match s.friction_law {
        2 => "linear",
        3 => "rational",
        4 => "exponential",
        6 => return Some(temperature_table(&s.friction, s.memory)),
        _ => return None,
    };
    let f = &s.friction;
    let mut pairs = vec![
        ("law", Value::String(law.into())),
        ("fkin", Value::Float(f[0])),
        ("f1", Value::Float(f[1])),
        ("sabsh1_mm_s", Value::Float(FallingTerms::scale(f[1], f[2]))),
    ];
    if f[3] != 0.0 {
        pairs.extend([("f2", Value::Float(f[3])), ("sabsh2_mm_s", Value::Float(FallingTerms::scale(f[3], f[4])))]);
    }
    if s.memory[0] != 0.0 {
        pairs.extend([("memory_mm", Value::Float(s.memory[0])), ("memory_s0_mm_s", Value::Float(s.memory[1]))]);
    }
    Some(table(pairs))
}

/// `[friction]` of the temperature law (L = 6) of FREF, TREF, DFHEAT, DTHEAT `f` and the memory
/// MEMDST, MEM_S0 where there is one.
fn temperature_table(f: &[f64], memory: [f64; 2]) -> Value {
    let names = ["fref", "tref_c", "dfheat", "dtheat_c"];
    let mut pairs: Pairs = vec![("law", Value::String("temperature".into()))];
    pairs.extend(names.into_iter().zip(f.iter().map(|&v| Value::Float(v))));
    if memory[0] != 0.0 {
        pairs.extend([("memory_mm", Value::Float(memory[0])), ("memory_s0_mm_s", Value::Float(memory[1]))]);
    }
    table(pairs)
}

/// `[model]` of CONTACT's FASTSIM (M = 3) or FaStrip (M = 5): Hertz's pressure of its B (3 parabolic, 2 ellipsoidal)
/// and the slope reduction K0_MF, ALFAMF, BETAMF where it is not 1, 1, 1 (none).
pub(super) fn fastsim_model(s: &State, b: u8) -> Value {
    let shape = if b == 2 { "ellipsoidal" } else { "parabolic" };
    let mut pairs: Pairs = vec![("pressure", Value::String(shape.into()))];
    if let Some(mf) = s.slope_mf.filter(|mf| *mf != [1.0; 3]) {
        pairs.push(("slope_reduction", floats(&mf)));
    }
    table(pairs)
}

/// `[normal]` of a history whose B is 2 or 3 (Hertz's elliptical or parabolic pressure) in some
/// case: `pressure` its steps' B, `start_pressure` its start's where it differs; `None`: B = 0.
fn normal_table(cases: &[Case], h: &History) -> Option<Value> {
    let name = |b: u8| match b {
        2 => "elliptical",
        3 => "parabolic",
        _ => "solved",
    };
    let b_of = |n: usize| case3(cases, h.cases[n]).digits.b;
    let (start, steps) = if h.run.has_start() { (b_of(0), b_of(1)) } else { (b_of(0), b_of(0)) };
    let mut pairs = Vec::new();
    if steps != 0 {
        pairs.push(("pressure", Value::String(name(steps).into())));
    }
    if start != steps {
        pairs.push(("start_pressure", Value::String(name(start).into())));
    }
    (!pairs.is_empty()).then(|| table(pairs))
}
