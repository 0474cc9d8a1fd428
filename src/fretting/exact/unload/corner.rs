//! The corner structure of the first unloading at bp > 0 (docs/theory_tangential.md section
//! 19): from the corner x = -1, a thin zone slipping forwards (q = -mu p), a layer stuck
//! since Q*, the leading zone slipping forwards, the stick set and the trailing zone,
//!
//!   (-1, e1) slip, (e1, e2) stick, (e2, a1) slip, (a1, a2) stick, (a2, 1) slip,
//!
//! with (U1)-(U4) on it, the two stick components each with its two border constants, and
//! (C2): both components move with the punch, so the slip since Q* returns to zero across
//! the leading zone. Four ends, four border constants, a root in their logarithms.
//!
//! The outer model (section 20) drops the corner zone, exponentially thinner than the
//! layer: the layer reaches the corner carrying the bonded increment u^(-1/2 + i eps) B(u)
//! with B(0) free ([`Kind::Corner`]), one border constant on it and two on the stick set,
//! three ends (e2, a1, a2); the corner zone sits near the outer field's first zero of
//! q + mu p below e2 ([`first_zero`]).

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
    solve_on_kinks(m, qp, level, |kinks| corner_specs(k, kinks, x))
}

/// The unloading's fixed-ends system on the zones `specs` builds from the loaded state's
/// kinks, the kinks cutting the gap rows' rules and the loaded state as the forcing.
fn solve_on_kinks<D: Start + ?Sized>(
    m: &D,
    qp: f64,
    level: usize,
    specs: impl FnOnce(&[super::Kink]) -> Vec<ZoneSpec>,
) -> Result<Solved> {
    let kinks = m.kinks();
    let cuts: Vec<f64> = kinks.iter().map(|c| c.opx).collect();
    let forcing = |opx: f64, omx: f64| m.forcing(opx, omx);
    solve_parts(
        *m.coupling(),
        &specs(&kinks),
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

/// The outer model of the corner (docs/theory_tangential.md section 20): the ends
/// 1 + e2, 1 + a1, 1 - a2, the stuck layer (-1, e2) reaching the corner with the bonded
/// field's singularity there.
pub(crate) type OuterEnds = [f64; 3];

/// The corner zone's share of the layer: (-1, -1 + INNER (1 + e2)) carries the loaded edge
/// state and the bonded powers, whose analytic factor is singular first at e2 (the slip
/// zone's end), so each power gains a factor INNER; the rest of the layer is a stick zone.
/// INNER must stay below 1/11: the leading zone's first pole lies a tenth of its
/// neighbour's length (1 - INNER)(1 + e2) beyond e2, at 1 + x = (1.1 INNER - 0.1)(1 + e2),
/// which must be beyond the corner (at INNER = 0.1 it fell on a collocation point: NaN).
/// Measured against INNER = 0.02 (docs/theory_tangential.md section 20): the ends at
/// b* = 0.9 (level 3) within 1e-8, on the ply (ladder) within 1e-12.
pub(crate) const INNER: f64 = 0.05;

/// The bonded powers at level l: 3 + l (10 at most), so that INNER^(3 + l) is 1.6e-8 at
/// level 3 and 3.9e-11 at level 5.
pub(crate) fn outer_powers(level: usize) -> usize {
    (3 + level).min(10)
}

/// The outer zones: the corner zone (loaded edge state with q = -mu p, exponent -g at -1,
/// and the bonded powers), the rest of the layer (stick; {0} for p at both ends, q {0} at
/// its lower end and {0, 1 - g} at e2), the leading zone ({0, 1 - g} at e2, {0, g} at a1),
/// then the three-zone pattern's stick set and trailing zone ([`specs`]).
pub(crate) fn outer_specs(
    k: &Coupling,
    kinks: &[super::Kink],
    x: OuterEnds,
    level: usize,
) -> Vec<ZoneSpec> {
    let [e2, wa, w2] = x;
    let g = edge_exponent(k);
    let mut rest = specs(k, kinks, wa, Some(w2));
    rest.remove(0);
    let inner = INNER * e2;
    let corner = ZoneSpec {
        kind: Kind::Corner(outer_powers(level)),
        len: inner,
        p: [vec![-g], vec![0.0]],
        q: [vec![], vec![]],
        near: [None, None],
    };
    let layer = ZoneSpec {
        kind: Kind::Stick,
        len: e2 - inner,
        p: [vec![0.0], vec![0.0]],
        q: [vec![0.0], vec![0.0, 1.0 - g]],
        near: [None, None],
    };
    let lead = ZoneSpec {
        kind: Kind::Slip(-1.0),
        len: wa - e2,
        p: [vec![0.0, 1.0 - g], vec![0.0, g]],
        q: [vec![], vec![]],
        near: [None, None],
    };
    [corner, layer, lead].into_iter().chain(rest).collect()
}

/// The outer model's fixed-geometry solve at Q/P = `qp` from the state `m`: three border
/// constants (one on the layer, two on the stick set) and (C2) across the leading zone.
pub(crate) fn outer_fixed<D: Start + ?Sized>(
    m: &D,
    x: OuterEnds,
    qp: f64,
    level: usize,
) -> Result<Solved> {
    let k = m.coupling();
    let [e2, wa, w2] = x;
    if !(0.0 < e2 && e2 < wa && w2 > 0.0 && wa + w2 < 2.0) {
        return Err(Error::InvalidArgument(format!(
            "exact corner (outer): ends out of order (1 + e2 = {e2:e}, 1 + a1 = {wa:e}, \
             1 - a2 = {w2:e})"
        )));
    }
    solve_on_kinks(m, qp, level, |kinks| outer_specs(k, kinks, x, level))
}

/// A layered outer model at one level: its N ends, the solution there, the last step.
pub(crate) struct LayeredLevel<const N: usize, S = Solved> {
    pub(crate) x: [f64; N],
    pub(crate) state: S,
    /// The last Newton step's largest move of an end, relative to that end's offset.
    pub(crate) step: f64,
    pub(crate) solves: usize,
}

/// A level of the outer model (three ends, [`outer_level`]).
pub(crate) type OuterLevel = LayeredLevel<3>;

/// A ladder's rung: the trace shows 1 + e2 and 1 - a2; the change sums all the ends; the
/// step is made absolute by the largest end (an upper bound of every end's move).
impl<const N: usize> super::super::Rung for LayeredLevel<N> {
    fn unknowns(&self) -> (f64, f64) {
        (self.x[0], self.x[2])
    }
    fn moved(&self, before: &Self) -> f64 {
        (0..N).map(|i| (self.x[i] - before.x[i]).abs()).sum()
    }
    fn step(&self) -> f64 {
        self.step * self.x.iter().fold(0.0f64, |a, v| a.max(*v))
    }
    fn state(&self) -> &Solved {
        &self.state
    }
    fn solves(&self) -> usize {
        self.solves
    }
}

/// The factors on the outer model's ladder estimates (twice the ends' change plus the steps,
/// twice the (T1) distance of the last two levels): on the ply the levels' tractions stall
/// at a floor of 1e-9 .. 8e-9, where the last two levels' distance underestimates the
/// distance to the levels above. Measured (`measure_outer_estimates`; mu = 0.3,
/// Q* = 0.6 mu P, ladder from level 3 at (1e-10, 1e-8) with both factors 1; the distances
/// to levels L + 1 and L + 2 as fractions of the estimates at the level L reached):
///
/// | Q/Q* | L | ends: L + 1, L + 2 | tractions: L + 1, L + 2 |
/// |---|---|---|---|
/// | 0.9 | 6 | 0.19, (2.95) | 1.88, (8.09) |
/// | 0.5 | 6 | 1.87, (4.22) | 3.68, (26.4) |
/// | 0 | 4 | 0.017, 0.015 | 0.92, 0.92 |
/// | -0.3 | 5 | 0.012, 0.050 | 0.38, 1.71 |
/// | -0.45 | 6 | 0.40, (-) | 2.87, (-) |
///
/// The factors cover every ratio against levels up to 7 (largest 1.87 and 3.68). Level 8
/// (in brackets) is no reference: its ends move by 3-4 of the estimate, where levels 5-7
/// agree with each other, and its tractions by 2e-8 .. 6e-8; its columns are past the
/// frame's floor (docs/theory_tangential.md section 21).
pub(crate) const OUTER_END_FACTOR: f64 = 2.0;
pub(crate) const OUTER_TRACTION_FACTOR: f64 = 4.0;

/// The outer model at Q/P = `qp` from the ends `start`, by the ladder of levels `first`,
/// `first` + 1, ... (section 11's, [`super::super::ladder`]) until its estimates, raised by
/// [`OUTER_END_FACTOR`] and [`OUTER_TRACTION_FACTOR`], are within `tol` (the ends) and
/// `traction_tol` (the tractions); the chord method's Jacobian `jac` is kept between levels
/// (given, the first level starts from it: a march's at a nearby load, [`super::outer_cold`]).
pub(crate) fn outer<D: Start + ?Sized>(
    m: &D,
    qp: f64,
    tol: f64,
    traction_tol: f64,
    start: OuterEnds,
    first: usize,
    jac: &mut Option<[[f64; 3]; 3]>,
) -> Result<super::super::Climbed<OuterLevel>> {
    layered(m, qp, tol, traction_tol, start, first, jac)
}

/// [`outer`]'s ladder for either layered model, by its count of ends ([`model_level`]):
/// the outer model (3) or the outer model with a far layer (4, docs/theory_tangential.md
/// section 24), with the same factors on the estimates (the far model's levels are the
/// outer model's bases plus the mirrored corner's, whose transforms are the same functions,
/// `far_corner_mirrors_the_corner`).
pub(crate) fn layered<D: Start + ?Sized, const N: usize>(
    m: &D,
    qp: f64,
    tol: f64,
    traction_tol: f64,
    start: [f64; N],
    first: usize,
    jac: &mut Option<[[f64; N]; N]>,
) -> Result<super::super::Climbed<LayeredLevel<N>>> {
    let g = edge_exponent(m.coupling());
    let climbed = super::super::ladder(
        g,
        first,
        tol / OUTER_END_FACTOR,
        traction_tol / OUTER_TRACTION_FACTOR,
        0,
        |level, prev: Option<&LayeredLevel<N>>| {
            let x0 = prev.map_or(start, |p| p.x);
            model_level(m, x0, qp, level, 0.1 * tol, jac)
        },
    )?;
    climbed
        .map(|mut c| {
            c.c_error *= OUTER_END_FACTOR;
            c.traction_error *= OUTER_TRACTION_FACTOR;
            c
        })
        .map_err(|trace| {
            let last = trace.last().map_or((f64::NAN, f64::NAN), |t| (t.3, t.4));
            Error::NoConvergence(format!(
                "exact corner ({}): levels {first}-{} did not agree to {tol:e} (ends) and \
             {traction_tol:e} (tractions): the last two moved them by {:e} and {:e}",
                model_name(N),
                super::super::MAX_LEVEL,
                last.0,
                last.1
            ))
        })
}

/// The layered model with `n` ends, as the messages name it.
fn model_name(n: usize) -> &'static str {
    if n == 4 { "far layer" } else { "outer" }
}

/// The fixed-ends solve of the layered model with N ends: [`outer_fixed`] (3) or
/// [`far_fixed`] (4).
pub(crate) fn model_fixed<D: Start + ?Sized, const N: usize>(
    m: &D,
    x: [f64; N],
    qp: f64,
    level: usize,
) -> Result<Solved> {
    let x: &[f64] = &x;
    match N {
        3 => outer_fixed(m, [x[0], x[1], x[2]], qp, level),
        4 => far_fixed(m, [x[0], x[1], x[2], x[3]], qp, level),
        _ => Err(Error::InvalidArgument(format!(
            "exact corner: no layered model with {N} ends"
        ))),
    }
}

/// The layered model with N ends at one level ([`outer_level`], [`far_level`]): the near
/// layer is end 0, the far layer (N = 4) end 3.
pub(crate) fn model_level<D: Start + ?Sized, const N: usize>(
    m: &D,
    x0: [f64; N],
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; N]; N]>,
) -> Result<LayeredLevel<N>> {
    let layers: &[usize] = if N == 4 { &[0, 3] } else { &[0] };
    let tops = data_tops::<D, N>(m);
    layered_root(
        x0,
        tol,
        jac,
        model_name(N),
        layers,
        tops,
        |x| model_fixed(m, x, qp, level),
        |s: &Solved| std::array::from_fn(|i| s.sigma[i]),
    )
}

/// The upper bounds the data sets on the ends' logarithms (infinite where none): with a far
/// layer (N = 4), 1 - d2 below the data's nearest kink to +1 ([`far_fixed`] refuses a far
/// layer holding one: on the reloaded state the layer's top e_r, section 24).
fn data_tops<D: Start + ?Sized, const N: usize>(m: &D) -> [f64; N] {
    let mut tops = [f64::INFINITY; N];
    if N == 4 {
        tops[3] = m
            .kinks()
            .iter()
            .map(|c| 2.0 - c.opx)
            .fold(f64::INFINITY, f64::min)
            .ln();
    }
    tops
}

/// The fraction of its logarithm's distance to the data's bound that a chord step may take
/// an end which it would otherwise carry past the bound ([`damped_step`]): bisection in the
/// logarithm, so each such step at least halves the end's distance to the bound in ln and
/// the root, which lies inside (section 24: the far layer keeps inside the data's layer),
/// stays reachable in a bounded number of them. Where the step would not cross the bound it
/// is left as it was: the answers found before the damping are unchanged.
pub(crate) const BOUND_FRACTION: f64 = 0.5;

/// The closest an end may come to its data bound in its logarithm: the chord method's
/// forward differences ([`layered_root`]) step by 1e-3 in the ends' logarithms, so an end
/// closer than that to the bound would put a Jacobian's column beyond it. A shortened step
/// that leaves less than this gives up (NoConvergence): the chord method keeps pressing the
/// end outwards. A step crosses the bound only from within ln 2 of it (the factor-2
/// damping), and with [`BOUND_FRACTION`] 1/2 each shortened step halves the distance, so at
/// most log2(ln 2 / 1e-3) < 10 shortened steps in a row precede the refusal.
pub(crate) const BOUND_GAP: f64 = 1e-3;

/// A chord step in the ends' logarithms `lx` along the Newton step `d` (section 20): damped
/// to a factor 2 in the largest end, then, where it would carry an end past its data bound
/// `tops` (logarithms, infinite where none), shortened as a whole (its direction kept) so
/// that end moves [`BOUND_FRACTION`] of its distance to the bound; NoConvergence where the
/// shortened step leaves such an end within [`BOUND_GAP`] of its bound, as where a step takes an
/// end of `layers` below [`LAYER_MIN`] (the layer vanishes). Returns the next logarithms
/// and the largest Newton component (the chord method's measure of convergence).
pub(crate) fn damped_step<const N: usize>(
    lx: [f64; N],
    d: [f64; N],
    tops: [f64; N],
    layers: &[usize],
    what: &str,
) -> Result<([f64; N], f64)> {
    let big = d.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let mut damp = (std::f64::consts::LN_2 / big).min(1.0);
    let crossing: Vec<usize> = (0..N)
        .filter(|&i| lx[i] < tops[i] && lx[i] + damp * d[i] >= tops[i])
        .collect();
    for &i in &crossing {
        damp = damp.min(BOUND_FRACTION * (tops[i] - lx[i]) / d[i]);
    }
    let next: [f64; N] = std::array::from_fn(|i| lx[i] + damp * d[i]);
    if let Some(&i) = crossing.iter().find(|&&i| tops[i] - next[i] < BOUND_GAP) {
        return Err(Error::NoConvergence(format!(
            "exact corner ({what}): the chord method presses end {i} against the data's bound \
             (a step to {:e}, the bound {:e}, ends {:?})",
            next[i].exp(),
            tops[i].exp(),
            next.map(f64::exp)
        )));
    }
    if layers.iter().any(|&i| next[i].exp() < LAYER_MIN) {
        return Err(Error::NoConvergence(format!(
            "exact corner ({what}): the layer vanishes (a step to the layers' \
             widths {:?}, below {LAYER_MIN:e})",
            layers.iter().map(|&i| next[i].exp()).collect::<Vec<_>>()
        )));
    }
    Ok((next, big))
}

/// The layer's floor: a step of the chord method to 1 + e2 below it ends the outer model
/// with NoConvergence (the layer vanishes: the hand-over to the three-zone pattern,
/// docs/theory_tangential.md section 21). On the ply the layer is 6.2e-10 at -0.478 Q*,
/// and below the hand-over the chord method drove it to 6e-13 without converging (section
/// 20); the three-zone answer that takes over where the layer is below the floor differs
/// from the layered one by O(1 + e2) in the ends.
pub(crate) const LAYER_MIN: f64 = 1e-12;

/// The three border constants' root in the logarithms of the ends from `x0` (the chord
/// method as [`corner_level`]). No floor on the widths but [`LAYER_MIN`]: the corner zone's
/// columns carry the structure at -1 in closed form, and at the ply it is 8e-9 wide under a
/// 1.6e-7 layer.
pub(crate) fn outer_level<D: Start + ?Sized>(
    m: &D,
    x0: OuterEnds,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 3]; 3]>,
) -> Result<OuterLevel> {
    model_level(m, x0, qp, level, tol, jac)
}

/// The border constants' root in the logarithms of the ends from `x0` by the chord method
/// (steps damped to a factor 2 in the largest end, restarted with a fresh Jacobian up to
/// [`RESTARTS`] times while they stay above [`RESTART_ABOVE`]), `solve` giving the solution
/// at given ends (any state `S`, `value` its N functions to zero, the border constants for
/// the layered models); a step taking an end of `layers` below [`LAYER_MIN`] ends it (the layer
/// vanishes); a step that would carry an end past its data bound `tops` (the far layer past
/// the data's layer top) is shortened rather than refused ([`damped_step`]). `what` names
/// the model in the messages.
#[allow(clippy::too_many_arguments)]
pub(crate) fn layered_root<S, const N: usize>(
    x0: [f64; N],
    tol: f64,
    jac: &mut Option<[[f64; N]; N]>,
    what: &str,
    layers: &[usize],
    tops: [f64; N],
    mut solve: impl FnMut([f64; N]) -> Result<S>,
    value: impl Fn(&S) -> [f64; N],
) -> Result<LayeredLevel<N, S>> {
    let mut lx = x0.map(f64::ln);
    let mut restarts = 0;
    let mut solves = 0;
    loop {
        let (next, state, step) = chord(
            lx,
            [1e-3; N],
            tol,
            super::MAX_NEWTON,
            jac,
            |lx: [f64; N]| {
                solves += 1;
                solve(lx.map(f64::exp))
            },
            &value,
            |lx: [f64; N], d: [f64; N]| damped_step(lx, d, tops, layers, what),
        )?;
        lx = next;
        if restarts == RESTARTS && step > RESTART_ABOVE {
            return Err(Error::NoConvergence(format!(
                "exact corner ({what}): the chord method still takes relative steps of \
                 {step:e} after {RESTARTS} restarts (ends {:?})",
                lx.map(f64::exp)
            )));
        }
        if step <= tol.max(RESTART_ABOVE) || restarts == RESTARTS {
            return Ok(LayeredLevel {
                x: lx.map(f64::exp),
                state,
                step,
                solves,
            });
        }
        restarts += 1;
        *jac = None;
    }
}

/// The outer solution's q + mu p = Re((mu - i delta) f) on the corner zone's side of the
/// layer, and where it first vanishes below e2: scanning 1 + x down from the corner zone's
/// top by factors `ratio`, the last point above the first sign change, refined by
/// bisection in ln(1 + x) (None if it keeps its sign down to 1e-300).
pub(crate) fn first_zero(st: &Solved, mu: f64, top: f64, ratio: f64) -> Option<f64> {
    first_zero_of(
        |o: f64| {
            let (p, q) = st.tractions(o, 2.0 - o);
            q + mu * p
        },
        top,
        ratio,
    )
}

/// [`first_zero`] at the far corner +1 (docs/theory_tangential.md section 24): the first
/// zero of mu p - q below the far layer's top, in v = 1 - x from `top` down.
pub(crate) fn far_first_zero(st: &Solved, mu: f64, top: f64, ratio: f64) -> Option<f64> {
    first_zero_of(
        |v: f64| {
            let (p, q) = st.tractions(2.0 - v, v);
            mu * p - q
        },
        top,
        ratio,
    )
}

/// The first sign change of `f` scanning its argument down from `top` by factors `ratio`,
/// refined by bisection in its logarithm (None if none down to 1e-300).
fn first_zero_of(f: impl Fn(f64) -> f64, top: f64, ratio: f64) -> Option<f64> {
    let (mut hi, mut fhi) = (top, f(top));
    let mut lo = hi * ratio;
    while lo > 1e-300 {
        let flo = f(lo);
        if flo.signum() != fhi.signum() {
            for _ in 0..60 {
                let mid = (lo * hi).sqrt();
                let fm = f(mid);
                if fm.signum() == fhi.signum() {
                    hi = mid;
                    fhi = fm;
                } else {
                    lo = mid;
                }
            }
            return Some((lo * hi).sqrt());
        }
        (hi, fhi) = (lo, flo);
        lo *= ratio;
    }
    None
}

/// The second unloading's outer model (docs/theory_tangential.md sections 24-25; routed by
/// `unload` for data with a layer at +1): from a data state with a stuck layer at +1 (the reloaded state at +Q*), the
/// ends 1 + e2, 1 + a1, 1 - a2 as [`OuterEnds`] and 1 - d2, the far layer (d2, 1) stuck
/// since the data.
pub(crate) type FarEnds = [f64; 4];

/// The zones of the outer model with a far layer: [`outer_specs`]'s corner zone, layer,
/// leading zone and stick set; the trailing zone (a2, d2) slipping with q = +mu p ({0, g}
/// at a2, {0, 1 - g} at d2, where it lies left of a stick point: the mirror of e2); the far
/// layer's stick zone ({0} for p at both ends, q {0, 1 - g} at d2 and {0} at its top) and
/// the far corner zone (1 - INNER (1 - d2), 1) with the data's state on the bound
/// q = +mu p (exponent -g at +1) and the bonded powers ([`Kind::FarCorner`]).
pub(crate) fn far_specs(
    k: &Coupling,
    kinks: &[super::Kink],
    x: FarEnds,
    level: usize,
) -> Vec<ZoneSpec> {
    let [e2, wa, w2, wd] = x;
    let g = edge_exponent(k);
    let mut zones = outer_specs(k, kinks, [e2, wa, w2], level);
    zones.pop();
    let inner = INNER * wd;
    zones.push(ZoneSpec {
        kind: Kind::Slip(1.0),
        len: w2 - wd,
        p: [vec![0.0, g], vec![0.0, 1.0 - g]],
        q: [vec![], vec![]],
        near: [None, None],
    });
    zones.push(ZoneSpec {
        kind: Kind::Stick,
        len: wd - inner,
        p: [vec![0.0], vec![0.0]],
        q: [vec![0.0, 1.0 - g], vec![0.0]],
        near: [None, None],
    });
    zones.push(ZoneSpec {
        kind: Kind::FarCorner(outer_powers(level)),
        len: inner,
        p: [vec![0.0], vec![-g]],
        q: [vec![], vec![]],
        near: [None, None],
    });
    zones
}

/// The fixed-ends solve of the outer model with a far layer at Q/P = `qp` from the state
/// `m`: four border constants (the layer's, the stick set's two, the far layer's) and (C2)
/// across both slip zones between stick components. The far layer must hold none of the
/// data's kinks (InvalidArgument otherwise: its bases carry none).
pub(crate) fn far_fixed<D: Start + ?Sized>(
    m: &D,
    x: FarEnds,
    qp: f64,
    level: usize,
) -> Result<Solved> {
    let k = m.coupling();
    let [e2, wa, w2, wd] = x;
    if !(0.0 < e2 && e2 < wa && 0.0 < wd && wd < w2 && wa + w2 < 2.0) {
        return Err(Error::InvalidArgument(format!(
            "exact corner (far layer): ends out of order (1 + e2 = {e2:e}, 1 + a1 = {wa:e}, \
             1 - a2 = {w2:e}, 1 - d2 = {wd:e})"
        )));
    }
    if let Some(c) = m.kinks().iter().find(|c| 2.0 - c.opx < wd) {
        return Err(Error::InvalidArgument(format!(
            "exact corner (far layer): the far layer 1 - x < {wd:e} holds the data's kink at \
             1 - x = {:e}",
            2.0 - c.opx
        )));
    }
    solve_on_kinks(m, qp, level, |kinks| far_specs(k, kinks, x, level))
}

/// The outer model with a far layer at one level (four ends, [`far_level`]).
pub(crate) type FarLevel = LayeredLevel<4>;

/// The four border constants' root in the logarithms of the ends from `x0`, by the chord
/// method as [`outer_level`] (a step to either layer below [`LAYER_MIN`] ends it).
pub(crate) fn far_level<D: Start + ?Sized>(
    m: &D,
    x0: FarEnds,
    qp: f64,
    level: usize,
    tol: f64,
    jac: &mut Option<[[f64; 4]; 4]>,
) -> Result<FarLevel> {
    model_level(m, x0, qp, level, tol, jac)
}
