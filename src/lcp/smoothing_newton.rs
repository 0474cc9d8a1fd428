//! Smoothing Newton method for the affine LCP a(z) >= 0, b(z) >= 0, a_i b_i = 0
//! (the paper's "Newton-based optimization algorithm based on smoothing approximation",
//! section 4; docs/theory.md (P3)).
//!
//! Smoothed Fischer-Burmeister function phi(eps, a, b) = a + b - sqrt(a^2 + b^2 + 2 eps^2)
//! (phi = 0 iff a, b > 0 and a b = eps^2; at eps = 0 iff a, b >= 0 and a b = 0), and the
//! squared smoothing Newton method of Qi, Sun and Zhou (Math. Program. 87 (2000) 1-35):
//! Newton on H(eps, z) = (eps, phi(eps, a(z), b(z))) with the smoothing parameter as an
//! unknown driven to zero, step target beta(w) = gamma min(1, |H|^2) for eps and an Armijo
//! line search on |H|^2.

use super::dense::Lu;
use super::discretisation::AffineLcp;
use crate::error::{Error, Result};
use faer::Mat;

/// Line-search and smoothing constants (Qi-Sun-Zhou: gamma * eps0 < 1).
const GAMMA: f64 = 0.2;
const SIGMA: f64 = 1e-4;
const MAX_HALVINGS: usize = 40;

/// Iteration controls.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Controls {
    /// Initial smoothing parameter eps0 in (0, 1].
    pub eps0: f64,
    /// Stop when max_i |phi(0, a_i, b_i)| <= tol.
    pub tol: f64,
    /// Iteration cap.
    pub max_iter: usize,
}

/// Converged iterate: z, the complementarity pair (a, b) and the Newton iteration count.
pub(crate) struct LcpRoot {
    pub z: Vec<f64>,
    pub a: Vec<f64>,
    pub b: Vec<f64>,
    pub iterations: usize,
}

fn affine(v0: &[f64], m: &Mat<f64>, z: &[f64]) -> Vec<f64> {
    let mut out = v0.to_vec();
    for (j, &zj) in z.iter().enumerate() {
        if zj != 0.0 {
            let col = m.col(j);
            for (i, o) in out.iter_mut().enumerate() {
                *o += col[i] * zj;
            }
        }
    }
    out
}

fn fb(eps: f64, a: f64, b: f64) -> f64 {
    a + b - a.hypot(b).hypot(std::f64::consts::SQRT_2 * eps)
}

/// |H(eps, z)|^2 with the pair (a, b) already evaluated.
fn merit(eps: f64, a: &[f64], b: &[f64]) -> f64 {
    eps * eps
        + a.iter()
            .zip(b)
            .map(|(&ai, &bi)| fb(eps, ai, bi).powi(2))
            .sum::<f64>()
}

/// Solves the LCP from the start `z0`.
pub(crate) fn solve(lcp: &AffineLcp, z0: &[f64], ctl: Controls) -> Result<LcpRoot> {
    let n = z0.len();
    let eps_bar = ctl.eps0;
    let mut eps = eps_bar;
    let mut z = z0.to_vec();
    let mut a = affine(&lcp.a0, &lcp.a, &z);
    let mut b = affine(&lcp.b0, &lcp.b, &z);
    let mut psi = merit(eps, &a, &b);
    for iteration in 0..=ctl.max_iter {
        let residual = a
            .iter()
            .zip(&b)
            .map(|(&ai, &bi)| fb(0.0, ai, bi).abs())
            .fold(0.0f64, f64::max);
        if !residual.is_finite() {
            return Err(Error::NoConvergence(
                "non-finite complementarity residual".into(),
            ));
        }
        if residual <= ctl.tol {
            return Ok(LcpRoot {
                z,
                a,
                b,
                iterations: iteration,
            });
        }
        if iteration == ctl.max_iter {
            break;
        }
        // Newton step: d_eps = -eps + beta eps_bar; J dz = -phi - phi_eps d_eps.
        let beta = GAMMA * psi.min(1.0);
        let d_eps = -eps + beta * eps_bar;
        let mut da = vec![0.0; n];
        let mut db = vec![0.0; n];
        let mut rhs = vec![0.0; n];
        for i in 0..n {
            let rho = a[i].hypot(b[i]).hypot(std::f64::consts::SQRT_2 * eps);
            let (ga, gb, ge) = if rho > 0.0 {
                (1.0 - a[i] / rho, 1.0 - b[i] / rho, -2.0 * eps / rho)
            } else {
                // An element of the generalised Jacobian at the kink.
                let c = 1.0 - std::f64::consts::FRAC_1_SQRT_2;
                (c, c, 0.0)
            };
            da[i] = ga;
            db[i] = gb;
            rhs[i] = -(a[i] + b[i] - rho) - ge * d_eps;
        }
        let jac = Mat::from_fn(n, n, |i, j| da[i] * lcp.a[(i, j)] + db[i] * lcp.b[(i, j)]);
        let dz = Lu::new(jac)?.solve_vec(&rhs)?;
        let da_lin = affine(&vec![0.0; n], &lcp.a, &dz);
        let db_lin = affine(&vec![0.0; n], &lcp.b, &dz);
        // Armijo search on |H|^2 along the full (eps, z) direction.
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..MAX_HALVINGS {
            let eps_t = eps + lambda * d_eps;
            let a_t: Vec<f64> = a.iter().zip(&da_lin).map(|(x, d)| x + lambda * d).collect();
            let b_t: Vec<f64> = b.iter().zip(&db_lin).map(|(x, d)| x + lambda * d).collect();
            let psi_t = merit(eps_t, &a_t, &b_t);
            if psi_t <= (1.0 - 2.0 * SIGMA * (1.0 - GAMMA * eps_bar) * lambda) * psi {
                for (zi, d) in z.iter_mut().zip(&dz) {
                    *zi += lambda * d;
                }
                eps = eps_t;
                a = a_t;
                b = b_t;
                psi = psi_t;
                accepted = true;
                break;
            }
            lambda *= 0.5;
        }
        if !accepted {
            return Err(Error::NoConvergence(format!(
                "smoothing Newton line search failed at iteration {iteration} (|H|^2 = {psi:.3e})"
            )));
        }
    }
    Err(Error::NoConvergence(format!(
        "smoothing Newton did not converge in {} iterations (|H|^2 = {psi:.3e})",
        ctl.max_iter
    )))
}

/// An affine mixed complementarity problem with bounds that move with the unknowns: find
/// z in R^n such that, for the first m rows (m <= n), with the gaps to the lower and upper
/// bound g_l = gl0 + GL z >= 0, g_u = gu0 + GU z >= 0 and F = f0 + FM z,
/// g_l = 0 => F >= 0, g_u = 0 => F <= 0, and F = 0 where both gaps are positive; the rows
/// m..n are equalities F = 0 (free unknowns). (A box-constrained variational inequality: a
/// friction force between -mu p and mu p against a slip increment.)
pub(crate) struct BoxMcp<'a> {
    pub gl0: Vec<f64>,
    pub gl: &'a Mat<f64>,
    pub gu0: Vec<f64>,
    pub gu: &'a Mat<f64>,
    pub f0: Vec<f64>,
    pub f: &'a Mat<f64>,
}

/// The smoothed box function Phi = phi(g_l, -phi(g_u, -F)) (the nested Fischer-Burmeister
/// form of Billups and of Chen-Harker-Kanzow-Smale for bounds), with its partial derivatives
/// (d/dg_l, d/dg_u, d/dF, d/deps).
fn box_phi(eps: f64, gl: f64, gu: f64, f: f64) -> (f64, [f64; 4]) {
    let e2 = std::f64::consts::SQRT_2 * eps;
    let rho_in = gu.hypot(f).hypot(e2);
    let inner = gu - f - rho_in;
    let y = -inner;
    let rho = gl.hypot(y).hypot(e2);
    let phi = gl + y - rho;
    let (pa, pb, pe) = if rho > 0.0 {
        (1.0 - gl / rho, 1.0 - y / rho, -2.0 * eps / rho)
    } else {
        let c = 1.0 - std::f64::consts::FRAC_1_SQRT_2;
        (c, c, 0.0)
    };
    let (qa, qb, qe) = if rho_in > 0.0 {
        (1.0 - gu / rho_in, 1.0 + f / rho_in, -2.0 * eps / rho_in)
    } else {
        let c = 1.0 - std::f64::consts::FRAC_1_SQRT_2;
        (c, c, 0.0)
    };
    // inner = phi(g_u, -F): d inner = qa dg_u - qb dF + qe deps; y = -inner.
    (phi, [pa, -pb * qa, pb * qb, pe - pb * qe])
}

/// Converged iterate of a [`BoxMcp`]: z, the gaps and F there, and the Newton count.
pub(crate) struct BoxRoot {
    pub z: Vec<f64>,
    pub gl: Vec<f64>,
    pub gu: Vec<f64>,
    pub f: Vec<f64>,
    pub iterations: usize,
}

/// Solves the [`BoxMcp`] from `z0` by the same smoothing Newton method as [`solve`]
/// (Qi-Sun-Zhou on H(eps, z) = (eps, Phi_eps(z)), Armijo search on |H|^2); converged when
/// max |Phi_0| <= `ctl.tol`.
pub(crate) fn solve_box(mcp: &BoxMcp<'_>, z0: &[f64], ctl: Controls) -> Result<BoxRoot> {
    let n = z0.len();
    let m = mcp.gl0.len();
    let eps_bar = ctl.eps0;
    let mut eps = eps_bar;
    let mut z = z0.to_vec();
    let mut gl = affine(&mcp.gl0, mcp.gl, &z);
    let mut gu = affine(&mcp.gu0, mcp.gu, &z);
    let mut f = affine(&mcp.f0, mcp.f, &z);
    let values = |eps: f64, gl: &[f64], gu: &[f64], f: &[f64]| -> Vec<f64> {
        (0..n)
            .map(|i| {
                if i < m {
                    box_phi(eps, gl[i], gu[i], f[i]).0
                } else {
                    f[i]
                }
            })
            .collect()
    };
    let merit = |eps: f64, v: &[f64]| eps * eps + v.iter().map(|x| x * x).sum::<f64>();
    let mut psi = merit(eps, &values(eps, &gl, &gu, &f));
    for iteration in 0..=ctl.max_iter {
        let residual = values(0.0, &gl, &gu, &f)
            .iter()
            .fold(0.0f64, |r, v| r.max(v.abs()));
        if !residual.is_finite() {
            return Err(Error::NoConvergence(
                "non-finite complementarity residual".into(),
            ));
        }
        if residual <= ctl.tol {
            return Ok(BoxRoot {
                z,
                gl,
                gu,
                f,
                iterations: iteration,
            });
        }
        if iteration == ctl.max_iter {
            break;
        }
        let beta = GAMMA * psi.min(1.0);
        let d_eps = -eps + beta * eps_bar;
        let mut rhs = vec![0.0; n];
        let mut coef = vec![[0.0; 4]; m];
        for i in 0..n {
            if i < m {
                let (phi, d) = box_phi(eps, gl[i], gu[i], f[i]);
                coef[i] = d;
                rhs[i] = -phi - d[3] * d_eps;
            } else {
                rhs[i] = -f[i];
            }
        }
        let jac = Mat::from_fn(n, n, |i, j| {
            if i < m {
                let d = coef[i];
                d[0] * mcp.gl[(i, j)] + d[1] * mcp.gu[(i, j)] + d[2] * mcp.f[(i, j)]
            } else {
                mcp.f[(i, j)]
            }
        });
        let dz = Lu::new(jac)?.solve_vec(&rhs)?;
        let dgl = affine(&vec![0.0; m], mcp.gl, &dz);
        let dgu = affine(&vec![0.0; m], mcp.gu, &dz);
        let df = affine(&vec![0.0; n], mcp.f, &dz);
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..MAX_HALVINGS {
            let step = |v: &[f64], d: &[f64]| -> Vec<f64> {
                v.iter().zip(d).map(|(x, d)| x + lambda * d).collect()
            };
            let eps_t = eps + lambda * d_eps;
            let (gl_t, gu_t, f_t) = (step(&gl, &dgl), step(&gu, &dgu), step(&f, &df));
            let psi_t = merit(eps_t, &values(eps_t, &gl_t, &gu_t, &f_t));
            if psi_t <= (1.0 - 2.0 * SIGMA * (1.0 - GAMMA * eps_bar) * lambda) * psi {
                for (zi, d) in z.iter_mut().zip(&dz) {
                    *zi += lambda * d;
                }
                (eps, gl, gu, f, psi) = (eps_t, gl_t, gu_t, f_t, psi_t);
                accepted = true;
                break;
            }
            lambda *= 0.5;
        }
        if !accepted {
            return Err(Error::NoConvergence(format!(
                "smoothing Newton (box) line search failed at iteration {iteration} \
                 (|H|^2 = {psi:.3e})"
            )));
        }
    }
    Err(Error::NoConvergence(format!(
        "smoothing Newton (box) did not converge in {} iterations (|H|^2 = {psi:.3e})",
        ctl.max_iter
    )))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_small_lcp_with_known_solution() {
        // a = M z + q0 (M positive definite), b = z: the classical LCP w = M z + q0 >= 0,
        // z >= 0, w z = 0. Solution built in: z = (1, 0, 2), w = (0, 3, 0).
        let m = Mat::from_fn(3, 3, |i, j| {
            [[4.0, 1.0, 0.5], [1.0, 3.0, 1.0], [0.5, 1.0, 5.0]][i][j]
        });
        let z_true = [1.0, 0.0, 2.0];
        let w_true = [0.0, 3.0, 0.0];
        let mz: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| m[(i, j)] * z_true[j]).sum())
            .collect();
        let lcp = AffineLcp {
            a0: (0..3).map(|i| w_true[i] - mz[i]).collect(),
            a: m,
            b0: vec![0.0; 3],
            b: Mat::from_fn(3, 3, |i, j| if i == j { 1.0 } else { 0.0 }),
        };
        let ctl = Controls {
            eps0: 1.0,
            tol: 1e-13,
            max_iter: 50,
        };
        let root = solve(&lcp, &[0.0; 3], ctl).unwrap();
        for i in 0..3 {
            assert!((root.z[i] - z_true[i]).abs() < 1e-12);
            assert!((root.a[i] - w_true[i]).abs() < 1e-12);
        }
        assert!(root.iterations > 0 && root.iterations < 30);
    }
    #[test]
    fn solves_a_small_box_problem_with_moving_bounds_and_a_free_row() {
        // z = (x0, x1, t): bounds -1 - 0.1 x1 <= x0 <= 1 + 0.1 x1 and -2 <= x1 <= 2 with
        // F0 = x0 - t - 3, F1 = x1 - 0.5; free row t = 0.25. Solution: x1 = 0.5 inside;
        // x0 at its upper bound 1.05 with F0 = 1.05 - 0.25 - 3 < 0.
        let gl = Mat::from_fn(2, 3, |i, j| [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0]][i][j]);
        let gu = Mat::from_fn(2, 3, |i, j| [[-1.0, 0.1, 0.0], [0.0, -1.0, 0.0]][i][j]);
        let f = Mat::from_fn(3, 3, |i, j| {
            [[1.0, 0.0, -1.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]][i][j]
        });
        let mcp = BoxMcp {
            gl0: vec![1.0, 2.0],
            gl: &gl,
            gu0: vec![1.0, 2.0],
            gu: &gu,
            f0: vec![-3.0, -0.5, -0.25],
            f: &f,
        };
        let ctl = Controls {
            eps0: 1.0,
            tol: 1e-13,
            max_iter: 50,
        };
        let root = solve_box(&mcp, &[0.0; 3], ctl).unwrap();
        let want = [1.05, 0.5, 0.25];
        for (z, w) in root.z.iter().zip(want) {
            assert!((z - w).abs() < 1e-12, "{:?}", root.z);
        }
        assert!(root.gu[0].abs() < 1e-12 && root.f[0] < 0.0);
    }
}
