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

/// lc = ln(c / (1 - c)) of a stick edge.
fn logit(e: StickEdge) -> f64 {
    e.c.ln() - e.one_minus_c.ln()
}

/// The stick edge at b* (below [`NODE_B`]) whose Goodman edge at the same zeta is `goodman`,
/// from the `nodes` at [`NODE_B`], and its error (module documentation).
pub(crate) fn extrapolate(b: f64, goodman: StickEdge, nodes: [Node; 3]) -> (StickEdge, f64) {
    let y = NODE_B.map(|b| Some(b * b));
    let quad = lagrange(b * b, y);
    let line = lagrange(b * b, [y[0], y[1], None]);
    let h: [f64; 3] = std::array::from_fn(|i| {
        (logit(nodes[i].table) - logit(nodes[i].goodman)) / (NODE_B[i] * NODE_B[i])
    });
    // a node's bound on |dc| in h: over c (1 - c) b_i^2
    let h_error: [f64; 3] = std::array::from_fn(|i| {
        let e = nodes[i].table;
        nodes[i].bound / (e.c * e.one_minus_c * NODE_B[i] * NODE_B[i])
    });
    let dot = |w: [f64; 3], v: [f64; 3]| -> f64 { w.iter().zip(v).map(|(a, b)| a * b).sum() };
    let (h_quad, h_line) = (dot(quad, h), dot(line, h));
    let edge = StickEdge::from_logit(logit(goodman) + b * b * h_quad);
    let lc_error = b * b * (dot(quad.map(f64::abs), h_error) + (h_quad - h_line).abs());
    // |dc| <= c (1 - c) |d lc| to first order; the larger c (1 - c) of the edge moved by it
    let spread = edge.c * edge.one_minus_c * lc_error.exp();
    (edge, spread * lc_error)
}
