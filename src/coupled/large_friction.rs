//! The large-friction regime (mu~ -> infinity, THEORY.md sections 5 and 8): the stick edge
//! and the tractions are analytic in 1/mu~ there (the edge exponent g ~ 1 / (pi b* mu~)
//! enters through (x - c)^g = 1 + g ln(x - c) + ..., and on the slip zones q = mu p stays
//! finite while p = q / mu falls like 1/mu~). Measured with the panels at b* = 0.95:
//! c(1e8) - c(1e6) = 3.1331e-7 and c(1e10) - c(1e8) = 3.133e-9, a ratio of 100 to four
//! digits. The panels themselves lose the defect's sign beyond mu~ ~ 1e8 (g < 3e-9), so
//! above [`MU_EXTRAPOLATE`] the solution is the quadratic in 1/mu~ through the panels'
//! solutions at [`M`], 2 M and 4 M, evaluated at 1/mu~ (Lagrange weights, which add up to 1),
//! each solution taken in coordinates relative to its own stick edge (x c_i / c on the stick
//! zone, 1 - (1 - x) (1 - c_i) / (1 - c) on the slip zones), with p = q / mu~ on the slip
//! zones. Its model error is the distance from the line through 2 M and 4 M (the quadratic's
//! correction, a bound on its own error, which is of the next order in 1/M).

use super::{CoupledSolution, panels};
use crate::error::Result;
use crate::field::{Expand, Expansion, fitted_panel, graded_plain};
use crate::numerics::cauchy::Weight;
use crate::problem::{Coupling, Profile, StickEdge, traction_parts};

/// Reduced friction mu~ above which the solution is extrapolated.
pub(crate) const MU_EXTRAPOLATE: f64 = 1e7;

/// The lowest reduced friction the panels are solved at (then 2 M and 4 M).
const M: f64 = 1e6;

/// Share of the tolerances asked of each panel solution (the weights add up, in absolute
/// value, to at most 5 at mu~ = infinity).
const SHARE: f64 = 0.1;

/// The extrapolated solution.
#[derive(Clone, Debug)]
pub(crate) struct LargeFriction {
    coupling: Coupling,
    /// q = delta q~.
    delta: f64,
    /// The reduced friction mu~.
    mu: f64,
    /// The panels' solutions of the reduced problem at M, 2 M, 4 M.
    sols: Vec<CoupledSolution>,
    /// Lagrange weights in 1/mu~ at 1/mu~ of the quadratic (`quad`) and of the line through
    /// 2 M and 4 M (`line`).
    quad: [f64; 3],
    line: [f64; 3],
    edge: StickEdge,
    error: f64,
    traction_error: f64,
}

/// Lagrange weights at y of the polynomial through the nodes `nodes` (None: left out).
fn lagrange(y: f64, nodes: [Option<f64>; 3]) -> [f64; 3] {
    let mut w = [0.0; 3];
    for (i, wi) in w.iter_mut().enumerate() {
        let Some(yi) = nodes[i] else { continue };
        *wi = nodes
            .iter()
            .enumerate()
            .filter_map(|(j, yj)| yj.filter(|_| j != i))
            .map(|yj| (y - yj) / (yi - yj))
            .product();
    }
    w
}

/// The frictions whose stick edges are extrapolated: M, 2 M, 4 M.
pub(crate) const FRICTIONS: [f64; 3] = [M, 2.0 * M, 4.0 * M];

/// The stick edge at reduced friction `mu` extrapolated from the `edges` at [`FRICTIONS`]
/// (their errors `errors`): the edge, its error (the errors times the weights' magnitudes,
/// plus the distance from the line through 2 M and 4 M) and the Lagrange weights of the
/// quadratic and of the line.
pub(crate) fn extrapolate_edge(
    mu: f64,
    edges: [StickEdge; 3],
    errors: [f64; 3],
) -> (StickEdge, f64, [[f64; 3]; 2]) {
    let y = FRICTIONS.map(|m| Some(1.0 / m));
    let quad = lagrange(1.0 / mu, y);
    let line = lagrange(1.0 / mu, [None, y[1], y[2]]);
    let combine = |weights: [f64; 3], f: fn(&StickEdge) -> f64| -> f64 {
        weights.iter().zip(&edges).map(|(w, e)| w * f(e)).sum()
    };
    let (c, w) = (combine(quad, |e| e.c), combine(quad, |e| e.one_minus_c));
    let (edge, model) = if c < 0.5 {
        (StickEdge::from_c(c), (c - combine(line, |e| e.c)).abs())
    } else {
        let line_w = combine(line, |e| e.one_minus_c);
        (StickEdge::from_one_minus_c(w), (w - line_w).abs())
    };
    let own: f64 = quad.iter().zip(errors).map(|(q, e)| q.abs() * e).sum();
    (edge, own + model, [quad, line])
}

impl LargeFriction {
    /// The extrapolated solution of `k` (bp > 0, mu~ >= [`MU_EXTRAPOLATE`]) to tolerances
    /// `tol` on c and `traction_tol` on the tractions (what the panels reach is reported in
    /// the estimates; the caller compares).
    pub(crate) fn new(k: &Coupling, tol: f64, traction_tol: f64) -> Result<Self> {
        let (r, delta) = k.reduced();
        let sols = FRICTIONS
            .iter()
            .map(|&mu| {
                let at = Coupling { mu, ..r };
                panels(&at, SHARE * tol, SHARE * traction_tol / delta.max(1.0))
            })
            .collect::<Result<Vec<_>>>()?;
        let (edge, error, [quad, line]) = extrapolate_edge(
            r.mu,
            [0, 1, 2].map(|i| sols[i].edge),
            [0, 1, 2].map(|i| sols[i].error),
        );
        let combine = |weights: [f64; 3], f: &dyn Fn(&CoupledSolution) -> f64| {
            weights
                .iter()
                .zip(&sols)
                .map(|(w, s)| w * f(s))
                .sum::<f64>()
        };
        let own_tractions = combine(quad.map(f64::abs), &|s| s.traction_error);
        let line_edge = combine(line, &|s| s.edge.c);
        let mut s = LargeFriction {
            coupling: *k,
            delta,
            mu: r.mu,
            sols,
            quad,
            line,
            edge,
            error,
            traction_error: 0.0,
        };
        let (dp, dq) = traction_parts(
            |x| s.tractions(s.quad, x),
            |x| s.tractions(s.line, x),
            [edge.c, line_edge],
        );
        s.traction_error = own_tractions + dp + delta * dq;
        Ok(s)
    }

    /// (p, q) at 0 <= x < 1 of the combination with `weights` (its own stick edge).
    fn tractions(&self, weights: [f64; 3], x: f64) -> (f64, f64) {
        let pairs = || weights.iter().zip(&self.sols);
        let c: f64 = pairs().map(|(a, s)| a * s.edge.c).sum();
        let w: f64 = pairs().map(|(a, s)| a * s.edge.one_minus_c).sum();
        let stick = x < c;
        let (mut p, mut q) = (0.0, 0.0);
        for (a, s) in pairs() {
            let xi = if stick {
                x * s.edge.c / c
            } else {
                1.0 - (1.0 - x) * s.edge.one_minus_c / w
            };
            let (pi, qi) = s.half_line_tractions(xi);
            (p, q) = (p + a * pi, q + a * qi);
        }
        if !stick {
            p = q / self.mu;
        }
        (p, self.delta * q)
    }
}

impl Profile for LargeFriction {
    fn coupling(&self) -> Coupling {
        self.coupling
    }

    fn edge(&self) -> StickEdge {
        self.edge
    }

    fn numerical_error(&self) -> f64 {
        self.error
    }

    fn traction_error(&self) -> f64 {
        self.traction_error
    }

    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        self.tractions(self.quad, x)
    }
}

impl LargeFriction {
    /// The highest polynomial order per panel of the three panel solutions.
    pub(crate) fn order(&self) -> usize {
        self.sols.iter().map(|s| s.order).max().unwrap_or(0)
    }

    /// The unknowns of the largest of the three panel systems.
    pub(crate) fn unknowns(&self) -> usize {
        self.sols.iter().map(|s| s.unknowns()).max().unwrap_or(0)
    }
}

impl Expand for LargeFriction {
    /// Plain panels fitted to p and q, graded towards c from both sides ([`graded_plain`]: p
    /// and q are nearly logarithmic next to c, as g ~ 1e-8, with O(1) coefficients), and a
    /// last panel [(1 + c) / 2, 1] weighted (1 - t)^(-g). Not the sampling of the
    /// approximations ([`crate::field::sample`]), which writes q = mu p + R on the stick
    /// panel at c: with mu ~ 1e12 the difference q - mu p lost everything.
    fn expansion(&self) -> Expansion {
        let (c, w) = (self.edge.c, self.edge.one_minus_c);
        let x_of = |s: f64| c + s;
        let at = |s: f64| self.half_line_tractions(c + s);
        let mut panels = graded_plain(-c, x_of, at);
        panels.extend(graded_plain(0.5 * w, x_of, at));
        let g = self.coupling.edge_exponent();
        panels.push(fitted_panel(
            c + 0.5 * w,
            1.0,
            Weight::Right(-g),
            |omt, _| self.half_line_tractions(1.0 - 0.25 * w * omt),
        ));
        Expansion { panels }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupled::tests::check_solution;
    use crate::coupled::{Regime, solve_to};
    use crate::problem::traction_distance;

    /// Continuity at the switch: just above MU_EXTRAPOLATE the extrapolation, just below it
    /// the panels solved at mu~ itself (a different computation: one solve instead of three
    /// and no extrapolation) agree on c and on the tractions within their estimates.
    #[test]
    fn extrapolation_continues_the_panels() {
        for b in [0.6, 0.95] {
            let below = Coupling {
                bp: b,
                bq: b,
                mu: MU_EXTRAPOLATE * (1.0 - 1e-12),
            };
            let above = Coupling {
                mu: MU_EXTRAPOLATE,
                ..below
            };
            let p = solve_to(&below, 1e-10, 1e-10).unwrap();
            let l = solve_to(&above, 1e-10, 1e-10).unwrap();
            assert!(matches!(p.regime, Regime::Panels(_)));
            assert!(matches!(l.regime, Regime::LargeFriction(_)));
            let dc = (p.edge().c - l.edge().c).abs();
            let dt = traction_distance(&p, &l);
            println!(
                "b* {b}: c {:.13} vs {:.13}, |dc| {dc:.1e} (estimates {:.1e} + {:.1e}), traction distance {dt:.1e} (estimates {:.1e} + {:.1e})",
                p.edge().c,
                l.edge().c,
                p.numerical_error(),
                l.numerical_error(),
                p.traction_error(),
                l.traction_error()
            );
            assert!(dc <= p.numerical_error() + l.numerical_error());
            assert!(dt <= p.traction_error() + l.traction_error());
        }
    }

    /// Far beyond the panels' reach (mu~ = 1e12 and 1e100): (E1), (E2), the mass, Coulomb
    /// and the slip direction against the independent quadratures, and c non-decreasing in
    /// mu~ towards its limit.
    #[test]
    fn extrapolation_solves_the_equations() {
        for b in [0.6, 0.95] {
            let mut last = 0.0;
            for mu in [1e7, 1e12, 1e100] {
                let k = Coupling { bp: b, bq: b, mu };
                let s = solve_to(&k, 1e-10, 1e-10).unwrap();
                assert!(s.numerical_error() <= 1e-10 && s.traction_error() <= 1e-10);
                let worst = check_solution(&k, &s);
                let c = s.edge().c;
                println!("b* {b} mu~ {mu:e}: c = {c:.13}, worst residual {worst:.1e}");
                assert!(c >= last - 1e-10, "c = {c} below {last}");
                last = c;
            }
        }
    }
}
