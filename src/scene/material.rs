//! `[material]`: the combined elastic constants (G or E, and ν), or the two bodies' constants,
//! and an interface layer; its keys declared once ([`KEYS`], [`BODY_KEYS`], [`LAYER_KEYS`]) for
//! the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::MaterialSpec;
use crate::error::InputError;
use crate::physics::halfspace::blanco::Blanco;
use crate::physics::temperature::Thermal;

/// A combined modulus [MPa].
const MODULUS: Allowed = Allowed::Number(Range::new(0.0, false, 1e7, true), "");
/// A body's modulus [MPa]: a body may be far stiffer than the pair (CONTACT's "rigid" body of
/// G = 2e7 N/mm²).
const BODY_MODULUS: Allowed = Allowed::Number(Range::new(0.0, false, 1e12, true), "");
/// A body's Poisson's ratio.
const BODY_RATIO: Allowed = Allowed::Number(Range::new(0.0, true, 0.5, true), "");
/// With the other three bodies' keys.
const WITH_BODIES: Absent = Absent::Text("– (with the other three)");

/// `[material]`'s combined constants (`<!-- keys:material -->`).
pub const KEYS: Keys = Keys {
    id: "material",
    owner: file!(),
    keys: &[
        key(
            "g_mpa",
            "MPa",
            MODULUS,
            Absent::Text("from `e_mpa`"),
            r#"the combined shear modulus G: `g_mpa = 82000.0`"#,
        ),
        key(
            "e_mpa",
            "MPa",
            MODULUS,
            Absent::Text("from `g_mpa`"),
            r#"Young's modulus E; alone it gives G = E/(2(1 + ν)): `e_mpa = 210000.0`"#,
        ),
        key(
            "poisson",
            "–",
            Allowed::Number(Range::new(0.0, true, 0.5, false), ""),
            Absent::Required,
            r#"the combined Poisson's ratio ν: `poisson = 0.28`"#,
        ),
        key(
            "sheet_flexibility_mm3_per_n",
            "mm³/N",
            Allowed::Number(Range::new(1e-10, true, 1e20, true), ""),
            Absent::Text("– (no sheet)"),
            r#"a thin compressible sheet on the surface (pressure-sensitive paper; CONTACT's B = 1, FLXZ): the normal part of Kalker's first-order theory, u_z = L_z p_n in the element that carries the pressure, added to the half-spaces' normal displacement (L_z = h (1 + ν)(1 − 2ν)/((1 − ν) E) of the sheet); the normal problem only: `sheet_flexibility_mm3_per_n = 7.429e-5`"#,
        ),
    ],
};

/// `[material]`'s conformal correction of the influence coefficients (`<!-- keys:material_blanco -->`).
pub const BLANCO_KEYS: Keys = Keys {
    id: "material_blanco",
    owner: file!(),
    keys: &[
        key(
            "blanco_variant",
            "–",
            Allowed::Whole(1, 4, "CONTACT's VARIANT 1 to 4"),
            Absent::Text("– (the half-space's coefficients)"),
            r#"Blanco-Lorenzo's correction of the influence coefficients for conformal contact (CONTACT's C3 = 4 with its VARIANT): the half-space's coefficients of the loaded element J turned about x by the inclination difference α = α_J − α_I of the two rows, 1 the traction turned (`B = A R(α)`, Blanco's formulas), 2 the same with the longitudinal displacement of a pressure kept (`B_xn = A_xn`), 3 the displacement turned into the displaced element's frame (`B = R(α) A`, the half-space at J), 4 both turned by half the angle (`B = R(α/2) A R(α/2)`), which couples the normal and tangential problems (the exact solver iterates them, as CONTACT's Panagiotopoulos process); a wheel–rail scene with `approach = "conformal"` and one material only, the rows' inclinations its curved reference's: `blanco_variant = 3`"#,
        ),
        key(
            "blanco_inclination",
            "–",
            Allowed::Choice(&["interpolated", "linear"], ""),
            Absent::Choice("interpolated"),
            r#"with `blanco_variant`: each grid row's inclination from the curved reference's table of (s, α), one entry per row: the table interpolated at the row, its own value (CONTACT's IF_METH = 1), or the least-squares line through it (IF_METH = 0): `blanco_inclination = "interpolated"`"#,
        ),
    ],
};

/// `[material]`'s two bodies' constants (`<!-- keys:material_bodies -->`), in the order they are named.
pub const BODY_KEYS: Keys = Keys {
    id: "material_bodies",
    owner: file!(),
    keys: &[
        key("g1_mpa", "MPa", BODY_MODULUS, WITH_BODIES, r#"body 1's shear modulus G1: `g1_mpa = 23000.0`"#),
        key("poisson1", "–", BODY_RATIO, WITH_BODIES, r#"body 1's Poisson's ratio ν1: `poisson1 = 0.31`"#),
        key("g2_mpa", "MPa", BODY_MODULUS, WITH_BODIES, r#"body 2's shear modulus G2: `g2_mpa = 82000.0`"#),
        key(
            "poisson2",
            "–",
            BODY_RATIO,
            WITH_BODIES,
            r#"body 2's Poisson's ratio ν2 (the combined ν must stay below 0.5): `poisson2 = 0.28`"#,
        ),
    ],
};

/// `[material]`'s interface layer (`<!-- keys:material_layer -->`), given together.
pub const LAYER_KEYS: Keys = Keys {
    id: "material_layer",
    owner: file!(),
    keys: &[
        key(
            "layer_g_mpa",
            "MPa",
            Allowed::Number(Range::new(0.0, false, 1e12, true), ""),
            Absent::Text("– (no layer; with `layer_thickness_mm`)"),
            r#"the layer's shear modulus G3 (CONTACT's GG3): `layer_g_mpa = 8200.0`"#,
        ),
        key(
            "layer_thickness_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Text("– (no layer; with `layer_g_mpa`)"),
            r#"the layer's thickness h3 (LAYTHK); only h3/G3 matters; its displacement moves with the material in steady rolling and stays in place in transient rolling, as CONTACT's: `layer_thickness_mm = 1.25`"#,
        ),
    ],
};

/// `[material]`'s interface layer's plasticity (`<!-- keys:material_plastic -->`), with the layer.
pub const PLASTIC_KEYS: Keys = Keys {
    id: "material_plastic",
    owner: file!(),
    keys: &[
        key(
            "layer_yield_mpa",
            "MPa",
            Allowed::Number(Range::new(0.0, false, 1e10, false), ""),
            Absent::Text("– (an elastic layer)"),
            r#"the layer's yield limit τ_c0 (CONTACT's TAU_C0), with `layer_g_mpa` and `layer_thickness_mm` (0: the bodies' surface yields without a layer's flexibility, CONTACT's LAYTHK = 0): the traction bound is min(μ pn, τc), τc = τ_c0 unless the layer hardens; exact model only, not with falling friction or dissimilar bodies: `layer_yield_mpa = 560.0`"#,
        ),
        key(
            "layer_hardening_mpa_per_mm",
            "MPa/mm",
            Allowed::Number(Range::new(-1e10, false, 1e10, false), ""),
            Absent::Num(0.0),
            r#"the rate K_TAU (CONTACT's K_TAU, N/mm³) at which each element's yield limit moves with its accumulated plastic slip, τc = τ_c0 + K_TAU Σ|Δu_pl|, not below 0.1 τ_c0 nor (hardening) above μ pn; > 0 hardens, < 0 softens, 0 elastic-perfectly plastic; with `layer_yield_mpa`, in shifts (`[rolling] motion = "shift"`), steady rolling (a sweep: each element's limit taken from the element upstream) and transient rolling along x (`chi_deg` 0, or 180 for the whole history: each element's limit moved with the material by dq before the step): `layer_hardening_mpa_per_mm = 435.0`"#,
        ),
    ],
};

/// `[material]`'s viscoelastic bodies (`<!-- keys:material_visco -->`), given together.
pub const VISCO_KEYS: Keys = Keys {
    id: "material_visco",
    owner: file!(),
    keys: &[
        key(
            "visco_ratio",
            "–",
            Allowed::Number(Range::new(0.0, true, 1e6, true), ""),
            Absent::Text("– (elastic; with `visco_time_s`)"),
            r#"C_v/C_g, CONTACT's FG: the relaxed shear modulus is G/(1 + FG): `visco_ratio = 1.0`"#,
        ),
        key(
            "visco_time_s",
            "s",
            Allowed::Number(Range::new(0.0, true, 1e20, true), "CONTACT's range of TC"),
            Absent::Text("– (elastic; with `visco_ratio`)"),
            r#"the creep relaxation time τ, CONTACT's TC (its VT = VELOC·TC): `visco_time_s = 0.009`"#,
        ),
    ],
};

/// A body's bulk temperature [°C] (above absolute zero).
const BULK: Allowed = Allowed::Number(Range::new(-273.15, false, 1e4, true), "");
/// A positive thermal constant.
const THERMAL: Allowed = Allowed::Number(Range::new(0.0, false, 1e10, true), "");
/// With the other seven heat keys.
const WITH_HEAT: Absent = Absent::Text("– (no surface temperatures; with the other seven)");

/// `[material]`'s thermal constants of both bodies for their surface temperatures
/// (`<!-- keys:material_heat -->`, CONTACT's H = 3; physics/temperature.rs), all eight or none.
pub const HEAT_KEYS: Keys = Keys {
    id: "material_heat",
    owner: file!(),
    keys: &[
        key(
            "bulk1_c",
            "°C",
            BULK,
            WITH_HEAT,
            r#"body 1's bulk (initial) temperature T0 (CONTACT's BKTEMP1): `bulk1_c = 0.0`"#,
        ),
        key(
            "heat_capacity1_j_per_kg_c",
            "J/(kg °C)",
            THERMAL,
            WITH_HEAT,
            r#"body 1's specific heat capacity c_p (HEATCP1): `heat_capacity1_j_per_kg_c = 450.0`"#,
        ),
        key(
            "conductivity1_w_per_mm_c",
            "W/(mm °C)",
            THERMAL,
            WITH_HEAT,
            r#"body 1's thermal conductivity λ (LAMBDA1): `conductivity1_w_per_mm_c = 0.05`"#,
        ),
        key(
            "density1_kg_per_mm3",
            "kg/mm³",
            THERMAL,
            WITH_HEAT,
            r#"body 1's density ρ (DENS1): `density1_kg_per_mm3 = 7.85e-6`"#,
        ),
        key(
            "bulk2_c",
            "°C",
            BULK,
            WITH_HEAT,
            r#"body 2's bulk temperature (BKTEMP2); with all eight keys the exact model (steady rolling only) adds the columns temp1_max_c, temp2_max_c, the bodies' largest surface temperature on the contact: `bulk2_c = 150.0`"#,
        ),
        key(
            "heat_capacity2_j_per_kg_c",
            "J/(kg °C)",
            THERMAL,
            WITH_HEAT,
            r#"body 2's c_p (HEATCP2): `heat_capacity2_j_per_kg_c = 450.0`"#,
        ),
        key(
            "conductivity2_w_per_mm_c",
            "W/(mm °C)",
            THERMAL,
            WITH_HEAT,
            r#"body 2's λ (LAMBDA2): `conductivity2_w_per_mm_c = 0.05`"#,
        ),
        key(
            "density2_kg_per_mm3",
            "kg/mm³",
            THERMAL,
            WITH_HEAT,
            r#"body 2's ρ (DENS2): `density2_kg_per_mm3 = 7.85e-6`"#,
        ),
    ],
};

/// Both bodies' thermal constants: all eight keys of [`HEAT_KEYS`] or none.
fn heat(m: &mut Section) -> Result<Option<[Thermal; 2]>, InputError> {
    if !together(m, &HEAT_KEYS, "all eight")? {
        return Ok(None);
    }
    let one = Thermal {
        bulk_c: m.num("bulk1_c")?,
        heat_capacity_j_per_kg_c: m.num("heat_capacity1_j_per_kg_c")?,
        conductivity_w_per_mm_c: m.num("conductivity1_w_per_mm_c")?,
        density_kg_per_mm3: m.num("density1_kg_per_mm3")?,
    };
    let two = Thermal {
        bulk_c: m.num("bulk2_c")?,
        heat_capacity_j_per_kg_c: m.num("heat_capacity2_j_per_kg_c")?,
        conductivity_w_per_mm_c: m.num("conductivity2_w_per_mm_c")?,
        density_kg_per_mm3: m.num("density2_kg_per_mm3")?,
    };
    Ok(Some([one, two]))
}

/// Whether the keys of `keys` are given, all of them (`true`) or none (`false`); some of them is
/// an error naming the first missing (`how_many`: "both", "all four").
fn together(m: &Section, keys: &Keys, how_many: &str) -> Result<bool, InputError> {
    let all: Vec<&str> = keys.keys.iter().map(|k| k.key).collect();
    let given: Vec<&str> = all.iter().copied().filter(|k| m.has(k)).collect();
    if given.is_empty() {
        return Ok(false);
    }
    match all.iter().find(|k| !given.contains(k)) {
        Some(missing) => Err(InputError::new(
            m.field(missing),
            "missing",
            format!("{how_many} of {} with {}", all.join(", "), given.join(", ")),
        )),
        None => Ok(true),
    }
}

/// `[material]`: g_mpa or e_mpa (or both), and poisson; or the two bodies' g1_mpa, poisson1,
/// g2_mpa, poisson2 (dissimilar bodies, [`bodies`]).
pub fn read(top: &mut Section) -> Result<MaterialSpec, InputError> {
    let mut m = top
        .table("material")?
        .declare(&KEYS)
        .declare(&BODY_KEYS)
        .declare(&LAYER_KEYS)
        .declare(&PLASTIC_KEYS)
        .declare(&VISCO_KEYS)
        .declare(&HEAT_KEYS)
        .declare(&BLANCO_KEYS);
    let heat = heat(&mut m)?;
    let blanco = blanco(&mut m)?;
    let sheet_mm3_per_n = m.opt_num("sheet_flexibility_mm3_per_n")?.unwrap_or(0.0);
    let layer = layer(&mut m)?;
    let visco = visco(&mut m)?;
    if let (Some(_), Some(_)) = (layer, visco) {
        return Err(InputError::new(
            m.field("visco_ratio"),
            "given with layer_g_mpa",
            "either an interface layer or viscoelastic bodies (CONTACT's M is one material model: 4 or 1)",
        ));
    }
    if let Some(spec) = bodies(&mut m)? {
        m.finish()?;
        return Ok(MaterialSpec { layer, visco, heat, sheet_mm3_per_n, blanco, ..spec });
    }
    let g_mpa = m.opt_num("g_mpa")?;
    let e_mpa = m.opt_num("e_mpa")?;
    let poisson = m.num("poisson")?;
    if g_mpa.is_none() && e_mpa.is_none() {
        return Err(InputError::new(
            "material.g_mpa",
            "missing",
            "g_mpa (or e_mpa, from which g_mpa = e/(2(1+poisson)))",
        ));
    }
    m.finish()?;
    Ok(MaterialSpec { g_mpa, e_mpa, poisson, bodies: None, layer, visco, heat, sheet_mm3_per_n, blanco })
}

/// Blanco-Lorenzo's conformal correction ([`BLANCO_KEYS`]): `blanco_variant` asks for it,
/// `blanco_inclination` (only with it) says how the rows' inclinations are taken.
fn blanco(m: &mut Section) -> Result<Option<Blanco>, InputError> {
    use crate::physics::halfspace::blanco::Inclination;
    let variant = m.opt_whole("blanco_variant")?;
    let inclination = m.opt_pick("blanco_inclination")?;
    match (variant, inclination) {
        (None, None) => Ok(None),
        (None, Some(i)) => {
            Err(InputError::new(m.field("blanco_inclination"), i, "with blanco_variant (the correction it shapes)"))
        }
        (Some(v), i) => {
            let inclination = if i == Some("linear") { Inclination::Linear } else { Inclination::Interpolated };
            Ok(Some(Blanco { inclination, variant: v as u8 }))
        }
    }
}

/// Viscoelastic bodies (CONTACT's M = 1 with FG 1 = FG 2, TC 1 = TC 2): both keys or neither. A
/// ratio of 0 is elastic bodies.
fn visco(m: &mut Section) -> Result<Option<crate::physics::material::Visco>, InputError> {
    if !together(m, &VISCO_KEYS, "both")? {
        return Ok(None);
    }
    let ratio = m.num("visco_ratio")?;
    let time_s = m.num("visco_time_s")?;
    Ok((ratio > 0.0).then_some(crate::physics::material::Visco { ratio, time_s }))
}

/// An interface layer (CONTACT's M = 4: GG3, LAYTHK): both keys or neither. A thickness of 0 is
/// no layer's flexibility, as CONTACT's (`use_3bl` needs LAYTHK >= 1e-10); with a yield limit
/// (TAU_C0) it is the plasticity of the bodies' surface (LAYTHK = 0: the bound min(μ pn, τc) alone).
fn layer(m: &mut Section) -> Result<Option<crate::physics::material::Layer>, InputError> {
    let yield_mpa = m.opt_num("layer_yield_mpa")?;
    let hardening_mpa_per_mm = m.opt_num("layer_hardening_mpa_per_mm")?;
    if let (Some(k), None) = (hardening_mpa_per_mm, yield_mpa) {
        return Err(InputError::new(
            m.field("layer_hardening_mpa_per_mm"),
            k,
            "a rate of the yield limit with its yield limit: layer_yield_mpa (and the layer)",
        ));
    }
    let hardening_mpa_per_mm = hardening_mpa_per_mm.unwrap_or(0.0);
    if !together(m, &LAYER_KEYS, "both")? {
        return match yield_mpa {
            Some(v) => Err(InputError::new(
                m.field("layer_yield_mpa"),
                v,
                "a yield limit with its layer: layer_g_mpa and layer_thickness_mm (0: the bodies' surface yields)",
            )),
            None => Ok(None),
        };
    }
    let g_mpa = m.num("layer_g_mpa")?;
    let thickness_mm = m.num("layer_thickness_mm")?;
    Ok((thickness_mm > 0.0 || yield_mpa.is_some()).then_some(crate::physics::material::Layer {
        g_mpa,
        thickness_mm,
        yield_mpa,
        hardening_mpa_per_mm,
    }))
}

/// `[material]` given per body (CONTACT's GG 1, 2 and POISS 1, 2): all four keys, none of
/// g_mpa, e_mpa, poisson; the combined constants and Kalker's K follow ([`crate::physics::Material::from_bodies`]).
fn bodies(m: &mut Section) -> Result<Option<MaterialSpec>, InputError> {
    if !together(m, &BODY_KEYS, "all four")? {
        return Ok(None);
    }
    if let Some(both) = ["g_mpa", "e_mpa", "poisson"].iter().find(|k| m.has(k)) {
        return Err(InputError::new(
            m.field(both),
            "given with the bodies' g1_mpa .. poisson2",
            "either the combined g_mpa (or e_mpa) and poisson, or the two bodies' constants",
        ));
    }
    let g = [m.num("g1_mpa")?, m.num("g2_mpa")?];
    let nu = [m.num("poisson1")?, m.num("poisson2")?];
    let bodies = crate::physics::material::Bodies { g_mpa: g, poisson: nu };
    let combined = crate::physics::Material::from_bodies(bodies);
    if combined.poisson >= 0.5 {
        return Err(InputError::new(
            m.field("poisson1"),
            nu[0],
            "bodies whose combined Poisson's ratio is below 0.5 (both at 0.5 is an incompressible pair: give g_mpa and poisson)",
        ));
    }
    Ok(Some(MaterialSpec {
        g_mpa: None,
        e_mpa: None,
        poisson: combined.poisson,
        bodies: Some(bodies),
        layer: None,
        visco: None,
        heat: None,
        sheet_mm3_per_n: 0.0,
        blanco: None,
    }))
}
