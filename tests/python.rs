//! The Python package (`python/`): its pytest suite (`python/tests/`: the API, its exceptions,
//! and the same c, p and q as C programs built against the package's library, bit for bit)
//! and the README's Python snippet, in two tiers.
//!
//! - Fast tier, [`package_against_the_built_library`]: the package as the wheel lays it out,
//!   assembled in a scratch directory from `python/orthoslip/` and the shared library this
//!   `cargo test` has already built: no wheel and no second build of the library. The
//!   `_native` module is made the way maturin makes it for `bindings = "cffi"`: cbindgen's
//!   header of `src/ffi/` with the settings maturin enforces for cffi (no includes, include
//!   guard or C++ guards), cffi's ABI-mode declarations of it (`ffi.py`), and a loader that
//!   opens the library copied beside them; next to the package, the distribution's metadata
//!   (its version is Cargo.toml's, as maturin makes it). A virtual environment holding the
//!   package's dependencies and its `test` extra from `python/pyproject.toml` (kept between
//!   runs and made afresh when they change) runs the suite and the snippet with that
//!   directory on PYTHONPATH. matplotlib is not installed there: the one plotting test that needs it is
//!   skipped, and the test fails if any other is.
//! - Slow tier (`--ignored`), [`pip_install_then_pytest_and_the_readme_snippet`]: the
//!   README's route as a user takes it: a fresh virtual environment, the README's
//!   `pip install ./python` (maturin builds the Rust library and bundles it in the wheel), the
//!   `test` and `plot` extras, then the whole suite (none skipped) and the snippet.
//!
//! Both need python3 with venv and pip (Debian: python3-venv), a C compiler and the package
//! index (pip fetches cffi, numpy and pytest; the slow tier also maturin and matplotlib). A
//! missing tool fails the test saying what to install, unless ORTHOSLIP_SKIP_PYTHON=1.
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
const NEEDS_INDEX: &str = "; pip needs the package index (or a configured mirror) to fetch \
                           the packages named above";
/// Where the virtual environment of the fast tier records the packages installed into it.
const VENV_RECORD: &str = "orthoslip-test-packages.txt";

fn on_path(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Whether the test is skipped (ORTHOSLIP_SKIP_PYTHON); otherwise asserts that the tools it
/// needs are on PATH.
fn skipped_or_tools_checked() -> bool {
    if shell::skipped(SKIP_VAR, "Python test") {
        return true;
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
    false
}

fn source_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The requirements `python/pyproject.toml` lists on its one line `key = ["...", ...]`
/// (`dependencies`, or an extra: `test`, `plot`).
fn pyproject_list(key: &str) -> Vec<String> {
    let path = source_dir().join("python/pyproject.toml");
    let text = std::fs::read_to_string(&path).expect("python/pyproject.toml");
    let prefix = format!("{key} = [");
    let lines: Vec<&str> = text
        .lines()
        .filter_map(|l| l.strip_prefix(&prefix)?.strip_suffix(']'))
        .collect();
    let [line] = lines[..] else {
        panic!("python/pyproject.toml: expected one line `{prefix}\"...\"]`, found {lines:?}");
    };
    let list: Vec<String> = line
        .split(',')
        .map(|item| item.trim().trim_matches('"').to_owned())
        .filter(|item| !item.is_empty())
        .collect();
    assert!(!list.is_empty(), "python/pyproject.toml: `{key}` is empty");
    list
}

/// Makes `cmd` run inside the virtual environment `venv`: its bin/ first on PATH, no
/// bytecode written into the checkout, no PYTHONPATH or PYTHONHOME from outside, and no
/// LD_LIBRARY_PATH (`cargo test` points it at target/<profile>/deps).
fn in_venv<'a>(cmd: &'a mut Command, venv: &Path) -> &'a mut Command {
    let path = std::env::var_os("PATH").unwrap_or_default();
    let path =
        std::env::join_paths(std::iter::once(venv.join("bin")).chain(std::env::split_paths(&path)))
            .expect("PATH");
    cmd.env("PATH", path)
        .env("VIRTUAL_ENV", venv)
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

/// Seconds per step, printed at the end of a test.
#[derive(Default)]
struct Times(Vec<(String, f64)>);

impl Times {
    fn step<T>(&mut self, what: &str, step: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let out = step();
        self.0
            .push((what.to_owned(), start.elapsed().as_secs_f64()));
        out
    }

    fn print(&self) {
        for (what, seconds) in &self.0 {
            println!("{what}: {seconds:.1} s");
        }
    }
}

/// Makes a fresh virtual environment at `venv`; returns its interpreter.
fn create_venv(venv: &Path, times: &mut Times) -> PathBuf {
    fresh_dir(venv);
    times.step("create the virtual environment", || {
        run_or_explain(
            command("python3").arg("-m").arg("venv").arg(venv),
            &format!(
                "; python3 cannot create a virtual environment with pip: install python3-venv \
                 (Debian: apt-get install python3-venv) or set {SKIP_VAR}=1"
            ),
        )
    });
    venv.join("bin/python")
}

fn pip_install(python: &Path, venv: &Path, packages: &[String], times: &mut Times) {
    times.step(&format!("pip install {}", packages.join(" ")), || {
        run_or_explain(
            in_venv(&mut command(python), venv)
                .args(["-m", "pip", "install", "--quiet"])
                .args(packages),
            NEEDS_INDEX,
        )
    });
}

/// The virtual environment at `venv` with `packages` installed, kept between runs: reused if
/// it records exactly these packages and its interpreter finds each of them, made afresh
/// otherwise. Returns its interpreter.
fn kept_venv(venv: &Path, packages: &[String], times: &mut Times) -> PathBuf {
    let python = venv.join("bin/python");
    let record = venv.join(VENV_RECORD);
    let wanted = packages.join("\n");
    let names: Vec<&str> = packages
        .iter()
        .map(|p| {
            p.split(|ch: char| !(ch.is_ascii_alphanumeric() || "-_.".contains(ch)))
                .next()
                .unwrap_or_default()
        })
        .collect();
    let intact = times.step("check the kept virtual environment", || {
        std::fs::read_to_string(&record).is_ok_and(|r| r == wanted)
            && in_venv(&mut command(&python), venv)
                .args([
                    "-c",
                    "import importlib.metadata as m, sys\nfor n in sys.argv[1:]: m.distribution(n)",
                ])
                .args(&names)
                .output()
                .is_ok_and(|o| o.status.success())
    });
    if intact {
        println!(
            "virtual environment {} kept from an earlier run",
            venv.display()
        );
        return python;
    }
    let python = create_venv(venv, times);
    pip_install(&python, venv, packages, times);
    std::fs::write(&record, wanted).unwrap();
    python
}

/// pytest's closing counts ("87 passed, 1 skipped in 5.6s") as (count, outcome) pairs.
fn pytest_counts(output: &str) -> Vec<(u32, String)> {
    let summary = output
        .lines()
        .rev()
        .find(|l| l.starts_with('=') && l.contains(" in "))
        .unwrap_or_else(|| panic!("no closing summary line in pytest's output"));
    let (counts, _) = summary
        .trim_matches(|ch: char| ch == '=' || ch.is_whitespace())
        .rsplit_once(" in ")
        .unwrap();
    counts
        .split(", ")
        .map(|item| {
            let (n, outcome) = item
                .split_once(' ')
                .unwrap_or_else(|| panic!("pytest summary {summary:?}"));
            (n.parse().unwrap(), outcome.to_owned())
        })
        .collect()
}

/// How many tests pytest skipped, from its closing counts.
fn skipped(counts: &[(u32, String)]) -> u32 {
    counts
        .iter()
        .filter(|(_, outcome)| outcome == "skipped")
        .map(|(n, _)| n)
        .sum()
}

/// Runs the package's pytest suite with `cmd` (an interpreter set up by [`in_venv`]) from
/// `work`, without its cache (it would write into the checkout); returns its output (with
/// the reasons of skips, `-ra`) and its closing counts.
fn pytest(cmd: &mut Command, work: &Path) -> (String, Vec<(u32, String)>) {
    let out = run(cmd
        .args(["-m", "pytest", "-p", "no:cacheprovider", "-ra"])
        .arg(source_dir().join("python/tests"))
        .current_dir(work));
    let counts = pytest_counts(&out);
    assert!(
        counts.iter().any(|(n, o)| *n > 0 && o == "passed"),
        "pytest passed nothing: {counts:?}"
    );
    (out, counts)
}

/// The README's Python snippet printed (`output`) the c of the default scene that the Rust
/// library computes.
fn assert_readme_snippet_prints_c(output: &str) {
    let printed = readme::printed_c(output);
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
}

/// target/<profile>/, from this test binary at target/<profile>/deps/python-<hash>.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("path of the test binary");
    let deps = exe.parent().expect("deps directory");
    deps.parent().expect("profile directory").to_path_buf()
}

/// The shared library this `cargo test` built: the newer liborthoslip.so of
/// target/<profile>/deps/ and target/<profile>/ (a `cargo test` leaves it in deps/; an older
/// `cargo build` may have left a stale copy in the other).
fn built_shared_library() -> PathBuf {
    let profile = profile_dir();
    [profile.join("deps"), profile]
        .iter()
        .map(|dir| dir.join("liborthoslip.so"))
        .filter_map(|p| Some((p.metadata().ok()?.modified().ok()?, p)))
        .max()
        .map(|(_, p)| p)
        .expect("liborthoslip.so in target/<profile>/deps or target/<profile>")
}

/// Copies the files of directory `from` into `to` (created), recursively, without
/// `__pycache__`.
fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let (path, name) = (entry.path(), entry.file_name());
        if path.is_dir() {
            if name != "__pycache__" {
                copy_tree(&path, &to.join(&name));
            }
        } else {
            std::fs::copy(&path, to.join(&name))
                .unwrap_or_else(|e| panic!("copy {}: {e}", path.display()));
        }
    }
}

/// The C header of src/ffi/ as maturin feeds it to cffi: cbindgen with cbindgen.toml and the
/// settings maturin enforces, since cffi's parser takes no preprocessor lines (C, no
/// includes, no include guard or `#pragma once`, no `extern "C"` guards, no defines).
fn cffi_header() -> String {
    let root = source_dir();
    let mut config =
        cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    config.language = cbindgen::Language::C;
    config.no_includes = true;
    config.sys_includes = Vec::new();
    config.defines = Default::default();
    config.include_guard = None;
    config.pragma_once = false;
    config.cpp_compat = false;
    let mut header = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen failed on src/ffi")
        .write(&mut header);
    String::from_utf8(header).expect("header is UTF-8")
}

/// cffi's out-of-line ABI-mode module `ffi` of the declarations in `header`, as maturin makes
/// `_native/ffi.py`: written to `destination` by `python` (which has cffi).
const MAKE_FFI_PY: &str = "\
import sys
import cffi
from cffi import recompiler

header, destination = sys.argv[1:]
ffi = cffi.FFI()
with open(header) as f:
    ffi.cdef(f.read())
recompiler.make_py_source(ffi, 'ffi', destination)
";

/// `_native/__init__.py`: opens the library next to it with the declarations of `ffi.py`
/// (what maturin writes for a cffi module, with the library's file name).
const NATIVE_INIT: &str = "\
__all__ = [\"lib\", \"ffi\"]

import os
from .ffi import ffi

lib = ffi.dlopen(os.path.join(os.path.dirname(__file__), 'lib_native.so'))
del os
";

/// Lays the package out in `site` as the wheel does (see the module's documentation), with
/// the library this `cargo test` built, using `python` (with cffi) for the declarations, and
/// the distribution's metadata (name, version, requirements).
fn assemble_package(site: &Path, python: &Path, venv: &Path) {
    let source = source_dir().join("python/orthoslip");
    assert!(
        !source.join("_native").exists(),
        "python/orthoslip/_native exists in the checkout (left by `maturin develop`?): remove \
         it, the build makes the package's native module"
    );
    fresh_dir(site);
    let package = site.join("orthoslip");
    copy_tree(&source, &package);
    let native = package.join("_native");
    std::fs::create_dir_all(&native).unwrap();
    let header = site.join("orthoslip_cffi.h");
    std::fs::write(&header, cffi_header()).unwrap();
    run(in_venv(&mut command(python), venv)
        .args(["-c", MAKE_FFI_PY])
        .arg(&header)
        .arg(native.join("ffi.py")));
    std::fs::write(native.join("__init__.py"), NATIVE_INIT).unwrap();
    let library = built_shared_library();
    println!("library: {}", library.display());
    std::fs::copy(&library, native.join("lib_native.so")).unwrap();
    // The distribution's metadata, whose version maturin takes from Cargo.toml.
    let version = env!("CARGO_PKG_VERSION");
    let dist_info = site.join(format!("orthoslip-{version}.dist-info"));
    std::fs::create_dir_all(&dist_info).unwrap();
    let mut metadata = format!("Metadata-Version: 2.1\nName: orthoslip\nVersion: {version}\n");
    for requirement in pyproject_list("dependencies") {
        metadata.push_str(&format!("Requires-Dist: {requirement}\n"));
    }
    std::fs::write(dist_info.join("METADATA"), metadata).unwrap();
}

#[test]
fn package_against_the_built_library() {
    if skipped_or_tools_checked() {
        return;
    }
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("python/built-library");
    let venv = work.join("venv");
    let site = work.join("site");
    let snippets = work.join("readme");
    let mut times = Times::default();

    let mut packages = pyproject_list("dependencies");
    packages.extend(pyproject_list("test"));
    let python = kept_venv(&venv, &packages, &mut times);
    times.step("lay the package out with the built library", || {
        assemble_package(&site, &python, &venv)
    });
    let (output, counts) = times.step("pytest python/tests", || {
        pytest(
            in_venv(&mut command(&python), &venv).env("PYTHONPATH", &site),
            &work,
        )
    });
    // Only the plotting test may skip, for want of matplotlib (the slow tier has it).
    let plot_skip = output.lines().any(|l| {
        l.starts_with("SKIPPED [1] ") && l.contains("test_plot.py") && l.contains("matplotlib")
    });
    assert!(
        plot_skip && skipped(&counts) == 1,
        "pytest: {counts:?}; all must pass but the plotting test, skipped without matplotlib"
    );
    let output = times.step("README Python snippet", || {
        fresh_dir(&snippets);
        run(in_venv(&mut readme::route("python").bash(&snippets), &venv).env("PYTHONPATH", &site))
    });
    assert_readme_snippet_prints_c(&output);
    times.print();
}

#[test]
#[ignore = "slow tier: the README's pip install ./python (maturin builds the wheel) in a fresh \
            virtual environment, the whole pytest suite with matplotlib"]
fn pip_install_then_pytest_and_the_readme_snippet() {
    if skipped_or_tools_checked() {
        return;
    }
    let source = source_dir();
    let work = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("python/wheel");
    let venv = work.join("venv");
    let snippets = work.join("readme");
    let cargo_target = shell::library_target_dir();
    let mut times = Times::default();

    let python = create_venv(&venv, &mut times);
    // The README's install line, run in the checkout as the README says, with the wheel's
    // cargo build in the shared target directory.
    let install = readme::route("python-install");
    times.step("pip install ./python (README)", || {
        run_or_explain(
            in_venv(&mut install.bash(source), &venv).env("CARGO_TARGET_DIR", &cargo_target),
            NEEDS_INDEX,
        )
    });
    let mut extras = pyproject_list("test");
    extras.extend(pyproject_list("plot"));
    pip_install(&python, &venv, &extras, &mut times);
    // pytest from the scratch directory, so `import orthoslip` finds the installed package.
    let (_, counts) = times.step("pytest python/tests", || {
        pytest(in_venv(&mut command(&python), &venv), &work)
    });
    assert_eq!(
        skipped(&counts),
        0,
        "pytest: {counts:?}; with matplotlib installed no test may skip"
    );
    let output = times.step("README Python snippet", || {
        fresh_dir(&snippets);
        run(in_venv(&mut readme::route("python").bash(&snippets), &venv))
    });
    assert_readme_snippet_prints_c(&output);
    times.print();
}
