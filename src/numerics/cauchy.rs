//! Cauchy (finite Hilbert) transforms of Jacobi-weighted Legendre polynomials on [-1, 1]:
//! C_k(y) = PV int_{-1}^{1} w(t) P_k(t) / (y - t) dt for the end weights w = 1, (1 - t)^e,
//! (1 + t)^e with e in (-1, 1) (the local exponents g, g - 1, -g of the contact tractions,
//! docs/theory.md (X1), (X2), (K2)).
//!
//! Real y (the solvers): near the interval (|y| <= 1.1) C_0 is evaluated in closed form and
//! the rest follow from the exact recurrence (k+1) C_{k+1} + k C_{k-1} = (2k+1) (y C_k - M_k),
//! M_k = int w P_k in closed form (forward recurrence: absolute error <= eps rho(y)^k <= 1e-11
//! for |y| <= 1.1, k < 26); farther away a Gauss-Jacobi rule for w, sized to the distance and
//! the degree, is exact to rounding. y must be off the interval ends.
//!
//! Complex zeta (the stress field, [`near_transforms`]): the same closed form C_0 continued
//! off the axis through the Lerch sum Phi(w, 1, a) and the same recurrence, plus the
//! derivatives C_k' (C_0' in closed form, then the differentiated recurrence). Meant for the
//! near field, Bernstein parameter rho(zeta) < [`NEAR_RHO`] (forward recurrence: absolute
//! error <= eps rho^k <= 4e-12 for k < 26); farther away the caller's Gauss rules are exact.
//! A point of the segment itself is the limit from below (zero imaginary part -0.0).

use std::f64::consts::PI;

use faer::complex::Complex;

use super::orthopoly::{bonnet, jacobi_mass, legendre};
use super::quadrature::gauss_jacobi;
use super::special::{exprel, exprel2, hyp2f1, lerch_phi1, polylog, sin_pi, tan_pi, zeta_int};

/// Complex numbers (faer's re-export of num-complex).
pub(crate) type C64 = Complex<f64>;

/// Far-field bands: the |y| above which each rule is used. A rule of m nodes integrates
/// P_k(t) / (y - t) with error ~ rho^(k - 2m), rho = |y| + sqrt(y^2 - 1) at the band's lower
/// end ([`far_nodes`]), so the wider bands far away need few nodes.
const FAR_BANDS: [f64; 6] = [150.0, 40.0, 12.0, 4.0, 1.5, 1.1];

/// Partial sums per far-field dot product (and the nodes' padding).
const LANES: usize = 8;

/// Nodes of the far-field rule for |y| > y_min and Legendre degrees below `degrees`:
/// rho^(degrees - 1 - 2m) <= 1e-17.
fn far_nodes(y_min: f64, degrees: usize) -> usize {
    let rho = y_min + (y_min * y_min - 1.0).sqrt();
    ((degrees as f64 - 1.0 + 17.0 / rho.log10()) / 2.0).ceil() as usize
}

/// Endpoint weight of a basis function on [-1, 1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Weight {
    /// w = 1.
    One,
    /// w = (1 - t)^e: the exponent sits at the right end.
    Right(f64),
    /// w = (1 + t)^e: the exponent sits at the left end.
    Left(f64),
    /// w = ((1 - t)^g - 1) / g for g > 0 (-> ln(1 - t) as g -> 0): spans with `One` what
    /// `Right(g)` spans with it, without their near-dependence at small g.
    RightLog(f64),
    /// w = ((1 + t)^g - 1) / g for g > 0.
    LeftLog(f64),
}

impl Weight {
    /// Jacobi exponents (alpha at t = 1, beta at t = -1).
    /// A log weight's are those of its power part (1 -+ t)^g.
    pub(crate) fn exponents(self) -> (f64, f64) {
        match self {
            Weight::One => (0.0, 0.0),
            Weight::Right(e) | Weight::RightLog(e) => (e, 0.0),
            Weight::Left(e) | Weight::LeftLog(e) => (0.0, e),
        }
    }

    /// A log weight as (its power part, g).
    pub(crate) fn log_parts(self) -> Option<(Weight, f64)> {
        match self {
            Weight::RightLog(g) => Some((Weight::Right(g), g)),
            Weight::LeftLog(g) => Some((Weight::Left(g), g)),
            _ => None,
        }
    }

    /// w given the distances 1 - t and 1 + t to the ends (each to full relative accuracy);
    /// +infinity at an end where the exponent is negative.
    pub(crate) fn at(self, one_minus_t: f64, one_plus_t: f64) -> f64 {
        match self {
            Weight::One => 1.0,
            Weight::Right(e) => one_minus_t.powf(e),
            Weight::Left(e) => one_plus_t.powf(e),
            Weight::RightLog(g) => log_weight(g, one_minus_t),
            Weight::LeftLog(g) => log_weight(g, one_plus_t),
        }
    }

    /// The Gauss rule with m nodes for this weight (ascending nodes), exact for degrees
    /// below 2m. A log weight has none (it changes sign): its rule is the interpolatory
    /// product rule on the 2m Gauss-Legendre nodes t_j (weights lambda_j), exact for the same
    /// degrees: W_j = lambda_j sum_{k < 2m} (k + 1/2) P_k(t_j) M_k with the weight's moments
    /// M_k ([`Weight::moments`], free of the eps / g a difference of two Gauss rules costs).
    pub(crate) fn rule(self, m: usize) -> (Vec<f64>, Vec<f64>) {
        if self.log_parts().is_some() {
            let n = 2 * m;
            let (nodes, lambda) = gauss_jacobi(n, 0.0, 0.0);
            let moments = self.moments(n);
            let mut p = vec![0.0; n];
            let weights = nodes
                .iter()
                .zip(&lambda)
                .map(|(&t, &l)| {
                    legendre(t, &mut p);
                    let sum: f64 = (0..n).map(|k| (k as f64 + 0.5) * p[k] * moments[k]).sum();
                    l * sum
                })
                .collect();
            return (nodes, weights);
        }
        let (alpha, beta) = self.exponents();
        gauss_jacobi(m, alpha, beta)
    }

    /// M_k = int_{-1}^{1} w P_k for k < n: for (1 - t)^e, M_0 = 2^(e+1) / (e + 1) and
    /// M_k = M_{k-1} (k - 1 - e) / (k + 1 + e) (from int (1-t)^e P_k = 2^(e+1) Gamma(e+1)^2 /
    /// (Gamma(e+k+2) Gamma(e+1-k)), Gradshteyn-Ryzhik 7.127); (1 + t)^e by P_k(-t) = (-1)^k P_k(t).
    /// A log weight's: (M_k of its power part - M_k of 1) / g, with M_0 - 2 = 2 (e^s - 1),
    /// s = g ln 2 - ln(1 + g), and M_1 = M_0 g / (2 + g) divided by g exactly.
    pub(crate) fn moments(self, n: usize) -> Vec<f64> {
        let (e, sign) = match self {
            Weight::One => (0.0, 1.0),
            Weight::Right(e) | Weight::RightLog(e) => (e, 1.0),
            Weight::Left(e) | Weight::LeftLog(e) => (e, -1.0),
        };
        let mut m = Vec::with_capacity(n);
        if self.log_parts().is_some() {
            let g = e;
            let s = g * std::f64::consts::LN_2 - g.ln_1p();
            let m0 = jacobi_mass(g, 0.0);
            m.push(2.0 * (std::f64::consts::LN_2 - g.ln_1p() / g) * exprel(s));
            let mut v = -sign * m0 / (2.0 + g);
            for k in 1..n {
                if k > 1 {
                    let kf = k as f64;
                    v *= sign * (kf - 1.0 - g) / (kf + 1.0 + g);
                }
                m.push(v);
            }
            m.truncate(n);
            return m;
        }
        let mut v = jacobi_mass(e, 0.0);
        for k in 0..n {
            if k > 0 {
                let kf = k as f64;
                v *= sign * (kf - 1.0 - e) / (kf + 1.0 + e);
            }
            m.push(v);
        }
        m
    }

    /// PV int_{-1}^{1} w(t) / (y - t) dt for |y| <= ~1.3, y != +-1.
    fn cauchy0(self, y: f64) -> f64 {
        match self {
            Weight::One => ((1.0 + y) / (1.0 - y)).abs().ln(),
            Weight::Right(e) => end_cauchy(e, 1.0 - y),
            Weight::Left(e) => -end_cauchy(e, 1.0 + y),
            Weight::RightLog(g) => log_cauchy(g, 1.0 - y),
            Weight::LeftLog(g) => -log_cauchy(g, 1.0 + y),
        }
    }
}

/// (u^g - 1) / g at u = 1 -+ t, to full accuracy for every g > 0: ln u exprel(g ln u)
/// (-1 / g at u = 0).
fn log_weight(g: f64, u: f64) -> f64 {
    if u == 0.0 {
        return -1.0 / g;
    }
    let l = u.ln();
    l * exprel(g * l)
}

/// Below this g, [`log_cauchy`] takes its series form; above it the difference quotient of
/// [`end_cauchy`] loses at most eps / g <= 2e-14.
const LOG_SERIES_BELOW: f64 = 0.05;

/// D(g, z) = PV int_0^2 ((u^g - 1) / g) / (u - z) du = (E(g, z) - E(0, z)) / g for
/// -0.3 < z < 2.3 (z != 0, 2), E of [`end_cauchy`]. For small g the difference of
/// [`end_cauchy_small`]'s parts, each divided by g without cancellation (a = ln 2,
/// b = ln|z|, zeta = z / 2):
///   D = a^2 exprel2(g a) - b^2 exprel2(g b) + |z|^g gap(g) / g
///       - ln 2 exprel(g ln 2) S_g(zeta) - R_g(zeta),
/// S_g = sum_{n >= 1} zeta^n / (n - g) = zeta / (1 - g) 2F1(1, 1 - g; 2 - g; zeta),
/// R_g = (S_g - S_0) / g = sum_{n >= 1} zeta^n / (n (n - g)), summed directly for
/// |zeta| <= 1/2 and as sum_j g^j Li_(j+2)(zeta) beyond; gap(g) / g of [`gap_over`].
/// Checked against mpmath quadrature to 6e-15 for g = 1e-7 .. 0.05 (tests below).
pub(crate) fn log_cauchy(g: f64, z: f64) -> f64 {
    if g >= LOG_SERIES_BELOW {
        return (end_cauchy(g, z) - end_cauchy(0.0, z)) / g;
    }
    let (a, b, zeta) = (std::f64::consts::LN_2, z.abs().ln(), 0.5 * z);
    let s_g = tail_series(g, zeta);
    let r_g = pochhammer_tail(g, zeta);
    a * a * exprel2(g * a) - b * b * exprel2(g * b) + z.abs().powf(g) * gap_over(g, z > 0.0)
        - a * exprel(g * a) * s_g
        - r_g
}

/// R_e(zeta) = sum_{n >= 1} zeta^n / (n (n - e)) for |e| < 1 and -1/2 <= zeta <= 3/2 (the real
/// part beyond 1): summed directly for |zeta| <= 1/2, and as sum_j e^j Li_(j+2)(zeta) beyond
/// (1 / (n (n - e)) = sum_j e^j / n^(j+2)), to |e|^j <= 1e-18 or Li_16. It is
/// (S_e - S_0) / e of [`tail_series`] without the cancellation, for [`log_cauchy`] and the
/// difference-quotient families of `numerics::quotient`.
pub(crate) fn pochhammer_tail(e: f64, zeta: f64) -> f64 {
    if zeta.abs() <= 0.5 {
        let (mut sum, mut power, mut n) = (0.0f64, zeta, 1.0);
        while power.abs() > 1e-18 * sum.abs().max(f64::MIN_POSITIVE) {
            sum += power / (n * (n - e));
            power *= zeta;
            n += 1.0;
        }
        return sum;
    }
    let (mut sum, mut ej, mut j) = (0.0, 1.0f64, 2);
    while ej.abs() > 1e-18 && j <= 16 {
        sum += ej * polylog(j, zeta);
        ej *= e;
        j += 1;
    }
    sum
}

/// T(a, zeta) = int_2^inf u^(-a) / (u - 2 zeta) du (principal value for zeta > 1) for a in
/// (0, 1) and -1/2 <= zeta < 3/2: with u = 2 / s, T = 2^(-a) int_0^1 s^(a-1) / (1 - zeta s) ds
/// = 2^(-a) / a 2F1(1, a; 1 + a; zeta) (DLMF 15.6.1; the real part of the continuation for
/// zeta > 1).
fn end_tail(a: f64, zeta: f64) -> f64 {
    let w = 1.0 - zeta;
    (-a).exp2() / a * hyp2f1(1.0, a, 0.0, zeta, w, w.abs().ln())
}

/// E(e, z) = PV int_0^2 u^e / (u - z) du for e in (-1, 1) and -0.3 < z < 2.3 (z != 0, 2).
/// Negative e: the integral over (0, inf) in closed form (pi z^e cot(-pi e), or
/// pi |z|^e / sin(-pi e) for z < 0) minus the tail over (2, inf); e > 0 reduces to e - 1.
pub(crate) fn end_cauchy(e: f64, z: f64) -> f64 {
    if e == 0.0 {
        return ((2.0 - z) / z).abs().ln();
    }
    if e.abs() < SMALL_EXPONENT {
        return end_cauchy_small(e, z);
    }
    if e > 0.0 {
        return e.exp2() / e + z * end_cauchy(e - 1.0, z);
    }
    let a = -e;
    let base = if z > 0.0 {
        PI * z.powf(e) / tan_pi(a)
    } else {
        PI * (-z).powf(e) / sin_pi(a)
    };
    base - end_tail(a, 0.5 * z)
}

/// Below this |e|, [`end_cauchy`] takes [`end_cauchy_small`]: the general formula's two parts
/// each grow like 1 / e and cancel (an absolute error of eps / e, which the panel solver's
/// nearly dependent blocks (x - c)^g P_k and P_k turn into eps / g^2: defect noise 1e-5 at
/// g = 4e-5, i.e. b* = 0.83, mu~ = 1e4).
const SMALL_EXPONENT: f64 = 0.1;

/// E(e, z) for 0 < |e| < [`SMALL_EXPONENT`] without the cancelling 1 / e parts: with
/// L = ln(2 / |z|) and zeta = z / 2 (from the formula of [`end_cauchy`], for e > 0 after its
/// reduction to e - 1, and 2F1(1, a; 1 + a; zeta) = 1 + a zeta / (1 + a) 2F1(1, 1 + a; 2 + a;
/// zeta) for e < 0, both signs give the same expression)
///   E = |z|^e (L exprel(e L) + gap(e)) - 2^e zeta / (1 - e) 2F1(1, 1 - e; 2 - e; zeta),
/// gap(e) = 1/e - pi cot(pi e) for z > 0 (principal value), 1/e - pi / sin(pi e) for z < 0
/// ([`gap_over`]). At e = 0 it is ln|(2 - z) / z|.
fn end_cauchy_small(e: f64, z: f64) -> f64 {
    let l = (2.0 / z.abs()).ln();
    let gap = e * gap_over(e, z > 0.0);
    z.abs().powf(e) * (l * exprel(e * l) + gap) - e.exp2() * tail_series(e, 0.5 * z)
}

/// S_e(zeta) = sum_{n >= 1} zeta^n / (n - e) = zeta / (1 - e) 2F1(1, 1 - e; 2 - e; zeta), the
/// tail of [`end_cauchy_small`] and [`log_cauchy`] (-1/2 <= zeta <= 3/2, real part beyond 1).
fn tail_series(e: f64, zeta: f64) -> f64 {
    let w = 1.0 - zeta;
    zeta / (1.0 - e) * hyp2f1(1.0, 1.0 - e, 0.0, zeta, w, w.abs().ln())
}

/// gap(x) / x for 0 < |x| < 0.1: gap = 1/x - pi cot(pi x) = 2 sum_k zeta(2k) x^(2k-1) where
/// `principal` (the principal value, z > 0), gap = 1/x - pi / sin(pi x) = that minus
/// pi tan(pi x / 2) otherwise; the series to zeta(16) leaves out less than 1e-16 relative.
pub(crate) fn gap_over(x: f64, principal: bool) -> f64 {
    let (mut sum, mut power, mut k) = (0.0, 1.0, 1);
    while let Some(zk) = zeta_int(2 * k) {
        sum += 2.0 * zk * power;
        power *= x * x;
        if power < 1e-18 {
            break;
        }
        k += 1;
    }
    if principal {
        sum
    } else {
        sum - PI * (0.5 * PI * x).tan() / x
    }
}

/// |e| up to which u^e is 1 for every double u in (0, 2]: |e ln u| <= 745 |e| < eps / 2.
/// Below it [`end_cauchy_complex`]'s closed form divides by sin(pi e) ~ pi e, which overflows
/// for |e| below about 7e-309 (g = 2.2e-309 at mu = 1.8e308: NaN stresses next to the
/// punch edge, issue 26).
const UNIT_POWER_BELOW: f64 = 1e-19;

/// Largest Bernstein parameter rho(zeta) = |zeta + sqrt(zeta^2 - 1)| at which
/// [`near_transforms`] is meant to be used: its forward recurrence loses at most
/// eps rho^k <= 4e-12 at degree 25, and its Lerch sums converge there (|w - 1/2| <= 0.55 for
/// w = (1 - zeta) / 2).
pub(crate) const NEAR_RHO: f64 = 1.5;

/// A point zeta of the complex plane in a panel's local coordinate, with 1 - zeta and
/// 1 + zeta carried separately so that they keep their relative accuracy next to the ends.
/// On the segment (zero imaginary part) it stands for the limit from below when the zero is
/// -0.0 (the sign of zero is kept through every operation below).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Local {
    /// zeta.
    pub(crate) zeta: C64,
    /// 1 - zeta.
    pub(crate) omz: C64,
    /// 1 + zeta.
    pub(crate) opz: C64,
}

/// E(e, s) = int_0^2 u^e / (u - s) du and its derivative dE/ds for complex s off [0, 2]
/// (given with 2 - s), e in (-1, 1): for e < 0 the integral over (0, inf),
/// pi (-s)^e / sin(-pi e), minus the tail over (2, inf), 2^e Phi(s/2, 1, -e); e = 0 the
/// logarithm; e > 0 reduces to e - 1 by u^e / (u - s) = u^(e-1) + s u^(e-1) / (u - s).
/// The derivative follows from integrating by parts: dE/ds = -2^e / (2 - s) + e E(e - 1, s),
/// which for e <= 0 reads -2^e / (2 - s) + (e E(e, s) - 2^e) / s.
/// |e| <= [`UNIT_POWER_BELOW`] is e = 0.
fn end_cauchy_complex(e: f64, s: C64, two_minus_s: C64) -> (C64, C64) {
    let e = if e.abs() <= UNIT_POWER_BELOW { 0.0 } else { e };
    if e > 0.0 {
        let (lower, _) = end_cauchy_complex(e - 1.0, s, two_minus_s);
        let value = e.exp2() / e + s * lower;
        return (value, -e.exp2() / two_minus_s + lower * e);
    }
    let value = if e == 0.0 {
        // ln(2 - s) - ln(-s): one real logarithm of the ratio of squared moduli (two where
        // one of them is too small to square, a point at an end), the arguments as they are
        let (a2, b2) = (two_minus_s.norm_sqr(), s.norm_sqr());
        let re = if a2 > f64::MIN_POSITIVE && b2 > f64::MIN_POSITIVE {
            0.5 * (a2 / b2).ln()
        } else {
            two_minus_s.norm().ln() - s.norm().ln()
        };
        C64::new(re, two_minus_s.arg() - (-s).arg())
    } else {
        let whole = (-s).powf(e) * (PI / sin_pi(-e));
        whole - lerch_phi1(s * 0.5, two_minus_s * 0.5, -e) * e.exp2()
    };
    let slope = -e.exp2() / two_minus_s + (value * e - e.exp2()) / s;
    (value, slope)
}

impl Weight {
    /// C_0(zeta) and C_0'(zeta) for complex zeta off the segment (or on it, from below):
    /// E(e, 1 - zeta) for (1 - t)^e and 1, -E(e, 1 + zeta) for (1 + t)^e; C_0' = -E'(e, s)
    /// in both cases (s the distance to the weighted end).
    fn cauchy0_complex(self, l: Local) -> (C64, C64) {
        if let Some((power, g)) = self.log_parts() {
            // the difference quotient (eps / g): the field gets log weights as their parts
            let ((v, d), (v1, d1)) = (power.cauchy0_complex(l), Weight::One.cauchy0_complex(l));
            return ((v - v1) / g, (d - d1) / g);
        }
        let (value, slope) = match self {
            Weight::One => end_cauchy_complex(0.0, l.omz, l.opz),
            Weight::Right(e) => end_cauchy_complex(e, l.omz, l.opz),
            Weight::Left(e) => {
                let (v, d) = end_cauchy_complex(e, l.opz, l.omz);
                (-v, d)
            }
            Weight::RightLog(_) | Weight::LeftLog(_) => unreachable!("log weights: above"),
        };
        (value, -slope)
    }
}

/// C_k(zeta) for k < out.len() (and C_k'(zeta) into `slope` when given, same length) for
/// complex zeta in the near field (rho(zeta) < [`NEAR_RHO`]): C_0 in closed form, then
/// (k+1) C_{k+1} = (2k+1) (zeta C_k - M_k) - k C_{k-1} and its derivative
/// (k+1) C'_{k+1} = (2k+1) (C_k + zeta C'_k) - k C'_{k-1}. `moments` are M_k = int w P_k
/// ([`Weight::moments`], at least out.len() of them).
pub(crate) fn near_transforms(
    weight: Weight,
    moments: &[f64],
    l: Local,
    out: &mut [C64],
    slope: Option<&mut [C64]>,
) {
    let n = out.len();
    if n == 0 {
        return;
    }
    let (c0, d0) = weight.cauchy0_complex(l);
    let z = l.zeta;
    out[0] = c0;
    if n > 1 {
        out[1] = z * c0 - moments[0];
    }
    for k in 1..n - 1 {
        let (fa, fb) = bonnet(k);
        out[k + 1] = (z * out[k] - moments[k]) * fa - out[k - 1] * fb;
    }
    if let Some(d) = slope {
        d[0] = d0;
        if n > 1 {
            d[1] = c0 + z * d0;
        }
        for k in 1..n - 1 {
            let (fa, fb) = bonnet(k);
            d[k + 1] = (out[k] + z * d[k]) * fa - d[k - 1] * fb;
        }
    }
}

/// Everything needed to transform one weight's Legendre family: its far-field Gauss rules
/// (with the Legendre values at the nodes) and the moments M_k.
#[derive(Clone, Debug)]
pub(crate) struct WeightedFamily {
    /// The weight.
    pub(crate) weight: Weight,
    /// Number of Legendre degrees handled (0..degrees).
    pub(crate) degrees: usize,
    /// Per far band: nodes (padded to a multiple of [`LANES`]) and Gauss weights times
    /// P_k(node), row-major [k][node].
    far: Vec<(Vec<f64>, Vec<f64>)>,
    moments: Vec<f64>,
}

impl WeightedFamily {
    /// Family for `weight` and Legendre degrees below `degrees`.
    pub(crate) fn new(weight: Weight, degrees: usize) -> Self {
        let far = FAR_BANDS
            .iter()
            .map(|&y_min| {
                let (mut nodes, weights) = weight.rule(far_nodes(y_min, degrees));
                // padded to whole chunks of LANES with zero-weight nodes at t = 0 (where the
                // kernels are finite: the far bands lie beyond |y| = 1.1)
                let count = nodes.len().div_ceil(LANES) * LANES;
                let mut wp = vec![0.0; count * degrees];
                let mut p = vec![0.0; degrees];
                for (j, (&t, &w)) in nodes.iter().zip(&weights).enumerate() {
                    legendre(t, &mut p);
                    for (k, v) in p.iter().enumerate() {
                        wp[k * count + j] = w * v;
                    }
                }
                nodes.resize(count, 0.0);
                (nodes, wp)
            })
            .collect();
        Self {
            weight,
            degrees,
            far,
            moments: weight.moments(degrees),
        }
    }

    /// int_{-1}^{1} w P_k.
    pub(crate) fn moment(&self, k: usize) -> f64 {
        self.moments[k]
    }

    /// C_k(y) for k < min(out.len(), degrees) into `out` (y real, not a panel end point).
    pub(crate) fn cauchy(&self, y: f64, out: &mut [f64]) {
        let n = out.len().min(self.degrees);
        if let Some(r) = FAR_BANDS.iter().position(|&lim| y.abs() > lim) {
            self.far_sum(r, |t| 1.0 / (y - t), &mut out[..n]);
            return;
        }
        out[0] = self.weight.cauchy0(y);
        if n > 1 {
            out[1] = y * out[0] - self.moments[0];
        }
        for k in 1..n.saturating_sub(1) {
            let (fa, fb) = bonnet(k);
            out[k + 1] = fa * (y * out[k] - self.moments[k]) - fb * out[k - 1];
        }
    }

    /// C_k(y) + sign C_k(y2) for |y2| >= |y| (the mirrored target) into `out`; `buf` is
    /// scratch of the same length. When y is in a far band, its rule serves y2 as well (it is
    /// only more accurate farther away), so both cost one pass over the nodes.
    pub(crate) fn cauchy_pair(&self, y: f64, y2: f64, sign: f64, out: &mut [f64], buf: &mut [f64]) {
        let n = out.len().min(self.degrees);
        if let Some(r) = FAR_BANDS.iter().position(|&lim| y.abs() > lim) {
            // one division per node: 1 / a + sign / b = (b + sign a) / (a b)
            self.far_sum(
                r,
                |t| {
                    let (a, b) = (y - t, y2 - t);
                    (b + sign * a) / (a * b)
                },
                &mut out[..n],
            );
            return;
        }
        self.cauchy(y, &mut out[..n]);
        self.cauchy(y2, &mut buf[..n]);
        for (o, b) in out[..n].iter_mut().zip(&buf[..n]) {
            *o += sign * b;
        }
    }

    /// sum_j f(t_j) w_j P_k(t_j) over the nodes of far band r into `out`.
    /// The kernel at every node first, then one dot product per degree over the nodes, in
    /// LANES independent partial sums (loops the compiler vectorises; a node-by-node update of
    /// all degrees ran one division and one store at a time).
    fn far_sum(&self, r: usize, f: impl Fn(f64) -> f64, out: &mut [f64]) {
        let (nodes, wp) = &self.far[r];
        let m = nodes.len();
        let mut stack = [0.0f64; 64];
        let mut heap;
        let kernel: &mut [f64] = if m <= stack.len() {
            &mut stack[..m]
        } else {
            heap = vec![0.0; m];
            &mut heap
        };
        for (v, &t) in kernel.iter_mut().zip(nodes) {
            *v = f(t);
        }
        for (o, row) in out.iter_mut().zip(wp.chunks_exact(m)) {
            let mut acc = [0.0f64; LANES];
            for (a, b) in kernel.chunks_exact(LANES).zip(row.chunks_exact(LANES)) {
                for i in 0..LANES {
                    acc[i] += a[i] * b[i];
                }
            }
            *o = acc.iter().sum();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent reference: PV int_{-1}^{1} w(t) f(t) / (y - t) dt by singularity
    /// subtraction, the regular part with an adaptive Gauss-Kronrod-free scheme: composite
    /// Gauss-Legendre on a t = -1 + 2 s^m graded mesh (m removes the end singularity).
    fn reference(w: Weight, k: usize, y: f64) -> f64 {
        let pk = |t: f64| {
            let mut v = vec![0.0; k + 1];
            legendre(t, &mut v);
            v[k]
        };
        let f = |t: f64| w.at(1.0 - t, 1.0 + t) * pk(t);
        // Regular part: int (f(t) - f(y)) / (y - t) dt (f(y) = 0 outside [-1,1] use plain).
        let inside = y.abs() < 1.0;
        let fy = if inside { f(y) } else { 0.0 };
        let (x, wts) = crate::numerics::quadrature::gauss_legendre(30);
        // graded composite rule on [-1, 1], dense near both ends and near y
        let mut breaks = vec![-1.0, 1.0];
        for j in 1..40 {
            let d = 0.5f64.powi(j);
            breaks.push(-1.0 + d);
            breaks.push(1.0 - d);
            if inside {
                for s in [-1.0, 1.0] {
                    let b = y + s * d;
                    if b > -1.0 && b < 1.0 {
                        breaks.push(b);
                    }
                }
            }
        }
        if inside {
            breaks.push(y);
        }
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        // log weights have no Gauss-Jacobi rule: Gauss-Legendre on the graded panels (the
        // innermost, of width 2^-39, carries a log singularity of mass ~1e-10)
        let log = matches!(w, Weight::RightLog(_) | Weight::LeftLog(_));
        let (a, b) = if log { (0.0, 0.0) } else { w.exponents() };
        let mut sum = 0.0;
        for p in breaks.windows(2) {
            let (m, h) = (0.5 * (p[0] + p[1]), 0.5 * (p[1] - p[0]));
            // the panel touching a weighted end: Gauss-Jacobi for w P_k / (y - t)
            let (ea, eb) = (
                if p[1] == 1.0 { a } else { 0.0 },
                if p[0] == -1.0 { b } else { 0.0 },
            );
            if ea != 0.0 || eb != 0.0 {
                let (xj, wj) = gauss_jacobi(30, ea, eb);
                // one-sided weights: w(t) = (h (1 - xi))^ea (h (1 + xi))^eb exactly here
                for (xi, wi) in xj.iter().zip(&wj) {
                    let t = m + h * xi;
                    sum += h * wi * h.powf(ea + eb) * pk(t) / (y - t);
                }
                for (xi, wi) in x.iter().zip(&wts) {
                    let t = m + h * xi;
                    sum -= h * wi * fy / (y - t);
                }
            } else {
                for (xi, wi) in x.iter().zip(&wts) {
                    let t = m + h * xi;
                    // distances to the ends without cancellation (dyadic break points)
                    let omt = (1.0 - p[1]) + h * (1.0 - xi);
                    let opt = (1.0 + p[0]) + h * (1.0 + xi);
                    let ft = w.at(omt, opt) * pk(t);
                    sum += h * wi * (ft - fy) / (y - t);
                }
            }
        }
        sum + fy * ((1.0 + y) / (1.0 - y)).abs().ln()
    }

    #[test]
    fn end_cauchy_matches_quadrature() {
        for w in [
            Weight::One,
            Weight::Right(-0.37),
            Weight::Left(0.37),
            Weight::Right(0.2),
            Weight::Right(-0.8),
            Weight::Left(-0.5),
            // small exponents (end_cauchy_small): the general formula was off by eps / e
            Weight::Left(1e-6),
            Weight::Right(-1e-6),
            Weight::Right(3e-4),
            Weight::Left(-0.0999),
            Weight::Right(0.0999),
            // log weights: the series form of log_cauchy, and the difference quotient
            Weight::LeftLog(1e-7),
            Weight::RightLog(1e-4),
            Weight::LeftLog(0.03),
            Weight::RightLog(0.3),
        ] {
            let fam = WeightedFamily::new(w, 12);
            let mut out = vec![0.0; 12];
            for y in [
                -1.6, -1.2, -1.05, -0.999, -0.7, -0.2, 0.01, 0.5, 0.9, 0.9999, 1.02, 1.3, 3.0,
            ] {
                fam.cauchy(y, &mut out);
                for k in [0usize, 1, 2, 5, 11] {
                    let r = reference(w, k, y);
                    let scale = 1.0 + r.abs();
                    assert!(
                        (out[k] - r).abs() < 2e-12 * scale,
                        "{w:?} y {y} k {k}: {} vs {r}",
                        out[k]
                    );
                }
            }
        }
    }

    /// Far-field bands at the highest order used (degrees < 26), both signs of y.
    #[test]
    fn far_field_at_high_degree() {
        for w in [
            Weight::Right(-0.45),
            Weight::Left(0.55),
            Weight::One,
            // log weights: their product rules
            Weight::LeftLog(1e-7),
            Weight::RightLog(1e-3),
            Weight::LeftLog(0.3),
        ] {
            let fam = WeightedFamily::new(w, 26);
            let mut out = vec![0.0; 26];
            for y in [1.12, -1.45, 1.6, 4.5, -13.0, 45.0, 200.0] {
                fam.cauchy(y, &mut out);
                for k in [0usize, 7, 15, 25] {
                    let r = reference(w, k, y);
                    assert!(
                        (out[k] - r).abs() < 2e-12 * (1.0 + r.abs()),
                        "{w:?} y {y} k {k}: {} vs {r}",
                        out[k]
                    );
                }
            }
        }
    }

    /// cauchy_pair equals the two transforms summed (far and near y, mirrored farther).
    #[test]
    fn pair_is_the_sum() {
        let fam = WeightedFamily::new(Weight::Left(0.3), 13);
        let (mut out, mut buf, mut a, mut b) =
            (vec![0.0; 13], vec![0.0; 13], vec![0.0; 13], vec![0.0; 13]);
        for (y, y2) in [(0.4, -3.0), (1.3, -2.2), (5.0, -200.0), (-45.0, -46.0)] {
            fam.cauchy_pair(y, y2, -1.0, &mut out, &mut buf);
            fam.cauchy(y, &mut a);
            fam.cauchy(y2, &mut b);
            for k in 0..13 {
                assert!(
                    (out[k] - (a[k] - b[k])).abs() < 1e-14 * (1.0 + a[k].abs()),
                    "y {y} k {k}"
                );
            }
        }
    }

    /// Independent reference for complex zeta: int_{-1}^{1} w(t) P_k(t) / (zeta - t)^power dt
    /// by composite Gauss rules in s = t - xi (xi = Re zeta, so that zeta - t = (zeta - xi) - s
    /// and the panels tile exactly next to the point) graded towards s = 0 (panels at most
    /// their distance from zeta wide), with Gauss-Jacobi panels at the weighted ends.
    fn reference_complex(w: Weight, k: usize, zeta: C64, power: i32) -> C64 {
        let pk = |t: f64| {
            let mut v = vec![0.0; k + 1];
            legendre(t, &mut v);
            v[k]
        };
        let (xi, eta) = (zeta.re.clamp(-1.0, 1.0), zeta.im.abs().max(1e-300));
        let (lo, hi) = (-1.0 - xi, 1.0 - xi);
        let mut breaks = vec![lo, hi];
        for j in 0..60 {
            let d = 0.5f64.powi(j);
            breaks.extend([lo + d, hi - d]);
            let r = eta * 2f64.powi(j);
            breaks.extend([-r, r]);
        }
        breaks.retain(|b| (lo..=hi).contains(b));
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let (a, b) = w.exponents();
        let (gl, gw) = crate::numerics::quadrature::gauss_legendre(40);
        let to_point = zeta - xi;
        let mut sum = C64::new(0.0, 0.0);
        for p in breaks.windows(2) {
            let (m, h) = (0.5 * (p[0] + p[1]), 0.5 * (p[1] - p[0]));
            let ea = if p[1] == hi { a } else { 0.0 };
            let eb = if p[0] == lo { b } else { 0.0 };
            let (xs, ws) = if ea != 0.0 || eb != 0.0 {
                gauss_jacobi(40, ea, eb)
            } else {
                (gl.clone(), gw.clone())
            };
            for (x, wi) in xs.iter().zip(&ws) {
                let s = m + h * x;
                // the weight: exact on an end panel (the rule carries it), else sampled
                let wt = if ea != 0.0 || eb != 0.0 {
                    h.powf(ea + eb)
                } else {
                    w.at((hi - p[1]) + h * (1.0 - x), (p[0] - lo) + h * (1.0 + x))
                };
                sum += (to_point - s).powi(-power) * (h * wi * wt * pk(xi + s));
            }
        }
        sum
    }

    /// The local point of zeta, the signs of zero imaginary parts kept (1 + (-0.0) would
    /// round to +0.0).
    fn local(zeta: C64) -> Local {
        Local {
            zeta,
            omz: C64::new(1.0 - zeta.re, -zeta.im),
            opz: C64::new(1.0 + zeta.re, zeta.im),
        }
    }

    /// The complex closed forms plus recurrence against the graded quadrature, at points of
    /// the near field down to 1e-7 from the segment, above and below it, and their
    /// derivatives.
    #[test]
    fn complex_transforms_match_quadrature() {
        let n = 20;
        for w in [
            Weight::One,
            Weight::Right(-0.37),
            Weight::Left(0.37),
            Weight::Right(0.5),
            Weight::Left(-0.45),
            Weight::Right(-0.05),
        ] {
            let m = w.moments(n);
            let (mut out, mut d) = (vec![C64::new(0.0, 0.0); n], vec![C64::new(0.0, 0.0); n]);
            for zeta in [
                C64::new(0.3, -1e-7),
                C64::new(-0.999, -1e-5),
                C64::new(0.9999, -2e-6),
                C64::new(1.0 + 1e-6, -1e-6),
                C64::new(-1.02, -0.01),
                C64::new(0.0, -0.4),
                C64::new(0.5, 0.3),
                C64::new(1.05, 0.05),
                C64::new(-0.6, -0.2),
            ] {
                near_transforms(w, &m, local(zeta), &mut out, Some(&mut d));
                for k in [0usize, 1, 2, 7, 13, 19] {
                    let r = reference_complex(w, k, zeta, 1);
                    let err = (out[k] - r).norm();
                    assert!(
                        err < 2e-12 * (1.0 + r.norm()),
                        "{w:?} {zeta} k {k}: {} vs {r}",
                        out[k]
                    );
                    let rd = -reference_complex(w, k, zeta, 2);
                    let err = (d[k] - rd).norm();
                    // the derivative recurrence amplifies by about k rho^k (2e-11 at k = 19)
                    assert!(
                        err < 5e-11 * (1.0 + rd.norm()) * (1.0 + 1.0 / zeta.im.abs()),
                        "{w:?} {zeta} k {k}: slope {} vs {rd}",
                        d[k]
                    );
                }
            }
        }
    }

    /// On the segment with a -0.0 imaginary part the complex transform is the limit from
    /// below: the real principal value (the closed form above) plus i pi w(y) P_k(y); off the
    /// segment on the real line it is the real transform.
    #[test]
    fn complex_transforms_on_the_axis() {
        let n = 16;
        for w in [Weight::One, Weight::Right(-0.3), Weight::Left(0.6)] {
            let fam = WeightedFamily::new(w, n);
            let (mut real, mut leg) = (vec![0.0; n], vec![0.0; n]);
            let mut out = vec![C64::new(0.0, 0.0); n];
            for y in [-1.08, -0.999, -0.4, 0.0, 0.3, 0.99999, 1.001, 1.07] {
                let zeta = C64::new(y, -0.0);
                near_transforms(w, &fam.moments, local(zeta), &mut out, None);
                fam.cauchy(y, &mut real);
                legendre(y, &mut leg);
                let weight = if y.abs() < 1.0 {
                    w.at(1.0 - y, 1.0 + y)
                } else {
                    0.0
                };
                for k in 0..n {
                    let im = PI * weight * leg[k];
                    let scale = 1.0 + real[k].abs() + im.abs();
                    assert!(
                        (out[k].re - real[k]).abs() < 2e-12 * scale,
                        "{w:?} y {y} k {k}: {} vs {}",
                        out[k],
                        real[k]
                    );
                    assert!((out[k].im - im).abs() < 2e-12 * scale, "{w:?} y {y} k {k}");
                }
            }
        }
    }
}
