//! `[wheelrail]` of a wheel–rail scene: the side, the friction (one μ or μ varying across the
//! rail or along the track) and the elements; its keys declared once ([`KEYS`]) for the reader
//! and docs/scene-format.md.

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::wheelrail::{Approach, ContactSearch, MotionSpec, MuBy, MuVariation, SideSpec};
use super::wheelrail_cases::LENGTH;
use crate::error::InputError;

/// Coulomb's μ range.
const MU: Range = Range::new(0.0, false, 10.0, true);
/// Largest number of friction control points (CONTACT's NVF).
const MAX_MU_POINTS: usize = 1000;
/// The temperature law's ranges per control point (`[friction]`'s `tref_c`, `dfheat`, `dtheat_c`).
const CELSIUS: Range = crate::scene::friction::CELSIUS;
const DFHEAT: Range = Range::new(-1e3, true, 1e3, true);
const DTHEAT: Range = Range::new(0.0, false, 1e5, true);
/// An element's size [mm].
const ELEMENT: Allowed = Allowed::Number(Range::new(1e-3, true, 100.0, true), "");

/// `[wheelrail]`'s keys (`<!-- keys:wheelrail -->`).
pub const KEYS: Keys = Keys {
    id: "wheelrail",
    owner: file!(),
    keys: &[
        key(
            "side",
            "–",
            Allowed::Choice(&["left", "right"], ""),
            Absent::Required,
            r#"the wheel computed (CONTACT's C = 0, 1); a left wheel is solved as the mirror image of a right one and its results mirrored back, as CONTACT does: `side = "right"`"#,
        ),
        key(
            "mu",
            "–",
            Allowed::Number(MU, ""),
            Absent::Text("required unless `mu_by` is given, refused with it"),
            r#"Coulomb's coefficient of friction on every patch: `mu = 0.3`"#,
        ),
        key(
            "mu_by",
            "–",
            Allowed::Choice(&["contact_angle", "track_s"], ""),
            Absent::Text("absent: `mu` on every patch"),
            r#"friction varying across the rail (CONTACT's V = 1: each patch takes μ at its contact angle on the wheel, the reference's roll in the wheel's frame) or along the track (V = 2: μ at the wheelset's position `s_mm`); one μ per patch as CONTACT's planar contact: `mu_by = "contact_angle"`"#,
        ),
        key(
            "mu_at",
            "rad (`contact_angle`) or mm (`track_s`)",
            Allowed::Text("[-π, π] or [-1e5, 1e5], 1 to 1000 values, strictly increasing"),
            Absent::Text("required with `mu_by`, refused without"),
            r#"the control points (CONTACT's ALPHVF, negative on the gauge face, or SVF); μ is linear between them and the end value beyond them: `mu_at = [-0.349, -0.175]`"#,
        ),
        key(
            "mu_values",
            "–",
            Allowed::Numbers { range: MU, min_len: 1, max_len: MAX_MU_POINTS, note: "one per `mu_at`" },
            Absent::Text("required with `mu_by`, refused without"),
            r#"Coulomb's μ at each control point (FSTAT): `mu_values = [0.2, 0.3]`"#,
        ),
        key(
            "tref_c_values",
            "°C",
            Allowed::Numbers { range: CELSIUS, min_len: 1, max_len: MAX_MU_POINTS, note: "one per `mu_at`" },
            Absent::Text("required with `mu_by` and `[friction] law = \"temperature\"`, refused otherwise"),
            r#"the temperature law's TREF at each control point (CONTACT's L = 6 with V = 1, 2: each parameter interpolated as μ is, `mu_values` its FREF; `[friction]` then gives only `law`): `tref_c_values = [0.0, 0.0]`"#,
        ),
        key(
            "dfheat_values",
            "–",
            Allowed::Numbers { range: DFHEAT, min_len: 1, max_len: MAX_MU_POINTS, note: "one per `mu_at`; each mu_values + dfheat > 0" },
            Absent::Text("required with `mu_by` and `[friction] law = \"temperature\"`, refused otherwise"),
            r#"the temperature law's DFHEAT at each control point: `dfheat_values = [-0.12, -0.3]`"#,
        ),
        key(
            "dtheat_c_values",
            "°C",
            Allowed::Numbers { range: DTHEAT, min_len: 1, max_len: MAX_MU_POINTS, note: "one per `mu_at`" },
            Absent::Text("required with `mu_by` and `[friction] law = \"temperature\"`, refused otherwise"),
            r#"the temperature law's DTHEAT at each control point: `dtheat_c_values = [300.0, 600.0]`"#,
        ),
        key(
            "s_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Text(
                "0; only with `mu_by = \"track_s\"`, `motion = \"shift\"` or a rail slices file (`.slcs`), not with the cases table's column `s_mm`",
            ),
            r#"the wheelset's position along the track (CONTACT's S_WS), where μ is taken, in a shift where the material-fixed grid is anchored (element centres at track x = −`s_mm` + i `dx_mm`), and on a rail whose profile varies along the track (`[rail] profile` a `.slcs` slices file) where the track's x = 0 lies on the slices (u = S_WS + x): `s_mm = 60.0`"#,
        ),
        key(
            "dx_mm",
            "mm",
            ELEMENT,
            Absent::Required,
            r#"the elements' size along the track (CONTACT's DX): `dx_mm = 0.2`"#,
        ),
        key(
            "ds_mm",
            "mm",
            ELEMENT,
            Absent::Required,
            r#"the elements' size along the rail profile's arc length (DS); the contact search's lateral mesh is 0.3 DS: `ds_mm = 0.2`"#,
        ),
        key(
            "a_sep_rad",
            "rad",
            Allowed::Number(Range::new(0.0, true, std::f64::consts::PI, true), ""),
            Absent::Num(std::f64::consts::FRAC_PI_2),
            r#"two interpenetration regions whose contact angles differ by more are always separate patches (CONTACT's A_SEP): `a_sep_rad = 1.5707963`"#,
        ),
        key(
            "d_sep_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Num(8.0),
            r#"regions closer than this are one patch (D_SEP), the cross-influence of those beyond D_COMB attenuated (CONTACT's blending approach, docs/wheelrail.md): `d_sep_mm = 8.0`"#,
        ),
        key(
            "d_comb_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), "at most `d_sep_mm`"),
            Absent::Num(4.0),
            r#"regions closer than this are combined fully (D_COMB): `d_comb_mm = 4.0`"#,
        ),
        key(
            "d_turn_mm",
            "mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Text("2 `d_sep_mm` − `d_comb_mm`"),
            r#"separate patches between D_SEP and this apart have their contact angles turned towards their weighted mean (CONTACT's D_TURN; none where it is at most `d_sep_mm`): `d_turn_mm = 12.0`"#,
        ),
        key(
            "frictionless",
            "–",
            Allowed::Bool,
            Absent::Text("`false`"),
            r#"frictionless compression (CONTACT's T = 0): only the normal problem is solved, at every height the vertical balance tries; every model's FX, FS and MN are 0 and every element in contact counts as adhering (`mu` is still required and not used): `frictionless = true`"#,
        ),
        key(
            "motion",
            "–",
            Allowed::Choice(&["rolling", "shift", "shift_sequence", "rolling_sequence"], ""),
            Absent::Choice("rolling"),
            r#"steady rolling (CONTACT's T = 3), transient rolling (`"rolling_sequence"`: the first case steady rolling, each later case one transient rolling step of `dq_rel` × `dx_mm` continuing it, CONTACT's T = 3 then T = 2 with P = 0: the grid fixed laterally in the rail's material and moving with the wheelset along the track, the tractions the case before left carried over and rolled by the step, docs/wheelrail.md "Transient rolling"; the exact theory and the UBA (FASTSIM has no memory in rolling), one material, the pitch velocity given, with friction), a sequence of shifts (`"shift_sequence"`: the first case from rest, each later case continuing the one before it, CONTACT's T = 1 with P = 0: it takes the tractions the case before left on the material-fixed grid, patches connected by overlap, split and merged as CONTACT's, docs/wheelrail.md "Shifts that continue"; the wheelset's position of each later case is the one before plus its shift `vs_mm_s` × 1 s, from `s_mm` at the first, or each case's own where the cases table has the column `s_mm`), or a shift from rest (T = 1 with P = 2, docs/wheelrail.md "Shifts"): each case is one step from zero tractions, its velocity columns the step's shifts (mm and rad, CONTACT's dummy time step of 1 s: `vs_mm_s = 0.4` shifts the wheelset 0.4 mm), the creepages printed as shifts (mm, rad), the grid fixed in the rail's material (x from −`s_mm`, s along the rail profile's own arc length; a profile file, not a closed form); the exact theory, FASTSIM and the UBA, each carrying its own tractions (docs/wheelrail.md "The simplified models in shifts and transient rolling"), one material, `[cases] longitudinal = "velocity"`: `motion = "shift"`"#,
        ),
        key(
            "dq_rel",
            "–",
            Allowed::Number(Range::new(0.0, false, 10.0, true), ""),
            Absent::Text("1; only with `motion = \"rolling_sequence\"`"),
            r#"the rolling distance of a transient step over `dx_mm` (CONTACT's DQREL: DQ = `dq_rel` × `dx_mm`): `dq_rel = 1.0`"#,
        ),
        key(
            "start",
            "–",
            Allowed::Choice(&["steady", "rest"], ""),
            Absent::Text("`\"steady\"` with `motion = \"rolling_sequence\"`, `\"rest\"` with `\"shift_sequence\"`"),
            r#"with `motion = "rolling_sequence"` or `"shift_sequence"` only, how the sequence starts: the first case steady rolling (`"steady"`, CONTACT's T = 3 before T = 2 or T = 1 with P = 0; its tractions put on the super-grid at its reference's nearest element, `shift_grid_super`; in a shift sequence the steady case at `s_mm` and each shift at the position before plus its own shift `vs_mm_s` × 1 s, as `examples_trans/t3_t1_force.inp`, or the cases table's `s_mm`) or from zero tractions (`"rest"`: a transient step, T = 2 with P = 2, or a shift, T = 1 with P = 2): `start = "rest"`"#,
        ),
        key(
            "wheel_surface",
            "–",
            Allowed::Choice(&["exact", "contact_mesh"], ""),
            Absent::Choice("exact"),
            r#"the wheel surface the undeformed distance is measured to: the profile's exact surface of revolution, or CONTACT's mesh of it (`wr_ud_planar`: profile points `ds_mm` apart in its spline's parameter (the chord length of its points, `trim_wheel_profile`) from the patch's reference, revolved into slices `dx_mm` apart, bilinear between them; up to ~DS²/(8R) off the exact surface, inside a convex wheel and outside a concave flange root); `import contact` writes the mesh, CONTACT's own surface, and every shipped scene of `scenes/wheelrail` takes it (the gate: worst 0.939 of a bound; on the exact surface the worn flange root of `iestim_site_b` carries FN up to 1.8 % less than CONTACT's): `wheel_surface = "contact_mesh"`"#,
        ),
        key(
            "approach",
            "–",
            Allowed::Choice(&["planar", "planar_surface_slip", "conformal"], ""),
            Absent::Choice("planar"),
            r#"the contact approach: planar (CONTACT's D = 2: each patch on its tangent plane, its creepages those of its reference point), planar with the rigid slip of the actual surfaces (`"planar_surface_slip"`, D = 3, docs/wheelrail.md "Rigid slip on the actual surfaces": the tangent plane's grid and gap, the rail's and the wheel's material velocities at every element's points of both surfaces, the printed creepages their least-squares part, the rest an extra rigid slip per element; steady rolling, shifts or transient rolling of one material with the exact theory) or conformal (D = 4, docs/wheelrail.md "The conformal approach": each patch on a curved reference surface midway between the rail and the wheel, rows `ds_mm` apart in its arc length, the gap turned by each row's inclination, the rigid slip of the actual surfaces, the tractions turned back to the tangent plane, regions between D_COMB and D_SEP apart its blended sub-patches; steady rolling, shifts (`motion = "shift_sequence"`) or transient rolling (`"rolling_sequence"`), one material, the exact theory alone, profile files): `approach = "conformal"`"#,
        ),
        key(
            "contact_search",
            "–",
            Allowed::Choice(&["locus", "grid", "grid_steep"], ""),
            Absent::Choice("locus"),
            r#"how the interpenetration regions are found: on the contact locus (CONTACT's D = 2: the gap along the wheel's locus over a lateral mesh of step 0.3 `ds_mm`) or by CONTACT's brute-force grid search (D = 5, `m_wr_locatecp`: `compute_round_whl`, `compute_wr_surfc`, `locate_interpen_2d`; the wheel revolved over x in ±R/8 (±0.242 R below R = 30.5 mm) in slices about 1.5 `dx_mm` apart, on a roller rig the roller revolved about its axis, a gap mesh of step 0.75 `ds_mm` across, the local minima of the gap grown to their bounding boxes; what an out-of-round wheel always takes), or that search made for steep slopes such as a guard rail's (`"grid_steep"`, D = 6, `use_steep_slopes`: the gap mesh's step 0.3 `ds_mm` across, a round wheel revolved over ±0.242 R): `contact_search = "grid"`"#,
        ),
    ],
};

/// The `[wheelrail]` table read.
pub struct WheelRailSection {
    pub side: SideSpec,
    pub mu: f64,
    pub mu_variation: Option<MuVariation>,
    pub dx_mm: f64,
    pub ds_mm: f64,
    pub a_sep_rad: f64,
    pub d_sep_mm: f64,
    pub d_comb_mm: f64,
    pub d_turn_mm: f64,
    pub wheel_mesh: bool,
    /// The contact locus or the grid search (`contact_search`, CONTACT's D = 5, 6).
    pub search: ContactSearch,
    pub approach: Approach,
    pub frictionless: bool,
    pub motion: MotionSpec,
    /// S_WS (`s_mm`, 0 if absent): the wheelset's position along the track.
    pub s_ws_mm: f64,
}

/// `[wheelrail]` (the table `w`): side, friction, elements, patch separation and the wheel's
/// surface; `varying_rail`: the rail is a slices file (`s_mm` places the wheelset on it).
pub fn read(w: Section, varying_rail: bool) -> Result<WheelRailSection, InputError> {
    let mut w = w.declare(&KEYS);
    let side = match w.pick("side")? {
        "left" => SideSpec::Left,
        _ => SideSpec::Right,
    };
    let motion = match w.pick_or_default("motion")? {
        m @ ("shift" | "shift_sequence") => MotionSpec::Shift {
            s_ws_mm: w.opt_num("s_mm")?.unwrap_or(0.0),
            sequence: m == "shift_sequence",
            steady_start: m == "shift_sequence" && w.opt_pick("start")?.unwrap_or("rest") == "steady",
        },
        "rolling_sequence" => MotionSpec::RollingSequence {
            dq_rel: w.opt_num("dq_rel")?.unwrap_or(1.0),
            from_rest: w.opt_pick("start")?.unwrap_or("steady") == "rest",
        },
        _ => MotionSpec::Rolling,
    };
    if !matches!(motion, MotionSpec::RollingSequence { .. }) {
        w.refuse("dq_rel", "no dq_rel without motion = \"rolling_sequence\"")?;
    }
    if !matches!(motion, MotionSpec::RollingSequence { .. } | MotionSpec::Shift { sequence: true, .. }) {
        w.refuse("start", "no start without motion = \"rolling_sequence\" or \"shift_sequence\"")?;
    }
    let shift_s = match motion {
        MotionSpec::Shift { s_ws_mm, .. } => Some(s_ws_mm),
        MotionSpec::Rolling | MotionSpec::RollingSequence { .. } => None,
    };
    let s_ws_mm = w.opt_num("s_mm")?.unwrap_or(0.0);
    let (mu, mu_variation) = friction(&mut w, shift_s.or(varying_rail.then_some(s_ws_mm)))?;
    let dx_mm = w.num("dx_mm")?;
    let ds_mm = w.num("ds_mm")?;
    let a_sep_rad = w.num_or_default("a_sep_rad")?;
    let d_sep_mm = w.num_or_default("d_sep_mm")?;
    let d_comb_mm = w.num_or_default("d_comb_mm")?;
    if d_comb_mm > d_sep_mm {
        return Err(InputError::new("wheelrail.d_comb_mm", d_comb_mm, format!("at most d_sep_mm = {d_sep_mm}")));
    }
    let d_turn_mm = w.opt_num("d_turn_mm")?.unwrap_or(2.0 * d_sep_mm - d_comb_mm);
    let wheel_mesh = w.pick_or_default("wheel_surface")? == "contact_mesh";
    let search = match w.pick_or_default("contact_search")? {
        "grid" => ContactSearch::Grid,
        "grid_steep" => ContactSearch::GridSteep,
        _ => ContactSearch::Locus,
    };
    let approach = match w.pick_or_default("approach")? {
        "conformal" => Approach::Conformal,
        "planar_surface_slip" => Approach::PlanarSurfaceSlip,
        _ => Approach::Planar,
    };
    let frictionless = w.opt_bool("frictionless")?.unwrap_or(false);
    w.finish()?;
    Ok(WheelRailSection {
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
    })
}

/// The temperature law's parameters per control point, besides FREF (`mu_values`).
const TEMPERATURE_VALUES: [&str; 3] = ["tref_c_values", "dfheat_values", "dtheat_c_values"];

/// `tref_c_values`, `dfheat_values`, `dtheat_c_values` (all or none), one per point of
/// `fref` (`mu_values`), with FREF + DFHEAT > 0 at each (μ at high temperatures stays positive).
fn temperature_values(w: &mut Section, fref: &[f64]) -> Result<Option<[Vec<f64>; 3]>, InputError> {
    let lists = [
        w.opt_f64_list("tref_c_values", CELSIUS, MAX_MU_POINTS)?,
        w.opt_f64_list("dfheat_values", DFHEAT, MAX_MU_POINTS)?,
        w.opt_f64_list("dtheat_c_values", DTHEAT, MAX_MU_POINTS)?,
    ];
    if lists.iter().all(Option::is_none) {
        return Ok(None);
    }
    let mut out: [Vec<f64>; 3] = Default::default();
    for ((key, list), slot) in TEMPERATURE_VALUES.into_iter().zip(lists).zip(out.iter_mut()) {
        let field = w.field(key);
        let Some(list) = list else {
            return Err(InputError::new(
                field,
                "missing",
                "all three of tref_c_values, dfheat_values, dtheat_c_values",
            ));
        };
        if list.len() != fref.len() {
            let given = format!("{} values", list.len());
            return Err(InputError::new(field, given, format!("one per point of mu_at ({})", fref.len())));
        }
        *slot = list;
    }
    if let Some(k) = (0..fref.len()).find(|&k| fref[k] + out[1][k] <= 0.0) {
        let given = format!("{} (mu_values + dfheat = {})", out[1][k], fref[k] + out[1][k]);
        let field = format!("{}[{k}]", w.field("dfheat_values"));
        return Err(InputError::new(field, given, "mu_values + dfheat > 0 at every point"));
    }
    Ok(Some(out))
}

/// `mu`, or `mu_by` with `mu_at`, `mu_values` (and `s_mm` for `mu_by = "track_s"`); `shift_s`:
/// the position `s_mm` a shift or a rail slices file has read already.
fn friction(w: &mut Section, shift_s: Option<f64>) -> Result<(f64, Option<MuVariation>), InputError> {
    let Some(by) = w.opt_pick("mu_by")? else {
        w.refuse("mu_at", "no mu_at without mu_by")?;
        w.refuse("mu_values", "no mu_values without mu_by")?;
        for key in TEMPERATURE_VALUES {
            w.refuse(key, "only with mu_by and [friction] law = \"temperature\"")?;
        }
        if shift_s.is_none() {
            w.refuse("s_mm", "no s_mm without mu_by = \"track_s\" or motion = \"shift\"")?;
        }
        return Ok((w.num("mu")?, None));
    };
    w.refuse("mu", "no mu with mu_by (mu_values give it)")?;
    let range = match by {
        "contact_angle" => Range::new(-std::f64::consts::PI, true, std::f64::consts::PI, true),
        _ => LENGTH,
    };
    let field = w.field("mu_at");
    let at = w
        .opt_f64_list("mu_at", range, MAX_MU_POINTS)?
        .ok_or_else(|| InputError::new(&field, "missing", "the control points of mu_by, increasing (rad or mm)"))?;
    let values_field = w.field("mu_values");
    let values = w
        .opt_num_list("mu_values")?
        .ok_or_else(|| InputError::new(&values_field, "missing", "mu at each point of mu_at"))?;
    if at.is_empty() || at.windows(2).any(|p| p[1] <= p[0]) {
        return Err(InputError::new(field, format!("{at:?}"), "at least one control point, strictly increasing"));
    }
    if values.len() != at.len() {
        return Err(InputError::new(
            values_field,
            format!("{} values", values.len()),
            format!("one mu per point of mu_at ({})", at.len()),
        ));
    }
    let by = match by {
        "contact_angle" => {
            if shift_s.is_none() {
                w.refuse("s_mm", "no s_mm with mu_by = \"contact_angle\" (the patch's contact angle selects mu)")?;
            }
            MuBy::ContactAngle
        }
        _ => MuBy::TrackS {
            s_mm: match shift_s {
                Some(s) => s,
                None => w.opt_num("s_mm")?.unwrap_or(0.0),
            },
        },
    };
    let temperature = temperature_values(w, &values)?;
    let v = MuVariation { by, at, values, temperature };
    let mu = match by {
        MuBy::ContactAngle => v.values[0],
        MuBy::TrackS { s_mm } => v.at(s_mm),
    };
    Ok((mu, Some(v)))
}
