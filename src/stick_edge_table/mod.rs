//! A tabulated exact stick edge: piecewise Chebyshev interpolants of COUPLED's
//! lc = ln(c / (1 - c)) over the reduced plane (b*, mu~) (docs/theory.md (R2), (T5): c depends on
//! these two alone), so that c alone costs a lookup instead of a root search.
//!
//! Coordinates, chosen so that lc is smooth and the table's lower edge follows the stick
//! zone's opening:
//! - beta = artanh(b*) (the bonded field's index eps = beta / pi; b* -> 1 is beta -> inf, not
//!   a singular endpoint);
//! - zeta = ln(mu~ / mu_lo(b*)), where mu_lo is the friction at which the full-slip law
//!   c ~ 4 (1 - b*^2)^(pi / (2 b* mu~)) (`coupled::full_slip`) gives c = [`C_LO`].
//!   Below zeta = 0 the stick zone is below C_LO (the full-slip regime answers c there).
//!
//! Covered: b* = 0.25 .. 0.99999 (towards the auxetic limit nu -> -1; beta = 0.26 .. 6.10)
//! from zeta = 0 up to mu~ = 4e6 at least; below, b* = 0.02 .. 0.25
//! from zeta = 0 up to the thin slip zones' tops (the generator's `THIN`): zeta = 5.05 .. 6.6
//! for b* = 0.02 .. 0.16, where 1 - c has fallen to about 1e-11 and the near-bonded law
//! answers c alone above, and from b* = 0.16 on up to the friction at which the edge
//! exponent g falls to 0.0025 (mu~ = 400-730; the panels answer above). The patches are a
//! union of rectangles, not one: [`lookup`] is None outside them.
//!
//! Each [`Patch`] is a tensor Chebyshev interpolant on a rectangle of (beta, zeta) from
//! COUPLED's c at its Chebyshev points of the first kind. Its `bound` on |c_table - c| was
//! set by the generator (`cargo run --release --example stick_edge_table`, outside the
//! library): the larger of the coefficient tail (the last two Chebyshev rows and columns,
//! times the patch's largest c (1 - c)) and [`SAFETY`] times the largest error at random
//! points of the patch against COUPLED solves not used to build it, plus the nodes' own
//! tolerance. It is empirical, not a proof; `tests/stick_edge_table.rs` re-solves nodes of
//! the committed patches and checks the bounds at fresh random points.

#[rustfmt::skip]
mod table;

use crate::numerics::orthopoly::{chebyshev_fit, chebyshev_points, chebyshev_sum};

/// The stick zone at the table's lower edge (zeta = 0) by the full-slip law.
pub const C_LO: f64 = 1e-11;

/// Multiplier on the largest error measured off the nodes, in each patch's bound.
pub const SAFETY: f64 = 4.0;

/// How far outside a patch (in beta and zeta) a point still counts as inside it.
const EDGE_SLACK: f64 = 1e-12;

/// Largest number of Chebyshev rows (over beta) of a patch.
pub const MAX_ROWS: usize = 32;

/// One rectangle of (beta, zeta) and the Chebyshev coefficients of lc on it.
#[derive(Clone, Copy, Debug)]
pub struct Patch {
    /// beta = artanh(b*) range.
    pub beta: [f64; 2],
    /// zeta range.
    pub zeta: [f64; 2],
    /// Coefficients: `rows` (degrees in beta) of `cols` (degrees in zeta), row-major.
    pub coef: &'static [f64],
    /// Number of degrees in beta (at most [`MAX_ROWS`]).
    pub rows: usize,
    /// Number of degrees in zeta.
    pub cols: usize,
    /// Bound on |c_table - c| over the patch.
    pub bound: f64,
}

/// The committed patches.
pub fn patches() -> &'static [Patch] {
    table::PATCHES
}

/// The smallest rectangle of (beta, zeta) holding every patch. The patches do not fill it:
/// below b* = 0.25 they stop at their strips' tops, and [`lookup`] is None at the
/// rectangle's points outside them.
pub fn extent() -> ([f64; 2], [f64; 2]) {
    let span = |f: fn(&Patch) -> [f64; 2]| {
        patches()
            .iter()
            .map(f)
            .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], r| {
                [lo.min(r[0]), hi.max(r[1])]
            })
    };
    (span(|p| p.beta), span(|p| p.zeta))
}

/// mu_lo(b*): where the full-slip law gives c = [`C_LO`], pi L / (2 b* ln(4 / C_LO)) with
/// L = -ln(1 - b*^2). Below b* = 1e-8, L / b* is b* to rounding (L = b*^2 (1 + b*^2 / 2 +
/// ...)), taken as such: b*^2 underflows below 1e-154.
fn mu_lo(b: f64) -> f64 {
    let pi = std::f64::consts::PI;
    if b < 1e-8 {
        pi * b / (2.0 * (4.0 / C_LO).ln())
    } else {
        pi * -(-b * b).ln_1p() / (2.0 * b * (4.0 / C_LO).ln())
    }
}

/// The table's coordinates (beta, zeta) of the reduced coupling (b*, mu~), 0 < b* < 1.
pub fn coordinates(b: f64, mu: f64) -> (f64, f64) {
    (b.atanh(), (mu / mu_lo(b)).ln())
}

/// The reduced coupling (b*, mu~) at table coordinates (beta, zeta).
pub fn coupling_at(beta: f64, zeta: f64) -> (f64, f64) {
    let b = beta.tanh();
    (b, mu_lo(b) * zeta.exp())
}

/// The Chebyshev nodes of a patch of `rows` x `cols` degrees on the rectangle, row-major
/// (beta outer), as table coordinates.
pub fn nodes(beta: [f64; 2], zeta: [f64; 2], rows: usize, cols: usize) -> Vec<(f64, f64)> {
    let zs = chebyshev_points(zeta[0], zeta[1], cols);
    chebyshev_points(beta[0], beta[1], rows)
        .into_iter()
        .flat_map(|b| zs.iter().map(move |&z| (b, z)))
        .collect()
}

/// The patch's coefficients from lc at its [`nodes`] (same order).
pub fn coefficients(values: &[f64], rows: usize, cols: usize) -> Vec<f64> {
    // along zeta for every beta node, then along beta for every zeta degree
    let along_zeta: Vec<Vec<f64>> = values
        .chunks(cols)
        .map(|row| chebyshev_fit(|_| row.to_vec(), -1.0, 1.0, cols))
        .collect();
    let mut coef = vec![0.0; rows * cols];
    for j in 0..cols {
        let column = chebyshev_fit(
            |_| along_zeta.iter().map(|r| r[j]).collect(),
            -1.0,
            1.0,
            rows,
        );
        for (i, v) in column.into_iter().enumerate() {
            coef[i * cols + j] = v;
        }
    }
    coef
}

/// lc of the interpolant with these coefficients at (beta, zeta) of the rectangle.
pub fn evaluate(
    coef: &[f64],
    (rows, cols): (usize, usize),
    (beta, zeta): ([f64; 2], [f64; 2]),
    (b, z): (f64, f64),
) -> f64 {
    let local = |v: f64, r: [f64; 2]| (2.0 * v - r[0] - r[1]) / (r[1] - r[0]);
    let (tb, tz) = (local(b, beta), local(z, zeta));
    let mut row_sums = [0.0; MAX_ROWS];
    for (sum, row) in row_sums.iter_mut().zip(coef.chunks(cols).take(rows)) {
        *sum = chebyshev_sum(row, tz);
    }
    chebyshev_sum(&row_sums[..rows], tb)
}

/// The largest zeta the patches cover at b* (the top of its strip), or None where no patch
/// covers b*.
pub fn top(b: f64) -> Option<f64> {
    let beta = b.atanh();
    patches()
        .iter()
        .filter(|p| p.beta[0] - EDGE_SLACK <= beta && beta <= p.beta[1] + EDGE_SLACK)
        .map(|p| p.zeta[1])
        .reduce(f64::max)
}

/// The table's stick edge at the reduced coupling (b*, mu~): (lc, bound on |c_table - c|),
/// or None outside the patches.
pub fn lookup(b: f64, mu: f64) -> Option<(f64, f64)> {
    let (beta, zeta) = coordinates(b, mu);
    // the coordinates' rounding (a few ulps) must not leave the table's outer edges
    let inside = |v: f64, r: [f64; 2]| r[0] - EDGE_SLACK <= v && v <= r[1] + EDGE_SLACK;
    patches()
        .iter()
        .find(|p| inside(beta, p.beta) && inside(zeta, p.zeta))
        .map(|p| {
            let lc = evaluate(p.coef, (p.rows, p.cols), (p.beta, p.zeta), (beta, zeta));
            (lc, p.bound)
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interpolant of a smooth function of both coordinates reproduces it, and the
    /// coordinates invert.
    #[test]
    fn interpolant_and_coordinates() {
        let f = |b: f64, z: f64| (0.3 * b).sin() * z.cos() + b * b * z;
        let (beta, zeta) = ([0.3, 1.1], [-1.0, 2.5]);
        let values: Vec<f64> = nodes(beta, zeta, 14, 18)
            .into_iter()
            .map(|(b, z)| f(b, z))
            .collect();
        let coef = coefficients(&values, 14, 18);
        for (b, z) in [(0.3, -1.0), (0.77, 0.4), (1.1, 2.5), (0.5, 1.9)] {
            let v = evaluate(&coef, (14, 18), (beta, zeta), (b, z));
            assert!((v - f(b, z)).abs() < 1e-13, "{v} {}", f(b, z));
        }
        for (b, mu) in [(0.3, 0.02), (0.9, 5.0), (0.99, 1e6)] {
            let (beta, zeta) = coordinates(b, mu);
            let (b2, mu2) = coupling_at(beta, zeta);
            assert!((b2 - b).abs() < 1e-15 && (mu2 / mu - 1.0).abs() < 1e-13);
        }
        // the lower edge: the full-slip law's c is C_LO there
        let k = crate::problem::Coupling {
            bp: 0.6,
            bq: 0.6,
            mu: coupling_at(0.6f64.atanh(), 0.0).1,
        };
        let c = crate::coupled::full_slip::ln_c_law(&k).exp();
        assert!((c / C_LO - 1.0).abs() < 1e-12);
    }
}
