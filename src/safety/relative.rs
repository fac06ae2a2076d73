//! A path from one folder to a file, relative, for a file that names another (a scene its
//! profiles, a CONTACT deck its profiles): both resolved as the guard resolves them (symbolic
//! links followed, `.` and `..` applied, a folder that does not exist yet taken lexically).

use super::guard::{resolve, GuardError};
use std::path::{Component, Path, PathBuf};

/// The path from folder `from` (existing or not) to `to`: `..` for each of `from`'s components
/// below their common ancestor, then the rest of `to`. An empty path is the working folder.
pub fn relative(from: &Path, to: &Path) -> Result<PathBuf, GuardError> {
    let here = |p: &Path| if p.as_os_str().is_empty() { PathBuf::from(".") } else { p.to_path_buf() };
    Ok(between(&resolve(&here(from))?, &resolve(&here(to))?))
}

/// The relative path between two absolute, normal paths.
fn between(from: &Path, to: &Path) -> PathBuf {
    let (a, b): (Vec<Component>, Vec<Component>) = (from.components().collect(), to.components().collect());
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut out: PathBuf = std::iter::repeat_n(Component::ParentDir, a.len() - common).collect();
    out.extend(&b[common..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_relative_path_climbs_to_the_common_folder() {
        let rel = |a: &str, b: &str| between(Path::new(a), Path::new(b)).display().to_string();
        assert_eq!(rel("/w/out", "/w/ref/ex/r.prr"), "../ref/ex/r.prr");
        assert_eq!(rel("/w/ref/ex", "/w/ref/ex/r.prr"), "r.prr");
        assert_eq!(rel("/a/b/c", "/x/r.prr"), "../../../x/r.prr");
    }

    #[test]
    fn a_folder_not_made_yet_and_links_are_resolved() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        std::fs::create_dir_all(root.join("deck/profiles")).unwrap();
        std::fs::write(root.join("deck/profiles/r.prr"), "x").unwrap();
        std::os::unix::fs::symlink(root.join("deck"), root.join("link")).unwrap();
        let to = root.join("link/profiles/r.prr");
        assert_eq!(relative(&root.join("out/new/../new2"), &to).unwrap(), PathBuf::from("../../deck/profiles/r.prr"));
        assert_eq!(relative(&root.join("deck"), &to).unwrap(), PathBuf::from("profiles/r.prr"));
    }
}
