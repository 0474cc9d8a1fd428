//! The Gauss hypergeometric function 2F1(a, b; c; z) for 0 <= z < 1 and positive a, b, c with
//! 0 <= c - a - b < 1, as needed by Spence's compatibility condition: the power series for
//! z <= 1/2, and for z > 1/2 the z -> 1 - z transformation (DLMF 15.8.4) written uniformly in
//! eps = c - a - b, so that it goes over into the logarithmic case (DLMF 15.8.10) at eps = 0
//! without cancellation between the two terms of 15.8.4.

use std::f64::consts::PI;

use crate::quadrature::ln_gamma;

/// Largest number of series terms; z <= 1/2 needs about 60.
const MAX_TERMS: usize = 400;

/// Stirling coefficients B_2k / (2k (2k - 1)), k = 1..8.
const STIRLING: [f64; 8] = [
    1.0 / 12.0,
    -1.0 / 360.0,
    1.0 / 1260.0,
    -1.0 / 1680.0,
    1.0 / 1188.0,
    -691.0 / 360_360.0,
    1.0 / 156.0,
    -3617.0 / 122_400.0,
];

/// ln(1 + e/x) / e, with its limit 1/x at e = 0.
fn log_slope(x: f64, e: f64) -> f64 {
    if e == 0.0 {
        1.0 / x
    } else {
        (e / x).ln_1p() / e
    }
}

/// (e^t - 1) / t, with its limit 1 at t = 0.
fn exprel(t: f64) -> f64 {
    if t == 0.0 { 1.0 } else { t.exp_m1() / t }
}

/// [ln Gamma(x + e) - ln Gamma(x)] / e for x > 0, x + e > 0 (psi(x) at e = 0), to a few ulps
/// for every e: recurrence up to x >= 10, then the difference of two Stirling series with
/// every difference written as ln_1p / exp_m1 of e / x.
pub(super) fn ln_gamma_slope(x: f64, e: f64) -> f64 {
    let mut shift = 0.0;
    let mut y = x;
    while y < 10.0 {
        shift -= log_slope(y, e);
        y += 1.0;
    }
    let l = (e / y).ln_1p();
    let ls = log_slope(y, e);
    // (y + e - 1/2) ln(y + e) - (y - 1/2) ln y - e, divided by e.
    let mut d = (y - 0.5) * ls + (y + e).ln() - 1.0;
    let mut yp = 1.0 / y;
    for (k, ck) in STIRLING.iter().enumerate() {
        let j = -((2 * k + 1) as f64);
        d += ck * yp * j * ls * exprel(j * l);
        yp /= y * y;
    }
    d + shift
}

/// The power series of 2F1(a, b; c; z) for 0 <= z <= 1/2 (all terms positive here).
pub(super) fn series(a: f64, b: f64, c: f64, z: f64) -> f64 {
    let (mut term, mut sum) = (1.0, 1.0);
    for n in 0..MAX_TERMS {
        let n = n as f64;
        term *= (a + n) * (b + n) / ((c + n) * (n + 1.0)) * z;
        sum += term;
        if term.abs() <= 0.5 * f64::EPSILON * sum.abs() {
            break;
        }
    }
    sum
}

/// 2F1(a, b; a + b + e; 1 - w) for a, b > 0, 0 <= e < 1 and 0 <= w <= 1/2, given ln w
/// separately (w may underflow). DLMF 15.8.4 with c = a + b + e, summed term by term:
///   2F1 = Gamma(c) / (Gamma(a + e) Gamma(b + e) Gamma(1 - e)) (pi e / sin(pi e))
///         sum_n r_n w^n (-D_n) exprel(e D_n),
///   r_n = (a)_n (b)_n / (n! (1 - e)_n),
///   D_n = [ln Gamma(a+n+e) - ln Gamma(a+n) + ln Gamma(b+n+e) - ln Gamma(b+n)
///          - ln Gamma(n+1+e) + ln Gamma(n+1-e)] / e + ln w,
/// which at e = 0 is DLMF 15.8.10 (D_n = psi(a+n) + psi(b+n) - 2 psi(n+1) + ln w).
pub(super) fn near_one(a: f64, b: f64, e: f64, w: f64, ln_w: f64) -> f64 {
    let c = a + b + e;
    let prefactor = (ln_gamma(c) - ln_gamma(a + e) - ln_gamma(b + e) - ln_gamma(1.0 - e)).exp();
    let reflection = if e == 0.0 {
        1.0
    } else {
        PI * e / (PI * e).sin()
    };
    let mut da = ln_gamma_slope(a, e);
    let mut db = ln_gamma_slope(b, e);
    // [ln Gamma(n + 1 + e) - ln Gamma(n + 1 - e)] / (2 e)
    let mut dn = ln_gamma_slope(1.0 - e, 2.0 * e);
    let (mut r, mut wn, mut sum) = (1.0, 1.0, 0.0);
    for n in 0..MAX_TERMS {
        let d = da + db - 2.0 * dn + ln_w;
        let term = -r * wn * d * exprel(e * d);
        sum += term;
        let nf = n as f64;
        wn *= w;
        if wn == 0.0 || (n > 0 && term.abs() <= 0.5 * f64::EPSILON * sum.abs()) {
            break;
        }
        da += log_slope(a + nf, e);
        db += log_slope(b + nf, e);
        dn += log_slope(nf + 1.0 - e, 2.0 * e);
        r *= (a + nf) * (b + nf) / ((nf + 1.0) * (nf + 1.0 - e));
    }
    prefactor * reflection * sum
}

/// 2F1(a, b; a + b + e; z) for 0 <= z < 1 (a, b > 0, 0 <= e < 1), given z, 1 - z and
/// ln(1 - z) to full relative accuracy.
pub(super) fn hyp2f1(a: f64, b: f64, e: f64, z: f64, one_minus_z: f64, ln_one_minus_z: f64) -> f64 {
    if z <= 0.5 {
        series(a, b, a + b + e, z)
    } else {
        near_one(a, b, e, one_minus_z, ln_one_minus_z)
    }
}
