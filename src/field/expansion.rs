//! The method-independent traction expansion: what a method hands to the field solution.
//!
//! p (even) and q (odd) on [0, 1] as panels [a, b], each mapped affinely to t in [-1, 1]
//! (x = m + h t), carrying one or more weighted Legendre families
//!   p(x) = sum_families w(t) sum_k p_k P_k(t),   q(x) = sum_families w(t) sum_k q_k P_k(t),
//! with the Jacobi end weights of [`Weight`] (1, (1 - t)^e, (1 + t)^e): a family's weight holds
//! a local exponent of the tractions at a panel end (the punch edge x = 1, the stick edge
//! x = c). The panels tile [0, 1] from 0 to 1, the last one ending at the punch edge; the
//! whole line follows by symmetry. A method only has to build one ([`Expand`]):
//! - from its own basis when it has one (COUPLED: its panels and families; LCP: its
//!   piecewise-constant grid);
//! - or by sampling its tractions on panels graded towards c and 1 ([`sample`]), given the
//!   exponents it knows: the punch edge's g, and on the stick side of c
//!   q - mu p = (c - x)^s times an analytic function (p analytic across c), s = 1/2 for
//!   GOODMAN and SPENCE (the sqrt(c - x) of their stick-zone shear, docs/theory.md (G3), (S3)).

use crate::numerics::cauchy::Weight;
use crate::numerics::orthopoly::{legendre, legendre_sum};
use crate::numerics::quadrature::gauss_legendre;
use crate::problem::Profile;

/// One weighted Legendre family of a panel: w(t) sum_k p[k] P_k(t) for p, the same with q
/// (either may be shorter than the other, or empty).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Family {
    /// The end weight w(t).
    pub(crate) weight: Weight,
    /// Legendre coefficients of p / w.
    pub(crate) p: Vec<f64>,
    /// Legendre coefficients of q / w.
    pub(crate) q: Vec<f64>,
}

/// A panel [a, b] of [0, 1] with its families.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Panel {
    /// Left end.
    pub(crate) a: f64,
    /// Right end.
    pub(crate) b: f64,
    /// The families whose sum is (p, q) on the panel.
    pub(crate) families: Vec<Family>,
}

impl Panel {
    /// Centre and half-width.
    pub(crate) fn centre(&self) -> (f64, f64) {
        (0.5 * (self.a + self.b), 0.5 * (self.b - self.a))
    }

    /// (p, q) at x in [a, b] (a weight that is infinite at an end gives infinity there).
    pub(crate) fn tractions(&self, x: f64) -> (f64, f64) {
        let (m, h) = self.centre();
        let t = ((x - m) / h).clamp(-1.0, 1.0);
        let (omt, opt) = ((self.b - x) / h, (x - self.a) / h);
        self.families.iter().fold((0.0, 0.0), |(p, q), f| {
            let w = f.weight.at(omt, opt);
            (p + w * legendre_sum(&f.p, t), q + w * legendre_sum(&f.q, t))
        })
    }
}

/// The traction expansion of a solution (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Expansion {
    /// Panels tiling [0, 1], left to right (p even, q odd: the mirror stands for [-1, 0]);
    /// or tiling [-1, 1], left to right, for tractions without symmetry
    /// ([`Expansion::whole_line`]).
    pub(crate) panels: Vec<Panel>,
}

impl Expansion {
    /// Whether the panels tile the whole contact [-1, 1] (the first starts left of 0): no
    /// symmetry is assumed and nothing is mirrored (a load-path state, issue 27).
    pub(crate) fn whole_line(&self) -> bool {
        self.panels.first().is_some_and(|p| p.a < 0.0)
    }

    /// (p, q) at 0 <= x < 1 (-1 <= x < 1 for a whole-line expansion).
    pub(crate) fn tractions(&self, x: f64) -> (f64, f64) {
        let i = self.panels.iter().position(|p| x < p.b);
        self.panels[i.unwrap_or(self.panels.len() - 1)].tractions(x)
    }

    /// The punch-edge singularity p ~ k (1 - x)^(-g) of the last panel's family with a
    /// negative exponent at t = 1: (k, g), with (1 - t)^(-g) = h^g (1 - x)^(-g) and
    /// P_k(1) = 1. None if the last panel has no such family.
    pub(crate) fn edge_intensity(&self) -> Option<(f64, f64)> {
        let last = self.panels.last()?;
        let (_, h) = last.centre();
        last.families.iter().find_map(|f| match f.weight {
            Weight::Right(e) if e < 0.0 => Some((h.powf(-e) * f.p.iter().sum::<f64>(), -e)),
            _ => None,
        })
    }
}

/// A solved method's tractions as an [`Expansion`] (crate-internal: the field solution is
/// built from it).
pub(crate) trait Expand {
    /// The expansion of this solution's own tractions.
    fn expansion(&self) -> Expansion;

    /// The punch-edge singularity (k, g) of p ~ k (1 - x)^(-g) of these tractions, given
    /// their expansion `e`: by default the expansion's ([`Expansion::edge_intensity`]); a
    /// solution whose edge field lies below the panels' resolution gives its own.
    fn edge_intensity(&self, e: &Expansion) -> Option<(f64, f64)> {
        e.edge_intensity()
    }
}

/// What a sampled method knows of its tractions' local exponents.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Exponents {
    /// p, q ~ (1 - x)^(-edge) at the punch edge.
    pub(crate) edge: f64,
    /// q - mu p = (c - x)^stick times an analytic function on the stick side of c; p is
    /// analytic across c.
    pub(crate) stick: f64,
}

/// Below this stick half-width the stick zone is left out (q = mu p sgn x on the whole
/// contact): what it changes in q is an odd dipole of size mu p(0) c^2, below 1e-13 of the
/// stresses at depth 1e-6.
const C_MIN: f64 = 1e-12;

/// Below this slip width the slip zones are left out (p and q sampled as they are on one
/// panel weighted for the punch edge): panels narrower than this next to x = 1 are below the
/// resolution of doubles there.
const W_MIN: f64 = 1e-13;

/// Legendre orders tried per panel, until the fitted series' last three coefficients fall
/// below [`TAIL`] times its largest.
const ORDERS: [usize; 5] = [16, 24, 32, 48, 64];
const TAIL: f64 = 1e-15;

/// Distances from a singular point of the break points of panels graded towards it, up to
/// `limit` (exclusive): h, 2h, 4h, ..., each panel at least its own width from the singular
/// point; the panel left over, [last, limit], is at most twice as wide as its distance.
pub(crate) fn graded(h: f64, limit: f64) -> Vec<f64> {
    let mut d = vec![h];
    while let Some(&last) = d.last() {
        if limit <= 3.0 * last {
            break;
        }
        d.push(2.0 * last);
    }
    d
}

/// The innermost of [`graded_plain`]'s panels, relative to their span: within it a logarithm
/// at the singular point is fitted by a polynomial (an error confined to points within 1e-6
/// of the span from it). Not narrower: the field's panels are given by their ends' x, and a
/// panel a few ulps of x wide has no geometry (at 3e-14 of the span the slip next to c came
/// out with the wrong sign, COUPLED at b* = 0.7, mu~ = 1e6).
const INNERMOST: f64 = 1.0 / (1u64 << 20) as f64;

/// Plain panels (p and q fitted) over the signed distances s from a singular point between 0
/// and `span` (< 0: to its left), graded towards it ([`graded`], down to [`INNERMOST`] of the
/// span): for tractions with O(1) logarithms there, which no Jacobi weight carries. `x_of(s)`
/// gives the panel ends, `tractions(s)` the values, s taken from the nearer end of each
/// panel so that it keeps its accuracy next to the singular point.
pub(crate) fn graded_plain(
    span: f64,
    x_of: impl Fn(f64) -> f64,
    tractions: impl Fn(f64) -> (f64, f64),
) -> Vec<Panel> {
    let width = span.abs();
    let mut ends = vec![0.0];
    ends.extend(graded(INNERMOST * width, width));
    ends.push(width);
    ends.windows(2)
        .map(|e| {
            if span < 0.0 {
                (-e[1], -e[0])
            } else {
                (e[0], e[1])
            }
        })
        // panels narrower than the doubles at x (c + s = c next to c ~ 1: the thin slip zone
        // of a large-friction scene, 1 - c = 1.6e-11) have no width and nothing to fit: their
        // h = 0 made the whole field NaN
        .filter(|&(s0, s1)| x_of(s0) < x_of(s1))
        .map(|(s0, s1)| {
            let h = 0.5 * (s1 - s0);
            fitted_panel(x_of(s0), x_of(s1), Weight::One, |omt, opt| {
                tractions(if opt <= omt {
                    s0 + h * opt
                } else {
                    s1 - h * omt
                })
            })
        })
        .collect()
}

/// Legendre coefficients of f(t) on [-1, 1] from its values at Gauss-Legendre nodes (exact
/// for polynomials of degree < n), at the lowest order of [`ORDERS`] whose tail is below
/// [`TAIL`] times its largest coefficient, or else at the last order before the tail stopped
/// halving: it has then reached the rounding noise of the samples (the functions fitted are
/// polynomials, or analytic at least a panel width beyond their panel, whose uncorrupted
/// tails shrink by far more than 2 from one order to the next). The highest order otherwise.
pub(crate) fn fit(f: impl Fn(f64) -> f64) -> Vec<f64> {
    let mut last: Option<(Vec<f64>, f64)> = None;
    for n in ORDERS {
        let coef = legendre_coefficients(&f, n);
        let top = coef.iter().fold(0.0f64, |m, c| m.max(c.abs()));
        let tail = coef[n - 3..].iter().fold(0.0f64, |m, c| m.max(c.abs()));
        if tail <= TAIL * top {
            return coef;
        }
        if let Some((previous, previous_tail)) = last.take()
            && tail > 0.5 * previous_tail
        {
            return previous;
        }
        last = Some((coef, tail));
    }
    last.map(|(coef, _)| coef).unwrap_or_default()
}

/// The first n Legendre coefficients of f by the n-point Gauss-Legendre rule.
fn legendre_coefficients(f: impl Fn(f64) -> f64, n: usize) -> Vec<f64> {
    let (nodes, weights) = gauss_legendre(n);
    let mut leg = vec![0.0; n];
    let mut coef = vec![0.0; n];
    for (&t, &w) in nodes.iter().zip(&weights) {
        let v = f(t) * w;
        legendre(t, &mut leg);
        for (c, l) in coef.iter_mut().zip(&leg) {
            *c += v * l;
        }
    }
    for (k, c) in coef.iter_mut().enumerate() {
        *c *= k as f64 + 0.5;
    }
    coef
}

/// The expansion of a grid method on consecutive `breaks`: one panel per interval, given by
/// `end(a, b)` where that returns a family (the end panels, which carry the edge weight),
/// else its tractions `at(x)` fitted in Legendre series with no weight.
pub(crate) fn grid_expansion(
    breaks: &[f64],
    at: impl Fn(f64) -> (f64, f64),
    end: impl Fn(f64, f64) -> Option<Family>,
) -> Expansion {
    let panels = breaks
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let family = end(a, b).unwrap_or_else(|| {
                let (m, r) = (0.5 * (a + b), 0.5 * (b - a));
                let at = |t: f64| at(m + r * t);
                Family {
                    weight: Weight::One,
                    p: fit(|t| at(t).0),
                    q: fit(|t| at(t).1),
                }
            });
            Panel {
                a,
                b,
                families: vec![family],
            }
        })
        .collect();
    Expansion { panels }
}

/// A panel [a, b] of one family with end weight `weight`: p / w and q / w fitted from
/// `tractions(1 - t, 1 + t)`, the tractions at local t given its distances to the panel's
/// ends (so that a closed form can keep them to full relative accuracy next to an end).
pub(crate) fn fitted_panel(
    a: f64,
    b: f64,
    weight: Weight,
    tractions: impl Fn(f64, f64) -> (f64, f64),
) -> Panel {
    let at = |t: f64| {
        let (omt, opt) = (1.0 - t, 1.0 + t);
        let (p, q) = tractions(omt, opt);
        let w = weight.at(omt, opt);
        (p / w, q / w)
    };
    Panel {
        a,
        b,
        families: vec![Family {
            weight,
            p: fit(|t| at(t).0),
            q: fit(|t| at(t).1),
        }],
    }
}

/// Samples a method's tractions into an expansion (see the module documentation): panels
/// graded geometrically towards c from both sides (the panels at c as wide as
/// min(c, 1 - c) / 2) and a last panel weighted (1 - t)^(-edge) for p and q; the stick panel
/// at c carries q = mu p + (1 - t)^stick R with R sampled as (q - mu p) / (1 - t)^stick;
/// on slip panels q = mu p exactly (E3).
pub(crate) fn sample(profile: &dyn Profile, ex: Exponents) -> Expansion {
    let mu = profile.coupling().mu;
    let edge = profile.edge();
    let at = |x: f64| profile.half_line_tractions(x);
    // p on [a, b] divided by w, with w from the distances to the ends
    let plain = |a: f64, b: f64| {
        let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
        fit(|t| at(m + h * t).0)
    };
    let end_panel = |a: f64, sample_q: bool| {
        let h = 0.5 * (1.0 - a);
        let values = |t: f64| {
            let x = 1.0 - h * (1.0 - t);
            let w = ((1.0 - x) / h).powf(-ex.edge);
            let (p, q) = at(x);
            (p / w, q / w)
        };
        let p = fit(|t| values(t).0);
        let q = if sample_q {
            fit(|t| values(t).1)
        } else {
            p.iter().map(|v| mu * v).collect()
        };
        Panel {
            a,
            b: 1.0,
            families: vec![Family {
                weight: Weight::Right(-ex.edge),
                p,
                q,
            }],
        }
    };
    let (c, w) = (edge.c, edge.one_minus_c);
    if c < C_MIN || mu == 0.0 {
        return Expansion {
            panels: vec![end_panel(0.0, false)],
        };
    }
    if w < W_MIN {
        return Expansion {
            panels: vec![end_panel(0.0, true)],
        };
    }
    let half = 0.5 * c.min(w);
    let stick = graded(half, c);
    let slip = graded(half, w);
    let mut panels = Vec::new();
    // stick side, from 0 to c: [0, c - d_last], ..., [c - d_0, c]
    let mut left = 0.0;
    for (i, d) in stick.iter().enumerate().rev() {
        let b = c - d;
        let p = plain(left, b);
        let (m, h) = (0.5 * (left + b), 0.5 * (b - left));
        panels.push(Panel {
            a: left,
            b,
            families: vec![Family {
                weight: Weight::One,
                p,
                q: fit(|t| at(m + h * t).1),
            }],
        });
        left = b;
        if i == 0 {
            // the stick panel at c: q = mu p + (1 - t)^stick R
            let (m, h) = (0.5 * (left + c), 0.5 * (c - left));
            let p = plain(left, c);
            let r = fit(|t| {
                let x = m + h * t;
                let (p, q) = at(x);
                (q - mu * p) / ((c - x) / h).powf(ex.stick)
            });
            panels.push(Panel {
                a: left,
                b: c,
                families: vec![
                    Family {
                        weight: Weight::One,
                        q: p.iter().map(|v| mu * v).collect(),
                        p,
                    },
                    Family {
                        weight: Weight::Right(ex.stick),
                        p: Vec::new(),
                        q: r,
                    },
                ],
            });
        }
    }
    // slip side: [c, c + d_0], ..., [c + d_last, 1]
    let mut left = c;
    for d in &slip {
        let b = c + d;
        let p = plain(left, b);
        panels.push(Panel {
            a: left,
            b,
            families: vec![Family {
                weight: Weight::One,
                q: p.iter().map(|v| mu * v).collect(),
                p,
            }],
        });
        left = b;
    }
    panels.push(end_panel(left, false));
    Expansion { panels }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::Coupling;
    use crate::{goodman, spence};

    /// The sampled expansions of GOODMAN and SPENCE reproduce their tractions (and so their
    /// stick-side exponent 1/2 holds: otherwise R would not converge) and their edge
    /// intensity: Goodman's p = 1 / (pi sqrt(1 - x^2)) has k = 1 / (pi sqrt 2), Spence's
    /// p = (1 - x^2)^(-g) / B(1/2, 1 - g) has k = 2^(-g) / B(1/2, 1 - g).
    #[test]
    fn sampled_expansions_reproduce_the_tractions() {
        for (bp, bq, mu) in [
            (0.2, 0.3, 0.4),
            (0.05, 0.28, 0.1),
            (0.4, 0.45, 2.0),
            (0.3, 0.3, 0.0),
        ] {
            let k = Coupling { bp, bq, mu };
            let g = goodman::solve(&k).unwrap();
            let s = spence::solve(&k).unwrap();
            for (profile, edge) in [
                (&g as &dyn Profile, 0.5),
                (&s as &dyn Profile, s.edge_exponent()),
            ] {
                let e = sample(profile, Exponents { edge, stick: 0.5 });
                let c = profile.edge().c;
                // relative to 1e-12 plus the conditioning of p(x) in x next to the punch edge:
                // the rounding of x (eps) moves p by ~ eps / (1 - x) relative (c = 1 - 7e-6 at
                // mu = 2)
                let mut worst: f64 = 0.0;
                for i in 0..2000 {
                    let x = (i as f64 + 0.5) / 2000.0;
                    for x in [x, c * (1.0 - 1e-9 * (i + 1) as f64)] {
                        let (p, q) = profile.half_line_tractions(x);
                        let (pe, qe) = e.tractions(x);
                        let allowed = 1e-12 + 2.0 * f64::EPSILON / (1.0 - x);
                        let r = ((pe - p).abs() / p).max((qe - q).abs() / p) / allowed;
                        worst = worst.max(r);
                    }
                }
                assert!(
                    worst < 1.0,
                    "{k:?}: worst relative error / allowed {worst:e}"
                );
                let (kk, gg) = e.edge_intensity().unwrap();
                let norm = 1.0 / crate::numerics::special::beta(0.5, 1.0 - edge);
                assert!((gg - edge).abs() < 1e-15);
                assert!(
                    (kk - norm * 2f64.powf(-edge)).abs() < 1e-13,
                    "{k:?}: k = {kk}, expected {}",
                    norm * 2f64.powf(-edge)
                );
            }
        }
    }
}
