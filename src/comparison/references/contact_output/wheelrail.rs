//! CONTACT's printed module-1 (wheel–rail) output read case by case (user guide, Section 3.8
//! "Global outputs for module 1"; printed by `wr_output` in CONTACT's `m_wr_output.f90`): per
//! case its heading (wheel side, rail or roller, number of patches), the wheelset position and
//! velocity, the rail irregularity and massless-rail deflection, the flexible wheel deviations and
//! the total forces on the rail; per contact patch its reference location, kinematic constants,
//! totals and statistics. Every number as printed, in CONTACT's units and signs (N, mm, rad, s;
//! forces on the rail, body 1; `y` mirrored back for a left wheel as CONTACT prints it), with half
//! a unit of its last printed digit ([`Printed`]). The module-3 cases of a mixed file are skipped:
//! [`super::parse`] reads them.

use super::printed::Printed;
use super::scan::labels;
use super::Statistics;
use crate::error::Error;
use std::path::Path;

/// The largest output file read (as [`super::read`]).
const LIMIT_BYTES: u64 = 256 << 20;

/// Why a file is not CONTACT's printed module-1 output as this reader knows it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WheelRailOutputError {
    #[error("no line `Case n`: not CONTACT's printed output")]
    NoCase,
    #[error(
        "line {line}: {got:?} under the labels `{labels}` of the {block} block: expected one printed number per label"
    )]
    Values { line: usize, block: &'static str, labels: String, got: String },
    #[error("line {line} (case {case}): {label} = {value} is not a count as CONTACT prints it (a whole number, >= 0 for an element count)")]
    NotACount { case: u32, line: usize, label: &'static str, value: f64 },
    #[error(
        "line {line}: {got:?} is not a heading `WHEEL-RAIL|ROLLER CONTACT, LEFT|RIGHT WHEEL, n CONTACT PATCH(ES)`"
    )]
    Heading { line: usize, got: String },
    #[error("line {line}: {got:?} is not a patch line `----- DATA FOR CONTACT PATCH n [(NEW PATCH|PREV i, j)] -----`")]
    PatchLine { line: usize, got: String },
    #[error("line {line} (case {case}): the {block} block is printed outside a contact patch")]
    OutsidePatch { case: u32, line: usize, block: &'static str },
    #[error("line {line} (case {case}): the patch totals (FN FX FS …) are not followed by their second line (FN/G … APPROACH)")]
    NoRatios { case: u32, line: usize },
    #[error("line {line} (case {case}): the heading announces {announced} contact patch(es), {printed} are printed")]
    PatchCount { case: u32, line: usize, announced: u32, printed: usize },
}

/// Whether the wheel rolls on a rail (C = 0, 1) or on a roller (C = 4, 5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Support {
    Rail,
    Roller,
}

/// The wheel of the wheelset a case computes (the C digit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WheelSide {
    Left,
    Right,
}

/// `WHEEL-RAIL CONTACT, LEFT WHEEL,  1 CONTACT PATCH`, printed with OUTPUT ≥ 2.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Heading {
    pub support: Support,
    pub side: WheelSide,
    pub patches: u32,
}

/// Where the wheelset is along the track: `S_WS` on a track, `X_WS` on a roller rig.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Along {
    TrackSMm(Printed),
    RollerXMm(Printed),
}

/// `S_WS|X_WS Y_WS Z_WS ROLL_WS YAW_WS PITCH_WS` [mm, rad].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetPosition {
    pub along: Along,
    pub y_mm: Printed,
    pub z_mm: Printed,
    pub roll_rad: Printed,
    pub yaw_rad: Printed,
    pub pitch_rad: Printed,
}

/// The first column of the velocity line: the forward velocity on a track, the rollers' angular
/// velocity on a roller rig.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Forward {
    VxMmS(Printed),
    RollerPitchRadS(Printed),
}

/// `VX_WS|VPITCH_ROL VY_WS VZ_WS VROLL_WS VYAW_WS VPITCH_WS` [mm/s, rad/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetVelocity {
    pub forward: Forward,
    pub vy_mm_s: Printed,
    pub vz_mm_s: Printed,
    pub vroll_rad_s: Printed,
    pub vyaw_rad_s: Printed,
    pub vpitch_rad_s: Printed,
}

/// RAIL IRREGULARITY `DYRAIL DZRAIL DROLLR VYRAIL VZRAIL VROLLR`, printed where not all zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailIrregularity {
    pub dy_mm: Printed,
    pub dz_mm: Printed,
    pub droll_rad: Printed,
    pub vy_mm_s: Printed,
    pub vz_mm_s: Printed,
    pub vroll_rad_s: Printed,
}

/// MASSLESS RAIL DEFLECTION `KY_RAIL DY_DEFL FY_RAIL KZ_RAIL DZ_DEFL FZ_RAIL` (F = 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailDeflection {
    pub ky_n_mm: Printed,
    pub dy_defl_mm: Printed,
    pub fy_rail_n: Printed,
    pub kz_n_mm: Printed,
    pub dz_defl_mm: Printed,
    pub fz_rail_n: Printed,
}

/// FLEXIBLE WHEEL-SET DEVIATIONS, positions `DXWHL DYWHL DZWHL DROLLW DYAWW DPITCHW`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelDeviation {
    pub dx_mm: Printed,
    pub dy_mm: Printed,
    pub dz_mm: Printed,
    pub droll_rad: Printed,
    pub dyaw_rad: Printed,
    pub dpitch_rad: Printed,
}

/// FLEXIBLE WHEEL-SET DEVIATIONS, velocities `VXWHL VYWHL VZWHL VROLLW VYAWW VPITCHW`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelDeviationRate {
    pub vx_mm_s: Printed,
    pub vy_mm_s: Printed,
    pub vz_mm_s: Printed,
    pub vroll_rad_s: Printed,
    pub vyaw_rad_s: Printed,
    pub vpitch_rad_s: Printed,
}

/// TOTAL FORCES ON RAIL (or ROLLER) `FX(TR) FY(TR) FZ(TR) FX(WS) FY(WS) FZ(WS)` [N]: on the rail,
/// in track and in wheelset coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailForces {
    pub fx_tr_n: Printed,
    pub fy_tr_n: Printed,
    pub fz_tr_n: Printed,
    pub fx_ws_n: Printed,
    pub fy_ws_n: Printed,
    pub fz_ws_n: Printed,
}

/// `MX@R(TR) MY@R(TR) MZ@R(TR) MX@W(WS) MY@W(WS) MZ@W(WS)` [N mm], printed with OUTPUT ≥ 4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailMoments {
    pub mx_r_tr_nmm: Printed,
    pub my_r_tr_nmm: Printed,
    pub mz_r_tr_nmm: Printed,
    pub mx_w_ws_nmm: Printed,
    pub my_w_ws_nmm: Printed,
    pub mz_w_ws_nmm: Printed,
}

/// Which earlier patches a patch continues (printed when P ≠ 2).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PatchHistory {
    /// P = 2: no sequence, nothing printed.
    NotPrinted,
    /// `(NEW PATCH)`.
    New,
    /// `(PREV i, j)`: the patches of the previous case it continues.
    Previous(Vec<u32>),
}

/// CONTACT REFERENCE LOCATION `XCP(TR) YCP(TR) ZCP(TR) DELTCP(TR) YCP(R) ZCP(R)` [mm, rad]: the
/// contact reference point in track coordinates, its contact angle, and on the rail profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceLocation {
    pub xcp_tr_mm: Printed,
    pub ycp_tr_mm: Printed,
    pub zcp_tr_mm: Printed,
    pub deltcp_tr_rad: Printed,
    pub ycp_r_mm: Printed,
    pub zcp_r_mm: Printed,
}

/// `XCP(W) YCP(W) ZCP(W)` [mm]: the contact reference point on the wheel profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelReference {
    pub xcp_w_mm: Printed,
    pub ycp_w_mm: Printed,
    pub zcp_w_mm: Printed,
}

/// KINEMATIC CONSTANTS `CHI DQ VELOC CKSI CETA CPHI` of a patch [rad, mm, mm/s, -, -, 1/mm].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchKinematics {
    pub chi_rad: Printed,
    pub dq_mm: Printed,
    pub veloc_mm_s: Printed,
    pub cksi: Printed,
    pub ceta: Printed,
    pub cphi_per_mm: Printed,
}

/// A force ratio of the totals' second line: over FSTAT·FN, or over FN where the friction varies
/// (V = 1: CONTACT's `use_muscal` is off).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ratio {
    OverFstatFn(Printed),
    OverFn(Printed),
}

impl Ratio {
    pub fn value(&self) -> Printed {
        match *self {
            Ratio::OverFstatFn(p) | Ratio::OverFn(p) => p,
        }
    }
}

/// The first place of the totals' second line: FN/G (planar contact) or TILDE_FN (conformal).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalMeasure {
    FnOverGMm2(Printed),
    TildeFnN(Printed),
}

/// The maximum surface temperatures printed with H ≥ 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MaxTemperature {
    /// `MAX(T1) MAX(T2)`.
    Each(Printed, Printed),
    /// `MAX(T1,T2)`.
    Both(Printed),
}

/// TOTAL FORCES, TORSIONAL MOMENT, ELASTIC ENERGY, FRICTIONAL POWER of a patch, in its contact
/// coordinates, with the second line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchTotals {
    /// `BAR_FN BAR_FX BAR_FS` (conformal contact, D = 4) instead of `FN FX FS`.
    pub conformal: bool,
    pub fn_n: Printed,
    pub fx_n: Printed,
    pub fs_n: Printed,
    pub mn_nmm: Printed,
    pub elastic_energy_nmm: Printed,
    pub fric_power_nmm_s: Printed,
    pub normal: NormalMeasure,
    pub fx_ratio: Ratio,
    pub fs_ratio: Ratio,
    pub approach_mm: Printed,
    pub pmax_mpa: Option<Printed>,
    pub max_temperature: Option<MaxTemperature>,
}

/// One contact patch of a case.
#[derive(Debug, Clone, PartialEq)]
pub struct Patch {
    /// Its number (1, 2, …) as printed.
    pub index: u32,
    /// The line of its `----- DATA FOR CONTACT PATCH` (1-based).
    pub line: usize,
    pub history: PatchHistory,
    pub reference: Option<ReferenceLocation>,
    pub wheel_reference: Option<WheelReference>,
    pub kinematics: Option<PatchKinematics>,
    /// `SPINXO SPINYO` [mm], printed where not zero.
    pub spin_centre_mm: Option<[Printed; 2]>,
    pub totals: Option<PatchTotals>,
    pub statistics: Option<Statistics>,
    /// NPLAST of the statistics (interfacial layer with plasticity).
    pub nplast: Option<u32>,
}

/// One module-1 case of the output.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelRailCase {
    pub case: u32,
    /// `Case n for w/r contact on result element k` (CONTACT's library).
    pub result_element: Option<u32>,
    /// The line of its `Case n` (1-based).
    pub line: usize,
    pub heading: Option<Heading>,
    pub position: Option<WheelsetPosition>,
    pub velocity: Option<WheelsetVelocity>,
    pub rail_irregularity: Option<RailIrregularity>,
    pub rail_deflection: Option<RailDeflection>,
    pub wheel_deviation: Option<WheelDeviation>,
    pub wheel_deviation_rate: Option<WheelDeviationRate>,
    pub forces: Option<RailForces>,
    pub moments: Option<RailMoments>,
    pub patches: Vec<Patch>,
}

impl WheelRailCase {
    /// The wheel side, where the heading is printed.
    pub fn side(&self) -> Option<WheelSide> {
        self.heading.map(|h| h.side)
    }
}

/// Every module-1 case of CONTACT's output file `path`.
pub fn read(path: &Path) -> Result<Vec<WheelRailCase>, Error> {
    let text = crate::safety::read::read_text(path, LIMIT_BYTES, "CONTACT's output")?;
    parse(&text).map_err(|e| Error::Import { path: path.to_path_buf(), source: Box::new(e) })
}

/// Every module-1 case of CONTACT's printed output `text`, in the order printed.
pub fn parse(text: &str) -> Result<Vec<WheelRailCase>, WheelRailOutputError> {
    let lines: Vec<&str> = text.lines().collect();
    let spans = case_spans(&lines);
    if spans.is_empty() {
        return Err(WheelRailOutputError::NoCase);
    }
    spans.into_iter().filter(|s| is_module1(&lines[s.body.clone()])).map(|s| read_case(&lines, s)).collect()
}

/// A `Case n` line and the lines up to the next one.
struct CaseSpan {
    case: u32,
    result_element: Option<u32>,
    /// Index of the `Case n` line.
    at: usize,
    body: std::ops::Range<usize>,
}

/// `Case 12` → (12, None); `Case 2 for w/r contact on result element 1` → (2, Some(1)).
fn case_line(line: &str) -> Option<(u32, Option<u32>)> {
    let words: Vec<&str> = line.split_whitespace().collect();
    (words.first() == Some(&"Case")).then_some(())?;
    let case = words.get(1)?.trim_end_matches(',').parse().ok()?;
    let element = match words.iter().position(|&w| w == "element") {
        Some(k) => words.get(k + 1).and_then(|w| w.parse().ok()),
        None => None,
    };
    Some((case, element))
}

fn case_spans(lines: &[&str]) -> Vec<CaseSpan> {
    let starts: Vec<(usize, u32, Option<u32>)> =
        lines.iter().enumerate().filter_map(|(i, l)| case_line(l).map(|(c, e)| (i, c, e))).collect();
    let ends = starts.iter().skip(1).map(|s| s.0).chain(std::iter::once(lines.len()));
    starts
        .iter()
        .zip(ends)
        .map(|(&(at, case, result_element), end)| CaseSpan { case, result_element, at, body: at + 1..end })
        .collect()
}

/// A module-1 case prints its heading, its patch lines, its control words `CPBTNFS.` or the
/// labels of its total forces on the rail (OUTPUT = 1 prints only the last two).
fn is_module1(body: &[&str]) -> bool {
    body.iter().any(|l| {
        let t = l.trim_start();
        t.starts_with("WHEEL-RAIL CONTACT")
            || t.starts_with("WHEEL-ROLLER CONTACT")
            || t.starts_with("CPBTNFS.")
            || t.contains("DATA FOR CONTACT PATCH")
            || labels(l).is_some_and(|ls| kind_of(&ls) == Some(Kind::Forces))
    })
}

/// The blocks of labels over one line of as many printed numbers that are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Position,
    Velocity,
    RailIrregularity,
    RailDeflection,
    WheelDeviation,
    WheelDeviationRate,
    Forces,
    Moments,
    Reference,
    WheelReference,
    Kinematics,
    SpinCentre,
    Totals,
    Ratios,
    Statistics,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Position => "wheelset position (S_WS … PITCH_WS)",
            Kind::Velocity => "wheelset velocity (VX_WS … VPITCH_WS)",
            Kind::RailIrregularity => "RAIL IRREGULARITY",
            Kind::RailDeflection => "MASSLESS RAIL DEFLECTION",
            Kind::WheelDeviation => "FLEXIBLE WHEEL-SET DEVIATIONS (DXWHL …)",
            Kind::WheelDeviationRate => "FLEXIBLE WHEEL-SET DEVIATIONS (VXWHL …)",
            Kind::Forces => "TOTAL FORCES ON RAIL",
            Kind::Moments => "TOTAL MOMENTS ON RAIL",
            Kind::Reference => "CONTACT REFERENCE LOCATION (XCP(TR) …)",
            Kind::WheelReference => "CONTACT REFERENCE LOCATION (XCP(W) …)",
            Kind::Kinematics => "KINEMATIC CONSTANTS",
            Kind::SpinCentre => "KINEMATIC CONSTANTS (SPINXO SPINYO)",
            Kind::Totals => "patch TOTAL FORCES (FN FX FS MN …)",
            Kind::Ratios => "patch totals' second line (FN/G … APPROACH)",
            Kind::Statistics => "CONTACT STATISTICS",
        }
    }

    fn in_patch(self) -> bool {
        matches!(
            self,
            Kind::Reference
                | Kind::WheelReference
                | Kind::Kinematics
                | Kind::SpinCentre
                | Kind::Totals
                | Kind::Ratios
                | Kind::Statistics
        )
    }
}

/// Whether `labels` are `columns` (each place one of its alternatives), exactly or as a prefix.
fn matches_columns(labels: &[String], columns: &[&[&str]], prefix: bool) -> bool {
    let length_ok = if prefix { labels.len() >= columns.len() } else { labels.len() == columns.len() };
    length_ok && labels.iter().zip(columns).all(|(l, alts)| alts.contains(&l.as_str()))
}

/// The labels of the blocks of a module-1 case (format statements of `wr_output`).
const BLOCKS: &[(Kind, &[&[&str]])] = &[
    (Kind::Position, &[&["S_WS", "X_WS"], &["Y_WS"], &["Z_WS"], &["ROLL_WS"], &["YAW_WS"], &["PITCH_WS"]]),
    (Kind::Velocity, &[&["VX_WS", "VPITCH_ROL"], &["VY_WS"], &["VZ_WS"], &["VROLL_WS"], &["VYAW_WS"], &["VPITCH_WS"]]),
    (Kind::RailIrregularity, &[&["DYRAIL"], &["DZRAIL"], &["DROLLR"], &["VYRAIL"], &["VZRAIL"], &["VROLLR"]]),
    (Kind::RailDeflection, &[&["KY_RAIL"], &["DY_DEFL"], &["FY_RAIL"], &["KZ_RAIL"], &["DZ_DEFL"], &["FZ_RAIL"]]),
    (Kind::WheelDeviation, &[&["DXWHL"], &["DYWHL"], &["DZWHL"], &["DROLLW"], &["DYAWW"], &["DPITCHW"]]),
    (Kind::WheelDeviationRate, &[&["VXWHL"], &["VYWHL"], &["VZWHL"], &["VROLLW"], &["VYAWW"], &["VPITCHW"]]),
    (Kind::Forces, &[&["FX(TR)"], &["FY(TR)"], &["FZ(TR)"], &["FX(WS)"], &["FY(WS)"], &["FZ(WS)"]]),
    (Kind::Moments, &[&["MX@R(TR)"], &["MY@R(TR)"], &["MZ@R(TR)"], &["MX@W(WS)"], &["MY@W(WS)"], &["MZ@W(WS)"]]),
    (Kind::Reference, &[&["XCP(TR)"], &["YCP(TR)"], &["ZCP(TR)"], &["DELTCP(TR)"], &["YCP(R)"], &["ZCP(R)"]]),
    (Kind::WheelReference, &[&["XCP(W)"], &["YCP(W)"], &["ZCP(W)"]]),
    (Kind::Kinematics, &[&["CHI"], &["DQ"], &["VELOC"], &["CKSI"], &["CETA"], &["CPHI"]]),
    (Kind::SpinCentre, &[&["SPINXO"], &["SPINYO"]]),
    (
        Kind::Totals,
        &[&["FN", "BAR_FN"], &["FX", "BAR_FX"], &["FS", "BAR_FS"], &["MN"], &["ELAST.EN."], &["FRIC.POWER"]],
    ),
    (Kind::Statistics, &[&["NPOT"], &["NCON"], &["NADH"], &["NSLIP"], &["INORM"], &["ITANG"]]),
    (Kind::Statistics, &[&["NPOT"], &["NCON"], &["NADH"], &["NSLIP"], &["NPLAST"], &["INORM"], &["ITANG"]]),
];

/// The second line of the patch totals: four fixed places and PMAX, temperatures after them.
const RATIOS: &[&[&str]] =
    &[&["FN/G", "TILDE_FN"], &["FX/FSTAT/FN", "FX/FN"], &["FS/FSTAT/FN", "FS/FN"], &["APPROACH"]];
const RATIOS_TAIL: &[&str] = &["PMAX", "MAX(T1)", "MAX(T2)", "MAX(T1,T2)"];

/// The block a line of labels heads, if it is one this reader reads.
fn kind_of(labels: &[String]) -> Option<Kind> {
    if let Some(&(kind, _)) = BLOCKS.iter().find(|(_, cols)| matches_columns(labels, cols, false)) {
        return Some(kind);
    }
    let tail_in = |n: usize, allowed: &[&str]| labels[n..].iter().all(|l| allowed.contains(&l.as_str()));
    if matches_columns(labels, RATIOS, true) && tail_in(RATIOS.len(), RATIOS_TAIL) {
        return Some(Kind::Ratios);
    }
    None
}

/// One block as printed: its labels and values, the line of the values (1-based).
struct Block {
    kind: Kind,
    line: usize,
    labels: Vec<String>,
    values: Vec<Printed>,
}

impl Block {
    /// The value at place `k` (the places of a block's kind are fixed by [`kind_of`]).
    fn at(&self, k: usize) -> Printed {
        self.values[k]
    }

    fn get(&self, label: &str) -> Option<Printed> {
        self.labels.iter().position(|l| l == label).map(|k| self.values[k])
    }

    fn six(&self) -> [Printed; 6] {
        [self.at(0), self.at(1), self.at(2), self.at(3), self.at(4), self.at(5)]
    }
}

/// The values line under a block's labels: as many printed numbers as labels.
fn block(kind: Kind, labels: Vec<String>, text: Option<&str>, line: usize) -> Result<Block, WheelRailOutputError> {
    let text = text.unwrap_or("");
    let numbers: Option<Vec<Printed>> = text.split_whitespace().map(Printed::parse).collect();
    match numbers {
        Some(values) if values.len() == labels.len() => Ok(Block { kind, line, labels, values }),
        _ => Err(WheelRailOutputError::Values {
            line,
            block: kind.name(),
            labels: labels.join(" "),
            got: crate::error::excerpt(text.trim()),
        }),
    }
}

/// `WHEEL-RAIL CONTACT, LEFT WHEEL,  1 CONTACT PATCH` (`m_wr_output.f90`, format 1001); None if
/// the line is not a heading, an error if it starts like one and is not.
fn heading(line: &str, number: usize) -> Result<Option<Heading>, WheelRailOutputError> {
    let t = line.trim();
    if !(t.starts_with("WHEEL-RAIL CONTACT") || t.starts_with("WHEEL-ROLLER CONTACT")) {
        return Ok(None);
    }
    let bad = || WheelRailOutputError::Heading { line: number, got: crate::error::excerpt(t) };
    let parts: Vec<&str> = t.split(',').map(str::trim).collect();
    let support = match parts.first() {
        Some(&"WHEEL-RAIL CONTACT") => Support::Rail,
        Some(&"WHEEL-ROLLER CONTACT") => Support::Roller,
        _ => return Err(bad()),
    };
    let side = match parts.get(1) {
        Some(&"LEFT WHEEL") => WheelSide::Left,
        Some(&"RIGHT WHEEL") => WheelSide::Right,
        _ => return Err(bad()),
    };
    let count =
        parts.get(2).and_then(|p| p.strip_suffix("CONTACT PATCHES").or_else(|| p.strip_suffix("CONTACT PATCH")));
    let patches = count.and_then(|n| n.trim().parse().ok()).ok_or_else(bad)?;
    Ok(Some(Heading { support, side, patches }))
}

/// `----- DATA FOR CONTACT PATCH  2 (PREV  1,  2) -----` (formats 6000, 6001); None if the line
/// is not a patch line, an error if it starts like one and is not.
fn patch_line(line: &str, number: usize) -> Result<Option<(u32, PatchHistory)>, WheelRailOutputError> {
    let t = line.trim();
    let Some(rest) = t.strip_prefix("----- DATA FOR CONTACT PATCH") else { return Ok(None) };
    let bad = || WheelRailOutputError::PatchLine { line: number, got: crate::error::excerpt(t) };
    let rest = rest.strip_suffix("-----").ok_or_else(bad)?.trim();
    let (index, note) = match rest.split_once('(') {
        Some((i, n)) => (i.trim(), Some(n.strip_suffix(')').ok_or_else(bad)?.trim())),
        None => (rest, None),
    };
    let index = index.parse().map_err(|_| bad())?;
    let history = match note {
        None => PatchHistory::NotPrinted,
        Some("NEW PATCH") => PatchHistory::New,
        Some(n) => {
            let list = n.strip_prefix("PREV").ok_or_else(bad)?;
            let previous: Result<Vec<u32>, _> = list.split(',').map(|p| p.trim().parse()).collect();
            PatchHistory::Previous(previous.map_err(|_| bad())?)
        }
    };
    Ok(Some((index, history)))
}

/// A patch being read: its totals wait for their second line.
struct PatchBuilder {
    patch: Patch,
    pending_totals: Option<Block>,
}

/// Reads the lines of one module-1 case.
struct CaseReader {
    case: WheelRailCase,
    patch: Option<PatchBuilder>,
}

fn read_case(lines: &[&str], span: CaseSpan) -> Result<WheelRailCase, WheelRailOutputError> {
    let case = WheelRailCase {
        case: span.case,
        result_element: span.result_element,
        line: span.at + 1,
        heading: None,
        position: None,
        velocity: None,
        rail_irregularity: None,
        rail_deflection: None,
        wheel_deviation: None,
        wheel_deviation_rate: None,
        forces: None,
        moments: None,
        patches: Vec::new(),
    };
    let mut reader = CaseReader { case, patch: None };
    for i in span.body {
        reader.line(lines, i)?;
    }
    reader.finish()
}

impl CaseReader {
    /// Read line `i` (0-based) of the file.
    fn line(&mut self, lines: &[&str], i: usize) -> Result<(), WheelRailOutputError> {
        let text = lines[i];
        if let Some(h) = heading(text, i + 1)? {
            self.case.heading = Some(h);
        } else if let Some((index, history)) = patch_line(text, i + 1)? {
            self.close_patch()?;
            let patch = Patch {
                index,
                line: i + 1,
                history,
                reference: None,
                wheel_reference: None,
                kinematics: None,
                spin_centre_mm: None,
                totals: None,
                statistics: None,
                nplast: None,
            };
            self.patch = Some(PatchBuilder { patch, pending_totals: None });
        } else if let Some(kind) = labels(text).as_deref().and_then(kind_of) {
            let b = block(kind, labels(text).unwrap_or_default(), lines.get(i + 1).copied(), i + 2)?;
            self.apply(b)?;
        }
        Ok(())
    }

    fn apply(&mut self, b: Block) -> Result<(), WheelRailOutputError> {
        if b.kind.in_patch() {
            let case = self.case.case;
            let p = self.patch.as_mut().ok_or(WheelRailOutputError::OutsidePatch {
                case,
                line: b.line,
                block: b.kind.name(),
            })?;
            return p.apply(case, b);
        }
        let c = &mut self.case;
        match b.kind {
            Kind::Position => c.position = Some(position(&b)),
            Kind::Velocity => c.velocity = Some(velocity(&b)),
            Kind::RailIrregularity => c.rail_irregularity = Some(rail_irregularity(&b)),
            Kind::RailDeflection => c.rail_deflection = Some(rail_deflection(&b)),
            Kind::WheelDeviation => c.wheel_deviation = Some(wheel_deviation(&b)),
            Kind::WheelDeviationRate => c.wheel_deviation_rate = Some(wheel_deviation_rate(&b)),
            Kind::Forces => c.forces = Some(forces(&b)),
            _ => c.moments = Some(moments(&b)),
        }
        Ok(())
    }

    fn close_patch(&mut self) -> Result<(), WheelRailOutputError> {
        if let Some(p) = self.patch.take() {
            if let Some(t) = p.pending_totals {
                return Err(WheelRailOutputError::NoRatios { case: self.case.case, line: t.line });
            }
            self.case.patches.push(p.patch);
        }
        Ok(())
    }

    /// The case, its patch count checked against its heading.
    fn finish(mut self) -> Result<WheelRailCase, WheelRailOutputError> {
        self.close_patch()?;
        let c = self.case;
        if let Some(h) = c.heading {
            if h.patches as usize != c.patches.len() {
                return Err(WheelRailOutputError::PatchCount {
                    case: c.case,
                    line: c.line,
                    announced: h.patches,
                    printed: c.patches.len(),
                });
            }
        }
        Ok(c)
    }
}

impl PatchBuilder {
    fn apply(&mut self, case: u32, b: Block) -> Result<(), WheelRailOutputError> {
        if let Some(t) = self.pending_totals.take() {
            if b.kind != Kind::Ratios {
                return Err(WheelRailOutputError::NoRatios { case, line: t.line });
            }
            self.patch.totals = Some(patch_totals(&t, &b));
            return Ok(());
        }
        let p = &mut self.patch;
        match b.kind {
            Kind::Reference => p.reference = Some(reference(&b)),
            Kind::WheelReference => {
                p.wheel_reference = Some(WheelReference { xcp_w_mm: b.at(0), ycp_w_mm: b.at(1), zcp_w_mm: b.at(2) })
            }
            Kind::Kinematics => p.kinematics = Some(kinematics(&b)),
            Kind::SpinCentre => p.spin_centre_mm = Some([b.at(0), b.at(1)]),
            Kind::Totals => self.pending_totals = Some(b),
            Kind::Statistics => (p.statistics, p.nplast) = statistics(case, &b)?,
            // A second line without its first: the totals are not printed as CONTACT prints them.
            _ => return Err(WheelRailOutputError::NoRatios { case, line: b.line }),
        }
        Ok(())
    }
}

fn position(b: &Block) -> WheelsetPosition {
    let [a, y, z, roll, yaw, pitch] = b.six();
    let along = if b.labels[0] == "S_WS" { Along::TrackSMm(a) } else { Along::RollerXMm(a) };
    WheelsetPosition { along, y_mm: y, z_mm: z, roll_rad: roll, yaw_rad: yaw, pitch_rad: pitch }
}

fn velocity(b: &Block) -> WheelsetVelocity {
    let [f, vy, vz, vroll, vyaw, vpitch] = b.six();
    let forward = if b.labels[0] == "VX_WS" { Forward::VxMmS(f) } else { Forward::RollerPitchRadS(f) };
    WheelsetVelocity { forward, vy_mm_s: vy, vz_mm_s: vz, vroll_rad_s: vroll, vyaw_rad_s: vyaw, vpitch_rad_s: vpitch }
}

fn rail_irregularity(b: &Block) -> RailIrregularity {
    let [dy_mm, dz_mm, droll_rad, vy_mm_s, vz_mm_s, vroll_rad_s] = b.six();
    RailIrregularity { dy_mm, dz_mm, droll_rad, vy_mm_s, vz_mm_s, vroll_rad_s }
}

fn rail_deflection(b: &Block) -> RailDeflection {
    let [ky_n_mm, dy_defl_mm, fy_rail_n, kz_n_mm, dz_defl_mm, fz_rail_n] = b.six();
    RailDeflection { ky_n_mm, dy_defl_mm, fy_rail_n, kz_n_mm, dz_defl_mm, fz_rail_n }
}

fn wheel_deviation(b: &Block) -> WheelDeviation {
    let [dx_mm, dy_mm, dz_mm, droll_rad, dyaw_rad, dpitch_rad] = b.six();
    WheelDeviation { dx_mm, dy_mm, dz_mm, droll_rad, dyaw_rad, dpitch_rad }
}

fn wheel_deviation_rate(b: &Block) -> WheelDeviationRate {
    let [vx_mm_s, vy_mm_s, vz_mm_s, vroll_rad_s, vyaw_rad_s, vpitch_rad_s] = b.six();
    WheelDeviationRate { vx_mm_s, vy_mm_s, vz_mm_s, vroll_rad_s, vyaw_rad_s, vpitch_rad_s }
}

fn forces(b: &Block) -> RailForces {
    let [fx_tr_n, fy_tr_n, fz_tr_n, fx_ws_n, fy_ws_n, fz_ws_n] = b.six();
    RailForces { fx_tr_n, fy_tr_n, fz_tr_n, fx_ws_n, fy_ws_n, fz_ws_n }
}

fn moments(b: &Block) -> RailMoments {
    let [mx_r_tr_nmm, my_r_tr_nmm, mz_r_tr_nmm, mx_w_ws_nmm, my_w_ws_nmm, mz_w_ws_nmm] = b.six();
    RailMoments { mx_r_tr_nmm, my_r_tr_nmm, mz_r_tr_nmm, mx_w_ws_nmm, my_w_ws_nmm, mz_w_ws_nmm }
}

fn reference(b: &Block) -> ReferenceLocation {
    let [xcp_tr_mm, ycp_tr_mm, zcp_tr_mm, deltcp_tr_rad, ycp_r_mm, zcp_r_mm] = b.six();
    ReferenceLocation { xcp_tr_mm, ycp_tr_mm, zcp_tr_mm, deltcp_tr_rad, ycp_r_mm, zcp_r_mm }
}

fn kinematics(b: &Block) -> PatchKinematics {
    let [chi_rad, dq_mm, veloc_mm_s, cksi, ceta, cphi_per_mm] = b.six();
    PatchKinematics { chi_rad, dq_mm, veloc_mm_s, cksi, ceta, cphi_per_mm }
}

/// The patch totals and their second line (formats 6401–6411).
fn patch_totals(t: &Block, r: &Block) -> PatchTotals {
    let [fn_n, fx_n, fs_n, mn_nmm, elastic_energy_nmm, fric_power_nmm_s] = t.six();
    let normal =
        if r.labels[0] == "FN/G" { NormalMeasure::FnOverGMm2(r.at(0)) } else { NormalMeasure::TildeFnN(r.at(0)) };
    let ratio = |k: usize| {
        if r.labels[k].contains("FSTAT") {
            Ratio::OverFstatFn(r.at(k))
        } else {
            Ratio::OverFn(r.at(k))
        }
    };
    let max_temperature = match (r.get("MAX(T1)"), r.get("MAX(T2)"), r.get("MAX(T1,T2)")) {
        (Some(t1), Some(t2), _) => Some(MaxTemperature::Each(t1, t2)),
        (_, _, Some(t)) => Some(MaxTemperature::Both(t)),
        _ => None,
    };
    PatchTotals {
        conformal: t.labels[0] == "BAR_FN",
        fn_n,
        fx_n,
        fs_n,
        mn_nmm,
        elastic_energy_nmm,
        fric_power_nmm_s,
        normal,
        fx_ratio: ratio(1),
        fs_ratio: ratio(2),
        approach_mm: r.at(3),
        pmax_mpa: r.get("PMAX"),
        max_temperature,
    }
}

/// CONTACT STATISTICS (format 6601) and NPLAST where printed: the element counts are whole
/// numbers ≥ 0; INORM, ITANG may be negative (a solver that stopped without converging).
fn statistics(case: u32, b: &Block) -> Result<(Option<Statistics>, Option<u32>), WheelRailOutputError> {
    let whole = |label: &'static str, min: f64| -> Result<Option<f64>, WheelRailOutputError> {
        let Some(v) = b.get(label) else { return Ok(None) };
        let ok = v.value.fract() == 0.0 && (min..1e9).contains(&v.value);
        ok.then_some(Some(v.value)).ok_or(WheelRailOutputError::NotACount { case, line: b.line, label, value: v.value })
    };
    // Every label but NPLAST is in every statistics block (`BLOCKS`).
    let count = |label: &'static str| whole(label, 0.0).map(|v| v.unwrap_or(0.0) as u32);
    let iterations = |label: &'static str| whole(label, -1e9).map(|v| v.unwrap_or(0.0) as i32);
    let stats = Statistics {
        npot: count("NPOT")?,
        ncon: count("NCON")?,
        nadh: count("NADH")?,
        nslip: count("NSLIP")?,
        inorm: iterations("INORM")?,
        itang: iterations("ITANG")?,
    };
    Ok((Some(stats), whole("NPLAST", 0.0)?.map(|v| v as u32)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn case_lines_with_and_without_result_element() {
        assert_eq!(case_line(" Case     2"), Some((2, None)));
        assert_eq!(case_line(" Case 2 for w/r contact on result element 1"), Some((2, Some(1))));
        assert_eq!(case_line(" Cases 1 - 2"), None);
    }

    #[test]
    fn headings_of_rail_and_roller() {
        let h = heading(" WHEEL-RAIL CONTACT, LEFT WHEEL,  1 CONTACT PATCH", 3).unwrap().unwrap();
        assert_eq!(h, Heading { support: Support::Rail, side: WheelSide::Left, patches: 1 });
        let h = heading(" WHEEL-ROLLER CONTACT, RIGHT WHEEL,  3 CONTACT PATCHES", 3).unwrap().unwrap();
        assert_eq!(h, Heading { support: Support::Roller, side: WheelSide::Right, patches: 3 });
        assert_eq!(heading(" TOTAL FORCES ON RAIL", 3), Ok(None));
        let e = heading(" WHEEL-RAIL CONTACT, MIDDLE WHEEL,  1 CONTACT PATCH", 7).unwrap_err();
        assert!(e.to_string().starts_with("line 7:"), "{e}");
    }

    #[test]
    fn patch_lines_with_their_history() {
        assert_eq!(patch_line(" ----- DATA FOR CONTACT PATCH  1 -----", 1), Ok(Some((1, PatchHistory::NotPrinted))));
        assert_eq!(
            patch_line(" ----- DATA FOR CONTACT PATCH  2 (PREV  1,  2) -----", 1),
            Ok(Some((2, PatchHistory::Previous(vec![1, 2]))))
        );
        assert_eq!(
            patch_line(" ----- DATA FOR CONTACT PATCH  3 (NEW PATCH) -----", 1),
            Ok(Some((3, PatchHistory::New)))
        );
        assert!(patch_line(" ----- DATA FOR CONTACT PATCH  x -----", 9).is_err());
    }

    #[test]
    fn totals_without_their_second_line_are_refused() {
        let text = " Case     1\n\n ----- DATA FOR CONTACT PATCH  1 -----\n     FN          FX          FS          MN         ELAST.EN.   FRIC.POWER\n   9997.  0.2783  253.6  4605.  6.042E-02  -0.4677\n";
        let e = parse(text).unwrap_err();
        assert_eq!(e, WheelRailOutputError::NoRatios { case: 1, line: 5 });
    }

    #[test]
    fn a_heading_announcing_more_patches_than_printed_is_refused() {
        let text = " Case     1\n WHEEL-RAIL CONTACT, LEFT WHEEL,  2 CONTACT PATCHES\n ----- DATA FOR CONTACT PATCH  1 -----\n";
        let e = parse(text).unwrap_err();
        assert!(matches!(e, WheelRailOutputError::PatchCount { announced: 2, printed: 1, .. }), "{e:?}");
    }
}
