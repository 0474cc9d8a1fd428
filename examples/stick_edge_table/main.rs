//! Regenerates `src/stick_edge_table/table.rs`: COUPLED's stick edge lc = ln(c / (1 - c)) as
//! piecewise Chebyshev interpolants over the table's coordinates (beta, zeta)
//! ([`orthoslip::stick_edge_table`]), with a validated bound per patch.
//!
//! Run: `cargo run --release --example stick_edge_table` (one command; it prints its runtime,
//! the number of patches and COUPLED solves, and the largest bound).
//!
//! Covered: b* from [`B_HIGH`] to 0.99 and on to [`B_AUXETIC`] and [`B_EXTREME`], mu~ from the table's lower edge (the full-slip law's
//! c = 1e-11) up to at least [`MU_HI`]; b* from [`B_FROM`] to B_HIGH, zeta from 0 up to the
//! tops of [`BELOW`] and on into the thin slip zones ([`THIN`]). Each patch starts at
//! `ROWS` x `COLS` Chebyshev points;
//! where its coefficient tail (the last two rows and columns, times the patch's largest
//! c (1 - c)) exceeds [`TAIL_TARGET`] it is halved along the direction with the larger tail.
//! Accepted patches are then checked at [`CHECKS`] random points against COUPLED; the bound is
//! the larger of the tail and `SAFETY` times the largest error found there, plus the nodes'
//! largest relative error in lc times the patch's largest c (1 - c).
//!
//! Nodes are solved to a relative accuracy in lc of [`NODE_REL`] over the patch's largest
//! c (1 - c) ([`node_rel`]): the interpolant spreads a node's error in lc over the whole
//! patch, where c (1 - c) may be far larger than at the node. The strips of [`BELOW`] and
//! above b* = 0.25 were built with the rule 4 min(c, 1 - c) NODE_REL at every node, which is
//! the same where a patch reaches c = 1/2 and stricter elsewhere; [`THIN`] and the small stick
//! zones below [`BELOW`] (`--strip 10` .. `21`, 3.5 min on 2 cores, 32 patches, 5312 solves)
//! with this one.

#[path = "../support/mod.rs"]
mod support;

use orthoslip::stick_edge_table::{
    C_LO, SAFETY, coefficients, coordinates, coupling_at, evaluate, nodes,
};
use orthoslip::{Coupling, Profile, StickEdge, coupled};
use std::time::Instant;

/// Smallest b* covered.
const B_FROM: f64 = 0.02;
/// b* where the strips up to [`MU_HI`] begin; below it the strips of [`BELOW`].
const B_HIGH: f64 = 0.25;
/// The strips below [`B_HIGH`]: (b* from, b* to, zeta top), each from [`ZETA_BELOW`] to its
/// top. Their edges in b* start at [`B_FROM`], where the spectral solver's start from
/// Spence's guess begins (`spectral::GUESS_B_MIN`). The tops keep the nodes out of the thin
/// slip zones, where the panels' node solves take seconds: measured with the generator's
/// node solve (`solve_node`, 2 threads busy), 1 - c = 2e-6 lies at zeta = 4.4 (b* = 0.02
/// and 0.05), 4.49 (0.1), about 4.6 (0.15), 4.9 (0.2) and 5.4 (0.25), where a node took
/// 2.4-12 s; at zeta = 4.0, 1 - c = 3.4e-4 (b* = 0.02, node 1.5 s), 4.6e-4 (0.1, 0.95 s),
/// 6.7e-4 (0.15, 0.69 s); at zeta = 4.5, 1 - c = 6.7e-6 (0.15, 1.3 s) and 2.6e-5 (0.2,
/// 1.0 s). Each top lies where 1 - c is a few 1e-5 .. 1e-4 at its strip's smallest b*
/// (1 - c grows with b* at fixed zeta), a decade or more above 2e-6: the thinnest slip zones
/// at the nodes came out at 3.5e-4, 3.9e-5 and 1.3e-5 in the three strips (printed per
/// patch), the build took 8.7, 8.2 and 19.2 min on 2 busy cores (load average about 6).
/// Above the tops the spectral solver starts from Spence's guess. Three strips, so that the
/// tops can rise with b*.
const BELOW: [(f64, f64, f64); 3] = [(0.02, 0.1, 4.0), (0.1, 0.175, 4.25), (0.175, 0.25, 4.5)];
/// Lower edge in zeta of the strips of [`BELOW`]: c = 1.32e-5 there at every b* (measured at
/// b* = 0.02, 0.05, 0.1 and 0.25), under the spectral solver's smallest stick zone
/// (`spectral::C_MIN`, 4e-5), so that every stick edge the spectral solver serves in these
/// strips is tabulated. Lower, the panels' node solves slow down at small b*: at b* = 0.02 a
/// node took 3.4 s at zeta = 0.75, 3.2-6.0 s at 0.5 and 1.0-1.9 s at 0 (0.16-0.57 s at
/// b* = 0.25).
const ZETA_BELOW: f64 = 0.75;
/// zeta cut inside each strip of [`BELOW`] (as at zeta = 2 in the strips above).
const ZETA_CUT_BELOW: f64 = 2.0;
/// Largest b* covered.
const B_TO: f64 = 0.99;
/// mu~ covered at every b* (the last zeta row of a strip reaches it at the strip's smallest b*).
const MU_HI: f64 = 4e6;
/// Initial degrees (beta, zeta).
const ROWS: usize = 10;
const COLS: usize = 16;
/// Largest accepted coefficient tail, in c.
const TAIL_TARGET: f64 = 5e-12;
/// Accuracy of the nodes in c where c (1 - c) is largest in their patch ([`node_rel`]).
const NODE_REL: f64 = 1e-12;
/// Random checks per patch.
const CHECKS: usize = 6;
/// Splits at most this deep.
const MAX_DEPTH: usize = 4;

/// A solved node: (lc, c (1 - c), tolerance reached in c), or why COUPLED failed.
type Node = Result<(f64, f64, f64), String>;

/// Who solves a strip's nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Solver {
    /// The panels' root search (`coupled::solve`), which never looks at the table.
    Panels,
    /// The spectral solver from its own guess of the stick edge
    /// (`coupled::solve_spectral_untabulated`), the panels where it misses the tolerance:
    /// in the thin slip zones below b* = 0.25, where a panel node to the tolerances below
    /// takes 2-50 s and a spectral one 16-32 ms (measured at b* = 0.02 .. 0.245,
    /// 1 - c = 2e-11 .. 9e-8: relative accuracy 1e-9 in lc met at five of six points, the
    /// panels agreeing within 9e-11 of c (1 - c); 1e-11 missed at all six).
    Spectral,
}

/// COUPLED's solution at table coordinates with c to `tol` (up to 100 times that where
/// `solver` misses it), or why it failed.
fn solve_at(
    beta: f64,
    zeta: f64,
    solver: Solver,
    tol: f64,
) -> Result<orthoslip::coupled::CoupledSolution, String> {
    let (b, mu) = coupling_at(beta, zeta);
    let k = Coupling { bp: b, bq: b, mu };
    let at = |tol: f64| -> orthoslip::Result<orthoslip::coupled::CoupledSolution> {
        if solver == Solver::Spectral
            && let Some(s) = coupled::solve_spectral_untabulated(&k, tol, f64::INFINITY)
        {
            return Ok(s);
        }
        coupled::solve(&k, tol)
    };
    let mut t = tol.max(1e-300);
    loop {
        match at(t) {
            Ok(s) => return Ok(s),
            Err(_) if t < tol * 1e2 => t *= 10.0,
            Err(err) => return Err(format!("b* {b} mu~ {mu} tol {t:e}: {err}")),
        }
    }
}

/// The stick edges to 1e-8 at the points (the guesses that set a patch's node rule), on the
/// available threads.
fn guesses(points: &[(f64, f64)], solver: Solver) -> Vec<Result<StickEdge, String>> {
    support::parallel::map(points, |&(beta, zeta)| {
        solve_at(beta, zeta, solver, 1e-8).map(|s| s.edge())
    })
}

/// The node rule of a patch whose largest c (1 - c) (at the guesses) is `largest`: relative
/// accuracy NODE_REL / largest in lc, so that a node's error, spread by the interpolant over
/// the patch, moves c by about NODE_REL wherever c (1 - c) is largest (for a patch reaching
/// c = 1/2 this is the former rule 4 min(c, 1 - c) NODE_REL; in thin slip zones and small
/// stick zones it is that much looser, what lets those nodes be solved in milliseconds).
fn node_rel(largest: f64) -> f64 {
    NODE_REL / largest.max(1e-300)
}

/// Each point to |dc| <= `rel` min(c, 1 - c) at its guess (relative in lc), on the available
/// threads.
fn solve_all(
    points: &[(f64, f64)],
    guesses: &[Result<StickEdge, String>],
    solver: Solver,
    rel: f64,
) -> Vec<Node> {
    let jobs: Vec<_> = points.iter().zip(guesses).collect();
    support::parallel::map(&jobs, |&(&(beta, zeta), guess)| {
        let e = guess.as_ref().map_err(|e| e.clone())?;
        let s = solve_at(beta, zeta, solver, e.c.min(e.one_minus_c) * rel)?;
        let e = s.edge();
        Ok((e.logit(), e.c * e.one_minus_c, s.numerical_error()))
    })
}

struct Built {
    beta: [f64; 2],
    zeta: [f64; 2],
    rows: usize,
    cols: usize,
    coef: Vec<f64>,
    bound: f64,
}

/// A patch and its splits, appended to `out`; returns the COUPLED solves made.
fn build(
    beta: [f64; 2],
    zeta: [f64; 2],
    solver: Solver,
    depth: usize,
    out: &mut Vec<Built>,
) -> usize {
    let started = Instant::now();
    let points = nodes(beta, zeta, ROWS, COLS);
    let guessed = guesses(&points, solver);
    let largest = guessed
        .iter()
        .map(|r| r.as_ref().map_or(0.25, |e| e.c * e.one_minus_c))
        .fold(0.0, f64::max);
    let rel = node_rel(largest);
    let solved = solve_all(&points, &guessed, solver, rel);
    let mut values = Vec::with_capacity(points.len());
    let (mut scale, mut node_tol) = (0.0f64, 0.0f64);
    let mut thinnest = f64::INFINITY;
    for r in &solved {
        match r {
            Ok((lc, cw, tol)) => {
                values.push(*lc);
                scale = scale.max(*cw);
                // the node's error in lc, spread over the patch below
                node_tol = node_tol.max(tol / cw);
                thinnest = thinnest.min(1.0 / (1.0 + lc.exp()));
            }
            Err(e) => panic!("node failed: {e}"),
        }
    }
    let coef = coefficients(&values, ROWS, COLS);
    let row_tail: f64 = coef[(ROWS - 2) * COLS..]
        .iter()
        .map(|v| v.abs())
        .sum::<f64>()
        * scale;
    let col_tail: f64 = coef
        .chunks(COLS)
        .map(|r| r[COLS - 2].abs() + r[COLS - 1].abs())
        .sum::<f64>()
        * scale;
    let tail = row_tail.max(col_tail);
    eprintln!(
        "patch beta [{:.4}, {:.4}] zeta [{:.3}, {:.3}] depth {depth}: tails {row_tail:.1e} (beta) {col_tail:.1e} (zeta), smallest 1 - c at the nodes {thinnest:.1e}, {:.1?}",
        beta[0],
        beta[1],
        zeta[0],
        zeta[1],
        started.elapsed()
    );
    if tail > TAIL_TARGET && depth < MAX_DEPTH {
        let mut n = points.len();
        if row_tail > col_tail {
            let m = 0.5 * (beta[0] + beta[1]);
            n += build([beta[0], m], zeta, solver, depth + 1, out);
            n += build([m, beta[1]], zeta, solver, depth + 1, out);
        } else {
            let m = 0.5 * (zeta[0] + zeta[1]);
            n += build(beta, [zeta[0], m], solver, depth + 1, out);
            n += build(beta, [m, zeta[1]], solver, depth + 1, out);
        }
        return n;
    }
    // checks at random points of the patch
    // seeded by the patch, so that a partial run (`--strip i`) checks the same points
    let seed = (beta[0].to_bits() ^ zeta[0].to_bits().rotate_left(17)) ^ 7;
    let mut rng = fastrand::Rng::with_seed(seed);
    let checks: Vec<(f64, f64)> = (0..CHECKS)
        .map(|_| {
            (
                beta[0] + rng.f64() * (beta[1] - beta[0]),
                zeta[0] + rng.f64() * (zeta[1] - zeta[0]),
            )
        })
        .collect();
    let mut worst = 0.0f64;
    let checked = solve_all(&checks, &guesses(&checks, solver), solver, rel);
    for (p, r) in checks.iter().zip(checked) {
        let (lc, cw, tol) = r.unwrap_or_else(|e| panic!("check failed: {e}"));
        let v = evaluate(&coef, (ROWS, COLS), (beta, zeta), *p);
        worst = worst.max(StickEdge::from_logit(v).distance(StickEdge::from_logit(lc)));
        node_tol = node_tol.max(tol / cw);
    }
    // the nodes' largest error in lc at the patch's largest c (1 - c)
    let bound = tail.max(SAFETY * worst) + node_tol * scale;
    eprintln!("  accepted: checked error {worst:.1e}, bound {bound:.1e}");
    out.push(Built {
        beta,
        zeta,
        rows: ROWS,
        cols: COLS,
        coef,
        bound,
    });
    points.len() + CHECKS
}

/// The edges in beta = artanh(b*) of the strips up to [`MU_HI`]: b* = B_HIGH .. 0.3, then six
/// equal steps of beta up to B_TO.
fn strips() -> Vec<f64> {
    let (from, to) = (0.3f64.atanh(), B_TO.atanh());
    std::iter::once(B_HIGH.atanh())
        .chain((0..=6).map(|i| from + (to - from) * i as f64 / 6.0))
        .collect()
}

/// The thin slip zones below b* = 0.25, above the tops of [`BELOW`]: (b* from, b* to, top).
/// Each strip runs from its [`BELOW`] strip's top to its own; None is the zeta at which the
/// edge exponent g falls to [`G_TOP`] at b* to. Nodes by [`Solver::Spectral`].
///
/// The tops are where the near-bonded law takes over c alone (its estimate meets 1e-10 where
/// 1 - c is below about 2e-11) at the strip's largest b*, while at its smallest b* the
/// thinnest slip zone is still above the spectral solver's `W_MIN` (2.5e-13). Measured
/// (1 - c from `coupled::solve_to` at 1e-13; the zeta from which the law answers c alone at
/// 1e-10, z_L, and that at which 1 - c falls to 2.5e-13, z_W; steps of 0.1 in zeta):
///
/// | b* | 0.02 | 0.05 | 0.08 | 0.11 | 0.13 | 0.145 | 0.16 |
/// |---|---|---|---|---|---|---|---|
/// | z_L | 5.0 | 5.0 | 5.2 | 5.4 | 5.6 | 5.9 | 6.5 |
/// | z_W | 5.1 | 5.2 | 5.4 | 5.7 | 6.2 | > 7.5 | none |
///
/// (at b* = 0.15 1 - c levels off at 2.1e-13, at 0.16 at 1.7e-12, at 0.2 at 8.7e-10, at
/// 0.245 at 8.7e-8 as mu~ grows), so from b* = 0.16 on the strips run up to [`G_TOP`].
const THIN: [(f64, f64, Option<f64>); 9] = [
    (0.02, 0.05, Some(5.05)),
    (0.05, 0.08, Some(5.2)),
    (0.08, 0.1, Some(5.35)),
    (0.1, 0.12, Some(5.5)),
    (0.12, 0.135, Some(5.75)),
    (0.135, 0.15, Some(6.2)),
    (0.15, 0.16, Some(6.6)),
    (0.16, 0.175, None),
    (0.175, 0.25, None),
];

/// The edge exponent g at the top of the thin strips that run on with friction: the
/// spectral solver serves g >= 0.002 (`spectral::G_MIN`); above that friction the panels
/// answer (large friction).
const G_TOP: f64 = 0.0025;

/// zeta cuts inside the strips of [`THIN`] that run up to [`G_TOP`], and below the tops of
/// the others. The node rule ([`node_rel`]) asks a relative accuracy in lc of NODE_REL over
/// the patch's largest c (1 - c); in one patch from a strip's foot (1 - c about 1e-3) to its
/// top (1 - c down to 3e-12) that is 3e-9 at slip zones of 1e-11, which the spectral solver
/// missed at three of six such points (b* = 0.02 .. 0.05, zeta = 5 .. 5.05, 1 - c = 3e-12 ..
/// 5e-11), handing them to the panels (tens of seconds each). Cut where 1 - c has fallen to
/// about 1e-7, each patch above asks 1e-5 or less.
const THIN_CUTS: [f64; 3] = [5.0, 6.0, 8.0];

/// The cuts below a fixed top of [`THIN`]: at top - 0.5 and top - 0.25 ([`THIN_CUTS`]).
const BELOW_TOP: [f64; 2] = [0.5, 0.25];

/// Every strip: its beta range, zeta cuts and node solver. First the strips up to
/// [`MU_HI`], from zeta = 0, then those of [`BELOW`], of [`THIN`], and the small stick
/// zones below [`BELOW`] (zeta = 0 .. [`ZETA_BELOW`], c = 1e-11 .. 1.3e-5, the panels'
/// nodes: 60-320 ms each at the node rule there), so that the earlier patches keep their
/// place in the generated file.
fn all_strips() -> Vec<([f64; 2], Vec<f64>, Solver)> {
    let mut out: Vec<([f64; 2], Vec<f64>, Solver)> = strips()
        .windows(2)
        .map(|w| {
            // zeta reaching MU_HI at the strip's smallest b* (where mu_lo is smallest)
            let top = coordinates(w[0].tanh(), MU_HI).1;
            (
                [w[0], w[1]],
                vec![0.0, 2.0, 4.0, 6.0, 9.0, 13.0, top],
                Solver::Panels,
            )
        })
        .collect();
    out.extend(BELOW.iter().map(|&(b0, b1, top)| {
        (
            [b0.atanh(), b1.atanh()],
            vec![ZETA_BELOW, ZETA_CUT_BELOW, top],
            Solver::Panels,
        )
    }));
    out.extend(THIN.iter().map(|&(b0, b1, top)| {
        let from = BELOW
            .iter()
            .find(|s| s.0 <= b0 && b1 <= s.1)
            .expect("a thin strip inside a strip of BELOW")
            .2;
        let cuts = match top {
            Some(t) => vec![from, t - BELOW_TOP[0], t - BELOW_TOP[1], t],
            None => {
                let mu = (std::f64::consts::PI * G_TOP).tan().recip() / b1;
                let t = coordinates(b1, mu).1;
                std::iter::once(from)
                    .chain(THIN_CUTS)
                    .chain(std::iter::once(t))
                    .collect()
            }
        };
        ([b0.atanh(), b1.atanh()], cuts, Solver::Spectral)
    }));
    out.extend(BELOW.iter().map(|&(b0, b1, _)| {
        (
            [b0.atanh(), b1.atanh()],
            vec![0.0, ZETA_BELOW],
            Solver::Panels,
        )
    }));
    // towards the auxetic limit: AUXETIC_STRIPS equal steps of beta from B_TO to B_AUXETIC,
    // then one on to B_EXTREME, cut as the strips up to MU_HI
    let (from, to) = (B_TO.atanh(), B_AUXETIC.atanh());
    let step = (to - from) / AUXETIC_STRIPS as f64;
    let edge = |i: usize| from + step * i as f64;
    let auxetic = (0..AUXETIC_STRIPS).map(|i| [edge(i), edge(i + 1)]);
    out.extend(
        auxetic
            .chain(std::iter::once([edge(AUXETIC_STRIPS), B_EXTREME.atanh()]))
            .map(|beta| {
                let top = coordinates(beta[0].tanh(), MU_HI).1;
                (
                    beta,
                    vec![0.0, 2.0, 4.0, 6.0, 9.0, 13.0, top],
                    Solver::Panels,
                )
            }),
    );
    out
}

/// Largest b* covered towards the auxetic limit (nu -> -1), from [`B_TO`] on in
/// [`AUXETIC_STRIPS`] strips. The panels' node solves there (to 4e-12 min(c, 1 - c), one
/// run): 46-50 ms at b* = 0.995 (c = 0.014 .. 0.025, zeta = 3 .. 15), 0.5 s at zeta = 0.5
/// (c = 1.1e-7); 0.13-0.67 s at b* = 0.9999 (c = 2.8e-4 .. 4.9e-4), 1.2 s at zeta = 0.5
/// (c = 1.2e-8). c falls like (1 - b*)^(1/k0) there (`coupled::auxetic`), linear in beta in
/// the log, so lc stays smooth in these coordinates.
const B_AUXETIC: f64 = 0.9999;

/// Strips between [`B_TO`] and [`B_AUXETIC`] (beta = 2.65 .. 4.95).
const AUXETIC_STRIPS: usize = 2;

/// Largest b* covered: one strip more from [`B_AUXETIC`] up to the lowest node of the
/// auxetic extrapolation (`coupled::auxetic`, s = 1 - b* = 1e-5), whose four nodes
/// (s = 1e-5 .. 8e-5) the table then gives for c alone (`--strip 24`: 6 patches, none
/// halved, 996 panel solves, 16 min on 2 cores shared with a test run, 72-208 s a patch;
/// largest bound 2.4e-12, largest error at the checks 5.4e-14).
const B_EXTREME: f64 = 0.99999;

/// A patch as a line of the generated source.
fn patch_source(p: &Built) -> String {
    format!(
        "    Patch {{ beta: [{:?}, {:?}], zeta: [{:?}, {:?}], rows: {}, cols: {}, bound: {:.2e}, coef: &[{}] }},",
        p.beta[0],
        p.beta[1],
        p.zeta[0],
        p.zeta[1],
        p.rows,
        p.cols,
        p.bound,
        p.coef
            .iter()
            .map(|v| format!("{v:?}"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

fn main() -> std::io::Result<()> {
    let t = Instant::now();
    let args: Vec<String> = std::env::args().collect();
    // `--strip i` builds strip i alone and prints its patches' source lines (for probing and
    // for building the strips in separate runs; the patches are the same as in a whole run)
    let only: Option<usize> = args
        .iter()
        .position(|a| a == "--strip")
        .map(|i| args[i + 1].parse().expect("--strip takes a strip index"));
    let mut out = Vec::new();
    let mut solves = 0;
    for (s, (beta, cuts, solver)) in all_strips().into_iter().enumerate() {
        if only.is_some_and(|o| o != s) {
            continue;
        }
        for z in cuts.windows(2) {
            solves += build(beta, [z[0], z[1]], solver, 0, &mut out);
        }
    }
    if only.is_some() {
        for p in &out {
            println!("{}", patch_source(p));
        }
        eprintln!(
            "{} patches, {solves} solves, {:.1?}",
            out.len(),
            t.elapsed()
        );
        return Ok(());
    }
    let mut src = String::from(
        "//! Generated by `cargo run --release --example stick_edge_table`; do not edit.\n\n\
         use super::Patch;\n\n",
    );
    src += &format!(
        "/// {} patches: over b* = {B_HIGH} .. {B_TO} and on to {B_EXTREME} from the full-slip \
         law's c = {C_LO:e} up to mu~ = {MU_HI:e} at least; over b* = {B_FROM} .. {B_HIGH} from zeta = 0 up to zeta = {} \
         (the thin slip zones), and on to g = {G_TOP} from b* = {} on.\n\
         pub(super) const PATCHES: &[Patch] = &[\n",
        out.len(),
        THIN.iter()
            .filter_map(|&(b0, b1, top)| top.map(|t| format!("{t} (b* = {b0} .. {b1})")))
            .collect::<Vec<_>>()
            .join(", "),
        THIN.iter()
            .find(|s| s.2.is_none())
            .expect("a strip up to G_TOP")
            .0
    );
    for p in &out {
        src += &patch_source(p);
        src += "\n";
    }
    src += "];\n";
    std::fs::write("src/stick_edge_table/table.rs", src)?;
    let worst = out.iter().map(|p| p.bound).fold(0.0, f64::max);
    println!(
        "wrote src/stick_edge_table/table.rs: {} patches, {solves} COUPLED solves, largest bound {worst:.1e}, in {:.1?}",
        out.len(),
        t.elapsed()
    );
    Ok(())
}
