//! [`Fretting::solve`] with [`CycleMethod::Exact`]: the cycle's loads on the exact load path
//! ([`exact::path::ExactPath`]), where it answers every one of them (bp = 0: the loading,
//! the slipping parts of the branches and their full-stick ranges, docs/theory_tangential.md
//! section 18). A load it refuses (the corner structure at bp > 0, sections 13 and 15) ends
//! the run with its status and message; the grid is never used in its place.
//!
//! The run takes the grid's load steps (`options.steps` in the first loading, twice that
//! per half cycle): the loop's points, the cycle's states and the slip's history are read at
//! them. Profiles are the exact values at the grid's 2n panel midpoints (`options.panels`
//! per half-width), presented as the grid's panel values.

use std::f64::consts::LN_2;

use super::exact::path::{Branch, ExactPath};
use super::exact::{edge_exponent, position, rule_on};
use super::*;

/// |L[f](x)| per unit of int |f| when |f| has the shape of the edge singularity,
/// |f| = (int |f|) p0 with p0 = 1/(pi sqrt(1 - t^2)): (1/pi) int p0 |ln|x - t|| dt <= 2 ln 2 / pi
/// for every x on the contact (docs/theory_tangential.md (T18b)). The estimates take the
/// tractions' error (an estimate in the norm (T1)) in that shape, which bounds neither its
/// log potential nor its point values: a model, not a bound.
const LOG_POTENTIAL: f64 = 2.0 * LN_2 / PI;

/// The error `e` of the exact path at `what`, said to come from a fretting run.
fn in_run(what: &str, e: Error) -> Error {
    e.reworded(|m| format!("Fretting::solve with CycleMethod::Exact, {what}: {m}"))
}

/// The grid's midpoints as (1 + x, 1 - x) with their digits.
fn offsets(n: usize) -> Vec<(f64, f64)> {
    let h = 1.0 / n as f64;
    (0..2 * n)
        .map(|i| ((i as f64 + 0.5) * h, ((2 * n - i) as f64 - 0.5) * h))
        .collect()
}

/// One state of the run: its point on the path (profiles at the nodes), H[q] at the nodes
/// (for sigma_xx), the dissipation and its estimate since the normal load (pi B P^2), the
/// estimates of its tractions (norm (T1), COUPLED's normal load's added) and of its D (pi B
/// P; absolute, and since the cycle's start), and in a cycle -int q_mid ds over the step
/// that reached it (pi B P^2, [`ExactPath::step_mid_work`]; 0 elsewhere).
#[derive(Clone)]
struct Step {
    point: PathPoint,
    hq: Vec<f64>,
    dissipated: f64,
    dissipated_error: f64,
    stick_error: f64,
    traction_error: f64,
    punch_error: f64,
    cycle_punch_error: f64,
    mid_work: f64,
}

/// The tractions' estimate of a state in the norm (T1): the ladders' (this state's and its
/// branch data's, [`ExactPath::estimates`]) and COUPLED's of the normal load, which the
/// loading takes as its data and the ladders hold fixed.
fn traction_error(path: &ExactPath) -> f64 {
    path.estimates().1 + path.normal.traction_error
}

/// [`traction_error`] of the path's normal-load state, without building that state: its
/// ladder's estimate is COUPLED's of the normal load, so twice that.
fn normal_traction_error(path: &ExactPath) -> f64 {
    2.0 * path.normal.traction_error
}

/// The estimate of |de(x)| per unit of a state's traction estimate: the log potential of q's
/// error ([`LOG_POTENTIAL`]) and bq |S[dp]| <= (bq/2) int |dp|.
fn surface_factor(k: &Coupling) -> f64 {
    LOG_POTENTIAL + 0.5 * k.bq
}

fn step(path: &ExactPath, at: &[(f64, f64)], unit: f64) -> Step {
    let (c1, c2) = path.stick_set();
    let mut p = Vec::with_capacity(at.len());
    let mut q = Vec::with_capacity(at.len());
    let mut hq = Vec::with_capacity(at.len());
    let mut zones = Vec::with_capacity(at.len());
    for &(opx, omx) in at {
        let (pp, qq) = path.tractions(opx, omx);
        let (_, h) = path.pressure_and_hq(opx, omx);
        let x = position(opx, omx);
        zones.push(if (x >= c1 && x <= c2) || path.in_stuck_layer(opx, omx) {
            Zone::Stick
        } else if qq < 0.0 {
            Zone::SlipPositive
        } else {
            Zone::SlipNegative
        });
        p.push(pp);
        q.push(qq);
        hq.push(h);
    }
    Step {
        point: PathPoint {
            q_over_p: path.q_over_p(),
            stick: (c1, c2),
            punch: path.punch * unit,
            p,
            q,
            zones,
        },
        hq,
        dissipated: path.dissipated,
        dissipated_error: path.dissipated_error,
        stick_error: path.estimates().0,
        traction_error: traction_error(path),
        punch_error: 0.0,
        cycle_punch_error: 0.0,
        mid_work: 0.0,
    }
}

/// The slip since the cycle's start at the nodes (pi B P) and its estimate: per node the
/// largest over the cycle's states so far (`error`), made of the estimate settled by the
/// cycle's earlier branches and the current branch's, for the nodes that slipped on it
/// (`moved`).
struct Slip {
    value: Vec<f64>,
    error: Vec<f64>,
    settled: Vec<f64>,
    branch: Vec<f64>,
    moved: Vec<bool>,
}

impl Slip {
    fn new(m: usize) -> Self {
        Self {
            value: vec![0.0; m],
            error: vec![0.0; m],
            settled: vec![0.0; m],
            branch: vec![0.0; m],
            moved: vec![false; m],
        }
    }

    /// A new branch (the load reverses): the current branch's estimates are settled.
    fn reverse(&mut self) {
        for j in 0..self.value.len() {
            self.settled[j] += self.branch[j];
            self.branch[j] = 0.0;
            self.moved[j] = false;
        }
    }
}

/// Moves the path to `q`, recording the state; `data` is the state the current branch
/// started from (where the load last reversed; the normal load while loading). The step's
/// slip at the nodes is added to `slip` when given. The estimates (docs/theory_tangential.md
/// (T18b)): a branch's slip since its data at x is de(x) - de(z), z in the stick set, and its
/// D - D_d is de at the stick set's middle, both (T16) with de = e - e_d, which the path
/// sums over the branch's steps; an intermediate state's error enters at two points of its
/// own stick set, where its e - e_d is constant to the solve's residual, and cancels. So the
/// slip's estimate is 2 [`surface_factor`] times the traction estimates of the state and
/// the data, D's the data's plus [`surface_factor`] times the same (from the normal load
/// while loading), and a full-stick range keeps the data's (its shift is a closed form).
fn advance(
    path: &mut ExactPath,
    data: &Step,
    q: f64,
    at: &[(f64, f64)],
    unit: f64,
    slip: Option<&mut Slip>,
    what: &str,
) -> Result<Step> {
    let prev = path.clone();
    path.load(q).map_err(|e| in_run(what, e))?;
    let mut st = step(path, at, unit);
    let factor = surface_factor(&path.k);
    let both = st.traction_error + data.traction_error;
    if slip.is_some() {
        // a cycle's step: its mid-step work enters the cycle's loop work and energy
        st.mid_work = path.step_mid_work(&prev);
    }
    if let Some(s) = slip {
        for (j, ds) in path.step_slip(&prev, at).into_iter().enumerate() {
            s.value[j] += ds;
            s.moved[j] |= ds != 0.0;
            if s.moved[j] {
                s.branch[j] = 2.0 * factor * both;
                s.error[j] = s.error[j].max(s.settled[j] + s.branch[j]);
            }
        }
    }
    (st.punch_error, st.cycle_punch_error) = match path.branch {
        Branch::Normal => (0.0, 0.0),
        Branch::Loading { .. } => {
            // D from the normal load; against the cycle's start, plus the start's estimate
            // (the data's estimate less its estimate since the cycle's start)
            let e = factor * (st.traction_error + normal_traction_error(path));
            (e, e + data.punch_error - data.cycle_punch_error)
        }
        Branch::Unloading { .. } => (
            data.punch_error + factor * both,
            data.cycle_punch_error + factor * both,
        ),
        Branch::Stuck { .. } => (data.punch_error, data.cycle_punch_error),
    };
    Ok(st)
}

/// The loads of `steps` equal steps from `from` to `to` (the last exactly `to`).
fn loads(from: f64, to: f64, steps: usize) -> Vec<f64> {
    (1..=steps)
        .map(|i| {
            if i == steps {
                to
            } else {
                from + (to - from) * i as f64 / steps as f64
            }
        })
        .collect()
}

/// The part of the grid's elastic energy (1/2) int q u (docs/theory_tangential.md section
/// 4) that is linear in q at bp = 0, (1/2) int q (-bq S[p0]) with S[p0](x) = arcsin(x)/pi,
/// changed from `a` to `b` (units of pi B P^2; (T18c)): -(bq/(2 pi)) int (q_b - q_a) arcsin x
/// by the graded rule on both states' zone ends.
fn linear_energy(k: &Coupling, a: &ExactPath, b: &ExactPath) -> f64 {
    let mut bps = a.breakpoints();
    bps.extend(b.breakpoints());
    let sum: f64 = rule_on(edge_exponent(k), bps)
        .into_iter()
        .map(|(opx, omx, w)| {
            let x = position(opx, omx);
            w * (b.tractions(opx, omx).1 - a.tractions(opx, omx).1) * x.asin()
        })
        .sum();
    -k.bq / (2.0 * PI) * sum
}

/// The factor on the rise of the parabola through a peak node and its neighbours in the
/// estimate of the profile's largest value above the node's: the parabola misses the peak's
/// quartic term. The largest ratio of the true rise to the parabola's over peak shapes
/// 1/(1 + (x/w)^2), exp(-(x/w)^2) and cos(x/w) and 101 offsets of the peak between two
/// nodes, by the half-width w in node spacings (measured):
///
/// | w | 1 | 1.5 | 2 | 3 | 5 | 8 | 20 |
/// |---|---|---|---|---|---|---|---|
/// | ratio | 8.0 | 3.0 | 1.95 | 1.37 | 1.12 | 1.05 | 1.008 |
///
/// So 2 holds for peaks two node spacings wide and wider.
const PEAK_RISE: f64 = 2.0;

/// The peak of a profile at the nodes with the estimates of (T18d), from the estimates `err`
/// of its node values: the largest node value moves by at most the largest of them, and
/// lies at a node whose value could exceed the peak's within them; there the profile's
/// largest value along the contact lies within one node spacing when the profile is
/// unimodal around it, above the node's by at most [`PEAK_RISE`] times the rise of the
/// parabola through the node and its neighbours. At a node next to a contact edge the
/// profile grows without bound towards the edge (tau_max follows p's edge singularity, the
/// slip amplitude stays finite): error +infinity, the position the edge's, half a node
/// spacing away. A profile that vanishes at every node: error the largest of `err`, position
/// anywhere (2) unless that is 0.
pub(super) fn node_peak(f: &[f64], err: &[f64], nodes: &[f64], h: f64) -> Peak {
    let (value, x) = peak(f, nodes);
    let worst = err.iter().fold(0.0f64, |a, &b| a.max(b));
    let Some(i) = nodes.iter().position(|&n| n == x) else {
        return Peak {
            value,
            x,
            error: worst,
            x_error: if worst == 0.0 { 0.0 } else { 2.0 },
        };
    };
    if i == 0 || i + 1 == nodes.len() {
        return Peak {
            value,
            x,
            error: f64::INFINITY,
            x_error: 0.5 * h,
        };
    }
    let spread = (0..f.len())
        .filter(|&j| f[j] + err[j] >= value - err[i])
        .map(|j| (nodes[j] - x).abs())
        .fold(0.0, f64::max);
    // the rise of the parabola through the peak and its neighbours above the peak's value
    let (l, r) = (f[i - 1], f[i + 1]);
    let curvature = 2.0 * value - l - r;
    let rise = if curvature > 0.0 {
        (r - l).powi(2) / (8.0 * curvature)
    } else {
        0.0
    };
    Peak {
        value,
        x,
        error: worst + PEAK_RISE * rise,
        x_error: h + spread,
    }
}

/// The run for the coupling `k` (the contact's; Goodman's bp = 0 in tests) with the
/// contact's material (units, sigma_xx) and tolerances.
pub(super) fn solve(
    contact: &Contact,
    k: &Coupling,
    q_amp: f64,
    options: &CycleOptions,
) -> Result<Fretting> {
    let k = *k;
    let unit = unit(contact);
    let (n, s) = (options.panels, options.steps);
    let tol = options.repeat_tolerance;
    let at = offsets(n);
    let h = 1.0 / n as f64;
    let nodes: Vec<f64> = at.iter().map(|&(o, m)| position(o, m)).collect();
    let mut path = ExactPath::new(&k, contact.tolerance(), contact.traction_tolerance())
        .map_err(|e| in_run("the normal load", e))?;
    let normal = step(&path, &at, unit);
    // A probe: the state at Q* (the loading is path-independent, one solve), the first
    // unloading step, and the first reloading step from -Q* (the unloading is
    // path-independent from Q*, one solve), so that a refusal there comes before the first
    // loading's steps are spent. Where the first reloading step is the corner's outer model
    // (bp > 0, a layer stuck since -Q* at +1: docs/theory_tangential.md section 23) the run
    // would reverse at +Q* from a reloading state with that layer, which no branch takes as
    // data yet (on the ply the layer persists up to +Q*): the probe asks for a reversal from
    // the first step's state, refused at once, instead of the whole first cycle's steps. (A
    // layer that vanished before +Q* would be refused too.)
    {
        let mut probe = path.clone();
        probe
            .load(q_amp)
            .map_err(|e| in_run("the first loading", e))?;
        let mut reversed = probe.clone();
        let first_step = loads(q_amp, -q_amp, 2 * s)[0];
        probe
            .load(first_step)
            .map_err(|e| in_run(&format!("cycle 0, unloading to Q/P = {first_step}"), e))?;
        reversed
            .load(-q_amp)
            .map_err(|e| in_run(&format!("cycle 0, unloading to Q/P = {}", -q_amp), e))?;
        let back = loads(-q_amp, q_amp, 2 * s)[0];
        reversed
            .load(back)
            .map_err(|e| in_run(&format!("cycle 0, reloading to Q/P = {back}"), e))?;
        if reversed.corner_layer() {
            reversed.load(-q_amp).map_err(|e| {
                in_run(
                    &format!(
                        "cycle 0, reloading to Q/P = {back} (answered with the corner's stuck \
                         layer at +1; the run's reversal at Q/P = {q_amp} would take such a \
                         state as data)"
                    ),
                    e,
                )
            })?;
        }
    }
    let mut first: Vec<Step> = Vec::new();
    for q in loads(0.0, q_amp, s) {
        first.push(advance(
            &mut path,
            &normal,
            q,
            &at,
            unit,
            None,
            "the first loading",
        )?);
    }
    let first_w = path.dissipated * unit;
    let first_err = path.dissipated_error * unit;
    let surface = SurfaceSxx::new(contact);
    let sxx = |st: &Step| -> Vec<f64> {
        st.point
            .p
            .iter()
            .zip(&st.hq)
            .map(|(&p, &hq)| surface.at(p, hq))
            .collect()
    };
    // p0 at the nodes, from the offsets: the shape the point-wise estimates give the
    // tractions' error ([`LOG_POTENTIAL`])
    let p0: Vec<f64> = at
        .iter()
        .map(|&(o, m)| 1.0 / (PI * (o * m).sqrt()))
        .collect();
    let mut start = first.last().expect("at least two steps").clone();
    let mut start_path = path.clone();
    let mut cycles = Vec::new();
    let mut repeated = false;
    for i in 0..options.max_cycles {
        start.cycle_punch_error = 0.0;
        let mut slip = Slip::new(at.len());
        let (mut lo, mut hi) = (slip.value.clone(), slip.value.clone());
        let mut states: Vec<Step> = Vec::new();
        let (w0, e0) = (start.dissipated, start.dissipated_error);
        for (half, (from, to)) in [(q_amp, -q_amp), (-q_amp, q_amp)].into_iter().enumerate() {
            let data = states.last().unwrap_or(&start).clone();
            slip.reverse();
            for q in loads(from, to, 2 * s) {
                let what = format!(
                    "cycle {i}, {} to Q/P = {q}",
                    if half == 0 { "unloading" } else { "reloading" }
                );
                let st = advance(&mut path, &data, q, &at, unit, Some(&mut slip), &what)?;
                for j in 0..at.len() {
                    lo[j] = lo[j].min(slip.value[j]);
                    hi[j] = hi[j].max(slip.value[j]);
                }
                states.push(st);
            }
        }
        let end = states.last().expect("steps");
        let dissipation = (end.dissipated - w0) * unit;
        let dissipation_error = (end.dissipated_error - e0) * unit;
        // a node that stuck at every step keeps its relative displacement: amplitude 0
        let slip_amplitude: Vec<f64> = (0..at.len())
            .map(|j| {
                if states.iter().all(|st| st.point.zones[j] == Zone::Stick) {
                    0.0
                } else {
                    0.5 * (hi[j] - lo[j]) * unit
                }
            })
            .collect();
        // at bp = 0 each node's slip is monotone along a branch and the extremes lie at the
        // turning points, which are steps (T18b): the estimate is the slips' own
        let slip_error: Vec<f64> = slip.error.iter().map(|e| e * unit).collect();
        let mut tau_max: Vec<f64> = start.point.q.iter().map(|q| q.abs()).collect();
        let mut sxx_max = sxx(&start);
        for st in &states {
            let sx = sxx(st);
            for j in 0..at.len() {
                tau_max[j] = tau_max[j].max(st.point.q[j].abs());
                sxx_max[j] = sxx_max[j].max(sx[j]);
            }
        }
        let f1: Vec<f64> = (0..at.len())
            .map(|j| tau_max[j] * slip_amplitude[j])
            .collect();
        let f2: Vec<f64> = (0..at.len()).map(|j| sxx_max[j].max(0.0) * f1[j]).collect();
        // point-wise estimates of tau_max, sigma_xx,max, F1 and F2 (T18d)
        let traction = states
            .iter()
            .map(|st| st.traction_error)
            .fold(start.traction_error, f64::max);
        let f1_error: Vec<f64> = (0..at.len())
            .map(|j| tau_max[j] * slip_error[j] + slip_amplitude[j] * traction * p0[j])
            .collect();
        let f2_error: Vec<f64> = (0..at.len())
            .map(|j| {
                let e = surface.weight() * traction * p0[j];
                let d = if sxx_max[j] + e > 0.0 { e } else { 0.0 };
                sxx_max[j].max(0.0) * f1_error[j] + (f1[j] + f1_error[j]) * d
            })
            .collect();
        let mut loop_points = vec![(start.point.q_over_p, start.point.punch)];
        loop_points.extend(states.iter().map(|st| (st.point.q_over_p, st.point.punch)));
        let loop_work: f64 = loop_points
            .windows(2)
            .map(|w| 0.5 * (w[0].0 + w[1].0) * (w[1].1 - w[0].1))
            .sum();
        let mid_work: f64 = states.iter().map(|st| st.mid_work).sum();
        let w_cycle = end.dissipated - w0;
        // the loop work's estimate (T18c): the trapezoidal rule's error W_mid - W, and D's
        // estimates since the cycle's start with the weights of sum Q_mid dD = sum c_k D_k
        let punch_part: f64 = {
            let mut errs = vec![0.0];
            errs.extend(states.iter().map(|st| st.cycle_punch_error));
            let qs: Vec<f64> = loop_points.iter().map(|l| l.0).collect();
            let last = qs.len() - 1;
            (0..=last)
                .map(|k| {
                    let weight = if k == 0 {
                        0.5 * (qs[0] + qs[1])
                    } else if k == last {
                        0.5 * (qs[last - 1] + qs[last])
                    } else {
                        0.5 * (qs[k - 1] - qs[k + 1])
                    };
                    weight.abs() * errs[k]
                })
                .sum()
        };
        let (loop_work_error, energy_change) = if k.bp == 0.0 {
            (
                ((mid_work - w_cycle).abs() + punch_part) * unit,
                loop_work + (linear_energy(&k, &start_path, &path) - mid_work) * unit,
            )
        } else {
            // not reached: the exact run answers bp = 0 only
            (f64::INFINITY, f64::NAN)
        };
        let minus = &states[2 * s - 1];
        let stick_error = minus.stick_error.max(end.stick_error);
        let dq: f64 = h * end
            .point
            .q
            .iter()
            .zip(&start.point.q)
            .map(|(a, b)| (a - b).abs())
            .sum::<f64>();
        let du = (end.point.punch - start.point.punch).abs();
        let result = CycleResult {
            dissipation: Estimate {
                value: dissipation,
                error: dissipation_error,
            },
            slip_amplitude_error: slip_error.iter().fold(0.0, |a, &b| a.max(b)),
            loop_points,
            loop_error: minus.punch_error.max(end.punch_error) * unit,
            loop_work,
            loop_work_error,
            // at bp = 0 the normal displacement depends on p alone, which does not change
            normal_work: if k.bp == 0.0 { 0.0 } else { f64::NAN },
            energy_change,
            // at bp = 0 (T9) holds for the energy of q alone; see the field's doc
            balance_residual: f64::NAN,
            f1_peak: node_peak(&f1, &f1_error, &nodes, h),
            f2_peak: node_peak(&f2, &f2_error, &nodes, h),
            slip_amplitude,
            tau_max,
            sxx_max,
            f1,
            f2,
            stick_at_minus: minus.point.stick,
            stick_at_plus: end.point.stick,
            stick_error,
            path: states.iter().map(|st| st.point.clone()).collect(),
        };
        cycles.push(result);
        start = states.pop().expect("steps");
        start_path = path.clone();
        if dq <= tol && du <= tol {
            repeated = true;
            break;
        }
    }
    let state = match (repeated, cycles.last()) {
        (true, Some(c)) if c.dissipation.value <= tol => CycleState::Shakedown,
        (true, _) => CycleState::SteadySlip,
        (false, _) => CycleState::CycleLimitReached,
    };
    let first_loading: Vec<PathPoint> = first.into_iter().map(|st| st.point).collect();
    Ok(Fretting {
        method: CycleMethod::Exact,
        options: *options,
        q_amp_over_p: q_amp,
        nodes,
        h,
        normal_load: normal.point,
        first_loading,
        first_loading_dissipation: Estimate {
            value: first_w,
            error: first_err,
        },
        cycles,
        state,
    })
}
