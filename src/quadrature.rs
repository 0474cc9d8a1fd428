//! Gauss-Jacobi quadrature on [-1, 1] for the weight (1 - x)^alpha (1 + x)^beta.
//!
//! Golub-Welsch: the nodes are the eigenvalues of the symmetric tridiagonal Jacobi matrix of
//! the Jacobi recurrence (found by implicit QL with Wilkinson shifts, O(n^2)); each node is
//! then polished by Newton's method on the three-term recurrence, and the weights are the
//! Christoffel numbers w_i = mu0 / sum_{k<n} p_k(x_i)^2 with p_k orthonormal for the
//! normalised weight, mu0 = int w = 2^(alpha+beta+1) B(alpha+1, beta+1). This keeps the
//! weights to full relative accuracy (the eigenvector form loses it for small weights).

use std::f64::consts::PI;

/// Stirling's series 1/(12y) - 1/(360y^3) + ... to y^-13 (error < 1e-17 for y >= 15).
fn stirling_series(y: f64) -> f64 {
    let r = 1.0 / y;
    let r2 = r * r;
    r * (1.0 / 12.0
        + r2 * (-1.0 / 360.0
            + r2 * (1.0 / 1260.0
                + r2 * (-1.0 / 1680.0
                    + r2 * (1.0 / 1188.0 + r2 * (-691.0 / 360_360.0 + r2 / 156.0))))))
}

/// Gamma(x) for 0 < x < 171 to a few ulps: upward recurrence to y >= 15, then
/// Gamma(y) = sqrt(2 pi) y^(y - 1/2) e^(-y) e^(series(y)) with the power split in halves.
pub fn gamma(x: f64) -> f64 {
    let mut y = x;
    let mut prod = 1.0;
    while y < 15.0 {
        prod *= y;
        y += 1.0;
    }
    let half = y.powf(0.5 * (y - 0.5));
    (2.0 * PI).sqrt() * half * (-y).exp() * half * stirling_series(y).exp() / prod
}

/// ln Gamma(x) for x > 0 (via [`gamma`] below 170, Stirling's series above).
pub fn ln_gamma(x: f64) -> f64 {
    if x < 170.0 {
        gamma(x).ln()
    } else {
        (x - 0.5) * x.ln() - x + 0.5 * (2.0 * PI).ln() + stirling_series(x)
    }
}

/// Total mass int_{-1}^{1} (1 - x)^alpha (1 + x)^beta dx = 2^(alpha+beta+1) B(alpha+1, beta+1).
pub fn jacobi_mass(alpha: f64, beta: f64) -> f64 {
    let s = alpha + beta + 2.0;
    if s < 170.0 {
        gamma(alpha + 1.0) / gamma(s) * gamma(beta + 1.0) * (s - 1.0).exp2()
    } else {
        ((s - 1.0) * std::f64::consts::LN_2 + ln_gamma(alpha + 1.0) + ln_gamma(beta + 1.0)
            - ln_gamma(s))
        .exp()
    }
}

/// Recurrence coefficients of the orthonormal Jacobi polynomials: diagonal a_k (k < n) and
/// off-diagonal e_k = sqrt(b_{k+1}) (k < n - 1), with the k = 0, 1 cases written so that
/// alpha + beta = 0 or -1 cause no 0/0.
fn jacobi_matrix(n: usize, alpha: f64, beta: f64) -> (Vec<f64>, Vec<f64>) {
    let (a, b) = (alpha, beta);
    let ab = a + b;
    let diag = (0..n)
        .map(|k| {
            let s = 2.0 * k as f64 + ab;
            if k == 0 {
                (b - a) / (ab + 2.0)
            } else {
                (b * b - a * a) / (s * (s + 2.0))
            }
        })
        .collect();
    let off = (1..n)
        .map(|k| {
            let kf = k as f64;
            let s = 2.0 * kf + ab;
            let b_k = if k == 1 {
                4.0 * (1.0 + a) * (1.0 + b) / ((2.0 + ab) * (2.0 + ab) * (3.0 + ab))
            } else {
                4.0 * kf * (kf + a) * (kf + b) * (kf + ab) / (s * s * (s + 1.0) * (s - 1.0))
            };
            b_k.sqrt()
        })
        .collect();
    (diag, off)
}

/// sqrt(a^2 + b^2) without overflow (cheaper than `f64::hypot`, to a few ulps).
fn pythag(a: f64, b: f64) -> f64 {
    let (a, b) = (a.abs(), b.abs());
    if a > b {
        a * (1.0 + (b / a) * (b / a)).sqrt()
    } else if b == 0.0 {
        0.0
    } else {
        b * (1.0 + (a / b) * (a / b)).sqrt()
    }
}

/// Eigenvalues (ascending) of the symmetric tridiagonal matrix (d, e) by implicit QL with
/// Wilkinson shifts. `e[i]` couples rows i and i + 1.
fn tridiagonal_eigenvalues(mut d: Vec<f64>, off: &[f64]) -> Vec<f64> {
    let n = d.len();
    let mut e: Vec<f64> = off.to_vec();
    e.push(0.0);
    for l in 0..n {
        for _ in 0..100 {
            let mut m = l;
            while m + 1 < n {
                let dd = d[m].abs() + d[m + 1].abs();
                if e[m].abs() <= f64::EPSILON * dd {
                    break;
                }
                m += 1;
            }
            if m == l {
                break;
            }
            let mut g = (d[l + 1] - d[l]) / (2.0 * e[l]);
            let mut r = pythag(g, 1.0);
            g = d[m] - d[l] + e[l] / (g + r.copysign(g));
            let (mut s, mut c, mut p) = (1.0, 1.0, 0.0);
            let mut i = m;
            let mut deflated = false;
            while i > l {
                i -= 1;
                let f = s * e[i];
                let b = c * e[i];
                r = pythag(f, g);
                e[i + 1] = r;
                if r == 0.0 {
                    d[i + 1] -= p;
                    e[m] = 0.0;
                    deflated = true;
                    break;
                }
                s = f / r;
                c = g / r;
                g = d[i + 1] - p;
                r = (d[i] - g) * s + 2.0 * c * b;
                p = s * r;
                d[i + 1] = g + p;
                g = c * r - b;
            }
            if !deflated {
                d[l] -= p;
                e[l] = g;
                e[m] = 0.0;
            }
        }
    }
    d.sort_by(f64::total_cmp);
    d
}

/// Orthonormal recurrence at x: returns (P_n(x), P_n'(x), sum_{k<n} p_k(x)^2), where P_n is
/// the (unnormalised last step of the) degree-n polynomial whose zeros are the nodes;
/// `inv_off[k]` = 1 / off[k] (and 1 for the last step).
fn recurrence(x: f64, diag: &[f64], off: &[f64], inv_off: &[f64]) -> (f64, f64, f64) {
    let (mut p_prev, mut p) = (0.0, 1.0);
    let (mut d_prev, mut dp) = (0.0, 0.0);
    let mut sum = 1.0;
    let mut e_prev = 0.0;
    for k in 0..diag.len() {
        let xd = x - diag[k];
        let p_next = (xd * p - e_prev * p_prev) * inv_off[k];
        let d_next = (xd * dp + p - e_prev * d_prev) * inv_off[k];
        p_prev = p;
        p = p_next;
        d_prev = dp;
        dp = d_next;
        sum += p * p;
        e_prev = off.get(k).copied().unwrap_or(0.0);
    }
    // the last step's value (the unnormalised P_n) is not a p_k with k < n
    (p, dp, sum - p * p)
}

/// Gauss-Jacobi rule with n nodes for int_{-1}^{1} f(x) (1 - x)^alpha (1 + x)^beta dx:
/// (nodes ascending, weights), exact for polynomials of degree < 2n. Requires alpha, beta > -1
/// (an empty rule is returned for n = 0 or for invalid exponents).
pub fn gauss_jacobi(n: usize, alpha: f64, beta: f64) -> (Vec<f64>, Vec<f64>) {
    if n == 0 || !(alpha > -1.0 && beta > -1.0 && alpha.is_finite() && beta.is_finite()) {
        return (Vec::new(), Vec::new());
    }
    let (diag, off) = jacobi_matrix(n, alpha, beta);
    let mut nodes = tridiagonal_eigenvalues(diag.clone(), &off);
    let inv_off: Vec<f64> = off.iter().map(|e| 1.0 / e).chain([1.0]).collect();
    let mass = jacobi_mass(alpha, beta);
    let mut weights = Vec::with_capacity(n);
    for x in nodes.iter_mut() {
        for _ in 0..3 {
            let (p, dp, _) = recurrence(*x, &diag, &off, &inv_off);
            if dp == 0.0 || !dp.is_finite() {
                break;
            }
            let step = p / dp;
            let xn = (*x - step).clamp(-1.0, 1.0);
            let done = (xn - *x).abs() <= 2.0 * f64::EPSILON * x.abs().max(1e-300);
            *x = xn;
            if done {
                break;
            }
        }
        let (_, _, sum) = recurrence(*x, &diag, &off, &inv_off);
        weights.push(mass / sum);
    }
    (nodes, weights)
}

/// Gauss-Legendre rule (alpha = beta = 0) with n nodes on [-1, 1].
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    gauss_jacobi(n, 0.0, 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn ln_gamma_known_values() {
        assert!(rel(ln_gamma(0.5), 0.5 * PI.ln()) < 1e-14);
        assert!(rel(ln_gamma(5.0).exp(), 24.0) < 1e-14);
        assert!(rel(ln_gamma(1.0 / 3.0).exp(), 2.678_938_534_707_747_6) < 1e-14);
        assert!(rel(ln_gamma(0.01).exp(), 99.432_585_119_150_6) < 1e-14);
        assert!(rel(ln_gamma(100.0), 359.134_205_369_575_4) < 1e-15);
        assert!(rel(ln_gamma(300.0), 1_409.202_067_470_411_8) < 1e-15);
        assert!(rel(gamma(2.0), 1.0) < 3e-16 && rel(gamma(1.0), 1.0) < 3e-16);
        assert!(rel(gamma(30.5), 4.822_696_933_490_909e31) < 1e-14);
    }

    /// int (1-x)^a (1+x)^(b+j) = 2^(a+b+j+1) B(a+1, b+j+1): all-positive integrands, so the
    /// rule must reproduce them to rounding for j < 2n (both end factors, odd and even n).
    #[test]
    fn exact_moments() {
        for &(a, b) in &[
            (0.0, 0.0),
            (0.3, -0.6),
            (-0.5, 0.5),
            (-0.9, 2.5),
            (0.25, -0.25),
            (-0.5, -0.5),
            (1.7, 0.2),
        ] {
            for n in [1usize, 2, 3, 5, 7, 10, 21, 40, 151] {
                let (x, w) = gauss_jacobi(n, a, b);
                assert_eq!(x.len(), n);
                assert!(x.windows(2).all(|p| p[0] < p[1]));
                for j in 0..2 * n {
                    let jf = j as f64;
                    let plus: f64 = x.iter().zip(&w).map(|(x, w)| w * (1.0 + x).powf(jf)).sum();
                    let minus: f64 = x.iter().zip(&w).map(|(x, w)| w * (1.0 - x).powf(jf)).sum();
                    let e_plus = jacobi_mass(a, b + jf);
                    let e_minus = jacobi_mass(a + jf, b);
                    // high powers sample the end weights (see weight_tol)
                    let tol = 2e-13f64.max(4.0 * (n * n) as f64 * f64::EPSILON);
                    assert!(
                        rel(plus, e_plus) < tol,
                        "n {n} a {a} b {b} j {j} {}",
                        rel(plus, e_plus)
                    );
                    assert!(
                        rel(minus, e_minus) < tol,
                        "n {n} a {a} b {b} j {j} {} {minus} {e_minus}",
                        rel(minus, e_minus)
                    );
                }
            }
        }
    }

    #[test]
    fn legendre_three_point() {
        let (x, w) = gauss_legendre(3);
        let r = (0.6f64).sqrt();
        assert!((x[0] + r).abs() < 3e-16 && x[1].abs() < 1e-16 && (x[2] - r).abs() < 3e-16);
        assert!(rel(w[0], 5.0 / 9.0) < 1e-15 && rel(w[1], 8.0 / 9.0) < 1e-15);
    }

    /// Weights are relatively accurate to rounding away from the ends; within O(1/n^2) of an
    /// end a one-ulp node perturbation moves the Christoffel number by O(n^2 eps).
    fn weight_tol(x: f64, n: f64) -> f64 {
        if x.abs() < 0.9 {
            50.0 * f64::EPSILON
        } else {
            4.0 * n * n * f64::EPSILON
        }
    }

    /// Closed forms: Chebyshev first kind (a = b = -1/2) and second kind (a = b = 1/2).
    #[test]
    fn chebyshev_closed_forms_large_n() {
        for n in [1usize, 7, 64, 301] {
            let nf = n as f64;
            let (x, w) = gauss_jacobi(n, -0.5, -0.5);
            for i in 0..n {
                let t = (2.0 * (n - i) as f64 - 1.0) * PI / (2.0 * nf);
                assert!((x[i] - t.cos()).abs() < 2e-15, "n {n} i {i}");
                assert!(rel(w[i], PI / nf) < weight_tol(x[i], nf), "n {n} i {i}");
            }
            let (x, w) = gauss_jacobi(n, 0.5, 0.5);
            for i in 0..n {
                let t = (n - i) as f64 * PI / (nf + 1.0);
                assert!((x[i] - t.cos()).abs() < 2e-15, "n {n} i {i}");
                let exact = PI / (nf + 1.0) * t.sin().powi(2);
                assert!(rel(w[i], exact) < weight_tol(x[i], nf), "n {n} i {i}");
            }
        }
    }

    /// Odd n with alpha != beta (where one published crate misplaces the middle node): the
    /// one-node rule is the mean, and a smooth non-polynomial integral converges.
    #[test]
    fn odd_n_asymmetric() {
        let (a, b) = (0.7, -0.4);
        let (x, w) = gauss_jacobi(1, a, b);
        assert!((x[0] - (b - a) / (a + b + 2.0)).abs() < 1e-16);
        assert!(rel(w[0], jacobi_mass(a, b)) < 1e-15);
        // int (1-x)^a (1+x)^b e^x dx via a large rule vs moments series sum_j (1+x)^j e^-1/j!.
        let exact: f64 = (0..60)
            .map(|j| {
                (-1.0f64).exp() * jacobi_mass(a, b + j as f64) / ln_gamma(j as f64 + 1.0).exp()
            })
            .sum();
        for n in [9usize, 15, 201] {
            let (x, w) = gauss_jacobi(n, a, b);
            let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.exp()).sum();
            assert!(rel(s, exact) < 1e-14, "n {n}: {s} vs {exact}");
        }
    }

    #[test]
    fn invalid_exponents_give_empty_rule() {
        assert!(gauss_jacobi(4, -1.0, 0.0).0.is_empty());
        assert!(gauss_jacobi(4, 0.0, f64::NAN).0.is_empty());
        assert!(gauss_jacobi(0, 0.0, 0.0).0.is_empty());
    }
}
