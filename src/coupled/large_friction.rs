//! The large-friction regime (mu~ -> infinity, docs/theory.md §6 and (K6)): the stick edge
//! and the tractions are analytic in 1/mu~ there (the edge exponent g ~ 1 / (pi b* mu~)
//! enters through (x - c)^g = 1 + g ln(x - c) + ..., and on the slip zones q = mu p stays
//! finite while p = q / mu falls like 1/mu~). Measured with the panels at b* = 0.95:
//! c(1e8) - c(1e6) = 3.1331e-7 and c(1e10) - c(1e8) = 3.133e-9, a ratio of 100 to four
//! digits. The panels themselves lose the defect's sign beyond mu~ ~ 1e8 (g < 3e-9), so
//! above [`MU_EXTRAPOLATE`] the solution is the quadratic in 1/mu~ through the panels'
//! solutions at M, 2 M and 4 M ([`M`]), evaluated at 1/mu~ (Lagrange weights, which add up
//! to 1), each solution taken in coordinates relative to its own stick edge (x c_i / c on the
//! stick zone, 1 - (1 - x) (1 - c_i) / (1 - c) on the slip zones), with p = q / mu~ on the
//! slip zones. Its model error is the distance from the line through 2 M and 4 M (the
//! quadratic's correction, a bound on its own error, which is of the next order in 1/M).
//!
//! COUPLED tries first the same extrapolation from four spectral solutions at lower friction
//! ([`spectral_nodes`], [`LargeFriction::from_nodes`]) wherever g is below the spectral bases'
//! smallest (`spectral::G_MIN`); the panels' nodes below serve where those do not answer.
//!
//! Thin slip zones (1 - c below about 1e-15, b* <~ 0.13) lose the panels' root search much
//! earlier, once g < 1e-3 (b* = 0.1: mu~ >= 4.6e3, 1 - c ~ 1.4e-20; b* = 0.12: mu~ >= 2e5).
//! There the same extrapolation runs from [`thin_base`], whose 4 M has g = [`THIN_NODE_G`].
//! Its error stays small although 1/M is not: the tractions outside the slip layer are the
//! bonded punch's whatever mu~ (`near_bonded`), and 1 - c = 8 exp(-kappa arctan(mu~) / eps)
//! moves by a few per cent from 4 M to infinity (b* = 0.1: 1.4159e-20 at mu~ = 1e3,
//! 1.3934e-20 at 1e6).

use super::{CoupledSolution, node_solve, panels_or_auxetic};
use crate::error::Result;
use crate::field::{Expand, Expansion, fitted_panel, graded_plain};
use crate::numerics::cauchy::Weight;
use crate::problem::{Coupling, Profile, StickEdge, traction_parts};

/// Reduced friction mu~ above which the solution is extrapolated.
pub(crate) const MU_EXTRAPOLATE: f64 = 1e7;

/// The lowest reduced friction the panels are solved at (then 2 M and 4 M).
pub(crate) const M: f64 = 1e6;

/// Thin slip zones: the edge exponent g at the highest node 4 M of [`thin_base`]; the thin
/// windows' root search is reliable from g ~ 1e-3 up (b* = 0.1 solved at mu~ = 2.2e3, g =
/// 1.5e-3).
const THIN_NODE_G: f64 = 1.5e-3;

/// The lowest node M for thin slip zones at b*: 4 M is where g = arctan(1 / (b* 4 M)) / pi
/// equals [`THIN_NODE_G`] (b* = 0.1: M = 530; b* = 0.12: 442).
pub(crate) fn thin_base(b: f64) -> f64 {
    0.25 / (b * (std::f64::consts::PI * THIN_NODE_G).tan())
}

/// The reduced frictions the panels are solved at: M, 2 M, 4 M.
pub(crate) fn nodes(m: f64) -> [f64; 3] {
    [m, 2.0 * m, 4.0 * m]
}

/// Share of the tolerances asked of each node's solution (the weights add up, in absolute
/// value, to at most 5 at mu~ = infinity for the three nodes M, 2 M, 4 M, to 6.4 for the four
/// of [`spectral_nodes`]).
pub(crate) const SHARE: f64 = 0.1;

/// The edge exponent g at the highest of the spectral nodes ([`spectral_nodes`]), above the
/// bases' smallest (`spectral::G_MIN` = 3e-5). Measured with the four nodes at b* = 0.5 and
/// 0.95 (c to 1e-11 and tractions to 1e-9 at each node; reference: this regime's panel
/// extrapolation from mu~ = 1e6 at mu~ = 1e8, estimates 3.4e-15 and 2.5e-14), the cubic's
/// distance from the reference in 1 - c and its model error (the distance from the quadratic
/// through the upper three nodes) at mu~ = 1e8:
///
/// | g at 8 M | b* = 0.5: cubic, model | b* = 0.95: cubic, model |
/// |---|---|---|
/// | 4e-5 | 5.7e-15, 7.8e-14 | 1.6e-15, 2.4e-12 |
/// | 1e-4 | 3.0e-15, 1.2e-12 | 7.6e-14, 3.8e-11 |
///
/// (at 4e-5 the nodes at b* = 0.5 asked to 1e-12 went to the panels). The model error grows
/// like the cube of the lowest node's 1/mu~; 5e-5 keeps it near 5e-12 with the highest node
/// a step above the bases' limit.
const SPECTRAL_NODE_G: f64 = 5e-5;

/// The four reduced frictions M, 2 M, 4 M, 8 M of the extrapolation from spectral solutions
/// at b*, 8 M where g = [`SPECTRAL_NODE_G`] (b* = 0.5: M = 796).
pub(crate) fn spectral_nodes(b: f64) -> [f64; 4] {
    let top = 1.0 / (b * (std::f64::consts::PI * SPECTRAL_NODE_G).tan());
    [0.125 * top, 0.25 * top, 0.5 * top, top]
}

/// The extrapolated solution.
#[derive(Clone, Debug)]
pub(crate) struct LargeFriction {
    coupling: Coupling,
    /// q = delta q~.
    delta: f64,
    /// The reduced friction mu~.
    mu: f64,
    /// The solutions of the reduced problem at the nodes.
    sols: Vec<CoupledSolution>,
    /// Lagrange weights in 1/mu~ at 1/mu~ of the polynomial through all nodes (`all`) and
    /// through all but the lowest (`upper`).
    all: Vec<f64>,
    upper: Vec<f64>,
    edge: StickEdge,
    error: f64,
    traction_error: f64,
}

/// Lagrange weights at y of the polynomial through the nodes `nodes` (None: left out).
pub(crate) fn lagrange<const N: usize>(y: f64, nodes: [Option<f64>; N]) -> [f64; N] {
    let mut w = [0.0; N];
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

/// The stick edge at reduced friction `mu` extrapolated from the `edges` at the reduced
/// frictions `mus` (their errors `errors`), the polynomial in 1/mu~ through all of them: the
/// edge, its error (the errors times the weights' magnitudes, plus the distance from the
/// polynomial through all nodes but the lowest) and the Lagrange weights of both.
pub(crate) fn extrapolate_edge<const N: usize>(
    mu: f64,
    mus: [f64; N],
    edges: [StickEdge; N],
    errors: [f64; N],
) -> (StickEdge, f64, [[f64; N]; 2]) {
    let y = mus.map(|m| Some(1.0 / m));
    let all = lagrange(1.0 / mu, y);
    let mut above = y;
    above[0] = None;
    let upper = lagrange(1.0 / mu, above);
    let combine = |weights: [f64; N], f: fn(&StickEdge) -> f64| -> f64 {
        weights.iter().zip(&edges).map(|(w, e)| w * f(e)).sum()
    };
    let (c, w) = (combine(all, |e| e.c), combine(all, |e| e.one_minus_c));
    let (edge, model) = if c < 0.5 {
        (StickEdge::from_c(c), (c - combine(upper, |e| e.c)).abs())
    } else {
        let upper_w = combine(upper, |e| e.one_minus_c);
        (StickEdge::from_one_minus_c(w), (w - upper_w).abs())
    };
    let own: f64 = all.iter().zip(errors).map(|(q, e)| q.abs() * e).sum();
    (edge, own + model, [all, upper])
}

impl LargeFriction {
    /// The solution of `k` (bp > 0, mu~ > 4 `m`) extrapolated from the nodes `m`, 2 `m`,
    /// 4 `m` to tolerances `tol` on c and `traction_tol` on the tractions (what the panels
    /// reach is reported in the estimates; the caller compares).
    pub(crate) fn new(k: &Coupling, m: f64, tol: f64, traction_tol: f64) -> Result<Self> {
        let (r, delta) = k.reduced();
        let mus = nodes(m);
        let sols = mus
            .iter()
            .map(|&mu| {
                let at = Coupling { mu, ..r };
                node_solve(
                    &at,
                    SHARE * tol,
                    SHARE * traction_tol / delta.max(1.0),
                    panels_or_auxetic,
                )
            })
            .collect::<Result<Vec<_>>>()?;
        let sols: [CoupledSolution; 3] = sols.try_into().expect("three nodes");
        Ok(Self::from_nodes(k, mus, sols))
    }

    /// The solution of `k` (bp > 0) extrapolated from the reduced problem's solutions `sols`
    /// at the reduced frictions `mus` (increasing, below k's): the polynomial in 1/mu~ through
    /// all of them, its error estimates the distance from the polynomial through all but the
    /// lowest node, plus the nodes' own estimates times the weights' magnitudes.
    pub(crate) fn from_nodes<const N: usize>(
        k: &Coupling,
        mus: [f64; N],
        sols: [CoupledSolution; N],
    ) -> Self {
        let (r, delta) = k.reduced();
        let (edge, error, [all, upper]) = extrapolate_edge(
            r.mu,
            mus,
            std::array::from_fn(|i| sols[i].edge),
            std::array::from_fn(|i| sols[i].error),
        );
        let combine = |weights: &[f64], f: &dyn Fn(&CoupledSolution) -> f64| {
            weights
                .iter()
                .zip(&sols)
                .map(|(w, s)| w * f(s))
                .sum::<f64>()
        };
        let abs: Vec<f64> = all.iter().map(|w| w.abs()).collect();
        let own_tractions = combine(&abs, &|s| s.traction_error);
        let upper_edge = combine(&upper, &|s| s.edge.c);
        let mut s = LargeFriction {
            coupling: *k,
            delta,
            mu: r.mu,
            sols: sols.into(),
            all: all.into(),
            upper: upper.into(),
            edge,
            error,
            traction_error: 0.0,
        };
        let (dp, dq) = traction_parts(
            |x| s.tractions(&s.all, x),
            |x| s.tractions(&s.upper, x),
            [edge.c, upper_edge],
        );
        s.traction_error = own_tractions + dp + delta * dq;
        s
    }

    /// (p, q) at 0 <= x < 1 of the combination with `weights` (its own stick edge). Next to
    /// x = 1 the points are placed by u = 1 - x: in thin slip zones c and the c_i
    /// round to 1, and the combinations' c, off by a few ulps of 1, would move x c_i / c by
    /// several layer widths (u_i = (c_i u + w_i - w) / c there instead).
    fn tractions(&self, weights: &[f64], x: f64) -> (f64, f64) {
        let pairs = || weights.iter().zip(&self.sols);
        let c: f64 = pairs().map(|(a, s)| a * s.edge.c).sum();
        let w: f64 = pairs().map(|(a, s)| a * s.edge.one_minus_c).sum();
        let u = 1.0 - x;
        let stick = if x < 0.5 { x < c } else { u > w };
        let (mut p, mut q) = (0.0, 0.0);
        for (a, s) in pairs() {
            let (ci, wi) = (s.edge.c, s.edge.one_minus_c);
            let mut xi = if !stick {
                1.0 - u * wi / w
            } else if x < 0.5 {
                x * ci / c
            } else {
                1.0 - (ci * u + (wi - w)) / c
            };
            if ci > 0.0 && ci < 1.0 {
                // x's side of the combination's edge is each solution's side of its own
                // edge. The maps round: in a slip zone 1e-8 wide (b* = 0.22, mu~ = inf) x = c
                // went one ulp past c_i and mixed p = q / mu_i of the slip side into the stick
                // side's p (p = -1024 at x = c). Exactly at c_i the slip panel's (x - c)^g
                // weights vanish (g ~ 1e-7: they reach 1/2 only 1e-(3e6) from c) and q = mu_i p
                // jumps to mu_i times the stick side's p (p = -0.24 at x = c, b* = 0.89,
                // mu~ = 1e7). So the next double on x's side at the least.
                xi = if stick {
                    xi.min(ci.next_down())
                } else {
                    xi.max(ci.next_up())
                };
            }
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
        self.tractions(&self.all, x)
    }
}

impl LargeFriction {
    /// The highest order (panels: polynomial order per panel; spectral: level) of the node
    /// solutions.
    pub(crate) fn order(&self) -> usize {
        self.sols.iter().map(|s| s.order).max().unwrap_or(0)
    }

    /// The unknowns of the largest of the node solutions' systems.
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
    use crate::coupled::{Regime, solve_panels_to, solve_to};
    use crate::problem::traction_distance;

    /// Continuity at a switch mu~ = `at` of the panels' regimes (`solve_panels_to`; COUPLED
    /// extrapolates from spectral nodes there, [`LargeFriction::from_nodes`]): just below it
    /// the panels solved at mu~ itself, just above it the extrapolation (a different
    /// computation: one solve instead of three and no extrapolation) agree on c and on the
    /// tractions within their estimates.
    fn continuous_at(b: f64, at: f64) {
        let below = Coupling {
            bp: b,
            bq: b,
            mu: at * (1.0 - 1e-12),
        };
        let above = Coupling {
            mu: at * (1.0 + 1e-12),
            ..below
        };
        let p = solve_panels_to(&below, 1e-10, 1e-10).unwrap();
        let l = solve_panels_to(&above, 1e-10, 1e-10).unwrap();
        assert!(matches!(p.regime, Regime::Panels(_)));
        assert!(matches!(l.regime, Regime::LargeFriction(_)));
        let dc = (p.edge().c - l.edge().c).abs();
        let dw = (p.edge().one_minus_c - l.edge().one_minus_c).abs();
        let dt = traction_distance(&p, &l);
        println!(
            "b* {b}: 1 - c {:.6e} vs {:.6e}, |dc| {dw:.1e} (estimates {:.1e} + {:.1e}), \
             traction distance {dt:.1e} (estimates {:.1e} + {:.1e})",
            p.edge().one_minus_c,
            l.edge().one_minus_c,
            p.numerical_error(),
            l.numerical_error(),
            p.traction_error(),
            l.traction_error()
        );
        assert!(dc.min(dw) <= p.numerical_error() + l.numerical_error());
        assert!(dt <= p.traction_error() + l.traction_error());
    }

    /// Continuity at MU_EXTRAPOLATE.
    #[test]
    fn extrapolation_continues_the_panels() {
        for b in [0.6, 0.95] {
            continuous_at(b, MU_EXTRAPOLATE);
        }
    }

    /// Continuity where thin slip zones switch to the extrapolation from [`thin_base`]: g =
    /// SMALL_G at b* = 0.12 (mu~ = 2.65e3, 1 - c = 5.4e-17, nodes 442 .. 1768).
    #[test]
    #[ignore = "slow tier: the thin-slip switch to the extrapolation, 1 - c = 5.4e-17 (panels up to mu~ = 1768)"]
    fn thin_extrapolation_continues_the_panels() {
        let b = 0.12;
        continuous_at(
            b,
            1.0 / (b * (std::f64::consts::PI * crate::coupled::SMALL_G).tan()),
        );
    }

    /// Far beyond the panels' reach (mu~ = 1e12 and 1e100): (E1), (E2), the mass, Coulomb
    /// and the slip direction against the independent quadratures, and c non-decreasing in
    /// mu~ towards its limit. The fast tier at b* = 0.95
    /// ([`extrapolation_solves_the_equations_wide`]: also 0.6).
    #[test]
    fn extrapolation_solves_the_equations() {
        extrapolation_solves_the_equations_at(&[0.95]);
    }

    #[test]
    #[ignore = "slow tier: the extrapolation in 1/mu~ against the quadratures at two b*"]
    fn extrapolation_solves_the_equations_wide() {
        extrapolation_solves_the_equations_at(&[0.6, 0.95]);
    }

    /// Each node is read on x's side of its own stick edge: at a thin slip zone (b* = 0.222,
    /// mu~ = infinity, 1 - c = 1.0e-8, the hostile C draw that found it) the doubles next to
    /// c give p > 0 on the stick side and p = q / mu~ = 0 on the slip side (at c itself
    /// either), q finite and p, q even and odd.
    #[test]
    fn points_next_to_the_edge_keep_their_side() {
        let k = Coupling {
            bp: 0.8118278966658558,
            bq: 0.060706390274337586,
            mu: f64::MAX,
        };
        let s = solve_to(&k, 8.5e-8, 7.2e-6).unwrap();
        let c = s.edge().c;
        assert!(
            s.edge().one_minus_c < 1e-7,
            "1 - c = {}",
            s.edge().one_minus_c
        );
        let mut x = c.next_down().next_down();
        for _ in 0..5 {
            let (p, q) = s.half_line_tractions(x);
            let (pm, qm) = s.tractions(-x);
            println!("x = c + {:.1e}: p = {p}, q = {q}", x - c);
            assert!(p.is_finite() && q.is_finite());
            // at x = c itself either side's limit
            assert!(
                if x < c {
                    p > 0.0
                } else if x > c {
                    p == 0.0
                } else {
                    p >= 0.0
                },
                "p = {p} at x - c = {:e}",
                x - c
            );
            assert!(pm == p && qm == -q);
            x = x.next_up();
        }
    }

    fn extrapolation_solves_the_equations_at(b_star: &[f64]) {
        for &b in b_star {
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
