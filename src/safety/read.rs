//! Reading an input file: regular files only (a FIFO or a device never blocks or streams
//! forever), at most a size limit, text only, and errors that name the file but never quote it.

use std::fs::{File, Metadata};
use std::io::{self, Read};
use std::path::{Path, PathBuf};

/// A scene is a page of TOML: a mebibyte is hundreds of pages.
pub const SCENE_LIMIT_BYTES: u64 = 1 << 20;
/// A creepage table of two million rows (the step limit) at up to 128 bytes a row.
pub const TABLE_LIMIT_BYTES: u64 = 256 << 20;
/// A model's history of two million rows (the step limit) at up to 256 bytes a row (ten numbers).
pub const MODEL_OUTPUT_LIMIT_BYTES: u64 = 512 << 20;
/// Reference cases are published tables of thousands of rows, not histories of millions.
pub const REFERENCE_LIMIT_BYTES: u64 = 64 << 20;
/// Golden histories are creepbench's own histories: the same bound as a model's.
pub const GOLDEN_LIMIT_BYTES: u64 = MODEL_OUTPUT_LIMIT_BYTES;

/// Why a file could not be read. `what` says which input it was ("scene file", "table file"…).
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("cannot read {what} {}: {source}", path.display())]
    Io {
        what: String,
        path: PathBuf,
        #[source]
        source: io::Error,
    },
    #[error("{what} {} is a {kind}, not a regular file", path.display())]
    NotRegular { what: String, path: PathBuf, kind: FileKind },
    #[error("{what} {} is larger than the limit of {limit_bytes} bytes for a {what}", path.display())]
    TooLarge { what: String, path: PathBuf, limit_bytes: u64 },
    #[error("{what} {} is not UTF-8 text (invalid byte at offset {offset_bytes})", path.display())]
    NotUtf8 { what: String, path: PathBuf, offset_bytes: u64 },
    #[error("{what} {} is not a text file (NUL byte at offset {offset_bytes})", path.display())]
    Binary { what: String, path: PathBuf, offset_bytes: u64 },
}

/// What a path names, when it is not a regular file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    Directory,
    Fifo,
    CharacterDevice,
    BlockDevice,
    Socket,
    SymbolicLink,
    Other,
}

impl std::fmt::Display for FileKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FileKind::Directory => "directory",
            FileKind::Fifo => "FIFO (named pipe)",
            FileKind::CharacterDevice => "character device",
            FileKind::BlockDevice => "block device",
            FileKind::Socket => "socket",
            FileKind::SymbolicLink => "symbolic link",
            FileKind::Other => "special file",
        })
    }
}

impl FileKind {
    /// The kind of a non-regular file, from its metadata.
    pub fn of(meta: &Metadata) -> FileKind {
        let t = meta.file_type();
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if t.is_fifo() {
                return FileKind::Fifo;
            }
            if t.is_char_device() {
                return FileKind::CharacterDevice;
            }
            if t.is_block_device() {
                return FileKind::BlockDevice;
            }
            if t.is_socket() {
                return FileKind::Socket;
            }
        }
        if t.is_dir() {
            FileKind::Directory
        } else if t.is_symlink() {
            FileKind::SymbolicLink
        } else {
            FileKind::Other
        }
    }
}

/// Open `path` for reading if it is a regular file (following symbolic links), without ever
/// blocking: the type is checked before opening, the open is non-blocking, and the opened file
/// is checked again (it may have been swapped in between). Returns the file and its size.
pub fn open_regular(path: &Path, what: &str) -> Result<(File, u64), ReadError> {
    let io_err = |source| ReadError::Io { what: what.into(), path: path.into(), source };
    let not_regular =
        |meta: &Metadata| ReadError::NotRegular { what: what.into(), path: path.into(), kind: FileKind::of(meta) };
    let meta = std::fs::metadata(path).map_err(io_err)?;
    if !meta.is_file() {
        return Err(not_regular(&meta));
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags((rustix::fs::OFlags::NONBLOCK | rustix::fs::OFlags::NOCTTY).bits() as i32);
    }
    let file = options.open(path).map_err(io_err)?;
    let meta = file.metadata().map_err(io_err)?;
    if !meta.is_file() {
        return Err(not_regular(&meta));
    }
    Ok((file, meta.len()))
}

/// The bytes of the regular file `path`, refused past `limit_bytes` (at most `limit_bytes + 1`
/// bytes are ever read: files such as those of /proc report no size).
pub fn read_bytes(path: &Path, limit_bytes: u64, what: &str) -> Result<Vec<u8>, ReadError> {
    let too_large = || ReadError::TooLarge { what: what.into(), path: path.into(), limit_bytes };
    let (file, size_bytes) = open_regular(path, what)?;
    if size_bytes > limit_bytes {
        return Err(too_large());
    }
    let mut bytes = Vec::with_capacity(size_bytes as usize);
    file.take(limit_bytes.saturating_add(1)).read_to_end(&mut bytes).map_err(|source| ReadError::Io {
        what: what.into(),
        path: path.into(),
        source,
    })?;
    if bytes.len() as u64 > limit_bytes {
        return Err(too_large());
    }
    Ok(bytes)
}

/// The text of the regular file `path`: at most `limit_bytes`, UTF-8, no NUL byte (binary files
/// such as /proc/self/environ are refused without a word of their contents).
pub fn read_text(path: &Path, limit_bytes: u64, what: &str) -> Result<String, ReadError> {
    let bytes = read_bytes(path, limit_bytes, what)?;
    if let Some(offset) = bytes.iter().position(|&b| b == 0) {
        return Err(ReadError::Binary { what: what.into(), path: path.into(), offset_bytes: offset as u64 });
    }
    String::from_utf8(bytes).map_err(|e| ReadError::NotUtf8 {
        what: what.into(),
        path: path.into(),
        offset_bytes: e.utf8_error().valid_up_to() as u64,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fifo(path: &Path) {
        use rustix::fs::{mknodat, FileType, Mode, CWD};
        mknodat(CWD, path, FileType::Fifo, Mode::RUSR | Mode::WUSR, 0).unwrap();
    }

    #[test]
    fn a_small_text_file_is_read() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("s.toml");
        std::fs::write(&p, "name = \"x\"\n").unwrap();
        assert_eq!(read_text(&p, 100, "scene file").unwrap(), "name = \"x\"\n");
        assert_eq!(read_text(&p, 11, "scene file").unwrap().len(), 11);
    }

    #[test]
    fn a_fifo_is_refused_without_blocking() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("pipe.toml");
        fifo(&p);
        let e = read_text(&p, 100, "scene file").unwrap_err();
        assert!(matches!(e, ReadError::NotRegular { kind: FileKind::Fifo, .. }), "{e}");
        assert!(e.to_string().contains("pipe.toml") && e.to_string().contains("scene file"), "{e}");
    }

    #[test]
    fn devices_and_directories_are_refused() {
        let e = read_text(Path::new("/dev/zero"), 100, "scene file").unwrap_err();
        assert!(matches!(e, ReadError::NotRegular { kind: FileKind::CharacterDevice, .. }), "{e}");
        let dir = tempfile::tempdir().unwrap();
        let e = read_text(dir.path(), 100, "table file").unwrap_err();
        assert!(matches!(e, ReadError::NotRegular { kind: FileKind::Directory, .. }), "{e}");
    }

    #[test]
    fn one_byte_over_the_limit_is_refused_naming_path_limit_and_kind() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("big.csv");
        std::fs::write(&p, "0123456789a").unwrap();
        let e = read_text(&p, 10, "table file").unwrap_err();
        let m = e.to_string();
        assert!(matches!(e, ReadError::TooLarge { limit_bytes: 10, .. }), "{m}");
        assert!(m.contains("big.csv") && m.contains("10 bytes") && m.contains("table file"), "{m}");
        // The whole contents: the random temporary folder's name may hold a shorter piece.
        assert!(!m.contains("0123456789a"), "{m}");
    }

    #[test]
    fn files_without_a_size_are_cut_at_the_limit() {
        // /proc files report size 0: the limit holds on what is read.
        let e = read_bytes(Path::new("/proc/self/maps"), 16, "table file").unwrap_err();
        assert!(matches!(e, ReadError::TooLarge { .. }), "{e}");
    }

    #[test]
    fn binary_and_invalid_utf8_are_refused_without_their_contents() {
        let e = read_text(Path::new("/proc/self/environ"), 1 << 20, "table file").unwrap_err();
        assert!(matches!(e, ReadError::Binary { .. }), "{e}");
        assert!(!e.to_string().contains("PATH"), "{e}");
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("latin1.csv");
        std::fs::write(&p, b"t_s,cx\n0,caf\xe9\n").unwrap();
        let e = read_text(&p, 1 << 20, "table file").unwrap_err();
        assert!(matches!(e, ReadError::NotUtf8 { offset_bytes: 12, .. }), "{e}");
        // "0,caf" (a comma): the random temporary folder's name may hold "caf" itself.
        assert!(!e.to_string().contains("0,caf"), "{e}");
    }

    #[test]
    fn a_missing_file_is_named() {
        let e = read_text(Path::new("/nonexistent/s.toml"), 10, "scene file").unwrap_err();
        assert!(e.to_string().contains("/nonexistent/s.toml"), "{e}");
    }
}
