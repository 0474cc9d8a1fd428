//! Finite Hilbert (Cauchy) transforms of Jacobi-weighted orthonormal Jacobi polynomials, for
//! any exponents a, b in (-1, 1) with a + b > -1, at any real point off the interval ends:
//!
//!   T_k(y) = (1/pi) PV int_{-1}^{1} w(t) p_k(t) / (t - y) dt,   w(t) = (1 - t)^a (1 + t)^b,
//!
//! p_k the orthonormal Jacobi polynomials of [`JacobiRecurrence`] (p_0 = 1). The finite
//! Hilbert transform of the docs' convention is H = -T (docs/theory_spectral.md, (J1)).
//!
//! - T_0 in closed form (docs/theory_spectral.md, (J2)-(J4)): inside (-1, 1) Tricomi's
//!   cot(pi a) w(y) - K_0 2F1(1, -a-b; 1-a; (1-y)/2); outside, the Stieltjes transform of the
//!   weight, -(mu_0 / pi) 2F1(1, b+1; a+b+2; 2/(1+y)) / (1 + y) for y > 1, and the reflection
//!   T^(a,b)(y) = -T^(b,a)(-y) for the left half. Every 2F1 is evaluated at an argument
//!   <= 1/2 by its series, or near 1 by [`Hyp2f1`] (after Euler's transformation where its
//!   exponent c - a - b is negative), with 1 - z formed from the offsets 1 -+ y the caller
//!   gives to full accuracy.
//! - T_k, k >= 1, by the three-term recurrence of the p_k with the moment int w p_k =
//!   mu_0 delta_k0 as its inhomogeneity (J5): forward inside the interval and close to it
//!   (up to a loss of e^3 in relative accuracy), else backward as a ratio recurrence (Miller's
//!   algorithm: outside, T_k is the minimal solution, decaying like rho^-k with
//!   rho = |y| + sqrt(y^2 - 1)), normalised by T_0.
//! - Poles: the transform of w(t) / (z - t) for z outside [-1, 1] is the divided difference
//!   (T_0(y) - T_0(z)) / (z - y) (J6), and its integral is -pi T_0(z).

use std::f64::consts::PI;

use super::cauchy::gap_over;
use super::orthopoly::{JacobiRecurrence, jacobi_mass};
use super::special::{Hyp2f1, SeriesRatios, exprel, symmetric_mass_tail, tan_pi};

/// A real point y with its offsets 1 - y and 1 + y, each to full relative accuracy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    pub(crate) y: f64,
    pub(crate) omy: f64,
    pub(crate) opy: f64,
}

impl Point {
    /// The point y (its offsets as rounded from y; use [`Point::offsets`] near the ends).
    #[cfg(test)]
    pub(crate) fn new(y: f64) -> Self {
        Point {
            y,
            omy: 1.0 - y,
            opy: 1.0 + y,
        }
    }

    /// The point with the given offsets 1 - y and 1 + y (y from the smaller one).
    pub(crate) fn offsets(omy: f64, opy: f64) -> Self {
        let y = if omy.abs() < opy.abs() {
            1.0 - omy
        } else {
            opy - 1.0
        };
        Point { y, omy, opy }
    }

    /// -y.
    pub(crate) fn reflected(self) -> Self {
        Point {
            y: -self.y,
            omy: self.opy,
            opy: self.omy,
        }
    }

    /// z - y for a point z outside [-1, 1] (self), from the offsets at z's end: (1 - y) - (1 - z)
    /// for z > 1, (1 + z) - (1 + y) for z < -1. Each offset is exact to rounding, so the
    /// difference is too where z and y lie near the same end (y - z computed from the rounded
    /// y values loses eps / |z - y| of it: 2e-3 at |z - y| = 1e-13).
    pub(crate) fn minus(self, y: Point) -> f64 {
        if self.y > 0.0 {
            y.omy - self.omy
        } else {
            self.opy - y.opy
        }
    }

    /// Whether the point lies inside (-1, 1).
    pub(crate) fn inside(self) -> bool {
        self.omy > 0.0 && self.opy > 0.0
    }

    /// ln rho = arcosh |y| for |y| > 1 (0 inside), from the offset |y| - 1.
    pub(crate) fn ln_rho(self) -> f64 {
        let d = if self.omy < 0.0 {
            -self.omy
        } else if self.opy < 0.0 {
            -self.opy
        } else {
            return 0.0;
        };
        (d + (d * (2.0 + d)).sqrt()).ln_1p()
    }
}

/// Relative accuracy lost at most by the forward recurrence outside the interval: it is run
/// forward while k ln rho <= FORWARD_SPAN (error growth e^(2 k ln rho) <= e^3 = 20).
pub(crate) const FORWARD_SPAN: f64 = 1.5;

/// Miller's backward recurrence starts this far (in units of 1 / ln rho) above the top
/// degree: the ratio's error falls like rho^(-2 m), e^-40 = 4e-18 at m ln rho = 20.
const MILLER_SPAN: f64 = 20.0;

/// Size at which Miller's unnormalised backward recurrence is scaled down, 2^500 (it grows like
/// rho per step; a power of two scales exactly, and any one far from the overflow threshold
/// serves).
const RESCALE: f64 = f64::from_bits((1023 + 500) << 52);

/// The deepest start of a backward recurrence (or boundary-value form) that starts `span` /
/// ln rho above the top degree, for n functions: it is used only where
/// n ln rho > [`FORWARD_SPAN`], so it starts at most n + span n / FORWARD_SPAN.
pub(crate) fn deepest(n: usize, span: f64) -> usize {
    n + (span / FORWARD_SPAN * n as f64).ceil() as usize
}

/// The family w p_k, k < n, for exponents (a, b).
#[derive(Clone, Debug)]
pub(crate) struct JacobiFamily {
    a: f64,
    b: f64,
    n: usize,
    /// mu_0 = int w.
    mass: f64,
    /// The recurrence coefficients, up to the deepest start of the backward recurrence.
    rec: JacobiRecurrence,
    /// The hypergeometric functions of T_0 with their constants, for the exponents as given
    /// and swapped (the reflection).
    ends: [Ends; 2],
}

/// The 2F1s of T_0 near z = 1 for one orientation (a, b) of the exponents: Tricomi's inside
/// (None where it is 1 or not needed) and the outside one (J2)-(J3).
#[derive(Clone, Debug)]
struct Ends {
    inside: Option<Hyp2f1>,
    outside: Hyp2f1,
    /// Tricomi's 2F1(1, -a-b; 1-a; z) by its power series for z <= 1/2, built on first use.
    series: std::sync::OnceLock<SeriesRatios>,
    /// (J2s): equal exponents a = b below [`SYMMETRIC_SERIES_BELOW`].
    symmetric: Option<SmallSymmetric>,
}

impl Ends {
    fn new(a: f64, b: f64) -> Self {
        let inside = if a + b == 0.0 {
            None
        } else if b == 0.0 && a > 0.0 {
            Some(Hyp2f1::new(1.0, 1.0 - a, 0.0))
        } else if -a - b > 0.0 && b >= 0.0 {
            Some(Hyp2f1::new(1.0, -a - b, b))
        } else if a < 0.0 && b <= 0.0 {
            Some(Hyp2f1::new(-a, 1.0 + b, -b))
        } else {
            None
        };
        let outside = if a >= 0.0 {
            Hyp2f1::new(1.0, b + 1.0, a)
        } else {
            Hyp2f1::new(a + b + 1.0, a + 1.0, -a)
        };
        Ends {
            inside,
            outside,
            series: std::sync::OnceLock::new(),
            symmetric: (a == b && a > 0.0 && a < SYMMETRIC_SERIES_BELOW)
                .then(|| SmallSymmetric::new(a)),
        }
    }
}

impl JacobiFamily {
    /// The family of `n` functions for exponents a, b in (-1, 1), a + b > -1 (the integer
    /// exponent allowed is 0, and at most at one end unless both are 0).
    pub(crate) fn new(a: f64, b: f64, n: usize) -> Self {
        debug_assert!(a > -1.0 && a < 1.0 && b > -1.0 && b < 1.0 && a + b > -1.0);
        debug_assert!(n >= 1);
        JacobiFamily {
            a,
            b,
            n,
            mass: jacobi_mass(a, b),
            rec: JacobiRecurrence::new(deepest(n, MILLER_SPAN) + 2, a, b),
            ends: [Ends::new(a, b), Ends::new(b, a)],
        }
    }

    /// Whether `other` is the same family (exponents and length).
    pub(crate) fn same_as(&self, other: &JacobiFamily) -> bool {
        (self.a, self.b, self.n) == (other.a, other.b, other.n)
    }

    /// Number of functions.
    pub(crate) fn len(&self) -> usize {
        self.n
    }

    /// int w p_k = mu_0 for k = 0 (0 for k >= 1).
    pub(crate) fn mass(&self) -> f64 {
        self.mass
    }

    /// w(y) for y in [-1, 1].
    pub(crate) fn weight(&self, p: Point) -> f64 {
        power(p.omy, self.a) * power(p.opy, self.b)
    }

    /// The weight's factors (1 - y)^a and (1 + y)^b.
    pub(crate) fn weight_factors(&self, p: Point) -> (f64, f64) {
        (power(p.omy, self.a), power(p.opy, self.b))
    }

    /// w(y) p_k(y), k < n, for y in (-1, 1).
    #[cfg(test)]
    pub(crate) fn values(&self, p: Point, out: &mut [f64]) {
        self.values_weighted(p, self.weight(p), out);
    }

    /// w p_k(y), k < n, for y in [-1, 1] with the weight's value `w` given (e.g. one end's
    /// factor left out, to split off the singular factor there).
    pub(crate) fn values_weighted(&self, p: Point, w: f64, out: &mut [f64]) {
        let r = &self.rec;
        let (mut prev, mut cur) = (0.0, 1.0);
        for (k, o) in out.iter_mut().take(self.n).enumerate() {
            *o = w * cur;
            if k + 1 < self.n {
                let back = if k == 0 { 0.0 } else { r.off[k - 1] * prev };
                let next = ((p.y - r.diag[k]) * cur - back) * r.inv_off[k];
                (prev, cur) = (cur, next);
            }
        }
    }

    /// T_0(y) (module documentation), y off the interval ends.
    pub(crate) fn t0(&self, p: Point) -> f64 {
        self.t0_with(p, None)
    }

    /// [`JacobiFamily::t0`] with the weight's factors at y in (-1, 1), (1 - y)^a and
    /// (1 + y)^b as [`JacobiFamily::weight_factors`] gives them, where the caller has them
    /// (the same value to the bit).
    pub(crate) fn t0_with(&self, p: Point, factors: Option<(f64, f64)>) -> f64 {
        let (a, b, mass) = (self.a, self.b, self.mass);
        if a == 0.0 && b == 0.0 {
            return (p.omy.abs() / p.opy.abs()).ln() / PI;
        }
        let [own, swapped] = &self.ends;
        if p.inside() {
            // Tricomi's form needs a non-integer exponent at the end it expands about
            let w = factors.map(|(fa, fb)| fa * fb);
            if a != 0.0 && (p.y >= 0.0 || b == 0.0) {
                inside(a, b, mass, own, p, w)
            } else {
                -inside(b, a, mass, swapped, p.reflected(), w)
            }
        } else if p.omy < 0.0 {
            right_of(a, mass, own, p)
        } else {
            -right_of(b, mass, swapped, p.reflected())
        }
    }

    /// T_k(y), k < n (module documentation), y off the interval ends.
    #[cfg(test)]
    pub(crate) fn transforms(&self, p: Point, out: &mut [f64]) {
        self.transforms_with(p, None, out);
    }

    /// T_k(y), k < n (module documentation), y off the interval ends, with the weight's
    /// factors at y where the caller has them ([`JacobiFamily::t0_with`]).
    pub(crate) fn transforms_with(&self, p: Point, factors: Option<(f64, f64)>, out: &mut [f64]) {
        let out = &mut out[..self.n];
        if let Some(m) = self.head(p, factors, out) {
            let t0 = out[0];
            self.backward(&[(p, m, 0, t0)], out);
        }
    }

    /// T_0 at y into the first entry of `out`, and the rest of the transforms by the forward recurrence where
    /// it applies; else the start of the backward recurrence that gives them
    /// ([`JacobiFamily::miller_start`]).
    fn head(&self, p: Point, factors: Option<(f64, f64)>, out: &mut [f64]) -> Option<usize> {
        out[0] = self.t0_with(p, factors);
        if self.n == 1 {
            return None;
        }
        let m = self.miller_start(p);
        if m.is_none() {
            self.forward(p, out);
        }
        m
    }

    /// [`JacobiFamily::transforms_with`] at each of `points` with its `factors`, point i's
    /// transforms into out[i n..(i + 1) n]: the same values to the bit, with the backward
    /// recurrences of up to [`MILLER_LANES`] points run together (independent dependency
    /// chains, which the processor overlaps; one point's recurrence is a chain of dependent
    /// multiplications and subtractions).
    pub(crate) fn transforms_many(
        &self,
        points: &[Point],
        factors: &[Option<(f64, f64)>],
        out: &mut [f64],
    ) {
        let n = self.n;
        let mut lanes: Vec<(Point, usize, usize, f64)> = Vec::with_capacity(MILLER_LANES);
        for (i, (&p, &f)) in points.iter().zip(factors).enumerate() {
            let row = &mut out[i * n..(i + 1) * n];
            if let Some(m) = self.head(p, f, row) {
                lanes.push((p, m, i * n, row[0]));
                if lanes.len() == MILLER_LANES {
                    self.backward(&lanes, out);
                    lanes.clear();
                }
            }
        }
        if !lanes.is_empty() {
            self.backward(&lanes, out);
        }
    }

    /// Where the transforms at y come from Miller's backward recurrence: its start m (well
    /// above n), or None for the forward recurrence (inside, or k ln rho <= [`FORWARD_SPAN`]
    /// for every k < n).
    fn miller_start(&self, p: Point) -> Option<usize> {
        let n = self.n;
        let ln_rho = p.ln_rho();
        if p.inside() || (n as f64) * ln_rho <= FORWARD_SPAN {
            None
        } else {
            Some((n + (MILLER_SPAN / ln_rho).ceil() as usize).min(deepest(n, MILLER_SPAN)))
        }
    }

    /// The forward recurrence from T_0 in the first entry of `out`: T_1 from the
    /// inhomogeneous step, then T_(k+1) = A_k T_k - B_k T_(k-1) with the divisions by
    /// `off[k]` as multiplications (one
    /// fused step per degree on the dependency chain).
    fn forward(&self, p: Point, out: &mut [f64]) {
        let (n, r) = (self.n, &self.rec);
        out[1] = ((p.y - r.diag[0]) * out[0] + self.mass / PI) * r.inv_off[0];
        let (mut prev, mut cur) = (out[0], out[1]);
        for k in 1..n - 1 {
            let next = (p.y - r.diag[k]) * r.inv_off[k] * cur - r.off[k - 1] * r.inv_off[k] * prev;
            out[k + 1] = next;
            (prev, cur) = (cur, next);
        }
    }

    /// Miller's backward recurrence for each lane (point, start m, offset of its n
    /// transforms in `out`, its T_0): the minimal solution f_k, unnormalised, by the
    /// homogeneous recurrence backward from f_m = 0, f_(m-1) = 1,
    ///   f_(k-1) = ((y - diag_k) f_k - off_k f_(k+1)) / off_(k-1),
    /// rescaled before it can overflow (it grows like rho per step); then
    /// T_k = T_0 f_k / f_0. The lanes step through the degrees together, each from its own
    /// start.
    fn backward(&self, lanes: &[(Point, usize, usize, f64)], out: &mut [f64]) {
        #[cfg(target_arch = "x86_64")]
        if lanes.len() == MILLER_LANES && std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: the CPU has AVX (checked just above)
            unsafe { self.backward_avx(lanes, out) };
            return;
        }
        self.backward_scalar(lanes, out);
    }

    /// [`JacobiFamily::backward`] for [`MILLER_LANES`] = 4 lanes in one AVX register: the
    /// same operations in the same order per lane (no fused multiply-add), so the same
    /// values to the bit. A lane waits (f_k = 1, f_(k+1) = 0) until its own start; every
    /// start lies above n, so every lane is running where the transforms are stored.
    /// Measured on the 12 speed scenes (thread CPU time, the median over the scenes, against
    /// the lanes one after the other, alternated four times in one run): 0.097-0.098 to
    /// 0.095 ms at (1e-10, 1e-8), 0.121-0.123 to 0.116-0.118 ms at (1e-10, 1e-10); steel at
    /// mu = 0.3 1.148M to 1.108M instructions per answer (callgrind), kappa = 0.4 at mu = 1
    /// 1.408M to 1.354M; the 48 answers of the 12 speed scenes at four tolerances (c, both
    /// estimates, the tractions at five points) the same to the bit.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    unsafe fn backward_avx(&self, lanes: &[(Point, usize, usize, f64)], out: &mut [f64]) {
        use std::arch::x86_64::*;
        let (n, r) = (self.n, &self.rec);
        let at = [lanes[0].2, lanes[1].2, lanes[2].2, lanes[3].2];
        let starts = [lanes[0].1, lanes[1].1, lanes[2].1, lanes[3].1];
        debug_assert!(starts.iter().all(|&m| m > n));
        let y = _mm256_setr_pd(lanes[0].0.y, lanes[1].0.y, lanes[2].0.y, lanes[3].0.y);
        let m = _mm256_setr_pd(
            starts[0] as f64,
            starts[1] as f64,
            starts[2] as f64,
            starts[3] as f64,
        );
        let (sign, rescale) = (_mm256_set1_pd(-0.0), _mm256_set1_pd(RESCALE));
        let mut next = _mm256_setzero_pd();
        let mut cur = _mm256_set1_pd(1.0);
        let mut lane = [0.0; MILLER_LANES];
        let top = starts.iter().copied().max().unwrap_or(0);
        for k in (1..top).rev() {
            let (inv, diag, off) = (r.inv_off[k - 1], r.diag[k], r.off[k]);
            let running = _mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_set1_pd(k as f64), m);
            let a = _mm256_mul_pd(_mm256_sub_pd(y, _mm256_set1_pd(diag)), _mm256_set1_pd(inv));
            let prev = _mm256_sub_pd(
                _mm256_mul_pd(a, cur),
                _mm256_mul_pd(_mm256_set1_pd(off * inv), next),
            );
            next = _mm256_blendv_pd(next, cur, running);
            cur = _mm256_blendv_pd(cur, prev, running);
            if k - 1 < n {
                // SAFETY: `lane` holds four f64
                unsafe { _mm256_storeu_pd(lane.as_mut_ptr(), cur) };
                for j in 0..MILLER_LANES {
                    out[at[j] + k - 1] = lane[j];
                }
            }
            let big = _mm256_cmp_pd::<_CMP_GT_OQ>(_mm256_andnot_pd(sign, cur), rescale);
            if _mm256_movemask_pd(big) != 0 {
                let mut low = [0.0; MILLER_LANES];
                // SAFETY: `lane` and `low` hold four f64
                unsafe {
                    _mm256_storeu_pd(lane.as_mut_ptr(), cur);
                    _mm256_storeu_pd(low.as_mut_ptr(), next);
                }
                for j in 0..MILLER_LANES {
                    if lane[j].abs() > RESCALE {
                        low[j] /= RESCALE;
                        lane[j] /= RESCALE;
                        if k - 1 < n {
                            for v in &mut out[at[j] + k - 1..at[j] + n] {
                                *v /= RESCALE;
                            }
                        }
                    }
                }
                // SAFETY: as above
                unsafe {
                    cur = _mm256_loadu_pd(lane.as_ptr());
                    next = _mm256_loadu_pd(low.as_ptr());
                }
            }
        }
        // SAFETY: `lane` holds four f64
        unsafe { _mm256_storeu_pd(lane.as_mut_ptr(), cur) };
        self.normalise(lanes, &lane, out);
    }

    /// [`JacobiFamily::backward`], one lane after the other at each degree.
    fn backward_scalar(&self, lanes: &[(Point, usize, usize, f64)], out: &mut [f64]) {
        let (n, r) = (self.n, &self.rec);
        let mut next = [0.0; MILLER_LANES];
        let mut cur = [1.0; MILLER_LANES];
        let top = lanes.iter().map(|l| l.1).max().unwrap_or(0);
        for k in (1..top).rev() {
            let (inv, diag, off) = (r.inv_off[k - 1], r.diag[k], r.off[k]);
            for (j, &(p, m, at, _)) in lanes.iter().enumerate() {
                if k >= m {
                    continue;
                }
                let prev = (p.y - diag) * inv * cur[j] - off * inv * next[j];
                (next[j], cur[j]) = (cur[j], prev);
                if k - 1 < n {
                    out[at + k - 1] = cur[j];
                }
                if cur[j].abs() > RESCALE {
                    next[j] /= RESCALE;
                    cur[j] /= RESCALE;
                    if k - 1 < n {
                        for v in &mut out[at + k - 1..at + n] {
                            *v /= RESCALE;
                        }
                    }
                }
            }
        }
        self.normalise(lanes, &cur, out);
    }

    /// T_k = T_0 f_k / f_0 for each lane of [`JacobiFamily::backward`], from its unnormalised
    /// f_k in `out` and its f_0.
    fn normalise(&self, lanes: &[(Point, usize, usize, f64)], f0: &[f64], out: &mut [f64]) {
        for (&(_, _, at, t0), &f0) in lanes.iter().zip(f0) {
            let norm = t0 / f0;
            for v in &mut out[at + 1..at + self.n] {
                *v *= norm;
            }
            out[at] = t0;
        }
    }
}

/// Points whose backward recurrences [`JacobiFamily::transforms_many`] runs together.
const MILLER_LANES: usize = 4;

/// The transform at y of w(t) / (z - t), z outside [-1, 1], from the family's T_0 at y and at
/// z (J6).
pub(crate) fn pole_transform(t0_y: f64, y: Point, z: Point, t0_z: f64) -> f64 {
    (t0_y - t0_z) / z.minus(y)
}

/// x^e for x >= 0, with 0^0 = 1.
fn power(x: f64, e: f64) -> f64 {
    if e == 0.0 { 1.0 } else { x.powf(e) }
}

/// (J2) for |y| < 1, a != 0: cot(pi a) w(y) - K_0 2F1(1, -a-b; 1-a; z), z = (1 - y)/2,
/// K_0 = mu_0 (a + b + 1) / (2 pi a).
/// `w`: the weight at y where the caller has it (the product of its two factors, in either
/// order).
fn inside(a: f64, b: f64, mass: f64, ends: &Ends, p: Point, w: Option<f64>) -> f64 {
    if let Some(s) = &ends.symmetric {
        return s.t0(p);
    }
    let (z, omz) = (0.5 * p.omy, 0.5 * p.opy);
    let f = if a + b == 0.0 {
        1.0
    } else if z <= 0.5 {
        ends.series
            .get_or_init(|| SeriesRatios::new(1.0, -a - b, 1.0 - a))
            .sum(z)
    } else {
        let h = ends.inside.as_ref();
        let h = h.unwrap_or_else(|| panic!("T_0 inside: exponents ({a}, {b}) not covered"));
        let f = h.value(z, omz, omz.ln());
        if b == 0.0 && a > 0.0 {
            // 2F1(1, -a; 1-a; z) = -a Phi(z, 1, -a) = 1 - a z / (1 - a) 2F1(1, 1-a; 2-a; z),
            // the last with exponent c - a - b = 0 and positive parameters
            1.0 - a * z / (1.0 - a) * f
        } else if -a - b > 0.0 && b >= 0.0 {
            // c - a - b = b in [0, 1)
            f
        } else {
            // Euler: (1 - z)^b 2F1(-a, 1 + b; 1 - a; z), exponent -b in [0, 1)
            power(omz, b) * f
        }
    };
    let w = w.unwrap_or_else(|| power(p.omy, a) * power(p.opy, b));
    w / tan_pi(a) - mass * (a + b + 1.0) / (2.0 * PI * a) * f
}

/// Below this exponent, T_0 of the weight (1 - t^2)^g inside comes from (J2s): (J2)'s two
/// terms each grow like 1 / (pi g) and cancel to O(1), an absolute error of eps / g (2e-11
/// at g = 1e-5, measured against (J2s); they agree to 5e-15 at g = 0.04 and 1.5e-14 at 0.01).
pub(crate) const SYMMETRIC_SERIES_BELOW: f64 = 0.05;

/// The constants of (J2s) for the weight (1 - t^2)^g, 0 < g < [`SYMMETRIC_SERIES_BELOW`]:
/// with A = pi g cot(pi g), B = mu_0 (2g + 1) / 2 = e^beta,
///   pi T_0(y) = A L exprel(g L) - g gap(g) / g - (beta / g) exprel(beta) + 2 B S(z),
/// L = ln((1 - y)(1 + y)), z = (1 - y) / 2, gap(g) / g of `cauchy::gap_over` (principal),
///   beta / g = 2 ln 2 + g h(g) ([`symmetric_mass_tail`]), and
///   S(z) = sum_(n >= 1) (1 - 2g)_(n-1) / (1 - g)_n z^n = z / (1 - g) 2F1(1, 1 - 2g; 2 - g; z)
/// ((F - 1) / (-2g) for Tricomi's F = 2F1(1, -2g; 1 - g; z), whose every term but the first
/// carries the factor -2g). Every term is O(1) as g -> 0, where the sum tends to
/// ln((1 - y) / (1 + y)).
/// The stick zone's quotient family (`numerics::quotient`, (Q6)) builds on the same
/// constants and S.
#[derive(Clone, Debug)]
pub(crate) struct SmallSymmetric {
    pub(crate) g: f64,
    /// A, gap(g) / g, beta / g, beta, B.
    cot: f64,
    pub(crate) gap: f64,
    pub(crate) beta_over_g: f64,
    pub(crate) beta: f64,
    pub(crate) b: f64,
    series: SeriesRatios,
}

impl SmallSymmetric {
    pub(crate) fn new(g: f64) -> Self {
        let gap = gap_over(g, true);
        let beta_over_g = 2.0 * std::f64::consts::LN_2 + g * symmetric_mass_tail(g);
        let beta = beta_over_g * g;
        SmallSymmetric {
            g,
            cot: 1.0 - g * g * gap,
            gap,
            beta_over_g,
            beta,
            b: beta.exp(),
            series: SeriesRatios::new(1.0, 1.0 - 2.0 * g, 2.0 - g),
        }
    }

    /// S(z) for 0 <= z <= 1/2.
    pub(crate) fn s(&self, z: f64) -> f64 {
        z / (1.0 - self.g) * self.series.sum(z)
    }

    /// T_0(y) for 0 <= y < 1 (z <= 1/2).
    fn t0(&self, p: Point) -> f64 {
        let g = self.g;
        let s = self.s(0.5 * p.omy);
        let l = p.omy.ln() + p.opy.ln();
        (self.cot * l * exprel(g * l) - g * self.gap - self.beta_over_g * exprel(self.beta)
            + 2.0 * self.b * s)
            / PI
    }
}

/// (J3) for y > 1: -(mu_0 / pi) 2F1(1, b+1; a+b+2; zeta) / (1 + y), zeta = 2 / (1 + y).
fn right_of(a: f64, mass: f64, ends: &Ends, p: Point) -> f64 {
    let zeta = 2.0 / p.opy;
    let omz = -p.omy / p.opy;
    let ln_omz = (-p.omy).ln() - p.opy.ln();
    let f = ends.outside.value(zeta, omz, ln_omz);
    // for a < 0 Euler's (1 - zeta)^a 2F1(a+b+1, a+1; a+b+2; zeta), exponent -a in (0, 1)
    let f = if a >= 0.0 { f } else { (a * ln_omz).exp() * f };
    -mass / PI * f / p.opy
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::quadrature::{gauss_jacobi, graded_rule};

    /// T_k at a point outside by a Gauss-Jacobi rule (the integrand is smooth there).
    fn by_quadrature(a: f64, b: f64, n: usize, y: f64) -> Vec<f64> {
        let fam = JacobiFamily::new(a, b, n);
        let (t, w) = gauss_jacobi(200, a, b);
        let mut out = vec![0.0; n];
        let mut vals = vec![0.0; n];
        for (&t, &w) in t.iter().zip(&w) {
            // values() includes the weight; the rule's weights already carry it
            fam.values(Point::new(t), &mut vals);
            let wt = fam.weight(Point::new(t));
            for k in 0..n {
                out[k] += w * vals[k] / wt / (t - y) / PI;
            }
        }
        out
    }

    const WEIGHTS: [(f64, f64); 7] = [
        (0.0, 0.0),
        (0.3, 0.0),
        (0.3, 0.3),
        (-0.3, 0.3),
        (-0.3, 0.0),
        (0.3, -0.3),
        (0.0, -0.3),
    ];

    /// Four points' backward recurrences run together ([`JacobiFamily::backward_avx`] where
    /// the CPU has AVX) give each point's transforms to the bit as the point alone
    /// ([`JacobiFamily::backward_scalar`]): points at different distances, so that the lanes
    /// start at different degrees, and far points (y = 1e6 .. -1e8), whose recurrences grow
    /// past [`RESCALE`] at n = 24 (rho^n > 2^500) and are rescaled.
    #[test]
    fn four_lanes_are_each_lane_alone_to_the_bit() {
        for (a, b) in WEIGHTS {
            for n in [6, 17, 24] {
                let fam = JacobiFamily::new(a, b, n);
                for ys in [
                    [1.3, -2.5, 1e6, -30.0],
                    [1.05, 1.01, -1e8, 4.0],
                    [-1.2, -1.2, 1.5, 2e7],
                ] {
                    let points: Vec<Point> = ys.iter().map(|&y| Point::new(y)).collect();
                    let factors = vec![None; points.len()];
                    let mut together = vec![0.0; 4 * n];
                    fam.transforms_many(&points, &factors, &mut together);
                    for (i, p) in points.iter().enumerate() {
                        let mut alone = vec![0.0; n];
                        fam.transforms_many(&[*p], &[None], &mut alone);
                        for k in 0..n {
                            assert_eq!(
                                together[i * n + k].to_bits(),
                                alone[k].to_bits(),
                                "({a}, {b}) n = {n} y = {} k = {k}",
                                ys[i]
                            );
                        }
                    }
                }
            }
        }
    }

    /// Far from the interval (Gauss-Jacobi converges like rho^-400): every family and degree.
    #[test]
    fn outside_matches_quadrature() {
        for (a, b) in WEIGHTS {
            for y in [1.3, 2.5, 4.0, 30.0, -1.3, -2.5, -7.0] {
                let fam = JacobiFamily::new(a, b, 24);
                let mut t = vec![0.0; 24];
                fam.transforms(Point::new(y), &mut t);
                let q = by_quadrature(a, b, 24, y);
                for k in 0..24 {
                    let err = (t[k] - q[k]).abs() / q[0].abs();
                    assert!(
                        err < 1e-13,
                        "({a}, {b}) y = {y} k = {k}: {} vs {}",
                        t[k],
                        q[k]
                    );
                }
            }
        }
    }

    /// Inside: the principal value (1/pi) [int (f(t) - f(y)) / (t - y) dt + f(y) ln((1-y)/(1+y))],
    /// f = w p_k, the regular integral by a rule graded towards the end singularities and
    /// split at y (it omits 1e-15 of each end: up to ~1e-10 of the integral for a = -0.3).
    #[test]
    fn inside_matches_subtracted_quadrature() {
        for (a, b) in WEIGHTS {
            let n = 12;
            let fam = JacobiFamily::new(a, b, n);
            for y in [-0.9, -0.4, 0.0, 0.35, 0.8, 0.97] {
                let mut t = vec![0.0; n];
                fam.transforms(Point::new(y), &mut t);
                let mut fy = vec![0.0; n];
                fam.values(Point::new(y), &mut fy);
                let mut q: Vec<f64> = fy
                    .iter()
                    .map(|f| f * ((1.0 - y) / (1.0 + y)).ln())
                    .collect();
                let mut f = vec![0.0; n];
                // in the offsets from the ends (so that the grading reaches 1e-15 of each
                // piece, not 16 ulps of 1): v = 1 + t on [-1, y], u = 1 - t on [y, 1]
                let pieces = [(1.0 + y, false), (1.0 - y, true)];
                for (len, right) in pieces {
                    for (off, wt) in graded_rule(0.0, len, 0.15, 1e-15, 12) {
                        let (p, x) = if right {
                            (Point::offsets(off, 2.0 - off), 1.0 - off)
                        } else {
                            (Point::offsets(2.0 - off, off), off - 1.0)
                        };
                        fam.values(p, &mut f);
                        for k in 0..n {
                            q[k] += wt * (f[k] - fy[k]) / (x - y);
                        }
                    }
                }
                for k in 0..n {
                    let err = (t[k] - q[k] / PI).abs() / (1.0 + t[k].abs());
                    assert!(
                        err < 1e-9,
                        "({a}, {b}) y = {y} k = {k}: {} vs {}",
                        t[k],
                        q[k] / PI
                    );
                }
            }
        }
    }

    /// The weight (1/2, 1/2): p_k = U_k, and T_k = -T_{k+1}(y) (Chebyshev, first kind) inside,
    /// -(y - sqrt(y^2 - 1))^(k+1) for y > 1; at points next to the ends too.
    #[test]
    fn chebyshev_second_kind_closed_form() {
        let n = 30;
        let fam = JacobiFamily::new(0.5, 0.5, n);
        let mut t = vec![0.0; n];
        for y in [-0.999999, -0.5, 0.1, 0.7, 0.9999999] {
            fam.transforms(Point::new(y), &mut t);
            let th = y.acos();
            for (k, tk) in t.iter().enumerate() {
                let exact = -((k + 1) as f64 * th).cos();
                assert!(
                    (tk - exact).abs() < 1e-12,
                    "y = {y} k = {k}: {tk} vs {exact}"
                );
            }
        }
        // (1e6: Miller's unnormalised recurrence grows past 2^500 there and is rescaled)
        for d in [1e-12, 1e-8, 1e-4, 0.01, 0.3, 2.0, 50.0, 1e6] {
            let p = Point::offsets(-d, 2.0 + d);
            fam.transforms(p, &mut t);
            let r = 1.0 / (1.0 + d + (d * (2.0 + d)).sqrt());
            for (k, tk) in t.iter().enumerate() {
                let exact = -r.powi(k as i32 + 1);
                let err = (tk - exact).abs() / exact.abs();
                assert!(err < 1e-12, "d = {d} k = {k}: {tk} vs {exact}");
            }
            // and the mirror point, T(-y) = (-1)^(k+1) T(y) for the symmetric weight
            let mut m = vec![0.0; n];
            fam.transforms(p.reflected(), &mut m);
            for k in 0..n {
                let sign = if k % 2 == 0 { -1.0 } else { 1.0 };
                assert!(
                    (m[k] - sign * t[k]).abs() <= 1e-12 * t[k].abs(),
                    "mirror d = {d} k = {k}"
                );
            }
        }
    }

    /// Next to the ends (1 -+ y down to 1e-12, inside and out) T_0 of every family agrees with
    /// the one-sided closed forms of `numerics::cauchy` where those apply (w = 1, (1 - t)^e,
    /// (1 + t)^e), and the two-sided ones are continuous in the offsets' rounding.
    #[test]
    fn t0_next_to_the_ends_matches_the_one_sided_forms() {
        use crate::numerics::cauchy::end_cauchy;
        for e in [0.3, -0.3, -0.45] {
            let left = JacobiFamily::new(0.0, e, 1);
            let right = JacobiFamily::new(e, 0.0, 1);
            for d in [1e-12, 1e-8, 1e-4, 0.05] {
                // next to the end whose offset end_cauchy takes (it forms 2 - z itself, so
                // the other end is out of its reach), inside (+d) and outside (-d)
                for off in [d, -d] {
                    let p = Point::offsets(2.0 - off, off);
                    let exact = end_cauchy(e, p.opy) / PI;
                    let got = left.t0(p);
                    assert!(
                        (got - exact).abs() < 1e-13 * (1.0 + exact.abs()),
                        "(0, {e}) at 1 + y = {off}: {got} vs {exact}"
                    );
                    let exact = -end_cauchy(e, p.opy) / PI;
                    let got = right.t0(p.reflected());
                    assert!(
                        (got - exact).abs() < 1e-13 * (1.0 + exact.abs()),
                        "({e}, 0) at 1 - y = {off}: {got} vs {exact}"
                    );
                }
            }
        }
        // the two-sided weights agree with themselves across the point y = 0 where the
        // evaluation switches ends
        for (a, b) in [(0.3, 0.3), (-0.3, 0.3), (0.3, -0.3), (-0.3, 0.0)] {
            let fam = JacobiFamily::new(a, b, 1);
            let (l, r) = (fam.t0(Point::new(-1e-15)), fam.t0(Point::new(1e-15)));
            assert!((l - r).abs() < 1e-13, "({a}, {b}): {l} vs {r}");
        }
    }

    /// z - y from the offsets to full relative accuracy where z and y lie next to the same
    /// end: a stick point 1e-13 inside x = 1 and a pole 1e-14 beyond it (in rounded y values
    /// the difference 1.1e-13 keeps two digits).
    #[test]
    fn pole_distance_from_the_offsets() {
        for (d, e) in [(1e-13, 1e-14), (3e-16, 7e-17), (0.25, 1e-9)] {
            for end in [1.0, -1.0] {
                let (y, z) = (Point::offsets(d, 2.0 - d), Point::offsets(-e, 2.0 + e));
                let (y, z) = if end > 0.0 {
                    (y, z)
                } else {
                    (y.reflected(), z.reflected())
                };
                let exact = end * (d + e);
                let got = z.minus(y);
                assert!(
                    (got - exact).abs() <= 4.0 * f64::EPSILON * exact.abs(),
                    "d = {d}, e = {e}, end {end}: {got:e} vs {exact:e}"
                );
            }
        }
    }

    /// A pole's transform by the divided difference (J6) against quadrature outside.
    #[test]
    fn pole_transform_matches_quadrature() {
        for (a, b) in WEIGHTS {
            let fam = JacobiFamily::new(a, b, 1);
            let (t, w) = gauss_jacobi(300, a, b);
            for z in [1.05, 1.7, -1.2, -4.0] {
                let zp = Point::new(z);
                let t0z = fam.t0(zp);
                for y in [1.5, -1.5, 3.0] {
                    if (y - z).abs() < 0.1 {
                        continue;
                    }
                    let exact: f64 = t
                        .iter()
                        .zip(&w)
                        .map(|(&t, &w)| w / (z - t) / (t - y) / PI)
                        .sum();
                    let yp = Point::new(y);
                    let got = pole_transform(fam.t0(yp), yp, zp, t0z);
                    assert!(
                        (got - exact).abs() < 1e-12 * exact.abs(),
                        "({a},{b}) z={z} y={y}: {got} vs {exact}"
                    );
                }
            }
        }
    }

    /// (J2s) against mpmath (40 digits: the subtracted principal value by tanh-sinh
    /// quadrature split at y) for the weight (1 - t^2)^g at small g, where (J2) itself loses
    /// eps / g; y = 1 - 2^-20 and -1 + 2^-17 with their offsets exact.
    #[test]
    fn small_symmetric_exponents_match_mpmath() {
        const T0: [(f64, f64, f64); 20] = [
            (1e-06, 0.3, -0.19704656078483548),
            (1e-06, 0.9, -0.9372443501740632),
            (1e-06, 0.9999990463256836, -4.633320676596753),
            (1e-06, -0.5, 0.34969957091762927),
            (1e-06, -0.9999923706054688, 3.971420842579041),
            (0.0001, 0.3, -0.1970723798466067),
            (0.0001, 0.9, -0.9372754068459149),
            (0.0001, 0.9999990463256836, -4.630671033375669),
            (0.0001, -0.5, 0.34974098451875596),
            (0.0001, -0.9999923706054688, 3.9695656005397386),
            (0.01, 0.3, -0.1996394147030792),
            (0.01, 0.9, -0.9402474917902148),
            (0.01, 0.9999990463256836, -4.376053877958824),
            (0.01, -0.5, 0.35385055439308105),
            (0.01, -0.9999923706054688, 3.7899394471723085),
            (0.04, 0.3, -0.20724401658914493),
            (0.04, 0.9, -0.9477202379964721),
            (0.04, 0.9999990463256836, -3.7163278234660315),
            (0.04, -0.5, 0.3659310152522686),
            (0.04, -0.9999923706054688, 3.310904897457804),
        ];
        for (g, y, want) in T0 {
            let fam = JacobiFamily::new(g, g, 1);
            let p = if y > 0.99 {
                Point::offsets(2f64.powi(-20), 2.0 - 2f64.powi(-20))
            } else if y < -0.99 {
                Point::offsets(2.0 - 2f64.powi(-17), 2f64.powi(-17))
            } else {
                Point::new(y)
            };
            let got = fam.t0(p);
            assert!(
                (got - want).abs() <= 2e-15 * (1.0 + want.abs()),
                "g = {g}, y = {y}: {got} vs {want}"
            );
        }
    }
}
