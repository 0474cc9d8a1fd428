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

use super::exact::path::ExactPath;
use super::*;

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
/// (for sigma_xx), and the dissipation and its estimate since the normal load (pi B P^2).
#[derive(Clone)]
struct Step {
    point: PathPoint,
    hq: Vec<f64>,
    dissipated: f64,
    dissipated_error: f64,
    stick_error: f64,
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
        let x = if opx < 1.0 { opx - 1.0 } else { 1.0 - omx };
        zones.push(if x >= c1 && x <= c2 {
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
    }
}

/// Moves the path to `q`, recording the state; the step's slip at the nodes is added to
/// `slip` (the slip since the cycle's start, pi B P) when given.
fn advance(
    path: &mut ExactPath,
    q: f64,
    at: &[(f64, f64)],
    unit: f64,
    slip: Option<&mut Vec<f64>>,
    what: &str,
) -> Result<Step> {
    let prev = path.clone();
    path.load(q).map_err(|e| in_run(what, e))?;
    if let Some(s) = slip {
        for (acc, ds) in s.iter_mut().zip(path.step_slip(&prev, at)) {
            *acc += ds;
        }
    }
    Ok(step(path, at, unit))
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
    let nodes: Vec<f64> = at
        .iter()
        .map(|&(o, m)| if o < 1.0 { o - 1.0 } else { 1.0 - m })
        .collect();
    let mut path = ExactPath::new(&k, contact.tolerance(), contact.traction_tolerance())
        .map_err(|e| in_run("the normal load", e))?;
    let normal = step(&path, &at, unit);
    // A probe: the state at Q* (the loading is path-independent, one solve) and the first
    // unloading step, so that a refusal there (bp > 0: the corner structure, not built)
    // comes before the first loading's steps are spent.
    {
        let mut probe = path.clone();
        probe
            .load(q_amp)
            .map_err(|e| in_run("the first loading", e))?;
        let first_step = loads(q_amp, -q_amp, 2 * s)[0];
        probe
            .load(first_step)
            .map_err(|e| in_run(&format!("cycle 0, unloading to Q/P = {first_step}"), e))?;
    }
    let mut first = Vec::new();
    for q in loads(0.0, q_amp, s) {
        first.push(advance(&mut path, q, &at, unit, None, "the first loading")?);
    }
    let first_w = path.dissipated * unit;
    let first_err = path.dissipated_error * unit;
    let c = contact.material().constants();
    let root = (2.0 * (1.0 + c.kappa)).sqrt();
    let sxx = |st: &Step| -> Vec<f64> {
        st.point
            .p
            .iter()
            .zip(&st.hq)
            .map(|(p, hq)| -c.delta * c.delta * p - c.delta * root * hq)
            .collect()
    };
    let mut start = first.last().expect("at least two steps").clone();
    let mut cycles = Vec::new();
    let mut repeated = false;
    for i in 0..options.max_cycles {
        let mut slip = vec![0.0; at.len()];
        let (mut lo, mut hi) = (slip.clone(), slip.clone());
        let mut states = Vec::new();
        let (w0, e0) = (start.dissipated, start.dissipated_error);
        for (half, (from, to)) in [(q_amp, -q_amp), (-q_amp, q_amp)].into_iter().enumerate() {
            for q in loads(from, to, 2 * s) {
                let what = format!(
                    "cycle {i}, {} to Q/P = {q}",
                    if half == 0 { "unloading" } else { "reloading" }
                );
                let st = advance(&mut path, q, &at, unit, Some(&mut slip), &what)?;
                for j in 0..at.len() {
                    lo[j] = lo[j].min(slip[j]);
                    hi[j] = hi[j].max(slip[j]);
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
        let mut loop_points = vec![(start.point.q_over_p, start.point.punch)];
        loop_points.extend(states.iter().map(|st| (st.point.q_over_p, st.point.punch)));
        let loop_work: f64 = loop_points
            .windows(2)
            .map(|w| 0.5 * (w[0].0 + w[1].0) * (w[1].1 - w[0].1))
            .sum();
        let minus = &states[2 * s - 1];
        let stick_error = minus.stick_error.max(end.stick_error);
        let unpeaked = |pk: (f64, f64)| Peak {
            value: pk.0,
            x: pk.1,
            error: f64::INFINITY,
            x_error: f64::INFINITY,
        };
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
            slip_amplitude_error: f64::INFINITY,
            loop_points,
            loop_error: f64::INFINITY,
            loop_work,
            loop_work_error: f64::INFINITY,
            // at bp = 0 the normal displacement depends on p alone, which does not change
            normal_work: if k.bp == 0.0 { 0.0 } else { f64::NAN },
            energy_change: f64::NAN,
            balance_residual: f64::NAN,
            f1_peak: unpeaked(peak(&f1, &nodes)),
            f2_peak: unpeaked(peak(&f2, &nodes)),
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
