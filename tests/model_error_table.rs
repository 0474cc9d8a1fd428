//! The model-error table behind the approximations' error estimates and AUTO
//! (`src/model_error/`): the committed table is what its generator
//! (`examples/model_error_table/generator.rs`) computes now, and the empirical bound it gives
//! holds at random points the table was not built from.
//!
//! The fast tier (`cargo test --release`) recomputes five entries and checks both bounds at 12
//! random points each; the slow tier (`cargo test --release -- --ignored`) does the rest.
//! What the slow tier covers, to stay within a few minutes on 2 cores: the entries of every fifth
//! diagonal of the grid (rows i and columns j with (2 i + j) mod 5 = 0, about a fifth of
//! the entries, spread over every row and every column) and every row's first and last
//! column (with the bounds below and above the tabulated friction range); then the bounds on
//! c and on the tractions at 200 random points each, uniform in the grid's cells (a cell
//! drawn at random, then a point in it; `ORTHOSLIP_OFF_GRID_POINTS` sets another count, for
//! the measurement quoted in `src/model_error/mod.rs`).

#[allow(dead_code)]
#[path = "../examples/model_error_table/generator.rs"]
mod generator;
#[path = "../examples/support/mod.rs"]
mod support;

use generator::{REFERENCE_TRACTION_TOL, round_up, samples};
use orthoslip::model_error::{
    Approximation, B_STAR, FLOOR, LOG10_MU, TRACTION_FLOOR, bound, tabulated, tabulated_beyond,
    tabulated_tractions, traction_bound,
};
use orthoslip::problem::traction_distance;
use orthoslip::{Contact, Coupling, Material, Method, Profile, coupled, goodman, spence};

/// Random points of each validation, unless `ORTHOSLIP_OFF_GRID_POINTS` says otherwise.
fn points() -> usize {
    std::env::var("ORTHOSLIP_OFF_GRID_POINTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(200)
}

/// Tolerance on c of the COUPLED reference at those points (a tenth of the [`FLOOR`] every
/// bound adds); its tractions are asked to the generator's [`REFERENCE_TRACTION_TOL`], a tenth
/// of [`TRACTION_FLOOR`].
const REFERENCE_TOL: f64 = 1e-11;

/// A random point of the grid `g`: a cell drawn uniformly, then a uniform point inside it (so
/// the points are as dense as the grid, which is densest where the errors vary fast).
fn off_grid(rng: &mut fastrand::Rng, g: &[f64]) -> f64 {
    let i = rng.usize(..g.len() - 1);
    g[i] + (g[i + 1] - g[i]) * rng.f64()
}

/// A fresh value against the committed one: equal after rounding up to two digits (to 10%
/// of the value plus the reference's accuracy).
fn assert_matches(what: &str, stored: f64, fresh: f64) {
    let floor = if what.contains("tractions") {
        TRACTION_FLOOR
    } else {
        FLOOR
    };
    assert!(
        (stored - round_up(fresh)).abs() <= 0.1 * fresh + 2.0 * floor,
        "{what}: table {stored:e}, fresh {fresh:e} \
         (regenerate: cargo run --release --example model_error_table)"
    );
}

/// The entries of every fifth diagonal and of the first and last columns (see the top of
/// the file): COUPLED solves at 1e-10, the model errors of both approximations, and the
/// bounds below and above the tabulated friction range.
#[test]
#[ignore = "slow tier: regenerates a fifth of the model-error table (COUPLED at 1e-10)"]
fn committed_table_matches_a_fresh_computation() {
    let last = LOG10_MU.len() - 1;
    table_matches(|i, j| (2 * i + j) % 5 == 0 || j == 0 || j == last);
}

/// The fast tier's share of [`committed_table_matches_a_fresh_computation`]: one row's first,
/// middle and last entries (with the bounds below and above the friction range) and the
/// middle column of the first and last rows.
#[test]
fn committed_table_matches_at_a_few_entries() {
    let (rows, last) = (B_STAR.len(), LOG10_MU.len() - 1);
    let (mid_row, mid) = (rows / 2, last / 2);
    table_matches(|i, j| {
        (i == mid_row && (j == 0 || j == mid || j == last))
            || ((i == 0 || i == rows - 1) && j == mid)
    });
}

/// The entries (i, j) that `take` selects against a fresh computation.
fn table_matches(take: impl Fn(usize, usize) -> bool) {
    let (below, above) = tabulated_beyond();
    let last = LOG10_MU.len() - 1;
    let entries: Vec<(usize, usize)> = (0..B_STAR.len())
        .flat_map(|i| (0..=last).map(move |j| (i, j)))
        .filter(|&(i, j)| take(i, j))
        .collect();
    let points: Vec<(f64, f64)> = entries
        .iter()
        .map(|&(i, j)| (B_STAR[i], LOG10_MU[j]))
        .collect();
    let fresh = samples(&points);
    let mut finite = 0;
    for (&(i, j), s) in entries.iter().zip(fresh) {
        let (b, l) = (B_STAR[i], LOG10_MU[j]);
        let at = format!("b* = {b}, log10 mu~ = {l}");
        let [g, sp] = [Approximation::Goodman, Approximation::Spence];
        let stored = [
            tabulated(g)[i][j],
            tabulated(sp)[i][j],
            tabulated_tractions(g)[i][j],
            tabulated_tractions(sp)[i][j],
        ];
        match s {
            Some(s) => {
                assert_matches(&format!("Goodman at {at}"), stored[0], s.goodman);
                assert_matches(&format!("Spence at {at}"), stored[1], s.spence);
                let t = (s.goodman_tractions, s.spence_tractions);
                assert_matches(&format!("Goodman's tractions at {at}"), stored[2], t.0);
                assert_matches(&format!("Spence's tractions at {at}"), stored[3], t.1);
                if j == 0 {
                    assert_matches(&format!("largest c at {at}"), below[i], s.max_c);
                }
                if j == last {
                    let w = s.max_one_minus_c;
                    assert_matches(&format!("largest 1 - c at {at}"), above[i], w);
                }
                finite += 1;
            }
            None => {
                let beyond = [(j == 0, below[i]), (j == last, above[i])];
                assert!(
                    stored.iter().all(|v| v.is_infinite())
                        && beyond.iter().all(|&(edge, v)| !edge || v.is_infinite()),
                    "{at}: the reference fails now, the table has {stored:?}"
                );
            }
        }
    }
    println!(
        "{finite} of {} recomputed entries (of {}) finite and equal to a fresh computation",
        entries.len(),
        B_STAR.len() * LOG10_MU.len()
    );
    assert!(finite >= entries.len() / 2, "only {finite} finite entries");
}

/// The bound is empirical (twice the largest tabulated error at the corners of the grid
/// cell, plus FLOOR), so it is checked where the table knows nothing: at random (b*, mu~)
/// inside its range ([`off_grid`], fixed seed), against COUPLED's c to 1e-11 (c alone: where
/// they meet that, the tabulated stick edge or a closed-form limit).
#[test]
#[ignore = "slow tier: the bound on c at 200 random points against COUPLED at 1e-11"]
fn empirical_bound_holds_off_the_grid() {
    bound_holds_at(points(), 20_240_607);
}

/// The fast tier's share of [`empirical_bound_holds_off_the_grid`]: 12 random points (their
/// own seed).
#[test]
fn empirical_bound_holds_at_a_few_points() {
    bound_holds_at(12, 20_261_126);
}

/// The bound on c at `n` random points from `seed` (drawn in turn, solved over the machine's
/// cores).
fn bound_holds_at(n: usize, seed: u64) {
    let mut rng = fastrand::Rng::with_seed(seed);
    let points: Vec<(f64, f64)> = (0..n)
        .map(|_| {
            let b = off_grid(&mut rng, &B_STAR);
            (b, 10f64.powf(off_grid(&mut rng, &LOG10_MU)))
        })
        .collect();
    // per point: None without a reference, else per approximation its error and bound
    let errors = support::parallel::map(&points, |&(b, mu)| {
        let k = Coupling { bp: b, bq: b, mu };
        let exact = coupled::solve_to(&k, REFERENCE_TOL, f64::INFINITY).ok()?;
        let edges = [
            (Approximation::Goodman, goodman::solve(&k).unwrap().edge()),
            (Approximation::Spence, spence::solve(&k).unwrap().edge()),
        ];
        Some(edges.map(|(a, approx)| (a, approx.distance(exact.edge()), bound(a, &k))))
    });
    let mut compared = [0usize; 2];
    let mut no_bound = [0usize; 2];
    let mut no_reference = 0;
    let mut worst = [(0.0_f64, 0.0, 0.0); 2];
    for (&(b, mu), errors) in points.iter().zip(errors) {
        let Some(errors) = errors else {
            no_reference += 1;
            continue;
        };
        for (n, (a, err, bd)) in errors.into_iter().enumerate() {
            let Some(bd) = bd else {
                no_bound[n] += 1;
                continue;
            };
            assert!(
                err <= bd,
                "{a:?} at b* = {b}, mu~ = {mu}: error {err:e} above the bound {bd:e}"
            );
            compared[n] += 1;
            if err / bd > worst[n].0 {
                worst[n] = (err / bd, b, mu);
            }
        }
    }
    for (n, name) in ["Goodman", "Spence"].iter().enumerate() {
        let (ratio, b, mu) = worst[n];
        println!(
            "{name}: bound held at {} random points ({} without a bound, {no_reference} \
             without a reference); worst error / bound {ratio:.3} at b* = {b:.4}, mu~ = {mu:.4}",
            compared[n], no_bound[n]
        );
    }
    assert!(compared.iter().all(|&c| c >= n / 2), "{compared:?}");
}

/// The traction bound, like the bound on c, where the table knows nothing: at random
/// (b*, mu~) over its cells ([`off_grid`]) and one decade below its first column (where the
/// first column's values are used), and in materials with delta != 1 (the bound
/// scales with 1 + delta), through `Contact` (the solution's traction estimate) against
/// COUPLED (`problem::traction_distance`), c to 1e-11 and the tractions to a tenth of
/// [`TRACTION_FLOOR`].
#[test]
#[ignore = "slow tier: the traction bound at 200 random points against COUPLED"]
fn empirical_traction_bound_holds_off_the_grid() {
    traction_bound_holds_at(points(), 20_261_123);
}

/// The fast tier's share of [`empirical_traction_bound_holds_off_the_grid`]: 12 random points
/// (their own seed; two with delta != 1).
#[test]
fn empirical_traction_bound_holds_at_a_few_points() {
    traction_bound_holds_at(12, 20_261_126);
}

/// The traction bound at `n` random points from `seed` (drawn in turn, solved over the
/// machine's cores).
fn traction_bound_holds_at(n: usize, seed: u64) {
    let mut rng = fastrand::Rng::with_seed(seed);
    let columns: Vec<f64> = std::iter::once(LOG10_MU[0] - 1.0).chain(LOG10_MU).collect();
    let points: Vec<(f64, f64, f64)> = (0..n)
        .map(|i| {
            let b = off_grid(&mut rng, &B_STAR);
            let mu_tilde = 10f64.powf(off_grid(&mut rng, &columns));
            // reduced scenes (delta = 1) and every third one with delta = 0.3 or 3 (E = 1,
            // kappa = 1: b* = (1 - nu) / 2)
            (b, mu_tilde, [1.0, 1.0, 0.3, 1.0, 1.0, 3.0][i % 6])
        })
        .collect();
    // per point and method: the traction error and its estimate, None where either is missing
    let errors = support::parallel::map(&points, |&(b, mu_tilde, delta)| {
        let m = Material::effective(1.0, 1.0 - 2.0 * b, delta, 1.0).unwrap();
        let k = m.coupling(1.0);
        let mu = mu_tilde * (k.bq / k.bp).sqrt();
        let k = m.coupling(mu);
        let Ok(exact) = coupled::solve_to(&k, REFERENCE_TOL, REFERENCE_TRACTION_TOL) else {
            return [None, None];
        };
        [Method::Goodman, Method::Spence].map(|method| {
            let mut contact = Contact::new(m);
            contact.set_friction(mu).unwrap();
            contact.set_method(method);
            let s = contact
                .solve()
                .unwrap_or_else(|e| panic!("{method:?} at {k:?}: {e}"));
            let est = s.traction_error_estimate();
            (!est.is_infinite()).then(|| (method, traction_distance(s.profile(), &exact), est))
        })
    });
    let mut worst = [(0.0_f64, 0.0, 0.0, 0.0); 2];
    let mut compared = [0usize; 2];
    for (&(b, mu_tilde, delta), errors) in points.iter().zip(errors) {
        for (n, e) in errors.into_iter().enumerate() {
            let Some((method, err, est)) = e else {
                continue;
            };
            assert!(
                err <= est,
                "{method:?} at b* = {b}, mu~ = {mu_tilde}, delta = {delta}: traction error \
                 {err:e} above the estimate {est:e}"
            );
            compared[n] += 1;
            if err / est > worst[n].0 {
                worst[n] = (err / est, b, mu_tilde, delta);
            }
        }
    }
    for (n, name) in ["Goodman", "Spence"].iter().enumerate() {
        let (r, b, mu, delta) = worst[n];
        println!(
            "{name}: traction bound held at {} random points; worst error / bound {r:.3} at \
             b* = {b:.4}, mu~ = {mu:.4}, delta = {delta}",
            compared[n]
        );
    }
    assert!(compared.iter().all(|&c| c >= n / 2), "{compared:?}");
    // The bound exists exactly where the table says: none above its last column.
    let k = Coupling {
        bp: 0.2,
        bq: 0.2,
        mu: 10f64.powf(LOG10_MU[LOG10_MU.len() - 1] + 0.5),
    };
    assert_eq!(traction_bound(Approximation::Goodman, &k), None);
}
