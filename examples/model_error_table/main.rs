//! Regenerates `src/model_error/table.rs`: the model error of Goodman's and Spence's
//! approximations on a grid of (b*, log10 mu~), against COUPLED solutions to 1e-10
//! ([`generator`]; `tests/model_error_table.rs` re-runs it on the committed grid).
//!
//! Run: `cargo run --release --example model_error_table`.

mod generator;

fn main() -> std::io::Result<()> {
    let b_star: Vec<f64> = (1..=19).map(|i| i as f64 / 20.0).collect();
    let log10_mu: Vec<f64> = (-5..=10).map(|i| i as f64 / 5.0).collect();
    let t = std::time::Instant::now();
    let source = generator::table_source(&b_star, &log10_mu);
    std::fs::write("src/model_error/table.rs", source)?;
    println!(
        "wrote src/model_error/table.rs ({} x {} points) in {:.1?}",
        b_star.len(),
        log10_mu.len(),
        t.elapsed()
    );
    Ok(())
}
