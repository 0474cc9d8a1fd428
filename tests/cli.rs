//! The `orthoslip` binary run as a user runs it: every number it prints must be the library's
//! own result to the last bit (it prints shortest round-trip decimals), the exit status must
//! tell bad input (2) from solver failures (1), errors must be one line, JSON must parse, and
//! the README's command-line snippets must run.

mod readme;

use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Command, Stdio};

use orthoslip::{Contact, Material, Method, Solution};
use serde_json::Value;

const PLY: [&str; 5] = ["--plane-stress", "181e9", "10.3e9", "7.17e9", "0.28"];

struct Run {
    status: i32,
    stdout: String,
    stderr: String,
}

fn run_cmd(mut cmd: Command) -> Run {
    let out = cmd.output().expect("run the orthoslip binary");
    Run {
        status: out.status.code().expect("exit status"),
        stdout: String::from_utf8(out.stdout).expect("UTF-8 stdout"),
        stderr: String::from_utf8(out.stderr).expect("UTF-8 stderr"),
    }
}

fn orthoslip(args: &[&str]) -> Run {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_orthoslip"));
    cmd.args(args);
    run_cmd(cmd)
}

/// The arguments of `command` on the ply, then `extra`.
fn on_ply(command: &'static str, extra: &[&'static str]) -> Vec<&'static str> {
    [&[command][..], &PLY[..], extra].concat()
}

/// `orthoslip solve` on the ply with `extra` arguments, expecting success.
fn solve_ply(extra: &[&'static str]) -> Run {
    let args = on_ply("solve", extra);
    let run = orthoslip(&args);
    assert_eq!(run.status, 0, "{args:?}: {}", run.stderr);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    run
}

fn ply() -> Material {
    Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap()
}

/// The library's solution, with the CLI's defaults (AUTO, the library's default tolerance).
fn library(material: Material, mu: f64, method: Method, tol: Option<f64>) -> Solution {
    let mut contact = Contact::new(material);
    contact.set_friction(mu).unwrap();
    contact.set_method(method);
    if let Some(tol) = tol {
        contact.set_tolerance(tol).unwrap();
    }
    contact.solve().unwrap()
}

/// The value printed after `label = ` at the start of a line.
fn field<'a>(output: &'a str, label: &str) -> &'a str {
    let prefix = format!("{label} = ");
    output
        .lines()
        .find_map(|l| l.strip_prefix(prefix.as_str()))
        .unwrap_or_else(|| panic!("no `{prefix}` line in:\n{output}"))
}

fn number(text: &str) -> f64 {
    text.parse()
        .unwrap_or_else(|e| panic!("cannot parse {text:?}: {e}"))
}

fn json(output: &str) -> Value {
    serde_json::from_str(output).unwrap_or_else(|e| panic!("invalid JSON ({e}):\n{output}"))
}

fn floats(v: &Value) -> Vec<f64> {
    let values = v.as_array().unwrap_or_else(|| panic!("not an array: {v}"));
    values
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect()
}

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli")
        .join(name);
    if dir.exists() {
        std::fs::remove_dir_all(&dir).unwrap();
    }
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn without_arguments_it_runs_the_default_scene() {
    let run = orthoslip(&[]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    let out = &run.stdout;
    assert!(out.starts_with(&format!(
        "orthoslip {}: default scene\n",
        env!("CARGO_PKG_VERSION")
    )));
    for method in ["Goodman", "Spence", "Lcp", "Coupled", "Auto"] {
        assert!(
            out.lines().any(|l| l.starts_with(method)),
            "no {method} row:\n{out}"
        );
    }
    let coupled = library(ply(), 0.3, Method::Coupled, Some(1e-10));
    let row = out
        .lines()
        .find(|l| l.starts_with("Coupled"))
        .expect("Coupled row");
    let printed: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(printed[3], format!("{:.16}", coupled.c()), "{row}");
    assert!(out.contains("tractions per P/a (Coupled)"));
}

#[test]
fn solve_prints_the_librarys_solution_exactly() {
    let run = solve_ply(&["--mu", "0.3"]);
    let out = &run.stdout;
    let s = library(ply(), 0.3, Method::Auto, None);
    assert_eq!(number(field(out, "c")).to_bits(), s.c().to_bits());
    assert_eq!(
        number(field(out, "1 - c")).to_bits(),
        s.one_minus_c().to_bits()
    );
    assert_eq!(number(field(out, "error estimate")), s.error_estimate());
    assert_eq!(
        number(field(out, "traction error estimate")),
        s.traction_error_estimate()
    );
    assert_eq!(number(field(out, "traction tolerance")), 1e-8);
    assert_eq!(field(out, "method"), "coupled");
    assert_eq!(field(out, "method requested"), "auto");
    assert_eq!(number(field(out, "mu")), 0.3);
    let k = ply().constants();
    assert!(out.contains(&format!(
        "effective: E = {:?}, nu = {:?}, delta = {:?}, kappa = {:?}\n",
        k.e, k.nu, k.delta, k.kappa
    )));
    // The default table: 21 midpoints, exact p and q, the zone.
    let rows: Vec<Vec<&str>> = out
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("x "))
        .skip(1)
        .map(|l| l.split_whitespace().collect())
        .collect();
    assert_eq!(rows.len(), 21);
    for (i, row) in rows.iter().enumerate() {
        let x = number(row[0]);
        assert_eq!(x, (2.0 * i as f64 + 1.0 - 21.0) / 21.0);
        let (p, q) = s.tractions(x);
        assert_eq!((number(row[1]), number(row[2])), (p, q), "row {i}");
        let zone = if x.abs() < s.c() { "stick" } else { "slip" };
        assert_eq!(row[3], zone);
    }
}

#[test]
fn json_output_parses_and_holds_every_material_kind() {
    let steel = ["210e9", "210e9", "210e9", "80.8e9", "0.3", "0.3", "0.3"];
    let cases: [(&str, &[&str], Material, &str, Method); 3] = [
        ("plane_stress", &PLY[1..], ply(), "spence", Method::Spence),
        (
            "plane_strain",
            &steel,
            Material::plane_strain(210e9, 210e9, 210e9, 80.8e9, 0.3, 0.3, 0.3).unwrap(),
            "coupled",
            Method::Coupled,
        ),
        (
            "effective",
            &["1", "0.3", "10", "0.4"],
            Material::effective(1.0, 0.3, 10.0, 0.4).unwrap(),
            "goodman",
            Method::Goodman,
        ),
    ];
    for (model, constants, material, method, expected_method) in cases {
        let flag = format!("--{}", model.replace('_', "-"));
        let mut args = vec!["solve", flag.as_str()];
        args.extend(constants);
        args.extend(["--mu", "0.7", "--method", method, "--tol", "1e-6"]);
        args.extend(["--points", "7", "--format", "json"]);
        let run = orthoslip(&args);
        assert_eq!(run.status, 0, "{args:?}: {}", run.stderr);
        let v = json(&run.stdout);
        let s = library(material, 0.7, expected_method, Some(1e-6));
        assert_eq!(v["material"]["model"], model);
        assert_eq!(v["method_requested"], method);
        assert_eq!(v["method"], method);
        assert_eq!(v["tolerance"].as_f64(), Some(1e-6));
        assert_eq!(v["mu"].as_f64(), Some(0.7));
        assert_eq!(v["c"].as_f64(), Some(s.c()));
        assert_eq!(v["one_minus_c"].as_f64(), Some(s.one_minus_c()));
        assert_eq!(v["error_estimate"].as_f64(), Some(s.error_estimate()));
        let traction_estimate = s.traction_error_estimate();
        assert_eq!(
            v["traction_error_estimate"].as_f64(),
            traction_estimate.is_finite().then_some(traction_estimate)
        );
        assert_eq!(v["traction_tolerance"].as_f64(), Some(1e-6));
        assert_eq!(
            v["effective"]["kappa"].as_f64(),
            Some(material.constants().kappa)
        );
        let x = floats(&v["tractions"]["x"]);
        assert_eq!(x.len(), 7);
        let (p, q): (Vec<f64>, Vec<f64>) = x.iter().map(|&x| s.tractions(x)).unzip();
        assert_eq!(floats(&v["tractions"]["p"]), p);
        assert_eq!(floats(&v["tractions"]["q"]), q);
        assert_eq!(v["tractions"]["zone"].as_array().unwrap().len(), 7);
    }
}

/// --traction-tol sets the traction target apart from --tol, as
/// `orthoslip_contact_set_traction_tolerance` does: the library's solution with the same
/// targets, printed exactly, with a traction estimate within the target; `inf` (tractions not
/// needed) lets AUTO answer c alone: at 1e-6 from COUPLED's tabulated c with Goodman's
/// tractions (their estimate far above 1e-6), at 5e-2 from SPENCE.
#[test]
fn traction_tolerance_is_set_apart_from_the_tolerance() {
    let solved = |tol: &'static str, traction_tol: &'static str| {
        let run = solve_ply(&[
            "--mu",
            "0.3",
            "--tol",
            tol,
            "--traction-tol",
            traction_tol,
            "--points",
            "0",
            "--format",
            "json",
        ]);
        let v = json(&run.stdout);
        let mut contact = Contact::new(ply());
        contact.set_friction(0.3).unwrap();
        contact.set_tolerance(tol.parse().unwrap()).unwrap();
        contact
            .set_traction_tolerance(traction_tol.parse().unwrap())
            .unwrap();
        let s = contact.solve().unwrap();
        assert_eq!(v["c"].as_f64(), Some(s.c()));
        assert_eq!(v["method"], method_name(s.method()));
        let estimate = s.traction_error_estimate();
        assert_eq!(
            v["traction_error_estimate"].as_f64(),
            estimate.is_finite().then_some(estimate)
        );
        (v, s)
    };
    let (v, s) = solved("1e-6", "1e-10");
    assert_eq!(v["traction_tolerance"].as_f64(), Some(1e-10));
    assert_eq!(v["tolerance"].as_f64(), Some(1e-6));
    assert!(s.traction_error_estimate() <= 1e-10);
    assert_eq!(s.method(), Method::Coupled);
    let (v, s) = solved("1e-6", "inf");
    // JSON has no infinity: the target prints as null, like an estimate outside the table
    assert!(v["traction_tolerance"].is_null());
    assert!(s.error_estimate() <= 1e-6);
    assert!(s.traction_error_estimate() > 1e-3, "tractions not refined");
    let (_, s) = solved("5e-2", "inf");
    assert!(s.error_estimate() <= 5e-2);
    assert_eq!(s.method(), Method::Spence);
}

/// The method's name as the CLI should print it (spelled out here rather than taken from the
/// CLI's own table, so that the tests check its spelling).
fn method_name(m: Method) -> &'static str {
    match m {
        Method::Auto => "auto",
        Method::Goodman => "goodman",
        Method::Spence => "spence",
        Method::Coupled => "coupled",
        Method::Lcp => "lcp",
    }
}

#[test]
fn an_error_estimate_outside_the_table_is_infinite_in_text_and_null_in_json() {
    // b* = 0.995 lies outside the model-error table (b* 0.005 .. 0.99): Goodman's estimate
    // is +infinity.
    let args = [
        "solve",
        "--effective",
        "1",
        "-0.99",
        "1",
        "1",
        "--mu",
        "0.3",
    ];
    let goodman = [&args[..], &["--method", "goodman", "--points", "0"]].concat();
    let table = orthoslip(&goodman);
    assert_eq!(table.status, 0, "{}", table.stderr);
    assert_eq!(field(&table.stdout, "error estimate"), "inf");
    assert!(!table.stdout.contains(" x "), "--points 0 prints no table");
    let v = json(&orthoslip(&[&goodman[..], &["--format", "json"]].concat()).stdout);
    assert!(v["error_estimate"].is_null());
    assert!(v["c"].as_f64().is_some_and(|c| c > 0.0 && c < 1.0));
    assert_eq!(v["tractions"]["x"].as_array().map(Vec::len), Some(0));
}

#[test]
fn csv_output_is_a_table_after_comment_lines() {
    let run = solve_ply(&[
        "--mu", "1.5", "--method", "goodman", "--points", "4", "--format", "csv",
    ]);
    let lines: Vec<&str> = run.stdout.lines().collect();
    let header = lines.iter().position(|l| !l.starts_with("# ")).unwrap();
    assert!(lines[..header].contains(&"# method = goodman"));
    assert_eq!(lines[header], "x,p,q,zone");
    let s = library(ply(), 1.5, Method::Goodman, None);
    let rows = &lines[header + 1..];
    assert_eq!(rows.len(), 4);
    for row in rows {
        let cells: Vec<&str> = row.split(',').collect();
        let x = number(cells[0]);
        assert_eq!((number(cells[1]), number(cells[2])), s.tractions(x));
    }
}

#[test]
fn sweep_prints_c_against_mu() {
    let args = on_ply(
        "sweep",
        &[
            "--mu-from",
            "0.1",
            "--mu-to",
            "10",
            "--steps",
            "5",
            "--format",
            "csv",
        ],
    );
    let run = orthoslip(&args);
    assert_eq!(run.status, 0, "{}", run.stderr);
    let rows: Vec<Vec<&str>> = run
        .stdout
        .lines()
        .skip_while(|l| l.starts_with("# "))
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(
        rows[0],
        [
            "mu",
            "c",
            "one_minus_c",
            "method",
            "error_estimate",
            "traction_error_estimate",
            "status"
        ]
    );
    let mu: Vec<f64> = rows[1..].iter().map(|r| number(r[0])).collect();
    assert_eq!(mu[0], 0.1);
    assert_eq!(mu[2], 1.0);
    assert_eq!(mu[4], 10.0);
    let mut last_c = 0.0;
    for (row, &mu) in rows[1..].iter().zip(&mu) {
        let s = library(ply(), mu, Method::Auto, None);
        assert_eq!(number(row[1]), s.c(), "mu = {mu}");
        assert_eq!(number(row[2]), s.one_minus_c());
        assert_eq!(row[3], "coupled");
        assert_eq!(number(row[4]), s.error_estimate());
        assert_eq!(number(row[5]), s.traction_error_estimate());
        assert_eq!(row[6], "ok");
        assert!(s.c() > last_c, "c grows with mu");
        last_c = s.c();
    }
    // Linear spacing, JSON, several materials options shared with solve.
    let run = orthoslip(&[
        "sweep",
        "--effective",
        "1",
        "0.3",
        "1",
        "1",
        "--mu-from",
        "0",
        "--mu-to",
        "1",
        "--steps",
        "3",
        "--spacing",
        "linear",
        "--method",
        "goodman",
        "--format",
        "json",
    ]);
    assert_eq!(run.status, 0, "{}", run.stderr);
    let v = json(&run.stdout);
    assert_eq!(floats(&v["sweep"]["mu"]), [0.0, 0.5, 1.0]);
    assert_eq!(v["sweep"]["c"][0].as_f64(), Some(0.0));
    assert_eq!(v["sweep"]["status"][2], "ok");
}

#[test]
fn a_failed_point_of_a_sweep_keeps_the_others_and_exits_1() {
    // b* = 0.05 (nu = 0.9) at tolerance 1e-12 (below the 1e-10 that every scene meets): at
    // mu = 1.2 the slip zones (1 - c ~ 2e-23) are below the panels' range and too wide for
    // the bonded limit; at mu = 10 the bonded limit meets it.
    let args = [
        "sweep",
        "--effective",
        "1",
        "0.9",
        "1",
        "1",
        "--method",
        "coupled",
        "--tol",
        "1e-12",
        "--mu-from",
        "1.2",
        "--mu-to",
        "10",
        "--steps",
        "2",
    ];
    let json_args = [&args[..], &["--format", "json"]].concat();
    let run = orthoslip(&json_args);
    assert_eq!(run.status, 1);
    let v = json(&run.stdout);
    assert_eq!(v["sweep"]["status"][0], "no_convergence");
    assert!(v["sweep"]["c"][0].is_null());
    assert_eq!(v["sweep"]["status"][1], "ok");
    let material = Material::effective(1.0, 0.9, 1.0, 1.0).unwrap();
    assert_eq!(
        v["sweep"]["c"][1].as_f64(),
        Some(library(material, 10.0, Method::Coupled, Some(1e-12)).c())
    );
    assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
    assert!(
        run.stderr
            .starts_with("orthoslip: 1 of 2 solves failed; the first at mu = 1.2: no convergence"),
        "{}",
        run.stderr
    );
    let table = orthoslip(&args);
    assert!(
        table
            .stdout
            .lines()
            .any(|l| l.trim_end().ends_with("no_convergence"))
    );
}

#[test]
fn bad_input_exits_2_and_solver_failures_exit_1_with_one_line() {
    let solve = |extra: &[&'static str]| on_ply("solve", extra);
    let cases: Vec<(Vec<&str>, i32, &str)> = vec![
        (
            vec!["solve", "--mu", "0.3"],
            2,
            "required arguments were not provided",
        ),
        (
            vec!["solve", "--plane-stress", "1", "2", "3", "--mu", "0.3"],
            2,
            "4 values required",
        ),
        (
            solve(&["--effective", "1", "0", "1", "1", "--mu", "0.3"]),
            2,
            "cannot be used with",
        ),
        (
            solve(&["--mu", "abc"]),
            2,
            "invalid value 'abc' for '--mu <MU>'",
        ),
        (
            solve(&["--mu", "-0.3"]),
            2,
            "friction coefficient mu = -0.3 must be finite and >= 0",
        ),
        (solve(&["--mu", "nan"]), 2, "friction coefficient mu = NaN"),
        (
            solve(&["--mu", "0.3", "--method", "newton"]),
            2,
            "possible values: auto, goodman",
        ),
        (
            solve(&["--mu", "0.3", "--tol", "2"]),
            2,
            "tolerance 2 must be finite with 0 < tol < 1",
        ),
        (
            solve(&["--mu", "0.3", "--format", "xml"]),
            2,
            "invalid value 'xml'",
        ),
        (
            solve(&["--mu", "0.3", "--points", "many"]),
            2,
            "invalid value 'many'",
        ),
        (
            solve(&["--mu", "0.3", "--frobnicate"]),
            2,
            "unexpected argument '--frobnicate'",
        ),
        (
            vec![
                "solve",
                "--plane-stress",
                "1",
                "1",
                "1",
                "1.5",
                "--mu",
                "0.3",
            ],
            2,
            "inadmissible material: plane stress needs nu12^2 < E11/E22",
        ),
        (
            vec![
                "solve",
                "--effective",
                "1",
                "0.9",
                "1",
                "1",
                "--mu",
                "1.2",
                "--method",
                "coupled",
                "--tol",
                "1e-12",
            ],
            1,
            "no convergence: the slip zones (1 - c ~ 2e-23 by the near-bonded law) are too thin",
        ),
        (
            vec![
                "solve",
                "--plane-strain",
                "1",
                "1",
                "1",
                "1",
                "0.6",
                "0.6",
                "0.6",
                "--mu",
                "1",
            ],
            2,
            "inadmissible material",
        ),
        (
            vec!["solve", "--effective", "-1", "0.3", "1", "1", "--mu", "1"],
            2,
            "E = -1 must be",
        ),
        (
            vec!["frobnicate"],
            2,
            "unrecognized subcommand 'frobnicate'",
        ),
        (
            on_ply("sweep", &["--mu-from", "0", "--mu-to", "1", "--steps", "3"]),
            2,
            "--spacing log needs --mu-from and --mu-to > 0",
        ),
        (
            on_ply(
                "sweep",
                &["--mu-from", "0.1", "--mu-to", "1", "--steps", "1"],
            ),
            2,
            "'--steps <N>': 1 is not in 2..=1000000",
        ),
        (
            vec![
                "solve",
                "--effective",
                "1",
                "0.3",
                "1",
                "1",
                "--mu",
                "0.3",
                "--method",
                "coupled",
                "--tol",
                "1e-15",
            ],
            1,
            "tolerance not met: error estimate",
        ),
    ];
    for (args, status, words) in cases {
        let run = orthoslip(&args);
        assert_eq!(run.status, status, "{args:?}: {}", run.stderr);
        assert!(run.stdout.is_empty(), "{args:?} printed {}", run.stdout);
        assert_eq!(run.stderr.lines().count(), 1, "{args:?}: {}", run.stderr);
        assert!(run.stderr.starts_with("orthoslip: "), "{}", run.stderr);
        assert!(
            run.stderr.contains(words),
            "{args:?}: {:?} lacks {words:?}",
            run.stderr
        );
    }
}

#[test]
fn a_closed_pipe_ends_the_output_quietly() {
    // As in `orthoslip solve ... | head -1`: far more output than a pipe holds.
    let mut child = Command::new(env!("CARGO_BIN_EXE_orthoslip"))
        .args(on_ply("solve", &["--mu", "0.3", "--points", "200000"]))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start orthoslip");
    let mut first = String::new();
    BufReader::new(child.stdout.take().expect("stdout"))
        .read_line(&mut first)
        .expect("read a line");
    let out = child.wait_with_output().expect("wait for orthoslip");
    assert!(first.starts_with("material: "), "{first}");
    assert_eq!(out.status.code(), Some(0));
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn help_documents_every_option_and_the_exit_status() {
    let top = orthoslip(&["--help"]);
    assert_eq!(top.status, 0);
    for words in [
        "solve",
        "sweep",
        "default scene",
        "Exit status:",
        "  2  bad input",
    ] {
        assert!(top.stdout.contains(words), "--help lacks {words:?}");
    }
    let solve = orthoslip(&["solve", "--help"]);
    assert_eq!(solve.status, 0);
    let sweep = orthoslip(&["sweep", "--help"]);
    assert_eq!(sweep.status, 0);
    for help in [&solve.stdout, &sweep.stdout] {
        for words in [
            "--plane-stress <E11> <E22> <G12> <NU12>",
            "--plane-strain <E11> <E22> <E33> <G12> <NU12> <NU13> <NU23>",
            "--effective <E> <NU> <DELTA> <KAPPA>",
            "--method <METHOD>",
            "auto:",
            "goodman:",
            "spence:",
            "coupled:",
            "lcp:",
            "--tol <TOL>",
            "[default: 1e-8]",
            "--format <FORMAT>",
            "Exit status:",
        ] {
            assert!(help.contains(words), "help lacks {words:?}:\n{help}");
        }
    }
    for words in ["--mu <MU>", "--points <N>"] {
        assert!(solve.stdout.contains(words), "solve --help lacks {words:?}");
    }
    for words in [
        "--mu-from <MU>",
        "--mu-to <MU>",
        "--steps <N>",
        "--spacing <SPACING>",
    ] {
        assert!(sweep.stdout.contains(words), "sweep --help lacks {words:?}");
    }
    let version = orthoslip(&["--version"]);
    assert_eq!(
        version.stdout.trim(),
        format!("orthoslip {}", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn readme_command_line_snippets_run() {
    let route = readme::route("cli");
    let dir = scratch("readme");
    let bin_dir = PathBuf::from(env!("CARGO_BIN_EXE_orthoslip"));
    let path = std::env::join_paths(
        std::iter::once(bin_dir.parent().unwrap().to_path_buf()).chain(std::env::split_paths(
            &std::env::var_os("PATH").unwrap_or_default(),
        )),
    )
    .unwrap();
    let mut cmd = route.bash(&dir);
    cmd.env("PATH", path);
    let run = run_cmd(cmd);
    assert_eq!(
        run.status, 0,
        "README command-line snippets failed:\n{}",
        run.stderr
    );
    let expected = library(ply(), 0.3, Method::Auto, None).c();
    assert_eq!(readme::printed_c(&run.stdout), [expected]);
    let json_line = run
        .stdout
        .lines()
        .find(|l| l.starts_with('{'))
        .expect("JSON output");
    assert_eq!(json(json_line)["method"], "coupled");
    let csv = std::fs::read_to_string(dir.join("c_vs_mu.csv")).expect("c_vs_mu.csv");
    let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows.len(), 1 + 9, "{csv}");
    assert!(rows[1..].iter().all(|r| r.ends_with(",ok")), "{csv}");
}

/// `orthoslip fretting` prints the library's fretting run to the last bit (JSON: the table as
/// columns, NaN positions as null), the same with the amplitude given relative to mu, and
/// the profiles of one cycle with --profile; bad amplitudes and cycles exit 2, lift-off 1.
#[test]
fn fretting_prints_the_librarys_run_exactly() {
    use orthoslip::fretting::{CycleOptions, Fretting};
    let common = [
        "--mu", "0.3", "--panels", "16", "--steps", "2", "--format", "json",
    ];
    let absolute =
        orthoslip(&[&on_ply("fretting", &["--amplitude", "0.18"])[..], &common].concat());
    assert_eq!(absolute.status, 0, "{}", absolute.stderr);
    let relative = orthoslip(
        &[
            &on_ply("fretting", &["--relative-amplitude", "0.6"])[..],
            &common,
        ]
        .concat(),
    );
    assert_eq!(relative.status, 0, "{}", relative.stderr);
    let mut contact = Contact::new(ply());
    contact.set_friction(0.3).unwrap();
    let options = CycleOptions {
        panels: 16,
        steps: 2,
        ..CycleOptions::default()
    };
    for (run, q_amp) in [(&absolute, 0.18), (&relative, 0.6 * 0.3)] {
        let lib = Fretting::solve(&contact, q_amp, &options).unwrap();
        let v = json(&run.stdout);
        assert_eq!(v["state"], "shakedown");
        assert_eq!(v["cycle_count"].as_f64(), Some(lib.cycles.len() as f64));
        assert_eq!(v["q_amp_over_p"].as_f64(), Some(q_amp));
        let table = &v["cycles"];
        let column = |key: &str| floats(&table[key]);
        let energy: Vec<f64> = lib.cycles.iter().map(|c| c.dissipation.value).collect();
        assert_eq!(column("energy"), energy);
        let error: Vec<f64> = lib.cycles.iter().map(|c| c.dissipation.error).collect();
        assert_eq!(column("energy_error"), error);
        let c1: Vec<f64> = lib.cycles.iter().map(|c| c.stick_at_minus.0).collect();
        assert_eq!(column("c1_minus"), c1);
        assert_eq!(table["x_f1"][0].as_f64(), Some(lib.cycles[0].f1_peak.x));
        assert!(table["x_f1"][1].is_null(), "no slip in cycle 2: no peak");
        assert_eq!(
            v["first_loading_energy"].as_f64(),
            Some(lib.first_loading_dissipation.value)
        );
    }
    let profile = orthoslip(
        &[
            &on_ply("fretting", &["--amplitude", "0.18", "--profile", "1"])[..],
            &common,
        ]
        .concat(),
    );
    assert_eq!(profile.status, 0, "{}", profile.stderr);
    let lib = Fretting::solve(&contact, 0.18, &options).unwrap();
    let table = &json(&profile.stdout)["profile"];
    assert_eq!(floats(&table["x"]), lib.nodes);
    assert_eq!(
        floats(&table["slip_amplitude"]),
        lib.cycles[0].slip_amplitude
    );
    assert_eq!(floats(&table["f2"]), lib.cycles[0].f2);
    let fretting = |extra: &[&'static str]| {
        let args = [
            &on_ply(
                "fretting",
                &["--mu", "0.3", "--panels", "8", "--steps", "2"],
            )[..],
            extra,
        ]
        .concat();
        orthoslip(&args)
    };
    for (extra, status, words) in [
        (&["--amplitude", "0.3"][..], 2, "gross sliding"),
        (&["--amplitude", "-0.1"][..], 2, "must be > 0"),
        (&["--amplitude", "nan"][..], 2, "not finite"),
        (&["--relative-amplitude", "1"][..], 2, "gross sliding"),
        (
            &["--amplitude", "0.1", "--profile", "9"][..],
            2,
            "--profile 9",
        ),
        (
            &["--amplitude", "0.1", "--relative-amplitude", "0.1"][..],
            2,
            "cannot be used with",
        ),
        (&[][..], 2, "required"),
    ] {
        let run = fretting(extra);
        assert_eq!(run.status, status, "{extra:?}: {}", run.stderr);
        assert_eq!(run.stderr.lines().count(), 1, "{}", run.stderr);
        assert!(run.stderr.contains(words), "{extra:?}: {}", run.stderr);
    }
    // strong coupling at a large amplitude: the pressure turns negative (lift-off)
    let lift = orthoslip(&[
        "fretting",
        "--effective",
        "1",
        "-0.6",
        "1",
        "1",
        "--mu",
        "2",
        "--relative-amplitude",
        "0.9",
        "--panels",
        "16",
        "--steps",
        "2",
    ]);
    assert_eq!(lift.status, 1, "{}", lift.stderr);
    assert!(
        lift.stderr.contains("no admissible solution"),
        "{}",
        lift.stderr
    );
    let help = orthoslip(&["fretting", "--help"]);
    for words in [
        "--amplitude <Q/P>",
        "--relative-amplitude",
        "--max-cycles <N>",
        "--profile <K>",
    ] {
        assert!(
            help.stdout.contains(words),
            "fretting --help lacks {words:?}"
        );
    }
}
