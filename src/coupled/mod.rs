//! orthoslip's solver of the full coupled partial-slip problem (E1)-(E4) (METHOD_COUPLED).
//!
//! Method (COUPLED.md, THEORY.md sections 3-5):
//! - the exact reduction (bp, bq, mu) -> (b*, b*, mu / delta), q = delta q~ (bp > 0);
//! - for a trial stick edge c, a collocation system on panels graded geometrically towards
//!   x = c and x = 1 ([`mesh`]), whose bases carry the local exponents: (1 - x)^(-g) at the
//!   punch edge, (x - c)^g on the slip side and (c - x)^g in q on the stick side, plus the
//!   wrong-c modes |x - c|^(g-1) ([`system`]); all singular integrals are evaluated in closed
//!   form or to rounding ([`cauchy`]), so the error decays geometrically in the order n;
//! - c is the root of kappa(c), the coefficient of q's (c - x)^(g-1) mode (bounded q at c is
//!   the compatibility condition), found in t = ln(c / (1 - c)) so that c ~ 1e-20 and
//!   1 - c ~ 1e-12 are both carried to full relative accuracy;
//! - the order is raised until two successive orders agree on c within the tolerance.
//!
//! Which root: kappa < 0 for small c (checked at a c far below Goodman's estimate, walking
//! down until it is; never above c = 1/2), then c is increased in steps of 1 in t until kappa
//! (at the cheap order 4) changes sign: the
//! first sign change met from c = 0 brackets the physical root (the one continuous in mu from
//! small friction), which Brent's method then refines. The solution is checked for
//! |q| <= mu p on the stick zone before it is returned.
//!
//! Range: 2e-35 < c and 1 - c > 4e-18 (outside it NoConvergence says so); the number of
//! panels grows like log(1 / min(c, 1 - c)). Cost (measured, one core): 15-80 ms per solve
//! to tol = 1e-10 for c in [1e-5, 1 - 2e-3] (100-400 unknowns, a few least-squares solves
//! per order); tractions afterwards 40-60 ns per point.

pub mod cauchy;
pub mod mesh;
pub mod system;

#[cfg(test)]
mod tests;

use crate::error::{Error, Result};
use crate::problem::{Coupling, Profile, StickEdge};
use mesh::{Layout, Pt};
use std::f64::consts::PI;
use system::{Constants, Discrete, Families, solve_fixed};

/// Step in t = ln(c / (1 - c)) of the scan for the first root (the roots near full stick
/// repeat every pi / eps >= 12 in ln(1 - c) for b* < 0.99).
const SCAN_STEP: f64 = 1.0;

/// Order of the scan for the first sign change of kappa (only its sign is used).
const SCAN_ORDER: usize = 4;

/// Polynomial orders tried in turn (per panel).
const ORDERS: [usize; 5] = [6, 12, 16, 21, 26];

/// The coupled solution: stick edge, error estimate and the discretised tractions.
#[derive(Clone, Debug)]
pub struct CoupledSolution {
    edge: StickEdge,
    error: f64,
    /// q = delta q~ (1 when bp = 0).
    delta: f64,
    /// None for mu = 0 (p = p0, q = 0 exactly).
    discrete: Option<Discrete>,
    /// Order per panel of the returned discretisation.
    order: usize,
}

impl CoupledSolution {
    /// Polynomial order per panel of the returned discretisation (0 for mu = 0).
    pub fn order(&self) -> usize {
        self.order
    }

    /// Number of unknowns of the returned discretisation.
    pub fn unknowns(&self) -> usize {
        self.discrete.as_ref().map_or(0, |d| d.mesh.unknowns)
    }
}

impl Profile for CoupledSolution {
    fn edge(&self) -> StickEdge {
        self.edge
    }

    fn numerical_error(&self) -> f64 {
        self.error
    }

    /// (p, q) at -1 < x < 1: one panel lookup and two short Legendre sums.
    fn tractions(&self, x: f64) -> (f64, f64) {
        let ax = x.abs();
        match &self.discrete {
            None => (1.0 / (PI * ((1.0 - ax) * (1.0 + ax)).sqrt()), 0.0),
            Some(d) => {
                let (p, q) = d.eval(Pt { x: ax, u: 1.0 - ax });
                (
                    p,
                    if x < 0.0 {
                        -self.delta * q
                    } else {
                        self.delta * q
                    },
                )
            }
        }
    }
}

/// c and 1 - c from t = ln(c / (1 - c)), both to full relative accuracy.
fn edge_of(t: f64) -> (f64, f64) {
    (1.0 / (1.0 + (-t).exp()), 1.0 / (1.0 + t.exp()))
}

/// Leading-order Goodman estimate of t (THEORY.md section 5, first term of the theta series).
fn goodman_guess(bq: f64, mu: f64) -> f64 {
    let r = bq / mu;
    let t = if r >= 1.0 {
        let c = 4.0 * (-0.5 * PI * r).exp();
        c.ln() - (-c).ln_1p()
    } else {
        let w = 8.0 * (-PI / r).exp();
        (-w).ln_1p() - w.ln()
    };
    t.clamp(-60.0, 30.0)
}

/// Root finder state for one order n.
struct Level<'a> {
    k: Constants,
    n: usize,
    fams: &'a Families,
    /// Fixed panel layout while refining a bracket (None: each c its own layout).
    layout: Option<Layout>,
    /// The last two evaluations (t, kappa), for the slope at the root.
    hist: [(f64, f64); 2],
    /// Accuracy wanted in t (a small fraction of the order's own error in c).
    xtol: f64,
}

impl Level<'_> {
    fn kappa(&mut self, t: f64) -> Result<f64> {
        let (c, w) = edge_of(t);
        let own;
        let layout = match &self.layout {
            Some(l) => l,
            None => {
                own = Layout::for_edge(c, w);
                &own
            }
        };
        let kappa = solve_fixed(self.k, c, w, self.n, self.fams, layout)?.kappa;
        self.hist = [self.hist[1], (t, kappa)];
        if kappa.is_finite() {
            Ok(kappa)
        } else {
            Err(Error::NoConvergence(format!("kappa not finite at c = {c}")))
        }
    }

    /// Fixes the layout to the one of t.
    fn fix_layout(&mut self, t: f64) {
        let (c, w) = edge_of(t);
        self.layout = Some(Layout::for_edge(c, w));
    }

    /// Brent's method on kappa(t) in [a, b] with kappa(a) < 0 < kappa(b).
    fn brent(&mut self, mut a: f64, mut b: f64, mut fa: f64, mut fb: f64) -> Result<f64> {
        let xtol = self.xtol;
        let (mut c, mut fc) = (a, fa);
        let (mut d, mut e) = (b - a, b - a);
        for _ in 0..100 {
            if fb * fc > 0.0 {
                (c, fc) = (a, fa);
                d = b - a;
                e = d;
            }
            if fc.abs() < fb.abs() {
                (a, fa, b, fb, c, fc) = (b, fb, c, fc, b, fb);
            }
            let tol = xtol.max(4.0 * f64::EPSILON * b.abs().max(1.0));
            let m = 0.5 * (c - b);
            if m.abs() <= tol || fb == 0.0 {
                return Ok(b);
            }
            if e.abs() >= tol && fa.abs() > fb.abs() {
                let s = fb / fa;
                let (mut p, mut q) = if a == c {
                    (2.0 * m * s, 1.0 - s)
                } else {
                    let (qq, r) = (fa / fc, fb / fc);
                    (
                        s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0)),
                        (qq - 1.0) * (r - 1.0) * (s - 1.0),
                    )
                };
                if p > 0.0 {
                    q = -q;
                }
                p = p.abs();
                if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                    e = d;
                    d = p / q;
                } else {
                    d = m;
                    e = m;
                }
            } else {
                d = m;
                e = m;
            }
            (a, fa) = (b, fb);
            b += if d.abs() > tol { d } else { tol.copysign(m) };
            fb = self.kappa(b)?;
        }
        Err(Error::NoConvergence("Brent iteration limit in c".into()))
    }

    /// First sign change of kappa met increasing c from 0 (scanned at order SCAN_ORDER),
    /// then refined at this level's order.
    fn first_root(&mut self, t0: f64) -> Result<f64> {
        let order = self.n;
        self.n = SCAN_ORDER.min(order);
        // never start above c = 1/2: for large friction Goodman's c is far too close to 1,
        // beyond further roots of the oscillatory near-full-stick regime
        let mut lo = (t0 - 1.0).min(0.0);
        let mut steps = 0;
        while self.kappa(lo)?.partial_cmp(&0.0) != Some(std::cmp::Ordering::Less) {
            lo -= 2.0;
            steps += 1;
            if steps > 30 || lo < -80.0 {
                return Err(Error::NoConvergence(
                    "kappa >= 0 down to c = 2e-35: the stick zone is below the solver's range"
                        .into(),
                ));
            }
        }
        loop {
            let hi = lo + SCAN_STEP;
            let f_hi = self.kappa(hi)?;
            if f_hi >= 0.0 {
                // the scan order's sign may be off within its error of the root: widen once
                self.n = order;
                self.fix_layout(0.5 * (lo + hi));
                for widen in [0.0, 0.5] {
                    let (a, b) = (lo - widen, hi + widen);
                    let (f_a, f_b) = (self.kappa(a)?, self.kappa(b)?);
                    if f_a < 0.0 && f_b >= 0.0 {
                        return self.brent(a, b, f_a, f_b);
                    }
                }
                return Err(Error::NoConvergence(format!(
                    "kappa changes sign with the panel layout or order near t = {lo}"
                )));
            }
            lo = hi;
            if lo > 40.0 {
                return Err(Error::NoConvergence(
                    "no sign change of kappa for 1 - c >= 4e-18: the slip zones are below the \
                     solver's range"
                        .into(),
                ));
            }
        }
    }

    /// The root near t_prev (from a lower order), bracketed by a growing step.
    /// d kappa / dt from the last two evaluations.
    fn slope(&self) -> f64 {
        let [(t0, f0), (t1, f1)] = self.hist;
        (f1 - f0) / (t1 - t0)
    }

    /// The root near t_prev (from a lower order) by the secant method started with the
    /// lower order's slope, stopped when the step is below xtol; if that fails, by bracketing
    /// and Brent. Returns t and its uncertainty |step| + |kappa| / |slope| at the last
    /// iterate (which also measures the rounding noise of kappa).
    fn root_near(&mut self, t_prev: f64, slope: f64, first: f64) -> Result<(f64, f64)> {
        self.fix_layout(t_prev);
        let f = self.kappa(t_prev)?;
        if slope.is_finite() && slope != 0.0 {
            let (mut t0, mut f0) = (t_prev, f);
            let mut t1 = t0 - f0 / slope;
            for _ in 0..6 {
                let f1 = self.kappa(t1)?;
                let s = if f1 == f0 {
                    slope
                } else {
                    (f1 - f0) / (t1 - t0)
                };
                let step = -f1 / s;
                if !step.is_finite() || step.abs() > 1.0 || s * slope <= 0.0 {
                    break;
                }
                if step.abs() <= self.xtol || f1 == 0.0 {
                    return Ok((t1 + step, 2.0 * step.abs()));
                }
                if f1.abs() >= f0.abs() {
                    // no progress: kappa's rounding noise reached; its size sets the
                    // uncertainty of t
                    let best = if f1.abs() < f0.abs() { t1 } else { t0 };
                    return Ok((best, 2.0 * (f0.abs().max(f1.abs()) / slope.abs())));
                }
                (t0, f0) = (t1, f1);
                t1 += step;
            }
        }
        let mut step = 1e-6f64.max(4.0 * first);
        while step < 8.0 {
            let (lo, hi) = (t_prev - step, t_prev + step);
            let (f_lo, f_hi) = if f < 0.0 {
                (f, self.kappa(hi)?)
            } else {
                (self.kappa(lo)?, f)
            };
            if f_lo < 0.0 && f_hi >= 0.0 {
                let (a, b) = if f < 0.0 { (t_prev, hi) } else { (lo, t_prev) };
                return Ok((self.brent(a, b, f_lo, f_hi)?, self.xtol));
            }
            step *= 4.0;
        }
        Err(Error::NoConvergence(
            "lost the root when raising the order".into(),
        ))
    }
}

/// Checks |q| <= mu p (to 1e-6 relative) at the stick panels' Gauss points.
fn admissible(d: &Discrete, mu: f64) -> bool {
    let (nodes, _) = crate::quadrature::gauss_legendre(7);
    d.mesh.panels.iter().filter(|p| p.stick).all(|panel| {
        nodes.iter().all(|&t| {
            let x = if panel.central {
                panel.h * (0.5 * (1.0 + t)).sqrt()
            } else {
                Pt::local(panel.m, panel.h, t).x
            };
            let (p, q) = d.eval(Pt { x, u: 1.0 - x });
            q.abs() <= mu * p * (1.0 + 1e-6) + 1e-12
        })
    })
}

/// Solves (E1)-(E4) for `k` to |c - c_exact| <= tol (see the module documentation).
pub fn solve(k: &Coupling, tol: f64) -> Result<CoupledSolution> {
    let ok = |v: f64| v.is_finite() && v >= 0.0;
    if !(ok(k.bp) && ok(k.bq) && ok(k.mu) && k.bq > 0.0) {
        return Err(Error::InvalidArgument(format!(
            "coupled: need finite bp >= 0, bq > 0, mu >= 0 (got {k:?})"
        )));
    }
    if tol.is_nan() || tol <= 0.0 {
        return Err(Error::InvalidArgument(format!(
            "coupled: tolerance {tol} must be > 0"
        )));
    }
    if k.b_star() >= 1.0 {
        return Err(Error::InvalidArgument(format!(
            "coupled: b* = {} must be < 1",
            k.b_star()
        )));
    }
    if k.mu == 0.0 {
        return Ok(CoupledSolution {
            edge: StickEdge {
                c: 0.0,
                one_minus_c: 1.0,
            },
            error: 0.0,
            delta: 1.0,
            discrete: None,
            order: 0,
        });
    }
    let (r, delta) = if k.bp > 0.0 { k.reduced() } else { (*k, 1.0) };
    let consts = Constants {
        bp: r.bp,
        bq: r.bq,
        mu: r.mu,
        g: r.edge_exponent(),
    };
    let mut prev: Option<f64> = None;
    let mut last_diff = 0.0;
    let mut slope = f64::NAN;
    let fams = Families::new(consts.g, ORDERS[ORDERS.len() - 1]);
    for &n in &ORDERS {
        // first order: t to 1e-6 (its own error is larger anyway); later orders: c to 5% of
        // the tolerance
        let xtol = match prev {
            None => 1e-6,
            Some(t) => {
                let (c, w) = edge_of(t);
                (0.05 * tol / (c * w)).clamp(1e-13, 1e-3)
            }
        };
        let mut t_unc = 0.0;
        let mut level = Level {
            k: consts,
            n,
            fams: &fams,
            layout: None,
            hist: [(f64::NAN, f64::NAN); 2],
            xtol,
        };
        let t = match prev {
            None => level.first_root(goodman_guess(r.bq, r.mu))?,
            Some(t_prev) => {
                let (t, unc) = level.root_near(t_prev, slope, last_diff)?;
                t_unc = unc;
                t
            }
        };
        let (c, w) = edge_of(t);
        if let Some(t_prev) = prev {
            let (c_prev, w_prev) = edge_of(t_prev);
            // |c - c_prev| from whichever of c, 1 - c is small
            // |c - c_prev| from whichever of c, 1 - c is small, plus the root's own
            // uncertainty (dc = c (1 - c) dt)
            let diff = if c < 0.5 {
                (c - c_prev).abs()
            } else {
                (w - w_prev).abs()
            } + c * w * t_unc;
            last_diff = (t - t_prev).abs();
            if diff <= tol {
                let layout = level.layout.unwrap_or_else(|| Layout::for_edge(c, w));
                let d = solve_fixed(consts, c, w, n, &fams, &layout)?;
                if !admissible(&d, consts.mu) {
                    return Err(Error::NoConvergence(format!(
                        "root c = {c} violates |q| <= mu p on the stick zone"
                    )));
                }
                let edge = if c < 0.5 {
                    StickEdge::from_c(c)
                } else {
                    StickEdge::from_one_minus_c(w)
                };
                return Ok(CoupledSolution {
                    edge,
                    error: diff,
                    delta,
                    discrete: Some(d),
                    order: n,
                });
            }
            if n == ORDERS[ORDERS.len() - 1] {
                return Err(Error::ToleranceNotMet {
                    estimate: diff,
                    tolerance: tol,
                    detail: format!("coupled: orders up to {n} per panel"),
                });
            }
        }
        prev = Some(t);
        slope = level.slope();
    }
    Err(Error::Internal("coupled: order loop fell through".into()))
}
