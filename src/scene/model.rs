//! `[model]` (optional): the options the simplified models share; the keys left are the models'
//! own parameters, declared and read by each model (`solvers::MODEL_KEYS`). The scene's keys
//! are declared once ([`KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Deferred, Range, Section};
use super::ModelOptions;
use crate::error::InputError;
use crate::physics::{CoefficientSource, FlexibilityModel, LeadingEdge, PatchFlexibility, PressureShape};

/// `[model]`'s keys the scene reads (`<!-- keys:model -->`; the models declare their own, `solvers::MODEL_KEYS`).
pub const KEYS: Keys = Keys {
    id: "model",
    owner: file!(),
    keys: &[
        key(
            "flexibility",
            "–",
            Allowed::Choice(&["kalker", "thesis"], ""),
            Absent::Choice("kalker"),
            r#"FASTSIM's and the UBA's flexibilities L1, L2, L3: Kalker's simplified theory (thesis Eq. 2.35) or the thesis's Eq. 3.5 (L1 = L2 = 2b(1 + ν)/E, L3 = b(1 + ν)(1 − 2ν)/((1 − ν)E)): `flexibility = "thesis"`"#,
        ),
        key(
            "coefficients",
            "–",
            Allowed::Choice(&["table", "fit"], ""),
            Absent::Choice("table"),
            r#"Kalker's coefficients C11, C22, C23, C33: his Table A1 interpolated in ν and the axis ratio (beyond b/a 0.1 … 10 extrapolated, with a warning), or the polynomial fit of Eq. 2.36 (refused outside 1/25 ≤ b/a ≤ 25; made for ν = 0.27, a warning when ν is more than 0.02 away): `coefficients = "fit"`"#,
        ),
        key(
            "pressure",
            "–",
            Allowed::Choice(&["parabolic", "ellipsoidal"], ""),
            Absent::Choice("parabolic"),
            r#"the pressure under the traction bound μp of the simplified models: parabolic (Eq. 2.32, what CONTACT's FASTSIM uses) or Hertz's ellipsoidal (Eq. 2.9): `pressure = "ellipsoidal"`"#,
        ),
        key(
            "leading_edge",
            "–",
            Allowed::Choice(&["grid", "exact"], ""),
            Absent::Choice("grid"),
            r#"where the simplified models start each row: one element upstream of the first loaded element (the UBA's own scheme, what CONTACT's FASTSIM does) or the ellipse's exact edge (Kalker's strip integration): `leading_edge = "exact"`"#,
        ),
        key(
            "flexibilities",
            "–",
            Allowed::Choice(&["three", "one"], ""),
            Absent::Choice("three"),
            r#"FASTSIM and the UBA with Kalker's three flexibilities, or his single one (Kalker 1982) L = (\|cx\|·L1 + \|cy\|·L2 + c·\|cs\|·L3)/√(cx² + cy² + c²·cs²), c = √(ab), recomputed for every sample's creepage: `flexibilities = "one"`"#,
        ),
        key(
            "slope_reduction",
            "–",
            Allowed::Numbers {
                range: Range::new(0.0, true, 1e3, true),
                min_len: 3,
                max_len: 3,
                note: "`[k0, alpha, beta]` with k0 > 0, alpha ≤ 1",
            },
            Absent::Text("absent: no reduction"),
            r#"the modified FASTSIM (Spiryagin, Polach & Cole 2013, as CONTACT's M = 2/3 options): FASTSIM's and the UBA's flexibilities divided by k = k0·(α + (1 − α)/(1 + β·ε)), ε = G·π·a·b·k0·C11·w/(4·μ·FN), w = √(cx² + (cy + a·cs)²): `slope_reduction = [1.0, 0.5, 2.0]`"#,
        ),
        key(
            "nonhertz_flexibility",
            "–",
            Allowed::Choice(&["equivalent_ellipse", "strip"], ""),
            Absent::Choice("equivalent_ellipse"),
            r#"the simplified models on a contact given per element (both run on the exact normal pressure): Kalker's flexibilities of Kik & Piotrowski's equivalent ellipse (its area and length-to-width ratio kept, as CONTACT's FASTSIM) or per strip scaled by its half-length, L(y) = L·a(y)/a_e: `nonhertz_flexibility = "strip"`"#,
        ),
    ],
};

/// `[model]` (optional): the options the simplified models share; the keys left are the models'
/// own parameters, which the pipeline has each model read.
pub fn read(top: &mut Section) -> Result<(ModelOptions, Deferred), InputError> {
    let mut model = ModelOptions::default();
    let Some(mut md) = top.opt_table("model")?.map(|m| m.declare(&KEYS)) else {
        return Ok((model, Deferred::empty("model", &KEYS)));
    };
    if let Some(f) = md.opt_pick("flexibility")? {
        model.flexibility = if f == "thesis" { FlexibilityModel::Thesis } else { FlexibilityModel::Kalker };
    }
    if let Some(c) = md.opt_pick("coefficients")? {
        model.coefficients = if c == "fit" { CoefficientSource::Fit } else { CoefficientSource::Table };
    }
    if let Some(p) = md.opt_pick("pressure")? {
        model.pressure = if p == "ellipsoidal" { PressureShape::Ellipsoidal } else { PressureShape::Parabolic };
    }
    if let Some(e) = md.opt_pick("leading_edge")? {
        model.leading_edge = if e == "exact" { LeadingEdge::Exact } else { LeadingEdge::Grid };
    }
    model.slope_reduction = slope_reduction(&mut md)?;
    if let Some(n) = md.opt_pick("flexibilities")? {
        model.single_flexibility = n == "one";
    }
    if let Some(f) = md.opt_pick("nonhertz_flexibility")? {
        model.nonhertz_flexibility =
            if f == "strip" { PatchFlexibility::Strip } else { PatchFlexibility::EquivalentEllipse };
    }
    Ok((model, md.defer()))
}

/// `[model] slope_reduction = [k0, alpha, beta]` (optional): k0 > 0, 0 ≤ α ≤ 1, β ≥ 0.
fn slope_reduction(md: &mut Section) -> Result<Option<[f64; 3]>, InputError> {
    let Some([k0, alpha, beta]) = md.opt_nums::<3>("slope_reduction")? else {
        return Ok(None);
    };
    if !(k0 > 0.0 && (0.0..=1.0).contains(&alpha)) {
        return Err(InputError::new(
            md.field("slope_reduction"),
            format!("[{k0}, {alpha}, {beta}]"),
            "[k0, alpha, beta] with k0 > 0, 0 <= alpha <= 1, beta >= 0",
        ));
    }
    Ok(Some([k0, alpha, beta]))
}
