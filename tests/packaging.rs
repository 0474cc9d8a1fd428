//! The install-and-consume route of the README, end to end: CMake builds this crate (through
//! cargo) and installs it into a temporary prefix; `c_examples/` is then configured and built
//! as an outside project against that prefix, once with the shared and once with the static
//! library (the second time after moving the prefix, which checks that the package is
//! relocatable); a C consumer is built through pkg-config. Every consumer must print the same
//! stick half-width `c` and the same p, q table. Then the README's C/CMake, pkg-config, C++
//! and Fortran snippets run against the moved prefix and must print that c too. (The Python
//! route is checked by tests/python.rs.)
//!
//! Needs cmake, C, C++ and Fortran compilers, pkg-config, bash and binutils. A missing tool
//! fails the test with what to install, unless ORTHOSLIP_SKIP_PACKAGING=1. The C++ and Fortran
//! consumers are built from a copy of `c_examples/` without its `orthoslip.hpp` and
//! `orthoslip_mod.f90`: they take the installed ones (include/ and share/orthoslip/fortran/).

mod readme;
mod shell;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use shell::{command, run};

const SKIP_VAR: &str = "ORTHOSLIP_SKIP_PACKAGING";
const VERSION: &str = env!("CARGO_PKG_VERSION");
/// The SONAME build.rs gave the library (ABI version by Cargo's semver rule); the CMake route
/// must install exactly this name.
const SONAME: &str = env!("ORTHOSLIP_SONAME");
/// The native libraries build.rs got from `rustc --print native-static-libs`.
const NATIVE_LIBS: &str = env!("ORTHOSLIP_NATIVE_STATIC_LIBS");
/// Points in the p, q table each example prints.
const TABLE_ROWS: usize = 21;
/// Agreement required between consumers (they all call the same library).
const TOLERANCE: f64 = 1e-12;

/// Tools the route needs that are not on PATH, with the Debian package providing each.
fn missing_tools() -> Vec<String> {
    let env_or = |var: &str, default: &str| std::env::var(var).unwrap_or_else(|_| default.into());
    let tools = [
        (env_or("CC", "cc"), "gcc"),
        (env_or("CXX", "c++"), "g++"),
        (env_or("FC", "gfortran"), "gfortran"),
        ("cmake".into(), "cmake"),
        ("pkg-config".into(), "pkg-config"),
        ("bash".into(), "bash"),
        ("readelf".into(), "binutils"),
        ("ldd".into(), "libc-bin"),
    ];
    tools
        .into_iter()
        .filter(|(tool, _)| {
            !Command::new(tool)
                .arg("--version")
                .output()
                .is_ok_and(|o| o.status.success())
        })
        .map(|(tool, package)| format!("{tool} (Debian package {package})"))
        .collect()
}

fn readelf_dynamic(file: &Path) -> String {
    run(command("readelf").arg("-d").arg(file))
}

/// The value printed after `label` at the start of a line of `output`.
fn labelled(consumer: &str, output: &str, label: &str) -> f64 {
    let value = output
        .lines()
        .find_map(|l| l.strip_prefix(label))
        .unwrap_or_else(|| panic!("{consumer}: no line starting with {label:?}"));
    value
        .trim()
        .parse()
        .unwrap_or_else(|e| panic!("{consumer}: cannot parse {label}{value:?}: {e}"))
}

/// What a consumer printed that every consumer must agree on.
struct SceneOutput {
    consumer: String,
    c: f64,
    table: Vec<[f64; 3]>,
    /// The fretting lines: the cycle count and the first cycle's dissipation.
    fretting: [f64; 2],
}

fn parse_scene(consumer: &str, output: &str) -> SceneOutput {
    let c = labelled(consumer, output, "c = ");
    let one_minus_c = labelled(consumer, output, "1 - c = ");
    assert!(c > 0.0 && c < 1.0, "{consumer}: c = {c} outside (0, 1)");
    assert!(
        (c + one_minus_c - 1.0).abs() <= 4.0 * f64::EPSILON,
        "{consumer}: c = {c} and 1 - c = {one_minus_c} do not add up to 1"
    );
    assert!(
        output.lines().any(|l| l.starts_with("method = ")),
        "{consumer}: no method line"
    );
    let table: Vec<[f64; 3]> = output
        .lines()
        .filter_map(|l| {
            let v: Vec<f64> = l
                .split_whitespace()
                .map(str::parse)
                .collect::<Result<_, _>>()
                .ok()?;
            <[f64; 3]>::try_from(v).ok()
        })
        .collect();
    assert_eq!(table.len(), TABLE_ROWS, "{consumer}: p, q table rows");
    let fretting = [
        labelled(consumer, output, "fretting cycles = "),
        labelled(consumer, output, "fretting W1 = "),
    ];
    SceneOutput {
        consumer: consumer.into(),
        c,
        table,
        fretting,
    }
}

fn assert_close(what: &str, reference: f64, value: f64) {
    assert!(
        (value - reference).abs() <= TOLERANCE * reference.abs().max(1.0),
        "{what}: {value:e} differs from the reference {reference:e}"
    );
}

fn assert_needs_soname(exe: &Path) {
    let dynamic = readelf_dynamic(exe);
    assert!(
        dynamic.contains(&format!("Shared library: [{SONAME}]")),
        "{} does not record {SONAME}",
        exe.display()
    );
}

fn assert_static(exe: &Path) {
    let dynamic = readelf_dynamic(exe);
    assert!(
        !dynamic.contains("liborthoslip"),
        "{} needs a shared liborthoslip although linked statically",
        exe.display()
    );
}

/// `ldd` resolves the SONAME of `exe` (run with `lib_path` as LD_LIBRARY_PATH if given)
/// to the installed file in `libdir`.
fn assert_resolves_into(exe: &Path, libdir: &Path, lib_path: Option<&Path>) {
    let mut ldd = command("ldd");
    ldd.arg(exe);
    if let Some(dir) = lib_path {
        ldd.env("LD_LIBRARY_PATH", dir);
    }
    let out = run(&mut ldd);
    let expected = format!("{SONAME} => {}", libdir.join(SONAME).display());
    assert!(
        out.contains(&expected),
        "{}: expected `{expected}` in ldd output",
        exe.display()
    );
}

fn fresh_dir(dir: &Path) {
    if dir.exists() {
        std::fs::remove_dir_all(dir).unwrap();
    }
}

/// The consumer programs of c_examples and its CMakeLists.txt, copied into `work` without the
/// C++ wrapper and the Fortran module beside them, so that the build can only use the
/// installed ones.
const CONSUMER_FILES: [&str; 4] = [
    "CMakeLists.txt",
    "default_scene.c",
    "default_scene.cpp",
    "default_scene.f90",
];

/// Configures and builds (a copy of) c_examples against `prefix`; returns the build directory.
fn build_examples(source: &Path, work: &Path, prefix: &Path, static_link: bool) -> PathBuf {
    let build = work.join(if static_link {
        "examples-static"
    } else {
        "examples-shared"
    });
    fresh_dir(&build);
    let consumer = work.join("examples-source");
    fresh_dir(&consumer);
    std::fs::create_dir_all(&consumer).unwrap();
    for file in CONSUMER_FILES {
        std::fs::copy(source.join("c_examples").join(file), consumer.join(file))
            .unwrap_or_else(|e| panic!("copy c_examples/{file}: {e}"));
    }
    let configure = run(command("cmake")
        .arg("-S")
        .arg(&consumer)
        .arg("-B")
        .arg(&build)
        .arg(format!("-DCMAKE_PREFIX_PATH={}", prefix.display()))
        .arg(format!(
            "-DORTHOSLIP_EXAMPLES_STATIC={}",
            if static_link { "ON" } else { "OFF" }
        )));
    let found = format!(
        "orthoslip {VERSION} from {}",
        prefix.join("lib/cmake/orthoslip").display()
    );
    assert!(
        configure.contains(&found),
        "configure did not report `{found}`"
    );
    // the wrappers come from the package
    for (what, path) in [
        ("C++ wrapper", prefix.join("include/orthoslip.hpp")),
        (
            "Fortran module source",
            prefix.join("share/orthoslip/fortran/orthoslip_mod.f90"),
        ),
    ] {
        let line = format!("orthoslip {what}: {}", path.display());
        assert!(
            configure.contains(&line),
            "configure did not report `{line}`"
        );
    }
    run(command("cmake")
        .arg("--build")
        .arg(&build)
        .arg("--parallel")
        .arg("2"));
    build
}

#[test]
fn install_and_consume() {
    if shell::skipped(SKIP_VAR, "packaging test") {
        return;
    }
    let missing = missing_tools();
    assert!(
        missing.is_empty(),
        "the packaging test needs: {}. Install them (Debian: apt-get install cmake g++ gfortran \
         pkg-config binutils) or set {SKIP_VAR}=1 to skip this test",
        missing.join(", ")
    );
    let total = Instant::now();
    let source = Path::new(env!("CARGO_MANIFEST_DIR"));
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("packaging");
    // The CMake build tree and cargo's target directory are kept between runs so that only
    // the first run pays for a cold cargo build; everything else starts fresh.
    let build = work.join("build");
    let prefix = work.join("prefix");
    let moved = work.join("prefix-moved");
    fresh_dir(&prefix);
    fresh_dir(&moved);
    // cmake refuses a build tree configured elsewhere or from another source (a target
    // directory copied from, or shared with, another checkout): start that one afresh too
    let cache = std::fs::read_to_string(build.join("CMakeCache.txt")).unwrap_or_default();
    let ours = [
        ("CMAKE_CACHEFILE_DIR", &build),
        ("CMAKE_HOME_DIRECTORY", &source.to_path_buf()),
    ]
    .iter()
    .all(|(key, dir)| cache.contains(&format!("{key}:INTERNAL={}\n", dir.display())));
    if !ours {
        fresh_dir(&build);
    }

    // 1. Root project: configure, build (cargo build --release), install.
    let mut configure = command("cmake");
    configure
        .arg("-S")
        .arg(source)
        .arg("-B")
        .arg(&build)
        .arg(format!(
            "-DORTHOSLIP_CARGO_TARGET_DIR={}",
            shell::library_target_dir().display()
        ));
    if let Some(cargo) = std::env::var_os("CARGO") {
        configure.arg(format!(
            "-DCARGO_EXECUTABLE={}",
            Path::new(&cargo).display()
        ));
    }
    run(&mut configure);
    run(command("cmake").arg("--build").arg(&build));
    run(command("cmake")
        .arg("--install")
        .arg(&build)
        .arg("--prefix")
        .arg(&prefix));

    let libdir = prefix.join("lib");
    let real = format!("liborthoslip.so.{VERSION}");
    assert!(libdir.join(&real).is_file(), "{real} not installed");
    for (link, target) in [(SONAME, real.as_str()), ("liborthoslip.so", SONAME)] {
        let read = std::fs::read_link(libdir.join(link))
            .unwrap_or_else(|e| panic!("{link} is not an installed symlink: {e}"));
        assert_eq!(read, Path::new(target), "{link} points elsewhere");
    }
    assert!(readelf_dynamic(&libdir.join(&real)).contains(&format!("soname: [{SONAME}]")));
    assert!(libdir.join("liborthoslip.a").is_file());
    for file in ["orthoslipConfig.cmake", "orthoslipConfigVersion.cmake"] {
        assert!(
            libdir.join("cmake/orthoslip").join(file).is_file(),
            "{file} not installed"
        );
    }
    for (installed, committed) in [
        ("include/orthoslip.h", "include/orthoslip.h"),
        ("include/orthoslip.hpp", "c_examples/orthoslip.hpp"),
        (
            "share/orthoslip/fortran/orthoslip_mod.f90",
            "c_examples/orthoslip_mod.f90",
        ),
    ] {
        let read = |p: PathBuf| {
            std::fs::read(&p).unwrap_or_else(|e| panic!("{} not installed: {e}", p.display()))
        };
        assert_eq!(
            read(prefix.join(installed)),
            read(source.join(committed)),
            "installed {installed} differs from {committed}"
        );
    }

    let mut scenes = Vec::new();
    let consumers = ["c", "cpp", "f90"];

    // 2. Outside project, shared library, at the install prefix.
    let shared = build_examples(source, &work, &prefix, false);
    for name in consumers {
        let exe = shared.join(format!("default_scene_{name}"));
        assert_needs_soname(&exe);
        assert_resolves_into(&exe, &libdir, None);
        scenes.push(parse_scene(
            &format!("{name} shared"),
            &run(&mut command(&exe)),
        ));
    }

    // 3. The prefix moved elsewhere: static linking through the CMake package and a pkg-config
    // build find everything relative to the new location.
    std::fs::rename(&prefix, &moved).unwrap();
    let libdir = moved.join("lib");
    let statik = build_examples(source, &work, &moved, true);
    for name in consumers {
        let exe = statik.join(format!("default_scene_{name}"));
        assert_static(&exe);
        scenes.push(parse_scene(
            &format!("{name} static"),
            &run(&mut command(&exe)),
        ));
    }

    let pc_path = libdir.join("pkgconfig");
    let pkg_config = |args: &[&str]| {
        run(command("pkg-config")
            .env("PKG_CONFIG_PATH", &pc_path)
            .args(args)
            .arg("orthoslip"))
    };
    assert_eq!(pkg_config(&["--modversion"]).trim(), VERSION);
    let static_libs = pkg_config(&["--static", "--libs"]);
    for lib in NATIVE_LIBS.split_whitespace() {
        let listed = static_libs.split_whitespace().any(|l| l == lib);
        assert!(listed, "Libs.private lacks {lib}");
    }
    let flags = pkg_config(&["--cflags", "--libs"]);
    let exe = work.join("default_scene_pkgconfig");
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    run(command(cc)
        .arg("-std=c11")
        .arg(source.join("c_examples/default_scene.c"))
        .arg("-o")
        .arg(&exe)
        .args(flags.split_whitespace()));
    assert_needs_soname(&exe);
    assert_resolves_into(&exe, &libdir, Some(&libdir));
    scenes.push(parse_scene(
        "c pkg-config",
        &run(command(&exe).env("LD_LIBRARY_PATH", &libdir)),
    ));

    // 4. The README's snippets for these routes, against the moved prefix.
    let snippets = work.join("readme");
    fresh_dir(&snippets);
    std::fs::create_dir_all(&snippets).unwrap();
    let mut script = readme::route("packaging").bash(&snippets);
    script
        .env_remove("LD_LIBRARY_PATH")
        .env("PREFIX", &moved)
        .env("ORTHOSLIP_SRC", source);
    let readme_c = readme::printed_c(&run(&mut script));
    assert_eq!(
        readme_c.len(),
        4,
        "the README's C/CMake, pkg-config, C++ and Fortran snippets each print c"
    );

    // 5. Every consumer printed the same numbers, and the fretting lines are the Rust
    // library's (through C, the C++ wrapper and the Fortran bindings).
    let reference = &scenes[0];
    let mut contact = orthoslip::Contact::new(
        orthoslip::Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
    );
    contact.set_friction(0.3).unwrap();
    let options = orthoslip::fretting::CycleOptions {
        panels: 32,
        steps: 4,
        ..Default::default()
    };
    let run = orthoslip::fretting::Fretting::solve(&contact, 0.6 * 0.3, &options).unwrap();
    let fretting = [run.cycles.len() as f64, run.cycles[0].dissipation.value];
    for (i, &c) in readme_c.iter().enumerate() {
        assert_close(&format!("README snippet {i} c"), reference.c, c);
    }
    for scene in &scenes {
        println!("{:>22}: c = {:.17}", scene.consumer, scene.c);
        assert_close(&format!("{} c", scene.consumer), reference.c, scene.c);
        for (i, (&v, &r)) in scene.fretting.iter().zip(&fretting).enumerate() {
            assert_close(&format!("{} fretting line {i}", scene.consumer), r, v);
        }
        for (row, (mine, theirs)) in scene.table.iter().zip(&reference.table).enumerate() {
            for (col, (&v, &r)) in mine.iter().zip(theirs).enumerate() {
                assert_close(
                    &format!("{} table row {row} column {col}", scene.consumer),
                    r,
                    v,
                );
            }
        }
    }
    println!(
        "packaging route: {} consumers and {} README snippets agree, {:.1} s in total",
        scenes.len(),
        readme_c.len(),
        total.elapsed().as_secs_f64()
    );
}
