//! The Cauchy transforms of a whole traction expansion at a complex point:
//! G_p(z) = (1/pi) int_{-1}^{1} p(t) / (z - t) dt and G_q(z) the same for q (and their
//! derivatives), p even and q odd, so that each panel [a, b] of [0, 1] also stands for its
//! mirror [-b, -a]: G_p(z) = sum g_p(z) - g_p(-z), G_q(z) = sum g_q(z) + g_q(-z) over the
//! panels' own transforms g.
//!
//! A whole-line expansion ([`Expansion::whole_line`]: panels tiling [-1, 1], no symmetry,
//! the state of a load path) is summed as it is: each panel's own transform, near or far as
//! below, and for |z| >= [`FAR_RADIUS`] the moment series with every moment M_k of p and q.
//! Its slip quantities (`p_from`, `log_potential_q`) assume the mirror and are not used.
//!
//! Each panel's transform is taken, by the Bernstein parameter rho of z with respect to the
//! panel (rho + 1/rho = (|z - a| + |z - b|) / h):
//! - near (rho < [`NEAR_RHO`]): closed form and recurrence ([`near_transforms`]);
//! - far: the Gauss-Jacobi rule of each family for the band of rho it lies in, sized from the
//!   family's own coefficients so that its error (~|c_k| rho^(k - 2m) for degree k and m
//!   nodes) stays below [`FAR_TOL`] of p(0) ([`band_nodes`]). With
//!   Re z >= 0 the mirror panel is farther than the panel itself, so one rule serves both:
//!   1/(z - x) + 1/(z + x) = 2z / ((z - x)(z + x)) for p, 1/(z - x) - 1/(z + x) =
//!   2x / ((z - x)(z + x)) for q (Re z < 0 follows from G_p odd, G_q even). Several points
//!   (the two characteristic roots' x + i beta_k y) share one pass over the rule of the
//!   nearest one's band, so that their transforms also share its (smooth) error.
//!
//! The families' series are taken without the tail that adds up to less than [`TAIL_TOL`] of
//! p(0) (the rounding noise of sampled series): [`NearFamily::new`].
//!
//! Points far from the whole contact (|z| >= [`FAR_RADIUS`]) skip the panels: there
//! G_p(z) = (1/pi) sum_j M_2j / z^(2j+1) and G_q(z) = (1/pi) sum_j M_(2j+1) / z^(2j+2) with the
//! moments M_k = int_{-1}^{1} f t^k dt (p even, q odd), exact from each family's Gauss rule;
//! the series converges like |z|^(-k) whatever the tractions' singularities.
//!
//! For the slip, the same panels give int_x^1 p and the log potential
//! L_q(x) = int_{-1}^{1} q(s) ln|x - s| ds on the axis exactly, from each family's
//! antiderivative anchored at its weighted end ([`Antiderivative`]).

use std::collections::HashMap;
use std::f64::consts::PI;

use super::expansion::{Expansion, Family};
use crate::numerics::cauchy::{C64, Local, NEAR_RHO, Weight, near_transforms};
use crate::numerics::orthopoly::{legendre, legendre_sum};
use crate::numerics::quadrature::{gauss_jacobi, gauss_legendre};

/// Lower ends of the far bands in rho (the last band reaches to infinity).
const BANDS: [f64; 13] = [
    NEAR_RHO, 1.75, 2.0, 2.5, 3.0, 4.0, 5.0, 7.0, 10.0, 20.0, 50.0, 200.0, 1000.0,
];

/// The bands' lower ends as the semi-major axis s = (rho + 1/rho) / 2 of their ellipse, to
/// which a point's distances to the panel ends give it directly ([`KernelPanel::band`]).
const BAND_AXES: [f64; BANDS.len()] = {
    let mut s = [0.0; BANDS.len()];
    let mut i = 0;
    while i < s.len() {
        s[i] = 0.5 * (BANDS[i] + 1.0 / BANDS[i]);
        i += 1;
    }
    s
};

/// |z| from which the moment series is used, and its length: FAR_RADIUS^(-MOMENTS) ~ 2e-18.
const FAR_RADIUS: f64 = 1.5;
const MOMENTS: usize = 100;

/// Largest degree of a family the kernel takes (scratch on the stack).
pub(crate) const MAX_DEGREE: usize = 72;

/// Error allowed to each family's far rule, relative to p(0): far below the field's 1e-8
/// target and the near field's own recurrence error (~4e-12 of the transforms, [`NEAR_RHO`]).
const FAR_TOL: f64 = 1e-13;

/// The part of each family's series left out, relative to p(0) ([`NearFamily::new`]): the
/// rounding noise that sampled series carry in their tails, and no more (the stresses next
/// to a punch edge, ~p(0) / sqrt(depth), keep their relative accuracy).
const TAIL_TOL: f64 = 1e-14;

/// Nodes of a Gauss rule for a family whose p and q series have coefficients of size at most
/// `size[k]` (the rule serves both), at rho >= rho_min: the fewest m with
/// sum_k size[k] min(1, rho^(k - 2m)) <= tol (an m-node rule integrates P_k / (z - t) with
/// error ~rho^(k - 2m) while k < 2m, and O(1) beyond), so that a decaying series needs fewer
/// nodes than its length; at most the m with rho^(n - 2m) <= 1e-16 for the whole series.
fn band_nodes(rho_min: f64, size: &[f64], tol: f64) -> usize {
    let error = |m: usize| -> f64 {
        size.iter()
            .enumerate()
            .map(|(k, s)| s * rho_min.powf((k as f64 - 2.0 * m as f64).min(0.0)))
            .sum()
    };
    let exact = ((size.len() as f64 + 16.0 / rho_min.log10()) / 2.0).ceil() as usize;
    (1..exact).find(|&m| error(m) <= tol).unwrap_or(exact)
}

/// Depth standing in for a point exactly at a panel end on the axis: the point is taken this
/// far below the end (so each of the two panels meeting there sees half of the jump of its
/// density, as the limit at an end has it; their logarithms, ln(1e-300) ~ -690, still cancel
/// to ~1e-13).
const AT_END: f64 = 1e-300;

/// One family prepared for its near-field transforms.
#[derive(Clone, Debug)]
struct NearFamily {
    weight: Weight,
    p: Vec<f64>,
    q: Vec<f64>,
    /// M_k = int w P_k, for max(p.len(), q.len()) degrees.
    moments: Vec<f64>,
}

impl NearFamily {
    /// The family `f` without the tail of its series whose sizes ([`size`]) add up
    /// to at most `tol`: as |P_k| <= 1, that moves p and q by at most `tol` times the weight
    /// (the rounding noise of sampled series, whose tails need not decay below it).
    fn new(f: &Family, tol: f64) -> Self {
        let mut n = f.p.len().max(f.q.len()).max(1);
        let mut tail = 0.0;
        while n > 1 && tail + size(&f.p, &f.q, n - 1) <= tol {
            tail += size(&f.p, &f.q, n - 1);
            n -= 1;
        }
        let cut = |v: &[f64]| v[..v.len().min(n)].to_vec();
        NearFamily {
            weight: f.weight,
            p: cut(&f.p),
            q: cut(&f.q),
            moments: f.weight.moments(n),
        }
    }

    /// The sizes of its coefficients ([`size`]).
    fn sizes(&self) -> Vec<f64> {
        (0..self.moments.len())
            .map(|k| size(&self.p, &self.q, k))
            .collect()
    }
}

/// max(|p_k|, |q_k|) (0 beyond a series' end): the size of a family's degree-k terms.
fn size(p: &[f64], q: &[f64], k: usize) -> f64 {
    let c = |v: &[f64]| v.get(k).map_or(0.0, |c: &f64| c.abs());
    c(p).max(c(q))
}

/// A far-field rule of one panel: physical nodes x_j and the weights h W_j p(t_j) / w(t_j)
/// and h W_j q(t_j) x_j / w(t_j) of all its families together.
#[derive(Clone, Debug, Default)]
struct FarRule {
    x: Vec<f64>,
    wp: Vec<f64>,
    wqx: Vec<f64>,
    wq: Vec<f64>,
}

/// A family's antiderivative anchored at its weighted end: for 1 and (1 - t)^e,
/// V(t) = int_t^1 w f = w(t) sum_k r_k P_k(t), and the log potential
/// Lambda(zeta) = int w f log(zeta - t) dt = M log(zeta + 1) - C[V](zeta) (by parts); for
/// (1 + t)^e, U(t) = int_{-1}^t w f = w(t) sum_k r_k P_k(t) and
/// Lambda = M log(zeta - 1) + C[U](zeta). (V / w is (1 - t) times a polynomial, U / w is
/// (1 + t) times one.) At the anchor itself Re Lambda = M ln 2 - int w R with R = V / w(1 - t)
/// (resp. U / w(1 + t)): finite where C[V] alone is not.
#[derive(Clone, Debug)]
struct Antiderivative {
    weight: Weight,
    /// Anchored at t = -1.
    left: bool,
    /// Coefficients r of V / w (or U / w) for p and for q, degree one above the family's.
    rp: Vec<f64>,
    rq: Vec<f64>,
    /// M = int w f for p and for q.
    mass: (f64, f64),
    /// int w R for p and for q.
    end: (f64, f64),
    /// int w P_k for the degrees of r.
    moments: Vec<f64>,
}

impl Antiderivative {
    /// The antiderivatives of the p and q series of `f` (degrees < n).
    fn new(f: &NearFamily, n: usize) -> Self {
        let left = matches!(f.weight, Weight::Left(_));
        // the field's families carry Jacobi weights only (coupled::expansion splits the
        // solver's log weights into their power part and 1)
        debug_assert!(!matches!(
            f.weight,
            Weight::RightLog(_) | Weight::LeftLog(_)
        ));
        let (alpha, beta) = f.weight.exponents();
        let e = alpha + beta;
        // int from the anchor to t of w f, in the anchor's own orientation (u = 1 - t or 1 + t):
        // ((u / 2)^(e + 1)) int_{-1}^{1} (1 - s)^e f(...) ds by Gauss-Jacobi, exact for degree < n
        let (sj, wj) = gauss_jacobi(n / 2 + 2, e, 0.0);
        let from_anchor = |coef: &[f64], t: f64| {
            let u = if left { 1.0 + t } else { 1.0 - t };
            let sum: f64 = sj
                .iter()
                .zip(&wj)
                .map(|(&s, &w)| {
                    let at = u * 0.5 * (1.0 - s);
                    let x = if left { -1.0 + at } else { 1.0 - at };
                    w * legendre_sum(coef, x)
                })
                .sum();
            (0.5 * u).powf(e + 1.0) * sum
        };
        // r: the polynomial antiderivative / w at n + 1 Gauss-Legendre nodes (exact: degree n)
        let (nodes, weights) = gauss_legendre(n + 1);
        let fit = |coef: &[f64]| {
            let mut r = vec![0.0; n + 1];
            let mut leg = vec![0.0; n + 1];
            for (&t, &w) in nodes.iter().zip(&weights) {
                let u = if left { 1.0 + t } else { 1.0 - t };
                let v = w * from_anchor(coef, t) / u.powf(e);
                legendre(t, &mut leg);
                r.iter_mut().zip(&leg).for_each(|(r, l)| *r += v * l);
            }
            r.iter_mut()
                .enumerate()
                .for_each(|(k, r)| *r *= k as f64 + 0.5);
            r
        };
        let (rp, rq) = (fit(&f.p), fit(&f.q));
        let moments = f.weight.moments(n + 1);
        let mass = |coef: &[f64]| coef.iter().zip(&moments).map(|(c, m)| c * m).sum::<f64>();
        // int w R: the rule for w applied to (r series) / u, exact for degree < n
        let end = |r: &[f64]| {
            let (tj, wj) = f.weight.rule(n / 2 + 2);
            tj.iter()
                .zip(&wj)
                .map(|(&t, &w)| {
                    let u = if left { 1.0 + t } else { 1.0 - t };
                    w * legendre_sum(r, t) / u
                })
                .sum::<f64>()
        };
        Antiderivative {
            weight: f.weight,
            left,
            mass: (mass(&f.p), mass(&f.q)),
            end: (end(&rp), end(&rq)),
            rp,
            rq,
            moments,
        }
    }

    /// int_t^1 of the p series times w (on the axis, -1 <= t <= 1).
    fn p_from(&self, t: f64, omt: f64, opt: f64) -> f64 {
        let v = self.weight.at(omt, opt) * legendre_sum(&self.rp, t);
        if self.left { self.mass.0 - v } else { v }
    }

    /// Re Lambda_q(zeta) on the axis (l from below), `c` scratch of the degree of r.
    fn log_q(&self, l: Local, c: &mut [C64]) -> f64 {
        let to_anchor = if self.left { l.opz } else { l.omz };
        if to_anchor.re == 0.0 && to_anchor.im.abs() == AT_END {
            return self.mass.1 * std::f64::consts::LN_2 - self.end.1;
        }
        let n = self.moments.len();
        near_transforms(self.weight, &self.moments, l, &mut c[..n], None);
        let transform: f64 = self.rq.iter().zip(c.iter()).map(|(r, c)| r * c.re).sum();
        if self.left {
            self.mass.1 * l.omz.norm().ln() + transform
        } else {
            self.mass.1 * l.opz.norm().ln() - transform
        }
    }
}

/// A panel ready for transforms.
#[derive(Clone, Debug)]
struct KernelPanel {
    a: f64,
    b: f64,
    m: f64,
    h: f64,
    near: Vec<NearFamily>,
    anti: Vec<Antiderivative>,
    far: Vec<FarRule>,
}

/// The sums G_p, G_q (and G_p', G_q' when asked for) at one point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Transforms {
    pub(crate) p: C64,
    pub(crate) q: C64,
    pub(crate) dp: C64,
    pub(crate) dq: C64,
}

impl Transforms {
    fn zero() -> Self {
        let z = C64::new(0.0, 0.0);
        Transforms {
            p: z,
            q: z,
            dp: z,
            dq: z,
        }
    }
}

/// A point z = x + w of the plane given as a point x of the axis and a small offset w, so
/// that its distance to a panel end keeps its relative accuracy: (b - x) - w, where x + w
/// rounded would lose it (kappa < 1 puts z at x -+ delta sqrt((1 - kappa) / 2) y, beside an
/// end when x is at it).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Point {
    pub(crate) x: f64,
    pub(crate) w: C64,
}

impl Point {
    /// x + w.
    fn z(self) -> C64 {
        self.w + self.x
    }

    /// -z.
    fn neg(self) -> Point {
        Point {
            x: -self.x,
            w: -self.w,
        }
    }
}

/// The expansion's panels prepared for transforms at any point.
#[derive(Clone, Debug)]
pub(crate) struct Kernel {
    panels: Vec<KernelPanel>,
    /// M_(2j) of p and M_(2j+1) of q, j < MOMENTS / 2 (mirrored expansions).
    even_p: Vec<f64>,
    odd_q: Vec<f64>,
    /// A whole-line expansion ([`Expansion::whole_line`]): every moment M_k of p and of q,
    /// k < MOMENTS; its panels are summed as they are, without mirrors.
    whole: Option<(Vec<f64>, Vec<f64>)>,
}

/// Gauss rules shared between the panels while building (keyed by weight and size).
type Rules = HashMap<(u64, u64, usize), (Vec<f64>, Vec<f64>)>;

fn rule(rules: &mut Rules, weight: Weight, m: usize) -> &(Vec<f64>, Vec<f64>) {
    let (a, b) = weight.exponents();
    rules
        .entry((a.to_bits(), b.to_bits(), m))
        .or_insert_with(|| weight.rule(m))
}

impl KernelPanel {
    /// The panel [a, b] with its families, for tractions of scale p0 = p(0): their series
    /// without a tail of TAIL_TOL p0, far rules to FAR_TOL p0 ([`band_nodes`]).
    fn new(a: f64, b: f64, families: &[Family], p0: f64, rules: &mut Rules) -> Self {
        let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
        let near: Vec<NearFamily> = families
            .iter()
            .map(|f| NearFamily::new(f, TAIL_TOL * p0))
            .collect();
        let tol = FAR_TOL * p0;
        let far = BANDS
            .iter()
            .map(|&rho| {
                let mut r = FarRule::default();
                for f in &near {
                    let n = f.moments.len();
                    let nodes = band_nodes(rho, &f.sizes(), tol);
                    let (nodes, weights) = rule(rules, f.weight, nodes);
                    let mut leg = vec![0.0; n];
                    for (&t, &w) in nodes.iter().zip(weights) {
                        legendre(t, &mut leg);
                        let sum = |c: &[f64]| c.iter().zip(&leg).map(|(c, l)| c * l).sum::<f64>();
                        let x = m + h * t;
                        let (wp, wq) = (h * w * sum(&f.p), h * w * sum(&f.q));
                        r.x.push(x);
                        r.wp.push(wp);
                        r.wq.push(wq);
                        r.wqx.push(wq * x);
                    }
                }
                r
            })
            .collect();
        let anti = near
            .iter()
            .map(|f| Antiderivative::new(f, f.moments.len()))
            .collect();
        KernelPanel {
            a,
            b,
            m,
            h,
            near,
            anti,
            far,
        }
    }

    /// int_x^b p over this panel for a <= x <= b.
    fn p_from(&self, x: f64) -> f64 {
        let (omt, opt) = ((self.b - x) / self.h, (x - self.a) / self.h);
        let t = ((x - self.m) / self.h).clamp(-1.0, 1.0);
        self.h * self.anti.iter().map(|f| f.p_from(t, omt, opt)).sum::<f64>()
    }

    /// int over this panel of q(s) ln|x - s| ds for real x, minus the same at -x when
    /// `mirror` (x >= 0: the mirror is then farther, and one far rule with one logarithm per
    /// node, ln|(x - s) / (x + s)|, serves both).
    fn log_q(&self, x: f64, mirror: bool, scratch: &mut [C64]) -> f64 {
        let z = Point {
            x,
            w: C64::new(0.0, -0.0),
        };
        match self.band(z.z()) {
            Some(b) => {
                let r = &self.far[b];
                let nodes = r.x.iter().zip(&r.wq);
                if mirror {
                    nodes
                        .map(|(&s, &w)| w * ((x - s) / (x + s)).abs().ln())
                        .sum()
                } else {
                    nodes.map(|(&s, &w)| w * (x - s).abs().ln()).sum()
                }
            }
            None => {
                let l = self.local(z);
                let (mass, own): (f64, f64) = self.anti.iter().fold((0.0, 0.0), |(m, v), f| {
                    (m + f.mass.1, v + f.log_q(l, scratch))
                });
                let other = if mirror {
                    self.log_q(-x, false, scratch)
                } else {
                    0.0
                };
                self.h * (mass * self.h.ln() + own) - other
            }
        }
    }

    /// The far band of z for this panel (None: near field), by the semi-major axis
    /// s = (|z - a| + |z - b|) / (2h) = (rho + 1/rho) / 2 of its Bernstein ellipse (distances by
    /// sqrt, not the slower hypot of `norm`: z is never near overflow here).
    fn band(&self, z: C64) -> Option<usize> {
        let dist = |e: f64| ((z.re - e) * (z.re - e) + z.im * z.im).sqrt();
        let s = (dist(self.a) + dist(self.b)) / (2.0 * self.h);
        BAND_AXES.iter().rposition(|&lo| s >= lo)
    }

    /// The local point of z, the distances to the ends from the physical ones, (b - x) - w
    /// and (x - a) + w, formed part by part so that they keep their accuracy next to an end
    /// and the sign of a zero imaginary part (a point of the axis exactly at an end is moved
    /// [`AT_END`] off it, to that side).
    fn local(&self, z: Point) -> Local {
        let Point { x, w } = z;
        let mut omz = C64::new((self.b - x) - w.re, -w.im) / self.h;
        let mut opz = C64::new((x - self.a) + w.re, w.im) / self.h;
        let off = AT_END.copysign(w.im);
        if omz.re == 0.0 && omz.im == 0.0 {
            omz.im = -off;
        }
        if opz.re == 0.0 && opz.im == 0.0 {
            opz.im = off;
        }
        Local {
            zeta: C64::new((x - self.m) + w.re, w.im) / self.h,
            omz,
            opz,
        }
    }

    /// This panel's own g_p(z), g_q(z) (times pi) and their z-derivatives when `deriv`, in
    /// closed form; `scratch` holds two vectors of the largest degree.
    fn near_sums(
        &self,
        z: Point,
        deriv: bool,
        scratch: &mut [[C64; MAX_DEGREE + 1]; 2],
    ) -> Transforms {
        let l = self.local(z);
        let mut t = Transforms::zero();
        let [c, d] = scratch;
        for f in &self.near {
            let n = f.moments.len();
            near_transforms(
                f.weight,
                &f.moments,
                l,
                &mut c[..n],
                deriv.then_some(&mut d[..n]),
            );
            let dot = |coef: &[f64], v: &[C64]| {
                coef.iter()
                    .zip(v)
                    .fold(C64::new(0.0, 0.0), |s, (a, b)| s + b * a)
            };
            t.p += dot(&f.p, c);
            t.q += dot(&f.q, c);
            if deriv {
                t.dp += dot(&f.p, d) / self.h;
                t.dq += dot(&f.q, d) / self.h;
            }
        }
        t
    }

    /// g_p(z), g_q(z) (times pi) of this panel alone by its far rule of band `band`.
    fn far_sums(&self, z: C64, band: usize, deriv: bool) -> Transforms {
        let r = &self.far[band];
        let mut t = Transforms::zero();
        for ((&x, &wp), &wq) in r.x.iter().zip(&r.wp).zip(&r.wq) {
            let inv = (z - x).inv();
            t.p += inv * wp;
            t.q += inv * wq;
            if deriv {
                let inv2 = inv * inv;
                t.dp -= inv2 * wp;
                t.dq -= inv2 * wq;
            }
        }
        t
    }

    /// This panel and its mirror by one far rule at each of the points z (Re z >= 0, the
    /// mirror farther; `band` suits them all), in one pass over the rule's nodes:
    /// pi (g_p(z) - g_p(-z)) = 2z sum wp / ((z - x)(z + x)),
    /// pi (g_q(z) + g_q(-z)) = 2 sum wq x / ((z - x)(z + x)).
    /// With (z - x)(z + x) = u - i v, u = (Re z - x)(Re z + x) - (Im z)^2 and v = -2 Re z Im z
    /// the same for every node, 1 / ((z - x)(z + x)) = (u + i v) r with r = 1 / (u^2 + v^2),
    /// so the sums are real ones ([`FarSums`]), taken in lanes the compiler vectorises.
    fn far_pair<const N: usize>(
        &self,
        z: [C64; N],
        band: usize,
        deriv: bool,
        t: &mut [Transforms; N],
    ) {
        let r = &self.far[band];
        let sums = if deriv {
            FarSums::new::<true>(&r.x, &r.wp, &r.wqx, z)
        } else {
            FarSums::new::<false>(&r.x, &r.wp, &r.wqx, z)
        };
        for ((t, s), z) in t.iter_mut().zip(&sums.0).zip(z) {
            let v = -2.0 * z.re * z.im;
            let sp = C64::new(s.p[0], v * s.p[1]);
            let sq = C64::new(s.q[0], v * s.q[1]);
            t.p += z * sp * 2.0;
            t.q += sq * 2.0;
            if deriv {
                // 1 / ((z - x)(z + x))^2 = (u^2 - v^2 + 2 i u v) r^2
                let sp2 = C64::new(s.p[2] - v * v * s.p[3], 2.0 * v * s.p[4]);
                let sq2 = C64::new(s.q[2] - v * v * s.q[3], 2.0 * v * s.q[4]);
                // d/dz 2z/(z^2 - x^2) = 2/(z^2 - x^2) - 4 z^2/(z^2 - x^2)^2; 2x/(...) gives
                // -4xz/(...)^2
                t.dp += sp * 2.0 - z * z * sp2 * 4.0;
                t.dq -= z * sq2 * 4.0;
            }
        }
    }
}

/// Lanes of the far-rule dot products ([`dot`]).
const LANES: usize = 4;

/// The real sums of [`KernelPanel::far_pair`] over the nodes for one point, for the weights
/// wp and wq x: sum w u r, sum w r and, for the derivatives, sum w u^2 r^2, sum w r^2,
/// sum w u r^2.
#[derive(Clone, Copy, Default)]
struct PointSums {
    p: [f64; 5],
    q: [f64; 5],
}

/// [`PointSums`] of N points, from one pass over the nodes.
struct FarSums<const N: usize>([PointSums; N]);

impl<const N: usize> FarSums<N> {
    /// The sums over nodes x with weights wp, wq, block by block: first the per-node factors
    /// r and u r of each point (elementwise, so vectorised), then their dot products with the
    /// weights ([`dot`]).
    fn new<const DERIV: bool>(x: &[f64], wp: &[f64], wq: &[f64], z: [C64; N]) -> Self {
        let mut sums = [PointSums::default(); N];
        for ((x, wp), wq) in x.chunks(BLOCK).zip(wp.chunks(BLOCK)).zip(wq.chunks(BLOCK)) {
            for (s, z) in sums.iter_mut().zip(&z) {
                // (z - x)(z + x) = u - i v, v = -2 Re z Im z
                let v = -2.0 * z.re * z.im;
                let (v2, vv) = (z.im * z.im, v * v);
                let (mut r, mut ur) = ([0.0; BLOCK], [0.0; BLOCK]);
                for ((r, ur), &x) in r.iter_mut().zip(&mut ur).zip(x) {
                    let u = (z.re - x) * (z.re + x) - v2;
                    *r = 1.0 / (u * u + vv);
                    *ur = u * *r;
                }
                let (r, ur) = (&r[..x.len()], &ur[..x.len()]);
                for (s, w) in [&mut s.p, &mut s.q].into_iter().zip([wp, wq]) {
                    s[0] += dot(w, ur, None);
                    s[1] += dot(w, r, None);
                    if DERIV {
                        s[2] += dot(w, ur, Some(ur));
                        s[3] += dot(w, r, Some(r));
                        s[4] += dot(w, ur, Some(r));
                    }
                }
            }
        }
        FarSums(sums)
    }
}

/// Nodes per block of [`FarSums::new`] (its per-node factors live on the stack).
const BLOCK: usize = 32;

/// sum_j w_j a_j b_j, in [`LANES`] independent accumulators (so that the compiler can
/// vectorise it); `b` all ones when None.
#[inline(always)]
/// 1 / z for the moment series, without overflow: Smith's quotient (|z|^2 overflows from
/// |z| ~ 1.3e154 on, and x + i beta y from |y| ~ DBL_MAX / beta), and 0 where z itself is
/// infinite (the series' limit: every transform decays like 1 / z).
fn far_inverse(z: C64) -> C64 {
    if !(z.re.is_finite() && z.im.is_finite()) {
        return C64::new(0.0, 0.0);
    }
    if z.re.abs() >= z.im.abs() {
        let r = z.im / z.re;
        let d = z.re + z.im * r;
        C64::new(1.0 / d, -r / d)
    } else {
        let r = z.re / z.im;
        let d = z.im + z.re * r;
        C64::new(r / d, -1.0 / d)
    }
}

fn dot(w: &[f64], a: &[f64], b: Option<&[f64]>) -> f64 {
    let mut acc = [0.0; LANES];
    let chunks = w.chunks_exact(LANES).zip(a.chunks_exact(LANES));
    match b {
        None => chunks.for_each(|(w, a)| {
            for l in 0..LANES {
                acc[l] += w[l] * a[l];
            }
        }),
        Some(b) => chunks.zip(b.chunks_exact(LANES)).for_each(|((w, a), b)| {
            for l in 0..LANES {
                acc[l] += w[l] * a[l] * b[l];
            }
        }),
    }
    let n = w.len() / LANES * LANES;
    let rest = (n..w.len()).map(|j| w[j] * a[j] * b.map_or(1.0, |b| b[j]));
    acc.iter().sum::<f64>() + rest.sum::<f64>()
}

/// Every moment M_k = int f t^k dt, k < MOMENTS, of p and of q of a whole-line expansion
/// (no mirror), from each family's rule exact for degree n + MOMENTS.
fn whole_moments(panels: &[KernelPanel], e: &Expansion, rules: &mut Rules) -> (Vec<f64>, Vec<f64>) {
    let (mut mp, mut mq) = (vec![0.0; MOMENTS], vec![0.0; MOMENTS]);
    for (panel, source) in panels.iter().zip(&e.panels) {
        for f in &source.families {
            let n = f.p.len().max(f.q.len());
            let (nodes, weights) = rule(rules, f.weight, (n + MOMENTS) / 2 + 1);
            let mut leg = vec![0.0; n];
            for (&t, &w) in nodes.iter().zip(weights) {
                let x = panel.m + panel.h * t;
                legendre(t, &mut leg);
                let val = |c: &[f64]| c.iter().zip(&leg).map(|(c, l)| c * l).sum::<f64>();
                let (vp, vq) = (panel.h * w * val(&f.p), panel.h * w * val(&f.q));
                let mut power = 1.0;
                for k in 0..MOMENTS {
                    mp[k] += vp * power;
                    mq[k] += vq * power;
                    power *= x;
                }
            }
        }
    }
    (mp, mq)
}

impl Kernel {
    /// Prepares an expansion's panels.
    pub(crate) fn new(e: &Expansion) -> Self {
        let mut rules = Rules::new();
        // the tractions' scale; where p(0) is infinite (the full-slip limit's |x|^(2g-1)),
        // the mean pressure 1/2
        let p0 = Some(e.tractions(0.0).0)
            .filter(|p| p.is_finite())
            .unwrap_or(0.5);
        let panels: Vec<KernelPanel> = e
            .panels
            .iter()
            .map(|p| KernelPanel::new(p.a, p.b, &p.families, p0, &mut rules))
            .collect();
        // the moments, from each family's rule exact for degree n + MOMENTS, doubled for the
        // mirror half
        let (mut even_p, mut odd_q) = (vec![0.0; MOMENTS / 2], vec![0.0; MOMENTS / 2]);
        for (panel, source) in panels.iter().zip(&e.panels) {
            for f in &source.families {
                let n = f.p.len().max(f.q.len());
                let (nodes, weights) = rule(&mut rules, f.weight, (n + MOMENTS) / 2 + 1);
                for (&t, &w) in nodes.iter().zip(weights) {
                    let x = panel.m + panel.h * t;
                    let mut leg = vec![0.0; n];
                    legendre(t, &mut leg);
                    let val = |c: &[f64]| c.iter().zip(&leg).map(|(c, l)| c * l).sum::<f64>();
                    let (vp, vq) = (2.0 * panel.h * w * val(&f.p), 2.0 * panel.h * w * val(&f.q));
                    let mut power = 1.0;
                    for j in 0..MOMENTS / 2 {
                        even_p[j] += vp * power;
                        odd_q[j] += vq * power * x;
                        power *= x * x;
                    }
                }
            }
        }
        let whole = e
            .whole_line()
            .then(|| whole_moments(&panels, e, &mut rules));
        Kernel {
            panels,
            even_p,
            odd_q,
            whole,
        }
    }

    /// The moment series of a whole-line expansion at |z| >= FAR_RADIUS (times pi):
    /// pi G_f(z) = sum_k M_k / z^(k+1), pi G_f'(z) = -sum_k (k + 1) M_k / z^(k+2).
    fn far_field_whole(&self, z: C64, deriv: bool, mp: &[f64], mq: &[f64]) -> Transforms {
        let terms = ((32.0 / z.norm_sqr().log10()).ceil() as usize + 2).min(MOMENTS);
        let inv = far_inverse(z);
        let zero = C64::new(0.0, 0.0);
        let (mut sp, mut sq, mut dp, mut dq) = (zero, zero, zero, zero);
        for k in (0..terms).rev() {
            sp = sp * inv + mp[k];
            sq = sq * inv + mq[k];
            if deriv {
                dp = dp * inv + mp[k] * (k + 1) as f64;
                dq = dq * inv + mq[k] * (k + 1) as f64;
            }
        }
        let inv2 = inv * inv;
        Transforms {
            p: sp * inv,
            q: sq * inv,
            dp: -dp * inv2,
            dq: -dq * inv2,
        }
    }

    /// Sums over the panels of a whole-line expansion (times pi), each panel's own transform
    /// only: its far rule of the point's band, or its closed form when near.
    fn whole_sums(&self, point: Point, deriv: bool) -> Transforms {
        let zero = C64::new(0.0, 0.0);
        let mut scratch = None;
        let mut t = Transforms::zero();
        let z = point.z();
        for panel in &self.panels {
            let own = match panel.band(z) {
                Some(b) => panel.far_sums(z, b, deriv),
                None => {
                    let scratch =
                        scratch.get_or_insert([[zero; MAX_DEGREE + 1], [zero; MAX_DEGREE + 1]]);
                    panel.near_sums(point, deriv, scratch)
                }
            };
            t.p += own.p;
            t.q += own.q;
            t.dp += own.dp;
            t.dq += own.dq;
        }
        t
    }

    /// The moment series at |z| >= FAR_RADIUS (times pi), with as many terms as |z| needs.
    fn far_field(&self, z: C64, deriv: bool) -> Transforms {
        let terms = ((32.0 / z.norm_sqr().log10()) / 2.0).ceil() as usize + 1;
        let terms = terms.min(MOMENTS / 2);
        let inv = far_inverse(z);
        let w = inv * inv;
        let (mut sp, mut sq) = (C64::new(0.0, 0.0), C64::new(0.0, 0.0));
        let (mut dp, mut dq) = (sp, sq);
        for j in (0..terms).rev() {
            sp = sp * w + self.even_p[j];
            sq = sq * w + self.odd_q[j];
            if deriv {
                dp = dp * w + self.even_p[j] * (2 * j + 1) as f64;
                dq = dq * w + self.odd_q[j] * (2 * j + 2) as f64;
            }
        }
        Transforms {
            p: sp * inv,
            q: sq * w,
            dp: -dp * w,
            dq: -dq * w * inv,
        }
    }

    /// int_x^1 p for 0 <= x <= 1.
    pub(crate) fn p_from(&self, x: f64) -> f64 {
        self.panels
            .iter()
            .filter(|p| p.b > x)
            .map(|p| {
                if p.a >= x {
                    p.h * p.anti.iter().map(|f| f.mass.0).sum::<f64>()
                } else {
                    p.p_from(x)
                }
            })
            .sum()
    }

    /// L_q(x) = int_{-1}^{1} q(s) ln|x - s| ds for real x >= 0 (q odd: each panel minus its
    /// value at -x).
    pub(crate) fn log_potential_q(&self, x: f64) -> f64 {
        let mut scratch = [C64::new(0.0, 0.0); MAX_DEGREE + 1];
        self.panels
            .iter()
            .map(|p| p.log_q(x, true, &mut scratch))
            .sum()
    }

    /// G_p(z), G_q(z) and, when `deriv`, G_p'(z), G_q'(z), at each of the points z, off the
    /// segment [-1, 1] or on it (the limit from below when Im z = -0.0). Points near the
    /// contact share one pass over each far panel's rule.
    pub(crate) fn transforms<const N: usize>(
        &self,
        points: [Point; N],
        deriv: bool,
    ) -> [Transforms; N] {
        if let Some((mp, mq)) = &self.whole {
            let s = 1.0 / PI;
            return points.map(|point| {
                let z = point.z();
                let mut t = if z.norm_sqr() >= FAR_RADIUS * FAR_RADIUS {
                    self.far_field_whole(z, deriv, mp, mq)
                } else {
                    self.whole_sums(point, deriv)
                };
                t.p *= s;
                t.q *= s;
                t.dp *= s;
                t.dq *= s;
                t
            });
        }
        // G_p odd, G_q even (so G_p' even, G_q' odd): each point is taken with Re z >= 0
        let left = points.map(|p| p.z().re < 0.0);
        let right: [Point; N] =
            std::array::from_fn(|i| if left[i] { points[i].neg() } else { points[i] });
        let far = right.map(|p| p.z().norm_sqr() >= FAR_RADIUS * FAR_RADIUS);
        let mut t = if far.iter().any(|&f| f) {
            std::array::from_fn(|i| {
                if far[i] {
                    self.far_field(right[i].z(), deriv)
                } else {
                    self.panel_sums([right[i]], deriv)[0]
                }
            })
        } else {
            self.panel_sums(right, deriv)
        };
        let s = 1.0 / PI;
        for (t, left) in t.iter_mut().zip(left) {
            let sign = if left { -s } else { s };
            t.p *= sign;
            t.q *= s;
            t.dp *= s;
            t.dq *= sign;
        }
        t
    }

    /// Sums over the panels and their mirrors (times pi) at points with Re z >= 0: one pass
    /// over a panel's far rule for all of them when it is far from all of them, by the band of
    /// the nearest.
    fn panel_sums<const N: usize>(&self, points: [Point; N], deriv: bool) -> [Transforms; N] {
        let zero = C64::new(0.0, 0.0);
        // scratch for the near field, filled only when a panel is near
        let mut scratch = None;
        let mut t = [Transforms::zero(); N];
        let mut z = [zero; N];
        for (z, p) in z.iter_mut().zip(&points) {
            *z = p.z();
        }
        for panel in &self.panels {
            let mut bands = [None; N];
            for (b, z) in bands.iter_mut().zip(&z) {
                *b = panel.band(*z);
            }
            // the lowest band (None, near, sorts first)
            if let Some(Some(b)) = bands.iter().min() {
                panel.far_pair(z, *b, deriv, &mut t);
                continue;
            }
            for ((t, point), band) in t.iter_mut().zip(points).zip(bands) {
                let one = std::slice::from_mut(t).try_into().expect("one point");
                if let Some(b) = band {
                    panel.far_pair([point.z()], b, deriv, one);
                    continue;
                }
                let scratch =
                    scratch.get_or_insert([[zero; MAX_DEGREE + 1], [zero; MAX_DEGREE + 1]]);
                let own = panel.near_sums(point, deriv, scratch);
                let mirror = match panel.band(-point.z()) {
                    Some(b) => panel.far_sums(-point.z(), b, deriv),
                    None => panel.near_sums(point.neg(), deriv, scratch),
                };
                // g_p(z) - g_p(-z), g_q(z) + g_q(-z); derivatives in z
                t.p += own.p - mirror.p;
                t.q += own.q + mirror.q;
                t.dp += own.dp + mirror.dp;
                t.dq += own.dq - mirror.dq;
            }
        }
        t
    }
}
