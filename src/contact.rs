//! A contact scene (material, friction, method, tolerance) and its solution.

use std::sync::OnceLock;

use crate::error::{Error, Result};
use crate::field::{Expand, Field};
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

/// Default target for |c - c_exact| (and, unless set apart, for the traction error).
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

pub use crate::problem::TOLERANCE_FLOOR;

/// An a-priori bound on the traction error norm ([`crate::problem::traction_distance`]) of
/// any admissible tractions of friction `mu` (p >= 0 with int p = 1 and |q| <= mu p, as the
/// exact solution): int |dp| <= 2 and int |dq| <= 2 mu.
fn admissible_traction_bound(mu: f64) -> f64 {
    2.0 * (1.0 + mu)
}

/// A scene: the material, the friction coefficient and how to solve it.
#[derive(Clone, Debug)]
pub struct Contact {
    material: Material,
    mu: f64,
    method: Method,
    tolerance: f64,
    /// Target for the traction error; None: the same as `tolerance`.
    traction_tolerance: Option<f64>,
}

impl Contact {
    /// A frictionless contact (mu = 0) solved by [`Method::Auto`] to [`DEFAULT_TOLERANCE`].
    pub fn new(material: Material) -> Self {
        Self {
            material,
            mu: 0.0,
            method: Method::Auto,
            tolerance: DEFAULT_TOLERANCE,
            traction_tolerance: None,
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

    /// Sets the target for |c - c_exact| (finite, 0 < tol < 1), and for the traction error
    /// unless [`Contact::set_traction_tolerance`] set that apart.
    pub fn set_tolerance(&mut self, tol: f64) -> Result<()> {
        validate_tolerance(tol)?;
        self.tolerance = tol;
        Ok(())
    }

    /// The target for |c - c_exact| ([`Contact::set_tolerance`]).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The material.
    pub fn material(&self) -> &Material {
        &self.material
    }

    /// The coupling constants (bp, bq, mu) of this scene.
    pub fn coupling(&self) -> Coupling {
        self.material.coupling(self.mu)
    }

    /// Solves the scene with the chosen method; AUTO picks the cheapest method whose error
    /// estimate meets the tolerance ([`Contact::auto_choice`]). COUPLED and LCP are run to
    /// the tolerances or [`TOLERANCE_FLOOR`], whichever is larger, and fail with
    /// [`Error::ToleranceNotMet`] where their estimates miss what was asked.
    pub fn solve(&self) -> Result<Solution> {
        let k = self.coupling();
        let method = match self.method {
            Method::Auto => self.auto_choice(&k),
            m => m,
        };
        let (tol, ttol) = (self.tolerance, self.traction_tolerance());
        let (run_tol, run_ttol) = (tol.max(TOLERANCE_FLOOR), ttol.max(TOLERANCE_FLOOR));
        let below_floor = |e: Error| match e {
            Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail,
            } => {
                let asked = if tolerance == run_tol { tol } else { ttol };
                not_met(estimate, asked, &detail)
            }
            e => e,
        };
        let profile: Box<dyn Solved> = match method {
            Method::Goodman => Box::new(goodman::solve(&k)?),
            Method::Spence => Box::new(spence::solve(&k)?),
            Method::Coupled | Method::Auto => {
                Box::new(coupled::solve_to(&k, run_tol, run_ttol).map_err(below_floor)?)
            }
            Method::Lcp => {
                Box::new(lcp::solve_to_tolerance(&k, run_tol, run_ttol).map_err(below_floor)?)
            }
        };
        let (model, traction_model) = match method {
            Method::Goodman => model_bounds(Approximation::Goodman, &k),
            Method::Spence => model_bounds(Approximation::Spence, &k),
            _ => (0.0, 0.0),
        };
        let c_error = profile.numerical_error() + model;
        let mut traction_error = profile.traction_error() + traction_model;
        if !matches!(method, Method::Goodman | Method::Spence) {
            // finite also where the solver's own estimate is not (c alone from the tabulated
            // stick edge with Goodman's tractions, whose model-error table has no bound there)
            traction_error = traction_error.min(admissible_traction_bound(k.mu));
            // what was asked, met also where the solver worked to the floor only
            if !(c_error <= tol && traction_error <= ttol && traction_error.is_finite()) {
                let detail = format!(
                    "{method:?}: c within {c_error:.1e}, tractions within {traction_error:.1e}"
                );
                return Err(if c_error > tol {
                    not_met(c_error, tol, &detail)
                } else {
                    not_met(traction_error, ttol, &detail)
                });
            }
        }
        Ok(Solution {
            method,
            c_error,
            traction_error,
            profile,
            material: self.material,
            stick_set: None,
            field: OnceLock::new(),
        })
    }

    /// AUTO's choice: Goodman if its empirical model-error bounds (the tables of
    /// [`crate::model_error`]) on c and on the tractions are within the tolerances, else
    /// Spence if its are, else COUPLED.
    pub fn auto_choice(&self, k: &Coupling) -> Method {
        let ttol = self.traction_tolerance();
        [
            (Method::Goodman, Approximation::Goodman),
            (Method::Spence, Approximation::Spence),
        ]
        .into_iter()
        .find(|&(_, a)| {
            let (c, t) = model_bounds(a, k);
            c <= self.tolerance && (ttol.is_infinite() || t <= ttol)
        })
        .map_or(Method::Coupled, |(m, _)| m)
    }

    /// Sets the target for the traction error ([`crate::problem::traction_distance`]):
    /// 0 < tol, +infinity when the tractions are not needed (then only c counts, for AUTO's
    /// choice too). Until set, it follows [`Contact::set_tolerance`].
    pub fn set_traction_tolerance(&mut self, tol: f64) -> Result<()> {
        if tol.is_nan() || tol <= 0.0 {
            return Err(Error::InvalidArgument(format!(
                "traction tolerance {tol} must be > 0 (infinity: tractions not needed)"
            )));
        }
        self.traction_tolerance = Some(tol);
        Ok(())
    }

    /// The target for the traction error in force.
    pub fn traction_tolerance(&self) -> f64 {
        self.traction_tolerance.unwrap_or(self.tolerance)
    }
}

/// The tolerance `tolerance` missed with `estimate` (`detail`: the solver's account), below
/// [`TOLERANCE_FLOOR`] with the floor named as the reason.
fn not_met(estimate: f64, tolerance: f64, detail: &str) -> Error {
    let detail = if tolerance < TOLERANCE_FLOOR {
        format!("{detail}; below the tolerance floor {TOLERANCE_FLOOR:e}, worked to the floor")
    } else {
        detail.to_owned()
    };
    Error::ToleranceNotMet {
        estimate,
        tolerance,
        detail,
    }
}

/// The empirical model-error bounds of an approximation on c and on the tractions,
/// +infinity where the tables give none.
fn model_bounds(a: Approximation, k: &Coupling) -> (f64, f64) {
    let inf = |b: Option<f64>| b.unwrap_or(f64::INFINITY);
    (
        inf(model_error::bound(a, k)),
        inf(model_error::traction_bound(a, k)),
    )
}

/// A solved scene: the stick edge, the method used, its error estimate and the tractions.
#[derive(Debug)]
pub struct Solution {
    method: Method,
    profile: Box<dyn Solved>,
    c_error: f64,
    traction_error: f64,
    material: Material,
    /// The stick set [c1, c2] of a state without symmetry (a load-path state,
    /// [`crate::LoadPath::solution`]); None for the normal-load solutions, whose stick set is
    /// [-c, c].
    stick_set: Option<(f64, f64)>,
    /// The stress field, built on first use (then read-only: safe from many threads).
    field: OnceLock<Field>,
}

/// What every method's solution provides: its tractions and their expansion.
trait Solved: Profile + Expand {}
impl<T: Profile + Expand> Solved for T {}

impl Solution {
    /// A solution of tractions without symmetry (`profile`'s expansion tiles [-1, 1]) with
    /// stick set `stick_set`, the estimates of its ends' error and of the traction error.
    pub(crate) fn asymmetric<T: Profile + Expand + 'static>(
        method: Method,
        profile: T,
        stick_set: (f64, f64),
        c_error: f64,
        traction_error: f64,
        material: Material,
    ) -> Self {
        Self {
            method,
            profile: Box::new(profile),
            c_error,
            traction_error,
            material,
            stick_set: Some(stick_set),
            field: OnceLock::new(),
        }
    }

    /// Whether the tractions are symmetric (p even, q odd: the normal-load solutions of
    /// [`Contact::solve`]); false for a load-path state ([`crate::fretting::LoadPath::solution`]),
    /// which has no single stick half-width c, no edge intensity common to both edges and no
    /// slip function of its tractions alone.
    pub fn is_symmetric(&self) -> bool {
        self.stick_set.is_none()
    }

    /// The stick set [c1, c2]: (-c, c) for a symmetric solution; a load-path state's own
    /// (NaN, NaN when nothing sticks).
    pub fn stick_set(&self) -> (f64, f64) {
        self.stick_set.unwrap_or_else(|| {
            let c = self.c();
            (-c, c)
        })
    }

    /// `Err(InvalidArgument)` naming `what` for a solution without symmetry.
    pub(crate) fn require_symmetric(&self, what: &str) -> Result<()> {
        if self.is_symmetric() {
            Ok(())
        } else {
            Err(Error::InvalidArgument(format!(
                "{what} is defined for a symmetric (normal-load) solution only; this is a \
                 load-path state without symmetry (stick set [c1, c2]: use the stick zone)"
            )))
        }
    }

    /// The method that produced this solution (never [`Method::Auto`]).
    pub fn method(&self) -> Method {
        self.method
    }

    /// The stick edge c and 1 - c.
    pub fn edge(&self) -> StickEdge {
        self.profile.edge()
    }

    /// The stick half-width c (units of the punch half-width); NaN for a load-path state
    /// ([`Solution::is_symmetric`] false: see [`Solution::stick_set`]).
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

    /// The field solution of this solution's own tractions, built on first use.
    fn field(&self) -> &Field {
        self.field.get_or_init(|| {
            let e = self.profile.expansion();
            let edge = self.profile.edge_intensity(&e);
            Field::new(e, edge, &self.material.constants(), self.c())
        })
    }

    /// Stresses (sxx, syy, sxy) per P/a inside the solid at (x, y) in units of the punch
    /// half-width a, the solid being y < 0; y = 0 gives the surface values as limits from
    /// inside (syy = -p, sxy = q on the punch), and so do depths below 1e-150 (they differ
    /// from it by less than rounding). Tension is positive. At the punch edges (|x| = 1 on
    /// the surface) sxx = syy = -infinity and sxy = +-infinity (0 when mu = 0).
    /// The first call builds the field of the solution's tractions (a fraction of a
    /// millisecond); later calls cost about a microsecond per point.
    ///
    /// Errors: `InvalidArgument` for NaN or infinite coordinates or y > 0.
    pub fn stresses(&self, x: f64, y: f64) -> Result<[f64; 3]> {
        if !(x.is_finite() && y.is_finite()) {
            return Err(Error::InvalidArgument(format!(
                "point ({x}, {y}) must have finite coordinates"
            )));
        }
        if y > 0.0 {
            return Err(Error::InvalidArgument(format!(
                "point ({x}, {y}) is outside the solid (y must be <= 0)"
            )));
        }
        Ok(self.field().stresses(x, y))
    }

    /// The punch-edge singularity of this solution's pressure: p ~ k (1 - |x|)^(-g) as
    /// |x| -> 1, (k, g) with k per P/a. On a slip edge q ~ mu p sgn x. g is the method's own
    /// exponent: 1/2 - arctan(bp mu) / pi, and 1/2 for GOODMAN (whose p = 1/(pi sqrt(1 - x^2))
    /// has k = 1/(pi sqrt 2)). (NaN, NaN) for a load-path state, whose two edges differ
    /// ([`Solution::is_symmetric`]).
    pub fn edge_intensity(&self) -> (f64, f64) {
        if !self.is_symmetric() {
            return (f64::NAN, f64::NAN);
        }
        self.field().edge_intensity()
    }

    /// Tangential surface displacement of the solid relative to the punch at x (units of a),
    /// per P/E (E: the effective modulus of [`Material::constants`], P the normal force per
    /// unit thickness): 0 on the stick zone, the slip on the slip zones (negative for x > c:
    /// the solid slides inward), odd in x; beyond the punch the surface displacement.
    ///
    /// Errors: `InvalidArgument` for NaN or infinite x, and for a load-path state (its slip
    /// depends on the path, not on its tractions alone: [`Solution::is_symmetric`]).
    pub fn slip(&self, x: f64) -> Result<f64> {
        self.require_symmetric("the slip function")?;
        if !x.is_finite() {
            return Err(Error::InvalidArgument(format!("x = {x} is not finite")));
        }
        Ok(self.field().slip(x))
    }

    /// The method's own profile (stick edge, numerical error and tractions).
    pub fn profile(&self) -> &dyn Profile {
        self.profile.as_ref()
    }

    /// Estimate of the traction error, the norm of [`crate::problem::traction_distance`]
    /// (int (|p - p_exact| + |q - q_exact|) dx over the punch, in units of the normal load):
    /// from the last two orders for COUPLED (at most 2 (1 + mu), which any admissible
    /// tractions meet), the last two grids for LCP, the empirical
    /// model-error table of [`crate::model_error`] for GOODMAN and SPENCE (+infinity where it
    /// gives no bound).
    pub fn traction_error_estimate(&self) -> f64 {
        self.traction_error
    }
}
