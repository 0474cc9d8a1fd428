//! Build facts the library and its tests share, derived rather than written down:
//! - the SONAME, from the ABI version that Cargo's semver rule gives the package version
//!   (0.y.z: "0.y", x.y.z with x >= 1: "x"); CMakeLists.txt applies the same rule to the same
//!   version and tests/packaging.rs checks that the installed library agrees;
//! - the native libraries a Rust staticlib needs on this target, from
//!   `rustc --print native-static-libs` (for the C test programs);
//! - the target triple (for the C test harness).
use std::env;
use std::process::Command;

fn main() {
    let target = env::var("TARGET").unwrap_or_default();
    let major: u64 = env::var("CARGO_PKG_VERSION_MAJOR")
        .unwrap()
        .parse()
        .unwrap();
    let minor = env::var("CARGO_PKG_VERSION_MINOR").unwrap();
    let abi = if major == 0 {
        format!("0.{minor}")
    } else {
        major.to_string()
    };
    let soname = format!("liborthoslip.so.{abi}");
    if target.contains("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,{soname}");
    }
    println!("cargo:rustc-env=ORTHOSLIP_SONAME={soname}");
    println!(
        "cargo:rustc-env=ORTHOSLIP_NATIVE_STATIC_LIBS={}",
        native_static_libs(&target)
    );
    println!("cargo:rustc-env=ORTHOSLIP_TARGET={target}");
    println!("cargo:rerun-if-changed=build.rs");
}

/// What `rustc --print native-static-libs` lists for a staticlib on `target` (an empty crate
/// links the same native libraries as this one: std's, no dependency adds any).
fn native_static_libs(target: &str) -> String {
    let out_dir = std::path::PathBuf::from(env::var("OUT_DIR").unwrap());
    let source = out_dir.join("native_libs_probe.rs");
    std::fs::write(&source, "").unwrap();
    let rustc = env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let output = Command::new(&rustc)
        .args([
            "--crate-type",
            "staticlib",
            "--crate-name",
            "native_libs_probe",
        ])
        .args(["--print", "native-static-libs", "--target", target])
        .arg("-o")
        .arg(out_dir.join("libnative_libs_probe.a"))
        .arg(&source)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {rustc}: {e}"));
    let stderr = String::from_utf8_lossy(&output.stderr);
    stderr
        .lines()
        .find_map(|l| l.split("native-static-libs:").nth(1))
        .map(|libs| libs.trim().to_string())
        .unwrap_or_else(|| panic!("{rustc} --print native-static-libs printed no list:\n{stderr}"))
}
