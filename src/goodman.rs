//! Goodman's approximation (docs/theory.md §7, (G1)-(G3)): the shear traction's effect on the
//! pressure is dropped (bp = 0 in eq. (10)), so p = p0 = 1 / (pi sqrt(1 - x^2)); the stick
//! half-width c solves K(sqrt(1 - c^2)) / K(c) = bq / mu, and q follows from eq. (11) on the
//! stick zone and from eq. (9) on the slip zones.

use std::f64::consts::PI;

use ellip::{elliprf, elliprj};

use crate::error::{Error, Result};
use crate::field::{Expand, Expansion, Exponents, sample};
use crate::problem::{Coupling, Profile, StickEdge};

/// Jacobi theta functions (theta2, theta3, theta4) of a nome 0 <= q <= exp(-pi), summed
/// until the terms no longer change the sums (at most a handful of terms).
fn thetas(q: f64) -> (f64, f64, f64) {
    let (mut s2, mut s3, mut s4) = (1.0, 1.0, 1.0);
    let mut n = 1.0_f64;
    loop {
        let t2 = q.powf(n * (n + 1.0));
        let t3 = q.powf(n * n);
        s2 += t2;
        s3 += 2.0 * t3;
        s4 += if n as u64 % 2 == 1 { -2.0 } else { 2.0 } * t3;
        if t3 <= f64::EPSILON * 1e-3 {
            break;
        }
        n += 1.0;
    }
    (2.0 * q.powf(0.25) * s2, s3, s4)
}

/// The stick edge of Goodman's equation K(k') / K(k) = ratio (ratio = bq / mu > 0, k = c) in
/// closed form through the nome: with q = exp(-pi ratio), k = theta2^2 / theta3^2 and
/// k'^2 = theta4^4 / theta3^4; for ratio < 1 the complementary nome exp(-pi / ratio) swaps
/// the roles of k and k'. 1 - c = k'^2 / (1 + k) never cancels.
pub(crate) fn stick_edge(ratio: f64) -> StickEdge {
    if ratio >= 1.0 {
        let (t2, t3, t4) = thetas((-PI * ratio).exp());
        let k = (t2 / t3).powi(2);
        StickEdge {
            c: k,
            one_minus_c: (t4 / t3).powi(4) / (1.0 + k),
        }
    } else {
        let (t2, t3, t4) = thetas((-PI / ratio).exp());
        let k = (t4 / t3).powi(2);
        StickEdge {
            c: k,
            one_minus_c: (t2 / t3).powi(4) / (1.0 + k),
        }
    }
}

/// Below this c^2 the stick-zone shear is taken linear ([`GoodmanSolution::q_stick`]).
const C2_MIN: f64 = 1e-300;

/// Goodman's solution for one coupling (bp is ignored by the model).
#[derive(Clone, Debug)]
pub struct GoodmanSolution {
    coupling: Coupling,
    edge: StickEdge,
    /// c^2 and 1 - c^2, kept to full relative accuracy.
    c2: f64,
    k2: f64,
    /// RF(0, c^2, 1) = K(k'), the complementary complete integral.
    kk: f64,
}

/// Solves Goodman's approximation (the coupling must pass [`Coupling::validate`]). mu = 0
/// gives c = 0, q = 0.
pub fn solve(k: &Coupling) -> Result<GoodmanSolution> {
    k.validate()?;
    let edge = if k.mu == 0.0 {
        StickEdge::from_c(0.0)
    } else {
        stick_edge(k.bq / k.mu)
    };
    let c2 = edge.c * edge.c;
    let k2 = edge.one_minus_c * (1.0 + edge.c);
    let kk = if c2 > 0.0 {
        elliprf(0.0, c2, 1.0).map_err(|e| Error::Internal(format!("RF(0, c^2, 1): {e}")))?
    } else {
        f64::INFINITY
    };
    Ok(GoodmanSolution {
        coupling: *k,
        edge,
        c2,
        k2,
        kk,
    })
}

/// The pressure of a flat punch without shear coupling, p0 = 1 / (pi sqrt(1 - x^2)).
pub(crate) fn p0(x: f64) -> f64 {
    1.0 / (PI * ((1.0 - x) * (1.0 + x)).sqrt())
}

impl GoodmanSolution {
    /// q on the stick zone 0 <= x < c by the bounded inversion of eq. (11):
    /// q = (2x/pi) sqrt(c^2 - x^2) (-bq J1 + mu J2) with
    /// J1 = PV int_0^c p0(t) / (sqrt(c^2 - t^2) (t^2 - x^2)) dt = RJ(0, 1 - c^2, 1, 1 - x^2) / (3 pi),
    /// J2 = int_c^1 p0(s) / (sqrt(s^2 - c^2) (s^2 - x^2)) ds
    ///    = [RF(0, c^2, 1) + n/3 RJ(0, c^2, 1, 1 - n)] / (pi (1 - x^2)), n = (1 - c^2) / (1 - x^2).
    ///
    /// When 1 - c^2 underflows (bq / mu below ~ pi / 745), J1 diverges like K(c) and the
    /// stick-edge equation mu K(k') = bq K(c) cancels it against mu J2 exactly: with
    /// RJ(0, k'^2, 1, 1 - x^2) = 3 (Pi(x^2, c) - K(c)) / x^2 and, as k' -> 0,
    /// Pi(n, c) - K(c) = n K(c) / (1 - n) - sqrt(n) artanh(sqrt(n)) / (1 - n) + O(k'^2 ln k'),
    /// the limit is q = (2 bq / pi^2) sqrt(c^2 - x^2) artanh(x) / (1 - x^2), exact to rounding
    /// once k'^2 is below the smallest normal double.
    fn q_stick(&self, x: f64) -> f64 {
        let d2 = (self.edge.c - x) * (self.edge.c + x);
        let w = (1.0 - x) * (1.0 + x);
        let k = &self.coupling;
        if self.c2 < C2_MIN {
            // c < 1e-150: c^2 and c^2 - x^2 leave the normal doubles and RJ fails; on a stick
            // zone this narrow q rises from 0 to mu p, taken linear (what it changes in any
            // integral of q is below mu c)
            return k.mu * p0(x) * x / self.edge.c;
        }
        if self.k2 < f64::MIN_POSITIVE {
            return 2.0 * k.bq / (PI * PI) * d2.sqrt() * x.atanh() / w;
        }
        let j1 = elliprj(0.0, self.k2, 1.0, w).unwrap_or(f64::NAN) / (3.0 * PI);
        let n = self.k2 / w;
        let j2 =
            (self.kk + n / 3.0 * elliprj(0.0, self.c2, 1.0, d2 / w).unwrap_or(f64::NAN)) / (PI * w);
        2.0 * x / PI * d2.sqrt() * (k.mu * j2 - k.bq * j1)
    }
}

/// p = p0 has the punch-edge exponent 1/2 and is analytic across c; q - mu p ~ sqrt(c - x)
/// on the stick side (the elliptic-integral form of `q_stick`).
impl Expand for GoodmanSolution {
    fn expansion(&self) -> Expansion {
        sample(
            self,
            Exponents {
                edge: 0.5,
                stick: 0.5,
            },
        )
    }
}

impl Profile for GoodmanSolution {
    fn coupling(&self) -> Coupling {
        self.coupling
    }

    fn edge(&self) -> StickEdge {
        self.edge
    }

    fn numerical_error(&self) -> f64 {
        // The theta series are summed to below rounding: a few ulps of c.
        8.0 * f64::EPSILON * self.edge.c.max(f64::MIN_POSITIVE)
    }

    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        let p = p0(x);
        let mu = self.coupling.mu;
        let q = if mu == 0.0 {
            0.0
        } else if x < self.edge.c {
            self.q_stick(x)
        } else {
            mu * p
        };
        (p, q)
    }
}

/// Test reference for every method's Goodman limit: the root c of Goodman's equation
/// K(sqrt(1 - c^2)) / K(c) = ratio by bisection on `ellip::ellipk` (parameter m = k^2) down to
/// adjacent doubles, independent of the theta-function closed form of [`stick_edge`].
#[cfg(test)]
pub(crate) fn c_by_bisection(ratio: f64) -> f64 {
    let f = |c: f64| ellip::ellipk((1.0 - c) * (1.0 + c)).unwrap() / ellip::ellipk(c * c).unwrap();
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return mid;
        }
        if f(mid) > ratio { lo = mid } else { hi = mid }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn theta_form_agrees_with_elliptic_root() {
        for ratio in [0.3, 0.7, 0.99, 1.0, 1.01, 1.5, 3.0] {
            let e = stick_edge(ratio);
            let c = c_by_bisection(ratio);
            assert!((e.c - c).abs() < 4e-15, "ratio {ratio}: {} vs {c}", e.c);
            assert!((e.one_minus_c - (1.0 - c)).abs() < 4e-15);
        }
    }

    /// A stick zone so narrow that c^2 leaves the normal doubles (c ~ 1e-153; the nome
    /// exp(-pi ratio) itself underflows beyond ratio ~ 226) keeps q finite with |q| <= mu p;
    /// just above C2_MIN (c ~ 1e-136) the elliptic form still holds it.
    #[test]
    fn tiny_stick_zones_keep_finite_shear() {
        for ratio in [200.0, 225.0] {
            let k = Coupling {
                bp: 0.0,
                bq: 0.3,
                mu: 0.3 / ratio,
            };
            let s = solve(&k).unwrap();
            let c = s.edge().c;
            assert!(c > 0.0 && c < 1e-130, "ratio {ratio}: c = {c}");
            for x in [0.0, 0.5 * c, c * (1.0 - 1e-9)] {
                let (p, q) = s.half_line_tractions(x);
                assert!(
                    q.is_finite() && q.abs() <= k.mu * p * (1.0 + 1e-12),
                    "x {x}: p {p}, q {q}"
                );
            }
        }
    }

    #[test]
    fn extreme_edges_keep_relative_accuracy() {
        // ratio = 30: c = 4 q^(1/2) (1 + ...) with q = exp(-30 pi).
        let e = stick_edge(30.0);
        let lead = 4.0 * (-15.0 * PI).exp();
        assert!((e.c / lead - 1.0).abs() < 1e-12);
        // ratio = 1/30: 1 - c = k'^2/(1+k), k' = 4 q'^(1/2) (...), q' = exp(-30 pi).
        let e = stick_edge(1.0 / 30.0);
        let lead = 16.0 * (-30.0 * PI).exp() / 2.0;
        assert!((e.one_minus_c / lead - 1.0).abs() < 1e-12);
        assert_eq!(e.c, 1.0);
    }

    /// H[q](x) = (1/pi) PV int q(t) / (x - t) dt by subtracting q(x) and integrating the
    /// smooth remainder with a fine composite Gauss-Legendre rule in a variable that
    /// flattens the edge singularities: an independent check of eq. (11).
    fn hilbert(f: &dyn Fn(f64) -> f64, x: f64, c: f64) -> f64 {
        // Split at -c, c and x; substitute t = a + (b - a) (1 - cos th) / 2 on each piece.
        let mut cuts = [-1.0, -c, x, c, 1.0];
        cuts.sort_by(f64::total_cmp);
        let fx = f(x);
        let (nodes, weights) = crate::numerics::quadrature::gauss_legendre(20);
        let mut sum = 0.0;
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b - a <= 0.0 {
                continue;
            }
            let panels = 200;
            for j in 0..panels {
                let (t0, t1) = (
                    PI * j as f64 / panels as f64,
                    PI * (j + 1) as f64 / panels as f64,
                );
                for (&s, &wt) in nodes.iter().zip(&weights) {
                    let th = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * s;
                    let t = a + (b - a) * (1.0 - th.cos()) / 2.0;
                    let dt = (b - a) * th.sin() / 2.0 * 0.5 * (t1 - t0) * wt;
                    sum += (f(t) - fx) / (x - t) * dt;
                }
            }
        }
        // PV int_{-1}^{1} dt / (x - t) = ln((1 + x) / (1 - x)).
        (sum + fx * ((1.0 + x) / (1.0 - x)).ln()) / PI
    }

    #[test]
    fn shear_satisfies_eq_11_on_the_stick_zone() {
        let k = Coupling {
            bp: 0.1,
            bq: 0.2857142857142857,
            mu: 0.3,
        };
        let s = solve(&k).unwrap();
        let c = s.edge().c;
        assert!(c > 0.2 && c < 0.9);
        let q = |t: f64| s.tractions(t).1;
        for i in 1..10 {
            let x = c * (i as f64 / 10.0 - 0.03);
            let h = hilbert(&q, x, c);
            let r = h + k.bq * p0(x);
            assert!(r.abs() < 1e-9 * k.bq * p0(x), "x = {x}: residual {r}");
        }
        // Continuity at the stick edge and the friction bound.
        let below = s.tractions(c * (1.0 - 1e-10)).1;
        assert!((below - k.mu * p0(c)).abs() < 1e-4 * k.mu * p0(c));
        for i in 0..50 {
            let x = c * i as f64 / 50.0;
            let (p, q) = s.tractions(x);
            assert!(q.abs() <= k.mu * p * (1.0 + 1e-12));
        }
    }

    /// Where 1 - c underflows (bq / mu = 1e-3) q is the k' -> 0 limit of the full formula,
    /// which it meets continuously: at bq / mu = 4.6e-3 (1 - c ~ 1e-296, still normal) the
    /// full formula agrees with the limit to rounding of the cancelled logarithm.
    #[test]
    fn shear_stays_finite_when_the_slip_width_underflows() {
        let at = |mu: f64| {
            let s = solve(&Coupling {
                bp: 0.2,
                bq: 0.2,
                mu,
            })
            .unwrap();
            assert!(s.k2 >= 0.0 && s.edge().c <= 1.0);
            s
        };
        let underflowed = at(200.0);
        assert_eq!(underflowed.k2, 0.0);
        let normal = at(0.2 / 4.6e-3);
        assert!(normal.k2 > 0.0 && normal.k2 < 1e-290, "{}", normal.k2);
        for x in [1e-3, 0.1, 0.5, 0.9, 0.999_999] {
            let q = underflowed.tractions(x).1;
            assert!(q.is_finite() && q > 0.0, "x = {x}: q = {q}");
            let limit = 2.0 * 0.2 / (PI * PI) * x.atanh() / ((1.0 - x) * (1.0 + x)).sqrt();
            assert!((q / limit - 1.0).abs() < 1e-14, "x = {x}");
            let full = normal.tractions(x).1;
            assert!(
                (full / limit - 1.0).abs() < 1e-12,
                "x = {x}: {full} vs {limit}"
            );
        }
    }

    #[test]
    fn frictionless_limit() {
        let s = solve(&Coupling {
            bp: 0.2,
            bq: 0.3,
            mu: 0.0,
        })
        .unwrap();
        assert_eq!(s.edge().c, 0.0);
        assert_eq!(s.tractions(0.5).1, 0.0);
    }
}
