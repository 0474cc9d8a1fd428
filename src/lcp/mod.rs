//! The paper's numerical method (its section 4; docs/theory.md §9): (E1)-(E4) in
//! displacement (Volterra) form on a uniform grid, posed as a linear complementarity
//! problem between the tangential slip and the friction reserve mu p - |q| at each point,
//! solved by a smoothing Newton method.
//!
//! - `discretisation`: uniform panels on [0, 1] (p even, q odd), piecewise-constant
//!   tractions, exact panel integrals of the log kernel; (E1) and (E4) eliminated, leaving an
//!   affine LCP in q / mu.
//! - `smoothing_newton`: smoothed Fischer-Burmeister + Qi-Sun-Zhou smoothing Newton.
//! - `stick_edge`: c interpolated between the last stick and the first slip point.
//! - `history`: the same grid on the whole contact with a loading history: the tangential
//!   load Q after P, moved in steps and cycled (issue 27; docs/theory_tangential.md).
//!
//! Accuracy: first order in c (measured against Goodman at bp = 0: |c - c*| <= 0.16 h
//! for h = 1/n, n = 100..800; up to ~0.5 h in coupled cases); the pressure is first order
//! away from the punch edge, the last panel (~ 5 % low) does not converge. Cost: dense LU
//! on n unknowns per Newton step (~10 steps per grid). The LCP imposes q <= mu p and
//! slip >= 0 on x > 0; q >= -mu p on the stick zone is not imposed (checked in the tests).
//! For large mu the LCP has other solutions (e.g. full slip): the coarsest grid is reached
//! by continuation in mu, which follows the branch continuous from small friction.

mod dense;
mod discretisation;
pub mod history;
mod smoothing_newton;
mod stick_edge;

use crate::error::{Error, Result};
use crate::field::{Expand, Expansion, Family, grid_expansion};
use crate::numerics::cauchy::Weight;
use crate::problem::{Coupling, Profile, StickEdge, traction_distance, validate_tolerance};
use discretisation::Grid;
use smoothing_newton::Controls;

/// Solution of the discrete LCP on one grid, with its error estimate.
#[derive(Clone, Debug)]
pub struct LcpSolution {
    coupling: Coupling,
    grid: Grid,
    /// Panel values of p on [0, 1].
    p: Vec<f64>,
    /// Panel values of q on [0, 1].
    q: Vec<f64>,
    /// Slip s = int_0^x (bq p + H[q]) at the midpoints.
    slip: Vec<f64>,
    edge: StickEdge,
    stick_points: usize,
    error: f64,
    /// Estimate of the traction error (see `Ladder::step`).
    traction_error: f64,
    iterations: usize,
}

/// Smallest grid solved cold; finer grids start from the solution one level coarser.
const COARSEST: usize = 25;
/// Largest grid of `solve_to_tolerance` (dense LU: 2-3 s for the whole ladder; n = 3200
/// takes 15-20 s).
pub const MAX_PANELS: usize = 1600;
/// Friction coefficient where the continuation on the coarsest grid starts, and its step.
const CONTINUATION_MU0: f64 = 0.05;
const CONTINUATION_RATIO: f64 = 1.5;
/// Initial smoothing parameter when started from a nearby solution.
const WARM_SMOOTHING: f64 = 1e-3;
/// Converged when max_i |phi_FB(a_i, b_i)| <= this (a, b scaled to O(1)).
const COMPLEMENTARITY_TOL: f64 = 1e-12;
/// Newton iteration cap per grid.
const MAX_NEWTON: usize = 100;
/// Factor on the traction difference between two successive grids in the traction error.
const TRACTION_SAFETY: f64 = 4.0;

fn controls(eps0: f64) -> Controls {
    Controls {
        eps0,
        tol: COMPLEMENTARITY_TOL,
        max_iter: MAX_NEWTON,
    }
}

/// q / mu at friction `k.mu` on `grid`, reached from q = 0 at mu_0 = min(mu, `CONTINUATION_MU0`)
/// (full smoothing) through mu_{j+1} = `CONTINUATION_RATIO` mu_j, each solve started from the
/// previous q.
fn continuation_start(k: &Coupling, grid: Grid) -> Result<Vec<f64>> {
    let mut mu = k.mu.min(CONTINUATION_MU0);
    let mut z = vec![0.0; grid.n];
    let mut eps0 = 1.0;
    loop {
        let kj = Coupling { mu, ..*k };
        z = smoothing_newton::solve(&discretisation::assemble(grid, &kj)?, &z, controls(eps0))?.z;
        if mu >= k.mu {
            return Ok(z);
        }
        let next = (mu * CONTINUATION_RATIO).min(k.mu);
        z.iter_mut().for_each(|v| *v *= mu / next);
        mu = next;
        eps0 = WARM_SMOOTHING;
    }
}

/// Solves on one grid, starting from `start` (a coarser solution) when given.
fn solve_level(k: &Coupling, grid: Grid, start: Option<&LcpSolution>) -> Result<LcpSolution> {
    let n = grid.n;
    if k.mu == 0.0 {
        // No friction: q = 0, c = 0 exactly, p from (E1) + (E4) alone.
        let p = discretisation::frictionless_pressure(grid)?;
        return Ok(LcpSolution {
            coupling: *k,
            grid,
            slip: grid.running_integral(&p).iter().map(|v| k.bq * v).collect(),
            p,
            q: vec![0.0; n],
            edge: StickEdge::from_c(0.0),
            stick_points: 0,
            error: 0.0,
            traction_error: f64::INFINITY,
            iterations: 0,
        });
    }
    // On the coarsest grid: continuation in mu from the small-friction regime, which
    // selects the physical solution (docs/theory.md (P3): for large mu the LCP has other
    // solutions, e.g. full slip); on finer grids: the coarser q as the start.
    let z0 = match start {
        Some(s) => (0..n).map(|i| s.tractions(grid.mid(i)).1 / k.mu).collect(),
        None => continuation_start(k, grid)?,
    };
    let root = smoothing_newton::solve(
        &discretisation::assemble(grid, k)?,
        &z0,
        controls(WARM_SMOOTHING),
    )?;
    let e = stick_edge::locate(grid, &root.a, &root.b);
    let p: Vec<f64> = root.b.iter().zip(&root.z).map(|(b, z)| b + z).collect();
    // The LCP constrains slip and friction reserve, not the sign of p: a solution with
    // tension under the punch is another (non-physical) branch, not an answer.
    if let Some(i) = p.iter().position(|&v| v < 0.0) {
        return Err(Error::NoConvergence(format!(
            "LCP reached a non-physical branch on {n} panels (pressure {:.3e} < 0 at x = {:.4}); \
             use METHOD_COUPLED",
            p[i],
            grid.mid(i)
        )));
    }
    Ok(LcpSolution {
        coupling: *k,
        grid,
        p,
        q: root.z.iter().map(|z| k.mu * z).collect(),
        slip: root.a.iter().map(|a| k.bq * a).collect(),
        edge: StickEdge {
            c: e.c,
            one_minus_c: e.one_minus_c,
        },
        stick_points: e.stick_points,
        error: f64::INFINITY,
        traction_error: f64::INFINITY,
        iterations: root.iterations,
    })
}

/// Successive grids n_0, 2 n_0, ... (each started from the previous solution), keeping the
/// last three edges for the error estimate.
struct Ladder {
    coupling: Coupling,
    finest: Option<LcpSolution>,
    edges: Vec<f64>,
}

impl Ladder {
    fn new(k: &Coupling) -> Result<Self> {
        k.validate()?;
        Ok(Self {
            coupling: *k,
            finest: None,
            edges: Vec::new(),
        })
    }

    /// Solves on `n` panels from the current finest solution and sets its error estimate
    /// E = 2.5 max(|c_n - c_{n/2}|, |c_{n/2} - c_{n/4}| / 2) + h / 2: the error in c is a
    /// smooth first-order term (Richardson with order 1: |c_n - c_{n/2}|, or the previous
    /// difference halved) plus a sawtooth in the position of c within its cell, measured
    /// <= 0.12 h wide (see `stick_edge`). The factors cover what the stability map measured
    /// against COUPLED: near full stick, with 1 - c a few h (b* = 0.53, mu~ = 46 .. 464;
    /// b* = 0.61, mu~ = 10), the error reached 1.4 times the former 1.5 d + h / 4. When c is
    /// not bracketed (c < x_0 or c > x_{n-1}) the half-panel h / 2 is the floor.
    ///
    /// The traction error ([`crate::problem::traction_distance`]) is estimated from the
    /// previous grid's tractions as [`TRACTION_SAFETY`] times their distance (the pressure's
    /// last panel converges like h^(1 - g), so the error is up to 1 / (2^(1/2) - 1) = 2.4
    /// times the difference).
    fn step(&mut self, n: usize) -> Result<()> {
        let mut s = solve_level(&self.coupling, Grid::new(n), self.finest.as_ref())?;
        if let Some(coarse) = &self.finest {
            s.traction_error = TRACTION_SAFETY * traction_distance(&s, coarse);
        }
        self.edges.push(s.edge.c);
        let m = self.edges.len();
        if s.coupling.mu == 0.0 {
            s.error = 0.0;
        } else if m >= 3 {
            let d1 = (self.edges[m - 1] - self.edges[m - 2]).abs();
            let d2 = (self.edges[m - 2] - self.edges[m - 3]).abs();
            let h = s.grid.h;
            let bracketed = s.stick_points > 0 && s.stick_points < n;
            let floor = if bracketed { 0.0 } else { 0.5 * h };
            s.error = (2.5 * d1.max(0.5 * d2) + 0.5 * h).max(floor);
        }
        self.finest = Some(s);
        Ok(())
    }
}

/// Solves on `n` >= 100 panels per half-width (x in [0, 1]; 2n on the contact), after the
/// coarser grids n/2, n/4, ... down to >= 25 panels (each the start of the next), whose
/// edges give the error estimate. Cost ~ n^3 (dense LU): n = 800 ~ 0.3 s, 1600 2-3 s.
pub fn solve(k: &Coupling, n: usize) -> Result<LcpSolution> {
    if n < 4 * COARSEST {
        return Err(Error::InvalidArgument(format!(
            "need n >= {} panels (got {n})",
            4 * COARSEST
        )));
    }
    let mut ladder = Ladder::new(k)?;
    let mut sizes = vec![n];
    while sizes[sizes.len() - 1] / 2 >= COARSEST {
        sizes.push(sizes[sizes.len() - 1] / 2);
    }
    for &m in sizes.iter().rev() {
        ladder.step(m)?;
    }
    finish(ladder)
}

/// Doubles the grid from 25 panels until the error estimate (defined from the third grid,
/// n = 100, on) is <= `tol` and the traction error estimate <= `traction_tol` (infinity:
/// tractions not needed), up to `MAX_PANELS` = 1600 panels per half-width (2-3 s
/// measured on 2 shared cores); otherwise `Error::ToleranceNotMet` with the estimate reached,
/// at once where the traction estimate shows that `MAX_PANELS` would not do.
pub fn solve_to_tolerance(k: &Coupling, tol: f64, traction_tol: f64) -> Result<LcpSolution> {
    validate_tolerance(tol)?;
    let mut ladder = Ladder::new(k)?;
    let mut n = COARSEST;
    loop {
        ladder.step(n)?;
        let Some(s) = ladder.finest.as_ref() else {
            return Err(Error::Internal("LCP ladder without a solution".into()));
        };
        // (the traction estimate needs a second grid, also where c is exact: mu = 0)
        if s.error <= tol && s.traction_error.is_finite() && s.traction_error <= traction_tol {
            return finish(ladder);
        }
        // the traction error falls like h^(1/2) at worst (the edge panels): give up at once
        // when even `MAX_PANELS` would not bring it within reach
        let hopeless = s.traction_error * (n as f64 / MAX_PANELS as f64).sqrt() > traction_tol;
        if 2 * n > MAX_PANELS || (n >= 4 * COARSEST && hopeless) {
            let (estimate, tolerance, what) = if s.error > tol && !hopeless {
                (s.error, tol, "c")
            } else {
                (s.traction_error, traction_tol, "the tractions")
            };
            return Err(Error::ToleranceNotMet {
                estimate,
                tolerance,
                detail: format!(
                    "first-order LCP discretisation at {n} panels, capped at {MAX_PANELS} \
                     (error in {what})"
                ),
            });
        }
        n *= 2;
    }
}

fn finish(ladder: Ladder) -> Result<LcpSolution> {
    match ladder.finest {
        Some(s) if s.error.is_finite() && s.edge.c.is_finite() => Ok(s),
        _ => Err(Error::Internal(
            "LCP ladder ended without a finite estimate".into(),
        )),
    }
}

impl LcpSolution {
    /// Newton iterations used on the finest grid.
    pub fn newton_iterations(&self) -> usize {
        self.iterations
    }
    /// Panels per half-width.
    pub fn panels(&self) -> usize {
        self.grid.n
    }
    /// Number of midpoints in the stick zone.
    pub fn stick_points(&self) -> usize {
        self.stick_points
    }
    /// Midpoints x_i of the panels on [0, 1].
    pub fn nodes(&self) -> Vec<f64> {
        (0..self.grid.n).map(|i| self.grid.mid(i)).collect()
    }
    /// Panel values of p and q on [0, 1].
    pub fn panel_tractions(&self) -> (&[f64], &[f64]) {
        (&self.p, &self.q)
    }
    /// Slip s(x_i) = int_0^{x_i} (bq p + H\[q\]) >= 0 (u = -pi B s).
    pub fn slip(&self) -> &[f64] {
        &self.slip
    }

    /// Panel average of the edge weight (1 - x)^(-g) over panel i.
    fn weight_average(&self, i: usize) -> f64 {
        let g = self.coupling.edge_exponent();
        let h = self.grid.h;
        let (a, b) = (i as f64 * h, (i + 1) as f64 * h);
        ((1.0 - a).powf(1.0 - g) - (1.0 - b).powf(1.0 - g)) / ((1.0 - g) * h)
    }
}

/// The LCP's tractions as `tractions` reports them ([`Profile::half_line_tractions`]): the
/// regular parts p / w, q / w interpolated linearly between the grid midpoints, times
/// w = (1 - x)^(-g). One panel between each two midpoints (and [0, mid_0], where q ramps to
/// q(0) = 0), fitted in Legendre series (w is analytic there); on the last, [mid_{n-1}, 1],
/// the regular parts are constant and, on [-1, 1], (1 - x)^(-g) = r^(-g) (1 - t)^(-g) with r
/// the panel's half-width: one family weighted (1 - t)^(-g).
impl Expand for LcpSolution {
    fn expansion(&self) -> Expansion {
        let n = self.grid.n;
        let mut breaks = vec![0.0];
        breaks.extend((0..n).map(|j| self.grid.mid(j)));
        breaks.push(1.0);
        let g = self.coupling.edge_exponent();
        grid_expansion(
            &breaks,
            |x| self.half_line_tractions(x),
            |a, b| {
                (b == 1.0).then(|| {
                    let j = n - 1;
                    let scale = (0.5 * (b - a)).powf(-g) / self.weight_average(j);
                    Family {
                        weight: Weight::Right(-g),
                        p: vec![scale * self.p[j]],
                        q: vec![scale * self.q[j]],
                    }
                })
            },
        )
    }
}

impl Profile for LcpSolution {
    fn coupling(&self) -> Coupling {
        self.coupling
    }
    fn edge(&self) -> StickEdge {
        self.edge
    }
    fn numerical_error(&self) -> f64 {
        self.error
    }
    fn traction_error(&self) -> f64 {
        self.traction_error
    }
    /// Linear interpolation of the regular parts p / w, q / w between midpoints, with
    /// w = (1 - x)^(-g) the edge weight (panel values divided by the panel average of w).
    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        let n = self.grid.n;
        let t = x.min(1.0 - f64::EPSILON);
        let u = t / self.grid.h - 0.5;
        let j = (u.floor().max(0.0) as usize).min(n - 2);
        let theta = (u - j as f64).clamp(0.0, 1.0);
        let reg = |v: &[f64]| {
            (1.0 - theta) * v[j] / self.weight_average(j)
                + theta * v[j + 1] / self.weight_average(j + 1)
        };
        let w = (1.0 - t).powf(-self.coupling.edge_exponent());
        // q is odd: below the first midpoint, interpolate linearly to q(0) = 0.
        let q_ramp = (t / self.grid.mid(0)).min(1.0);
        (w * reg(&self.p), q_ramp * w * reg(&self.q))
    }
}

#[cfg(test)]
mod tests;
