//! The slip: tangential surface displacement of the solid relative to the punch, per P/E
//! (THEORY.md section 3 with pi B E = sqrt(2 (1 + kappa)) / delta and pi B E bq = 1 - nu):
//!   u(x) = -(1 - nu) int_c^x p - (sqrt(2 (1 + kappa)) / (pi delta)) (L_q(x) - L_q(c))
//! for x > c, with L_q(x) = int q(s) ln|x - s| ds (so that (1/pi) dL_q/dx = H[q]); 0 on the
//! stick zone, odd in x. Beyond the punch (|x| > 1) it is the surface displacement relative to
//! the punch, p = 0 there. At mu = 0 (c = 0, q = 0, p = 1 / (pi sqrt(1 - x^2)) for GOODMAN)
//! it is -(1 - nu) arcsin(x) / pi.

use std::f64::consts::PI;

use super::kernel::Kernel;
use crate::material::Effective;

/// What the slip needs besides the kernel.
#[derive(Clone, Debug)]
pub(super) struct Slip {
    c: f64,
    /// 1 - nu.
    normal: f64,
    /// sqrt(2 (1 + kappa)) / (pi delta).
    shear: f64,
    /// int_c^1 p and L_q(c).
    p_from_c: f64,
    log_at_c: f64,
}

impl Slip {
    pub(super) fn new(kernel: &Kernel, k: &Effective, c: f64) -> Self {
        Slip {
            c,
            normal: 1.0 - k.nu,
            shear: (2.0 * (1.0 + k.kappa)).sqrt() / (PI * k.delta),
            p_from_c: kernel.p_from(c),
            log_at_c: kernel.log_potential_q(c),
        }
    }

    /// u(x) per P/E.
    pub(super) fn at(&self, x: f64, kernel: &Kernel) -> f64 {
        let ax = x.abs();
        if ax <= self.c {
            return 0.0;
        }
        let p = self.p_from_c - kernel.p_from(ax.min(1.0));
        let l = kernel.log_potential_q(ax) - self.log_at_c;
        let u = -(self.normal * p + self.shear * l);
        if x < 0.0 { -u } else { u }
    }
}
