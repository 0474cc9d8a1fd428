//! A contact scene (material, friction, method, tolerance) and its solution.

use crate::error::{Error, Result};
use crate::material::Material;
use crate::model_error::{self, Approximation};
use crate::problem::{Coupling, Profile, StickEdge, validate_tolerance};
use crate::{coupled, goodman, lcp, spence};

/// Solution methods; the discriminants are the C ABI's `orthoslip_method` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// The cheapest method whose error estimate meets the tolerance.
    Auto = 0,
    /// Goodman's approximation (closed form).
    Goodman = 1,
    /// Spence's approximation (closed form).
    Spence = 2,
    /// The high-order solver of the full coupled equations.
    Coupled = 3,
    /// The paper's linear-complementarity formulation with a smoothing Newton method.
    Lcp = 4,
}

impl Method {
    /// All methods, in discriminant order.
    pub const ALL: [Method; 5] = [
        Method::Auto,
        Method::Goodman,
        Method::Spence,
        Method::Coupled,
        Method::Lcp,
    ];

    /// The method with this C ABI value, if any.
    pub fn from_code(code: i32) -> Option<Method> {
        Method::ALL.into_iter().find(|m| *m as i32 == code)
    }
}

/// Default target for |c - c_exact|.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// A scene: the material, the friction coefficient and how to solve it.
#[derive(Clone, Debug)]
pub struct Contact {
    material: Material,
    mu: f64,
    method: Method,
    tolerance: f64,
}

impl Contact {
    /// A frictionless contact (mu = 0) solved by [`Method::Auto`] to [`DEFAULT_TOLERANCE`].
    pub fn new(material: Material) -> Self {
        Self {
            material,
            mu: 0.0,
            method: Method::Auto,
            tolerance: DEFAULT_TOLERANCE,
        }
    }

    /// Sets the Coulomb friction coefficient mu (finite, >= 0; 0 is the frictionless limit).
    pub fn set_friction(&mut self, mu: f64) -> Result<()> {
        if !(mu.is_finite() && mu >= 0.0) {
            return Err(Error::InvalidArgument(format!(
                "friction coefficient mu = {mu} must be finite and >= 0"
            )));
        }
        self.mu = mu;
        Ok(())
    }

    /// Sets the method.
    pub fn set_method(&mut self, method: Method) {
        self.method = method;
    }

    /// Sets the target for |c - c_exact| (finite, 0 < tol < 1).
    pub fn set_tolerance(&mut self, tol: f64) -> Result<()> {
        validate_tolerance(tol)?;
        self.tolerance = tol;
        Ok(())
    }

    /// The coupling constants (bp, bq, mu) of this scene.
    pub fn coupling(&self) -> Coupling {
        self.material.coupling(self.mu)
    }

    /// Solves the scene with the chosen method; AUTO picks the cheapest method whose error
    /// estimate meets the tolerance ([`Contact::auto_choice`]).
    pub fn solve(&self) -> Result<Solution> {
        let k = self.coupling();
        let method = match self.method {
            Method::Auto => self.auto_choice(&k),
            m => m,
        };
        let tol = self.tolerance;
        let profile: Box<dyn Profile> = match method {
            Method::Goodman => Box::new(goodman::solve(&k)?),
            Method::Spence => Box::new(spence::solve(&k)?),
            Method::Coupled | Method::Auto => Box::new(coupled::solve(&k, tol)?),
            Method::Lcp => Box::new(lcp::solve_to_tolerance(&k, tol)?),
        };
        let model = match method {
            Method::Goodman => model_bound(Approximation::Goodman, &k),
            Method::Spence => model_bound(Approximation::Spence, &k),
            _ => 0.0,
        };
        let c_error = profile.numerical_error() + model;
        Ok(Solution {
            method,
            profile,
            c_error,
        })
    }

    /// AUTO's choice: Goodman if its empirical model-error bound (the table of
    /// [`crate::model_error`]) is within the tolerance, else Spence if its is, else COUPLED.
    pub fn auto_choice(&self, k: &Coupling) -> Method {
        [
            (Method::Goodman, Approximation::Goodman),
            (Method::Spence, Approximation::Spence),
        ]
        .into_iter()
        .find(|&(_, a)| model_error::bound(a, k).is_some_and(|b| b <= self.tolerance))
        .map_or(Method::Coupled, |(m, _)| m)
    }
}

/// The empirical model-error bound of an approximation, +infinity where the table gives none.
fn model_bound(a: Approximation, k: &Coupling) -> f64 {
    model_error::bound(a, k).unwrap_or(f64::INFINITY)
}

/// A solved scene: the stick edge, the method used, its error estimate and the tractions.
#[derive(Debug)]
pub struct Solution {
    method: Method,
    profile: Box<dyn Profile>,
    c_error: f64,
}

impl Solution {
    /// The method that produced this solution (never [`Method::Auto`]).
    pub fn method(&self) -> Method {
        self.method
    }

    /// The stick edge c and 1 - c.
    pub fn edge(&self) -> StickEdge {
        self.profile.edge()
    }

    /// The stick half-width c (units of the punch half-width).
    pub fn c(&self) -> f64 {
        self.edge().c
    }

    /// The slip-zone width 1 - c with full relative accuracy.
    pub fn one_minus_c(&self) -> f64 {
        self.edge().one_minus_c
    }

    /// Estimate of |c - c_exact|, c_exact being the exact solution of the coupled problem:
    /// discretisation error for COUPLED and LCP, the empirical model-error bound of
    /// [`crate::model_error`] (plus rounding) for GOODMAN and SPENCE, +infinity where the
    /// table gives no bound.
    pub fn error_estimate(&self) -> f64 {
        self.c_error
    }

    /// The coupling constants (bp, bq, mu) solved for.
    pub fn coupling(&self) -> Coupling {
        self.profile.coupling()
    }

    /// Dimensionless tractions (p(x), q(x)) per P/a at x in units of the punch half-width:
    /// zero outside the punch, +infinity (q: +-infinity, or 0 when mu = 0) at the punch
    /// edges x = +-1 where p ~ (1 - |x|)^(-g). x must not be NaN.
    pub fn tractions(&self, x: f64) -> (f64, f64) {
        self.profile.tractions(x)
    }
}
