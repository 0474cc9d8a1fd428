//! External commands run from the tests: echoed with their environment changes, output and
//! run time, and failing the test on a non-zero exit.

use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;

/// The cargo target directory of the tests that build the library again, in release mode
/// without the `cli` feature: tests/packaging.rs (through CMake) and the slow tier's wheel
/// test in tests/python.rs (through maturin). It is kept between runs, and as both builds
/// share every dependency, whichever runs second compiles only this crate.
pub fn library_target_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("library-target")
}

/// Whether the environment variable `var` asks to skip the slow `test`: set to anything but
/// empty or `0` (e.g. `ORTHOSLIP_SKIP_PACKAGING=1`). The test then passes without running and
/// says so on stderr, past the test harness's output capture, so that `cargo test` shows it.
pub fn skipped(var: &str, test: &str) -> bool {
    let value = std::env::var_os(var).unwrap_or_default();
    let skip = !value.is_empty() && value != "0";
    if skip {
        use std::io::Write as _;
        let _ = writeln!(
            std::io::stderr(),
            "NOTE: {test} skipped ({var}={}); unset it to run the test",
            value.to_string_lossy()
        );
    }
    skip
}

/// A command with LD_LIBRARY_PATH removed: `cargo test` points it at target/<profile>/deps,
/// which holds another liborthoslip.so that must not stand in for the installed one.
pub fn command(program: impl AsRef<std::ffi::OsStr>) -> Command {
    let mut cmd = Command::new(program);
    cmd.env_remove("LD_LIBRARY_PATH");
    cmd
}

fn describe(cmd: &Command) -> String {
    let mut words: Vec<String> = cmd
        .get_envs()
        .filter_map(|(k, v)| v.map(|v| format!("{}={}", k.to_string_lossy(), v.to_string_lossy())))
        .collect();
    words.push(cmd.get_program().to_string_lossy().into_owned());
    words.extend(cmd.get_args().map(|a| a.to_string_lossy().into_owned()));
    let mut line = words.join(" ");
    if let Some(dir) = cmd.get_current_dir() {
        line = format!("(cd {} && {line})", dir.display());
    }
    line
}

/// Runs `cmd`, printing it and its output; panics unless it exits successfully. Returns stdout.
pub fn run(cmd: &mut Command) -> String {
    run_or_explain(cmd, "")
}

/// [`run`], adding `hint` (what may be missing) to the panic message.
pub fn run_or_explain(cmd: &mut Command, hint: &str) -> String {
    let line = describe(cmd);
    println!("$ {line}");
    let start = Instant::now();
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot start `{line}`: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    print!("{stdout}");
    if !stderr.is_empty() {
        println!("[stderr]\n{stderr}");
    }
    println!("[{:.1} s, {}]", start.elapsed().as_secs_f64(), out.status);
    assert!(
        out.status.success(),
        "`{line}` failed with {}{hint}",
        out.status
    );
    stdout
}
