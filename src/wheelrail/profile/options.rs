//! The options CONTACT reads with a profile's file name (user guide, "Inputs regarding wheel and
//! rail profiles" and the module-1 input lines `'RFNAME' MIRRORY SCALEYZ SMOOTH {MIRRORZ}
//! {PRFOPT}`, `ISMOOTH ZIGTHRS KINKHIGH KINKLOW KINKWID`, `ERRHND MAXOMIT`; `m_profile.f90`:
//! `profile_init`, `profile_setopt`, `profile_read_config`), with CONTACT's defaults.

use super::error::ProfileError;
use std::f64::consts::PI;

/// How a profile's file is to be taken (CONTACT's defaults by [`Default`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileOptions {
    /// MIRRORY: −1 or 0 as is, 1 mirror y (a left-side profile). For SIMPACK files CONTACT adds it
    /// to the file's `mirror.y` and mirrors when the sum is 1.
    pub mirror_y: i32,
    /// MIRRORZ: 0 detect (Miniprof and plain tables; SIMPACK files are taken as they are), −1 as
    /// is, 1 mirror z. For SIMPACK files added to the file's `mirror.z` as MIRRORY.
    pub mirror_z: i32,
    /// SCALEYZ: every coordinate multiplied by it (1000 for a table in m).
    pub scale: f64,
    /// SMOOTH: λ of the unweighted smoothing spline (ISMOOTH = 0) or L_filt [mm] of the weighted
    /// one (ISMOOTH = 1); 0 for the interpolating spline.
    pub smooth: f64,
    /// ISMOOTH: 0 unweighted, 1 weighted smoothing spline; 2 (CONTACT's B-spline) is not supported.
    pub ismooth: u8,
    /// ZIGTHRS [rad]: turn above which two successive turns make a zig-zag (at least π/4, as
    /// CONTACT raises it; ≥ π disables the check).
    pub zig_thrs_rad: f64,
    /// KINKHIGH [rad]: turn above which an isolated point is a kink (≥ π: no kinks).
    pub kink_high_rad: f64,
    /// KINKLOW [rad]: largest turn of a kink's neighbours.
    pub kink_low_rad: f64,
    /// KINKWID [mm]: half-width of the window of a kink's neighbours.
    pub kink_wid_mm: f64,
    /// MAXOMIT: largest fraction of a wheel profile's points CONTACT may leave out where the
    /// wheel folds back (used by [`super::Profile::uni_valued_range`]).
    pub max_omit: f64,
}

impl Default for ProfileOptions {
    fn default() -> Self {
        ProfileOptions {
            mirror_y: 0,
            mirror_z: 0,
            scale: 1.0,
            smooth: 0.0,
            ismooth: 0,
            zig_thrs_rad: 150.0 * PI / 180.0,
            kink_high_rad: 30.0 * PI / 180.0,
            kink_low_rad: 30.0 * PI / 180.0 / 5.0,
            kink_wid_mm: 2.0,
            max_omit: 0.5,
        }
    }
}

/// CONTACT replaces a SCALEYZ at or below this by 1 (`profile_setopt`); refused here instead.
pub const SCALE_MIN: f64 = 5e-4;

impl ProfileOptions {
    /// The options checked: MIRRORY and MIRRORZ in −1..=1, SCALEYZ finite and above
    /// [`SCALE_MIN`], SMOOTH finite and ≥ 0, ISMOOTH 0 or 1, the angles and KINKWID finite and
    /// ≥ 0, MAXOMIT in [0, 1]. Returns them as CONTACT uses them: ZIGTHRS raised to π/4.
    pub fn checked(&self) -> Result<ProfileOptions, ProfileError> {
        for (field, v) in [("mirror_y", self.mirror_y), ("mirror_z", self.mirror_z)] {
            if !(-1..=1).contains(&v) {
                return Err(ProfileError::option(field, v, "-1 (as is), 0 (as is; MIRRORZ: detect) or 1 (mirror)"));
            }
        }
        if !(self.scale.is_finite() && self.scale > SCALE_MIN) {
            return Err(ProfileError::option(
                "scale",
                crate::error::number(self.scale),
                format!("a finite factor above {SCALE_MIN} (CONTACT would silently use 1 instead)"),
            ));
        }
        if !(self.smooth.is_finite() && self.smooth >= 0.0) {
            return Err(ProfileError::option("smooth", crate::error::number(self.smooth), "a finite value ≥ 0"));
        }
        if self.ismooth > 1 {
            return Err(ProfileError::option(
                "ismooth",
                self.ismooth,
                "0 (unweighted smoothing spline) or 1 (weighted); CONTACT's 2 (weighted B-spline, 3rd-order penalty) is not supported",
            ));
        }
        let angles = [
            ("zig_thrs_rad", self.zig_thrs_rad),
            ("kink_high_rad", self.kink_high_rad),
            ("kink_low_rad", self.kink_low_rad),
            ("kink_wid_mm", self.kink_wid_mm),
        ];
        for (field, v) in angles {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ProfileError::option(field, crate::error::number(v), "a finite value ≥ 0"));
            }
        }
        if !(self.max_omit.is_finite() && (0.0..=1.0).contains(&self.max_omit)) {
            return Err(ProfileError::option("max_omit", crate::error::number(self.max_omit), "a fraction in [0, 1]"));
        }
        Ok(ProfileOptions { zig_thrs_rad: self.zig_thrs_rad.max(PI / 4.0), ..self.clone() })
    }

    /// The smoothing parameter λ CONTACT passes to its spline and whether the data are weighted
    /// by their spacing: ISMOOTH = 0: λ = SMOOTH, unweighted; 1: λ = L_filt⁴ / (16 π⁴), weighted.
    pub fn lambda(&self) -> (f64, bool) {
        match self.ismooth {
            0 => (self.smooth, false),
            _ => (self.smooth.powi(4) / (16.0 * PI.powi(4)), true),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contact_defaults_are_the_default() {
        let o = ProfileOptions::default();
        // The user guide's 2.618, 0.5236, 0.1047 rad: 150°, 30°, 6°.
        let shown = |v: f64| format!("{v:.4}");
        assert_eq!(
            [shown(o.zig_thrs_rad), shown(o.kink_high_rad), shown(o.kink_low_rad)],
            ["2.6180", "0.5236", "0.1047"]
        );
        assert!(o.kink_wid_mm == 2.0 && o.max_omit == 0.5);
        assert_eq!(o.checked().unwrap(), o);
    }

    #[test]
    fn options_outside_contact_s_range_are_refused_naming_the_field() {
        let bad = |o: ProfileOptions, field: &str| {
            let e = o.checked().unwrap_err();
            assert!(matches!(&e, ProfileError::Option { field: f, .. } if f == field), "{e}");
        };
        bad(ProfileOptions { scale: 0.0, ..Default::default() }, "scale");
        bad(ProfileOptions { scale: f64::NAN, ..Default::default() }, "scale");
        bad(ProfileOptions { mirror_y: 2, ..Default::default() }, "mirror_y");
        bad(ProfileOptions { ismooth: 2, ..Default::default() }, "ismooth");
        bad(ProfileOptions { smooth: -1.0, ..Default::default() }, "smooth");
        bad(ProfileOptions { max_omit: 1.5, ..Default::default() }, "max_omit");
        let raised = ProfileOptions { zig_thrs_rad: 0.1, ..Default::default() }.checked().unwrap();
        assert_eq!(raised.zig_thrs_rad, PI / 4.0);
    }
}
