//! The bonded punch's fundamental function and the finite Hilbert transforms, over the stick
//! zone [-c, c] alone, of its products with powers of x (docs/theory_spectral.md (X1)-(X4)):
//!
//!   X(x) = (1 - x)^a (1 + x)^conj(a),   a = -1/2 - i eps,   eps = artanh(b) / pi,
//!
//! the solution of H[f] = -i b f on (-1, 1) (f = p + i q of a punch stuck over its whole
//! width; cot(pi a) = i b). On the whole interval H[X x^k] = -i b X x^k minus a polynomial
//! of the moments M_j = int X t^j (X2); the slip zones' parts are subtracted in closed form:
//! on [c, 1], X x^k = (1 - x)^a sum_m g_(k,m) (1 - x)^m (a Taylor series of
//! (1 + x)^conj(a) x^k about x = 1, ratio (1 - c) / 2 per term), and each power's transform
//! over [c, 1] is an incomplete beta function of complex exponent (X3); [-1, -c] by the
//! reflection X(-x) = conj(X(x)) (X4).

use std::f64::consts::PI;

use faer::complex::Complex;

use super::special::digamma_complex;

type C64 = Complex<f64>;

/// Euler's constant.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Relative size of the first term left out of every series.
const SERIES_TOL: f64 = 1e-18;

/// The transforms' regimes in Z = (1 - c) / (1 - y) (X3): the power series in Z below,
/// the expansion about Z = 1 between, the series in 1/Z above (each converging at least
/// like 2/3 per term).
const Z_SERIES: f64 = 0.5;
const Z_INVERSE: f64 = 1.5;

/// Most powers x^k of one [`Bonded`] (callers size their buffers by it).
pub(crate) const MAX_DEGREE: usize = 8;

/// Most terms of any series (ratio 2/3: 2/3^110 < 1e-19).
const MAX_TERMS: usize = 110;

/// X and its stick-zone transforms for one coupling, stick edge and number of powers.
#[derive(Clone, Debug)]
pub(crate) struct Bonded {
    eps: f64,
    /// b = tanh(pi eps).
    b: f64,
    c: f64,
    w: f64,
    /// Powers x^k, k < degree.
    degree: usize,
    /// M_j = int_{-1}^{1} X t^j dt, j < degree.
    moments: Vec<C64>,
    /// g_(k, m): X x^k = (1 - x)^a sum_m g_(k,m) (1 - x)^m on [c, 1], every row `powers`
    /// long (zeros past its own terms).
    taylor: Vec<Vec<C64>>,
    /// Length of the Taylor rows.
    powers: usize,
    /// -(psi(a + m + 1) + gamma) (the expansion about Z = 1 of each power).
    psi: Vec<C64>,
    /// 1 / (a + i) for i from -MAX_TERMS on (the series' coefficients).
    recips: Vec<C64>,
    /// (1 - c)^(a + m).
    w_pow: Vec<C64>,
}

/// A point's quantities shared by the powers' transforms.
struct Offsets {
    omy: f64,
    z: f64,
    u: f64,
    ln_u: f64,
    /// (1 - y)^a, in the expansion about Z = 1 only.
    pow_a: C64,
    inside: bool,
}

impl Bonded {
    /// X for the reduced coupling b (0 < b < 1), the stick zone [-c, c] (1 - c = w) and the
    /// powers x^k, k < degree.
    pub(crate) fn new(b: f64, c: f64, w: f64, degree: usize) -> Self {
        assert!(degree <= MAX_DEGREE, "at most {MAX_DEGREE} powers");
        let eps = b.atanh() / PI;
        let a_bar = C64::new(-0.5, eps);
        // moments: (j + 1) M_(j+1) = 2 i eps M_j + j M_(j-1), M_0 = pi / cosh(pi eps)
        let mut moments = Vec::with_capacity(degree);
        let m0 = C64::new(PI / (PI * eps).cosh(), 0.0);
        for j in 0..degree {
            let m = match j {
                0 => m0,
                1 => m0 * C64::new(0.0, 2.0 * eps),
                _ => {
                    let i = (j - 1) as f64;
                    (moments[j - 1] * C64::new(0.0, 2.0 * eps) + moments[j - 2] * i) / (i + 1.0)
                }
            };
            moments.push(m);
        }
        // (1 + x)^conj(a) = 2^conj(a) sum_j binom(conj(a), j) (-h/2)^j, h = 1 - x
        let terms = ((SERIES_TOL.ln() / (0.5 * w).ln()).ceil() as usize + 1).clamp(2, MAX_TERMS);
        let mut e = Vec::with_capacity(terms);
        e.push((a_bar * std::f64::consts::LN_2).exp());
        for j in 1..terms {
            let prev = e[j - 1];
            e.push(prev * (a_bar - (j - 1) as f64) * (-0.5 / j as f64));
        }
        let taylor: Vec<Vec<C64>> = (0..degree)
            .map(|k| {
                // times x^k = (1 - h)^k
                let mut row = vec![C64::new(0.0, 0.0); terms + degree];
                let mut binom = 1.0;
                for i in 0..=k {
                    let coef = if i % 2 == 0 { binom } else { -binom };
                    for (j, ej) in e.iter().enumerate() {
                        row[i + j] += ej * coef;
                    }
                    binom *= (k - i) as f64 / (i + 1) as f64;
                }
                row
            })
            .collect();
        let a = C64::new(-0.5, -eps);
        let psi = (0..terms + degree)
            .map(|m| -(digamma_complex(a + (m + 1) as f64) + EULER_GAMMA))
            .collect();
        let recips = (0..2 * MAX_TERMS + terms + degree + 2)
            .map(|i| (a + (i as f64 - MAX_TERMS as f64)).inv())
            .collect();
        let w_pow = (0..terms + degree + 1)
            .map(|m| ((a + m as f64) * w.ln()).exp())
            .collect();
        Bonded {
            powers: terms + degree,
            eps,
            b: (PI * eps).tanh(),
            c,
            w,
            degree,
            moments,
            taylor,
            psi,
            recips,
            w_pow,
        }
    }

    /// Number of powers.
    pub(crate) fn degree(&self) -> usize {
        self.degree
    }

    /// X(x) from the offsets 1 - x and 1 + x.
    pub(crate) fn value(&self, omx: f64, opx: f64) -> C64 {
        let phase = self.eps * (opx / omx).ln();
        C64::from_polar(1.0 / (omx * opx).sqrt(), phase)
    }

    /// X(x) x^k, k < degree, at a point of the stick zone.
    pub(crate) fn values(&self, x: f64, omx: f64, out: &mut [C64]) {
        let mut v = self.value(omx, 1.0 + x);
        for o in out.iter_mut().take(self.degree) {
            *o = v;
            v *= x;
        }
    }

    /// The transform over [c, 1] of (1 - x)^(a + m) at the point `at`: without its
    /// singular part -cot(pi a) (1 - y)^(a + m) when the point lies inside (X3).
    fn power_transform(&self, m: usize, at: &Offsets) -> C64 {
        let tol2 = SERIES_TOL * SERIES_TOL;
        let z = at.z;
        if z <= Z_SERIES {
            // -(1/pi) w^(beta+1) / (1 - y) sum_n Z^n / (n + beta + 1)
            let (mut sum, mut zn) = (C64::new(0.0, 0.0), 1.0);
            for n in 0..MAX_TERMS {
                let t = self.recip(m as isize + n as isize + 1) * zn;
                sum += t;
                if t.norm_sqr() < tol2 * sum.norm_sqr() {
                    break;
                }
                zn *= z;
            }
            -self.w_pow[m + 1] / at.omy * sum / PI
        } else if z >= Z_INVERSE {
            // (1/pi) w^beta sum_n Z^-n / (beta - n)
            let (mut sum, mut zn) = (C64::new(0.0, 0.0), 1.0);
            let iz = 1.0 / z;
            for n in 0..MAX_TERMS {
                let t = self.recip(m as isize - n as isize) * zn;
                sum += t;
                if t.norm_sqr() < tol2 * sum.norm_sqr() {
                    break;
                }
                zn *= iz;
            }
            self.w_pow[m] * sum / PI
        } else {
            // -(1/pi) (1 - y)^beta [F(1) - sum_k binom(beta, k) (-u)^k / k - ln|u|],
            // u = 1 - Z = (c - y) / (1 - y)
            let beta = C64::new(m as f64 - 0.5, -self.eps);
            let u = at.u;
            let (mut sum, mut d, mut un) = (C64::new(0.0, 0.0), C64::new(1.0, 0.0), 1.0);
            for k in 1..MAX_TERMS {
                d = d * (k as f64 - 1.0 - beta) * (1.0 / k as f64);
                un *= u;
                let t = d * (un / k as f64);
                sum += t;
                if t.norm_sqr() < tol2 * sum.norm_sqr().max(1.0) {
                    break;
                }
            }
            let pow = at.pow_a * at.omy.powi(m as i32);
            let full = -pow * (self.psi[m] - sum - at.ln_u) / PI;
            if at.inside {
                // inside: remove -cot(pi beta) (1 - y)^beta, cot(pi beta) = i b
                full + pow * C64::new(0.0, self.b)
            } else {
                full
            }
        }
    }

    /// The full finite Hilbert transforms over [c, 1] of the powers (1 - x)^(a + m),
    /// m < `out.len()` (at most the powers the Taylor rows carry: `degree` plus the terms
    /// for w), at the point y given by 1 - y > 0 and c - y (inside the zone when negative,
    /// where the singular part -cot(pi a) (1 - y)^(a + m) = -i b (1 - y)^(a + m) is
    /// included). Only w = 1 - c enters, so c itself may be rounded.
    pub(crate) fn end_powers(&self, omy: f64, cmy: f64, out: &mut [C64]) {
        assert!(out.len() <= self.powers, "at most {} powers", self.powers);
        let z = self.w / omy;
        let u = cmy / omy;
        let middle = z > Z_SERIES && z < Z_INVERSE;
        let at = Offsets {
            omy,
            z,
            u,
            ln_u: if middle { u.abs().ln() } else { 0.0 },
            pow_a: if middle {
                (C64::new(-0.5, -self.eps) * omy.ln()).exp()
            } else {
                C64::new(0.0, 0.0)
            },
            inside: cmy < 0.0,
        };
        let a = C64::new(-0.5, -self.eps);
        for (m, o) in out.iter_mut().enumerate() {
            *o = self.power_transform(m, &at);
            if at.inside {
                *o -= ((a + m as f64) * omy.ln()).exp() * C64::new(0.0, self.b);
            }
        }
    }

    /// Number of powers [`Bonded::end_powers`] can give.
    pub(crate) fn powers(&self) -> usize {
        self.powers
    }

    /// 1 / (a + i).
    fn recip(&self, i: isize) -> C64 {
        self.recips[(i + MAX_TERMS as isize) as usize]
    }

    /// H_[c,1][X x^k](y) for every k (without the singular part inside the zone), y given
    /// by 1 - y > 0 and c - y (< 0 inside the zone).
    fn slip_part(&self, omy: f64, cmy: f64, out: &mut [C64]) {
        out.iter_mut().for_each(|o| *o = C64::new(0.0, 0.0));
        let z = self.w / omy;
        let u = cmy / omy;
        let at = Offsets {
            omy,
            z,
            u,
            ln_u: if z > Z_SERIES && z < Z_INVERSE {
                u.abs().ln()
            } else {
                0.0
            },
            pow_a: if z > Z_SERIES && z < Z_INVERSE {
                (C64::new(-0.5, -self.eps) * omy.ln()).exp()
            } else {
                C64::new(0.0, 0.0)
            },
            inside: cmy < 0.0,
        };
        for m in 0..self.powers {
            let h = self.power_transform(m, &at);
            for (o, row) in out.iter_mut().zip(&self.taylor) {
                *o += row[m] * h;
            }
        }
    }

    /// H_[-c,c][X x^k](y), k < degree, at 0 <= y < 1 given with 1 - y and y - c (!= 0).
    pub(crate) fn transforms(&self, y: f64, omy: f64, ymc: f64, out: &mut [C64], buf: &mut [C64]) {
        let n = self.degree;
        let (own, mirror) = buf.split_at_mut(n);
        self.slip_part(omy, -ymc, own);
        // the reflection: H_[-1,-c][F_k](y) = -(-1)^k conj(H_[c,1][F_k](-y))
        self.slip_part(1.0 + y, self.c + y, &mut mirror[..n]);
        let inside = ymc < 0.0;
        let mut xv = if inside {
            self.value(omy, 1.0 + y) * C64::new(0.0, -self.b)
        } else {
            C64::new(0.0, 0.0)
        };
        for k in 0..n {
            // the whole interval: -i b X y^k - (1/pi) sum_j y^(k-1-j) M_j
            let mut poly = C64::new(0.0, 0.0);
            for j in 0..k {
                poly = poly * y + self.moments[j];
            }
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            out[k] = xv - poly / PI - own[k] + mirror[k].conj() * sign;
            xv *= y;
        }
    }

    /// Length of the scratch buffer of [`Bonded::transforms`].
    pub(crate) fn scratch_len(&self) -> usize {
        2 * self.degree
    }

    /// int_{-c}^{c} X x^k dx, k < degree.
    pub(crate) fn integrals(&self) -> Vec<C64> {
        let a = C64::new(-0.5, -self.eps);
        (0..self.degree)
            .map(|k| {
                let slip: C64 = self.taylor[k]
                    .iter()
                    .enumerate()
                    .map(|(m, g)| {
                        g * ((a + (m + 1) as f64) * self.w.ln()).exp() / (a + (m + 1) as f64)
                    })
                    .sum();
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                self.moments[k] - slip - slip.conj() * sign
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::quadrature::gauss_legendre;

    /// int_lo^hi f by Gauss-Legendre on panels graded geometrically towards both ends.
    fn graded(f: &dyn Fn(f64, f64, f64) -> C64, lo: f64, hi: f64) -> C64 {
        // f(x, x - lo, hi - x)
        let (nodes, weights) = gauss_legendre(30);
        let mut sum = C64::new(0.0, 0.0);
        let len = hi - lo;
        let mut edges = vec![0.0];
        let mut d = 1e-15;
        while d < 0.25 {
            edges.push(d);
            d *= 4.0;
        }
        edges.push(0.5);
        for side in [0, 1] {
            for w in edges.windows(2) {
                let (a, b) = (w[0] * len, w[1] * len);
                for (t, wt) in nodes.iter().zip(&weights) {
                    let s = a + (b - a) * 0.5 * (t + 1.0);
                    let v = if side == 0 {
                        f(lo + s, s, len - s)
                    } else {
                        f(hi - s, len - s, s)
                    };
                    sum += v * (wt * 0.5 * (b - a));
                }
            }
        }
        sum
    }

    /// The transforms against quadrature of the Cauchy integral (the subtracted form at
    /// stick points), at stick and slip points, for thin and wide slip zones.
    #[test]
    fn transforms_match_quadrature() {
        for (b, c) in [(0.3, 0.7), (0.2857, 1.0 - 1e-3), (0.6, 0.2), (0.1, 0.95)] {
            let w = 1.0 - c;
            let bx = Bonded::new(b, c, w, 5);
            for y in [
                0.0,
                0.3 * c,
                0.9 * c,
                c - 1e-3 * w,
                c + 0.3 * w,
                c + 0.9 * w,
                1.0 - 1e-3 * w,
            ] {
                let (omy, ymc) = (1.0 - y, y - c);
                let mut out = vec![C64::new(0.0, 0.0); 5];
                let mut buf = vec![C64::new(0.0, 0.0); bx.scratch_len()];
                bx.transforms(y, omy, ymc, &mut out, &mut buf);
                for (k, got) in out.iter().enumerate() {
                    let f = |t: f64| bx.value(1.0 - t, 1.0 + t) * t.powi(k as i32);
                    let want = if ymc < 0.0 {
                        let fy = f(y);
                        let g = |t: f64, _: f64, _: f64| {
                            if t == y {
                                C64::new(0.0, 0.0)
                            } else {
                                (f(t) - fy) / (y - t)
                            }
                        };
                        (graded(&g, -c, y) + graded(&g, y, c) + fy * ((c + y) / (c - y)).ln()) / PI
                    } else {
                        graded(&|t, _, _| f(t) / (y - t), -c, c) / PI
                    };
                    let scale = want.norm().max(1.0);
                    assert!(
                        (got - want).norm() < 1e-11 * scale,
                        "b {b} c {c} y {y} k {k}: {got} vs {want}"
                    );
                }
            }
            let ints = bx.integrals();
            for (k, got) in ints.iter().enumerate() {
                let want = graded(
                    &|t, _, _| bx.value(1.0 - t, 1.0 + t) * t.powi(k as i32),
                    -c,
                    c,
                );
                assert!(
                    (got - want).norm() < 1e-12 * want.norm().max(1.0),
                    "{k}: {got} {want}"
                );
            }
        }
    }

    /// int_0^top h(s) ds for h ~ s^(-1/2) at 0, as int_0^sqrt(top) h(v^2) 2 v dv (bounded).
    fn from_zero(h: &dyn Fn(f64) -> C64, top: f64) -> C64 {
        graded(&|v, _, _| h(v * v) * (2.0 * v), 0.0, top.sqrt())
    }

    /// The full transforms of the powers over a thin end zone [c, 1] (w = 1 - c), the
    /// corner zone's columns (docs/theory_tangential.md section 20), against quadrature of
    /// the Cauchy integral, at points inside (all three regimes of Z = w / (1 - y)) and
    /// outside.
    #[test]
    fn end_powers_match_quadrature() {
        for (b, w) in [(0.9, 1e-2), (0.2857, 6e-9)] {
            let bx = Bonded::new(b, 1.0 - w, w, MAX_DEGREE);
            let n = 10.min(bx.powers());
            let a = C64::new(-0.5, -bx.eps);
            for omy in [
                1e-4 * w,
                0.3 * w,
                0.6 * w,
                0.9 * w,
                1.2 * w,
                1.9 * w,
                3.0 * w,
                50.0 * w,
            ] {
                let cmy = omy - w;
                let mut out = vec![C64::new(0.0, 0.0); n];
                bx.end_powers(omy, cmy, &mut out);
                for (m, got) in out.iter().enumerate() {
                    // in s = 1 - t on (0, w): (1/pi) int s^(a + m) / (s - omy) ds
                    let f = |s: f64| ((a + m as f64) * s.ln()).exp();
                    let want = if cmy < 0.0 {
                        let fy = f(omy);
                        let g = |s: f64, _: f64, _: f64| {
                            if s == omy {
                                C64::new(0.0, 0.0)
                            } else {
                                (f(s) - fy) / (s - omy)
                            }
                        };
                        (from_zero(&|s| g(s, 0.0, 0.0), omy)
                            + graded(&g, omy, w)
                            + fy * ((w - omy) / omy).ln())
                            / PI
                    } else {
                        from_zero(&|s| f(s) / (s - omy), w) / PI
                    };
                    let scale = want.norm().max(f(omy).norm());
                    assert!(
                        (got - want).norm() < 1e-10 * scale,
                        "b {b} w {w} 1 - y = {omy:e} m {m}: {got} vs {want}"
                    );
                }
            }
        }
    }
}
