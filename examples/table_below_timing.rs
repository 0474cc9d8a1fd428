//! COUPLED below b* = 0.25, where the stick-edge table's strips below b* = 0.25 reach
//! (docs/theory_spectral.md (S7)): at 8 reduced couplings inside those strips, c alone (traction
//! tolerance +infinity, c to 1e-10) and the full answer (c to 1e-10, tractions to 1e-8), each
//! the median CPU time of the thread over repeated solves, with the regime that answered and
//! its level or order. Run it on the commit before the table's strips below b* = 0.25 and on
//! the one after for the before and after of docs/theory_spectral.md (S7).
//!
//! `cargo run --release --example table_below_timing`
mod support;

use orthoslip::coupled::{CoupledSolution, solve_to};
use orthoslip::problem::{Coupling, Profile};
use support::clock::{cpu_seconds, median, repeated};

/// Median CPU time of repeated solves (at least 5, up to 0.3 s or 2000) and the last answer.
fn time(f: impl Fn() -> CoupledSolution) -> (f64, CoupledSolution) {
    repeated(cpu_seconds, 0.3, 2000, f)
}

fn main() {
    // the six scenes of coupled::tests::spectral_agrees_with_the_panels_from_the_table_below
    // (c = 4.4e-5 .. 1 - 1.2e-4) and two mid-range ones
    let scenes = [
        (0.02, 0.0176),
        (0.05, 0.0721),
        (0.07, 0.05),
        (0.1, 0.0281),
        (0.12, 0.15),
        (0.15, 0.4722),
        (0.2, 0.0281),
        (0.24, 1.2089),
    ];
    println!(
        "| b* | mu~ | c | 1 - c | c alone: regime | time | full answer: regime, level/order | time |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let (mut alone, mut full) = (Vec::new(), Vec::new());
    for (b, mu) in scenes {
        let k = Coupling { bp: b, bq: b, mu };
        let (ta, a) = time(|| solve_to(&k, 1e-10, f64::INFINITY).expect("c alone"));
        let (tf, f) = time(|| solve_to(&k, 1e-10, 1e-8).expect("full answer"));
        let e = f.edge();
        println!(
            "| {b} | {mu} | {:.4e} | {:.2e} | {} | {:.1} µs | {}, {} | {:.2} ms |",
            e.c,
            e.one_minus_c,
            a.regime(),
            ta * 1e6,
            f.regime(),
            f.order(),
            tf * 1e3
        );
        assert!(a.edge().distance(e) <= a.numerical_error() + f.numerical_error());
        alone.push(ta);
        full.push(tf);
    }
    println!(
        "\nmedians: c alone {:.1} µs, full answer {:.2} ms",
        median(alone) * 1e6,
        median(full) * 1e3
    );
}
