//! The exact first unloading branch (docs/theory_tangential.md sections 13-14): P held, Q
//! loaded monotonically to Q* and then decreased to Q < Q*. The state at Q is
//! path-independent from the loaded state (the grid LCP's one step and ten steps agree to
//! 4e-10 or better, section 13) and solves one problem per Q, with the loaded state (p*, q*) as data:
//!
//! - (U1) H[p] = bp q on (-1, 1);
//! - (U2) on the stick set (a1, a2): H[q] + bq p = H[q*] + bq p* (the tangential
//!   displacement moves with the punch since Q*);
//! - (U3) on the new leading zone (-1, a1): q = -mu p (slip in +x since Q*); on the trailing
//!   edge zone (a2, 1): q = +mu p (slip in -x since Q*, the loaded leading zone's direction);
//! - (U4) int p = 1, int q = Q/P; bounded tractions at a1 and a2.
//!
//! This is (M1)-(M4) with the forcing of the loaded state instead of the normal load's, the
//! thin zone at +1 (the mirror of section 10's argument) and the growing zone at -1. The
//! forcing carries the loaded state's stick-slip exponents at c1*, c2* (and the normal
//! load's at -c where the loaded stick set holds it): the stick set is split there, or poles
//! sit beyond its ends where they lie in a slip zone ([`specs`]). With bp = 0 there is no
//! zone at +1, and the branch sticks fully down to the first-slip load of (T13).
//!
//! Limits (section 13): for bp > 0 the grid shows, besides these zones, a stick layer at the
//! corner x = -1 inside the leading zone (b* = 0.9: 0.015, 0.010, 0.0088 wide at N =
//! 200, 400, 800) that this three-zone pattern omits, and early in the branch the ply's
//! corner has that structure on the scale of 1e-6; [`Unloading::admissible`] refuses an
//! answer whose leading zone slips backwards there. The five-zone pattern of that corner
//! (section 19) is solved at fixed level by [`corner`], as is its outer model without the
//! corner zone (section 20). Where the three-zone answer is refused or does not converge,
//! [`unload`] answers with the outer model ([`outer_cold`], section 21), with its own
//! admissibility check ([`Unloading::layer_check`]) and estimates; [`unload_from`] follows
//! the outer model's branch from an answer of it and hands over to the three-zone pattern
//! where the layer vanishes. The same route answers the reloading (the unloading of the
//! mirrored unloaded state, [`Mirror`]), whose mirrored corner is the unloaded trailing zone
//! ((O1) with w = 1 - a2**, docs/theory_tangential.md sections 22-23). Data with a layer
//! stuck at +1 (the reloaded state, `Start::far_layer`) is the second unloading's: [`unload`]
//! answers it with the outer model with a far layer ([`far_cold`], sections 24-25), handing
//! over to the outer model where the far layer vanishes; near the far layer's end the march's
//! steps follow the layer's law ([`LayerLaw`], section 26), and [`unload_from`] marches from
//! a far answer to that end where its ladder at the target fails.

pub(crate) mod corner;
#[cfg(test)]
pub(crate) mod tests;

use super::frame::{Kind, Sizes, Solved, ZoneSpec, solve};
use super::{
    MAX_LEVEL, MAX_NEWTON, Monotonic, START_PANELS, STEP_LN_W1, W1_MIN, edge_exponent,
    edge_zone_scan,
};
use std::sync::Arc;

use crate::error::{Error, Result};
use crate::numerics::roots::chord2;
use crate::problem::Coupling;

/// A point where the data's forcing r* = H[q*] + bq p* is singular, as 1 + x, and the side
/// on which it carries |x - x0|^g (the side that slipped in the state that made it).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Kink {
    pub(crate) opx: f64,
    pub(crate) slip_left: bool,
    /// Whether the forcing continued from the right across the point is singular there (not
    /// at c1*, where the forcing right of it is the normal load's r0, analytic at c1*).
    pub(crate) seen_from_right: bool,
    /// The same from the left (poles beyond the stick set's right end, [`specs`]).
    pub(crate) seen_from_left: bool,
}

impl Kink {
    /// The kink of the mirrored state (x -> -x): the sides swap.
    pub(crate) fn mirrored(self) -> Self {
        Kink {
            opx: 2.0 - self.opx,
            slip_left: !self.slip_left,
            seen_from_right: self.seen_from_left,
            seen_from_left: self.seen_from_right,
        }
    }
}

/// The end state of the previous branch, the data of a branch whose stick set has stuck
/// since that state (docs/theory_tangential.md sections 13 and 15): the loaded state for the
/// first unloading, an unloading state for the reloading (through [`Mirror`]).
pub(crate) trait Start: Send + Sync {
    fn coupling(&self) -> &Coupling;
    /// Q/P at this state, in its own frame.
    fn qp(&self) -> f64;
    /// The forcing's kinks, in increasing 1 + x.
    fn kinks(&self) -> Vec<Kink>;
    /// (p, q) at x given by (1 + x, 1 - x).
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64);
    /// The forcing H[q] + bq p at x given by (1 + x, 1 - x).
    fn forcing(&self, opx: f64, omx: f64) -> f64;
    /// The loads Q/P from the normal load to this state, in the contact's frame (for the
    /// grid start).
    fn path(&self) -> Vec<f64>;
    /// +1 in the contact's frame, -1 when the state is seen mirrored ([`Mirror`]).
    fn sign(&self) -> f64;
    /// Whether the corner x = -1 of this state is the loading's edge zone ((O1) of
    /// docs/theory_tangential.md section 20: q = -mu p, p ~ (1 + x)^(-g) below its first
    /// kink), the data for which the corner's outer model is derived and checked.
    fn loaded_edge_at_corner(&self) -> bool {
        false
    }
    /// Whether the corner x = +1 of this state is a slip zone on the friction bound with
    /// q = +mu p and p ~ (1 - x)^(-g) below its last kink: (O1) seen from the other end, the
    /// corner of the mirrored state ([`Mirror`]). An unloading state's trailing zone is one
    /// (docs/theory_tangential.md section 22): the reloading's data.
    fn slip_edge_at_far_corner(&self) -> bool {
        false
    }
    /// 1 + e2 of a layer (-1, e2) stuck since this state's data at the corner -1, carrying
    /// the bonded field there (an answer of the corner's outer model, docs/theory_tangential.md
    /// section 20).
    fn near_layer(&self) -> Option<f64> {
        None
    }
    /// 1 - d of a layer (d, 1) stuck since this state's data at the corner +1 (the reloaded
    /// state's, docs/theory_tangential.md section 24): the data for which [`unload`] takes
    /// the outer model with a far layer (section 25).
    fn far_layer(&self) -> Option<f64> {
        None
    }
}

/// A shared state is the state it points to.
impl<T: Start + ?Sized> Start for Arc<T> {
    fn coupling(&self) -> &Coupling {
        (**self).coupling()
    }
    fn qp(&self) -> f64 {
        (**self).qp()
    }
    fn kinks(&self) -> Vec<Kink> {
        (**self).kinks()
    }
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        (**self).tractions(opx, omx)
    }
    fn forcing(&self, opx: f64, omx: f64) -> f64 {
        (**self).forcing(opx, omx)
    }
    fn path(&self) -> Vec<f64> {
        (**self).path()
    }
    fn sign(&self) -> f64 {
        (**self).sign()
    }
    fn loaded_edge_at_corner(&self) -> bool {
        (**self).loaded_edge_at_corner()
    }
    fn slip_edge_at_far_corner(&self) -> bool {
        (**self).slip_edge_at_far_corner()
    }
    fn near_layer(&self) -> Option<f64> {
        (**self).near_layer()
    }
    fn far_layer(&self) -> Option<f64> {
        (**self).far_layer()
    }
}

/// The loaded state's kinks: c1* (edge zone left of it), -c where the loaded stick set holds
/// it (the normal load's slip zone left of it), c2* (the leading zone right of it).
impl Start for Monotonic {
    fn coupling(&self) -> &Coupling {
        &self.k
    }
    fn qp(&self) -> f64 {
        self.qp
    }
    fn kinks(&self) -> Vec<Kink> {
        let (w1, c2) = self.stick_set();
        let mut out = Vec::new();
        if w1 > 0.0 {
            out.push(Kink {
                opx: w1,
                slip_left: true,
                seen_from_right: false,
                seen_from_left: true,
            });
        }
        if c2 > -self.c {
            out.push(Kink {
                opx: 1.0 - self.c,
                slip_left: true,
                seen_from_right: true,
                seen_from_left: true,
            });
        }
        out.push(Kink {
            opx: 1.0 + c2,
            slip_left: false,
            seen_from_right: true,
            seen_from_left: true,
        });
        out
    }
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        self.level.state.tractions(opx, omx)
    }
    fn forcing(&self, opx: f64, omx: f64) -> f64 {
        forcing_of(&self.level.state, self.k.bq, opx, omx)
    }
    fn path(&self) -> Vec<f64> {
        vec![self.qp]
    }
    fn sign(&self) -> f64 {
        1.0
    }
    fn loaded_edge_at_corner(&self) -> bool {
        self.stick_set().0 > 0.0
    }
}

/// H[q] + bq p of a solved state at x given by (1 + x, 1 - x).
fn forcing_of(s: &Solved, bq: f64, opx: f64, omx: f64) -> f64 {
    let l = s.frame.locate(opx, omx);
    let (p, _) = s.tractions_at(&l);
    let (_, hq) = s.hilbert_at(&l);
    hq + bq * p
}

/// A state seen mirrored, x -> -x and q -> -q (section 5): p(-x), -q(-x), and H[q](-x)
/// (H changes sign under the reflection), so the forcing H[q] + bq p is read at -x. A branch
/// with Q rising from it is the mirror of a branch with Q falling from the mirrored state.
pub(crate) struct Mirror {
    pub(crate) inner: Arc<dyn Start>,
}

impl Start for Mirror {
    fn coupling(&self) -> &Coupling {
        self.inner.coupling()
    }
    fn qp(&self) -> f64 {
        -self.inner.qp()
    }
    fn kinks(&self) -> Vec<Kink> {
        self.inner
            .kinks()
            .into_iter()
            .rev()
            .map(Kink::mirrored)
            .collect()
    }
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        let (p, q) = self.inner.tractions(omx, opx);
        (p, -q)
    }
    fn forcing(&self, opx: f64, omx: f64) -> f64 {
        self.inner.forcing(omx, opx)
    }
    fn path(&self) -> Vec<f64> {
        self.inner.path()
    }
    fn sign(&self) -> f64 {
        -self.inner.sign()
    }
    /// The mirrored corner -1 is the inner state's +1: (O1) there when the inner state's +1
    /// is a slip zone with q = +mu p (an unloading's trailing zone: the reloading's corner,
    /// docs/theory_tangential.md section 22), so that [`unload`] routes the mirrored branch
    /// to the corner's outer model as it routes the first unloading.
    fn loaded_edge_at_corner(&self) -> bool {
        self.inner.slip_edge_at_far_corner()
    }
    fn slip_edge_at_far_corner(&self) -> bool {
        self.inner.loaded_edge_at_corner()
    }
    fn near_layer(&self) -> Option<f64> {
        self.inner.far_layer()
    }
    fn far_layer(&self) -> Option<f64> {
        self.inner.near_layer()
    }
}

/// An unloading state as the data of the next branch: its forcing is singular at a1 (the
/// leading zone left of it) and a2 (the trailing zone right of it), and inside (a1, a2),
/// where it equals its own data's forcing by (U2), at that data's kinks there; and at the
/// data's kinks in the leading zone beyond the layer that are singular seen from the stick
/// set (`seen_from_right`: the data's forcing the stick set reads continues singularly to
/// them; on the ply's unloaded state c2*, 0.019 beyond a1). Without that kink the
/// reloading's stick set, which covers it, is neither split nor its gap rule cut there, and
/// the outer model's border constants move 6.5e-5 .. 9.4e-5 between levels 3 and 4 at fixed
/// ends, against 3.7e-7 with it (docs/theory_tangential.md section 22). On (a1, a2)
/// the forcing is read from the data (exact by (U2), where the state's own H[q] + bq p
/// carries its residual), elsewhere from the state.
impl<D: Start + ?Sized> Start for Unloading<D> {
    fn coupling(&self) -> &Coupling {
        self.loaded.coupling()
    }
    fn qp(&self) -> f64 {
        self.qp
    }
    fn kinks(&self) -> Vec<Kink> {
        let (wa, hi) = (self.level.wa, 2.0 - self.level.w2.unwrap_or(0.0));
        let mut out = Vec::new();
        if let Some(e2) = self.level.layer {
            out.push(Kink {
                opx: e2,
                slip_left: false,
                seen_from_right: true,
                seen_from_left: true,
            });
        }
        let e2 = self.level.layer.unwrap_or(0.0);
        out.extend(
            self.loaded
                .kinks()
                .into_iter()
                .filter(|c| c.opx > e2 && c.opx < wa && c.seen_from_right),
        );
        out.push(Kink {
            opx: wa,
            slip_left: true,
            seen_from_right: false,
            seen_from_left: true,
        });
        out.extend(
            self.loaded
                .kinks()
                .into_iter()
                .filter(|c| c.opx > wa && c.opx < hi),
        );
        if self.level.w2.is_some() {
            out.push(Kink {
                opx: hi,
                slip_left: false,
                seen_from_right: true,
                seen_from_left: false,
            });
        }
        if let Some(wd) = self.level.far {
            out.push(Kink {
                opx: 2.0 - wd,
                slip_left: true,
                seen_from_right: true,
                seen_from_left: true,
            });
        }
        out
    }
    fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        self.level.state.tractions(opx, omx)
    }
    fn forcing(&self, opx: f64, omx: f64) -> f64 {
        let stuck = opx > self.level.wa && omx > self.level.w2.unwrap_or(0.0);
        let layers = self.level.layer.is_some_and(|e2| opx < e2)
            || self.level.far.is_some_and(|wd| omx < wd);
        if stuck || layers {
            self.loaded.forcing(opx, omx)
        } else {
            forcing_of(&self.level.state, self.loaded.coupling().bq, opx, omx)
        }
    }
    fn path(&self) -> Vec<f64> {
        let mut p = self.loaded.path();
        p.push(self.loaded.sign() * self.qp);
        p
    }
    fn sign(&self) -> f64 {
        self.loaded.sign()
    }
    /// The trailing zone (a2, 1) slips with q = +mu p, and p ~ (1 - x)^(-g) at +1 (section
    /// 13's local exponents): present wherever bp > 0, unless a far layer (d2, 1) sticks
    /// there (docs/theory_tangential.md section 24).
    fn slip_edge_at_far_corner(&self) -> bool {
        self.level.w2.is_some() && self.level.far.is_none()
    }
    fn near_layer(&self) -> Option<f64> {
        self.level.layer
    }
    fn far_layer(&self) -> Option<f64> {
        self.level.far
    }
}

/// The unloading zones: the leading zone (-1, a1) of width `wa` = 1 + a1, the stick set
/// split at the kinks inside it, and the trailing edge zone (a2, 1) of width `w2` = 1 - a2
/// (None: the stick set reaches +1, bp = 0 only).
fn specs(k: &Coupling, kinks: &[Kink], wa: f64, w2: Option<f64>) -> Vec<ZoneSpec> {
    let g = edge_exponent(k);
    let slip_end = || (vec![0.0, g], vec![0.0, g]);
    let stick_end = || (vec![0.0], vec![0.0, g]);
    let hi = 2.0 - w2.unwrap_or(0.0);
    // a kink closer than this to a zone end is taken as that end (no zone of zero length):
    // far below the thinnest zone the bases resolve (W1_MIN = 1e-7), far above the
    // offsets' rounding (1e-16)
    let gap = 1e-9;
    let inside: Vec<&Kink> = kinks
        .iter()
        .filter(|c| c.opx > wa + gap && c.opx < hi - gap)
        .collect();
    // singular points of the continuation beyond the stick set's ends (section 13)
    let before = kinks
        .iter()
        .filter(|c| c.opx <= wa + gap && c.seen_from_right)
        .map(|c| (wa - c.opx).max(gap))
        .fold(None, |a: Option<f64>, d| Some(a.map_or(d, |a| a.min(d))));
    let after = kinks
        .iter()
        .filter(|c| c.opx >= hi - gap && c.seen_from_left)
        .map(|c| (c.opx - hi).max(gap))
        .fold(None, |a: Option<f64>, d| Some(a.map_or(d, |a| a.min(d))));
    let mut out = vec![ZoneSpec {
        kind: Kind::Slip(-1.0),
        len: wa,
        p: [vec![-g], vec![0.0, g]],
        q: [vec![], vec![]],
        near: [None, None],
    }];
    let mut lo_opx = wa;
    let (mut lo_p, mut lo_q) = stick_end();
    let mut near_lo = before;
    for c in &inside {
        let (hp, hq) = if c.slip_left { slip_end() } else { stick_end() };
        out.push(ZoneSpec {
            kind: Kind::Stick,
            len: c.opx - lo_opx,
            p: [lo_p, hp],
            q: [lo_q, hq],
            near: [near_lo, None],
        });
        (lo_p, lo_q) = if c.slip_left { stick_end() } else { slip_end() };
        lo_opx = c.opx;
        near_lo = None;
    }
    let (hp, hq) = match w2 {
        Some(_) => stick_end(),
        None => (vec![-g], vec![-g]),
    };
    out.push(ZoneSpec {
        kind: Kind::Stick,
        len: hi - lo_opx,
        p: [lo_p, hp],
        q: [lo_q, hq],
        near: [near_lo, after],
    });
    if let Some(w2) = w2 {
        out.push(ZoneSpec {
            kind: Kind::Slip(1.0),
            len: w2,
            p: [vec![0.0, g], vec![-g]],
            q: [vec![], vec![]],
            near: [None, None],
        });
    }
    out
}

/// The fixed-geometry unloading solve at Q/P = `qp` from the state `m`.
pub(crate) fn unload_fixed<D: Start + ?Sized>(
    m: &D,
    wa: f64,
    w2: Option<f64>,
    qp: f64,
    level: usize,
) -> Result<Solved> {
    let k = m.coupling();
    let hi = 2.0 - w2.unwrap_or(0.0);
    if !(wa > 0.0 && wa < hi) {
        return Err(Error::InvalidArgument(format!(
            "exact unloading: stick set ({}, {}) empty or outside the contact",
            wa - 1.0,
            hi - 1.0
        )));
    }
    let forcing = |opx: f64, omx: f64| m.forcing(opx, omx);
    let n_sigma = if w2.is_some() { 2 } else { 1 };
    solve(
        *k,
        &specs(k, &m.kinks(), wa, w2),
        Sizes::at(level),
        n_sigma,
        qp,
        &forcing,
    )
}

/// For bp = 0, the first-slip load Q_s/P = Q*/P - (mu + q*/p0 at x = -1) (section 13: the
/// full-stick increment is ((Q - Q*)/P) p0, so q/p0 moves uniformly and reaches -mu first
/// where q*/p0 is least, at the corner); None for bp > 0. q*/p0 = q*/p* is read at
/// 1 + x = 1e-12, where its (1 + x)-term is below 1e-12.
pub(crate) fn first_slip<D: Start + ?Sized>(m: &D) -> Option<f64> {
    let k = m.coupling();
    (k.bp == 0.0).then(|| {
        let (p, q) = m.tractions(1e-12, 2.0 - 1e-12);
        m.qp() - (k.mu + q / p)
    })
}

/// The unloading state at one level.
pub(crate) struct Level {
    /// 1 + a1 and 1 - a2 (None: no trailing edge zone, bp = 0).
    pub(crate) wa: f64,
    pub(crate) w2: Option<f64>,
    /// 1 + e2 when the answer is the corner's outer model (docs/theory_tangential.md
    /// sections 20-21): the layer (-1, e2) stuck since Q*, the leading zone (e2, a1).
    pub(crate) layer: Option<f64>,
    /// 1 - d2 when the answer is the outer model with a far layer (sections 24-25): the
    /// far layer (d2, 1) stuck since the data, the trailing zone (a2, d2).
    pub(crate) far: Option<f64>,
    pub(crate) state: Solved,
    /// The last Newton step's size in a1 and a2 (its own error bound).
    pub(crate) step: f64,
    pub(crate) solves: usize,
}

/// Solves (U1)-(U4) at one level: the border constants' root in (ln wa, ln w2) by Newton's
/// method with a Jacobian by differences (`jac`, computed if None; the chord kept while the
/// steps halve, as [`super::monotonic_level`]); a secant in wa on the one constant when
/// bp = 0.
pub(crate) fn unload_level<D: Start + ?Sized>(
    m: &D,
    wa: f64,
    w2: Option<f64>,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 2]; 2]>,
) -> Result<Level> {
    let mut solves = 0;
    let mut at = |wa: f64, w2: Option<f64>| -> Result<Solved> {
        solves += 1;
        unload_fixed(m, wa, w2, qp, level)
    };
    let Some(w2) = w2 else {
        let (mut a, mut b) = (wa, wa * (1.0 + STEP_LN_W1));
        let mut fa = at(a, None)?.sigma[0];
        let mut sb = at(b, None)?;
        let mut step = f64::INFINITY;
        for _ in 0..MAX_NEWTON {
            let fb = sb.sigma[0];
            if fb == fa {
                break;
            }
            let next = (b - fb * (b - a) / (fb - fa)).clamp(0.5 * b, (b + 0.05).min(1.999));
            (a, fa) = (b, fb);
            b = next;
            sb = at(b, None)?;
            let last = (b - a).abs();
            let stalled = last > 0.5 * step;
            step = last;
            if step <= 0.1 * tol || stalled {
                break;
            }
        }
        return Ok(Level {
            wa: b,
            w2: None,
            layer: None,
            far: None,
            state: sb,
            step,
            solves,
        });
    };
    let ([la, lw], state, step) = chord2(
        [wa.ln(), w2.ln()],
        [STEP_LN_W1, STEP_LN_W1],
        0.1 * tol,
        MAX_NEWTON,
        jac,
        |[la, lw]| at(la.exp(), Some(lw.exp())),
        |s| [s.sigma[0], s.sigma[1]],
        |[la, lw]: [f64; 2], [d_la, d_lw]: [f64; 2]| {
            // at most a factor e in either width per step (the scales of section 10's scans)
            let damp = 1.0f64.min(1.0 / d_la.abs()).min(1.0 / d_lw.abs());
            let lw = lw + damp * d_lw;
            // the stick set keeps at least half the contact's span left by the two zones
            let la = (la + damp * d_la).min((1.0 - 0.5 * lw.exp()).ln());
            if lw.exp() < W1_MIN || la.exp() < W1_MIN {
                return Err(Error::NoConvergence(format!(
                    "exact unloading: an edge zone went below {W1_MIN:e}, thinner than the \
                     bases resolve (Newton's step to 1 + a1 = {:e}, 1 - a2 = {:e})",
                    la.exp(),
                    lw.exp()
                )));
            }
            let last = (la.exp() * damp * d_la)
                .abs()
                .max((lw.exp() * damp * d_lw).abs());
            Ok(([la, lw], last))
        },
    )?;
    Ok(Level {
        wa: la.exp(),
        w2: Some(lw.exp()),
        layer: None,
        far: None,
        state,
        step,
        solves,
    })
}

/// Fractions of a slip zone's width, from its stick end, at which [`Unloading::zone_slips`]
/// reads the slip: log-spaced towards the contact's end, where the three-zone pattern first
/// fails (section 13: at b* = 0.9 the leading zone's slip is negative from the corner to
/// 0.01 .. 0.5 of its width, at the ply at Q = 0 over all of it), down to 1e-8 of it.
pub(crate) const CHECK_FRACTIONS: [f64; 9] = [1e-8, 1e-6, 1e-4, 1e-2, 0.1, 0.3, 0.5, 0.7, 0.9];

/// The first level of the outer model's ladder: the ply's runs of docs/theory_tangential.md
/// section 20 start there (6 bonded powers, B's series to 1.6e-8).
const OUTER_FIRST: usize = 3;

/// A bound on e1/u0, the corner zone's width over the outer field's first zero of
/// q + mu p below e2 (the inner problem's constant kappa, docs/theory_tangential.md sections
/// 20-21), measured against the five-zone solver at mu/delta = 1:
///
/// | b* | 0.9 | 0.85 | 0.81 | 0.77 | 0.75 | 0.74 |
/// |---|---|---|---|---|---|---|
/// | e1/u0 | 5.93 | 5.92 | 5.88 | 5.82 | 5.79 | 5.77 |
///
/// The ends the outer model leaves out move by 0.51-0.57 e1 in all (the same table), so
/// KAPPA u0 bounds the ends' model error where e1/u0 stays below 6.
pub(crate) const KAPPA: f64 = 6.0;

/// Whether [`unload`] may answer with the corner's outer model: bp > 0 and the data's corner
/// on the friction bound as the loaded edge zone ((O1)): the loaded state's edge zone, or
/// through [`Mirror`] an unloading state's trailing zone (the reloading).
fn outer_applies<D: Start + ?Sized>(m: &D) -> bool {
    m.coupling().bp > 0.0 && m.loaded_edge_at_corner()
}

/// The outer model's march to the start at Q/P = `qp` (section 21): from the limit pattern
/// of the first step (section 19's width laws 1 + e2 = 0.08 w1*, a1 = c1* + 0.05 w1*,
/// 1 - a2 = 0.9 w1*, measured there for Q -> Q*) down the branch at level [`OUTER_FIRST`]
/// to `qp`, each load from the ends of the two before extrapolated in their logarithms,
/// steps of [`MARCH_STEP`] Q* at first, doubled after a success (up to [`MAX_MARCH_STEP`]
/// Q*) and halved after a failure (down to 1e-3 Q*); then the ladder at `qp` from there.
/// The march's loads serve only as the next load's predictor, so each is solved to
/// relative steps of [`MARCH_TOL`] only; the chord method's Jacobian is carried from load to
/// load and into the ladder's first level at `qp` (where it has gone stale the chord method
/// takes a fresh one, and a failed load drops it before the halved step).
pub(crate) fn outer_cold<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    outer_cold_with(m, qp, tol, traction_tol, true)
}

/// The relative step to which [`outer_cold`]'s march solves each load: the predictor it
/// serves (the ends extrapolated in their logarithms from the two loads before) is itself
/// off by the ends' second differences in their logarithms, 1 % .. 39 % in 1 + a1 and
/// 0.25 % .. 12 % in 1 + e2 per 0.2 Q* on the ply's reloading march (docs/theory_tangential.md
/// section 23's table, -0.9 Q* to 0.9 Q*), so a march load solved beyond 1e-3 relatively
/// does not improve the next start;
/// 1e-3 is also the chord method's restart threshold ([`corner`]'s `RESTART_ABOVE`), above
/// which its steps are still damped.
pub(crate) const MARCH_TOL: f64 = 1e-3;

/// [`outer_cold`] (`cheap`), or with every march load solved to relative steps of 1e-8 and
/// a fresh Jacobian at every load and at the ladder's first level: the march before
/// [`MARCH_TOL`] and the carried Jacobian, kept for the measurement of what they save
/// (`measure_cold_march_jacobian`, docs/theory_tangential.md section 24).
pub(crate) fn outer_cold_with<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
    cheap: bool,
) -> Result<Unloading<D>> {
    let march_tol = if cheap { MARCH_TOL } else { 1e-8 };
    let w1 = edge_width(&**m)?;
    let mut jac = None;
    let marched = march(
        Marched::start(&**m, qp, [0.08 * w1, 1.05 * w1, 0.9 * w1]),
        qp,
        cheap,
        march_tol,
        &mut jac,
        None,
        |x, q, t, jac| corner::outer_level(&**m, x, q, OUTER_FIRST, t, jac),
    );
    if let Some((next, e)) = marched.stopped {
        return Err(e.reworded(|msg| {
            format!("marching the outer model down to Q/P = {qp}, at {next}: {msg}")
        }));
    }
    corner_zone_above(&**m, marched.reached.as_ref(), tol)?;
    if !cheap {
        jac = None;
    }
    layered_answer(m, qp, tol, traction_tol, marched.x, &mut jac).map(|mut u| {
        u.solves += marched.solves;
        u
    })
}

/// The width of the data's slip zone at -1 ((O1): its first kink, with the slip zone on its
/// left), the scale of section 19's width laws.
fn edge_width<D: Start + ?Sized>(m: &D) -> Result<f64> {
    match m.kinks().first() {
        Some(c) if c.slip_left => Ok(c.opx),
        _ => Err(Error::InvalidArgument(
            "exact corner (outer): the data has no edge zone at -1".into(),
        )),
    }
}

/// Where a march along a layered model's branch has got to ([`march`]).
struct Marched<const N: usize, L = corner::LayeredLevel<N>> {
    /// The load reached and its ends; the load and ends before it (the predictor's).
    t: f64,
    x: [f64; N],
    before: Option<(f64, [f64; N])>,
    /// The last load's solution (None: none solved yet).
    reached: Option<L>,
    /// The next step, and the step's unit ([`Marched::start`]).
    h: f64,
    unit: f64,
    solves: usize,
    /// Why the march stopped short of its target: the last failed load and its failure, once
    /// the step had been halved below [`MIN_MARCH_STEP`] units.
    stopped: Option<(f64, Error)>,
}

impl<const N: usize, L> Marched<N, L> {
    /// A march from the data's load with the ends `x` (the width laws of the first step).
    /// The step's unit is the data's load |Q*|/P (a cycle's amplitude; the data's Q is
    /// negative in its own frame for a reversal on the way down, seen mirrored), or, at
    /// Q* = 0, the distance to the target `qp`.
    fn start<D: Start + ?Sized>(m: &D, qp: f64, x: [f64; N]) -> Self {
        let q_star = m.qp();
        let unit = if q_star != 0.0 {
            q_star.abs()
        } else {
            q_star - qp
        };
        Marched {
            t: q_star,
            x,
            before: None,
            reached: None,
            h: MARCH_STEP * unit,
            unit,
            solves: 0,
            stopped: None,
        }
    }
}

/// The layered models' march down the branch to Q/P = `qp` from `at` (section 21; the
/// first march of [`outer_cold`], now for either model): each load from the ends of the two
/// before extrapolated in their logarithms, solved by `solve(guess, load, tolerance, jac)`
/// to relative steps of `march_tol`, steps doubled after a success (up to
/// [`MAX_MARCH_STEP`] units) and halved after a failure; the Jacobian carried from load to
/// load when `keep` (a failed load drops it). It returns where it got to, with the last
/// failure in `stopped` if the step fell below [`MIN_MARCH_STEP`] units before `qp`.
fn march<const N: usize, L: Marchable<N>>(
    mut at: Marched<N, L>,
    qp: f64,
    keep: bool,
    march_tol: f64,
    jac: &mut Option<[[f64; N]; N]>,
    layer: Option<(usize, f64)>,
    mut solve: impl FnMut([f64; N], f64, f64, &mut Option<[[f64; N]; N]>) -> Result<L>,
) -> Marched<N, L> {
    while at.t > qp {
        let (t, x) = (at.t, at.x);
        // the layer's law from the two loads before, where the layer falls
        let law = layer.and_then(|(i, alpha)| {
            at.before
                .and_then(|(tb, xb)| LayerLaw::fit((tb, xb[i]), (t, x[i]), alpha))
                .map(|l| (i, l))
        });
        // the law governs the steps, the layer's prediction and the floor where its step is
        // below the march's largest: near the layer's end
        let law = law.filter(|(_, l)| LAW_STEP * l.d < MAX_MARCH_STEP * at.unit);
        if let Some((_, l)) = &law {
            at.h = at.h.min(LAW_STEP * l.d);
        }
        let next = (t - at.h).max(qp);
        let mut guess = at.before.map_or(x, |(tb, xb)| {
            let r = (next - t) / (t - tb);
            std::array::from_fn(|i| x[i] * (x[i] / xb[i]).powf(r))
        });
        let mut below = None;
        if let Some((i, l)) = &law {
            guess[*i] = l.at(t - next);
            if guess[*i] < corner::LAYER_MIN {
                below = Some(Error::NoConvergence(format!(
                    "the layer's law (Q - Q0)^{:.3} puts it at {:e} there, below LAYER_MIN \
                     (Q0 at {:e} below the last load)",
                    l.alpha, guess[*i], l.d
                )));
            }
        }
        if !keep {
            *jac = None;
        }
        let solved = match below {
            Some(e) => Err(e),
            None => solve(guess, next, march_tol, jac),
        };
        match solved {
            Ok(o) => {
                at.solves += o.solves();
                at.before = Some((t, x));
                (at.t, at.x) = (next, o.ends());
                at.h = (2.0 * at.h).min(MAX_MARCH_STEP * at.unit);
                at.reached = Some(o);
            }
            Err(e) => {
                *jac = None;
                at.h *= 0.5;
                let floor = law.map_or(MIN_MARCH_STEP * at.unit, |(_, l)| {
                    (MIN_MARCH_STEP * at.unit).min(LAW_FLOOR * l.d)
                });
                if at.h < floor {
                    at.stopped = Some((next, e));
                    return at;
                }
            }
        }
    }
    at
}

/// What [`march`] needs of a load's solution: its ends and its count of solves.
pub(crate) trait Marchable<const N: usize> {
    fn ends(&self) -> [f64; N];
    fn solves(&self) -> usize;
}

impl<const N: usize> Marchable<N> for corner::LayeredLevel<N> {
    fn ends(&self) -> [f64; N] {
        self.x
    }
    fn solves(&self) -> usize {
        self.solves
    }
}

/// A vanishing layer's width against the load, w = C (Q - Q0)^alpha (docs/theory_tangential.md
/// section 26), fitted through two loads of a march: `d` the distance of the later load to
/// Q0 (in the march's direction), `w` the layer there.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LayerLaw {
    pub(crate) alpha: f64,
    pub(crate) d: f64,
    pub(crate) w: f64,
}

impl LayerLaw {
    /// The law through (t0, w0) and (t1, w1), t1 after t0 along the march, where the layer
    /// falls (w1 < w0): (w1/w0)^(1/alpha) = d1/d0 = r, d0 - d1 = |t0 - t1|, so
    /// d1 = r |t0 - t1| / (1 - r). None where it does not fall (or a width is not positive).
    pub(crate) fn fit((t0, w0): (f64, f64), (t1, w1): (f64, f64), alpha: f64) -> Option<Self> {
        if !(w1 > 0.0 && w0 > w1 && t0 != t1) {
            return None;
        }
        let r = (w1 / w0).powf(1.0 / alpha);
        Some(LayerLaw {
            alpha,
            d: r * (t0 - t1).abs() / (1.0 - r),
            w: w1,
        })
    }

    /// The layer a step `h` further on (zero at and past Q0).
    pub(crate) fn at(&self, h: f64) -> f64 {
        if h >= self.d {
            0.0
        } else {
            self.w * (1.0 - h / self.d).powf(self.alpha)
        }
    }
}

/// The fraction of the distance to the layer law's zero Q0 that one step of [`march`] may
/// take where a layer falls ([`LayerLaw`]): the layer falls by (1 - 1/2)^alpha, a factor 3.8
/// at the ply's alpha = 1/(1 - g) = 1.94. On the ply's far layer at level 4 steps that
/// divided it by 2.9, 2.3, 1.8 and 1.2 .. 1.4 converged from the answer before, one dividing it
/// by 26 did not (docs/theory_tangential.md section 25). It governs the march only where
/// LAW_STEP times the distance is below [`MAX_MARCH_STEP`] units: on the ply's cold march to
/// -0.4 Q* on its last step only (section 26).
pub(crate) const LAW_STEP: f64 = 0.5;

/// The smallest step of [`march`] where the layer's law holds, as a fraction of the distance
/// to its zero (below [`MIN_MARCH_STEP`] units only where that is larger): four halvings of
/// [`LAW_STEP`]'s step, a step over which the law moves the layer by 6 % (1 - 1/32)^1.94;
/// where that fails too, the march has reached the layered model's end (on the ply's far
/// layer [`corner::LAYER_MIN`], section 26).
pub(crate) const LAW_FLOOR: f64 = 1.0 / 32.0;

/// ToleranceNotMet where the corner zones' share, [`KAPPA`] times the outer fields' first
/// zeros below half of each layer, is already above the ends' tolerance at the march's last
/// load (level 3): no ladder then (at b* = 0.9 it is 8e-5, section 21).
fn corner_zone_above<D: Start + ?Sized, const N: usize>(
    m: &D,
    reached: Option<&corner::LayeredLevel<N>>,
    tol: f64,
) -> Result<()> {
    let Some(o) = reached else {
        return Ok(());
    };
    let mu = m.coupling().mu;
    let u0 = corner::first_zero(&o.state, mu, 0.5 * o.x[0], 0.95).unwrap_or(0.0);
    let v0 = o.x.get(3).map_or(0.0, |&wd| {
        corner::far_first_zero(&o.state, mu, 0.5 * wd, 0.95).unwrap_or(0.0)
    });
    let e1 = KAPPA * (u0 + v0);
    if e1 > tol {
        return Err(Error::ToleranceNotMet {
            estimate: e1,
            tolerance: tol,
            detail: format!("the ends with the corner zone, e1 <= {e1:.2e} (level {OUTER_FIRST})"),
        });
    }
    Ok(())
}

/// The second unloading's cold start (docs/theory_tangential.md sections 24-25): the data
/// has a layer stuck at +1 (the reloaded state's) and its slip zone at -1 is (O1). The
/// outer model with a far layer ([`corner::far_level`]) is marched from the data's load by
/// [`march`] from the width laws of section 24's first step (1 + e2 = 0.08 w, 1 + a1 =
/// 1.05 w, 1 - a2 = 0.9 w, 1 - d2 = 0.9 e_r; w the data's zone at -1, e_r its layer at
/// +1), then section 20's ladder at `qp` with both layers' checks and corner terms
/// ([`layered_answer`]). Where the far model stops (the far layer vanishes: on the ply
/// between -0.4 and -0.5 Q*, section 24), the march goes on from there with section 20's
/// outer model (the trailing zone reaching +1) on the far model's first three ends: the
/// hand-over. Where the far model's ladder fails at `qp` itself, the outer model's ladder
/// from the same ends is tried before the refusal.
pub(crate) fn far_cold<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    let w = edge_width(&**m)?;
    let er = m.far_layer().ok_or_else(|| {
        Error::InvalidArgument("exact corner (far layer): the data has no layer at +1".into())
    })?;
    far_route(
        m,
        Marched::start(&**m, qp, [0.08 * w, 1.05 * w, 0.9 * w, 0.9 * er]),
        qp,
        tol,
        traction_tol,
    )
}

/// The exponent of the far layer's law near its end, 1 - d2 ~ (Q - Q0)^alpha
/// (docs/theory_tangential.md section 26): alpha = 1/(1 - g), the layer's top where the
/// margin d^(1 - g) next to it is of the size of the increment, O(Q - Q0) (section 24's
/// balance, a balance rather than a solution of the inner problem); on the ply 1.940, against
/// 2.11 fitted to the far layer's last six answers (section 25).
pub(crate) fn far_law_exponent(k: &Coupling) -> f64 {
    1.0 / (1.0 - edge_exponent(k))
}

/// The far model's march from `start` (the data's load and the width laws, or an answer
/// and the one before it along the branch) to Q/P = `qp`, its steps near the far layer's
/// end sized by the layer's law ([`LayerLaw`], [`far_law_exponent`]); at `qp` the far
/// model's ladder ([`layered_answer`]); where the march stops (the far layer at its end) or
/// the ladder fails, section 20's outer model marched on from the last far ends to `qp`
/// and its ladder: the hand-over.
fn far_route<D: Start + ?Sized>(
    m: &Arc<D>,
    start: Marched<4>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    let mut jac = None;
    let far = march(
        start,
        qp,
        true,
        MARCH_TOL,
        &mut jac,
        Some((3, far_law_exponent(m.coupling()))),
        |x, q, t, jac| corner::far_level(&**m, x, q, OUTER_FIRST, t, jac),
    );
    let three = |x: [f64; 4]| [x[0], x[1], x[2]];
    let far_reason = match &far.stopped {
        None => {
            corner_zone_above(&**m, far.reached.as_ref(), tol)?;
            match layered_answer(m, qp, tol, traction_tol, far.x, &mut jac) {
                Ok(mut u) => {
                    u.solves += far.solves;
                    return Ok(u);
                }
                Err(e) => format!("its ladder at Q/P = {qp}: {e}"),
            }
        }
        Some((next, e)) => format!(
            "its march answered down to Q/P = {} and stopped at {next}: {e}",
            far.t
        ),
    };
    // the hand-over: section 20's outer model from the far model's last ends
    let mut jac3 = None;
    let near = march(
        Marched {
            t: far.t,
            x: three(far.x),
            before: far.before.map(|(t, x)| (t, three(x))),
            reached: None,
            h: (far.t - qp).min(far.h.max(MIN_MARCH_STEP * far.unit)),
            unit: far.unit,
            solves: far.solves,
            stopped: None,
        },
        qp,
        true,
        MARCH_TOL,
        &mut jac3,
        None,
        |x, q, t, jac| corner::outer_level(&**m, x, q, OUTER_FIRST, t, jac),
    );
    let refuse = |e: Error| {
        e.reworded(|msg| {
            format!(
                "the outer model with a far layer (docs/theory_tangential.md section 25): \
                 {far_reason}; section 20's outer model after it, from Q/P = {}: {msg}",
                far.t
            )
        })
    };
    if let Some((next, e)) = near.stopped {
        return Err(refuse(e.reworded(|msg| format!("at Q/P = {next}: {msg}"))));
    }
    corner_zone_above(&**m, near.reached.as_ref(), tol).map_err(refuse)?;
    layered_answer(m, qp, tol, traction_tol, near.x, &mut jac3)
        .map(|mut u| {
            u.solves += near.solves;
            u.far_end = Some((far.t, far.x[3]));
            u
        })
        .map_err(refuse)
}

/// The first and the largest step of [`outer_cold`]'s march, in units of Q*: the ply's
/// branch was followed at level 4 in steps of 0.2 Q* down to -0.4 Q*, then 0.05 and 0.01
/// (docs/theory_tangential.md section 20); the first step is the first unloading step of
/// that run (0.9 Q*), where the width laws were measured.
const MARCH_STEP: f64 = 0.1;
const MAX_MARCH_STEP: f64 = 0.2;

/// The smallest step of [`march`], in units of Q*: the step halving of section 21's march
/// (a failed load halves it, and the march gives up below 1e-3 Q*); on the ply's second
/// unloading this brackets the far layer's vanishing to within it (section 25).
const MIN_MARCH_STEP: f64 = 1e-3;

/// A layered model's answer at Q/P = `qp` from the ends `start` ([`corner::layered`]'s
/// ladder; 3 ends: the outer model, 4: with the far layer), checked
/// ([`Unloading::admissible`], with the layers' margins), its estimates raised by the terms
/// of the corner zones it leaves out: [`KAPPA`] u0 for the ends and
/// 6 (1 + delta) |B| sqrt(KAPPA u0) for the tractions in (T1) (section 21), delta =
/// sqrt(bq/bp), for the corner zone below the near layer (u0, B) and, with a far layer, for
/// the far corner zone above it (v0, B_u; the same inner problem mirrored, section 24);
/// ToleranceNotMet where those exceed the tolerances. `jac`: the chord method's Jacobian to
/// start the ladder's first level from, if any ([`corner::layered`]).
fn layered_answer<D: Start + ?Sized, const N: usize>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
    start: [f64; N],
    jac: &mut Option<[[f64; N]; N]>,
) -> Result<Unloading<D>> {
    let c = corner::layered(&**m, qp, tol, traction_tol, start, OUTER_FIRST, jac)?;
    let x = c.level.x;
    let largest = x.iter().fold(0.0f64, |a, v| a.max(*v));
    let mut u = Unloading {
        loaded: m.clone(),
        qp,
        level: Level {
            wa: x[1],
            w2: Some(x[2]),
            layer: Some(x[0]),
            far: x.get(3).copied(),
            step: c.level.step * largest,
            solves: c.level.solves,
            state: c.level.state,
        },
        c_error: c.c_error,
        traction_error: c.traction_error,
        levels: c.levels,
        solves: c.solves,
        trace: c.trace,
        far_end: None,
    };
    u.admissible()?;
    let k = m.coupling();
    let mut e1 = 0.0;
    for (z, b) in [u.layer_check()?, u.far_layer_check()?] {
        let e = KAPPA * z;
        e1 += e;
        u.c_error += e;
        u.traction_error += 6.0 * (1.0 + (k.bq / k.bp).sqrt()) * b * e.sqrt();
    }
    for (estimate, tolerance, what) in [
        (u.c_error, tol, "ends"),
        (u.traction_error, traction_tol, "tractions"),
    ] {
        if estimate > tolerance {
            return Err(Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail: format!("the {what} with the corner zone, e1 <= {e1:.2e}"),
            });
        }
    }
    Ok(u)
}

/// Fractions of the layer's width 1 + e2 at which [`Unloading::layer_check`] reads p and
/// q: from e2 towards the corner, log-spaced below 0.1.
pub(crate) const LAYER_FRACTIONS: [f64; 9] = [0.99, 0.9, 0.5, 0.1, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10];

/// (offset of a point from its contact end, slip since Q* there) along a slip zone.
pub(crate) type Slips = Vec<(f64, f64)>;

/// The unloading state with error estimates.
pub(crate) struct Unloading<D: Start + ?Sized = Monotonic> {
    /// The state at Q* (the data: the loaded state, or a mirrored one, [`Mirror`]).
    pub(crate) loaded: Arc<D>,
    pub(crate) qp: f64,
    pub(crate) level: Level,
    /// Bounds on |a1 - a1_exact| + |a2 - a2_exact| and on the traction norm (T1) from the
    /// ladder of levels (the loaded state held fixed; its own estimates are the data's).
    pub(crate) c_error: f64,
    pub(crate) traction_error: f64,
    pub(crate) levels: usize,
    /// Fixed-geometry solves: the ladder's, and a cold outer model's march before it.
    pub(crate) solves: usize,
    /// Per level after the first, the unknowns (wa, w2) ([`super::Trace`]).
    pub(crate) trace: super::Trace,
    /// Where an answer handed over from the outer model with a far layer: the far model's
    /// march's last load (its start where no step answered) and its far layer 1 - d2 there
    /// (docs/theory_tangential.md section 26); None otherwise.
    pub(crate) far_end: Option<(f64, f64)>,
}

/// The unloading state at Q/P = qp (-mu < qp < Q*/P) from the loaded state `m`, a1, a2 to
/// `tol` and the tractions to `traction_tol`, by the ladder of levels 1, 2, ... until two
/// levels agree. The start: a1 of the grid LCP history at N = [`START_PANELS`] (loaded to
/// Q* and unloaded in one step each); then, for bp > 0, w2 from the first sign change of the
/// border value at a2, sigma_0 + sigma_1, at level 1 scanning w2 = 0.3, 0.03, ... down to
/// [`W1_MIN`] (as the loading's scan of w1).
///
/// Where that answer is refused or does not converge and the data's corner is the loaded
/// edge zone with bp > 0, or (mirrored) an unloading state's trailing zone (the reloading,
/// section 23) (the corner structure of docs/theory_tangential.md section 19), the
/// answer is the corner's outer model instead ([`outer_cold`], section 21), with its own
/// admissibility check and estimates; if that fails too, the three-zone refusal is returned
/// (its status) with the outer model's reason appended (a ToleranceNotMet of the outer
/// model, where the corner zone it leaves out exceeds the tolerance, reads "tolerance not
/// met" there).
pub(crate) fn unload<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    check_load(&**m, qp)?;
    if m.far_layer().is_some() {
        return far_cold(m, qp, tol, traction_tol);
    }
    match three_zone(m, qp, tol, traction_tol) {
        Err(e @ (Error::NoAdmissibleSolution(_) | Error::NoConvergence(_)))
            if outer_applies(&**m) =>
        {
            outer_cold(m, qp, tol, traction_tol).map_err(|o| {
                e.reworded(|msg| format!("{msg}; the corner's outer model (section 21): {o}"))
            })
        }
        other => other,
    }
}

/// The three-zone answer of [`unload`] (its grid start, scan of w2, ladder and check).
pub(crate) fn three_zone<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    let k = m.coupling();
    let mut solves = 0;
    let wa0 = {
        let mut h = crate::lcp::history::History::new(k, START_PANELS)?;
        for q in m.path() {
            h.load(q, 1)?;
        }
        h.load(m.sign() * qp, 1)?;
        let (s0, s1) = h.state().stick;
        let a1 = if m.sign() > 0.0 { s0 } else { -s1 };
        if a1.is_finite() {
            (1.0 + a1).clamp(0.5 / START_PANELS as f64, 1.5)
        } else {
            0.5 / START_PANELS as f64
        }
    };
    let w2_0 = if k.bp == 0.0 {
        None
    } else {
        let at = |w2: f64| -> Result<f64> {
            let s = unload_fixed(&**m, wa0, Some(w2), qp, 1)?;
            Ok(s.sigma[0] + s.sigma[1])
        };
        let (found, scanned) = edge_zone_scan(0.3f64.min(0.5 * (2.0 - wa0)), at);
        solves += scanned;
        Some(found.ok_or_else(|| {
            Error::NoConvergence(format!(
                "exact unloading: no trailing edge zone of width >= {W1_MIN:e} found"
            ))
        })?)
    };
    ladder(m, qp, tol, traction_tol, (wa0, w2_0), 1, solves)
}

/// Q/P must lie on the branch: -mu < Q/P < Q*/P, and below the first-slip load when bp = 0.
fn check_load<D: Start + ?Sized>(m: &D, qp: f64) -> Result<()> {
    let (k, q_star) = (m.coupling(), m.qp());
    if m.near_layer().is_some() {
        return Err(Error::InvalidArgument(
            "exact unloading: the data has a stuck layer at the branch's corner -1 (an answer \
             of the corner's outer model there, docs/theory_tangential.md sections 21 and 23), \
             which no branch takes as data yet"
                .into(),
        ));
    }
    if m.far_layer().is_some() && !(k.bp > 0.0 && m.loaded_edge_at_corner()) {
        return Err(Error::InvalidArgument(
            "exact unloading: the data has a stuck layer at +1 but no slip zone on the bound at \
             -1 ((O1) of docs/theory_tangential.md section 20), the only such data the outer \
             model with a far layer is derived for (section 24)"
                .into(),
        ));
    }
    if !(qp < q_star && qp > -k.mu) {
        return Err(Error::InvalidArgument(format!(
            "exact unloading: needs -mu < Q/P < Q*/P (Q/P = {qp}, Q*/P = {q_star}, mu = {})",
            k.mu
        )));
    }
    if let Some(qs) = first_slip(m)
        && qp >= qs
    {
        return Err(Error::InvalidArgument(format!(
            "exact unloading: with bp = 0 the branch sticks fully down to Q_s/P = {qs} \
             (q = q* + (Q - Q*)/P p0, docs/theory_tangential.md (T13)); Q/P = {qp} is above it"
        )));
    }
    Ok(())
}

/// The unloading state at Q/P = qp from the answer `prev` at another load of the same
/// branch (a warm start along a path): Newton from prev's (wa, w2), extrapolated linearly in
/// Q (wa, and ln w2) when the answer `before` prev is given too; no grid start and no scan
/// of w2; the ladder from level 1 (started at prev's last level but one, it took more time
/// than the cold start on the ply: each solve at levels 4-5 costs several at levels 1-2,
/// section 14), and the cold start [`unload`] if that ladder does not converge.
pub(crate) fn unload_from<D: Start + ?Sized>(
    prev: &Unloading<D>,
    before: Option<&Unloading<D>>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
) -> Result<Unloading<D>> {
    let m = &prev.loaded;
    check_load(&**m, qp)?;
    let (wa, w2) = (prev.level.wa, prev.level.w2);
    if let (Some(e2), Some(w2), Some(wd)) = (prev.level.layer, w2, prev.level.far) {
        // the far model's ladder from prev's ends; where it fails, the far model marched from
        // prev (and the answer before it, where that has a far layer too) to the far layer's
        // end and the hand-over there (section 26); then section 20's outer model from prev's
        // first three ends (section 25's hand-over), then the cold start
        let x = [e2, wa, w2, wd];
        let far = layered_answer(m, qp, tol, traction_tol, x, &mut None);
        return far
            .or_else(|_| far_route(m, far_march_from(prev, before, qp), qp, tol, traction_tol))
            .or_else(|_| {
                layered_answer(m, qp, tol, traction_tol, [e2, wa, w2], &mut None)
                    .or_else(|_| unload(m, qp, tol, traction_tol))
            });
    }
    if let (Some(e2), Some(w2)) = (prev.level.layer, w2) {
        // the outer model from prev's ends; where it fails (the layer gone), the three-zone
        // pattern from prev's stick set: the hand-over (section 21), then the cold start
        return match layered_answer(m, qp, tol, traction_tol, [e2, wa, w2], &mut None) {
            Ok(u) => Ok(u),
            Err(_) => match ladder(m, qp, tol, traction_tol, (wa, Some(w2)), 1, 0) {
                Ok(u) => Ok(u),
                Err(_) => unload(m, qp, tol, traction_tol),
            },
        };
    }
    let start = match before {
        Some(b) if b.qp != prev.qp => {
            let r = (qp - prev.qp) / (prev.qp - b.qp);
            // wa linearly (it grows fast at the phase's start, where ln wa would overshoot),
            // kept within a factor 2 of prev's; the thin w2 in its logarithm
            let wa_next = (wa + r * (wa - b.level.wa)).clamp(0.5 * wa, (2.0 * wa).min(1.9));
            let ln_next = |now: f64, then: f64| (now.ln() + r * (now.ln() - then.ln())).exp();
            (wa_next, w2.zip(b.level.w2).map(|(n, t)| ln_next(n, t)))
        }
        _ => (wa, w2),
    };
    // a start that fails (no convergence near the ply's noise floor, or a prediction off the
    // contact) falls back to the cold start
    match ladder(m, qp, tol, traction_tol, start, 1, 0) {
        Err(Error::NoConvergence(_) | Error::InvalidArgument(_)) => {
            unload(m, qp, tol, traction_tol)
        }
        other => other,
    }
}

/// The far model's march from the far answer `prev` towards Q/P = `qp` ([`far_route`]):
/// from prev's load and ends, with `before`'s as the one before where it has a far layer
/// (the predictor and the layer's law from the first step on); without it the first step
/// is half the way to `qp` (prev's ladder having failed at `qp` itself).
fn far_march_from<D: Start + ?Sized>(
    prev: &Unloading<D>,
    before: Option<&Unloading<D>>,
    qp: f64,
) -> Marched<4> {
    let ends = |u: &Unloading<D>| -> Option<[f64; 4]> {
        Some([u.level.layer?, u.level.wa, u.level.w2?, u.level.far?])
    };
    let x = ends(prev).unwrap_or([f64::NAN; 4]);
    let before = before
        .filter(|b| b.qp > prev.qp)
        .and_then(|b| ends(b).map(|xb| (b.qp, xb)));
    let unit = prev.loaded.qp().abs();
    let h = if before.is_some() {
        MARCH_STEP * unit
    } else {
        0.5 * (prev.qp - qp)
    };
    Marched {
        t: prev.qp,
        x,
        before,
        reached: None,
        h,
        unit,
        solves: 0,
        stopped: None,
    }
}

/// The ladder of levels `first`, `first` + 1, ... up to [`MAX_LEVEL`] from (wa, w2), until
/// two levels agree; the answer is checked for admissibility.
fn ladder<D: Start + ?Sized>(
    m: &Arc<D>,
    qp: f64,
    tol: f64,
    traction_tol: f64,
    start: (f64, Option<f64>),
    first: usize,
    solves: usize,
) -> Result<Unloading<D>> {
    let g = edge_exponent(m.coupling());
    let mut jac = None;
    let climbed = super::ladder(
        g,
        first,
        tol,
        traction_tol,
        solves,
        |level, prev: Option<&Level>| {
            let (wa, w2) = prev.map_or(start, |p| (p.wa, p.w2));
            unload_level(&**m, wa, w2, qp, level, tol, &mut jac)
        },
    )?;
    match climbed {
        Ok(l) => {
            let u = Unloading {
                loaded: m.clone(),
                qp,
                level: l.level,
                c_error: l.c_error,
                traction_error: l.traction_error,
                levels: l.levels,
                solves: l.solves,
                trace: l.trace,
                far_end: None,
            };
            u.admissible().map(|()| u)
        }
        Err(trace) => {
            let last = trace
                .last()
                .map_or((f64::NAN, f64::NAN, f64::NAN), |t| (t.1, t.3, t.4));
            Err(Error::NoConvergence(format!(
                "exact unloading: levels {first}-{MAX_LEVEL} did not agree to {tol:e} (a1, a2) and \
                 {traction_tol:e} (tractions): the last two moved them by {:e} and {:e} (1 + a1 = {})",
                last.1, last.2, last.0
            )))
        }
    }
}

impl super::Rung for Level {
    fn unknowns(&self) -> (f64, f64) {
        (self.wa, self.w2.unwrap_or(0.0))
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

impl<D: Start + ?Sized> Unloading<D> {
    /// Err(NoAdmissibleSolution) when a slip zone slips against its friction ((T5); the
    /// three-zone pattern does not hold there, section 13).
    pub(crate) fn admissible(&self) -> Result<()> {
        let (leading, trailing) = self.zone_slips();
        if let Some((o, s)) = leading.iter().find(|(_, s)| s.is_nan() || *s <= 0.0) {
            return Err(Error::NoAdmissibleSolution(format!(
                "exact unloading at Q/P = {}: the leading zone (-1, {}) slips against q = -mu p \
                 (slip {s:e} at 1 + x = {o:e}); the corner does not follow the three-zone \
                 pattern here (docs/theory_tangential.md section 13)",
                self.qp,
                self.level.wa - 1.0
            )));
        }
        if let Some((o, s)) = trailing.iter().find(|(_, s)| s.is_nan() || *s >= 0.0) {
            return Err(Error::NoAdmissibleSolution(format!(
                "exact unloading at Q/P = {}: the trailing zone slips against q = +mu p \
                 (slip {s:e} at 1 - x = {o:e})",
                self.qp
            )));
        }
        if self.level.layer.is_some() {
            self.layer_check()?;
        }
        if self.level.far.is_some() {
            self.far_layer_check()?;
        }
        Ok(())
    }

    /// The far layer (d2, 1) of an answer of the outer model with a far layer
    /// (docs/theory_tangential.md sections 24-25), as [`Unloading::layer_check`] mirrored:
    /// p > 0 and |q| <= mu p at the fractions [`LAYER_FRACTIONS`] of 1 - d2 that lie above
    /// v0, the outer field's first zero of mu p - q below (1 - d2)/2 ([`corner::far_first_zero`];
    /// the far corner zone sits there); Err(NoAdmissibleSolution) otherwise. Returns v0 and
    /// the new increment's bonded amplitude |B_u| = |f| v^(1/2), f = (p - p_r) +
    /// i (q - q_r)/delta ((S4): the data's own bonded field cancels), read at
    /// v = INNER (1 - d2)/2; (0, 0) without a far layer.
    pub(crate) fn far_layer_check(&self) -> Result<(f64, f64)> {
        let Some(wd) = self.level.far else {
            return Ok((0.0, 0.0));
        };
        let k = self.loaded.coupling();
        let st = &self.level.state;
        let v0 = corner::far_first_zero(st, k.mu, 0.5 * wd, 0.95).unwrap_or(0.0);
        for f in LAYER_FRACTIONS {
            let v = f * wd;
            if v <= v0 {
                break;
            }
            let (p, q) = st.tractions(2.0 - v, v);
            if !(p > 0.0 && q.abs() <= k.mu * p) {
                return Err(Error::NoAdmissibleSolution(format!(
                    "exact corner (far layer) at Q/P = {}: the layer ({}, 1) stuck since the \
                     data breaks |q| <= mu p at 1 - x = {v:e} (p = {p:e}, q = {q:e}; the outer \
                     field's first zero of mu p - q lies at {v0:e}; docs/theory_tangential.md \
                     section 25)",
                    self.qp,
                    1.0 - wd
                )));
            }
        }
        let v = 0.5 * corner::INNER * wd;
        let (p, q) = st.tractions(2.0 - v, v);
        let (pr, qr) = self.loaded.tractions(2.0 - v, v);
        let b = (p - pr).hypot((q - qr) / (k.bq / k.bp).sqrt()) * v.sqrt();
        Ok((v0, b))
    }

    /// The corner's stuck layer (-1, e2) of an outer-model answer (docs/theory_tangential.md
    /// section 21): p > 0 and |q| <= mu p at the fractions [`LAYER_FRACTIONS`] of 1 + e2
    /// that lie above u0, the outer field's first zero of q + mu p ((O4)) below e2/2, where
    /// the corner zone sits (e1 ~ KAPPA u0; found by [`corner::first_zero`], scanning by
    /// factors 0.95); Err(NoAdmissibleSolution) otherwise. Returns u0 and the bonded
    /// amplitude |B| = |f| u^(1/2), f = (p - p*) + i (q - q*)/delta, read at u = INNER e2/2
    /// (inside the corner zone's columns, where f = u^beta B(u) with B's series converged).
    pub(crate) fn layer_check(&self) -> Result<(f64, f64)> {
        let Some(e2) = self.level.layer else {
            return Ok((0.0, 0.0));
        };
        let k = self.loaded.coupling();
        let st = &self.level.state;
        let refuse = |what: String| {
            Error::NoAdmissibleSolution(format!(
                "exact corner (outer) at Q/P = {}: the layer (-1, {}) stuck since Q* {what} \
                 (docs/theory_tangential.md section 21)",
                self.qp,
                e2 - 1.0
            ))
        };
        let u0 = corner::first_zero(st, k.mu, 0.5 * e2, 0.95).unwrap_or(0.0);
        for f in LAYER_FRACTIONS {
            let o = f * e2;
            if o <= u0 {
                break;
            }
            let (p, q) = st.tractions(o, 2.0 - o);
            if !(p > 0.0 && q.abs() <= k.mu * p) {
                return Err(refuse(format!(
                    "breaks |q| <= mu p at 1 + x = {o:e} (p = {p:e}, q = {q:e}; the outer \
                     field's first zero of q + mu p lies at {u0:e})"
                )));
            }
        }
        let u = 0.5 * corner::INNER * e2;
        let (p, q) = st.tractions(u, 2.0 - u);
        let (ps, qs) = self.loaded.tractions(u, 2.0 - u);
        let b = (p - ps).hypot((q - qs) / (k.bq / k.bp).sqrt()) * u.sqrt();
        Ok((u0, b))
    }

    /// (a1, a2), the stick set.
    pub(crate) fn stick_set(&self) -> (f64, f64) {
        (self.level.wa - 1.0, 1.0 - self.level.w2.unwrap_or(0.0))
    }

    /// (p, q) at x given by (1 + x, 1 - x).
    pub(crate) fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        self.level.state.tractions(opx, omx)
    }

    /// The slip's slope relative to the punch since Q*, per pi B P:
    /// -(bq (p - p*) + H[q] - H[q*]) (zero on the stick set).
    pub(crate) fn slip_slope(&self, opx: f64, omx: f64) -> f64 {
        let own = forcing_of(&self.level.state, self.loaded.coupling().bq, opx, omx);
        -(own - self.loaded.forcing(opx, omx))
    }

    /// The slip since Q* at x (per pi B P), integrated from the nearer stick end by
    /// Gauss-Legendre graded towards both ends of each piece (the loaded state's kinks inside
    /// the leading zone are breakpoints too); 0 on the stick set and on the corner's stuck
    /// layer (its corner zone, e1 ~ 1e-19 at the ply, is the inner problem's). The trailing
    /// zone is integrated in 1 - x, so that points within rounding of +1 keep their offsets.
    /// Between the layer and the stick set the leading zone is integrated from the nearer of
    /// its stick ends e2 and a1 (the slip vanishes at both, (C2)).
    pub(crate) fn slip(&self, opx: f64, omx: f64) -> f64 {
        let (wa, w2) = (self.level.wa, self.level.w2.unwrap_or(0.0));
        if let Some(e2) = self.level.layer
            && opx < wa
        {
            if opx <= e2 {
                return 0.0;
            }
            if opx - e2 < wa - opx {
                // s(x) = int_{e2}^x slope
                let mut cuts = vec![e2, opx];
                for c in self.loaded.kinks() {
                    if c.opx > e2 && c.opx < opx {
                        cuts.push(c.opx);
                    }
                }
                cuts.sort_by(|a, b| a.total_cmp(b));
                return cuts
                    .windows(2)
                    .map(|w| graded(w[0], w[1], &|o| self.slip_slope(o, 2.0 - o)))
                    .sum::<f64>();
            }
        }
        if opx < wa {
            // s(x) = -int_x^{a1} slope, in 1 + x
            let mut cuts = vec![opx, wa];
            for c in self.loaded.kinks() {
                if c.opx > opx && c.opx < wa {
                    cuts.push(c.opx);
                }
            }
            cuts.sort_by(|a, b| a.total_cmp(b));
            -cuts
                .windows(2)
                .map(|w| graded(w[0], w[1], &|o| self.slip_slope(o, 2.0 - o)))
                .sum::<f64>()
        } else if omx < w2 {
            let wd = self.level.far.unwrap_or(0.0);
            if omx <= wd {
                return 0.0;
            }
            // the data's kinks inside the trailing zone (the reloaded state's layer top,
            // section 24) cut the rule, in 1 - x; a node whose slope is not finite is one that
            // the frame places onto a zone end (the far layer's top d2 is held in 1 + x, whose
            // ulp 2.2e-16 exceeds the rule's nodes nearest d2 when 1 - d2 < 1e-10, section
            // 25), where the zones' H[q] is NaN: left out, as in [`graded`] (its weight below
            // 1.4e-13 of the piece, the slope bounded there)
            let slope = |r: f64| {
                let v = self.slip_slope(2.0 - r, r);
                if v.is_finite() { v } else { 0.0 }
            };
            let piecewise = |lo: f64, hi: f64| {
                let mut cuts = vec![lo, hi];
                for c in self.loaded.kinks() {
                    let r = 2.0 - c.opx;
                    if r > lo && r < hi {
                        cuts.push(r);
                    }
                }
                cuts.sort_by(f64::total_cmp);
                cuts.windows(2)
                    .map(|w| graded(w[0], w[1], &slope))
                    .sum::<f64>()
            };
            if self.level.far.is_some() && omx - wd < w2 - omx {
                // s(x) = -int_x^{d2} slope = -int_{1 - d2}^{1 - x} slope d(1 - x): from the
                // far layer, the nearer stick end (the slip vanishes at both, (C2))
                -piecewise(wd, omx)
            } else {
                // s(x) = int_{a2}^x slope = int_{1 - x}^{w2} slope d(1 - x)
                piecewise(omx, w2)
            }
        } else {
            0.0
        }
    }

    /// The slip since Q* at 1 + x = f wa in the leading zone for each fraction f of
    /// [`CHECK_FRACTIONS`] (one running integral from a1 towards -1), and at 1 - x = f w2 in
    /// the trailing zone: (leading, trailing). By (T5) the first must be > 0 (q = -mu p) and
    /// the second < 0 (q = +mu p).
    pub(crate) fn zone_slips(&self) -> (Slips, Slips) {
        let (wa, w2) = (self.level.wa, self.level.w2.unwrap_or(0.0));
        // with a far layer the trailing zone (a2, d2) at the fractions of its width from d2,
        // each point from its nearer stick end
        let wd = self.level.far.unwrap_or(0.0);
        let trailing = || {
            CHECK_FRACTIONS
                .iter()
                .map(|f| {
                    let o = wd + f * (w2 - wd);
                    (o, self.slip(2.0 - o, o))
                })
                .collect()
        };
        if let Some(e2) = self.level.layer {
            // the leading zone (e2, a1), at the fractions of its width from e2, each point
            // from its nearer stick end
            let leading = CHECK_FRACTIONS
                .iter()
                .map(|f| {
                    let o = e2 + f * (wa - e2);
                    (o, self.slip(o, 2.0 - o))
                })
                .collect();
            return (leading, trailing());
        }
        let mut marks: Vec<f64> = CHECK_FRACTIONS.iter().map(|f| f * wa).collect();
        for c in self.loaded.kinks() {
            if c.opx < wa {
                marks.push(c.opx);
            }
        }
        marks.push(wa);
        marks.sort_by(|a, b| b.total_cmp(a));
        let mut running = 0.0;
        let mut leading = Vec::new();
        for w in marks.windows(2) {
            running -= graded(w[1], w[0], &|o| self.slip_slope(o, 2.0 - o));
            if CHECK_FRACTIONS.iter().any(|f| f * wa == w[1]) {
                leading.push((w[1], running));
            }
        }
        let trailing = if w2 > 0.0 { trailing() } else { Vec::new() };
        (leading, trailing)
    }

    /// mu int p s over the leading zone (per pi B P^2): the energy the slip since Q* would
    /// have dissipated under the present pressure, by parts as [`dissipation`].
    pub(crate) fn slip_work(&self) -> f64 {
        let k = self.loaded.coupling();
        let wa = self.level.wa;
        let mut cuts = vec![0.0, wa];
        for c in self.loaded.kinks() {
            if c.opx > 0.0 && c.opx < wa {
                cuts.push(c.opx);
            }
        }
        cuts.sort_by(f64::total_cmp);
        let m = |o: f64| k.mu * self.tractions(o, 2.0 - o).0;
        by_parts(edge_exponent(k), &cuts, &m, &|o| {
            self.slip_slope(o, 2.0 - o)
        })
    }

    /// int x p dx, the moment the guided punch carries (per P a).
    pub(crate) fn moment(&self) -> f64 {
        super::moment(edge_exponent(self.loaded.coupling()), &self.level.state)
    }
}

/// int_a^b f by 16-point Gauss-Legendre on pieces graded geometrically (ratio 0.1, 11
/// levels) towards both ends, where the slip's slope carries the zone ends' exponents.
///
/// A node that rounds onto an end (x = a or x = b: its offset from that end, at least
/// 2.7e-14 (b - a), is below half an ulp of the end's coordinate, i.e. b - a < 4e-9 at
/// 1 - x = 1.4e-6) is left out: at a zone end the zones' H[q] is NaN (each zone's
/// logarithm there is infinite; they cancel only in the limit), and the node's true
/// position is not representable. Its weight is below 1.4e-13 (b - a) and the slope is
/// bounded there (the tractions are, (U4)), so the share left out is below that times the
/// slope's largest value. This was the NaN of the slip near the trailing zone's stick end
/// (docs/theory_tangential.md section 18: at 1 - x within 1.4e-12 of 1 - a2 on the ply).
fn graded(a: f64, b: f64, f: &dyn Fn(f64) -> f64) -> f64 {
    use crate::numerics::quadrature::{gauss_legendre, graded_cuts};
    let (xs, ws) = gauss_legendre(16);
    let len = b - a;
    // increasing towards b too (cuts built the other way there left pieces of negative
    // length and one 16-point piece over (0.5 len, len) at b's singularity: slips 1e-5 off,
    // docs/theory_tangential.md section 18)
    let pieces = graded_cuts(len, 0.1, 11);
    let mut total = 0.0;
    for piece in pieces.windows(2) {
        let (u, v) = (piece[0], piece[1]);
        for (t, w) in xs.iter().zip(&ws) {
            let s = u + 0.5 * (v - u) * (1.0 + t);
            // from the nearer end, so that offsets keep their digits
            let x = if s < 0.5 * len { a + s } else { b - (len - s) };
            if x <= a || x >= b {
                continue;
            }
            total += 0.5 * (v - u) * w * f(x);
        }
    }
    total
}

/// The energy dissipated in the leading zone between two states of the branch, `a` at the
/// higher load and `b` at the lower (per unit thickness, in pi B P^2; (T8) with the mean of
/// the two pressures, so second order in the load step): int mu p_mid (s_b - s_a) over
/// (-1, a1_b). With o = 1 + x and the slip increment ds(o) = -int_o^{wa_b} dslope (zero at
/// a1_b), integration by parts gives -int_0^{wa_b} dslope(o) M(o) do, M(o) = int_0^o mu p_mid,
/// where dslope = -(bq (p_b - p_a) + H[q_b] - H[q_a]) needs no loaded state.
pub(crate) fn dissipation<D: Start + ?Sized>(a: &Unloading<D>, b: &Unloading<D>) -> f64 {
    let k = a.loaded.coupling();
    let (sa, sb) = (&a.level.state, &b.level.state);
    let mut cuts = vec![0.0, a.level.wa, b.level.wa];
    for c in a.loaded.kinks() {
        if c.opx > 0.0 && c.opx < b.level.wa {
            cuts.push(c.opx);
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let m = |o: f64| {
        let (pa, _) = sa.tractions(o, 2.0 - o);
        let (pb, _) = sb.tractions(o, 2.0 - o);
        0.5 * k.mu * (pa + pb)
    };
    let dslope = |o: f64| {
        let (la, lb) = (sa.frame.locate(o, 2.0 - o), sb.frame.locate(o, 2.0 - o));
        let (pa, _) = sa.tractions_at(&la);
        let (pb, _) = sb.tractions_at(&lb);
        let (_, ha) = sa.hilbert_at(&la);
        let (_, hb) = sb.hilbert_at(&lb);
        -(k.bq * (pb - pa) + hb - ha)
    };
    by_parts(edge_exponent(k), &cuts, &m, &dslope)
}

/// -int_0^{cuts.last} f(o) M(o) do with M(o) = int_0^o m: [`graded_rule`]'s panels on each
/// piece between cuts (f and m carry power singularities at the cuts), M accumulated between
/// consecutive nodes by 8-point Gauss-Legendre, and from 0 to the first node by Gauss-Jacobi
/// with m's weight o^-g taken out.
///
/// [`graded_rule`]: crate::numerics::quadrature::graded_rule
pub(crate) fn by_parts(
    g: f64,
    cuts: &[f64],
    m: &dyn Fn(f64) -> f64,
    f: &dyn Fn(f64) -> f64,
) -> f64 {
    use crate::numerics::quadrature::{gauss_jacobi, gauss_legendre, graded_rule};
    let (jx, jw) = gauss_jacobi(8, 0.0, -g);
    let (lx, lw) = gauss_legendre(8);
    let (mut acc, mut prev, mut total) = (0.0, 0.0, 0.0);
    for piece in cuts.windows(2) {
        // panels shrinking by 0.1 towards both ends, down to 1e-15 of the half piece
        for (o, wt) in graded_rule(piece[0], piece[1], 0.1, 1e-15, 16) {
            let h = 0.5 * (o - prev);
            acc += if prev == 0.0 {
                // int_0^o m = h int_{-1}^{1} m(h (1 + t)) (1 + t)^g (1 + t)^-g dt, h = o/2,
                // the last factor the rule's weight
                jx.iter()
                    .zip(&jw)
                    .map(|(t, w)| {
                        let s = h * (1.0 + t);
                        h * w * m(s) * (1.0 + t).powf(g)
                    })
                    .sum::<f64>()
            } else {
                lx.iter()
                    .zip(&lw)
                    .map(|(t, w)| h * w * m(prev + h * (1.0 + t)))
                    .sum::<f64>()
            };
            prev = o;
            total -= wt * f(o) * acc;
        }
    }
    total
}
