//! Panels on 0 <= x <= 1 (p even and q odd supply -1 < x < 0) graded geometrically towards
//! the singular points x = c and x = 1, and the basis carried by each panel: weighted
//! Legendre polynomials ([`Basis`]) whose weights hold the local exponents (docs/theory.md (X1), (X2), (K1)):
//! - central panel [-l, l]: p and q / x polynomials in x^2;
//! - stick panels: p, q polynomials; the one ending at c adds q (c - x)^g P_k (at large
//!   friction ((c - x)^g - 1) / g P_k in the local variable, [`LOG_BELOW`]) and the wrong-c
//!   mode (c - x)^(g-1);
//! - slip panels: p polynomial; the one starting at c adds (x - c)^g P_k (or its log form)
//!   and the wrong-c mode (x - c)^(g-1); the one ending at 1 is (1 - x)^(-g) P_k. On slip
//!   panels q = mu p.
//!
//! Grading ([`Layout`]): each panel lies at least its own width away from every singular
//! point that its basis does not carry, so the error decays geometrically in the order n.

use crate::numerics::cauchy::Weight;

/// A point of [0, 1] held both as x and as u = 1 - x, each to full relative accuracy, so
/// that lengths near x = 1 (slip zones of width 1e-9 and less) keep their relative accuracy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pt {
    /// x.
    pub(crate) x: f64,
    /// 1 - x.
    pub(crate) u: f64,
}

impl Pt {
    /// The point at signed distance s from the stick edge (c, w = 1 - c).
    pub(crate) fn from_edge(c: f64, w: f64, s: f64) -> Self {
        let u = w - s;
        if u < 0.5 {
            Pt { x: 1.0 - u, u }
        } else {
            let x = c + s;
            Pt { x, u: 1.0 - x }
        }
    }

    /// The point at local coordinate t of the panel with centre m and half-width h.
    pub(crate) fn local(m: Pt, h: f64, t: f64) -> Self {
        let (x, u) = (m.x + h * t, m.u - h * t);
        if u < 0.5 {
            Pt { x: 1.0 - u, u }
        } else {
            Pt { x, u: 1.0 - x }
        }
    }

    /// self - other (x difference) without cancellation near x = 1.
    pub(crate) fn minus(self, other: Pt) -> f64 {
        if self.u < 0.5 && other.u < 0.5 {
            other.u - self.u
        } else {
            self.x - other.x
        }
    }
}

/// The panel bases, each a family weight(t) P_k(t) whose endpoint weight carries one local
/// exponent of the solution; [`Basis::weight`] is the one place the weights are built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Basis {
    /// Polynomials (w = 1).
    Plain,
    /// q on the stick panel ending at c: (c - x)^g, or below [`LOG_BELOW`] the log weight
    /// ((c - x)^g - 1) / g in the local variable (see there).
    StickEdge,
    /// q's wrong-c mode on that panel, (c - x)^(g-1): its coefficient is the root function.
    StickWrongC,
    /// p on the slip panel starting at c: (x - c)^g, or below [`LOG_BELOW`]
    /// ((x - c)^g - 1) / g in the local variable.
    SlipEdge,
    /// p's wrong-c mode on that panel: (x - c)^(g-1).
    SlipWrongC,
    /// p on the panel ending at the punch edge: (1 - x)^(-g).
    PunchEdge,
    /// The central panel's p in the variable Y: (1 + Y)^(-1/2).
    CentralP,
    /// The central panel's q / x in Y: (1 + Y)^(1/2).
    CentralQ,
}

impl Basis {
    /// Every basis, in discriminant order (the index of its transform family).
    pub(crate) const ALL: [Basis; 8] = [
        Basis::Plain,
        Basis::StickEdge,
        Basis::StickWrongC,
        Basis::SlipEdge,
        Basis::SlipWrongC,
        Basis::PunchEdge,
        Basis::CentralP,
        Basis::CentralQ,
    ];

    /// A wrong-c mode (|x - c|^(g-1)): in the system, absent from the solution.
    pub(crate) fn is_wrong_c(self) -> bool {
        matches!(self, Basis::StickWrongC | Basis::SlipWrongC)
    }

    /// The endpoint weight on the local coordinate t in [-1, 1] for edge exponent g.
    pub(crate) fn weight(self, g: f64) -> Weight {
        match self {
            Basis::Plain => Weight::One,
            Basis::StickEdge if g < LOG_BELOW => Weight::RightLog(g),
            Basis::StickEdge => Weight::Right(g),
            Basis::StickWrongC => Weight::Right(g - 1.0),
            Basis::SlipEdge if g < LOG_BELOW => Weight::LeftLog(g),
            Basis::SlipEdge => Weight::Left(g),
            Basis::SlipWrongC => Weight::Left(g - 1.0),
            Basis::PunchEdge => Weight::Right(-g),
            Basis::CentralP => Weight::Left(-0.5),
            Basis::CentralQ => Weight::Left(0.5),
        }
    }
}

/// Below this edge exponent g (large friction, g ~ 1 / (pi b* mu~)) the edge blocks take
/// the log weights ((1 -+ t)^g - 1) / g: with the panel's polynomials the same span as
/// (1 -+ t)^g and 1, but not nearly dependent on them as g -> 0, where the solution's
/// coefficients in (1 -+ t)^g and 1 grow like 1 / g and cancel (its limit has ln|x - c|):
/// the least squares lost accuracy like eps / g^2 there (defect noise 1e-9 at g = 4e-5; 2e-11
/// in the log basis). The loss grows as b* -> 1: at g = 3.2e-3 (mu~ = 100) the power weights'
/// traction estimate stalled at 2.0e-10, 3.1e-10, 3.2e-9 and 6.5e-9 for b* = 0.999, 0.9995,
/// 0.9999 and 0.99995 (orders up to 34), the log weights meet 1e-10 at order 19 (6.5e-12 ..
/// 9.6e-11); on 17 scenes with g = 1e-3 .. 1e-2 (b* = 0.15 .. 0.99, tolerance 1e-10) the two
/// bases agree on c within their estimates, or to 2.5e-14 (b* = 0.99, mu~ = 35, estimates
/// 2.0e-14 together), and both meet the traction tolerance. Above it the power weights,
/// which the field takes as Jacobi weights (the log-weighted panels it resamples,
/// `coupled::expansion`).
pub(crate) const LOG_BELOW: f64 = 1e-2;

/// `count` functions of one basis on a panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Block {
    /// The basis.
    pub(crate) basis: Basis,
    /// Number of functions (Legendre degrees 0..count).
    pub(crate) count: usize,
}

/// One panel [a, b] of [0, 1]. The central panel [0, l] stands for [-l, l]: there p and q/x
/// are polynomials in Y = 2 x^2 / l^2 - 1 (p even and q odd built in), so the transforms reduce
/// to the weights (1 + Y)^(-1/2) and (1 + Y)^(1/2) in Y.
#[derive(Clone, Debug)]
pub(crate) struct Panel {
    /// Left end.
    pub(crate) a: Pt,
    /// Right end.
    pub(crate) b: Pt,
    /// Midpoint.
    pub(crate) m: Pt,
    /// Half-width.
    pub(crate) h: f64,
    /// The central panel (variable Y = 2 x^2 / l^2 - 1).
    pub(crate) central: bool,
    /// Inside the stick zone.
    pub(crate) stick: bool,
    /// Basis of p.
    pub(crate) p: Vec<Block>,
    /// Basis of q (stick panels only; q = mu p on slip panels).
    pub(crate) q: Vec<Block>,
    /// Offset of this panel's p coefficients in the unknown vector.
    pub(crate) p_offset: usize,
    /// Offset of this panel's q coefficients.
    pub(crate) q_offset: usize,
}

impl Panel {
    fn new(a: Pt, b: Pt, stick: bool, p: Vec<Block>, q: Vec<Block>) -> Self {
        let h = 0.5 * b.minus(a);
        let m = Pt::local(a, h, 1.0);
        Panel {
            a,
            b,
            m,
            h,
            central: false,
            stick,
            p,
            q,
            p_offset: 0,
            q_offset: 0,
        }
    }

    /// Local coordinate t of the point x (|t| <= 1 inside), with 1 - t and 1 + t computed
    /// from the distances to the ends.
    pub(crate) fn local(&self, x: Pt) -> (f64, f64, f64) {
        if self.central {
            let r = x.x / self.h;
            let (db, dsum) = (self.b.minus(x) / self.h, 1.0 + r);
            return (2.0 * r * r - 1.0, 2.0 * db * dsum, 2.0 * r * r);
        }
        let (da, db) = (x.minus(self.a), self.b.minus(x));
        ((da - db) / (2.0 * self.h), db / self.h, da / self.h)
    }

    /// Number of p (resp. q) unknowns.
    pub(crate) fn np(&self) -> usize {
        self.p.iter().map(|b| b.count).sum()
    }

    /// Number of q unknowns.
    pub(crate) fn nq(&self) -> usize {
        self.q.iter().map(|b| b.count).sum()
    }
}

/// Panel break points as distances from c in units of sigma = min(c, 1 - c): stick panels
/// end at c - sigma stick[k] (the central panel takes the rest), slip panels at
/// c + sigma slip[k] (the end panel takes the rest). Fixed while c is refined, so that the
/// root function defect(c) is smooth.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Layout {
    stick: Vec<f64>,
    slip: Vec<f64>,
}

impl Layout {
    /// The grading for stick edge (c, w = 1 - c): the panels at c have width sigma / 2; every
    /// further panel stays at least its own width away from c (and from 1), down to the
    /// central panel [-l, l] with l <= 1.5 times its distance from c (local Bernstein
    /// parameter >= 4.4, so errors decay at least like 4.4^(-n)).
    pub(crate) fn for_edge(c: f64, w: f64) -> Self {
        let sigma = c.min(w);
        let h = 0.5 * sigma;
        let mut stick = vec![h];
        let mut d = h;
        loop {
            let l = c - d;
            if l <= 1.5 * d {
                break;
            }
            let last = l <= 3.0 * d;
            d += if last { 0.5 * (l - d) } else { d };
            stick.push(d);
            if last {
                break;
            }
        }
        let mut slip = vec![h];
        let (mut d, mut rest) = (h, w - h);
        while rest > 1.5 * d {
            let last = rest <= 3.0 * d;
            let step = if last { 0.5 * (rest - d) } else { d };
            rest -= step;
            d += step;
            slip.push(d);
            if last {
                break;
            }
        }
        let scale = |v: Vec<f64>| v.into_iter().map(|x| x / sigma).collect();
        Layout {
            stick: scale(stick),
            slip: scale(slip),
        }
    }
}

/// The discretisation for a given c (w = 1 - c accurate) and polynomial order n.
#[derive(Clone, Debug)]
pub(crate) struct Mesh {
    /// Stick half-width.
    pub(crate) c: f64,
    /// 1 - c.
    pub(crate) w: f64,
    /// Panels left to right, central first.
    pub(crate) panels: Vec<Panel>,
    /// Index of the stick panel ending at c.
    pub(crate) c_stick: usize,
    /// Total number of unknowns.
    pub(crate) unknowns: usize,
}

/// Shorthand for a [`Block`].
fn block(basis: Basis, count: usize) -> Block {
    Block { basis, count }
}

impl Mesh {
    /// Builds the panels for stick edge c (0 < c < 1, w = 1 - c) and order n,
    /// with the panel break points of `layout` scaled to this c; None if the layout does not
    /// fit (it was made for a too different c). Uncoupled (bp = 0): p = p0 is smooth at c,
    /// and the slip panel at c carries polynomials only (the redundant singular blocks would
    /// only cost conditioning).
    pub(crate) fn new(c: f64, w: f64, n: usize, coupled: bool, layout: &Layout) -> Option<Self> {
        let sigma = c.min(w);
        let at = |s: f64| Pt::from_edge(c, w, s);
        let one = |count| block(Basis::Plain, count);
        let stick_d: Vec<f64> = layout.stick.iter().map(|r| r * sigma).collect();
        let slip_d: Vec<f64> = layout.slip.iter().map(|r| r * sigma).collect();
        let widths = |d: &[f64]| d[d.len() - 1] - if d.len() > 1 { d[d.len() - 2] } else { 0.0 };
        let (l, rest) = (c - stick_d[stick_d.len() - 1], w - slip_d[slip_d.len() - 1]);
        if !(l > 0.25 * widths(&stick_d) && rest > 0.25 * widths(&slip_d)) {
            return None;
        }
        let mut panels = vec![Panel::new(
            Pt { x: 0.0, u: 1.0 },
            at(-stick_d[stick_d.len() - 1]),
            true,
            vec![one(n)],
            vec![one(n)],
        )];
        panels[0].central = true;
        panels[0].h = panels[0].b.x;
        for k in (0..stick_d.len()).rev() {
            let right = if k == 0 { 0.0 } else { stick_d[k - 1] };
            let q = if k == 0 {
                vec![
                    one(n),
                    block(Basis::StickEdge, n),
                    block(Basis::StickWrongC, 1),
                ]
            } else {
                vec![one(n)]
            };
            panels.push(Panel::new(
                at(-stick_d[k]),
                at(-right),
                true,
                vec![one(n)],
                q,
            ));
        }
        let c_stick = panels.len() - 1;
        for k in 0..slip_d.len() {
            let left = at(if k == 0 { 0.0 } else { slip_d[k - 1] });
            let p = if k == 0 && coupled {
                vec![
                    one(n),
                    block(Basis::SlipEdge, n),
                    block(Basis::SlipWrongC, 1),
                ]
            } else {
                vec![one(n)]
            };
            panels.push(Panel::new(left, at(slip_d[k]), false, p, vec![]));
        }
        let end = Pt { x: 1.0, u: 0.0 };
        panels.push(Panel::new(
            at(slip_d[slip_d.len() - 1]),
            end,
            false,
            vec![block(Basis::PunchEdge, n)],
            vec![],
        ));
        let mut offset = 0;
        for p in panels.iter_mut() {
            p.p_offset = offset;
            offset += p.np();
            p.q_offset = offset;
            offset += p.nq();
        }
        Some(Mesh {
            c,
            w,
            panels,
            c_stick,
            unknowns: offset,
        })
    }

    /// The columns of the two wrong-c modes with their panels' half-widths,
    /// (q's on the stick panel at c, p's on the slip panel at c); None when uncoupled.
    pub(crate) fn wrong_c_columns(&self) -> Option<((usize, f64), (usize, f64))> {
        let column = |blocks: &[Block], offset: usize| {
            let mut col = offset;
            for b in blocks {
                if b.basis.is_wrong_c() {
                    return Some(col);
                }
                col += b.count;
            }
            None
        };
        let (stick, slip) = (&self.panels[self.c_stick], &self.panels[self.c_stick + 1]);
        Some((
            (column(&stick.q, stick.q_offset)?, stick.h),
            (column(&slip.p, slip.p_offset)?, slip.h),
        ))
    }

    /// Index of the panel holding the point x of [0, 1).
    pub(crate) fn locate(&self, x: Pt) -> usize {
        self.panels
            .iter()
            .position(|p| x.minus(p.b) < 0.0)
            .unwrap_or(self.panels.len() - 1)
    }
}
