//! The exact solver of monotonic tangential loading after the normal load
//! (docs/theory_tangential.md sections 10-12): Q from 0 to Q < mu P with P held. The end
//! state is path-independent and solves one problem per Q:
//!
//! - (M1) H[p] = bp q on (-1, 1);
//! - (M2) on the stick set (c1, c2): H[q] + bq p = H[q0] + bq p0 (the tangential displacement
//!   moves with the punch since the normal load; (p0, q0) the normal-load state);
//! - (M3) on the leading slip zone (c2, 1): q = mu p; on the trailing edge zone (-1, c1):
//!   q = -mu p;
//! - (M4) int p = 1, int q = Q/P; bounded tractions at c1 and c2.
//!
//! Zones: the edge zone (-1, c1) (width w1 = 1 + c1), the stick set, split at -c when
//! c2 > -c (the forcing's (-c - x)^g there), and the leading zone (c2, 1), each with the
//! exponents of section 10 ([`frame`]). Two border constants in (M2) vanish at the exact
//! (c1, c2), found by Newton's method in (ln w1, c2). With bp = 0 there is no edge zone
//! (g = 1/2 and the bonded exponent -1/2 coincide) and one border constant fixes c2.

pub(crate) mod frame;
pub(crate) mod path;
pub(crate) mod reload;
pub(crate) mod unload;

#[cfg(test)]
pub(crate) mod tests;

use crate::error::{Error, Result};
use crate::numerics::roots::chord2;
use crate::problem::Coupling;
use frame::{Kind, Sizes, Solved, ZoneSpec, solve};

/// The edge exponent g = 1/2 - arctan(bp mu)/pi (docs/theory.md (X1)).
pub(crate) fn edge_exponent(k: &Coupling) -> f64 {
    0.5 - (k.bp * k.mu).atan() / std::f64::consts::PI
}

/// The normal-load zones for the stick half-width c (1 - c = w).
pub(crate) fn normal_specs(k: &Coupling, c: f64, w: f64) -> Vec<ZoneSpec> {
    let g = edge_exponent(k);
    vec![
        ZoneSpec {
            kind: Kind::Slip(-1.0),
            len: w,
            p: [vec![-g], vec![0.0, g]],
            q: [vec![], vec![]],
            near: [None, None],
        },
        ZoneSpec {
            kind: Kind::Stick,
            len: 2.0 * c,
            p: [vec![0.0], vec![0.0]],
            q: [vec![0.0, g], vec![0.0, g]],
            near: [None, None],
        },
        ZoneSpec {
            kind: Kind::Slip(1.0),
            len: w,
            p: [vec![0.0, g], vec![-g]],
            q: [vec![], vec![]],
            near: [None, None],
        },
    ]
}

/// The normal-load state on the frame at the stick half-width c (two border constants; at
/// the exact c both vanish).
pub(crate) fn normal_load(k: &Coupling, c: f64, w: f64, level: usize) -> Result<Solved> {
    solve(
        *k,
        &normal_specs(k, c, w),
        Sizes::at(level),
        2,
        0.0,
        &|_, _| 0.0,
    )
}

/// The trailing edge zone: none (bp = 0 only), or width w1 = 1 + c1 with q = s mu p there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Edge {
    None,
    Zone { w1: f64, sign: f64 },
}

/// The monotonic-loading zones for the edge zone, the stick set's end c2 and the normal
/// load's stick half-width c (1 - c = w).
pub(crate) fn monotonic_specs(k: &Coupling, edge: Edge, c2: f64, c: f64, w: f64) -> Vec<ZoneSpec> {
    let g = edge_exponent(k);
    let mut specs = Vec::new();
    let (w1, stick_lo_p, stick_lo_q) = match edge {
        Edge::None => (0.0, vec![-g], vec![-g]),
        Edge::Zone { w1, sign } => {
            specs.push(ZoneSpec {
                kind: Kind::Slip(sign),
                len: w1,
                p: [vec![-g], vec![0.0, g]],
                q: [vec![], vec![]],
                near: [None, None],
            });
            (w1, vec![0.0], vec![0.0, g])
        }
    };
    if c2 > -c {
        // the forcing carries (-c - x)^g on the left of -c, zero on the right
        specs.push(ZoneSpec {
            kind: Kind::Stick,
            len: w - w1,
            p: [stick_lo_p, vec![0.0, g]],
            q: [stick_lo_q, vec![0.0, g]],
            near: [None, None],
        });
        specs.push(ZoneSpec {
            kind: Kind::Stick,
            len: c2 + c,
            p: [vec![0.0], vec![0.0]],
            q: [vec![0.0, g], vec![0.0, g]],
            near: [None, None],
        });
    } else {
        specs.push(ZoneSpec {
            kind: Kind::Stick,
            len: (1.0 + c2) - w1,
            p: [stick_lo_p, vec![0.0]],
            q: [stick_lo_q, vec![0.0, g]],
            // the forcing's singular point -c lies c2 + c beyond c2
            near: [None, Some(-c - c2)],
        });
    }
    specs.push(ZoneSpec {
        kind: Kind::Slip(1.0),
        len: 1.0 - c2,
        p: [vec![0.0, g], vec![-g]],
        q: [vec![], vec![]],
        near: [None, None],
    });
    specs
}

/// The fixed-geometry monotonic solve at Q/P = `qp` with the normal-load state `normal`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn monotonic_fixed(
    k: &Coupling,
    normal: &Solved,
    c: f64,
    w: f64,
    edge: Edge,
    c2: f64,
    qp: f64,
    level: usize,
) -> Result<Solved> {
    if !(c2 > -1.0 && c2 < c) {
        return Err(Error::InvalidArgument(format!(
            "exact: stick end c2 = {c2} outside (-1, c)"
        )));
    }
    let specs = monotonic_specs(k, edge, c2, c, w);
    let n_sigma = match edge {
        Edge::None => 1,
        Edge::Zone { .. } => 2,
    };
    let bq = k.bq;
    let forcing = |opx: f64, omx: f64| {
        let l = normal.frame.locate(opx, omx);
        let (p0, _) = normal.tractions_at(&l);
        let (_, hq0) = normal.hilbert_at(&l);
        hq0 + bq * p0
    };
    solve(*k, &specs, Sizes::at(level), n_sigma, qp, &forcing)
}

/// The monotonic end state at one level.
pub(crate) struct Level {
    pub(crate) edge: Edge,
    pub(crate) c2: f64,
    pub(crate) state: Solved,
    /// The last Newton step's size in c1 and c2 (its own error bound).
    pub(crate) step: f64,
    pub(crate) solves: usize,
}

impl Level {
    /// 1 + c1 (0 without an edge zone).
    pub(crate) fn w1(&self) -> f64 {
        match self.edge {
            Edge::None => 0.0,
            Edge::Zone { w1, .. } => w1,
        }
    }
}

/// Newton steps per level at most (the levels of docs/theory_tangential.md section 12 took
/// 2-25 solves, i.e. at most about 8 steps with their Jacobians).
pub(crate) const MAX_NEWTON: usize = 20;

/// Finite-difference steps of the Jacobian in ln w1 and c2: far above sigma's rounding
/// (1e-9 .. 1e-8 of its scale at the root, measured at the ply's levels 3-5) and far below
/// its variation scales (a decade of w1; c2 + c).
pub(crate) const STEP_LN_W1: f64 = 1e-3;
pub(crate) const STEP_C2: f64 = 1e-5;

/// Thinnest edge zone the frame resolves: at the ply (Q/P = 0.09, c2 fixed) the border
/// constants at levels 4 and 6 agreed to 1e-4 of their size for w1 >= 1e-7 and differed by
/// factors of 2 and signs for w1 <= 1e-8 (docs/theory_tangential.md section 11).
pub(crate) const W1_MIN: f64 = 1e-7;

/// The first decade (hi/10, hi), from `hi` down to [`W1_MIN`], over which the border value
/// `f` at an edge zone's width changes sign, as its geometric middle (a width whose solve
/// fails gives no sign and is passed over), and the solves taken.
pub(crate) fn edge_zone_scan(mut hi: f64, f: impl Fn(f64) -> Result<f64>) -> (Option<f64>, usize) {
    let mut f_hi = f(hi).ok();
    let mut solves = 1;
    while hi > W1_MIN {
        let lo = 0.1 * hi;
        let f_lo = f(lo).ok();
        solves += 1;
        if let (Some(a), Some(b)) = (f_lo, f_hi)
            && a.signum() != b.signum()
        {
            return (Some((lo * hi).sqrt()), solves);
        }
        (hi, f_hi) = (lo, f_lo);
    }
    (None, solves)
}

/// Solves (M1)-(M4) at one level: the border constants' root in (ln w1, c2) by Newton's
/// method with a Jacobian by differences (`jac`, computed if None), from (edge, c2).
#[allow(clippy::too_many_arguments)]
pub(crate) fn monotonic_level(
    k: &Coupling,
    normal: &Solved,
    c: f64,
    w: f64,
    edge: Edge,
    c2: f64,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 2]; 2]>,
) -> Result<Level> {
    let mut solves = 0;
    let mut at = |edge: Edge, c2: f64| -> Result<Solved> {
        solves += 1;
        monotonic_fixed(k, normal, c, w, edge, c2, qp, level)
    };
    match edge {
        Edge::None => {
            // secant in c2 on the one border constant
            let (mut a, mut b) = (c2, c2 - 1e-3);
            let mut fa = at(edge, a)?.sigma[0];
            let mut sb = at(edge, b)?;
            let mut step = f64::INFINITY;
            for _ in 0..MAX_NEWTON {
                let fb = sb.sigma[0];
                if fb == fa {
                    break;
                }
                let next = (b - fb * (b - a) / (fb - fa)).clamp(b - 0.05, b + 0.05);
                (a, fa) = (b, fb);
                b = next;
                sb = at(edge, b)?;
                let last = (b - a).abs();
                let stalled = last > 0.5 * step;
                step = last;
                if step <= 0.1 * tol || stalled {
                    break;
                }
            }
            Ok(Level {
                edge,
                c2: b,
                state: sb,
                step,
                solves,
            })
        }
        Edge::Zone { w1, sign } => {
            let zone = |lw: f64| Edge::Zone { w1: lw.exp(), sign };
            let ([lw, c2], state, step) = chord2(
                [w1.ln(), c2],
                [STEP_LN_W1, STEP_C2],
                0.1 * tol,
                MAX_NEWTON,
                jac,
                |[lw, c2]| at(zone(lw), c2),
                |s| [s.sigma[0], s.sigma[1]],
                |[lw, c2]: [f64; 2], [d_lw, d_c2]: [f64; 2]| {
                    // at most a factor e in w1 and 0.05 in c2 per step: the border constants
                    // vary on the scales of a decade of w1 and of c2 + c (section 10's scans)
                    let damp = 1.0f64.min(1.0 / d_lw.abs()).min(0.05 / d_c2.abs());
                    let lw = lw + damp * d_lw;
                    // (the Jacobian's step in c2 stays left of c)
                    let c2 = (c2 + damp * d_c2).clamp(-1.0 + 2.0 * lw.exp(), c - 10.0 * STEP_C2);
                    // the edge zone stays within half the span to c2
                    let lw = lw.min((0.5 * (1.0 + c2)).ln());
                    if lw.exp() < W1_MIN {
                        return Err(Error::NoConvergence(format!(
                            "exact: the trailing edge zone went below {W1_MIN:e}, thinner \
                             than the bases resolve"
                        )));
                    }
                    let last = (damp * d_c2).abs().max(lw.exp() * (damp * d_lw).abs());
                    Ok(([lw, c2], last))
                },
            )?;
            Ok(Level {
                edge: zone(lw),
                c2,
                state,
                step,
                solves,
            })
        }
    }
}

/// Breakpoints of a solution, as (1 + x, 1 - x).
fn breakpoints(s: &Solved) -> Vec<(f64, f64)> {
    let f = &s.frame;
    let mut out = vec![(0.0, 2.0)];
    let mut acc = 0.0;
    for i in 0..f.zone_count() {
        acc += f.zone_len(i);
        let omx: f64 = (i + 1..f.zone_count()).map(|j| f.zone_len(j)).sum();
        out.push((acc.min(2.0 - omx), omx));
    }
    out
}

/// int p and int q of a solved state by the graded rule of [`contact_rule`] on its returned
/// tractions (not the bases' moments): the equilibrium checks of the tests.
#[cfg(test)]
pub(crate) fn quadrature_forces(g: f64, s: &Solved) -> (f64, f64) {
    contact_rule(g, s, s)
        .into_iter()
        .fold((0.0, 0.0), |(ip, iq), (opx, omx, w)| {
            let (p, q) = s.tractions(opx, omx);
            (ip + w * p, iq + w * q)
        })
}

/// Quadrature nodes (1 + x, 1 - x) and weights over [-1, 1] with breakpoints at both
/// solutions' zone ends: each half piece graded geometrically towards its end (ratio
/// [`GRADING`], [`GRADED_LEVELS`] levels), [`RULE_POINTS`]-point Gauss-Legendre per
/// subinterval, Gauss-Jacobi with the exponent -g on the last subinterval at the contact's
/// ends. A subinterval [r h, h] sees the end's singularity at r / (1 - r) of its length
/// (normalised 2 r / (1 - r) = 0.5 for r = 0.2), so Gauss-Legendre converges like
/// (1.5 + sqrt(1.25))^(-2n) = 2.6^(-2n): 1e-17 at n = 20 (with ratio 0.1 and 12 points,
/// 2e-7, which the rule was off by on int p of the normal load).
pub(crate) fn contact_rule(g: f64, a: &Solved, b: &Solved) -> Vec<(f64, f64, f64)> {
    let mut bp = breakpoints(a);
    bp.extend(breakpoints(b));
    rule_on(g, bp)
}

/// [`contact_rule`] on the breakpoints `bp` ((1 + x, 1 - x), both contact ends among them,
/// in any order; duplicates are dropped).
pub(crate) fn rule_on(g: f64, mut bp: Vec<(f64, f64)>) -> Vec<(f64, f64, f64)> {
    use crate::numerics::quadrature::{gauss_jacobi, gauss_legendre};
    bp.sort_by(|u, v| u.0.total_cmp(&v.0));
    bp.dedup_by(|u, v| (u.0 - v.0).abs() <= 1e-15 * v.0.max(1e-300));
    let (gl_x, gl_w) = gauss_legendre(RULE_POINTS);
    let (gj_x, gj_w) = gauss_jacobi(RULE_POINTS, 0.0, -g);
    let mut out = Vec::new();
    for pair in bp.windows(2) {
        let ((oa, ma), (ob, mb)) = (pair[0], pair[1]);
        let len = if oa < mb { ob - oa } else { ma - mb };
        if len <= 0.0 {
            continue;
        }
        // from the left end: s in [lo, hi] offsets from a; from the right end likewise
        let half = 0.5 * len;
        for from_left in [true, false] {
            let contact_end = if from_left { oa == 0.0 } else { mb == 0.0 };
            let mut hi = half;
            for level in 0..=GRADED_LEVELS {
                let last = level == GRADED_LEVELS;
                let lo = if last { 0.0 } else { GRADING * hi };
                let (xs, ws): (&[f64], &[f64]) = if last && contact_end {
                    (&gj_x, &gj_w)
                } else {
                    (&gl_x, &gl_w)
                };
                for (t, wt) in xs.iter().zip(ws) {
                    let s = lo + 0.5 * (hi - lo) * (1.0 + t);
                    let wq = 0.5 * (hi - lo) * wt;
                    let wq = if last && contact_end {
                        // the rule carries the weight (2 s / hi)^(-g): take it out of f
                        wq * (2.0 * s / (hi - lo)).powf(g)
                    } else {
                        wq
                    };
                    let (opx, omx) = if from_left {
                        (oa + s, ma - s)
                    } else {
                        (ob - s, mb + s)
                    };
                    out.push((opx, omx, wq));
                }
                hi = lo;
            }
        }
    }
    out
}

const GRADING: f64 = 0.2;
const GRADED_LEVELS: usize = 20;
const RULE_POINTS: usize = 20;

/// int |p_a - p_b| + |q_a - q_b| over the contact (the traction norm (T1) of theory.md).
pub(crate) fn distance(g: f64, a: &Solved, b: &Solved) -> f64 {
    contact_rule(g, a, b)
        .into_iter()
        .map(|(opx, omx, w)| {
            let (pa, qa) = a.tractions(opx, omx);
            let (pb, qb) = b.tractions(opx, omx);
            w * ((pa - pb).abs() + (qa - qb).abs())
        })
        .sum()
}

/// The monotonic end state with error estimates.
pub(crate) struct Monotonic {
    pub(crate) k: Coupling,
    /// Q/P.
    pub(crate) qp: f64,
    /// The normal load's stick half-width (COUPLED) and its state on the frame.
    pub(crate) c: f64,
    pub(crate) normal: Solved,
    pub(crate) level: Level,
    /// Bounds on |c1 - c1_exact| + |c2 - c2_exact| and on the traction norm (T1).
    pub(crate) c_error: f64,
    pub(crate) traction_error: f64,
    /// Levels used and fixed-geometry solves in all.
    pub(crate) levels: usize,
    pub(crate) solves: usize,
    /// Per level after the first, the unknowns (w1, c2) ([`Trace`]).
    pub(crate) trace: Trace,
}

/// Panels per half-width of the grid LCP that gives the start of c2 (cost about a
/// millisecond; its c2 lies within about 0.2 / START_PANELS of the exact one at the ply).
pub(crate) const START_PANELS: usize = 25;

/// The edge zone's width while the start's c2 is corrected: about the ply's (1.2e-6 ..
/// 1.6e-6, docs/theory_tangential.md section 10). At the ply, Q = 0.006 mu P, the border
/// value at c2 moved by about 1e-4 per decade of w1 and by 1e-3 per 2e-3 of c2.
pub(crate) const START_W1: f64 = 1e-6;

/// Levels tried at most: the scenes of docs/theory_tangential.md section 12 stopped at
/// levels 2-8 (698 unknowns at level 8).
pub(crate) const MAX_LEVEL: usize = 8;

/// Factor on the distance between two levels in the estimates (as the normal-load solver's,
/// docs/theory_spectral.md (S6)).
pub(crate) const SAFETY: f64 = 2.0;

/// One level of a ladder ([`ladder`]): the two unknowns its border constants fix, its last
/// Newton step's size in them (its own error bound), its state and its fixed-geometry solves.
pub(crate) trait Rung {
    fn unknowns(&self) -> (f64, f64);
    /// The unknowns' change from the level `before` (the sum over them).
    fn moved(&self, before: &Self) -> f64 {
        let ((a0, a1), (b0, b1)) = (self.unknowns(), before.unknowns());
        (a1 - b1).abs() + (a0 - b0).abs()
    }
    fn step(&self) -> f64;
    fn state(&self) -> &Solved;
    fn solves(&self) -> usize;
}

impl Rung for Level {
    fn unknowns(&self) -> (f64, f64) {
        (self.w1(), self.c2)
    }
    fn step(&self) -> f64 {
        self.step
    }
    fn state(&self) -> &Solved {
        &self.state
    }
    fn solves(&self) -> usize {
        self.solves
    }
}

/// Per level after the first: (level, the two unknowns, their change from the level before
/// plus both levels' steps, the traction distance (T1) to it, the level's solves).
pub(crate) type Trace = Vec<(usize, f64, f64, f64, f64, usize)>;

/// The level a ladder stopped at, with its estimates.
pub(crate) struct Climbed<L> {
    pub(crate) level: L,
    /// [`SAFETY`] times the unknowns' change plus both steps, and times the traction distance.
    pub(crate) c_error: f64,
    pub(crate) traction_error: f64,
    pub(crate) levels: usize,
    /// Solves in all, `solves` given to [`ladder`] included.
    pub(crate) solves: usize,
    pub(crate) trace: Trace,
}

/// The ladder of levels `first`, `first` + 1, ... up to [`MAX_LEVEL`], each
/// `solve(level, the level before)`, until two levels agree within `tol` (the unknowns) and
/// `traction_tol` (the tractions); Ok(Err(trace)) where none do, Err where a level fails.
/// The loading's and the unloading's solvers climb it.
pub(crate) fn ladder<L: Rung>(
    g: f64,
    first: usize,
    tol: f64,
    traction_tol: f64,
    mut solves: usize,
    mut solve: impl FnMut(usize, Option<&L>) -> Result<L>,
) -> Result<std::result::Result<Climbed<L>, Trace>> {
    let mut trace = Vec::new();
    let mut prev: Option<L> = None;
    for level in first..=MAX_LEVEL {
        let l = solve(level, prev.as_ref())?;
        solves += l.solves();
        if let Some(p) = &prev {
            let (a0, a1) = l.unknowns();
            let dc = l.moved(p) + l.step() + p.step();
            let dt = distance(g, l.state(), p.state());
            let (c_error, traction_error) = (SAFETY * dc, SAFETY * dt);
            trace.push((level, a0, a1, dc, dt, l.solves()));
            if c_error <= tol && traction_error <= traction_tol {
                return Ok(Ok(Climbed {
                    level: l,
                    c_error,
                    traction_error,
                    levels: level,
                    solves,
                    trace,
                }));
            }
        }
        prev = Some(l);
    }
    Ok(Err(trace))
}

/// x from the offsets (1 + x, 1 - x), from the smaller one (the one with the digits).
pub(crate) fn position(opx: f64, omx: f64) -> f64 {
    if opx < omx { opx - 1.0 } else { 1.0 - omx }
}

/// int x p dx of a state, the moment the guided punch carries (per P a).
pub(crate) fn moment(g: f64, s: &Solved) -> f64 {
    contact_rule(g, s, s)
        .into_iter()
        .map(|(opx, omx, w)| w * position(opx, omx) * s.tractions(opx, omx).0)
        .sum()
}

/// The monotonic end state at Q/P = qp (0 < qp < mu), c1, c2 to `tol` and the tractions to
/// `traction_tol` in the norm (T1), by the ladder of levels 1, 2, ... until two levels agree.
pub(crate) fn monotonic(k: &Coupling, qp: f64, tol: f64, traction_tol: f64) -> Result<Monotonic> {
    if !(qp > 0.0 && qp < k.mu) {
        return Err(Error::InvalidArgument(format!(
            "exact: monotonic loading needs 0 < Q/P < mu (Q/P = {qp}, mu = {})",
            k.mu
        )));
    }
    let cs = crate::coupled::solve_to(k, 1e-13, 1e-12)?;
    let e = crate::problem::Profile::edge(&cs);
    let (c, w) = (e.c, e.one_minus_c);
    let normal = normal_load(k, c, w, 3)?;
    let g = edge_exponent(k);
    // the start: c2 of the grid LCP history at N = START_PANELS (first order, about 0.2 h
    // from the exact c2 at the ply, docs/theory_tangential.md section 7)
    let mut solves = 0;
    let c2_start = {
        let mut h = crate::lcp::history::History::new(k, START_PANELS)?;
        h.load(qp, 1)?;
        h.state().stick.1.clamp(-1.0 + 1e-3, c - 1e-3)
    };
    // the border value at c2, sigma_0 + sigma_1, depends mostly on c2: a few secant steps
    // on it at level 1 with a thin edge zone correct the grid's c2 where it is coarse
    // against c - c2 (small loads: at the ply, Q = 0.006 mu P, the grid's 0.0719 against
    // 0.085)
    let c2_start = if k.bp == 0.0 {
        c2_start
    } else {
        let lo = -1.0 + 2.0 * START_W1;
        let f = |c2: f64| -> Option<f64> {
            let edge = Edge::Zone {
                w1: START_W1,
                sign: -1.0,
            };
            let s = monotonic_fixed(k, &normal, c, w, edge, c2, qp, 1).ok()?;
            Some(s.sigma[0] + s.sigma[1])
        };
        let top = c - 10.0 * STEP_C2;
        let (mut a, mut b) = (c2_start, (c2_start + 1e-3).min(top));
        let mut best = c2_start;
        if let (Some(mut fa), Some(mut fb)) = (f(a), f(b)) {
            solves += 2;
            for _ in 0..8 {
                if fb == fa {
                    break;
                }
                let next = (b - fb * (b - a) / (fb - fa)).clamp(lo, top);
                (a, fa) = (b, fb);
                b = next;
                match f(b) {
                    Some(v) => fb = v,
                    None => break,
                }
                solves += 1;
                best = b;
                if (b - a).abs() < 1e-6 {
                    break;
                }
            }
        }
        best
    };
    let edge0 = if k.bp == 0.0 {
        Edge::None
    } else {
        // the first sign change of the border value at c1, sigma_0 - sigma_1, scanning w1
        // from 0.3 down a decade at a time at level 1 (c2 from the bp = 0 start)
        let at = |w1: f64| -> Result<f64> {
            let s = monotonic_fixed(
                k,
                &normal,
                c,
                w,
                Edge::Zone { w1, sign: -1.0 },
                c2_start,
                qp,
                1,
            )?;
            Ok(s.sigma[0] - s.sigma[1])
        };
        let (found, scanned) = edge_zone_scan(0.3f64.min(0.5 * (1.0 + c2_start)), at);
        solves += scanned;
        let w1 = found.ok_or_else(|| {
            Error::NoConvergence(format!(
                "exact: no trailing edge zone of width >= {W1_MIN:e} found (the bases resolve \
                 no thinner one)"
            ))
        })?;
        Edge::Zone { w1, sign: -1.0 }
    };
    let mut jac = None;
    let climbed = ladder(
        g,
        1,
        tol,
        traction_tol,
        solves,
        |level, prev: Option<&Level>| {
            let (edge, c2) = prev.map_or((edge0, c2_start), |p| (p.edge, p.c2));
            monotonic_level(k, &normal, c, w, edge, c2, qp, level, tol, &mut jac)
        },
    )?;
    match climbed {
        Ok(l) => Ok(Monotonic {
            k: *k,
            qp,
            c,
            normal,
            level: l.level,
            c_error: l.c_error,
            traction_error: l.traction_error,
            levels: l.levels,
            solves: l.solves,
            trace: l.trace,
        }),
        Err(trace) => {
            let last = trace
                .last()
                .map_or((f64::NAN, f64::NAN, f64::NAN), |t| (t.2, t.3, t.4));
            Err(Error::NoConvergence(format!(
                "exact: levels 1-{MAX_LEVEL} did not agree to {tol:e} (c) and {traction_tol:e} (tractions): \
                 the last two moved c by {:e} and the tractions by {:e} (c2 = {})",
                last.1, last.2, last.0
            )))
        }
    }
}

impl Monotonic {
    /// 1 + c1 and c2.
    pub(crate) fn stick_set(&self) -> (f64, f64) {
        (self.level.w1(), self.level.c2)
    }

    /// (p, q) at x given by (1 + x, 1 - x).
    pub(crate) fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        self.level.state.tractions(opx, omx)
    }

    /// The moment the guided punch carries, int x p dx (per P a; docs/theory_tangential.md
    /// section 2), by the graded rule of [`contact_rule`].
    pub(crate) fn moment(&self) -> f64 {
        moment(edge_exponent(&self.k), &self.level.state)
    }

    /// The slip's slope relative to the punch since the normal load, per pi B P:
    /// ds/dx = -(bq p + H[q] - (bq p0 + H[q0])) (zero on the stick set).
    pub(crate) fn slip_slope(&self, opx: f64, omx: f64) -> f64 {
        let s = &self.level.state;
        let l = s.frame.locate(opx, omx);
        let (p, _) = s.tractions_at(&l);
        let (_, hq) = s.hilbert_at(&l);
        let ln = self.normal.frame.locate(opx, omx);
        let (p0, _) = self.normal.tractions_at(&ln);
        let (_, hq0) = self.normal.hilbert_at(&ln);
        -(self.k.bq * (p - p0) + hq - hq0)
    }

    /// The slip since the normal load at x (per pi B P), integrated from the nearer stick end
    /// (c1 for x < c1, c2 for x > c2) by graded Gauss-Legendre; 0 on the stick set.
    pub(crate) fn slip(&self, opx: f64, omx: f64) -> f64 {
        use crate::numerics::quadrature::gauss_legendre;
        let (w1, c2) = self.stick_set();
        let (xs, ws) = gauss_legendre(16);
        // offsets from the end, towards x
        let (end_opx, end_omx, dir, len) = if opx < w1 {
            (w1, 2.0 - w1, -1.0, w1 - opx)
        } else if opx > 1.0 + c2 {
            (
                1.0 + c2,
                1.0 - c2,
                1.0,
                (1.0 + c2 - opx).abs().min(omx - (1.0 - c2)).abs(),
            )
        } else {
            return 0.0;
        };
        let len = if dir > 0.0 { (1.0 - c2) - omx } else { len };
        // the normal load's kinks +-c (its stick-slip points: H[q0] carries |x -+ c|^g) inside
        // [0, len] cut it (they were not cuts: the slope's kink at c inside one 16-point
        // piece put the slip 1.5e-4 off beyond c, docs/theory_tangential.md section 18)
        let c = self.c;
        let mut pieces = vec![0.0, len];
        for kink_opx in [1.0 - c, 1.0 + c] {
            let sk = dir * (kink_opx - end_opx);
            if sk > 0.0 && sk < len {
                pieces.push(sk);
            }
        }
        pieces.sort_by(f64::total_cmp);
        let mut total = 0.0;
        for piece in pieces.windows(2) {
            let (lo, plen) = (piece[0], piece[1] - piece[0]);
            // graded towards both ends of the piece, increasing (built the other way towards
            // plen they gave pieces of negative length, section 18)
            let cuts = crate::numerics::quadrature::graded_cuts(plen, 0.1, 11);
            for seg in cuts.windows(2) {
                let (a, b) = (seg[0], seg[1]);
                for (t, w) in xs.iter().zip(&ws) {
                    let u = a + 0.5 * (b - a) * (1.0 + t);
                    // from the piece's nearer end, so that offsets keep their digits
                    let s = if u < 0.5 * plen {
                        lo + u
                    } else {
                        piece[1] - (plen - u)
                    };
                    let (po, mo) = (end_opx + dir * s, end_omx - dir * s);
                    // a node within rounding of a zone end or kink lands on it, where H[q]
                    // is NaN: left out, as in `unload::graded` (weight below 1.4e-13 plen);
                    // so is one whose offsets round onto the normal load's kink at +-c from
                    // inside the piece (s 5.6e-17 past it: b* = 0.9, mu = 1 at Q = 0.3 mu P
                    // met one once COUPLED's c moved in its last digits)
                    if s <= lo || s >= piece[1] || po == end_opx || mo == end_omx {
                        continue;
                    }
                    let slope = self.slip_slope(po, mo);
                    if !slope.is_finite() {
                        continue;
                    }
                    total += 0.5 * (b - a) * w * slope;
                }
            }
        }
        dir * total
    }
}
