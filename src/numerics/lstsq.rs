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

/// Why [`constrained`] gave no solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ConstrainedFailure {
    /// A constraint is zero (or not finite) on every column still free to pivot on.
    DependentConstraints,
    /// The least-squares solution of the reduced system is not finite.
    NotFinite,
}

/// x minimising ||A x - b|| subject to a few exact constraints c_i . x = d_i, by elimination:
/// Gauss-Jordan on the constraints, each pivot the largest entry left in its row among the
/// first `pivot_cols` columns; those columns eliminated from A; the reduced least squares by
/// the column-pivoted QR ([`LeastSquares::pivoted`], for frames whose columns are
/// near-dependent by design); then the eliminated coefficients from the constraints. A is
/// row-major with `cols` columns, each constraint row of length `cols`.
pub(crate) fn constrained(
    a: &[f64],
    cols: usize,
    b: &[f64],
    mut cons: Vec<(Vec<f64>, f64)>,
    pivot_cols: usize,
) -> Result<Vec<f64>, ConstrainedFailure> {
    let mut pivots: Vec<usize> = Vec::new();
    for i in 0..cons.len() {
        let row = &cons[i].0;
        let j = (0..pivot_cols)
            .filter(|j| !pivots.contains(j))
            .max_by(|&p, &q| row[p].abs().total_cmp(&row[q].abs()))
            .unwrap_or(0);
        let piv = cons[i].0[j];
        if piv == 0.0 || !piv.is_finite() {
            return Err(ConstrainedFailure::DependentConstraints);
        }
        for v in &mut cons[i].0 {
            *v /= piv;
        }
        cons[i].1 /= piv;
        let (row, d) = cons[i].clone();
        for (i2, (other, od)) in cons.iter_mut().enumerate() {
            if i2 != i {
                let f = other[j];
                for (o, r) in other.iter_mut().zip(&row) {
                    *o -= f * r;
                }
                *od -= f * d;
            }
        }
        pivots.push(j);
    }
    let keep: Vec<usize> = (0..cols).filter(|j| !pivots.contains(j)).collect();
    let m = keep.len();
    let rows = b.len();
    let mut reduced = vec![0.0; rows * m];
    let mut rhs = vec![0.0; rows];
    for i in 0..rows {
        let row = &a[i * cols..(i + 1) * cols];
        for (jj, &j) in keep.iter().enumerate() {
            reduced[i * m + jj] = row[j]
                - pivots
                    .iter()
                    .zip(&cons)
                    .map(|(&pj, (k, _))| row[pj] * k[j])
                    .sum::<f64>();
        }
        rhs[i] = b[i]
            - pivots
                .iter()
                .zip(&cons)
                .map(|(&pj, (_, d))| row[pj] * d)
                .sum::<f64>();
    }
    let x = LeastSquares::pivoted().solve(&reduced, m, &rhs);
    if x.iter().any(|v| !v.is_finite()) {
        return Err(ConstrainedFailure::NotFinite);
    }
    let mut full = vec![0.0; cols];
    for (jj, &j) in keep.iter().enumerate() {
        full[j] = x[jj];
    }
    for (&pj, (k, d)) in pivots.iter().zip(&cons) {
        full[pj] = d - keep.iter().map(|&j| k[j] * full[j]).sum::<f64>();
    }
    Ok(full)
}
