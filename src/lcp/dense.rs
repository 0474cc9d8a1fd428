//! Dense LU with partial pivoting (faer, sequential), with the singularity checks faer
//! leaves to the caller: its factorisation returns NaN or infinite entries, not an error,
//! when the matrix is singular.

use crate::error::{Error, Result};
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::perm::Perm;
use faer::{Mat, MatMut, Par};

/// A factorised square matrix P A = L U (L unit lower, U upper, stored together).
pub(crate) struct Lu {
    lu: Mat<f64>,
    perm: Perm<usize>,
}

impl Lu {
    /// Factorises `a` in place (sequentially). Fails when a pivot is zero or non-finite,
    /// or smaller than `1e-14` times the largest pivot (numerically singular).
    pub(crate) fn new(mut a: Mat<f64>) -> Result<Self> {
        let n = a.nrows();
        if n == 0 || a.ncols() != n {
            return Err(Error::Internal(format!(
                "LU of a {}x{} matrix",
                a.nrows(),
                a.ncols()
            )));
        }
        let mut fwd = vec![0usize; n];
        let mut bwd = vec![0usize; n];
        let mut buf = MemBuffer::new(factor::lu_in_place_scratch::<usize, f64>(
            n,
            n,
            Par::Seq,
            Default::default(),
        ));
        factor::lu_in_place(
            a.as_mut(),
            &mut fwd,
            &mut bwd,
            Par::Seq,
            MemStack::new(&mut buf),
            Default::default(),
        );
        let pivots: Vec<f64> = (0..n).map(|i| a[(i, i)].abs()).collect();
        let largest = pivots.iter().fold(0.0f64, |m, &d| m.max(d));
        if !largest.is_finite() || pivots.iter().any(|&d| d.is_nan() || d <= 1e-14 * largest) {
            return Err(Error::NoConvergence(format!(
                "singular or non-finite {n}x{n} linear system (largest pivot {largest:.3e})"
            )));
        }
        let perm = Perm::new_checked(fwd.into_boxed_slice(), bwd.into_boxed_slice(), n);
        Ok(Self { lu: a, perm })
    }

    /// Overwrites `rhs` (n x k) with A^-1 rhs; fails if the result is not finite.
    pub(crate) fn solve_in_place(&self, mut rhs: MatMut<'_, f64>) -> Result<()> {
        let n = self.lu.nrows();
        let mut buf = MemBuffer::new(solve::solve_in_place_scratch::<usize, f64>(
            n,
            rhs.ncols(),
            Par::Seq,
        ));
        solve::solve_in_place(
            self.lu.as_ref(),
            self.lu.as_ref(),
            self.perm.as_ref(),
            rhs.as_mut(),
            Par::Seq,
            MemStack::new(&mut buf),
        );
        for j in 0..rhs.ncols() {
            for i in 0..n {
                if !rhs[(i, j)].is_finite() {
                    return Err(Error::NoConvergence(
                        "non-finite solution of a linear system".into(),
                    ));
                }
            }
        }
        Ok(())
    }

    /// A^-1 b for one right-hand side.
    pub(crate) fn solve_vec(&self, b: &[f64]) -> Result<Vec<f64>> {
        let mut m = Mat::from_fn(b.len(), 1, |i, _| b[i]);
        self.solve_in_place(m.as_mut())?;
        Ok((0..b.len()).map(|i| m[(i, 0)]).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_nonsymmetric_system_and_rejects_a_singular_one() {
        // A = tridiag(-1, 4, 2) plus a rank-one term: residual check against the product.
        let n = 37;
        let a = Mat::from_fn(n, n, |i, j| {
            let t = match i as i64 - j as i64 {
                0 => 4.0,
                1 => -1.0,
                -1 => 2.0,
                _ => 0.0,
            };
            t + 0.01 * ((i + 1) as f64) / ((j + 2) as f64)
        });
        let b: Vec<f64> = (0..n).map(|i| (i as f64).sin()).collect();
        let x = Lu::new(a.clone()).unwrap().solve_vec(&b).unwrap();
        for i in 0..n {
            let ax: f64 = (0..n).map(|j| a[(i, j)] * x[j]).sum();
            assert!((ax - b[i]).abs() < 1e-13, "row {i}: {ax} vs {}", b[i]);
        }
        let singular = Mat::from_fn(4, 4, |i, j| ((i + 1) * (j + 1)) as f64);
        assert!(matches!(Lu::new(singular), Err(Error::NoConvergence(_))));
    }
}
