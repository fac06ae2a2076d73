//! The Python package (issue 34, docs/python.md): a virtual environment under target/pyenv with
//! python/requirements-test.txt installed from PyPI (made once, kept while that file is
//! unchanged), the package built as an abi3 wheel by maturin (a member of this workspace: its
//! cargo build shares target/ and reuses what `cargo test` built) and installed, then pytest on
//! python/tests (the bindings
//! against the CLI bit for bit — simulate, check and run —, the array API with one thread and
//! several, the errors, the in-process model on a scene and in suites, pandas frames, the
//! examples).
//! Every step has a timeout; a missing python3 fails with what to install.

use crate::common::root;
use creepbench::safety::process::{self, ProcessError};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// Files a step may write (wheels, the venv's packages).
const FILE_LIMIT_BYTES: u64 = 4 << 30;

/// Run a step; on failure, panic with what it printed.
fn step(what: &str, mut command: Command, timeout_s: u64) -> String {
    command.current_dir(root());
    match process::run(command, Duration::from_secs(timeout_s), FILE_LIMIT_BYTES) {
        Ok(out) => out.stdout.text(),
        Err(ProcessError::Spawn { program, source }) => {
            panic!("{what}: could not start {}: {source}", program.display())
        }
        Err(e) => {
            let printed = e.output().map(|o| format!("{}\n{}", o.stdout.text(), o.stderr.text())).unwrap_or_default();
            panic!("{what} failed: {e}\n{printed}")
        }
    }
}

/// target/pyenv with the test requirements, made (or remade) when its marker differs from them.
fn venv(target: &Path) -> PathBuf {
    let python = std::env::var_os("PYTHON").map_or_else(|| PathBuf::from("python3"), PathBuf::from);
    if Command::new(&python).arg("--version").output().is_err() {
        panic!(
            "{} not found: the Python package's tests need CPython >= 3.8 with venv and pip \
             (Debian: apt-get install python3 python3-venv; or set PYTHON to one)",
            python.display()
        );
    }
    let env = target.join("pyenv");
    let requirements = root().join("python/requirements-test.txt");
    let wanted = std::fs::read_to_string(&requirements).unwrap();
    let marker = env.join("creepbench-requirements.txt");
    if std::fs::read_to_string(&marker).ok().as_deref() != Some(wanted.as_str()) {
        let _ = std::fs::remove_dir_all(&env);
        let mut make = Command::new(&python);
        make.args(["-m", "venv"]).arg(&env);
        step("python3 -m venv target/pyenv", make, 300);
        let mut pip = Command::new(env.join("bin/python"));
        pip.args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-r"]).arg(&requirements);
        step("pip install -r python/requirements-test.txt", pip, 1200);
        std::fs::write(&marker, wanted).unwrap();
    }
    env
}

#[test]
fn the_python_package_builds_and_passes_its_tests() {
    let target = root().join("target");
    let env = venv(&target);
    let bin = env.join("bin");
    let wheels = target.join("python/wheels");
    let _ = std::fs::remove_dir_all(&wheels);
    let mut build = Command::new(bin.join("maturin"));
    build
        .args(["build", "--release", "--locked", "--quiet", "-m", "python/Cargo.toml", "-o"])
        .arg(&wheels)
        .env("PATH", format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default()));
    step("maturin build --release (the package's wheel)", build, 2400);
    let wheel = std::fs::read_dir(&wheels)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .find(|p| p.extension().is_some_and(|e| e == "whl"));
    let wheel = wheel.unwrap_or_else(|| panic!("maturin wrote no wheel into {}", wheels.display()));
    let name = wheel.file_name().unwrap().to_string_lossy().to_string();
    assert!(name.contains("-abi3-"), "{name}: not an abi3 wheel");
    let mut install = Command::new(bin.join("python"));
    install.args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "--force-reinstall", "--no-deps"]);
    install.arg(&wheel);
    step("pip install the wheel", install, 300);
    let mut pytest = Command::new(bin.join("python"));
    pytest
        .args(["-m", "pytest", "-q", "-p", "no:cacheprovider", "python/tests"])
        .env("CREEPBENCH_BIN", env!("CARGO_BIN_EXE_creepbench"))
        .env("PYTHONDONTWRITEBYTECODE", "1");
    let out = step("pytest python/tests", pytest, 900);
    let summary = out.lines().last().unwrap_or_default();
    assert!(summary.contains("passed") && !summary.contains("failed"), "pytest: {out}");
}

/// The Python floor of pyproject.toml's `requires-python`, e.g. (3, 11).
fn requires_python() -> (u32, u32) {
    let text = std::fs::read_to_string(root().join("python/pyproject.toml")).unwrap();
    let line = text.lines().find(|l| l.starts_with("requires-python")).expect("requires-python in pyproject.toml");
    let floor = line.split(">=").nth(1).expect("requires-python = \">=3.N\"").trim().trim_matches('"');
    let (major, minor) = floor.split_once('.').unwrap();
    (major.parse().unwrap(), minor.parse().unwrap())
}

#[test]
fn the_supported_pythons_are_the_ones_the_tests_run() {
    let (major, minor) = requires_python();
    let cargo = std::fs::read_to_string(root().join("python/Cargo.toml")).unwrap();
    assert!(
        cargo.contains(&format!("\"abi3-py{major}{minor}\"")),
        "python/Cargo.toml's abi3 floor differs from requires-python >= {major}.{minor}"
    );
    let python = std::env::var_os("PYTHON").map_or_else(|| PathBuf::from("python3"), PathBuf::from);
    let mut version = Command::new(python);
    version.args(["-c", "import sys; print(sys.version_info[0], sys.version_info[1])"]);
    let out = step("python3 -c sys.version_info", version, 60);
    let got: Vec<u32> = out.split_whitespace().map(|v| v.parse().unwrap()).collect();
    // The floor is the version the tests run; later ones are served by the abi3 wheel.
    assert_eq!(
        (got[0], got[1]),
        (major, minor),
        "the tests run Python {}.{} but the package's floor is {major}.{minor}: the floor would be untested",
        got[0],
        got[1]
    );
}
