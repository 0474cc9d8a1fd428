//! Gives the shared library a SONAME so consumers record `liborthoslip.so.0`, not a path,
//! and forwards the target triple to the C test harness.
fn main() {
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.contains("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,liborthoslip.so.0");
    }
    println!("cargo:rustc-env=ORTHOSLIP_TARGET={target}");
    println!("cargo:rerun-if-changed=build.rs");
}
