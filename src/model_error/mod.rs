//! Model error of the closed-form approximations: empirical bounds on |c_approx - c_exact|
//! for Goodman's and Spence's c, and on their traction error
//! ([`crate::problem::traction_distance`]), used for their error estimates and by
//! METHOD_AUTO.
//!
//! c depends on the material and the friction only through (b*, mu~) (docs/theory.md (R2)),
//! for the approximations as for the exact problem, so the model error is a function on that
//! plane. It is measured offline with the COUPLED solver (c to [`FLOOR`], the tractions to a
//! tenth of [`TRACTION_FLOOR`]) on a grid of b* and
//! log10 mu~ (`cargo run --release --example model_error_table` regenerates `table.rs`; the
//! generator lives with that example, outside the library).
//!
//! The grid spans b* = 0.005 .. 0.99 (31 rows, geometric below 0.1 and denser near 1) and
//! mu~ = 1e-6 .. 1e6 (43 columns, log10 mu~ by 0.2 over -4 .. 1, where the stick zone opens
//! at every b* of the grid, and coarser outside; the generator's `main.rs` says why). Entries
//! would be inf where COUPLED failed, and the cells around them give no bound, so AUTO
//! leaves the approximations alone there. Since the regeneration of 2026-11-25 (thin slip
//! zones at large friction extrapolated in 1/mu~, the last 5 columns of b* = 0.1) there are
//! none; the table of 2026-11-23 had 64 of the 1333 points inf (166 before COUPLED's
//! large-friction work), 21 were left after the thin slip zones.
//!
//! The bound at a point is empirical, not certified: [`SAFETY`] times the largest tabulated
//! error at the corners of its grid cell, plus [`FLOOR`] (see [`bound`]). It relies on the
//! errors varying smoothly in b* and log mu~ within a cell (where they change sign they are
//! small). `tests/model_error_table.rs` recomputes a fifth of the committed entries (spread
//! over every row and column) and checks the bounds against COUPLED at random points off the
//! grid, uniform in its cells. Measured at 2000 such points each (against COUPLED at 1e-11,
//! with the table's first generation on 2026-11-23; 1688 and 1685 of them had a reference and
//! a bound), the worst error / bound was 0.505 for Goodman and 0.533 for Spence in c, 0.475 and
//! 0.490 in the tractions; with the regenerated table, at the test's 200 points: 0.505 and
//! 0.486 in c, 0.457 and 0.468 in the tractions.
//!
//! The traction error is tabulated as max(int |dp|, int |dq~|) in the reduced problem
//! (q = delta q~ with the same p, docs/theory.md (R2), (T3)), so that the bound in a material with
//! delta != 1 is (1 + delta) times it ([`traction_bound`]).
//!
//! Why a table and not an a-posteriori residual: the residual of eq. (10) for Goodman's p0 is
//! bp q, known at once, but turning it into a bound on c needs the sensitivity of c to the
//! pressure near the edges, i.e. the coupled solve itself; a table costs a lookup.

#[rustfmt::skip]
mod table;

use crate::problem::Coupling;

/// The closed-form approximations whose model error is tabulated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approximation {
    /// Goodman's approximation.
    Goodman,
    /// Spence's approximation.
    Spence,
}

/// Multiplier on the largest tabulated error of a cell (an empirical safety factor).
pub const SAFETY: f64 = 2.0;

/// Tolerance of the COUPLED reference the table is made with (absolute, in c), added to
/// every bound.
pub const FLOOR: f64 = 1e-10;

pub use table::{B_STAR, LOG10_MU};

/// One approximation's tabulated errors: rows over [`B_STAR`], columns over [`LOG10_MU`].
pub type Grid = [[f64; LOG10_MU.len()]; B_STAR.len()];

/// The tabulated model errors of an approximation in c.
pub fn tabulated(a: Approximation) -> &'static Grid {
    match a {
        Approximation::Goodman => &table::GOODMAN,
        Approximation::Spence => &table::SPENCE,
    }
}

/// The tabulated model errors of an approximation in the tractions (reduced problem).
pub fn tabulated_tractions(a: Approximation) -> &'static Grid {
    match a {
        Approximation::Goodman => &table::GOODMAN_TRACTIONS,
        Approximation::Spence => &table::SPENCE_TRACTIONS,
    }
}

/// Added to every traction bound: ten times the traction tolerance of the COUPLED
/// reference (the generator solves its tractions to 1e-9).
pub const TRACTION_FLOOR: f64 = 1e-8;

/// An empirical bound on the traction error of the approximation at the coupling k
/// ([`crate::problem::traction_distance`] from the exact tractions): (1 + delta) times
/// [`SAFETY`] times the worst tabulated value at the corners of the cell, plus
/// [`TRACTION_FLOOR`]; below the first column of mu~ the first column's values (the error
/// vanishes with mu~, like mu~ there; checked off the grid a decade below the first column),
/// None above the last column, outside the rows of b* or where the reference failed nearby
/// (an inf entry at a corner).
pub fn traction_bound(a: Approximation, k: &Coupling) -> Option<f64> {
    if k.mu == 0.0 {
        return Some(0.0); // every method gives p = p0 and q = 0 exactly
    }
    let (reduced, delta) = k.reduced();
    let (b, l) = (reduced.bp, reduced.mu.log10().max(LOG10_MU[0]));
    if !(B_STAR[0]..=B_STAR[B_STAR.len() - 1]).contains(&b) || l > LOG10_MU[LOG10_MU.len() - 1] {
        return None;
    }
    let worst = corner_max(tabulated_tractions(a), b, l);
    worst
        .is_finite()
        .then_some((1.0 + delta) * SAFETY * worst + TRACTION_FLOOR)
}

/// The largest of the grid's values at the corners of the cell holding (b*, log10 mu~).
fn corner_max(e: &Grid, b: f64, l: f64) -> f64 {
    let ((i0, i1), (j0, j1)) = (interval(&B_STAR, b), interval(&LOG10_MU, l));
    e[i0][j0].max(e[i0][j1]).max(e[i1][j0]).max(e[i1][j1])
}

/// Per row of [`B_STAR`]: the largest c of the three methods at the first column and the
/// largest 1 - c at the last column (the bounds below and above the tabulated mu~).
pub fn tabulated_beyond() -> (&'static [f64; B_STAR.len()], &'static [f64; B_STAR.len()]) {
    (&table::BELOW, &table::ABOVE)
}

/// The grid interval [i, i + 1] holding v (clamped to the ends).
fn interval(grid: &[f64], v: f64) -> (usize, usize) {
    match grid.partition_point(|&g| g <= v) {
        0 => (0, 0),
        i if i == grid.len() => (i - 1, i - 1),
        i => (i - 1, i),
    }
}

/// An empirical bound on |c_approx - c_exact| for the approximation at the coupling k:
/// [`SAFETY`] times the worst of the tabulated values below plus [`FLOOR`], or None where
/// the table gives none (b* outside the rows, or the reference failed nearby: an inf entry
/// at a corner, or in the row's [`tabulated_beyond`] value beyond the columns).
///
/// Inside the grid: the largest error at the cell's corners. Below the first column (mu~
/// smaller): c grows with mu~ for every method, so |c_approx - c_exact| <= max of the c's
/// at the first column ([`tabulated_beyond`]). Above the last column: 1 - c falls with mu~, so
/// the error is at most the largest 1 - c at the last column (ibidem). Between
/// rows of b*, the larger of the two rows' values.
pub fn bound(a: Approximation, k: &Coupling) -> Option<f64> {
    if k.mu == 0.0 {
        return Some(0.0); // every method gives c = 0 exactly
    }
    let (reduced, _) = k.reduced();
    let (b, l) = (reduced.bp, reduced.mu.log10());
    if !(B_STAR[0]..=B_STAR[B_STAR.len() - 1]).contains(&b) {
        return None;
    }
    let (i0, i1) = interval(&B_STAR, b);
    let worst = if l < LOG10_MU[0] {
        table::BELOW[i0].max(table::BELOW[i1])
    } else if l > LOG10_MU[LOG10_MU.len() - 1] {
        table::ABOVE[i0].max(table::ABOVE[i1])
    } else {
        corner_max(tabulated(a), b, l)
    };
    worst.is_finite().then_some(SAFETY * worst + FLOOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(b: f64, l: f64) -> Coupling {
        Coupling {
            bp: b,
            bq: b,
            mu: 10f64.powf(l),
        }
    }

    /// In every cell of the grid, for both approximations: no bound where a corner is inf
    /// (the reference failed there), else SAFETY times the corners' largest error plus the
    /// floor (tractions: times 1 + delta = 2 in these reduced scenes), finite; outside the rows of b*, none; beyond the columns, from
    /// [`tabulated_beyond`].
    #[test]
    fn bounds_follow_the_cell_corners_and_skip_failed_references() {
        let mid = |g: &[f64], i: usize| 0.5 * (g[i] + g[i + 1]);
        for a in [Approximation::Goodman, Approximation::Spence] {
            for (e, scale, floor, get) in [
                (tabulated(a), 1.0, FLOOR, bound as fn(_, &_) -> _),
                (tabulated_tractions(a), 2.0, TRACTION_FLOOR, traction_bound),
            ] {
                for i in 0..B_STAR.len() - 1 {
                    for j in 0..LOG10_MU.len() - 1 {
                        let corners = [e[i][j], e[i][j + 1], e[i + 1][j], e[i + 1][j + 1]];
                        let k = at(mid(&B_STAR, i), mid(&LOG10_MU, j));
                        let expected = corners.iter().all(|v| v.is_finite()).then(|| {
                            scale * SAFETY * corners.iter().copied().fold(0.0, f64::max) + floor
                        });
                        assert_eq!(get(a, &k), expected, "{a:?} cell ({i}, {j})");
                    }
                }
                let l = mid(&LOG10_MU, 0);
                for b in [0.5 * B_STAR[0], 0.5 * (1.0 + B_STAR[B_STAR.len() - 1])] {
                    assert_eq!(get(a, &at(b, l)), None);
                }
            }
        }
        let (below, above) = tabulated_beyond();
        let (first, last) = (LOG10_MU[0], LOG10_MU[LOG10_MU.len() - 1]);
        let beyond = |v: &[f64; B_STAR.len()], i: usize| {
            let v = v[i].max(v[i + 1]);
            v.is_finite().then_some(SAFETY * v + FLOOR)
        };
        for i in 0..B_STAR.len() - 1 {
            let (b, a) = (mid(&B_STAR, i), Approximation::Spence);
            assert_eq!(bound(a, &at(b, first - 1.0)), beyond(below, i));
            assert_eq!(bound(a, &at(b, last + 1.0)), beyond(above, i));
            assert_eq!(traction_bound(a, &at(b, last + 1.0)), None);
        }
    }
}
