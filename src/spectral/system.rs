//! The fixed-c system of the half problem (docs/theory_spectral.md, (S1)-(S3)): for a trial
//! stick edge c, the coefficients of the zone bases ([`super::basis`]) and the border
//! constant sigma that solve, in the least-squares sense at the collocation points
//! ([`super::points`]),
//!
//! - (E1) H[p](x) - b q(x) = 0 at every point, 0 <= x < 1;
//! - (E2) H[q](x) + b p(x) = sigma at the stick points;
//! - int p = 1, and p and q continuous at x = c, by elimination of one column each
//!   (Gauss-Jordan on the three constraints, pivoting on the largest entry);
//!
//! with q = mu p on the slip zone built into the slip columns. The exact c is where
//! sigma(c) = 0 (the bounded shear traction at x = c). Rows are weighted by (1 - x)^g (the
//! pressure's edge growth) and columns scaled to unit norm before the least-squares solve.

use crate::error::{Error, Result};
use crate::numerics::jacobi_transform::{JacobiFamily, Point};
use crate::numerics::lstsq::{ColMajor, ConstrainedFailure, constrained_nested, constrained_sized};
use crate::problem::TOLERANCE_FLOOR;

use crate::numerics::bonded::{Bonded, MAX_DEGREE};
use faer::complex::Complex;
use std::sync::Arc;

use super::basis::{Block, Family, parity};
use crate::numerics::quotient::QuotientFamily;

type C64 = Complex<f64>;
use super::points::{Pt, collocation, small_stick_slip_points};

/// The reduced problem's constants: bp = bq = b (b*), friction mu (mu~), edge exponent g.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Constants {
    pub(crate) b: f64,
    pub(crate) mu: f64,
    pub(crate) g: f64,
}

/// Sizes of the bases at one level of refinement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Sizes {
    /// Even Legendre polynomials in the stick p, odd ones in the stick q.
    pub(crate) legendre: usize,
    /// Odd P^(g,g) (below [`QUOTIENT_BELOW`] the quotient family's) in the stick q.
    pub(crate) stick_g: usize,
    /// P^(-g,0) and P^(-g,g) on the slip zone.
    pub(crate) slip: [usize; 2],
    /// Pole pairs per stick block and poles per slip block.
    pub(crate) poles: [usize; 2],
    /// Columns X x^(2k) and i X x^(2k+1), k < bonded, on the stick zone ((X1)).
    pub(crate) bonded: usize,
    /// Factor on the collocation points per unknown ([`STICK_POINTS`], [`SLIP_POINTS`]):
    /// 1 at level 1 and below and where [`SMALL_STICK_BELOW`] <= c < [`DENSE_BELOW_C`],
    /// [`SPARSE_POINTS`] above (and below [`SMALL_STICK_BELOW`], whose own slip points carry
    /// the decades next to x = c). The
    /// rule on c is here, with the sizes fixed by the starting c, so that sigma(lc) stays
    /// smooth across the trial c of one search; g's rule ([`DENSE_BELOW_G`]) is fixed per
    /// answer and applied at the assembly.
    pub(crate) points: f64,
}

impl Sizes {
    /// The sizes at `level` (1, 2, ...) for the stick edge c (1 - c = w): polynomial degrees
    /// growing linearly in the level, pole counts in the decades between the zones' ends
    /// and their nearest singularities, 2 + level / 2 per decade (B4: at b* = 0.2857,
    /// mu~ = 1, 1 - c = 2.1e-3, 1 + level / 2 per decade needed level 9 for tractions to
    /// 1e-10, 2 + level / 2 level 7, with 15% fewer unknowns).
    pub(crate) fn at(level: usize, c: f64, w: f64) -> Self {
        Self::at_real(level as f64, c, w)
    }

    /// [`Sizes::at`] for a fractional level l (the half levels of the known edge's ladder):
    /// the same rules, each count rounded to the nearest integer.
    pub(crate) fn at_real(l: f64, c: f64, w: f64) -> Self {
        let per_decade = 2.0 + 0.5 * l;
        let decades = |[near, far]: [f64; 2]| (far / near).log10().max(0.0);
        let [stick, slip] = pole_ranges(c, w);
        let bonded = w < BONDED_BELOW;
        let (stick_decades, slip_decades) = (decades(stick), decades(slip));
        Sizes {
            legendre: (3.0 + 2.0 * l).round() as usize,
            stick_g: (2.0 + 2.0 * l).round() as usize,
            slip: {
                let d = if l > 1.0 && !bonded {
                    SLIP_DEGREES
                } else {
                    DENSE_SLIP_DEGREES
                };
                [
                    (d[0] + 3.0 * l).round() as usize,
                    (d[1] + 2.0 * l).round() as usize,
                ]
            },
            poles: [
                (stick_decades
                    * if bonded {
                        BONDED_STICK_DENSITY
                    } else if l >= STICK_EXTRA_FROM {
                        per_decade + STICK_EXTRA_DENSITY
                    } else {
                        per_decade
                    })
                .ceil() as usize,
                (slip_decades * per_decade).ceil() as usize,
            ],
            bonded: if bonded { BONDED } else { 0 },
            points: if l <= 1.0 || (SMALL_STICK_BELOW..DENSE_BELOW_C).contains(&c) {
                1.0
            } else {
                SPARSE_POINTS
            },
        }
    }
}

/// Stick pole pairs per decade added from level [`STICK_EXTRA_FROM`] on (where the slip zone
/// is not thin; there [`BONDED_STICK_DENSITY`] holds). Where the stick poles span about two
/// decades (1 - c = 0.13, c = 0.87) the levels' traction errors at the tabulated c against
/// level 8 fell by only 3 from level 2 to 2.5 (their distance to their coarser columns
/// 1.8e-9, 6.2e-10), and by 20 to level 3, the first to add a pole pair (2 + l / 2 per
/// decade over 1.82 decades: 6, 6, 7 pairs): the stick poles, not the degrees, set the pace.
/// Measured on the 10 spectral speed scenes (c to 1e-10; thread CPU time, the median over
/// the scenes, the offsets alternated in one run; true error against the panels at
/// (1e-13, 1e-11)), the offset at every level:
///
/// | offset per decade | tractions 1e-10 | the two scenes at 1 - c = 0.13 | 1e-8 |
/// |---|---|---|---|
/// | 0 | 0.353 ms | 0.392 ms, 60 unknowns | 0.135 ms |
/// | 0.5 | 0.333 ms | 0.41-0.42 ms, 62 | |
/// | 1 | 0.251 ms | 0.184-0.189 ms, 57 | 0.140 ms |
/// | 1.5 | 0.252 ms | 0.189-0.191 ms, 59 | |
///
/// (every answer within its estimate, largest true / estimate 0.082 with each). At tractions
/// to 1e-8 the offset only added 4 unknowns to three scenes, so it starts at level 2.5, the
/// first level at tractions to 1e-10 where 1 - c = 0.01 .. 0.2 (`first_half_level` in
/// `spectral`): from level 2 the median at 1e-8 went 0.124 to 0.138 ms (the two scenes at
/// 1 - c = 0.13 start at level 2 there), from level 2.5 it stayed at 0.123-0.124 ms while
/// the median at 1e-10 went 0.357, 0.356 to 0.301, 0.303 ms (alternated twice in one run).
const STICK_EXTRA_DENSITY: f64 = 1.0;
const STICK_EXTRA_FROM: f64 = 2.5;

/// The slip families' degrees above level 1 where the slip zone is not thin (no bonded
/// columns, 1 - c >= [`BONDED_BELOW`]): 2 + 3 l for P^(-g,0) and 2 l for P^(-g,g) at level
/// l. The slip zone's functions are smoother on their zone than the stick zone's on theirs
/// (the nearest singularity not carried by a weight or a pole lies farther out in the
/// zone's own variable), and the coarser columns' estimate is carried by the stick blocks: at level 1.5 on the 10 spectral speed scenes, at the tabulated c against
/// level 5, three degrees fewer in either slip family left the true error where it was, one
/// stick degree fewer raised it 2-30 times (docs/theory_spectral.md section 5). Measured on
/// those scenes (`coupled::solve_to`, c to 1e-10; true: the traction distance to the panels
/// at (1e-13, 1e-11); thread CPU time, the median over the scenes, the four offsets
/// alternated in one run; level 1 at [`DENSE_SLIP_DEGREES`] in all four, steel at mu = 1,
/// 1 - c = 2.1e-3, at the row's offsets):
///
/// | offsets | tractions 1e-8 | 1e-10 | largest true / estimate |
/// |---|---|---|---|
/// | (5, 3) | 0.229 ms | 0.493 ms | 0.18 |
/// | (3, 1) | 0.206 ms | 0.454 ms | 0.52 |
/// | (2, 0) (this rule) | 0.196 ms | 0.429 ms | 0.086 |
/// | (0, 0) | 0.184 ms | 0.405 ms | 0.066 |
///
/// With (2, 0) every answer but steel's at mu = 1 comes at its level with 6 unknowns fewer;
/// steel at mu = 1 took half a level more at 1e-10 (and with (0, 0) at 1e-8 too); with
/// (-1, -1) the ply, steel and kappa = 0.4 at mu = 1 each took a level more at 1e-8. Thin
/// slip zones, steel at mu = 1 among them, keep [`DENSE_SLIP_DEGREES`]; with that rule, against
/// the dense sizes everywhere (the same scenes, alternated twice in one run): 0.243, 0.241 to
/// 0.211, 0.210 ms at tractions to 1e-8, 0.551, 0.541 to 0.479, 0.470 ms at 1e-10.
const SLIP_DEGREES: [f64; 2] = [2.0, 0.0];

/// The slip families' offsets at level 1 and in thin slip zones (1 - c < [`BONDED_BELOW`]).
/// Thin slip zones' answers are sensitive to rounding at the level of their estimates
/// (docs/theory_spectral.md section 5), and there the leaner sizes moved one answer past its
/// estimate: b* = 0.17, mu~ = 32.45 (1 - c = 1.4e-11) answered at level 5 (165 unknowns)
/// 7.3e-9 from the panels against the sum of both estimates 3.4e-9, where the dense sizes
/// answer at level 3 (149), 2.2e-9 from them
/// (`coupled::tests::spectral_agrees_with_the_panels_below_the_table_edge_on_a_grid`).
/// The ladder's first level measures sigma's slope and the tractions' move per lc for the
/// levels above it, whose bounds (`SENSITIVITY_BOUNDS` in `spectral`) were measured with
/// these sizes; with [`SLIP_DEGREES`] at level 1 too, the
/// move per sigma measured there at b* = 0.262, mu~ = 11.2 rose to 1.51, past the band's bound
/// of 1.4 (twice the largest measured, 0.69). It was also the level that answered alone at
/// loose tolerances, where (2, 0) gained nothing (tractions to 1e-6: 0.226 against 0.226 ms);
/// since `FIRST_HALF_LEVEL_MIN` in `spectral` level 1.5 answers there.
const DENSE_SLIP_DEGREES: [f64; 2] = [5.0, 3.0];

/// Below this g the slip zone's second family is the difference quotient
/// (1 - s)^-g ((1 + s)^g - 1) / g p_k (docs/theory_spectral.md, section 7) in place of
/// (1 - s)^-g (1 + s)^g P^(-g,g): the same span, without the near-dependence on the first
/// family as g -> 0. Above it the power family is kept, as measured on every grid of (B5)
/// (from g = 0.03 up). Below it, on the grid of `coupled::tests::small_g_against_the_panels`
/// (c to 1e-10, tractions to 1e-8, 8 x 9 points with g = 0.002 .. 0.03; switch at 0.05 in
/// that run), all 72 answered with the quotient and 71 with the power family; at g = 0.001,
/// 6 of 8 answered, all agreeing with the panels, against 5 with the power family, one of
/// them with c 1.7 times the sum of both estimates from the panels'.
///
/// The stick q's edge family switches at the same g ([`stick_edge_family`], (Q6)). On the
/// same test's grid with g = 2.1e-4 .. 0.03 (9 x 13 points, (J2s) in both runs), switched at
/// 0.03 or only below 0.002: 117 of 117 answered and agreeing either way (median 0.8 ms); on
/// `coupled::tests::thin_slip_zones_at_small_g_agree_with_the_panels` the seven points
/// answered at the same levels but one, b* = 0.25, mu~ = 100 (g = 0.0127, 1 - c = 1.4e-7):
/// level 2 in 2 ms with the quotient, level 4 in 13 ms with the power family. Below about
/// g = 2e-4 only the quotient answers (`spectral::G_MIN`).
pub(crate) const QUOTIENT_BELOW: f64 = 0.03;

/// Bonded columns X x^(2k), i X x^(2k+1), k < BONDED, where 1 - c < BONDED_BELOW (X1).
const BONDED: usize = 3;
const BONDED_BELOW: f64 = 1e-2;

/// The nearest stick pole's distance beyond x = 1, in units of 1 - c, with the bonded columns
/// (elsewhere 0.1). The traction distance of level 5, at its own root, to the panels at c to
/// 1e-12 and tractions to 1e-10 (three Newton steps at level 5 from the panels' c; the
/// panels' own distance to a solve at (1e-13, 1e-12) was below 1.4e-13):
///
/// | nearest / (1 - c) | b* = 0.15, mu~ = 10, 8.3e-13 | 0.1, 1.5, 3.7e-13 | 0.15, 4, 1.2e-11 | 0.1, 1, 1.8e-10 |
/// |---|---|---|---|---|
/// | 0.3 | 4.6e-8 .. 5.3e-8 | | | |
/// | 0.1 | 1.7e-8 .. 1.8e-8 | 1.0e-8 .. 1.2e-8 | 3.0e-10 .. 4.4e-10 | 3.3e-11 |
/// | 0.03 | 1.6e-10 .. 2.3e-10 | 5.8e-11 .. 6.4e-11 | 9.7e-11 .. 1.8e-10 | 9.8e-13 .. 4.9e-12 |
/// | 0.01 | 1.6e-10 .. 2.9e-10 | 5.9e-11 .. 1.6e-10 | 1.6e-11 .. 2.8e-10 | 1.7e-12 .. 2.4e-11 |
/// | 0.001 | 1.1e-10 .. 1.5e-10 | | | |
///
/// The three values per entry are the three roots; 4 bonded powers in place of 3 gave
/// 2.4e-8 .. 2.7e-8 at the first scene, 2 gave 4.1e-8 .. 4.5e-8, and 4 poles per decade
/// in place of 2.5 7.4e-8 .. 1.6e-7: the stick functions next to x = c see the edge
/// singularity at x = 1, (1 - c) away, and need poles within a fraction of that distance
/// from it. At fixed c (the panels') the residual (R1) of levels 2-5 fell from
/// 5e-12 .. 5e-10 to 1e-14 .. 5e-12 at 1 - c = 3.7e-13 .. 2.2e-9.
const BONDED_NEAREST: f64 = 0.03;

/// Stick poles per decade with the bonded columns, at every level (level 1's density).
const BONDED_STICK_DENSITY: f64 = 2.5;

/// The ranges [nearest, farthest] of the poles' distances (B4): the stick poles at
/// x = +-(1 + zeta), zeta from (1 - c) / 10 (with the bonded columns [`BONDED_NEAREST`]
/// (1 - c)) to c, the slip poles at x = -(c + eta), eta from
/// c / 10 to 1 - c. The nearest is a tenth of the distance from the zone's end to the
/// singular point beyond it; the farthest is the zone's own length scale. A pole farther
/// away than that is resolved by the zone's polynomials already (for the stick zone,
/// tau >= 2 and a convergence factor of 3.7 per degree) and adds only a near-dependent
/// column, whose large cancelling coefficients are rounding noise in the tractions ((R2)).
/// Measured in one run of
/// `examples/spectral_timing.rs` (the 8 scenes the spectral solver answers, c to 1e-10,
/// tractions to 1e-8): with zeta up to 2 and eta up to 1 (the first rule) 79-191 unknowns;
/// with this rule 66-157, and the answers met the same noise bound. Before the noise bound,
/// on the 14 scenes of tests/c/coupled_residuals.c the spectral solver serves, the largest
/// rounding amplification (noise / machine epsilon) fell from 2.0e6 to 5.4e4.
fn pole_ranges(c: f64, w: f64) -> [[f64; 2]; 2] {
    let near = if w < BONDED_BELOW {
        BONDED_NEAREST
    } else {
        0.1
    };
    [[near * w, c], [0.1 * c, w]]
}

/// `n` points log-spaced over [lo, hi].
fn log_spaced(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![(lo * hi).sqrt()];
    }
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// The families' transforms at a set of points, each family at all of them at once
/// ([`Block::family_transforms_many`]): the stick blocks' at tau(x) (the odd Legendre block
/// sharing the even one's family), the slip blocks' at s(x) and at the mirror point s(-x),
/// each with the weight factors of the point's own zone ([`Basis::factors`]).
struct FamilyRows {
    /// Per family (stick 0, 1, 2; slip 0, 1; mirror 0, 1): its length and its rows.
    rows: [(usize, Vec<f64>); 7],
    /// Which of `rows` serves stick block 1 (0 where it shares block 0's family).
    stick_odd: usize,
    /// The points' weight factors.
    factors: Vec<Factors>,
}

impl FamilyRows {
    fn new(basis: &Basis, points: &[Pt]) -> Self {
        let factors: Vec<Factors> = points.iter().map(|p| basis.factors(p)).collect();
        let tau: Vec<Point> = points.iter().map(|p| basis.tau(p)).collect();
        let (s, sm): (Vec<Point>, Vec<Point>) = points.iter().map(|p| basis.s_pair(p)).unzip();
        let none = vec![None; points.len()];
        let stick_g: Vec<_> = factors.iter().map(|f| f.stick_g).collect();
        let slip: [Vec<_>; 2] = [0, 1].map(|i| factors.iter().map(|f| f.slip[i]).collect());
        let run = |block: &Block, at: &[Point], f: &[Option<(f64, f64)>]| {
            let n = block.scratch();
            let mut out = vec![0.0; n * at.len()];
            block.family_transforms_many(at, f, &mut out);
            (n, out)
        };
        let shared = basis.stick[1].same_family(&basis.stick[0]);
        FamilyRows {
            rows: [
                run(&basis.stick[0], &tau, &none),
                if shared {
                    (0, Vec::new())
                } else {
                    run(&basis.stick[1], &tau, &none)
                },
                run(&basis.stick[2], &tau, &stick_g),
                run(&basis.slip[0], &s, &slip[0]),
                run(&basis.slip[1], &s, &slip[1]),
                run(&basis.slip[0], &sm, &none),
                run(&basis.slip[1], &sm, &none),
            ],
            stick_odd: if shared { 0 } else { 1 },
            factors,
        }
    }

    /// The seven families' transforms at point i ([`Basis::hilbert_row_from`]).
    fn at(&self, i: usize) -> [&[f64]; 7] {
        let row = |k: usize| {
            let (n, v) = &self.rows[k];
            &v[i * n..(i + 1) * n]
        };
        [
            row(0),
            row(self.stick_odd),
            row(2),
            row(3),
            row(4),
            row(5),
            row(6),
        ]
    }
}

/// The weight factors of a point's own zone's blocks ([`Basis::factors`]).
#[derive(Clone, Copy, Debug)]
struct Factors {
    stick_g: Option<(f64, f64)>,
    slip: [Option<(f64, f64)>; 2],
}

/// The stick q's edge family: (1 - tau^2)^g P^(g,g), or below [`QUOTIENT_BELOW`] the
/// difference-quotient family of the same span with the Legendre block
/// (`numerics::quotient::QuotientFamily::stick`, docs/theory_spectral.md (Q6)-(Q8)).
fn stick_edge_family(g: f64, n: usize) -> Family {
    if g < QUOTIENT_BELOW {
        QuotientFamily::stick(g, n).into()
    } else {
        JacobiFamily::new(g, g, n).into()
    }
}

/// The bases of both zones for one c.
#[derive(Clone, Debug)]
pub(crate) struct Basis {
    pub(crate) c: f64,
    pub(crate) w: f64,
    pub(crate) k: Constants,
    /// The sizes the bases were built with (for the tests to assemble a level again).
    #[cfg(test)]
    pub(crate) sizes: Sizes,
    /// Stick zone: p (even), q (odd Legendre), q ((1 - tau^2)^g P^(g,g), odd; below
    /// [`QUOTIENT_BELOW`] ((1 - tau^2)^g - 1) / g times odd Legendre).
    stick: [Block; 3],
    /// Slip zone: (1 - s)^-g P^(-g,0), (1 - s)^-g (1 + s)^g P^(-g,g).
    slip: [Block; 2],
    /// The bonded columns (last), if any.
    bonded: Option<Bonded>,
    scratch: usize,
}

/// Column ranges: stick p, stick q (both blocks), slip, sigma.
impl Basis {
    pub(crate) fn new(k: Constants, c: f64, w: f64, sizes: Sizes) -> Self {
        let g = k.g;
        let [[z0, z1], [e0, e1]] = pole_ranges(c, w);
        // stick poles at x = +-(1 + zeta): tau = (1 + zeta) / c
        let stick_z: Vec<Point> = log_spaced(z0, z1, sizes.poles[0])
            .into_iter()
            .map(|z| Point::offsets(-(w + z) / c, (1.0 + z + c) / c))
            .collect();
        // slip poles at x = -(c + eta): s = (2 x - c - 1) / w
        let slip_z: Vec<Point> = log_spaced(e0, e1, sizes.poles[1])
            .into_iter()
            .map(|e| Point::offsets(2.0 * (1.0 + c + e) / w, -2.0 * (2.0 * c + e) / w))
            .collect();
        let n = sizes.legendre;
        let ng = sizes.stick_g;
        // the even and odd Legendre blocks: one family (built once)
        let legendre = JacobiFamily::new(0.0, 0.0, 2 * n);
        let stick = [
            Block::new(legendre.clone(), parity(n, 0), &stick_z, 1.0),
            Block::new(legendre, parity(n, 1), &stick_z, -1.0),
            // the poles times (1 - tau^2)^g only in thin slip zones (with the bonded
            // columns): elsewhere the unweighted pairs carry the stick q's continuation to
            // x = +-1 alone (docs/theory_spectral.md (B2), measured there)
            Block::new(
                stick_edge_family(g, 2 * ng),
                parity(ng, 1),
                if sizes.bonded > 0 { &stick_z } else { &[] },
                -1.0,
            ),
        ];
        let [s0, sg] = sizes.slip;
        let second: Family = if g < QUOTIENT_BELOW {
            QuotientFamily::new(g, sg).into()
        } else {
            JacobiFamily::new(-g, g, sg).into()
        };
        let slip = [
            Block::new(
                JacobiFamily::new(-g, 0.0, s0),
                (0..s0).collect(),
                &slip_z,
                0.0,
            ),
            Block::new(second, (0..sg).collect(), &slip_z, 0.0),
        ];
        let scratch = stick
            .iter()
            .chain(&slip)
            .map(Block::scratch)
            .max()
            .unwrap_or(1);
        let bonded = (sizes.bonded > 0).then(|| Bonded::new(k.b, c, w, 2 * sizes.bonded));
        Basis {
            c,
            w,
            k,
            #[cfg(test)]
            sizes,
            stick,
            slip,
            bonded,
            scratch,
        }
    }

    /// The columns of the coarser system of [`Assembled::solve_pair`]: each block less its
    /// highest polynomial degree and one pole (its second nearest), the bonded columns kept.
    ///
    /// The coarser solution's distance from the finer one is the finer one's error estimate
    /// (twice it, [`super::SAFETY`]). Measured against level 8 (c from the table, 8 scenes
    /// b* = 0.25 .. 0.9, mu~ = 0.2 .. 8, c = 0.007 .. 1 - 4e-6), the ratio of that estimate
    /// to the finer solution's true traction error at levels 1 and 2 was, for the pole
    /// dropped:
    ///
    /// | pole dropped | smallest ratio | largest | level-1 estimates <= 1e-8 |
    /// |---|---|---|---|
    /// | second nearest (this rule) | 2.7 | 1.2e3 | 6 of 8 |
    /// | nearest | 3.9 | 6.1e3 | 4 of 8 |
    /// | farthest | 1.3 | 1.3e3 | 7 of 8 |
    ///
    /// The farthest pole is nearly resolved by the polynomials, so dropping it hides the
    /// pole part of the error (ratios down to 1.3, at the noise floor of a thin slip zone);
    /// dropping two degrees per family instead of one made the level-1 estimates 10-100
    /// times larger (2 of 8 within 1e-8).
    pub(crate) fn coarse_columns(&self) -> Vec<bool> {
        let mut keep: Vec<bool> = self
            .stick
            .iter()
            .chain(&self.slip)
            .flat_map(|b| b.coarse_columns(1, 1))
            .collect();
        keep.extend(std::iter::repeat_n(true, self.bonded_len()));
        keep
    }

    /// Number of coefficients (without sigma).
    pub(crate) fn len(&self) -> usize {
        self.stick
            .iter()
            .chain(&self.slip)
            .map(Block::len)
            .sum::<usize>()
            + self.bonded_len()
    }

    fn bonded_len(&self) -> usize {
        self.bonded.as_ref().map_or(0, Bonded::degree)
    }

    /// Start of the bonded columns.
    fn bonded_start(&self) -> usize {
        self.len() - self.bonded_len()
    }

    /// The bonded columns' (p, q) parts from the complex X x^k (or their transforms):
    /// X x^(2k) gives (Re, Im), i X x^(2k+1) gives (-Im, Re).
    /// `pv` and `qv` are the bonded block of the columns (from [`Basis::bonded_start`]).
    fn bonded_split(f: &[C64], pv: &mut [f64], qv: &mut [f64]) {
        for (j, v) in f.iter().enumerate() {
            let col = j / 2 + (j % 2) * (f.len() / 2);
            if j % 2 == 0 {
                pv[col] = v.re;
                qv[col] = v.im;
            } else {
                pv[col] = -v.im;
                qv[col] = v.re;
            }
        }
    }

    /// Start of the stick q columns, of the slip columns.
    fn starts(&self) -> (usize, usize) {
        let q = self.stick[0].len();
        (q, q + self.stick[1].len() + self.stick[2].len())
    }

    /// tau = x / c with its offsets.
    fn tau(&self, p: &Pt) -> Point {
        Point::offsets(-p.xmc / self.c, (self.c + p.x) / self.c)
    }

    /// s(x) and s(-x) with their offsets.
    fn s_pair(&self, p: &Pt) -> (Point, Point) {
        let w = self.w;
        (
            Point::offsets(2.0 * p.omx / w, 2.0 * p.xmc / w),
            Point::offsets(2.0 * (1.0 + p.x) / w, -2.0 * (p.x + self.c) / w),
        )
    }

    /// The weight factors at a point of its own zone's blocks ([`Block::factors`]): the
    /// stick q's P^(g,g) at a stick point, the two slip blocks at a slip point (the second
    /// with the first's (1 - s)^-g). Each is computed once for the values and the transforms
    /// there.
    fn factors(&self, p: &Pt) -> Factors {
        if p.on_stick() {
            Factors {
                stick_g: self.stick[2].factors(self.tau(p), None),
                slip: [None, None],
            }
        } else {
            let (s, _) = self.s_pair(p);
            let first = self.slip[0].factors(s, None);
            Factors {
                stick_g: None,
                slip: [first, self.slip[1].factors(s, first.map(|f| f.0))],
            }
        }
    }

    /// The columns' values (p and q parts) at a point of the zone it lies in; `buf` of
    /// length [`Basis::scratch_len`] at least.
    pub(crate) fn tractions_row(&self, p: &Pt, pv: &mut [f64], qv: &mut [f64], buf: &mut [f64]) {
        self.tractions_row_with(p, &self.factors(p), pv, qv, buf);
    }

    /// [`Basis::tractions_row`] with the point's weight factors ([`Basis::factors`]).
    fn tractions_row_with(
        &self,
        p: &Pt,
        factors: &Factors,
        pv: &mut [f64],
        qv: &mut [f64],
        buf: &mut [f64],
    ) {
        pv.fill(0.0);
        qv.fill(0.0);
        let buf = &mut buf[..self.scratch];
        let (q0, s0) = self.starts();
        if p.on_stick() {
            let t = self.tau(p);
            // the even and odd Legendre blocks share their family's values
            let n0 = self.stick[0].len();
            let w = self.stick[0].weight(t);
            self.stick[0].family_values(t, w, buf);
            self.stick[0].values_from(t, w, buf, &mut pv[..n0]);
            let n1 = self.stick[1].len();
            let w = if self.stick[1].same_family(&self.stick[0]) {
                w
            } else {
                let w = self.stick[1].weight(t);
                self.stick[1].family_values(t, w, buf);
                w
            };
            self.stick[1].values_from(t, w, buf, &mut qv[q0..q0 + n1]);
            let n2 = self.stick[2].len();
            self.stick[2].values_with(t, factors.stick_g, buf, &mut qv[q0 + n1..q0 + n1 + n2]);
            if let Some(bx) = &self.bonded {
                let mut f = [C64::new(0.0, 0.0); MAX_DEGREE];
                let f = &mut f[..bx.degree()];
                bx.values(p.x, p.omx, f);
                let at = self.bonded_start();
                Self::bonded_split(f, &mut pv[at..], &mut qv[at..]);
            }
        } else {
            let (s, _) = self.s_pair(p);
            let mut at = s0;
            for (b, f) in self.slip.iter().zip(factors.slip) {
                let n = b.len();
                b.values_with(s, f, buf, &mut pv[at..at + n]);
                at += n;
            }
            for j in s0..at {
                qv[j] = self.k.mu * pv[j];
            }
        }
    }

    /// The columns' H[p] and H[q] at a point; `scratch` of length [`Basis::scratch_len`].
    #[cfg(test)]
    fn hilbert_row(&self, p: &Pt, hp: &mut [f64], hq: &mut [f64], scratch: &mut [f64]) {
        let rows = FamilyRows::new(self, std::slice::from_ref(p));
        self.hilbert_row_from(p, &rows.at(0), hp, hq, scratch);
    }

    /// The columns' H\[p\] and H\[q\] at a point from the families' transforms there
    /// ([`FamilyRows`]); `scratch` of length [`Basis::scratch_len`].
    fn hilbert_row_from(
        &self,
        p: &Pt,
        fam: &[&[f64]; 7],
        hp: &mut [f64],
        hq: &mut [f64],
        scratch: &mut [f64],
    ) {
        hp.fill(0.0);
        hq.fill(0.0);
        let other = &mut scratch[self.scratch..self.scratch + hp.len()];
        let (q0, s0) = self.starts();
        let t = self.tau(p);
        let n0 = self.stick[0].len();
        self.stick[0].transforms_from(t, fam[0], &mut hp[..n0]);
        let n1 = self.stick[1].len();
        self.stick[1].transforms_from(t, fam[1], &mut hq[q0..q0 + n1]);
        let n2 = self.stick[2].len();
        self.stick[2].transforms_from(t, fam[2], &mut hq[q0 + n1..q0 + n1 + n2]);
        // H = -T on the zone's own map
        for v in &mut hp[..s0] {
            *v = -*v;
        }
        for v in &mut hq[..s0] {
            *v = -*v;
        }
        let (s, sm) = self.s_pair(p);
        let mut at = s0;
        for (i, b) in self.slip.iter().enumerate() {
            let n = b.len();
            b.transforms_from(s, fam[3 + i], &mut hp[at..at + n]);
            b.transforms_from(sm, fam[5 + i], &mut other[at..at + n]);
            at += n;
        }
        let mu = self.k.mu;
        for j in s0..at {
            // the mirror zone: p even adds +T(s(-x)), q odd -T(s(-x))
            let (own, mirror) = (hp[j], other[j]);
            hp[j] = -own + mirror;
            hq[j] = mu * (-own - mirror);
        }
        if let Some(bx) = &self.bonded {
            // on the stack: this runs at every collocation point
            let mut f = [C64::new(0.0, 0.0); MAX_DEGREE];
            let mut fb = [C64::new(0.0, 0.0); 2 * MAX_DEGREE];
            let f = &mut f[..bx.degree()];
            bx.transforms(p.x, p.omx, p.xmc, f, &mut fb[..bx.scratch_len()]);
            let at = self.bonded_start();
            Self::bonded_split(f, &mut hp[at..], &mut hq[at..]);
        }
    }

    /// Length of the scratch buffer of the rows' evaluations ([`Basis::tractions_row`],
    /// [`Basis::hilbert_row_from`]).
    fn scratch_len(&self) -> usize {
        self.scratch + self.len()
    }

    /// int_{-1}^{1} p of each column.
    fn integrals(&self) -> Vec<f64> {
        let mut out = vec![0.0; self.len()];
        let n0 = self.stick[0].len();
        self.stick[0].integrals(&mut out[..n0]);
        for v in &mut out[..n0] {
            *v *= self.c;
        }
        let (_, s0) = self.starts();
        let mut at = s0;
        for b in &self.slip {
            let n = b.len();
            b.integrals(&mut out[at..at + n]);
            at += n;
        }
        for v in &mut out[s0..at] {
            *v *= self.w;
        }
        if let Some(bx) = &self.bonded {
            let at = self.bonded_start();
            let mut q = vec![0.0; out.len() - at];
            Self::bonded_split(&bx.integrals(), &mut out[at..], &mut q);
        }
        out
    }
}

/// Chebyshev points per unknown in each zone (rows: two per stick point, one per slip point;
/// about 2.6 rows per unknown in all with the clusters, docs/theory_spectral.md (C1)).
const STICK_POINTS: f64 = 0.6;
const SLIP_POINTS: f64 = 1.0;

/// Factor on [`STICK_POINTS`] and [`SLIP_POINTS`] above level 1 where g >= [`DENSE_BELOW_G`]
/// (about 1.5 rows per unknown there; docs/theory_spectral.md (C1)). Level 1 keeps the full
/// points: it answered alone at loose tolerances (before `FIRST_HALF_LEVEL_MIN` in
/// `spectral`), where with halved points its traction estimate missed once (tests/auto.rs,
/// ply at mu = 0.1 and 1e-4: error 7.2e-8 against an estimate of 6.6e-8), and it measures
/// the slope and the move per lc whose bounds were measured with these points. Measured, with the sparser points at every c (before
/// [`DENSE_BELOW_C`]), on the 10 spectral scenes of the 12 speed scenes (thread CPU time,
/// median over the scenes, the two alternated twice in one run):
///
/// | points above level 1 | (1e-10, 1e-8) | (1e-10, 1e-10) |
/// |---|---|---|
/// | 1 (0.6, 1.0 per unknown) | 0.841, 0.836 ms | 1.476, 1.457 ms |
/// | 0.5 (0.3, 0.5 per unknown) | 0.588, 0.594 ms | 1.159, 1.182 ms |
///
/// and, with halved points at every level, on 120 mid-range points and the 53 x 53 grid of
/// (C1): every answer at (1e-10, 1e-8) agreeing with the panels, 23 of 765 lost at
/// (1e-10, 1e-10), 20 of them at g < 0.015 ([`DENSE_BELOW_G`]).
const SPARSE_POINTS: f64 = 0.5;

/// Below this stick edge every level keeps the full points: next to a small stick zone the
/// slip zone's tractions vary on the scale c, and with the sparser points the answers, whose
/// traction distance (the L1 norm of the estimates) still held, moved pointwise by far more
/// than with the full points between the collocation points a few c beyond x = c. The
/// largest pointwise distance to the panels at (1e-13, 1e-12) on |x| <= 0.99 (and on a fine
/// grid of (0, 50 c)) of the answers at (1e-10, 1e-10), at b* = 0.3, 0.6, 0.9:
///
/// | c | sparser points | full points |
/// |---|---|---|
/// | 1.7e-4 .. 2.7e-4 | 1.1e-10 .. 7.8e-9 | 2.6e-12 .. 1.2e-11 |
/// | 4.8e-4 .. 7.8e-4 | 9.9e-12 .. 1.8e-9 | 1.1e-12 .. 2.8e-11 |
/// | 1.2e-3 .. 1.4e-3 | 1.3e-11 .. 3.4e-11 | 4.3e-12 .. 1.4e-11 |
/// | 2.0e-3 .. 4.6e-3 | 1.6e-12 .. 1.2e-11 | 7.9e-13 .. 2.5e-12 |
/// | 5.3e-3 .. 4.4e-2 | 2.3e-12 .. 1.7e-11 | 7.4e-13 .. 8.0e-12 |
///
/// (the carbon ply at mu = 0.1, c = 4.8e-5: 6.4e-9 against 3.0e-10 at (1e-10, 1e-10), and
/// 1.2e-9 against 1.4e-11 at (1e-12, 1e-12)). Next to thin slip zones (1 - c = 4e-6 .. 5e-2,
/// the same b*) neither kind of points was the better one pointwise (both 4e-13 .. 5e-9),
/// and the sparser ones answered more of them.
const DENSE_BELOW_C: f64 = 2e-3;

/// Below this edge exponent every level keeps the full points: there the slip columns'
/// rounding (q = mu~ p) sets the traction floor near 1e-10 (docs/theory_spectral.md
/// section 5), and halved points lost 20 answers of the 53 x 53 grid at (1e-10, 1e-10)
/// below g = 0.015; with the full points below 0.02, 762 of 765 answered.
const DENSE_BELOW_G: f64 = 0.02;

/// Below this stick edge (the smallest served before, `spectral::C_MIN` of the session that
/// measured it) the slip zone gets one more collocation point per slip pole column and
/// decade of x - c, next to the cluster's three per decade ([`slip_columns_per_decade`],
/// [`small_stick_slip_points`]), and the levels above 1 the sparser Chebyshev points
/// ([`SPARSE_POINTS`]). Next to a small stick zone the slip tractions vary over the decades
/// of x - c from c up, and the slip poles at x = -(c + eta) give both slip blocks
/// 2 (2 + l/2) columns per decade there (5.5-7 at levels 1.5-3) against the cluster's three
/// rows: the least squares was underdetermined decade by decade, and the levels' common
/// error lay between the rows (b* = 0.85, mu~ = 0.1343, c = 7.7e-8, at (1e-10, 1e-8): p off
/// the panels by 1.1e-4 .. 3.3e-4 of p at x - c = 10 c .. 100 c, 2.3e-8 in the traction
/// distance against an estimate of 2.8e-9; with 6 rows per decade 2.4e-12 against 1.8e-11,
/// the same 83 unknowns). Measured on the 26 and 31 points with 1e-13 < c < 4e-5 of
/// b* = 0.25 .. 0.95 (8 rows) by mu~ = 0.01 .. 100 (40 log-spaced) that the full-slip limit
/// does not answer, c to 1e-10, each answer against the panels at (1e-12, 1e-10) (true
/// traction error over the answer's own estimate; thread CPU time of single answers):
///
/// | slip rows per decade of x - c | tractions 1e-8: failed, largest | median, max | 1e-10: failed, largest | median, max |
/// |---|---|---|---|---|
/// | 3 (the cluster alone) | 17 of 26, 5102 | 0.60, 1.47 ms | 21 of 30, 1778 | 0.80, 2.58 ms |
/// | 3 + a quarter column each | 3 of 26, 70 | 0.62, 1.18 ms | 10 of 30, 496 | 0.76, 1.85 ms |
/// | 6 | 0 of 26, 0.36 | 0.67, 1.25 ms | 0 of 30, 0.48 | 0.82, 3.29 ms |
/// | 3 + half a column each | 0 of 26, 0.31 | 0.62, 1.04 ms | 0 of 30, 0.54 | 0.87, 3.36 ms |
/// | 3 + one each, full points | 0 of 26, 0.32 | 0.71, 1.16 ms | 0 of 30, 0.34 | 0.91, 4.67 ms |
/// | 3 + one each, sparser points (this rule) | 0 of 26, 0.35 | 0.50, 0.97 ms | 0 of 30, 0.50 | 0.63, 2.10 ms |
/// | the same with `spectral::RATE_FLOOR` | 0 of 26, 0.24 | 0.53, 0.87 ms | 0 of 30, 0.57 | 0.63, 2.90 ms |
///
/// With half a column each the rows only match the columns at level 2; one each keeps a
/// row per column at every level. The full points (kept below [`DENSE_BELOW_C`] for the
/// decades next to x = c, (C1)) are not needed once these rows carry them: with the sparser
/// ones the answers were as near the panels (largest true / estimate 0.35 and 0.50) and
/// pointwise, at x - c = 0.1 c .. 1 - c, no farther (the largest pointwise distance over
/// the estimate 16 and 49 against 17 and 80 with the full points; both at the panels' own
/// pointwise error next to x = c, section 4).
pub(crate) const SMALL_STICK_BELOW: f64 = 4e-5;

/// The slip pole columns per decade of their distances (both slip blocks, [`pole_ranges`]'
/// slip range): the extra slip points per decade of [`SMALL_STICK_BELOW`].
fn slip_columns_per_decade(c: f64, w: f64, sizes: Sizes) -> f64 {
    let [_, [near, far]] = pole_ranges(c, w);
    let decades = (far / near).log10().max(1.0);
    2.0 * sizes.poles[1] as f64 / decades
}

/// The solution of the fixed-c system.
#[derive(Clone, Debug)]
pub(crate) struct Fixed {
    /// Shared by the solutions of one assembly ([`Assembled::solve_pair`]).
    pub(crate) basis: Arc<Basis>,
    /// The coefficients of the basis columns.
    pub(crate) coef: Vec<f64>,
    /// The border constant of (E2) (zero at the exact c).
    pub(crate) sigma: f64,
    /// The largest residual of (E1) and (E2) at the collocation points, relative to the
    /// smallest term of the equation there (R1); infinite for the coarser solution of a
    /// pair ([`Assembled::solve_pair`]), whose residual no test reads.
    pub(crate) residual: f64,
}

/// The weighted collocation rows of the fixed-c system with their column scales, and the
/// three constraints in the scaled columns.
pub(crate) struct Assembled {
    basis: Arc<Basis>,
    /// `basis.len() + 1` columns (the last one sigma's), scaled.
    a: ColMajor,
    rows: usize,
    scale: Vec<f64>,
    cons: Vec<(Vec<f64>, f64)>,
    /// Each point's p columns and row weight, and whether it is a stick point (two rows).
    p_rows: Vec<f64>,
    weights: Vec<f64>,
    on_stick: Vec<bool>,
}

impl Assembled {
    /// The fixed-c system at `sizes` (module documentation), assembled, to be solved once as
    /// it stands ([`Assembled::solve`]) and, for the rounding check, again with its rows in
    /// another order ([`Assembled::solve_rows`]).
    pub(crate) fn new(k: Constants, c: f64, w: f64, sizes: Sizes) -> Self {
        let basis = Basis::new(k, c, w, sizes);
        let n = basis.len();
        let cols = n + 1;
        let points = if k.g < DENSE_BELOW_G {
            1.0
        } else {
            sizes.points
        };
        let (stick, mut slip) = collocation(
            c,
            w,
            (points * STICK_POINTS * cols as f64).ceil() as usize,
            (points * SLIP_POINTS * cols as f64).ceil() as usize,
        );
        if c < SMALL_STICK_BELOW {
            slip.extend(small_stick_slip_points(
                c,
                w,
                slip_columns_per_decade(c, w, sizes),
            ));
        }
        let rows = 2 * stick.len() + slip.len();
        let mut a = ColMajor::zeros(rows, cols);
        let (mut pv, mut qv, mut hp, mut hq) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut scratch = vec![0.0; basis.scratch_len()];
        let mut r = 0;
        let points = stick.len() + slip.len();
        let mut p_rows = Vec::with_capacity(points * n);
        let mut weights = Vec::with_capacity(points);
        let mut on_stick = Vec::with_capacity(points);
        let mut row = vec![0.0; cols];
        let mut scale = vec![0.0; cols];
        let all: Vec<Pt> = stick.iter().chain(&slip).copied().collect();
        let family_rows = FamilyRows::new(&basis, &all);
        for (i, (pt, stick_point)) in stick
            .iter()
            .map(|p| (p, true))
            .chain(slip.iter().map(|p| (p, false)))
            .enumerate()
        {
            basis.tractions_row_with(pt, &family_rows.factors[i], &mut pv, &mut qv, &mut scratch);
            basis.hilbert_row_from(pt, &family_rows.at(i), &mut hp, &mut hq, &mut scratch);
            p_rows.extend_from_slice(&pv);
            let weight = pt.omx.powf(k.g);
            weights.push(weight);
            on_stick.push(stick_point);
            // each row with its squares summed into the column scales, row by row
            for j in 0..n {
                row[j] = weight * (hp[j] - k.b * qv[j]);
                scale[j] += row[j] * row[j];
            }
            for (j, &v) in row[..n].iter().enumerate() {
                *a.at_mut(r, j) = v;
            }
            r += 1;
            if stick_point {
                for j in 0..n {
                    row[j] = weight * (hq[j] + k.b * pv[j]);
                    scale[j] += row[j] * row[j];
                }
                row[n] = -weight;
                scale[n] += row[n] * row[n];
                for (j, &v) in row.iter().enumerate() {
                    *a.at_mut(r, j) = v;
                }
                r += 1;
            }
        }
        // column scales
        for (j, s) in scale.iter_mut().enumerate() {
            *s = if *s > 0.0 { 1.0 / s.sqrt() } else { 1.0 };
            a.col_mut(j).iter_mut().for_each(|v| *v *= *s);
        }
        // the constraints, in the scaled columns: int p = 1 (S3), and p and q continuous at
        // x = c (C2)
        let (mut ps, mut qs, mut pc, mut qc) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let at_c = |xmc| Pt { x: c, omx: w, xmc };
        basis.tractions_row(&at_c(-0.0), &mut ps, &mut qs, &mut scratch);
        basis.tractions_row(&at_c(0.0), &mut pc, &mut qc, &mut scratch);
        let integral = basis.integrals();
        let cons: Vec<(Vec<f64>, f64)> = [
            (integral, 1.0),
            ((0..n).map(|j| ps[j] - pc[j]).collect(), 0.0),
            ((0..n).map(|j| qs[j] - qc[j]).collect(), 0.0),
        ]
        .into_iter()
        .map(|(row, d)| {
            let mut row: Vec<f64> = row.iter().zip(&scale).map(|(v, s)| v * s).collect();
            row.push(0.0);
            (row, d)
        })
        .collect();
        Assembled {
            basis: Arc::new(basis),
            a,
            rows,
            scale,
            cons,
            p_rows,
            weights,
            on_stick,
        }
    }

    /// The least-squares solution on all columns. The frame is ill-conditioned (near-dependent
    /// columns by design: cond 1e15 and more); Householder QR without pivoting spreads their
    /// rounding over every coefficient (the mid-range scenes of the tests lost c at 1e-8 that
    /// way), so the pivoted QR at once, here and in [`Assembled::solve_pair`].
    pub(crate) fn solve(&self) -> Result<Fixed> {
        self.solve_matrix(&self.a)
    }

    /// The least squares of `a` (this system's rows, in any order) under its constraints.
    fn solve_matrix(&self, a: &ColMajor) -> Result<Fixed> {
        let cols = self.basis.len() + 1;
        let x = constrained_sized(a, &vec![0.0; self.rows], self.cons.clone(), cols - 1)
            .map_err(|e| self.failure(e))?;
        Ok(self.fixed(x, true))
    }

    /// Number of collocation rows.
    pub(crate) fn rows(&self) -> usize {
        self.rows
    }

    /// [`Assembled::solve`] with the rows taken in the order `order` (a permutation of
    /// 0..[`Assembled::rows`]): the same least-squares problem in exact arithmetic, in
    /// another rounding of the QR (docs/theory_spectral.md section 5, (S10)). The residual
    /// (R1) is taken on the rows as assembled.
    pub(crate) fn solve_rows(&self, order: &[usize]) -> Result<Fixed> {
        self.solve_matrix(&self.a.rows_permuted(order))
    }

    /// The solutions on the coarser columns ([`Basis::coarse_columns`]) and on all, from the
    /// same rows and one factorisation (coarser, finer): the finer one with the distance
    /// that estimates its error.
    pub(crate) fn solve_pair(&self) -> Result<(Fixed, Fixed)> {
        let n = self.basis.len();
        let cols = n + 1;
        let keep = self.basis.coarse_columns();
        // the coarser columns first (sigma among them), then the rest
        let order: Vec<usize> = (0..n)
            .filter(|&j| keep[j])
            .chain([n])
            .chain((0..n).filter(|&j| !keep[j]))
            .collect();
        let inner = keep.iter().filter(|&&k| k).count() + 1;
        let cons = self
            .cons
            .iter()
            .map(|(row, d)| (order.iter().map(|&j| row[j]).collect(), *d))
            .collect();
        // the constraints' pivots among the coarser coefficients
        let zeros = vec![0.0; self.rows];
        let (xi, xf) = constrained_nested(&self.a, &order, &zeros, cons, inner - 1, inner)
            .map_err(|e| self.failure(e))?;
        let back = |x: Vec<f64>| {
            let mut out = vec![0.0; cols];
            for (&j, v) in order.iter().zip(x) {
                out[j] = v;
            }
            out
        };
        Ok((self.fixed(back(xi), false), self.fixed(back(xf), true)))
    }

    fn failure(&self, e: ConstrainedFailure) -> Error {
        let c = self.basis.c;
        Error::NoConvergence(match e {
            ConstrainedFailure::DependentConstraints => {
                format!("spectral: dependent constraints at c = {c}")
            }
            ConstrainedFailure::NotFinite => {
                format!("spectral: least-squares solution not finite at c = {c}")
            }
        })
    }

    /// The solution from the scaled coefficients `full` (sigma last), with its residual (R1)
    /// where `residual` (else infinite).
    fn fixed(&self, full: Vec<f64>, with_residual: bool) -> Fixed {
        let n = self.basis.len();
        let coef: Vec<f64> = (0..n).map(|j| full[j] * self.scale[j]).collect();
        let sigma = full[n] * self.scale[n];
        let residual = if with_residual {
            self.residual(&full, &coef)
        } else {
            f64::INFINITY
        };
        Fixed {
            basis: Arc::clone(&self.basis),
            coef,
            sigma,
            residual,
        }
    }

    /// (R1) of the solution with scaled coefficients `full` (sigma last) and coefficients
    /// `coef`: each row's residual relative to the smallest term of its equation, b mu p in
    /// (E1) (|q| <= mu p) and b p in (E2), in the rows' weights; the largest. A row whose
    /// computed residual lies within the rounding of its own sum, gamma_n (|A| |x|) for the
    /// row ([`ColMajor::abs_times`]), counts as 0: the coefficients solve it exactly
    /// with its entries perturbed by gamma_n relative (a componentwise backward error at the
    /// rounding), and the rounding of the tractions themselves is in the estimate ((R2)).
    /// Where b mu is small the smallest term is tiny against the columns' own sizes: at
    /// b* = 3.8e-4, mu~ = 1.7e-4 (b mu = 6.5e-8, c = 0.13) the rows' rounding alone gave
    /// (R1) = 1.3e-8 .. 2.7e-8 at every half level from 1.5 to 5.5 while the tractions'
    /// distance to the coarser columns was below 1e-15, and no level answered at tractions to
    /// 1e-8. On the 9 x 10 grid of b* = 1e-4 .. 0.0199 (log-spaced) by zeta = 0.1 .. 4.5
    /// below the stick-edge table (c to 1e-10, one run; before: the same session's code
    /// without this rule), the spectral solver answered 90 of 90 points at tractions to 1e-8
    /// (before 60, the panels the rest in 7-650 ms), median 0.41 ms (0.82 ms), and 89 at
    /// 1e-10 (before 26), median 0.70 ms (17 ms); every answer within the sum of both
    /// estimates of the panels' root search at the same traction tolerance (largest ratios
    /// 0.79 and 0.34 in the tractions, 0.25 in c). The 48 answers of the speed scenes are
    /// bit-identical.
    fn residual(&self, full: &[f64], coef: &[f64]) -> f64 {
        let rows = self.a.times(full);
        let largest = self.largest_ratio(&rows, coef, None);
        // the rows' rounding scales only where the largest exceeds the smallest tolerance
        // the library works to (below it the check passes at every tolerance, and the
        // scales cost another product with A)
        if largest <= TOLERANCE_FLOOR {
            return largest;
        }
        let nf = full.len() as f64;
        let gamma = nf * f64::EPSILON / (1.0 - nf * f64::EPSILON);
        let scales: Vec<f64> = self.a.abs_times(full).iter().map(|s| gamma * s).collect();
        self.largest_ratio(&rows, coef, Some(&scales))
    }

    /// The largest of the rows' residuals `rows` relative to their equations' smallest terms
    /// ([`Assembled::residual`]), leaving out the rows within `rounding` where given (a NaN
    /// ratio, from a vanishing term, is not counted).
    fn largest_ratio(&self, rows: &[f64], coef: &[f64], rounding: Option<&[f64]>) -> f64 {
        let k = self.basis.k;
        let n = self.basis.len();
        let mut residual: f64 = 0.0;
        let mut r = 0;
        for (i, &stick_point) in self.on_stick.iter().enumerate() {
            let p: f64 = self.p_rows[i * n..(i + 1) * n]
                .iter()
                .zip(coef)
                .map(|(a, b)| a * b)
                .sum();
            let size = k.b * p * self.weights[i];
            for (eq, scale) in [(true, k.mu), (stick_point, 1.0)] {
                if eq {
                    if rounding.is_none_or(|s| rows[r].abs() > s[r]) {
                        residual = residual.max(rows[r].abs() / (scale * size));
                    }
                    r += 1;
                }
            }
        }
        residual
    }
}

/// The rounding noise of (p, q) at a point, absolute ([`Fixed::combine`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Noise {
    pub(crate) p: f64,
    pub(crate) q: f64,
}

impl Fixed {
    /// (p, q) of the reduced problem at a point.
    pub(crate) fn eval(&self, p: &Pt) -> (f64, f64) {
        let (p, q, _) = self.eval_with_noise(p);
        (p, q)
    }

    /// (p, q) at a point, and their rounding noise ([`Fixed::combine`]).
    pub(crate) fn eval_with_noise(&self, p: &Pt) -> (f64, f64, Noise) {
        let mut work = Vec::new();
        self.columns_into(p, &mut work);
        self.combine(p, &work)
    }

    /// This solution's (p, q) with their noise, and `other`'s (p, q), each at its own point
    /// `at(solution)`, the columns' values in the reusable buffer `work`: evaluated once
    /// where both come from one assembly ([`Assembled::solve_pair`]), whose point is this one's.
    pub(crate) fn probe_both(
        &self,
        other: &Fixed,
        at: impl Fn(&Fixed) -> Pt,
        work: &mut Vec<f64>,
    ) -> ((f64, f64, Noise), (f64, f64)) {
        let p = at(self);
        self.columns_into(&p, work);
        let mine = self.combine(&p, work);
        let (p_other, q_other, _) = if Arc::ptr_eq(&self.basis, &other.basis) {
            other.combine(&p, work)
        } else {
            let p = at(other);
            other.columns_into(&p, work);
            other.combine(&p, work)
        };
        (mine, (p_other, q_other))
    }

    /// The columns' values at a point into `work`: their p parts, then their q parts (and the
    /// transforms' scratch after them).
    fn columns_into(&self, p: &Pt, work: &mut Vec<f64>) {
        let n = self.coef.len();
        // (tractions_row sets every value it is read for: no zeroing between points)
        let len = 2 * n + self.basis.scratch_len();
        if work.len() < len {
            work.resize(len, 0.0);
        }
        let (pv, rest) = work.split_at_mut(n);
        let (qv, buf) = rest.split_at_mut(n);
        self.basis.tractions_row(p, pv, qv, buf);
    }

    /// (p, q) at the point `p` from the columns' values in `work` ([`Fixed::columns_into`]),
    /// and their rounding noise: the machine epsilon times sum |a_j phi_j(x)| over p's columns
    /// and over q's on the stick zone, mu times p's on the slip zone (q = mu p is exact
    /// there). The frame's columns are near-dependent, so its coefficients can be large and
    /// cancel (docs/theory_spectral.md (R2)).
    fn combine(&self, p: &Pt, work: &[f64]) -> (f64, f64, Noise) {
        let n = self.coef.len();
        let (pv, qv) = (&work[..n], &work[n..2 * n]);
        // the sums over the columns that can be nonzero in the point's zone, in the columns'
        // order (the others' exact zeros leave the sums as they are)
        let sum = |v: &[f64], ranges: &[(usize, usize)]| {
            let (mut value, mut size) = (0.0, 0.0);
            for &(from, to) in ranges {
                for (v, a) in v[from..to].iter().zip(&self.coef[from..to]) {
                    value += v * a;
                    size += (v * a).abs();
                }
            }
            (value, size)
        };
        let (q0, s0) = self.basis.starts();
        let bonded = (self.basis.bonded_start(), n);
        let on_stick = p.on_stick();
        let (value, size) = if on_stick {
            sum(pv, &[(0, q0), bonded])
        } else {
            sum(pv, &[(s0, bonded.0)])
        };
        let mu = self.basis.k.mu;
        // q = mu p on the slip zone exactly, not to the rounding of a second sum
        let (q, q_size) = if on_stick {
            sum(qv, &[(q0, s0), bonded])
        } else {
            (mu * value, mu * size)
        };
        let noise = Noise {
            p: f64::EPSILON * size,
            q: f64::EPSILON * q_size,
        };
        (value, q, noise)
    }

    /// (p, q) at 0 <= x < 1 (the stick side at x = c).
    pub(crate) fn at(&self, x: f64) -> (f64, f64) {
        self.eval(&Pt::at(x, self.basis.c))
    }

    /// The residuals of (E1) and (E2) (0 on the slip zone) at 0 <= x < 1, x != c, with
    /// sigma = 0.
    #[cfg(test)]
    pub(crate) fn residuals(&self, x: f64) -> (f64, f64) {
        let n = self.coef.len();
        let pt = Pt {
            x,
            omx: 1.0 - x,
            xmc: x - self.basis.c,
        };
        let (mut hp, mut hq) = (vec![0.0; n], vec![0.0; n]);
        let mut scratch = vec![0.0; self.basis.scratch_len()];
        self.basis.hilbert_row(&pt, &mut hp, &mut hq, &mut scratch);
        let dot = |v: &[f64]| v.iter().zip(&self.coef).map(|(a, b)| a * b).sum::<f64>();
        let (p, q) = self.eval(&pt);
        let b = self.basis.k.b;
        let e2 = if pt.xmc < 0.0 { dot(&hq) + b * p } else { 0.0 };
        (dot(&hp) - b * q, e2)
    }

    /// int_{-1}^{1} p.
    #[cfg(test)]
    pub(crate) fn integral_of_p(&self) -> f64 {
        let i = self.basis.integrals();
        i.iter().zip(&self.coef).map(|(a, b)| a * b).sum()
    }

    /// At a stick point 0 <= x < c: (p, q_plain, q_edge) with q = q_plain + (c - x)^g q_edge,
    /// the three smooth up to x = c ((E1)'s local exponents at c on the stick side).
    pub(crate) fn stick_split(&self, x: f64) -> (f64, f64, f64) {
        let b = &self.basis;
        let (c, g) = (b.c, b.k.g);
        let t = Point::offsets((c - x) / c, (c + x) / c);
        let mut buf = vec![0.0; b.scratch];
        let mut dot = |block: &Block, w: Option<f64>, at: usize| {
            let n = block.len();
            let mut v = vec![0.0; n];
            match w {
                Some(w) => block.values_weighted(t, w, &mut buf, &mut v),
                None => block.values(t, &mut buf, &mut v),
            }
            v.iter()
                .zip(&self.coef[at..at + n])
                .map(|(a, b)| a * b)
                .sum::<f64>()
        };
        let (q0, _) = b.starts();
        let n1 = b.stick[1].len();
        let mut p = dot(&b.stick[0], None, 0);
        let mut q_plain = dot(&b.stick[1], None, q0);
        // (1 - tau^2)^g = (c - x)^g (1 + tau)^g / c^g; the quotient family's
        // ((1 - tau^2)^g - 1) / g adds -1 / g times its polynomials to the plain part
        let edge = t.opy.powf(g) / c.powf(g);
        let q_edge = if b.stick[2].is_quotient() {
            let s = dot(&b.stick[2], Some(1.0 / g), q0 + n1);
            q_plain -= s;
            s * edge
        } else {
            dot(&b.stick[2], Some(edge), q0 + n1)
        };
        if let Some(bx) = &b.bonded {
            // the bonded columns are smooth at x = c from the stick side
            let n = bx.degree();
            let (mut f, mut pv, mut qv) = (
                [C64::new(0.0, 0.0); MAX_DEGREE],
                [0.0; MAX_DEGREE],
                [0.0; MAX_DEGREE],
            );
            bx.values(x, 1.0 - x, &mut f[..n]);
            Basis::bonded_split(&f[..n], &mut pv[..n], &mut qv[..n]);
            let coef = &self.coef[b.bonded_start()..];
            p += pv[..n].iter().zip(coef).map(|(a, c)| a * c).sum::<f64>();
            q_plain += qv[..n].iter().zip(coef).map(|(a, c)| a * c).sum::<f64>();
        }
        (p, q_plain, q_edge)
    }

    /// At a slip point c < x < 1: (p_plain, p_edge) with p = p_plain + (x - c)^g p_edge
    /// (q = mu p there), both smooth down to x = c.
    pub(crate) fn slip_split(&self, x: f64) -> (f64, f64) {
        let b = &self.basis;
        let (c, w, g) = (b.c, b.w, b.k.g);
        let s = Point::offsets(2.0 * (1.0 - x) / w, 2.0 * (x - c) / w);
        let mut buf = vec![0.0; b.scratch];
        let (_, s0) = b.starts();
        let n0 = b.slip[0].len();
        let mut v = vec![0.0; n0.max(b.slip[1].len())];
        b.slip[0].values(s, &mut buf, &mut v[..n0]);
        let plain: f64 = v[..n0]
            .iter()
            .zip(&self.coef[s0..])
            .map(|(a, b)| a * b)
            .sum();
        // (1 - s)^-g (1 + s)^g = (1 - s)^-g (2 (x - c) / w)^g; the quotient family's
        // (1 - s)^-g ((1 + s)^g - 1) / g adds -(1 - s)^-g / g to the plain part
        let (oms, _) = b.slip[1].weight_factors(s);
        let n1 = b.slip[1].len();
        let quotient = b.slip[1].is_quotient();
        let factor = if quotient { 1.0 / g } else { 1.0 };
        b.slip[1].values_weighted(s, oms * factor, &mut buf, &mut v[..n1]);
        let second: f64 = v[..n1]
            .iter()
            .zip(&self.coef[s0 + n0..])
            .map(|(a, b)| a * b)
            .sum();
        let plain = if quotient { plain - second } else { plain };
        (plain, second * (2.0 / w).powf(g))
    }

    /// Number of unknowns (coefficients and sigma).
    pub(crate) fn unknowns(&self) -> usize {
        self.coef.len() + 1
    }
}
