//! CONTACT's module-1 (wheel–rail) cases as typed records (user guide, "Specification of the input
//! file", Module 1, and Chapter 3 "Module 1: wheel/rail contact"; the line order of CONTACT's
//! `wr_input` in `m_wr_input.f90`): the control words C-P-B-T-N-F-S, V-L-D-C-M-Z-E {M2} and
//! [X-]H-G-I-A-O-W-R, then every line the digits ask for. A group a case does not read is kept
//! from the previous module-1 case, as CONTACT keeps its `wtd` ([`WheelRailState`]); the module-3
//! state is separate ([`super::deck::State`]). What the project does not carry is named per case
//! by [`super::features::assess_wheelrail`], never dropped. Values as the deck gives them (N, mm,
//! rad, s; angles written `90d` converted to radians).

use super::deck::{self, CaseKind, CaseReader};
use super::features::{self, FeatureUse};
use super::lexer::{Kind, Place};
use super::DeckError;

/// The control digits of a module-1 case (user guide, "Module 1 -- wheel-rail contact").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WheelRailDigits {
    /// C: 0, 1 left or right wheel on a track; 4, 5 on a roller rig.
    pub c: u8,
    /// P (CONTACT sets 2 in the deck's first case).
    pub p: u8,
    pub b: u8,
    pub t: u8,
    pub n: u8,
    pub f: u8,
    pub s: u8,
    pub v: u8,
    pub l: u8,
    pub d: u8,
    /// C3, the influence functions (CONTACT sets 0 to 1: module 1 keeps them).
    pub c3: u8,
    pub m: u8,
    pub z: u8,
    pub e: u8,
    /// M2, the damping model (the optional integer after V-L-D-C-M-Z-E, its last digit; 1 when
    /// absent).
    pub m2: u8,
    /// The gap weighting (that integer's tens digit).
    pub gap_weighting: u8,
    pub x: u8,
    pub h: u8,
    pub g: u8,
    /// I (CONTACT sets 0 in the deck's first case).
    pub i: u8,
    pub a: u8,
    pub o: u8,
    pub w: u8,
    pub r: u8,
}

impl WheelRailDigits {
    /// The wheel the case computes.
    pub fn side(&self) -> Side {
        if self.c.is_multiple_of(2) {
            Side::Left
        } else {
            Side::Right
        }
    }

    /// Whether the wheel rolls on a roller rig (C = 4, 5) instead of a track.
    pub fn roller_rig(&self) -> bool {
        self.c >= 4
    }
}

/// The wheel (and rail) a case computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    Left,
    Right,
}

/// The iteration constants (G ≠ 1) and the parameters G = 2–5 add.
#[derive(Debug, Clone, PartialEq)]
pub struct SolverSettings {
    pub maxgs: i64,
    pub maxin: i64,
    pub maxnr: i64,
    pub maxout: i64,
    pub eps: f64,
    /// NPOT_MAX, the largest potential contact per patch, where given (CONTACT: 20000).
    pub npot_max: Option<i64>,
    /// G = 2, 3: OMEGAH, OMEGAS, INISLP, OMGSLP; G = 4: INISLP, OMGSLP; G = 5: the eight GDsteady
    /// parameters; as read.
    pub extra: Vec<f64>,
}

/// How the friction varies (the V digit).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FrictionVariation {
    /// V = 0: one set for the whole rail.
    Uniform,
    /// V = 1: sets at contact angles ALPHA across the rail profile.
    AcrossRail,
    /// V = 2: sets at positions SVF along the track.
    AlongTrack,
}

/// One set of friction parameters (`m_friclaw.f90`, `fric_input`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionValues {
    /// L = 0: Coulomb friction (CONTACT requires FSTAT = FKIN within 0.1 %).
    Coulomb { fstat: f64, fkin: f64 },
    /// L = 2: friction falling linearly with the slip velocity.
    Linear { fkin: f64, flin1: f64, sabsh1_mm_s: f64, flin2: f64, sabsh2_mm_s: f64 },
    /// L = 3: rational.
    Rational { fkin: f64, frat1: f64, sabsh1_mm_s: f64, frat2: f64, sabsh2_mm_s: f64 },
    /// L = 4: exponential.
    Exponential { fkin: f64, fexp1: f64, sabsh1_mm_s: f64, fexp2: f64, sabsh2_mm_s: f64 },
    /// L = 6: piecewise linear in the temperature.
    Temperature { fref: f64, tref_c: f64, dfheat: f64, dtheat_c: f64 },
}

impl FrictionValues {
    /// The static coefficient where the law has one (FSTAT, else FKIN or FREF).
    pub fn fstat(&self) -> f64 {
        match *self {
            FrictionValues::Coulomb { fstat, .. } => fstat,
            FrictionValues::Linear { fkin, flin1, flin2, .. } => fkin + flin1 + flin2,
            FrictionValues::Rational { fkin, frat1, frat2, .. } => fkin + frat1 + frat2,
            FrictionValues::Exponential { fkin, fexp1, fexp2, .. } => fkin + fexp1 + fexp2,
            FrictionValues::Temperature { fref, .. } => fref,
        }
    }
}

/// One set of a friction description: where it applies (V = 1: ALPHA [rad]; V = 2: SVF [mm];
/// V = 0: none) and its values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionSet {
    pub at: Option<f64>,
    pub values: FrictionValues,
}

/// The friction of a case (L ≠ 1 reads a new one).
#[derive(Debug, Clone, PartialEq)]
pub struct Friction {
    pub law: u8,
    pub variation: FrictionVariation,
    pub sets: Vec<FrictionSet>,
    /// MEMDST [mm], MEM_S0 [mm/s] of the laws L = 2–4, 6.
    pub memory: Option<[f64; 2]>,
}

/// The material model's own line (the M digit, read with the material when C3 = 2–4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MaterialModel {
    /// M = 0, 6, 7 (no line).
    Elastic,
    /// M = 1: FG 1, 2, VT 1, 2.
    Viscoelastic { fg: [f64; 2], vt: [f64; 2] },
    /// M = 2: FLX, K0_MF, ALFAMF, BETAMF.
    SimplifiedFlexibility { flx_mm3_n: f64, k0_mf: f64, alfamf: f64, betamf: f64 },
    /// M = 3, 5: K0_MF, ALFAMF, BETAMF.
    SlopeReduction { k0_mf: f64, alfamf: f64, betamf: f64 },
    /// M = 4: GG3, LAYTHK, TAU_C0, K_TAU.
    InterfaceLayer { gg3_mpa: f64, laythk_mm: f64, tau_c0_mpa: f64, k_tau: f64 },
}

/// The material (C3 = 2, 3, 4).
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    /// C3: 2 piecewise constant, 3 bilinear half-space influence functions, 4 conformal (Blanco).
    pub influence: u8,
    /// C3 = 4: IF_METH, VARIANT.
    pub if_correction: Option<[i64; 2]>,
    /// POISS of rail (body 1) and wheel (body 2).
    pub poiss: [f64; 2],
    pub gg_mpa: [f64; 2],
    /// B = 1: the flexibility FLXZ of the compressible layer [mm³/N].
    pub flxz: Option<f64>,
    pub model: MaterialModel,
}

/// H = 3: both bodies' temperature data, and BETAPL with M = 4.
#[derive(Debug, Clone, PartialEq)]
pub struct Heat {
    /// BKTEMP, HEATCP, LAMBDA, DENS of body 1 then body 2.
    pub bodies: [[f64; 4]; 2],
    pub betapl: Option<f64>,
}

/// The discretisation (D = 2–9: `discret_input`).
#[derive(Debug, Clone, PartialEq)]
pub struct Discretisation {
    /// The D digit that read it, the contact approach in force (CONTACT's `discns1_eff`): 2 planar
    /// with the contact locus, 3 planar with rigid slip on the actual surfaces, 4 conformal, 5–9
    /// other contact searches.
    pub method: u8,
    pub dx_mm: f64,
    pub ds_mm: f64,
    pub dqrel: f64,
    pub a_sep_rad: f64,
    pub d_sep_mm: f64,
    pub d_comb_mm: f64,
    /// D_TURN where given (CONTACT: 2 D_SEP − D_COMB otherwise, see [`Discretisation::d_turn_mm`]).
    pub d_turn_given_mm: Option<f64>,
    /// G_MISS: given here, or kept from an earlier discretisation (CONTACT's default −1: no near
    /// misses).
    pub g_miss_mm: f64,
}

impl Discretisation {
    /// D_TURN in force.
    pub fn d_turn_mm(&self) -> f64 {
        self.d_turn_given_mm.unwrap_or(2.0 * self.d_sep_mm - self.d_comb_mm)
    }
}

/// How the rail is placed laterally (GAUGHT > 0: the gauge point; ≤ 0: absolute).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RailPlacement {
    /// GAUGHT, GAUGSQ, GAUGWD.
    Gauge { gaught_mm: f64, gaugsq: i64, gaugwd_mm: f64 },
    /// GAUGHT ≤ 0, RAILY0, RAILZ0.
    Absolute { gaught_mm: f64, raily0_mm: f64, railz0_mm: f64 },
}

/// The track's (or roller rig's) design dimensions (Z = 1, 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Track {
    pub placement: RailPlacement,
    /// CANT [rad] on a track (C = 0, 1), NOMRADR [mm] on a roller rig (C = 4, 5).
    pub fourth: TrackFourth,
    /// CURV [1/mm] (0: tangent track; CONTACT's default when not given).
    pub curv_per_mm: f64,
}

/// The fourth value of the track line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TrackFourth {
    CantRad(f64),
    RollerRadiusMm(f64),
}

/// The kinds of profile file CONTACT tells by their extension (`profile_get_filetype`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProfileFormat {
    /// `.prr`, `.prw`: SIMPACK.
    Simpack,
    /// `.ban`, `.whl` (any case): Miniprof.
    Miniprof,
    /// `.slcs`, `.slcw`: a slices file (variable rail, out-of-round wheel).
    Slices,
    /// Anything else: a two-column table of y, z.
    Table,
}

/// Smoothing and kink detection of a profile (PRFOPT ≥ 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileCuration {
    pub ismooth: i64,
    pub zigthrs_rad: f64,
    pub kinkhigh_rad: f64,
    pub kinklow_rad: f64,
    pub kinkwid_mm: f64,
    /// PRFOPT = 2: ERRHND, MAXOMIT.
    pub errors: Option<(i64, f64)>,
}

/// A profile line `'FNAME' MIRRORY SCALE SMOOTH {MIRRORZ} {PRFOPT}` and its option lines.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileSpec {
    /// The file name as written (relative to the deck's folder; a `\` kept).
    pub file: String,
    /// Where the name stands in the deck.
    pub place: Place,
    pub mirror_y: i64,
    pub scale: f64,
    pub smooth: f64,
    /// MIRRORZ (0, auto-detect, when not given).
    pub mirror_z: i64,
    pub prfopt: i64,
    pub curation: Option<ProfileCuration>,
}

impl ProfileSpec {
    /// The file's format, from its extension.
    pub fn format(&self) -> ProfileFormat {
        let ext = self.file.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase()).unwrap_or_default();
        match ext.as_str() {
            "prr" | "prw" => ProfileFormat::Simpack,
            "ban" | "whl" => ProfileFormat::Miniprof,
            "slcs" | "slcw" => ProfileFormat::Slices,
            _ => ProfileFormat::Table,
        }
    }
}

/// The rail's deviations from its design position (Z = 2, 3) [mm, rad, mm/s, rad/s].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RailDeviation {
    pub dy_mm: f64,
    pub dz_mm: f64,
    pub droll_rad: f64,
    pub vy_mm_s: f64,
    pub vz_mm_s: f64,
    pub vroll_rad_s: f64,
}

/// The massless rail (Z = 2, 3 with F = 3): KYRAIL, FYRAIL, KZRAIL, FZRAIL {DYSTEP0}.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MasslessRail {
    pub ky_n_mm: f64,
    pub fy_n: f64,
    pub kz_n_mm: f64,
    pub fz_n: f64,
    /// DYSTEP0 (1 mm when not given).
    pub dystep0_mm: f64,
}

/// The wheelset dimensions (E = 3, 5): FBDIST, FBPOS, NOMRAD {YTAPE}.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetGeometry {
    pub fbdist_mm: f64,
    pub fbpos_mm: f64,
    pub nomrad_mm: f64,
    /// YTAPE where given (CONTACT's 1000 mm otherwise: no tape-circle computation).
    pub ytape_mm: Option<f64>,
}

/// Where the wheelset is along the track: S_WS on a track, X_WS on a roller rig.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Along {
    SMm(f64),
    XMm(f64),
}

/// The third value of the position line: Z_WS (N = 0) or FZ (N = 1, the vertical force on the
/// rail, z then found by CONTACT).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Vertical {
    ZMm(f64),
    FzN(f64),
}

/// The wheelset position (E ≥ 1): S_WS|X_WS, Y_WS, Z_WS|FZ, ROLL, YAW, PITCH.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetPosition {
    pub along: Along,
    pub y_mm: f64,
    pub vertical: Vertical,
    pub roll_rad: f64,
    pub yaw_rad: f64,
    pub pitch_rad: f64,
}

/// The first value of the velocity line: VS_WS on a track, RPITCH (the rollers' angular
/// velocity) on a roller rig.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Forward {
    VsMmS(f64),
    RollerPitchRadS(f64),
}

/// The sixth value of the velocity line (the F digit): VPITCH (F = 0, 3), FX_WS (F = 1) or
/// MY_WS (F = 2), the last two prescribed on the rail with VPITCH then found by CONTACT.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PitchInput {
    VpitchRadS(f64),
    FxWsN(f64),
    MyWsNmm(f64),
}

/// The wheelset velocity (E ≥ 2): VS_WS|RPITCH, VY_WS, VZ_WS, VROLL, VYAW, VPITCH|FX|MY. With
/// T = 1 the same line gives the shifts of one step (SHFT_SWS … [mm, rad]): `per_step`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetVelocity {
    pub per_step: bool,
    pub forward: Forward,
    pub vy_mm_s: f64,
    pub vz_mm_s: f64,
    pub vroll_rad_s: f64,
    pub vyaw_rad_s: f64,
    pub sixth: PitchInput,
}

/// The flexible wheel deviations (E = 4, 5): positions DXWHL … DPITCHW then velocities VXWHL …
/// VPITCHW, in wheelset coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelDeviation {
    pub position: [f64; 6],
    pub velocity: [f64; 6],
}

/// Everything module 1 keeps from case to case (CONTACT's `wtd`); `None`: never read.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelRailState {
    /// The previous case's digits (CONTACT's checks between cases).
    pub previous: Option<WheelRailDigits>,
    pub solver: Option<SolverSettings>,
    pub friction: Option<Friction>,
    pub material: Option<Material>,
    /// CDAMPN, CDAMPT, DFNMAX, DFTMAX (M2 = 2; M2 = 0 clears them).
    pub damping: Option<[f64; 4]>,
    pub heat: Option<Heat>,
    pub discretisation: Option<Discretisation>,
    pub track: Option<Track>,
    pub rail_profile: Option<ProfileSpec>,
    pub rail_deviation: RailDeviation,
    pub massless_rail: Option<MasslessRail>,
    pub wheelset: Option<WheelsetGeometry>,
    pub wheel_profile: Option<ProfileSpec>,
    pub position: Option<WheelsetPosition>,
    pub velocity: Option<WheelsetVelocity>,
    pub wheel_deviation: Option<WheelDeviation>,
    /// Whether subsurface points were ever read (S = 3; S = 1, 2 need them).
    pub subsurface_points: bool,
}

/// A module-1 case: its digits, result element and the state after it (every group in force,
/// read in this case or kept).
#[derive(Debug, Clone, PartialEq)]
pub struct WheelRailCase {
    /// The case number, counted from 1 over the deck as CONTACT counts (modules 1 and 3).
    pub number: usize,
    /// The line of its MODULE line or control words.
    pub line: usize,
    /// REID of the MODULE line (0 when absent); each result element keeps its own state.
    pub result_element: i64,
    pub digits: WheelRailDigits,
    pub state: WheelRailState,
}

impl WheelRailCase {
    /// Every feature of the table the case uses, supported or not
    /// ([`features::WHEELRAIL_FEATURES`]).
    pub fn features(&self) -> Vec<FeatureUse> {
        features::assess_wheelrail(self)
    }

    /// The features the project does not carry, each named with its value and why.
    pub fn unsupported(&self) -> Vec<FeatureUse> {
        self.features().into_iter().filter(|f| !f.supported).collect()
    }
}

/// Every module-1 case of a deck (its module-3 cases read and left out; numbers count both).
pub fn parse(file: &str, text: &str) -> Result<Vec<WheelRailCase>, DeckError> {
    let cases = deck::parse(file, text)?;
    Ok(cases
        .into_iter()
        .filter_map(|c| match c.kind {
            CaseKind::Module1(mut wr) => {
                wr.line = c.line;
                Some(*wr)
            }
            CaseKind::Module3(_) => None,
        })
        .collect())
}

/// The module-1 deck at `path`, read whole.
pub fn read(path: &std::path::Path) -> Result<Vec<WheelRailCase>, crate::error::InputError> {
    let file = path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_else(|| path.display().to_string());
    let text = crate::safety::read::read_text(path, super::DECK_LIMIT_BYTES, "CONTACT input file").map_err(|e| {
        crate::error::InputError::new(
            path.display().to_string(),
            "unreadable",
            format!("a readable CONTACT input file: {e}"),
        )
    })?;
    parse(&file, &text).map_err(Into::into)
}

/// Read one module-1 case after its MODULE line (`wr_input`); `state` is updated with every
/// group read.
pub(super) fn read_case(
    r: &mut CaseReader<'_>,
    state: &mut WheelRailState,
    result_element: i64,
) -> Result<WheelRailCase, DeckError> {
    let line = r.lx.line_number();
    let digits = control_digits(r, state.previous.as_ref(), state.subsurface_points)?;
    let mut m = M1 { r, d: digits };
    m.read_groups(state)?;
    state.previous = Some(digits);
    Ok(WheelRailCase { number: m.r.number, line, result_element, digits, state: state.clone() })
}

/// A module-1 case being read: the reader and the case's digits.
struct M1<'r, 'a> {
    r: &'r mut CaseReader<'a>,
    d: WheelRailDigits,
}

/// The three control words, checked as CONTACT's `ic_input` checks module 1.
fn control_digits(
    r: &mut CaseReader<'_>,
    previous: Option<&WheelRailDigits>,
    subsurface_points: bool,
) -> Result<WheelRailDigits, DeckError> {
    let (w1, _) = r.word("C-P-B-T-N-F-S", 6, false)?;
    let (w2, m2) = r.word("V-L-D-C-M-Z-E", 6, true)?;
    let (w3, _) = r.word("X-H-G-I-A-O-W-R", 7, false)?;
    let m2 = m2.unwrap_or(1);
    let mut d = WheelRailDigits {
        c: w1[0],
        p: w1[1],
        b: w1[2],
        t: w1[3],
        n: w1[4],
        f: w1[5],
        s: w1[6],
        v: w2[0],
        l: w2[1],
        d: w2[2],
        c3: w2[3],
        m: w2[4],
        z: w2[5],
        e: w2[6],
        m2: (m2.rem_euclid(10)) as u8,
        gap_weighting: (m2 / 10).clamp(0, 255) as u8,
        x: w3[0],
        h: w3[1],
        g: w3[2],
        i: w3[3],
        a: w3[4],
        o: w3[5],
        w: w3[6],
        r: w3[7],
    };
    check_ranges(r, &d)?;
    // CONTACT overrules these with a warning: module 1 always has influence functions, and the
    // deck's first case starts a sequence from zero tractions.
    if d.c3 == 0 {
        d.c3 = 1;
    }
    if r.first {
        d.p = 2;
        d.i = 0;
    }
    check_consistency(r, &d, previous, subsurface_points)?;
    Ok(d)
}

/// Each digit in CONTACT's range for module 1 (`ic_input`, imodul = 1).
fn check_ranges(r: &CaseReader<'_>, d: &WheelRailDigits) -> Result<(), DeckError> {
    let (a, b, c) = ("C-P-B-T-N-F-S", "V-L-D-C-M-Z-E", "X-H-G-I-A-O-W-R");
    let checks: [(&str, &str, u8, &[u8]); 24] = [
        (a, "C", d.c, &[0, 1, 4, 5]),
        (a, "P", d.p, &[0, 1, 2, 3]),
        (a, "B", d.b, &[0, 1, 5, 6]),
        (a, "T", d.t, &[0, 1, 2, 3]),
        (a, "N", d.n, &[0, 1]),
        (a, "F", d.f, &[0, 1, 3]),
        (a, "S", d.s, &[0, 1, 2, 3]),
        (b, "V", d.v, &[0, 1, 2]),
        (b, "L", d.l, &[0, 1, 2, 3, 4, 6]),
        (b, "D", d.d, &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]),
        (b, "C", d.c3, &[0, 1, 2, 3, 4]),
        (b, "M", d.m, &[0, 1, 2, 3, 4, 5, 6, 7]),
        (b, "Z", d.z, &[0, 1, 2, 3]),
        (b, "E", d.e, &[0, 1, 2, 3, 4, 5]),
        (b, "M2", d.m2, &[0, 1, 2]),
        (b, "gap weighting", d.gap_weighting, &[0, 1, 2]),
        (c, "X", d.x, &[0, 1]),
        (c, "H", d.h, &[0, 1, 3]),
        (c, "G", d.g, &[0, 1, 2, 3, 4, 5]),
        (c, "I", d.i, &[0, 1, 2, 3]),
        (c, "A", d.a, &[0, 1, 2]),
        (c, "O", d.o, &[0, 1, 2, 3, 4, 5]),
        (c, "W", d.w, &[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]),
        (c, "R", d.r, &[0, 1, 2, 3]),
    ];
    checks.iter().try_for_each(|&(word, digit, v, allowed)| r.check(word, digit, v, allowed))
}

/// CONTACT's checks of a case against the deck's first case and the previous module-1 case.
fn check_consistency(
    r: &CaseReader<'_>,
    d: &WheelRailDigits,
    previous: Option<&WheelRailDigits>,
    subsurface_points: bool,
) -> Result<(), DeckError> {
    let (a, b, c) = ("C-P-B-T-N-F-S", "V-L-D-C-M-Z-E", "X-H-G-I-A-O-W-R");
    let fail = |word: &str, digit: &str, v: u8, allowed: &str| Err(r.digit_error(word, digit, v.into(), allowed));
    if r.first && d.l == 1 {
        return fail(b, "L", d.l, "0, 2, 3, 4 or 6 in the deck's first case (its friction must be given)");
    }
    if r.first && d.d == 0 {
        return fail(b, "D", d.d, "1 to 9 in the deck's first case (its discretisation must be given)");
    }
    if matches!(d.s, 1 | 2) && (r.first || !subsurface_points) {
        return fail(a, "S", d.s, "0 or 3 until subsurface points were read (S = 3)");
    }
    let (prev_v, prev_n) = previous.map_or((0, 0), |p| (p.v, p.n));
    if d.l == 1 && d.v != prev_v {
        return fail(b, "V", d.v, "the previous case's V when L = 1 (V changes only with new friction, L != 1)");
    }
    if d.e == 0 && d.n != prev_n {
        return fail(
            a,
            "N",
            d.n,
            "the previous case's N when E = 0 (switching between Z and FZ needs a new position, E >= 1)",
        );
    }
    if d.f == 1 && d.n != 1 {
        return fail(a, "F", d.f, "0 or 3 unless N = 1 (a prescribed FX needs a prescribed FZ)");
    }
    if d.m == 1 && d.t != 3 {
        return fail(b, "M", d.m, "other than 1 unless T = 3 (viscoelastic materials need steady rolling)");
    }
    if d.h >= 1 && d.t != 3 {
        return fail(c, "H", d.h, "0 unless T = 3 (temperatures need steady rolling)");
    }
    if d.l == 6 && (d.h == 0 || matches!(d.m, 2 | 3 | 5 | 6 | 7)) {
        return fail(b, "L", d.l, "other than 6 unless H >= 1 and M is 0, 1 or 4 (temperature-dependent friction)");
    }
    Ok(())
}

impl M1<'_, '_> {
    fn file(&self) -> String {
        self.r.lx.file().to_string()
    }

    /// A value error at value `k` of the last group.
    fn value_error(&self, k: usize, what: &str, value: String, allowed: &str) -> DeckError {
        let p = self.r.lx.place(k);
        DeckError::Value {
            file: self.file(),
            line: p.line,
            column: p.column,
            what: what.into(),
            value,
            allowed: allowed.into(),
        }
    }

    /// `value` at place `k` of the last group within [lo, hi].
    fn in_range(&self, k: usize, what: &str, value: f64, lo: f64, hi: f64) -> Result<(), DeckError> {
        if (lo..=hi).contains(&value) {
            Ok(())
        } else {
            Err(self.value_error(k, what, value.to_string(), &format!("{lo} to {hi}")))
        }
    }

    fn group(&mut self, what: &str, kinds: &[Kind], optional: &[Kind]) -> Result<Vec<f64>, DeckError> {
        self.r.lx.group_with(what, kinds, optional).map(|(v, _)| v)
    }

    /// Every group the digits ask for, in `wr_input`'s order.
    fn read_groups(&mut self, state: &mut WheelRailState) -> Result<(), DeckError> {
        let d = self.d;
        if d.x == 1 {
            self.group("debug output P-S-F-L-C-I-N {READLN}", &[Kind::Int], &[Kind::Int])?;
        }
        if d.g != 1 {
            state.solver = Some(self.solver()?);
        }
        if d.l != 1 {
            state.friction = Some(self.friction()?);
        }
        if matches!(d.c3, 2..=4) {
            state.material = Some(self.material()?);
        }
        self.damping(state)?;
        if d.h == 3 {
            state.heat = Some(self.heat()?);
        }
        if (2..=9).contains(&d.d) {
            let kept_g_miss = state.discretisation.as_ref().map_or(-1.0, |x| x.g_miss_mm);
            state.discretisation = Some(self.discretisation(kept_g_miss)?);
        }
        self.track_and_rail(state)?;
        self.wheelset(state)?;
        if d.s >= 2 {
            drop(self.r.subsurface(d.s)?);
            state.subsurface_points |= d.s == 3;
        }
        Ok(())
    }

    /// G ≠ 1: MAXGS, MAXIN, MAXNR, MAXOUT, EPS {NPOT_MAX}, then the lines G = 2–5 add
    /// (`solv_input`).
    fn solver(&mut self) -> Result<SolverSettings, DeckError> {
        let k = [Kind::Int, Kind::Int, Kind::Int, Kind::Int, Kind::Real];
        let v = self.group("MAXGS, MAXIN, MAXNR, MAXOUT, EPS {NPOT_MAX}", &k, &[Kind::Int])?;
        let names = ["MAXGS", "MAXIN", "MAXNR", "MAXOUT"];
        let highs = [9999.0, 999999.0, 9999.0, 9999.0];
        for (i, (name, hi)) in names.iter().zip(highs).enumerate() {
            self.in_range(i, name, v[i], 1.0, hi)?;
        }
        let extra = match self.d.g {
            2 | 3 => {
                self.group("OMEGAH, OMEGAS, INISLP, OMGSLP", &[Kind::Real, Kind::Real, Kind::Int, Kind::Real], &[])?
            }
            4 => self.group("INISLP, OMGSLP", &[Kind::Int, Kind::Real], &[])?,
            5 => {
                let k = [Kind::Real, Kind::Real, Kind::Int, Kind::Real, Kind::Real, Kind::Real, Kind::Real, Kind::Real];
                self.group("FDECAY, BETATH, KDOWFB, D_IFC, D_LIN, D_CNS, D_SLP, POW_S", &k, &[])?
            }
            _ => Vec::new(),
        };
        Ok(SolverSettings {
            maxgs: v[0] as i64,
            maxin: v[1] as i64,
            maxnr: v[2] as i64,
            maxout: v[3] as i64,
            eps: v[4],
            npot_max: v.get(5).map(|&n| n as i64),
            extra,
        })
    }

    /// L ≠ 1: NVF (V = 1, 2), one set per NVF, the memory of the laws L = 2–4, 6 (`fric_input`).
    fn friction(&mut self) -> Result<Friction, DeckError> {
        let (law, variation) = (self.d.l, self.variation());
        let nvf = if variation == FrictionVariation::Uniform {
            1
        } else {
            let v = self.group("NVF", &[Kind::Int], &[])?;
            self.in_range(0, "NVF", v[0], 1.0, 10.0)?;
            v[0] as usize
        };
        let sets = (0..nvf).map(|_| self.friction_set(law, variation)).collect::<Result<Vec<_>, _>>()?;
        let memory = if matches!(law, 2..=4 | 6) {
            let m = self.group("MEMDST, MEM_S0", &[Kind::Real, Kind::Real], &[])?;
            Some([m[0], m[1]])
        } else {
            None
        };
        Ok(Friction { law, variation, sets, memory })
    }

    fn variation(&self) -> FrictionVariation {
        match self.d.v {
            0 => FrictionVariation::Uniform,
            1 => FrictionVariation::AcrossRail,
            _ => FrictionVariation::AlongTrack,
        }
    }

    /// One set: [ALPHA (angle) | SVF] then the law's values; L = 0 checks FSTAT = FKIN.
    fn friction_set(&mut self, law: u8, variation: FrictionVariation) -> Result<FrictionSet, DeckError> {
        let lead: &[Kind] = match variation {
            FrictionVariation::Uniform => &[],
            FrictionVariation::AcrossRail => &[Kind::Angle],
            FrictionVariation::AlongTrack => &[Kind::Real],
        };
        let (n, what) = match law {
            0 => (2, "FSTAT, FKIN"),
            2 => (5, "FKIN, FLIN1, SABSH1, FLIN2, SABSH2"),
            3 => (5, "FKIN, FRAT1, SABSH1, FRAT2, SABSH2"),
            4 => (5, "FKIN, FEXP1, SABSH1, FEXP2, SABSH2"),
            _ => (4, "FREF, TREF, DFHEAT, DTHEAT"),
        };
        let mut kinds = lead.to_vec();
        kinds.extend(std::iter::repeat_n(Kind::Real, n));
        let what = if lead.is_empty() { what.to_string() } else { format!("ALPHA/SVF, {what}") };
        let v = self.group(&what, &kinds, &[])?;
        let (at, x) = if lead.is_empty() { (None, &v[..]) } else { (Some(v[0]), &v[1..]) };
        let o = lead.len();
        let values = match law {
            0 => {
                let (fstat, fkin) = (x[0], x[1]);
                self.in_range(o + 1, "FKIN", fkin, 1e-4, 1e10)?;
                if !(0.999 * fkin..=1.001 * fkin).contains(&fstat) {
                    let allowed = "FSTAT = FKIN (within 0.1 %): CONTACT's Coulomb law has one coefficient";
                    return Err(self.value_error(o, "FSTAT, FKIN", format!("{fstat}, {fkin}"), allowed));
                }
                FrictionValues::Coulomb { fstat, fkin }
            }
            2 => FrictionValues::Linear { fkin: x[0], flin1: x[1], sabsh1_mm_s: x[2], flin2: x[3], sabsh2_mm_s: x[4] },
            3 => {
                FrictionValues::Rational { fkin: x[0], frat1: x[1], sabsh1_mm_s: x[2], frat2: x[3], sabsh2_mm_s: x[4] }
            }
            4 => FrictionValues::Exponential {
                fkin: x[0],
                fexp1: x[1],
                sabsh1_mm_s: x[2],
                fexp2: x[3],
                sabsh2_mm_s: x[4],
            },
            _ => FrictionValues::Temperature { fref: x[0], tref_c: x[1], dfheat: x[2], dtheat_c: x[3] },
        };
        Ok(FrictionSet { at, values })
    }

    /// C3 = 2–4: [IF_METH, VARIANT], POISS 1, 2, GG 1, 2, [FLXZ], the material model's line
    /// (`mater_input`, imodul = 1).
    fn material(&mut self) -> Result<Material, DeckError> {
        let if_correction = if self.d.c3 == 4 {
            let v = self.group("IF_METH, VARIANT", &[Kind::Int, Kind::Int], &[])?;
            self.in_range(0, "IF_METH", v[0], 0.0, 1.0)?;
            self.in_range(1, "VARIANT", v[1], 1.0, 4.0)?;
            Some([v[0] as i64, v[1] as i64])
        } else {
            None
        };
        let v = self.group("POISS 1, 2, GG 1, 2", &[Kind::Real; 4], &[])?;
        for (k, name) in ["POISS1", "POISS2"].iter().enumerate() {
            self.in_range(k, name, v[k], 0.0, 0.5)?;
        }
        for (k, name) in ["GG1", "GG2"].iter().enumerate() {
            self.in_range(k + 2, name, v[k + 2], 1e-5, 1e20)?;
        }
        let flxz = if self.d.b == 1 { Some(self.group("FLXZ", &[Kind::Real], &[])?[0]) } else { None };
        let model = self.material_model()?;
        Ok(Material { influence: self.d.c3, if_correction, poiss: [v[0], v[1]], gg_mpa: [v[2], v[3]], flxz, model })
    }

    fn material_model(&mut self) -> Result<MaterialModel, DeckError> {
        Ok(match self.d.m {
            1 => {
                let v = self.group("FG 1, 2, VT 1, 2", &[Kind::Real; 4], &[])?;
                MaterialModel::Viscoelastic { fg: [v[0], v[1]], vt: [v[2], v[3]] }
            }
            2 => {
                let v = self.group("FLX, K0_MF, ALFAMF, BETAMF", &[Kind::Real; 4], &[])?;
                MaterialModel::SimplifiedFlexibility { flx_mm3_n: v[0], k0_mf: v[1], alfamf: v[2], betamf: v[3] }
            }
            3 | 5 => {
                let v = self.group("K0_MF, ALFAMF, BETAMF", &[Kind::Real; 3], &[])?;
                MaterialModel::SlopeReduction { k0_mf: v[0], alfamf: v[1], betamf: v[2] }
            }
            4 => {
                let v = self.group("GG3, LAYTHK, TAU_C0, K_TAU", &[Kind::Real; 4], &[])?;
                MaterialModel::InterfaceLayer { gg3_mpa: v[0], laythk_mm: v[1], tau_c0_mpa: v[2], k_tau: v[3] }
            }
            _ => MaterialModel::Elastic,
        })
    }

    /// M2 = 2: CDAMPN, CDAMPT, DFNMAX, DFTMAX; M2 = 0 clears them, 1 keeps them (`mater2_input`).
    fn damping(&mut self, state: &mut WheelRailState) -> Result<(), DeckError> {
        match self.d.m2 {
            0 => state.damping = None,
            2 => {
                let v = self.group("CDAMPN, CDAMPT, DFNMAX, DFTMAX", &[Kind::Real; 4], &[])?;
                state.damping = Some([v[0], v[1], v[2], v[3]]);
            }
            _ => {}
        }
        Ok(())
    }

    /// H = 3: both bodies' BKTEMP, HEATCP, LAMBDA, DENS, and BETAPL with M = 4 (`heat_input`).
    fn heat(&mut self) -> Result<Heat, DeckError> {
        let one = self.group("BKTEMP1, HEATCP1, LAMBDA1, DENS1", &[Kind::Real; 4], &[])?;
        let two = self.group("BKTEMP2, HEATCP2, LAMBDA2, DENS2", &[Kind::Real; 4], &[])?;
        let betapl = if self.d.m == 4 { Some(self.group("BETAPL", &[Kind::Real], &[])?[0]) } else { None };
        Ok(Heat { bodies: [[one[0], one[1], one[2], one[3]], [two[0], two[1], two[2], two[3]]], betapl })
    }

    /// D = 2–9: DX, DS, DQREL, A_SEP, D_SEP, D_COMB {D_TURN, G_MISS} (`discret_input`); G_MISS
    /// not given keeps `kept_g_miss`.
    fn discretisation(&mut self, kept_g_miss: f64) -> Result<Discretisation, DeckError> {
        let k = [Kind::Real, Kind::Real, Kind::Real, Kind::Angle, Kind::Real, Kind::Real];
        let v = self.group("DX, DS, DQREL, A_SEP, D_SEP, D_COMB {D_TURN, G_MISS}", &k, &[Kind::Real, Kind::Real])?;
        self.in_range(0, "DX", v[0], 1e-8, 1e20)?;
        self.in_range(1, "DS", v[1], 1e-8, 1e20)?;
        self.in_range(2, "DQREL", v[2], 5e-7, 10.0)?;
        let (d_sep, d_comb) = (v[4].max(0.0), v[5]);
        if d_sep < d_comb {
            let allowed = "D_SEP >= D_COMB (patches combined fully below D_COMB, separated above D_SEP)";
            return Err(self.value_error(4, "D_SEP, D_COMB", format!("{}, {}", v[4], v[5]), allowed));
        }
        Ok(Discretisation {
            method: self.d.d,
            dx_mm: v[0],
            ds_mm: v[1],
            dqrel: v[2],
            a_sep_rad: v[3],
            d_sep_mm: v[4],
            d_comb_mm: v[5],
            d_turn_given_mm: v.get(6).copied(),
            g_miss_mm: v.get(7).copied().unwrap_or(kept_g_miss),
        })
    }

    /// Z = 1, 3: the track line; Z = 3: the rail profile; Z = 2, 3: the rail deviations and with
    /// F = 3 the massless rail (`trackdata_input`). Z = 0, 2 need a rail profile read before.
    fn track_and_rail(&mut self, state: &mut WheelRailState) -> Result<(), DeckError> {
        let z = self.d.z;
        if matches!(z, 1 | 3) {
            state.track = Some(self.track()?);
        }
        if z == 3 {
            let p = self.profile("RFNAME, MIRRORY, SCALE, SMOOTH {MIRRORZ, PRFOPT}")?;
            let gauge = matches!(state.track.map(|t| t.placement), Some(RailPlacement::Gauge { .. }));
            if p.format() == ProfileFormat::Slices && gauge {
                let allowed = "a rail profile that is not a slices file (.slcs) while GAUGHT > 0 (variable profiles need absolute rail placement, GAUGHT <= 0)";
                return Err(self.value_error(0, "RFNAME", p.file.clone(), allowed));
            }
            state.rail_profile = Some(p);
        }
        if matches!(z, 2 | 3) {
            let k = [Kind::Real, Kind::Real, Kind::Angle, Kind::Real, Kind::Real, Kind::Angle];
            let v = self.group("DYRAIL, DZRAIL, DROLLR, VYRAIL, VZRAIL, VROLLR", &k, &[])?;
            state.rail_deviation = RailDeviation {
                dy_mm: v[0],
                dz_mm: v[1],
                droll_rad: v[2],
                vy_mm_s: v[3],
                vz_mm_s: v[4],
                vroll_rad_s: v[5],
            };
            if self.d.f == 3 {
                let v = self.group("KYRAIL, FYRAIL, KZRAIL, FZRAIL {DYSTEP0}", &[Kind::Real; 4], &[Kind::Real])?;
                let dystep0_mm = v.get(4).copied().unwrap_or(1.0);
                state.massless_rail =
                    Some(MasslessRail { ky_n_mm: v[0], fy_n: v[1], kz_n_mm: v[2], fz_n: v[3], dystep0_mm });
            }
        }
        if state.rail_profile.is_none() && matches!(z, 0 | 2) {
            let allowed = "1 or 3 until a rail profile has been given (Z = 3)";
            return Err(self.r.digit_error("V-L-D-C-M-Z-E", "Z", z.into(), allowed));
        }
        Ok(())
    }

    /// GAUGHT, GAUGSQ|RAILY0, GAUGWD|RAILZ0, CANT|NOMRADR {CURV}.
    fn track(&mut self) -> Result<Track, DeckError> {
        let roller = self.d.roller_rig();
        let (what, fourth) = if roller {
            ("GAUGHT, GAUGSQ|RAILY0, GAUGWD|RAILZ0, NOMRADR {CURV}", Kind::Real)
        } else {
            ("GAUGHT, GAUGSQ|RAILY0, GAUGWD|RAILZ0, CANT {CURV}", Kind::Angle)
        };
        let v = self.group(what, &[Kind::Real, Kind::Real, Kind::Real, fourth], &[Kind::Real])?;
        let placement = if v[0] > 0.0 {
            RailPlacement::Gauge { gaught_mm: v[0], gaugsq: v[1].round() as i64, gaugwd_mm: v[2] }
        } else {
            RailPlacement::Absolute { gaught_mm: v[0], raily0_mm: v[1], railz0_mm: v[2] }
        };
        let fourth = if roller { TrackFourth::RollerRadiusMm(v[3]) } else { TrackFourth::CantRad(v[3]) };
        Ok(Track { placement, fourth, curv_per_mm: v.get(4).copied().unwrap_or(0.0) })
    }

    /// A profile line and its option lines (`profile_read_config`).
    fn profile(&mut self, what: &str) -> Result<ProfileSpec, DeckError> {
        let (file, v, place) =
            self.r.lx.quoted_group(what, &[Kind::Int, Kind::Real, Kind::Real], &[Kind::Int, Kind::Int])?;
        let (mirror_y, mirror_z, prfopt) = (v[0], v.get(3).copied().unwrap_or(0.0), v.get(4).copied().unwrap_or(0.0));
        self.in_range(1, "MIRRORY", mirror_y, -1.0, 1.0)?;
        self.in_range(4, "MIRRORZ", mirror_z, -1.0, 1.0)?;
        self.in_range(5, "PRFOPT", prfopt, 0.0, 2.0)?;
        let curation = if prfopt >= 1.0 { Some(self.curation(prfopt >= 2.0)?) } else { None };
        Ok(ProfileSpec {
            file,
            place,
            mirror_y: mirror_y as i64,
            scale: v[1],
            smooth: v[2],
            mirror_z: mirror_z as i64,
            prfopt: prfopt as i64,
            curation,
        })
    }

    /// PRFOPT ≥ 1: ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID; PRFOPT = 2: ERRHND, MAXOMIT.
    fn curation(&mut self, errors: bool) -> Result<ProfileCuration, DeckError> {
        let k = [Kind::Int, Kind::Angle, Kind::Angle, Kind::Angle, Kind::Real];
        let v = self.group("ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID", &k, &[])?;
        let errors = if errors {
            let e = self.group("ERRHND, MAXOMIT", &[Kind::Int, Kind::Real], &[])?;
            Some((e[0] as i64, e[1]))
        } else {
            None
        };
        Ok(ProfileCuration {
            ismooth: v[0] as i64,
            zigthrs_rad: v[1],
            kinkhigh_rad: v[2],
            kinklow_rad: v[3],
            kinkwid_mm: v[4],
            errors,
        })
    }

    /// E = 3, 5: the wheelset dimensions and the wheel profile; E ≥ 1: the position; E ≥ 2: the
    /// velocity; E = 4, 5: the flexible deviations (`wheelset_input`). E = 1, 2, 4 need a wheel
    /// profile read before.
    fn wheelset(&mut self, state: &mut WheelRailState) -> Result<(), DeckError> {
        let e = self.d.e;
        if matches!(e, 3 | 5) {
            let v = self.group("FBDIST, FBPOS, NOMRAD {YTAPE}", &[Kind::Real; 3], &[Kind::Real])?;
            self.in_range(2, "NOMRAD", v[2], 1e-3, 1e20)?;
            let ytape_mm = v.get(3).copied();
            state.wheelset = Some(WheelsetGeometry { fbdist_mm: v[0], fbpos_mm: v[1], nomrad_mm: v[2], ytape_mm });
            state.wheel_profile = Some(self.profile("WFNAME, MIRRORY, SCALE, SMOOTH {MIRRORZ, PRFOPT}")?);
        }
        if e >= 1 {
            state.position = Some(self.position()?);
        }
        if e >= 2 {
            state.velocity = Some(self.velocity()?);
        }
        if matches!(e, 4 | 5) {
            let k = [Kind::Real, Kind::Real, Kind::Real, Kind::Angle, Kind::Angle, Kind::Angle];
            let p = self.group("DXWHL, DYWHL, DZWHL, DROLLW, DYAWW, DPITCHW", &k, &[])?;
            let v = self.group("VXWHL, VYWHL, VZWHL, VROLLW, VYAWW, VPITCHW", &k, &[])?;
            state.wheel_deviation = Some(WheelDeviation { position: six(&p), velocity: six(&v) });
        }
        if state.wheel_profile.is_none() && matches!(e, 1 | 2 | 4) {
            let allowed = "0, 3 or 5 until a wheel profile has been given (E = 3, 5)";
            return Err(self.r.digit_error("V-L-D-C-M-Z-E", "E", e.into(), allowed));
        }
        Ok(())
    }

    /// S_WS|X_WS, Y_WS, Z_WS|FZ, ROLL, YAW, PITCH.
    fn position(&mut self) -> Result<WheelsetPosition, DeckError> {
        let k = [Kind::Real, Kind::Real, Kind::Real, Kind::Angle, Kind::Angle, Kind::Angle];
        let v = self.group("S_WS|X_WS, Y_WS, Z_WS|FZ, ROLL, YAW, PITCH", &k, &[])?;
        let along = if self.d.roller_rig() { Along::XMm(v[0]) } else { Along::SMm(v[0]) };
        let vertical = if self.d.n == 0 { Vertical::ZMm(v[2]) } else { Vertical::FzN(v[2]) };
        Ok(WheelsetPosition { along, y_mm: v[1], vertical, roll_rad: v[3], yaw_rad: v[4], pitch_rad: v[5] })
    }

    /// VS_WS|RPITCH, VY_WS, VZ_WS, VROLL, VYAW, VPITCH|FX_WS|MY_WS (T = 1: the shifts of a step).
    fn velocity(&mut self) -> Result<WheelsetVelocity, DeckError> {
        let roller = self.d.roller_rig();
        let force = matches!(self.d.f, 1 | 2);
        let first = if roller { Kind::Angle } else { Kind::Real };
        let sixth = if force { Kind::Real } else { Kind::Angle };
        let k = [first, Kind::Real, Kind::Real, Kind::Angle, Kind::Angle, sixth];
        let v = self.group("VS_WS|RPITCH, VY_WS, VZ_WS, VROLL, VYAW, VPITCH|FX_WS|MY_WS", &k, &[])?;
        let forward = if roller { Forward::RollerPitchRadS(v[0]) } else { Forward::VsMmS(v[0]) };
        let sixth = match self.d.f {
            1 => PitchInput::FxWsN(v[5]),
            2 => PitchInput::MyWsNmm(v[5]),
            _ => PitchInput::VpitchRadS(v[5]),
        };
        Ok(WheelsetVelocity {
            per_step: self.d.t == 1,
            forward,
            vy_mm_s: v[1],
            vz_mm_s: v[2],
            vroll_rad_s: v[3],
            vyaw_rad_s: v[4],
            sixth,
        })
    }
}

fn six(v: &[f64]) -> [f64; 6] {
    [v[0], v[1], v[2], v[3], v[4], v[5]]
}

#[cfg(test)]
mod tests {
    use super::*;

    const CASE1: &str = "  1 MODULE
 0203100    C-P-B-T-N-F-S
 0022033    V-L-D-C-M-Z-E
 0000321    H-G-I-A-O-W-R
    999     100    30    1     1e-5         MAXGS , MAXIN , MAXNR , MAXOUT, EPS
  0.300   0.300                                 FSTAT, FKIN
  0.280   0.280   82000.  82000.                POISS 1,2,  GG 1,2
  0.200   0.200   1.000   90d   8.0   4.0       DX,DS, DQREL, A_SEP, D_SEP, D_COMB
   14.0     0    1435.0   0.000                GAUGHT, GAUGSQ, GAUGWD, CANT
  'MBench_UIC60_v3.prr'   0     1.0   0.0       RFNAME, MIRRORY, SCALE, SMOOTH
     0.0    0.0   0.000   0.0   0.0   0.000     DY, DZ, ROLL, VY, VZ, VROLL
  1360.0  -70.0   460.0                         FBDIST, FBPOS, NOMRAD
  'MBench_S1002_v3.prw'   0     1.0   0.0       WFNAME, MIRRORY, SCALE, SMOOTH
  0.0  0.0  10000.  0.00000000 0.0000  0.0      S, Y, FZ, ROLL, YAW, PITCH
 2000. 0.0    0.0   0.0        0.0  -4.34811810 VS,VY,VZ, VROLL,VYAW,VPITCH
";

    #[test]
    fn a_first_case_reads_every_group() {
        let cases = parse("t.inp", &format!("{CASE1}  0 MODULE\n")).unwrap();
        assert_eq!(cases.len(), 1);
        let c = &cases[0];
        assert_eq!((c.number, c.line, c.digits.side()), (1, 1, Side::Left));
        let s = &c.state;
        let disc = s.discretisation.as_ref().unwrap();
        assert_eq!(
            (disc.dx_mm, disc.a_sep_rad, disc.d_turn_mm(), disc.g_miss_mm),
            (0.2, 90f64.to_radians(), 12.0, -1.0)
        );
        assert_eq!(s.rail_profile.as_ref().unwrap().format(), ProfileFormat::Simpack);
        assert_eq!(s.position.unwrap().vertical, Vertical::FzN(10000.0));
        assert_eq!(s.velocity.unwrap().sixth, PitchInput::VpitchRadS(-4.34811810));
    }

    #[test]
    fn a_later_case_keeps_what_it_does_not_read() {
        let second = "  1 MODULE\n 0203100\n 0111002\n 0100321\n  0.0  0.5  10000. -0.00002304 0.0012  0.0\n 2000. 0.0 0.0 0.0 0.0 -4.34741340\n  0 MODULE\n";
        let cases = parse("t.inp", &format!("{CASE1}{second}")).unwrap();
        let (one, two) = (&cases[0].state, &cases[1].state);
        assert_eq!(two.position.unwrap().y_mm, 0.5);
        assert_eq!(
            (&two.friction, &two.material, &two.discretisation),
            (&one.friction, &one.material, &one.discretisation)
        );
        assert_eq!((&two.track, &two.rail_profile, &two.wheelset), (&one.track, &one.rail_profile, &one.wheelset));
    }

    #[test]
    fn unequal_static_and_kinetic_friction_is_refused_at_its_place() {
        let deck = CASE1.replace("  0.300   0.300  ", "  0.300   0.250  ");
        let e = parse("t.inp", &deck).unwrap_err();
        assert!(matches!(&e, DeckError::Value { line: 6, column: 3, .. }), "{e}");
    }

    #[test]
    fn a_wheel_position_without_a_wheel_profile_is_refused() {
        let deck: String = CASE1
            .replace(" 0022033 ", " 0022032 ")
            .lines()
            .filter(|l| !l.contains("FBDIST") && !l.contains("WFNAME"))
            .map(|l| format!("{l}\n"))
            .collect();
        let e = parse("t.inp", &deck).unwrap_err();
        assert!(e.to_string().contains("control word V-L-D-C-M-Z-E: E = 2 is not allowed"), "{e}");
    }
}
