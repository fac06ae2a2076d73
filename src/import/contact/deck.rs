//! CONTACT's module-3 cases as typed records (user guide, "Specification of the input file",
//! module 3; the line order of CONTACT's `m_sinput.f90`): the control words P-B-T-N-F-S,
//! [V-]L-D-C-M-Z-E {M2} and [X-]H-G-I-A-O-W-R, then every input line the digits ask for. A value not
//! read in a case is kept from the previous case ([`State`]). Module-1 cases are read by
//! [`super::wheelrail_deck`] (their own state); module 0 ends the deck.

use super::lexer::{Kind, Lexer, Place};
use super::wheelrail_deck::{self, WheelRailCase, WheelRailState};
use super::DeckError;
use std::collections::BTreeMap;

/// The control digits of a module-3 case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Digits {
    /// C (module 1's configuration; a leading seventh digit of P-B-T-N-F-S, unused in module 3).
    pub c1: u8,
    pub p: u8,
    pub b: u8,
    pub t: u8,
    pub n: u8,
    pub f: u8,
    pub s: u8,
    pub v: u8,
    pub l: u8,
    pub d: u8,
    pub c: u8,
    pub m: u8,
    pub z: u8,
    pub e: u8,
    /// M2, the damping model (the optional second integer of L-D-C-M-Z-E; 1 when absent).
    pub m2: u8,
    pub x: u8,
    pub h: u8,
    pub g: u8,
    pub i: u8,
    pub a: u8,
    pub o: u8,
    pub w: u8,
    pub r: u8,
}

/// The potential contact (`IPOTCN` and its line).
#[derive(Debug, Clone, PartialEq)]
pub enum Potcon {
    /// IPOTCN < 0: a Hertzian option, MX, MY and its parameters (AA, BB, SCALE for −3; A1, B1,
    /// SCALE for −1; …) as given.
    Hertz { ipotcn: i64, mx: usize, my: usize, params: Vec<f64> },
    /// IPOTCN = 1…4: a grid, converted to its lower-left corner and element sizes.
    Grid { ipotcn: i64, mx: usize, my: usize, xl_mm: f64, yl_mm: f64, dx_mm: f64, dy_mm: f64 },
}

impl Potcon {
    pub fn mx_my(&self) -> (usize, usize) {
        match self {
            Potcon::Hertz { mx, my, .. } | Potcon::Grid { mx, my, .. } => (*mx, *my),
        }
    }
    pub fn ipotcn(&self) -> i64 {
        match self {
            Potcon::Hertz { ipotcn, .. } | Potcon::Grid { ipotcn, .. } => *ipotcn,
        }
    }
}

/// The undeformed distance of a grid (`IBASE`, `IPLAN` and their lines).
#[derive(Debug, Clone, PartialEq)]
pub struct Undeformed {
    pub ibase: i64,
    pub iplan: i64,
    /// IBASE = 1: B1…B6 of h = B1 x² + B2 x y + B3 y² + B4 x + B5 y + B6; IBASE = 2: NN, XM, RX1,
    /// Y1, DY1 and the NN heights (CONTACT's `prmudf`); IBASE = 9: h per element in CONTACT's
    /// order; other IBASE: their values as read.
    pub values: Vec<f64>,
}

/// One block of subsurface points of an S = 3 (its ISUBS): explicit X, Y, Z (ISUBS = 9), or
/// element centres of the potential contact (ISUBS = 1, 2, 3, 5, 6, 7).
#[derive(Debug, Clone, PartialEq)]
pub enum SubsurfaceBlock {
    /// X(NX), Y(NY), Z(NZ) as given [mm].
    Points([Vec<f64>; 3]),
    /// The ISUBS of a block at element centres.
    ElementCentres(i64),
}

/// Everything a case sets; a value not read is kept from the previous case.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct State {
    /// The blocks of subsurface points read by the last S = 3 (kept for S = 1, 2).
    pub subsurface: Vec<SubsurfaceBlock>,
    /// PEN (N = 0) or FN (N = 1).
    pub pen_or_fn: f64,
    /// CKSI (F = 0) or FX (F = 1, 2).
    pub cksi_or_fx: f64,
    /// CETA (F = 0, 1) or FY (F = 2).
    pub ceta_or_fy: f64,
    pub cphi_per_mm: f64,
    pub spin_centre_mm: [f64; 2],
    /// The friction law in force (the last L other than 1) and its values (FSTAT, FKIN for L = 0).
    pub friction_law: u8,
    pub friction: Vec<f64>,
    /// Friction per grid row (V = 3): the values of every row.
    pub friction_rows: Vec<f64>,
    /// The friction memory MEMDST [mm], MEM_S0 [mm/s] of a law L = 2-4, 6 (zero: none).
    pub memory: [f64; 2],
    pub chi_rad: f64,
    pub dq_mm: f64,
    pub veloc_mm_s: f64,
    /// Whether CHI, DQ, VELOC were ever read.
    pub rolling_read: bool,
    pub poiss: [f64; 2],
    pub gg_mpa: [f64; 2],
    pub potcon: Option<Potcon>,
    /// The N digit and PEN or FN of the last case with D ≥ 1: a Hertzian grid is sized by that
    /// case's ellipse and kept by cases with D = 0 (CONTACT's `init_curr_grid` runs for D ≥ 1).
    pub grid_load: Option<(u8, f64)>,
    pub undeformed: Option<Undeformed>,
    /// Whether an extra rigid-slip term is in force (E = 2, 3, 9, or kept by E = 1).
    pub extra_rhs: bool,
    /// The extra rigid slip EXRHS, pairs (wx, wy) per element in CONTACT's element order, given
    /// with E = 9 (kept by E = 1; `None` for E = 0, 2, 3).
    pub exrhs: Option<Vec<f64>>,
    /// The influence functions in force: the last C of 2, 3, 4, 9 (0 before any: CONTACT's first
    /// case must give one).
    pub inflcf: u8,
    /// INISLP, OMGSLP of the slip-velocity iteration as last read (G = 2, 3, 4); `None`: CONTACT's
    /// defaults 0, 0.5 (`m_hierarch_data.f90` lines 1748-1749).
    pub slip_start: Option<(i64, f64)>,
    /// MAXOUT as last read (G ≠ 1), the most outer iterations between the normal and tangential
    /// problems of dissimilar bodies; `None`: none read.
    pub maxout: Option<i64>,
    /// MAXIN as last read (G ≠ 1): with L = 6 it bounds the temperature iteration; `None`: none
    /// read (CONTACT's default 20, `m_hierarch_data.f90`).
    pub maxin: Option<i64>,
    /// K0_MF, ALFAMF, BETAMF of the simplified theories (M = 3, 5) as last read (CONTACT's
    /// defaults 1, 1, 1 before: no slope reduction).
    pub slope_mf: Option<[f64; 3]>,
    /// GG3 [N/mm²], LAYTHK [mm], TAU_C0 [N/mm²], K_TAU [N/mm³] of the interface layer (M = 4) as
    /// last read, TAU_C0 ≥ 1e10 read as 0 (no plasticity) as CONTACT does (`m_sinput.f90`); a case
    /// with M = 4 takes them.
    pub layer: Option<[f64; 4]>,
    /// Whether the case's M is 4 (CONTACT reads M in every case; its layer values persist).
    pub m4: bool,
    /// FG 1, FG 2 [-] and TC 1, TC 2 [s] of viscoelastic bodies (M = 1) as last read.
    pub visco: Option<[f64; 4]>,
    /// Whether the case's M is 1 (its viscoelastic values persist).
    pub m1: bool,
    /// FLXZ [mm³/N] of the compressible sheet (B = 1) as last read.
    pub flxz: Option<f64>,
    /// Whether the case's B is 1 (its FLXZ persists).
    pub b1: bool,
    /// BKTEMP, HEATCP, LAMBDA, DENS of body 1 then body 2 as last read (H = 3).
    pub heat: Option<[f64; 8]>,
    /// Whether the case computes surface temperatures (H = 1 or 3; the values persist).
    pub heated: bool,
}

impl State {
    /// GG3, LAYTHK, TAU_C0, K_TAU of the interface layer in force: M = 4 with the values last read.
    pub fn layer_in_force(&self) -> Option<[f64; 4]> {
        self.layer.filter(|_| self.m4)
    }

    /// BKTEMP, HEATCP, LAMBDA, DENS of both bodies in force: H ≥ 1 with the values last read.
    pub fn heat_in_force(&self) -> Option<[f64; 8]> {
        self.heat.filter(|_| self.heated)
    }

    /// FG 1, FG 2, TC 1, TC 2 of the viscoelastic bodies in force: M = 1 with the values last read.
    pub fn visco_in_force(&self) -> Option<[f64; 4]> {
        self.visco.filter(|_| self.m1)
    }

    /// FLXZ if the case has a compressible sheet (B = 1, CONTACT's `bound_eff`).
    pub fn sheet_in_force(&self) -> Option<f64> {
        self.flxz.filter(|_| self.b1)
    }

    /// The outer iterations CONTACT makes for dissimilar bodies (K ≠ 0): MAXOUT as read, at least
    /// 1; none read: 10 (`m_sinput.f90` warns at MAXOUT ≤ 1 with K ≠ 0 and keeps it).
    pub fn max_outer(&self) -> usize {
        self.maxout.map_or(crate::scene::MAX_OUTER, |m| m.max(1) as usize)
    }

    /// The most iterations of the temperature iteration (L = 6): CONTACT's loop runs while its
    /// count is at most max(1, MAXIN − 10) (`m_stang.f90`), max(1, MAXIN − 10) + 1 iterations.
    pub fn temperature_iterations(&self) -> usize {
        (self.maxin.unwrap_or(CONTACT_MAXIN) - 10).max(1) as usize + 1
    }
}

/// CONTACT's MAXIN before any is read (`m_hierarch_data.f90`).
const CONTACT_MAXIN: i64 = 20;

/// A module-3 case: its digits and the state after it.
#[derive(Debug, Clone, PartialEq)]
pub struct Case3 {
    pub digits: Digits,
    pub state: State,
}

/// What a case of the deck is.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseKind {
    Module3(Box<Case3>),
    /// A module-1 (wheel–rail) case, read by [`super::wheelrail_deck`].
    Module1(Box<WheelRailCase>),
}

/// One case: its number (counted from 1 over the deck, as CONTACT counts), the line it starts at.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub number: usize,
    pub line: usize,
    pub kind: CaseKind,
}

/// Read every case of a deck: module-3 cases here, module-1 cases by [`super::wheelrail_deck`],
/// each module with its own state carried from case to case (CONTACT's `gd` and `wtd`; a
/// module-1 state per result element REID of the MODULE line).
pub fn parse(file: &str, text: &str) -> Result<Vec<Case>, DeckError> {
    let mut lx = Lexer::new(file, text);
    let mut cases = Vec::new();
    let mut state = State::default();
    let mut wheelrail: BTreeMap<i64, WheelRailState> = BTreeMap::new();
    // The module the next case belongs to, with its result element (None: a MODULE line comes next).
    let mut module: Option<(i64, i64)> = None;
    while !lx.at_end() {
        let line = lx.line_number();
        let (current, reid) = match module {
            Some(m) => m,
            None => match module_line(&mut lx)? {
                Some(m) => m,
                None => break,
            },
        };
        let number = cases.len() + 1;
        let mut reader = CaseReader { lx: &mut lx, number, first: number == 1 };
        let (kind, stays) = if current == 1 {
            let wr = wheelrail_deck::read_case(&mut reader, wheelrail.entry(reid).or_default(), reid)?;
            let stays = wr.digits.r % 2 == 0;
            (CaseKind::Module1(Box::new(wr)), stays)
        } else {
            let digits = reader.case(&mut state)?;
            (CaseKind::Module3(Box::new(Case3 { digits, state: state.clone() })), digits.r % 2 == 0)
        };
        cases.push(Case { number, line, kind });
        // R = 0, 2: stay in the module (the next case has no MODULE line); R = 1, 3: return.
        module = if stays { Some((current, reid)) } else { None };
    }
    Ok(cases)
}

/// A MODULE line: the module (1 or 3) and its optional result element REID (0 when absent);
/// None for module 0, the end of the deck.
fn module_line(lx: &mut Lexer) -> Result<Option<(i64, i64)>, DeckError> {
    let (v, place) = lx.group("MODULE", &[Kind::Int], (2, Kind::Int))?;
    let reid = v.get(1).map_or(0, |&r| r as i64);
    match v[0] as i64 {
        0 => Ok(None),
        m @ (1 | 3) => Ok(Some((m, reid))),
        other => Err(DeckError::Value {
            file: lx.file().into(),
            line: place.line,
            column: place.column,
            what: "MODULE".into(),
            value: other.to_string(),
            allowed: "1 (wheel-rail), 3 (basic contact) or 0 (stop)".into(),
        }),
    }
}

/// Reads one case (module 3 here; module 1 in [`super::wheelrail_deck`] with the same helpers).
pub(super) struct CaseReader<'a> {
    pub(super) lx: &'a mut Lexer,
    /// The case number, counted from 1 over the deck.
    pub(super) number: usize,
    /// Whether it is the deck's first case (CONTACT's checks of `ncase = 1`).
    pub(super) first: bool,
}

impl CaseReader<'_> {
    pub(super) fn reals(&mut self, what: &str, n: usize) -> Result<Vec<f64>, DeckError> {
        self.lx.group(what, &vec![Kind::Real; n], (0, Kind::Real)).map(|(v, _)| v)
    }

    pub(super) fn ints(&mut self, what: &str, n: usize) -> Result<(Vec<i64>, Place), DeckError> {
        let (v, p) = self.lx.group(what, &vec![Kind::Int; n], (0, Kind::Real))?;
        Ok((v.into_iter().map(|x| x as i64).collect(), p))
    }

    pub(super) fn digit_error(&self, word: &str, digit: &str, value: i64, allowed: &str) -> DeckError {
        DeckError::Digit {
            file: self.lx.file().into(),
            case: self.number,
            word: word.into(),
            digit: digit.into(),
            value,
            allowed: allowed.into(),
        }
    }

    /// A control word's digits, most significant first; `n` digits, a leading extra one allowed
    /// when `extra` (so `n + 1` at most).
    pub(super) fn word(
        &mut self,
        word: &str,
        n: usize,
        optional_int: bool,
    ) -> Result<(Vec<u8>, Option<i64>), DeckError> {
        let (v, place) = self.lx.group(word, &[Kind::Int], (usize::from(optional_int), Kind::Int))?;
        let value = v[0] as i64;
        if !(0..10_i64.pow(n as u32 + 1)).contains(&value) {
            return Err(DeckError::Value {
                file: self.lx.file().into(),
                line: place.line,
                column: place.column,
                what: format!("control word {word}"),
                value: value.to_string(),
                allowed: format!("{n} digits (one more leading digit allowed), each 0 to 9"),
            });
        }
        let digits = (0..=n).rev().map(|k| ((value / 10_i64.pow(k as u32)) % 10) as u8).collect();
        Ok((digits, v.get(1).map(|x| *x as i64)))
    }

    pub(super) fn check(&self, word: &str, digit: &str, value: u8, allowed: &[u8]) -> Result<(), DeckError> {
        if allowed.contains(&value) {
            Ok(())
        } else {
            let list: Vec<String> = allowed.iter().map(u8::to_string).collect();
            Err(self.digit_error(word, digit, value.into(), &list.join(", ")))
        }
    }

    fn digits(&mut self) -> Result<Digits, DeckError> {
        let (w1, _) = self.word("P-B-T-N-F-S", 6, false)?;
        let (w2, m2) = self.word("L-D-C-M-Z-E", 6, true)?;
        let (w3, _) = self.word("H-G-I-A-O-W-R", 7, false)?;
        let m2 = m2.unwrap_or(1);
        let d = Digits {
            c1: w1[0],
            p: w1[1],
            b: w1[2],
            t: w1[3],
            n: w1[4],
            f: w1[5],
            s: w1[6],
            v: w2[0],
            l: w2[1],
            d: w2[2],
            c: w2[3],
            m: w2[4],
            z: w2[5],
            e: w2[6],
            m2: (m2 % 10) as u8,
            x: w3[0],
            h: w3[1],
            g: w3[2],
            i: w3[3],
            a: w3[4],
            o: w3[5],
            w: w3[6],
            r: w3[7],
        };
        let (a, b, c) = ("P-B-T-N-F-S", "L-D-C-M-Z-E", "H-G-I-A-O-W-R");
        self.check(a, "P", d.p, &[0, 1, 2, 3])?;
        self.check(a, "B", d.b, &[0, 1, 2, 3, 4, 5, 6])?;
        self.check(a, "T", d.t, &[0, 1, 2, 3])?;
        self.check(a, "N", d.n, &[0, 1])?;
        self.check(a, "F", d.f, &[0, 1, 2])?;
        self.check(a, "S", d.s, &[0, 1, 2, 3])?;
        self.check(b, "V", d.v, &[0, 3])?;
        self.check(b, "L", d.l, &[0, 1, 2, 3, 4, 6])?;
        self.check(b, "D", d.d, &[0, 1, 2])?;
        self.check(b, "C", d.c, &[0, 1, 2, 3, 4, 9])?;
        self.check(b, "M", d.m, &[0, 1, 2, 3, 4, 5, 6, 7])?;
        self.check(b, "Z", d.z, &[0, 1, 2])?;
        self.check(b, "E", d.e, &[0, 1, 2, 3, 9])?;
        self.check(b, "M2", d.m2, &[0, 1, 2])?;
        self.check(c, "X", d.x, &[0, 1])?;
        self.check(c, "H", d.h, &[0, 1, 3])?;
        self.check(c, "G", d.g, &[0, 1, 2, 3, 4, 5])?;
        self.check(c, "I", d.i, &[0, 1, 2, 3])?;
        self.check(c, "A", d.a, &[0, 1, 2])?;
        self.check(c, "O", d.o, &[0, 1, 2, 3, 4, 5, 6])?;
        self.check(c, "R", d.r, &[0, 1, 2, 3])?;
        if self.first {
            // CONTACT: the first case must read what later cases may keep.
            self.check(b, "L", d.l, &[0, 2, 3, 4, 6])?;
            self.check(b, "D", d.d, &[1, 2])?;
        }
        Ok(d)
    }

    /// The case after its MODULE line; `state` is updated with every value read.
    fn case(&mut self, state: &mut State) -> Result<Digits, DeckError> {
        let d = self.digits()?;
        state.m4 = d.m == 4;
        state.m1 = d.m == 1;
        state.b1 = d.b == 1;
        if d.x == 1 {
            self.lx.group("debug output P-S-F-L-C-I-N", &[Kind::Int], (1, Kind::Int))?;
        }
        if let Some(start) = self.solver(d.g, state)? {
            state.slip_start = Some(start);
        }
        self.kinematics(state)?;
        self.friction(&d, state)?;
        if matches!(d.c, 2..=4 | 9) {
            self.rolling_and_material(&d, state)?;
        }
        state.heated = d.h >= 1;
        self.damping_and_heat(&d, state)?;
        if d.d == 2 {
            state.potcon = Some(self.potcon()?);
        }
        if d.d >= 1 {
            state.grid_load = Some((d.n, state.pen_or_fn));
        }
        let gridded = state.potcon.as_ref().is_some_and(|p| p.ipotcn() > 0);
        if d.z == 2 && gridded {
            let npot = state.potcon.as_ref().map_or(0, |p| p.mx_my().0 * p.mx_my().1);
            state.undeformed = Some(self.undeformed(npot)?);
        }
        if d.l != 1 && d.v == 3 {
            self.friction_per_row(&d, state)?;
        }
        self.extra_rhs(&d, state)?;
        if let Some(blocks) = self.subsurface(d.s)? {
            state.subsurface = blocks;
        }
        Ok(d)
    }

    /// PEN or FN, CKSI or FX, CETA or FY, CPHI, and SPINXO, SPINYO where given.
    fn kinematics(&mut self, state: &mut State) -> Result<(), DeckError> {
        let (k, _) = self.lx.group("kinematics PEN/FN, CKSI/FX, CETA/FY, CPHI", &[Kind::Real; 4], (2, Kind::Real))?;
        (state.pen_or_fn, state.cksi_or_fx, state.ceta_or_fy, state.cphi_per_mm) = (k[0], k[1], k[2], k[3]);
        state.spin_centre_mm = if k.len() >= 6 { [k[4], k[5]] } else { [0.0, 0.0] };
        Ok(())
    }

    /// L, V: a new friction law (L ≠ 1) and, with V = 0, its one set of parameters and memory
    /// (V = 3: one set per grid row, read after the geometry, [`CaseReader::friction_per_row`]).
    fn friction(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        if d.l == 1 && (d.v == 3) == state.friction_rows.is_empty() {
            // CONTACT (`m_sinput.f90`): switching V on or off needs new friction parameters.
            let allowed =
                "the previous case's V when L = 1 keeps its friction (V changes only with new friction, L != 1)";
            return Err(self.digit_error("L-D-C-M-Z-E", "V", d.v.into(), allowed));
        }
        if d.l == 1 {
            return Ok(());
        }
        state.friction_law = d.l;
        state.friction_rows.clear();
        state.memory = [0.0; 2];
        if d.v == 3 {
            // One set per grid row follows the geometry; no single set is in force.
            state.friction.clear();
        }
        if d.v == 0 {
            state.friction = self.friction_values(d.l)?;
            if matches!(d.l, 2..=4 | 6) {
                let m = self.reals("MEMDST, MEM_S0", 2)?;
                state.memory = [m[0], m[1]];
            }
        }
        Ok(())
    }

    /// C = 2, 3, 4, 9: the influence functions, CHI, DQ, VELOC for rolling (T ≥ 2) and the material.
    fn rolling_and_material(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        state.inflcf = d.c;
        if d.t >= 2 {
            let (v, _) = self.lx.group("CHI, DQ, VELOC", &[Kind::Angle, Kind::Real, Kind::Real], (1, Kind::Real))?;
            (state.chi_rad, state.dq_mm, state.veloc_mm_s, state.rolling_read) = (v[0], v[1], v[2], true);
        }
        self.material(d, state)
    }

    /// M = 2: the damping line; H = 3: both bodies' temperature lines (and BETAPL with M = 4).
    /// The damping is read past (not modelled); the temperature data are kept.
    fn damping_and_heat(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        if d.m2 == 2 {
            self.reals("CDAMPN, CDAMPT, DFNMAX, DFTMAX", 4)?;
        }
        if d.h == 3 {
            let one = self.reals("BKTEMP1, HEATCP1, LAMBDA1, DENS1", 4)?;
            let two = self.reals("BKTEMP2, HEATCP2, LAMBDA2, DENS2", 4)?;
            state.heat = Some([one[0], one[1], one[2], one[3], two[0], two[1], two[2], two[3]]);
            if d.m == 4 {
                self.reals("BETAPL", 1)?;
            }
        }
        Ok(())
    }

    /// V = 3 with a new law: one set of friction parameters per grid row (MY of the potential
    /// contact), then the memory.
    fn friction_per_row(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        let my = state.potcon.as_ref().map_or(0, |p| p.mx_my().1);
        for _ in 0..my {
            let row = self.friction_values(d.l)?;
            state.friction_rows.extend(row);
        }
        if matches!(d.l, 2..=4 | 6) {
            let m = self.reals("MEMDST, MEM_S0", 2)?;
            state.memory = [m[0], m[1]];
        }
        Ok(())
    }

    /// E: whether an extra right-hand side (EXRHS) is in force (0: none, 1: as before, else a new
    /// one), its values read past where E = 9 gives them per element.
    fn extra_rhs(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        state.extra_rhs = match d.e {
            0 => false,
            1 => state.extra_rhs,
            _ => true,
        };
        match d.e {
            9 => {
                let npot = state.potcon.as_ref().map_or(0, |p| p.mx_my().0 * p.mx_my().1);
                state.exrhs = Some(self.lx.array("EXRHS", 2 * npot)?);
            }
            1 => {}
            _ => state.exrhs = None,
        }
        Ok(())
    }

    /// G: the iteration constants; INISLP, OMGSLP where G = 2, 3, 4 gives them.
    fn solver(&mut self, g: u8, state: &mut State) -> Result<Option<(i64, f64)>, DeckError> {
        if g != 1 {
            let (v, _) = self.lx.group(
                "MAXGS, MAXIN, MAXNR, MAXOUT, EPS",
                &[Kind::Int, Kind::Int, Kind::Int, Kind::Int, Kind::Real],
                (1, Kind::Int),
            )?;
            state.maxout = Some(v[3] as i64);
            state.maxin = Some(v[1] as i64);
        }
        let start = match g {
            2 | 3 => {
                let (v, _) = self.lx.group(
                    "OMEGAH, OMEGAS, INISLP, OMGSLP",
                    &[Kind::Real, Kind::Real, Kind::Int, Kind::Real],
                    (0, Kind::Real),
                )?;
                Some((v[2] as i64, v[3]))
            }
            4 => {
                let (v, _) = self.lx.group("INISLP, OMGSLP", &[Kind::Int, Kind::Real], (0, Kind::Real))?;
                Some((v[0] as i64, v[1]))
            }
            5 => {
                let k = [Kind::Real, Kind::Real, Kind::Int, Kind::Real, Kind::Real, Kind::Real, Kind::Real, Kind::Real];
                self.lx.group("FDECAY, BETATH, KDOWFB, D_IFC, D_LIN, D_CNS, D_SLP, POW_S", &k, (0, Kind::Real))?;
                None
            }
            _ => None,
        };
        Ok(start)
    }

    /// The friction law's values of one set (L = 0: FSTAT, FKIN), and MEMDST, MEM_S0 for the
    /// laws that have them (V = 0 only: with V = 3 they follow the rows).
    fn friction_values(&mut self, l: u8) -> Result<Vec<f64>, DeckError> {
        let v = match l {
            0 => self.reals("FSTAT, FKIN", 2)?,
            2 => self.reals("FKIN, FLIN1, SABSH1, FLIN2, SABSH2", 5)?,
            3 => self.reals("FKIN, FRAT1, SABSH1, FRAT2, SABSH2", 5)?,
            4 => self.reals("FKIN, FEXP1, SABSH1, FEXP2, SABSH2", 5)?,
            _ => self.reals("FREF, TREF, DFHEAT, DTHEAT", 4)?,
        };
        Ok(v)
    }

    /// C ≥ 2: the material lines (C = 4, 9 extras, POISS, GG, B = 1, M = 1…5).
    fn material(&mut self, d: &Digits, state: &mut State) -> Result<(), DeckError> {
        if d.c == 4 {
            let (v, _) = self.ints("IF_METH, VARIANT, NN", 3)?;
            self.lx.array("Y(I), ALPHA(I)", 2 * v[2].clamp(0, 9999) as usize)?;
        }
        if d.c == 9 {
            self.lx.string("CFNAME")?;
        }
        let v = self.reals("POISS 1, 2, GG 1, 2", 4)?;
        (state.poiss, state.gg_mpa) = ([v[0], v[1]], [v[2], v[3]]);
        if d.b == 1 {
            state.flxz = Some(self.reals("FLXZ", 1)?[0]);
        }
        match d.m {
            1 => {
                let v = self.reals("FG 1, 2, TC 1, 2", 4)?;
                state.visco = Some([v[0], v[1], v[2], v[3]]);
            }
            2 => drop(self.reals("FLX, K0_MF, ALFAMF, BETAMF", 4)?),
            3 | 5 => {
                let v = self.reals("K0_MF, ALFAMF, BETAMF", 3)?;
                state.slope_mf = Some([v[0], v[1], v[2]]);
            }
            4 => {
                let v = self.reals("GG3, LAYTHK, TAU_C0, K_TAU", 4)?;
                let tau_c0 = if v[2] >= 1e10 { 0.0 } else { v[2] };
                state.layer = Some([v[0], v[1], tau_c0, v[3]]);
            }
            _ => {}
        }
        Ok(())
    }

    /// D = 2: IPOTCN and its line.
    fn potcon(&mut self) -> Result<Potcon, DeckError> {
        let (v, place) = self.ints("IPOTCN", 1)?;
        let ipotcn = v[0];
        let n_params = match ipotcn {
            -5..=-1 => 3,
            -6 | 1..=4 => 4,
            _ => {
                return Err(DeckError::Value {
                    file: self.lx.file().into(),
                    line: place.line,
                    column: place.column,
                    what: "IPOTCN".into(),
                    value: ipotcn.to_string(),
                    allowed: "-6 to -1 (Hertzian options) or 1 to 4 (a grid)".into(),
                })
            }
        };
        let mut kinds = vec![Kind::Int, Kind::Int];
        kinds.extend(std::iter::repeat_n(Kind::Real, n_params));
        let (v, place) = self.lx.group("MX, MY and the potential contact", &kinds, (0, Kind::Real))?;
        let (mx, my) = (v[0], v[1]);
        if !(mx >= 1.0 && my >= 1.0) {
            return Err(DeckError::Value {
                file: self.lx.file().into(),
                line: place.line,
                column: place.column,
                what: "MX, MY".into(),
                value: format!("{mx}, {my}"),
                allowed: "whole numbers >= 1".into(),
            });
        }
        let (mx, my) = (mx as usize, my as usize);
        let p = &v[2..];
        Ok(match ipotcn {
            i if i < 0 => Potcon::Hertz { ipotcn, mx, my, params: p.to_vec() },
            // 1: XL YL DX DY; 2: XL YL XH YH; 3: XC1 YC1 DX DY; 4: XC1 YC1 XCM YCM.
            1 => Potcon::Grid { ipotcn, mx, my, xl_mm: p[0], yl_mm: p[1], dx_mm: p[2], dy_mm: p[3] },
            2 => {
                let (dx, dy) = ((p[2] - p[0]) / mx as f64, (p[3] - p[1]) / my as f64);
                Potcon::Grid { ipotcn, mx, my, xl_mm: p[0], yl_mm: p[1], dx_mm: dx, dy_mm: dy }
            }
            3 => Potcon::Grid {
                ipotcn,
                mx,
                my,
                xl_mm: p[0] - 0.5 * p[2],
                yl_mm: p[1] - 0.5 * p[3],
                dx_mm: p[2],
                dy_mm: p[3],
            },
            _ => {
                let dx = if mx > 1 { (p[2] - p[0]) / (mx - 1) as f64 } else { 0.0 };
                let dy = if my > 1 { (p[3] - p[1]) / (my - 1) as f64 } else { 0.0 };
                Potcon::Grid { ipotcn, mx, my, xl_mm: p[0] - 0.5 * dx, yl_mm: p[1] - 0.5 * dy, dx_mm: dx, dy_mm: dy }
            }
        })
    }

    /// Z = 2 on a grid: IBASE, IPLAN and their lines.
    fn undeformed(&mut self, npot: usize) -> Result<Undeformed, DeckError> {
        let (v, _) = self.ints("IBASE, IPLAN", 2)?;
        let (ibase, iplan) = (v[0], v[1]);
        let values = match ibase {
            1 => self.lx.array("B1..B6", 6)?,
            2 => {
                let (mut h, place) = self.lx.group(
                    "NN, XM, RX1, Y1, DY1",
                    &[Kind::Int, Kind::Real, Kind::Real, Kind::Real, Kind::Real],
                    (0, Kind::Real),
                )?;
                // CONTACT's checks (m_sinput.f90 lines 1477-1480): NN >= 2, DY1 >= 1e-8.
                if !(h[0] >= 2.0 && h[0] <= 1e7 && h[4] >= 1e-8 && h[2] != 0.0) {
                    return Err(DeckError::Value {
                        file: self.lx.file().into(),
                        line: place.line,
                        column: place.column,
                        what: "NN, XM, RX1, Y1, DY1".into(),
                        value: format!("NN = {}, RX1 = {}, DY1 = {}", h[0], h[2], h[4]),
                        allowed: "NN >= 2 points, a radius RX1 other than 0 and a step DY1 >= 1e-8".into(),
                    });
                }
                let b = self.lx.array("the heights in y, k=1..NN", h[0] as usize)?;
                h.extend(b);
                h
            }
            3 => self.lx.array("B1..B8", 8)?,
            9 => self.lx.array("H(I), I=1..NPOT", npot)?,
            other => {
                return Err(self.digit_error("IBASE, IPLAN", "IBASE", other, "1, 2, 3 or 9"));
            }
        };
        match iplan {
            1 => {}
            2 => drop(self.lx.array("PL1..PL6", 6)?),
            3 => drop(self.lx.array("XL1..YH2", 8)?),
            4 => {
                let (n, _) = self.ints("NPATCH", 1)?;
                let n = n[0].clamp(0, 1000) as usize;
                self.lx.array("XL, XH, YL, YH per patch", 4 * n)?;
                self.lx.array("FAC", n * n.saturating_sub(1) / 2)?;
            }
            other => return Err(self.digit_error("IBASE, IPLAN", "IPLAN", other, "1, 2, 3 or 4")),
        }
        Ok(Undeformed { ibase, iplan, values })
    }

    /// S = 2, 3: the subsurface points (user guide, "Subsurface-stress input"): the blocks read
    /// by S = 3 (`None` for S < 3).
    pub(super) fn subsurface(&mut self, s: u8) -> Result<Option<Vec<SubsurfaceBlock>>, DeckError> {
        if s < 2 {
            return Ok(None);
        }
        self.ints("MATFIL, OUTPUT (subsurface)", 2)?;
        if s < 3 {
            return Ok(None);
        }
        let mut blocks = Vec::new();
        loop {
            let (v, _) = self.ints("ISUBS", 1)?;
            let isubs = v[0];
            let count = |x: f64| x.clamp(0.0, 1e7) as usize;
            match isubs {
                0 => return Ok(Some(blocks)),
                2 | 6 => {
                    // Two lines of three, as CONTACT reads them (`m_subsurf.f90`: 'iii' twice).
                    self.ints("IXL, IXINC, IXH", 3)?;
                    self.ints("IYL, IYINC, IYH", 3)?;
                }
                3 | 7 => {
                    let (n, _) = self.ints("NX, NY", 2)?;
                    self.lx.array("IX(i)", count(n[0] as f64))?;
                    self.lx.array("IY(j)", count(n[1] as f64))?;
                }
                _ => {}
            }
            match isubs {
                1..=3 => drop(self.lx.group("NZ, ZL, DZ", &[Kind::Int, Kind::Real, Kind::Real], (0, Kind::Real))?),
                5..=7 => {
                    let (n, _) = self.ints("NZ", 1)?;
                    self.lx.array("Z(iz)", count(n[0] as f64))?;
                }
                9 => {
                    let (n, _) = self.ints("NX, NY, NZ", 3)?;
                    let mut axes: [Vec<f64>; 3] = Default::default();
                    for (axis, k) in axes.iter_mut().zip(n) {
                        *axis = self.lx.array("X, Y, Z", count(k as f64))?;
                    }
                    blocks.push(SubsurfaceBlock::Points(axes));
                }
                other => return Err(self.digit_error("ISUBS", "ISUBS", other, "0, 1, 2, 3, 5, 6, 7 or 9")),
            }
            if isubs != 9 {
                blocks.push(SubsurfaceBlock::ElementCentres(isubs));
            }
        }
    }
}
