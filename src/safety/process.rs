//! Running an external program so that it can neither hang creepbench, flood its memory nor
//! outlive it: a timeout, stdin closed, its own process group killed whole when it ends, times
//! out, fails or creepbench is interrupted, and stdout/stderr kept only as a bounded tail.

use super::interrupt::{self, HandlerError, Registration};
use rustix::process::{Pid, Signal};
use std::fs::File;
use std::io::{self, Read};
use std::os::fd::OwnedFd;
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// Ten minutes: a model marches a two-million-step scene well within it, and a hung model is
/// stopped long before a CI job's own limit.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(600);
/// The end of stdout and stderr kept for error messages: a traceback's last frames.
pub const CAPTURE_LIMIT_BYTES: usize = 4 << 10;
/// After the group is killed, how long pipes still held open (by a process that left the group)
/// are read before creepbench stops waiting for their end.
const DRAIN_GRACE: Duration = Duration::from_secs(2);
/// Longest wait between two checks of the child's exit.
const TICK: Duration = Duration::from_millis(10);

/// Why an external program did not finish successfully.
#[derive(Debug, thiserror::Error)]
pub enum ProcessError {
    #[error("could not start {}: {source}", program.display())]
    Spawn {
        program: PathBuf,
        #[source]
        source: io::Error,
    },
    #[error("{} did not finish within {} s: its process group was killed", program.display(), timeout.as_secs_f64())]
    Timeout { program: PathBuf, timeout: Duration, output: Output },
    #[error("{} exited with {status}{}", program.display(), stderr_suffix(&output.stderr.text()))]
    Failed { program: PathBuf, status: ExitStatus, output: Output },
    #[error("waiting for {}: {source}", program.display())]
    Wait {
        program: PathBuf,
        #[source]
        source: io::Error,
    },
    #[error(transparent)]
    Handler(#[from] HandlerError),
}

impl ProcessError {
    /// What the program printed before it failed or was killed (none when it did not start).
    pub fn output(&self) -> Option<&Output> {
        match self {
            ProcessError::Timeout { output, .. } | ProcessError::Failed { output, .. } => Some(output),
            _ => None,
        }
    }
}

fn stderr_suffix(tail: &str) -> String {
    if tail.is_empty() {
        String::new()
    } else {
        format!("; the end of its stderr:\n{tail}")
    }
}

/// A stream's last [`CAPTURE_LIMIT_BYTES`] bytes and how many it held in all.
#[derive(Debug, Default, Clone)]
pub struct Captured {
    tail: Vec<u8>,
    total_bytes: u64,
}

impl Captured {
    fn push(&mut self, bytes: &[u8]) {
        self.total_bytes += bytes.len() as u64;
        self.tail.extend_from_slice(bytes);
        if self.tail.len() > 2 * CAPTURE_LIMIT_BYTES {
            self.tail.drain(..self.tail.len() - CAPTURE_LIMIT_BYTES);
        }
    }

    /// The last [`CAPTURE_LIMIT_BYTES`] bytes (all of them when the stream was shorter).
    pub fn tail(&self) -> &[u8] {
        &self.tail[self.tail.len().saturating_sub(CAPTURE_LIMIT_BYTES)..]
    }

    /// How many bytes the stream held in all, kept or not.
    pub fn total_bytes(&self) -> u64 {
        self.total_bytes
    }

    /// The tail as printable text: lossy UTF-8, control characters but newline and tab escaped,
    /// `…` in front when the beginning was dropped.
    pub fn text(&self) -> String {
        let tail = String::from_utf8_lossy(self.tail());
        let mut out = String::new();
        if self.total_bytes > self.tail().len() as u64 {
            out.push('…');
        }
        for c in tail.trim_end().chars() {
            match c {
                '\n' | '\t' => out.push(c),
                c if c.is_control() => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
                c => out.push(c),
            }
        }
        out
    }

    /// The tail as the text of a log file: [`Captured::text`] and a final newline, empty when
    /// nothing printable was written.
    pub fn log_text(&self) -> String {
        let text = self.text();
        if text.is_empty() {
            text
        } else {
            text + "\n"
        }
    }
}

/// What a run printed (the bounded tails of its stdout and stderr).
#[derive(Debug, Default)]
pub struct Output {
    pub stdout: Captured,
    pub stderr: Captured,
}

/// Run `command` to completion: stdin is `/dev/null`, the program leads a new process group,
/// on Linux it is killed if creepbench dies, files it writes are limited to `file_limit_bytes`
/// (RLIMIT_FSIZE), and it is killed with its whole group after `timeout`. When it ends, what is
/// left of its group is killed too. A non-zero exit is [`ProcessError::Failed`] with the end of
/// its stderr.
pub fn run(mut command: Command, timeout: Duration, file_limit_bytes: u64) -> Result<Output, ProcessError> {
    interrupt::install()?;
    let program = PathBuf::from(command.get_program());
    let parent = rustix::process::getpid();
    command.stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped()).process_group(0);
    // SAFETY: the closure runs between fork and exec and makes raw system calls only (no
    // allocation, no lock).
    unsafe {
        command.pre_exec(move || in_child(parent, file_limit_bytes));
    }
    let mut group = {
        // Spawn and register as one step: an interruption in between would orphan the child.
        let mut held = interrupt::hold();
        let mut child = command.spawn().map_err(|source| ProcessError::Spawn { program: program.clone(), source })?;
        let pid = Pid::from_child(&child);
        let pipes = [child.stdout.take().map(OwnedFd::from), child.stderr.take().map(OwnedFd::from)];
        let registration = held.register_group(pid.as_raw_nonzero().get());
        Group { child, pid, pipes: pipes.map(|p| p.map(File::from)), _registration: registration, reaped: false }
    };
    let wait_err = |source| ProcessError::Wait { program: program.clone(), source };
    let mut captured = [Captured::default(), Captured::default()];
    let deadline = Instant::now() + timeout;
    let timed_out = loop {
        if group.exited().map_err(wait_err)? {
            break false;
        }
        let now = Instant::now();
        if now >= deadline {
            break true;
        }
        group.pump(&mut captured, TICK.min(deadline - now)).map_err(wait_err)?;
    };
    group.kill();
    let drain_deadline = Instant::now() + DRAIN_GRACE;
    while group.pipes.iter().any(Option::is_some) && Instant::now() < drain_deadline {
        group.pump(&mut captured, TICK).map_err(wait_err)?;
    }
    let status = group.reap().map_err(wait_err)?;
    let [stdout, stderr] = captured;
    let output = Output { stdout, stderr };
    if timed_out {
        Err(ProcessError::Timeout { program, timeout, output })
    } else if status.success() {
        Ok(output)
    } else {
        Err(ProcessError::Failed { program, status, output })
    }
}

/// In the child, between fork and exec: die with the parent, cap the size of written files.
fn in_child(parent: Pid, file_limit_bytes: u64) -> io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        rustix::process::set_parent_process_death_signal(Some(Signal::KILL))?;
        // The parent may have died before the signal was armed.
        if rustix::process::getppid() != Some(parent) {
            return Err(rustix::io::Errno::SRCH.into());
        }
    }
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    let _ = parent;
    use rustix::process::{getrlimit, setrlimit, Resource, Rlimit};
    let old = getrlimit(Resource::Fsize);
    let soft = old.maximum.map_or(file_limit_bytes, |max| max.min(file_limit_bytes));
    setrlimit(Resource::Fsize, Rlimit { current: Some(soft), maximum: old.maximum })?;
    Ok(())
}

/// The running child with its group; dropping it kills the group and reaps the child.
struct Group {
    child: Child,
    pid: Pid,
    /// stdout and stderr, `None` once at their end.
    pipes: [Option<File>; 2],
    _registration: Registration,
    reaped: bool,
}

impl Group {
    /// Whether the child has exited, without reaping it: its pid, and so its process group id,
    /// stays reserved until the group is killed.
    fn exited(&self) -> io::Result<bool> {
        use rustix::process::{waitid, WaitId, WaitIdOptions};
        match waitid(WaitId::Pid(self.pid), WaitIdOptions::EXITED | WaitIdOptions::NOHANG | WaitIdOptions::NOWAIT) {
            Ok(status) => Ok(status.is_some()),
            Err(rustix::io::Errno::INTR) => Ok(false),
            Err(rustix::io::Errno::CHILD) => Ok(true),
            Err(e) => Err(e.into()),
        }
    }

    /// Wait up to `wait` for output and read what came; a stream at its end is closed.
    fn pump(&mut self, captured: &mut [Captured; 2], wait: Duration) -> io::Result<()> {
        use rustix::event::{poll, PollFd, PollFlags, Timespec};
        let timeout = Timespec { tv_sec: wait.as_secs() as i64, tv_nsec: wait.subsec_nanos().into() };
        let open: Vec<usize> = (0..2).filter(|&k| self.pipes[k].is_some()).collect();
        if open.is_empty() {
            std::thread::sleep(wait);
            return Ok(());
        }
        let ready: Vec<bool> = {
            let mut fds: Vec<PollFd<'_>> =
                open.iter().filter_map(|&k| self.pipes[k].as_ref()).map(|f| PollFd::new(f, PollFlags::IN)).collect();
            match poll(&mut fds, Some(&timeout)) {
                Ok(_) | Err(rustix::io::Errno::INTR) => {}
                Err(e) => return Err(e.into()),
            }
            fds.iter().map(|fd| !fd.revents().is_empty()).collect()
        };
        let mut buf = [0u8; 64 << 10];
        for (&k, ready) in open.iter().zip(ready) {
            let Some(pipe) = self.pipes[k].as_mut().filter(|_| ready) else { continue };
            match pipe.read(&mut buf) {
                Ok(0) => self.pipes[k] = None,
                Ok(n) => captured[k].push(&buf[..n]),
                Err(e) if matches!(e.kind(), io::ErrorKind::Interrupted | io::ErrorKind::WouldBlock) => {}
                Err(_) => self.pipes[k] = None,
            }
        }
        Ok(())
    }

    /// SIGKILL to every process of the group (none left is fine).
    fn kill(&self) {
        let _ = rustix::process::kill_process_group(self.pid, Signal::KILL);
    }

    /// Kill what is left of the group, then reap the child.
    fn reap(&mut self) -> io::Result<ExitStatus> {
        self.kill();
        self.reaped = true;
        self.child.wait()
    }
}

impl Drop for Group {
    fn drop(&mut self) {
        if !self.reaped {
            let _ = self.reap();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sh(script: &str) -> Command {
        let mut c = Command::new("sh");
        c.arg("-c").arg(script);
        c
    }

    #[test]
    fn output_is_captured_and_success_is_ok() {
        let out = run(sh("echo hello; echo oops >&2"), Duration::from_secs(10), 1 << 20).unwrap();
        assert_eq!(out.stdout.tail(), b"hello\n");
        assert_eq!(out.stderr.text(), "oops");
    }

    #[test]
    fn a_failure_names_the_status_and_the_end_of_stderr() {
        let e = run(sh("echo 'Traceback: boom' >&2; exit 3"), Duration::from_secs(10), 1 << 20).unwrap_err();
        let m = e.to_string();
        assert!(matches!(e, ProcessError::Failed { .. }), "{m}");
        assert!(m.contains("exit status: 3") && m.contains("Traceback: boom"), "{m}");
    }

    #[test]
    fn a_flood_of_output_keeps_only_the_tail() {
        let out = run(sh("head -c 3000000 /dev/zero; echo end"), Duration::from_secs(20), 1 << 20).unwrap();
        assert_eq!(out.stdout.total_bytes(), 3_000_004);
        assert_eq!(out.stdout.tail().len(), CAPTURE_LIMIT_BYTES);
        assert!(out.stdout.tail().ends_with(b"end\n"));
        assert!(out.stdout.text().starts_with('…'));
    }

    #[test]
    fn a_missing_program_is_named() {
        let e = run(Command::new("/nonexistent/model"), Duration::from_secs(1), 1 << 20).unwrap_err();
        assert!(matches!(e, ProcessError::Spawn { .. }) && e.to_string().contains("/nonexistent/model"), "{e}");
    }

    #[test]
    fn large_files_are_cut_by_the_file_size_limit() {
        let dir = tempfile::tempdir().unwrap();
        let script = format!("head -c 100000 /dev/zero > {}/out", dir.path().display());
        let e = run(sh(&script), Duration::from_secs(10), 1000).unwrap_err();
        assert!(matches!(e, ProcessError::Failed { .. }), "{e}");
        assert!(std::fs::metadata(dir.path().join("out")).unwrap().len() <= 1000);
    }
}
