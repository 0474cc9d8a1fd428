//! Overdetermined linear least squares min ||A x - b||_2 for the panel systems: Householder
//! QR without column pivoting (faer's blocked factorisation, 1.5 times faster than the
//! column-pivoted one at 300 unknowns, which runs at level-2 speed), and the column-pivoted
//! QR where the first looks rank deficient.
//!
//! Householder QR is backward stable column by column, so the columns' scaling does not
//! matter (the rows are equilibrated by the caller). Without pivoting, though, a column
//! that is numerically dependent on those before it (a tiny diagonal entry of R) spreads its
//! rounding garbage over every coefficient in back substitution: the panel bases at high
//! orders (19-28) and at extreme friction are that redundant (diagonal ratios down to 0,
//! measured), and there the defect changed sign at random. Pivoting keeps such columns last.

use faer::MatRef;
use faer::linalg::solvers::SolveLstsq;

/// Smallest ratio of the smallest to the largest |diagonal entry| of R that the unpivoted QR
/// is trusted with: the panel systems of the 12 scenes of examples/speed_accuracy.rs and 12
/// more of the reduced plane (b* = 0.05 .. 0.9, mu~ = 0.05 .. 30) went down to 2e-13 without
/// loss in c (3% of their solves fall below this at tolerance 1e-10, 8% at 1e-12); with no
/// fallback, coupled's unit tests failed (ratios below 1e-14 and exact zeros).
const RANK_RATIO: f64 = 1e-13;

/// The least-squares solver of one sequence of similar systems (a root search): once a
/// system needed the pivoted QR, the next ones go to it directly.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct LeastSquares {
    pivot: bool,
}

impl LeastSquares {
    /// A solver that goes to the column-pivoted QR directly (frames whose near-dependent
    /// columns are the rule, not the exception).
    pub(crate) fn pivoted() -> Self {
        LeastSquares { pivot: true }
    }

    /// x minimising ||A x - b||, A given row-major with n columns (and b.len() rows).
    pub(crate) fn solve(&mut self, a: &[f64], n: usize, b: &[f64]) -> Vec<f64> {
        let a = MatRef::from_row_major_slice(a, b.len(), n);
        let b = MatRef::from_column_major_slice(b, b.len(), 1);
        if !self.pivot {
            let qr = a.qr();
            let r = qr.thin_R();
            let (lo, hi) = (0..n).fold((f64::INFINITY, 0.0f64), |(lo, hi), i| {
                let d = r[(i, i)].abs();
                (lo.min(d), hi.max(d))
            });
            // (a NaN ratio also goes to the pivoted QR)
            if lo >= RANK_RATIO * hi {
                let x = qr.solve_lstsq(b);
                return (0..n).map(|i| x[(i, 0)]).collect();
            }
            self.pivot = true;
        }
        let x = a.col_piv_qr().solve_lstsq(b);
        (0..n).map(|i| x[(i, 0)]).collect()
    }
}
