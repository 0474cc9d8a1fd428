//! The README's Python route as a user takes it: a fresh virtual environment, the README's
//! `pip install ./python` there (maturin builds the Rust library and bundles it in the wheel),
//! then the package's pytest suite (`python/tests/`: the API, its exceptions, and the same c,
//! p and q as C programs built against the bundled library, bit for bit) and the README's
//! Python snippet, both run by the environment's interpreter.
//!
//! Needs python3 with venv and pip (Debian: python3-venv), a C compiler and the package
//! index (pip fetches maturin, cffi, numpy, pytest and matplotlib). A missing tool fails the
//! test saying what to install, unless ORTHOSLIP_SKIP_PYTHON=1.
//!
//! The wheel's cargo build shares its target directory with the packaging test's CMake build
//! (`shell::library_target_dir`): after that test, it compiles only this crate.

mod readme;
mod shell;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use orthoslip::{Contact, Material};
use shell::{command, run, run_or_explain};

const SKIP_VAR: &str = "ORTHOSLIP_SKIP_PYTHON";
/// What the tests need beyond the package and its dependencies.
const TEST_PACKAGES: [&str; 2] = ["pytest", "matplotlib"];
const NEEDS_INDEX: &str = "; pip needs the package index (or a configured mirror) to fetch \
                           maturin, cffi, numpy, pytest and matplotlib";

fn on_path(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Makes `cmd` run inside the virtual environment `venv`: its bin/ first on PATH, the wheel's
/// cargo build in `cargo_target`, no bytecode written into the checkout, and no
/// LD_LIBRARY_PATH (`cargo test` points it at another liborthoslip.so).
fn in_venv<'a>(cmd: &'a mut Command, venv: &Path, cargo_target: &Path) -> &'a mut Command {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let path =
        std::env::join_paths(std::iter::once(venv.join("bin")).chain(std::env::split_paths(&path)))
            .expect("PATH");
    cmd.env("PATH", path)
        .env("VIRTUAL_ENV", venv)
        .env("CARGO_TARGET_DIR", cargo_target)
        .env("PYTHONDONTWRITEBYTECODE", "1")
        .env("PIP_DISABLE_PIP_VERSION_CHECK", "1")
        .env_remove("PYTHONPATH")
        .env_remove("PYTHONHOME")
        .env_remove("LD_LIBRARY_PATH")
}

fn fresh_dir(dir: &Path) {
    if dir.exists() {
        std::fs::remove_dir_all(dir).unwrap();
    }
    std::fs::create_dir_all(dir).unwrap();
}

fn timed<T>(what: &str, times: &mut Vec<(String, f64)>, step: impl FnOnce() -> T) -> T {
    let start = Instant::now();
    let out = step();
    times.push((what.to_owned(), start.elapsed().as_secs_f64()));
    out
}

#[test]
fn pip_install_then_pytest_and_the_readme_snippet() {
    if shell::skipped(SKIP_VAR, "Python test") {
        return;
    }
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let missing: Vec<String> = [("python3", "python3"), (cc.as_str(), "gcc")]
        .into_iter()
        .filter(|(tool, _)| !on_path(tool))
        .map(|(tool, package)| format!("{tool} (Debian package {package})"))
        .collect();
    assert!(
        missing.is_empty(),
        "the Python test needs: {}; or set {SKIP_VAR}=1 to skip it",
        missing.join(", ")
    );
    let source = Path::new(env!("CARGO_MANIFEST_DIR"));
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("python");
    let venv = work.join("venv");
    let cargo_target = shell::library_target_dir();
    let snippets = work.join("readme");
    fresh_dir(&venv);
    fresh_dir(&snippets);
    let mut times = Vec::new();

    timed("create the virtual environment", &mut times, || {
        run_or_explain(
            command("python3").arg("-m").arg("venv").arg(&venv),
            &format!(
                "; python3 cannot create a virtual environment with pip: install python3-venv \
                 (Debian: apt-get install python3-venv) or set {SKIP_VAR}=1"
            ),
        )
    });
    let python = venv.join("bin/python");

    // The README's install line, run in the checkout as the README says.
    let install = readme::route("python-install");
    timed("pip install ./python (README)", &mut times, || {
        run_or_explain(
            in_venv(&mut install.bash(source), &venv, &cargo_target),
            NEEDS_INDEX,
        )
    });
    timed("pip install the test packages", &mut times, || {
        run_or_explain(
            in_venv(&mut command(&python), &venv, &cargo_target)
                .args(["-m", "pip", "install", "--quiet"])
                .args(TEST_PACKAGES),
            NEEDS_INDEX,
        )
    });
    // pytest from the scratch directory, so `import orthoslip` finds the installed package,
    // and without its cache (it would write into the checkout).
    timed("pytest python/tests", &mut times, || {
        run(in_venv(&mut command(&python), &venv, &cargo_target)
            .args(["-m", "pytest", "-p", "no:cacheprovider", "-ra"])
            .arg(source.join("python/tests"))
            .current_dir(&work))
    });
    let printed = timed("README Python snippet", &mut times, || {
        let snippet = readme::route("python");
        readme::printed_c(&run(in_venv(
            &mut snippet.bash(&snippets),
            &venv,
            &cargo_target,
        )))
    });

    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap();
    let mut contact = Contact::new(ply);
    contact.set_friction(0.3).unwrap();
    let c = contact.solve().unwrap().c();
    assert_eq!(
        printed.len(),
        1,
        "the README's Python snippet prints c once"
    );
    assert!(
        (printed[0] - c).abs() <= 1e-12,
        "README Python snippet: c = {} but the library gives {c}",
        printed[0]
    );
    for (what, seconds) in &times {
        println!("{what}: {seconds:.1} s");
    }
}
