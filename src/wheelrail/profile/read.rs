//! Reading a profile file (CONTACT's `profile_read_file`, `profile_get_filetype`,
//! `profile_read_slice` in `m_varprof.f90`): the format from the extension (`prr`, `prw`:
//! SIMPACK; `ban`, `whl`: Miniprof; `slcs`, `slcw`: CONTACT's variable profiles, read by
//! [`super::slices`], not as one profile;
//! anything else: a plain table), the file read with the project's bounded reader (a directory, a
//! FIFO or a device is refused without blocking), then the format's reader and CONTACT's
//! finishing ([`super::Profile`]).

use super::error::ProfileError;
use super::{miniprof, simpack, Profile, ProfileKind, ProfileOptions};
use std::path::Path;

/// The largest profile file read: a measured profile is a few thousand lines.
pub const PROFILE_LIMIT_BYTES: u64 = 4 << 20;

/// A profile file's format, from its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Simpack,
    Miniprof,
    Plain,
}

/// The format of `name` and the kind its extension implies (CONTACT's `profile_get_filetype`: the
/// text after the last `.` of the whole name, lower case, compared by its first letters).
pub fn format_of(name: &str) -> Result<(Format, Option<ProfileKind>), ProfileError> {
    let ext = name.rsplit_once('.').map(|(_, e)| e.to_lowercase()).unwrap_or_else(|| name.to_lowercase());
    let starts = |p: &str| ext.starts_with(p);
    if starts("slcs") || starts("slcw") {
        return Err(ProfileError::profile(
            name,
            "the file extension",
            ext,
            "prr, prw (SIMPACK), ban, whl (Miniprof) or a plain y z table: a slices file (slcs, slcw: CONTACT's variable profiles) is read by `profile::slices` and the contact on it is not supported yet",
        ));
    }
    Ok(if starts("prr") {
        (Format::Simpack, Some(ProfileKind::Rail))
    } else if starts("prw") {
        (Format::Simpack, Some(ProfileKind::Wheel))
    } else if starts("ban") {
        (Format::Miniprof, Some(ProfileKind::Rail))
    } else if starts("whl") {
        (Format::Miniprof, Some(ProfileKind::Wheel))
    } else {
        (Format::Plain, None)
    })
}

/// The extensions a kind's files may have, for messages.
fn extensions(kind: ProfileKind) -> &'static str {
    match kind {
        ProfileKind::Rail => "prr (SIMPACK) or ban (Miniprof) for a rail, or a plain table of another extension",
        ProfileKind::Wheel => "prw (SIMPACK) or whl (Miniprof) for a wheel, or a plain table of another extension",
    }
}

/// Read the profile at `path` as a `kind` profile with the input's options `opts`.
pub fn read_profile(path: &Path, kind: ProfileKind, opts: &ProfileOptions) -> Result<Profile, ProfileError> {
    let opts = opts.checked()?;
    let file = path.display().to_string();
    let (format, implied) = format_of(&file)?;
    if implied.is_some_and(|k| k != kind) {
        let ext = file.rsplit_once('.').map(|(_, e)| e).unwrap_or_default();
        return Err(ProfileError::profile(
            &file,
            "the file extension",
            ext,
            format!("{} (CONTACT's error 301)", extensions(kind)),
        ));
    }
    let text = crate::safety::read::read_text(path, PROFILE_LIMIT_BYTES, "profile file")
        .map_err(|e| ProfileError::Unreadable { file: file.clone(), reason: e.to_string() })?;
    if text.trim().is_empty() {
        return Err(ProfileError::profile(&file, "the file", "empty", "a profile's points"));
    }
    let (pts, cleaning) = match format {
        Format::Simpack => simpack::read(&text, &file, kind, &opts)?,
        Format::Miniprof | Format::Plain => miniprof::read(&text, &file, kind, &opts)?,
    };
    Profile::finish(&file, kind, pts, &opts, cleaning)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lines of profile-like garbage never make a reader panic: each file is a profile or an error.
    #[test]
    fn no_input_makes_the_readers_panic() {
        let tokens = [
            "header.begin",
            "header.end",
            "spline.begin",
            "spline.end",
            "point.begin",
            "point.end",
            "type = 0",
            "type = 1",
            "units.len.f = 0",
            "units.len.f = 1e-300",
            "mirror.y = 1",
            "inversion = 1",
            "bound.y.min = 5",
            "bound.y.max = -5",
            "ColumnDef=X",
            "ColumnDef=Y,X,K",
            "XOffset=1e308",
            "1 2",
            "0 0",
            "1e300 1e300",
            "-1 3 4 5",
            "nan 1",
            "2,3",
            "\"3 4",
            "% c",
            "",
            "  ",
            "x",
            "=",
            "1 2 note",
            "0.00001 0",
            "5 -3",
            "-5 -3",
            "=1",
            "'",
        ];
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        for _ in 0..3000 {
            let n = (next() % 40) as usize;
            let text: String =
                (0..n).map(|_| format!("{}\n", tokens[(next() % tokens.len() as u64) as usize])).collect();
            for kind in [ProfileKind::Rail, ProfileKind::Wheel] {
                let opts = ProfileOptions { mirror_z: (next() % 3) as i32 - 1, ..Default::default() };
                let results = [simpack::read(&text, "f.prr", kind, &opts), miniprof::read(&text, "f.txt", kind, &opts)];
                for (pts, cleaning) in results.into_iter().flatten() {
                    let _ =
                        Profile::finish("f", kind, pts, &opts, cleaning).map(|p| (p.z_at(0.0), p.uni_valued_range()));
                }
            }
        }
    }

    #[test]
    fn the_format_comes_from_the_extension_as_contact_takes_it() {
        assert_eq!(format_of("a/b/UIC60.PRR").unwrap(), (Format::Simpack, Some(ProfileKind::Rail)));
        assert_eq!(format_of("x.whl").unwrap(), (Format::Miniprof, Some(ProfileKind::Wheel)));
        assert_eq!(format_of("x.txt").unwrap(), (Format::Plain, None));
        assert_eq!(format_of("dir.d/rail").unwrap(), (Format::Plain, None));
        assert!(format_of("x.slcs").unwrap_err().to_string().contains("not supported"));
    }

    #[test]
    fn a_wheel_file_read_as_a_rail_is_refused() {
        let e =
            read_profile(Path::new("/nonexistent/w.prw"), ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(e.to_string().contains("301"), "{e}");
    }

    #[test]
    fn directories_fifos_devices_and_empty_files_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let e = read_profile(dir.path(), ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(matches!(&e, ProfileError::Unreadable { reason, .. } if reason.contains("directory")), "{e}");
        let fifo = dir.path().join("pipe.txt");
        rustix::fs::mknodat(
            rustix::fs::CWD,
            &fifo,
            rustix::fs::FileType::Fifo,
            rustix::fs::Mode::RUSR | rustix::fs::Mode::WUSR,
            0,
        )
        .unwrap();
        let e = read_profile(&fifo, ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(e.to_string().contains("FIFO"), "{e}");
        let e = read_profile(Path::new("/dev/null"), ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(e.to_string().contains("character device"), "{e}");
        let empty = dir.path().join("e.txt");
        std::fs::write(&empty, "  \n").unwrap();
        let e = read_profile(&empty, ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(e.to_string().contains("empty"), "{e}");
    }
}
