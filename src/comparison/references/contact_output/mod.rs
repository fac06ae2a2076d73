//! CONTACT's printed output (`.out`, `.ref_out`) read case by case (issue 32 item 2): the totals
//! it prints for each module-3 case, each value with the resolution of its printed digits, in
//! this project's sign convention (reference/README.md, "Signs"; converted in [`totals`] only).
//! Module-1 (wheel–rail) cases keep their case numbers and are not read here: [`wheelrail`] reads them. The one reader of
//! CONTACT's printed totals: `scripts/contact_to_csv.py` reads the same text and
//! `tests/all/contact_output.rs` checks that both give the same numbers on every shipped file.

pub mod printed;
pub mod reference_csv;
pub mod scan;
pub mod wheelrail;

use crate::error::Error;
use printed::Printed;
use scan::{Block, BlockKind, ScannedCase};
use std::path::Path;

/// The largest output file read (the largest of CONTACT's public examples has 1.5 MB).
const LIMIT_BYTES: u64 = 256 << 20;

/// Why a file is not CONTACT's printed output as this reader knows it.
#[derive(Debug, thiserror::Error)]
pub enum ContactOutputError {
    #[error("no line `Case n`: not CONTACT's printed output")]
    NoCase,
    #[error(
        "none of its {cases} case(s) is a module-3 case with printed totals ({module1} module-1 case(s), not read)"
    )]
    NoTotals { cases: usize, module1: usize },
    #[error(
        "line {line}: {got:?} under the labels `{labels}` of the {block} block: expected one printed number per label"
    )]
    Values { line: usize, block: &'static str, labels: String, got: String },
    #[error("case {case} (line {line}): prints the {block} block but not its second line (FN/G … APPROACH PMAX)")]
    NoRatios { case: u32, line: usize, block: &'static str },
    #[error("line {line} (case {case}): the {block} block has no {label}")]
    Missing { case: u32, line: usize, block: &'static str, label: &'static str },
    #[error("line {line} (case {case}): {label} = {value} is not a count (a whole number >= 0)")]
    NotACount { case: u32, line: usize, label: &'static str, value: f64 },
}

/// One `Case n` of the output.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseOutput {
    pub case: u32,
    /// The line of its `Case n` (1-based).
    pub line: usize,
    pub body: CaseBody,
}

/// What a case printed.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseBody {
    /// A module-3 case's totals.
    Totals(Box<Totals>),
    /// A module-1 (wheel–rail) case: not read (this project has no wheel–rail profiles).
    Module1,
    /// No totals (OUTPUT digit 0, or a case that stopped).
    Nothing,
}

/// The totals of one module-3 case, this project's convention: forces and moment on body 2
/// (CONTACT prints those on body 1), so that positive creepage gives positive fx/fn.
#[derive(Debug, Clone, PartialEq)]
pub struct Totals {
    pub fn_n: Printed,
    /// −FX, −FY, −MZ of CONTACT.
    pub fx_n: Printed,
    pub fy_n: Printed,
    pub mz_nmm: Printed,
    /// ELAST.EN. [N mm].
    pub elastic_energy_nmm: Printed,
    /// FRIC.POWER (rolling, [N mm/s]) or FRIC.WORK (shifts, [N mm]) with CONTACT's sign.
    pub frictional: Frictional,
    /// What the totals' second line prints in the places of FX/FSTAT/FN and FY/FSTAT/FN.
    pub x: Tangential,
    pub y: Tangential,
    /// APPROACH [mm] and PMAX [N/mm²].
    pub approach_mm: Printed,
    pub pn_max_mpa: Printed,
    /// The largest surface temperature of both bodies on the contact [°C] (H ≥ 1: `MAX(T1,T2)`
    /// beside PMAX, or the larger of `MAX(T1)`, `MAX(T2)`); `None`: not printed.
    pub temperature_max_c: Option<Printed>,
    /// The KINEMATIC CONSTANTS block, printed with OUTPUT ≥ 2.
    pub kinematics: Option<Kinematics>,
    /// The FRICTION LAW PARAMETERS block.
    pub friction: Friction,
    /// The CONTACT STATISTICS block, printed with OUTPUT ≥ 2.
    pub statistics: Option<Statistics>,
}

/// The frictional dissipation CONTACT prints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Frictional {
    /// FRIC.POWER [N mm/s] (rolling).
    PowerNmmPerS(Printed),
    /// FRIC.WORK [N mm] (shifts, T = 1).
    WorkNmm(Printed),
}

/// The friction a case prints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Friction {
    /// No FRICTION LAW PARAMETERS block (OUTPUT < 2: the friction of an earlier case, or unknown).
    NotPrinted,
    /// `FSTAT FKIN`: Coulomb friction, one coefficient for the whole contact.
    Coulomb { fstat: Printed, fkin: Printed },
    /// Another law or friction varying per row (`FKIN FEXP1 …`, `IY FSTAT FKIN`): no one μ.
    Other,
}

impl Friction {
    /// FSTAT where it is the contact's one static coefficient.
    pub fn fstat(&self) -> Option<Printed> {
        match *self {
            Friction::Coulomb { fstat, .. } => Some(fstat),
            _ => None,
        }
    }
}

/// A tangential quantity in the x or y place of the totals' second line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tangential {
    /// F/FSTAT/FN (−FX/FSTAT/FN of CONTACT): the creepage was prescribed.
    ForceOverFstatFn(Printed),
    /// F/FN (−FX/FN of CONTACT), printed where FSTAT is not the friction coefficient.
    ForceOverFn(Printed),
    /// CREEP X or Y: the creepage solved for under a prescribed force (rolling).
    SolvedCreepage(Printed),
    /// SHIFT X or Y: the shift solved for under a prescribed force (T = 1) [mm].
    SolvedShiftMm(Printed),
}

/// The KINEMATIC CONSTANTS block.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics {
    pub stepping: Stepping,
    /// VELOC [mm/s].
    pub veloc_mm_s: Printed,
    /// CKSI / CETA, or the prescribed force (−FX/FSTAT/FN, −FY/FSTAT/FN of CONTACT).
    pub x: Prescribed,
    pub y: Prescribed,
    /// CPHI [1/mm].
    pub cphi_per_mm: Printed,
}

/// How the case steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Stepping {
    /// DT [s] (shifts).
    Shift { dt_s: Printed },
    /// CHI [deg] and DQ [mm] (rolling).
    Rolling { chi_deg: Printed, dq_mm: Printed },
}

/// What the kinematic block prescribes in the x or y place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Prescribed {
    /// CKSI or CETA (a shift [mm] under T = 1).
    Creepage(Printed),
    /// F/FSTAT/FN on body 2 (−FX/FSTAT/FN of CONTACT).
    ForceOverFstatFn(Printed),
}

/// The CONTACT STATISTICS block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Statistics {
    pub npot: u32,
    pub ncon: u32,
    pub nadh: u32,
    pub nslip: u32,
    pub inorm: i32,
    pub itang: i32,
}

impl Totals {
    /// The creepage (shift) in x: prescribed, or solved for under a prescribed force.
    pub fn cx(&self) -> Option<Printed> {
        match (self.kinematics.map(|k| k.x), self.x) {
            (Some(Prescribed::Creepage(c)), _) => Some(c),
            (_, Tangential::SolvedCreepage(c) | Tangential::SolvedShiftMm(c)) => Some(c),
            _ => None,
        }
    }

    /// The creepage (shift) in y, as [`Totals::cx`].
    pub fn cy(&self) -> Option<Printed> {
        match (self.kinematics.map(|k| k.y), self.y) {
            (Some(Prescribed::Creepage(c)), _) => Some(c),
            (_, Tangential::SolvedCreepage(c) | Tangential::SolvedShiftMm(c)) => Some(c),
            _ => None,
        }
    }

    /// FX/FSTAT/FN on body 2: printed with the totals, or prescribed.
    pub fn fx_over_fstat_fn(&self) -> Option<Printed> {
        over_fstat_fn(self.x, self.kinematics.map(|k| k.x))
    }

    /// FY/FSTAT/FN on body 2, as [`Totals::fx_over_fstat_fn`].
    pub fn fy_over_fstat_fn(&self) -> Option<Printed> {
        over_fstat_fn(self.y, self.kinematics.map(|k| k.y))
    }
}

fn over_fstat_fn(printed: Tangential, prescribed: Option<Prescribed>) -> Option<Printed> {
    match (printed, prescribed) {
        (Tangential::ForceOverFstatFn(f), _) | (_, Some(Prescribed::ForceOverFstatFn(f))) => Some(f),
        _ => None,
    }
}

/// Every case of CONTACT's output file `path`.
pub fn read(path: &Path) -> Result<Vec<CaseOutput>, Error> {
    let text = crate::safety::read::read_text(path, LIMIT_BYTES, "CONTACT's output")?;
    parse(&text).map_err(|e| Error::Import { path: path.to_path_buf(), source: Box::new(e) })
}

/// Every case of CONTACT's printed output `text`, in the order printed.
pub fn parse(text: &str) -> Result<Vec<CaseOutput>, ContactOutputError> {
    scan::scan(text)?.iter().map(case_output).collect()
}

fn case_output(c: &ScannedCase) -> Result<CaseOutput, ContactOutputError> {
    let body = match (c.module1, c.block(BlockKind::Totals)) {
        (true, _) => CaseBody::Module1,
        (false, None) => CaseBody::Nothing,
        (false, Some(t)) => CaseBody::Totals(Box::new(totals(c, t)?)),
    };
    Ok(CaseOutput { case: c.case, line: c.line, body })
}

/// A block's value under one of `labels` (the first printed).
fn first_of(case: u32, b: &Block, labels: &[&'static str]) -> Result<(&'static str, Printed), ContactOutputError> {
    let found = labels.iter().find_map(|&l| b.get(l).map(|v| (l, v)));
    found.ok_or(ContactOutputError::Missing { case, line: b.line, block: b.kind.name(), label: labels[0] })
}

/// The totals of a module-3 case: the one place where CONTACT's signs (tractions on body 1)
/// become this project's (on body 2): FX, FY, MZ and every force ratio change sign; creepages,
/// shifts, FN, the energies and the counts are kept.
fn totals(c: &ScannedCase, t: &Block) -> Result<Totals, ContactOutputError> {
    let case = c.case;
    let get = |b: &Block, l: &'static str| first_of(case, b, &[l]).map(|(_, v)| v);
    let r = c.block(BlockKind::Ratios).ok_or(ContactOutputError::NoRatios {
        case,
        line: t.line,
        block: BlockKind::Totals.name(),
    })?;
    let frictional = match first_of(case, t, &["FRIC.POWER", "FRIC.WORK"])? {
        ("FRIC.POWER", v) => Frictional::PowerNmmPerS(v),
        (_, v) => Frictional::WorkNmm(v),
    };
    let tangential = |labels: [&'static str; 4]| -> Result<Tangential, ContactOutputError> {
        Ok(match first_of(case, r, &labels)? {
            (l, v) if l == labels[0] => Tangential::ForceOverFstatFn(v.negated()),
            (l, v) if l == labels[1] => Tangential::ForceOverFn(v.negated()),
            (l, v) if l == labels[2] => Tangential::SolvedCreepage(v),
            (_, v) => Tangential::SolvedShiftMm(v),
        })
    };
    Ok(Totals {
        fn_n: get(t, "FN")?,
        fx_n: get(t, "FX")?.negated(),
        fy_n: get(t, "FY")?.negated(),
        mz_nmm: get(t, "MZ")?.negated(),
        elastic_energy_nmm: get(t, "ELAST.EN.")?,
        frictional,
        x: tangential(["FX/FSTAT/FN", "FX/FN", "CREEP X", "SHIFT X"])?,
        y: tangential(["FY/FSTAT/FN", "FY/FN", "CREEP Y", "SHIFT Y"])?,
        approach_mm: get(r, "APPROACH")?,
        pn_max_mpa: get(r, "PMAX")?,
        temperature_max_c: temperature_max(r),
        kinematics: c.block(BlockKind::Kinematics).map(|k| kinematics(case, k)).transpose()?,
        friction: friction(c.block(BlockKind::Friction)),
        statistics: c.block(BlockKind::Statistics).map(|s| statistics(case, s)).transpose()?,
    })
}

/// The largest surface temperature the second line prints (`m_soutpt.f90`: MAX(T1,T2) with PMAX,
/// else MAX(T1) and MAX(T2)).
fn temperature_max(r: &Block) -> Option<Printed> {
    r.get("MAX(T1,T2)").or_else(|| {
        let (one, two) = (r.get("MAX(T1)")?, r.get("MAX(T2)")?);
        Some(if two.value > one.value { two } else { one })
    })
}

/// The FRICTION LAW PARAMETERS block: Coulomb where it prints exactly `FSTAT FKIN`.
fn friction(f: Option<&Block>) -> Friction {
    let Some(f) = f else { return Friction::NotPrinted };
    match (f.values.len(), f.get("FSTAT"), f.get("FKIN")) {
        (2, Some(fstat), Some(fkin)) => Friction::Coulomb { fstat, fkin },
        _ => Friction::Other,
    }
}

/// The KINEMATIC CONSTANTS block (prescribed forces change sign, as in [`totals`]).
fn kinematics(case: u32, k: &Block) -> Result<Kinematics, ContactOutputError> {
    let get = |l: &'static str| first_of(case, k, &[l]).map(|(_, v)| v);
    let prescribed = |creepage: &'static str, force: &'static str| -> Result<Prescribed, ContactOutputError> {
        Ok(match first_of(case, k, &[creepage, force])? {
            (l, v) if l == creepage => Prescribed::Creepage(v),
            (_, v) => Prescribed::ForceOverFstatFn(v.negated()),
        })
    };
    let stepping = match k.get("DT") {
        Some(dt_s) => Stepping::Shift { dt_s },
        None => Stepping::Rolling { chi_deg: get("CHI")?, dq_mm: get("DQ")? },
    };
    Ok(Kinematics {
        stepping,
        veloc_mm_s: get("VELOC")?,
        x: prescribed("CKSI", "FX/FSTAT/FN")?,
        y: prescribed("CETA", "FY/FSTAT/FN")?,
        cphi_per_mm: get("CPHI")?,
    })
}

/// The CONTACT STATISTICS block.
fn statistics(case: u32, s: &Block) -> Result<Statistics, ContactOutputError> {
    let count = |l: &'static str| -> Result<f64, ContactOutputError> {
        let v = first_of(case, s, &[l])?.1.value;
        let whole = v.fract() == 0.0 && v.abs() < 1e9;
        whole.then_some(v).ok_or(ContactOutputError::NotACount { case, line: s.line, label: l, value: v })
    };
    let unsigned = |l: &'static str| -> Result<u32, ContactOutputError> {
        let v = count(l)?;
        (v >= 0.0).then_some(v as u32).ok_or(ContactOutputError::NotACount { case, line: s.line, label: l, value: v })
    };
    Ok(Statistics {
        npot: unsigned("NPOT")?,
        ncon: unsigned("NCON")?,
        nadh: unsigned("NADH")?,
        nslip: unsigned("NSLIP")?,
        inorm: count("INORM")? as i32,
        itang: count("ITANG")? as i32,
    })
}
