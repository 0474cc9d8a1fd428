//! A load path on the exact solvers (`CycleMethod::Exact`): the normal-load state, the
//! monotonic loading from it ([`super::monotonic`], either sign of Q by mirror symmetry), and
//! each reversal of the load direction as a new branch whose data is the state where it
//! reversed ([`super::unload::unload`]; a branch with Q rising is the unloading of the
//! mirrored state, docs/theory_tangential.md sections 5 and 15). Continuing in the same
//! direction re-solves the same branch at the new load (each branch is path-independent
//! from its data, sections 10 and 13). At bp = 0 a branch starts fully stuck ((T13a),
//! (T15a)): that range is carried in closed form ([`Branch::Stuck`], section 18).
//!
//! Every state is held in a frame of its own, the contact's or its mirror (x -> -x,
//! q -> -q); [`ExactPath`]'s getters read it in the contact's frame.

use std::f64::consts::{LN_2, PI};
use std::sync::Arc;

use super::frame::Solved;
use super::unload::{Mirror, Start, Unloading, by_parts, first_slip, unload, unload_from};
use super::{Monotonic, edge_exponent, monotonic, normal_load, rule_on};
use crate::error::{Error, Result};
use crate::problem::{Coupling, Profile};

/// Where the exact solvers stop answering, for the messages of refused loads.
const COVERAGE: &str = "the exact solver covers the normal load, monotonic loading from \
    Q = 0, the first unloading (at bp > 0 through its corner, docs/theory_tangential.md \
    section 21) and the branches after it where they keep one stick set with a slip zone at \
    each end (at bp = 0 with their full-stick ranges), and at bp > 0 the reloading through \
    its corner (section 23); a reversal from a state with the corner's stuck layer (the \
    first unloading's corner phase, the reloading's corner) is not built yet (sections 21, \
    23)";

/// The loaded state is the data of the unloading after a reversal, and is solved to at
/// least these tolerances (c1 + c2, and the tractions in the norm (T1)): on the ply the
/// unloading's ladder converges from a loaded state solved to (1e-10, 1e-6), not from one
/// solved to (1e-8, 1e-5) (its tractions' levels stayed 4e-2 apart at -Q*, Q* = 0.6 mu P).
const DATA_TOL: f64 = 1e-10;
const DATA_TRACTION_TOL: f64 = 1e-6;

/// The state on the path.
#[derive(Clone)]
pub(crate) enum Branch {
    /// The normal load (Q = 0).
    Normal,
    /// Monotonic loading from the normal load; the state is `m` mirrored when `flip` (Q < 0).
    Loading { m: Arc<Monotonic>, flip: bool },
    /// A branch from the state where the load last reversed, in a frame where its Q
    /// decreases (the contact's mirrored when `flip`); `data_c_error` and
    /// `data_traction_error` are the estimates of that state.
    Unloading {
        u: Arc<Unloading<dyn Start>>,
        flip: bool,
        data_c_error: f64,
        data_traction_error: f64,
    },
    /// bp = 0 only: a branch after a reversal in its full-stick range ((T13a), (T15a) of
    /// docs/theory_tangential.md): p = p0 unchanged and q = q_d + ((Q - Q_d)/P) p0, with
    /// `data` the state where the load reversed (a `Loading` or `Unloading` state, at Q_d)
    /// and `qp` = Q/P, both in the contact's frame; `slip_at` is the first-slip load Q_s/P
    /// of the branch (contact's frame), which bounds the range: Q lies between Q_d and Q_s.
    Stuck {
        data: Box<ExactPath>,
        qp: f64,
        slip_at: f64,
    },
}

/// The normal-load state on the exact solvers' frame, with COUPLED's estimates.
pub(crate) struct Normal {
    pub(crate) c: f64,
    pub(crate) state: Solved,
    pub(crate) c_error: f64,
    pub(crate) traction_error: f64,
}

/// An exact load path: the normal-load state and the current branch.
#[derive(Clone)]
pub(crate) struct ExactPath {
    pub(crate) k: Coupling,
    tol: f64,
    traction_tol: f64,
    pub(crate) normal: Arc<Normal>,
    pub(crate) branch: Branch,
    /// The punch's rigid tangential displacement D (units of pi B P, the gauge of (T1):
    /// docs/theory_tangential.md section 16), in the contact's frame; 0 at the normal load.
    pub(crate) punch: f64,
    /// Energy dissipated since the normal load (units of pi B P^2, (T8)), summed over the
    /// load steps the path took (docs/theory_tangential.md section 17), and its estimate.
    pub(crate) dissipated: f64,
    pub(crate) dissipated_error: f64,
}

/// The error `e` of the exact solver on `what`, with the method that answers every load
/// path first (a caller's fixed-size buffer keeps the message's start) and what the exact
/// path covers.
fn refused(what: &str, e: Error) -> Error {
    e.reworded(|m| {
        format!(
            "CycleMethod::Exact (ORTHOSLIP_CYCLE_METHOD_EXACT): {what} is not answered; \
             CycleMethod::LcpHistory (ORTHOSLIP_CYCLE_METHOD_LCP_HISTORY) answers every load \
             path ({m}); {COVERAGE}"
        )
    })
}

impl ExactPath {
    /// The normal-load state of `k`: COUPLED's stick half-width (to 1e-13) and its state on
    /// the exact frame; later loads solved to `tol` (c1, c2) and `traction_tol` (tractions,
    /// norm (T1)).
    pub(crate) fn new(k: &Coupling, tol: f64, traction_tol: f64) -> Result<Self> {
        let cs =
            crate::coupled::solve_to(k, 1e-13, 1e-12).map_err(|e| refused("the normal load", e))?;
        let e = cs.edge();
        let state =
            normal_load(k, e.c, e.one_minus_c, 3).map_err(|e| refused("the normal load", e))?;
        Ok(Self {
            k: *k,
            tol,
            traction_tol,
            normal: Arc::new(Normal {
                c: e.c,
                state,
                c_error: cs.numerical_error(),
                traction_error: cs.traction_error(),
            }),
            branch: Branch::Normal,
            punch: 0.0,
            dissipated: 0.0,
            dissipated_error: 0.0,
        })
    }

    /// The current Q/P.
    pub(crate) fn q_over_p(&self) -> f64 {
        match &self.branch {
            Branch::Normal => 0.0,
            Branch::Loading { m, flip } => sign(*flip) * m.qp,
            Branch::Unloading { u, flip, .. } => sign(*flip) * u.qp,
            Branch::Stuck { qp, .. } => *qp,
        }
    }

    /// Moves Q/P monotonically from its current value to `qp` (checked by the caller:
    /// finite, |qp| < mu). On error the path is unchanged.
    pub(crate) fn load(&mut self, qp: f64) -> Result<()> {
        let now = self.q_over_p();
        if qp == now {
            return Ok(());
        }
        let what = format!("the load step Q/P = {now} -> {qp}");
        let (tol, ttol) = (self.tol, self.traction_tol);
        let next = match &self.branch {
            Branch::Normal => Branch::Loading {
                m: Arc::new(
                    monotonic(
                        &self.k,
                        qp.abs(),
                        tol.min(DATA_TOL),
                        ttol.min(DATA_TRACTION_TOL),
                    )
                    .map_err(|e| refused(&what, e))?,
                ),
                flip: qp < 0.0,
            },
            Branch::Loading { m, flip } => {
                let t = sign(*flip) * qp;
                if t > m.qp {
                    Branch::Loading {
                        m: Arc::new(
                            monotonic(&self.k, t, tol.min(DATA_TOL), ttol.min(DATA_TRACTION_TOL))
                                .map_err(|e| refused(&what, e))?,
                        ),
                        flip: *flip,
                    }
                } else {
                    let data: Arc<dyn Start> = m.clone();
                    match self.full_stick(&*data, *flip, t, qp) {
                        Some(stuck) => stuck.map_err(|e| refused(&what, e))?,
                        None => Branch::Unloading {
                            u: Arc::new(
                                unload(&data, t, tol, ttol).map_err(|e| refused(&what, e))?,
                            ),
                            flip: *flip,
                            data_c_error: m.c_error,
                            data_traction_error: m.traction_error,
                        },
                    }
                }
            }
            Branch::Unloading {
                u,
                flip,
                data_c_error,
                data_traction_error,
            } => {
                let t = sign(*flip) * qp;
                if t < u.qp {
                    Branch::Unloading {
                        u: Arc::new(
                            unload_from(u, None, t, tol, ttol).map_err(|e| refused(&what, e))?,
                        ),
                        flip: *flip,
                        data_c_error: *data_c_error,
                        data_traction_error: *data_traction_error,
                    }
                } else {
                    if u.level.layer.is_some() {
                        // `unload` takes the reloaded state's layer at +1 as data (the second
                        // unloading, docs/theory_tangential.md section 25), but the path's
                        // getters, dissipation and data estimates do not read a far layer yet
                        return Err(refused(
                            &what,
                            Error::InvalidArgument(
                                "a reversal from a state with the corner's stuck layer is not \
                                 on the exact path yet"
                                    .into(),
                            ),
                        ));
                    }
                    let inner: Arc<dyn Start> = u.clone();
                    let data: Arc<dyn Start> = Arc::new(Mirror { inner });
                    match self.full_stick(&*data, !*flip, -t, qp) {
                        Some(stuck) => stuck.map_err(|e| refused(&what, e))?,
                        None => Branch::Unloading {
                            u: Arc::new(
                                unload(&data, -t, tol, ttol).map_err(|e| refused(&what, e))?,
                            ),
                            flip: !*flip,
                            data_c_error: u.c_error + data_c_error,
                            data_traction_error: u.traction_error + data_traction_error,
                        },
                    }
                }
            }
            Branch::Stuck { data, slip_at, .. } => {
                let qd = data.q_over_p();
                let inside =
                    (qp - qd) * (slip_at - qd) > 0.0 && (qp - qd).abs() <= (slip_at - qd).abs();
                if inside {
                    Branch::Stuck {
                        data: data.clone(),
                        qp,
                        slip_at: *slip_at,
                    }
                } else {
                    // Outside the full-stick range the path passes through Q_d, where the
                    // state is the data's again (q = q_d), and a full-stick step slips
                    // nowhere (dissipates nothing): the load is the data's own load to qp,
                    // continuing its branch (beyond Q_d) or the slipping part of this one
                    // (beyond Q_s). The data's D and dissipation are this state's.
                    let mut from = (**data).clone();
                    from.load(qp)?;
                    *self = from;
                    return Ok(());
                }
            }
        };
        let mut next = ExactPath {
            branch: next,
            punch: f64::NAN,
            ..self.clone()
        };
        next.punch = next.punch_from(self);
        let (w, err) = next.step_dissipation(self);
        self.branch = next.branch;
        self.punch = next.punch;
        self.dissipated += w;
        self.dissipated_error += err;
        Ok(())
    }

    /// For bp = 0, the branch from this state (where the load reverses, seen through
    /// `data` in the branch's frame, the contact's mirrored when `flip`) at the load `t` of
    /// that frame (`qp` in the contact's), when `t` lies in the branch's full-stick range
    /// ((T13a), (T15a): down to the first-slip load [`first_slip`], included): the state
    /// q = q_d + ((Q - Q_d)/P) p0 with p = p0. None when bp > 0 or `t` lies below the
    /// first slip (the slipping part, the unloading solver's). Err(NoAdmissibleSolution) if
    /// that state exceeds the friction bound anywhere ([`Self::stuck_admissible`]).
    fn full_stick(&self, data: &dyn Start, flip: bool, t: f64, qp: f64) -> Option<Result<Branch>> {
        let qs = first_slip(data)?;
        if t < qs {
            return None;
        }
        let stuck = Branch::Stuck {
            data: Box::new(self.clone()),
            qp,
            slip_at: sign(flip) * qs,
        };
        Some(self.stuck_admissible(&stuck).map(|()| stuck))
    }

    /// |q| <= mu p (T7) for a full-stick state q = q_d + ((Q - Q_d)/P) p0: q/p0 read at
    /// [`STUCK_CHECKS`] Chebyshev points of the contact must lie in [-mu, mu], up to the data's
    /// traction estimate (the first slip is located at the corner, where section 13 and 15
    /// find the extreme of q_d/p0; this checks that no inner point reaches the bound first).
    fn stuck_admissible(&self, stuck: &Branch) -> Result<()> {
        let Branch::Stuck { data, qp, slip_at } = stuck else {
            return Ok(());
        };
        let mu = self.k.mu;
        let slack = data.estimates().1;
        for i in 0..STUCK_CHECKS {
            let theta = PI * (i as f64 + 0.5) / STUCK_CHECKS as f64;
            // 1 + x and 1 - x with their digits: 1 -+ cos = 2 sin^2(theta/2), 2 cos^2(theta/2)
            let (opx, omx) = (
                2.0 * (0.5 * theta).sin().powi(2),
                2.0 * (0.5 * theta).cos().powi(2),
            );
            let (p, q) = data.tractions(opx, omx);
            let r = q / p + (qp - data.q_over_p());
            if r.is_nan() || r.abs() > mu + slack {
                return Err(Error::NoAdmissibleSolution(format!(
                    "the full-stick state at Q/P = {qp} (first slip at Q/P = {slip_at} by the \
                     corner's q/p0) has q/p = {r} at x = {} beyond mu = {mu}: the branch \
                     slips first inside the contact, which the exact path does not carry",
                    opx - 1.0
                )));
            }
        }
        Ok(())
    }

    /// The state's own solution (in its own frame, the contact's mirrored when flipped).
    fn own(&self) -> &Solved {
        match &self.branch {
            Branch::Normal => &self.normal.state,
            Branch::Loading { m, .. } => &m.level.state,
            Branch::Unloading { u, .. } => &u.level.state,
            Branch::Stuck { data, .. } => data.own(),
        }
    }

    /// (p, H[q]) at x given by (1 + x, 1 - x), in the contact's frame (mirrored:
    /// p~(x) = p(-x) and H[q~](x) = H[q](-x), section 15).
    pub(crate) fn pressure_and_hq(&self, opx: f64, omx: f64) -> (f64, f64) {
        if let Branch::Stuck { data, .. } = &self.branch {
            // p = p_d, and H[q] = H[q_d] since H[p0] = 0 on (-1, 1)
            return data.pressure_and_hq(opx, omx);
        }
        let s = self.own();
        let (o, m) = if self.flipped() {
            (omx, opx)
        } else {
            (opx, omx)
        };
        let l = s.frame.locate(o, m);
        let (p, _) = s.tractions_at(&l);
        let (_, hq) = s.hilbert_at(&l);
        (p, hq)
    }

    /// The energy dissipated over the load step from `prev` to this state (units of pi B P^2;
    /// docs/theory_tangential.md (T17)) and its estimate. Per slip zone of this state, with
    /// ds the step's slip (zero at the zone's stick end) and dslope = d(ds)/dx =
    /// -(bq (p - p_prev) + H[q] - H[q_prev]): dW = |int mu p_mid ds| = |int dslope M|,
    /// M = int mu p_mid from the contact's end (by parts, [`by_parts`]; one sign of ds over
    /// the zone, as admissibility asks). The estimate: twice mu times the step's largest
    /// slip (at the zone's contact end) times this state's traction estimate.
    fn step_dissipation(&self, prev: &ExactPath) -> (f64, f64) {
        let k = self.k;
        let g = edge_exponent(&k);
        let te = self.estimates().1;
        let (mut w, mut err) = (0.0, 0.0);
        self.over_slip_zones(prev, &mut |cuts, at, f| {
            let m = |o: f64| {
                let (opx, omx) = at(o);
                let (pa, _) = prev.tractions(opx, omx);
                let (pb, _) = self.tractions(opx, omx);
                0.5 * k.mu * (pa + pb)
            };
            w += by_parts(g, cuts, &m, f).abs();
            // the slip at the contact's end, int_0^width f
            let edge: f64 = cuts
                .windows(2)
                .flat_map(|c| crate::numerics::quadrature::graded_rule(c[0], c[1], 0.1, 1e-15, 16))
                .map(|(o, wt)| wt * f(o))
                .sum();
            err += 2.0 * k.mu * edge.abs() * te;
        });
        (w, err)
    }

    /// -int q_mid ds over the load step from `prev` to this state (units of pi B P^2), the
    /// work of the mid-step traction on the step's slip (docs/theory_tangential.md (T9) and
    /// (T18c)): per slip zone by parts as [`Self::step_dissipation`], with q_mid = (q_prev +
    /// q)/2 in place of mu p_mid (int_Z r ds = -int dslope R, R = int r from the contact's
    /// end). Zero for the normal load and full stick.
    pub(crate) fn step_mid_work(&self, prev: &ExactPath) -> f64 {
        let g = edge_exponent(&self.k);
        let mut total = 0.0;
        self.over_slip_zones(prev, &mut |cuts, at, f| {
            let r = |o: f64| {
                let (opx, omx) = at(o);
                let (_, qa) = prev.tractions(opx, omx);
                let (_, qb) = self.tractions(opx, omx);
                0.5 * (qa + qb)
            };
            total -= by_parts(g, cuts, &r, f);
        });
        total
    }

    /// Calls `each(cuts, at, f)` per slip zone of this state after the step from `prev`: the
    /// zone as offsets o from its contact end (the zone at -1 in 1 + x, the one at +1 in
    /// 1 - x), `cuts` from 0 to the zone's width with both states' zone ends between, `at`
    /// the point (1 + x, 1 - x) of an offset, and `f` = d(ds)/do, the step's slip slope
    /// dslope = -(bq (p - p_prev) + H[q] - H[q_prev]) oriented along o (ds = 0 at the stick
    /// end, o = width). None for the normal load and full stick.
    fn over_slip_zones(&self, prev: &ExactPath, each: &mut ZoneVisit) {
        if matches!(self.branch, Branch::Normal | Branch::Stuck { .. }) {
            return;
        }
        let k = self.k;
        let (c1, c2) = self.stick_set();
        let mut bps = self.breakpoints();
        bps.extend(prev.breakpoints());
        for (left, width) in [(true, 1.0 + c1), (false, 1.0 - c2)] {
            if width <= 0.0 {
                continue;
            }
            let at = |o: f64| if left { (o, 2.0 - o) } else { (2.0 - o, o) };
            let mut cuts: Vec<f64> = bps
                .iter()
                .map(|&(o, m)| if left { o } else { m })
                .filter(|&o| o > 0.0 && o < width)
                .collect();
            cuts.extend([0.0, width]);
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
            let f = |o: f64| {
                let (opx, omx) = at(o);
                let (pa, ha) = prev.pressure_and_hq(opx, omx);
                let (pb, hb) = self.pressure_and_hq(opx, omx);
                let dslope = -(k.bq * (pb - pa) + hb - ha);
                if !dslope.is_finite() && o < NEAR_END {
                    // H[q] of the normal load's bases is NaN within 1e-17 of the contact's
                    // ends; the share of the rule's nodes there is below 1e-16 of dW
                    return 0.0;
                }
                if left { dslope } else { -dslope }
            };
            each(&cuts, &at, &f);
        }
    }

    /// The slip of the solid relative to the punch over the load step from `prev` to this
    /// state (units of pi B P; (T3): ds = de - dD), at points given as (1 + x, 1 - x), in the
    /// contact's frame: zero on this state's stick set (stuck since `prev`), and in each slip
    /// zone the integral of the step's slip slope -(bq dp + dH[q]) from the zone's stick end,
    /// as [`Self::step_dissipation`] reads it. The points of a zone are integrated in one
    /// running sum from the stick end towards the contact's end, with 16-point Gauss-Legendre
    /// between neighbours and the graded rule on pieces that end at a zone end or kink of
    /// either state (where the slope is singular).
    pub(crate) fn step_slip(&self, prev: &ExactPath, points: &[(f64, f64)]) -> Vec<f64> {
        use crate::numerics::quadrature::{gauss_legendre, graded_rule};
        let mut out = vec![0.0; points.len()];
        if matches!(self.branch, Branch::Normal | Branch::Stuck { .. }) {
            return out;
        }
        let k = self.k;
        let (c1, c2) = self.stick_set();
        let mut bps = self.breakpoints();
        bps.extend(prev.breakpoints());
        let (gx, gw) = gauss_legendre(16);
        for (left, width) in [(true, 1.0 + c1), (false, 1.0 - c2)] {
            if width <= 0.0 {
                continue;
            }
            let at = |o: f64| if left { (o, 2.0 - o) } else { (2.0 - o, o) };
            let f = |o: f64| {
                let (opx, omx) = at(o);
                let (pa, ha) = prev.pressure_and_hq(opx, omx);
                let (pb, hb) = self.pressure_and_hq(opx, omx);
                let dslope = -(k.bq * (pb - pa) + hb - ha);
                if left { dslope } else { -dslope }
            };
            // the zone's points by offset from the contact's end, from the stick end out
            let mut mine: Vec<(f64, usize)> = points
                .iter()
                .enumerate()
                .map(|(i, &(o, m))| (if left { o } else { m }, i))
                .filter(|&(o, _)| o < width)
                .collect();
            if mine.is_empty() {
                continue;
            }
            mine.sort_by(|a, b| b.0.total_cmp(&a.0));
            let mut cuts: Vec<f64> = bps
                .iter()
                .map(|&(o, m)| if left { o } else { m })
                .filter(|&o| o > 0.0 && o < width)
                .collect();
            cuts.push(width);
            // every stop from the stick end down: (offset, point index or None for a cut)
            let mut stops: Vec<(f64, Option<usize>)> = cuts.iter().map(|&c| (c, None)).collect();
            stops.extend(mine.iter().map(|&(o, i)| (o, Some(i))));
            stops.sort_by(|a, b| b.0.total_cmp(&a.0));
            let (mut running, mut hi, mut hi_cut) = (0.0, width, true);
            for (o, idx) in stops {
                let is_cut = idx.is_none();
                if o < hi {
                    let piece: f64 = if hi_cut || is_cut {
                        // nodes rounded onto a zone end (where H[q] is NaN) left out, as in
                        // `unload::graded` (docs/theory_tangential.md section 18)
                        graded_rule(o, hi, 0.1, 1e-15, 16)
                            .into_iter()
                            .filter(|&(t, _)| t > o && t < hi)
                            .map(|(t, w)| w * f(t))
                            .sum()
                    } else {
                        let h = 0.5 * (hi - o);
                        gx.iter()
                            .zip(&gw)
                            .map(|(t, w)| h * w * f(o + h * (1.0 + t)))
                            .sum()
                    };
                    // ds(o) = ds(hi) - int_o^hi f
                    running -= piece;
                }
                hi = o;
                hi_cut = is_cut;
                if let Some(i) = idx {
                    out[i] = running;
                }
            }
        }
        out
    }

    /// The normal-load state of this path.
    fn normal_path(&self) -> ExactPath {
        ExactPath {
            branch: Branch::Normal,
            punch: 0.0,
            ..self.clone()
        }
    }

    /// D of this state, reached from `prev` (the state before the load step, with its D):
    /// docs/theory_tangential.md (T16). A point of this state's stick set has stuck since its
    /// branch's data (the normal load for the loading; for a later branch the state where the
    /// load reversed, or any earlier state of the same branch, whose stick set holds this
    /// one's), so D = D_ref + e(x) - e_ref(x) there; x is the stick set's middle.
    fn punch_from(&self, prev: &ExactPath) -> f64 {
        let (c1, c2) = self.stick_set();
        let x = 0.5 * (c1 + c2);
        match self.branch {
            Branch::Normal => 0.0,
            Branch::Loading { .. } => self.surface_change(&self.normal_path(), x),
            Branch::Unloading { .. } => prev.punch + self.surface_change(prev, x),
            // (T16) with the data as ref: e - e_d = -L[(Q - Q_d)/P p0] = (Q - Q_d)/P ln 2 / pi
            // everywhere on the contact (L[p0] = -ln 2 / pi there, section 16)
            Branch::Stuck { ref data, qp, .. } => data.punch + (qp - data.q_over_p()) * LN_2 / PI,
        }
    }

    /// e(x) - e_ref(x), the change of the surface's tangential displacement (T1),
    /// e = -(bq S[p] + L[q]) (units of pi B P), from the state `reference` to this one, by
    /// the graded rule of [`rule_on`] with both states' zone ends and x as breakpoints.
    pub(crate) fn surface_change(&self, reference: &ExactPath, x: f64) -> f64 {
        let g = edge_exponent(&self.k);
        let (o0, m0) = (1.0 + x, 1.0 - x);
        let mut bp = self.breakpoints();
        bp.extend(reference.breakpoints());
        bp.push((o0, m0));
        let (mut left, mut total, mut log) = (0.0, 0.0, 0.0);
        for (opx, omx, w) in rule_on(g, bp) {
            let (pn, qn) = self.tractions(opx, omx);
            let (pr, qr) = reference.tractions(opx, omx);
            let dp = w * (pn - pr);
            total += dp;
            if opx < o0 {
                left += dp;
            }
            // x - t from the nearer contact end, for its relative accuracy
            let d = if opx.min(o0) < 1.0 {
                o0 - opx
            } else {
                omx - m0
            };
            // the innermost nodes next to x round onto it (weights below 1e-16): their
            // share of the integrable logarithm is below rounding
            if d != 0.0 {
                log += w * (qn - qr) * d.abs().ln();
            }
        }
        -(self.k.bq * (left - 0.5 * total) + log / std::f64::consts::PI)
    }

    /// (p, q) at x given by (1 + x, 1 - x), in the contact's frame.
    pub(crate) fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        if let Branch::Stuck { data, qp, .. } = &self.branch {
            let (p, q) = data.tractions(opx, omx);
            // p0 = 1/(pi sqrt(1 - x^2)) from the offsets, for its digits at the edges
            let p0 = 1.0 / (PI * (opx * omx).sqrt());
            return (p, q + (qp - data.q_over_p()) * p0);
        }
        let own = |o: f64, m: f64| match &self.branch {
            Branch::Normal => self.normal.state.tractions(o, m),
            Branch::Loading { m: s, .. } => s.tractions(o, m),
            Branch::Unloading { u, .. } => u.tractions(o, m),
            Branch::Stuck { .. } => unreachable!("handled above"),
        };
        if self.flipped() {
            let (p, q) = own(omx, opx);
            (p, -q)
        } else {
            own(opx, omx)
        }
    }

    fn flipped(&self) -> bool {
        match &self.branch {
            Branch::Normal => false,
            Branch::Loading { flip, .. } | Branch::Unloading { flip, .. } => *flip,
            // its getters read the data, in the contact's frame
            Branch::Stuck { .. } => false,
        }
    }

    /// Whether the point x given by (1 + x, 1 - x) lies in the corner's layer stuck since the
    /// branch's data (an answer of the corner's outer model, docs/theory_tangential.md
    /// section 21): (-1, e2) in the branch's frame.
    pub(crate) fn in_stuck_layer(&self, opx: f64, omx: f64) -> bool {
        match &self.branch {
            Branch::Unloading { u, flip, .. } => u
                .level
                .layer
                .is_some_and(|e2| if *flip { omx < e2 } else { opx < e2 }),
            _ => false,
        }
    }

    /// Whether the state is an answer of the corner's outer model (a layer stuck since the
    /// branch's data at one end, docs/theory_tangential.md sections 21 and 23): a reversal
    /// from it is refused.
    pub(crate) fn corner_layer(&self) -> bool {
        matches!(&self.branch, Branch::Unloading { u, .. } if u.level.layer.is_some())
    }

    /// The stick set [c1, c2] in the contact's frame.
    pub(crate) fn stick_set(&self) -> (f64, f64) {
        let (a, b) = match &self.branch {
            Branch::Normal => (-self.normal.c, self.normal.c),
            Branch::Loading { m, .. } => {
                let (w1, c2) = m.stick_set();
                (w1 - 1.0, c2)
            }
            Branch::Unloading { u, .. } => u.stick_set(),
            Branch::Stuck { .. } => (-1.0, 1.0),
        };
        if self.flipped() { (-b, -a) } else { (a, b) }
    }

    /// The estimates of |c1 - c1_exact| + |c2 - c2_exact| and of the tractions in the norm
    /// (T1): the ladder's of this state, plus those of the state its branch started from
    /// (held fixed in the ladder; how they carry over is not measured).
    pub(crate) fn estimates(&self) -> (f64, f64) {
        match &self.branch {
            Branch::Normal => (self.normal.c_error, self.normal.traction_error),
            Branch::Loading { m, .. } => (m.c_error, m.traction_error),
            Branch::Unloading {
                u,
                data_c_error,
                data_traction_error,
                ..
            } => (
                u.c_error + data_c_error,
                u.traction_error + data_traction_error,
            ),
            // the closed-form shift adds nothing to the data's errors
            Branch::Stuck { data, .. } => data.estimates(),
        }
    }

    /// int x p dx (per P a) in the contact's frame.
    pub(crate) fn moment(&self) -> f64 {
        let own = match &self.branch {
            Branch::Normal => super::moment(edge_exponent(&self.k), &self.normal.state),
            Branch::Loading { m, .. } => m.moment(),
            Branch::Unloading { u, .. } => u.moment(),
            // p is the data's
            Branch::Stuck { data, .. } => return data.moment(),
        };
        if self.flipped() { -own } else { own }
    }

    /// The zone ends of the current state as (1 + x, 1 - x), increasing in x, both contact
    /// ends included, in the contact's frame.
    pub(crate) fn breakpoints(&self) -> Vec<(f64, f64)> {
        let s = match &self.branch {
            // q_d's kinks (p0's edge singularities are the contact's ends)
            Branch::Stuck { data, .. } => return data.breakpoints(),
            Branch::Normal => &self.normal.state,
            Branch::Loading { m, .. } => &m.level.state,
            Branch::Unloading { u, .. } => &u.level.state,
        };
        let f = &s.frame;
        let n = f.zone_count();
        let mut out = vec![(0.0, 2.0)];
        let mut acc = 0.0;
        for i in 0..n {
            acc += f.zone_len(i);
            let omx: f64 = (i + 1..n).map(|j| f.zone_len(j)).sum();
            out.push(if i + 1 == n { (2.0, 0.0) } else { (acc, omx) });
        }
        if self.flipped() {
            out = out.into_iter().rev().map(|(o, m)| (m, o)).collect();
        }
        out
    }
}

/// Points of the contact (Chebyshev, denser towards the edges) at which a full-stick state
/// is checked against the friction bound ([`ExactPath::stuck_admissible`]); one traction
/// evaluation each, against the 9,000 of one (T16).
const STUCK_CHECKS: usize = 400;

/// What [`ExactPath::over_slip_zones`] calls per slip zone: (cuts, offset -> (1 + x, 1 - x),
/// the slip slope along the offset).
type ZoneVisit<'a> = dyn FnMut(&[f64], &dyn Fn(f64) -> (f64, f64), &dyn Fn(f64) -> f64) + 'a;

/// Offset from a contact end (in units of a) inside which a non-finite slip slope counts as
/// zero in [`ExactPath::step_dissipation`] and [`ExactPath::step_mid_work`].
const NEAR_END: f64 = 1e-14;

/// A load-path state as a [`Profile`]: its tractions in the contact's frame at any x.
#[derive(Clone)]
pub(crate) struct ExactProfile {
    pub(crate) path: ExactPath,
}

impl std::fmt::Debug for ExactProfile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ExactProfile")
            .field("q_over_p", &self.path.q_over_p())
            .field("stick_set", &self.path.stick_set())
            .finish()
    }
}

impl Profile for ExactProfile {
    fn coupling(&self) -> Coupling {
        self.path.k
    }
    /// No single stick half-width: NaN (the stick set is the solution's).
    fn edge(&self) -> crate::problem::StickEdge {
        crate::problem::StickEdge {
            c: f64::NAN,
            one_minus_c: f64::NAN,
        }
    }
    fn numerical_error(&self) -> f64 {
        self.path.estimates().0
    }
    fn traction_error(&self) -> f64 {
        self.path.estimates().1
    }
    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        self.tractions(x)
    }
    /// (p, q) at any x (not NaN): zero outside the punch, p = +infinity at x = +-1 with q
    /// infinite of the sign of q next to that edge (0 where q vanishes there).
    fn tractions(&self, x: f64) -> (f64, f64) {
        let ax = x.abs();
        if ax > 1.0 {
            return (0.0, 0.0);
        }
        if ax == 1.0 {
            let d = 1e-12;
            let (_, q) = if x < 0.0 {
                self.path.tractions(d, 2.0 - d)
            } else {
                self.path.tractions(2.0 - d, d)
            };
            return (f64::INFINITY, crate::problem::edge_infinity(q));
        }
        self.path.tractions(1.0 + x, 1.0 - x)
    }
}

/// Grading of the expansion's panels towards every zone end: ratio and levels (the
/// innermost panel 0.2^14 = 1.6e-10 of the half zone).
const GRADING: f64 = 0.2;
const GRADED_LEVELS: usize = 14;

/// Each zone cut into panels graded geometrically towards both its ends, fitted in Legendre
/// series ([`crate::field::fitted_panel`]); the panels at the contact's ends weighted
/// (1 + t)^(-g) and (1 - t)^(-g).
impl crate::field::Expand for ExactProfile {
    fn expansion(&self) -> crate::field::Expansion {
        use crate::numerics::cauchy::Weight;
        let g = edge_exponent(&self.path.k);
        let mut panels = Vec::new();
        for w in self.path.breakpoints().windows(2) {
            let ((oa, ma), (ob, mb)) = (w[0], w[1]);
            let len = if oa < mb { ob - oa } else { ma - mb };
            if len <= 0.0 {
                continue;
            }
            // panel ends as offsets s from the zone's left end, increasing
            let half = 0.5 * len;
            let mut cuts = vec![0.0];
            for j in (1..=GRADED_LEVELS).rev() {
                cuts.push(half * GRADING.powi(j as i32));
            }
            cuts.push(half);
            for j in 1..=GRADED_LEVELS {
                cuts.push(len - half * GRADING.powi(j as i32));
            }
            cuts.push(len);
            for c in cuts.windows(2) {
                let (s0, s1) = (c[0], c[1]);
                let h = 0.5 * (s1 - s0);
                // offsets of the panel's ends from the contact's ends, each from its nearer
                // zone end
                let (o0, m1) = (oa + s0, mb + (len - s1));
                let weight = if oa == 0.0 && s0 == 0.0 {
                    Weight::Left(-g)
                } else if mb == 0.0 && s1 == len {
                    Weight::Right(-g)
                } else {
                    Weight::One
                };
                let (a, b) = (o0 - 1.0, 1.0 - m1);
                panels.push(crate::field::fitted_panel(a, b, weight, |omt, opt| {
                    self.path.tractions(o0 + h * opt, m1 + h * omt)
                }));
            }
        }
        crate::field::Expansion { panels }
    }

    /// The two edges differ: none.
    fn edge_intensity(&self, _: &crate::field::Expansion) -> Option<(f64, f64)> {
        None
    }
}

fn sign(flip: bool) -> f64 {
    if flip { -1.0 } else { 1.0 }
}

#[cfg(test)]
mod tests;
