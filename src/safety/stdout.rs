//! The console (standard output) as a best-effort channel (issue 48 item 1): a reader that went
//! away (`creepbench check | head -1`) or a full device (`> /dev/full`) must neither kill a
//! command midway — Rust's `println!` panics, exit 101 — nor cost it the files it writes after
//! printing (`--junit`, `--json`, `--summary`) or change its exit status, which stays the
//! verdict's. What cannot be printed is dropped: silently for a closed pipe (the reader chose to
//! stop reading, as `head` does), with one warning on standard error for any other failure.
//!
//! Standard error is best-effort too ([`errln!`]): `2> /dev/full` must not panic either.
//!
//! Data a command writes *as its output* to standard output (`import contact-output` without
//! `--out`) is no console text: it goes through [`write_data`], whose failure is an error.

use std::fmt;
use std::io::{self, Write};
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once standard output failed: later console text is dropped without another attempt.
static LOST: AtomicBool = AtomicBool::new(false);

/// Print `args` on standard output (the console): never panics, never fails the command.
pub fn print(args: fmt::Arguments) {
    if LOST.load(Ordering::Relaxed) {
        return;
    }
    if let Err(e) = write_console(&mut io::stdout().lock(), args) {
        lose(&e);
    }
}

/// Write `args` to `out` and flush, so that a failure shows here rather than at exit.
fn write_console(out: &mut impl Write, args: fmt::Arguments) -> io::Result<()> {
    out.write_fmt(args)?;
    out.flush()
}

/// Remember that standard output is gone; warn once unless a reader closed the pipe.
fn lose(e: &io::Error) {
    if !LOST.swap(true, Ordering::Relaxed) {
        if let Some(warning) = warning(e) {
            // Standard error may be gone too: nothing more can be said then.
            let _ = writeln!(io::stderr(), "{warning}");
        }
    }
}

/// The one warning about a console that could not be written (none for a closed pipe).
fn warning(e: &io::Error) -> Option<String> {
    (e.kind() != io::ErrorKind::BrokenPipe)
        .then(|| format!("warning: standard output could not be written ({e}); the console text is dropped"))
}

/// Write `bytes` to standard output as a command's data (not console text): an error if they
/// cannot all be written.
pub fn write_data(bytes: &[u8]) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(bytes)?;
    out.flush()
}

/// [`print`] with `format!` syntax: console text on standard output that never fails a command.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::safety::stdout::print(format_args!($($arg)*))
    };
}

/// [`out!`] with a newline.
macro_rules! outln {
    () => {
        $crate::safety::stdout::print(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::safety::stdout::print(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// Print `args` on standard error: never panics (a full or closed standard error drops the
/// text, as `eprintln!` would panic instead).
pub fn print_err(args: fmt::Arguments) {
    let _ = io::stderr().lock().write_fmt(args);
}

/// [`print_err`] with `format!` syntax and a newline: warnings and notes on standard error.
macro_rules! errln {
    ($($arg:tt)*) => {
        $crate::safety::stdout::print_err(format_args!("{}\n", format_args!($($arg)*)))
    };
}

pub(crate) use {errln, out, outln};

#[cfg(test)]
mod tests {
    use super::*;

    /// A writer that fails as a full device does.
    struct Full;

    impl Write for Full {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::Error::from_raw_os_error(28))
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_full_device_is_an_error_to_warn_about_and_a_closed_pipe_is_not() {
        let e = write_console(&mut Full, format_args!("PASS\n")).unwrap_err();
        let w = warning(&e).expect("a full device is worth a warning");
        assert!(w.contains("No space left on device") && w.contains("dropped"), "{w}");
        assert!(warning(&io::ErrorKind::BrokenPipe.into()).is_none());
    }

    #[test]
    fn console_text_is_written_and_flushed() {
        let mut out = Vec::new();
        write_console(&mut out, format_args!("gates: {}\n", "PASS")).unwrap();
        assert_eq!(out, b"gates: PASS\n");
    }
}
