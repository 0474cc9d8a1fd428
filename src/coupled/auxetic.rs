//! The auxetic limit b* -> 1 (an isotropic solid with nu -> -1; docs/theory.md (L3), (L5): the
//! oscillation index eps = artanh(b*) / pi grows without bound). There the stick zone closes
//! like a power of s = 1 - b*,
//!   c = K(s) s^(1/k0),  k0 = 2 arctan(b* mu~) / pi = 1 - 2 g,
//! with K smooth in s (measured with the panels' root search: K = 11.817 at mu~ = 1, 5.270 at
//! 10, 4.966 at 100, 4.938 at 1e3, 4.935 at 1e6, changing by 3e-5 relative or less from
//! s = 1e-4 to 4e-4; taken with k0 at b* = 1, the same data gave a K that bends like s ln s).
//! It has the exponent of the full-slip law c ~ 4 (1 - b*^2)^(pi / (2 b* mu~)) as mu~ -> 0
//! ([`super::full_slip`]); c / (4 (2 s)^(1/k0)) = 0.62 .. 0.74 over mu~ = 1 .. 1e6.
//!
//! The panels' root search loses its way as s -> 0 (from s ~ 1e-6 on: spurious roots with
//! p < 0, or sign changes that move with the layout), and the tractions become
//! ill-conditioned: they move by about 4 / s (mu~ = 10) to 11 / s (mu~ = 100) per unit change
//! of b*, so that one rounding of b* (1.1e-16) moves them by 5e-16 / s .. 1.2e-15 / s, and the
//! panels at a given c reach traction estimates of about 5e-15 / s at best (s = 1e-5: 5e-10;
//! 1e-7: 2e-8 .. 5e-8; 1e-10: 6e-5).
//!
//! So above b* = 1 - [`S_AUX`] the stick edge is extrapolated: K at the nodes s = S_AUX,
//! 2 S_AUX, 4 S_AUX, 8 S_AUX (c alone from the panels, to the relative accuracy the
//! tractions need, [`node_relative`]), the cubic in s through them, times s^(1/k0); its
//! error is the nodes' errors carried over plus the distance from the quadratic through the
//! upper three nodes (the quadratic through three nodes, with the distance from a line as
//! its error, left 7e-11 in c from nodes at s = 1e-4 .. 4e-4 to s = 5e-5, mu~ = 1e3: too
//! much for the tractions to 1e-10, which move by mu p(c) dc there). Then the root search
//! runs inside a window around that c ([`super::panels_in_window`]) and is taken where it
//! agrees with it within both estimates and meets the tolerances (closer to S_AUX it is the
//! more accurate); else the tractions are the panels' at the extrapolated c, without root
//! search ([`super::panels_at_edge`]), with their estimate. Tolerances below their reach are
//! reported as not met, with the conditioning as the reason. With c alone asked for and no
//! admissible panel solution at c, the full-slip tractions come with it
//! ([`super::full_slip`]), their estimate +infinity.

use super::full_slip::FullSlip;
use super::large_friction::lagrange;
use super::{
    CoupledSolution, Regime, Sensitivity, node_solve, panel_regimes, panels_at_edge,
    panels_in_window,
};
use crate::error::{Error, Result};
use crate::problem::{Coupling, StickEdge};

/// 1 - b* of the lowest node: above b* = 1 - S_AUX the stick edge is extrapolated. At
/// s = 1e-5 .. 5e-5 the panels' root search still finds c, to 1e-10 with or without the
/// tractions, at mu~ = 0.3 .. 1e6 (0.1-6 s), and the tractions to 1e-8 (to 1e-10 at some
/// mu~, where the conditioning allows); at s = 1e-6 it fails at mu~ = 1e6 (a spurious root
/// with p < 0), at 1e-7 from mu~ = 1 on. Its c is also what the tractions need: extrapolated
/// from s = 1e-4 .. 8e-4 to 5e-5 (mu~ = 10), c was 7.5e-10 off relative, and the wrong-c modes
/// that left in the tractions weighed 3.5e-9.
pub(crate) const S_AUX: f64 = 1e-5;

/// The nodes' b* (the first one bounds the regime: the nodes themselves lie outside it).
fn node_b() -> [f64; 4] {
    [1.0, 2.0, 4.0, 8.0].map(|m| 1.0 - m * S_AUX)
}

/// Relative accuracy of the nodes' c (K carries it over to c at any s below S_AUX) for
/// traction tolerance `traction_tol`: the wrong-c modes that an error in c leaves in the
/// tractions weigh about 5 times its relative size (s = 5e-5, mu~ = 10: 3.5e-9 for 7.5e-10),
/// so [`super::TRACTION_PER_C`] times below the traction tolerance, within 1e-11 (the nodes'
/// rounding) and 1e-6 (c alone).
fn node_relative(traction_tol: f64) -> f64 {
    (traction_tol / super::TRACTION_PER_C).clamp(1e-11, 1e-6)
}

/// Share of the tolerance on c left to the nodes' errors.
const SHARE: f64 = 0.1;

/// Whether the reduced coupling `r` lies in the auxetic limit (b* above the lowest node).
pub(crate) fn applies(r: &Coupling) -> bool {
    r.bp > node_b()[0]
}

/// The exponent 1/k0 = 1 / (1 - 2 g) of the law at the reduced coupling `r`.
fn exponent(r: &Coupling) -> f64 {
    1.0 / (1.0 - 2.0 * r.edge_exponent())
}

/// The nodes' reduced couplings: b* = 1 - s at s = S_AUX, 2 S_AUX, 4 S_AUX, 8 S_AUX, the
/// friction of `r`.
pub(crate) fn nodes(r: &Coupling) -> [Coupling; 4] {
    node_b().map(|b| Coupling { bp: b, bq: b, ..*r })
}

/// The Lagrange weights at s of the cubic through the nodes and of the quadratic through the
/// upper three (0 at the lowest).
fn weights(s: f64) -> ([f64; 4], [f64; 4]) {
    let ys = node_b().map(|b| 1.0 - b);
    (
        lagrange(s, ys.map(Some)),
        lagrange(s, [None, Some(ys[1]), Some(ys[2]), Some(ys[3])]),
    )
}

/// The stick edge of the reduced coupling `r` ([`applies`]) and its error from the nodes'
/// stick zones `c` ([`nodes`]) and their errors: K = c / s^(1/k0) at the nodes, the cubic
/// through them at s = 1 - b*, times s^(1/k0); the error is the nodes' errors carried over
/// plus the cubic's distance from the quadratic through the upper three.
pub(crate) fn extrapolate(r: &Coupling, c: [f64; 4], c_error: [f64; 4]) -> (StickEdge, f64) {
    let s = 1.0 - r.bp;
    let scale = s.powf(exponent(r));
    let (cubic, quad) = weights(s);
    let node_scale = nodes(r).map(|n| (1.0 - n.bp).powf(exponent(&n)));
    let k: [f64; 4] = std::array::from_fn(|i| c[i] / node_scale[i]);
    let k_error: [f64; 4] = std::array::from_fn(|i| c_error[i] / node_scale[i]);
    let dot = |w: [f64; 4], v: [f64; 4]| -> f64 { w.iter().zip(v).map(|(a, b)| a * b).sum() };
    let (k_cubic, k_quad) = (dot(cubic, k), dot(quad, k));
    let error = (dot(cubic.map(f64::abs), k_error) + (k_cubic - k_quad).abs()) * scale;
    (StickEdge::from_c(k_cubic * scale), error)
}

/// The stick edge of the reduced coupling `r` ([`applies`]) and its error ([`extrapolate`]),
/// with the nodes' c solved by the panels to their share of `tol` and to
/// [`node_relative`]`(traction_tol)`.
fn extrapolated_edge(r: &Coupling, tol: f64, traction_tol: f64) -> Result<(StickEdge, f64)> {
    let scale = (1.0 - r.bp).powf(exponent(r));
    let (cubic, quad) = weights(1.0 - r.bp);
    // what an error in the nodes' K moves the cubic and its distance from the quadratic by
    let spread: f64 = cubic
        .iter()
        .zip(quad)
        .map(|(a, b)| a.abs() + (a - b).abs())
        .sum();
    let (mut c, mut c_error) = ([0.0; 4], [0.0; 4]);
    for (i, node) in nodes(r).iter().enumerate() {
        let node_scale = (1.0 - node.bp).powf(exponent(node));
        // c is below 4 (2 s)^(1/k0) (measured: 0.62 .. 0.74 of it)
        let c_above = 4.0 * 2f64.powf(exponent(node)) * node_scale;
        let node_tol = (SHARE * tol * node_scale / (scale * spread))
            .min(node_relative(traction_tol) * c_above)
            .min(0.5);
        let sol = node_solve(node, node_tol, f64::INFINITY, panel_regimes)?;
        c[i] = sol.edge.c;
        c_error[i] = sol.error;
    }
    Ok(extrapolate(r, c, c_error))
}

/// Half-width in lc = ln(c / (1 - c)) of the window around the extrapolated c in which the
/// root search is tried: wide enough for the low orders' roots (order 8: within 1e-3 of the
/// last order's c at s = 1e-5), narrow enough to hold no other root.
const WINDOW: f64 = 0.05;

/// The solution of `k` in the auxetic limit ([`applies`] to its reduced coupling): the
/// extrapolated c to `tol`; then the root search inside a window around it, taken where it
/// agrees with the extrapolation within both estimates and meets both tolerances (it is
/// more accurate where it works: at s = 9e-6, mu~ = 1e6 the tractions at the extrapolated
/// c, 7e-13 off, came to 1.7e-7, the search's to 1e-8); else the panels' tractions at the
/// extrapolated c towards `traction_tol`. What misses the tolerances is returned with its
/// estimates (the smaller traction estimate of the two): the caller compares, as for the
/// panels.
pub(crate) fn solve(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    let (r, _) = k.reduced();
    let (edge, error) = extrapolated_edge(&r, tol, traction_tol)?;
    let lc = edge.logit();
    let search = panels_in_window(k, tol, traction_tol, (lc - WINDOW, lc + WINDOW))
        .filter(|s| (s.edge.c - edge.c).abs() <= s.error + error);
    if let Some(s) = &search
        && s.error <= tol
        && s.traction_error <= traction_tol
    {
        return Ok(search.unwrap());
    }
    let fixed = panels_at_edge(k, edge, error, traction_tol, Sensitivity::AtFinalOrder);
    match (search, fixed) {
        (Some(a), Some(b)) => Ok(if a.traction_error < b.traction_error {
            a
        } else {
            b
        }),
        (Some(s), None) | (None, Some(s)) => Ok(s),
        (None, None) if traction_tol == f64::INFINITY => Ok(CoupledSolution {
            coupling: *k,
            edge,
            error,
            traction_error: f64::INFINITY,
            delta: 1.0,
            regime: Regime::FullSlip(FullSlip::with_edge(k, edge.c)),
            order: 0,
        }),
        (None, None) => Err(Error::ToleranceNotMet {
            estimate: f64::INFINITY,
            tolerance: traction_tol,
            detail: format!(
                "coupled: the panels at c = {:e} give no admissible tractions; {}",
                edge.c,
                conditioning(&r)
            ),
        }),
    }
}

/// Why the tractions near the auxetic limit stop short of a tolerance: the conditioning in
/// b* (module documentation), for the reduced coupling `r`.
pub(crate) fn conditioning(r: &Coupling) -> String {
    let s = 1.0 - r.bp;
    format!(
        "b* = 1 - {s:.2e} lies within {s:.1e} of the auxetic limit b* = 1, where the tractions \
         move by about 10 / (1 - b*) per unit change of b* (one rounding of b* moves them by \
         ~{:.0e}), and the panels reach about {:.0e}",
        1e-15 / s,
        5e-15 / s
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupled::{panels, solve_to};
    use crate::problem::{Profile, traction_distance};

    fn at(s: f64, mu: f64) -> Coupling {
        Coupling {
            bp: 1.0 - s,
            bq: 1.0 - s,
            mu,
        }
    }

    /// The extrapolated c and the panels' tractions at it (no root search) against the
    /// panels' root search at s itself (s = 2e-6, where it still finds c for these
    /// frictions), both asked for the tractions to 1e-8 (the panels at the extrapolated c
    /// reach 2.4e-8 at mu~ = 100, the search 6.5e-9): they agree on c and on the tractions
    /// within the two estimates. (The quadrature residuals of [`check_solution`] are not
    /// asked for: pointwise, (E2) on the stick zone, 1e-11 wide at mu~ = 1, holds only to
    /// 2e-6 of its terms, as the conditioning leaves it.)
    #[test]
    #[ignore = "slow tier: five frictions, extrapolation against the root search at b* = 1 - 2e-6"]
    fn extrapolated_edge_matches_the_root_search() {
        for mu in [1.0, 10.0, 100.0, 1e3, 1e5] {
            let k = at(2e-6, mu);
            assert!(applies(&k));
            let (edge, error) = extrapolated_edge(&k, 1e-12, 1e-8).unwrap();
            let fixed = panels_at_edge(&k, edge, error, 1e-8, Sensitivity::AtFinalOrder).unwrap();
            let search = panels(&k, 1e-12, 1e-8).unwrap();
            let (a, b) = (edge.c, search.edge().c);
            let dt = traction_distance(&fixed, &search);
            println!(
                "mu~ {mu}: c {a:.12e} (extrapolated, {error:.1e}) vs {b:.12e} (search, {:.1e}); \
                 traction distance {dt:.1e} (estimates {:.1e} + {:.1e})",
                search.numerical_error(),
                fixed.traction_error(),
                search.traction_error()
            );
            assert!((a - b).abs() <= error + search.numerical_error());
            assert!(dt <= fixed.traction_error() + search.traction_error());
        }
    }

    /// At the lowest node itself (s = S_AUX, the last b* the root search takes) the
    /// extrapolation and the root search agree on c and on the tractions within their
    /// estimates; the next double of b* is the extrapolation's.
    #[test]
    #[ignore = "slow tier: continuity at the lowest auxetic node, two frictions"]
    fn continuous_at_the_lowest_node() {
        for mu in [3.0, 100.0] {
            let k = at(S_AUX, mu);
            let k = Coupling {
                bp: node_b()[0],
                bq: node_b()[0],
                ..k
            };
            let next = Coupling {
                bp: k.bp.next_up(),
                bq: k.bq.next_up(),
                ..k
            };
            assert!(!applies(&k) && applies(&next));
            let p = solve_to(&k, 1e-12, 1e-8).unwrap();
            let x = solve(&k, 1e-12, 1e-8).unwrap();
            let dc = (p.edge().c - x.edge().c).abs();
            let dt = traction_distance(&p, &x);
            println!(
                "mu~ {mu}: |dc| {dc:.1e} (estimates {:.1e} + {:.1e}), traction distance \
                 {dt:.1e} (estimates {:.1e} + {:.1e})",
                p.numerical_error(),
                x.numerical_error(),
                p.traction_error(),
                x.traction_error()
            );
            assert!(dc <= p.numerical_error() + x.numerical_error());
            assert!(dt <= p.traction_error() + x.traction_error());
        }
    }

    /// The conditioning that limits the tractions (module documentation): between b* and a
    /// b* moved by 1e-3 s the tractions (each to 1e-7) move by 2 / s .. 20 / s per unit of b*
    /// (s = 1e-6, mu~ = 10 and 100), and a traction tolerance far below what that leaves
    /// (1e-12) is refused as not met, naming the auxetic limit, never as no convergence.
    #[test]
    #[ignore = "slow tier: the conditioning in b* at s = 1e-6, two frictions"]
    fn tractions_are_ill_conditioned_in_b() {
        let s = 1e-6;
        for mu in [10.0, 100.0] {
            let (k, moved) = (at(s, mu), at(s * (1.0 + 1e-3), mu));
            let a = solve_to(&k, 1e-12, 1e-7).unwrap();
            let b = solve_to(&moved, 1e-12, 1e-7).unwrap();
            let per_b = traction_distance(&a, &b) / (1e-3 * s);
            println!("mu~ {mu}: d tractions / d b* = {:.2} / s", per_b * s);
            assert!((2.0..=20.0).contains(&(per_b * s)), "{per_b:e}");
            match solve_to(&k, 1e-10, 1e-12) {
                Err(Error::ToleranceNotMet { detail, .. }) => {
                    assert!(detail.contains("auxetic limit"), "{detail}")
                }
                other => panic!("{other:?}"),
            }
        }
    }

    /// c alone down to the last double below b* = 1 (s = 1.1e-16) and up to mu~ = 1e12: an
    /// answer, 0 < c below the full-slip law 4 (1 - b*^2)^(pi / (2 b* mu~)) (which bounds c
    /// wherever measured), non-decreasing in mu~. A friction's nodes asked to the same
    /// tolerance at another s (their tolerance is set by the relative accuracy of c alone at
    /// the two smallest s) are solved once (`coupled::tests::memo_node`).
    #[test]
    #[ignore = "slow tier: c alone down to b* = 1 - 1.1e-16 and up to mu~ = 1e12"]
    fn c_alone_up_to_the_last_double_below_one() {
        for s in [1e-7, 1e-13, f64::EPSILON / 2.0] {
            let mut last = 0.0;
            // mu~ = 1e12 (each node extrapolated in 1/mu~ as well, 15-25 s) at the last s only
            let frictions: &[f64] = if s > f64::EPSILON {
                &[1.0, 10.0, 1e3, 1e6]
            } else {
                &[1.0, 10.0, 1e3, 1e6, 1e12]
            };
            for &mu in frictions {
                let k = at(s, mu);
                let sol = solve_to(&k, 1e-10, f64::INFINITY).unwrap();
                let c = sol.edge().c;
                let bound = crate::coupled::full_slip::ln_c_law(&k).exp();
                println!("s {s:e} mu~ {mu:e}: c {c:.6e} (bound {bound:.1e})");
                assert!(c > 0.0 && c <= bound && sol.numerical_error() <= 1e-10);
                assert!(c >= last * (1.0 - 1e-9), "c = {c:e} below {last:e}");
                last = c;
            }
        }
    }

    /// The fast tier's auxetic scene (the sweeps above are the slow tier's): b* = 1 - 1e-6,
    /// mu~ = 10 through the auxetic regime, c alone (the extrapolated c, 0 < c below the
    /// full-slip law) and with the tractions to 1e-7 (the panels at that c), which agree with
    /// it on c.
    #[test]
    fn one_auxetic_scene() {
        let k = at(1e-6, 10.0);
        assert!(applies(&k));
        let alone = solve_to(&k, 1e-10, f64::INFINITY).unwrap();
        let c = alone.edge().c;
        let bound = crate::coupled::full_slip::ln_c_law(&k).exp();
        assert!(
            c > 0.0 && c <= bound && alone.numerical_error() <= 1e-10,
            "c = {c:e}"
        );
        let with = solve_to(&k, 1e-10, 1e-7).unwrap();
        assert!(with.traction_error() <= 1e-7);
        assert!(
            with.edge().distance(alone.edge()) <= 2e-10,
            "{:e}",
            with.edge().c
        );
    }
}
