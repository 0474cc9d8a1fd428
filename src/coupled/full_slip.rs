//! The small-stick-zone regime (c -> 0, docs/theory.md (L1), (L2)): the full-slip limit problem
//! and the asymptotic law of c.
//!
//! Full slip: q = mu p sgn x on the whole contact. Then (E1) reads H\[p\] = bp mu sgn(x) p,
//! and with g = 1/2 - arctan(bp mu) / pi (the punch-edge exponent) its solution with
//! int p = 1 is
//!   p_fs(x) = sin(pi g) / pi |x|^(2g - 1) (1 - x^2)^(-g):
//! in s = x^2 the even p gives H\[p\](x) = x / pi PV int_0^1 s^(g-1) (1 - s)^(-g) / (x^2 - s) ds
//! = cot(pi g) p(x) (the classical principal value of s^(a-1) (1 - s)^(-a) / (s - sigma)), and
//! cot(pi g) = bp mu; int_{-1}^{1} |x|^(2g-1) (1 - x^2)^(-g) dx = B(g, 1 - g) = pi / sin(pi g).
//! The weak central singularity |x|^(-k0), k0 = 1 - 2g = 2 arctan(bp mu) / pi, is cut off by
//! the stick zone: there the solution has the scale c, p ~ c^(2g-1), so replacing it by p_fs
//! (and by p_fs(c), q = mu p_fs(c) x / c on |x| < c, which keeps p and q finite) changes the
//! tractions by O(c^(2g)) in the norm of [`crate::problem::traction_distance`].
//!
//! The stick edge follows the law c ~ 4 (1 - b*^2)^(pi / (2 b* mu~)) (reduced variables,
//! docs/theory.md (R2)), which tends to Goodman's 4 exp(-pi b* / (2 mu~)) as b* -> 0. Against
//! COUPLED (tests.rs) c / law = 1 + a1(b*) mu~ + O(mu~^2), a1 = -0.05 (b* = 0.1), -0.17 (0.3),
//! -0.33 (0.5), -0.60 (0.7), -1.2 (0.9), -2.3 (0.99) (c below the law everywhere measured):
//! the law is used only where its c is below the tolerance, and its error estimate is c
//! itself. Its c underflows to 0 below the smallest double (mu~ -> 0), and ln c itself to
//! -infinity where pi / (2 mu) overflows (subnormal mu); the stick zone's pressure
//! p_fs(c) = norm c^(2g - 1) is formed as one product that tends to norm / (1 - b*^2), so the
//! tractions stay finite.

use std::f64::consts::PI;

use crate::field::{Expand, Expansion, fitted_panel};
use crate::numerics::cauchy::Weight;
use crate::problem::{Coupling, Profile, StickEdge};

/// Bound on the traction error of the full-slip tractions, in units of c^(2g) with the law's
/// c: against the panels (tests below) the distance is about K(b*) mu~ c^(2g), K = 0.3
/// (b* = 0.5) .. 1.1 (b* = 0.99), at most 0.83 c^(2g) over the overlap (b* = 0.1 .. 0.99,
/// c = 1e-14 .. 1e-2).
const TRACTION_FACTOR: f64 = 10.0;

/// ln c of the law c = 4 (1 - b*^2)^(pi / (2 b* mu~)) = 4 (1 - bp bq)^(pi / (2 bp mu)) (b* mu~
/// = bp mu), finite where c underflows; at bp = 0 Goodman's limit ln 4 - pi bq / (2 mu).
pub(crate) fn ln_c_law(k: &Coupling) -> f64 {
    4f64.ln() + PI / (2.0 * k.mu) * law_per_bp(k)
}

/// ln(1 - bp bq) / bp, -> -bq as bp -> 0 (no 0/0).
fn law_per_bp(k: &Coupling) -> f64 {
    if k.bp > 0.0 {
        (-k.bp * k.bq).ln_1p() / k.bp
    } else {
        -k.bq
    }
}

/// ln(p_fs(c) / norm) = (2g - 1) ln c = -k0 ln c at the law's c, k0 = 2 arctan(bp mu) / pi,
/// taken as one product: -(2 / pi) arctan(bp mu) ln 4 - (arctan(bp mu) / mu) ln(1 - bp bq) / bp.
/// As mu -> 0, ln c -> -infinity and k0 -> 0 while their product tends to -ln(1 - b*^2) (the
/// stick zone's pressure stays finite); formed apart, they overflow to -infinity and
/// underflow to 0 and multiply to NaN (mu = 4.9e-324 gave p(0) = NaN; issue 26).
fn ln_stick_pressure_law(k: &Coupling) -> f64 {
    let t = k.bp * k.mu;
    // arctan(t) / mu = bp arctan(t) / t, = bp to rounding for t < 1e-8 (also where t
    // underflows)
    let atan_per_mu = if t < 1e-8 { k.bp } else { t.atan() / k.mu };
    -(2.0 / PI) * t.atan() * 4f64.ln() - atan_per_mu * law_per_bp(k)
}

/// The full-slip solution with the law's stick edge.
#[derive(Clone, Debug)]
pub(crate) struct FullSlip {
    coupling: Coupling,
    /// ln c (finite although c may underflow).
    ln_c: f64,
    /// Punch-edge exponent g.
    g: f64,
    /// sin(pi g) / pi, the normalisation of p_fs.
    norm: f64,
    /// ln(p_fs(c) / norm) = (2g - 1) ln c, the pressure on the stick zone (finite where c
    /// underflows: [`ln_stick_pressure_law`]).
    ln_stick: f64,
}

impl FullSlip {
    /// The full-slip solution of `k` (mu > 0), its c from the law in the reduced variables.
    pub(crate) fn new(k: &Coupling) -> Self {
        let g = k.edge_exponent();
        FullSlip {
            coupling: *k,
            ln_c: ln_c_law(k),
            g,
            norm: (PI * g).sin() / PI,
            ln_stick: ln_stick_pressure_law(k),
        }
    }

    /// The full-slip tractions of `k` (mu > 0) cut off at a stick edge c known otherwise (the
    /// auxetic limit, `super::auxetic`).
    pub(crate) fn with_edge(k: &Coupling, c: f64) -> Self {
        let s = Self::new(k);
        FullSlip {
            ln_c: c.ln(),
            ln_stick: (2.0 * s.g - 1.0) * c.ln(),
            ..s
        }
    }

    /// The traction error bound TRACTION_FACTOR c^(2g).
    fn traction_bound(&self) -> f64 {
        TRACTION_FACTOR * (2.0 * self.g * self.ln_c).exp()
    }

    /// p_fs at 0 < x < 1.
    fn p(&self, x: f64) -> f64 {
        self.norm * x.powf(2.0 * self.g - 1.0) * ((1.0 - x) * (1.0 + x)).powf(-self.g)
    }
}

impl Profile for FullSlip {
    fn coupling(&self) -> Coupling {
        self.coupling
    }

    fn edge(&self) -> StickEdge {
        StickEdge::from_c(self.ln_c.exp())
    }

    /// The law's c is far below any tolerance it is used for: c itself bounds its error.
    fn numerical_error(&self) -> f64 {
        self.ln_c.exp()
    }

    fn traction_error(&self) -> f64 {
        self.traction_bound()
    }

    /// p_fs and mu p_fs beyond c; on the stick zone p_fs(c) and q rising linearly to
    /// mu p_fs(c) (finite at x = 0 even where c underflows).
    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        let mu = self.coupling.mu;
        if x.ln() > self.ln_c {
            let p = self.p(x);
            (p, mu * p)
        } else {
            // x = 0 is the whole stick zone where c underflows (ln c = -infinity): q(0) = 0
            let p = self.norm * self.ln_stick.exp();
            let q = if x > 0.0 {
                mu * p * (x.ln() - self.ln_c).exp()
            } else {
                0.0
            };
            (p, q)
        }
    }
}

/// Two panels: [0, 1/2] weighted |x|^(2g-1) (the central singularity), [1/2, 1] weighted
/// (1 - x)^(-g); the stick zone (below 1e-12 wherever this regime is used) is left out.
impl Expand for FullSlip {
    fn expansion(&self) -> Expansion {
        let (g, mu) = (self.g, self.coupling.mu);
        let h = 0.25;
        let panel = |a: f64, weight: Weight| {
            fitted_panel(a, a + 2.0 * h, weight, |_, opt| {
                let p = self.p(a + h * opt);
                (p, mu * p)
            })
        };
        Expansion {
            panels: vec![
                panel(0.0, Weight::Left(2.0 * g - 1.0)),
                panel(0.5, Weight::Right(-g)),
            ],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupled::tests::{hilbert_ref, integral_ref};
    use crate::problem::traction_distance;

    /// p_fs solves (E1) with q = mu p sgn x and has int p = 1, against the reference
    /// quadratures of the coupled tests (not the principal value used to derive it).
    #[test]
    fn full_slip_solves_the_limit_problem() {
        for (bp, bq, mu) in [
            (0.3, 0.3, 0.1),
            (0.1, 0.5, 0.4),
            (0.8, 0.6, 0.3),
            (0.0, 0.4, 0.3),
        ] {
            let k = Coupling { bp, bq, mu };
            let fs = FullSlip::new(&k);
            let p = |t: f64| fs.p(t.abs());
            for i in 0..12 {
                let x = -0.95 + 1.9 * (i as f64 + 0.37) / 12.0;
                let h = hilbert_ref(&p, x, 0.0, 1.0, fs.g);
                let rhs = bp * mu * x.signum() * p(x);
                assert!(
                    (h - rhs).abs() <= 1e-9 * h.abs().max(p(x)),
                    "{k:?} x = {x}: H[p] = {h}, bp mu p sgn x = {rhs}"
                );
            }
            let total = 2.0 * integral_ref(&p, 0.0, 1.0, &[0.0], fs.g, 1.0);
            assert!((total - 1.0).abs() < 1e-10, "{k:?}: int p = {total}");
        }
    }

    /// Against the panels where both work (law's c from 1e-14 to 1e-2): the law's error bound
    /// (its c) holds, c / law - 1 is O(mu~) (the first correction, |a1| <= 2.5), the full-slip
    /// tractions are within their bound, and where COUPLED takes this regime (solve_to at the
    /// tolerances its bounds meet) the panels' c and tractions agree with it within them: the
    /// switch is continuous. The fast tier at two b* ([`law_matches_the_panels_wide`]: six).
    #[test]
    fn law_matches_the_panels() {
        assert!(law_matches_the_panels_at(&[0.3, 0.9]) >= 5);
    }

    #[test]
    #[ignore = "slow tier: the full-slip law against the panels at six b*"]
    fn law_matches_the_panels_wide() {
        let checked = law_matches_the_panels_at(&[0.1, 0.3, 0.5, 0.7, 0.9, 0.99]);
        assert!(checked >= 12, "only {checked} points in the overlap");
    }

    /// The points of [`law_matches_the_panels`] in the overlap at these b*: how many.
    fn law_matches_the_panels_at(b_star: &[f64]) -> usize {
        let mut checked = 0;
        for &b in b_star {
            for m in [0.3, 0.2, 0.1, 0.05, 0.03] {
                let k = Coupling {
                    bp: b,
                    bq: b,
                    mu: m,
                };
                let fs = FullSlip::new(&k);
                if !(-32.0..=-4.6).contains(&fs.ln_c) {
                    continue;
                }
                let s = crate::coupled::panels(&k, 1e-12, f64::INFINITY).unwrap();
                let (c, law) = (s.edge().c, fs.ln_c.exp());
                assert!(
                    (c - law).abs() <= fs.numerical_error(),
                    "b {b} m {m}: c {c}, law {law}"
                );
                assert!(
                    (c / law - 1.0).abs() <= 2.5 * m,
                    "b {b} m {m}: c / law = {}",
                    c / law
                );
                let d = traction_distance(&s, &fs);
                assert!(d <= fs.traction_error(), "b {b} m {m}: distance {d:e}");
                let (tol, ttol) = (fs.numerical_error() * 1.01, fs.traction_error() * 1.01);
                let chosen = crate::coupled::solve_to(&k, tol, ttol).unwrap();
                assert!(matches!(chosen.regime, super::super::Regime::FullSlip(_)));
                assert!(chosen.edge().distance(s.edge()) <= tol);
                assert!(traction_distance(&chosen, &s) <= ttol);
                checked += 1;
            }
        }
        checked
    }
}
