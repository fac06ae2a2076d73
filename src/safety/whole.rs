//! Files written whole: the contents go to a temporary file beside the target, which is then
//! renamed over it in one step, so a reader (or a run killed midway) sees the old file or the new
//! one, never a part. (Atomic against crashes of creepbench; durability against power loss is the
//! file system's.)

use std::io::Write;
use std::path::Path;

/// Write `contents` to `path` whole (a temporary file in the same folder, then one rename), with
/// the permissions a newly created file gets (0666 less the umask), as `std::fs::write` would.
/// A symbolic link is written through: the file it names is replaced (atomically, in that
/// file's folder), the link stays ([`super::link::write_target`]); never into a protected tree
/// ([`super::guard::guard_link_target`]).
pub fn write(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    let target = super::link::write_target(path)?;
    if target != path {
        super::guard::guard_link_target(&target).map_err(std::io::Error::other)?;
    }
    let path = &target;
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let mut builder = tempfile::Builder::new();
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let mut tmp = builder.tempfile_in(dir)?;
    tmp.write_all(contents)?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}
