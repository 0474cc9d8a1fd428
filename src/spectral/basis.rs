//! The global bases of the two zones of the half problem (docs/theory_spectral.md, (B1)-(B4)),
//! each with its values and its Cauchy transform at any point, in closed form
//! ([`crate::numerics::jacobi_transform`]).
//!
//! Stick zone [-c, c], tau = x / c:
//! - p: even orthonormal Legendre polynomials, and the even pole pairs
//!   1 / (Z - tau) + 1 / (Z + tau), Z = (1 + zeta_j) / c (B1);
//! - q: odd Legendre polynomials, (1 - tau^2)^g times odd orthonormal P^(g,g), and the odd pole
//!   pairs 1 / (Z - tau) - 1 / (Z + tau), alone and, in thin slip zones, times (1 - tau^2)^g
//!   (B2); below `system::QUOTIENT_BELOW` the weight ((1 - tau^2)^g - 1) / g with the odd
//!   orthonormal Legendre polynomials in place of (1 - tau^2)^g P^(g,g) (the same span).
//!
//! Slip zone [c, 1], s = (2 x - c - 1) / (1 - c): p = (1 - s)^-g P^(-g,0) and
//! (1 - s)^-g (1 + s)^g P^(-g,g), with poles 1 / (S_j - s), S_j = s(-(c + eta_j)), in both
//! weights; q = mu p there (B3).

use crate::numerics::jacobi_transform::{JacobiFamily, Point, pole_transform};
use crate::numerics::quotient::QuotientFamily;

/// A block's weighted polynomials: a Jacobi family, or below [`super::system::QUOTIENT_BELOW`]
/// a zone's difference-quotient family (docs/theory_spectral.md, section 7).
#[derive(Clone, Debug)]
pub(crate) enum Family {
    Jacobi(JacobiFamily),
    Quotient(QuotientFamily),
}

impl Family {
    fn len(&self) -> usize {
        match self {
            Family::Jacobi(f) => f.len(),
            Family::Quotient(f) => f.len(),
        }
    }

    fn weight(&self, y: Point) -> f64 {
        match self {
            Family::Jacobi(f) => f.weight(y),
            Family::Quotient(f) => f.weight(y),
        }
    }

    fn values_weighted(&self, y: Point, w: f64, out: &mut [f64]) {
        match self {
            Family::Jacobi(f) => f.values_weighted(y, w, out),
            Family::Quotient(f) => f.values_weighted(y, w, out),
        }
    }

    fn t0(&self, y: Point) -> f64 {
        match self {
            Family::Jacobi(f) => f.t0(y),
            Family::Quotient(f) => f.t0(y),
        }
    }

    fn transforms(&self, y: Point, out: &mut [f64]) {
        match self {
            Family::Jacobi(f) => f.transforms_with(y, None, out),
            Family::Quotient(f) => f.transforms(y, out),
        }
    }

    /// The weight at y from its factors ([`Block::factors`]): their product for a Jacobi
    /// family (as its own weight computes it), the quotient family's own weight.
    fn weight_from(&self, y: Point, factors: Option<(f64, f64)>) -> f64 {
        match (self, factors) {
            (Family::Jacobi(_), Some((fa, fb))) => fa * fb,
            _ => self.weight(y),
        }
    }

    fn same_as(&self, other: &Family) -> bool {
        match (self, other) {
            (Family::Jacobi(a), Family::Jacobi(b)) => a.same_as(b),
            (Family::Quotient(a), Family::Quotient(b)) => a.same_as(b),
            _ => false,
        }
    }

    /// int w p_k.
    fn moment(&self, k: usize) -> f64 {
        match self {
            Family::Jacobi(f) => {
                if k == 0 {
                    f.mass()
                } else {
                    0.0
                }
            }
            Family::Quotient(f) => f.moment(k),
        }
    }

    /// The weight's two factors: (1 - y)^a and (1 + y)^b of a Jacobi family, (1 - y)^-g and
    /// ((1 + y)^g - 1) / g of the quotient family.
    fn weight_factors(&self, y: Point) -> (f64, f64) {
        match self {
            Family::Jacobi(f) => f.weight_factors(y),
            Family::Quotient(f) => f.factors(y),
        }
    }
}

impl From<JacobiFamily> for Family {
    fn from(f: JacobiFamily) -> Self {
        Family::Jacobi(f)
    }
}

impl From<QuotientFamily> for Family {
    fn from(f: QuotientFamily) -> Self {
        Family::Quotient(f)
    }
}

/// One weight's polynomials and poles: columns `k` of the family taken (all, or one parity),
/// then the poles, each a pair at +Z and -Z with the pair's sign (+1 even, -1 odd) or a single
/// pole (sign 0).
#[derive(Clone, Debug)]
pub(crate) struct Block {
    family: Family,
    /// The degrees used (all k < n, or the even or odd ones).
    degrees: Vec<usize>,
    /// The poles Z (outside [-1, 1]) and T_0 there; for pairs also T_0(-Z).
    poles: Vec<(Point, f64, f64)>,
    /// +1: even pairs, -1: odd pairs, 0: single poles.
    pair: f64,
}

impl Block {
    /// A block of `family`'s `degrees` and the poles `z` (pairs with sign `pair`, or single
    /// poles for pair = 0).
    pub(crate) fn new(
        family: impl Into<Family>,
        degrees: Vec<usize>,
        z: &[Point],
        pair: f64,
    ) -> Self {
        let family = family.into();
        let poles = z
            .iter()
            .map(|&z| {
                let minus = if pair != 0.0 {
                    family.t0(z.reflected())
                } else {
                    0.0
                };
                (z, family.t0(z), minus)
            })
            .collect();
        Block {
            family,
            degrees,
            poles,
            pair,
        }
    }

    /// Number of columns.
    pub(crate) fn len(&self) -> usize {
        self.degrees.len() + self.poles.len()
    }

    /// The columns' values at y in (-1, 1) into out[..len].
    pub(crate) fn values(&self, y: Point, buf: &mut [f64], out: &mut [f64]) {
        self.values_weighted(y, self.family.weight(y), buf, out);
    }

    /// [`Block::values`] with the weight's factors at y given ([`Block::factors`]).
    pub(crate) fn values_with(
        &self,
        y: Point,
        factors: Option<(f64, f64)>,
        buf: &mut [f64],
        out: &mut [f64],
    ) {
        self.values_weighted(y, self.family.weight_from(y, factors), buf, out);
    }

    /// A Jacobi family's weight factors at y in (-1, 1), (1 - y)^a and (1 + y)^b, shared by
    /// its values and its transform at the same point (and, given, by another block with the
    /// same exponent a); None for the quotient family.
    pub(crate) fn factors(&self, y: Point, first: Option<f64>) -> Option<(f64, f64)> {
        match &self.family {
            Family::Jacobi(f) => {
                let (fa, fb) = match first {
                    Some(fa) => (fa, f.weight_factors(y).1),
                    None => f.weight_factors(y),
                };
                Some((fa, fb))
            }
            Family::Quotient(_) => None,
        }
    }

    /// The columns' values at y with the weight's value `w` given in place of w(y).
    pub(crate) fn values_weighted(&self, y: Point, w: f64, buf: &mut [f64], out: &mut [f64]) {
        self.family_values(y, w, buf);
        self.values_from(y, w, buf, out);
    }

    /// The family's weight at y.
    pub(crate) fn weight(&self, y: Point) -> f64 {
        self.family.weight(y)
    }

    /// The family's values w p_k(y), k < [`Block::scratch`], into buf: shared by the blocks of
    /// one family ([`Block::same_family`]).
    pub(crate) fn family_values(&self, y: Point, w: f64, buf: &mut [f64]) {
        let n = self.family.len();
        self.family.values_weighted(y, w, &mut buf[..n]);
    }

    /// The columns' values at y (weight w) into out[..len] from the family's, `family` (from
    /// [`Block::family_values`] at the same y and w, of this block or one of the same family).
    pub(crate) fn values_from(&self, y: Point, w: f64, family: &[f64], out: &mut [f64]) {
        let buf = family;
        for (o, &k) in out.iter_mut().zip(&self.degrees) {
            *o = buf[k];
        }
        let m = self.degrees.len();
        for (o, (z, _, _)) in out[m..].iter_mut().zip(&self.poles) {
            *o = w * self.pole(*z, y);
        }
    }

    /// 1 / (Z - y) with its pair, Z - y and Z + y from the offsets ([`Point::minus`]).
    fn pole(&self, z: Point, y: Point) -> f64 {
        if self.pair == 0.0 {
            1.0 / z.minus(y)
        } else {
            1.0 / z.minus(y) + self.pair / z.minus(y.reflected())
        }
    }

    /// The columns' transforms T at y (off the ends) into out[..len].
    pub(crate) fn transforms(&self, y: Point, buf: &mut [f64], out: &mut [f64]) {
        let n = self.family.len();
        self.family.transforms(y, &mut buf[..n]);
        self.transforms_from(y, buf, out);
    }

    /// The family's transforms T_k, k < s = [`Block::scratch`], at each of `points` with its
    /// weight factors ([`Block::factors`]; a Jacobi family's T_0 takes them at a point
    /// inside), point i's into out[i s..(i + 1) s]: the backward recurrences of several points
    /// together ([`JacobiFamily::transforms_many`]; the same values to the bit).
    pub(crate) fn family_transforms_many(
        &self,
        points: &[Point],
        factors: &[Option<(f64, f64)>],
        out: &mut [f64],
    ) {
        match &self.family {
            Family::Jacobi(f) => f.transforms_many(points, factors, out),
            Family::Quotient(f) => {
                let n = f.len();
                for (p, row) in points.iter().zip(out.chunks_exact_mut(n)) {
                    f.transforms(*p, row);
                }
            }
        }
    }

    /// The columns' transforms at y into out[..len] from the family's transforms `family` at
    /// the same y (of this block or of one with the same family, [`Block::same_family`]).
    pub(crate) fn transforms_from(&self, y: Point, family: &[f64], out: &mut [f64]) {
        let t0 = family[0];
        for (o, &k) in out.iter_mut().zip(&self.degrees) {
            *o = family[k];
        }
        let m = self.degrees.len();
        for (o, &(z, t0z, t0mz)) in out[m..].iter_mut().zip(&self.poles) {
            // w / (z - t) has the transform (T_0(y) - T_0(z)) / (z - y) (J6); the pair's
            // second pole 1 / (z + t) = -1 / (-z - t)
            let mut t = pole_transform(t0, y, z, t0z);
            if self.pair != 0.0 {
                t -= self.pair * pole_transform(t0, y, z.reflected(), t0mz);
            }
            *o = t;
        }
    }

    /// Whether this block is the quotient family.
    pub(crate) fn is_quotient(&self) -> bool {
        matches!(self.family, Family::Quotient(_))
    }

    /// Whether `other` has this block's family (the same exponents and length), so that
    /// the family's transforms serve both.
    pub(crate) fn same_family(&self, other: &Block) -> bool {
        self.family.same_as(&other.family)
    }

    /// The columns' integrals over [-1, 1].
    pub(crate) fn integrals(&self, out: &mut [f64]) {
        for (o, &k) in out.iter_mut().zip(&self.degrees) {
            *o = self.family.moment(k);
        }
        let m = self.degrees.len();
        for (o, &(_, t0z, t0mz)) in out[m..].iter_mut().zip(&self.poles) {
            // int w / (z - t) = -pi T_0(z)
            let pi = std::f64::consts::PI;
            *o = -pi * t0z
                + if self.pair != 0.0 {
                    self.pair * pi * t0mz
                } else {
                    0.0
                };
        }
    }

    /// The family's weight factors at y ([`Family::weight_factors`]).
    pub(crate) fn weight_factors(&self, y: Point) -> (f64, f64) {
        self.family.weight_factors(y)
    }

    /// The columns of a coarser block: all but the `degrees` highest polynomial degrees and
    /// `poles` of the poles, every other one from the second nearest on (so that the rest
    /// still spans the cluster's decades; [`super::system::Basis::coarse_columns`]).
    pub(crate) fn coarse_columns(&self, degrees: usize, poles: usize) -> Vec<bool> {
        let nd = self.degrees.len();
        let np = self.poles.len();
        let drop_d = degrees.min(nd.saturating_sub(1));
        let drop_p = poles.min(np / 2);
        (0..nd)
            .map(|i| i < nd - drop_d)
            .chain((0..np).map(|i| i % 2 == 0 || i / 2 >= drop_p))
            .collect()
    }

    /// Length of the scratch buffer the evaluations need.
    pub(crate) fn scratch(&self) -> usize {
        self.family.len()
    }
}

/// Degrees k < n of one parity (0 even, 1 odd), `count` of them.
pub(crate) fn parity(count: usize, odd: usize) -> Vec<usize> {
    (0..count).map(|i| 2 * i + odd).collect()
}
