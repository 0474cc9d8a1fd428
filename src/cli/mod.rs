//! The `orthoslip` command-line tool over the library's public Rust API: the default scene
//! without arguments ([`scene`]), `solve` ([`solve`]), `sweep` ([`sweep`]) and `fretting`
//! ([`fretting`]); the command line is declared in [`args`], the output formats in
//! [`report`].
//!
//! Exit status: 0 success, 1 solver failure (or output not written), 2 bad input; every error
//! is one line on stderr.

mod args;
mod fretting;
mod report;
mod scene;
mod solve;
mod sweep;

use std::io::{self, BufWriter, Write};
use std::process::ExitCode;

use clap::Parser;
use clap::error::ErrorKind;
use orthoslip::{Contact, Error};

use args::{Cli, Command, SceneArgs, method_name};
use report::{Name, Value, name};

/// Why a command failed, deciding the exit status.
#[derive(Debug)]
pub enum Failure {
    /// The command line or a value the library rejects (exit status 2).
    Input(String),
    /// A solve failed (exit status 1).
    Solver(String),
    /// The output could not be written (exit status 1; a closed pipe is not an error).
    Output(io::Error),
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        match e {
            Error::InvalidArgument(_) | Error::InadmissibleMaterial(_) => {
                Failure::Input(e.to_string())
            }
            _ => Failure::Solver(e.to_string()),
        }
    }
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        Failure::Output(e)
    }
}

/// The kind of a library error as a status word, e.g. `no_convergence` (the text before the
/// first colon of its message).
pub fn status_of(e: &Error) -> String {
    let message = e.to_string();
    let kind = message.split(':').next().unwrap_or_default();
    kind.trim().replace(' ', "_")
}

/// A contact built from the command line, and the fields that describe it in a report.
pub struct Scene {
    pub contact: Contact,
    pub fields: Vec<(Name, Value)>,
}

impl Scene {
    fn new(args: &SceneArgs) -> Result<Self, Failure> {
        let given = args.material.material()?;
        let k = given.material.constants();
        let mut contact = Contact::new(given.material);
        let method = args.method.into();
        contact.set_method(method);
        contact.set_tolerance(args.tol)?;
        if let Some(t) = args.traction_tol {
            contact.set_traction_tolerance(t)?;
        }
        let mut material = vec![("model", Value::from(given.model))];
        material.extend(given.constants.into_iter().map(|(key, v)| (key, v.into())));
        let effective = [
            ("E", k.e),
            ("nu", k.nu),
            ("delta", k.delta),
            ("kappa", k.kappa),
        ];
        let fields = vec![
            (name("material"), Value::Group(material)),
            (
                name("effective"),
                Value::Group(effective.map(|(key, v)| (key, v.into())).to_vec()),
            ),
            (
                Name {
                    key: "method_requested",
                    label: "method requested",
                },
                method_name(method).into(),
            ),
            (name("tolerance"), args.tol.into()),
            (
                Name {
                    key: "traction_tolerance",
                    label: "traction tolerance",
                },
                contact.traction_tolerance().into(),
            ),
        ];
        Ok(Self { contact, fields })
    }
}

/// Parses the command line, runs it and reports failures; the process's exit status.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return command_line_error(e),
    };
    let mut out = BufWriter::new(io::stdout().lock());
    let done = match &cli.command {
        None => scene::run(&mut out).map_err(Failure::from),
        Some(Command::Solve(a)) => solve::run(a, &mut out),
        Some(Command::Sweep(a)) => sweep::run(a, &mut out),
        Some(Command::Fretting(a)) => fretting::run(a, &mut out),
    };
    // Flush what was written, also before reporting a failure.
    let flushed = out.flush().map_err(Failure::from);
    match done.and(flushed) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(Failure::Output(e)) => fail(1, &format!("cannot write the output: {e}")),
        Err(Failure::Solver(m)) => fail(1, &m),
        Err(Failure::Input(m)) => fail(2, &m),
    }
}

/// Help and version go to stdout with status 0; a usage error becomes one line and status 2.
fn command_line_error(e: clap::Error) -> ExitCode {
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        return match e.print() {
            Ok(()) => ExitCode::SUCCESS,
            Err(_) => ExitCode::from(1),
        };
    }
    // clap's message is the first paragraph (the usage and tips follow a blank line).
    let rendered = e.render().to_string();
    let first = rendered.split("\n\n").next().unwrap_or_default();
    let words: Vec<&str> = first.split_whitespace().collect();
    let message = words.join(" ");
    let message = message.strip_prefix("error: ").unwrap_or(&message);
    fail(2, &format!("{message} (try --help)"))
}

/// Writes `orthoslip: message` as one line on stderr and returns the exit status.
fn fail(status: u8, message: &str) -> ExitCode {
    let line: Vec<&str> = message.lines().map(str::trim).collect();
    eprintln!("orthoslip: {}", line.join(" "));
    ExitCode::from(status)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each kind of library error has its status word and exit class: bad input exits 2,
    /// every solver failure (the inadmissible root included) exits 1.
    #[test]
    fn library_errors_get_their_status_word_and_exit_class() {
        let text = || "x".to_owned();
        let cases = [
            (Error::InvalidArgument(text()), "invalid_argument", true),
            (
                Error::InadmissibleMaterial(text()),
                "inadmissible_material",
                true,
            ),
            (Error::NoConvergence(text()), "no_convergence", false),
            (
                Error::ToleranceNotMet {
                    estimate: 2.0,
                    tolerance: 1.0,
                    detail: text(),
                },
                "tolerance_not_met",
                false,
            ),
            (
                Error::NoAdmissibleSolution(text()),
                "no_admissible_solution",
                false,
            ),
            (Error::Internal(text()), "internal_error", false),
        ];
        for (e, word, input) in cases {
            assert_eq!(status_of(&e), word);
            match Failure::from(e) {
                Failure::Input(m) => assert!(input, "{m}"),
                Failure::Solver(m) => assert!(!input, "{m}"),
                Failure::Output(e) => panic!("{e}"),
            }
        }
    }
}
