//! The compatibility condition (docs/theory.md (X3), (S2)) for Spence's pressure
//! p_S = (1 - x^2)^(-g) / B(1/2, 1 - g), with h = 1/2 - g = atan(bp mu) / pi, m = c^2:
//!   int_0^c (1 - x^2)^(-g) / sqrt(c^2 - x^2) dx = (pi/2) 2F1(g, 1/2; 1; m)        (x = c sqrt(v)),
//!   int_c^1 (1 - t^2)^(-g) / sqrt(t^2 - c^2) dt
//!       = (1/2) B(1/2 + h, 1/2) (1 - m)^h 2F1(1/2, 1/2 + h; 1 + h; 1 - m)       (t^2 = 1 - (1 - m) v),
//! so bq (left) = mu (right) reads
//!   Phi(s) = ln(bq pi 2F1(g, 1/2; 1; m)) - ln(mu B(1/2 + h, 1/2) (1 - m)^h 2F1(...; 1 - m)) = 0.
//! Phi increases strictly with m (the left side grows, the right side shrinks), so the root is
//! unique. It is sought in s = ln(m / (1 - m)), which keeps both c and 1 - c to full relative
//! accuracy from c ~ 1e-300 to 1 - c ~ 1e-300, by Newton's method with the slope dPhi/ds from
//! the same series as Phi, started from the small-c limit of Phi and kept inside the bracket
//! it builds (Brent's method on that bracket should Newton leave it).

use std::f64::consts::PI;

use crate::error::{Error, Result};
use crate::numerics::roots::brent;
use crate::numerics::special::Hyp2f1;

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

/// |s| beyond which the root is not sought (below -S_MAX, c = 0 in floating point).
const S_MAX: f64 = 1.0e7;

/// Newton steps before Brent's method takes over.
const NEWTON_STEPS: usize = 50;

/// Phi at one s, with its slope dPhi/ds and a bound on its rounding error.
#[derive(Clone, Copy, Debug)]
pub(super) struct Value {
    pub phi: f64,
    pub slope: f64,
    pub err: f64,
}

/// The compatibility function Phi of one coupling, in the variable s.
#[derive(Clone, Debug)]
pub(super) struct Compatibility {
    h: f64,
    /// ln(bq pi / (mu B(1/2 + h, 1/2))).
    ln_ratio: f64,
    /// 2F1(1/2 - h, 1/2; 1; .) and 2F1(1/2, 1/2 + h; 1 + h; .).
    left: Hyp2f1,
    right: Hyp2f1,
}

impl Compatibility {
    /// For bq > 0, mu > 0 and 0 <= h < 1/2, given ln B(1/2 + h, 1/2).
    pub fn new(bq: f64, mu: f64, h: f64, ln_beta: f64) -> Self {
        Self {
            h,
            ln_ratio: (bq * PI).ln() - mu.ln() - ln_beta,
            left: Hyp2f1::new(0.5 - h, 0.5, h),
            right: Hyp2f1::new(0.5, 0.5 + h, 0.0),
        }
    }

    /// The two hypergeometric factors 2F1(1/2 - h, 1/2; 1; m) and 2F1(1/2, 1/2 + h; 1 + h; 1 - m),
    /// each with its derivative in the logit of its own argument (ln(m/(1-m)) = s, resp. -s).
    pub fn factors(&self, v: &Split) -> ((f64, f64), (f64, f64)) {
        let left = self.left.eval(v.m, v.m1, v.ln_m1);
        let right = self.right.eval(v.m1, v.m, v.ln_m);
        (left, right)
    }

    /// Phi(s), dPhi/ds = (dL/ds) / L + (dR/d(-s)) / R + h m, and a bound on Phi's rounding
    /// error (a few ulps of each logarithm summed).
    pub fn eval(&self, s: f64) -> Value {
        let v = Split::new(s);
        let ((left, dleft), (right, dright)) = self.factors(&v);
        let parts = [self.ln_ratio, left.ln(), -right.ln(), -self.h * v.ln_m1];
        let phi: f64 = parts.iter().sum();
        // Each logarithm is of a quantity known to a few ulps (positive-term series), so
        // its absolute error is a few EPSILON; ln_ratio and h ln m1 also carry relative errors.
        let err = f64::EPSILON * (16.0 + 2.0 * parts.iter().map(|t| t.abs()).sum::<f64>());
        Value {
            phi,
            slope: dleft / left + dright / right + self.h * v.m,
            err,
        }
    }

    /// The small-c limit of the root: with L -> 1 and R = -P (D + ln m) + O(m ln m) (the
    /// logarithmic case of 2F1 at 1), Phi = 0 gives ln m = -D - exp(ln_ratio) / P.
    fn guess(&self) -> f64 {
        let (p, d) = self.right.log_limit();
        -d - self.ln_ratio.exp() / p
    }

    /// The root s* of Phi with an estimate of its error |s - s*|. Newton's iterates stop where
    /// |Phi| is within its rounding error or the step is below 2 ulps of s, after taking that
    /// last step.
    pub fn root(&self) -> Result<(f64, f64)> {
        let mut s = self.guess().clamp(-S_MAX, S_MAX);
        // The bracket found so far: (s, Phi(s)) with Phi < 0 and with Phi > 0.
        let (mut lo, mut hi) = (None, None);
        for _ in 0..NEWTON_STEPS {
            let v = self.eval(s);
            if !v.phi.is_finite() || v.slope.is_nan() {
                return Err(Error::NoConvergence(format!(
                    "Spence compatibility function not finite at s = ln(c^2/(1-c^2)) = {s}"
                )));
            }
            let step = v.phi / v.slope;
            if v.phi.abs() <= v.err || step.abs() <= 2.0 * f64::EPSILON * s.abs() {
                // the last step too: the estimate from its start also bounds its end
                return Ok((s - step, Self::error_of(s, &v)));
            }
            if v.phi < 0.0 {
                lo = Some((s, v.phi));
            } else {
                hi = Some((s, v.phi));
            }
            let next = (s - step).clamp(-S_MAX, S_MAX);
            let inside = lo.is_none_or(|l: (f64, f64)| next > l.0)
                && hi.is_none_or(|h: (f64, f64)| next < h.0);
            if !inside || next == s {
                break;
            }
            s = next;
        }
        match (lo, hi) {
            // Phi > 0 already at s = -S_MAX (tiny friction): the root lies below it, where
            // c^2 < exp(-1e7) rounds to 0 as it does at s = -S_MAX itself.
            (None, Some((s, _))) if s == -S_MAX => Ok((s, 0.0)),
            (Some(a), Some(b)) => {
                let s = brent(|s| Ok(self.eval(s).phi), a, b, 1e-300, 300)?;
                Ok((s, Self::error_of(s, &self.eval(s))))
            }
            _ => Err(Error::NoConvergence(format!(
                "Spence compatibility condition not bracketed for |ln(c^2/(1-c^2))| <= {S_MAX:e}"
            ))),
        }
    }

    /// Error estimate of a root s: rounding error and residual of Phi over its slope, plus
    /// two ulps of s.
    fn error_of(s: f64, v: &Value) -> f64 {
        (v.err + v.phi.abs()) / v.slope.abs() + 2.0 * f64::EPSILON * s.abs()
    }
}
