//! Special functions: Gamma, ln Gamma, the Beta function, digamma, the difference quotient of
//! ln Gamma, the Gauss hypergeometric function 2F1 in the cases the solvers meet, and the
//! Lerch sum Phi(w, 1, a) of complex argument (the complex Cauchy transforms' closed forms).
//!
//! Gamma and ln Gamma are libm's `tgamma` and `lgamma`. Measured against mpmath on 4000
//! points of (1e-3, 170): `tgamma` within 3.7 ulp (the former Stirling-series Gamma here: 12.6)
//! and `lgamma` within 1.7 ulp of max(1, |ln Gamma|) (former: 12.5), `lgamma` 4 times faster.
//! Digamma and the ln Gamma quotient use Stirling's series with one coefficient table.

use std::f64::consts::PI;

use faer::complex::Complex;

/// Gamma(x) for 0 < x < 171.6 (libm's `tgamma`).
pub(crate) fn gamma(x: f64) -> f64 {
    libm::tgamma(x)
}

/// ln Gamma(x) for x > 0 (libm's `lgamma`).
pub(crate) fn ln_gamma(x: f64) -> f64 {
    libm::lgamma(x)
}

/// B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b) for a, b > 0 (through ln Gamma once
/// Gamma(a + b) would overflow).
pub(crate) fn beta(a: f64, b: f64) -> f64 {
    if a + b < 170.0 {
        gamma(a) / gamma(a + b) * gamma(b)
    } else {
        (ln_gamma(a) + ln_gamma(b) - ln_gamma(a + b)).exp()
    }
}

/// B_2k / (2k (2k - 1)), k = 1..8: Stirling's series
/// ln Gamma(y) = (y - 1/2) ln y - y + ln(2 pi) / 2 + sum_k STIRLING[k-1] y^(1 - 2k)
/// (DLMF 5.11.1), and psi(y) = ln y - 1/(2y) - sum_k (2k - 1) STIRLING[k-1] y^(-2k) (5.11.2).
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

/// The series are used from here on (the upward recurrence gets there first): the first
/// term left out, B_18 / (18 * 17) y^-17, is below 2e-18.
const STIRLING_FROM: f64 = 10.0;

/// Digamma psi(x) = Gamma'(x) / Gamma(x) for x > 0: psi(x + 1) = psi(x) + 1/x up to
/// y >= 10, then DLMF 5.11.2 (within 5 ulp of max(1, |psi|) against mpmath on (1e-3, 170)).
pub(crate) fn digamma(x: f64) -> f64 {
    let mut y = x;
    let mut shift = 0.0;
    while y < STIRLING_FROM {
        shift -= 1.0 / y;
        y += 1.0;
    }
    let r2 = 1.0 / (y * y);
    let (mut series, mut power) = (0.0, r2);
    for (k, ck) in STIRLING.iter().enumerate() {
        series += ck * (2 * k + 1) as f64 * power;
        power *= r2;
    }
    shift + y.ln() - 0.5 / y - series
}

/// Digamma psi(z) for complex z with Re z > 0, as [`digamma`]: psi(z + 1) = psi(z) + 1/z up
/// to Re z >= 10, then DLMF 5.11.2 (|z| >= 10 there, so the same truncation bound holds).
pub(crate) fn digamma_complex(z: Complex<f64>) -> Complex<f64> {
    let mut y = z;
    let mut shift = Complex::new(0.0, 0.0);
    while y.re < STIRLING_FROM {
        shift -= y.inv();
        y += 1.0;
    }
    let r2 = (y * y).inv();
    let (mut series, mut power) = (Complex::new(0.0, 0.0), r2);
    for (k, ck) in STIRLING.iter().enumerate() {
        series += power * (ck * (2 * k + 1) as f64);
        power *= r2;
    }
    shift + y.ln() - y.inv() * 0.5 - series
}

/// ln(1 + e/x) / e, with its limit 1/x at e = 0.
fn log_slope(x: f64, e: f64) -> f64 {
    if e == 0.0 {
        1.0 / x
    } else {
        (e / x).ln_1p() / e
    }
}

/// (e^s - 1 - s) / s^2, with its limit 1/2 at s = 0 (the series below |s| = 1/2, where the
/// direct form cancels).
pub(crate) fn exprel2(s: f64) -> f64 {
    if s.abs() >= 0.5 {
        return (s.exp_m1() - s) / (s * s);
    }
    let (mut sum, mut term, mut k) = (0.5f64, 0.5f64, 2.0);
    while term.abs() > 1e-18 * sum {
        term *= s / (k + 1.0);
        sum += term;
        k += 1.0;
    }
    sum
}

/// zeta(n) for n = 2..=16 (values from mpmath).
const ZETA: [f64; 15] = [
    1.644_934_066_848_226_4,
    1.202_056_903_159_594_3,
    1.082_323_233_711_138_2,
    1.036_927_755_143_37,
    1.017_343_061_984_449,
    1.008_349_277_381_922_8,
    1.004_077_356_197_944_4,
    1.002_008_392_826_082_2,
    1.000_994_575_127_818,
    1.000_494_188_604_119_5,
    1.000_246_086_553_308,
    1.000_122_713_347_578_5,
    1.000_061_248_135_058_7,
    1.000_030_588_236_307,
    1.000_015_282_259_408_6,
];

/// -B_2m / (2m) = zeta(1 - 2m), m = 1..=10 (zeta(-2m) = 0).
const ZETA_NEGATIVE_ODD: [f64; 10] = [
    -1.0 / 12.0,
    1.0 / 120.0,
    -1.0 / 252.0,
    1.0 / 240.0,
    -1.0 / 132.0,
    691.0 / 32_760.0,
    -1.0 / 12.0,
    3617.0 / 8160.0,
    -43_867.0 / 14_364.0,
    174_611.0 / 6600.0,
];

/// h(g) = (beta / g - 2 ln 2) / g with beta = ln(2^(2g) Gamma(1 + g)^2 / Gamma(1 + 2g)), the
/// logarithm of the mass of (1 - t^2)^g times (2g + 1)/2, for 0 <= g < 1/4: from
/// ln Gamma(1 + x) = -gamma x + sum_(k >= 2) (-1)^k zeta(k) x^k / k (the gamma terms cancel),
///   h = sum_(k >= 2) (-1)^k zeta(k) (2 - 2^k) g^(k-2) / k,
/// to 1e-18 or zeta(16) (docs/theory_spectral.md (J2s), (Q6)).
pub(crate) fn symmetric_mass_tail(g: f64) -> f64 {
    let (mut h, mut power) = (0.0, 1.0);
    for k in 2..=16 {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        let zeta = zeta_int(k).unwrap_or(1.0);
        let term = sign * zeta * (2.0 - f64::from(k).exp2()) * power / f64::from(k);
        h += term;
        if term.abs() < 1e-18 {
            break;
        }
        power *= g;
    }
    h
}

/// zeta(n) for integer -19 <= n <= 16, n != 1 (None outside).
pub(crate) fn zeta_int(n: i32) -> Option<f64> {
    match n {
        2..=16 => Some(ZETA[(n - 2) as usize]),
        0 => Some(-0.5),
        -19..=-1 if n % 2 == 0 => Some(0.0),
        -19..=-1 => Some(ZETA_NEGATIVE_ODD[((1 - n) / 2 - 1) as usize]),
        _ => None,
    }
}

/// The polylogarithm Li_n(x) = sum_{k >= 1} x^k / k^n for integer 2 <= n <= 16 and
/// -1/2 <= x <= 3/2 (for x > 1 the real part of the principal branch): the series for
/// |x| <= 1/2, beyond it the expansion about x = 1 in m = ln x (|m| < 2 pi, DLMF 25.12.12):
///   Li_n(e^m) = m^(n-1) / (n-1)! (H_(n-1) - ln|m|) + sum_{k != n-1} zeta(n - k) m^k / k!.
pub(crate) fn polylog(n: i32, x: f64) -> f64 {
    debug_assert!((2..=16).contains(&n) && (-0.5..=1.5).contains(&x));
    if x.abs() <= 0.5 {
        let (mut sum, mut power, mut k) = (0.0f64, x, 1.0f64);
        while power.abs() > 1e-18 * sum.abs().max(f64::MIN_POSITIVE) {
            sum += power / k.powi(n);
            power *= x;
            k += 1.0;
        }
        return sum;
    }
    let m = x.ln();
    if m == 0.0 {
        return ZETA[(n - 2) as usize];
    }
    let (mut sum, mut power) = (0.0, 1.0); // power = m^k / k!
    for k in 0..=n + 19 {
        let term = if k == n - 1 {
            let harmonic: f64 = (1..n).map(|i| 1.0 / i as f64).sum();
            power * (harmonic - m.abs().ln())
        } else {
            power * zeta_int(n - k).unwrap_or(0.0)
        };
        sum += term;
        power *= m / (k + 1) as f64;
    }
    sum
}

/// sin(pi x), exact in the argument reduction (x - round(x) carries no rounding), so that it
/// keeps its relative accuracy near the integers (sin(pi (1 - g)) for g ~ 1e-5: (pi * x).sin()
/// is off by eps / g relative there).
pub(crate) fn sin_pi(x: f64) -> f64 {
    let n = x.round();
    let s = (PI * (x - n)).sin();
    if n % 2.0 == 0.0 { s } else { -s }
}

/// tan(pi x), exact in the argument reduction like [`sin_pi`] (period 1).
pub(crate) fn tan_pi(x: f64) -> f64 {
    (PI * (x - x.round())).tan()
}

/// (e^t - 1) / t, with its limit 1 at t = 0.
pub(crate) fn exprel(t: f64) -> f64 {
    if t == 0.0 { 1.0 } else { t.exp_m1() / t }
}

/// [ln Gamma(x + e) - ln Gamma(x)] / e for x > 0, x + e > 0 ([`digamma`] at e = 0), to a few
/// ulps for every e: recurrence up to x >= 10, then the difference of two Stirling series with
/// every difference written as ln_1p / exp_m1 of e / x.
pub(crate) fn ln_gamma_slope(x: f64, e: f64) -> f64 {
    if e == 0.0 {
        return digamma(x);
    }
    let mut shift = 0.0;
    let mut y = x;
    while y < STIRLING_FROM {
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

/// Largest number of hypergeometric series terms; |z| <= 1/2 needs about 60.
const MAX_TERMS: usize = 400;

/// Relative size of the first hypergeometric series term left out.
const SERIES_TOL: f64 = 1e-17;

/// The Gauss hypergeometric function F(z) = 2F1(a, b; a + b + e; z) for fixed a, b > 0 and
/// 0 <= e < 1, on -1/2 <= z < 1 (also 1 < z <= 3/2 when e = 0: the real part of the
/// continuation, the mean of its values above and below the cut), with its derivative in the
/// logit s = ln(z / (1 - z)): dF/ds = z (1 - z) F'(z). Evaluated by the power series about
/// z = 0 for z <= 1/2 and about z = 1 beyond ([`Hyp2f1::near_one`]), whose constants
/// (Gamma functions of a, b, e) are computed once, on first use.
#[derive(Clone, Debug)]
pub(crate) struct Hyp2f1 {
    a: f64,
    b: f64,
    e: f64,
    near_one: std::sync::OnceLock<NearOne>,
    /// The power series' term ratios without z ([`SeriesRatios`]), built on first use.
    ratios: std::sync::OnceLock<SeriesRatios>,
    /// The terms of the expansion about z = 1 that do not depend on z, in chunks of
    /// [`CHUNK`] built on first use ([`Hyp2f1::near_one`]); boxed, so that the function stays
    /// small to move (the spectral bases hold about 20 of them).
    chunks: [std::sync::OnceLock<Box<Chunk>>; CHUNKS],
}

/// The constants of the expansion about z = 1 (DLMF 15.8.4, see [`Hyp2f1::near_one`]).
#[derive(Clone, Copy, Debug)]
struct NearOne {
    /// Gamma(c) / (Gamma(a + e) Gamma(b + e) Gamma(1 - e)) (pi e / sin(pi e)).
    prefactor: f64,
    /// The three parts of D_0 - ln w: [ln Gamma(a + e) - ln Gamma(a)] / e,
    /// [ln Gamma(b + e) - ln Gamma(b)] / e and [ln Gamma(1 + e) - ln Gamma(1 - e)] / (2 e).
    slopes: [f64; 3],
}

/// Terms per chunk of the table of [`Hyp2f1::near_one`].
const CHUNK: usize = 16;

/// Chunks of the table: 96 terms, more than |w| <= 1/2 needs (2^-96 ~ 1e-29 against the
/// series tolerance 1e-17; about 60 terms are summed at |w| = 1/2).
const CHUNKS: usize = 6;

/// One term's z-independent part: r_n, D_n - ln w, and expm1(e (D_n - ln w)).
#[derive(Clone, Copy, Debug, Default)]
struct Term {
    r: f64,
    d0: f64,
    am1: f64,
}

/// [`CHUNK`] terms, and the running (r, the three slopes) after the last of them.
#[derive(Clone, Copy, Debug)]
struct Chunk {
    terms: [Term; CHUNK],
    next: (f64, [f64; 3]),
}

impl Hyp2f1 {
    /// 2F1(a, b; a + b + e; .) for a, b > 0 and 0 <= e < 1.
    pub(crate) fn new(a: f64, b: f64, e: f64) -> Self {
        Self {
            a,
            b,
            e,
            near_one: std::sync::OnceLock::new(),
            ratios: std::sync::OnceLock::new(),
            chunks: Default::default(),
        }
    }

    /// (F(z), dF/ds), given z, 1 - z and ln|1 - z| to full relative accuracy.
    pub(crate) fn eval(&self, z: f64, one_minus_z: f64, ln_one_minus_z: f64) -> (f64, f64) {
        if z <= 0.5 {
            self.series(z)
        } else {
            self.near_one(z, one_minus_z, ln_one_minus_z)
        }
    }

    /// F(z) alone: [`Hyp2f1::eval`]'s first part, to the bit, without the derivative's sums.
    pub(crate) fn value(&self, z: f64, one_minus_z: f64, ln_one_minus_z: f64) -> f64 {
        if z <= 0.5 {
            self.series_ratios().sum(z)
        } else {
            self.near_one_sums::<false>(z, one_minus_z, ln_one_minus_z)
                .0
        }
    }

    /// The power series' term ratios, built on first use.
    fn series_ratios(&self) -> &SeriesRatios {
        self.ratios
            .get_or_init(|| SeriesRatios::new(self.a, self.b, self.a + self.b + self.e))
    }

    /// (P, D) of the logarithmic case (e = 0) at z -> 1:
    /// F = -P (D + ln(1 - z)) + O((1 - z) ln(1 - z)) (the first term of [`Hyp2f1::near_one`]).
    pub(crate) fn log_limit(&self) -> (f64, f64) {
        debug_assert!(self.e == 0.0, "the logarithmic case only");
        let k = self.constants();
        let [da, db, dn] = k.slopes;
        (k.prefactor, da + db - 2.0 * dn)
    }

    /// The constants of [`Hyp2f1::near_one`], computed on first use.
    fn constants(&self) -> &NearOne {
        let (a, b, e) = (self.a, self.b, self.e);
        self.near_one.get_or_init(|| {
            let c = a + b + e;
            let reflection = if e == 0.0 {
                1.0
            } else {
                PI * e / (PI * e).sin()
            };
            let prefactor =
                (ln_gamma(c) - ln_gamma(a + e) - ln_gamma(b + e) - ln_gamma(1.0 - e)).exp();
            NearOne {
                prefactor: prefactor * reflection,
                slopes: [
                    ln_gamma_slope(a, e),
                    ln_gamma_slope(b, e),
                    ln_gamma_slope(1.0 - e, 2.0 * e),
                ],
            }
        })
    }

    /// The power series (DLMF 15.2.1) for |z| <= 1/2 with dF/ds = (1 - z) sum n t_n.
    fn series(&self, z: f64) -> (f64, f64) {
        let c = self.a + self.b + self.e;
        let (mut term, mut sum, mut slope) = (1.0, 1.0, 0.0);
        for n in 0..MAX_TERMS {
            let n = n as f64;
            term *= (self.a + n) * (self.b + n) / ((c + n) * (n + 1.0)) * z;
            sum += term;
            slope += (n + 1.0) * term;
            if term.abs() <= SERIES_TOL * sum.abs() {
                break;
            }
        }
        (sum, (1.0 - z) * slope)
    }

    /// Chunk `i` of the z-independent terms of [`Hyp2f1::near_one`], from the running
    /// values at its start (the constants for chunk 0, else the previous chunk's end).
    fn chunk(&self, i: usize) -> &Chunk {
        self.chunks[i].get_or_init(|| {
            let (mut r, [mut da, mut db, mut dn]) = if i == 0 {
                (1.0, self.constants().slopes)
            } else {
                self.chunk(i - 1).next
            };
            let (a, b, e) = (self.a, self.b, self.e);
            let mut terms = [Term::default(); CHUNK];
            for (j, t) in terms.iter_mut().enumerate() {
                let nf = (i * CHUNK + j) as f64;
                let d0 = da + db - 2.0 * dn;
                *t = Term {
                    r,
                    d0,
                    am1: (e * d0).exp_m1(),
                };
                da += log_slope(a + nf, e);
                db += log_slope(b + nf, e);
                dn += log_slope(nf + 1.0 - e, 2.0 * e);
                r *= (a + nf) * (b + nf) / ((nf + 1.0) * (nf + 1.0 - e));
            }
            Box::new(Chunk {
                terms,
                next: (r, [da, db, dn]),
            })
        })
    }

    /// The expansion about z = 1 in w = 1 - z (|w| <= 1/2; w < 0 only for e = 0), DLMF 15.8.4
    /// with c = a + b + e summed term by term:
    ///   F = prefactor sum_n r_n w^n (-Q_n),  Q_n = (exp(e D_n) - 1) / e,
    ///   r_n = (a)_n (b)_n / (n! (1 - e)_n),
    ///   D_n = [ln Gamma(a+n+e) - ln Gamma(a+n) + ln Gamma(b+n+e) - ln Gamma(b+n)
    ///          - ln Gamma(n+1+e) + ln Gamma(n+1-e)] / e + ln w,
    /// which at e = 0 is DLMF 15.8.10 (Q_n = D_n = psi(a+n) + psi(b+n) - 2 psi(n+1) + ln w),
    /// so it goes over into the logarithmic case without cancellation between the two terms
    /// of 15.8.4. With dQ_n/dw = (1 + e Q_n) / w,
    ///   dF/ds = -z w dF/dw = prefactor z sum_n r_n w^n ((n + e) Q_n + 1).
    /// The parts of D_n and Q_n that do not depend on w are tabulated once ([`Hyp2f1::chunk`]):
    /// with A_n = expm1(e (D_n - ln w)) and B = expm1(e ln w),
    /// e Q_n = expm1(e D_n) = A_n + B + A_n B, exact up to rounding of the size
    /// eps (|A_n| + |B|), so no transcendental function is left in the sum.
    fn near_one(&self, z: f64, w: f64, ln_w: f64) -> (f64, f64) {
        self.near_one_sums::<true>(z, w, ln_w)
    }

    /// [`Hyp2f1::near_one`], with the derivative's sum only where `SLOPE` (else 0).
    #[inline(always)]
    fn near_one_sums<const SLOPE: bool>(&self, z: f64, w: f64, ln_w: f64) -> (f64, f64) {
        let e = self.e;
        debug_assert!(w >= 0.0 || e == 0.0, "z > 1 only in the logarithmic case");
        let k = self.constants();
        let big_b = if e == 0.0 { 0.0 } else { (e * ln_w).exp_m1() };
        let (mut wn, mut sum, mut slope) = (1.0, 0.0, 0.0);
        'chunks: for i in 0..CHUNKS {
            for (j, t) in self.chunk(i).terms.iter().enumerate() {
                let q = if e == 0.0 {
                    t.d0 + ln_w
                } else {
                    (t.am1 + big_b + t.am1 * big_b) / e
                };
                let term = -t.r * wn * q;
                sum += term;
                let nf = (i * CHUNK + j) as f64;
                if SLOPE {
                    slope += t.r * wn * ((nf + e) * q + 1.0);
                }
                wn *= w;
                if wn == 0.0 || (nf > 0.0 && term.abs() <= SERIES_TOL * sum.abs()) {
                    break 'chunks;
                }
            }
        }
        (k.prefactor * sum, k.prefactor * z * slope)
    }
}

/// Terms of [`SeriesRatios`]' table: |z| <= 1/2 sums about 55-60.
const RATIOS: usize = 64;

/// The power series of 2F1(a, b; c; z) (DLMF 15.2.1) for fixed a, b, c not a non-positive
/// integer, |z| <= 1/2 (at most [`MAX_TERMS`] terms; about 55 at |z| = 1/2): its term ratios
/// without z, (a + n) (b + n) / ((c + n) (n + 1)), tabulated once, so that each sum costs one
/// multiplication by z per term; the term is term (ratio z), as the series summed term by
/// term computes it (beyond the table the ratios are computed in place).
#[derive(Clone, Debug)]
pub(crate) struct SeriesRatios {
    a: f64,
    b: f64,
    c: f64,
    ratios: Box<[f64; RATIOS]>,
}

impl SeriesRatios {
    pub(crate) fn new(a: f64, b: f64, c: f64) -> Self {
        let mut ratios = Box::new([0.0; RATIOS]);
        for (n, r) in ratios.iter_mut().enumerate() {
            let n = n as f64;
            *r = (a + n) * (b + n) / ((c + n) * (n + 1.0));
        }
        SeriesRatios { a, b, c, ratios }
    }

    /// The series at |z| <= 1/2.
    pub(crate) fn sum(&self, z: f64) -> f64 {
        let (mut term, mut sum) = (1.0, 1.0);
        for n in 0..MAX_TERMS {
            let r = match self.ratios.get(n) {
                Some(&r) => r,
                None => {
                    let n = n as f64;
                    (self.a + n) * (self.b + n) / ((self.c + n) * (n + 1.0))
                }
            };
            term *= r * z;
            sum += term;
            if term.abs() <= SERIES_TOL * sum.abs() {
                break;
            }
        }
        sum
    }
}

/// 2F1(a, b; a + b + e; z) alone (see [`Hyp2f1`]).
pub(crate) fn hyp2f1(a: f64, b: f64, e: f64, z: f64, one_minus_z: f64, ln_one_minus_z: f64) -> f64 {
    Hyp2f1::new(a, b, e).eval(z, one_minus_z, ln_one_minus_z).0
}

/// Largest |w| (resp. |1 - w|) where [`lerch_phi1`] sums its series about 0 (resp. 1):
/// 0.6^75 ~ 2e-17. The two discs cover the Cauchy transforms' near field (|w - 1/2| <= 0.55,
/// see `numerics::cauchy`).
const LERCH_DISC: f64 = 0.6;

/// Phi(w, 1, a) = sum_{n >= 0} w^n / (n + a) = 2F1(1, a; 1 + a; w) / a for 0 < a <= 1 and
/// complex w with |w| <= 0.6 or |1 - w| <= 0.6 (given with 1 - w to full accuracy), the
/// principal branch (cut w >= 1; a point on the cut is the limit from the side of the sign of
/// its zero imaginary part). Near w = 1, DLMF 15.8.10 with (a, b) = (1, a) gives
///   Phi = sum_k (a)_k / k! [psi(k + 1) - psi(a + k) - ln(1 - w)] (1 - w)^k.
pub(crate) fn lerch_phi1(w: Complex<f64>, one_minus_w: Complex<f64>, a: f64) -> Complex<f64> {
    // convergence tests on squared moduli (no hypot in the loop)
    let tol2 = SERIES_TOL * SERIES_TOL;
    let mut sum = Complex::new(0.0, 0.0);
    if w.norm_sqr() <= LERCH_DISC * LERCH_DISC {
        let mut power = Complex::new(1.0, 0.0);
        for n in 0..MAX_TERMS {
            let term = power / (n as f64 + a);
            sum += term;
            if term.norm_sqr() <= tol2 * sum.norm_sqr() {
                break;
            }
            power *= w;
        }
        return sum;
    }
    let log = one_minus_w.ln();
    let (mut r, mut power) = (1.0, Complex::new(1.0, 0.0));
    // psi(k + 1) - psi(a + k), updated by psi(x + 1) = psi(x) + 1/x
    let mut psi = digamma(1.0) - digamma(a);
    for k in 0..MAX_TERMS {
        let kf = k as f64;
        let term = power * r * (Complex::new(psi, 0.0) - log);
        sum += term;
        if k > 0 && term.norm_sqr() <= tol2 * sum.norm_sqr() {
            break;
        }
        psi += 1.0 / (kf + 1.0) - 1.0 / (a + kf);
        r *= (a + kf) / (kf + 1.0);
        power *= one_minus_w;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Li_n against independent values: closed forms at 1/2 and 1, direct sums below 1, and
    /// the inversion formula Re Li_2(x) = pi^2 / 3 - ln^2 x / 2 - Li_2(1 / x) above 1.
    #[test]
    fn polylog_matches_sums_and_closed_forms() {
        let direct = |n: i32, x: f64| {
            (1..4000)
                .map(|k| x.powi(k) / (k as f64).powi(n))
                .sum::<f64>()
        };
        let ln2 = std::f64::consts::LN_2;
        let z3 = zeta_int(3).unwrap();
        let cases = [
            (2, 0.5, PI * PI / 12.0 - ln2 * ln2 / 2.0),
            (
                3,
                0.5,
                0.875 * z3 - PI * PI * ln2 / 12.0 + ln2.powi(3) / 6.0,
            ),
            (2, 1.0, PI * PI / 6.0),
            (5, 1.0, zeta_int(5).unwrap()),
            (
                2,
                1.2,
                PI * PI / 3.0 - 1.2f64.ln().powi(2) / 2.0 - direct(2, 1.0 / 1.2),
            ),
            (2, 0.9, direct(2, 0.9)),
            (7, 0.75, direct(7, 0.75)),
            (12, 0.6, direct(12, 0.6)),
            (4, -0.4, direct(4, -0.4)),
        ];
        for (n, x, exact) in cases {
            let v = polylog(n, x);
            assert!(
                (v - exact).abs() < 4e-15 * exact.abs().max(1.0),
                "Li_{n}({x}) = {v} vs {exact}"
            );
        }
    }

    /// exprel2 is continuous where it switches from the series to the direct form.
    #[test]
    fn exprel2_switch() {
        for s in [-0.5f64, 0.5] {
            let s = s * (1.0 - 1e-12);
            let (a, b) = (exprel2(s), (s.exp_m1() - s) / (s * s));
            assert!((a - b).abs() < 1e-14, "{s}: {a} vs {b}");
        }
        assert!((exprel2(1e-9) - 0.5).abs() < 1e-9);
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    const EULER: f64 = 0.577_215_664_901_532_9;

    #[test]
    fn gamma_known_values() {
        assert!(rel(ln_gamma(0.5), 0.5 * PI.ln()) < 1e-14);
        assert!(rel(ln_gamma(5.0).exp(), 24.0) < 1e-14);
        assert!(rel(ln_gamma(1.0 / 3.0).exp(), 2.678_938_534_707_747_6) < 1e-14);
        assert!(rel(ln_gamma(0.01).exp(), 99.432_585_119_150_6) < 1e-14);
        assert!(rel(ln_gamma(100.0), 359.134_205_369_575_4) < 1e-15);
        assert!(rel(ln_gamma(300.0), 1_409.202_067_470_411_8) < 1e-15);
        assert!(rel(gamma(2.0), 1.0) < 3e-16 && rel(gamma(1.0), 1.0) < 3e-16);
        assert!(rel(gamma(30.5), 4.822_696_933_490_909e31) < 1e-14);
        // B(1/2, 1/2) = pi, B(2, 3) = 1/12, and the large-argument branch.
        assert!(rel(beta(0.5, 0.5), PI) < 1e-15);
        assert!(rel(beta(2.0, 3.0), 1.0 / 12.0) < 1e-15);
        let big = (ln_gamma(150.0) + ln_gamma(60.5) - ln_gamma(210.5)).exp();
        assert!(rel(beta(150.0, 60.5), big) < 1e-12);
    }

    #[test]
    fn digamma_values() {
        // psi(1) = -gamma, psi(1/2) = -gamma - 2 ln 2, psi(0.1) and psi(100) (mpmath).
        assert!((digamma(1.0) + EULER).abs() < 1e-15);
        let psi_half = -EULER - 2.0 * std::f64::consts::LN_2;
        assert!((digamma(0.5) - psi_half).abs() < 1e-15);
        assert!((digamma(0.1) + 10.423_754_940_411_076).abs() < 1e-13);
        assert!(rel(digamma(100.0), 4.600_161_852_738_087) < 1e-15);
    }

    #[test]
    fn series_ratios_sum_as_the_series_term_by_term() {
        // the series with each ratio computed in the term's update, as before the table
        let direct = |a: f64, b: f64, c: f64, z: f64| {
            let (mut term, mut sum) = (1.0, 1.0);
            for n in 0..MAX_TERMS {
                let n = n as f64;
                term *= (a + n) * (b + n) / ((c + n) * (n + 1.0)) * z;
                sum += term;
                if term.abs() <= SERIES_TOL * sum.abs() {
                    break;
                }
            }
            sum
        };
        for (a, b, c) in [
            (1.0, -0.6, 0.7),
            (1.0, 0.3, 1.3),
            (0.5, 0.5, 1.0),
            (1.0, 0.999, 1.0),
        ] {
            let table = SeriesRatios::new(a, b, c);
            for z in [-0.5, -0.1, 1e-9, 0.2, 0.4999, 0.5] {
                assert_eq!(
                    table.sum(z).to_bits(),
                    direct(a, b, c, z).to_bits(),
                    "{a} {b} {c} {z}"
                );
            }
        }
        // the value alone as eval's, through both expansions
        for (a, b, e) in [(1.0, 0.4, 0.3), (0.7, 1.0, 0.0), (1.0, 1.2, 0.6)] {
            let f = Hyp2f1::new(a, b, e);
            for z in [0.1f64, 0.5, 0.6, 0.9, 0.999] {
                let w = 1.0 - z;
                let (v, _) = f.eval(z, w, w.ln());
                assert_eq!(
                    f.value(z, w, w.ln()).to_bits(),
                    v.to_bits(),
                    "{a} {b} {e} {z}"
                );
            }
        }
    }

    #[test]
    fn ln_gamma_slope_matches_digamma_and_differences() {
        assert_eq!(ln_gamma_slope(0.7, 0.0), digamma(0.7));
        for (x, e) in [(0.5, 0.3), (1.0, -0.4), (0.2, 0.45), (3.7, 0.25)] {
            let d = (ln_gamma(x + e) - ln_gamma(x)) / e;
            assert!((ln_gamma_slope(x, e) - d).abs() < 1e-13);
        }
        // tiny e: the quotient tends to psi(x) without cancellation
        assert!((ln_gamma_slope(2.5, 1e-12) - digamma(2.5)).abs() < 1e-11);
    }

    #[test]
    fn hypergeometric_branches_agree() {
        // The z -> 1 - z branch against the plain series (slow but convergent) for z in
        // (1/2, 0.8], and its limit e -> 0 against the logarithmic case.
        for (a, b, e) in [
            (0.5, 0.5, 0.0),
            (0.5, 0.7, 0.0),
            (0.3, 0.5, 0.2),
            (0.01, 0.5, 0.49),
        ] {
            for z in [0.5, 0.6, 0.8] {
                let w: f64 = 1.0 - z;
                let f = Hyp2f1::new(a, b, e);
                let direct = f.series(z).0;
                let near = f.near_one(z, w, w.ln()).0;
                assert!(
                    (near / direct - 1.0).abs() < 1e-14,
                    "{a} {b} {e} {z}: {near} {direct}"
                );
            }
        }
        let w: f64 = 1e-3;
        let log_case = Hyp2f1::new(0.5, 0.5, 0.0).near_one(1.0 - w, w, w.ln()).0;
        let nearly = Hyp2f1::new(0.5 - 1e-10, 0.5, 1e-10)
            .near_one(1.0 - w, w, w.ln())
            .0;
        assert!((nearly / log_case - 1.0).abs() < 1e-9);
    }

    /// dF/ds = z (1 - z) F'(z) on both branches: for 2F1(1/2, 1/2; 1; m) = (2/pi) K(m) it is
    /// (E(m) - (1 - m) K(m)) / pi (DLMF 19.4.1; `ellip`'s K and E take the parameter m), and in
    /// general z (1 - z) (ab/c) 2F1(a + 1, b + 1; c + 1; z) (DLMF 15.5.1), summed directly.
    #[test]
    fn hypergeometric_slopes() {
        let f = Hyp2f1::new(0.5, 0.5, 0.0);
        for m in [0.01, 0.2, 0.5, 0.7, 0.95, 1.0 - 1e-9] {
            let (k, e) = (ellip::ellipk(m).unwrap(), ellip::ellipe(m).unwrap());
            let (value, slope) = f.eval(m, 1.0 - m, (1.0 - m).ln());
            assert!(rel(value, 2.0 / PI * k) < 1e-14, "m {m}: {value}");
            let exact = (e - (1.0 - m) * k) / PI;
            assert!(rel(slope, exact) < 1e-13, "m {m}: {slope} vs {exact}");
        }
        for (a, b, e) in [
            (0.3, 0.5, 0.2),
            (0.5, 0.7, 0.0),
            (0.01, 0.5, 0.49),
            (0.45, 0.5, 0.05),
        ] {
            let c = a + b + e;
            for z in [1e-6f64, 0.1, 0.45, 0.55, 0.8] {
                let (mut t, mut sum) = (1.0, 1.0);
                for n in 0..3000 {
                    let n = n as f64;
                    t *= (a + 1.0 + n) * (b + 1.0 + n) / ((c + 1.0 + n) * (n + 1.0)) * z;
                    sum += t;
                }
                let exact = z * (1.0 - z) * a * b / c * sum;
                let slope = Hyp2f1::new(a, b, e).eval(z, 1.0 - z, (1.0 - z).ln()).1;
                assert!(
                    rel(slope, exact) < 1e-13,
                    "{a} {b} {e} {z}: {slope} vs {exact}"
                );
            }
        }
    }

    /// 2F1(1, a; 1 + a; z) = a sum z^k / (a + k) (DLMF 15.2.1 with (1)_k = k!), and for z > 1
    /// the real part of the continuation against mpmath (`hyp2f1(1, 0.37, 1.37, z +- 1e-25j)`,
    /// 30 digits; equal from both sides).
    #[test]
    fn logarithmic_case_beyond_one() {
        let a: f64 = 0.37;
        for z in [-0.45f64, 0.3, 0.6, 0.9] {
            let direct: f64 = (0..400).map(|k| a * z.powi(k) / (a + k as f64)).sum();
            assert!(rel(hyp2f1(1.0, a, 0.0, z, 1.0 - z, (1.0 - z).ln()), direct) < 1e-15);
        }
        for (z, mpmath) in [
            (1.2f64, 1.364_193_525_079_932_5),
            (1.45, 1.050_824_553_167_441_4),
        ] {
            let ours = hyp2f1(1.0, a, 0.0, z, 1.0 - z, (z - 1.0).ln());
            assert!(rel(ours, mpmath) < 1e-14, "z {z}: {ours} vs {mpmath}");
        }
    }

    /// Phi(w, 1, 1) = -ln(1 - w) / w, and for a = 1/2: Phi(w, 1, 1/2) = 2 artanh(sqrt w) /
    /// sqrt(w) (sum w^n / (n + 1/2) = 2 sum (sqrt w)^(2n) / (2n + 1)), through both series and
    /// on the cut from either side.
    #[test]
    fn lerch_closed_forms() {
        let c = Complex::new;
        for w in [
            c(0.3, -0.2),
            c(-0.5, 0.1),
            c(0.5, 0.45),
            c(0.9, -0.3),
            c(1.3, -1e-30),
            c(1.3, 0.0),
            c(1.0 - 1e-12, 0.0),
            c(0.55, -0.01),
        ] {
            let omw = c(1.0, 0.0) - w;
            let one = lerch_phi1(w, omw, 1.0);
            let exact = -omw.ln() / w;
            assert!(
                (one - exact).norm() < 1e-14 * exact.norm(),
                "{w}: {one} vs {exact}"
            );
            let half = lerch_phi1(w, omw, 0.5);
            let r = w.sqrt();
            let exact = ((c(1.0, 0.0) + r).ln() - (omw / (c(1.0, 0.0) + r)).ln()) / r;
            assert!(
                (half - exact).norm() < 1e-14 * exact.norm(),
                "{w}: {half} vs {exact}"
            );
        }
        // the sign of a zero imaginary part picks the side of the cut
        let (above, below) = (c(1.5, 0.0), c(1.5, -0.0));
        let (pa, pb) = (
            lerch_phi1(above, c(-0.5, -0.0), 0.3),
            lerch_phi1(below, c(-0.5, 0.0), 0.3),
        );
        assert!((pa.re - pb.re).abs() < 1e-14 && (pa.im + pb.im).abs() < 1e-14 && pa.im > 0.0);
    }
}
