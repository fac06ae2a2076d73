//! `[rail]` and `[wheel]` of a wheel–rail scene: each profile and how to take it (CONTACT's
//! MIRRORY, MIRRORZ, SCALE, SMOOTH and PRFOPT), the rail's place in the track and its deviation,
//! the wheelset's dimensions; every key declared once ([`PROFILE_KEYS`], [`RAIL_KEYS`],
//! [`WHEEL_KEYS`]) for the reader and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, KeySpec, Keys};
use super::reader::{Range, Section};
use super::wheelrail::{PlacementSpec, ProfileSpec, RailDeviationSpec, WheelDeviationSpec};
use super::wheelrail_cases::{ANGLE, LENGTH};
use crate::error::InputError;
use std::f64::consts::PI;
use std::path::Path;

/// A turning angle of the profile's cleaning [rad].
const TURN: Range = Range::new(0.0, true, 2.0 * PI, true);
/// A velocity of the rail's or the wheel's deviation [mm/s or rad/s].
const RAIL_SPEED: Range = Range::new(-1e7, true, 1e7, true);

/// The values of `mirror_z` and CONTACT's MIRRORZ for each.
pub const MIRROR_Z: [(&str, i8); 3] = [("keep", -1), ("detect", 0), ("mirror", 1)];

/// CONTACT's defaults of a profile's cleaning (`m_profile.f90`, `profile_init`): ZIGTHRS 150°,
/// KINKHIGH 30°, KINKLOW KINKHIGH/5, KINKWID 2 mm, MAXOMIT 0.5.
pub const PROFILE_DEFAULTS: [f64; 5] = [150.0 * PI / 180.0, 30.0 * PI / 180.0, 6.0 * PI / 180.0, 2.0, 0.5];

/// A number key of the rail's deviation (0 when absent).
const fn deviation(name: &'static str, unit: &'static str, range: Range, meaning: &'static str) -> KeySpec {
    key(name, unit, Allowed::Number(range, ""), Absent::Num(0.0), meaning)
}

/// The keys of a profile, the same in `[rail]` and `[wheel]` (`<!-- keys:wheelrail_profile -->`);
/// the cleaning's defaults are CONTACT's ([`PROFILE_DEFAULTS`]).
pub const PROFILE_KEYS: Keys = Keys {
    id: "wheelrail_profile",
    owner: file!(),
    keys: &[
        key(
            "mirror_y",
            "–",
            Allowed::Bool,
            Absent::Text("`false`"),
            r#"mirror the profile's y (CONTACT's MIRRORY = 1): `mirror_y = true`"#,
        ),
        key(
            "mirror_z",
            "–",
            Allowed::Choice(&["detect", "keep", "mirror"], ""),
            Absent::Choice("detect"),
            r#"the profile's z as read (CONTACT's MIRRORZ = 0, −1, 1): `"detect"` turns a Miniprof file or a table whose z points upwards (SIMPACK files as they are), `"keep"` never mirrors, `"mirror"` always: `mirror_z = "mirror"`"#,
        ),
        key(
            "scale",
            "–",
            Allowed::Number(Range::new(0.0, false, 1e4, true), ""),
            Absent::Num(1.0),
            r#"multiply every coordinate (CONTACT's SCALE; 1000 for a table in m): `scale = 1000.0`"#,
        ),
        key(
            "smooth",
            "– (mm with `smooth_weighted`)",
            Allowed::Number(Range::new(0.0, true, 1e10, true), ""),
            Absent::Num(0.0),
            r#"the smoothing spline's parameter (CONTACT's SMOOTH; 0: the interpolating spline): λ of the spline y(s), z(s) that minimises Σ (f_i − f(s_i))² + (2/3) λ ∫ f″² ds, or with `smooth_weighted` the filter length L_filt (λ = L_filt⁴ / (16 π⁴), fluctuations shorter than L_filt damped; docs/wheelrail.md): `smooth = 10.0`"#,
        ),
        key(
            "smooth_weighted",
            "–",
            Allowed::Bool,
            Absent::Text("`false`"),
            r#"CONTACT's ISMOOTH = 1: each point's residual weighted by its spacing (20 times at the ends), `smooth` a length in mm (ISMOOTH = 0: unit weights, `smooth` = λ): `smooth_weighted = true`"#,
        ),
        key(
            "zig_zag_rad",
            "rad",
            Allowed::Number(TURN, ""),
            Absent::Num(PROFILE_DEFAULTS[0]),
            r#"where the profile turns by more than this (150° by default) into a segment and again out of it (a zig-zag), the segment's two points are replaced by their mean (CONTACT's ZIGTHRS; at least π/4 is used; ≥ π: no check): `zig_zag_rad = 2.618`"#,
        ),
        key(
            "kink_high_rad",
            "rad",
            Allowed::Number(TURN, ""),
            Absent::Num(PROFILE_DEFAULTS[1]),
            r#"a point where the profile turns by more than this (30° by default), its neighbours within `kink_width_mm` by less than `kink_low_rad`, is a kink: the spline breaks there (CONTACT's KINKHIGH; ≥ π: no kinks): `kink_high_rad = 0.5236`"#,
        ),
        key(
            "kink_low_rad",
            "rad",
            Allowed::Number(TURN, ""),
            Absent::Num(PROFILE_DEFAULTS[2]),
            r#"the largest turn of a kink's neighbours (KINKLOW; 6° by default): `kink_low_rad = 0.1047`"#,
        ),
        key(
            "kink_width_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Num(PROFILE_DEFAULTS[3]),
            r#"the half-width of the window of a kink's neighbours (KINKWID; 0: every point turning more than `kink_high_rad` is a kink): `kink_width_mm = 2.0`"#,
        ),
        key(
            "max_omit",
            "–",
            Allowed::Number(Range::new(0.0, true, 1.0, true), ""),
            Absent::Num(PROFILE_DEFAULTS[4]),
            r#"the largest fraction of a wheel profile's points left out where it folds back (CONTACT's MAXOMIT; the rail's is not used): `max_omit = 0.5`"#,
        ),
    ],
};

/// `[rail]`'s own keys (`<!-- keys:rail -->`): its profile, place in the track and deviation.
pub const RAIL_KEYS: Keys = Keys {
    id: "rail",
    owner: file!(),
    keys: &[
        key(
            "profile",
            "–",
            Allowed::Text(
                "a path relative to the scene file: SIMPACK (`.prr`), Miniprof (`.ban`), a table of two columns y, z, or CONTACT's slices file (`.slcs`: a rail whose profile varies along the track)",
            ),
            Absent::Required,
            r#"the rail profile (CONTACT's RFNAME), given as a right rail (the track centre at −y), as CONTACT takes it for either side; a slices file (switches and crossings) is read with its slices (each with this table's options) and interpolated along the track, the wheelset standing at `[wheelrail] s_mm` on it (docs/wheelrail.md, "Rails that vary along the track"): `profile = "profiles/uic60.prr"`"#,
        ),
        key(
            "gauge_height_mm",
            "mm",
            Allowed::Number(Range::new(0.0, false, 1e3, true), ""),
            Absent::Text("absent: placed by `y_mm`, `z_mm`"),
            r#"place the rail by its gauge point (CONTACT's GAUGHT > 0): its top on the track plane, its inner face at this depth below the top at y = `gauge_width_mm`/2: `gauge_height_mm = 14.0`"#,
        ),
        key(
            "gauge_width_mm",
            "mm",
            Allowed::Number(Range::new(0.0, false, 1e5, true), ""),
            Absent::Text("required with `gauge_height_mm`"),
            r#"the track gauge between the rails' inner faces (GAUGWD): `gauge_width_mm = 1435.0`"#,
        ),
        key(
            "y_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Text("required without `gauge_height_mm`, refused with it"),
            r#"the profile's origin's lateral place in the track (absolute placement, CONTACT's GAUGHT ≤ 0 and RAILY0; typically < 0 for a left rail): `y_mm = 750.0`"#,
        ),
        key(
            "z_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Text("0; only with `y_mm`"),
            r#"the profile's origin's height in the track (RAILZ0, z downwards): `z_mm = 0.0`"#,
        ),
        key(
            "cant_rad",
            "rad",
            Allowed::Number(ANGLE, ""),
            Absent::Num(0.0),
            r#"the rail's cant, a rotation towards the track centre (CANT), applied before the placement: `cant_rad = 0.025`"#,
        ),
        key(
            "roller_radius_mm",
            "mm",
            Allowed::Number(Range::new(0.0, false, 1e5, true), "not with `gauge_height_mm`, `cant_rad`, a slices file"),
            Absent::Text("absent: a rail on a track"),
            r#"a wheel on a roller rig (CONTACT's C = 4, 5; NOMRAD_R): the rail profile is the roller's, revolved about the roller's axis, the track's y at this depth below the profile's z = 0; the wheelset does not move forward (the cases' `vs_mm_s` 0), the roller turns at `roller_vpitch_rad_s` (docs/wheelrail.md, "A wheel on a roller rig"): `roller_radius_mm = 400.0`"#,
        ),
        key(
            "roller_vpitch_rad_s",
            "rad/s",
            Allowed::Number(RAIL_SPEED, "only with `roller_radius_mm`"),
            Absent::Text("required with `roller_radius_mm`"),
            r#"the roller's angular velocity about its axis (VPITCH_ROL; positive with the wheel's negative `vpitch_rad_s` rolling the contact forward): `roller_vpitch_rad_s = 0.25`"#,
        ),
        deviation(
            "deviation_y_mm",
            "mm",
            LENGTH,
            r#"the rail's lateral shift from its design position (CONTACT's DYRAIL, track coordinates, mirrored with the wheelset on the left), after the placement: `deviation_y_mm = 0.5`"#,
        ),
        deviation(
            "deviation_z_mm",
            "mm",
            LENGTH,
            r#"its vertical shift (DZRAIL, z downwards): `deviation_z_mm = 5.0`"#,
        ),
        deviation(
            "deviation_roll_rad",
            "rad",
            ANGLE,
            r#"its roll about the rail profile's origin, added to −`cant_rad` (DROLLR; the gauge point is found on the design position): `deviation_roll_rad = 0.2618`"#,
        ),
        deviation(
            "deviation_vy_mm_s",
            "mm/s",
            RAIL_SPEED,
            r#"the lateral velocity of the rail profile's origin (VYRAIL): the rail's material velocity enters the creepages (CONTACT's `m_wr_rigslip`): `deviation_vy_mm_s = 10.0`"#,
        ),
        deviation(
            "deviation_vz_mm_s",
            "mm/s",
            RAIL_SPEED,
            r#"its vertical velocity (VZRAIL): `deviation_vz_mm_s = 0.0`"#,
        ),
        deviation(
            "deviation_vroll_rad_s",
            "rad/s",
            RAIL_SPEED,
            r#"its roll rate about the profile's origin (VROLLR): moves the rail's material at the reference and adds to the spin creepage: `deviation_vroll_rad_s = 0.01`"#,
        ),
    ],
};

/// `[wheel]`'s own keys (`<!-- keys:wheel -->`): its profile and the wheelset's dimensions.
pub const WHEEL_KEYS: Keys = Keys {
    id: "wheel",
    owner: file!(),
    keys: &[
        key(
            "profile",
            "–",
            Allowed::Text(
                "a path relative to the scene file: SIMPACK (`.prw`), Miniprof (`.whl`) or a table of two columns y, z",
            ),
            Absent::Required,
            r#"the wheel profile (CONTACT's WFNAME): `profile = "profiles/s1002.prw"`"#,
        ),
        key(
            "flange_back_distance_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Required,
            r#"the distance between the wheels' flange backs (CONTACT's FBDIST; 0 puts the profile's flange back at the wheelset's centre, as CONTACT's decks of one wheel on a rail placed absolutely; CONTACT takes a negative one too, `test-rollers2` case 7's −100 mm): `flange_back_distance_mm = 1360.0`"#,
        ),
        key(
            "flange_back_position_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Required,
            r#"the flange back's lateral place in the wheel profile (FBPOS): `flange_back_position_mm = -70.0`"#,
        ),
        key(
            "nominal_radius_mm",
            "mm",
            Allowed::Number(Range::new(1.0, true, 1e5, true), ""),
            Absent::Required,
            r#"the wheel's nominal rolling radius, at the profile's origin (NOMRAD): `nominal_radius_mm = 460.0`"#,
        ),
        deviation(
            "deviation_x_mm",
            "mm",
            LENGTH,
            r#"the wheel profile origin's shift along the wheelset's x from its design place (CONTACT's DXWHL, E = 4, 5: a flexible wheelset; wheelset coordinates): `deviation_x_mm = 0.5`"#,
        ),
        deviation(
            "deviation_y_mm",
            "mm",
            LENGTH,
            r#"its lateral shift along the wheelset's y (DYWHL; as CONTACT, towards the wheelset's centre on the left wheel and to the field side on the right): `deviation_y_mm = 1.0`"#,
        ),
        deviation("deviation_z_mm", "mm", LENGTH, r#"its vertical shift (DZWHL, z downwards): `deviation_z_mm = 0.1`"#),
        deviation(
            "deviation_roll_rad",
            "rad",
            ANGLE,
            r#"the wheel's roll about the profile origin (DROLLW, right-hand about the wheelset's x, before the yaw): its own axle then NOMRAD above the origin, turned: `deviation_roll_rad = 0.0873`"#,
        ),
        deviation(
            "deviation_yaw_rad",
            "rad",
            ANGLE,
            r#"the wheel's yaw about the profile origin (DYAWW, after the roll): `deviation_yaw_rad = 0.002`"#,
        ),
        deviation(
            "deviation_pitch_rad",
            "rad",
            ANGLE,
            r#"the wheel's pitch (DPITCHW): carried and exported; it does not move a round wheel's surface (CONTACT leaves it out of the placement): `deviation_pitch_rad = 0.0`"#,
        ),
        deviation(
            "deviation_vx_mm_s",
            "mm/s",
            RAIL_SPEED,
            r#"the velocity of the wheel profile's origin relative to the wheelset along its x (VXWHL): the wheel's material velocity enters the creepages (`m_wr_rigslip`): `deviation_vx_mm_s = 20.0`"#,
        ),
        deviation(
            "deviation_vy_mm_s",
            "mm/s",
            RAIL_SPEED,
            r#"along its y (VYWHL, as `deviation_y_mm`): `deviation_vy_mm_s = 10.0`"#,
        ),
        deviation("deviation_vz_mm_s", "mm/s", RAIL_SPEED, r#"along its z (VZWHL): `deviation_vz_mm_s = 5.0`"#),
        deviation(
            "deviation_vroll_rad_s",
            "rad/s",
            RAIL_SPEED,
            r#"the wheel's roll rate on the wheelset about the profile origin (VROLLW, about the wheelset's x): moves the wheel's material and adds to the spin creepage: `deviation_vroll_rad_s = 0.1`"#,
        ),
        deviation(
            "deviation_vyaw_rad_s",
            "rad/s",
            RAIL_SPEED,
            r#"its yaw rate (VYAWW, about the wheelset's z): `deviation_vyaw_rad_s = 0.05`"#,
        ),
        deviation(
            "deviation_vpitch_rad_s",
            "rad/s",
            RAIL_SPEED,
            r#"its pitch rate (VPITCHW, about the wheelset's y, added to VPITCH about the profile origin; the rolling speed VELOC takes the wheelset's VPITCH alone, as CONTACT's): `deviation_vpitch_rad_s = -0.01`"#,
        ),
    ],
};

/// A profile's keys: `profile` (a path relative to the scene's folder `dir`) and the keys of
/// [`PROFILE_KEYS`].
fn profile(s: &mut Section, dir: &Path) -> Result<ProfileSpec, InputError> {
    let path = dir.join(s.text("profile")?);
    let mirror_z = s.pick_or_default("mirror_z")?;
    Ok(ProfileSpec {
        path,
        mirror_y: s.opt_bool("mirror_y")?.unwrap_or(false),
        mirror_z: MIRROR_Z.iter().find(|(name, _)| *name == mirror_z).map_or(0, |m| m.1),
        scale: s.num_or_default("scale")?,
        smooth: s.num_or_default("smooth")?,
        smooth_weighted: s.opt_bool("smooth_weighted")?.unwrap_or(false),
        zig_zag_rad: s.num_or_default("zig_zag_rad")?,
        kink_high_rad: s.num_or_default("kink_high_rad")?,
        kink_low_rad: s.num_or_default("kink_low_rad")?,
        kink_width_mm: s.num_or_default("kink_width_mm")?,
        max_omit: s.num_or_default("max_omit")?,
    })
}

/// `[rail]`'s deviation from its design position and its velocity (each 0 when absent).
fn rail_deviation(r: &mut Section) -> Result<RailDeviationSpec, InputError> {
    Ok(RailDeviationSpec {
        position: [
            r.num_or_default("deviation_y_mm")?,
            r.num_or_default("deviation_z_mm")?,
            r.num_or_default("deviation_roll_rad")?,
        ],
        velocity: [
            r.num_or_default("deviation_vy_mm_s")?,
            r.num_or_default("deviation_vz_mm_s")?,
            r.num_or_default("deviation_vroll_rad_s")?,
        ],
    })
}

/// The rail read from `[rail]`: its profile, placement, cant and deviation.
pub struct RailSection {
    pub profile: ProfileSpec,
    /// A roller rig's roller (`roller_radius_mm`, `roller_vpitch_rad_s`), if the rail is one.
    pub roller: Option<RollerSpec>,
    pub placement: PlacementSpec,
    pub cant_rad: f64,
    pub deviation: RailDeviationSpec,
}

/// `[rail]`: its profile, its placement (gauge point or absolute), the cant and the deviation.
pub fn rail(top: &mut Section, dir: &Path) -> Result<RailSection, InputError> {
    let mut r = top.table("rail")?.declare(&RAIL_KEYS).declare(&PROFILE_KEYS);
    let profile = profile(&mut r, dir)?;
    let placement = match r.opt_num("gauge_height_mm")? {
        Some(height_mm) => {
            r.refuse("y_mm", "no y_mm with gauge_height_mm (the gauge point places the rail)")?;
            PlacementSpec::Gauge { height_mm, width_mm: r.num("gauge_width_mm")? }
        }
        None => PlacementSpec::Absolute { y_mm: r.num("y_mm")?, z_mm: r.opt_num("z_mm")?.unwrap_or(0.0) },
    };
    let cant_rad = r.num_or_default("cant_rad")?;
    let deviation = rail_deviation(&mut r)?;
    let roller = roller(&mut r, &placement, cant_rad)?;
    r.finish()?;
    Ok(RailSection { profile, roller, placement, cant_rad, deviation })
}

/// A roller rig's roller: NOMRAD_R [mm] and VPITCH_ROL [rad/s] (CONTACT's C = 4, 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerSpec {
    pub radius_mm: f64,
    pub vpitch_rad_s: f64,
}

/// `roller_radius_mm` with `roller_vpitch_rad_s`, the rail placed absolutely and without cant (a
/// roller rig has neither gauge point nor cant, CONTACT's `trackdata_input`).
fn roller(r: &mut Section, placement: &PlacementSpec, cant_rad: f64) -> Result<Option<RollerSpec>, InputError> {
    let Some(radius_mm) = r.opt_num("roller_radius_mm")? else {
        r.refuse("roller_vpitch_rad_s", "no roller_vpitch_rad_s without roller_radius_mm (a rail on a track)")?;
        return Ok(None);
    };
    let why = if matches!(placement, PlacementSpec::Gauge { .. }) {
        "the rail placed by y_mm, z_mm (a roller rig has no gauge point)"
    } else if cant_rad != 0.0 {
        "cant_rad = 0 (a roller rig has no cant; tilt the roller by deviation_roll_rad)"
    } else {
        return Ok(Some(RollerSpec { radius_mm, vpitch_rad_s: r.num("roller_vpitch_rad_s")? }));
    };
    Err(InputError::new(r.field("roller_radius_mm"), radius_mm, format!("a roller only with {why}")))
}

/// The wheel read from `[wheel]`: its profile, the wheelset's FBDIST, FBPOS, NOMRAD and the
/// wheel's deviation.
pub struct WheelSection {
    pub profile: ProfileSpec,
    pub flange_back_distance_mm: f64,
    pub flange_back_position_mm: f64,
    pub nominal_radius_mm: f64,
    pub deviation: WheelDeviationSpec,
}

/// `[wheel]`'s deviation from its design place and its rate (each 0 when absent).
fn wheel_deviation(w: &mut Section) -> Result<WheelDeviationSpec, InputError> {
    Ok(WheelDeviationSpec {
        position: [
            w.num_or_default("deviation_x_mm")?,
            w.num_or_default("deviation_y_mm")?,
            w.num_or_default("deviation_z_mm")?,
            w.num_or_default("deviation_roll_rad")?,
            w.num_or_default("deviation_yaw_rad")?,
            w.num_or_default("deviation_pitch_rad")?,
        ],
        velocity: [
            w.num_or_default("deviation_vx_mm_s")?,
            w.num_or_default("deviation_vy_mm_s")?,
            w.num_or_default("deviation_vz_mm_s")?,
            w.num_or_default("deviation_vroll_rad_s")?,
            w.num_or_default("deviation_vyaw_rad_s")?,
            w.num_or_default("deviation_vpitch_rad_s")?,
        ],
    })
}

/// `[wheel]`: its profile, the wheelset's dimensions and the wheel's deviation.
pub fn wheel(top: &mut Section, dir: &Path) -> Result<WheelSection, InputError> {
    let mut w = top.table("wheel")?.declare(&WHEEL_KEYS).declare(&PROFILE_KEYS);
    let profile = profile(&mut w, dir)?;
    let flange_back_distance_mm = w.num("flange_back_distance_mm")?;
    let flange_back_position_mm = w.num("flange_back_position_mm")?;
    let nominal_radius_mm = w.num("nominal_radius_mm")?;
    let deviation = wheel_deviation(&mut w)?;
    w.finish()?;
    Ok(WheelSection { profile, flange_back_distance_mm, flange_back_position_mm, nominal_radius_mm, deviation })
}
