//! The slip: tangential surface displacement of the solid relative to the punch, per P/E
//! (docs/theory.md (U1), (F4), with pi B E = sqrt(2 (1 + kappa)) / delta and pi B E bq = 1 - nu):
//!   u(x) = -(1 - nu) int_c^x p - (sqrt(2 (1 + kappa)) / (pi delta)) (L_q(x) - L_q(c))
//! for x > c, with L_q(x) = int q(s) ln|x - s| ds (so that (1/pi) dL_q/dx = H[q]); 0 on the
//! stick zone, odd in x. Beyond the punch (|x| > 1) it is the surface displacement relative to
//! the punch, p = 0 there. At mu = 0 (c = 0, q = 0, p = 1 / (pi sqrt(1 - x^2)) for GOODMAN)
//! it is -(1 - nu) arcsin(x) / pi.
//!
//! Next to the stick edge the difference L_q(x) - L_q(c) of two potentials keeps their
//! absolute rounding, which large coefficients make large, the more so at c itself, a panel end
//! (COUPLED's log weights split into their parts at large friction: an offset of 3e-7 of the
//! slip at b* = 0.7, mu~ = 1e4, turning its sign next to c). So the potentials are taken
//! relative to an anchor x0 = c + [`NEAR_EDGE`] (1 - c) instead, where the slip u(x0) is the
//! integral of its slope u'(x) = nu p(x) + sxx(x, 0) / delta^2 (from sxx(x, 0) =
//! -delta^2 p - delta sqrt(2 (1 + kappa)) H[q], the surface strain), by Gauss-Legendre on
//! panels graded geometrically towards c; between c and x0 the slip is that integral itself.

use std::f64::consts::PI;

use super::kernel::Kernel;
use crate::material::Effective;
use crate::numerics::quadrature::gauss_legendre;

/// The anchor x0 = c + NEAR_EDGE (1 - c) (points between c and x0 cost one integral).
const NEAR_EDGE: f64 = 1e-3;

/// Levels of the graded panels [c + d 2^-(j+1), c + d 2^-j] (j < LEVELS, d = x - c) and
/// Gauss-Legendre nodes per panel: each panel is its own width away from c, where the slope
/// has its (x - c)^g terms, so 10 nodes give about 1e-12 relative; the part nearer c than
/// d 2^-LEVELS (bounded slope) is left out, 1e-12 d.
const LEVELS: usize = 40;
const NODES: usize = 10;

/// What the slip needs besides the kernel.
#[derive(Clone, Debug, Default)]
pub(super) struct Slip {
    c: f64,
    /// nu.
    nu: f64,
    /// delta^2.
    delta2: f64,
    /// sqrt(2 (1 + kappa)) / (pi delta).
    shear: f64,
    /// The anchor x0, the slip there, int_x0^1 p and L_q(x0).
    x0: f64,
    u0: f64,
    p_from_x0: f64,
    log_at_x0: f64,
    /// Gauss-Legendre nodes and weights of each graded panel.
    rule: (Vec<f64>, Vec<f64>),
}

impl Slip {
    /// The slip of the tractions in `kernel` on material k with stick half-width c;
    /// `slope_terms(t)` gives (p(t), sxx(t, 0)) for c < t < 1.
    pub(super) fn new(
        kernel: &Kernel,
        k: &Effective,
        c: f64,
        slope_terms: impl Fn(f64) -> (f64, f64),
    ) -> Self {
        let x0 = (c + NEAR_EDGE * (1.0 - c)).min(1.0);
        let mut s = Slip {
            c,
            nu: k.nu,
            delta2: k.delta * k.delta,
            shear: (2.0 * (1.0 + k.kappa)).sqrt() / (PI * k.delta),
            x0,
            u0: 0.0,
            p_from_x0: kernel.p_from(x0),
            log_at_x0: kernel.log_potential_q(x0),
            rule: gauss_legendre(NODES),
        };
        s.u0 = s.integral_from_c(x0, slope_terms);
        s
    }

    /// int_c^x u'(t) dt for c <= x <= 1 on the graded panels.
    fn integral_from_c(&self, x: f64, slope_terms: impl Fn(f64) -> (f64, f64)) -> f64 {
        let d = x - self.c;
        if d <= 0.0 {
            return 0.0;
        }
        let (nodes, weights) = &self.rule;
        let mut u = 0.0;
        for j in 0..LEVELS {
            let (a, b) = (d * 0.5f64.powi(j as i32 + 1), d * 0.5f64.powi(j as i32));
            let (m, h) = (self.c + 0.5 * (a + b), 0.5 * (b - a));
            if h == 0.0 {
                // the panels' widths have underflowed (x within a subnormal distance of c):
                // nothing left to add, and the slope at c itself may be infinite (c = 0 at
                // small friction, where p ~ |x|^(-k0)): 0 * inf would be NaN
                break;
            }
            for (t, w) in nodes.iter().zip(weights) {
                let (p, sxx) = slope_terms(m + h * t);
                u += h * w * (self.nu * p + sxx / self.delta2);
            }
        }
        u
    }

    /// u(x) per P/E (`slope_terms` as for [`Slip::new`], used between c and the anchor).
    pub(super) fn at(
        &self,
        x: f64,
        kernel: &Kernel,
        slope_terms: impl Fn(f64) -> (f64, f64),
    ) -> f64 {
        let ax = x.abs();
        let u = if ax <= self.c {
            return 0.0;
        } else if ax < self.x0 {
            self.integral_from_c(ax, slope_terms)
        } else {
            let p = self.p_from_x0 - kernel.p_from(ax.min(1.0));
            let l = kernel.log_potential_q(ax) - self.log_at_x0;
            self.u0 - ((1.0 - self.nu) * p + self.shear * l)
        };
        if x < 0.0 { -u } else { u }
    }
}
