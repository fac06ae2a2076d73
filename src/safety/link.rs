//! Outputs through symbolic links (issue 48 item 2): a file written whole is written where its
//! name leads — through every symbolic link of its last component to the file it names (which
//! may not exist yet) — so that a link is written through, never replaced by a regular file. The
//! guard checks that same place, so a dangling link into golden/ is refused like a direct path.

use std::io;
use std::path::{Path, PathBuf};

/// Links followed at most before a path is refused as a loop (the kernel's own limit).
const MAX_LINKS: usize = 40;

/// Where a write to `path` lands: `path` itself unless it is a symbolic link, else the path the
/// link names (a relative one against the link's folder), followed until it is no link.
pub fn write_target(path: &Path) -> io::Result<PathBuf> {
    let mut at = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&at) {
            Ok(m) if m.file_type().is_symlink() => {
                let next = std::fs::read_link(&at)?;
                let folder = at.parent().map(Path::to_path_buf).unwrap_or_default();
                at = folder.join(next);
            }
            _ => return Ok(at),
        }
    }
    Err(io::Error::other(format!("more than {MAX_LINKS} symbolic links")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    #[test]
    fn links_are_followed_to_the_file_they_name_existing_or_not() {
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path();
        std::fs::create_dir(d.join("real")).unwrap();
        symlink("real/a.xml", d.join("rel")).unwrap();
        symlink(d.join("rel"), d.join("chain")).unwrap();
        symlink(d.join("real/b.json"), d.join("abs")).unwrap();
        assert_eq!(write_target(&d.join("rel")).unwrap(), d.join("real/a.xml"));
        assert_eq!(write_target(&d.join("chain")).unwrap(), d.join("real/a.xml"));
        assert_eq!(write_target(&d.join("abs")).unwrap(), d.join("real/b.json"));
        assert_eq!(write_target(&d.join("plain")).unwrap(), d.join("plain"));
        symlink(d.join("loop"), d.join("loop")).unwrap();
        assert!(write_target(&d.join("loop")).is_err());
    }
}
