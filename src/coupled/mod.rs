//! orthoslip's solver of the full coupled partial-slip problem (E1)-(E4) (METHOD_COUPLED).
//!
//! Method (docs/theory.md §10, (K1)-(K6)):
//! - the exact reduction (bp, bq, mu) -> (b*, b*, mu / delta), q = delta q~ (bp > 0);
//! - for a trial stick edge c, a collocation system on panels graded geometrically towards
//!   x = c and x = 1 (`mesh`), whose bases carry the local exponents: (1 - x)^(-g) at the
//!   punch edge, (x - c)^g on the slip side and (c - x)^g in q on the stick side, plus the
//!   wrong-c modes |x - c|^(g-1) (`system`); all singular integrals are evaluated in closed
//!   form or to rounding (`numerics::cauchy`), so the error decays geometrically in
//!   the order n;
//! - c is the root of defect(c), the coefficient of q's (c - x)^(g-1) mode (bounded q at c is
//!   the compatibility condition), found in lc = ln(c / (1 - c)) so that c ~ 1e-20 and
//!   1 - c ~ 1e-12 are both carried to full relative accuracy;
//! - the order is raised (4, then 6, 8, 11, 13, 16, ...) until two successive orders agree
//!   on c within the tolerance (twice their difference plus both roots' location
//!   uncertainties) and on the tractions within max(100 tol, 1e-9), and the traction
//!   estimate meets the traction tolerance ([`solve_to`]). Each order starts
//!   from the previous order's root and slope: one secant step, usually two solves.
//!
//! Which root: defect < 0 for small c (checked at a c far below Goodman's estimate, walking
//! down until it is; never above c = 1/2), then c is increased in lc (steps of 1 to 3, a
//! little beyond the linearly extrapolated zero) until defect (at the cheap order 4) changes
//! sign: the first sign change met from c = 0 brackets the physical root (the one
//! continuous in mu from small friction); a bracket wider than 1 is bisected, then Brent's
//! method refines the root at order 4 (if a higher order loses it, the search is redone at
//! that order). If that fails, the whole search is redone scanning at order 8. Where the
//! near-bonded law (`near_bonded`) puts 1 - c below 1e-6, the root is instead sought inside
//! the law's window of lc at order 8, then 11 (the low orders lose the defect's sign there). At
//! large friction (g < 1e-3) the search runs at orders 11 and 13 instead. The solution is
//! checked for p > 0 and for |q| <= mu p on the stick zone before it is returned; an
//! inadmissible root makes the scan start again from far below (c = 1.4e-11): the start below
//! Goodman's c can lie beyond the first root (auxetic extremes). Only where that search ends
//! on the same inadmissible root is it reported as such (NoAdmissibleSolution), else as
//! NoConvergence. Where no order pair meets the tolerance, the last order's solution is
//! kept with its estimates, so that [`solve_to`] can take it if it meets what was asked.
//!
//! Regimes ([`solve_to`]): closed forms where their error bounds meet both tolerances, the
//! panels elsewhere:
//! - mu = 0: p = p0, q = 0; bp = 0: Goodman's closed form, which is then exact;
//! - a stick zone below the tolerance: the full-slip limit with the law
//!   c ~ 4 (1 - b*^2)^(pi / (2 b* mu~)) (`full_slip`);
//! - slip zones below the tolerance (small b*): the bonded punch with the law
//!   ln((1 - c) / 8) = -kappa arctan(mu~) / eps (`near_bonded`);
//! - mu~ >= 1e7, beyond the panels' reach: the quadratic in 1/mu~ through the panels'
//!   solutions at mu~ = 1e6, 2e6, 4e6 (`large_friction`); in thin slip zones (1 - c below
//!   about 1e-15) from g < 1e-3 on, through lower frictions (b* = 0.1: 530, 1061, 2122);
//! - b* within 1e-5 of 1 (the auxetic limit, ill-conditioned): c = K s^(1/k0) with K
//!   extrapolated in s = 1 - b* from the panels at s = 1e-5 .. 8e-5, then the root search
//!   in a window around it where it agrees, else the panels at that c (`auxetic`);
//! - c alone (traction tolerance +infinity, [`solve_to`]): the tabulated stick edge
//!   ([`crate::stick_edge_table`]) where its bound meets the tolerance, with Goodman's
//!   tractions and their model-error bound.
//!
//! Range of the panels: `T_MIN` < lc < `T_MAX`, i.e. c > 2e-35 and 1 - c > 2.6e-23, and for
//! thin slip zones at most `MAX_UNKNOWNS` at the order their tractions need (outside it
//! NoConvergence says so); the number of panels grows like log(1 / min(c, 1 - c)), and
//! thin slip zones cost seconds to a minute (1 - c = 1e-14 at b* = 0.1: ~2000 unknowns;
//! 1 - c = 1.3e-19: 2548 unknowns, 28 s; 1 - c = 3.2e-21: 2738 unknowns, 44 s). The bonded
//! limit takes over where its bound meets the tolerances (1 - c below 1.1e-21 at 1e-10), so
//! the two leave no gap at tolerances from 1e-10 up; at large friction (g < 1e-3) thin slip
//! zones (1 - c below about 1e-15) are extrapolated in 1/mu~ from the panels at lower
//! friction (`large_friction`).
//! A panel solve is 6-9 cheap order-4 solves, then about two Householder least-squares
//! solves per order (100-350 unknowns at the last); `cargo run --release --example
//! coupled_timing` measures the cost.

mod auxetic;
mod expansion;
pub(crate) mod full_slip;
mod large_friction;
mod mesh;
pub(crate) mod near_bonded;
mod system;
mod weak_coupling;

#[cfg(test)]
pub(crate) mod tests;

use crate::error::{Error, Result};
use crate::goodman::GoodmanSolution;
use crate::model_error::Approximation;
use crate::numerics::lstsq::LeastSquares;
use crate::numerics::quadrature::gauss_legendre_nodes;
use crate::numerics::roots::brent;
use crate::problem::{Coupling, Profile, StickEdge, validate_tolerance};
use crate::spectral::Spectral;
use full_slip::FullSlip;
use large_friction::{LargeFriction, MU_EXTRAPOLATE};
use mesh::{Layout, Mesh, Pt};
use near_bonded::NearBonded;
use system::{Constants, Discrete, Families, solve_fixed};

/// The range of lc = ln(c / (1 - c)) the first-root scan covers: c = e^-80 = 1.8e-35 up to
/// 1 - c = e^-52 = 2.6e-23 (roughly the smallest c and 1 - c the panel layouts resolve, and
/// below the 1 - c = 1.1e-21 from which the bonded limit meets 1e-10).
const T_MIN: f64 = -80.0;
const T_MAX: f64 = 52.0;

/// Range of Goodman's stick edge, in lc, as the start of the scan.
const GUESS_RANGE: (f64, f64) = (-60.0, 30.0);

/// Steps down from the start before the scan gives up on finding defect < 0.
const MAX_STEPS_DOWN: usize = 30;

/// Smallest and largest step in lc = ln(c / (1 - c)) of the scan for the first root (the
/// roots near full stick repeat every pi / eps >= 12 in ln(1 - c) for b* < 0.99, so no step
/// holds two of them); in between, the step goes a little beyond the linearly predicted zero.
const SCAN_STEP: f64 = 1.0;
const SCAN_MAX_STEP: f64 = 3.0;

/// Orders of the scan for the first sign change of defect (only its sign is used): the cheap
/// one, then, where it finds no root or one the layouts disagree on (thin slip zones at
/// small b*, e.g. b* = 0.2, mu~ = 5 and 20; b* = 0.1, mu~ = 1), the one whose sign is right
/// there, at 2-4 times the cost.
const SCAN_ORDERS: [usize; 2] = [4, 8];

/// Large friction: below this edge exponent g (g ~ 1 / (pi b* mu~)) the first root is sought
/// at [`SMALL_G_ORDERS`] instead of the scan's or the window's orders: the low orders' defect
/// is wrong there, even in sign (b* = 0.45, mu~ = 1e4, g = 7e-5: orders 4 and 6 wrong, 8
/// right; b* = 0.99, mu~ = 1e4, g = 3e-5: order 8 wrong, 11 right; b* = 0.45, mu~ = 1e6:
/// 11 right).
const SMALL_G: f64 = 1e-3;
const SMALL_G_ORDERS: [usize; 2] = [11, 13];

/// The orders the first root is sought at: `orders`, at large friction raised to at least
/// [`SMALL_G_ORDERS`] (the thin windows' own orders are higher still: at b* = 0.1, mu~ = 1e4,
/// 11 and 13 see no sign change where 13 and 16 find the root).
fn search_orders(g: f64, orders: [usize; 2]) -> [usize; 2] {
    if g < SMALL_G {
        [0, 1].map(|i| orders[i].max(SMALL_G_ORDERS[i]))
    } else {
        orders
    }
}

/// Where the scan is redone from when its root came out inadmissible: the start below
/// Goodman's c can lie beyond the first root, on a later lobe of the defect where it is
/// negative again (b* = 0.99995, mu~ = 10: Goodman's c is near 1, the scan started at
/// c = 1/2 found c = 0.888 with p < 0; the first root is c = 1.4e-4). At c = 1.4e-11
/// (lc = -25) the defect (-4e-7 there) stands well out of its rounding noise (1e-10 at
/// lc = -40, order 13).
const RESCAN_FROM: f64 = -25.0;

/// Thin slip zones: where the near-bonded law ([`near_bonded::ln_w_range`]) puts 1 - c below
/// WINDOW_BELOW, the root is sought inside its range of lc widened by WINDOW_MARGIN on both
/// sides (narrower than the spacing pi / eps of the roots near full stick, so it holds one),
/// at WINDOW_ORDERS in turn: the low scan orders lose the defect's sign there (b* = 0.05,
/// mu~ = 0.5: order 4 never crosses zero, order 8 crosses at the root but back near lc = 35,
/// order 13 is near-linear; at b* = 0.1, mu~ = 2 order 8 has no sign change in the window,
/// order 11 has). Order 8 first: it halves the cost where it suffices (b* = 0.2, mu~ = 100).
const WINDOW_BELOW: f64 = 1e-6;
const WINDOW_MARGIN: f64 = 1.0;
const WINDOW_ORDERS: [usize; 2] = [8, 11];

/// The window's orders where it ends beyond [`THIN_WINDOW`] in lc (1 - c below 4e-18): there
/// orders 8 and 11 see no sign change (b* = 0.1, mu~ = 10: the defect at lc = 38 .. 47 stays
/// negative at 8 and 11, while 13 and 16 agree on a root at lc = 43.5).
const THIN_WINDOW_ORDERS: [usize; 2] = [13, 16];
const THIN_WINDOW: f64 = 40.0;

/// The order whose traction estimate meets 1e-10 in the thin windows (b* = 0.1, mu~ = 10 and
/// b* = 0.12, mu~ = 1e4: 19, after the window's 13 and 16).
const THIN_FINAL_ORDER: usize = 19;

/// The unknowns of the panels at [`THIN_FINAL_ORDER`] for the stick edge at lc (None: no
/// layout fits).
fn thin_unknowns(lc: f64) -> Option<usize> {
    let (c, w) = edge_of(lc);
    Mesh::new(c, w, THIN_FINAL_ORDER, true, &Layout::for_edge(c, w)).map(|m| m.unknowns)
}

/// Whether the slip zones the near-bonded window (lo, hi) of lc predicts are beyond the
/// panels: past [`T_MAX`], or, in a thin window, more than [`MAX_UNKNOWNS`] at
/// [`THIN_FINAL_ORDER`].
fn too_thin(lo: f64, hi: f64) -> bool {
    let mid = 0.5 * (lo + hi);
    mid > T_MAX - WINDOW_MARGIN - 1.0
        || (hi > THIN_WINDOW && thin_unknowns(mid).is_none_or(|u| u > MAX_UNKNOWNS))
}

/// The orders of the window search for a window ending at `hi` in lc.
fn window_orders(hi: f64) -> [usize; 2] {
    if hi > THIN_WINDOW {
        THIN_WINDOW_ORDERS
    } else {
        WINDOW_ORDERS
    }
}

/// Two successive orders must also agree on the tractions to TRACTION_RATIO times the
/// tolerance (relative, [`traction_gap`]): near full stick a tolerance on c alone is met at
/// orders too low for the tractions.
const TRACTION_RATIO: f64 = 100.0;

/// The traction agreement asked for at most (below it, the least-squares rounding noise
/// of the higher orders would decide).
const TRACTION_FLOOR: f64 = 1e-9;

/// Smallest tolerance on c that the panels are re-run with to meet a traction tolerance.
const TIGHTEST: f64 = 1e-12;

/// The panels' traction estimate over their tolerance on c, at most (measured: up to 46 at
/// tolerances 1e-4 .. 1e-8 on six scenes of the reduced plane, b* = 0.1 .. 0.7).
const TRACTION_PER_C: f64 = 50.0;

/// Most unknowns of a panel system: thin slip zones at small b* need many panels (at order 19,
/// the order whose estimate meets 1e-10: b* = 0.1, mu~ = 10, 1 - c = 1.3e-19, 2548 unknowns,
/// 28 s in all; b* = 0.05, mu~ = 1, 1 - c = 3.2e-21, 2738, 44 s), and one least-squares solve
/// takes seconds there. The thinnest zones the bonded limit leaves at 1e-10 (1.1e-21) need
/// about 2800.
const MAX_UNKNOWNS: usize = 3200;

/// Relative accuracy of small c that [`solve_to`] asks of the panels when the tractions are
/// wanted: at c = 1e-7 (an auxetic material, mu = 0.1) c to 1e-10 left (E2) off by 2e-6
/// relative on the stick zone once the wrong-c modes were left out of the tractions.
const RELATIVE_C: f64 = 1e-7;

/// Factor on the difference of two successive orders' c in the error estimate.
const ORDER_SAFETY: f64 = 2.0;

/// The order at which [`panels_at_table_edge`] measures how the tractions move with c, and
/// the step in lc = ln(c / (1 - c)) it takes (far above the tractions' rounding at that order,
/// small enough to be linear). The lowest of [`ORDERS`]: a rate of change needs no more (one
/// solve at order 6 instead of 8 took 7% off the median fixed-c solve, 12 benchmark scenes).
const SENSITIVITY_ORDER: usize = 6;
const SENSITIVITY_STEP: f64 = 1e-6;

/// Tolerances below which the finer oversampling is used (defect's noise at the default one
/// is 1e-12 .. 1e-13 in c at orders 10-26).
const FINE_BELOW: f64 = 1e-11;

/// b* from which the root search keeps the default oversampling at every tolerance: near
/// b* = 1 at large friction the finer one moved the root by more than its estimates (c
/// alone to 1e-12 at mu~ = 4e6: 3.4e-10 off at b* = 0.99998, 6.3e-11 off with an estimate of
/// 7.4e-14 at b* = 0.99999), while the default stays within 3.4e-14 of c there (against c to
/// 1e-10 with the tractions to 1e-8; at b* = 0.9999 and 0.99995 the two agree).
const FINE_B_BELOW: f64 = 0.999;

/// Accuracy in lc of the first root at the scan order (a start for the higher orders).
const SCAN_XTOL: f64 = 1e-4;

/// Largest accuracy in lc asked of a root at the orders after the scan.
const LOOSEST_XTOL: f64 = 1e-3;

/// Polynomial orders tried in turn (per panel) after the scan order: steps of 2 or 3, so
/// that the order whose error first falls below the tolerance is soon confirmed by the next
/// (the error falls by 10-100 per step of 2, docs/theory.md (K5) / tests.rs). Up to 34: at
/// b* = 0.99, mu~ = 215 the tractions reach 1e-10 only at order 34 (1.3e-10 at 26); where the
/// unknowns grow past [`MAX_UNKNOWNS`] first (thin slip zones) the ladder stops before.
const ORDERS: [usize; 10] = [6, 8, 11, 13, 16, 19, 22, 26, 30, 34];

/// Whether the panels grow no further after order n with `unknowns` unknowns: the next of
/// [`ORDERS`] would exceed [`MAX_UNKNOWNS`] (the panels stay, the unknowns grow with the
/// order), or there is none.
fn at_largest_order(unknowns: usize, n: usize) -> bool {
    ORDERS
        .iter()
        .find(|&&m| m > n)
        .is_none_or(|&m| unknowns * m / n > MAX_UNKNOWNS)
}

/// The coupled solution: stick edge, error estimates and the tractions of its regime.
#[derive(Clone, Debug)]
pub struct CoupledSolution {
    coupling: Coupling,
    edge: StickEdge,
    error: f64,
    /// Estimate of the traction error ([`crate::problem::traction_distance`] from the exact
    /// tractions): for the panels [`ORDER_SAFETY`] times the distance between the tractions
    /// of the last two orders, plus the norm of the wrong-c modes the tractions leave out.
    traction_error: f64,
    /// q = delta q~ (1 when bp = 0).
    delta: f64,
    regime: Regime,
    /// Order per panel of the returned discretisation (0 outside the panel regime).
    order: usize,
}

/// How the solution was obtained.
#[derive(Clone, Debug)]
enum Regime {
    /// mu = 0: p = p0 exactly, q = 0.
    Frictionless,
    /// The panel discretisation of the coupled equations.
    Panels(Discrete),
    /// The global bases per zone ([`crate::spectral`]).
    Spectral(Box<Spectral>),
    /// bp = 0: p = p0 exactly, so Goodman's closed form is the exact solution.
    Uncoupled(GoodmanSolution),
    /// A stick zone below the tolerance: the full-slip limit ([`full_slip`]).
    FullSlip(FullSlip),
    /// Slip zones below the tolerance: the bonded punch ([`near_bonded`]).
    NearBonded(NearBonded),
    /// mu~ beyond the panels' reach: extrapolated in 1/mu~ ([`large_friction`]).
    LargeFriction(Box<LargeFriction>),
    /// c alone (no traction tolerance): the tabulated stick edge
    /// ([`crate::stick_edge_table`]); the tractions are Goodman's, with his traction bound.
    Tabulated(GoodmanSolution),
}

impl CoupledSolution {
    /// Polynomial order per panel of the returned discretisation (0 for mu = 0 and for the
    /// closed-form limit regimes).
    pub fn order(&self) -> usize {
        self.order
    }

    /// The regime that answered: "frictionless", "panels", "spectral", "uncoupled",
    /// "full slip", "near bonded", "large friction" or "tabulated" (docs/theory.md).
    pub fn regime(&self) -> &'static str {
        match &self.regime {
            Regime::Frictionless => "frictionless",
            Regime::Panels(_) => "panels",
            Regime::Spectral(_) => "spectral",
            Regime::Uncoupled(_) => "uncoupled",
            Regime::FullSlip(_) => "full slip",
            Regime::NearBonded(_) => "near bonded",
            Regime::LargeFriction(_) => "large friction",
            Regime::Tabulated(_) => "tabulated",
        }
    }

    /// Number of unknowns of the returned discretisation (0 without one).
    pub fn unknowns(&self) -> usize {
        match &self.regime {
            Regime::Panels(d) => d.mesh.unknowns,
            Regime::Spectral(s) => s.unknowns(),
            Regime::LargeFriction(l) => l.unknowns(),
            _ => 0,
        }
    }

    /// The solution of a closed-form regime: its profile, wrapped as the regime.
    fn from_profile<P: Profile>(profile: P, regime: fn(P) -> Regime) -> Self {
        CoupledSolution {
            coupling: profile.coupling(),
            edge: profile.edge(),
            error: profile.numerical_error(),
            traction_error: profile.traction_error(),
            delta: 1.0,
            regime: regime(profile),
            order: 0,
        }
    }
}

impl Profile for CoupledSolution {
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

    /// (p, q) at 0 <= x < 1: on panels one panel lookup and two short Legendre sums.
    fn half_line_tractions(&self, x: f64) -> (f64, f64) {
        match &self.regime {
            Regime::Frictionless => (crate::goodman::p0(x), 0.0),
            Regime::Panels(d) => {
                let (p, q) = d.eval(Pt { x, u: 1.0 - x });
                (p, self.delta * q)
            }
            Regime::Spectral(s) => {
                let (p, q) = s.half_line_tractions(x);
                (p, self.delta * q)
            }
            Regime::Uncoupled(g) => g.half_line_tractions(x),
            Regime::FullSlip(f) => f.half_line_tractions(x),
            Regime::NearBonded(b) => b.half_line_tractions(x),
            Regime::LargeFriction(l) => l.half_line_tractions(x),
            Regime::Tabulated(g) => g.half_line_tractions(x),
        }
    }
}

/// c and 1 - c from lc = ln(c / (1 - c)), both to full relative accuracy.
fn edge_of(lc: f64) -> (f64, f64) {
    let e = StickEdge::from_logit(lc);
    (e.c, e.one_minus_c)
}

/// Goodman's stick edge (the closed form of [`crate::goodman::stick_edge`]) as a starting
/// lc = ln(c / (1 - c)), clamped to the range the scan works in.
fn goodman_guess(bq: f64, mu: f64) -> f64 {
    let e = crate::goodman::stick_edge(bq / mu);
    e.logit().clamp(GUESS_RANGE.0, GUESS_RANGE.1)
}

/// Root finder state for one polynomial order per panel.
struct Level<'a> {
    k: Constants,
    order: usize,
    fams: &'a Families,
    /// Fixed panel layout while refining a bracket (None: each c its own layout).
    layout: Option<Layout>,
    /// The evaluations (lc, defect), for the slope at the root.
    evals: Vec<(f64, f64)>,
    /// Accuracy wanted in lc (a small fraction of the order's own error in c).
    xtol: f64,
    /// The discretisations of the last two evaluations (lc, solution), newest last.
    solved: [Option<(f64, Discrete)>; 2],
    /// Collocation points per unknown.
    oversample: f64,
    /// The least-squares solver of this level's systems (from the lower orders: once they
    /// needed the pivoted QR, so do the higher ones).
    ls: LeastSquares,
    /// The lower order's solution, whose field weights the rows of every solve at this
    /// level (the same weights throughout, so that defect(lc) stays smooth); None: the rows
    /// unweighted ([`system::weighs_rows`]).
    model: Option<Discrete>,
}

impl<'a> Level<'a> {
    fn new(
        k: Constants,
        order: usize,
        fams: &'a Families,
        xtol: f64,
        oversample: f64,
        ls: LeastSquares,
        model: Option<Discrete>,
    ) -> Self {
        Level {
            k,
            order,
            fams,
            layout: None,
            evals: Vec::new(),
            xtol,
            solved: [None, None],
            oversample,
            ls,
            model,
        }
    }

    /// The defect at lc, at this level's order.
    fn defect(&mut self, lc: f64) -> Result<f64> {
        self.defect_at_order(lc, self.order)
    }

    /// The defect at lc, at `order` (at most this level's: the families are built up to it).
    fn defect_at_order(&mut self, lc: f64, order: usize) -> Result<f64> {
        let (c, w) = edge_of(lc);
        let own;
        let layout = match &self.layout {
            Some(l) => l,
            None => {
                own = Layout::for_edge(c, w);
                &own
            }
        };
        let d = solve_fixed(
            self.k,
            c,
            w,
            order,
            self.fams,
            layout,
            self.oversample,
            &mut self.ls,
            self.model.as_ref(),
        )?;
        let defect = d.defect;
        self.evals.push((lc, defect));
        self.solved = [self.solved[1].take(), Some((lc, d))];
        if defect.is_finite() {
            Ok(defect)
        } else {
            Err(Error::NoConvergence(format!(
                "defect not finite at c = {c}"
            )))
        }
    }

    /// The discretisation at lc: one of the last two evaluations if it was made there,
    /// else a new solve.
    fn discrete_at(&mut self, lc: f64) -> Result<Discrete> {
        let i = self
            .solved
            .iter()
            .position(|s| s.as_ref().is_some_and(|(lc_s, _)| *lc_s == lc));
        match i.and_then(|i| self.solved[i].take()) {
            Some((_, d)) => Ok(d),
            None => {
                self.defect(lc)?;
                self.discrete_at(lc)
            }
        }
    }

    /// Fixes the layout to the one of lc. The evaluations so far (other layouts, or the scan
    /// order) no longer count for the slope.
    fn fix_layout(&mut self, lc: f64) {
        let (c, w) = edge_of(lc);
        self.layout = Some(Layout::for_edge(c, w));
        self.evals.clear();
    }
    /// Brent's method on defect(lc) in [a, b] with defect(a) < 0 < defect(b), to this level's
    /// xtol in lc.
    fn brent(&mut self, a: f64, b: f64, fa: f64, fb: f64) -> Result<f64> {
        let xtol = self.xtol;
        brent(|lc| self.defect(lc), (a, fa), (b, fb), xtol, 100)
    }

    /// The first root from `start` (at most this level's order), refined at this level's
    /// order.
    fn root_from(&mut self, start: Start) -> Result<f64> {
        match start {
            Start::Scan(lc0, order) => self.first_root(lc0, order.min(self.order)),
            Start::Window(lo, hi, order) => {
                let n = order.min(self.order);
                let (f_lo, f_hi) = (self.defect_at_order(lo, n)?, self.defect_at_order(hi, n)?);
                if f_lo < 0.0 && f_hi >= 0.0 {
                    self.refine_bracket((lo, f_lo), (hi, f_hi), n)
                } else {
                    Err(Error::NoConvergence(format!(
                        "no sign change of the defect in the near-bonded window \
                         {lo} < lc < {hi}"
                    )))
                }
            }
        }
    }

    /// First sign change of defect met increasing c from 0 (scanned at order `scan`, at
    /// most this level's), then refined at this level's order.
    fn first_root(&mut self, lc0: f64, scan: usize) -> Result<f64> {
        let (mut lo, mut f_lo) = self.scan_start(lc0, scan)?;
        let mut step = SCAN_STEP;
        loop {
            let hi = lo + step;
            let f_hi = self.defect_at_order(hi, scan)?;
            if f_hi >= 0.0 {
                return self.refine_bracket((lo, f_lo), (hi, f_hi), scan);
            }
            // next step: a little beyond the linearly predicted zero, within the bounds
            step = (1.2 * f_hi * step / (f_lo - f_hi)).clamp(SCAN_STEP, SCAN_MAX_STEP);
            if !step.is_finite() {
                step = SCAN_STEP;
            }
            (lo, f_lo) = (hi, f_hi);
            if lo > T_MAX {
                return Err(Error::NoConvergence(format!(
                    "no sign change of the defect for 1 - c >= {:.0e}: the slip zones are below \
                     the solver's range",
                    edge_of(T_MAX).1
                )));
            }
        }
    }

    /// The scan's start at or below lc0 (never above c = 1/2: for large friction Goodman's c
    /// is far too close to 1, beyond further roots of the oscillatory near-full-stick regime),
    /// walking down until the defect at the scan order is negative: (lc, defect).
    fn scan_start(&mut self, lc0: f64, scan: usize) -> Result<(f64, f64)> {
        let mut lo = (lc0 - 1.0).min(0.0);
        for _ in 0..=MAX_STEPS_DOWN {
            if lo < T_MIN {
                break;
            }
            let f = self.defect_at_order(lo, scan)?;
            if f < 0.0 {
                return Ok((lo, f));
            }
            lo -= 2.0;
        }
        Err(Error::NoConvergence(format!(
            "defect >= 0 down to c = {:.0e}: the stick zone is below the solver's range",
            edge_of(T_MIN).0
        )))
    }

    /// The root in a scan bracket (defect(lo) < 0 <= defect(hi) at the scan order): a bracket
    /// wider than SCAN_STEP is bisected (each point its own layout) first; then Brent at this
    /// level's order with the layout fixed, around the interpolated zero: first a narrow
    /// bracket, then (the scan order's sign may be off within its error of the root, or the
    /// defect far from linear) the scan's bracket widened.
    fn refine_bracket(
        &mut self,
        (mut lo, mut f_lo): (f64, f64),
        (mut hi, mut f_hi): (f64, f64),
        scan: usize,
    ) -> Result<f64> {
        while hi - lo > SCAN_STEP {
            let mid = 0.5 * (lo + hi);
            let f_mid = self.defect_at_order(mid, scan)?;
            if f_mid >= 0.0 {
                (hi, f_hi) = (mid, f_mid);
            } else {
                (lo, f_lo) = (mid, f_mid);
            }
        }
        let lc_s = lo + (hi - lo) * f_lo / (f_lo - f_hi);
        for (a, b) in [(lc_s - 0.25, lc_s + 0.25), (lo - 0.5, hi + 0.5)] {
            self.fix_layout(0.5 * (a + b));
            // a bracket the layout does not fit is skipped
            if let (Ok(f_a), Ok(f_b)) = (self.defect(a), self.defect(b))
                && f_a < 0.0
                && f_b >= 0.0
            {
                return self.brent(a, b, f_a, f_b);
            }
        }
        Err(Error::NoConvergence(format!(
            "the defect changes sign with the panel layout or order near lc = {lo}"
        )))
    }

    /// d defect / d lc at the root lc: the secant of the two evaluations (on this level's fixed
    /// layout) within 0.1 of lc whose defect differ most, if that difference stands out of
    /// defect's rounding noise (10 times the smallest |defect| seen) and the secant rises (defect
    /// crosses zero upwards at the physical root); NaN otherwise.
    fn slope(&self, lc: f64) -> f64 {
        let near: Vec<&(f64, f64)> = self
            .evals
            .iter()
            .filter(|e| (e.0 - lc).abs() <= 0.1)
            .collect();
        let noise = near.iter().map(|e| e.1.abs()).fold(f64::INFINITY, f64::min);
        let mut best = (10.0 * noise, f64::NAN);
        for (i, a) in near.iter().enumerate() {
            for b in &near[i + 1..] {
                let df = (a.1 - b.1).abs();
                let secant = (a.1 - b.1) / (a.0 - b.0);
                if df > best.0 && a.0 != b.0 && secant > 0.0 {
                    best = (df, secant);
                }
            }
        }
        best.1
    }

    /// The root near lc_prev (from a lower order) by the secant method started with the
    /// lower order's slope; if that fails, by bracketing and Brent. Returns an evaluated
    /// point lc and its distance from this order's root, |defect(lc)| / |slope| (which also
    /// measures the rounding noise of defect), once that is below xtol: usually two solves.
    fn root_near(&mut self, lc_prev: f64, slope: f64, first: f64) -> Result<(f64, f64)> {
        self.fix_layout(lc_prev);
        let f = self.defect(lc_prev)?;
        if slope.is_finite() && slope != 0.0 {
            let (mut lc0, mut f0) = (lc_prev, f);
            let mut step = -f0 / slope;
            if step.abs() <= self.xtol || f0 == 0.0 {
                return Ok((lc0, step.abs()));
            }
            let mut lc1 = lc0 + step;
            for _ in 0..6 {
                if step.abs() > 1.0 {
                    break;
                }
                let f1 = self.defect(lc1)?;
                // the secant slope, unless noise has made it useless: then the lower order's
                let s = (f1 - f0) / (lc1 - lc0);
                let s = if s.is_finite() && s * slope > 0.0 {
                    s
                } else {
                    slope
                };
                step = -f1 / s;
                if step.abs() <= self.xtol || f1 == 0.0 {
                    return Ok((lc1, step.abs()));
                }
                if f1.abs() >= f0.abs() && f0 * f1 < 0.0 && (lc1 - lc0).abs() > self.xtol {
                    // overshot a root by far (defect far from linear: the auxetic
                    // b* = 1 - 5e-7, mu~ = 10 at order 11): Brent in the bracket
                    let ((a, fa), (b, fb)) = if f0 < 0.0 {
                        ((lc0, f0), (lc1, f1))
                    } else {
                        ((lc1, f1), (lc0, f0))
                    };
                    return Ok((self.brent(a, b, fa, fb)?, self.xtol));
                }
                if f1.abs() >= f0.abs() {
                    // no progress: defect's rounding noise reached. The root lies between lc0
                    // and lc1 if defect changes sign there, else within the noise's size
                    // over the slope
                    let best = if f1.abs() < f0.abs() { lc1 } else { lc0 };
                    let unc = if f0 * f1 < 0.0 {
                        (lc1 - lc0).abs()
                    } else {
                        2.0 * f0.abs().max(f1.abs()) / slope.abs()
                    };
                    return Ok((best, unc));
                }
                (lc0, f0) = (lc1, f1);
                lc1 += step;
            }
        }
        let mut step = 1e-6f64.max(4.0 * first);
        while step < 8.0 {
            let (lo, hi) = (lc_prev - step, lc_prev + step);
            let (f_lo, f_hi) = if f < 0.0 {
                (f, self.defect(hi)?)
            } else {
                (self.defect(lo)?, f)
            };
            if f_lo < 0.0 && f_hi >= 0.0 {
                let (a, b) = if f < 0.0 {
                    (lc_prev, hi)
                } else {
                    (lo, lc_prev)
                };
                return Ok((self.brent(a, b, f_lo, f_hi)?, self.xtol));
            }
            step *= 4.0;
        }
        Err(Error::NoConvergence(
            "lost the root when raising the order".into(),
        ))
    }
}

/// Largest relative difference of the tractions of two discretisations (different orders,
/// nearby c) at points of 0 <= x <= 0.99 placed alike relative to each one's stick edge (x c'
/// / c on the stick zone, 1 - (1 - x) w' / w on the slip zone), so that it measures the
/// discretisation error rather than the shift of c: |dp| / p + |dq| / (mu p).
fn traction_gap(d: &Discrete, other: &Discrete) -> f64 {
    const POINTS: usize = 24;
    let (c, w) = (d.mesh.c, d.mesh.w);
    let (c2, w2) = (other.mesh.c, other.mesh.w);
    (0..POINTS)
        .map(|i| {
            let x = 0.99 * (i as f64 + 0.5) / POINTS as f64;
            let (a, b) = if x < c {
                let x2 = x * c2 / c;
                (Pt { x, u: 1.0 - x }, Pt { x: x2, u: 1.0 - x2 })
            } else {
                let (u, u2) = (1.0 - x, (1.0 - x) * w2 / w);
                (Pt { x, u }, Pt { x: 1.0 - u2, u: u2 })
            };
            let ((p, q), (p2, q2)) = (d.eval(a), other.eval(b));
            (p - p2).abs() / p + (q - q2).abs() / (d.k.mu * p)
        })
        .fold(0.0, f64::max)
}

/// The first violated admissibility condition at the panels' Gauss points, if any: p > 0
/// everywhere (on the slip zones p = q / mu is O(1 / mu) at large friction, so relative
/// accuracy matters) and |q| <= mu p (to 1e-6 relative) on the stick zone.
fn inadmissible(d: &Discrete, mu: f64) -> Option<String> {
    let nodes = gauss_legendre_nodes(7);
    d.mesh.panels.iter().find_map(|panel| {
        nodes.iter().find_map(|&node| {
            let at = if panel.central {
                let x = panel.h * (0.5 * (1.0 + node)).sqrt();
                Pt { x, u: 1.0 - x }
            } else {
                Pt::local(panel.m, panel.h, node)
            };
            let (p, q) = d.eval(at);
            if p <= 0.0 {
                Some(format!("p = {p:.3e} <= 0 near x = {}", at.x))
            } else if panel.stick && q.abs() > mu * p * (1.0 + 1e-6) + 1e-12 {
                Some(format!(
                    "|q| = {:.3e} > mu p = {:.3e} on the stick zone near x = {}",
                    q.abs(),
                    mu * p,
                    at.x
                ))
            } else {
                None
            }
        })
    })
}

/// Solves (E1)-(E4) for `k` to |c - c_exact| <= tol, with the tractions as accurate as
/// that tolerance makes them (see the module documentation; [`solve_to`] sets a traction
/// tolerance of its own).
pub fn solve(k: &Coupling, tol: f64) -> Result<CoupledSolution> {
    k.validate()?;
    validate_tolerance(tol)?;
    if let Some(s) = limit_regime(k, tol, tol) {
        return Ok(s);
    }
    let s = panel_regimes(k, tol, f64::INFINITY)?;
    if s.error > tol {
        return Err(not_met(s.error, tol, &s));
    }
    Ok(s)
}

/// The panels' estimate missing its tolerance (near b* = 1 with the conditioning there as
/// the reason, [`auxetic::conditioning`]).
fn not_met(estimate: f64, tolerance: f64, s: &CoupledSolution) -> Error {
    let r = s.coupling.reduced().0;
    let why = if s.coupling.bp > 0.0 && 1.0 - r.bp < CONDITIONING_NOTE_BELOW {
        format!("; {}", auxetic::conditioning(&r))
    } else {
        String::new()
    };
    Error::ToleranceNotMet {
        estimate,
        tolerance,
        detail: format!(
            "coupled: orders up to {} per panel, {} unknowns (c within {:.1e}, tractions \
             within {:.1e}){why}",
            s.order,
            s.unknowns(),
            s.error,
            s.traction_error
        ),
    }
}

/// 1 - b* below which a missed tolerance names the conditioning near b* = 1 as its reason
/// (the panels' traction estimates stall at about 5e-15 / (1 - b*), [`auxetic`]).
const CONDITIONING_NOTE_BELOW: f64 = 1e-3;

/// Solves (E1)-(E4) for `k` to |c - c_exact| <= tol and a traction error (the norm of
/// [`crate::problem::traction_distance`]) <= traction_tol (+infinity: c alone). A limit
/// regime is taken where its bounds meet both; else the spectral solver
/// (`spectral_from_table`) where it serves the coupling and meets both; else the panels,
/// whose stopping rule asks for
/// c (and a relative traction agreement of about 100 tol) and whose traction estimate came
/// out at up to `TRACTION_PER_C` times their tolerance on c: they are run to
/// min(tol, traction_tol / TRACTION_PER_C), and where the traction estimate still misses
/// traction_tol re-run with the tolerance on c scaled down by the ratio missed (twice over),
/// down to `TIGHTEST`, unless they stopped at their largest order (`at_largest_order`).
pub fn solve_to(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    solve_with(k, tol, traction_tol, true)
}

/// [`solve_to`] without the spectral solver: the panels (and the limit regimes) alone, the
/// independent discretisation the spectral solver is compared with in the tests and in
/// `examples/spectral_timing.rs`.
#[doc(hidden)]
pub fn solve_panels_to(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    solve_with(k, tol, traction_tol, false)
}

/// The spectral solver from its own guess of the stick edge ([`guessed_edge`]), never from
/// the tabulated one: the node solves of `examples/stick_edge_table` in the thin slip zones
/// below b* = 0.25 (so that a regenerated table does not interpolate itself). None where it
/// does not serve the coupling or misses the tolerances (the panels, [`solve`], answer there).
#[doc(hidden)]
pub fn solve_spectral_untabulated(
    k: &Coupling,
    tol: f64,
    traction_tol: f64,
) -> Option<CoupledSolution> {
    k.validate().ok()?;
    validate_tolerance(tol).ok()?;
    spectral_from(k, tol, traction_tol, false)
}

/// [`solve_to`], the spectral solver tried first where `spectral`.
fn solve_with(
    k: &Coupling,
    tol: f64,
    traction_tol: f64,
    spectral: bool,
) -> Result<CoupledSolution> {
    k.validate()?;
    validate_tolerance(tol)?;
    if let Some(s) = limit_regime(k, tol, traction_tol) {
        return Ok(s);
    }
    if traction_tol == f64::INFINITY
        && let Some(s) = tabulated(k, tol)
    {
        return Ok(s);
    }
    if spectral && let Some(s) = spectral_from_table(k, tol, traction_tol) {
        return Ok(s);
    }
    if spectral && let Some(s) = spectral_extrapolation(k, tol, traction_tol) {
        return Ok(s);
    }
    let tol_asked = tol;
    let mut tol = tol.min((traction_tol / TRACTION_PER_C).max(TIGHTEST));
    if traction_tol.is_finite() {
        // small stick zones: the tractions there need c to a relative accuracy (the wrong-c
        // modes they leave out grow with the relative error of c), so at most RELATIVE_C
        // times the full-slip law's c (which is above the exact c)
        tol = tol.min(RELATIVE_C * FullSlip::new(k).numerical_error());
    }
    let asked = tol_asked;
    if let Some(s) = panels_at_table_edge(k, tol_asked, traction_tol) {
        return Ok(s);
    }
    loop {
        // the panels' own tolerance may be missed as long as what was asked for is met
        let s = panel_regimes(k, tol, traction_tol)?;
        let e = s.traction_error();
        if s.error <= asked && e <= traction_tol {
            return Ok(s);
        }
        // panels stopped at their largest order stop there again with c tightened (their
        // traction estimate is the order-to-order distance, which c's tolerance does not
        // lower: thin slip zones, 17-35 s per futile re-run)
        let at_largest = matches!(&s.regime, Regime::Panels(d)
            if at_largest_order(d.mesh.unknowns, s.order));
        if s.error > tol || tol <= TIGHTEST || at_largest {
            return Err(if s.error > asked {
                not_met(s.error, asked, &s)
            } else {
                not_met(e, traction_tol, &s)
            });
        }
        tol = (0.5 * tol * traction_tol / e).min(0.1 * tol).max(TIGHTEST);
    }
}

/// The spectral solver ([`crate::spectral`]) from the tabulated stick edge, where the table
/// covers the reduced coupling below [`MU_EXTRAPOLATE`] ([`crate::spectral::from_edge`]: at
/// that edge where its bound meets `tol`, else by the root search started there), else from
/// a guessed stick edge ([`guessed_edge`], [`crate::spectral::from_guess`]); None where neither meets the
/// tolerances (the panels answer there).
fn spectral_from_table(k: &Coupling, tol: f64, traction_tol: f64) -> Option<CoupledSolution> {
    spectral_from(k, tol, traction_tol, true)
}

/// Large friction below the bases' smallest edge exponent (`spectral::G_MIN`): the
/// extrapolation in 1/mu~ ([`large_friction`]) from the spectral solutions at the four nodes
/// of [`large_friction::spectral_nodes`] (each asked [`large_friction::SHARE`] of the
/// tolerances); None where a node does not answer or the extrapolation's estimates miss the
/// tolerances (the panels' regimes answer there).
fn spectral_extrapolation(k: &Coupling, tol: f64, traction_tol: f64) -> Option<CoupledSolution> {
    if k.bp == 0.0 {
        return None;
    }
    let (r, delta) = k.reduced();
    let mus = large_friction::spectral_nodes(r.bp);
    if r.edge_exponent() >= crate::spectral::G_MIN || r.mu <= mus[3] {
        return None;
    }
    let share = large_friction::SHARE;
    let mut sols = Vec::with_capacity(mus.len());
    for mu in mus {
        let at = Coupling { mu, ..r };
        sols.push(spectral_from_table(
            &at,
            share * tol,
            share * traction_tol / delta.max(1.0),
        )?);
    }
    let l = LargeFriction::from_nodes(k, mus, sols.try_into().ok()?);
    if l.numerical_error() > tol || l.traction_error() > traction_tol {
        return None;
    }
    let order = l.order();
    let mut s = CoupledSolution::from_profile(l, |l| Regime::LargeFriction(Box::new(l)));
    s.order = order;
    Some(s)
}

/// [`spectral_from_table`], with the table left out where not `table`: from Spence's stick
/// edge everywhere (the tests compare both starts where the table covers the coupling).
fn spectral_from(
    k: &Coupling,
    tol: f64,
    traction_tol: f64,
    table: bool,
) -> Option<CoupledSolution> {
    if k.bp == 0.0 {
        return None;
    }
    let (r, delta) = k.reduced();
    if r.mu >= MU_EXTRAPOLATE {
        return None;
    }
    let consts = crate::spectral::Constants {
        b: r.bp,
        mu: r.mu,
        g: r.edge_exponent(),
    };
    let tabulated = if table {
        crate::stick_edge_table::lookup(r.bp, r.mu)
            .or_else(|| {
                // below the table's smallest b*, the weak-coupling law's edge
                let (e, bound) = weak_coupling::applies(r.bp).then(|| table_edge(k))??;
                Some((e.logit(), bound))
            })
            .filter(|_| known_edge_starts_spectral(r.bp))
    } else {
        None
    };
    let s = match tabulated {
        Some((lc, bound)) => {
            crate::spectral::from_edge(consts, lc, bound, tol, traction_tol, delta)?
        }
        None => {
            // outside the table (below b* = 0.25 above its strips' tops there,
            // [`crate::stick_edge_table`]): from the best guess of the stick edge
            let e = guessed_edge(k, &r)?;
            let lc0 = e.logit();
            crate::spectral::from_guess(consts, lc0, tol, traction_tol, delta)?
        }
    };
    Some(CoupledSolution {
        coupling: *k,
        edge: s.edge,
        error: s.error,
        traction_error: s.traction_parts.0 + delta * s.traction_parts.1,
        delta,
        order: s.level,
        regime: Regime::Spectral(Box::new(s)),
    })
}

/// Below b* = [`KNOWN_EDGE_B`] the tabulated stick edge starts the panels' tractions
/// ([`panels_at_table_edge`]) only where 1 - c is at least [`KNOWN_EDGE_MIN`], the thinnest
/// slip zone at the nodes of the table's first strips there, where that start was checked
/// against the panels' root search over the 8 x 28 grid of
/// `tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid`. The spectral
/// solver's start ([`crate::spectral::from_edge`]) takes the thin slip zones' strips too
/// ([`known_edge_starts_spectral`]). The small stick zones' strips (c = 1e-11 .. 1.3e-5,
/// which the guessed start does not serve) take the known edge: the 10 points of them on the
/// 53 x 53 grid of `tests::spectral_agrees_with_the_panels_on_a_grid` agree with the panels
/// (1114 of 1114 served points answered there). Above b* = [`KNOWN_EDGE_B_MAX`] (the strips
/// towards the auxetic limit, for c alone) the panels' own root search and the auxetic limit
/// answer the tractions, as before those strips. Below the table's smallest b* the known edge
/// is the weak-coupling law's ([`weak_coupling`]; at 12 points of b* = 1e-3 .. 0.019,
/// 1 - c >= 3.6e-5, the panels at it lay within both estimates of the root search's
/// tractions, `tests/stick_edge_table.rs`).
fn known_edge_serves_tractions(b: f64, edge: StickEdge) -> bool {
    b <= KNOWN_EDGE_B_MAX && (b >= KNOWN_EDGE_B || edge.one_minus_c >= KNOWN_EDGE_MIN)
}

/// Whether the tabulated stick edge starts the spectral solver's tractions
/// ([`crate::spectral::from_edge`]): up to b* = [`KNOWN_EDGE_B_MAX`], the thin slip zones'
/// strips below b* = 0.25 and the weak-coupling law's edge below b* = 0.02 included. In thin
/// slip zones the level's distance to its coarser columns is taken on the graded panels of
/// the root search (`spectral::graded_distance`), with the rounding spread below
/// 1 - c = 5e-9, as the root search takes them: with the plain Gauss points of the
/// mid-range, b* = 0.2, mu~ = 7.92 (1 - c = 3.0e-9) answered at level 2 with tractions
/// 1.02e-8 off the panels' (to 1e-10) against an estimate of 4.9e-9. With both, against the
/// panels' root search (one run each; the ratio is the tractions' distance over the sum of
/// both estimates):
/// - the 8 x 28 grid of `tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid`
///   at (1e-10, 1e-8): the 96 tabulated points (1 - c down to 2.8e-13) all answered from the
///   table and agreed, in a median 0.30 ms against 5.37 ms from the guessed start;
/// - below b* = 0.02 (the weak-coupling edge; b* = 0.005, 0.01, 0.015, 0.019 at
///   1 - c = 1e-5, 1e-7, 1e-9, 1e-11, 1e-13): at (1e-10, 1e-8) 16 of 20 answered (1 - c down
///   to 1.0e-11) in 1.0-16 ms, ratios at most 0.49, against the panels' 0.2-36 s; at
///   (1e-10, 1e-10) 13 of 20 answered (1 - c down to 1.3e-11) in 1.1-51 ms, ratios at most
///   0.28; the others went to the panels, which had answered every point below
///   1 - c = [`KNOWN_EDGE_MIN`] before.
fn known_edge_starts_spectral(b: f64) -> bool {
    b <= KNOWN_EDGE_B_MAX
}

/// See [`known_edge_serves_tractions`]: the table's largest b* before its strips towards the
/// auxetic limit.
const KNOWN_EDGE_B_MAX: f64 = 0.99;

/// See [`known_edge_serves_tractions`]: the table's b* above which every strip starts at the
/// full-slip law's c = 1e-11.
const KNOWN_EDGE_B: f64 = 0.25;

/// See [`known_edge_serves_tractions`]: the thinnest slip zone at the nodes of the first
/// strips below b* = 0.25.
const KNOWN_EDGE_MIN: f64 = 1.3e-5;

/// Where the near-bonded law ([`near_bonded`]) covers b* and puts 1 - c below this, the
/// spectral solver outside the table starts from the law's stick edge, elsewhere from
/// Spence's. On the 53 points outside the table with a spectral answer among the 7 + 4 thin
/// slip zones of `tests::thin_slip_zones_agree_with_the_panels` and
/// `tests::thin_slip_zones_at_small_g_agree_with_the_panels` and the grid of
/// `tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid` (1 - c = 2.8e-13 ..
/// 1.1e-4; c to 1e-10, tractions to 1e-8; thread CPU time, the starts alternated in one run):
///
/// | start | answered | total | per thin slip zone (1 - c < 1e-9) |
/// |---|---|---|---|
/// | Spence's | 53 | 2.27-2.38 s | 42-95 ms |
/// | the law below 1 - c = 1e-3 | 53 | 1.75-1.88 s | 30-69 ms |
/// | the law below 1 - c = 1e-2 | 53 | 1.77 s | 31-69 ms |
///
/// Spence's stick edge is far off in thin slip zones (his 1 - c = 6e-6 against 8.3e-13 at
/// b* = 0.15, mu~ = 10, 15.8 in lc), the law's 1.3e-12 there (0.45 in lc).
const LAW_START_BELOW: f64 = 1e-3;

/// The stick edge the spectral solver starts from outside the table ([`LAW_START_BELOW`]).
fn guessed_edge(k: &Coupling, reduced: &Coupling) -> Option<StickEdge> {
    let law = NearBonded::new(k);
    if law.covered() && law.edge().one_minus_c < LAW_START_BELOW {
        return Some(law.edge());
    }
    Some(crate::spence::solve(reduced).ok()?.edge())
}

/// The closed-form regimes, where they meet the tolerances: mu = 0 (p = p0, q = 0), bp = 0
/// (Goodman's closed form is exact), a stick zone below the tolerance ([`full_slip`]), slip
/// zones below it ([`near_bonded`]) and b* small enough for Goodman's bounds in b*^2
/// ([`weak_coupling::goodman_bounds`]).
fn limit_regime(k: &Coupling, tol: f64, traction_tol: f64) -> Option<CoupledSolution> {
    if k.mu == 0.0 {
        return Some(CoupledSolution {
            coupling: *k,
            edge: StickEdge::from_c(0.0),
            error: 0.0,
            traction_error: 0.0,
            delta: 1.0,
            regime: Regime::Frictionless,
            order: 0,
        });
    }
    if k.bp == 0.0 {
        let g = crate::goodman::solve(k).ok()?;
        return Some(CoupledSolution::from_profile(g, Regime::Uncoupled));
    }
    let meets = |p: &dyn Profile| p.numerical_error() <= tol && p.traction_error() <= traction_tol;
    let fs = FullSlip::new(k);
    if meets(&fs) {
        return Some(CoupledSolution::from_profile(fs, Regime::FullSlip));
    }
    let nb = NearBonded::new(k);
    if nb.covered() && meets(&nb) {
        return Some(CoupledSolution::from_profile(nb, Regime::NearBonded));
    }
    // b* -> 0: Goodman's solution within its bounds in b*^2
    let (r, delta) = k.reduced();
    let (c_bound, traction_bound) = weak_coupling::goodman_bounds(r.bp, delta);
    if c_bound > tol || traction_bound > traction_tol {
        return None;
    }
    let mut s = CoupledSolution::from_profile(crate::goodman::solve(k).ok()?, Regime::Uncoupled);
    s.error += c_bound;
    s.traction_error += traction_bound;
    (s.error <= tol && s.traction_error <= traction_tol).then_some(s)
}

/// The tabulated stick edge ([`crate::stick_edge_table`]) and its bound (from
/// [`MU_EXTRAPOLATE`] on, extrapolated in 1/mu~ from the table as [`large_friction`] does from
/// the panels; in the auxetic limit above the table's last strip, extrapolated in 1 - b* from
/// the table's c at the auxetic nodes as [`auxetic`] does from the panels; below its smallest
/// b*, Goodman's edge corrected by the table's difference from it, extrapolated in b*^2
/// ([`weak_coupling`])), where the table covers the coupling.
fn table_edge(k: &Coupling) -> Option<(StickEdge, f64)> {
    let (r, _) = k.reduced();
    if weak_coupling::applies(r.bp) {
        let zeta = crate::stick_edge_table::coordinates(r.bp, r.mu).1;
        let node = |b: f64| {
            let mu = crate::stick_edge_table::coupling_at(b.atanh(), zeta).1;
            let (table, bound) = table_edge(&Coupling { bp: b, bq: b, mu })?;
            let goodman = crate::goodman::stick_edge(b / mu);
            Some(weak_coupling::Node {
                table,
                bound,
                goodman,
            })
        };
        let [n0, n1, n2] = weak_coupling::NODE_B.map(node);
        let goodman = crate::goodman::stick_edge(r.bp / r.mu);
        return Some(weak_coupling::extrapolate(r.bp, goodman, [n0?, n1?, n2?]));
    }
    if auxetic::applies(&r) {
        let (mut c, mut error) = ([0.0; 4], [0.0; 4]);
        for (i, node) in auxetic::nodes(&r).iter().enumerate() {
            let (e, bound) = table_edge(node)?;
            (c[i], error[i]) = (e.c, bound);
        }
        return Some(auxetic::extrapolate(&r, c, error));
    }
    let at = |mu: f64| {
        crate::stick_edge_table::lookup(r.bp, mu)
            .map(|(lc, bound)| (StickEdge::from_logit(lc), bound))
    };
    let extrapolated = |m: f64| {
        let [e0, e1, e2] = large_friction::nodes(m).map(at);
        let (e0, e1, e2) = (e0?, e1?, e2?);
        let (edge, error, _) = large_friction::extrapolate_edge(
            r.mu,
            large_friction::nodes(m),
            [e0.0, e1.0, e2.0],
            [e0.1, e1.1, e2.1],
        );
        Some((edge, error))
    };
    let from_top = || {
        let zeta = crate::stick_edge_table::top(r.bp)?;
        let top = crate::stick_edge_table::coupling_at(r.bp.atanh(), zeta).1;
        let g = Coupling { mu: top, ..r }.edge_exponent();
        (r.mu > top && g <= TOP_NODE_G).then(|| extrapolated(0.25 * top))?
    };
    if r.mu >= MU_EXTRAPOLATE {
        extrapolated(large_friction::M).or_else(from_top)
    } else {
        at(r.mu).or_else(from_top)
    }
}

/// Largest edge exponent g at the top of the table's strip at which [`table_edge`]
/// extrapolates in 1/mu~ from the top down (nodes at top / 4, top / 2 and the top itself).
/// The strips of b* = 0.16 .. 0.25 end at g = 0.0025, where the edge is analytic in 1/mu~
/// ([`large_friction`]): measured with the panels at b* = 0.2, lc = 20.8700297 (mu~ = 500,
/// the table's top 637), 20.8778522 (1e3), 20.8817410 (2e3), 20.8836819 (4e3), differences
/// 7.82e-3, 3.89e-3, 1.94e-3 in the ratio 2.01, 2.003 of the leading 1/mu~ term, and c moving
/// by 1.2e-11 in all (1 - c = 8.63e-10 .. 8.52e-10). The strips below b* = 0.16 end at fixed
/// zeta where g is 0.2 and more (b* = 0.16, zeta = 6.6: mu~ = 7.2, g = 0.23), far from that
/// expansion; the near-bonded law answers c alone above them.
const TOP_NODE_G: f64 = 0.01;

/// c alone: the tabulated stick edge where its bound meets `tol`, with Goodman's tractions
/// and their model-error bound (+infinity where the model-error table gives none: no
/// traction tolerance was asked for).
fn tabulated(k: &Coupling, tol: f64) -> Option<CoupledSolution> {
    let (edge, error) = table_edge(k).filter(|&(_, error)| error <= tol)?;
    let goodman = crate::goodman::solve(k).ok()?;
    let traction_error =
        crate::model_error::traction_bound(Approximation::Goodman, k).unwrap_or(f64::INFINITY);
    Some(CoupledSolution {
        coupling: *k,
        edge,
        error,
        traction_error: traction_error + goodman.traction_error(),
        delta: 1.0,
        regime: Regime::Tabulated(goodman),
        order: 0,
    })
}

/// The panels at the tabulated stick edge, where its bound meets `tol` (below
/// [`MU_EXTRAPOLATE`]) and their estimate meets `traction_tol` ([`panels_at_edge`], the
/// sensitivity to c measured at [`SENSITIVITY_ORDER`]); None where they miss it, where the
/// sensitivity alone takes half the traction tolerance (large friction, b* -> 1: up to 1.2e-9
/// for the table's 3e-12) or the solution is inadmissible: the root search decides there.
fn panels_at_table_edge(k: &Coupling, tol: f64, traction_tol: f64) -> Option<CoupledSolution> {
    if k.reduced().0.mu >= MU_EXTRAPOLATE {
        return None;
    }
    let (edge, error) = table_edge(k).filter(|&(_, error)| error <= tol)?;
    if !known_edge_serves_tractions(k.reduced().0.bp, edge) {
        return None;
    }
    panels_at_edge(k, edge, error, traction_tol, Sensitivity::AtFirstOrder)
        .filter(|s| s.traction_error <= traction_tol)
}

/// Where [`panels_at_edge`] measures how the tractions move with c.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sensitivity {
    /// Once, at [`SENSITIVITY_ORDER`], the first of [`ORDERS`] (a rate of change needs no
    /// more, and is cheap there); where it alone takes half the traction tolerance, no
    /// solution.
    AtFirstOrder,
    /// At each order whose estimate meets the traction tolerance without it (the auxetic
    /// limit, where order 6 is far from converged: at b* = 1 - 1e-5, mu~ = 10 its measure took
    /// the whole tolerance 1e-8 for an error of 1e-10 c in c).
    AtFinalOrder,
}

/// The panels at a given stick edge, known within `error`: no root search, one solve per
/// order ([`ORDERS`]) at that c, until the traction estimate meets `traction_tol`, at
/// [`system::oversample_at_known_c`]. The estimate is [`ORDER_SAFETY`] times the distance of
/// the last two orders' tractions, plus the norm of the wrong-c modes they leave out (as in
/// [`panels_from`]), plus what the error in c moves the tractions: ORDER_SAFETY times the
/// distance of the tractions at c and at lc + [`SENSITIVITY_STEP`], scaled to `error`
/// (linear in it), measured where `sensitivity` says. Returns the first order's solution that
/// meets `traction_tol`, else the largest order's (its estimate above `traction_tol`, without
/// the sensitivity in [`Sensitivity::AtFinalOrder`]); None where a solve fails, the
/// sensitivity at the first order takes half the tolerance or the solution is inadmissible.
fn panels_at_edge(
    k: &Coupling,
    edge: StickEdge,
    error: f64,
    traction_tol: f64,
    sensitivity_at: Sensitivity,
) -> Option<CoupledSolution> {
    let (consts, delta) = reduced_constants(k);
    let oversample = system::oversample_at_known_c(traction_tol);
    let (c, w) = (edge.c, edge.one_minus_c);
    let (c2, w2) = edge_of(c.ln() - w.ln() + SENSITIVITY_STEP);
    let layout = Layout::for_edge(c, w);
    let mut ls = LeastSquares::default();
    let mut prev: Option<Discrete> = None;
    let mut sensitivity = 0.0;
    for &n in &ORDERS {
        let fams = Families::new(consts.g, n);
        let model = prev
            .as_ref()
            .filter(|_| system::weighs_rows(w, traction_tol));
        let mut solve =
            |c, w| solve_fixed(consts, c, w, n, &fams, &layout, oversample, &mut ls, model);
        let d = solve(c, w).ok()?;
        // ORDER_SAFETY times the distance to the tractions at lc + SENSITIVITY_STEP, per error
        let mut measure = || -> Option<f64> {
            let shifted = solve(c2, w2).ok()?;
            Some(
                ORDER_SAFETY * d.traction_distance(&shifted, delta) * error
                    / (c * w * SENSITIVITY_STEP),
            )
        };
        if sensitivity_at == Sensitivity::AtFirstOrder && n == SENSITIVITY_ORDER {
            sensitivity = measure()?;
            if sensitivity > 0.5 * traction_tol {
                // c is not known accurately enough for these tractions
                return None;
            }
        }
        let largest = at_largest_order(d.mesh.unknowns, n);
        if let Some(p) = &prev {
            let mut traction_error = ORDER_SAFETY * d.traction_distance(p, delta)
                + d.wrong_c_norm(delta, error)
                + sensitivity;
            if sensitivity_at == Sensitivity::AtFinalOrder && traction_error <= traction_tol {
                traction_error += measure()?;
            }
            if traction_error <= traction_tol || largest {
                let admissible = inadmissible(&d, consts.mu).is_none();
                return admissible.then_some(CoupledSolution {
                    coupling: *k,
                    edge,
                    error,
                    traction_error,
                    delta,
                    regime: Regime::Panels(d),
                    order: n,
                });
            }
        }
        if largest {
            return None;
        }
        prev = Some(d);
    }
    None
}

/// The panels ([`panels`]), or their extrapolation in 1/mu~ ([`large_friction`]): in thin
/// slip zones at large friction from lower nodes ([`thin_extrapolation`]), else beyond
/// [`MU_EXTRAPOLATE`]; or, near b* = 1, in b* ([`auxetic`]).
fn panel_regimes(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    let base = (k.bp > 0.0).then(|| k.reduced().0).and_then(|r| {
        thin_extrapolation(&r).or((r.mu >= MU_EXTRAPOLATE).then_some(large_friction::M))
    });
    if let Some(m) = base {
        let l = LargeFriction::new(k, m, tol, traction_tol)?;
        let order = l.order();
        let mut s = CoupledSolution::from_profile(l, |l| Regime::LargeFriction(Box::new(l)));
        s.order = order;
        return Ok(s);
    }
    panels_or_auxetic(k, tol, traction_tol)
}

/// The panels ([`panels`]), or near b* = 1 the auxetic limit ([`auxetic`]).
fn panels_or_auxetic(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    if k.bp > 0.0 && auxetic::applies(&k.reduced().0) {
        auxetic::solve(k, tol, traction_tol)
    } else {
        panels(k, tol, traction_tol)
    }
}

/// A node of the extrapolations in 1/mu~ ([`large_friction`], by [`panels_or_auxetic`]) and
/// in 1 - b* ([`auxetic`], by [`panel_regimes`]): `solve` at (k, tol, traction_tol).
fn node_solve(
    k: &Coupling,
    tol: f64,
    traction_tol: f64,
    solve: fn(&Coupling, f64, f64) -> Result<CoupledSolution>,
) -> Result<CoupledSolution> {
    #[cfg(test)]
    {
        tests::memo_node(k, tol, traction_tol, solve)
    }
    #[cfg(not(test))]
    {
        solve(k, tol, traction_tol)
    }
}

/// Thin slip zones at large friction: where the near-bonded law's window lies beyond
/// [`THIN_EXTRAPOLATE`] in lc and g < [`SMALL_G`], the panels' root search is unreliable (b*
/// = 0.1, mu~ = 1e4: order 22 and 4 min, or no answer; b* = 0.12, mu~ = 2e5: the layouts
/// disagree on the defect's sign); the lowest node of the extrapolation from below
/// ([`large_friction::thin_base`]) there.
fn thin_extrapolation(r: &Coupling) -> Option<f64> {
    let (lo, hi) = near_bonded::ln_w_range(r.bp, r.mu)?;
    (r.edge_exponent() < SMALL_G && -0.5 * (lo + hi) > THIN_EXTRAPOLATE)
        .then(|| large_friction::thin_base(r.bp))
}

/// The lc = ln(c / (1 - c)) of the near-bonded window's centre beyond which thin slip zones
/// at large friction are extrapolated (1 - c = 1.7e-15; b* = 0.12 at large friction: 37.6).
const THIN_EXTRAPOLATE: f64 = 34.0;

/// The system's constants of the reduced coupling (bp = bq = b*, mu~; `k` itself when
/// bp = 0) and delta (q = delta q~).
fn reduced_constants(k: &Coupling) -> (Constants, f64) {
    let (r, delta) = if k.bp > 0.0 { k.reduced() } else { (*k, 1.0) };
    let consts = Constants {
        bp: r.bp,
        bq: r.bq,
        mu: r.mu,
        g: r.edge_exponent(),
    };
    (consts, delta)
}

/// The panel discretisation of (E1)-(E4) for `k` (mu > 0) to |c - c_exact| <= tol and a
/// traction estimate <= traction_tol, or, where no search reaches that, the one with the
/// smallest estimate of c (the callers compare).
fn panels(k: &Coupling, tol: f64, traction_tol: f64) -> Result<CoupledSolution> {
    let (consts, delta) = reduced_constants(k);
    let oversample = search_oversample(tol, &consts);
    // the first root (where the near-bonded law predicts thin slip zones inside its window,
    // else scanned from below at the cheap order, then at the robust one), its slope, then
    // the orders in turn
    let window = near_bonded::ln_w_range(consts.bp, consts.mu)
        .filter(|&(_, hi)| consts.bp > 0.0 && hi < WINDOW_BELOW.ln())
        .map(|(lo, hi)| (-hi - WINDOW_MARGIN, -lo + WINDOW_MARGIN));
    let lc0 = goodman_guess(consts.bq, consts.mu);
    let scans = search_orders(consts.g, SCAN_ORDERS).map(|order| Start::Scan(lc0, order));
    let starts: Vec<Start> = match window {
        Some((lo, hi)) if too_thin(lo, hi) => {
            let mid = 0.5 * (lo + hi);
            return Err(Error::NoConvergence(format!(
                "the slip zones (1 - c ~ {:.0e} by the near-bonded law) are too thin for the \
                 panels (1 - c above about {:.0e}, and at most {MAX_UNKNOWNS} unknowns at \
                 order {THIN_FINAL_ORDER}: {} there), and the bonded limit's bounds miss the \
                 tolerances",
                edge_of(mid).1,
                edge_of(T_MAX - WINDOW_MARGIN - 1.0).1,
                thin_unknowns(mid).map_or("no layout".into(), |u| u.to_string())
            )));
        }
        Some((lo, hi)) => search_orders(consts.g, window_orders(hi))
            .map(|n| Start::Window(lo, hi, n))
            .to_vec(),
        None => scans.to_vec(),
    };
    let mut best: Option<CoupledSolution> = None;
    let mut failure = Error::Internal("coupled: no root search tried".into());
    // inadmissible roots found: (c, 1 - c, what fails)
    let mut inadmissible_roots: Vec<(f64, f64, String)> = Vec::new();
    let mut starts = starts.into_iter();
    let mut rescan = None;
    loop {
        let start = match starts.next() {
            Some(start) => start,
            // the scan may have started beyond the first root (its start's defect < 0 on a
            // later lobe): once more from far below, at the robust order
            None if rescan.is_none() && !inadmissible_roots.is_empty() && best.is_none() => {
                rescan = Some(inadmissible_roots.len());
                Start::Scan(RESCAN_FROM, search_orders(consts.g, SCAN_ORDERS)[1])
            }
            None => break,
        };
        let tols = (tol, traction_tol);
        match panels_from(k, tols, consts, delta, oversample, start) {
            Ok((s, Some(why))) => {
                let e = s.edge;
                inadmissible_roots.push((e.c, e.one_minus_c, why));
            }
            Ok((s, None)) if s.error <= tol => return Ok(s),
            Ok((s, None)) => {
                if best.as_ref().is_none_or(|b| s.error < b.error) {
                    best = Some(s);
                }
            }
            Err(e) => failure = e,
        }
    }
    if let Some(s) = best {
        return Ok(s);
    }
    // no admissible solution of this form: only where two searches (the scan from Goodman's
    // c and the one from far below) end on the same inadmissible root; else the searches
    // are not to be trusted there
    match inadmissible_roots.as_slice() {
        [] => Err(failure),
        [(c, w, why), rest @ ..] => {
            let same = |(c2, w2, _): &(f64, f64, String)| {
                (c2 - c).abs() <= 1e-6 * c.min(*w) || (w2 - w).abs() <= 1e-6 * c.min(*w)
            };
            let message = format!(
                "the first root of the stick-edge condition, c = {c} (1 - c = {w:e}), is \
                 inadmissible: {why}"
            );
            let rescan_agrees = rescan.is_some_and(|i| i < inadmissible_roots.len());
            if rescan_agrees && rest.iter().all(same) {
                Err(Error::NoAdmissibleSolution(message))
            } else {
                Err(Error::NoConvergence(format!(
                    "{message}; a second search ended elsewhere or not at all"
                )))
            }
        }
    }
}

/// Collocation points per unknown of a root search to tolerance `tol` on c: near the
/// defect's rounding noise the finer (costlier) oversampling, but not near b* = 1
/// ([`FINE_B_BELOW`]).
fn search_oversample(tol: f64, k: &Constants) -> f64 {
    if tol < FINE_BELOW && k.bp < FINE_B_BELOW {
        system::OVERSAMPLE_FINE
    } else {
        system::OVERSAMPLE
    }
}

/// The root search from a window (lo, hi) of lc = ln(c / (1 - c)) known to hold the root
/// (the auxetic limit's, around its extrapolated c), at the window orders in turn: the first
/// admissible solution ([`panels_from`]: it may miss the tolerances, the caller compares).
fn panels_in_window(
    k: &Coupling,
    tol: f64,
    traction_tol: f64,
    (lo, hi): (f64, f64),
) -> Option<CoupledSolution> {
    let (consts, delta) = reduced_constants(k);
    let oversample = search_oversample(tol, &consts);
    WINDOW_ORDERS.iter().find_map(|&n| {
        let start = Start::Window(lo, hi, n);
        match panels_from(k, (tol, traction_tol), consts, delta, oversample, start) {
            Ok((s, None)) => Some(s),
            _ => None,
        }
    })
}

/// Where the search for the first root starts.
#[derive(Clone, Copy, Debug)]
enum Start {
    /// Scan from below, from lc0 (or lower) up, at the given order.
    Scan(f64, usize),
    /// The sign change inside the window (lo, hi) of lc, at the given order.
    Window(f64, f64, usize),
}

impl Start {
    /// The order the first root is found at.
    fn order(self) -> usize {
        match self {
            Start::Scan(_, order) | Start::Window(_, _, order) => order,
        }
    }
}

/// [`panels`] with the first root found from `start`: the solution at the first order pair
/// that agrees (c within tol, and the tractions' estimate within traction_tol and their
/// relative gap within [`TRACTION_RATIO`] tol), else at the pair with the smallest traction
/// gap once the orders have drifted [`DRIFT`] times above it or reached their largest, and
/// what makes it inadmissible, if anything.
fn panels_from(
    k: &Coupling,
    (tol, traction_tol): (f64, f64),
    consts: Constants,
    delta: f64,
    oversample: f64,
    start: Start,
) -> Result<(CoupledSolution, Option<String>)> {
    let mut root = first_root(consts, start, oversample)?;
    let mut best: Option<OrderPair> = None;
    for &n in ORDERS.iter().filter(|&&n| n > start.order()) {
        let tols = (tol, traction_tol / delta.max(1.0));
        let next = root_at_order(consts, n, &root, tols, oversample, start)?;
        let diff = order_difference(&root, &next);
        let gap = traction_gap(&next.discrete, &root.discrete);
        let close = diff <= tol && gap <= (TRACTION_RATIO * tol).max(TRACTION_FLOOR);
        let last = at_largest_order(next.discrete.mesh.unknowns, n);
        let drifted = best.as_ref().is_some_and(|b| gap > DRIFT * b.gap);
        let lower = std::mem::replace(&mut root, next);
        let pair = OrderPair {
            order: n,
            diff,
            gap,
            lower: lower.discrete,
            upper: root.discrete.clone(),
        };
        if last || drifted || (close && pair.traction_error(delta) <= traction_tol) {
            // met, or the best this search reaches (the callers compare its estimates with
            // what they were asked for)
            let pair = match best {
                Some(b) if !close && b.gap < pair.gap => b,
                _ => pair,
            };
            return Ok(pair.solution(k, delta));
        }
        if best.as_ref().is_none_or(|b| pair.gap < b.gap) {
            best = Some(pair);
        }
    }
    Err(Error::Internal("coupled: order loop fell through".into()))
}

/// How far the traction gap of two successive orders may rise above the smallest one seen
/// before the orders count as drifting in rounding noise: near b* = 1 at large friction the
/// orders past 19 drift (b* = 0.99998, mu~ = 4e6: at order 34 the gap stood at 1e-6 and c
/// 3.4e-10 from order 19's, although orders 30 and 34 agreed on c within 2e-13).
const DRIFT: f64 = 100.0;

/// Two successive orders' discretisations at their roots: the upper one is the solution,
/// the lower one estimates its errors.
struct OrderPair {
    /// The upper order.
    order: usize,
    /// The error estimate of the upper order's c ([`order_difference`]).
    diff: f64,
    /// Their relative traction gap ([`traction_gap`]).
    gap: f64,
    lower: Discrete,
    upper: Discrete,
}

impl OrderPair {
    /// The traction estimate: [`ORDER_SAFETY`] times the distance of the two orders'
    /// tractions, plus the norm of the wrong-c modes left out of the upper one.
    fn traction_error(&self, delta: f64) -> f64 {
        ORDER_SAFETY * self.upper.traction_distance(&self.lower, delta)
            + self.upper.wrong_c_norm(delta, self.diff)
    }

    /// The upper order's solution of `k` with its estimates, and what makes it
    /// inadmissible, if anything.
    fn solution(self, k: &Coupling, delta: f64) -> (CoupledSolution, Option<String>) {
        let traction_error = self.traction_error(delta);
        let (c, w) = (self.upper.mesh.c, self.upper.mesh.w);
        let edge = if c < 0.5 {
            StickEdge::from_c(c)
        } else {
            StickEdge::from_one_minus_c(w)
        };
        let violation = inadmissible(&self.upper, self.upper.k.mu);
        let s = CoupledSolution {
            coupling: *k,
            edge,
            error: self.diff,
            traction_error,
            delta,
            regime: Regime::Panels(self.upper),
            order: self.order,
        };
        (s, violation)
    }
}

/// The first root from `start`, at its order.
fn first_root(consts: Constants, start: Start, oversample: f64) -> Result<Root> {
    let n = start.order();
    let fams = Families::new(consts.g, n);
    let mut level = Level::new(
        consts,
        n,
        &fams,
        SCAN_XTOL,
        oversample,
        Default::default(),
        None,
    );
    let lc = level.root_from(start)?;
    Ok(Root {
        lc,
        unc: level.xtol,
        slope: level.slope(lc),
        step: 1.0,
        discrete: level.discrete_at(lc)?,
        ls: level.ls,
    })
}

/// One order's root: lc = ln(c / (1 - c)), its distance from the order's exact root (unc),
/// the slope of the defect there, the step from the previous order's root, the
/// discretisation at lc and the least-squares solver's state (passed on to the next order).
struct Root {
    lc: f64,
    unc: f64,
    slope: f64,
    step: f64,
    discrete: Discrete,
    ls: LeastSquares,
}

/// The root at order n, started from the previous order's root and slope; if that fails
/// (a step left the layout's range or the root moved away), the first-root search again
/// (scan from below at the scan order, Brent at this order). Each order locates its root to
/// 5% of the tolerance in c (dc = c (1 - c) d lc) and of the traction tolerance.
fn root_at_order(
    consts: Constants,
    n: usize,
    prev: &Root,
    (tol, traction_tol): (f64, f64),
    oversample: f64,
    start: Start,
) -> Result<Root> {
    let (c_prev, w_prev) = edge_of(prev.lc);
    // the wrong-c modes left out of the tractions count in their estimate in proportion to
    // the defect left at the root ([`Discrete::wrong_c_norm`]): 5% of the traction tolerance
    // at most (at c = 8.5e-7, the auxetic b* = 1 - 5e-7, mu~ = 10, the tolerance on c alone
    // left a defect whose modes weighed 5e-8). Their norm grows as the error in c falls below
    // the panel at c, so it is taken at no more than the error in c the loosest xtol leaves
    // (b* = 0.15, mu~ = 1e3, 1 - c = 2e-13: taken at the tolerance on c, 2e-12, it was 0, the
    // root stayed 2e-4 off in lc, and the modes made 1.9e-10 of the traction estimate)
    let dc = tol.min(c_prev * w_prev * LOOSEST_XTOL);
    let per_lc = prev.slope.abs() * prev.discrete.wrong_c_per_defect(dc);
    let xtol = (0.05 * tol / (c_prev * w_prev))
        .min(0.05 * traction_tol / per_lc)
        .clamp(1e-13, LOOSEST_XTOL);
    let fams = Families::new(consts.g, n);
    let model = system::weighs_rows(w_prev, traction_tol).then(|| prev.discrete.clone());
    let mut level = Level::new(consts, n, &fams, xtol, oversample, prev.ls, model.clone());
    let (lc, unc) = match level.root_near(prev.lc, prev.slope, prev.step) {
        Ok(r) => r,
        Err(_) => {
            level = Level::new(consts, n, &fams, xtol, oversample, level.ls, model);
            (level.root_from(start)?, xtol)
        }
    };
    let discrete = level.discrete_at(lc)?;
    // the slope of this order if it made two evaluations near its root
    let slope = Some(level.slope(lc))
        .filter(|s| s.is_finite())
        .unwrap_or(prev.slope);
    Ok(Root {
        lc,
        unc,
        slope,
        step: (lc - prev.lc).abs(),
        discrete,
        ls: level.ls,
    })
}

/// The error estimate of `next`'s c from two successive orders: |c - c_prev| from whichever
/// of c, 1 - c is small, or, if the previous order's point was already within xtol of this
/// order's root, the step to it (dc = c (1 - c) d lc). ORDER_SAFETY times that (orders 2-3
/// apart, the error does not always fall far below the lower order's), plus the distances
/// of both evaluated points from their order's root.
fn order_difference(prev: &Root, next: &Root) -> f64 {
    let (c_prev, w_prev) = edge_of(prev.lc);
    let (c, w) = edge_of(next.lc);
    let own = c * w * next.unc;
    let dc = if next.lc == prev.lc {
        own
    } else if c < 0.5 {
        (c - c_prev).abs()
    } else {
        (w - w_prev).abs()
    };
    ORDER_SAFETY * dc + own + c * w * prev.unc
}
