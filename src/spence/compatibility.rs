//! The compatibility condition (THEORY.md section 5) for Spence's pressure
//! p_S = (1 - x^2)^(-g) / B(1/2, 1 - g), with h = 1/2 - g = atan(bp mu) / pi, m = c^2:
//!   int_0^c (1 - x^2)^(-g) / sqrt(c^2 - x^2) dx = (pi/2) 2F1(g, 1/2; 1; m)        (x = c sqrt(v)),
//!   int_c^1 (1 - t^2)^(-g) / sqrt(t^2 - c^2) dt
//!       = (1/2) B(1/2 + h, 1/2) (1 - m)^h 2F1(1/2, 1/2 + h; 1 + h; 1 - m)       (t^2 = 1 - (1 - m) v),
//! so bq (left) = mu (right) reads
//!   Phi(s) = ln(bq pi 2F1(g, 1/2; 1; m)) - ln(mu B(1/2 + h, 1/2) (1 - m)^h 2F1(...; 1 - m)) = 0.
//! Phi increases strictly with m (the left side grows, the right side shrinks), so the root is
//! unique. It is sought in s = ln(m / (1 - m)), which keeps both c and 1 - c to full relative
//! accuracy from c ~ 1e-300 to 1 - c ~ 1e-300.

use std::f64::consts::PI;

use crate::error::{Error, Result};
use crate::numerics::roots::brent;
use crate::numerics::special::{hyp2f1, ln_gamma};

/// m = c^2 and 1 - m with their logarithms, all to full relative accuracy, from s = ln(m/(1-m)).
#[derive(Clone, Copy, Debug)]
pub(super) struct Split {
    pub m: f64,
    pub m1: f64,
    pub ln_m: f64,
    pub ln_m1: f64,
}

impl Split {
    pub fn new(s: f64) -> Self {
        let e = (-s.abs()).exp();
        let l = e.ln_1p();
        let (small, big) = (e / (1.0 + e), 1.0 / (1.0 + e));
        if s <= 0.0 {
            Split {
                m: small,
                m1: big,
                ln_m: s - l,
                ln_m1: -l,
            }
        } else {
            Split {
                m: big,
                m1: small,
                ln_m: -l,
                ln_m1: -s - l,
            }
        }
    }
}

/// The compatibility function Phi of one coupling, in the variable s.
#[derive(Clone, Copy, Debug)]
pub(super) struct Compatibility {
    h: f64,
    /// ln(bq pi / (mu B(1/2 + h, 1/2))).
    ln_ratio: f64,
}

impl Compatibility {
    /// For bq > 0, mu > 0 and 0 <= h < 1/2.
    pub fn new(bq: f64, mu: f64, h: f64) -> Self {
        let ln_beta = ln_gamma(0.5 + h) + 0.5 * PI.ln() - ln_gamma(1.0 + h);
        Self {
            h,
            ln_ratio: (bq * PI).ln() - mu.ln() - ln_beta,
        }
    }

    /// The two hypergeometric factors 2F1(1/2 - h, 1/2; 1; m) and 2F1(1/2, 1/2 + h; 1 + h; 1 - m).
    pub fn factors(&self, v: &Split) -> (f64, f64) {
        let h = self.h;
        let left = hyp2f1(0.5 - h, 0.5, h, v.m, v.m1, v.ln_m1);
        let right = hyp2f1(0.5, 0.5 + h, 0.0, v.m1, v.m, v.ln_m);
        (left, right)
    }

    /// Phi(s) and a bound on its rounding error (a few ulps of each logarithm summed).
    pub fn eval(&self, s: f64) -> (f64, f64) {
        let v = Split::new(s);
        let (left, right) = self.factors(&v);
        let parts = [self.ln_ratio, left.ln(), -right.ln(), -self.h * v.ln_m1];
        let phi: f64 = parts.iter().sum();
        // Each logarithm is of a quantity known to a few ulps (positive-term series), so
        // its absolute error is a few EPSILON; ln_ratio and h ln m1 also carry relative errors.
        let err = f64::EPSILON * (16.0 + 2.0 * parts.iter().map(|t| t.abs()).sum::<f64>());
        (phi, err)
    }

    /// The root s* of Phi with an estimate of its error |s - s*|: an outward doubling search
    /// for a sign change from s = 0, then Brent's method to adjacent floating-point numbers.
    pub fn root(&self) -> Result<(f64, f64)> {
        const S_MAX: f64 = 1.0e7;
        let phi = |s: f64| self.eval(s).0;
        let f0 = phi(0.0);
        if f0 == 0.0 {
            return Ok((0.0, self.error_at(0.0)));
        }
        let dir = if f0 > 0.0 { -1.0 } else { 1.0 };
        let (mut a, mut fa) = (0.0, f0);
        let mut step = 1.0;
        loop {
            let b = dir * step;
            let fb = phi(b);
            if !fb.is_finite() {
                return Err(Error::NoConvergence(format!(
                    "Spence compatibility function not finite at s = ln(c^2/(1-c^2)) = {b}"
                )));
            }
            if fb.signum() != fa.signum() {
                let s = brent(|s| Ok(phi(s)), (a, fa), (b, fb), 1e-300, 300)?;
                return Ok((s, self.error_at(s)));
            }
            (a, fa) = (b, fb);
            step *= 2.0;
            if step > S_MAX {
                return Err(Error::NoConvergence(format!(
                    "Spence compatibility condition not bracketed for |ln(c^2/(1-c^2))| <= {S_MAX:e}"
                )));
            }
        }
    }

    /// Error estimate of the root s: rounding error of Phi over its slope, plus one ulp of s.
    fn error_at(&self, s: f64) -> f64 {
        let (f, err) = self.eval(s);
        let ds = 1e-6 * s.abs().max(1.0);
        let slope = (self.eval(s + ds).0 - self.eval(s - ds).0) / (2.0 * ds);
        (err + f.abs()) / slope.abs() + 2.0 * f64::EPSILON * s.abs()
    }
}
