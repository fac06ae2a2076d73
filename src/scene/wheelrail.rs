//! A wheel–rail scene (docs/scene-format.md, "A wheel–rail scene"): two profiles, the track,
//! the wheelset's dimensions and a table of wheelset positions and velocities, one case a row
//! (CONTACT's module 1). Read and checked here like every scene; the profiles are read by the
//! wheel–rail stage, from the paths resolved here.

use super::reader::{parse_toml, Range, Section};
use super::wheelrail_cases::{ANGLE, LENGTH};
use super::{is_valid_name, MaterialSpec, Origin};
use crate::error::InputError;
use std::path::{Path, PathBuf};

/// Which side of the track the wheel runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SideSpec {
    Left,
    Right,
}

/// A profile file and how to take it (CONTACT's RFNAME/WFNAME, MIRRORY, SCALE, SMOOTH).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileSpec {
    /// Resolved against the scene's folder.
    pub path: PathBuf,
    pub mirror_y: bool,
    pub scale: f64,
    pub smooth: f64,
}

/// The rail's placement (GAUGHT > 0: gauge point; else absolute).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlacementSpec {
    Gauge { height_mm: f64, width_mm: f64 },
    Absolute { y_mm: f64, z_mm: f64 },
}

/// How the cases fix the height: a vertical force or a position (CONTACT's N = 1, 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VerticalSpec {
    Force,
    Position,
}

/// One case: the wheelset's position and velocities (a row of the cases table).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaseRow {
    /// The case's number (CONTACT's case for an imported deck).
    pub contact_case: u64,
    pub y_mm: f64,
    /// FZ [N] or z [mm], as [`VerticalSpec`] says.
    pub vertical: f64,
    pub roll_rad: f64,
    pub yaw_rad: f64,
    pub velocity: [f64; 6],
}

/// A validated wheel–rail scene.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelRailScene {
    pub name: String,
    pub solvers: Vec<String>,
    pub side: SideSpec,
    pub rail: ProfileSpec,
    pub wheel: ProfileSpec,
    pub placement: PlacementSpec,
    pub cant_rad: f64,
    pub flange_back_distance_mm: f64,
    pub flange_back_position_mm: f64,
    pub nominal_radius_mm: f64,
    pub mu: f64,
    pub material: MaterialSpec,
    pub dx_mm: f64,
    pub ds_mm: f64,
    /// A_SEP [rad], D_SEP [mm], D_COMB [mm]: which interpenetration regions make one patch.
    pub a_sep_rad: f64,
    pub d_sep_mm: f64,
    pub d_comb_mm: f64,
    pub vertical: VerticalSpec,
    pub cases: Vec<CaseRow>,
    /// Where the report shows the scene (`[report]`).
    pub report: WheelRailReport,
    /// The CONTACT deck and cases an imported scene came from (`[origin]`, as a module-3 scene's).
    pub origin: Option<Origin>,
    /// The scene file's folder.
    pub dir: PathBuf,
}

/// Where the report shows a wheel–rail scene (`[report]`; report::wheelrail).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelRailReport {
    /// The scene declares the group `wheelrail`: it is drawn in the section "Wheel–rail contact".
    pub in_section: bool,
    /// CONTACT's printed output of the same cases, drawn beside the models (resolved path).
    pub contact_output: Option<PathBuf>,
    /// The cases (`contact_case`) whose patches are drawn as maps and on the profiles, as given
    /// (none: [`WheelRailScene::patch_cases`]'s default).
    pub patch_cases: Vec<u64>,
}

/// The report groups a wheel–rail scene may declare.
pub const WHEELRAIL_GROUPS: [&str; 2] = ["wheelrail", "other"];
/// The most cases drawn as patch maps.
const MAX_PATCH_CASES: usize = 20;

/// The columns of the cases table: the leading ones, then `fz_n` or `z_mm`, then the rest.
const LEAD: [&str; 2] = ["contact_case", "y_mm"];
const TAIL: [&str; 8] =
    ["roll_rad", "yaw_rad", "vs_mm_s", "vy_mm_s", "vz_mm_s", "vroll_rad_s", "vyaw_rad_s", "vpitch_rad_s"];

/// The columns of the cases table, in their order: `fz_n` or `z_mm` as `vertical` says.
pub fn case_columns(vertical: VerticalSpec) -> Vec<&'static str> {
    let middle = if vertical == VerticalSpec::Force { "fz_n" } else { "z_mm" };
    LEAD.iter().copied().chain([middle]).chain(TAIL).collect()
}

/// Whether a parsed TOML document is a wheel–rail scene (it has a `[wheelrail]` table).
pub fn is_wheelrail(doc: &toml::Table) -> bool {
    doc.contains_key("wheelrail")
}

/// The wheel–rail scene in `path`, if the file is one (a TOML file with a `[wheelrail]` table);
/// errors name the file.
pub fn read_if_wheelrail(path: &Path) -> Result<Option<WheelRailScene>, InputError> {
    let text = super::read_scene_text(path)?;
    let in_file = |e: InputError| InputError { field: format!("{}: {}", path.display(), e.field), ..e };
    let doc = parse_toml(&text, "scene").map_err(in_file)?;
    if !is_wheelrail(&doc) {
        return Ok(None);
    }
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    WheelRailScene::from_table(&doc, &dir).map(Some).map_err(in_file)
}

impl WheelRailScene {
    /// The cases drawn as patch maps and on the profiles: `[report] patch_cases`, or the first,
    /// middle and last case.
    pub fn patch_cases(&self) -> Vec<u64> {
        if !self.report.patch_cases.is_empty() {
            return self.report.patch_cases.clone();
        }
        let n: Vec<u64> = self.cases.iter().map(|c| c.contact_case).collect();
        let mut out = vec![n[0], n[n.len() / 2], n[n.len() - 1]];
        out.dedup();
        out
    }

    /// Read and check the scene file at `path` (its relative paths resolved against its folder);
    /// a file without `[wheelrail]` is an error.
    pub fn from_file(path: &Path) -> Result<WheelRailScene, InputError> {
        read_if_wheelrail(path)?.ok_or_else(|| {
            InputError::new(
                path.display().to_string(),
                "no [wheelrail] table",
                "a wheel–rail scene (docs/scene-format.md)",
            )
        })
    }

    pub fn from_toml(text: &str, dir: &Path) -> Result<WheelRailScene, InputError> {
        Self::from_table(&parse_toml(text, "scene")?, dir)
    }

    pub fn from_table(doc: &toml::Table, dir: &Path) -> Result<WheelRailScene, InputError> {
        let mut top = Section::new("", doc);
        let name = top.str("name", "a scene name of a-z, 0-9, _")?.to_string();
        if !is_valid_name(&name) {
            return Err(InputError::new(
                "name",
                format!("{name:?}"),
                "a scene name of a-z, 0-9, _ (a folder name, at most 100 characters)",
            ));
        }
        let solvers = top.opt_str_list("solvers", "model names")?.unwrap_or_else(|| vec!["contact".into()]);
        let mut w = top.table("wheelrail")?;
        let side = match w.choice("side", &["left", "right"])? {
            "left" => SideSpec::Left,
            _ => SideSpec::Right,
        };
        let mu = w.f64("mu", Range::new(0.0, false, 10.0, true))?;
        let dx_mm = w.f64("dx_mm", Range::new(1e-3, true, 100.0, true))?;
        let ds_mm = w.f64("ds_mm", Range::new(1e-3, true, 100.0, true))?;
        let a_sep_rad = w
            .opt_f64("a_sep_rad", Range::new(0.0, true, std::f64::consts::PI, true))?
            .unwrap_or(std::f64::consts::FRAC_PI_2);
        let d_sep_mm = w.opt_f64("d_sep_mm", Range::new(0.0, true, 1e3, true))?.unwrap_or(8.0);
        let d_comb_mm = w.opt_f64("d_comb_mm", Range::new(0.0, true, 1e3, true))?.unwrap_or(4.0);
        if d_comb_mm > d_sep_mm {
            return Err(InputError::new("wheelrail.d_comb_mm", d_comb_mm, format!("at most d_sep_mm = {d_sep_mm}")));
        }
        w.finish()?;
        let (rail, placement, cant_rad) = rail(&mut top, dir)?;
        let (wheel, fbd, fbp, radius) = wheel(&mut top, dir)?;
        let material = super::sections::material(&mut top)?;
        let (vertical, cases) = super::wheelrail_cases::read(&mut top, dir, radius)?;
        let origin = super::sections::origin(&mut top)?;
        check_origin(origin.as_ref(), &cases)?;
        let report = report(&mut top, dir, &cases)?;
        top.finish()?;
        Ok(WheelRailScene {
            name,
            solvers,
            side,
            rail,
            wheel,
            placement,
            cant_rad,
            flange_back_distance_mm: fbd,
            flange_back_position_mm: fbp,
            nominal_radius_mm: radius,
            mu,
            material,
            dx_mm,
            ds_mm,
            a_sep_rad,
            d_sep_mm,
            d_comb_mm,
            vertical,
            cases,
            report,
            origin,
            dir: dir.to_path_buf(),
        })
    }
}

/// `[origin] cases` = [first, last] are the smallest and largest `contact_case` of the table (an
/// imported scene's rows are the deck's cases it names).
fn check_origin(origin: Option<&Origin>, cases: &[CaseRow]) -> Result<(), InputError> {
    let Some(o) = origin else { return Ok(()) };
    let first = cases.iter().map(|c| c.contact_case).min().unwrap_or(0);
    let last = cases.iter().map(|c| c.contact_case).max().unwrap_or(0);
    if [first, last] == o.cases.map(|c| c as u64) {
        return Ok(());
    }
    Err(InputError::new(
        "origin.cases",
        format!("{:?}", o.cases),
        format!("[{first}, {last}]: the smallest and largest contact_case of the cases table"),
    ))
}

/// A profile's keys: `profile` (path), `mirror_y`, `scale`, `smooth`.
fn profile(s: &mut Section, dir: &Path) -> Result<ProfileSpec, InputError> {
    let path = dir.join(
        s.str("profile", "a profile file's path relative to the scene (.prr, .prw, .ban, .whl, or two columns y z)")?,
    );
    Ok(ProfileSpec {
        path,
        mirror_y: s.opt_bool("mirror_y")?.unwrap_or(false),
        scale: s.opt_f64("scale", Range::new(0.0, false, 1e4, true))?.unwrap_or(1.0),
        smooth: s.opt_f64("smooth", Range::new(0.0, true, 1e10, true))?.unwrap_or(0.0),
    })
}

/// `[rail]`: its profile, its placement (gauge point or absolute) and the cant.
fn rail(top: &mut Section, dir: &Path) -> Result<(ProfileSpec, PlacementSpec, f64), InputError> {
    let mut r = top.table("rail")?;
    let spec = profile(&mut r, dir)?;
    let placement = match r.opt_f64("gauge_height_mm", Range::new(0.0, false, 1e3, true))? {
        Some(height_mm) => {
            r.refuse("y_mm", "no y_mm with gauge_height_mm (the gauge point places the rail)")?;
            PlacementSpec::Gauge { height_mm, width_mm: r.f64("gauge_width_mm", Range::new(0.0, false, 1e5, true))? }
        }
        None => {
            PlacementSpec::Absolute { y_mm: r.f64("y_mm", LENGTH)?, z_mm: r.opt_f64("z_mm", LENGTH)?.unwrap_or(0.0) }
        }
    };
    let cant_rad = r.opt_f64("cant_rad", ANGLE)?.unwrap_or(0.0);
    r.finish()?;
    Ok((spec, placement, cant_rad))
}

/// `[wheel]`: its profile and the wheelset's FBDIST, FBPOS, NOMRAD.
fn wheel(top: &mut Section, dir: &Path) -> Result<(ProfileSpec, f64, f64, f64), InputError> {
    let mut w = top.table("wheel")?;
    let spec = profile(&mut w, dir)?;
    let fbd = w.f64("flange_back_distance_mm", Range::new(0.0, false, 1e5, true))?;
    let fbp = w.f64("flange_back_position_mm", LENGTH)?;
    let radius = w.f64("nominal_radius_mm", Range::new(1.0, true, 1e5, true))?;
    w.finish()?;
    Ok((spec, fbd, fbp, radius))
}

/// `[report]` of a wheel–rail scene: `group` (`wheelrail` or `other`), `contact_output` (a path
/// relative to the scene) and `patch_cases` (cases of the scene; default its first, middle and
/// last).
fn report(top: &mut Section, dir: &Path, cases: &[CaseRow]) -> Result<WheelRailReport, InputError> {
    let numbers: Vec<u64> = cases.iter().map(|c| c.contact_case).collect();
    let Some(mut t) = top.opt_table("report")? else {
        return Ok(WheelRailReport::default());
    };
    let in_section = t.opt_choice("group", &WHEELRAIL_GROUPS)? == Some("wheelrail");
    let contact_output = t
        .opt_str("contact_output", "a path relative to the scene file: CONTACT's printed output (.out, .ref_out)")?
        .map(|p| dir.join(p));
    let field = t.field("patch_cases");
    let patch_cases = match t.opt_f64_list("patch_cases", Range::new(0.0, true, 1e9, true), MAX_PATCH_CASES)? {
        None => Vec::new(),
        Some(list) => list
            .iter()
            .enumerate()
            .map(|(k, &v)| match numbers.iter().find(|&&n| n as f64 == v) {
                Some(&n) => Ok(n),
                None => Err(InputError::new(
                    format!("{field}[{k}]"),
                    v,
                    format!("a contact_case of the scene's cases ({} to {})", numbers[0], numbers[numbers.len() - 1]),
                )),
            })
            .collect::<Result<_, _>>()?,
    };
    t.finish()?;
    Ok(WheelRailReport { in_section, contact_output, patch_cases })
}
