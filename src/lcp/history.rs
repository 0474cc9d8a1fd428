//! The paper's grid LCP with a loading history (issue 27; docs/theory_tangential.md): the
//! normal load P, then a tangential load Q moved in steps and cycled (fretting).
//!
//! The whole contact [-1, 1] on 2n uniform panels (no symmetry: q is no longer odd),
//! piecewise-constant p and q. Each load step is one complementarity problem whose data is
//! the previous state (docs/theory_tangential.md (T1)-(T7)):
//! - (E1) for the totals, with the force balance: p = p_bar + bp K q (`FullLine`);
//! - the surface's tangential displacement e = -(bq S p + L q) (units of pi B P; u = pi B P e
//!   up to a constant) and the punch's rigid displacement D; the slip increment of node i is
//!   ds_i = (e_i - e_i^prev) - (D - D^prev);
//! - per node, q_i in [-mu p_i, mu p_i] with q_i = -mu p_i sgn(ds_i) where ds_i != 0 (the
//!   friction on the solid opposes its slip relative to the punch), a box complementarity
//!   problem (`smoothing_newton::solve_box`);
//! - the unknown increment D - D^prev fixed by h sum q = Q/P.
//!
//! No slip pattern is assumed: every node may stick or slip either way at every step. The
//! punch does not rotate (E1 holds with a zero normal displacement gradient), so it carries
//! the moment int x p dx (units of P a).
//!
//! Energies are in units of pi B P^2 per unit thickness (times pi B E = sqrt(2 (1 + kappa)) /
//! delta for units of P^2 / E); displacements in units of pi B P.
//!
//! Accuracy: first order in h = 1/n for the stick-set ends (the normal-load LCP's rule); the
//! dissipation sums mu p |ds| with p at the end of each step, first order in the load step.
//! Cost: the operators once (dense, order 2n), then one dense LU of order 2n + 1 per Newton
//! step, 3-20 Newton steps per load step (measured, one core: n = 200, five cycles of 40
//! steps, 3 s; n = 800, one cycle of 20 steps, 45 s).

use super::discretisation::{FullLine, Grid};
use super::smoothing_newton::{self, BoxMcp, BoxRoot, Controls};
use super::stick_edge;
use super::{COMPLEMENTARITY_TOL, MAX_NEWTON, WARM_SMOOTHING};
use crate::error::{Error, Result};
use crate::problem::Coupling;
use faer::Mat;

/// Slip increments up to this (units of pi B P) are rounding, not slip: ten times the
/// complementarity tolerance the step is solved to.
const SLIP_FLOOR: f64 = 10.0 * COMPLEMENTARITY_TOL;

/// What a node did over the step that reached a state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Zone {
    /// No slip increment; |q| <= mu p.
    Stick,
    /// The solid slipped in +x relative to the punch; q = -mu p.
    SlipPositive,
    /// The solid slipped in -x relative to the punch; q = +mu p.
    SlipNegative,
}

/// One state on the load path: the totals after a load step, and what the step did.
#[derive(Clone, Debug)]
pub struct State {
    /// Q / P.
    pub q_over_p: f64,
    /// Panel values of p on the 2n panels of [-1, 1] (units of P / a).
    pub p: Vec<f64>,
    /// Panel values of q (units of P / a).
    pub q: Vec<f64>,
    /// Tangential displacement of the solid's surface at the midpoints (units of pi B P,
    /// gauge: the symmetric Green's function; relative displacements are gauge-free).
    pub surface: Vec<f64>,
    /// The punch's rigid tangential displacement D (same units and gauge).
    pub punch: f64,
    /// The punch's normal displacement V (into the solid, units of pi B P, up to a constant;
    /// 0 when bp = 0, where p does not change).
    pub normal: f64,
    /// Slip increment of each node over the step: ds = (e - e_prev) - (D - D_prev).
    pub slip_increment: Vec<f64>,
    /// Stick / slip (with direction) of each node over the step.
    pub zones: Vec<Zone>,
    /// The largest run of sticking nodes [c1, c2], edges interpolated as in the normal-load
    /// LCP (first order); +-1 when the run reaches a punch edge; NaN when nothing sticks.
    pub stick: (f64, f64),
    /// Energy dissipated over the step, h sum mu p |ds| over the slipping nodes (= -h sum q ds;
    /// units of pi B P^2).
    pub dissipation: f64,
    /// -h sum (q_prev + q) / 2 ds: the same with the mid-step traction (enters the exact
    /// discrete energy balance, see [`Cycle::balance_residual`]).
    pub dissipation_mid: f64,
    /// Newton iterations of the step.
    pub newton: usize,
}

impl State {
    /// int p dx (= 1).
    pub fn force(&self, h: f64) -> f64 {
        h * self.p.iter().sum::<f64>()
    }
    /// int q dx (= Q / P).
    pub fn tangential_force(&self, h: f64) -> f64 {
        h * self.q.iter().sum::<f64>()
    }
    /// Relative tangential displacement of the solid against the punch, e - D, per node.
    pub fn relative(&self) -> Vec<f64> {
        self.surface.iter().map(|e| e - self.punch).collect()
    }
    /// The moment int x p dx the non-rotating punch carries (units of P a), with h = 1 / n.
    pub fn moment(&self, h: f64) -> f64 {
        h * self
            .p
            .iter()
            .enumerate()
            .map(|(i, p)| (-1.0 + (i as f64 + 0.5) * h) * p)
            .sum::<f64>()
    }
    /// Elastic energy (1/2)(P V + int q u) up to a constant (units of pi B P^2).
    pub(crate) fn elastic_energy(&self, h: f64) -> f64 {
        let qu: f64 = self.q.iter().zip(&self.surface).map(|(q, u)| q * u).sum();
        0.5 * (self.normal + h * qu)
    }
}

/// The operators of one grid and coupling, and the box problem's constant matrices.
struct Operators {
    line: FullLine,
    /// e = e_c + E q.
    e_c: Vec<f64>,
    e: Mat<f64>,
    /// Gaps to the friction bounds as affine maps of z = (q, dD): q + mu p, mu p - q.
    gl: Mat<f64>,
    gu: Mat<f64>,
    /// F = ds (rows < 2n) and h sum q (row 2n) as affine maps of z (constant part per step).
    f: Mat<f64>,
}

impl Operators {
    fn new(k: &Coupling, n: usize) -> Result<Self> {
        let line = FullLine::new(n)?;
        let m = 2 * n;
        let h = line.h;
        let (bp, bq, mu) = (k.bp, k.bq, k.mu);
        // (S K)_ij = h/2 (sum_{l<i} K_lj - sum_{l>i} K_lj), by running sums down each column.
        let mut sk = Mat::<f64>::zeros(m, m);
        if bp > 0.0 {
            for j in 0..m {
                let total: f64 = (0..m).map(|l| line.k[(l, j)]).sum();
                let mut below = 0.0;
                for i in 0..m {
                    let kij = line.k[(i, j)];
                    sk[(i, j)] = 0.5 * h * (below - (total - below - kij));
                    below += kij;
                }
            }
        }
        let sp_bar: Vec<f64> = (0..m)
            .map(|i| (0..m).map(|j| line.s[(i, j)] * line.p_bar[j]).sum())
            .collect();
        let e_c: Vec<f64> = sp_bar.iter().map(|v| -bq * v).collect();
        let e = Mat::from_fn(m, m, |i, j| -(bq * bp * sk[(i, j)] + line.l[(i, j)]));
        let eye = |i: usize, j: usize| if i == j { 1.0 } else { 0.0 };
        let gl = Mat::from_fn(m, m + 1, |i, j| {
            if j < m {
                eye(i, j) + mu * bp * line.k[(i, j)]
            } else {
                0.0
            }
        });
        let gu = Mat::from_fn(m, m + 1, |i, j| {
            if j < m {
                mu * bp * line.k[(i, j)] - eye(i, j)
            } else {
                0.0
            }
        });
        let f = Mat::from_fn(m + 1, m + 1, |i, j| match (i < m, j < m) {
            (true, true) => e[(i, j)],
            (true, false) => -1.0,
            (false, true) => h,
            (false, false) => 0.0,
        });
        Ok(Self {
            line,
            e_c,
            e,
            gl,
            gu,
            f,
        })
    }

    fn pressure(&self, k: &Coupling, q: &[f64]) -> Vec<f64> {
        let m = q.len();
        (0..m)
            .map(|i| {
                let kq: f64 = if k.bp > 0.0 {
                    (0..m).map(|j| self.line.k[(i, j)] * q[j]).sum()
                } else {
                    0.0
                };
                self.line.p_bar[i] + k.bp * kq
            })
            .collect()
    }

    fn surface(&self, q: &[f64]) -> Vec<f64> {
        let m = q.len();
        (0..m)
            .map(|i| self.e_c[i] + (0..m).map(|j| self.e[(i, j)] * q[j]).sum::<f64>())
            .collect()
    }

    /// V = -(C / B) W up to a constant, with C / B = bq / bp and W = w_bar + bp wk . q.
    fn normal(&self, k: &Coupling, q: &[f64]) -> f64 {
        if k.bp > 0.0 {
            -k.bq * self.line.wk.iter().zip(q).map(|(a, b)| a * b).sum::<f64>()
        } else {
            0.0
        }
    }
}

/// The grid LCP's state along a load path; see the module documentation.
pub struct History {
    coupling: Coupling,
    ops: Operators,
    state: State,
    ctl: Controls,
}

/// Validates the coupling for a history: bp, bq >= 0 (bq = 0 allowed: the uncoupled
/// material of the closed form), mu > 0, b* < 1.
fn validate(k: &Coupling) -> Result<()> {
    let finite = k.bp.is_finite() && k.bq.is_finite() && k.mu.is_finite();
    if !(finite && k.bp >= 0.0 && k.bq >= 0.0 && k.mu > 0.0) || k.b_star() >= 1.0 {
        return Err(Error::InvalidArgument(format!(
            "a load history needs finite bp >= 0, bq >= 0, mu > 0 and b* < 1 \
             (bp = {}, bq = {}, mu = {})",
            k.bp, k.bq, k.mu
        )));
    }
    Ok(())
}

impl History {
    /// The normal-load state (Q = 0) on n panels per half-width (2n on the contact), n >= 4:
    /// the existing half-grid LCP's solution (mirrored; reached by continuation in mu) as
    /// the start of the whole-contact problem for the step from P = 0, whose data are zero.
    pub fn new(k: &Coupling, n: usize) -> Result<Self> {
        validate(k)?;
        if n < 4 {
            return Err(Error::InvalidArgument(format!(
                "need n >= 4 panels per half-width (got {n})"
            )));
        }
        let m = 2 * n;
        let ops = Operators::new(k, n)?;
        let q_start = if k.bq > 0.0 {
            let half = super::solve_level(k, Grid::new(n), None)?;
            let (_, qh) = half.panel_tractions();
            (0..m)
                .map(|i| if i < n { -qh[n - 1 - i] } else { qh[i - n] })
                .collect()
        } else {
            vec![0.0; m]
        };
        let zero = State {
            q_over_p: 0.0,
            p: vec![0.0; m],
            q: vec![0.0; m],
            surface: vec![0.0; m],
            punch: 0.0,
            normal: 0.0,
            slip_increment: vec![0.0; m],
            zones: vec![Zone::Stick; m],
            stick: (-1.0, 1.0),
            dissipation: 0.0,
            dissipation_mid: 0.0,
            newton: 0,
        };
        let ctl = Controls {
            eps0: WARM_SMOOTHING,
            tol: COMPLEMENTARITY_TOL,
            max_iter: MAX_NEWTON,
        };
        let mut h = Self {
            coupling: *k,
            ops,
            state: zero,
            ctl,
        };
        h.state = h.step(&h.state, 0.0, &q_start)?;
        Ok(h)
    }

    /// The current state.
    pub fn state(&self) -> &State {
        &self.state
    }
    /// Panels per half-width.
    pub fn panels(&self) -> usize {
        self.ops.line.n
    }
    /// Panel width h = 1 / n.
    pub fn h(&self) -> f64 {
        self.ops.line.h
    }
    /// The coupling.
    pub fn coupling(&self) -> Coupling {
        self.coupling
    }
    /// Midpoints of the 2n panels of [-1, 1].
    pub fn nodes(&self) -> Vec<f64> {
        (0..2 * self.ops.line.n)
            .map(|i| self.ops.line.mid(i))
            .collect()
    }
    /// The moment int x p dx the non-rotating punch carries (units of P a).
    pub fn moment(&self) -> f64 {
        self.state.moment(self.ops.line.h)
    }

    /// Moves Q / P monotonically from its current value to `q_over_p` in `steps` equal
    /// steps; returns the state after each step. |Q| >= mu P (sliding) is refused; on any
    /// error the history is unchanged.
    pub fn load(&mut self, q_over_p: f64, steps: usize) -> Result<Vec<State>> {
        let mu = self.coupling.mu;
        if !q_over_p.is_finite() || q_over_p.abs() >= mu {
            return Err(Error::InvalidArgument(format!(
                "Q / P = {q_over_p} is not inside (-mu, mu) = (-{mu}, {mu}): |Q| >= mu P is \
                 gross sliding, not a partial-slip state"
            )));
        }
        if steps == 0 {
            return Err(Error::InvalidArgument("need at least one load step".into()));
        }
        let q0 = self.state.q_over_p;
        let mut states = Vec::with_capacity(steps);
        let mut current = self.state.clone();
        for s in 1..=steps {
            // (the last step reaches the target exactly, not up to rounding)
            let target = if s == steps {
                q_over_p
            } else {
                q0 + (q_over_p - q0) * s as f64 / steps as f64
            };
            let next = self.step(&current, target, &current.q)?;
            states.push(next.clone());
            current = next;
        }
        self.state = current;
        Ok(states)
    }

    /// One load step from `prev` to Q / P = `target`, Newton started from q = `q_start`
    /// (warm smoothing; once more from full smoothing if that fails).
    fn step(&self, prev: &State, target: f64, q_start: &[f64]) -> Result<State> {
        let ops = &self.ops;
        let k = &self.coupling;
        let m = prev.q.len();
        let mu_p_bar: Vec<f64> = ops.line.p_bar.iter().map(|p| k.mu * p).collect();
        let mut f0: Vec<f64> = (0..m).map(|i| ops.e_c[i] - prev.surface[i]).collect();
        f0.push(-target);
        let mcp = BoxMcp {
            gl0: mu_p_bar.clone(),
            gl: &ops.gl,
            gu0: mu_p_bar,
            gu: &ops.gu,
            f0,
            f: &ops.f,
        };
        let mut z0 = q_start.to_vec();
        z0.push(0.0);
        let root = match smoothing_newton::solve_box(&mcp, &z0, self.ctl) {
            Ok(r) => r,
            Err(_) if self.ctl.max_iter == MAX_NEWTON => smoothing_newton::solve_box(
                &mcp,
                &z0,
                Controls {
                    eps0: 1.0,
                    ..self.ctl
                },
            )?,
            Err(e) => return Err(e),
        };
        self.state_from(prev, target, root)
    }

    fn state_from(&self, prev: &State, target: f64, root: BoxRoot) -> Result<State> {
        let ops = &self.ops;
        let k = &self.coupling;
        let h = ops.line.h;
        let m = prev.q.len();
        let q = root.z[..m].to_vec();
        let p = ops.pressure(k, &q);
        if let Some(i) = p.iter().position(|&v| v < 0.0) {
            return Err(Error::NoAdmissibleSolution(format!(
                "load step to Q/P = {target}: pressure {:.3e} < 0 at x = {:.4}",
                p[i],
                ops.line.mid(i)
            )));
        }
        let ds = root.f[..m].to_vec();
        // A node slips when its slip increment exceeds both its gap to the friction bound and
        // the complementarity tolerance: a node held at the bound (|q| = mu p) whose slip is
        // rounding (~1e-17, e.g. in a shaken-down cycle) sticks.
        let zones: Vec<Zone> = (0..m)
            .map(|i| {
                if ds[i] > root.gl[i].max(SLIP_FLOOR) {
                    Zone::SlipPositive
                } else if -ds[i] > root.gu[i].max(SLIP_FLOOR) {
                    Zone::SlipNegative
                } else {
                    Zone::Stick
                }
            })
            .collect();
        // (over the slipping nodes: a sticking node's |ds| is rounding, ~1e-17)
        let dissipation = h
            * (0..m)
                .filter(|&i| zones[i] != Zone::Stick)
                .map(|i| k.mu * p[i] * ds[i].abs())
                .sum::<f64>();
        let dissipation_mid = -h
            * (0..m)
                .map(|i| 0.5 * (prev.q[i] + q[i]) * ds[i])
                .sum::<f64>();
        let stick = stick_set(h, &ds, &root.gl, &root.gu, &zones);
        Ok(State {
            q_over_p: target,
            surface: ops.surface(&q),
            punch: prev.punch + root.z[m],
            normal: ops.normal(k, &q),
            p,
            q,
            slip_increment: ds,
            zones,
            stick,
            dissipation,
            dissipation_mid,
            newton: root.iterations,
        })
    }
}

/// [c1, c2] of the largest run of sticking nodes, each end interpolated by
/// `stick_edge::locate` from the friction reserve on the stick side and the slip increment
/// on the slip side (as the normal-load LCP does for c); +-1 where the run reaches an edge.
fn stick_set(h: f64, ds: &[f64], gl: &[f64], gu: &[f64], zones: &[Zone]) -> (f64, f64) {
    let m = ds.len();
    // [s, e) of the longest run of Stick (the first of equal length)
    let mut best = (0, 0);
    let mut start = None::<usize>;
    for (i, z) in zones
        .iter()
        .chain(std::iter::once(&Zone::SlipPositive))
        .enumerate()
    {
        match (*z == Zone::Stick, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                if i - s > best.1 - best.0 {
                    best = (s, i);
                }
                start = None;
            }
            _ => {}
        }
    }
    let (s, e) = best;
    if e == s {
        return (f64::NAN, f64::NAN);
    }
    let mid = |i: usize| -1.0 + (i as f64 + 0.5) * h;
    let a: Vec<f64> = ds.iter().map(|v| v.abs()).collect();
    let b: Vec<f64> = gl.iter().zip(gu).map(|(l, u)| l.min(*u)).collect();
    let end = |idx: Vec<usize>| -> f64 {
        let grid = Grid { n: idx.len(), h };
        let (aa, bb): (Vec<f64>, Vec<f64>) = idx.iter().map(|&i| (a[i], b[i])).unzip();
        let est = stick_edge::locate(grid, &aa, &bb);
        est.c - 0.5 * h
    };
    let c2 = if e == m {
        1.0
    } else {
        mid(s) + end((s..m).collect())
    };
    let c1 = if s == 0 {
        -1.0
    } else {
        mid(e - 1) - end((0..e).rev().collect())
    };
    (c1, c2)
}

/// One load cycle +Q* -> -Q* -> +Q*.
#[derive(Clone, Debug)]
pub struct Cycle {
    /// The states after each step (the cycle starts at the last state of the previous
    /// cycle or of the first loading).
    pub states: Vec<State>,
    /// Energy dissipated in the cycle, sum over steps of h sum mu p |ds| (units of pi B P^2).
    pub dissipation: f64,
    /// Half the peak-to-peak relative tangential displacement e - D of each node over the
    /// cycle (units of pi B P).
    pub slip_amplitude: Vec<f64>,
    /// The loop: (Q / P, D) at the cycle's start and after each step.
    pub loop_points: Vec<(f64, f64)>,
    /// Work of Q over the cycle, sum (Q_prev + Q) / 2 dD (the loop's area).
    pub loop_work: f64,
    /// Work of P over the cycle, P (V_end - V_start).
    pub normal_work: f64,
    /// Change of the elastic energy over the cycle.
    pub energy_change: f64,
    /// loop_work + normal_work - (sum of the steps' mid-step dissipation + energy_change):
    /// zero up to rounding on the grid (bp > 0; NaN when bp = 0, not an elastic material).
    pub balance_residual: f64,
}

/// A fretting run: the normal load, the first loading 0 -> Q*, and the cycles.
#[derive(Clone, Debug)]
pub struct Cycles {
    /// Midpoints of the 2n panels.
    pub nodes: Vec<f64>,
    /// Panel width.
    pub h: f64,
    /// The normal-load state (Q = 0).
    pub normal_load: State,
    /// States of the first loading 0 -> Q*.
    pub first_loading: Vec<State>,
    /// The cycles +Q* -> -Q* -> +Q*, in order.
    pub cycles: Vec<Cycle>,
}

/// Normal load, then Q / P: 0 -> `q_amp` in `steps` steps, then `n_cycles` cycles
/// `q_amp` -> -`q_amp` -> `q_amp`, each half in 2 `steps` steps; n panels per half-width.
pub fn cycles(k: &Coupling, n: usize, q_amp: f64, n_cycles: usize, steps: usize) -> Result<Cycles> {
    if q_amp.is_nan() || q_amp <= 0.0 {
        return Err(Error::InvalidArgument(format!(
            "the amplitude Q*/P must be > 0 (got {q_amp})"
        )));
    }
    let mut hist = History::new(k, n)?;
    let h = hist.h();
    let normal_load = hist.state().clone();
    let first_loading = hist.load(q_amp, steps)?;
    let mut out = Vec::with_capacity(n_cycles);
    for _ in 0..n_cycles {
        let start = hist.state().clone();
        let mut states = hist.load(-q_amp, 2 * steps)?;
        states.extend(hist.load(q_amp, 2 * steps)?);
        out.push(cycle_summary(k, h, &start, states));
    }
    Ok(Cycles {
        nodes: hist.nodes(),
        h,
        normal_load,
        first_loading,
        cycles: out,
    })
}

/// The summary of one cycle from its start state and the states after each of its steps.
pub(crate) fn cycle_summary(k: &Coupling, h: f64, start: &State, states: Vec<State>) -> Cycle {
    let m = start.q.len();
    let mut lo = start.relative();
    let mut hi = lo.clone();
    let mut loop_points = vec![(start.q_over_p, start.punch)];
    let (mut loop_work, mut mid_diss, mut dissipation) = (0.0, 0.0, 0.0);
    let mut prev = start;
    for s in &states {
        for (i, r) in s.relative().into_iter().enumerate() {
            lo[i] = lo[i].min(r);
            hi[i] = hi[i].max(r);
        }
        loop_points.push((s.q_over_p, s.punch));
        loop_work += 0.5 * (prev.q_over_p + s.q_over_p) * (s.punch - prev.punch);
        mid_diss += s.dissipation_mid;
        dissipation += s.dissipation;
        prev = s;
    }
    let end = states.last().unwrap_or(start);
    let normal_work = end.normal - start.normal;
    let energy_change = end.elastic_energy(h) - start.elastic_energy(h);
    let balance_residual = if k.bp > 0.0 {
        loop_work + normal_work - (mid_diss + energy_change)
    } else {
        f64::NAN
    };
    Cycle {
        dissipation,
        slip_amplitude: (0..m).map(|i| 0.5 * (hi[i] - lo[i])).collect(),
        loop_points,
        loop_work,
        normal_work,
        energy_change,
        balance_residual,
        states,
    }
}

#[cfg(test)]
mod tests;
