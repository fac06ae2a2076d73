//! `[friction]` (optional): the friction law (Coulomb's with `contact.mu`, falling with the
//! slip velocity as CONTACT's L = 2, 3, 4, or varying with the surface temperature as its L = 6),
//! its memory and μ per grid row; its keys declared once ([`KEYS`]) for the reader and
//! docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::MAX_ELEMENTS_PER_AXIS;
use crate::error::InputError;
use crate::physics::{FallingTerms, FrictionLaw, Memory, RowFriction, TemperatureLaw};

/// A coefficient of a falling law.
const COEFFICIENT: Range = Range::new(0.0, true, 1e3, true);
/// A slip velocity [mm/s].
const SPEED: Range = Range::new(0.0, true, 1e9, true);
/// Required by a falling law.
const FALLING: Absent = Absent::Text("required for a falling law");
/// Required by the temperature law.
const TEMPERATURE: Absent = Absent::Text("required for law = \"temperature\"");
/// A temperature [°C].
pub(crate) const CELSIUS: Range = Range::new(-273.15, true, 1e5, true);
/// The keys of the falling laws (L = 2, 3, 4).
const FALLING_KEYS: [&str; 5] = ["fkin", "f1", "sabsh1_mm_s", "f2", "sabsh2_mm_s"];
/// The keys of the temperature law (L = 6).
const TEMPERATURE_KEYS: [&str; 4] = ["fref", "tref_c", "dfheat", "dtheat_c"];

/// `[friction]`'s keys (`<!-- keys:friction -->`).
pub const KEYS: Keys = Keys {
    id: "friction",
    owner: file!(),
    keys: &[
        key(
            "law",
            "–",
            Allowed::Choice(&["coulomb", "linear", "rational", "exponential", "temperature"], ""),
            Absent::Required,
            r#"`coulomb`: μ = `contact.mu` (no other key); `linear` (L = 2): μ = fkin + f1·max(0, 1 − s/(2·sabsh1)) + f2·max(0, 1 − s/(2·sabsh2)); `rational` (L = 3): fkin + f1/(1 + s/sabsh1) + f2/(1 + (s/sabsh2)²); `exponential` (L = 4): fkin + f1·exp(−ln2·s/sabsh1) + f2·exp(−ln2·s/sabsh2); `temperature` (L = 6): μ = fref + dfheat·clamp(T − tref_c, 0, dtheat_c)/dtheat_c of the surface temperature T (`[material]`'s heat keys required; the exact model only, in steady rolling: a fixed point between the tractions and the temperatures, docs/models.md "Temperature-dependent friction"): `law = "exponential"`"#,
        ),
        key(
            "fkin",
            "–",
            Allowed::Number(COEFFICIENT, "> 0 when the scene runs `contact`"),
            FALLING,
            r#"the kinetic coefficient, μ for large s (the exact solver's bound μ(s)·p must stay positive: with 0 the law falls to μ = 0): `fkin = 0.25`"#,
        ),
        key("f1", "–", Allowed::Number(COEFFICIENT, ""), FALLING, r#"the first term's height: `f1 = 0.2`"#),
        key(
            "sabsh1_mm_s",
            "mm/s",
            Allowed::Number(Range::new(0.0, false, 1e9, true), ""),
            FALLING,
            r#"the first term's slip velocity scale: `sabsh1_mm_s = 600.0`"#,
        ),
        key("f2", "–", Allowed::Number(COEFFICIENT, ""), Absent::Num(0.0), r#"the second term's height: `f2 = 0.08`"#),
        key(
            "sabsh2_mm_s",
            "mm/s",
            Allowed::Number(SPEED, "> 0 when f2 > 0"),
            Absent::Num(0.0),
            r#"the second term's scale: `sabsh2_mm_s = 2500.0`"#,
        ),
        key(
            "fref",
            "–",
            Allowed::Number(Range::new(0.0, false, 1e3, true), ""),
            TEMPERATURE,
            r#"with `law = "temperature"`: μ at low surface temperatures, up to `tref_c` (CONTACT's FREF; also μ's static value, FSTAT): `fref = 0.33`"#,
        ),
        key(
            "tref_c",
            "°C",
            Allowed::Number(CELSIUS, ""),
            TEMPERATURE,
            r#"with `law = "temperature"`: the surface temperature where μ starts changing (CONTACT's TREF): `tref_c = 0.0`"#,
        ),
        key(
            "dfheat",
            "–",
            Allowed::Number(Range::new(-1e3, true, 1e3, true), "fref + dfheat > 0"),
            TEMPERATURE,
            r#"with `law = "temperature"`: the change of μ from `tref_c` to `tref_c + dtheat_c`, beyond which μ stays fref + dfheat (CONTACT's DFHEAT; negative: friction falling with the temperature): `dfheat = -0.19`"#,
        ),
        key(
            "dtheat_c",
            "°C",
            Allowed::Number(Range::new(0.0, false, 1e5, true), ""),
            TEMPERATURE,
            r#"with `law = "temperature"`: the temperature span over which μ changes linearly (CONTACT's DTHEAT): `dtheat_c = 1200.0`"#,
        ),
        key(
            "memory_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e4, true), ""),
            Absent::Text("absent: no memory"),
            r#"the friction memory's relaxation distance d_c (CONTACT's MEMDST): along the material path μ relaxes to μ(s) as dμ/dt = −(max(s, s0)/d_c)(μ − μ(s)), one backward-Euler step per time step (grid element in steady rolling); 0 (or ≤ 1e-9) is no memory. With `law = "temperature"` μ relaxes to μ(T) at the constant rate max(s_i, s0)/d_c, s_i the slip velocity the fixed point starts from (`[contact_solver] inislp`: 0, or V with "above"), as CONTACT's L = 6: `memory_mm = 0.01`"#,
        ),
        key(
            "memory_s0_mm_s",
            "mm/s",
            Allowed::Number(SPEED, ""),
            Absent::Num(0.0),
            r#"the memory's slip velocity floor s0 (CONTACT's MEM_S0), only with `memory_mm`: `memory_s0_mm_s = 10.0`"#,
        ),
        key(
            "mu_rows",
            "–",
            Allowed::Numbers {
                range: super::MU_LIMIT,
                min_len: 1,
                max_len: MAX_ELEMENTS_PER_AXIS,
                note: "one per grid row, `grid.my` values",
            },
            Absent::Text("absent: one μ"),
            r#"only with `law = "coulomb"`: Coulomb's coefficient per grid row, the first at the lowest y (CONTACT's V = 3, FSTAT per row IY); the bound of an element of row j is μ_j·p; `contact.mu` is left out and the scene's nominal μ (`scene.json`'s `mu`) is the largest row value; a creepage table may not carry a `mu` column; only the exact solver (`contact`) takes it, the simplified and external models are refused: `mu_rows = [0.2, 0.3, 0.4]`"#,
        ),
    ],
};

/// The friction law (`[friction]`, optional: Coulomb with `contact.mu`) and μ's static value.
pub struct FrictionSpec {
    pub law: FrictionLaw,
    pub memory: Memory,
    pub mu_static: f64,
    /// Coulomb's μ per grid row (`[friction] mu_rows`, CONTACT V = 3); `mu_static` is their largest.
    pub rows: Option<RowFriction>,
}

/// Relative difference allowed between a given `contact.mu` and a falling law's FKIN + F1 + F2
/// (the sum is rounded in the last digit: 0.22 + 0.15 + 0.08 = 0.45000000000000007).
const MU_STATIC_REL: f64 = 1e-12;

/// `[friction]` (optional): the law and its parameters (CONTACT's names), the memory; `mu` is
/// `contact.mu` as given (required by Coulomb's law; a falling law's static value FKIN + F1 + F2);
/// Coulomb's law may give μ per grid row instead (`mu_rows`, `my` values).
pub fn read(top: &mut Section, mu: Option<f64>, my: usize) -> Result<FrictionSpec, InputError> {
    let Some(mut f) = top.opt_table("friction")?.map(|f| f.declare(&KEYS)) else {
        return coulomb(mu, Memory::NONE);
    };
    let law = f.pick("law")?;
    if law != "temperature" {
        for key in TEMPERATURE_KEYS {
            f.refuse(key, "only with law = \"temperature\"")?;
        }
    }
    if law == "temperature" {
        return temperature(f, mu);
    }
    if law == "coulomb" {
        for key in FALLING_KEYS.into_iter().chain(["memory_mm", "memory_s0_mm_s"]) {
            f.refuse(key, "only with a falling law (law = \"linear\", \"rational\" or \"exponential\")")?;
        }
        let rows = mu_rows(&mut f, mu, my)?;
        f.finish()?;
        return match rows {
            Some(rows) => {
                let mu_static = rows.mu_max();
                Ok(FrictionSpec {
                    law: FrictionLaw::Coulomb { mu: mu_static },
                    memory: Memory::NONE,
                    mu_static,
                    rows: Some(rows),
                })
            }
            None => coulomb(mu, Memory::NONE),
        };
    }
    f.refuse("mu_rows", "only with law = \"coulomb\" (a falling law is one for the whole contact)")?;
    let terms = FallingTerms {
        fkin: f.num("fkin")?,
        f1: f.num("f1")?,
        sabsh1_mm_s: f.num("sabsh1_mm_s")?,
        f2: f.num_or_default("f2")?,
        sabsh2_mm_s: f.num_or_default("sabsh2_mm_s")?,
    };
    if terms.f2 > 0.0 && terms.sabsh2_mm_s <= 0.0 {
        let given = if f.has("sabsh2_mm_s") { terms.sabsh2_mm_s.to_string() } else { "missing".into() };
        return Err(InputError::new(f.field("sabsh2_mm_s"), given, "a slip velocity > 0 [mm/s] when f2 > 0"));
    }
    let law = match law {
        "linear" => FrictionLaw::Linear(terms),
        "rational" => FrictionLaw::Rational(terms),
        _ => FrictionLaw::Exponential(terms),
    };
    let memory = memory(&mut f)?;
    let mu_static = law.mu_static();
    if !(mu_static > 0.0 && mu_static <= 1e3) {
        let given = format!("{} (fkin + f1 + f2 = {mu_static})", terms.fkin);
        return Err(InputError::new(f.field("fkin"), given, "a static value fkin + f1 + f2 in (0, 1000]"));
    }
    f.finish()?;
    if let Some(given) = mu {
        if (given - mu_static).abs() > MU_STATIC_REL * mu_static {
            return Err(InputError::new(
                "contact.mu",
                given,
                format!(
                    "left out with a falling friction law, or equal to its static value fkin + f1 + f2 = {mu_static}"
                ),
            ));
        }
    }
    Ok(FrictionSpec { law, memory, mu_static, rows: None })
}

/// `memory_mm`, `memory_s0_mm_s` (CONTACT's MEMDST, MEM_S0): none without `memory_mm`.
fn memory(f: &mut Section) -> Result<Memory, InputError> {
    match f.opt_num("memory_mm")? {
        Some(memory_mm) => Ok(Memory { memory_mm, s0_mm_s: f.num_or_default("memory_s0_mm_s")? }),
        None => {
            f.refuse("memory_s0_mm_s", "only with memory_mm (the memory's relaxation distance)")?;
            Ok(Memory::NONE)
        }
    }
}

/// `law = "temperature"` (CONTACT's L = 6): FREF, TREF, DFHEAT, DTHEAT with FREF + DFHEAT > 0
/// (`m_friclaw.f90` lines 819-824), and the memory (with L = 6 CONTACT relaxes μ at the rate of
/// the slip velocity its iteration starts from, `solvers/contact/tempdep.rs`); μ's static value
/// is FREF.
fn temperature(mut f: Section, mu: Option<f64>) -> Result<FrictionSpec, InputError> {
    for key in FALLING_KEYS {
        f.refuse(key, "only with a falling law (law = \"linear\", \"rational\" or \"exponential\"); law = \"temperature\" takes fref, tref_c, dfheat, dtheat_c")?;
    }
    f.refuse("mu_rows", "only with law = \"coulomb\" (the temperature law is one for the whole contact)")?;
    let t = TemperatureLaw {
        fref: f.num("fref")?,
        tref_c: f.num("tref_c")?,
        dfheat: f.num("dfheat")?,
        dtheat_c: f.num("dtheat_c")?,
    };
    if t.fref + t.dfheat <= 0.0 {
        let given = format!("{} (fref + dfheat = {})", t.dfheat, t.fref + t.dfheat);
        return Err(InputError::new(
            f.field("dfheat"),
            given,
            "fref + dfheat > 0 (μ at high temperatures stays positive)",
        ));
    }
    let memory = memory(&mut f)?;
    f.finish()?;
    if let Some(given) = mu.filter(|&m| m != t.fref) {
        return Err(InputError::new(
            "contact.mu",
            given,
            format!("left out with law = \"temperature\", or equal to its fref = {}", t.fref),
        ));
    }
    Ok(FrictionSpec { law: FrictionLaw::Temperature(t), memory, mu_static: t.fref, rows: None })
}

/// `[friction] mu_rows` (Coulomb only): μ of every grid row, `my` values in (0, 1000], the first
/// at the lowest y (CONTACT's V = 3, FSTAT per row IY); `contact.mu` is then left out.
fn mu_rows(f: &mut Section, mu: Option<f64>, my: usize) -> Result<Option<RowFriction>, InputError> {
    let Some(list) = f.opt_num_list("mu_rows")? else {
        return Ok(None);
    };
    if list.len() != my {
        return Err(InputError::new(
            f.field("mu_rows"),
            format!("{} values", list.len()),
            format!("one coefficient per grid row: grid.my = {my} values, the first at the lowest y"),
        ));
    }
    if let Some(given) = mu {
        return Err(InputError::new(
            "contact.mu",
            given,
            "left out with [friction] mu_rows (the rows give the friction; the nominal mu is their largest)",
        ));
    }
    Ok(RowFriction::new(list))
}

/// Coulomb's law with `contact.mu` (required).
fn coulomb(mu: Option<f64>, memory: Memory) -> Result<FrictionSpec, InputError> {
    let mu = mu.ok_or_else(|| {
        InputError::new("contact.mu", "missing", "a coefficient of friction in (0, 1000] (or a falling [friction] law)")
    })?;
    Ok(FrictionSpec { law: FrictionLaw::Coulomb { mu }, memory, mu_static: mu, rows: None })
}
