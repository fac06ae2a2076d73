//! Cases → scenes: one scene per history. A history is a run of cases that carries its state: a
//! transient case with P = 0 continues the case before it (a steady case before it is its steady
//! start, `[init] kind = "steady"`); a case with P = 2 starts afresh. Consecutive steady cases
//! (T = 3, or T = 0 at zero creepage) of one setup are one sweep (`at` the cases' creepages). A
//! transient history is a creepage table (`<name>_table.csv`) at the times `k DQ / VELOC`; a grid
//! geometry is h per element (`<name>_h.csv`). Each scene is written as a TOML table, read back
//! with the project's scene reader and resolved in a temporary folder, and must give every case's
//! creepages, load and friction bit for bit. A history whose cases move one grid by whole elements
//! (a moving window) is written on the union grid of its windows, checked exact per case.

mod contact;
mod history;
mod loading;
mod read_back;
mod rows;
mod stress;
pub mod wheelrail;
mod window;

pub use rows::{along_x, chi_deg, force_ratio};

use super::deck::{self, Case, Case3, CaseKind};
use super::{features, CaseStatus};
use crate::error::InputError;
use crate::physics::material::combine_bodies;
use history::{falling, group, outer_iteration, slip_iteration, History, Run, Start};
use read_back::{check_rows, probe, read_back, tempdir_for};
use rows::{courant_for, row, speeds, sweep_of};
use toml::{Table, Value};
use window::{check_union, quadratic_rows};

/// One scene's files: (file name, contents), the scene file first.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneFiles {
    pub name: String,
    /// The deck's first and last case of the scene.
    pub cases: [usize; 2],
    pub files: Vec<(String, String)>,
}

/// The import of one deck: its supported scenes and every case's status.
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    pub scenes: Vec<SceneFiles>,
    pub statuses: Vec<CaseStatus>,
}

/// The scenes of a deck's text (`file`: its name for `[origin]` and messages; `stem`: the scene
/// names' prefix); a wheel–rail scene's profiles as the deck names them (a scene beside the deck).
pub fn import_text(file: &str, stem: &str, text: &str) -> Result<Imported, InputError> {
    import_text_with(file, stem, text, &wheelrail::ProfilePaths::AsNamed)
}

/// [`import_text`] with the wheel–rail scenes' profile paths from `paths`: module-3 cases become
/// scenes of histories, module-1 cases wheel–rail scenes ([`wheelrail`]), in the deck's order.
pub fn import_text_with(
    file: &str,
    stem: &str,
    text: &str,
    paths: &wheelrail::ProfilePaths,
) -> Result<Imported, InputError> {
    let cases = deck::parse(file, text)?;
    let mut imported = module3(file, stem, &cases)?;
    let module1 = wheelrail::scenes(file, stem, &cases, &mut imported.statuses, paths);
    imported.scenes.extend(module1);
    imported.scenes.sort_by_key(|s| s.cases[0]);
    Ok(imported)
}

/// The module-3 cases' scenes, and every case's status (a module-1 case's its assessment).
fn module3(file: &str, stem: &str, cases: &[Case]) -> Result<Imported, InputError> {
    let mut statuses: Vec<CaseStatus> = cases.iter().map(status).collect();
    // Steady cases whose creepages no sweep reproduces exactly are scenes of one case each.
    let grouped = group(cases, &mut statuses);
    for h in &grouped {
        check_union(cases, h, &mut statuses);
    }
    let histories: Vec<History> = grouped
        .into_iter()
        .flat_map(|h| {
            let points: Vec<[f64; 3]> =
                h.cases.iter().map(|&k| row(case3(cases, k))).map(|r| [r[0], r[1], r[2]]).collect();
            if h.run == Run::Sweep && speeds(cases, &h).is_none() && sweep_of(&points).is_none() {
                h.cases.iter().map(|&k| History { run: Run::Sweep, cases: vec![k] }).collect()
            } else {
                vec![h]
            }
        })
        .collect();
    let mut scenes = Vec::new();
    for h in histories {
        let numbers: Vec<usize> = h.cases.iter().map(|&k| cases[k].number).collect();
        let span = format!("cases {} to {}", numbers[0], numbers[numbers.len() - 1]);
        // A history's state flows forward: the cases before its first refused one are a history.
        let cut = h.cases.iter().position(|&k| !statuses[k].supported()).unwrap_or(h.cases.len());
        for &k in &h.cases[cut..] {
            if statuses[k].supported() {
                let bad = cases[h.cases[cut]].number;
                statuses[k].refused.push(format!("its history ({span}) holds case {bad}, which is not supported"));
            }
        }
        let h = match (h.run, cut) {
            (_, 0) => continue,
            // A start alone: the steady case or the shift itself.
            (Run::Transient { start: Start::Steady }, 1) => History { run: Run::Sweep, cases: vec![h.cases[0]] },
            (Run::Transient { start: Start::Shift }, 1) => History { run: Run::Shifts, cases: vec![h.cases[0]] },
            (run, cut) => History { run, cases: h.cases[..cut].to_vec() },
        };
        let numbers: Vec<usize> = h.cases.iter().map(|&k| cases[k].number).collect();
        let span = format!("cases {} to {}", numbers[0], numbers[numbers.len() - 1]);
        match build(file, stem, cases, &h) {
            Ok(s) => {
                for &k in &h.cases {
                    statuses[k].scene = Some(s.name.clone());
                }
                scenes.push(s);
            }
            Err(e) => {
                for &k in &h.cases {
                    statuses[k].refused.push(format!("the project refuses the scene of its history ({span}): {e}"));
                }
            }
        }
    }
    Ok(Imported { scenes, statuses })
}

fn status(c: &Case) -> CaseStatus {
    let base = CaseStatus { case: c.number, line: c.line, module: 3, scene: None, refused: vec![], notes: vec![] };
    match &c.kind {
        CaseKind::Module1(wr) => {
            let (refused, notes) = wheelrail::assess(wr);
            CaseStatus { module: 1, refused, notes, ..base }
        }
        CaseKind::Module3(c3) => {
            let (refused, notes) = features::assess(c3);
            CaseStatus { refused, notes, ..base }
        }
    }
}

pub(super) fn case3(cases: &[Case], k: usize) -> &Case3 {
    match &cases[k].kind {
        CaseKind::Module3(c) => c,
        CaseKind::Module1(_) => unreachable!("histories hold module-3 cases only"),
    }
}

/// What a history's scene is written from.
struct Source<'a> {
    /// The deck's name, for `[origin]` and messages.
    file: &'a str,
    cases: &'a [Case],
    h: &'a History,
    /// The deck's first and last case of the history.
    numbers: [usize; 2],
    name: String,
    first: &'a Case3,
    last: &'a Case3,
    /// The case whose rolling step the history takes (after a shift start, its first rolling case).
    roll: &'a Case3,
    /// Each case's [`row`].
    rows: Vec<[f64; 5]>,
    /// B(1..6) per case where they change ([`quadratic_rows`]).
    quads: Option<Vec<[f64; 6]>>,
}

impl<'a> Source<'a> {
    fn new(file: &'a str, stem: &str, cases: &'a [Case], h: &'a History) -> Self {
        let numbers = [cases[h.cases[0]].number, cases[h.cases[h.cases.len() - 1]].number];
        let roll = case3(cases, h.cases[usize::from(h.run == (Run::Transient { start: Start::Shift }))]);
        Source {
            file,
            cases,
            h,
            numbers,
            name: scene_name(stem, numbers[0]),
            first: case3(cases, h.cases[0]),
            last: case3(cases, h.cases[h.cases.len() - 1]),
            roll,
            rows: h.cases.iter().map(|&k| row(case3(cases, k))).collect(),
            quads: quadratic_rows(cases, h),
        }
    }

    /// The history's place in the deck, for messages.
    fn place(&self) -> String {
        format!("{}, cases {} to {}", self.file, self.numbers[0], self.numbers[1])
    }

    /// The history's first case's place in the deck, for messages.
    fn first_place(&self) -> String {
        format!("{}, case {}", self.file, self.numbers[0])
    }
}

/// A scene being written: its table and its files (file name, contents).
struct Draft {
    doc: Table,
    files: Vec<(String, String)>,
}

impl Draft {
    fn insert(&mut self, key: &str, value: Value) {
        self.doc.insert(key.into(), value);
    }
}

/// The scene of one history: its sections in turn, then read back and checked case by case.
fn build(file: &str, stem: &str, cases: &[Case], h: &History) -> Result<SceneFiles, InputError> {
    let src = Source::new(file, stem, cases, h);
    let mut draft = Draft { doc: Table::new(), files: Vec::new() };
    draft.insert("name", Value::String(src.name.clone()));
    let simplified = super::features::contact_simplified(src.first);
    let fastsim = simplified.is_some();
    // CONTACT's FASTSIM, and the project's beside it where it rolls along +x with the creepages
    // given (reported against the printed totals, not gated: tolerances.toml); CONTACT's FaStrip;
    // else the exact theory.
    let along_x = rows::chi_deg(src.first.state.chi_rad) == 0.0;
    let solvers: &[&str] = match simplified {
        Some(crate::solvers::fastsim_contact::NAME) if along_x && src.first.digits.f == 0 => {
            &[crate::solvers::fastsim_contact::NAME, crate::solvers::fastsim::MODEL.name]
        }
        Some(crate::solvers::fastsim_contact::NAME) => &[crate::solvers::fastsim_contact::NAME],
        Some(_) => &[crate::solvers::fastrip_contact::NAME],
        None => &["contact"],
    };
    draft.insert("solvers", Value::Array(solvers.iter().map(|s| Value::String(s.to_string())).collect()));
    contact::write(&src, &mut draft)?;
    if fastsim {
        draft.insert("model", contact::fastsim_model(&src.first.state, src.first.digits.b));
    }
    match h.run {
        Run::Sweep => loading::sweep(&src, &mut draft),
        Run::Transient { .. } | Run::Shifts => loading::transient(&src, &mut draft)?,
    }
    if let Some(solver) = contact_solver(src.last).filter(|_| !fastsim) {
        draft.insert("contact_solver", solver);
    }
    if let Some(rolling) = rolling(&src) {
        draft.insert("rolling", rolling);
    }
    let cases_value = Value::Array(src.numbers.iter().map(|&n| Value::Integer(n as i64)).collect());
    draft.insert("origin", table(vec![("file", Value::String(file.into())), ("cases", cases_value)]));
    finish(&src, draft)
}

/// CONTACT's fixed stop of the slip-velocity iteration: rms(S_k − S_(k−1)) ≤ 0.001·rms(S_k)
/// (`m_stang.f90` line 579), `[contact_solver] veldep_tolerance` of an imported falling law.
const CONTACT_VELDEP_TOLERANCE: f64 = 1e-3;

/// CONTACT's fixed stop of the temperature iteration (L = 6): rms(T_k − T_(k−1)) ≤
/// 0.0001·rms(T_k) (`m_stang.f90`, the L = 6 branch), `[contact_solver] tempdep_tolerance`.
const CONTACT_TEMPDEP_TOLERANCE: f64 = 1e-4;

/// `[contact_solver]` of the history's last case, if it needs one: CONTACT's slip-velocity
/// iteration of a falling law as the deck sets it (a steady start is solved with its transient
/// cases'), or its temperature iteration of L = 6 (OMGSLP), stopped where CONTACT stops it, and
/// the bilinear influence functions (C = 3).
fn contact_solver(last: &Case3) -> Option<Value> {
    let mut pairs = Vec::new();
    if falling(&last.state) {
        let (start, omgslp) = slip_iteration(&last.state);
        // Every iterate solved tightly, as CONTACT does: its loose stop then falls on the same iterate.
        pairs.push(("veldep_tolerance", Value::Float(CONTACT_VELDEP_TOLERANCE)));
        pairs.push(("veldep_solves", Value::String("tight".into())));
        if start != "previous" {
            pairs.push(("inislp", Value::String(start.into())));
        }
        if omgslp != crate::scene::OMGSLP {
            pairs.push(("omgslp", Value::Float(omgslp)));
        }
    } else if outer_iteration(&last.state) {
        // L = 6: the damping, and the start where a memory takes its rate from it.
        let (start, omgslp) = slip_iteration(&last.state);
        if last.state.memory[0] > 1e-9 && start != "previous" {
            pairs.push(("inislp", Value::String(start.into())));
        }
        pairs.push(("tempdep_tolerance", Value::Float(CONTACT_TEMPDEP_TOLERANCE)));
        let most = last.state.temperature_iterations();
        if most != crate::scene::TEMPDEP_MAX_ITERATIONS {
            pairs.push(("tempdep_max_iterations", Value::Integer(most as i64)));
        }
        pairs.push(("veldep_solves", Value::String("tight".into())));
        if omgslp != crate::scene::OMGSLP {
            pairs.push(("omgslp", Value::Float(omgslp)));
        }
    }
    if last.state.inflcf == 3 {
        pairs.push(("influence", Value::String("bilinear".into())));
    }
    let coupled = combine_bodies(last.state.poiss, last.state.gg_mpa).k != 0.0;
    if coupled && last.state.max_outer() != crate::scene::MAX_OUTER {
        pairs.push(("max_outer", Value::Integer(last.state.max_outer() as i64)));
    }
    (!pairs.is_empty()).then(|| table(pairs))
}

/// `[rolling]`: shifts (`motion = "shift"`, their speed and Courant number set in [`finish`]), or
/// the rolling step's VELOC and CHI where the deck reads one (its Courant number set in
/// [`finish`]). CONTACT rolls along CHI for T = 2, 3 only (shifts take CHI = 0, `m_sdis.f90`).
fn rolling(src: &Source) -> Option<Value> {
    let roll = &src.roll.state;
    if src.h.run == Run::Shifts {
        return Some(table(vec![("motion", Value::String("shift".into()))]));
    }
    if !roll.rolling_read {
        return None;
    }
    let mut pairs = vec![("v_mm_s", Value::Float(roll.veloc_mm_s)), ("courant", Value::Float(1.0))];
    if src.roll.digits.t >= 2 && chi_deg(roll.chi_rad) != 0.0 {
        pairs.push(("chi_deg", Value::Float(chi_deg(roll.chi_rad))));
    }
    Some(table(pairs))
}

/// Read the scene back in a temporary folder: the Courant number from the project's own grid
/// (shifts: dt = courant·dx/v = 1 s exactly with v = dx, courant = 1; rolling: courant·dx = DQ),
/// then the final scene, which must reproduce every case ([`check_rows`]); the scene file first.
fn finish(src: &Source, mut draft: Draft) -> Result<SceneFiles, InputError> {
    let place = src.place();
    let dir = tempdir_for(&place)?;
    let scene_file = format!("{}.toml", src.name);
    let roll = &src.roll.state;
    // (the shifts' speed, the Courant number) from the project's grid.
    let step = if src.h.run == Run::Shifts {
        let dx_mm = read_back(dir.path(), &scene_file, &probe(&draft.doc), &draft.files)?.grid.dx_mm;
        Some((Some(dx_mm), 1.0))
    } else if roll.rolling_read {
        let dx_mm = read_back(dir.path(), &scene_file, &draft.doc, &draft.files)?.grid.dx_mm;
        Some((None, courant_for(roll.dq_mm, dx_mm)))
    } else {
        None
    };
    if let (Some((speed, courant)), Some(Value::Table(r))) = (step, draft.doc.get_mut("rolling")) {
        if let Some(v_mm_s) = speed {
            r.insert("v_mm_s".into(), Value::Float(v_mm_s));
        }
        r.insert("courant".into(), Value::Float(courant));
    }
    let problem = read_back(dir.path(), &scene_file, &draft.doc, &draft.files)?;
    let numbers: Vec<usize> = src.h.cases.iter().map(|&k| src.cases[k].number).collect();
    check_rows(&problem, &src.rows, src.quads.as_deref(), &numbers)?;
    if let Some(stress) = stress::section(src, &problem)? {
        // the subsurface points read back too
        draft.insert("stress", stress);
        read_back(dir.path(), &scene_file, &draft.doc, &draft.files)?;
    }
    let toml = toml::to_string(&draft.doc)
        .map_err(|e| InputError::new(&place, "a scene", format!("a scene TOML can hold: {e}")))?;
    let text = format!(
        "# Imported by `creepbench import contact` from {}, cases {} to {}.\n{toml}",
        src.file, src.numbers[0], src.numbers[1]
    );
    draft.files.insert(0, (scene_file, text));
    Ok(SceneFiles { name: src.name.clone(), cases: src.numbers, files: draft.files })
}

/// CONTACT's material of a case (`POISS`, `GG` of both bodies combined).
fn material_of(s: &deck::State) -> crate::physics::Material {
    let m = combine_bodies(s.poiss, s.gg_mpa);
    crate::physics::Material::from_g(m.g_mpa, m.poisson)
}

/// A scene name from the deck's stem: lower case, `[a-z0-9_]`.
fn scene_name(stem: &str, case: usize) -> String {
    let clean: String = stem
        .chars()
        .map(|c| c.to_ascii_lowercase())
        .map(|c| if c.is_ascii_lowercase() || c.is_ascii_digit() { c } else { '_' })
        .take(80)
        .collect();
    format!("{clean}_{case}")
}

fn table(pairs: Vec<(&str, Value)>) -> Value {
    Value::Table(pairs.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
}

fn floats(v: &[f64]) -> Value {
    Value::Array(v.iter().map(|&x| Value::Float(x)).collect())
}

#[cfg(test)]
mod tests {
    use super::super::deck::Potcon;
    use super::*;

    /// Two steady cases: the second has no MODULE line before it (R = 0 in the first) and keeps
    /// the friction (L = 1), the material and rolling step (C = 0) and the grid (D = 0, Z = 0).
    const DECK: &str = "\
 3  MODULE
  203100      P-B-T-N-F-S
  022020      L-D-C-M-Z-E
 0000340      H-G-I-A-O-W-R   (R = 0: stay in module 3)
   80  200  5  1  1e-6
 82000.  0.001  0.0  0.0      FN, CKSI, CETA, CPHI
 0.3  0.3                     FSTAT, FKIN
 0.0  0.4  30000.             CHI, DQ, VELOC
 0.28 0.28 82000. 82000.      POISS, GG
 -3
 44  44  8.0  4.0  1.1
  3100        P-B-T-N-F-S  (leading zeros left out: P = 0, B = 0)
  100000      L-D-C-M-Z-E
  100341      H-G-I-A-O-W-R
 82000.  0.002  0.0  0.0
 0  MODULE
";

    #[test]
    fn a_case_keeps_what_it_does_not_read_and_steady_cases_form_one_sweep() {
        let cases = deck::parse("t.inp", DECK).unwrap();
        assert_eq!(cases.len(), 2);
        let CaseKind::Module3(c2) = &cases[1].kind else { panic!("module 3") };
        assert_eq!((c2.digits.p, c2.digits.t, c2.digits.l, c2.digits.d), (0, 3, 1, 0));
        assert_eq!((cases[1].line, c2.state.cksi_or_fx), (12, 0.002));
        assert_eq!((c2.state.friction.clone(), c2.state.dq_mm, c2.state.gg_mpa), (vec![0.3, 0.3], 0.4, [82000.0; 2]));
        assert_eq!(c2.state.potcon, Some(Potcon::Hertz { ipotcn: -3, mx: 44, my: 44, params: vec![8.0, 4.0, 1.1] }));
        let imported = import_text("t.inp", "t", DECK).unwrap();
        assert!(imported.statuses.iter().all(CaseStatus::supported), "{:?}", imported.statuses);
        assert_eq!(imported.scenes.len(), 1);
        let s = &imported.scenes[0];
        assert_eq!((s.name.as_str(), s.cases), ("t_1", [1, 2]));
        assert!(s.files[0].1.contains("at = [0.001, 0.002]"), "{}", s.files[0].1);
    }

    #[test]
    fn coulomb_friction_is_fstat_whatever_fkin_says() {
        // CONTACT's L = 0 overwrites FKIN with FSTAT (`fric_update`, m_friclaw.f90).
        let deck =
            DECK.replace(" 0.3  0.3                     FSTAT, FKIN", " 0.3  0.25                    FSTAT, FKIN");
        let imported = import_text("t.inp", "t", &deck).unwrap();
        assert!(imported.statuses.iter().all(CaseStatus::supported), "{:?}", imported.statuses);
        assert!(imported.statuses[0].notes.iter().any(|n| n.starts_with("FSTAT = 0.3, FKIN = 0.25")));
        assert!(imported.scenes[0].files[0].1.contains("mu = 0.3\n"), "{}", imported.scenes[0].files[0].1);
    }

    #[test]
    fn a_transient_case_after_a_steady_one_is_its_steady_start() {
        let deck = DECK.replace("  3100        P-B-T-N-F-S", "  2100        P-B-T-N-F-S");
        let imported = import_text("t.inp", "t", &deck).unwrap();
        assert_eq!(imported.scenes.len(), 1, "{:?}", imported.statuses);
        let files = &imported.scenes[0].files;
        assert!(files[0].1.contains("[init]\nkind = \"steady\""), "{}", files[0].1);
        // t = k DQ/VELOC from the steady start at t = 0.
        assert_eq!(files[1], ("t_1_table.csv".to_string(), format!("t_s,cx\n0.0,0.001\n{:?},0.002\n", 0.4 / 30000.0)));
    }
}
