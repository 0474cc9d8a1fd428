//! The corner structure of the first unloading at bp > 0 (docs/theory_tangential.md section
//! 19): from the corner x = -1, a thin zone slipping forwards (q = -mu p), a layer stuck
//! since Q*, the leading zone slipping forwards, the stick set and the trailing zone,
//!
//!   (-1, e1) slip, (e1, e2) stick, (e2, a1) slip, (a1, a2) stick, (a2, 1) slip,
//!
//! with (U1)-(U4) on it, the two stick components each with its two border constants, and
//! (C2): both components move with the punch, so the slip since Q* returns to zero across
//! the leading zone. Four ends, four border constants, a root in their logarithms.

use super::super::W1_MIN;
use super::super::edge_exponent;
use super::super::frame::{Kind, Loc, Sizes, Solved, ZoneSpec, gap_rule, solve_parts};
use super::{Start, specs};
use crate::error::{Error, Result};
use crate::numerics::roots::chord;
use crate::problem::Coupling;

/// The four ends as offsets from the contact's ends: 1 + e1, 1 + e2, 1 + a1, 1 - a2.
pub(crate) type Ends = [f64; 4];

/// The five zones: the corner zone, the stuck layer and the leading zone with section 19's
/// exponents (-g at the corner; {0, g} at e1, where the slip zone with q = -mu p lies left
/// of the stick point, as at a1; {0, 1 - g} at e2, where it lies right: there a power
/// (x - e2)^l on the slip side solves H[p] = -bp mu p for cot(pi l) = -bp mu), then the
/// three-zone pattern's stick set and trailing zone ([`specs`]).
fn corner_specs(k: &Coupling, kinks: &[super::Kink], x: Ends) -> Vec<ZoneSpec> {
    let [e1, e2, wa, w2] = x;
    let g = edge_exponent(k);
    let mut rest = specs(k, kinks, wa, Some(w2));
    rest.remove(0);
    let slip = |len: f64, lo: Vec<f64>| ZoneSpec {
        kind: Kind::Slip(-1.0),
        len,
        p: [lo, vec![0.0, g]],
        q: [vec![], vec![]],
        near: [None, None],
    };
    let layer = ZoneSpec {
        kind: Kind::Stick,
        len: e2 - e1,
        p: [vec![0.0], vec![0.0]],
        q: [vec![0.0, g], vec![0.0, 1.0 - g]],
        near: [None, None],
    };
    [slip(e1, vec![-g]), layer, slip(wa - e2, vec![0.0, 1.0 - g])]
        .into_iter()
        .chain(rest)
        .collect()
}

/// The fixed-geometry solve at Q/P = `qp` from the state `m` on the five zones.
pub(crate) fn corner_fixed<D: Start + ?Sized>(
    m: &D,
    x: Ends,
    qp: f64,
    level: usize,
) -> Result<Solved> {
    let k = m.coupling();
    let [e1, e2, wa, w2] = x;
    if !(0.0 < e1 && e1 < e2 && e2 < wa && w2 > 0.0 && wa + w2 < 2.0) {
        return Err(Error::InvalidArgument(format!(
            "exact corner: ends out of order (1 + e1 = {e1:e}, 1 + e2 = {e2:e}, 1 + a1 = \
             {wa:e}, 1 - a2 = {w2:e})"
        )));
    }
    let kinks = m.kinks();
    let cuts: Vec<f64> = kinks.iter().map(|c| c.opx).collect();
    let forcing = |opx: f64, omx: f64| m.forcing(opx, omx);
    solve_parts(
        *k,
        &corner_specs(k, &kinks, x),
        Sizes::at(level),
        2,
        qp,
        &forcing,
        &cuts,
    )
}

/// The corner pattern at one level.
pub(crate) struct CornerLevel {
    pub(crate) x: Ends,
    pub(crate) state: Solved,
    /// The last Newton step's largest move of an end, relative to that end's offset.
    pub(crate) step: f64,
}

/// The four border constants' root in the logarithms of the ends from `x0`, by the chord
/// method (steps 1e-3, as the three-zone solver's; no end moves by more than a factor 2
/// per step), to relative Newton steps of `tol`.
pub(crate) fn corner_level<D: Start + ?Sized>(
    m: &D,
    x0: Ends,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 4]; 4]>,
) -> Result<CornerLevel> {
    let mut lx = x0.map(f64::ln);
    // a damped phase whose steps stop halving ends the chord method's search early: it is
    // started again, with a fresh Jacobian, from where it stopped (at most RESTARTS times)
    let mut restarts = 0;
    loop {
        let (next, state, step) = corner_chord(m, lx, qp, level, tol, jac)?;
        lx = next;
        if step <= tol.max(RESTART_ABOVE) || restarts == RESTARTS {
            return Ok(CornerLevel {
                x: lx.map(f64::exp),
                state,
                step,
            });
        }
        restarts += 1;
        *jac = None;
    }
}

/// Restarts of the chord method from a damped phase, and the relative step above which
/// one is made (below it the steps are Newton's own, and a stall is the rounding's).
const RESTARTS: usize = 4;
const RESTART_ABOVE: f64 = 1e-3;

fn corner_chord<D: Start + ?Sized>(
    m: &D,
    lx: Ends,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 4]; 4]>,
) -> Result<(Ends, Solved, f64)> {
    chord(
        lx,
        [1e-3; 4],
        tol,
        super::MAX_NEWTON,
        jac,
        |lx: Ends| corner_fixed(m, lx.map(f64::exp), qp, level),
        |s: &Solved| [s.sigma[0], s.sigma[1], s.sigma[2], s.sigma[3]],
        |lx: Ends, d: Ends| {
            let big = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let damp = (std::f64::consts::LN_2 / big).min(1.0);
            let next: Ends = std::array::from_fn(|i| lx[i] + damp * d[i]);
            if next.iter().any(|l| l.exp() < W1_MIN) {
                return Err(Error::NoConvergence(format!(
                    "exact corner: a zone went below {W1_MIN:e}, thinner than the bases \
                     resolve ({:?})",
                    next.map(f64::exp)
                )));
            }
            // the undamped step measures convergence (a damped one need not halve)
            Ok((next, big))
        },
    )
}

/// The slip since the data at 1 + x = `opx` in a left zone of `st` whose stick end is at
/// 1 + x = `z`: the slope -(H[q] + bq p - r) integrated from z by [`gap_rule`], cut at the
/// data's kinks.
pub(crate) fn slip_left<D: Start + ?Sized>(st: &Solved, m: &D, opx: f64, z: f64) -> f64 {
    let bq = m.coupling().bq;
    let (a, b, sign) = if opx < z {
        (opx, z, -1.0)
    } else {
        (z, opx, 1.0)
    };
    let cuts: Vec<f64> = m.kinks().iter().map(|c| c.opx).collect();
    let mut s = 0.0;
    for (Loc { from_lo, .. }, w) in gap_rule(b - a, a, &cuts) {
        let t = a + from_lo;
        let l = st.frame.locate(t, 2.0 - t);
        let (p, _) = st.tractions_at(&l);
        let (_, hq) = st.hilbert_at(&l);
        let slope = -(hq + bq * p - m.forcing(t, 2.0 - t));
        // nodes that round onto a kink or a zone end are left out, as in the constraint
        if slope.is_finite() {
            s += w * slope;
        }
    }
    sign * s
}
