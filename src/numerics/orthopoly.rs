//! Orthogonal polynomials: Legendre values and sums (Bonnet's recurrence), the orthonormal
//! Jacobi recurrence behind the Gauss-Jacobi rules, and Chebyshev interpolation with
//! Clenshaw's sum.

use std::f64::consts::FRAC_PI_2;

use super::special::beta;

/// Bonnet's factors ((2k + 1) / (k + 1), k / (k + 1)) of
/// P_{k+1}(t) = (2k + 1) / (k + 1) t P_k(t) - k / (k + 1) P_{k-1}(t) (DLMF 18.9.1), tabulated
/// for k < 64 (every degree the solvers use).
const BONNET_TABLE: [(f64, f64); 64] = {
    let mut t = [(0.0, 0.0); 64];
    let mut k = 0;
    while k < 64 {
        let kf = k as f64;
        t[k] = ((2.0 * kf + 1.0) / (kf + 1.0), kf / (kf + 1.0));
        k += 1;
    }
    t
};

/// Bonnet's factors for degree k (see [`BONNET_TABLE`]).
#[inline]
pub(crate) fn bonnet(k: usize) -> (f64, f64) {
    match BONNET_TABLE.get(k) {
        Some(&f) => f,
        None => {
            let kf = k as f64;
            ((2.0 * kf + 1.0) / (kf + 1.0), kf / (kf + 1.0))
        }
    }
}

/// Legendre polynomials P_0..P_{n-1} at t into `out` (n = out.len()).
pub(crate) fn legendre(t: f64, out: &mut [f64]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    out[0] = 1.0;
    if n > 1 {
        out[1] = t;
    }
    for k in 1..n.saturating_sub(1) {
        let (fa, fb) = bonnet(k);
        out[k + 1] = fa * t * out[k] - fb * out[k - 1];
    }
}

/// sum_k a_k P_k(t) by the forward recurrence (no allocation, no division).
pub(crate) fn legendre_sum(a: &[f64], t: f64) -> f64 {
    let (mut p_prev, mut p) = (0.0, 1.0);
    let mut s = 0.0;
    for (k, ak) in a.iter().enumerate() {
        s += ak * p;
        let (fa, fb) = bonnet(k);
        let next = fa * t * p - fb * p_prev;
        p_prev = p;
        p = next;
    }
    s
}

/// Total mass int_{-1}^{1} (1 - x)^alpha (1 + x)^beta dx = 2^(alpha+beta+1) B(alpha+1, beta+1)
/// (alpha, beta > -1), in closed form when one exponent is 0.
pub(crate) fn jacobi_mass(alpha: f64, beta_: f64) -> f64 {
    if beta_ == 0.0 {
        (alpha + 1.0).exp2() / (alpha + 1.0)
    } else if alpha == 0.0 {
        (beta_ + 1.0).exp2() / (beta_ + 1.0)
    } else {
        (alpha + beta_ + 1.0).exp2() * beta(alpha + 1.0, beta_ + 1.0)
    }
}

/// The first n steps of the orthonormal Jacobi recurrence for the weight
/// (1 - x)^alpha (1 + x)^beta scaled to unit mass (the Jacobi matrix of Golub and Welsch):
/// x p_k = off[k-1] p_{k-1} + diag[k] p_k + off[k] p_{k+1}, p_0 = 1, with the k = 0, 1
/// coefficients written so that alpha + beta = 0 or -1 cause no 0/0 (DLMF 18.9.2 normalised).
#[derive(Clone, Debug)]
pub(crate) struct JacobiRecurrence {
    /// a_k, k < n.
    pub(crate) diag: Vec<f64>,
    /// sqrt(b_{k+1}), k < n - 1.
    pub(crate) off: Vec<f64>,
    /// 1 / off[k], and 1 for the last step (which gives a multiple of p_n).
    pub(crate) inv_off: Vec<f64>,
}

impl JacobiRecurrence {
    /// The recurrence up to degree n for exponents alpha, beta > -1.
    pub(crate) fn new(n: usize, alpha: f64, beta: f64) -> Self {
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
        let off: Vec<f64> = (1..n)
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
        let inv_off = off.iter().map(|e| 1.0 / e).chain([1.0]).collect();
        Self { diag, off, inv_off }
    }

    /// Degree n of the recurrence.
    pub(crate) fn degree(&self) -> usize {
        self.diag.len()
    }

    /// At each point x[i] (all points advanced together, one degree at a time): a multiple of
    /// p_n(x[i]) into `value` and its derivative into `slope`. Their ratio is Newton's step
    /// towards a zero of p_n.
    pub(crate) fn newton_terms(&self, x: &[f64], value: &mut [f64], slope: &mut [f64]) {
        let m = x.len();
        let (mut p_prev, mut d_prev) = (vec![0.0; m], vec![0.0; m]);
        value[..m].fill(1.0);
        slope[..m].fill(0.0);
        let mut e_prev = 0.0;
        for k in 0..self.degree() {
            let (dk, ik) = (self.diag[k], self.inv_off[k]);
            for i in 0..m {
                let xd = x[i] - dk;
                let p = (xd * value[i] - e_prev * p_prev[i]) * ik;
                let d = (xd * slope[i] + value[i] - e_prev * d_prev[i]) * ik;
                (p_prev[i], value[i], d_prev[i], slope[i]) = (value[i], p, slope[i], d);
            }
            e_prev = self.off.get(k).copied().unwrap_or(0.0);
        }
    }

    /// sum_{k<n} p_k(x[i])^2 at each point into `out` (the reciprocal Christoffel function).
    pub(crate) fn christoffel_sums(&self, x: &[f64], out: &mut [f64]) {
        let m = x.len();
        let (mut p_prev, mut p) = (vec![0.0; m], vec![1.0; m]);
        out[..m].fill(1.0);
        let mut e_prev = 0.0;
        for k in 0..self.degree().saturating_sub(1) {
            let (dk, ik) = (self.diag[k], self.inv_off[k]);
            for i in 0..m {
                let next = ((x[i] - dk) * p[i] - e_prev * p_prev[i]) * ik;
                (p_prev[i], p[i]) = (p[i], next);
                out[i] += next * next;
            }
            e_prev = self.off[k];
        }
    }
}

/// The n Chebyshev coefficients of f on [a, b] from its values at the n Chebyshev points of
/// the first kind (the interpolant, DLMF 3.11.9 discretised); `f` maps all the points at once
/// to their values. Every cosine needed, T_j(t_k) = cos(pi j (2k + 1) / (2n)), is read from one
/// quarter wave cos(pi i / (2n)), i = 0..n.
pub(crate) fn chebyshev_fit(
    f: impl FnOnce(&[f64]) -> Vec<f64>,
    a: f64,
    b: f64,
    n: usize,
) -> Vec<f64> {
    let nf = n as f64;
    let quarter: Vec<f64> = (0..=n).map(|i| (FRAC_PI_2 * i as f64 / nf).cos()).collect();
    // cos(pi i / (2n)) for 0 <= i < 4n
    let wave: Vec<f64> = (0..4 * n)
        .map(|i| match i / n {
            0 => quarter[i],
            1 => -quarter[2 * n - i],
            2 => -quarter[i - 2 * n],
            _ => quarter[4 * n - i],
        })
        .collect();
    let cos = |i: usize| wave[i];
    let values = f(&chebyshev_points(a, b, n));
    let mut coef = vec![0.0; n];
    for (k, value) in values.iter().enumerate() {
        let step = 2 * k + 1;
        let v = value * 2.0 / nf;
        let mut i = 0;
        for cj in coef.iter_mut() {
            *cj += v * cos(i);
            i += step;
            if i >= 4 * n {
                i -= 4 * n;
            }
        }
    }
    if let Some(c0) = coef.first_mut() {
        *c0 *= 0.5;
    }
    coef
}

/// The n Chebyshev points of the first kind on [a, b], (a + b) / 2 + (b - a) / 2
/// cos(pi (2k + 1) / (2n)), k = 0..n (descending).
pub(crate) fn chebyshev_points(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|k| {
            let t = (std::f64::consts::PI * (2 * k + 1) as f64 / (2 * n) as f64).cos();
            0.5 * (a + b) + 0.5 * (b - a) * t
        })
        .collect()
}

/// sum_j coef_j T_j(t) by Clenshaw's recurrence.
pub(crate) fn chebyshev_sum(coef: &[f64], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &c in coef.iter().skip(1).rev() {
        (b1, b2) = (2.0 * t * b1 - b2 + c, b1);
    }
    t * b1 - b2 + coef.first().copied().unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Closed forms P_2 .. P_4 and the degree beyond the table (P_70(1) = 1, P_70(-1) = 1).
    #[test]
    fn legendre_closed_forms_and_sums() {
        let mut p = vec![0.0; 71];
        for t in [-0.9, -0.3, 0.0, 0.45, 1.0] {
            legendre(t, &mut p);
            let t2: f64 = t * t;
            assert!((p[2] - 0.5 * (3.0 * t2 - 1.0)).abs() < 1e-15);
            assert!((p[3] - 0.5 * (5.0 * t2 - 3.0) * t).abs() < 1e-15);
            assert!((p[4] - (35.0 * t2 * t2 - 30.0 * t2 + 3.0) / 8.0).abs() < 1e-15);
            let a: Vec<f64> = (0..71).map(|k| 1.0 / (k as f64 + 1.0)).collect();
            let direct: f64 = a.iter().zip(&p).map(|(a, p)| a * p).sum();
            assert!((legendre_sum(&a, t) - direct).abs() < 1e-14);
        }
        legendre(1.0, &mut p);
        assert!((p[70] - 1.0).abs() < 1e-13);
        legendre(-1.0, &mut p);
        assert!((p[70] - 1.0).abs() < 1e-13);
    }

    #[test]
    fn jacobi_masses() {
        assert!((jacobi_mass(0.0, 0.0) - 2.0).abs() < 1e-15);
        assert!((jacobi_mass(-0.5, -0.5) - PI).abs() < 1e-15);
        assert!((jacobi_mass(0.5, 0.5) - 0.5 * PI).abs() < 1e-15);
        assert!((jacobi_mass(-0.3, 0.0) - 0.7f64.exp2() / 0.7).abs() < 1e-15);
    }

    /// p_n from the recurrence against the Legendre polynomials (alpha = beta = 0:
    /// p_k = sqrt(2k + 1) P_k) and the Christoffel sums against their definition.
    #[test]
    fn orthonormal_recurrence_is_normalised_legendre() {
        let n = 9;
        let r = JacobiRecurrence::new(n, 0.0, 0.0);
        let x = [-0.7, 0.1, 0.93];
        let (mut sums, mut leg) = ([0.0; 3], vec![0.0; n + 1]);
        r.christoffel_sums(&x, &mut sums);
        for (i, &t) in x.iter().enumerate() {
            legendre(t, &mut leg);
            let direct: f64 = (0..n).map(|k| (2 * k + 1) as f64 * leg[k] * leg[k]).sum();
            assert!((sums[i] - direct).abs() < 1e-13 * direct);
        }
        // the zeros of P_n are where newton_terms' value vanishes
        let (zeros, _) = crate::numerics::quadrature::gauss_legendre(n);
        let (mut v, mut d) = (vec![0.0; n], vec![0.0; n]);
        r.newton_terms(&zeros, &mut v, &mut d);
        assert!(v.iter().zip(&d).all(|(v, d)| (v / d).abs() < 1e-15));
    }

    #[test]
    fn chebyshev_interpolation() {
        let c = chebyshev_fit(|xs| xs.iter().map(|x| x.exp()).collect(), -1.0, 2.0, 16);
        for x in [-1.0, -0.3, 0.5, 1.7, 2.0] {
            let t = (2.0 * x - 1.0) / 3.0;
            assert!((chebyshev_sum(&c, t) - x.exp()).abs() < 1e-14 * x.exp());
        }
    }
}
