//! `orthoslip solve`: one scene; c, 1 - c, the method used, its error estimate and the
//! tractions at the midpoints of equal cells of the punch.

use std::io::Write;

use super::args::{SolveArgs, method_name};
use super::report::{Name, Report, Value, name};
use super::{Failure, Scene};

pub const ONE_MINUS_C: Name = Name {
    key: "one_minus_c",
    label: "1 - c",
};
pub const ERROR_ESTIMATE: Name = Name {
    key: "error_estimate",
    label: "error estimate",
};

pub const TRACTION_ERROR_ESTIMATE: Name = Name {
    key: "traction_error_estimate",
    label: "traction error estimate",
};

/// Solves the scene and writes the report.
pub fn run(args: &SolveArgs, out: &mut impl Write) -> Result<(), Failure> {
    let Scene {
        mut contact,
        mut fields,
    } = Scene::new(&args.scene)?;
    contact.set_friction(args.mu)?;
    let s = contact.solve()?;
    fields.insert(2, (name("mu"), args.mu.into()));
    fields.extend([
        (name("c"), s.c().into()),
        (ONE_MINUS_C, s.one_minus_c().into()),
        (name("method"), method_name(s.method()).into()),
        (ERROR_ESTIMATE, s.error_estimate().into()),
        (TRACTION_ERROR_ESTIMATE, s.traction_error_estimate().into()),
    ]);
    let n = args.points;
    let rows = (0..n)
        .map(|i| {
            // (2i + 1 - n)/n: exact numerators, so the points are exactly symmetric.
            let x = (f64::from(2 * i + 1) - f64::from(n)) / f64::from(n);
            let (p, q) = s.tractions(x);
            let zone = if x.abs() < s.c() { "stick" } else { "slip" };
            vec![x.into(), p.into(), q.into(), Value::from(zone)]
        })
        .collect();
    let report = Report {
        fields,
        table_key: "tractions",
        columns: vec![name("x"), name("p"), name("q"), name("zone")],
        rows,
    };
    report.write(args.format, out)?;
    Ok(())
}
