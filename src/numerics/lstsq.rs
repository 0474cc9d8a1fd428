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
        self.solve_ref(MatRef::from_row_major_slice(a, b.len(), n), b)
    }

    /// [`LeastSquares::solve`] for a [`ColMajor`] A.
    fn solve_col_major(&mut self, a: &ColMajor, b: &[f64]) -> Vec<f64> {
        let a = MatRef::from_column_major_slice_with_stride(&a.data, a.rows, a.cols, a.ld);
        self.solve_ref(a, &b[..a.nrows()])
    }

    fn solve_ref(&mut self, a: MatRef<'_, f64>, b: &[f64]) -> Vec<f64> {
        let n = a.ncols();
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

/// A dense matrix stored by columns, each padded with zeros to `ld` rows, a multiple of
/// [`LANES`] (so that [`nested_qr_solve`]'s dot products run over whole chunks): the layout
/// of the least-squares pipeline from assembly through the elimination to the QR, which
/// works in place on it.
#[derive(Clone, Debug, Default)]
pub(crate) struct ColMajor {
    pub(crate) rows: usize,
    pub(crate) cols: usize,
    ld: usize,
    data: Vec<f64>,
}

impl ColMajor {
    /// The zero matrix.
    pub(crate) fn zeros(rows: usize, cols: usize) -> Self {
        let ld = rows.next_multiple_of(LANES);
        ColMajor {
            rows,
            cols,
            ld,
            data: vec![0.0; ld * cols],
        }
    }

    /// From a row-major `a` with `cols` columns.
    pub(crate) fn from_row_major(a: &[f64], cols: usize) -> Self {
        let mut m = Self::zeros(a.len() / cols, cols);
        for (i, row) in a.chunks_exact(cols).enumerate() {
            for (j, &v) in row.iter().enumerate() {
                m.data[j * m.ld + i] = v;
            }
        }
        m
    }

    /// Column j (its `rows` entries).
    pub(crate) fn col(&self, j: usize) -> &[f64] {
        &self.data[j * self.ld..j * self.ld + self.rows]
    }

    /// Column j, mutable.
    pub(crate) fn col_mut(&mut self, j: usize) -> &mut [f64] {
        &mut self.data[j * self.ld..j * self.ld + self.rows]
    }

    /// Entry (i, j), mutable.
    pub(crate) fn at_mut(&mut self, i: usize, j: usize) -> &mut f64 {
        &mut self.data[j * self.ld + i]
    }

    /// The rows taken in the order `order` (a permutation of 0..rows).
    pub(crate) fn rows_permuted(&self, order: &[usize]) -> Self {
        let mut m = Self::zeros(self.rows, self.cols);
        for j in 0..self.cols {
            let (from, to) = (self.col(j), m.col_mut(j));
            for (t, &i) in to.iter_mut().zip(order) {
                *t = from[i];
            }
        }
        m
    }

    /// A x, each entry summed over the columns in order: the computed entry i lies within
    /// gamma_n (|A| |x|)_i of the exact product of the stored A and x (n = `cols`,
    /// gamma_n = n eps / (1 - n eps), the bound of a recursive sum of products;
    /// [`ColMajor::abs_times`]).
    pub(crate) fn times(&self, x: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.rows];
        for (j, &xj) in x.iter().enumerate().take(self.cols) {
            for (o, a) in out.iter_mut().zip(self.col(j)) {
                *o += a * xj;
            }
        }
        out
    }

    /// |A| |x|: each row's sum of |a_ij x_j| over the columns, its rounding scale in A x.
    pub(crate) fn abs_times(&self, x: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.rows];
        for (j, &xj) in x.iter().enumerate().take(self.cols) {
            for (o, a) in out.iter_mut().zip(self.col(j)) {
                *o += (a * xj).abs();
            }
        }
        out
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
    cons: Vec<(Vec<f64>, f64)>,
    pivot_cols: usize,
) -> Result<Vec<f64>, ConstrainedFailure> {
    let a = ColMajor::from_row_major(a, cols);
    let order: Vec<usize> = (0..cols).collect();
    constrained_by(&a, &order, b, cons, pivot_cols, false)
}

/// [`constrained`] for a [`ColMajor`] A, with its pivoted QR chosen by size:
/// [`nested_qr_solve`]'s (one group) up to [`OWN_QR_COLUMNS`] columns, faer's above. For the
/// spectral frames, whose larger levels [`constrained_nested`] solves anyway. (The fretting
/// frames stay on faer's: on the unloading frames, with diagonal ratios of R down to
/// 2.7e-16, this one's solutions led to NaN residuals in `fretting::exact::unload::tests`;
/// measured before `fretting::exact::frame::locate`'s fix, not since.)
pub(crate) fn constrained_sized(
    a: &ColMajor,
    b: &[f64],
    cons: Vec<(Vec<f64>, f64)>,
    pivot_cols: usize,
) -> Result<Vec<f64>, ConstrainedFailure> {
    let order: Vec<usize> = (0..a.cols).collect();
    constrained_by(a, &order, b, cons, pivot_cols, a.cols <= OWN_QR_COLUMNS)
}

/// [`constrained`] on the columns of A taken in the order `order` (column j of the problem
/// is A's column `order[j]`), with the reduced least squares by [`nested_qr_solve`]'s pivoted
/// QR (one group) where `own`, else by faer's.
fn constrained_by(
    a: &ColMajor,
    order: &[usize],
    b: &[f64],
    cons: Vec<(Vec<f64>, f64)>,
    pivot_cols: usize,
    own: bool,
) -> Result<Vec<f64>, ConstrainedFailure> {
    let mut e = Elimination::new(a, order, b, cons, pivot_cols)?;
    let n = e.keep.len();
    let x = if own {
        let [_, x] = nested_qr_solve(std::mem::take(&mut e.reduced), &e.rhs, n);
        x
    } else {
        LeastSquares::pivoted().solve_col_major(&e.reduced, &e.rhs)
    };
    e.complete(&x)
}

/// Most columns for which [`constrained_sized`] takes its pivoted QR from [`nested_qr_solve`]
/// (one group), not from faer's `col_piv_qr`. Measured (`own_qr_crossover`: thread CPU time
/// per solve with the elimination of three constraints, the two alternated, minima of 7;
/// two runs) on matrices of the frames' shape (half the columns poles 1/(z_j - x) clustered
/// at z_j = 1 + 1e-3 1.3^j, half Chebyshev polynomials, at perturbed Chebyshev points; both
/// QRs' residual norms equal to rounding), at 1.8 rows per column (measured while the
/// spectral systems had 1.8, a change since reverted) and at 2.8 (about the spectral
/// systems' 3.0):
///
/// | columns | 1.8 rows per column: faer, us | own, us | ratio | 2.8: faer, us | own, us | ratio |
/// |---|---|---|---|---|---|---|
/// | 24 | 62 .. 63 | 25 .. 27 | 2.3 .. 2.5 | 74 .. 85 | 38 .. 39 | 2.0 .. 2.2 |
/// | 36 | 123 .. 124 | 66 .. 68 | 1.8 .. 1.9 | 174 .. 176 | 98 .. 100 | 1.7 .. 1.8 |
/// | 45 | 198 | 113 .. 115 | 1.7 .. 1.8 | 281 .. 282 | 175 .. 180 | 1.6 |
/// | 55 | 279 .. 286 | 194 .. 199 | 1.44 | 405 .. 421 | 307 .. 308 | 1.3 .. 1.4 |
/// | 62 | 346 .. 371 | 265 .. 277 | 1.3 | 548 .. 552 | 415 .. 418 | 1.3 |
/// | 66 | 403 .. 408 | 315 .. 320 | 1.3 | 575 .. 602 | 477 .. 495 | 1.2 |
/// | 72 | 494 .. 509 | 397 .. 405 | 1.25 | 707 .. 735 | 596 .. 619 | 1.19 |
/// | 80 | 622 | 537 .. 543 | 1.15 | 889 .. 896 | 796 .. 816 | 1.09 .. 1.13 |
/// | 93 | 843 .. 851 | 804 .. 808 | 1.04 .. 1.06 | 1232 .. 1244 | 1218 .. 1223 | 1.01 .. 1.02 |
/// | 110 | 1318 .. 1324 | 1261 .. 1294 | 1.02 .. 1.05 | 1756 .. 1801 | 1895 .. 1970 | 0.91 .. 0.93 |
///
/// (faer's blocked updates catch up from about 90 columns; on Chebyshev columns alone, at
/// 2.8 rows per column, the own QR was 2.2, 1.4, 1.06 .. 1.18 and 0.94 .. 0.98 times faster
/// at 24, 45, 72-80 and 93 columns.) Whole answers of `coupled::solve_to` on the 12 scenes
/// of `examples/support::scene_materials` (thread CPU time, the two alternated, minima of 5
/// rounds of at least 0.1 s; faer's time over the own's; one run at this crossover, on the
/// shared machine, with the spectral systems at 1.8 rows per unknown): c and tractions to
/// 1e-10, median 1.12, the 10 spectral scenes 1.08 ..
/// 1.22; tractions to 1e-8, median 1.04, the spectral scenes 1.00 .. 1.42 (there the
/// answers come mostly from [`constrained_nested`], already the own QR). 10 of the 12
/// answers were the same to the bit; the ply and kappa = 0.4 at mu = 1, tractions to 1e-8,
/// moved by 8e-12 and 2e-13 in c, 1.4e-11 and 4e-13 in the tractions. (With 3.0 rows per
/// unknown, the spectral systems' rows now, the crossover at 64 and at 96 had given
/// medians 1.09 .. 1.12 and 1.00 .. 1.01.)
const OWN_QR_COLUMNS: usize = 80;

/// [`constrained`] for two nested column sets at once, A's columns taken in the order
/// `order` ([`constrained_by`]): the first `inner` columns (the constraints' pivots among
/// the first `pivot_cols <= inner` of them), and all. One
/// Householder QR serves both ([`nested_qr_solve`]): its pivots are sought among the inner
/// columns first, so that its leading block is the inner problem's own factorisation.
/// Returns (inner solution, padded with zeros to `cols`, and the full one).
pub(crate) fn constrained_nested(
    a: &ColMajor,
    order: &[usize],
    b: &[f64],
    cons: Vec<(Vec<f64>, f64)>,
    pivot_cols: usize,
    inner: usize,
) -> Result<(Vec<f64>, Vec<f64>), ConstrainedFailure> {
    let cols = order.len();
    let mut e = Elimination::new(a, order, b, cons, pivot_cols)?;
    // the kept columns keep their order, so the inner ones still come first
    let split = e.keep.iter().filter(|&&j| j < inner).count();
    let [mut xi, xf] = nested_qr_solve(std::mem::take(&mut e.reduced), &e.rhs, split);
    xi.resize(e.keep.len(), 0.0);
    let mut inner_full = e.complete(&xi)?;
    for v in &mut inner_full[inner..cols] {
        *v = 0.0;
    }
    Ok((inner_full, e.complete(&xf)?))
}

/// The constraints eliminated from a least-squares problem ([`constrained`]).
struct Elimination {
    cons: Vec<(Vec<f64>, f64)>,
    pivots: Vec<usize>,
    keep: Vec<usize>,
    cols: usize,
    /// The reduced matrix and right-hand side.
    reduced: ColMajor,
    rhs: Vec<f64>,
}

impl Elimination {
    fn new(
        a: &ColMajor,
        order: &[usize],
        b: &[f64],
        mut cons: Vec<(Vec<f64>, f64)>,
        pivot_cols: usize,
    ) -> Result<Self, ConstrainedFailure> {
        let cols = order.len();
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
        let rows = a.rows;
        let mut reduced = ColMajor::zeros(rows, keep.len());
        // column by column: the pivots' multiples summed first, then subtracted, each entry
        // rounded as a[i][j] - sum_p a[i][p] k_p[j]: a thin slip zone's answer (b* = 0.15,
        // mu~ = 10, 1 - c = 8e-13, 161 unknowns) moved by 9.5e-9 with the subtractions taken
        // one by one
        let mut acc = vec![0.0; rows];
        let pivot_cols: Vec<&[f64]> = pivots.iter().map(|&pj| a.col(order[pj])).collect();
        for (jj, &j) in keep.iter().enumerate() {
            let col = a.col(order[j]);
            let out = reduced.col_mut(jj);
            if let [p0, p1, p2] = pivot_cols[..] {
                // three constraints (the spectral frames'): one pass, the same sums in the
                // same order (kappa = 0.4 at mu = 1: 1.438M to 1.420M instructions per
                // answer; later, one pass over any number of pivots, the pivots in the inner
                // loop, took 1.517M against this one's 1.404M)
                let (k0, k1, k2) = (cons[0].0[j], cons[1].0[j], cons[2].0[j]);
                for i in 0..rows {
                    let s = 0.0 + p0[i] * k0 + p1[i] * k1 + p2[i] * k2;
                    out[i] = col[i] - s;
                }
                continue;
            }
            acc.fill(0.0);
            for (pc, (k, _)) in pivot_cols.iter().zip(&cons) {
                let f = k[j];
                for (s, v) in acc.iter_mut().zip(pc.iter()) {
                    *s += v * f;
                }
            }
            for ((o, v), s) in out.iter_mut().zip(col).zip(&acc) {
                *o = v - s;
            }
        }
        let mut rhs = vec![0.0; rows];
        acc.fill(0.0);
        for (&pj, (_, d)) in pivots.iter().zip(&cons) {
            for (s, v) in acc.iter_mut().zip(a.col(order[pj])) {
                *s += v * d;
            }
        }
        for ((r, bi), s) in rhs.iter_mut().zip(b).zip(&acc) {
            *r = bi - s;
        }
        Ok(Elimination {
            cons,
            pivots,
            keep,
            cols,
            reduced,
            rhs,
        })
    }

    /// The full solution from the reduced one: the eliminated coefficients from the
    /// constraints.
    fn complete(&self, x: &[f64]) -> Result<Vec<f64>, ConstrainedFailure> {
        if x.iter().any(|v| !v.is_finite()) {
            return Err(ConstrainedFailure::NotFinite);
        }
        let mut full = vec![0.0; self.cols];
        for (jj, &j) in self.keep.iter().enumerate() {
            full[j] = x[jj];
        }
        for (&pj, (k, d)) in self.pivots.iter().zip(&self.cons) {
            full[pj] = d - self.keep.iter().map(|&j| k[j] * full[j]).sum::<f64>();
        }
        Ok(full)
    }
}

/// Least squares min ||A x - b|| on the first `inner` columns of A and on all of them, from
/// one Householder QR with column pivoting (A factorised in place, b.len() = its rows).
///
/// The pivot at each step is the remaining column of largest norm within the current group
/// (the inner columns, then the rest), the norms downdated after each step and recomputed
/// where cancellation has eaten half their digits (Businger & Golub's pivoting with LAPACK
/// xLAQP2's safeguard). So the first `inner` steps are the inner problem's own pivoted QR,
/// and its solution comes from the leading block of R. faer's column-pivoted QR pivots over
/// all columns at once, and would need a second factorisation for the inner problem.
/// Returns [inner solution (`inner` entries), full solution].
pub(crate) fn nested_qr_solve(a: ColMajor, b: &[f64], inner: usize) -> [Vec<f64>; 2] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU has AVX (checked just above)
        return unsafe { nested_qr_solve_avx(a, b, inner) };
    }
    nested_qr_solve_in::<false>(a, b, inner)
}

/// [`nested_qr_solve_in`] compiled for AVX, where the CPU has it: the dot products and the
/// updates ([`dot`] and the Householder steps) in 4-wide registers, the same operations in
/// the same order as the baseline build's 2-wide ones (no fused multiply-add), so the same
/// result to the bit (checked on the 12 speed scenes at four tolerances, c and 50 traction
/// values each). Measured on the 10 spectral speed scenes at c to 1e-10 (thread CPU time,
/// median over the scenes, alternated twice in one run): tractions to 1e-8, 0.210, 0.211 ms
/// without, 0.203, 0.203 ms with; to 1e-10, 0.469, 0.484 ms without, 0.442, 0.455 ms with;
/// instructions per answer (ply at mu = 0.3, steel at mu = 0.1, 0.3; tractions to 1e-8)
/// 2.24M to 2.09M.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn nested_qr_solve_avx(a: ColMajor, b: &[f64], inner: usize) -> [Vec<f64>; 2] {
    nested_qr_solve_in::<true>(a, b, inner)
}

/// [`nested_qr_solve`]'s body, inlined into each build of it.
///
/// The columns are stored with a leading dimension padded with zeros to a multiple of
/// [`LANES`], and each Householder vector is kept apart in a zero-padded buffer: every dot
/// product and update of step i then runs over rows from i rounded down to a multiple of
/// [`LANES`] to the padded end, whole chunks with no scalar remainder (the rows above i
/// meet zeros in the vector: their products are exact zeros and their updates leave them
/// as they were). With the dot products in AVX registers ([`dot_lanes_avx`]; the compiler
/// had kept [`dot`]'s eight sums in 2-wide registers with shuffles) and the norms' downdates
/// in one vectorised pass, the answer of steel at mu = 0.3 (c to 1e-10, tractions to 1e-8;
/// 59 rows, 37 columns after the elimination) took 1.307M instructions against 1.392M
/// (callgrind; the remainders' padding alone changed nothing). Step i's update is applied to
/// each trailing column in step i + 1's pass over it, which also takes step i + 1's dot
/// product ([`update_dot`]; the pivot for step i + 1 comes from the row-i entries, which are
/// known before the update); the same answers to the bit on the speed scenes, 1.152M to
/// 1.145M instructions, 0.102-0.104 to 0.100-0.103 ms median at tractions to 1e-8
/// (alternated, five rounds).
/// `AVX`: the build for CPUs with AVX ([`nested_qr_solve_avx`]), whose dot products are
/// [`dot_lanes_avx`].
#[inline(always)]
fn nested_qr_solve_in<const AVX: bool>(a: ColMajor, b: &[f64], inner: usize) -> [Vec<f64>; 2] {
    let dot_lanes = |x: &[f64], y: &[f64]| {
        #[cfg(target_arch = "x86_64")]
        if AVX {
            // SAFETY: AVX is enabled in this build (nested_qr_solve_avx)
            return unsafe { dot_lanes_avx(x, y) };
        }
        dot_lanes(x, y)
    };
    let update_dot = |col: &mut [f64], prev: &[f64], d: f64, next: &[f64]| {
        #[cfg(target_arch = "x86_64")]
        if AVX {
            // SAFETY: AVX is enabled in this build (nested_qr_solve_avx)
            return unsafe { update_dot_avx(col, prev, d, next) };
        }
        update_dot(col, prev, d, next)
    };
    let (m, n, ld) = (a.rows, a.cols, a.ld);
    debug_assert_eq!(b.len(), m);
    // factorised in place
    let mut q = a.data;
    let mut rhs = vec![0.0; ld];
    rhs[..m].copy_from_slice(b);
    // the last reflector's vector (zeros where it has none) and this step's
    let (mut prev, mut v) = (vec![0.0; ld], vec![0.0; ld]);
    // each trailing column's multiplier of `prev` not yet applied to it, and the rhs's: the
    // update of step i is applied in step i + 1's pass over the column, which also takes
    // the dot product of step i + 1 (one pass per column and step instead of two)
    let (mut pending, mut pending_rhs) = (vec![0.0; n], 0.0);
    let mut from = 0;
    let mut perm: Vec<usize> = (0..n).collect();
    let norm = |v: &[f64]| dot(v, v).sqrt();
    let mut vn1: Vec<f64> = q.chunks_exact(ld).map(|c| dot_lanes(c, c).sqrt()).collect();
    let mut vn2 = vn1.clone();
    let (mut row, mut lost, mut root) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let tol = f64::EPSILON.sqrt();
    let steps = m.min(n);
    // applies `prev` with each pending multiplier to the columns j >= first and the rhs
    let flush = |q: &mut [f64],
                 rhs: &mut [f64],
                 prev: &[f64],
                 pending: &mut [f64],
                 pr: &mut f64,
                 first: usize,
                 from: usize| {
        for (j, col) in q.chunks_exact_mut(ld).enumerate().skip(first) {
            let d = std::mem::take(&mut pending[j]);
            col[from..]
                .iter_mut()
                .zip(&prev[from..])
                .for_each(|(c, a)| *c -= d * a);
        }
        let d = std::mem::take(pr);
        rhs[from..]
            .iter_mut()
            .zip(&prev[from..])
            .for_each(|(c, a)| *c -= d * a);
    };
    for i in 0..steps {
        let end = if i < inner { inner } else { n };
        let p = (i..end).fold(i, |best, j| if vn1[j] > vn1[best] { j } else { best });
        if p != i {
            let (lo, hi) = q.split_at_mut(p * ld);
            lo[i * ld..(i + 1) * ld].swap_with_slice(&mut hi[..ld]);
            perm.swap(p, i);
            pending.swap(p, i);
            vn1[p] = vn1[i];
            vn2[p] = vn2[i];
        }
        let i0 = i - i % LANES;
        let (head, tail) = q.split_at_mut((i + 1) * ld);
        // the pivot column with the last step's update
        let col = &mut head[i * ld..];
        let d = std::mem::take(&mut pending[i]);
        col[from..]
            .iter_mut()
            .zip(&prev[from..])
            .for_each(|(c, a)| *c -= d * a);
        // the vector below the diagonal: rows i + 1 .. m of the column, zeros elsewhere
        v[from..=i].fill(0.0);
        v[i + 1..m].copy_from_slice(&col[i + 1..m]);
        let alpha = col[i];
        let xnorm = dot_lanes(&v[i0..], &v[i0..]).sqrt();
        if xnorm == 0.0 {
            // no reflector at this step: the last one's update to the rest, then none
            let (pr, pv) = (&mut pending_rhs, &mut pending);
            flush(&mut q, &mut rhs, &prev, pv, pr, i + 1, from);
            prev.fill(0.0);
            from = i0;
            continue;
        }
        let beta = -alpha.signum() * alpha.hypot(xnorm);
        let tau = (beta - alpha) / beta;
        let s = 1.0 / (alpha - beta);
        v[i + 1..m].iter_mut().for_each(|x| *x *= s);
        v[i] = 1.0;
        // the last step's update and this step's dot products in one pass per column
        for (j, col) in (i + 1..n).zip(tail.chunks_exact_mut(ld)) {
            let e = update_dot(&mut col[from..], &prev[from..], pending[j], &v[from..]);
            pending[j] = tau * e;
        }
        let e = update_dot(&mut rhs[from..], &prev[from..], pending_rhs, &v[from..]);
        pending_rhs = tau * e;
        head[i * ld + i] = beta;
        // the norms downdated by the row-i entries after this step's update (v_i = 1): the
        // divisions and square roots over all trailing columns in one pass (which the
        // compiler vectorises), then the rare recomputations where cancellation has eaten
        // half the digits (on the column with this step's update applied)
        for ((r, col), j) in row[i + 1..n]
            .iter_mut()
            .zip(tail.chunks_exact(ld))
            .zip(i + 1..)
        {
            *r = col[i] - pending[j] * 1.0;
        }
        for j in i + 1..n {
            let t = (1.0 - (row[j].abs() / vn1[j]).powi(2)).max(0.0);
            lost[j] = t * (vn1[j] / vn2[j]).powi(2);
            root[j] = t.sqrt();
        }
        for (j, col) in (i + 1..n).zip(tail.chunks_exact_mut(ld)) {
            if vn1[j] != 0.0 {
                if lost[j] <= tol {
                    let d = std::mem::take(&mut pending[j]);
                    col[i0..]
                        .iter_mut()
                        .zip(&v[i0..])
                        .for_each(|(c, a)| *c -= d * a);
                    vn1[j] = norm(&col[i + 1..m]);
                    vn2[j] = vn1[j];
                } else {
                    vn1[j] *= root[j];
                }
            }
        }
        std::mem::swap(&mut prev, &mut v);
        from = i0;
    }
    // the last step's update to the rhs (and to the columns beyond the steps, unread)
    flush(
        &mut q,
        &mut rhs,
        &prev,
        &mut pending,
        &mut pending_rhs,
        steps,
        from,
    );
    let solve = |k: usize| {
        let k = k.min(steps);
        let mut x = vec![0.0; k];
        for i in (0..k).rev() {
            let s: f64 = (i + 1..k).map(|j| q[j * ld + i] * x[j]).sum();
            x[i] = (rhs[i] - s) / q[i * ld + i];
        }
        x
    };
    let unpermute = |x: Vec<f64>, len: usize| {
        let mut out = vec![0.0; len];
        for (i, v) in x.into_iter().enumerate() {
            out[perm[i]] = v;
        }
        out
    };
    [unpermute(solve(inner), inner), unpermute(solve(n), n)]
}

/// col -= d prev, then next . col (the updated column), over lengths that are multiples of
/// [`LANES`]: the update of one Householder step and the dot product of the next in one
/// pass, each entry and each partial sum as the separate update and [`dot_lanes`] give them.
#[inline(always)]
fn update_dot(col: &mut [f64], prev: &[f64], d: f64, next: &[f64]) -> f64 {
    debug_assert!(col.len().is_multiple_of(LANES) && col.len() == prev.len());
    let (mut lo, mut hi) = ([0.0; 4], [0.0; 4]);
    for ((c, p), x) in col
        .chunks_exact_mut(LANES)
        .zip(prev.chunks_exact(LANES))
        .zip(next.chunks_exact(LANES))
    {
        for k in 0..4 {
            c[k] -= d * p[k];
            lo[k] += x[k] * c[k];
        }
        for k in 4..8 {
            c[k] -= d * p[k];
            hi[k - 4] += x[k] * c[k];
        }
    }
    (lo[0] + hi[0]) + (lo[1] + hi[1]) + ((lo[2] + hi[2]) + (lo[3] + hi[3]))
}

/// [`update_dot`] in two 4-wide AVX registers (the same operations in the same order).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn update_dot_avx(col: &mut [f64], prev: &[f64], d: f64, next: &[f64]) -> f64 {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_setzero_pd,
        _mm256_storeu_pd, _mm256_sub_pd,
    };
    assert!(col.len().is_multiple_of(LANES) && col.len() == prev.len() && col.len() == next.len());
    let dv = _mm256_set1_pd(d);
    let (mut lo, mut hi) = (_mm256_setzero_pd(), _mm256_setzero_pd());
    for k in (0..col.len()).step_by(LANES) {
        // SAFETY: k + 8 <= len for the three slices (asserted above)
        unsafe {
            let (pc, pp, px) = (
                col.as_mut_ptr().add(k),
                prev.as_ptr().add(k),
                next.as_ptr().add(k),
            );
            let c0 = _mm256_sub_pd(_mm256_loadu_pd(pc), _mm256_mul_pd(dv, _mm256_loadu_pd(pp)));
            let c1 = _mm256_sub_pd(
                _mm256_loadu_pd(pc.add(4)),
                _mm256_mul_pd(dv, _mm256_loadu_pd(pp.add(4))),
            );
            _mm256_storeu_pd(pc, c0);
            _mm256_storeu_pd(pc.add(4), c1);
            lo = _mm256_add_pd(lo, _mm256_mul_pd(_mm256_loadu_pd(px), c0));
            hi = _mm256_add_pd(hi, _mm256_mul_pd(_mm256_loadu_pd(px.add(4)), c1));
        }
    }
    let (mut l, mut h) = ([0.0; 4], [0.0; 4]);
    // SAFETY: four doubles each
    unsafe {
        _mm256_storeu_pd(l.as_mut_ptr(), lo);
        _mm256_storeu_pd(h.as_mut_ptr(), hi);
    }
    (l[0] + h[0]) + (l[1] + h[1]) + ((l[2] + h[2]) + (l[3] + h[3]))
}

/// The chunk length of [`dot_lanes`] and of the padding in [`nested_qr_solve_in`].
const LANES: usize = 8;

/// [`dot`] for lengths that are multiples of [`LANES`] (no remainder): the partial sums in
/// two groups of four, as [`dot_lanes_avx`] keeps them in two registers.
#[inline(always)]
fn dot_lanes(a: &[f64], b: &[f64]) -> f64 {
    debug_assert!(a.len().is_multiple_of(LANES) && a.len() == b.len());
    let (mut lo, mut hi) = ([0.0; 4], [0.0; 4]);
    for (x, y) in a.chunks_exact(LANES).zip(b.chunks_exact(LANES)) {
        let (xl, xh) = x.split_at(4);
        let (yl, yh) = y.split_at(4);
        for k in 0..4 {
            lo[k] += xl[k] * yl[k];
        }
        for k in 0..4 {
            hi[k] += xh[k] * yh[k];
        }
    }
    (lo[0] + hi[0]) + (lo[1] + hi[1]) + ((lo[2] + hi[2]) + (lo[3] + hi[3]))
}

/// [`dot_lanes`] in two 4-wide AVX registers: the same products and sums in the same order
/// (no fused multiply-add), so the same result to the bit.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn dot_lanes_avx(a: &[f64], b: &[f64]) -> f64 {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_setzero_pd, _mm256_storeu_pd,
    };
    assert!(a.len().is_multiple_of(LANES) && a.len() == b.len());
    let (mut lo, mut hi) = (_mm256_setzero_pd(), _mm256_setzero_pd());
    for k in (0..a.len()).step_by(LANES) {
        // SAFETY: k + 8 <= len for both slices (asserted above)
        unsafe {
            let (pa, pb) = (a.as_ptr().add(k), b.as_ptr().add(k));
            lo = _mm256_add_pd(lo, _mm256_mul_pd(_mm256_loadu_pd(pa), _mm256_loadu_pd(pb)));
            hi = _mm256_add_pd(
                hi,
                _mm256_mul_pd(_mm256_loadu_pd(pa.add(4)), _mm256_loadu_pd(pb.add(4))),
            );
        }
    }
    let (mut l, mut h) = ([0.0; 4], [0.0; 4]);
    // SAFETY: four doubles each
    unsafe {
        _mm256_storeu_pd(l.as_mut_ptr(), lo);
        _mm256_storeu_pd(h.as_mut_ptr(), hi);
    }
    (l[0] + h[0]) + (l[1] + h[1]) + ((l[2] + h[2]) + (l[3] + h[3]))
}

/// sum a_i b_i in eight independent partial sums, which the compiler keeps in vector
/// registers (a single running sum is a chain it may not reorder): [`nested_qr_solve`]'s
/// Householder steps are these dot products and their updates.
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0; 8];
    let (ca, cb) = (a.chunks_exact(8), b.chunks_exact(8));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        for k in 0..8 {
            acc[k] += x[k] * y[k];
        }
    }
    let tail: f64 = ra.iter().zip(rb).map(|(x, y)| x * y).sum();
    (acc[0] + acc[4]) + (acc[1] + acc[5]) + ((acc[2] + acc[6]) + (acc[3] + acc[7])) + tail
}

/// The examples' thread CPU clock, for the measurement below (one home for it).
#[cfg(all(test, feature = "measure"))]
#[allow(dead_code)]
#[path = "../../examples/support/clock.rs"]
mod clock;

#[cfg(test)]
mod tests {
    use super::*;

    /// A fixed pseudo-random sequence, uniform on [-1/2, 1/2) (a linear congruential
    /// generator from `seed`).
    fn uniform(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        }
    }

    /// The nested QR against faer's column-pivoted QR on both column sets of a random
    /// overdetermined system, and on a rank-deficient one (a repeated column) by residual.
    #[test]
    fn nested_qr_matches_faer() {
        let (m, n, inner) = (60, 20, 13);
        // a fixed pseudo-random matrix (linear congruential)
        let mut next = uniform(12345);
        let a: Vec<f64> = (0..m * n).map(|_| next()).collect();
        let b: Vec<f64> = (0..m).map(|_| next()).collect();
        let [xi, xf] = nested_qr_solve(ColMajor::from_row_major(&a, n), &b, inner);
        let sub: Vec<f64> = a
            .chunks_exact(n)
            .flat_map(|r| r[..inner].to_vec())
            .collect();
        let ri = LeastSquares::pivoted().solve(&sub, inner, &b);
        let rf = LeastSquares::pivoted().solve(&a, n, &b);
        let diff = |x: &[f64], y: &[f64]| {
            x.iter()
                .zip(y)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
        };
        assert!(diff(&xi, &ri) < 1e-13, "inner: {:e}", diff(&xi, &ri));
        assert!(diff(&xf, &rf) < 1e-13, "full: {:e}", diff(&xf, &rf));
        // the inner pivots stay inner: a column of the outer group nearly equal to an inner
        // one changes nothing in the inner solution, and the full residual is no worse than
        // without that column
        let mut a2 = a.clone();
        for row in a2.chunks_exact_mut(n) {
            row[n - 1] = row[0] * (1.0 + 1e-9 * next());
        }
        let [xi2, xf2] = nested_qr_solve(ColMajor::from_row_major(&a2, n), &b, inner);
        assert!(diff(&xi2, &ri) < 1e-13);
        let resid = |x: &[f64]| {
            a2.chunks_exact(n)
                .zip(&b)
                .map(|(r, bi)| (r.iter().zip(x).map(|(a, x)| a * x).sum::<f64>() - bi).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let best = {
            let sub2: Vec<f64> = a2
                .chunks_exact(n)
                .flat_map(|r| r[..n - 1].to_vec())
                .collect();
            let mut x = LeastSquares::pivoted().solve(&sub2, n - 1, &b);
            x.push(0.0);
            resid(&x)
        };
        assert!(
            resid(&xf2) <= best * (1.0 + 1e-6),
            "{} {}",
            resid(&xf2),
            best
        );
    }

    /// The AVX build of the nested QR (where the CPU has AVX) against the baseline build, to
    /// the bit: the same operations in the same order ([`dot_lanes_avx`]), on random systems
    /// of the spectral frames' shapes with every padding remainder (m mod 8).
    #[test]
    fn nested_qr_avx_is_the_baseline_to_the_bit() {
        let mut next = uniform(99);
        for (m, n, inner) in [
            (59, 37, 28),
            (60, 37, 30),
            (61, 20, 13),
            (66, 44, 37),
            (8, 5, 3),
        ] {
            let a: Vec<f64> = (0..m * n).map(|_| next()).collect();
            let b: Vec<f64> = (0..m).map(|_| next()).collect();
            let a = ColMajor::from_row_major(&a, n);
            let [xi, xf] = nested_qr_solve(a.clone(), &b, inner);
            let [yi, yf] = nested_qr_solve_in::<false>(a, &b, inner);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&xi), bits(&yi), "{m} x {n}");
            assert_eq!(bits(&xf), bits(&yf), "{m} x {n}");
        }
    }

    #[cfg(feature = "measure")]
    use super::clock::cpu_seconds;

    /// [`OWN_QR_COLUMNS`]' table: [`constrained`] (faer's pivoted QR) against
    /// [`constrained_by`] with our QR, thread CPU time, alternated, minima.
    /// A measurement, not a check (the `measure` feature only, kept out of the tiers):
    /// `cargo test --release --features measure --lib own_qr_crossover -- --ignored --nocapture`
    #[cfg(feature = "measure")]
    #[test]
    #[ignore = "measurement"]
    fn own_qr_crossover() {
        let mut next = uniform(777);
        // rows per column: the spectral systems' 1.8, and the 2.8 they had before
        for (per, n) in [1.8, 2.8]
            .into_iter()
            .flat_map(|per| [24, 36, 45, 55, 62, 66, 72, 80, 93, 110].map(|n| (per, n)))
        {
            let m = (per * n as f64) as usize;
            // the frames' shape at m perturbed Chebyshev points x: half the columns
            // Chebyshev polynomials, half poles 1/(z_j - x), z_j = 1 + 1e-3 1.3^j (clustered,
            // near-dependent), sigma's column random; columns scaled to unit norm
            let mut a = vec![0.0; m * n];
            let poles = (n - 1) / 2;
            for i in 0..m {
                let th = std::f64::consts::PI * (i as f64 + 0.5 + 0.1 * next()) / m as f64;
                for j in 0..n - 1 {
                    a[i * n + j] = if j < poles {
                        1.0 / (1.0 + 1e-3 * 1.3f64.powi(j as i32) - th.cos())
                    } else {
                        ((j - poles) as f64 * th).cos()
                    };
                }
                a[i * n + n - 1] = next();
            }
            for j in 0..n {
                let norm = (0..m).map(|i| a[i * n + j].powi(2)).sum::<f64>().sqrt();
                (0..m).for_each(|i| a[i * n + j] /= norm);
            }
            let b = vec![0.0; m];
            let cons: Vec<(Vec<f64>, f64)> = (0..3)
                .map(|k| {
                    let mut row: Vec<f64> = (0..n).map(|_| next()).collect();
                    row[n - 1] = 0.0;
                    (row, if k == 0 { 1.0 } else { 0.0 })
                })
                .collect();
            let (acm, order) = (ColMajor::from_row_major(&a, n), (0..n).collect::<Vec<_>>());
            let reps = (2_000_000 / (m * n * n)).max(3);
            let time = |own: bool| {
                let t = cpu_seconds();
                for _ in 0..reps {
                    std::hint::black_box(
                        constrained_by(&acm, &order, &b, cons.clone(), n - 1, own).unwrap(),
                    );
                }
                (cpu_seconds() - t) / reps as f64
            };
            let (mut tf, mut to) = (f64::INFINITY, f64::INFINITY);
            for _ in 0..7 {
                tf = tf.min(time(false));
                to = to.min(time(true));
            }
            let xf = constrained(&a, n, &b, cons.clone(), n - 1).unwrap();
            let xo = constrained_by(&acm, &order, &b, cons.clone(), n - 1, true).unwrap();
            // the residual norms (the near-dependent columns leave the coefficients free)
            let resid = |x: &[f64]| {
                a.chunks_exact(n)
                    .zip(&b)
                    .map(|(r, bi)| (dot(r, x) - bi).powi(2))
                    .sum::<f64>()
                    .sqrt()
            };
            println!(
                "| {m} x {n} | {:.0} | {:.0} | {:.2} | {:.3e} | {:.3e} |",
                1e6 * tf,
                1e6 * to,
                tf / to,
                resid(&xf),
                resid(&xo)
            );
        }
    }
}
