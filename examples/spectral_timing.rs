//! COUPLED as it runs (the spectral solver on global bases per zone where it serves,
//! docs/theory_spectral.md) against the panels alone (`coupled::solve_panels_to`, the
//! independent discretisation it falls back to), on the 12 scenes of
//! examples/speed_accuracy.rs, in one run: per scene the
//! regime that answered, the unknowns, the time per solve (median of repeated solves, wall
//! time) and the distance between the two answers' c and tractions; then the medians and
//! their ratio. Writes docs/spectral_timing.md.
//!
//! `cargo run --release --example spectral_timing`
mod support;

use std::time::{Duration, Instant};

use orthoslip::Result;
use orthoslip::coupled::{CoupledSolution, solve_panels_to, solve_to};
use orthoslip::problem::{Profile, traction_distance};
use support::clock::{median, repeated};

/// Median wall time over repeated solves (at least 5 runs, then up to 0.3 s or 200).
fn time(f: impl Fn() -> Result<CoupledSolution>) -> (Duration, Result<CoupledSolution>) {
    let start = Instant::now();
    let (t, last) = repeated(|| start.elapsed().as_secs_f64(), 0.3, 200, f);
    (Duration::from_secs_f64(t), last)
}

fn main() {
    let mut out = String::from(
        "# COUPLED: spectral solver against the panels\n\n\
         Written by `cargo run --release --example spectral_timing` (one run, both solvers \
         timed alternately on the same machine; wall time, median of repeated solves).\n\n",
    );
    for (tol, ttol) in [(1e-10, 1e-8), (1e-10, 1e-10)] {
        out += &format!(
            "## c to {tol:.0e}, tractions to {ttol:.0e}\n\n| scene | spectral: regime, unknowns | time | panels: unknowns | time | ratio | c distance | traction distance |\n|---|---|---|---|---|---|---|---|\n"
        );
        let (mut ts, mut tp) = (Vec::new(), Vec::new());
        for (name, m) in support::scene_materials() {
            for mu in [0.1, 0.3, 1.0] {
                let k = m.coupling(mu);
                let (a, sa) = time(|| solve_to(&k, tol, ttol));
                let (b, sb) = time(|| solve_panels_to(&k, tol, ttol));
                let (a, b) = (a.as_secs_f64(), b.as_secs_f64());
                let row = match (&sa, &sb) {
                    (Ok(s), Ok(p)) => {
                        ts.push(a);
                        tp.push(b);
                        format!(
                            "| {name}, mu = {mu} | {}, {} | {:.3} ms | {} | {:.3} ms | {:.2} | {:.1e} | {:.1e} |",
                            s.regime(),
                            s.unknowns(),
                            1e3 * a,
                            p.unknowns(),
                            1e3 * b,
                            b / a,
                            s.edge().distance(p.edge()),
                            traction_distance(s, p)
                        )
                    }
                    _ => format!(
                        "| {name}, mu = {mu} | {:?} | | {:?} | | | | |",
                        sa.as_ref().map(|s| s.regime()).map_err(|e| e.to_string()),
                        sb.as_ref().map(|s| s.unknowns()).map_err(|e| e.to_string())
                    ),
                };
                println!("{row}");
                out += &row;
                out += "\n";
            }
        }
        let (ms, mp) = (median(ts), median(tp));
        let line = format!(
            "\nMedian over the scenes: COUPLED (spectral first) {:.3} ms, panels alone {:.3} ms (ratio {:.2}).\n\n",
            1e3 * ms,
            1e3 * mp,
            mp / ms
        );
        print!("{line}");
        out += &line;
    }
    std::fs::write(
        concat!(env!("CARGO_MANIFEST_DIR"), "/docs/spectral_timing.md"),
        out,
    )
    .expect("docs/spectral_timing.md");
}
