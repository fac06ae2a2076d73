//! A wheel–rail scene (docs/scene-format.md, "A wheel–rail scene"): two profiles, the track,
//! the wheelset's dimensions and a table of wheelset positions and velocities, one case a row
//! (CONTACT's module 1). Read and checked here like every scene; the profiles are read by the
//! wheel–rail stage, from the paths resolved here.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{parse_toml, Range, Section};
use super::top::table;
use super::{is_valid_name, MaterialSpec, Origin};
use crate::error::InputError;
use crate::physics::TemperatureLaw;
use std::path::{Path, PathBuf};

/// Which side of the track the wheel runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SideSpec {
    Left,
    Right,
}

/// A profile file and how to take it (CONTACT's RFNAME/WFNAME, MIRRORY, SCALE, SMOOTH, MIRRORZ
/// and the options of PRFOPT: ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID, MAXOMIT).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileSpec {
    /// Resolved against the scene's folder.
    pub path: PathBuf,
    pub mirror_y: bool,
    /// MIRRORZ: −1 keep z as read, 0 detect (Miniprof files and tables), 1 mirror z.
    pub mirror_z: i8,
    pub scale: f64,
    /// SMOOTH: λ of the smoothing spline, or with `smooth_weighted` its filter length [mm].
    pub smooth: f64,
    /// ISMOOTH = 1: the smoothing spline weighted by the points' spacing, SMOOTH a length [mm].
    pub smooth_weighted: bool,
    /// ZIGTHRS, KINKHIGH, KINKLOW [rad], KINKWID [mm]: the cleaning of zig-zags and kinks.
    pub zig_zag_rad: f64,
    pub kink_high_rad: f64,
    pub kink_low_rad: f64,
    pub kink_width_mm: f64,
    /// MAXOMIT: the largest fraction of a wheel profile left out where it folds back.
    pub max_omit: f64,
}

/// The rail's deviation from its design position and its velocity (CONTACT's DYRAIL, DZRAIL,
/// DROLLR, VYRAIL, VZRAIL, VROLLR), in the side's own frame as CONTACT's input gives them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RailDeviationSpec {
    /// DYRAIL, DZRAIL [mm], DROLLR [rad].
    pub position: [f64; 3],
    /// VYRAIL, VZRAIL [mm/s], VROLLR [rad/s].
    pub velocity: [f64; 3],
}

/// The wheel's deviation from its design place on the wheelset and its rate (CONTACT's flexible
/// wheelset deviations DXWHL … DPITCHW, VXWHL … VPITCHW, E = 4, 5), in wheelset coordinates of
/// the side's own wheelset as CONTACT's input gives them.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelDeviationSpec {
    /// DXWHL, DYWHL, DZWHL [mm], DROLLW, DYAWW, DPITCHW [rad].
    pub position: [f64; 6],
    /// VXWHL, VYWHL, VZWHL [mm/s], VROLLW, VYAWW, VPITCHW [rad/s].
    pub velocity: [f64; 6],
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

/// How the cases fix the pitch: its velocity, or the longitudinal force it must give (CONTACT's
/// F = 0, 1: `[cases] longitudinal`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LongitudinalSpec {
    /// VPITCH given (`vpitch_rad_s`).
    Velocity,
    /// FX_WS given (`fx_ws_n`, the total force on the rail along the wheelset's x): VPITCH found.
    Force,
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
    /// VS, VY, VZ [mm/s], VROLL, VYAW [rad/s], then VPITCH [rad/s] or FX_WS [N], as
    /// [`LongitudinalSpec`] says.
    pub velocity: [f64; 6],
    /// The wheelset's position along the track S_WS [mm] where the table gives it (column
    /// `s_mm`, a shift's only: CONTACT reads S_WS per case, the anchor of the material-fixed grid).
    pub s_mm: Option<f64>,
    /// The wheelset's pitch angle PITCH [rad] (column `pitch_rad`, 0 if absent): which part of an
    /// out-of-round wheel (a wheel slices file) lies at its lowest point; a round wheel is the same
    /// at every pitch.
    pub pitch_rad: f64,
}

/// What the friction coefficient varies with (CONTACT's V digit in module 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MuBy {
    /// V = 1: the contact angle of each patch on the wheel (CONTACT's ALPHVF) [rad].
    ContactAngle,
    /// V = 2: the wheelset's position along the track (SVF) [mm]; the case's position `s_mm`.
    TrackS { s_mm: f64 },
}

/// Coulomb's μ at control points (`[wheelrail] mu_by`, `mu_at`, `mu_values`): linear between
/// them, constant beyond (CONTACT's `fric_interp`); with the temperature law each of its
/// parameters so (`fric_interp_arr`, L = 6).
#[derive(Debug, Clone, PartialEq)]
pub struct MuVariation {
    pub by: MuBy,
    /// The control points, increasing: rad (contact angle) or mm (track position).
    pub at: Vec<f64>,
    /// μ at each point; with the temperature law its FREF.
    pub values: Vec<f64>,
    /// With `[friction] law = "temperature"`: TREF [°C], DFHEAT and DTHEAT [°C] at each point
    /// (`tref_c_values`, `dfheat_values`, `dtheat_c_values`).
    pub temperature: Option<[Vec<f64>; 3]>,
}

impl MuVariation {
    /// μ at `x` (rad or mm as [`MuBy`] says): linear between the control points, the end values
    /// beyond them.
    pub fn at(&self, x: f64) -> f64 {
        interpolate(&self.at, &self.values, x)
    }

    /// The temperature law at `x`, each parameter interpolated as μ is; `None` for Coulomb's law.
    pub fn law_at(&self, x: f64) -> Option<TemperatureLaw> {
        let [tref, dfheat, dtheat] = self.temperature.as_ref()?;
        Some(TemperatureLaw {
            fref: self.at(x),
            tref_c: interpolate(&self.at, tref, x),
            dfheat: interpolate(&self.at, dfheat, x),
            dtheat_c: interpolate(&self.at, dtheat, x),
        })
    }
}

/// `v` given at the increasing points `a`, at `x`: linear between them, the end values beyond.
fn interpolate(a: &[f64], v: &[f64], x: f64) -> f64 {
    let n = a.len();
    if x <= a[0] {
        return v[0];
    }
    if x >= a[n - 1] {
        return v[n - 1];
    }
    let k = a.partition_point(|&p| p <= x).min(n - 1);
    let t = (x - a[k - 1]) / (a[k] - a[k - 1]);
    v[k - 1] + t * (v[k] - v[k - 1])
}

/// The contact approach (`[wheelrail] approach`, CONTACT's D).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Approach {
    /// Each patch on its tangent plane, its creepages those of its reference point (D = 2).
    #[default]
    Planar,
    /// The tangent plane's grid with the rigid slip of the actual surfaces at every element
    /// (D = 3, `wr_rigslip_wrsurf`).
    PlanarSurfaceSlip,
    /// Each patch on a curved reference surface midway between the rail and the wheel (D = 4).
    Conformal,
}

/// How the interpenetration regions are found (`[wheelrail] contact_search`, CONTACT's D = 2
/// against 5 and 6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ContactSearch {
    /// Along the wheel's contact locus (D = 2, 3, 4).
    #[default]
    Locus,
    /// CONTACT's brute-force grid search (D = 5, `locate_interpen_2d`).
    Grid,
    /// The grid search on a finer lateral mesh and a wider arc of the wheel, for steep slopes such
    /// as guard-rail contact (D = 6, `use_steep_slopes`: `fac_dyds` 0.2, the wheel's arc ±14°).
    GridSteep,
}

impl ContactSearch {
    /// Whether the regions come from the grid search (D = 5 or 6).
    pub fn is_grid(self) -> bool {
        self != Self::Locus
    }
}

/// How the wheel moves in every case (`[wheelrail] motion`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum MotionSpec {
    /// Steady rolling (CONTACT's T = 3; `"rolling"`, the default).
    #[default]
    Rolling,
    /// A shift from rest (T = 1, P = 2; `"shift"`): the cases' velocities are one step's shifts
    /// [mm, rad], the grid is fixed in the rail's material at the wheelset's position `s_mm`.
    /// With `sequence` (`"shift_sequence"`, P = 0 after the first case) each case continues the
    /// one before it, at the position the shifts before it reached
    /// ([`WheelRailScene::shift_positions_mm`]). With `steady_start` (`start = "steady"`) the
    /// sequence's first case is steady rolling (T = 3) and the shifts continue it (T = 1, P = 0).
    Shift { s_ws_mm: f64, sequence: bool, steady_start: bool },
    /// Transient rolling (`"rolling_sequence"`): the first case steady rolling (T = 3) or, with
    /// `from_rest` (`start = "rest"`), one transient step from zero tractions (T = 2, P = 2); each
    /// later case one transient rolling step of DQ = `dq_rel` DX continuing the one before (T = 2,
    /// P = 0).
    RollingSequence { dq_rel: f64, from_rest: bool },
}

/// The models that follow shifts (CONTACT's T = 1), each carrying its own tractions on the
/// material-fixed grid from case to case: the exact theory, and FASTSIM and the UBA (one brush
/// shift per element, `solvers::brush_shift`).
pub const SHIFT_MODELS: &[&str] = &["contact", "fastsim", "uba"];
/// The models that follow transient rolling (T = 2): the exact theory and the UBA (its explicit
/// transport step from the tractions the case before left).
pub const TRANSIENT_ROLLING_MODELS: &[&str] = &["contact", "uba"];

impl MotionSpec {
    /// The models that follow this motion and its `[wheelrail] motion` value; `None` in steady
    /// rolling (every model).
    pub fn models(&self) -> Option<(&'static [&'static str], &'static str)> {
        match self {
            MotionSpec::Rolling => None,
            MotionSpec::Shift { sequence: false, .. } => Some((SHIFT_MODELS, "shift")),
            MotionSpec::Shift { sequence: true, .. } => Some((SHIFT_MODELS, "shift_sequence")),
            MotionSpec::RollingSequence { .. } => Some((TRANSIENT_ROLLING_MODELS, "rolling_sequence")),
        }
    }

    /// Every model of `solvers` one that follows this motion, else the first that does not, named.
    pub fn check_models(&self, solvers: &[String]) -> Result<(), InputError> {
        let Some((able, motion)) = self.models() else { return Ok(()) };
        match solvers.iter().find(|m| !able.contains(&m.as_str())) {
            None => Ok(()),
            Some(m) => Err(InputError::new("solvers", format!("{m:?}"), moving_allowed(able, motion))),
        }
    }
}

/// What a scene of `motion` may run: `able`, and why the others cannot follow it.
pub fn moving_allowed(able: &[&str], motion: &str) -> String {
    let why = if able.contains(&"fastsim") {
        "the other models have no history of a shift"
    } else {
        "FASTSIM has no memory in rolling (it marches each step steady), the other models none either"
    };
    format!("models that carry their history through [wheelrail] motion = \"{motion}\": {} ({why})", able.join(", "))
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
    /// A roller rig's roller (`[rail] roller_radius_mm`, `roller_vpitch_rad_s`; CONTACT's C = 4, 5).
    pub roller: Option<super::wheelrail_profile::RollerSpec>,
    /// The rail's deviation from its design position and its velocity (`[rail] deviation_*`).
    pub rail_deviation: RailDeviationSpec,
    /// A rail deflecting on springs under the contact forces (`[massless_rail]`, CONTACT's F = 3).
    pub massless_rail: Option<super::wheelrail_massless::MasslessRailSpec>,
    /// CONTACT's T = 0 (`[wheelrail] frictionless`): the normal problem only, no tangential
    /// forces (every model's FX, FS, MN are 0).
    pub frictionless: bool,
    pub flange_back_distance_mm: f64,
    pub flange_back_position_mm: f64,
    pub nominal_radius_mm: f64,
    /// The wheel's deviation from its design place and its rate (`[wheel] deviation_*`).
    pub wheel_deviation: WheelDeviationSpec,
    /// Coulomb's μ of every patch (`mu`); with a variation by track position its value at the
    /// case's position; by contact angle its first value (each patch then takes its own).
    pub mu: f64,
    /// μ varying across the rail or along the track (CONTACT's V = 1, 2), if it does.
    pub mu_variation: Option<MuVariation>,
    pub material: MaterialSpec,
    /// Friction of the surface temperature and the exact solver's options (`[friction]`,
    /// `[contact_solver]`; CONTACT's L = 6 with H = 3).
    pub tangential: super::wheelrail_tangential::Tangential,
    pub dx_mm: f64,
    pub ds_mm: f64,
    /// A_SEP [rad], D_SEP [mm], D_COMB [mm]: which interpenetration regions make one patch;
    /// D_TURN [mm]: up to where separate patches' angles are turned.
    pub a_sep_rad: f64,
    pub d_sep_mm: f64,
    pub d_comb_mm: f64,
    pub d_turn_mm: f64,
    /// The wheel surface of the undeformed distance (`wheel_surface`): `false` the exact one,
    /// `true` CONTACT's mesh of it (`"contact_mesh"`).
    pub wheel_mesh: bool,
    /// The contact locus or the brute-force grid search (`contact_search`, CONTACT's D = 5, 6).
    pub search: ContactSearch,
    /// The contact approach (`approach`, CONTACT's D = 2, 3 or 4).
    pub approach: Approach,
    /// Steady rolling, or a shift from rest (`motion`, `s_mm`; CONTACT's T = 3 or 1 with P = 2).
    pub motion: MotionSpec,
    /// S_WS [mm] (`[wheelrail] s_mm`, 0 if absent): where the wheelset stands along the track (on a
    /// rail slices file, the track's x = 0 at u = S_WS).
    pub s_ws_mm: f64,
    pub vertical: VerticalSpec,
    /// VPITCH or FX_WS given (`[cases] longitudinal`).
    pub longitudinal: LongitudinalSpec,
    pub cases: Vec<CaseRow>,
    /// Where the report shows the scene (`[report]`).
    pub report: WheelRailReport,
    /// The CONTACT deck and cases an imported scene came from (`[origin]`, as a module-3 scene's).
    pub origin: Option<Origin>,
    /// The scene file's folder.
    pub dir: PathBuf,
}

/// The figures of the section "Wheel–rail contact" a scene declares (`[report] group`;
/// report::wheelrail).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WheelRailFigures {
    /// Not drawn (`"other"`).
    #[default]
    None,
    /// Every patch quantity against the lateral shift or S_WS, the profiles, the patch maps and the
    /// models' errors (`"wheelrail"`).
    Full,
    /// The wheel-flat figure: per patch FN, the approach, FX and FS against the distance rolled
    /// −PITCH·NOMRAD (`"wheel_flat"`; an out-of-round wheel, its cases' column `pitch_rad`).
    WheelFlat,
    /// The crossing figure: per patch the contact position on the rail YCP(R) and FN against each
    /// case's S_WS where the cases give theirs (the column `s_mm`), else against Y_WS (`"crossing"`).
    Crossing,
}

/// The choices of `[report] group` and the figures each declares.
const GROUPS: [(&str, WheelRailFigures); 4] = [
    ("wheelrail", WheelRailFigures::Full),
    ("wheel_flat", WheelRailFigures::WheelFlat),
    ("crossing", WheelRailFigures::Crossing),
    ("other", WheelRailFigures::None),
];

/// Where the report shows a wheel–rail scene (`[report]`; report::wheelrail).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelRailReport {
    /// The figures the scene declares (`group`); any but `None` draws it in the section
    /// "Wheel–rail contact".
    pub figures: WheelRailFigures,
    /// CONTACT's printed output of the same cases, drawn beside the models (resolved path).
    pub contact_output: Option<PathBuf>,
    /// The cases (`contact_case`) whose patches are drawn as maps and on the profiles, as given
    /// (none: [`WheelRailScene::patch_cases`]'s default).
    pub patch_cases: Vec<u64>,
}

/// A wheel–rail scene's top level (`<!-- keys:wheelrail_top -->`).
pub const TOP_KEYS: Keys = Keys {
    id: "wheelrail_top",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("1 to 100 characters of `[a-z0-9_]`"),
            Absent::Required,
            r#"the scene's id and its result folder: `name = "mbench_a22_left"`"#,
        ),
        key(
            "solvers",
            "–",
            Allowed::Text("a list of names of the built-in models (as a scene's `solvers`; no external models)"),
            Absent::Text("`[\"contact\"]`"),
            r#"the models run on every patch ([models.md](models.md)); `kpec` and `analyn` find their own patches and height: `solvers = ["contact", "fastsim", "kpec"]`"#,
        ),
        table("wheelrail"),
        table("rail"),
        table("wheel"),
        table("material"),
        table("friction"),
        table("contact_solver"),
        table("cases"),
        table("massless_rail"),
        table("origin"),
        table("report"),
    ],
};

/// `[report]` of a wheel–rail scene (`<!-- keys:wheelrail_report -->`).
pub const REPORT_KEYS: Keys = Keys {
    id: "wheelrail_report",
    owner: file!(),
    keys: &[
        key(
            "group",
            "–",
            Allowed::Choice(
                &["wheelrail", "wheel_flat", "crossing", "other"],
                "`\"wheel_flat\"` only on a wheel slices file (`[wheel] profile` a `.slcw` file)",
            ),
            Absent::Choice("other"),
            r#"the figures of the section "Wheel–rail contact" that draw the scene, every model beside CONTACT's points: `"wheelrail"` every patch quantity against the lateral shift (or S_WS), the profiles, the patch maps and the models' errors; `"wheel_flat"` per patch FN, the approach, FX and FS against the distance rolled −PITCH·NOMRAD [mm] (an out-of-round wheel turned by its cases' `pitch_rad`); `"crossing"` per patch the contact position on the rail YCP(R) and FN against each case's S_WS [mm] where the cases give theirs (the column `s_mm`), else against the lateral shift Y_WS [mm] (the contact moving from the wing rail to the nose and the load passing between them); `"other"` not drawn: `group = "crossing"`"#,
        ),
        key(
            "contact_output",
            "–",
            Allowed::Text("a path relative to the scene file: CONTACT's printed module-1 output (`.out`, `.ref_out`)"),
            Absent::Text("none"),
            r#"CONTACT's results of the same wheelset, drawn as black markers at their own printed Y_WS (S_WS where the cases give theirs, −PITCH·NOMRAD in a wheel flat's figure): `contact_output = "../../reference/contact_wheelrail/examples/mbench_a22_left.ref_out"`"#,
        ),
        key(
            "patch_cases",
            "–",
            Allowed::Numbers {
                range: Range::new(0.0, true, 1e9, true),
                min_len: 1,
                max_len: 20,
                note: "each a `contact_case` of the scene's cases",
            },
            Absent::Text("the first, middle and last case"),
            r#"the cases drawn on the profiles and as patch maps: `patch_cases = [1, 11, 21]`"#,
        ),
    ],
};

/// The columns of the cases table: the leading ones, then `fz_n` or `z_mm`, then the rest.
const LEAD: [&str; 2] = ["contact_case", "y_mm"];
const TAIL: [&str; 8] =
    ["roll_rad", "yaw_rad", "vs_mm_s", "vy_mm_s", "vz_mm_s", "vroll_rad_s", "vyaw_rad_s", "vpitch_rad_s"];

/// The columns of the cases table, in their order: `fz_n` or `z_mm` as `vertical` says, the last
/// `vpitch_rad_s` or `fx_ws_n` as `longitudinal` says.
pub fn case_columns(vertical: VerticalSpec, longitudinal: LongitudinalSpec) -> Vec<&'static str> {
    let middle = if vertical == VerticalSpec::Force { "fz_n" } else { "z_mm" };
    let last = if longitudinal == LongitudinalSpec::Force { "fx_ws_n" } else { "vpitch_rad_s" };
    LEAD.iter().copied().chain([middle]).chain(TAIL[..7].iter().copied()).chain([last]).collect()
}

/// The optional column of a shift's positions, second after `contact_case` where a table has it.
pub const POSITION_COLUMN: &str = "s_mm";

/// [`case_columns`] with the shift's positions [`POSITION_COLUMN`] after `contact_case`.
pub fn case_columns_with_positions(vertical: VerticalSpec, longitudinal: LongitudinalSpec) -> Vec<&'static str> {
    let mut out = case_columns(vertical, longitudinal);
    out.insert(1, POSITION_COLUMN);
    out
}

/// The optional last column of the cases table: the pitch angle per case.
pub const PITCH_COLUMN: &str = "pitch_rad";

/// The columns of the cases table with the pitch angle `pitch_rad` last (an out-of-round wheel).
pub fn case_columns_with_pitch(vertical: VerticalSpec, longitudinal: LongitudinalSpec) -> Vec<&'static str> {
    let mut out = case_columns(vertical, longitudinal);
    out.push(PITCH_COLUMN);
    out
}

/// Whether a parsed TOML document is a wheel–rail scene (it has a `[wheelrail]` table).
pub fn is_wheelrail(doc: &toml::Table) -> bool {
    doc.contains_key("wheelrail")
}

/// The wheel–rail scene in `path`, if the file is one (a TOML file with a `[wheelrail]` table);
/// errors name the file.
pub fn read_if_wheelrail(path: &Path) -> Result<Option<WheelRailScene>, InputError> {
    wheelrail_of(path, &read_scene_doc(path)?)
}

/// The scene file at `path` parsed as TOML (not yet validated); errors name the file.
pub fn read_scene_doc(path: &Path) -> Result<toml::Table, InputError> {
    let text = super::read_scene_text(path)?;
    parse_toml(&text, "scene").map_err(|e| in_file(path, e))
}

/// The wheel–rail scene of the parsed scene file `doc` read from `path`, if it is one (it has a
/// `[wheelrail]` table); errors name the file.
pub fn wheelrail_of(path: &Path, doc: &toml::Table) -> Result<Option<WheelRailScene>, InputError> {
    if !is_wheelrail(doc) {
        return Ok(None);
    }
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    WheelRailScene::from_table(doc, &dir).map(Some).map_err(|e| in_file(path, e))
}

/// `e`, naming the file `path` before its field.
fn in_file(path: &Path, e: InputError) -> InputError {
    InputError { field: format!("{}: {}", path.display(), e.field), ..e }
}

impl WheelRailReport {
    /// Whether the scene is drawn in the section "Wheel–rail contact".
    pub fn in_section(&self) -> bool {
        self.figures != WheelRailFigures::None
    }
}

impl WheelRailScene {
    /// Each case's S_WS [mm] where the cases give their own: a shift's positions
    /// ([`Self::shift_positions_mm`]), or every row's column `s_mm` (steady rolling on a rail
    /// slices file); `None` where every case stands at `[wheelrail] s_mm`.
    pub fn case_positions_mm(&self) -> Option<Vec<f64>> {
        self.shift_positions_mm().or_else(|| self.cases.iter().map(|r| r.s_mm).collect())
    }

    /// Each case's wheelset position along the track [mm] in a shift: the table's column `s_mm`
    /// where it has one (CONTACT's S_WS of each case), else `s_mm`, or in a sequence of
    /// shifts the position before plus the case before's shift VS × 1 s (CONTACT's dummy time
    /// step); after a steady start (`start = "steady"`) the steady case at `s_mm` and each shift
    /// at the position before plus its own shift (the wheelset moved from the steady state);
    /// `None` in rolling.
    pub fn shift_positions_mm(&self) -> Option<Vec<f64>> {
        let MotionSpec::Shift { s_ws_mm, sequence, steady_start } = self.motion else { return None };
        if let Some(given) = self.cases.iter().map(|r| r.s_mm).collect::<Option<Vec<f64>>>() {
            return Some(given);
        }
        let mut s = s_ws_mm;
        let mut out = Vec::with_capacity(self.cases.len());
        for (k, row) in self.cases.iter().enumerate() {
            if steady_start && k > 0 {
                s += row.velocity[0];
            }
            out.push(s);
            if sequence && !steady_start {
                s += row.velocity[0];
            }
        }
        Some(out)
    }

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
        let mut top = Section::new("", doc).declare(&TOP_KEYS);
        let name = top.text("name")?.to_string();
        if !is_valid_name(&name) {
            return Err(InputError::new(
                "name",
                format!("{name:?}"),
                "a scene name of a-z, 0-9, _ (a folder name, at most 100 characters)",
            ));
        }
        let allowed = TOP_KEYS.get("solvers").map(|k| k.allowed.message()).unwrap_or_default();
        let solvers = top.opt_str_list("solvers", &allowed)?.unwrap_or_else(|| vec!["contact".into()]);
        let super::wheelrail_section::WheelRailSection {
            side,
            mu,
            mu_variation,
            dx_mm,
            ds_mm,
            a_sep_rad,
            d_sep_mm,
            d_comb_mm,
            d_turn_mm,
            wheel_mesh,
            search,
            approach,
            frictionless,
            motion,
            s_ws_mm,
        } = super::wheelrail_section::read(top.table("wheelrail")?, rail_is_slices(doc))?;
        motion.check_models(&solvers)?;
        let rail = super::wheelrail_profile::rail(&mut top, dir)?;
        let wheel = super::wheelrail_profile::wheel(&mut top, dir)?;
        let radius = wheel.nominal_radius_mm;
        let material = super::material::read(&mut top)?;
        if material.visco.is_some() {
            return Err(InputError::new(
                "material.visco_ratio",
                "viscoelastic bodies in a wheel–rail scene",
                "elastic bodies: the wheel–rail scene solves elastic bodies (give viscoelastic bodies in a module-3 scene)",
            ));
        }
        if material.layer.is_some() {
            return Err(InputError::new(
                "material.layer_g_mpa",
                "an interface layer in a wheel–rail scene",
                "no layer: the wheel–rail scene solves elastic bodies that touch (give the layer in a module-3 scene)",
            ));
        }
        check_blanco(&material, approach, motion, &solvers)?;
        let context = super::wheelrail_tangential::Context {
            mu,
            mu_variation: mu_variation.as_ref(),
            heat: material.heat.is_some(),
            solvers: &solvers,
            motion,
            frictionless,
        };
        let tangential = super::wheelrail_tangential::read(&mut top, &context)?;
        let (vertical, longitudinal, cases) = super::wheelrail_cases::read(&mut top, dir, radius)?;
        if material.blanco.is_some() && vertical != VerticalSpec::Force {
            // The rounds of the vertical balance are where the two problems alternate.
            return Err(InputError::new(
                "cases.vertical",
                "\"position\"",
                "\"force\" with [material] blanco_variant (the rounds with FZ prescribed alternate the normal and tangential problems)",
            ));
        }
        super::wheelrail_cases::check_longitudinal(
            longitudinal,
            frictionless,
            mu_variation.as_ref().map_or(mu, |v| v.values.iter().copied().fold(mu, f64::max)),
            &cases,
        )?;
        if motion != MotionSpec::Rolling && (longitudinal == LongitudinalSpec::Force || frictionless) {
            return Err(InputError::new(
                "wheelrail.motion",
                format!("{motion:?}"),
                "a shift or transient rolling with the pitch's shift or velocity given ([cases] longitudinal = \"velocity\") and friction (not frictionless)",
            ));
        }
        let massless_rail = super::wheelrail_massless::read(&mut top, vertical == VerticalSpec::Position)?;
        if massless_rail.is_some() {
            check_massless(motion, longitudinal, frictionless, rail.roller.is_some())?;
        }
        let given_s = doc.get("wheelrail").and_then(|w| w.get("s_mm")).is_some();
        super::wheelrail_cases::check_positions(&cases, motion, (given_s, rail_is_slices(doc)), mu_variation.as_ref())?;
        match rail.roller {
            Some(_) => check_roller(&cases, (motion, longitudinal), (search, approach), rail_is_slices(doc))?,
            None => check_speeds(&cases)?,
        }
        let origin = super::origin::read(&mut top)?;
        check_origin(origin.as_ref(), &cases)?;
        let report = report(&mut top, dir, &cases)?;
        top.finish()?;
        let scene = WheelRailScene {
            name,
            solvers,
            side,
            rail: rail.profile,
            wheel: wheel.profile,
            placement: rail.placement,
            cant_rad: rail.cant_rad,
            roller: rail.roller,
            rail_deviation: rail.deviation,
            massless_rail,
            frictionless,
            flange_back_distance_mm: wheel.flange_back_distance_mm,
            flange_back_position_mm: wheel.flange_back_position_mm,
            nominal_radius_mm: radius,
            wheel_deviation: wheel.deviation,
            mu,
            mu_variation,
            material,
            tangential,
            dx_mm,
            ds_mm,
            a_sep_rad,
            d_sep_mm,
            d_comb_mm,
            d_turn_mm,
            wheel_mesh,
            search,
            approach,
            motion,
            s_ws_mm,
            vertical,
            longitudinal,
            cases,
            report,
            origin,
            dir: dir.to_path_buf(),
        };
        check_figures(&scene)?;
        Ok(scene)
    }
}

/// A massless rail (CONTACT's F = 3) in steady rolling with the pitch's velocity given and
/// friction, on a track: the rail's lateral spring balances the contact's lateral force.
fn check_massless(
    motion: MotionSpec,
    longitudinal: LongitudinalSpec,
    frictionless: bool,
    roller: bool,
) -> Result<(), InputError> {
    let why = if motion != MotionSpec::Rolling {
        format!("motion {motion:?}")
    } else if longitudinal != LongitudinalSpec::Velocity {
        "[cases] longitudinal = \"force\"".to_string()
    } else if frictionless {
        "frictionless = true".to_string()
    } else if roller {
        "a roller rig".to_string()
    } else {
        return Ok(());
    };
    Err(InputError::new(
        "massless_rail",
        why,
        "steady rolling (motion = \"rolling\") with friction, the pitch's velocity given ([cases] longitudinal = \"velocity\"), on a track (CONTACT's F = 3 with T = 3)",
    ))
}

/// On a track every case rolls or shifts: `vs_mm_s` other than 0 (the creepages are over it).
fn check_speeds(cases: &[CaseRow]) -> Result<(), InputError> {
    match cases.iter().find(|r| r.velocity[0] == 0.0) {
        Some(r) => Err(InputError::new(
            format!("cases, case {} column vs_mm_s", r.contact_case),
            0,
            "a rolling speed other than 0 (the creepages are over it; 0 only on a roller rig, [rail] roller_radius_mm)",
        )),
        None => Ok(()),
    }
}

/// Blanco's conformal correction (`[material] blanco_variant`) on the conformal approach's
/// curved rows (their inclinations), in steady rolling, for one material, with the exact model:
/// what the pipeline iterates (`pipeline::wheelrail_blanco`).
fn check_blanco(
    material: &super::MaterialSpec,
    approach: Approach,
    motion: MotionSpec,
    solvers: &[String],
) -> Result<(), InputError> {
    if material.blanco.is_none() {
        return Ok(());
    }
    let (field, value, allowed) = if approach != Approach::Conformal {
        (
            "wheelrail.approach",
            format!("{approach:?}"),
            "\"conformal\" with [material] blanco_variant (the rows' inclinations are the curved reference's)",
        )
    } else if motion != MotionSpec::Rolling {
        ("wheelrail.motion", format!("{motion:?}"), "\"rolling\" (steady) with [material] blanco_variant")
    } else if material.bodies.is_some() {
        ("material.g1_mpa", "two bodies".to_string(), "one material (g_mpa, poisson) with [material] blanco_variant")
    } else if solvers.iter().any(|m| m != "contact") {
        (
            "solvers",
            solvers.join(", "),
            "[\"contact\"] with [material] blanco_variant (the exact theory alone takes the corrected coefficients)",
        )
    } else {
        return Ok(());
    };
    Err(InputError::new(field, value, allowed))
}

/// A roller rig (`[rail] roller_radius_mm`) in steady rolling with the pitch's velocity given, on
/// the contact locus and the planar approach, on a profile file, the wheelset not moving forward
/// (CONTACT reads VPITCH_ROL in VS_WS's place and takes VS = 0).
fn check_roller(
    cases: &[CaseRow],
    (motion, longitudinal): (MotionSpec, LongitudinalSpec),
    (search, approach): (ContactSearch, Approach),
    slices: bool,
) -> Result<(), InputError> {
    let (field, value, allowed) = if motion != MotionSpec::Rolling {
        (
            "wheelrail.motion",
            format!("{motion:?}"),
            "\"rolling\" on a roller rig (shifts and transient rolling on a roller are not supported)",
        )
    } else if longitudinal != LongitudinalSpec::Velocity {
        (
            "cases.longitudinal",
            "\"force\"".into(),
            "\"velocity\" on a roller rig (FX_WS prescribed on a roller is not supported)",
        )
    } else if approach == Approach::Conformal || (search.is_grid() && approach != Approach::Planar) {
        (
            "wheelrail.approach",
            format!("{approach:?}, contact search {search:?}"),
            "the planar approach (\"planar\" or \"planar_surface_slip\") on the contact locus, or \"planar\" with the grid search, on a roller rig",
        )
    } else if slices {
        (
            "rail.profile",
            "a slices file".into(),
            "a profile file on a roller rig (a roller of varying profile is not supported)",
        )
    } else if let Some(r) = cases.iter().find(|r| r.velocity[0] != 0.0) {
        return Err(InputError::new(
            format!("cases, case {} column vs_mm_s", r.contact_case),
            r.velocity[0],
            "0 on a roller rig (the roller turns, the wheelset stays: [rail] roller_vpitch_rad_s)",
        ));
    } else {
        return Ok(());
    };
    Err(InputError::new(field, value, allowed))
}

/// `[origin] cases` = [first, last] are the smallest and largest `contact_case` of the table (an
/// imported scene's rows are the deck's cases it names).
/// Whether `[rail] profile` names a slices file (`.slcs`: a rail whose profile varies along the
/// track, read by `wheelrail::profile::slices`).
pub fn rail_is_slices(doc: &toml::Table) -> bool {
    doc.get("rail")
        .and_then(|r| r.get("profile"))
        .and_then(|p| p.as_str())
        .is_some_and(|p| p.to_lowercase().ends_with(".slcs"))
}

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

/// `[report]` of a wheel–rail scene: `group` (`wheelrail` or `other`), `contact_output` (a path
/// relative to the scene) and `patch_cases` (cases of the scene; default its first, middle and
/// last).
fn report(top: &mut Section, dir: &Path, cases: &[CaseRow]) -> Result<WheelRailReport, InputError> {
    let numbers: Vec<u64> = cases.iter().map(|c| c.contact_case).collect();
    let Some(t) = top.opt_table("report")? else {
        return Ok(WheelRailReport::default());
    };
    let mut t = t.declare(&REPORT_KEYS);
    let group = t.pick_or_default("group")?;
    let figures = GROUPS.iter().find(|(id, _)| *id == group).map_or(WheelRailFigures::None, |g| g.1);
    let contact_output = t.opt_text("contact_output")?.map(|p| dir.join(p));
    let field = t.field("patch_cases");
    let patch_cases = match t.opt_num_list("patch_cases")? {
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
    Ok(WheelRailReport { figures, contact_output, patch_cases })
}

/// The wheel-flat figure needs what it is drawn against: an out-of-round wheel (a `.slcw` wheel
/// slices file, turned by the cases' `pitch_rad`).
fn check_figures(s: &WheelRailScene) -> Result<(), InputError> {
    let why = match s.report.figures {
        WheelRailFigures::WheelFlat if !s.wheel.path.to_string_lossy().to_lowercase().ends_with(".slcw") => {
            "\"wheel_flat\" only on a wheel slices file ([wheel] profile a .slcw file): its figure is drawn against the distance the wheel rolled, −pitch_rad × nominal_radius_mm"
        }
        _ => return Ok(()),
    };
    let id = GROUPS.iter().find(|g| g.1 == s.report.figures).map_or("", |g| g.0);
    Err(InputError::new("report.group", format!("{id:?}"), why))
}
