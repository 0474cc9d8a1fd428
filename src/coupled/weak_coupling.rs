//! Weak coupling, b* -> 0 (docs/theory.md (L6)): the stick edge tends to Goodman's, whose c
//! depends on b* / mu~ alone (`goodman::stick_edge`), and the difference is even in b*. In
//! lc = ln(c / (1 - c)) at a fixed table coordinate zeta (`stick_edge_table::coordinates`,
//! which keeps b* / mu~ nearly fixed as b* -> 0),
//!
//!   lc(b*, zeta) = lc_G(b*, zeta) + b*^2 h(b*^2, zeta),  h smooth in b*^2,
//!
//! measured with the panels' root search (c to 1e-12) against Goodman's closed form:
//!
//! | zeta | b* = 0.02 | 0.01 | 0.005 | 0.0025 |
//! |---|---|---|---|---|
//! | 1 (c = 2.16e-4) | h = -4.999043 | -4.998760 | -4.998689 | -4.998671 |
//! | 3 (c = 0.822) | -3.949429 | -3.948790 | -3.948630 | -3.948590 |
//!
//! (h's steps shrink four times per halving of b*: linear in b*^2). So below the table's
//! smallest b* c alone is the table's h at [`NODE_B`] (b* = 0.02, 0.025, 0.03, the same
//! zeta), the quadratic in b*^2 through them evaluated at b*^2, added to Goodman's lc there.
//! Its error in c is c (1 - c) b*^2 times the nodes' errors in h carried over (the table's
//! bound over c (1 - c) b_i^2 at each node) plus the distance from the line through the two
//! nodes nearest b* = 0 (the quadratic's correction, a bound on its own error, of the next
//! order in b*^2).

use super::large_friction::lagrange;
use crate::problem::StickEdge;

/// The nodes' b*, at and above the table's smallest (0.02): evenly spaced by a quarter of it.
pub(crate) const NODE_B: [f64; 3] = [0.02, 0.025, 0.03];

/// Whether b* lies below the nodes (the table's smallest b*).
pub(crate) fn applies(b: f64) -> bool {
    b > 0.0 && b < NODE_B[0]
}

/// A node: the table's stick edge at (b_i, zeta), its bound on |dc|, and Goodman's stick edge
/// there.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node {
    pub(crate) table: StickEdge,
    pub(crate) bound: f64,
    pub(crate) goodman: StickEdge,
}

/// The stick edge at b* (below [`NODE_B`]) whose Goodman edge at the same zeta is `goodman`,
/// from the `nodes` at [`NODE_B`], and its error (module documentation).
pub(crate) fn extrapolate(b: f64, goodman: StickEdge, nodes: [Node; 3]) -> (StickEdge, f64) {
    let y = NODE_B.map(|b| Some(b * b));
    let quad = lagrange(b * b, y);
    let line = lagrange(b * b, [y[0], y[1], None]);
    let h: [f64; 3] = std::array::from_fn(|i| {
        (nodes[i].table.logit() - nodes[i].goodman.logit()) / (NODE_B[i] * NODE_B[i])
    });
    // a node's bound on |dc| in h: over c (1 - c) b_i^2
    let h_error: [f64; 3] = std::array::from_fn(|i| {
        let e = nodes[i].table;
        nodes[i].bound / (e.c * e.one_minus_c * NODE_B[i] * NODE_B[i])
    });
    let dot = |w: [f64; 3], v: [f64; 3]| -> f64 { w.iter().zip(v).map(|(a, b)| a * b).sum() };
    let (h_quad, h_line) = (dot(quad, h), dot(line, h));
    let edge = StickEdge::from_logit(goodman.logit() + b * b * h_quad);
    let lc_error = b * b * (dot(quad.map(f64::abs), h_error) + (h_quad - h_line).abs());
    // |dc| <= c (1 - c) |d lc| to first order; the larger c (1 - c) of the edge moved by it
    let spread = edge.c * edge.one_minus_c * lc_error.exp();
    (edge, spread * lc_error)
}

/// Bounds on Goodman's error as b* -> 0, in units of b*^2: on |c - c_G| ([`GOODMAN_C`]) and on
/// the traction distance at delta = 1 ([`GOODMAN_TRACTIONS`]). Measured against COUPLED (c
/// to 1e-12, tractions to 1e-11) at b* = 1e-4 over zeta = -1 .. 8 (steps of 0.25 from 1.5 to
/// 4), the largest |c - c_G| / b*^2 was 0.651 (zeta = 2.75, c = 0.64) and the largest
/// distance / b*^2 0.641 (zeta = 3, c = 0.82); it falls to 0.016 at zeta = -1 (c = 1e-31)
/// and levels off at 0.550 from zeta = 4 on (the near-bonded field). Both scale as b*^2:
///
/// | zeta | distance / b*^2 at b* = 1e-2 | 1e-3 | 1e-4 |
/// |---|---|---|---|
/// | 0.5 | 0.07174 | 0.07168 | 0.07167 |
/// | 2 | 0.3235 | 0.3220 | 0.3219 |
/// | 4 | 0.5591 | 0.5510 | 0.5502 |
///
/// The bounds are twice the largest, rounded up.
pub(crate) const GOODMAN_C: f64 = 1.4;
/// See [`GOODMAN_C`].
pub(crate) const GOODMAN_TRACTIONS: f64 = 1.4;

/// Bounds on Goodman's errors in c and in the tractions (q~ weighed by `delta`) at b* = `b`
/// ([`GOODMAN_C`], [`GOODMAN_TRACTIONS`]; the distance's q~ part grows at most like delta).
pub(crate) fn goodman_bounds(b: f64, delta: f64) -> (f64, f64) {
    let b2 = b * b;
    (GOODMAN_C * b2, GOODMAN_TRACTIONS * delta.max(1.0) * b2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupled::solve_to;
    use crate::problem::{Coupling, Profile, traction_distance};
    use crate::stick_edge_table::coupling_at;

    /// Goodman's c and tractions lie within [`goodman_bounds`] of the panels' root search (c
    /// to 1e-12, with its traction estimate) at b* = 1e-3 and 1e-4 over the stick zones from 1e-31 to the
    /// near-bonded field, with at least the measured margin of 2 at the largest; and at
    /// b* = 1e-300 (b*^2 underflows) and 5e-324 COUPLED answers with Goodman's edge, c = 1/sqrt(2)
    /// at b* = mu~.
    #[test]
    fn goodman_within_its_bounds_as_b_vanishes() {
        for b in [1e-3, 1e-4] {
            for zeta in [-1.0, 1.0, 2.75, 3.0, 6.0] {
                let (b, mu) = coupling_at(f64::atanh(b), zeta);
                let k = Coupling { bp: b, bq: b, mu };
                let g = crate::goodman::solve(&k).unwrap();
                // the panels' own root search (not from this module's edge)
                let s = crate::coupled::solve(&k, 1e-12).unwrap();
                let (c_bound, t_bound) = goodman_bounds(b, 1.0);
                let dc = g.edge().distance(s.edge()) + s.numerical_error();
                let dt = traction_distance(&g, &s) + s.traction_error();
                assert!(
                    dc <= 0.5 * c_bound,
                    "b* {b} zeta {zeta}: c {dc:e} ({c_bound:e})"
                );
                assert!(
                    dt <= 0.5 * t_bound,
                    "b* {b} zeta {zeta}: {dt:e} ({t_bound:e})"
                );
            }
        }
        for b in [1e-300, 5e-324] {
            let k = Coupling {
                bp: b,
                bq: b,
                mu: b,
            };
            let s = solve_to(&k, 1e-10, 1e-10).unwrap();
            assert!((s.edge().c - std::f64::consts::FRAC_1_SQRT_2).abs() <= 1e-15);
            assert!(s.numerical_error() <= 1e-14 && s.traction_error() <= 1e-13);
        }
    }
}
