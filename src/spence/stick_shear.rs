//! Spence's shear traction on the stick zone |x| < c: the inversion of (E2) bounded at
//! x = +-c, with q = mu p on the slip zones, for p = N (1 - x^2)^(-g), N = 1 / B(1/2, 1 - g),
//! evaluated in closed form up to one Stieltjes transform. With m = c^2, m1 = 1 - c^2,
//! y = x^2, and the Stieltjes form
//! (1 - t^2)^(-g) = (sin(pi g)/pi) int_1^inf (u - 1)^(-g) / (u - t^2) du, both integrals of
//! the inversion formula reduce to elementary ones plus one in u, giving for 0 <= x < c
//!   q(x) = (2/pi) mu p(x) atan(x sqrt(m1) / sqrt(m - y))
//!        + (N sin(pi g) / pi) x sqrt(m - y) S(1 - y),
//!   S(eta) = int_0^inf rho^(-g) G(rho) / (rho + eta) d rho,
//!   G(rho) = [-bq + (2 mu/pi) artanh(sqrt(u m1 / (u - m)))] / sqrt(u (u - m)),  u = 1 + rho.
//! The first term carries the sqrt(c - x) behaviour at x = c (where q = mu p) and the scale
//! 1 - c; S is analytic off eta <= 0, hence analytic in ln(eta) in the strip |Im| < pi.
//! S is therefore computed at solve time by the trapezoidal rule in r = ln(rho) (error
//! ~exp(-2 pi d / h) for strip half-width d) and stored as piecewise Chebyshev series in
//! ln(eta) on panels of width <= 2 (Bernstein ellipse radius >= 6.4).

use std::f64::consts::PI;

use crate::numerics::orthopoly::{chebyshev_fit, chebyshev_sum};

/// Trapezoidal step in r = ln(rho): exp(-2 pi 2.5 / h) ~ 3e-21.
const STEP: f64 = 1.0 / 3.0;
/// Chebyshev points per panel: 6.4^-22 ~ 1e-18.
const DEGREE: usize = 22;
/// Widest panel in ln(eta).
const PANEL_WIDTH: f64 = 2.0;
/// Below rho = RHO_CUT * eta_min the kernel 1/(rho + eta) is expanded in rho / eta.
const RHO_CUT: f64 = 1e-6;
/// Orders kept in that expansion: (1e-6)^3 ~ 1e-18.
const MOMENTS: usize = 3;

/// S(eta) on [eta_min, 1] as piecewise Chebyshev series in ln(eta).
#[derive(Clone, Debug)]
pub(super) struct StickShear {
    mu: f64,
    sqrt_m1: f64,
    /// N sin(pi g) / pi.
    scale: f64,
    /// Lower end of the ln(eta) range and the panel width.
    ell_lo: f64,
    width: f64,
    /// Chebyshev coefficients, DEGREE per panel.
    coef: Vec<[f64; DEGREE]>,
}

/// The trapezoidal nodes and weights of S in r = ln(rho), with the nodes below the cut
/// lumped into moments M_j = sum w_k rho_k^j.
struct Transform {
    rho: Vec<f64>,
    weight: Vec<f64>,
    moments: [f64; MOMENTS],
}

impl Transform {
    /// The integrand rho^(1-g) G(rho) of S in r, in logarithms (rho = e^r and 1 - c^2 may
    /// underflow): ln(u - m) = ln(m1 + rho), artanh(z) = ln(1 + z) - ln(1 - z^2)/2 with
    /// 1 - z^2 = m rho / (m1 + rho), never cancelling.
    fn new(bq: f64, mu: f64, g: f64, v: &super::compatibility::Split, eta_min: f64) -> Self {
        let integrand = |r: f64| {
            let ln_u = r.exp().ln_1p();
            let ln_um = v.ln_m1.max(r) + (-(v.ln_m1 - r).abs()).exp().ln_1p();
            let z = (0.5 * (ln_u + v.ln_m1 - ln_um)).exp();
            let artanh = z.ln_1p() - 0.5 * (v.ln_m + r - ln_um);
            ((1.0 - g) * r - 0.5 * (ln_u + ln_um)).exp() * (-bq + 2.0 * mu / PI * artanh)
        };
        // Tails: rho^(1-g) |ln rho| / eta below exp(ln(min(m1, eta)) - 85) (1 - g >= 1/2) and
        // rho^(-1-g) above exp(45) are below 1e-18 of S.
        let r_lo = v.ln_m1.min(eta_min.ln()) - 85.0;
        let r_hi = 45.0;
        let r_cut = (RHO_CUT * eta_min).ln();
        let n = ((r_hi - r_lo) / STEP).ceil() as usize;
        let mut t = Transform {
            rho: Vec::new(),
            weight: Vec::new(),
            moments: [0.0; MOMENTS],
        };
        for k in 0..=n {
            let r = r_hi - k as f64 * STEP;
            let w = STEP * integrand(r);
            if r < r_cut {
                let rho = r.exp();
                let mut rj = 1.0;
                for mj in t.moments.iter_mut() {
                    *mj += w * rj;
                    rj *= rho;
                }
            } else {
                t.rho.push(r.exp());
                t.weight.push(w);
            }
        }
        t
    }

    /// S(eta) for eta >= eta_min.
    fn eval(&self, eta: f64) -> f64 {
        let near: f64 = self
            .rho
            .iter()
            .zip(&self.weight)
            .map(|(r, w)| w / (r + eta))
            .sum();
        let mut far = 0.0;
        let mut inv = 1.0 / eta;
        for (j, mj) in self.moments.iter().enumerate() {
            far += if j % 2 == 0 { mj * inv } else { -mj * inv };
            inv /= eta;
        }
        near + far
    }
}

impl StickShear {
    /// For mu > 0 and c > 0 (split `v` of m = c^2), exponent g and normalisation N.
    pub fn new(bq: f64, mu: f64, g: f64, norm: f64, v: &super::compatibility::Split) -> Self {
        // Floating-point x < c < 1 has 1 - x^2 >= EPSILON, so ln(eta) >= ln(max(m1, EPSILON)).
        let eta_min = v.m1.max(f64::EPSILON);
        let ell_lo = eta_min.ln();
        let panels = ((-ell_lo / PANEL_WIDTH).ceil() as usize).max(1);
        // (m1 rounds to 1 for c < 1e-8: then every stick-zone ln(eta) is 0, a zero-width range.)
        let width = (-ell_lo / panels as f64).max(f64::MIN_POSITIVE);
        let transform = Transform::new(bq, mu, g, v, eta_min);
        let coef = (0..panels)
            .map(|i| {
                let a = ell_lo + i as f64 * width;
                chebyshev_fit(|ell| transform.eval(ell.exp()), a, a + width)
            })
            .collect();
        Self {
            mu,
            sqrt_m1: v.m1.sqrt(),
            scale: norm * (PI * g).sin() / PI,
            ell_lo,
            width,
            coef,
        }
    }

    /// q(x) for 0 <= x < c, given p(x), ln(1 - x^2) and c.
    pub fn q(&self, x: f64, p: f64, ell: f64, c: f64) -> f64 {
        let d = ((c - x) * (c + x)).sqrt();
        let t = (ell - self.ell_lo) / self.width;
        let i = (t.floor().max(0.0) as usize).min(self.coef.len() - 1);
        let local = (2.0 * (t - i as f64) - 1.0).clamp(-1.0, 1.0);
        let s = chebyshev_sum(&self.coef[i], local);
        2.0 / PI * self.mu * p * (x * self.sqrt_m1).atan2(d) + self.scale * x * d * s
    }
}
