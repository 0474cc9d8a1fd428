//! Spence's approximation (docs/theory.md §8, (S1)-(S3)): the pressure keeps the slip-zone coupling only
//! through its edge exponent, p_S = (1 - x^2)^(-g) / B(1/2, 1 - g) with
//! g = 1/2 - atan(bp mu) / pi; the stick half-width c_S solves the compatibility condition
//! with p_S (hypergeometric functions, `compatibility`); q_S is the bounded solution of (E2)
//! on the stick zone (`stick_shear`) and q_S = mu p_S sgn x on the slip zones (E3).
//! At bp = 0 (g = 1/2) it is Goodman's approximation exactly.

mod compatibility;
mod stick_shear;
#[cfg(test)]
mod tests;

use std::f64::consts::PI;

use crate::error::Result;
use crate::field::{Expand, Expansion, Exponents, sample};
use crate::numerics::special::ln_gamma;
use crate::problem::{Coupling, Profile, StickEdge};
use compatibility::{Compatibility, Split};
use stick_shear::StickShear;

/// Spence's solution for one coupling.
#[derive(Clone, Debug)]
pub struct SpenceSolution {
    coupling: Coupling,
    /// Edge exponent g.
    g: f64,
    /// N = 1 / B(1/2, 1 - g).
    norm: f64,
    edge: StickEdge,
    error: f64,
    /// The stick-zone shear traction (None when the stick zone is empty, c = 0).
    stick: Option<StickShear>,
}

/// Solves Spence's approximation (the coupling must pass [`Coupling::validate`]); mu = 0 gives
/// c = 0, q = 0. The compatibility condition has exactly one root for mu > 0; below
/// ln(c^2 / (1 - c^2)) = -1e7 (friction below about 3e-7 b*) that root gives c = 0 in
/// floating point, and so does the solution (full slip). NoConvergence only reports a root
/// above ln(c^2 / (1 - c^2)) = 1e7.
pub fn solve(k: &Coupling) -> Result<SpenceSolution> {
    k.validate()?;
    let h = (k.bp * k.mu).atan() / PI;
    let g = 0.5 - h;
    // ln B(1/2 + h, 1/2) = -ln N
    let ln_beta = ln_gamma(0.5 + h) + 0.5 * PI.ln() - ln_gamma(1.0 + h);
    let norm = (-ln_beta).exp();
    let mut sol = SpenceSolution {
        coupling: *k,
        g,
        norm,
        edge: StickEdge::from_c(0.0),
        error: 0.0,
        stick: None,
    };
    if k.mu == 0.0 {
        return Ok(sol);
    }
    let (s, ds) = Compatibility::new(k.bq, k.mu, h, ln_beta).root()?;
    let v = Split::new(s);
    let c = (0.5 * v.ln_m).exp();
    sol.edge = StickEdge {
        c,
        one_minus_c: v.m1 / (1.0 + c),
    };
    // dc/ds = c (1 - c^2) / 2, plus the rounding of c itself.
    sol.error = c * (0.5 * v.m1 * ds + f64::EPSILON);
    if c > 0.0 {
        sol.stick = Some(StickShear::new(k.bq, k.mu, g, norm, &v));
    }
    Ok(sol)
}

impl SpenceSolution {
    /// The punch-edge exponent g of p_S ~ (1 - |x|)^(-g).
    pub fn edge_exponent(&self) -> f64 {
        self.g
    }
}

/// p_S has the punch-edge exponent g and is analytic across c; q_S - mu p_S ~ sqrt(c - x)
/// on the stick side ([`stick_shear`]'s arctangent and sqrt(m - y) terms).
impl Expand for SpenceSolution {
    fn expansion(&self) -> Expansion {
        sample(
            self,
            Exponents {
                edge: self.g,
                stick: 0.5,
            },
        )
    }
}

impl Profile for SpenceSolution {
    fn coupling(&self) -> Coupling {
        self.coupling
    }

    fn edge(&self) -> StickEdge {
        self.edge
    }

    fn numerical_error(&self) -> f64 {
        self.error
    }

    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        let ell = ((1.0 - x) * (1.0 + x)).ln();
        let p = self.norm * (-self.g * ell).exp();
        let q = match &self.stick {
            Some(stick) if x < self.edge.c => stick.q(x, p, ell, self.edge.c),
            _ => self.coupling.mu * p,
        };
        (p, q)
    }
}
