//! Tangential load and fretting cycles (issue 27; theory in docs/theory_tangential.md, use in
//! docs/fretting.md): the punch pressed by P, then pulled sideways by Q and cycled between
//! +Q* and -Q*.
//!
//! Two entry points, both method-agnostic in their results:
//! - [`LoadPath`]: the normal-load state, then Q moved monotonically to any value, step by
//!   step, as an FE code scripts a load path; the stick set [c1, c2], p, q and the zones (with
//!   their slip directions) of the current state;
//! - [`Fretting::solve`]: the first loading 0 -> Q*, then cycles Q* -> -Q* -> Q* until the
//!   state repeats ([`CycleState::Shakedown`] or [`CycleState::SteadySlip`]) or the cycle
//!   limit is reached, with per cycle the dissipated energy, the slip amplitude, the
//!   Q-displacement loop, the Ruiz parameters and the stick sets.
//!
//! The method is a [`CycleMethod`]:
//! - [`CycleMethod::LcpHistory`], the paper's grid LCP with a loading history
//!   (`crate::lcp::history`): first order in the panel width and in the load step. Every
//!   result carries an error estimate from two more runs, one with half the panels and one
//!   with half the load steps (each error is first order, so the difference from the halved
//!   run estimates the error of the full run; the two are added and doubled for safety, the
//!   observed orders being 0.7-1.3).
//! - [`CycleMethod::Exact`], the exact solvers (`exact`) for a [`LoadPath`] where they
//!   answer (the normal load, monotonic loading, the branches after a reversal that keep one
//!   stick set with a slip zone at each end, at bp = 0 with their full-stick ranges), and
//!   [`Fretting::solve`] on those states (`exact_run`: the cycle's load steps, profiles
//!   sampled at the grid's midpoints); everything else is refused with a clear status and
//!   message.
//!
//! Units: x per a; p, q, tau and sigma_xx per P/a; displacements and slip amplitudes per P/E;
//! energies per unit thickness in P^2/E; F1 in P^2/(a E); F2 in P^3/(a^2 E). E is the
//! effective modulus of [`crate::Material::constants`]. Values on the grid are panel values
//! at the 2n panel midpoints [`Fretting::nodes`] (piecewise constant in x).

use std::f64::consts::PI;

use crate::contact::{Contact, Method, Solution};
use crate::error::{Error, Result};
use crate::field::{Expand, Expansion, Family, grid_expansion};
use crate::lcp::history::{self, History, State};
use crate::material::Material;
use crate::numerics::cauchy::Weight;
use crate::problem::{Coupling, Profile, StickEdge};

pub use crate::lcp::history::Zone;

/// The exact solvers of monotonic loading (docs/theory_tangential.md sections 10-12) and of
/// the unloading and reloading branches' three-zone phases (sections 13-15), reached by
/// [`LoadPath`] with [`CycleMethod::Exact`] (`exact::path`); the corner structure of the
/// unloading at strong coupling and early in the ply's branch, and of the ply's reloading,
/// is not built.
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) mod exact;

/// [`Fretting::solve`] on the exact load path (docs/theory_tangential.md section 18).
mod exact_run;

/// How a cycle is solved; the discriminants are the C ABI's `orthoslip_cycle_method` values
/// (append-only).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CycleMethod {
    /// The paper's grid LCP with a loading history: 2n uniform panels on the contact, one
    /// complementarity problem per load step (first order in the panel width and the step).
    LcpHistory = 0,
    /// The exact solvers of docs/theory_tangential.md sections 10-15 (global bases per zone
    /// carrying the zones' exponents, c1 and c2 to 1e-10 where they answer), to the
    /// contact's tolerances: for [`LoadPath`] the normal load, monotonic loading and the
    /// branches after each reversal where they keep one stick set with a slip zone at each
    /// end (at bp = 0 with their full-stick ranges); other loads are refused with a clear
    /// status, not answered by the grid. [`Fretting::solve`] takes the cycle's load steps on
    /// that path where it answers them all (bp = 0; docs/theory_tangential.md section 18),
    /// and otherwise returns the refusal.
    Exact = 1,
}

impl CycleMethod {
    /// All methods, in discriminant order.
    pub const ALL: [CycleMethod; 2] = [CycleMethod::LcpHistory, CycleMethod::Exact];

    /// The method with this C ABI value, if any.
    pub fn from_code(code: i32) -> Option<CycleMethod> {
        CycleMethod::ALL.into_iter().find(|m| *m as i32 == code)
    }
}

/// Default panels per half-width.
pub const DEFAULT_PANELS: usize = 100;
/// Default load steps per quarter cycle (per call of [`LoadPath::load`]).
pub const DEFAULT_STEPS: usize = 10;
/// Default cycle limit.
pub const DEFAULT_MAX_CYCLES: usize = 10;
/// Default tolerance for "the state repeats".
pub const DEFAULT_REPEAT_TOLERANCE: f64 = 1e-8;

/// Options of a load path or a fretting run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CycleOptions {
    /// The method (default [`CycleMethod::LcpHistory`]).
    pub method: CycleMethod,
    /// Panels per half-width n (2n on the contact), 8 ..= 2000; default 100. Cost grows like
    /// n^3 (one dense LU of order 2n + 1 per Newton step).
    pub panels: usize,
    /// Load steps per quarter cycle (the first loading 0 -> Q* has this many, each half
    /// cycle twice as many; [`LoadPath::load`] this many per call), 2 ..= 10000; default 10.
    pub steps: usize,
    /// Cycles at most, 1 ..= 1000; default 10. Every step's state is kept (p, q, zones: about
    /// 0.15 MB per cycle at the defaults, growing like panels x steps).
    pub max_cycles: usize,
    /// A cycle repeats when its end state differs from its start state by at most this:
    /// int |q_end - q_start| dx (units of P) and |U_end - U_start| (units of P/E). A repeating
    /// cycle dissipating at most this (units of P^2/E) is shakedown, else a steady slip
    /// cycle. Finite, > 0; default 1e-8.
    pub repeat_tolerance: f64,
}

impl Default for CycleOptions {
    fn default() -> Self {
        Self {
            method: CycleMethod::LcpHistory,
            panels: DEFAULT_PANELS,
            steps: DEFAULT_STEPS,
            max_cycles: DEFAULT_MAX_CYCLES,
            repeat_tolerance: DEFAULT_REPEAT_TOLERANCE,
        }
    }
}

impl CycleOptions {
    /// Checks the ranges documented on the fields.
    pub fn validate(&self) -> Result<()> {
        let bad = |what: String| Err(Error::InvalidArgument(what));
        if !(8..=2000).contains(&self.panels) {
            return bad(format!(
                "panels per half-width = {} must be in 8 ..= 2000",
                self.panels
            ));
        }
        if !(2..=10000).contains(&self.steps) {
            return bad(format!(
                "load steps per quarter cycle = {} must be in 2 ..= 10000",
                self.steps
            ));
        }
        if !(1..=1000).contains(&self.max_cycles) {
            return bad(format!(
                "cycle limit = {} must be in 1 ..= 1000",
                self.max_cycles
            ));
        }
        let t = self.repeat_tolerance;
        if !(t.is_finite() && t > 0.0) {
            return bad(format!("repeat tolerance = {t} must be finite and > 0"));
        }
        Ok(())
    }
}

/// A value and the estimate of its error (absolute, same units; +infinity when a check run
/// failed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// The estimate of |value - exact|.
    pub error: f64,
}

/// How a fretting run ended; the discriminants are the C ABI's `orthoslip_cycle_state`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CycleState {
    /// The last cycle repeats its start state and dissipates nothing (to the repeat
    /// tolerance): every later cycle is elastic.
    Shakedown = 0,
    /// The last cycle repeats its start state and dissipates energy: every later cycle is
    /// the same.
    SteadySlip = 1,
    /// No cycle up to the limit repeated its start state.
    CycleLimitReached = 2,
}

/// One state on the load path.
#[derive(Clone, Debug)]
pub struct PathPoint {
    /// Q / P.
    pub q_over_p: f64,
    /// The stick set [c1, c2] (the largest run of sticking panels over the step that reached
    /// this state, ends interpolated, +-1 at a punch edge; NaN when nothing sticks).
    pub stick: (f64, f64),
    /// The punch's tangential displacement U (units of P/E, in a fixed gauge: differences
    /// along the path are meaningful).
    pub punch: f64,
    /// Panel values of p at the nodes (units of P/a).
    pub p: Vec<f64>,
    /// Panel values of q at the nodes (units of P/a).
    pub q: Vec<f64>,
    /// What each panel did over the step that reached this state.
    pub zones: Vec<Zone>,
}

impl PathPoint {
    fn from_state(s: &State, unit: f64) -> Self {
        Self {
            q_over_p: s.q_over_p,
            stick: s.stick,
            punch: s.punch * unit,
            p: s.p.clone(),
            q: s.q.clone(),
            zones: s.zones.clone(),
        }
    }
}

/// The peak of a profile along the contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peak {
    /// The largest value (0 when the profile vanishes).
    pub value: f64,
    /// Where (a node; NaN when the profile vanishes everywhere).
    pub x: f64,
    /// Error estimate of the value. The grid: against its check runs. Exact: the largest
    /// estimate of the node values (docs/theory_tangential.md (T18d)), plus at an interior
    /// node twice the rise of the parabola through it and its neighbours; +infinity at a node next
    /// to a contact edge, towards which the profile grows without bound (tau_max follows the
    /// pressure's edge singularity, the slip amplitude stays finite).
    pub error: f64,
    /// Error estimate of the position (0 when both runs find no peak). Exact: one node
    /// spacing plus the distance to any node that could hold the peak within the estimates
    /// (the largest value lies between the peak node's neighbours where the profile is
    /// unimodal); half a node spacing at a node next to an edge (the edge itself); 0 when
    /// no node could hold a peak, 2 (anywhere) when none does but one could.
    pub x_error: f64,
}

/// One cycle Q* -> -Q* -> Q*.
#[derive(Clone, Debug)]
pub struct CycleResult {
    /// Energy dissipated in the cycle, int mu p |ds| dx summed over its steps (units of
    /// P^2/E per unit thickness; docs/theory_tangential.md (T8)).
    pub dissipation: Estimate,
    /// Half the peak-to-peak relative tangential displacement of solid and punch over the
    /// cycle, per node (units of P/E).
    pub slip_amplitude: Vec<f64>,
    /// Error estimate of the slip amplitude: the largest over the nodes. The grid: against
    /// its check runs. Exact: from the tractions' estimates of the cycle's states and of the
    /// branches' data (docs/theory_tangential.md (T18b); no load-step error at bp = 0, where
    /// each node's slip is monotone along a branch).
    pub slip_amplitude_error: f64,
    /// The loop: (Q/P, U) at the cycle's start and after each step (U in P/E).
    pub loop_points: Vec<(f64, f64)>,
    /// Error estimate of the loop's displacements, the larger at its turning points -Q* and
    /// +Q* (P/E; the intermediate points lie at different loads in the grid's check runs;
    /// exact: D's estimate from the tractions' (T18b)).
    pub loop_error: f64,
    /// Work of Q over the cycle, the loop's area by the trapezoidal rule (P^2/E).
    pub loop_work: f64,
    /// Error estimate of `loop_work` against the loop's area. Exact: the trapezoidal rule's
    /// error, computed (sum over the steps of W_mid - W, docs/theory_tangential.md (T18c)),
    /// plus the loop's D estimates.
    pub loop_work_error: f64,
    /// Work of P over the cycle, P (V_end - V_start) (P^2/E; p changes with Q when bp > 0).
    pub normal_work: f64,
    /// Change of the elastic energy (1/2)(P V + int q u) over the cycle (P^2/E; zero for a
    /// cycle that ends in its start state). Exact (bp = 0): `loop_work` less the mid-step
    /// dissipation, plus the change of the part of the energy linear in q
    /// (docs/theory_tangential.md (T18c)).
    pub energy_change: f64,
    /// loop_work + normal_work - (mid-step dissipation + energy_change), (T9) summed:
    /// rounding. NaN when bp = 0, where the operator is not symmetric: (T9) holds there for
    /// the energy of q alone, -(1/2) int q L\[q\], and the energy above adds (1/2) int q u_p
    /// with u_p = -pi B P bq S\[p0\] fixed, linear in q, which no work changes, so the residual
    /// would be its change, not rounding (docs/theory_tangential.md (T18c)).
    pub balance_residual: f64,
    /// tau_max: the largest |q| at each node over the cycle (P/a).
    pub tau_max: Vec<f64>,
    /// The largest surface sigma_xx(x, 0) at each node over the cycle (P/a, tension
    /// positive; docs/theory.md (F2)).
    pub sxx_max: Vec<f64>,
    /// Ruiz's F1 = tau_max * slip amplitude per node (P^2/(a E)).
    pub f1: Vec<f64>,
    /// Ruiz's F2 = max(sxx_max, 0) * tau_max * slip amplitude per node (P^3/(a^2 E)).
    pub f2: Vec<f64>,
    /// Peak of F1 along the contact.
    pub f1_peak: Peak,
    /// Peak of F2 along the contact.
    pub f2_peak: Peak,
    /// The stick set at Q = -Q* (middle of the cycle).
    pub stick_at_minus: (f64, f64),
    /// The stick set at Q = +Q* (end of the cycle).
    pub stick_at_plus: (f64, f64),
    /// Error estimate of the four stick-set ends (the largest).
    pub stick_error: f64,
    /// The states after each step of the cycle.
    pub path: Vec<PathPoint>,
}

/// A fretting run: normal load P, Q: 0 -> Q*, then cycles Q* -> -Q* -> Q*.
#[derive(Clone, Debug)]
pub struct Fretting {
    /// The method used.
    pub method: CycleMethod,
    /// The options used.
    pub options: CycleOptions,
    /// The amplitude Q*/P.
    pub q_amp_over_p: f64,
    /// The 2n panel midpoints on [-1, 1] where profiles are given.
    pub nodes: Vec<f64>,
    /// The panel width (units of a).
    pub h: f64,
    /// The normal-load state (Q = 0).
    pub normal_load: PathPoint,
    /// The states of the first loading 0 -> Q*.
    pub first_loading: Vec<PathPoint>,
    /// Energy dissipated in the first loading (P^2/E).
    pub first_loading_dissipation: Estimate,
    /// The cycles, in order.
    pub cycles: Vec<CycleResult>,
    /// How the run ended.
    pub state: CycleState,
}

/// sqrt(2 (1 + kappa)) / delta = pi B E: pi B P (the LCP's displacement unit) in P/E, and
/// pi B P^2 (its energy unit) in P^2/E.
fn unit(contact: &Contact) -> f64 {
    let k = contact.material().constants();
    (2.0 * (1.0 + k.kappa)).sqrt() / k.delta
}

/// Checks the amplitude or load level Q/P against the friction: finite, |Q| < mu P.
fn check_load(q_over_p: f64, mu: f64, what: &str) -> Result<()> {
    if !q_over_p.is_finite() {
        return Err(Error::InvalidArgument(format!(
            "{what} Q/P = {q_over_p} is not finite"
        )));
    }
    if mu <= 0.0 {
        return Err(Error::InvalidArgument(format!(
            "friction mu = {mu}: a tangential load needs mu > 0 (without friction any Q slides)"
        )));
    }
    if q_over_p.abs() >= mu {
        return Err(Error::InvalidArgument(format!(
            "{what} |Q/P| = {} >= mu = {mu} is gross sliding, not partial slip",
            q_over_p.abs()
        )));
    }
    Ok(())
}

/// The error estimates are this times the differences from the check runs: the observed
/// orders are 0.7-1.3 rather than 1 (docs/theory_tangential.md section 7), and at order 0.8
/// the difference from a halved run is 0.74 of the error.
const SAFETY: f64 = 2.0;

/// One grid run's raw results.
struct Run {
    h: f64,
    nodes: Vec<f64>,
    normal: State,
    first: Vec<State>,
    /// (start state, the cycle) per cycle.
    cycles: Vec<(State, history::Cycle)>,
    repeated: bool,
}

fn run(
    k: &Coupling,
    n: usize,
    steps: usize,
    q_amp: f64,
    max_cycles: usize,
    stop: Option<(f64, f64)>,
) -> Result<Run> {
    let mut hist = History::new(k, n)?;
    let h = hist.h();
    let normal = hist.state().clone();
    let first = hist.load(q_amp, steps)?;
    let mut cycles = Vec::new();
    let mut repeated = false;
    for _ in 0..max_cycles {
        let start = hist.state().clone();
        let mut states = hist.load(-q_amp, 2 * steps)?;
        states.extend(hist.load(q_amp, 2 * steps)?);
        let cycle = history::cycle_summary(k, h, &start, states);
        let end = hist.state();
        cycles.push((start.clone(), cycle));
        if let Some((tol, unit)) = stop {
            let dq: f64 = h * end
                .q
                .iter()
                .zip(&start.q)
                .map(|(a, b)| (a - b).abs())
                .sum::<f64>();
            let du = (end.punch - start.punch).abs() * unit;
            if dq <= tol && du <= tol {
                repeated = true;
                break;
            }
        }
    }
    Ok(Run {
        h,
        nodes: hist.nodes(),
        normal,
        first,
        cycles,
        repeated,
    })
}

/// The surface stress sigma_xx(x, 0) = -delta^2 p - delta sqrt(2 (1 + kappa)) H[q]
/// (docs/theory.md (F2)) from p and H[q] at a point, in the contact's material.
#[derive(Clone, Copy)]
struct SurfaceSxx {
    delta: f64,
    root: f64,
}

impl SurfaceSxx {
    fn new(contact: &Contact) -> Self {
        let c = contact.material().constants();
        Self {
            delta: c.delta,
            root: (2.0 * (1.0 + c.kappa)).sqrt(),
        }
    }

    fn at(&self, p: f64, hq: f64) -> f64 {
        -self.delta * self.delta * p - self.delta * self.root * hq
    }

    /// |d sigma_xx| per unit of |dp| and of |dH[q]| together: delta^2 + delta sqrt(2 (1 + kappa)).
    fn weight(&self) -> f64 {
        self.delta * self.delta + self.delta * self.root
    }
}

/// [`SurfaceSxx`] at the midpoints of piecewise-constant p, q on 2n panels:
/// H[q](x_i) = (1/pi) sum_j q_j ln|(x_i - a_j) / (x_i - b_j)| over the panels [a_j, b_j]
/// (exact for piecewise-constant q; the panel's own term vanishes at its midpoint).
struct SurfaceStress {
    m: usize,
    hilbert: Vec<f64>,
    sxx: SurfaceSxx,
}

impl SurfaceStress {
    fn new(contact: &Contact, nodes: &[f64], h: f64) -> Self {
        let m = nodes.len();
        let mut hilbert = vec![0.0; m * m];
        for (i, &x) in nodes.iter().enumerate() {
            for j in 0..m {
                if i != j {
                    let a = -1.0 + j as f64 * h;
                    hilbert[i * m + j] = ((x - a) / (x - a - h)).abs().ln() / PI;
                }
            }
        }
        Self {
            m,
            hilbert,
            sxx: SurfaceSxx::new(contact),
        }
    }

    fn sxx(&self, p: &[f64], q: &[f64]) -> Vec<f64> {
        (0..self.m)
            .map(|i| {
                let row = &self.hilbert[i * self.m..(i + 1) * self.m];
                let hq: f64 = row.iter().zip(q).map(|(a, b)| a * b).sum();
                self.sxx.at(p[i], hq)
            })
            .collect()
    }
}

/// A cycle's results on one grid, before the error estimates.
struct Raw {
    dissipation: f64,
    slip_amplitude: Vec<f64>,
    tau_max: Vec<f64>,
    sxx_max: Vec<f64>,
    f1: Vec<f64>,
    f2: Vec<f64>,
    f1_peak: (f64, f64),
    f2_peak: (f64, f64),
    stick_at_minus: (f64, f64),
    stick_at_plus: (f64, f64),
    /// U at -Q* and +Q* (P/E), and the loop's area (P^2/E).
    turning: [f64; 2],
    loop_work: f64,
}

fn peak(v: &[f64], nodes: &[f64]) -> (f64, f64) {
    let mut best = (0.0, f64::NAN);
    for (x, &f) in nodes.iter().zip(v) {
        if f > best.0 {
            best = (f, *x);
        }
    }
    best
}

fn raw(
    start: &State,
    c: &history::Cycle,
    steps: usize,
    nodes: &[f64],
    stress: &SurfaceStress,
    unit: f64,
) -> Raw {
    let m = nodes.len();
    let mut tau_max: Vec<f64> = start.q.iter().map(|q| q.abs()).collect();
    let mut sxx_max = stress.sxx(&start.p, &start.q);
    for s in &c.states {
        let sxx = stress.sxx(&s.p, &s.q);
        for i in 0..m {
            tau_max[i] = tau_max[i].max(s.q[i].abs());
            sxx_max[i] = sxx_max[i].max(sxx[i]);
        }
    }
    // A node that stuck at every step keeps its relative displacement (T4): its amplitude is
    // zero, not the rounding of e - D.
    let slip_amplitude: Vec<f64> = (0..m)
        .map(|i| {
            let slipped = c.states.iter().any(|s| s.zones[i] != Zone::Stick);
            if slipped {
                c.slip_amplitude[i] * unit
            } else {
                0.0
            }
        })
        .collect();
    let f1: Vec<f64> = (0..m).map(|i| tau_max[i] * slip_amplitude[i]).collect();
    let f2: Vec<f64> = (0..m).map(|i| sxx_max[i].max(0.0) * f1[i]).collect();
    let at = |i: usize| c.states.get(i).map_or((f64::NAN, f64::NAN), |s| s.stick);
    Raw {
        dissipation: c.dissipation * unit,
        f1_peak: peak(&f1, nodes),
        f2_peak: peak(&f2, nodes),
        slip_amplitude,
        tau_max,
        sxx_max,
        f1,
        f2,
        stick_at_minus: at(2 * steps - 1),
        stick_at_plus: at(4 * steps - 1),
        turning: [2 * steps - 1, 4 * steps - 1]
            .map(|i| c.states.get(i).map_or(f64::NAN, |s| s.punch * unit)),
        loop_work: c.loop_work * unit,
    }
}

/// |a - b|, with NaN against NaN as 0 (both runs agree there is nothing) and NaN against a
/// number as +infinity.
fn gap(a: f64, b: f64) -> f64 {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => 0.0,
        (false, false) => (a - b).abs(),
        _ => f64::INFINITY,
    }
}

/// The largest gap between node values of a fine profile and a check run's profile, read at
/// the fine nodes (piecewise constant: the check run's panel containing each fine node).
fn profile_gap(fine: &[f64], nodes: &[f64], check: &[f64]) -> f64 {
    fine.iter()
        .zip(nodes)
        .map(|(f, &x)| gap(*f, check[panel_index(check.len(), x)]))
        .fold(0.0, f64::max)
}

/// A check run's results per cycle (a failed check run is None: its estimates are infinite).
struct Check {
    raws: Vec<Raw>,
    first: f64,
}

impl Fretting {
    /// Normal load P, then Q/P: 0 -> `q_amp_over_p` in `options.steps` steps, then cycles
    /// `q_amp_over_p` -> -`q_amp_over_p` -> `q_amp_over_p` (2 `options.steps` steps each half)
    /// until the state repeats or `options.max_cycles` cycles are done.
    ///
    /// Errors: `InvalidArgument` for options out of range, a contact with mu = 0, an
    /// amplitude that is not finite, <= 0, or >= mu (gross sliding), and for
    /// [`CycleMethod::Exact`] the exact path's status where it refuses a load of the cycle
    /// (bp > 0: the corner structure, not built; the message names the cycle, the step and
    /// what is missing);
    /// `NoAdmissibleSolution`
    /// when the pressure turns negative somewhere on the path (strong coupling at large
    /// amplitudes: the punch would lift off, which this model does not describe);
    /// `NoConvergence` when a load step's Newton iteration fails.
    pub fn solve(contact: &Contact, q_amp_over_p: f64, options: &CycleOptions) -> Result<Self> {
        options.validate()?;
        let k = contact.coupling();
        check_load(q_amp_over_p, k.mu, "amplitude")?;
        if q_amp_over_p <= 0.0 {
            return Err(Error::InvalidArgument(format!(
                "amplitude Q*/P = {q_amp_over_p} must be > 0 (the cycle runs +Q* -> -Q* -> +Q*)"
            )));
        }
        if options.method == CycleMethod::Exact {
            return exact_run::solve(contact, &k, q_amp_over_p, options);
        }
        let unit = unit(contact);
        let (n, s) = (options.panels, options.steps);
        let tol = options.repeat_tolerance;
        let fine = run(
            &k,
            n,
            s,
            q_amp_over_p,
            options.max_cycles,
            Some((tol, unit)),
        )?;
        let count = fine.cycles.len();
        let stress = SurfaceStress::new(contact, &fine.nodes, fine.h);
        let raws: Vec<Raw> = fine
            .cycles
            .iter()
            .map(|(st, c)| raw(st, c, s, &fine.nodes, &stress, unit))
            .collect();
        let first_w = fine.first.iter().map(|st| st.dissipation).sum::<f64>() * unit;
        // The check runs: half the panels, half the steps (each for the same cycles).
        let checks: Vec<Option<Check>> = [(n / 2, s), (n, s / 2)]
            .into_iter()
            .map(|(nc, sc)| {
                let r = run(&k, nc, sc, q_amp_over_p, count, None).ok()?;
                let stress = SurfaceStress::new(contact, &r.nodes, r.h);
                Some(Check {
                    raws: r
                        .cycles
                        .iter()
                        .map(|(st, c)| raw(st, c, sc, &r.nodes, &stress, unit))
                        .collect(),
                    first: r.first.iter().map(|st| st.dissipation).sum::<f64>() * unit,
                })
            })
            .collect();
        let err = |f: &dyn Fn(&Check) -> f64| -> f64 {
            SAFETY
                * checks
                    .iter()
                    .map(|c| c.as_ref().map_or(f64::INFINITY, f))
                    .sum::<f64>()
        };
        let first_loading_dissipation = Estimate {
            value: first_w,
            error: err(&|c| gap(first_w, c.first)),
        };
        let cycles: Vec<CycleResult> = raws
            .into_iter()
            .zip(&fine.cycles)
            .enumerate()
            .map(|(i, (r, (_, c)))| {
                let d = r.dissipation;
                let dissipation = Estimate {
                    value: d,
                    error: err(&|ch| gap(d, ch.raws[i].dissipation)),
                };
                let slip_amplitude_error = err(&|ch| {
                    profile_gap(&r.slip_amplitude, &fine.nodes, &ch.raws[i].slip_amplitude)
                });
                let peak_of = |pk: (f64, f64), which: fn(&Raw) -> (f64, f64)| Peak {
                    value: pk.0,
                    x: pk.1,
                    error: err(&|ch| gap(pk.0, which(&ch.raws[i]).0)),
                    x_error: err(&|ch| gap(pk.1, which(&ch.raws[i]).1)),
                };
                let stick_error = err(&|ch| {
                    let o = &ch.raws[i];
                    [
                        gap(r.stick_at_minus.0, o.stick_at_minus.0),
                        gap(r.stick_at_minus.1, o.stick_at_minus.1),
                        gap(r.stick_at_plus.0, o.stick_at_plus.0),
                        gap(r.stick_at_plus.1, o.stick_at_plus.1),
                    ]
                    .into_iter()
                    .fold(0.0, f64::max)
                });
                let loop_error = err(&|ch| {
                    let o = &ch.raws[i];
                    gap(r.turning[0], o.turning[0]).max(gap(r.turning[1], o.turning[1]))
                });
                let loop_work_error = err(&|ch| gap(r.loop_work, ch.raws[i].loop_work));
                CycleResult {
                    dissipation,
                    loop_error,
                    loop_work_error,
                    slip_amplitude_error,
                    f1_peak: peak_of(r.f1_peak, |o| o.f1_peak),
                    f2_peak: peak_of(r.f2_peak, |o| o.f2_peak),
                    stick_error,
                    slip_amplitude: r.slip_amplitude,
                    loop_points: c.loop_points.iter().map(|&(q, u)| (q, u * unit)).collect(),
                    loop_work: c.loop_work * unit,
                    normal_work: c.normal_work * unit,
                    energy_change: c.energy_change * unit,
                    balance_residual: c.balance_residual * unit,
                    tau_max: r.tau_max,
                    sxx_max: r.sxx_max,
                    f1: r.f1,
                    f2: r.f2,
                    stick_at_minus: r.stick_at_minus,
                    stick_at_plus: r.stick_at_plus,
                    path: c
                        .states
                        .iter()
                        .map(|st| PathPoint::from_state(st, unit))
                        .collect(),
                }
            })
            .collect();
        let state = match (fine.repeated, cycles.last()) {
            (true, Some(c)) if c.dissipation.value <= tol => CycleState::Shakedown,
            (true, _) => CycleState::SteadySlip,
            (false, _) => CycleState::CycleLimitReached,
        };
        Ok(Self {
            method: options.method,
            options: *options,
            q_amp_over_p,
            h: fine.h,
            normal_load: PathPoint::from_state(&fine.normal, unit),
            first_loading: fine
                .first
                .iter()
                .map(|st| PathPoint::from_state(st, unit))
                .collect(),
            first_loading_dissipation,
            nodes: fine.nodes,
            cycles,
            state,
        })
    }

    /// Whether the last cycle repeats its start state (shakedown or a steady slip cycle).
    pub fn steady(&self) -> bool {
        self.state != CycleState::CycleLimitReached
    }

    /// The value at x (in [-1, 1], units of a) of a profile given at the nodes: the value of
    /// the panel containing x (x = +-1 belong to the end panels; a panel boundary to the
    /// panel on its right).
    ///
    /// Errors: `InvalidArgument` for x NaN or outside [-1, 1].
    pub fn at(&self, profile: &[f64], x: f64) -> Result<f64> {
        panel_value(profile, x)
    }
}

/// The panel value at x of a profile on 2n uniform panels of [-1, 1].
pub(crate) fn panel_value(profile: &[f64], x: f64) -> Result<f64> {
    if !(-1.0..=1.0).contains(&x) {
        return Err(Error::InvalidArgument(format!(
            "x = {x} is not on the contact [-1, 1]"
        )));
    }
    Ok(profile[panel_index(profile.len(), x)])
}

/// The panel of m uniform panels on [-1, 1] that contains x in [-1, 1] (x = 1: the last).
fn panel_index(m: usize, x: f64) -> usize {
    (((x + 1.0) * m as f64 / 2.0).floor() as usize).min(m - 1)
}

/// A load path an FE code scripts: the normal load P, then Q moved monotonically to one value
/// after another ([`LoadPath::load`]).
///
/// - [`CycleMethod::LcpHistory`]: the grid, with a second grid of half the panels alongside
///   for the error estimates (first order: their difference estimates the error).
/// - [`CycleMethod::Exact`]: the exact solvers (docs/theory_tangential.md sections 10-15),
///   to the contact's tolerances ([`Contact::tolerance`] on the stick set's ends,
///   [`Contact::traction_tolerance`] on the tractions in the norm (T1)): the normal load,
///   monotonic loading from Q = 0 (either sign), and after each reversal of the load
///   direction the branch from the state where it reversed, where that branch keeps one
///   stick set with a slip zone at each end. A load the exact solvers do not answer is
///   refused with the solver's status and a message that says so (the corner structure of
///   the ply's unloading above about -0.48 Q* and of its reloading is not built); the grid
///   answers every path, and is never used in its place.
pub struct LoadPath {
    material: Material,
    unit: f64,
    engine: Engine,
}

enum Engine {
    Grid(Box<Grid>),
    Exact(exact::path::ExactPath),
}

struct Grid {
    fine: History,
    coarse: Option<History>,
    steps: usize,
    dissipated: f64,
    dissipated_coarse: f64,
}

impl LoadPath {
    /// The normal-load state (Q = 0) of `contact` (its material and friction; with
    /// [`CycleMethod::Exact`] its tolerances too). With [`CycleMethod::LcpHistory`] on
    /// `options.panels` panels per half-width, each [`LoadPath::load`] taking `options.steps`
    /// steps; [`CycleMethod::Exact`] uses neither.
    ///
    /// Errors: `InvalidArgument` for options out of range or mu = 0 (no tangential load can be
    /// carried; the normal load alone is [`Contact::solve`]); `NoConvergence`.
    pub fn new(contact: &Contact, options: &CycleOptions) -> Result<Self> {
        options.validate()?;
        let k = contact.coupling();
        check_load(0.0, k.mu, "load")?;
        let engine = match options.method {
            CycleMethod::LcpHistory => {
                let fine = History::new(&k, options.panels)?;
                let coarse = History::new(&k, options.panels / 2).ok();
                Engine::Grid(Box::new(Grid {
                    fine,
                    coarse,
                    steps: options.steps,
                    dissipated: 0.0,
                    dissipated_coarse: 0.0,
                }))
            }
            CycleMethod::Exact => Engine::Exact(exact::path::ExactPath::new(
                &k,
                contact.tolerance(),
                contact.traction_tolerance(),
            )?),
        };
        Ok(Self {
            material: *contact.material(),
            unit: unit(contact),
            engine,
        })
    }

    /// The method.
    pub fn method(&self) -> CycleMethod {
        match self.engine {
            Engine::Grid(_) => CycleMethod::LcpHistory,
            Engine::Exact(_) => CycleMethod::Exact,
        }
    }

    fn coupling(&self) -> Coupling {
        match &self.engine {
            Engine::Grid(g) => g.fine.coupling(),
            Engine::Exact(e) => e.k,
        }
    }

    /// Moves Q/P monotonically from its current value to `q_over_p`.
    ///
    /// Errors: `InvalidArgument` for q_over_p not finite or |q_over_p| >= mu (gross
    /// sliding); `NoAdmissibleSolution` (the grid: p < 0 somewhere, lift-off) or
    /// `NoConvergence`. With [`CycleMethod::Exact`], a load the exact solvers do not answer
    /// gives their status (`NoConvergence`, `NoAdmissibleSolution`, `InvalidArgument`, or
    /// `ToleranceNotMet`) with a message naming the step, the solver's reason and what the
    /// exact path covers. On any error the path is unchanged.
    pub fn load(&mut self, q_over_p: f64) -> Result<()> {
        check_load(q_over_p, self.coupling().mu, "load")?;
        match &mut self.engine {
            Engine::Grid(g) => {
                let states = g.fine.load(q_over_p, g.steps)?;
                g.dissipated += states.iter().map(|s| s.dissipation).sum::<f64>();
                if let Some(c) = g.coarse.as_mut() {
                    match c.load(q_over_p, g.steps) {
                        Ok(st) => {
                            g.dissipated_coarse += st.iter().map(|s| s.dissipation).sum::<f64>()
                        }
                        Err(_) => g.coarse = None,
                    }
                }
                Ok(())
            }
            Engine::Exact(e) => e.load(q_over_p),
        }
    }

    /// The current state. With [`CycleMethod::Exact`] there is no grid: `p`, `q` and `zones`
    /// are empty (the state at any x is [`LoadPath::tractions_at`]); the punch displacement
    /// is the rigid displacement of the exact stick set (docs/theory_tangential.md (T16)), in
    /// the grid's gauge.
    pub fn point(&self) -> PathPoint {
        match &self.engine {
            Engine::Grid(g) => PathPoint::from_state(g.fine.state(), self.unit),
            Engine::Exact(e) => PathPoint {
                q_over_p: e.q_over_p(),
                stick: e.stick_set(),
                punch: e.punch * self.unit,
                p: Vec::new(),
                q: Vec::new(),
                zones: Vec::new(),
            },
        }
    }

    /// The current Q/P.
    pub fn q_over_p(&self) -> f64 {
        match &self.engine {
            Engine::Grid(g) => g.fine.state().q_over_p,
            Engine::Exact(e) => e.q_over_p(),
        }
    }

    /// The 2n panel midpoints (none with [`CycleMethod::Exact`]).
    pub fn nodes(&self) -> Vec<f64> {
        match &self.engine {
            Engine::Grid(g) => g.fine.nodes(),
            Engine::Exact(_) => Vec::new(),
        }
    }

    /// Panel width (units of a; NaN with [`CycleMethod::Exact`]).
    pub fn h(&self) -> f64 {
        match &self.engine {
            Engine::Grid(g) => g.fine.h(),
            Engine::Exact(_) => f64::NAN,
        }
    }

    /// The stick set [c1, c2] and the estimate of its ends' error. The grid: the stick set of
    /// the step that reached the current state, the error the larger end's against the
    /// half-panel grid. Exact: the stick set since the current branch's start (since the
    /// normal load while loading), the estimate bounds |dc1| + |dc2|.
    pub fn stick_zone(&self) -> ((f64, f64), f64) {
        match &self.engine {
            Engine::Grid(g) => {
                let (c1, c2) = g.fine.state().stick;
                let err = g.coarse.as_ref().map_or(f64::INFINITY, |c| {
                    let (d1, d2) = c.state().stick;
                    SAFETY * gap(c1, d1).max(gap(c2, d2))
                });
                ((c1, c2), err)
            }
            Engine::Exact(e) => (e.stick_set(), e.estimates().0),
        }
    }

    /// The traction error estimate int (|dp| + |dq|) dx (units of P): the grid's against the
    /// half-panel grid, read at the fine panels; the exact solvers' from their ladder of
    /// levels (plus the estimate of the state the branch started from).
    pub fn traction_error(&self) -> f64 {
        let g = match &self.engine {
            Engine::Grid(g) => g,
            Engine::Exact(e) => return e.estimates().1,
        };
        let Some(c) = g.coarse.as_ref() else {
            return f64::INFINITY;
        };
        let (f, s) = (g.fine.state(), c.state());
        let h = g.fine.h();
        SAFETY
            * (0..f.p.len())
                .zip(g.fine.nodes())
                .map(|(i, x)| {
                    let j = panel_index(s.p.len(), x);
                    h * ((f.p[i] - s.p[j]).abs() + (f.q[i] - s.q[j]).abs())
                })
                .sum::<f64>()
    }

    /// Energy dissipated since the normal load (P^2/E), with an estimate of its error. The grid:
    /// backward Euler over its steps (first order in the load step), the estimate its grid
    /// error against the half-panel grid. [`CycleMethod::Exact`]: (T8) with the mean pressure
    /// over each load step the path took (docs/theory_tangential.md (T17): exact at bp = 0,
    /// second order in the step for bp > 0), the estimate the tractions' part. Neither
    /// estimate includes the load-step error: a path's steps are the caller's choice.
    pub fn dissipated(&self) -> Result<Estimate> {
        match &self.engine {
            Engine::Grid(g) => Ok(Estimate {
                value: g.dissipated * self.unit,
                error: if g.coarse.is_some() {
                    SAFETY * (g.dissipated - g.dissipated_coarse).abs() * self.unit
                } else {
                    f64::INFINITY
                },
            }),
            Engine::Exact(e) => Ok(Estimate {
                value: e.dissipated * self.unit,
                error: e.dissipated_error * self.unit,
            }),
        }
    }

    /// The moment int x p dx the non-rotating punch carries (units of P a).
    pub fn moment(&self) -> f64 {
        match &self.engine {
            Engine::Grid(g) => g.fine.moment(),
            Engine::Exact(e) => e.moment(),
        }
    }

    /// The panel value at x in [-1, 1] of a profile at the nodes (see [`Fretting::at`]).
    pub fn at(&self, profile: &[f64], x: f64) -> Result<f64> {
        panel_value(profile, x)
    }

    /// (p, q) and the zone at x in [-1, 1] of the current state: the grid's panel values and
    /// the zone of the step that reached the state; the exact tractions (p = +infinity at
    /// x = +-1, q infinite of its sign there) and the zone since the current branch's start
    /// (stick on [c1, c2]; a slip zone's direction from q = -+ mu p there).
    ///
    /// Errors: `InvalidArgument` for x NaN or outside [-1, 1].
    pub fn tractions_at(&self, x: f64) -> Result<(f64, f64, Zone)> {
        match &self.engine {
            Engine::Grid(g) => {
                let s = g.fine.state();
                let i = {
                    panel_value(&s.p, x)?;
                    panel_index(s.p.len(), x)
                };
                Ok((s.p[i], s.q[i], s.zones[i]))
            }
            Engine::Exact(e) => {
                if !(-1.0..=1.0).contains(&x) {
                    return Err(Error::InvalidArgument(format!(
                        "x = {x} is not on the contact [-1, 1]"
                    )));
                }
                let profile = exact::path::ExactProfile { path: e.clone() };
                let (p, q) = profile.tractions(x);
                let (c1, c2) = e.stick_set();
                let zone = if (x >= c1 && x <= c2) || e.in_stuck_layer(1.0 + x, 1.0 - x) {
                    Zone::Stick
                } else if q < 0.0 {
                    Zone::SlipPositive
                } else {
                    Zone::SlipNegative
                };
                Ok((p, q, zone))
            }
        }
    }

    /// The current state as a [`Solution`], without symmetry ([`Solution::is_symmetric`] is
    /// false: no single stick half-width, edge intensity or slip function), with the stick
    /// set [c1, c2] ([`Solution::stick_set`]) and [`LoadPath::stick_zone`]'s estimate as
    /// [`Solution::error_estimate`], [`LoadPath::traction_error`] as
    /// [`Solution::traction_error_estimate`], and the stresses of the field of its tractions.
    /// - The grid (method [`Method::Lcp`]): its tractions on [-1, 1] as the normal-load LCP
    ///   solution presents its grid (`StateProfile`); at Q = 0 its tractions and stresses
    ///   are those of the normal-load LCP solution on the same grid (to rounding).
    /// - Exact (method [`Method::Coupled`], the same bases): the exact tractions at any x; the
    ///   field from them fitted on panels graded towards every zone end.
    pub fn solution(&self) -> Solution {
        let ((c1, c2), stick_error) = self.stick_zone();
        let traction_error = self.traction_error();
        match &self.engine {
            Engine::Grid(g) => {
                let s = g.fine.state();
                let profile = StateProfile::new(g.fine.coupling(), &s.p, &s.q, stick_error);
                Solution::asymmetric(
                    Method::Lcp,
                    profile,
                    (c1, c2),
                    stick_error,
                    traction_error,
                    self.material,
                )
            }
            Engine::Exact(e) => Solution::asymmetric(
                Method::Coupled,
                exact::path::ExactProfile { path: e.clone() },
                (c1, c2),
                stick_error,
                traction_error,
                self.material,
            ),
        }
    }
}

/// A load-path state's panel values on [-1, 1] presented as the normal-load LCP presents its
/// grid (`crate::lcp`'s `half_line_tractions`, over the whole line): the regular parts
/// p / w, q / w, with w = (1 - |x|)^(-g) and g the normal-load edge exponent
/// ([`Coupling::edge_exponent`]; each panel value divided by the panel average of w), taken
/// linearly between the panel midpoints and constant beyond the outermost ones. The grid's
/// values are first order; under load the edges' own exponents (which differ at the two
/// edges) are not resolved by it, and w serves as the shape of the end panels only.
#[derive(Clone, Debug)]
pub(crate) struct StateProfile {
    coupling: Coupling,
    /// Panels per half-width.
    n: usize,
    /// The midpoints, in the normal-load grid's form +-(j + 1/2) h (mirror images exactly).
    nodes: Vec<f64>,
    /// Regular parts of p and q at the midpoints.
    rp: Vec<f64>,
    rq: Vec<f64>,
    stick_error: f64,
}

impl StateProfile {
    fn new(coupling: Coupling, p: &[f64], q: &[f64], stick_error: f64) -> Self {
        let m = p.len();
        let n = m / 2;
        let h = 1.0 / n as f64;
        let g = coupling.edge_exponent();
        // distance index from the centre: panel i covers [j h, (j + 1) h] on its side
        let side = |i: usize| if i >= n { i - n } else { n - 1 - i };
        let average = |i: usize| {
            let j = side(i);
            let (a, b) = (j as f64 * h, (j + 1) as f64 * h);
            ((1.0 - a).powf(1.0 - g) - (1.0 - b).powf(1.0 - g)) / ((1.0 - g) * h)
        };
        let nodes = (0..m)
            .map(|i| {
                let x = (side(i) as f64 + 0.5) * h;
                if i >= n { x } else { -x }
            })
            .collect();
        Self {
            coupling,
            n,
            nodes,
            rp: (0..m).map(|i| p[i] / average(i)).collect(),
            rq: (0..m).map(|i| q[i] / average(i)).collect(),
            stick_error,
        }
    }

    /// The regular parts (p / w, q / w) at x in [-1, 1].
    fn regular(&self, x: f64) -> (f64, f64) {
        let m = self.nodes.len();
        if x <= self.nodes[0] {
            return (self.rp[0], self.rq[0]);
        }
        if x >= self.nodes[m - 1] {
            return (self.rp[m - 1], self.rq[m - 1]);
        }
        // the midpoint at or left of x: by distance from the centre, as the normal-load grid
        let h = 1.0 / self.n as f64;
        let u = x.abs() / h - 0.5;
        let (j, theta) = if x >= self.nodes[self.n] {
            let j = (u.floor().max(0.0) as usize).min(self.n - 2);
            (self.n + j, (u - j as f64).clamp(0.0, 1.0))
        } else if x <= self.nodes[self.n - 1] {
            // mirrored: between n - 2 - k and n - 1 - k with k = floor(u)
            let k = (u.floor().max(0.0) as usize).min(self.n - 2);
            (self.n - 2 - k, 1.0 - (u - k as f64).clamp(0.0, 1.0))
        } else {
            // across the centre, between the two innermost midpoints
            let (a, b) = (self.nodes[self.n - 1], self.nodes[self.n]);
            (self.n - 1, ((x - a) / (b - a)).clamp(0.0, 1.0))
        };
        let lerp = |v: &[f64]| (1.0 - theta) * v[j] + theta * v[j + 1];
        (lerp(&self.rp), lerp(&self.rq))
    }
}

impl Profile for StateProfile {
    fn coupling(&self) -> Coupling {
        self.coupling
    }
    /// No single stick half-width: NaN (the stick set is the solution's).
    fn edge(&self) -> StickEdge {
        StickEdge {
            c: f64::NAN,
            one_minus_c: f64::NAN,
        }
    }
    fn numerical_error(&self) -> f64 {
        self.stick_error
    }
    fn traction_error(&self) -> f64 {
        f64::INFINITY
    }
    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        self.tractions(x)
    }
    /// (p, q) at any x (not NaN): zero outside the punch, p = +infinity at x = +-1 with q
    /// infinite of the sign of the end panel's q (0 where that is 0).
    fn tractions(&self, x: f64) -> (f64, f64) {
        let ax = x.abs();
        if ax > 1.0 {
            return (0.0, 0.0);
        }
        let (rp, rq) = self.regular(x);
        if ax == 1.0 {
            return (f64::INFINITY, crate::problem::edge_infinity(rq));
        }
        let t = ax.min(1.0 - f64::EPSILON);
        let w = (1.0 - t).powf(-self.coupling.edge_exponent());
        (w * rp, w * rq)
    }
}

/// Panels between the midpoints (split at 0, where w has its kink), fitted in Legendre
/// series; the end panels [-1, x_0] and [x_(2n-1), 1] one family each, weighted
/// (1 + t)^(-g) and (1 - t)^(-g) (as the normal-load LCP's last panel).
impl Expand for StateProfile {
    fn expansion(&self) -> Expansion {
        let m = self.nodes.len();
        let mut breaks = vec![-1.0];
        breaks.extend_from_slice(&self.nodes[..self.n]);
        breaks.push(0.0);
        breaks.extend_from_slice(&self.nodes[self.n..]);
        breaks.push(1.0);
        let g = self.coupling.edge_exponent();
        grid_expansion(
            &breaks,
            |x| self.tractions(x),
            |a, b| {
                let end = |i: usize, weight: Weight| {
                    let scale = (0.5 * (b - a)).powf(-g);
                    Family {
                        weight,
                        p: vec![scale * self.rp[i]],
                        q: vec![scale * self.rq[i]],
                    }
                };
                if a == -1.0 {
                    Some(end(0, Weight::Left(-g)))
                } else if b == 1.0 {
                    Some(end(m - 1, Weight::Right(-g)))
                } else {
                    None
                }
            },
        )
    }

    /// The two edges differ: none.
    fn edge_intensity(&self, _: &Expansion) -> Option<(f64, f64)> {
        None
    }
}

#[cfg(test)]
mod tests;
