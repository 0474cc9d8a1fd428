//! The stress field of the orthotropic half-plane y < 0 under the contact tractions, the
//! punch-edge intensity and the slip: what engineers compute from the contact (issue 10).
//! Built once per solution from the method's [`Expansion`] of its own tractions, so it serves
//! every method alike.
//!
//! # Field solution (Lekhnistskii)
//! With the characteristic roots mu_k = i beta_k (docs/theory.md (M6): beta1 beta2 = delta^2,
//! beta1 + beta2 = delta sqrt(2 (1 + kappa)), Re beta_k > 0), the stresses are
//! sxx = 2 Re sum mu_k^2 F_k(z_k), syy = 2 Re sum F_k(z_k), sxy = -2 Re sum mu_k F_k(z_k) with
//! z_k = x + mu_k y in the lower half-plane. Writing F_k = (i/2) (a_k G_p + b_k G_q) with the
//! Cauchy transforms G_f(z) = (1/pi) int f(t) / (z - t) dt (analytic for y < 0; at the surface
//! G_f(x - i0) = H[f](x) + i f(x)), the surface conditions syy = -p, sxy = q fix
//! a_1 + a_2 = 1, mu_1 a_1 + mu_2 a_2 = 0, b_1 + b_2 = 0, mu_1 b_1 + mu_2 b_2 = 1. In terms of
//! h_f(beta) = G_f(x + i beta y), their means m_f = (h_f(beta1) + h_f(beta2)) / 2 and divided
//! differences d_f = (h_f(beta1) - h_f(beta2)) / (beta1 - beta2), with b = (beta1 + beta2) / 2:
//!   syy = -Im[m_p - b d_p - i d_q],
//!   sxy = -Re[delta^2 d_p + i (m_q + b d_q)],
//!   sxx = -Im[delta^2 (m_p + b d_p) + i (delta^2 kappa d_q + 2 b m_q)]
//! (in units of P/a, x and y in units of a). Nothing divides by beta1 - beta2: at the double
//! root (kappa = 1, and within [`DOUBLE_ROOT`] of it) m_f = h_f(b) and d_f = h_f'(b) =
//! i y G_f'(x + i b y) (the error of that limit, ~(kappa - 1) h'', balances the rounding of
//! the divided difference, ~eps h / (beta1 - beta2), near |kappa - 1| ~ 1e-10). Isotropic
//! (delta = kappa = 1) these are Flamant's kernels integrated over p and q.
//!
//! # The surface and the edge
//! At y = 0, d_f = 0 and m_f = H[f] + i f: syy = -p, sxy = q and
//!   sxx(x, 0) = -delta^2 p(x) - delta sqrt(2 (1 + kappa)) H[q](x).
//! Near the punch edge p ~ k (1 - x)^(-g) and q ~ mu p (slip), and H[(1 - t)^(-g)] ~
//! cot(pi g) (1 - x)^(-g), so sxx(x, 0) ~ -k [delta^2 + delta sqrt(2 (1 + kappa)) mu cot(pi g)]
//! (1 - x)^(-g): the same exponent g as p, amplitude -k (delta^2 + (1 - nu) mu^2) when
//! cot(pi g) = bp mu (SPENCE, COUPLED, LCP: g = 1/2 - arctan(bp mu) / pi, and
//! delta sqrt(2 (1 + kappa)) bp = 1 - nu), -k delta^2 for GOODMAN (g = 1/2).
//!
//! # Slip
//! The tangential surface displacement relative to the punch, per P/E (docs/theory.md (U1), (F4),
//! pi B E = sqrt(2 (1 + kappa)) / delta, pi B E bq = A E = 1 - nu):
//!   u(x) = -(1 - nu) int_c^x p dt - (sqrt(2 (1 + kappa)) / delta) int_c^x H[q] dt, x > c,
//! 0 on the stick zone, odd ([`slip`]).

mod expansion;
mod kernel;
mod slip;

pub(crate) use expansion::{
    Expand, Expansion, Exponents, Family, Panel, fit, fitted_panel, graded, graded_plain,
    grid_expansion, sample,
};

use crate::material::Effective;
use crate::numerics::cauchy::C64;
use kernel::{Kernel, Point};

/// |kappa - 1| up to which the roots are taken as the double root.
const DOUBLE_ROOT: f64 = 1e-10;

/// The characteristic roots as the stress formulas use them.
#[derive(Clone, Copy, Debug)]
struct Roots {
    /// b = (beta1 + beta2) / 2 = delta sqrt((1 + kappa) / 2) > 0.
    mean: f64,
    /// (beta1 - beta2) / 2: delta sqrt((kappa - 1) / 2) (imaginary for kappa < 1); None at
    /// the double root.
    half: Option<C64>,
    /// delta^2 = beta1 beta2.
    product: f64,
    /// delta^2 kappa = (beta1^2 + beta2^2) / 2.
    square_mean: f64,
    /// The points' largest depth per unit of depth, max Re beta_k: mean + (beta1 - beta2) / 2
    /// for real roots, mean for complex ones.
    deepest: f64,
}

impl Roots {
    fn new(k: &Effective) -> Self {
        let d = k.delta;
        let diff = k.kappa - 1.0;
        let half = (diff.abs() > DOUBLE_ROOT).then(|| {
            let r = d * (0.5 * diff.abs()).sqrt();
            if diff > 0.0 {
                C64::new(r, 0.0)
            } else {
                C64::new(0.0, r)
            }
        });
        let mean = d * (0.5 * (1.0 + k.kappa)).sqrt();
        Roots {
            mean,
            half,
            product: d * d,
            square_mean: d * d * k.kappa,
            deepest: mean + half.map_or(0.0, |h| h.re),
        }
    }
}

/// Depth of the point standing in for the surface (y = 0) in [`Field::stresses`]: far
/// below every panel's resolution, so that its transforms are the limits from inside.
const SURFACE_DEPTH: f64 = 1e-300;

/// Depth of the points x + i beta_k y, the largest of Re(beta_k) |y|, below which
/// [`Field::stresses`] gives the surface limit: there the derivative terms y d_f(z),
/// d_f ~ 1 / y^2 next to the surface's singular points, are no longer representable
/// (y^2 underflows), while the stresses differ from their surface limits by
/// O(Re(beta) |y| / l) for the smallest panel scale l (1e-21 and up), far below rounding.
/// The points' depth, not y: with delta = 1e-300 the roots are about 1e-300 and the points
/// of y = -1e-3 lay 1e-303 below the axis, where the transforms gave NaN (hostile draws of
/// seeds 7 and 11); at delta = 1e-100 the stresses at y = -0.5 equal their surface limits
/// to every digit.
const SURFACE_LIMIT_ABOVE: f64 = 1e-150;

/// |beta1 - beta2| / 2 below which the divided differences' 1 / (beta1 - beta2) is formed
/// from the modulus: C64::inv squares it, which underflows below 1e-154 (delta = 1e-200:
/// NaN at every depth).
const TINY_HALF: f64 = 1e-150;

/// The field of one solution (built lazily by [`crate::Solution`], shared by its threads).
#[derive(Clone, Debug)]
pub(crate) struct Field {
    roots: Roots,
    kernel: Kernel,
    expansion: Expansion,
    /// (k, g) of the expansion.
    edge: (f64, f64),
    slip: slip::Slip,
}

impl Field {
    /// The field of the tractions `e` on the material `k`, with stick half-width c and the
    /// punch-edge singularity `edge` ([`Expand::edge_intensity`]; None: (0, 0)).
    pub(crate) fn new(e: Expansion, edge: Option<(f64, f64)>, k: &Effective, c: f64) -> Self {
        let kernel = Kernel::new(&e);
        let edge = edge.unwrap_or((0.0, 0.0));
        let mut field = Field {
            roots: Roots::new(k),
            kernel,
            expansion: e,
            edge,
            slip: slip::Slip::default(),
        };
        if !field.expansion.whole_line() {
            // (a whole-line state's slip depends on its load path, not on its tractions
            // alone: not built, and not offered by its solution)
            field.slip = slip::Slip::new(&field.kernel, k, c, |t| field.slope_terms(t));
        }
        field
    }

    /// (p(t), sxx(t, 0)) on the surface: the slip's slope is nu p + sxx / delta^2.
    fn slope_terms(&self, t: f64) -> (f64, f64) {
        (self.expansion.tractions(t).0, self.stresses(t, 0.0)[0])
    }

    /// (k, g) of p ~ k (1 - |x|)^(-g) at the punch edges.
    pub(crate) fn edge_intensity(&self) -> (f64, f64) {
        self.edge
    }

    /// The slip u(x) per P/E (see the module documentation).
    pub(crate) fn slip(&self, x: f64) -> f64 {
        self.slip.at(x, &self.kernel, |t| self.slope_terms(t))
    }

    /// (sxx, syy, sxy) per P/a at (x, y), y <= 0, both finite (y = 0: the limit from inside).
    pub(crate) fn stresses(&self, x: f64, y: f64) -> [f64; 3] {
        let r = &self.roots;
        let surface = y > -SURFACE_LIMIT_ABOVE || -y * r.deepest < SURFACE_LIMIT_ABOVE;
        if surface && x.abs() == 1.0 {
            // the punch edge itself, also at the depths that take the surface limit: p, |q|
            // and -sxx are infinite (q = 0 without friction); at y = -1e-300 the transforms
            // of the edge singularity, ~1e150, times delta^2 = 1e300 gave sxx = -inf with a
            // finite syy (hostile draw 761)
            let sxy = if self.expansion.whole_line() {
                // no symmetry: the sign of q in the end panel at this edge
                let (_, q) = self.expansion.tractions(0.999 * x);
                crate::problem::edge_infinity(q)
            } else {
                let (_, q) = self.expansion.tractions(0.5);
                if q == 0.0 {
                    0.0
                } else {
                    f64::INFINITY.copysign(x)
                }
            };
            return [f64::NEG_INFINITY, f64::NEG_INFINITY, sxy];
        }
        let zero = C64::new(0.0, 0.0);
        let (mp, mq, dp, dq) = if surface {
            // the limit from inside, also for depths below SURFACE_LIMIT_ABOVE (y = -4.9e-324
            // and -1e-300 gave NaN through the derivative terms y d_f): both points at x - i0,
            // d_f = 0, as a point SURFACE_DEPTH
            // below the axis, so that every panel sees it on the same side (at x - i0
            // exactly at a panel end, the end's own substitute point and the other panels'
            // signed zeros disagreed: sxx at the end of the carbon ply's punch-edge panel,
            // mu = 0.3, came out -1.448 instead of -1.126)
            let [t] = self.kernel.transforms(
                [Point {
                    x,
                    w: C64::new(0.0, -SURFACE_DEPTH),
                }],
                false,
            );
            (t.p, t.q, zero, zero)
        } else if let Some(half) = r.half {
            // x + i beta y, the offset apart (see [`Point`])
            let point = |beta: C64| Point {
                x,
                w: C64::new(-(beta.im * y), beta.re * y),
            };
            let mean = C64::new(r.mean, 0.0);
            let [t1, t2] = self
                .kernel
                .transforms([point(mean + half), point(mean - half)], false);
            let size = half.norm();
            let inv = if size > TINY_HALF {
                (half * 2.0).inv()
            } else {
                half.conj().unscale(size).unscale(2.0 * size)
            };
            (
                (t1.p + t2.p) * 0.5,
                (t1.q + t2.q) * 0.5,
                (t1.p - t2.p) * inv,
                (t1.q - t2.q) * inv,
            )
        } else {
            let point = Point {
                x,
                w: C64::new(0.0, r.mean * y),
            };
            let [t] = self.kernel.transforms([point], true);
            let iy = C64::new(0.0, y);
            (t.p, t.q, iy * t.dp, iy * t.dq)
        };
        let i = C64::new(0.0, 1.0);
        let b = r.mean;
        let syy = -(mp - dp * b - i * dq).im;
        let sxy = -(dp * r.product + i * (mq + dq * b)).re;
        let sxx = -((mp + dp * b) * r.product + i * (dq * r.square_mean + mq * (2.0 * b))).im;
        [sxx, syy, sxy]
    }
}
