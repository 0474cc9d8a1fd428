//! The committed model-error table (`src/model_error/table.rs`) is what its generator
//! (`examples/model_error_table/generator.rs`) computes now.

#[allow(dead_code)]
#[path = "../examples/model_error_table/generator.rs"]
mod generator;

use generator::{round_up, sample};
use orthoslip::model_error::{Approximation, B_STAR, FLOOR, LOG10_MU, tabulated};

#[test]
fn committed_table_matches_a_fresh_computation() {
    // Every 13th entry (row and column both vary): 24 COUPLED solves.
    let mut checked = 0;
    for idx in (0..B_STAR.len() * LOG10_MU.len()).step_by(13) {
        let (i, j) = (idx / LOG10_MU.len(), idx % LOG10_MU.len());
        let fresh = sample(B_STAR[i], 10f64.powf(LOG10_MU[j]));
        for (a, pick) in [
            (Approximation::Goodman, fresh.as_ref().map(|s| s.goodman)),
            (Approximation::Spence, fresh.as_ref().map(|s| s.spence)),
        ] {
            let stored = tabulated(a)[i][j];
            match pick {
                Ok(e) => {
                    assert!(
                        (stored - round_up(e)).abs() <= 0.1 * e + 2.0 * FLOOR,
                        "{a:?} at b* = {}, log10 mu~ = {}: table {stored:e}, fresh {e:e} \
                         (regenerate: cargo run --release --example model_error_table)",
                        B_STAR[i],
                        LOG10_MU[j]
                    );
                    checked += 1;
                }
                Err(_) => assert!(stored.is_infinite()),
            }
        }
    }
    assert!(checked > 20, "only {checked} finite entries checked");
}
