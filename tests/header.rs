//! The committed header is what cbindgen generates from src/ffi now.
//! `ORTHOSLIP_BLESS=1 cargo test --release --test header` rewrites it.

use std::path::Path;

#[test]
fn committed_header_is_up_to_date() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(root.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(root)
        .with_config(config)
        .generate()
        .expect("cbindgen failed on src/ffi")
        .write(&mut generated);
    let generated = String::from_utf8(generated).expect("header is UTF-8");
    let path = root.join("include/orthoslip.h");
    if std::env::var_os("ORTHOSLIP_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("write include/orthoslip.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/orthoslip.h is stale: regenerate it with \
         ORTHOSLIP_BLESS=1 cargo test --release --test header"
    );
}
