//! The collocation system for a fixed stick edge c: (E1) H[p] = bp q on 0 < x < 1, (E2)
//! H[q] = -bq p on 0 < x < c, (E3) q = mu p on c < x < 1 built into the basis, (E4)
//! int p = 1, with p even and q odd (so H over (-1, 1) is the panel integral at x plus or
//! minus the mirrored one at -x). Unknowns: the coefficients of the panel bases of
//! [`super::mesh`], with the two wrong-c modes |x - c|^(g-1) as one unknown ([`WrongCFold`])
//! whose coefficient, the defect, vanishes exactly at the physical c (the compatibility
//! condition, docs/theory.md (X3), (K3)). On the slip panels the unknowns are scaled to q = mu p.
//!
//! Each panel gets OVERSAMPLE times as many collocation points (Gauss-Legendre points of the
//! panel) as it has unknowns; (E1) with p ~ (1-x)^(-g) has index 1, so (E4) fixes the scale.

use super::mesh::{Basis, Block, Layout, Mesh, Panel, Pt};
use crate::error::{Error, Result};
use crate::numerics::cauchy::WeightedFamily;
use crate::numerics::lstsq::LeastSquares;
use crate::numerics::orthopoly::{legendre, legendre_sum};
use crate::numerics::quadrature::gauss_legendre_nodes;
use crate::numerics::special::{exprel, sin_pi};
use std::f64::consts::PI;

/// Collocation points per unknown: the oversampled system is solved in the least-squares
/// sense (Householder QR), which keeps the redundant singular-plus-regular bases of the
/// panels at c from amplifying rounding errors (square collocation loses 3-4 digits in c).
pub(crate) const OVERSAMPLE: f64 = 2.0;

/// Oversampling at a stick edge known in advance (the tabulated c), for traction tolerance
/// `traction_tol`: no defect to resolve there, only the tractions. From 1e-9 up, 1.5 points
/// per unknown: the least-squares error stays well inside the order-to-order estimate (12
/// benchmark scenes and 8 of the reduced plane at 1e-6 .. 1e-10: true error at most 0.37 of
/// the estimate, against 0.11 with 2 points; median time at 1e-8 4.3 ms against 5.6 ms; one
/// point per unknown left errors of 6e-8 at 1e-8). Below, [`OVERSAMPLE`]: with 1.5 the
/// estimate met 1e-10 an order later (median 8.7 ms against 5.6 ms).
pub(crate) fn oversample_at_known_c(traction_tol: f64) -> f64 {
    if traction_tol >= 1e-9 {
        1.5
    } else {
        OVERSAMPLE
    }
}

/// Oversampling for tolerances at defect's rounding noise: 3 points per unknown lower that
/// noise 10-50 times at orders >= 8 (measured), for 1.6 times the least-squares work.
pub(crate) const OVERSAMPLE_FINE: f64 = 3.0;

/// Problem constants as the system uses them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Constants {
    /// Coupling of q into (E1).
    pub(crate) bp: f64,
    /// Coupling of p into (E2).
    pub(crate) bq: f64,
    /// Friction coefficient.
    pub(crate) mu: f64,
    /// Edge exponent g = 1/2 - atan(bp mu) / pi.
    pub(crate) g: f64,
}

/// The Cauchy-transform families of every basis, for order n, indexed by [`Basis`]: each
/// basis has its family, so a lookup cannot miss. Built inside each solve: no cache outlives
/// it, so solves share no mutable state (a process-wide cache measured 5-10% faster per
/// solve, not worth global state).
#[derive(Clone, Debug)]
pub(crate) struct Families {
    fams: [WeightedFamily; Basis::ALL.len()],
}

impl Families {
    /// Families for exponent g and order n (Legendre degrees below n).
    pub(crate) fn new(g: f64, n: usize) -> Self {
        Self {
            fams: Basis::ALL.map(|b| WeightedFamily::new(b.weight(g), n)),
        }
    }

    /// The family of a basis.
    pub(crate) fn get(&self, basis: Basis) -> &WeightedFamily {
        &self.fams[basis as usize]
    }
}

/// Values of a block's functions at local coordinate t (with 1 - t, 1 + t given accurately)
/// for edge exponent g, written to out[..count]; `leg` is scratch for Legendre values.
pub(crate) fn block_values(
    b: &Block,
    g: f64,
    (t, omt, opt): (f64, f64, f64),
    leg: &mut [f64],
    out: &mut [f64],
) {
    let w = b.basis.weight(g).at(omt, opt);
    legendre(t, &mut leg[..b.count]);
    for (o, l) in out[..b.count].iter_mut().zip(leg.iter()) {
        *o = w * l;
    }
}

/// A solved discretisation at fixed c.
#[derive(Clone, Debug)]
pub(crate) struct Discrete {
    /// The mesh.
    pub(crate) mesh: Mesh,
    /// Coefficients of all panel bases.
    pub(crate) coef: Vec<f64>,
    /// Physical coefficient of q's (c - x)^(g - 1) mode: zero at the physical c.
    pub(crate) defect: f64,
    /// The constants.
    pub(crate) k: Constants,
}

/// One collocation row: which equation and where.
struct Row {
    e2: bool,
    panel: usize,
    x: Pt,
    t: f64,
    omt: f64,
    opt: f64,
}

/// Number of collocation points for `count` unknowns.
fn oversampled(count: usize, oversample: f64) -> usize {
    (oversample * count as f64).ceil() as usize
}

fn rows(mesh: &Mesh, oversample: f64) -> Vec<Row> {
    let mut rows = Vec::with_capacity(mesh.unknowns);
    let last = mesh.panels.len() - 1;
    for (ip, p) in mesh.panels.iter().enumerate() {
        let counts = [
            (
                false,
                oversampled(p.np(), oversample) - usize::from(ip == last),
            ),
            (true, oversampled(p.nq(), oversample)),
        ];
        for (e2, count) in counts {
            if count == 0 {
                continue;
            }
            for &t in gauss_legendre_nodes(count).iter() {
                let x = if p.central {
                    let x = p.h * (0.5 * (1.0 + t)).sqrt();
                    Pt { x, u: 1.0 - x }
                } else {
                    Pt::local(p.m, p.h, t)
                };
                rows.push(Row {
                    e2,
                    panel: ip,
                    x,
                    t,
                    omt: 1.0 - t,
                    opt: 1.0 + t,
                });
            }
        }
    }
    rows
}

/// Parity in x of a density on the whole punch: p (and q on the slip zones, as mu p sgn x
/// with a sign the rows carry) is even, q on the stick zone is odd.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Parity {
    Even,
    Odd,
}

impl Parity {
    /// The sign of the mirrored panel's contribution: the transform over x < 0 of an even
    /// density is minus that over x > 0 at the mirrored target, of an odd one plus.
    fn mirror_sign(self) -> f64 {
        match self {
            Parity::Even => -1.0,
            Parity::Odd => 1.0,
        }
    }
}

/// Adds the Hilbert-transform contributions of `blocks` on panel `src` (and its mirror
/// image) at target x to `row[offset..]`: scale * (C(y) + s C(y')) / pi, y' the mirrored
/// target and s the parity's mirror sign.
#[allow(clippy::too_many_arguments)]
fn add_hilbert(
    fams: &Families,
    src: &Panel,
    blocks: &[Block],
    offset: usize,
    x: Pt,
    parity: Parity,
    scale: f64,
    buf: &mut [f64],
    buf2: &mut [f64],
    row: &mut [f64],
) {
    let mut col = offset;
    if src.central {
        // [-l, l] in Y = 2 x^2/l^2 - 1: an even f(Y) gives x (l^2/2)^(-1/2) C[(1+Y)^(-1/2) f],
        // an odd x f(Y) gives (l^2/2)^(1/2) C[(1+Y)^(1/2) f]
        let r = x.x / src.h;
        let yy = 2.0 * r * r - 1.0;
        let half = src.h * std::f64::consts::FRAC_1_SQRT_2;
        let (fam, factor) = match parity {
            Parity::Even => (fams.get(Basis::CentralP), x.x / half),
            Parity::Odd => (fams.get(Basis::CentralQ), half),
        };
        for b in blocks {
            fam.cauchy(yy, &mut buf[..b.count]);
            for u in &buf[..b.count] {
                row[col] += scale * factor * u / PI;
                col += 1;
            }
        }
        return;
    }
    let y = x.minus(src.m) / src.h;
    let ym = -(x.x + src.m.x) / src.h;
    for b in blocks {
        let fam = fams.get(b.basis);
        let sign = parity.mirror_sign();
        fam.cauchy_pair(y, ym, sign, &mut buf[..b.count], &mut buf2[..b.count]);
        for u in &buf[..b.count] {
            row[col] += scale * u / PI;
            col += 1;
        }
    }
}

/// The two wrong-c modes as one unknown, the local homogeneous solution at c: q = A (c - x)^(g-1)
/// on the stick side and p = B (x - c)^(g-1) on the slip side, where (E1) at x < c
/// (H[(x - c)_+^(g-1)] = |x - c|^(g-1) / sin(pi (g - 1)) there) fixes B = -bp sin(pi g) A
/// ((E2) then holds by the exponent equation cot(pi g) = bp mu). Two free columns instead
/// became nearly dependent at large friction (both tend to delta(x - c) / g), which left the
/// defect determined only to eps / g.
#[derive(Clone, Copy, Debug)]
struct WrongCFold {
    /// q's column (kept; its coefficient is the defect).
    q: usize,
    /// p's column (dropped from the system).
    p: usize,
    /// p's coefficient per unit of q's, in the panels' local weights (1 -+ t)^(g-1).
    ratio: f64,
}

impl WrongCFold {
    fn new(mesh: &Mesh, k: Constants) -> Option<Self> {
        let ((q, hq), (p, hp)) = mesh.wrong_c_columns()?;
        let ratio = -k.bp * sin_pi(k.g) * (hq / hp).powf(1.0 - k.g);
        Some(Self { q, p, ratio })
    }
}

/// From the mesh's unknowns to the system's columns and back: the wrong-c modes folded into
/// one ([`WrongCFold`]) and, at large friction (g below [`SCALED_BELOW`]), the slip panels'
/// unknowns scaled to q = mu p (O(1) where p is O(1 / mu)), so that no row's largest entry
/// is one whose term is mu times smaller (a row scaled by it lost eps mu ~ eps / g relative
/// in (E1) on the slip zones).
struct Columns {
    fold: Option<WrongCFold>,
    /// Scale of each unknown's column.
    scale: Vec<f64>,
}

/// The edge exponent below which the slip panels' unknowns are q = mu p ([`Columns`]). Not
/// at moderate friction: there the scaling cost the thin slip zones of b* = 0.12,
/// mu~ = 215-2154 (1 - c ~ 5e-17) the defect's sign change in the near-bonded window (tried
/// again up to g = 1e-2, with [`super::mesh::LOG_BELOW`]: no sign change in the window at
/// b* = 0.12, mu~ = 464 and at the thin extrapolation's nodes there).
const SCALED_BELOW: f64 = 1e-3;

impl Columns {
    fn new(mesh: &Mesh, k: Constants) -> Self {
        let slip_scale = if k.g < SCALED_BELOW { 1.0 / k.mu } else { 1.0 };
        let mut scale = vec![1.0; mesh.unknowns];
        for panel in mesh.panels.iter().filter(|p| !p.stick) {
            scale[panel.p_offset..panel.p_offset + panel.np()].fill(slip_scale);
        }
        Columns {
            fold: WrongCFold::new(mesh, k),
            scale,
        }
    }

    /// Number of the system's columns.
    fn count(&self) -> usize {
        self.scale.len() - usize::from(self.fold.is_some())
    }

    /// The system's column of unknown j (None for the folded one).
    fn column(&self, j: usize) -> Option<usize> {
        match self.fold {
            Some(f) if j == f.p => None,
            Some(f) if j > f.p => Some(j - 1),
            _ => Some(j),
        }
    }

    /// A row over the unknowns, folded and scaled in place.
    fn transform(&self, r: &mut [f64]) {
        if let Some(f) = self.fold {
            r[f.q] += f.ratio * r[f.p];
            r[f.p] = 0.0;
        }
        r.iter_mut().zip(&self.scale).for_each(|(v, s)| *v *= s);
    }

    /// Writes the transformed row `r`, times `factor`, into the system's row `out`.
    fn place(&self, r: &[f64], factor: f64, out: &mut [f64]) {
        for (j, v) in r.iter().enumerate() {
            if let Some(col) = self.column(j) {
                out[col] = v * factor;
            }
        }
    }

    /// The unknowns from the system's solution x.
    fn unknowns(&self, x: &[f64]) -> Vec<f64> {
        let mut coef: Vec<f64> = (0..self.scale.len())
            .map(|j| self.column(j).map_or(0.0, |col| x[col] * self.scale[j]))
            .collect();
        if let Some(f) = self.fold {
            coef[f.p] = f.ratio * coef[f.q];
        }
        coef
    }
}

/// Smallest field |p| + |q| a row is weighted by (p ~ 0.3 over most of the contact with
/// int p = 1; the floor only guards a model's zeros).
const FIELD_FLOOR: f64 = 1e-3;

/// Slip zones thinner than this (1 - c) get the weighted rows of [`row_weight`]
/// ([`weighs_rows`]); wider ones keep the rows as they are, which met their tolerances there
/// before (weighted, c moved by up to 5e-12 at b* = 0.005, mu~ = 2e-3 .. 5e-3, and two scenes
/// with strong singularities, c ~ 1e-4 at b* = 0.99995, and b* = 0.99 at mu~ = 215, missed
/// 1e-10 in the tractions).
const WEIGHTED_BELOW: f64 = 1e-6;

/// The unweighted rows' noise in the traction estimate, in units of eps / (1 - c)^(1/2)
/// (measured: the order-to-order distance 0.5 .. 1.6 of that unit, at 1 - c = 8e-13 and
/// 6e-18), with room for the estimate (twice the distance) to fall well inside a tolerance.
const ROW_NOISE: f64 = 100.0;

/// Whether the solves near stick edge 1 - c = w for traction tolerance `traction_tol` take a
/// model for their row weights ([`row_weight`]): slip zones thinner than [`WEIGHTED_BELOW`]
/// whose unweighted rows' noise, [`ROW_NOISE`] eps / w^(1/2), exceeds the tolerance. Below
/// it the rows stay as they are: weighting them slows the convergence of c, which the rows
/// next to c decide (b* = 0.2, mu~ = 5, 1 - c = 8e-9: c and tractions to 1e-8 in 516 ms
/// weighted, 230 ms not). The rule was a fixed tolerance, 1e-9, which left the thinnest
/// zones unweighted at 1e-9 (b* = 0.0075, mu~ = 0.1, 1 - c = 6e-18: estimate 8.8e-8, 3174
/// unknowns, while 1e-10 was met). Decided once per order (from the lower order's stick
/// edge), so that defect(c) at one order stays smooth.
pub(crate) fn weighs_rows(w: f64, traction_tol: f64) -> bool {
    w < WEIGHTED_BELOW && ROW_NOISE * f64::EPSILON / w.sqrt() > traction_tol
}

/// The weight of the collocation row at x, besides its scaling to a largest entry of 1:
/// (|p| + |q|)^(-1/2) of the model solution there. A row's rounding error is eps times its
/// terms, which are of the size of the field there; unweighted, the rows next to a thin slip
/// zone (field ~ (1 - c)^(-1/2)) let the bulk's tractions move by ~ eps / sqrt(1 - c) with
/// any change of c or of the points, and the order-to-order estimate stalled there
/// (b* = 0.15, mu~ = 10, 1 - c = 8e-13, orders 16-26: the tractions moved by 6e-11 .. 4e-10
/// for 1 - c changed by 1e-9 relative or 4 points per unknown instead of 3; weighted by the
/// order-13 solution, 1e-14 .. 3e-14). The full weight 1 / (|p| + |q|) quiets the noise as
/// well but starves the rows where the field is large over much of the contact: at small c
/// with a strong central singularity (|x|^-0.94, b* = 1 - 5e-7, mu~ = 10) the estimate then
/// stalled at 5e-9; the square root meets 1e-8 there.
fn row_weight(model: Option<&Discrete>, x: Pt) -> f64 {
    model.map_or(1.0, |d| {
        let (p, q) = d.eval(x);
        let field = p.abs() + q.abs();
        if field.is_finite() {
            1.0 / field.max(FIELD_FLOOR).sqrt()
        } else {
            1.0
        }
    })
}

/// Assembles and solves the system for stick edge (c, w = 1 - c) at order n, with
/// `oversample` collocation points per unknown, by `ls`. Each row is scaled to its largest
/// entry and, given a `model` of the solution (a lower order's, where [`weighs_rows`]),
/// weighted by the model's field at its point ([`row_weight`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_fixed(
    k: Constants,
    c: f64,
    w: f64,
    n: usize,
    fams: &Families,
    layout: &Layout,
    oversample: f64,
    ls: &mut LeastSquares,
    model: Option<&Discrete>,
) -> Result<Discrete> {
    if !(c > 1e-300 && w > 1e-300 && c <= 1.0 && w <= 1.0) {
        return Err(Error::NoConvergence(format!(
            "coupled: trial stick edge c = {c}, 1 - c = {w} out of range"
        )));
    }
    let mesh = Mesh::new(c, w, n, k.bp > 0.0, layout).ok_or_else(|| {
        Error::NoConvergence(format!("coupled: panel layout does not fit c = {c}"))
    })?;
    let unknowns = mesh.unknowns;
    let rows = rows(&mesh, oversample);
    let nr = rows.len() + 1;
    let deg = n;
    let (mut buf, mut buf2, mut leg, mut vals) = (
        vec![0.0; deg],
        vec![0.0; deg],
        vec![0.0; deg],
        vec![0.0; deg],
    );
    let map = Columns::new(&mesh, k);
    let columns = map.count();
    // row-major; each row assembled in `r` (all unknowns), then folded into its place
    let mut a = vec![0.0; nr * columns];
    let mut r = vec![0.0; unknowns];
    for (row, out) in rows.iter().zip(a.chunks_exact_mut(columns)) {
        r.fill(0.0);
        let own = &mesh.panels[row.panel];
        for src in &mesh.panels {
            // (E1) rows: H[p]; (E2) rows: H[q], q odd on the stick zone and mu p sgn x (p's
            // coefficients, odd) on the slip zones
            let (blocks, offset, parity, scale) = if !row.e2 {
                (&src.p, src.p_offset, Parity::Even, 1.0)
            } else if src.stick {
                (&src.q, src.q_offset, Parity::Odd, 1.0)
            } else {
                (&src.p, src.p_offset, Parity::Odd, k.mu)
            };
            add_hilbert(
                fams, src, blocks, offset, row.x, parity, scale, &mut buf, &mut buf2, &mut r,
            );
        }
        // local terms: (E1) - bp q(x), (E2) + bq p(x)
        let (blocks, mut col, scale) = if row.e2 {
            (&own.p, own.p_offset, k.bq)
        } else if own.stick {
            let xf = if own.central { row.x.x } else { 1.0 };
            (&own.q, own.q_offset, -k.bp * xf)
        } else {
            (&own.p, own.p_offset, -k.bp * k.mu)
        };
        for b in blocks {
            block_values(b, k.g, (row.t, row.omt, row.opt), &mut leg, &mut vals);
            for v in &vals[..b.count] {
                r[col] += scale * v;
                col += 1;
            }
        }
        map.transform(&mut r);
        let largest = r.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
        map.place(&r, row_weight(model, row.x) / largest, out);
    }
    // (E4): int_{-1}^{1} p = 1 (weighted row; the solution is rescaled to it exactly below)
    let last = nr - 1;
    let mut norm = vec![0.0; unknowns];
    for p in &mesh.panels {
        let mut col = p.p_offset;
        // central: int_{-l}^{l} f(Y) dx = (l^2/2)^(1/2) int (1+Y)^(-1/2) f dY
        let (factor, central) = if p.central {
            (p.h * std::f64::consts::FRAC_1_SQRT_2, Some(Basis::CentralP))
        } else {
            (2.0 * p.h, None)
        };
        for b in &p.p {
            let fam = fams.get(central.unwrap_or(b.basis));
            for j in 0..b.count {
                norm[col] = factor * fam.moment(j);
                col += 1;
            }
        }
    }
    const NORM_WEIGHT: f64 = 1e3;
    let nscale = NORM_WEIGHT / norm.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut folded = norm.clone();
    map.transform(&mut folded);
    map.place(&folded, nscale, &mut a[last * columns..]);
    let mut rhs = vec![0.0; nr];
    rhs[last] = nscale;
    let mut coef = map.unknowns(&ls.solve(&a, columns, &rhs));
    let mass: f64 = coef.iter().zip(&norm).map(|(c, v)| c * v).sum();
    for v in coef.iter_mut() {
        *v /= mass;
    }
    if coef.iter().any(|v| !v.is_finite()) {
        return Err(Error::NoConvergence(format!(
            "coupled system singular at c = {c}, n = {n}"
        )));
    }
    let cs = &mesh.panels[mesh.c_stick];
    let defect = coef[cs.q_offset + 2 * n] * cs.h.powf(1.0 - k.g);
    Ok(Discrete {
        mesh,
        coef,
        defect,
        k,
    })
}

impl Discrete {
    /// sum over `blocks` of weight * Legendre series, the wrong-c modes left out: the exact
    /// solution has none (their coefficient is the defect, zero at the physical c), and near
    /// c their weight |x - c|^(g-1) would turn the root's residual into a spurious
    /// singularity (|q| > mu p and p < 0 within 1e-6 of c at large friction, measured).
    fn series(&self, blocks: &[Block], offset: usize, t: f64, omt: f64, opt: f64) -> f64 {
        let mut s = 0.0;
        let mut col = offset;
        for b in blocks {
            let coef = &self.coef[col..col + b.count];
            col += b.count;
            if !b.basis.is_wrong_c() {
                s += b.basis.weight(self.k.g).at(omt, opt) * legendre_sum(coef, t);
            }
        }
        s
    }

    /// What leaving out the wrong-c modes costs in the norm
    /// ([`crate::problem::traction_distance`], over -1 < x < 1, q = delta q~), for a stick
    /// edge known to within dc: the mode c0 (1 -+ t)^(g-1) of a panel of half-width h counted
    /// farther than dc from c, int |.| dx = |c0| h (2^g - r^g) / g, r = dc / h, written as
    /// |c0| h r^g L exprel(g L), L = ln(2 / r), which stays finite as g -> 0 (large friction:
    /// the whole-panel norm |c0| h 2^g / g grew like 1 / g, all of it from within
    /// exp(-1 / g) of c, where c itself is not known; the tractions' change with c is
    /// measured apart, by comparing two orders' tractions at the same x). On the slip panel
    /// the mode is p's, and mu times it q's.
    pub(crate) fn wrong_c_norm(&self, delta: f64, dc: f64) -> f64 {
        let g = self.k.g;
        let dc = dc.max(f64::MIN_POSITIVE);
        let far = |h: f64| {
            let r = dc / h;
            if r >= 2.0 {
                return 0.0;
            }
            let l = (2.0 / r).ln();
            h * r.powf(g) * l * exprel(g * l)
        };
        // sum of |c0| times its far norm over the modes among `blocks` (from column `col`)
        let modes = |blocks: &[Block], mut col: usize, h: f64| {
            let mut sum = 0.0;
            for b in blocks {
                if b.basis.is_wrong_c() {
                    sum += self.coef[col].abs() * far(h);
                }
                col += b.count;
            }
            sum
        };
        let sum: f64 = self
            .mesh
            .panels
            .iter()
            .map(|panel| {
                (1.0 + delta * self.k.mu) * modes(&panel.p, panel.p_offset, panel.h)
                    + delta * modes(&panel.q, panel.q_offset, panel.h)
            })
            .sum();
        2.0 * sum
    }

    /// [`Self::wrong_c_norm`] (delta = 1) per unit |defect|: the norm is linear in the
    /// modes' coefficient, which is the defect.
    pub(crate) fn wrong_c_per_defect(&self, dc: f64) -> f64 {
        let d = self.defect.abs();
        if d > 0.0 {
            self.wrong_c_norm(1.0, dc) / d
        } else {
            0.0
        }
    }

    /// The distance of these tractions from `other`'s at the same x (each with its own stick
    /// edge): int |dp| + delta int |dq~| in the norm of [`crate::problem::traction_parts`].
    pub(crate) fn traction_distance(&self, other: &Discrete, delta: f64) -> f64 {
        let at = |x| Pt { x, u: 1.0 - x };
        let (dp, dq) = crate::problem::traction_parts(
            |x| self.eval(at(x)),
            |x| other.eval(at(x)),
            [self.mesh.c, other.mesh.c],
        );
        dp + delta * dq
    }

    /// (p, q) at 0 <= x < 1 given as a [`Pt`].
    pub(crate) fn eval(&self, x: Pt) -> (f64, f64) {
        let panel = &self.mesh.panels[self.mesh.locate(x)];
        let (t, omt, opt) = panel.local(x);
        let p = self.series(&panel.p, panel.p_offset, t, omt, opt);
        let q = if panel.central {
            x.x * self.series(&panel.q, panel.q_offset, t, omt, opt)
        } else if panel.stick {
            self.series(&panel.q, panel.q_offset, t, omt, opt)
        } else {
            self.k.mu * p
        };
        (p, q)
    }
}
