//! Discretisation of (E1)-(E4) in displacement (Volterra) form on N uniform panels of
//! [0, 1] with piecewise-constant tractions, p even and q odd (paper eqs. (4), (5), (7),
//! (8); docs/theory.md §3 and (P1), (P2)).
//!
//! With L[f](x) = (1/pi) int_{-1}^{1} f(t) ln|x - t| dt, H[f] = d/dx L[f], so integrating
//! the gradients from the centre gives, at the panel midpoints x_i:
//! - (E1): L[p](x_i) - bp int_0^{x_i} q = W (W = L[p](0), an unknown constant: the normal
//!   displacement gradient (5) vanishes under the punch);
//! - tangential slip: s(x_i) = bq int_0^{x_i} p + L[q](x_i) (L[q](0) = 0 as q is odd), the
//!   Volterra integral of (bq p + H[q]), i.e. of -u0'/(pi B) from eq. (4);
//! - (E4): 2 h sum_j p_j = 1.
//!
//! Eliminating p and W (linear in q) leaves an affine LCP in q^ = q / mu (mu > 0):
//! a = s / bq >= 0 (slip), b = p - q^ = (mu p - q) / mu >= 0 (friction reserve), a b = 0.

use super::dense::Lu;
use crate::error::Result;
use crate::problem::Coupling;
use faer::Mat;
use std::f64::consts::PI;

/// N uniform panels [j h, (j + 1) h] of [0, 1], collocation at the midpoints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grid {
    /// Number of panels on [0, 1].
    pub n: usize,
    /// Panel width 1 / n.
    pub h: f64,
}

impl Grid {
    pub(crate) fn new(n: usize) -> Self {
        Self {
            n,
            h: 1.0 / n as f64,
        }
    }

    /// Midpoint of panel i.
    pub(crate) fn mid(&self, i: usize) -> f64 {
        (i as f64 + 0.5) * self.h
    }

    /// Trapezoid-in-the-last-panel running integral at the midpoints:
    /// int_0^{x_i} v = h (sum_{j<i} v_j + v_i / 2), exact for piecewise-constant v.
    pub(crate) fn running_integral(&self, v: &[f64]) -> Vec<f64> {
        let mut acc = 0.0;
        v.iter()
            .map(|&vi| {
                let out = self.h * (acc + 0.5 * vi);
                acc += vi;
                out
            })
            .collect()
    }
}

/// int_{u1}^{u2} ln|u| du (u1 < u2), without the cancellation of the antiderivative
/// difference when the interval is short compared with its distance from 0.
fn log_integral(u1: f64, u2: f64) -> f64 {
    let m = 0.5 * (u1 + u2);
    let d = 0.5 * (u2 - u1);
    if m.abs() > 4.0 * d {
        // 2d [ln|m| - sum_{k>=1} r^(2k) / (2k (2k + 1))], r = d/m, |r| < 1/4.
        let r2 = (d / m).powi(2);
        let mut term = 1.0;
        let mut series = 0.0;
        for k in 1..=13 {
            term *= r2;
            let kk = 2.0 * k as f64;
            series += term / (kk * (kk + 1.0));
        }
        2.0 * d * (m.abs().ln() - series)
    } else {
        let f = |u: f64| if u == 0.0 { 0.0 } else { u * u.abs().ln() - u };
        f(u2) - f(u1)
    }
}

/// Log-kernel matrix (1/pi) int over panel j and its mirror image of ln|x_i - t| dt, for an
/// even (`sign` = +1) or odd (`sign` = -1) piecewise-constant density.
fn log_matrix(grid: Grid, sign: f64) -> Mat<f64> {
    let h = grid.h;
    Mat::from_fn(grid.n, grid.n, |i, j| {
        let x = grid.mid(i);
        let (a, b) = (j as f64 * h, (j + 1) as f64 * h);
        (log_integral(x - b, x - a) + sign * log_integral(x + a, x + b)) / PI
    })
}

/// The affine LCP in q^ = q / mu: find q^ with a = a0 + A q^ >= 0, b = b0 + B q^ >= 0,
/// a_i b_i = 0; then p = b + q^ and the slip is bq a.
pub(crate) struct AffineLcp {
    pub a0: Vec<f64>,
    pub a: Mat<f64>,
    pub b0: Vec<f64>,
    pub b: Mat<f64>,
}

/// Pressure for q = 0 (the frictionless flat punch, discretised) and, when `coupled`,
/// K with p = p_bar + bp K q (the response of (E1) + (E4) to the shear).
fn pressure_response(grid: Grid, coupled: bool) -> Result<(Vec<f64>, Option<Mat<f64>>)> {
    let n = grid.n;
    let le = log_matrix(grid, 1.0);
    // Unknowns (p_0..p_{n-1}, W); rows: (E1) at the midpoints, then (E4).
    let system = Mat::from_fn(n + 1, n + 1, |i, j| match (i < n, j < n) {
        (true, true) => le[(i, j)],
        (true, false) => -1.0,
        (false, true) => 2.0 * grid.h,
        (false, false) => 0.0,
    });
    drop(le);
    let lu = Lu::new(system)?;
    let mut unit = vec![0.0; n + 1];
    unit[n] = 1.0;
    let p_bar = lu.solve_vec(&unit)?[..n].to_vec();
    if !coupled {
        return Ok((p_bar, None));
    }
    // Right-hand sides: the running-integral matrix of q (rows of (E1)), 0 for (E4).
    let mut k = Mat::from_fn(n + 1, n, |i, j| match (i < n, j.cmp(&i)) {
        (false, _) | (true, std::cmp::Ordering::Greater) => 0.0,
        (true, std::cmp::Ordering::Equal) => 0.5 * grid.h,
        (true, std::cmp::Ordering::Less) => grid.h,
    });
    lu.solve_in_place(k.as_mut())?;
    Ok((p_bar, Some(k.subrows(0, n).to_owned())))
}

/// Frictionless discrete pressure on the panels of `grid` (mu = 0: q = 0).
pub(crate) fn frictionless_pressure(grid: Grid) -> Result<Vec<f64>> {
    Ok(pressure_response(grid, false)?.0)
}

/// Assembles the LCP for `k` (mu > 0, bq > 0).
pub(crate) fn assemble(grid: Grid, k: &Coupling) -> Result<AffineLcp> {
    let n = grid.n;
    let coupled = k.bp * k.mu > 0.0;
    let (p_bar, kmat) = pressure_response(grid, coupled)?;
    // a = (bq P[p] + L[q]) / bq with p = p_bar + bp mu K q^, q = mu q^.
    let a0 = grid.running_integral(&p_bar);
    let mut a = log_matrix(grid, -1.0);
    let scale = k.mu / k.bq;
    for j in 0..n {
        for i in 0..n {
            a[(i, j)] *= scale;
        }
    }
    let mut b = Mat::from_fn(n, n, |i, j| if i == j { -1.0 } else { 0.0 });
    if let Some(kmat) = kmat {
        let f = k.bp * k.mu;
        for j in 0..n {
            // Column j of bp mu P K (running integral down the column) into a; bp mu K into b.
            let mut acc = 0.0;
            for i in 0..n {
                let v = f * kmat[(i, j)];
                a[(i, j)] += grid.h * (acc + 0.5 * v);
                acc += v;
                b[(i, j)] += v;
            }
        }
    }
    Ok(AffineLcp {
        a0,
        a,
        b0: p_bar,
        b,
    })
}

/// The whole contact [-1, 1] without symmetry (for loads that break it: docs/theory_tangential.md, (E1)-(E4) of docs/theory.md §3
/// with int q = Q/P != 0): 2n uniform panels of width h = 1/n, midpoints
/// x_i = -1 + (i + 1/2) h, piecewise-constant p and q.
///
/// - `l`: L_ij = (1/pi) int_{panel j} ln|x_i - t| dt (symmetric Toeplitz);
/// - `s`: the symmetric running integral S f(x_i) = (int_{-1}^{x_i} f - int_{x_i}^1 f) / 2,
///   S_ij = sgn(i - j) h / 2 (antisymmetric; the kernel sgn(x - t) / 2 of the Green's
///   function's A terms in the gauge that makes them reciprocal);
/// - (E1) with the force balance, L p - bp S q = W (W: an unknown constant), h sum p = 1,
///   solved as p = `p_bar` + bp K q and W = W_bar + bp `wk`. q (the constant W_bar, a gauge
///   of the normal displacement, is not kept).
pub(crate) struct FullLine {
    /// Panels per half-width.
    pub n: usize,
    /// Panel width 1 / n.
    pub h: f64,
    pub l: Mat<f64>,
    pub s: Mat<f64>,
    pub p_bar: Vec<f64>,
    pub k: Mat<f64>,
    pub wk: Vec<f64>,
}

impl FullLine {
    /// Midpoint of panel i (0 <= i < 2n).
    pub(crate) fn mid(&self, i: usize) -> f64 {
        -1.0 + (i as f64 + 0.5) * self.h
    }

    /// The operators on 2n panels (n panels per half-width).
    pub(crate) fn new(n: usize) -> Result<Self> {
        let m = 2 * n;
        let h = 1.0 / n as f64;
        let toeplitz: Vec<f64> = (0..m)
            .map(|d| {
                let d = d as f64;
                log_integral((d - 0.5) * h, (d + 0.5) * h) / PI
            })
            .collect();
        let l = Mat::from_fn(m, m, |i, j| toeplitz[i.abs_diff(j)]);
        let s = Mat::from_fn(m, m, |i, j| match i.cmp(&j) {
            std::cmp::Ordering::Greater => 0.5 * h,
            std::cmp::Ordering::Less => -0.5 * h,
            std::cmp::Ordering::Equal => 0.0,
        });
        // Unknowns (p, W); rows: L p - W = rhs at the midpoints, then h sum p = 1.
        let system = Mat::from_fn(m + 1, m + 1, |i, j| match (i < m, j < m) {
            (true, true) => l[(i, j)],
            (true, false) => -1.0,
            (false, true) => h,
            (false, false) => 0.0,
        });
        let lu = Lu::new(system)?;
        let mut unit = vec![0.0; m + 1];
        unit[m] = 1.0;
        let bar = lu.solve_vec(&unit)?;
        let mut rhs = Mat::from_fn(m + 1, m, |i, j| if i < m { s[(i, j)] } else { 0.0 });
        lu.solve_in_place(rhs.as_mut())?;
        Ok(Self {
            n,
            h,
            p_bar: bar[..m].to_vec(),
            k: rhs.subrows(0, m).to_owned(),
            wk: (0..m).map(|j| rhs[(m, j)]).collect(),
            l,
            s,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_integral_matches_the_antiderivative_and_midpoint_quadrature() {
        let f = |u: f64| if u == 0.0 { 0.0 } else { u * u.abs().ln() - u };
        for &(u1, u2) in &[
            (0.3, 0.5),
            (-2.0, -1.9),
            (1.0, 1.001),
            (-0.1, 0.2),
            (0.0, 0.4),
        ] {
            let exact = f(u2) - f(u1);
            assert!((log_integral(u1, u2) - exact).abs() < 1e-14, "{u1} {u2}");
        }
        // Short interval far from 0: compare with a 2-point Gauss rule (error ~ d^5/m^4).
        let (u1, u2) = (1.7, 1.7 + 1e-4);
        let (m, d) = (0.5 * (u1 + u2), 0.5 * (u2 - u1));
        let g = d / 3f64.sqrt();
        let gauss = d * ((m - g).ln() + (m + g).ln());
        assert!((log_integral(u1, u2) - gauss).abs() < 1e-19);
    }

    #[test]
    fn frictionless_pressure_has_unit_force_and_converges_to_the_inverse_sqrt_profile() {
        // p0 = 1 / (pi sqrt(1 - x^2)); compare panel values with panel averages of p0 on
        // x < 0.9 (away from the edge singularity): first order, error ~ 0.2 / n.
        let worst = |n: usize| {
            let grid = Grid::new(n);
            let p = frictionless_pressure(grid).unwrap();
            let force: f64 = 2.0 * grid.h * p.iter().sum::<f64>();
            assert!((force - 1.0).abs() < 1e-13);
            (0..n)
                .filter(|&i| grid.mid(i) < 0.9)
                .map(|i| {
                    let (a, b) = (i as f64 * grid.h, (i + 1) as f64 * grid.h);
                    let avg = (b.asin() - a.asin()) / (PI * grid.h);
                    (p[i] / avg - 1.0).abs()
                })
                .fold(0.0f64, f64::max)
        };
        let (e100, e200, e400) = (worst(100), worst(200), worst(400));
        assert!(e100 < 1e-2, "{e100}");
        for (coarse, fine) in [(e100, e200), (e200, e400)] {
            let order = (coarse / fine).log2();
            assert!((0.8..1.3).contains(&order), "{e100} {e200} {e400}");
        }
    }
}
