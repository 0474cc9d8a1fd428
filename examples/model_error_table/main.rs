//! Regenerates `src/model_error/table.rs`: the model error of Goodman's and Spence's
//! approximations on a grid of (b*, log10 mu~), against COUPLED solutions to 1e-10
//! ([`generator`]; `tests/model_error_table.rs` re-runs it on part of the committed grid).
//!
//! Run: `cargo run --release --example model_error_table` (one command; it prints its
//! runtime and how many entries are inf, i.e. where COUPLED failed).
//!
//! The grid spans b* = 0.005 .. 0.99 and mu~ = 1e-6 .. 1e6. The errors change fastest where
//! the stick zone opens, around mu~ ~ b* (Goodman's c depends on b* / mu~ only, docs/theory.md
//! (G1)), so log10 mu~ steps by 0.2 over -4 .. 1, which holds that transition for every
//! b* of the grid, and more coarsely outside (c ~ 0 below; above, 1 - c settles towards its
//! large-friction limit). At small b* that transition moves with log10 b*, so the rows there
//! are spaced geometrically (factors up to 1.5); the rows close to b* = 1 are denser too.

mod generator;
#[path = "../support/mod.rs"]
mod support;

fn main() -> std::io::Result<()> {
    let b_star: Vec<f64> = [0.005, 0.0075, 0.01, 0.015, 0.02, 0.03, 0.04, 0.05, 0.075]
        .into_iter()
        .chain((2..=18).map(|i| i as f64 / 20.0))
        .chain([0.925, 0.95, 0.97, 0.98, 0.99])
        .collect();
    let log10_mu: Vec<f64> = [-6.0, -5.0, -4.5]
        .into_iter()
        .chain((-20..=5).map(|i| i as f64 / 5.0))
        .chain((5..=12).map(|i| i as f64 / 4.0))
        .chain((7..=12).map(|i| i as f64 / 2.0))
        .collect();
    let t = std::time::Instant::now();
    let source = generator::table_source(&b_star, &log10_mu);
    std::fs::write("src/model_error/table.rs", source.as_bytes())?;
    let inf = source.matches("f64::INFINITY").count();
    println!(
        "wrote src/model_error/table.rs ({} x {} points, {inf} inf entries in its tables) in \
         {:.1?} (wall clock, {} threads)",
        b_star.len(),
        log10_mu.len(),
        t.elapsed(),
        std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    Ok(())
}
