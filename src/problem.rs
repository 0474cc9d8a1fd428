//! The boundary-value problem (THEORY.md section 3), with the material entering only
//! through bp = A / (pi C) and bq = A / (pi B):
//! with H[f](x) = (1/pi) PV int_{-1}^{1} f(t) / (x - t) dt,
//! - (E1) H[p] = bp q on |x| < 1 (paper eq. (10)),
//! - (E2) H[q] = -bq p on |x| < c (stick, paper eq. (11)),
//! - (E3) q = mu p sgn(x) on c < |x| < 1 (slip, paper eq. (9)),
//! - (E4) int p = 1, q odd.
//!
//! Substituting q = delta q~ with delta = sqrt(bq / bp) gives the same problem with
//! bp = bq = b* = sqrt(bp bq) and friction mu~ = mu / delta (THEORY.md section 4).

/// The three numbers that fix the solution: coupling constants and friction coefficient.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coupling {
    /// bp = A / (pi C) >= 0: the shear traction's effect on the normal displacement.
    pub bp: f64,
    /// bq = A / (pi B) > 0: the pressure's effect on the tangential displacement.
    pub bq: f64,
    /// Coulomb friction coefficient mu >= 0.
    pub mu: f64,
}

impl Coupling {
    /// b* = sqrt(bp bq), in [0, 1) for admissible materials.
    pub fn b_star(&self) -> f64 {
        (self.bp * self.bq).sqrt()
    }

    /// Exponent g of the punch-edge singularity p ~ (1 - |x|)^(-g):
    /// g = 1/2 - arctan(bp mu) / pi (THEORY.md section 5).
    pub fn edge_exponent(&self) -> f64 {
        0.5 - (self.bp * self.mu).atan() / std::f64::consts::PI
    }

    /// The isotropic-form problem (b*, b*, mu / delta) with delta = sqrt(bq / bp), and
    /// delta itself (the factor in q = delta q~). Requires bp > 0.
    pub fn reduced(&self) -> (Coupling, f64) {
        let b = self.b_star();
        let delta = (self.bq / self.bp).sqrt();
        (
            Coupling {
                bp: b,
                bq: b,
                mu: self.mu / delta,
            },
            delta,
        )
    }
}

/// Edge of the stick zone, carried both ways so that 1 - c keeps full relative accuracy
/// when c is close to 1 (never form `1.0 - c` when c is near 1). A slip width below the
/// smallest double (~1e-308; Goodman's at large friction) underflows to 0, and then c = 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StickEdge {
    /// Stick half-width c in [0, 1).
    pub c: f64,
    /// Slip-zone width 1 - c, computed without cancellation.
    pub one_minus_c: f64,
}

impl StickEdge {
    /// From c when c is not close to 1 (for c <= 1/2, `1 - c` is exact to rounding).
    pub fn from_c(c: f64) -> Self {
        Self {
            c,
            one_minus_c: 1.0 - c,
        }
    }

    /// From the slip width w = 1 - c (accurate when c is close to 1).
    pub fn from_one_minus_c(w: f64) -> Self {
        Self {
            c: 1.0 - w,
            one_minus_c: w,
        }
    }
}

/// What every method hands back: the stick edge, its own numerical error estimate and the
/// traction profile.
pub trait Profile: std::fmt::Debug + Send + Sync {
    /// The stick-zone edge.
    fn edge(&self) -> StickEdge;
    /// The method's own a-posteriori estimate of |c - c*| where c* is the exact solution
    /// of the equations the method solves (discretisation, iteration and rounding error;
    /// ~1e-15 for closed forms). An approximation's model error is accounted separately.
    fn numerical_error(&self) -> f64;
    /// (p(x), q(x)) for -1 < x < 1; the caller handles |x| >= 1.
    fn tractions(&self, x: f64) -> (f64, f64);
}
