//! CONTACT's variable profiles: a slices file (`.slcs`, a rail whose profile changes along the
//! track, switches and crossings; `.slcw`, a wheel whose profile changes around its
//! circumference) read as CONTACT reads it (`m_varprof.f90`: `varprof_read_file`,
//! `varprof_make_vj`, `varprof_make_2dspline`, `varprof_intpol_xunif`; user guide, "Rail
//! slices-file", "Wheel slices-file" and its specification of the file): the header, each slice's
//! position and profile file (read relative to the slices file, with the deck's options, as any
//! profile), the features that divide each slice into parts, then each slice resampled at the
//! same number of points per part (the parts' longest length over the slices in steps of at most
//! 0.5 mm, each slice's part stretched over them) and every lateral path of samples interpolated
//! along the track by CONTACT's cubic not-a-knot spline (`U_INTPOL = 1`) or its approximating
//! cubic B-spline with the samples as control points (`U_INTPOL = 2`). A cross-section at a
//! position ([`Slices::section_at`]) is the interpolated samples with CONTACT's profile spline
//! through them (no kinks, the deck's SMOOTH unweighted).
//!
//! Interruptions (a slice whose first or last features are negative: parts missing on that slice)
//! resample only the slice's present parts and make CONTACT's masked surface
//! ([`super::masked`]): a cross-section then holds the points the surface has at its position.
//!
//! Not supported (refused naming the value): surface perturbations (`PERTURB`), and interruptions
//! with the approximating spline (`U_INTPOL = 2`, the wheel-flat files).

use super::approx::Approximating;
use super::band::{first_root, Band};
use super::error::ProfileError;
use super::lines::{self, At, Line};
use super::masked::Masked;
use super::memo::Memo;
use super::notaknot::{Curve, NotAKnot};
use super::{read_profile, Profile, ProfileKind, ProfileOptions};
use std::f64::consts::PI;
use std::path::Path;
use std::sync::OnceLock;

/// The comment characters of a slices file (CONTACT's `readline`).
const COMMENT: &str = "!%\"";

/// CONTACT's largest number of slices (`MAX_NUM_SLCS`).
pub const MAX_SLICES: usize = 4999;

/// The largest step between resampled points along a part [mm] (`ds_max2d`).
pub const RESAMPLE_STEP_MM: f64 = 0.5;

/// The samples kept on each side of a lateral range by [`Slices::section_near`]: (2 − √3)^40 ≈ 1e-23.
pub const WINDOW_PAD_SAMPLES: usize = 40;

/// The smallest distance between successive slices [mm or rad] (`tiny_ds`).
const TINY_DS: f64 = 1e-3;

/// A slices file read and resampled.
#[derive(Debug, Clone)]
pub struct Slices {
    file: String,
    kind: ProfileKind,
    /// Each slice's position: u along the track [mm] for a rail, θ around the wheel [rad].
    u: Vec<f64>,
    profiles: Vec<Profile>,
    /// The resampled points, slice by slice (each slice the same number, part by part).
    y_mm: Vec<Vec<f64>>,
    z_mm: Vec<Vec<f64>>,
    spline: Along,
    /// With the interpolating spline: each lateral path's spline along the track (y paths, then z
    /// paths), so that a cross-section costs one cubic per sample (the same spline as the weights
    /// of [`Along`], evaluated directly).
    paths: Option<(Vec<Curve>, Vec<Curve>)>,
    /// With the interpolating spline: per interval between slices, the lateral splines' data and
    /// second derivatives as cubics in the position (made when first needed).
    bands: Vec<OnceLock<Band>>,
    /// The not-a-knot spline across, over the samples' indices (CONTACT's v: 1, 2, …).
    across: NotAKnot,
    lambda: f64,
    /// With interruptions: CONTACT's masked surface, which then serves every evaluation.
    masked: Option<Masked>,
    /// Results derived from the slices kept for the next case ([`Memo`]).
    memo: Memo,
}

/// The spline along the track (or around the wheel) through the slices' samples.
#[derive(Debug, Clone)]
enum Along {
    /// U_INTPOL = 1: interpolating, not-a-knot ends.
    Interpolating(NotAKnot),
    /// U_INTPOL = 2: approximating, the samples as control points.
    Approximating(Approximating),
}

impl Along {
    fn weights(&self, u: f64) -> Vec<f64> {
        match self {
            Along::Interpolating(s) => s.weights(u),
            Along::Approximating(s) => s.weights(u),
        }
    }
}

/// The header of a slices file.
struct Header {
    offset: f64,
    scale: f64,
    nslc: usize,
    nfeat: usize,
    nkink: usize,
    naccel: usize,
    approximating: bool,
}

/// Read the slices file at `path` for a `kind` profile, each slice with `opts` (the deck's
/// MIRRORY, MIRRORZ, SCALE, SMOOTH, …).
pub fn read_slices(path: &Path, kind: ProfileKind, opts: &ProfileOptions) -> Result<Slices, ProfileError> {
    let opts = opts.checked()?;
    let Layout { file, u, names, features, approximating } = read_layout(path, kind)?;
    let dir = path.parent().unwrap_or(Path::new(""));
    let mut profiles = Vec::with_capacity(u.len());
    for (i, name) in names.iter().enumerate() {
        let p = read_profile(&dir.join(name), kind, &opts).map_err(|e| e.in_slice(&file, i + 1))?;
        profiles.push(p);
    }
    let (y_mm, z_mm, active) = resample(&profiles, &features, &file)?;
    let masked = masked_surface(&u, &y_mm, &z_mm, &active, approximating, &file)?;
    let spline = if approximating {
        Approximating::new(&u).map(Along::Approximating)
    } else {
        NotAKnot::new(&u).map(Along::Interpolating)
    };
    let spline = spline.ok_or_else(|| {
        ProfileError::profile(&file, "the slices' positions", format!("{u:?}"), "at least 4 increasing positions")
    })?;
    let sites: Vec<f64> = (0..y_mm[0].len()).map(|j| j as f64).collect();
    let across = NotAKnot::new(&sites).ok_or_else(|| {
        ProfileError::profile(&file, "the samples per slice", sites.len(), "at least 4 (CONTACT's error 404)")
    })?;
    let paths = match &spline {
        Along::Interpolating(s) if masked.is_none() => Some((lateral_paths(s, &y_mm), lateral_paths(s, &z_mm))),
        _ => None,
    };
    // CONTACT fits the cross-section with λ = SMOOTH as given, unweighted, whatever ISMOOTH.
    let bands = if paths.is_some() { (1..u.len()).map(|_| OnceLock::new()).collect() } else { Vec::new() };
    Ok(Slices {
        file,
        kind,
        u,
        profiles,
        y_mm,
        z_mm,
        spline,
        paths,
        bands,
        across,
        lambda: opts.smooth,
        masked,
        memo: Memo::default(),
    })
}

/// With interruptions (a slice whose samples do not all exist), CONTACT's masked surface;
/// refused with the approximating spline and where CONTACT refuses the mask.
fn masked_surface(
    u: &[f64],
    y: &[Vec<f64>],
    z: &[Vec<f64>],
    active: &[(usize, usize)],
    approximating: bool,
    file: &str,
) -> Result<Option<Masked>, ProfileError> {
    let m = y[0].len();
    let Some(i) = active.iter().position(|&(a, b)| a > 0 || b + 1 < m) else { return Ok(None) };
    if approximating {
        let what = format!("slice {}: its features (interruptions)", i + 1);
        let allowed = "interruptions with U_INTPOL = 1 (the interpolating spline; not with the approximating one)";
        return Err(ProfileError::profile(file, what, "U_INTPOL = 2", allowed));
    }
    Masked::new(u, y, z, active).map(Some).map_err(|e| ProfileError::profile(file, e.what, e.value, e.allowed))
}

/// The spline along the track of each lateral path j of the samples `v[slice][j]`.
fn lateral_paths(s: &NotAKnot, v: &[Vec<f64>]) -> Vec<Curve> {
    (0..v[0].len()).map(|j| s.curve(&v.iter().map(|row| row[j]).collect::<Vec<_>>())).collect()
}

/// A slices file's own content: its positions, the slices' file names and features (what the
/// file says, before any slice is read).
struct Layout {
    file: String,
    u: Vec<f64>,
    names: Vec<String>,
    features: Vec<Vec<f64>>,
    approximating: bool,
}

/// Check the slices file at `path` as [`read_slices`] does, without reading its slices'
/// profiles (what an importer can refuse early: interruptions, perturbations, bad positions).
pub fn check_slices_file(path: &Path, kind: ProfileKind) -> Result<(), ProfileError> {
    read_layout(path, kind).map(|_| ())
}

/// The slices file's header, positions, kinks, accelerations and features, each checked.
fn read_layout(path: &Path, kind: ProfileKind) -> Result<Layout, ProfileError> {
    let file = path.display().to_string();
    let ext = file.rsplit_once('.').map(|(_, e)| e.to_lowercase()).unwrap_or_default();
    let wanted = match kind {
        ProfileKind::Rail => "slcs",
        ProfileKind::Wheel => "slcw",
    };
    if ext != wanted {
        let allowed = format!("a {} slices file ends in .{wanted}", kind.name());
        return Err(ProfileError::profile(&file, "the file extension", ext, allowed));
    }
    let text = crate::safety::read::read_text(path, super::read::PROFILE_LIMIT_BYTES, "slices file")
        .map_err(|e| ProfileError::Unreadable { file: file.clone(), reason: e.to_string() })?;
    let lines = lines::non_empty_lines(&text, COMMENT);
    let mut cursor = Cursor { file: &file, lines: &lines, next: 0 };
    let header = read_header(&mut cursor, kind)?;
    let mut u = Vec::with_capacity(header.nslc);
    let mut names = Vec::with_capacity(header.nslc);
    for i in 0..header.nslc {
        let (at, code) = cursor.line(&format!("slice {}: its position and profile file", i + 1))?;
        let (pos, name) = slice_line(code, at)?;
        u.push(header.scale * (header.offset + pos));
        names.push(name);
    }
    check_positions(&u, kind, &file, &lines, &cursor)?;
    for what in [("NKINK", header.nkink), ("NACCEL", header.naccel)] {
        let values = cursor.values(what.1, &format!("{}: a part number", what.0))?;
        if let Some((v, at)) = values.iter().find(|(v, _)| !(1.0..=(header.nfeat as f64 - 2.0)).contains(v)) {
            let allowed = format!("a part number 1 ..= NFEAT − 2 = {} (CONTACT's error 154)", header.nfeat - 2);
            return Err(at.value(1, what.0, &v.to_string(), &allowed));
        }
    }
    let features = read_features(&mut cursor, &header, &u)?;
    if let Some(l) = lines.get(cursor.next) {
        let at = At { file: &file, line: l.number };
        return Err(at.structure("a line after the slices' features", "nothing (perturbations are not supported)"));
    }
    Ok(Layout { file, u, names, features, approximating: header.approximating })
}

impl Slices {
    /// The slices file.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// Results derived from these slices, kept for the next case of the scene.
    pub fn memo(&self) -> &Memo {
        &self.memo
    }

    pub fn kind(&self) -> ProfileKind {
        self.kind
    }

    /// Each slice's position: u [mm] along the track (rail) or θ [rad] around the wheel.
    pub fn positions(&self) -> &[f64] {
        &self.u
    }

    /// Slice `i`'s profile as read (0-based).
    pub fn slice(&self, i: usize) -> &Profile {
        &self.profiles[i]
    }

    /// The number of resampled points per slice.
    pub fn samples(&self) -> usize {
        self.y_mm[0].len()
    }

    /// The resampled points of every slice interpolated to position `u` (held to the first and
    /// last slice's: CONTACT's constant extrapolation), (y, z) [mm]. With interruptions, those
    /// from the first to the last point the surface has at u.
    pub fn samples_at(&self, u: f64) -> (Vec<f64>, Vec<f64>) {
        if let Some(masked) = &self.masked {
            let (y, z, _) = present_samples(masked, u);
            return (y, z);
        }
        if let Some((ys, zs)) = &self.paths {
            let n = self.u.len();
            let x = u.clamp(self.u[0], self.u[n - 1]);
            let k = self.u.partition_point(|&v| v <= x).saturating_sub(1).min(n - 2);
            let t = x - self.u[k];
            let at = |c: &Vec<Curve>| c.iter().map(|c| c.value_on(k, t)).collect();
            return (at(ys), at(zs));
        }
        let w = self.spline.weights(u);
        let m = self.samples();
        let (mut y, mut z) = (vec![0.0; m], vec![0.0; m]);
        for (i, &wi) in w.iter().enumerate() {
            if wi == 0.0 {
                continue;
            }
            for j in 0..m {
                y[j] += wi * self.y_mm[i][j];
                z[j] += wi * self.z_mm[i][j];
            }
        }
        (y, z)
    }

    /// The cross-section at position `u`: the interpolated samples with CONTACT's profile spline
    /// through them (`varprof_intpol_xunif` with one position: no kinks, λ = SMOOTH unweighted;
    /// with SMOOTH > 0 its points are the smoothed samples, as CONTACT replaces them).
    pub fn section_at(&self, u: f64) -> Result<Profile, ProfileError> {
        let (y, z) = self.section_samples(u)?;
        self.section_through(u, &y, &z)
    }

    /// [`Self::section_at`] cut to the samples near the lateral range `[lo, hi]` (profile y, mm):
    /// from the first to the last sample inside it, [`WINDOW_PAD_SAMPLES`] more on each side.
    /// The interpolating spline (λ = 0) feels a sample's change less by 2 − √3 per node, so the
    /// cut spline equals the whole one to the last bits inside the range; with λ > 0, the whole.
    pub fn section_near(&self, u: f64, [lo, hi]: [f64; 2]) -> Result<Profile, ProfileError> {
        let (y, z) = self.section_samples(u)?;
        let first = y.iter().position(|&v| v >= lo && v <= hi);
        let last = y.iter().rposition(|&v| v >= lo && v <= hi);
        match (first, last) {
            (Some(a), Some(b)) if self.lambda.abs() <= 1e-10 => {
                let a = a.saturating_sub(WINDOW_PAD_SAMPLES);
                let b = (b + WINDOW_PAD_SAMPLES + 1).min(y.len());
                self.section_through(u, &y[a..b], &z[a..b])
            }
            _ => self.section_through(u, &y, &z),
        }
    }

    /// The samples of the cross-section at `u` (with interruptions, those the surface has).
    fn section_samples(&self, u: f64) -> Result<(Vec<f64>, Vec<f64>), ProfileError> {
        match &self.masked {
            Some(masked) => match present_samples(masked, u) {
                (y, z, None) => Ok((y, z)),
                (_, _, Some(j)) => {
                    let what = format!("the cross-section at u = {u}: its sample {}", j + 1);
                    let allowed = "a cross-section without missing points between its first and last";
                    Err(ProfileError::profile(&self.file, what, "missing", allowed))
                }
            },
            None => Ok(self.samples_at(u)),
        }
    }

    /// The profile spline through samples of the cross-section at `u`.
    fn section_through(&self, u: f64, y: &[f64], z: &[f64]) -> Result<Profile, ProfileError> {
        let name = format!("{} at {u}", self.file);
        Profile::section(&name, self.kind, y, z, self.lambda).ok_or_else(|| {
            ProfileError::profile(&self.file, "the interpolated cross-section", u, "distinct finite points")
        })
    }
}

impl Slices {
    /// The height of the surface at (u, y) (CONTACT's `varprof_get_z_at_xy`,
    /// `bspline_get_z_at_xy`): across the track the surface at u is the not-a-knot spline through
    /// the interpolated samples over their indices (the tensor spline's v), the first segment
    /// that reaches y (lowest v) taken; u held to the first and last slice's. `None` where the
    /// surface does not reach y at u (CONTACT's value there is its marker 999).
    pub fn surface_z_at(&self, u: f64, y: f64) -> Option<f64> {
        if !y.is_finite() || u.is_nan() {
            return None;
        }
        if let Some(masked) = &self.masked {
            return masked.z_at(u, y, |c, y| first_root((c, 1.0), y));
        }
        if let Some((k, t)) = self.band_at(u) {
            return self.band(k).z_at(t, y);
        }
        let (ys, zs) = self.samples_at(u);
        let (cy, cz) = (self.across.curve(&ys), self.across.curve(&zs));
        (0..cy.segments()).find_map(|k| first_root(cy.cubic(k), y).map(|t| cz.value_on(k, t)))
    }
}

impl Slices {
    /// The surface's (y, z) at position u and lateral parameters v (the samples' indices 0 … m − 1,
    /// CONTACT's v less one; `bspline_eval2d_prod` at (u, v)): the not-a-knot spline across
    /// through the interpolated samples, its first or last segment beyond them.
    pub fn surface_at(&self, u: f64, v: &[f64]) -> Vec<(f64, f64)> {
        let (ys, zs) = self.samples_at(u);
        let (cy, cz) = (self.across.curve(&ys), self.across.curve(&zs));
        let last = cy.segments() - 1;
        v.iter()
            .map(|&v| {
                let k = (v.floor().max(0.0) as usize).min(last);
                let t = v - k as f64;
                (cy.value_on(k, t), cz.value_on(k, t))
            })
            .collect()
    }
}

impl Slices {
    /// The interval of the slices' positions holding u (held to the first and last) and u's
    /// offset in it, where the interpolating spline's bands are kept.
    fn band_at(&self, u: f64) -> Option<(usize, f64)> {
        if self.bands.is_empty() {
            return None;
        }
        let n = self.u.len();
        let x = u.clamp(self.u[0], self.u[n - 1]);
        let k = self.u.partition_point(|&v| v <= x).saturating_sub(1).min(n - 2);
        Some((k, x - self.u[k]))
    }

    /// Band `k`, made on first use.
    fn band(&self, k: usize) -> &Band {
        self.bands[k].get_or_init(|| {
            let (ys, zs) = self.paths.as_ref().expect("bands only with paths");
            Band::new(&self.across, (ys, zs), k, self.u[k + 1] - self.u[k])
        })
    }
}

/// The samples the masked surface has at u, from its first to its last (CONTACT's
/// `varprof_intpol_xunif` trims the 999 it gives the others), and the first one missing between
/// them, if any.
fn present_samples(masked: &Masked, u: f64) -> (Vec<f64>, Vec<f64>, Option<usize>) {
    let s = masked.samples_at(u);
    let first = s.iter().position(Option::is_some).unwrap_or(0);
    let last = s.iter().rposition(Option::is_some).unwrap_or(0);
    let hole = (first..=last).find(|&j| s[j].is_none());
    let (y, z) = s[first..=last].iter().map(|p| p.unwrap_or((f64::NAN, f64::NAN))).unzip();
    (y, z, hole)
}

/// The lines of a slices file read in order.
struct Cursor<'a> {
    file: &'a str,
    lines: &'a [Line<'a>],
    next: usize,
}

impl<'a> Cursor<'a> {
    /// The next line (comment cut), or an error naming what was expected.
    fn line(&mut self, what: &str) -> Result<(At<'a>, &'a str), ProfileError> {
        let Some(l) = self.lines.get(self.next) else {
            let last = self.lines.last().map_or(0, |l| l.number);
            let at = At { file: self.file, line: last };
            return Err(at.structure(format!("the end of the file before {what}"), "the slices file's lines in order"));
        };
        self.next += 1;
        Ok((At { file: self.file, line: l.number }, lines::cut_comment_outside_quotes(l.text, COMMENT)))
    }

    /// `count` numbers from the next lines (a group of values may continue on the next line; a
    /// line never holds more than the group needs).
    fn values(&mut self, count: usize, what: &str) -> Result<Vec<(f64, At<'a>)>, ProfileError> {
        let mut out = Vec::with_capacity(count);
        while out.len() < count {
            let (at, code) = self.line(what)?;
            let v = lines::numbers(code, at, what, 1)?;
            if out.len() + v.len() > count {
                let allowed = format!("{count} numbers in the group, {} still to come", count - out.len());
                return Err(at.value(1, what, code.trim(), &allowed));
            }
            out.extend(v.into_iter().map(|x| (x, at)));
        }
        Ok(out)
    }
}

/// A whole number in `lo ..= hi` at a line's column 1.
fn whole(v: f64, at: At<'_>, what: &str, lo: usize, hi: usize, allowed: &str) -> Result<usize, ProfileError> {
    if v.fract() == 0.0 && v >= lo as f64 && v <= hi as f64 {
        Ok(v as usize)
    } else {
        Err(at.value(1, what, &v.to_string(), allowed))
    }
}

/// The four header lines: offset and scale, NSLC, NFEAT NKINK NACCEL, U_INTPOL {PERTURB}.
fn read_header(c: &mut Cursor<'_>, kind: ProfileKind) -> Result<Header, ProfileError> {
    let (pos, unit) = match kind {
        ProfileKind::Rail => ("U", "mm"),
        ProfileKind::Wheel => ("TH", "rad"),
    };
    let what = format!("{pos}_OFFSET, {pos}_SCALE");
    let (at, code) = c.line(&what)?;
    let v = lines::numbers(code, at, &what, 2)?;
    let scale_allowed = format!("a positive factor to {unit}");
    if v[1] <= 0.0 {
        return Err(at.value(1, &format!("{pos}_SCALE"), &v[1].to_string(), &scale_allowed));
    }
    let (offset, scale) = (v[0], v[1]);
    let (at, code) = c.line("NSLC")?;
    let n = lines::numbers(code, at, "NSLC", 1)?[0];
    let nslc = whole(
        n,
        at,
        "NSLC",
        4,
        MAX_SLICES,
        &format!("4 ..= {MAX_SLICES} slices (CONTACT's errors 151, 404: its surface needs at least 4)"),
    )?;
    let (at, code) = c.line("NFEAT, NKINK, NACCEL")?;
    let v = lines::numbers(code, at, "NFEAT, NKINK, NACCEL", 3)?;
    let nfeat = whole(v[0], at, "NFEAT", 0, 999, "0 ..= 999 features (CONTACT's error 151)")?;
    let (nkink, naccel) = if nfeat <= 1 {
        (0, 0)
    } else {
        let allowed = format!("0 ..= NFEAT − 2 = {} (CONTACT's error 151)", nfeat - 2);
        (whole(v[1], at, "NKINK", 0, nfeat - 2, &allowed)?, whole(v[2], at, "NACCEL", 0, nfeat - 2, &allowed)?)
    };
    let what = format!("{pos}_INTPOL");
    let (at, code) = c.line(&what)?;
    let v = lines::numbers(code, at, &what, 1)?;
    let intpol = whole(v[0], at, &what, 1, 2, "1 (interpolating spline) or 2 (approximating spline)")?;
    if let Some(&p) = v.get(1) {
        whole(p, at, "PERTURB", 0, 0, "0: no perturbation (CONTACT's perturbations 1 and 2 are not supported)")?;
    }
    Ok(Header { offset, scale, nslc, nfeat, nkink, naccel, approximating: intpol == 2 })
}

/// A slice's line: its position and its profile's file name (quoted or one word).
fn slice_line(code: &str, at: At<'_>) -> Result<(f64, String), ProfileError> {
    let pos = lines::numbers(code, at, "the slice's position", 1)?[0];
    let rest = code.trim_start();
    let rest = rest[rest.find(|c: char| c.is_whitespace() || c == ',').unwrap_or(rest.len())..]
        .trim_start_matches(|c: char| c.is_whitespace() || c == ',');
    let column = code.len() - rest.len() + 1;
    let name = match rest.chars().next() {
        Some(q @ ('\'' | '"')) => rest[1..].split_once(q).map(|(n, _)| n.to_string()),
        Some(_) => rest.split_whitespace().next().map(str::to_string),
        None => None,
    };
    match name {
        Some(n) if !n.trim().is_empty() => Ok((pos, n.trim().to_string())),
        _ => Err(at.value(column, "the slice's profile file", rest, "a file name after the position ('name' or name)")),
    }
}

/// Positions strictly increasing by more than 0.001 (error 152); a wheel's within [−1.5π, 1.5π]
/// and covering [−π, π) or inside it (error 153).
fn check_positions(
    u: &[f64],
    kind: ProfileKind,
    file: &str,
    lines: &[Line<'_>],
    c: &Cursor<'_>,
) -> Result<(), ProfileError> {
    let first = c.next - u.len();
    for (k, w) in u.windows(2).enumerate() {
        if w[1] - w[0] <= TINY_DS {
            let at = At { file, line: lines[first + k + 1].number };
            let allowed =
                format!("a position more than 0.001 beyond the previous slice's {} (CONTACT's error 152)", w[0]);
            return Err(at.value(1, "the slice's position (scaled)", &w[1].to_string(), &allowed));
        }
    }
    if kind == ProfileKind::Wheel {
        let (t0, t1) = (u[0], u[u.len() - 1]);
        let inside = t0 >= -1.5 * PI && t1 <= 1.5 * PI;
        let covers = (t0 <= -PI + 1e-4 && t1 >= PI - 1e-4) || (t0 >= -PI - 1e-4 && t1 <= PI + 1e-4);
        if !(inside && covers) {
            let allowed = "positions within [−1.5π, 1.5π] that cover [−π, π] or lie within it (CONTACT's error 153)";
            return Err(ProfileError::profile(
                file,
                "the wheel slices' θ range [rad]",
                format!("[{t0}, {t1}]"),
                allowed,
            ));
        }
    }
    Ok(())
}

/// The features S_F of each slice (NFEAT > 1), or the whole profile ([0, 1e6] mm).
fn read_features(c: &mut Cursor<'_>, h: &Header, u: &[f64]) -> Result<Vec<Vec<f64>>, ProfileError> {
    if h.nfeat <= 1 {
        return Ok(vec![vec![0.0, 1e6]; u.len()]);
    }
    let mut out = Vec::with_capacity(u.len());
    for (i, &ui) in u.iter().enumerate() {
        let what = format!("slice {}: its position and {} features S_F", i + 1, h.nfeat);
        let v = c.values(h.nfeat + 1, &what)?;
        let pos = h.scale * (h.offset + v[0].0);
        if (pos - ui).abs() >= TINY_DS {
            let allowed = format!("the slice's position {ui} (CONTACT's error 155)");
            return Err(v[0].1.value(1, "the feature line's position (scaled)", &pos.to_string(), &allowed));
        }
        let f: Vec<f64> = v[1..].iter().map(|x| x.0).collect();
        let (ib0, ib1) = present_features(&f);
        if ib1 <= ib0 {
            let allowed = "at least two features at or beyond 0 (CONTACT's error 161)";
            return Err(v[1].1.value(1, "S_F", &format!("{f:?}"), allowed));
        }
        out.push(f);
    }
    Ok(out)
}

/// The first and last feature present on a slice (`varprof_make_vj`: those from the start and
/// the end whose S_F is negative are missing).
fn present_features(f: &[f64]) -> (usize, usize) {
    let n = f.len();
    let missing = |x: &f64| *x < -1e-6;
    let ib0 = f.iter().take(n - 1).take_while(|x| missing(x)).count();
    let ib1 = n - 1 - f.iter().rev().take(n - 1).take_while(|x| missing(x)).count();
    (ib0, ib1)
}

/// Each slice resampled part by part at the same number of points (`varprof_make_vj`,
/// `varprof_make_2dspline`): the slice's present features shifted to the profile's arc length
/// (the last held to its end), each part's segments 1 + ⌊(longest length over the slices that
/// have it + 1e-6) / 0.5 mm⌋; a slice's missing parts' samples left at 0. Also each slice's
/// present samples (first, last).
#[allow(clippy::type_complexity)]
fn resample(
    profiles: &[Profile],
    features: &[Vec<f64>],
    file: &str,
) -> Result<(Vec<Vec<f64>>, Vec<Vec<f64>>, Vec<(usize, usize)>), ProfileError> {
    let nfeat = features[0].len();
    let mut shifted = Vec::with_capacity(profiles.len());
    let mut longest = vec![-1.0f64; nfeat - 1];
    for (i, (p, f)) in profiles.iter().zip(features).enumerate() {
        let (s0, s1) = p.s_range();
        let (ib0, ib1) = present_features(f);
        let mut s: Vec<f64> = f.iter().map(|x| x + s0).collect();
        s[ib1] = s[ib1].min(s1);
        if let Some(k) = (ib0 + 1..=ib1).find(|&k| s[k] - s[k - 1] <= 1e-6) {
            let allowed = "strictly increasing features within the profile (CONTACT's error 162)";
            return Err(ProfileError::profile(
                file,
                format!("slice {}: S_F {} and {} (mm along the profile)", i + 1, k, k + 1),
                format!("{}, {}", s[k - 1], s[k]),
                allowed,
            ));
        }
        for k in ib0..ib1 {
            longest[k] = longest[k].max(s[k + 1] - s[k]);
        }
        shifted.push((s, ib0, ib1));
    }
    let mut first = vec![0usize; nfeat];
    for k in 0..nfeat - 1 {
        // Fortran's int() truncates towards zero: a part no slice has gets no segment.
        let segments = 1 + ((longest[k] + 1e-6) / RESAMPLE_STEP_MM).trunc() as i64;
        first[k + 1] = first[k] + segments.max(0) as usize;
    }
    let m = first[nfeat - 1] + 1;
    let (mut ys, mut zs, mut active) = (Vec::new(), Vec::new(), Vec::new());
    for (p, (s, ib0, ib1)) in profiles.iter().zip(&shifted) {
        let (j0, j1) = (first[*ib0], first[*ib1]);
        let mut sj = vec![0.0; m];
        for k in *ib0..*ib1 {
            let (i0, i1) = (first[k], first[k + 1]);
            let len = s[k + 1] - s[k];
            for (j, v) in sj.iter_mut().enumerate().take(i1 + 1).skip(i0) {
                *v = s[k] + len * (j - i0) as f64 / (i1 - i0) as f64;
            }
        }
        let (lo, hi) = p.s_range();
        let (mut y, mut z) = (vec![0.0; m], vec![0.0; m]);
        for ((yj, zj), &s) in y.iter_mut().zip(z.iter_mut()).zip(&sj).take(j1 + 1).skip(j0) {
            if let Some(q) = p.point_at_s(s.clamp(lo, hi)) {
                (*yj, *zj) = (q.y_mm, q.z_mm);
            }
        }
        ys.push(y);
        zs.push(z);
        active.push((j0, j1));
    }
    Ok((ys, zs, active))
}

#[cfg(test)]
#[path = "slices_tests.rs"]
mod tests;
