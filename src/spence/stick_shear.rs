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
//! S is therefore computed at solve time by the trapezoidal rule in r = ln(rho), whose
//! integrand is analytic in |Im r| < pi (its singularities lie at ln m1 + i pi, ln eta + i pi
//! and i pi, all with real parts in the band [ln m1, 0]), with the double-exponential map
//! r = r_mid + SIGMA t + A sinh t (Takahasi and Mori 1974): steps SIGMA * STEP in r across the
//! band, and tails (integrand ~rho^(1-g) |ln rho| below it, ~rho^(-1-g) above) that decay
//! doubly exponentially in t. S is stored as piecewise Chebyshev series in ln(eta) on panels of
//! width <= 2, of the degree each panel's width needs.

use std::f64::consts::PI;

use crate::numerics::orthopoly::{chebyshev_fit, chebyshev_sum};

/// Trapezoidal step in t. Across the band dr/dt <= SIGMA (1 + KAPPA) < 2, so the integrand is
/// analytic in |Im t| < pi / 2 (the map's own limit) and the error is ~exp(-pi^2 / STEP) ~ 7e-18.
const STEP: f64 = 0.25;
/// Slope of the map across the band (the step in r there is SIGMA * STEP ~ 0.33).
const SIGMA: f64 = 1.3;
/// A = KAPPA SIGMA exp(-t_band): the sinh term reaches KAPPA / 2 of the slope at the band's
/// ends t = +-t_band.
const KAPPA: f64 = 0.3;
/// e^(j STEP), j < 96 (t up to 24: every node of a band narrower than 2 SIGMA (24 - 6) ~ 47).
static EXP_STEPS: std::sync::LazyLock<[f64; 96]> =
    std::sync::LazyLock::new(|| std::array::from_fn(|j| (j as f64 * STEP).exp()));
/// Chebyshev interpolation error aimed at: rho^-n on a Bernstein ellipse rho (6.44^-22 for
/// width 2, the strip |Im ln eta| < pi).
const CHEBYSHEV_TOL: f64 = 2e-18;
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
    /// Chebyshev coefficients, `degree` per panel.
    panels: usize,
    degree: usize,
    coef: Vec<f64>,
}

/// The trapezoidal nodes and weights of S in r = ln(rho), with the nodes below the cut
/// lumped into moments M_j = sum w_k rho_k^j.
struct Transform {
    rho: Vec<f64>,
    weight: Vec<f64>,
    moments: [f64; MOMENTS],
}

impl Transform {
    /// The integrand rho^(1-g) G(rho) of S in r, with rho. With x = m1 / rho (at most e^85 on
    /// the nodes; exp(ln m1 - r) where rho or 1 - c^2 underflows):
    /// u - m = m1 + rho = rho (1 + x), z^2 = u x / (1 + x), and
    /// artanh(z) = ln(1 + z) - ln(1 - z^2) / 2 with 1 - z^2 = m / (1 + x), so
    ///   rho^(1-g) G = rho^(1/2-g) [-bq + (2 mu / pi) (ln((1 + z) sqrt(1 + x)) - ln(m) / 2)]
    ///                 / sqrt(u (1 + x)).
    fn integrand(bq: f64, mu: f64, g: f64, v: &super::compatibility::Split, r: f64) -> (f64, f64) {
        let rho = r.exp();
        let x = if rho >= f64::MIN_POSITIVE && v.m1 >= f64::MIN_POSITIVE {
            v.m1 / rho
        } else {
            (v.ln_m1 - r).exp()
        };
        let u = 1.0 + rho;
        let z = (u * x / (1.0 + x)).sqrt();
        let artanh = ((1.0 + z) * (1.0 + x).sqrt()).ln() - 0.5 * v.ln_m;
        let scale = ((0.5 - g) * r).exp() / (u * (1.0 + x)).sqrt();
        (rho, scale * (-bq + 2.0 * mu / PI * artanh))
    }

    fn new(bq: f64, mu: f64, g: f64, v: &super::compatibility::Split, eta_min: f64) -> Self {
        // The band [ln m1, 0] holds every near singularity (eta >= eta_min >= m1).
        let band = -v.ln_m1.min(0.0);
        let r_mid = -0.5 * band;
        let t_band = 0.5 * band / SIGMA;
        // Tails: rho^(1-g) |ln rho| / eta below exp(ln(min(m1, eta)) - 85) (1 - g >= 1/2) and
        // rho^(-1-g) above exp(45) are below 1e-18 of S: nodes beyond are left out.
        let r_lo = v.ln_m1.min(eta_min.ln()) - 85.0;
        let r_hi = 45.0;
        let r_cut = (RHO_CUT * eta_min).ln();
        let nodes = (band / (SIGMA * STEP)) as usize + 64;
        let mut t = Transform {
            rho: Vec::with_capacity(nodes),
            weight: Vec::with_capacity(nodes),
            moments: [0.0; MOMENTS],
        };
        let half_a = 0.5 * KAPPA * SIGMA * (-t_band).exp();
        for j in 0.. {
            let tj = j as f64 * STEP;
            // A e^(+-t) / 2 = KAPPA SIGMA exp(+-t - t_band) / 2, from the table of e^t while it
            // lasts (and while exp(-t_band) does not underflow).
            let (up, down) = match EXP_STEPS.get(j) {
                Some(&e) if half_a > 0.0 => (half_a * e, half_a / e),
                _ => (
                    0.5 * KAPPA * SIGMA * (tj - t_band).exp(),
                    0.5 * KAPPA * SIGMA * (-tj - t_band).exp(),
                ),
            };
            let (offset, slope) = (SIGMA * tj + up - down, SIGMA + up + down);
            let sides: &[f64] = if j == 0 { &[1.0] } else { &[1.0, -1.0] };
            let mut inside = false;
            for sign in sides {
                let r = r_mid + sign * offset;
                if !(r_lo..=r_hi).contains(&r) {
                    continue;
                }
                inside = true;
                let (rho, f) = Self::integrand(bq, mu, g, v, r);
                let w = STEP * slope * f;
                if r < r_cut {
                    let mut rj = 1.0;
                    for mj in t.moments.iter_mut() {
                        *mj += w * rj;
                        rj *= rho;
                    }
                } else {
                    t.rho.push(rho);
                    t.weight.push(w);
                }
            }
            if !inside {
                break;
            }
        }
        t
    }

    /// S(eta) at each of `etas` (all >= eta_min), the nodes summed in the same order for each.
    fn eval(&self, etas: &[f64]) -> Vec<f64> {
        let mut near = vec![0.0; etas.len()];
        for (r, w) in self.rho.iter().zip(&self.weight) {
            for (s, eta) in near.iter_mut().zip(etas) {
                *s += w / (r + eta);
            }
        }
        near.iter()
            .zip(etas)
            .map(|(near, eta)| {
                let mut far = 0.0;
                let mut inv = 1.0 / eta;
                for (j, mj) in self.moments.iter().enumerate() {
                    far += if j % 2 == 0 { mj * inv } else { -mj * inv };
                    inv /= eta;
                }
                near + far
            })
            .collect()
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
        // Bernstein ellipse of the strip |Im ln eta| < pi about a panel of this width.
        let b = 2.0 * PI / width;
        let radius = b + (b * b + 1.0).sqrt();
        let degree = ((CHEBYSHEV_TOL.ln() / radius.ln()).abs().ceil() as usize).max(1);
        let transform = Transform::new(bq, mu, g, v, eta_min);
        let mut coef = Vec::with_capacity(panels * degree);
        for i in 0..panels {
            let a = ell_lo + i as f64 * width;
            coef.extend(chebyshev_fit(
                |ells| transform.eval(&ells.iter().map(|ell| ell.exp()).collect::<Vec<_>>()),
                a,
                a + width,
                degree,
            ));
        }
        Self {
            mu,
            sqrt_m1: v.m1.sqrt(),
            scale: norm * (PI * g).sin() / PI,
            ell_lo,
            width,
            panels,
            degree,
            coef,
        }
    }

    /// q(x) for 0 <= x < c, given p(x), ln(1 - x^2) and c.
    pub fn q(&self, x: f64, p: f64, ell: f64, c: f64) -> f64 {
        let d = ((c - x) * (c + x)).sqrt();
        let t = (ell - self.ell_lo) / self.width;
        let i = (t.floor().max(0.0) as usize).min(self.panels - 1);
        let local = (2.0 * (t - i as f64) - 1.0).clamp(-1.0, 1.0);
        let s = chebyshev_sum(&self.coef[i * self.degree..(i + 1) * self.degree], local);
        2.0 / PI * self.mu * p * (x * self.sqrt_m1).atan2(d) + self.scale * x * d * s
    }
}
