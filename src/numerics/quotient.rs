//! The difference-quotient family of the slip zone for small edge exponents
//! (docs/theory_spectral.md, section 7): D(t) p_k(t), k < n, with
//!
//!   D(t) = (1 - t)^-g ((1 + t)^g - 1) / g   (-> ln(1 + t) as g -> 0)
//!
//! and p_k the orthonormal polynomials of the weight (1 - t)^-g (those of
//! [`JacobiFamily`] (-g, 0)). With the family (1 - t)^-g p_k it spans what (1 - t)^-g p_k and
//! (1 - t)^-g (1 + t)^g p_k span, without their near-dependence as g -> 0.
//!
//! The transforms T_k(y) = (1/pi) PV int D p_k / (t - y) dt (the convention of
//! [`crate::numerics::jacobi_transform`]):
//! - T_0 in closed form, each term finite as g -> 0 ((Q2) inside, (Q3) for y < -1);
//! - T_k by the recurrence of the p_k with the moments m_k = int D p_k in closed form (Q4):
//!   forward inside and, for y < -1, while n ln rho <= [`FORWARD_SPAN`]; beyond, Olver's
//!   boundary-value form (the T_k decay only algebraically there, since D is not analytic at
//!   t = -1, so Miller's normalisation does not apply).
//!
//! Points y > 1 do not occur (the slip zone's punch edge is its right end) and are not served.
//!
//! The stick zone's family ([`QuotientFamily::stick`], (Q6)-(Q8)): D_s(t) p_k(t) with
//! D_s = ((1 - t^2)^g - 1) / g (-> ln(1 - t^2)) and p_k the orthonormal Legendre polynomials,
//! which with the Legendre polynomials spans what they and (1 - t^2)^g P_k^(g,g) span. Its
//! T_0 is odd in y and served on both sides: inside (Q6), outside by the series in
//! x = (y - 1)/(y + 1) up to y = 3 and in 2/(1 + y) beyond (Q7); the same recurrence with
//! the Legendre coefficients and the moments (Q8), Olver's form on both sides.

use std::f64::consts::{LN_2, PI};

use super::cauchy::{gap_over, pochhammer_tail};
use super::jacobi_transform::{
    FORWARD_SPAN, JacobiFamily, Point, SYMMETRIC_SERIES_BELOW, SmallSymmetric, deepest,
};
use super::orthopoly::JacobiRecurrence;
use super::special::{exprel, exprel2, symmetric_mass_tail};

/// Olver's form starts this far (in units of 1 / ln rho) above the top degree with T = 0
/// there. The T_k decay only algebraically, so the error at degree k is about
/// |T_top| rho^-(top - k): e^-40 = 4e-18 of it at the top degree.
const OLVER_SPAN: f64 = 40.0;

/// Which difference quotient.
#[derive(Clone, Debug)]
enum Kind {
    /// The slip zone's D = (1 - t)^-g ((1 + t)^g - 1) / g with the p_k of (1 - t)^-g.
    Slip,
    /// The stick zone's D_s = ((1 - t^2)^g - 1) / g with the Legendre p_k ([`Symmetric`]).
    Stick(Box<Symmetric>),
}

/// The family D p_k, k < n, for one g in (0, 1/2).
#[derive(Clone, Debug)]
pub(crate) struct QuotientFamily {
    kind: Kind,
    g: f64,
    n: usize,
    /// The polynomials' family (-g, 0): its values give the p_k.
    polys: JacobiFamily,
    /// The recurrence of the p_k, up to the deepest start of Olver's form.
    rec: JacobiRecurrence,
    /// m_k = int D p_k, k < the recurrence's degree.
    moments: Vec<f64>,
}

impl QuotientFamily {
    /// The family of `n` functions for 0 < g < 1/2.
    pub(crate) fn new(g: f64, n: usize) -> Self {
        debug_assert!(g > 0.0 && g < 0.5 && n >= 1);
        let top = deepest(n, OLVER_SPAN) + 2;
        QuotientFamily {
            kind: Kind::Slip,
            g,
            n,
            polys: JacobiFamily::new(-g, 0.0, n),
            rec: JacobiRecurrence::new(top, -g, 0.0),
            moments: moments(g, top),
        }
    }

    /// The stick zone's family of `n` functions D_s p_k, D_s = ((1 - t^2)^g - 1) / g, p_k the
    /// orthonormal Legendre polynomials, for 0 < g < [`SYMMETRIC_SERIES_BELOW`] ((Q6)-(Q8)).
    pub(crate) fn stick(g: f64, n: usize) -> Self {
        debug_assert!(g > 0.0 && g < SYMMETRIC_SERIES_BELOW && n >= 1);
        let top = deepest(n, OLVER_SPAN) + 2;
        let sym = Symmetric::new(g);
        let moments = sym.moments(top);
        QuotientFamily {
            kind: Kind::Stick(Box::new(sym)),
            g,
            n,
            polys: JacobiFamily::new(0.0, 0.0, n),
            rec: JacobiRecurrence::new(top, 0.0, 0.0),
            moments,
        }
    }

    /// Whether `other` is the same family (g and length).
    pub(crate) fn same_as(&self, other: &QuotientFamily) -> bool {
        let stick = |f: &QuotientFamily| matches!(f.kind, Kind::Stick(_));
        (self.g, self.n, stick(self)) == (other.g, other.n, stick(other))
    }

    /// Number of functions.
    pub(crate) fn len(&self) -> usize {
        self.n
    }

    /// int D p_k (Q4).
    pub(crate) fn moment(&self, k: usize) -> f64 {
        self.moments[k]
    }

    /// D(y) for y in [-1, 1): (1 - y)^-g ln(1 + y) exprel(g ln(1 + y)), to full relative
    /// accuracy for every g (-1 / g (1 - y)^-g at y = -1).
    pub(crate) fn weight(&self, p: Point) -> f64 {
        let (a, b) = self.factors(p);
        a * b
    }

    /// D's factors (1 - y)^-g and ((1 + y)^g - 1) / g (the stick family's: 1 and D_s).
    pub(crate) fn factors(&self, p: Point) -> (f64, f64) {
        let g = self.g;
        if let Kind::Stick(_) = self.kind {
            let log = if p.omy == 0.0 || p.opy == 0.0 {
                -1.0 / g
            } else {
                let l = p.omy.ln() + p.opy.ln();
                l * exprel(g * l)
            };
            return (1.0, log);
        }
        let log = if p.opy == 0.0 {
            -1.0 / g
        } else {
            let l = p.opy.ln();
            l * exprel(g * l)
        };
        (p.omy.powf(-g), log)
    }

    /// w p_k(y), k < n, with the weight's value `w` given.
    pub(crate) fn values_weighted(&self, p: Point, w: f64, out: &mut [f64]) {
        self.polys.values_weighted(p, w, out);
    }

    /// T_0(y) for y in (-1, 1) (Q2) or y < -1 (Q3); the stick family's at any y off the
    /// ends ((Q6), (Q7)).
    pub(crate) fn t0(&self, p: Point) -> f64 {
        let g = self.g;
        if let Kind::Stick(sym) = &self.kind {
            return sym.t0(p);
        }
        if p.inside() {
            // rho = (1 + y) / (1 - y), zeta = (1 - y) / 2
            let l_rho = (p.opy / p.omy).ln();
            let zeta = 0.5 * p.omy;
            let l_zeta = zeta.ln();
            let rho_g = (g * l_rho).exp();
            let z_g = (-g * p.omy.ln()).exp();
            (gap_over(g, true) * (rho_g - z_g)
                - gap_over(g, false)
                - LN_2 * l_rho * exprel(-g * LN_2)
                - l_rho * l_rho * exprel2(g * l_rho)
                + (-g * LN_2).exp()
                    * (l_zeta * l_zeta * exprel2(-g * l_zeta) + pochhammer_tail(-g, zeta)))
                / PI
        } else {
            debug_assert!(p.opy < 0.0, "the quotient family serves y < 1");
            // xi = 2 / (1 - y), l = ln(1 - xi) = ln((-1 - y) / (1 - y))
            let xi = 2.0 / p.omy;
            let l = if xi < 0.5 {
                (-xi).ln_1p()
            } else {
                (-p.opy / p.omy).ln()
            };
            (-l * l * exprel2(g * l) - LN_2 * l * exprel(-g * LN_2)
                + g * l * exprel(g * l) * gap_over(g, false)
                - (-g * LN_2).exp() * pochhammer_tail(g, xi))
                / PI
        }
    }

    /// T_k(y), k < n, y in (-1, 1) or y < -1 (the stick family's: any y off the ends).
    pub(crate) fn transforms(&self, p: Point, out: &mut [f64]) {
        let n = self.n;
        let out = &mut out[..n];
        out[0] = self.t0(p);
        if n == 1 {
            return;
        }
        let ln_rho = p.ln_rho();
        let r = &self.rec;
        let m = &self.moments;
        if p.inside() || (n as f64) * ln_rho <= FORWARD_SPAN {
            // off_k T_(k+1) = (y - diag_k) T_k - off_(k-1) T_(k-1) + m_k / pi
            let mut prev = 0.0;
            for k in 0..n - 1 {
                let back = if k == 0 { 0.0 } else { r.off[k - 1] * prev };
                let next = ((p.y - r.diag[k]) * out[k] - back + m[k] / PI) * r.inv_off[k];
                prev = out[k];
                out[k + 1] = next;
            }
        } else {
            // Olver: the equations k = 1 .. top - 1 for T_1 .. T_(top-1), with T_0 known and
            // T_top = 0 (the error at degree k < n falls like rho^-(top - k)), by elimination
            // down the tridiagonal system (diagonally dominant outside [-1, 1]:
            // |y - diag_k| > 1 >= off_(k-1) + off_k)
            let top = (n + (OLVER_SPAN / ln_rho).ceil() as usize).min(r.off.len());
            // equation k: off_(k-1) T_(k-1) - (y - diag_k) T_k + off_k T_(k+1) = m_k / pi
            let mut c = vec![0.0; top];
            let mut d = vec![0.0; top];
            let mut t = vec![0.0; top + 1];
            t[0] = out[0];
            for k in 1..top {
                let lower = r.off[k - 1];
                let diag = -(p.y - r.diag[k]);
                let upper = if k + 1 < top { r.off[k] } else { 0.0 };
                let mut rhs = m[k] / PI;
                let (pivot, carried) = if k == 1 {
                    rhs -= lower * t[0];
                    (diag, 0.0)
                } else {
                    (diag - lower * c[k - 1], lower * d[k - 1])
                };
                c[k] = upper / pivot;
                d[k] = (rhs - carried) / pivot;
            }
            for k in (1..top).rev() {
                t[k] = d[k] - c[k] * t[k + 1];
            }
            out[1..n].copy_from_slice(&t[1..n]);
        }
    }
}

/// Number of terms of the power series in z, x, zeta <= 1/2 ((Q6), (Q7)): 2^-64 of the
/// first term left out.
const SERIES_TERMS: usize = 64;

/// The stick family's constants (docs/theory_spectral.md (J2s), (Q6)-(Q8)): with
/// B = mu_0^(g,g) (2g + 1) / 2 = e^beta, gap(g) / g principal and not ([`gap_over`]),
/// h = (beta / g - 2 ln 2) / g ([`symmetric_mass_tail`]),
/// and the coefficients of the four series, each a difference quotient in g formed from
/// logarithms that are O(g) to full relative accuracy (ln_1p), so that no 1/g is left.
#[derive(Clone, Debug)]
pub(crate) struct Symmetric {
    /// g, gap(g) / g, beta, B and S(z) of (J2s).
    base: SmallSymmetric,
    gap_not: f64,
    /// (B - 1) / g = (beta / g) exprel(beta), and -h - (beta / g)^2 exprel2(beta), the
    /// constant part of (Q6) and (Q7).
    b_step: f64,
    common: f64,
    /// Inside, (S - S_0) / g = sum d_n z^n (n >= 1; index n - 1).
    d: Vec<f64>,
    /// For 1 < y <= 3, V(x) = sum v_n x^n and (V - V_0) / g = sum e_n x^n.
    v: Vec<f64>,
    e: Vec<f64>,
    /// For y > 3, T_0 = -(1/pi) sum f_n zeta^(n+1), zeta = 2 / (1 + y) (n >= 0).
    f: Vec<f64>,
}

impl Symmetric {
    fn new(g: f64) -> Self {
        let base = SmallSymmetric::new(g);
        let h = symmetric_mass_tail(g);
        let (mut d, mut v, mut e, mut f) = (vec![], vec![], vec![], vec![]);
        // ln(n r_n) = sum_(j < n) [ln(1 - 2g/j) - ln(1 - g/j)] - ln(1 - g/n) for S's
        // coefficients r_n; the same for ln(n v_n) with ln(1 + g/j) in place of
        // ln(1 - 2g/j); ln((n + 1) (mu_0 / 2) (g + 1)_n / (2g + 2)_n) = ln(mu_0 / 2) +
        // sum_(j < n) [ln(1 + g/(1+j)) - ln(1 + 2g/(2+j))]
        let (mut lr, mut lv, mut lf) = (0.0, 0.0, base.beta - (2.0 * g).ln_1p());
        for n in 1..=SERIES_TERMS {
            let nf = n as f64;
            let last = -(-g / nf).ln_1p();
            d.push((lr + last).exp_m1() / (nf * g));
            v.push((lv + last).exp() / nf);
            e.push((lv + last).exp_m1() / (nf * g));
            lr += (-2.0 * g / nf).ln_1p() - (-g / nf).ln_1p();
            lv += (g / nf).ln_1p() - (-g / nf).ln_1p();
            // f_(n-1), from the logarithm at n - 1
            f.push(lf.exp_m1() / (nf * g));
            lf += (g / nf).ln_1p() - (2.0 * g / (nf + 1.0)).ln_1p();
        }
        let bg = base.beta_over_g;
        Symmetric {
            gap_not: gap_over(g, false),
            b_step: bg * exprel(base.beta),
            common: -h - bg * bg * exprel2(base.beta),
            base,
            d,
            v,
            e,
            f,
        }
    }

    /// T_0 of D_s at y off the ends: (Q6) for 0 <= y < 1, (Q7) for y > 1, odd in y.
    fn t0(&self, p: Point) -> f64 {
        let g = self.base.g;
        let series = |c: &[f64], z: f64| c.iter().rev().fold(0.0, |acc, &a| acc * z + a) * z;
        let (p, sign) = if p.y < 0.0 {
            (p.reflected(), -1.0)
        } else {
            (p, 1.0)
        };
        let value = if p.inside() {
            let z = 0.5 * p.omy;
            let l = p.omy.ln() + p.opy.ln();
            let gap = self.base.gap;
            -g * gap * l * exprel(g * l) + l * l * exprel2(g * l) - gap
                + self.common
                + 2.0 * (self.b_step * self.base.s(z) + series(&self.d, z))
        } else if p.y <= 3.0 {
            let x = -p.omy / p.opy;
            let l = (-p.omy).ln() + p.opy.ln();
            -self.gap_not * (g * l).exp() + l * l * exprel2(g * l) + self.common
                - 2.0 * (self.b_step * series(&self.v, x) + series(&self.e, x))
        } else {
            let zeta = 2.0 / p.opy;
            -series(&self.f, zeta)
        };
        sign * value / PI
    }

    /// m_k = int D_s p_k, k < top ((Q8)): m_0 = (mu_0 - 2) / g = 2 ((beta / g) exprel(beta) -
    /// 2) / (2g + 1), odd k 0, and for k = 2m >= 2, from int (1 - t^2)^g P_2m = mu_0 (-g)_m
    /// (1/2)_m / ((g + 3/2)_m m!) with (-g)_m / g = -(1 - g)_(m-1), times sqrt(4m + 1).
    fn moments(&self, top: usize) -> Vec<f64> {
        let g = self.base.g;
        let mu0 = 2.0 * self.base.b / (2.0 * g + 1.0);
        let mut out = vec![0.0; top];
        out[0] = 2.0 * (self.b_step - 2.0) / (2.0 * g + 1.0);
        // the product -(1 - g)_(m-1) (1/2)_m / ((g + 3/2)_m m!)
        let mut prod = -1.0;
        for m in 1..top.div_ceil(2) {
            let mf = m as f64;
            if m > 1 {
                prod *= mf - 1.0 - g;
            }
            prod *= (mf - 0.5) / ((g + 0.5 + mf) * mf);
            if 2 * m < top {
                out[2 * m] = (4.0 * mf + 1.0).sqrt() * mu0 * prod;
            }
        }
        out
    }
}

/// m_k = int D p_k, k < top (Q4): m_0 = (mu(-g,g) - mu(-g,0)) / g
/// = -2 g gap(g)' - 2 (1 - ln 2 exprel(-g ln 2)) / (1 - g), gap' = gap_over(g, false), and for
/// k >= 1, from int (1 - t)^-g (1 + t)^g P_k^(-g,0) (Gradshteyn-Ryzhik 7.391 with
/// Chu-Vandermonde), divided by g exactly and normalised (p_k = P_k sqrt((2k + 1 - g) / (1 - g))):
/// m_k = sqrt((2k + 1 - g) / (1 - g)) mu (-1)^(k-1) (1 - g)_k (1 - g)_(k-1) / (k! (k + 1)!),
/// mu = 2 pi g / sin(pi g).
fn moments(g: f64, top: usize) -> Vec<f64> {
    let mu = 2.0 * (1.0 - g * g * gap_over(g, false));
    let mut m = Vec::with_capacity(top);
    m.push(-2.0 * g * gap_over(g, false) - 2.0 * (1.0 - LN_2 * exprel(-g * LN_2)) / (1.0 - g));
    // the product without the square root: (-1)^(k-1) (1 - g)_k (1 - g)_(k-1) / (k! (k+1)!)
    let mut prod = (1.0 - g) / 2.0;
    for k in 1..top {
        if k > 1 {
            let kf = k as f64;
            prod *= -(kf - g) * (kf - 1.0 - g) / (kf * (kf + 1.0));
        }
        let kf = k as f64;
        m.push(((2.0 * kf + 1.0 - g) / (1.0 - g)).sqrt() * mu * prod);
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::quadrature::gauss_legendre;

    /// Reference values of T_0 from mpmath (40 digits: the closed forms (Q2), (Q3), each
    /// checked there against mpmath's quadrature of the principal value to 1e-30).
    const T0: [(f64, f64, f64); 6] = [
        (1e-6, -0.9, 0.252_402_659_104_338_25),
        (1e-3, 0.99, -0.636_201_564_326_222_6),
        (0.01, -0.3, 0.877_124_645_073_608_5),
        (0.03, -1.01, -3.527_391_009_976_812_6),
        (0.1, -1e4, -1.277_523_720_652_390_4e-5),
        (0.03, 0.999_999_999_9, -6.981_178_165_543_627),
    ];

    #[test]
    fn t0_matches_mpmath() {
        for (g, y, v) in T0 {
            let f = QuotientFamily::new(g, 1);
            // the offsets of the decimal y, as mpmath took it
            let p = if y > 0.99 {
                Point::offsets(1e-10, 1.999_999_999_9)
            } else {
                Point::new(y)
            };
            let t = f.t0(p);
            assert!(
                (t - v).abs() <= 1e-14 * v.abs(),
                "g = {g}, y = {y}: {t} against {v}"
            );
        }
    }

    /// int_{-1}^{1} f by Gauss-Legendre on panels graded geometrically towards both ends (in
    /// the offsets, so that the singular ends keep their digits) and towards `pole`.
    fn graded(f: &dyn Fn(f64, f64, f64) -> f64, cuts: &[f64]) -> f64 {
        let (x, w) = gauss_legendre(30);
        let mut sum = 0.0;
        for pair in cuts.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let h = 0.5 * (b - a);
            for (xi, wi) in x.iter().zip(&w) {
                let t = a + h * (1.0 + xi);
                // offsets from the nearer end, exactly
                let omt = if t > 0.0 {
                    (1.0 - b) + h * (1.0 - xi)
                } else {
                    1.0 - t
                };
                let opt = if t <= 0.0 {
                    (1.0 + a) + h * (1.0 + xi)
                } else {
                    1.0 + t
                };
                sum += h * wi * f(t, omt, opt);
            }
        }
        sum
    }

    fn cuts_towards(ends: &[f64]) -> Vec<f64> {
        let mut c: Vec<f64> = ends.to_vec();
        for e in 1..=60 {
            let d = 0.5f64.powi(e);
            c.push(-1.0 + d);
            c.push(1.0 - d);
        }
        c.sort_by(|a, b| a.partial_cmp(b).unwrap());
        c.dedup();
        c
    }

    #[test]
    fn moments_and_outside_transforms_match_quadrature() {
        for g in [1e-6, 1e-3, 0.01, 0.03, 0.1] {
            let n = 24;
            moments_and_outside(&QuotientFamily::new(g, n), &[-1.3, -1.05, -3.0, -40.0]);
        }
    }

    /// The stick family's moments, and its transforms on both sides outside (the series in
    /// x up to y = 3, in zeta beyond).
    #[test]
    fn stick_moments_and_outside_transforms_match_quadrature() {
        for g in [1e-6, 1e-3, 0.01, 0.049] {
            let ys = [1.05, 1.3, 2.9, 3.1, 40.0, -1.3, -5.0];
            moments_and_outside(&QuotientFamily::stick(g, 24), &ys);
        }
    }

    fn moments_and_outside(f: &QuotientFamily, ys: &[f64]) {
        {
            let (g, n) = (f.g, f.n);
            let cuts = cuts_towards(&[-1.0, 0.0, 1.0]);
            let mut v = vec![0.0; n];
            let k_of = |k: usize, y: Option<f64>| {
                let f = &f;
                graded(
                    &move |t, omt, opt| {
                        let p = Point::offsets(omt, opt);
                        let mut v = vec![0.0; n];
                        f.values_weighted(p, f.weight(p), &mut v);
                        match y {
                            None => v[k],
                            Some(y) => v[k] / (t - y) / PI,
                        }
                    },
                    &cuts,
                )
            };
            for k in 0..n {
                let q = k_of(k, None);
                assert!(
                    (f.moment(k) - q).abs() <= 1e-13 * (1.0 + q.abs()),
                    "g = {g}, m_{k} = {} against {q}",
                    f.moment(k)
                );
            }
            for &y in ys {
                f.transforms(Point::new(y), &mut v);
                for k in [0, 1, 5, 13, 23] {
                    let q = k_of(k, Some(y));
                    let scale = v[0].abs();
                    assert!(
                        (v[k] - q).abs() <= 1e-13 * scale,
                        "g = {g}, y = {y}: T_{k} = {} against {q}",
                        v[k]
                    );
                }
            }
        }
    }

    /// Inside: the principal value by subtracting D p_k(y) (the rest by the graded rule,
    /// with the pole cut into the panels), against the recurrence.
    #[test]
    fn inside_transforms_match_subtracted_quadrature() {
        for g in [1e-6, 1e-3, 0.03, 0.1] {
            inside(&QuotientFamily::new(g, 16));
        }
    }

    #[test]
    fn stick_inside_transforms_match_subtracted_quadrature() {
        for g in [1e-6, 1e-3, 0.03, 0.049] {
            inside(&QuotientFamily::stick(g, 16));
        }
    }

    fn inside(f: &QuotientFamily) {
        let n = f.n;
        {
            let g = f.g;
            for y in [-0.97, -0.4, 0.25, 0.9] {
                let py = Point::new(y);
                let mut vy = vec![0.0; n];
                f.values_weighted(py, f.weight(py), &mut vy);
                let mut t = vec![0.0; n];
                f.transforms(py, &mut t);
                let mut cuts = cuts_towards(&[-1.0, 1.0]);
                for e in 0..12 {
                    let d = 0.5f64.powi(e) * 0.5 * (1.0 - y.abs());
                    cuts.push(y - d);
                    cuts.push(y + d);
                }
                cuts.push(y);
                cuts.sort_by(|a, b| a.partial_cmp(b).unwrap());
                cuts.dedup();
                for k in [0, 1, 4, 15] {
                    let rest = graded(
                        &|t, omt, opt| {
                            let p = Point::offsets(omt, opt);
                            let mut v = vec![0.0; n];
                            f.values_weighted(p, f.weight(p), &mut v);
                            (v[k] - vy[k]) / (t - y)
                        },
                        &cuts,
                    );
                    let q = (rest + vy[k] * ((1.0 - y) / (1.0 + y)).ln()) / PI;
                    assert!(
                        (t[k] - q).abs() <= 1e-11 * (1.0 + q.abs()),
                        "g = {g}, y = {y}: T_{k} = {} against {q}",
                        t[k]
                    );
                }
            }
        }
    }

    /// The stick family's T_0 against mpmath ((T_0^(g,g) - T_0^(0,0)) / g, each by mpmath's
    /// quadrature at 45 digits, the principal value subtracted inside), inside and on both
    /// sides outside; y = 1 -+ 2^-20 with their offsets exact.
    #[test]
    fn stick_t0_matches_mpmath() {
        const T0: [(f64, f64, f64); 30] = [
            (1e-6, 0.3, -0.26081374663133977),
            (1e-6, 0.9, -0.3138404766481284),
            (1e-6, 0.9999990463256836, 26.774826912836442),
            (1e-6, -0.5, 0.4183515695003038),
            (1e-6, 1.0000009536743164, 28.345597106064492),
            (1e-6, 1.5, 0.3862940374364411),
            (1e-6, 2.9, 0.1470221152796743),
            (1e-6, 3.5, 0.11840202150416249),
            (1e-6, 40.0, 0.009771667407017997),
            (1e-6, -1.2, -0.699458547323026),
            (1e-3, 0.3, -0.26066257788691327),
            (1e-3, 0.9, -0.3124762489260126),
            (1e-3, 0.9999990463256836, 26.667670697291765),
            (1e-3, -0.5, 0.4180284592341317),
            (1e-3, 1.0000009536743164, 28.217911435716516),
            (1e-3, 1.5, 0.38591781992433255),
            (1e-3, 2.9, 0.14688949540061216),
            (1e-3, 3.5, 0.11829593716912326),
            (1e-3, 40.0, 0.009763031469065458),
            (1e-3, -1.2, -0.69870409681166),
            (0.03, 0.3, -0.2563766024942402),
            (0.03, 0.9, -0.274387168114575),
            (0.03, 0.9999990463256836, 23.808065127732252),
            (0.03, -0.5, 0.40886379267237916),
            (0.03, 1.0000009536743164, 24.8669590503747),
            (0.03, 1.5, 0.37531528131249364),
            (0.03, 2.9, 0.14314784383184073),
            (0.03, 3.5, 0.11530266989308297),
            (0.03, 40.0, 0.00951931638571119),
            (0.03, -1.2, -0.6774788586204615),
        ];
        let tiny = 2f64.powi(-20);
        for (g, y, v) in T0 {
            let f = QuotientFamily::stick(g, 1);
            let p = if (y - 1.0).abs() < 1e-5 {
                let omy = if y < 1.0 { tiny } else { -tiny };
                Point::offsets(omy, 2.0 - omy)
            } else {
                Point::new(y)
            };
            let t = f.t0(p);
            assert!(
                (t - v).abs() <= 4e-15 * (1.0 + v.abs()),
                "g = {g}, y = {y}: {t} against {v}"
            );
        }
    }
}
