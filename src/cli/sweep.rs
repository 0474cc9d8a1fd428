//! `orthoslip sweep`: c, 1 - c, the method used and its error estimates against the friction
//! coefficient, one solve per mu. A failed solve leaves its row empty but for its status and
//! does not stop the sweep.

use std::io::Write;

use super::args::{Spacing, SweepArgs, method_name};
use super::report::{Report, Value, name};
use super::solve::{ERROR_ESTIMATE, ONE_MINUS_C, TRACTION_ERROR_ESTIMATE};
use super::{Failure, Scene, status_of};

/// The friction coefficients: `steps` values from `from` to `to`, both ends exactly, equally
/// spaced in mu or in log10(mu) (so that decades fall on round numbers).
fn grid(from: f64, to: f64, steps: u32, spacing: Spacing) -> Vec<f64> {
    let last = steps - 1;
    // (a (last - i) + b i) / last: exact wherever a and b are small integers.
    let between =
        |a: f64, b: f64, i: u32| (a * f64::from(last - i) + b * f64::from(i)) / f64::from(last);
    (0..steps)
        .map(|i| match i {
            0 => from,
            i if i == last => to,
            i => match spacing {
                Spacing::Log => 10f64.powf(between(from.log10(), to.log10(), i)),
                Spacing::Linear => between(from, to, i),
            },
        })
        .collect()
}

/// Solves every friction coefficient and writes the report; fails (after writing it) when
/// any solve failed.
pub fn run(args: &SweepArgs, out: &mut impl Write) -> Result<(), Failure> {
    let Scene {
        mut contact,
        mut fields,
    } = Scene::new(&args.scene)?;
    // The ends are checked by the library before anything is solved.
    contact.set_friction(args.mu_from)?;
    contact.set_friction(args.mu_to)?;
    if args.spacing == Spacing::Log && !(args.mu_from > 0.0 && args.mu_to > 0.0) {
        return Err(Failure::Input(
            "--spacing log needs --mu-from and --mu-to > 0 (--spacing linear may start at 0)"
                .into(),
        ));
    }
    let spacing = match args.spacing {
        Spacing::Log => "log",
        Spacing::Linear => "linear",
    };
    fields.push((name("spacing"), spacing.into()));
    let mut failed = Vec::new();
    let rows = grid(args.mu_from, args.mu_to, args.steps, args.spacing)
        .into_iter()
        .map(|mu| {
            let solved = contact.set_friction(mu).and_then(|()| contact.solve());
            match solved {
                Ok(s) => vec![
                    mu.into(),
                    s.c().into(),
                    s.one_minus_c().into(),
                    method_name(s.method()).into(),
                    s.error_estimate().into(),
                    s.traction_error_estimate().into(),
                    "ok".into(),
                ],
                Err(e) => {
                    let row = vec![
                        mu.into(),
                        Value::Missing,
                        Value::Missing,
                        Value::Missing,
                        Value::Missing,
                        Value::Missing,
                        Value::Text(status_of(&e)),
                    ];
                    failed.push(format!("mu = {mu:?}: {e}"));
                    row
                }
            }
        })
        .collect();
    let report = Report {
        fields,
        table_key: "sweep",
        columns: vec![
            name("mu"),
            name("c"),
            ONE_MINUS_C,
            name("method"),
            ERROR_ESTIMATE,
            TRACTION_ERROR_ESTIMATE,
            name("status"),
        ],
        rows,
    };
    report.write(args.format, out)?;
    match failed.first() {
        None => Ok(()),
        Some(first) => Err(Failure::Solver(format!(
            "{} of {} solves failed; the first at {first}",
            failed.len(),
            args.steps
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_hit_both_ends_and_space_evenly() {
        assert_eq!(grid(0.01, 10.0, 4, Spacing::Log), [0.01, 0.1, 1.0, 10.0]);
        let g = grid(0.3, 0.03, 3, Spacing::Log);
        assert_eq!((g[0], g[2]), (0.3, 0.03));
        assert!((g[1] - 0.3 / 10f64.sqrt()).abs() < 1e-16, "{g:?}");
        assert_eq!(
            grid(0.0, 1.0, 5, Spacing::Linear),
            [0.0, 0.25, 0.5, 0.75, 1.0]
        );
        assert_eq!(grid(2.0, 1.0, 2, Spacing::Linear), [2.0, 1.0]);
    }
}
