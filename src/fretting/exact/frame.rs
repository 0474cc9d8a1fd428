//! A contact [-1, 1] cut into zones, each with global Jacobi bases carrying the local
//! exponents at its two ends, and the bordered least-squares solve of the whole-contact
//! equations on it (docs/theory_tangential.md section 11):
//!
//! - (A) H[p](x) - bp q(x) = 0 at every collocation point;
//! - (B) H[q](x) + bq p(x) = r(x) + sigma_0 + sigma_1 tau(x) at the stick points, r a given
//!   forcing and tau the stick set mapped to [-1, 1] (one or two border constants);
//! - int p = 1, int q = Q/P, and p, q continuous at every zone boundary inside the contact,
//!   by elimination;
//! - on a slip zone q = s mu p (s = +-1) is built into its columns.
//!
//! Per zone and component, the families are the Jacobi weights (x - lo)^e_lo (hi - x)^e_hi
//! for every pair of the zone's exponents at its two ends, each with orthonormal Jacobi
//! polynomials and single poles beyond the nearest singular point outside each end
//! (`spectral::basis::Block`, transforms in closed form by `numerics::jacobi_transform`).

use crate::error::{Error, Result};
use crate::numerics::bonded::{Bonded, MAX_DEGREE};
use crate::numerics::jacobi_transform::{JacobiFamily, Point};
use crate::numerics::lstsq::{ConstrainedFailure, constrained};
use crate::problem::Coupling;
use crate::spectral::basis::Block;

/// Stick, or slip with q = s mu p, or a stick zone at the contact's end x = -1 carrying a
/// state on the friction bound q = -mu p plus the bonded increment (docs/theory_tangential.md
/// section 20): its p families have q = -mu p built in (the loaded edge zone's p*, q*), and
/// `n` complex powers (1 + x)^(-1/2 + i eps + j), j < n, of the increment
/// dp + i dq / delta each add two columns (A = 1 and A = i).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Kind {
    Stick,
    Slip(f64),
    Corner(usize),
    /// The mirror of [`Kind::Corner`] at x = +1 (x -> -x, q -> -q, docs/theory_tangential.md
    /// section 5): the state on the bound q = +mu p plus the bonded increment, whose
    /// powers (1 - x)^(a + j), a = -1/2 - i eps (the conjugate of -1 + x's exponent), each
    /// add two columns of dp + i dq / delta (section 24).
    FarCorner(usize),
}

impl Kind {
    /// The sign s of q = s mu p built into the zone's p families, if any.
    fn tie(self) -> Option<f64> {
        match self {
            Kind::Stick => None,
            Kind::Slip(s) => Some(s),
            Kind::Corner(_) => Some(-1.0),
            Kind::FarCorner(_) => Some(1.0),
        }
    }

    fn sticks(self) -> bool {
        !matches!(self, Kind::Slip(_))
    }
}

/// One zone: its kind, its length, its components' exponents at the two ends ([lo, hi];
/// q's are unused on a slip zone), and the distance beyond each end to a singular point of
/// the solution's continuation that is no zone end (the forcing's -c beyond c2,
/// docs/theory_tangential.md section 10), if nearer than the neighbouring zone's far end. Every exponent list holds 0 or
/// values in (-1, 1) whose sums over the two ends exceed -1.
#[derive(Clone, Debug)]
pub(crate) struct ZoneSpec {
    pub(crate) kind: Kind,
    pub(crate) len: f64,
    pub(crate) p: [Vec<f64>; 2],
    pub(crate) q: [Vec<f64>; 2],
    pub(crate) near: [Option<f64>; 2],
}

/// A point of zone `zone` given by its offsets from the zone's ends, each to full relative
/// accuracy.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Loc {
    pub(crate) zone: usize,
    pub(crate) from_lo: f64,
    pub(crate) to_hi: f64,
}

/// Sizes at one level: polynomials per family, poles per decade.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sizes {
    pub(crate) degree: usize,
    pub(crate) per_decade: f64,
}

impl Sizes {
    /// Level l = 1, 2, ...: 4 + 3 l polynomials per family and 2 + l/2 poles per decade,
    /// about the normal-load solver's slip families (5 + 3 l) and its pole density
    /// (docs/theory_spectral.md (B4)).
    pub(crate) fn at(level: usize) -> Self {
        Sizes {
            degree: 4 + 3 * level,
            per_decade: 2.0 + 0.5 * level as f64,
        }
    }
}

struct Zone {
    kind: Kind,
    len: f64,
    /// 1 + lo and 1 - hi (offsets of the zone's ends from the contact's ends).
    opl: f64,
    omh: f64,
    /// Distances beyond the ends to the nearest singular point (None at the contact's ends).
    near: [Option<f64>; 2],
    /// p blocks, then q blocks (stick only), then the bonded powers (corner only).
    p: Vec<Block>,
    q: Vec<Block>,
    bonded: Option<Bonded>,
    start: usize,
    count: usize,
}

/// The zones' bases, column layout and geometry.
pub(crate) struct Frame {
    zones: Vec<Zone>,
    pub(crate) k: Coupling,
    n: usize,
    scratch: usize,
}

type C64 = faer::complex::Complex<f64>;

/// The bonded powers of a zone kind.
fn bonded_powers(kind: Kind) -> usize {
    match kind {
        Kind::Corner(n) | Kind::FarCorner(n) => n,
        _ => 0,
    }
}

fn log_spaced(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if n == 0 {
        return Vec::new();
    }
    if n == 1 {
        return vec![(lo * hi).sqrt()];
    }
    (0..n)
        .map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64))
        .collect()
}

impl Frame {
    pub(crate) fn new(k: Coupling, specs: &[ZoneSpec], sizes: Sizes) -> Self {
        let nz = specs.len();
        let mut opl = Vec::with_capacity(nz);
        let mut acc = 0.0;
        for s in specs {
            opl.push(acc);
            acc += s.len;
        }
        let mut omh = vec![0.0; nz];
        let mut acc = 0.0;
        for i in (0..nz).rev() {
            omh[i] = acc;
            acc += specs[i].len;
        }
        let mut zones = Vec::with_capacity(nz);
        let mut start = 0;
        let mut scratch = 1;
        for (i, s) in specs.iter().enumerate() {
            let len = s.len;
            // poles beyond the nearest zone boundary outside each end, from a tenth of the
            // distance to it out to the zone's length (docs/theory_spectral.md (B4))
            let near = [
                (i > 0).then(|| specs[i - 1].len.min(s.near[0].unwrap_or(f64::INFINITY))),
                (i + 1 < nz).then(|| specs[i + 1].len.min(s.near[1].unwrap_or(f64::INFINITY))),
            ];
            let mut poles = Vec::new();
            if let Some(d) = near[0] {
                let n = ((len / (0.1 * d)).log10().max(0.0) * sizes.per_decade).ceil() as usize;
                for z in log_spaced(0.1 * d, len, n) {
                    // x = lo - d - z: t = -1 - 2 (d + z) / len
                    let o = 2.0 * (d + z) / len;
                    poles.push(Point::offsets(2.0 + o, -o));
                }
            }
            if let Some(d) = near[1] {
                let n = ((len / (0.1 * d)).log10().max(0.0) * sizes.per_decade).ceil() as usize;
                for z in log_spaced(0.1 * d, len, n) {
                    let o = 2.0 * (d + z) / len;
                    poles.push(Point::offsets(-o, 2.0 + o));
                }
            }
            let blocks = |ends: &[Vec<f64>; 2]| -> Vec<Block> {
                let mut out = Vec::new();
                for &b in &ends[0] {
                    for &a in &ends[1] {
                        let f = JacobiFamily::new(a, b, sizes.degree);
                        out.push(Block::new(f, (0..sizes.degree).collect(), &poles, 0.0));
                    }
                }
                out
            };
            let p = blocks(&s.p);
            let q = if s.kind == Kind::Stick {
                blocks(&s.q)
            } else {
                Vec::new()
            };
            let bonded = match s.kind {
                Kind::Corner(n) => {
                    assert!(i == 0, "a corner zone lies at x = -1");
                    let b = Bonded::new(k.b_star(), 1.0 - len, len, MAX_DEGREE);
                    assert!(n <= b.powers(), "at most {} bonded powers", b.powers());
                    Some(b)
                }
                Kind::FarCorner(n) => {
                    assert!(i + 1 == nz, "a far corner zone lies at x = +1");
                    let b = Bonded::new(k.b_star(), 1.0 - len, len, MAX_DEGREE);
                    assert!(n <= b.powers(), "at most {} bonded powers", b.powers());
                    Some(b)
                }
                _ => None,
            };
            let count: usize =
                p.iter().chain(&q).map(Block::len).sum::<usize>() + 2 * bonded_powers(s.kind);
            scratch = scratch.max(p.iter().chain(&q).map(Block::scratch).max().unwrap_or(1));
            zones.push(Zone {
                kind: s.kind,
                len,
                opl: opl[i],
                omh: omh[i],
                near,
                p,
                q,
                bonded,
                start,
                count,
            });
            start += count;
        }
        Frame {
            zones,
            k,
            n: start,
            scratch: scratch.max(start),
        }
    }

    /// Number of basis columns.
    pub(crate) fn len(&self) -> usize {
        self.n
    }

    pub(crate) fn zone_count(&self) -> usize {
        self.zones.len()
    }

    pub(crate) fn zone_len(&self, i: usize) -> f64 {
        self.zones[i].len
    }

    /// The stick set's components, maximal runs of stick zones: (first zone, last zone,
    /// 1 + lo, 1 - hi).
    pub(crate) fn stick_parts(&self) -> Vec<(usize, usize, f64, f64)> {
        let mut out: Vec<(usize, usize, f64, f64)> = Vec::new();
        for (i, z) in self.zones.iter().enumerate() {
            if !z.kind.sticks() {
                continue;
            }
            match out.last_mut() {
                Some(last) if last.1 + 1 == i => {
                    last.1 = i;
                    last.3 = z.omh;
                }
                _ => out.push((i, i, z.opl, z.omh)),
            }
        }
        out
    }

    /// The columns' int (H[q] + bq p) over the slip zones `from..to` (between two stick
    /// components) and the same integral of the forcing `r`, whose singular points (as
    /// 1 + x) are `kinks`: a composite Gauss-Legendre rule ([`gap_rule`]) on the pieces
    /// between the zones' ends and the kinks (the columns' H[q] carries logarithms at the
    /// zone ends, the solution |x - end|^g there, the forcing |x - kink|^g).
    fn gap_row(
        &self,
        from: usize,
        to: usize,
        r: &dyn Fn(f64, f64) -> f64,
        kinks: &[f64],
    ) -> (Vec<f64>, f64) {
        let n = self.n;
        let (mut pv, mut qv, mut hp, mut hq) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut buf = vec![0.0; self.scratch];
        let mut row = vec![0.0; n];
        let mut rint = 0.0;
        for zone in from..to {
            let z = &self.zones[zone];
            for (l, w) in gap_rule(z.len, z.opl, kinks) {
                let l = Loc { zone, ..l };
                let (opx, omx) = self.offsets(&l);
                // a node that rounds onto a kink, where the data's H[q] is infinite, is left
                // out (weight below 1e-14 of its piece; the integrand is integrable there)
                let rv = r(opx, omx);
                if !rv.is_finite() {
                    continue;
                }
                self.values(&l, &mut pv, &mut qv, &mut buf);
                self.hilbert(&l, &mut hp, &mut hq, &mut buf);
                for j in 0..n {
                    row[j] += w * (hq[j] + self.k.bq * pv[j]);
                }
                rint += w * rv;
            }
        }
        (row, rint)
    }

    pub(crate) fn is_stick(&self, i: usize) -> bool {
        self.zones[i].kind.sticks()
    }

    /// Whether zone i is a corner zone ([`Kind::Corner`] or [`Kind::FarCorner`]).
    pub(crate) fn is_corner(&self, i: usize) -> bool {
        matches!(self.zones[i].kind, Kind::Corner(_) | Kind::FarCorner(_))
    }

    /// (1 + x, 1 - x) of a point.
    pub(crate) fn offsets(&self, l: &Loc) -> (f64, f64) {
        let z = &self.zones[l.zone];
        (z.opl + l.from_lo, z.omh + l.to_hi)
    }

    /// The point at x (given with 1 + x and 1 - x), strictly inside a zone.
    ///
    /// The zone and both offsets in it are read from the offset with the more digits, 1 + x
    /// on the left half and 1 - x on the right: the two may disagree by their rounding (a
    /// caller's 2 - (1 + x) has lost digits of 1 + x), and an offset from a zone end taken
    /// from the other one can round to zero, where the zones' H[q] is NaN, for a point that
    /// the first one places inside the zone.
    pub(crate) fn locate(&self, opx: f64, omx: f64) -> Loc {
        // 1 + x < z.opl + z.len is 1 - x > z.omh
        let left = opx <= omx;
        let i = self
            .zones
            .iter()
            .position(|z| {
                if left {
                    opx < z.opl + z.len
                } else {
                    omx > z.omh
                }
            })
            .unwrap_or(self.zones.len() - 1);
        let z = &self.zones[i];
        let (from_lo, to_hi) = if left {
            (opx - z.opl, z.len - (opx - z.opl))
        } else {
            (z.len - (omx - z.omh), omx - z.omh)
        };
        // a point within rounding of a zone end is taken at that end
        Loc {
            zone: i,
            from_lo: from_lo.max(0.0),
            to_hi: to_hi.max(0.0),
        }
    }

    /// The point mapped to zone j's variable t in [-1, 1] (outside for other zones).
    fn mapped(&self, l: &Loc, j: usize) -> Point {
        let (xlo, hix) = self.rel(l, j);
        let len = self.zones[j].len;
        Point::offsets(2.0 * hix / len, 2.0 * xlo / len)
    }

    /// (x - lo, hi - x) of the point for zone j's ends, each to full relative accuracy.
    fn rel(&self, l: &Loc, j: usize) -> (f64, f64) {
        let i = l.zone;
        let len = self.zones[j].len;
        let (xlo, hix) = if i == j {
            (l.from_lo, l.to_hi)
        } else if j < i {
            let between: f64 = self.zones[j + 1..i].iter().map(|z| z.len).sum();
            (l.from_lo + between + len, -(l.from_lo + between))
        } else {
            let between: f64 = self.zones[i + 1..j].iter().map(|z| z.len).sum();
            (-(l.to_hi + between), l.to_hi + between + len)
        };
        (xlo, hix)
    }

    /// The columns' p and q at a point of its zone (a zone end included, where no exponent
    /// there is negative).
    pub(crate) fn values(&self, l: &Loc, pv: &mut [f64], qv: &mut [f64], buf: &mut [f64]) {
        pv.fill(0.0);
        qv.fill(0.0);
        let z = &self.zones[l.zone];
        let t = self.mapped(l, l.zone);
        let mut at = z.start;
        for b in &z.p {
            let n = b.len();
            b.values(t, buf, &mut pv[at..at + n]);
            if let Some(s) = z.kind.tie() {
                for j in at..at + n {
                    qv[j] = s * self.k.mu * pv[j];
                }
            }
            at += n;
        }
        for b in &z.q {
            let n = b.len();
            b.values(t, buf, &mut qv[at..at + n]);
            at += n;
        }
        if let Some((np, a, far)) = self.corner_powers(z.kind) {
            // (u / len)^(a + j), u the offset from the zone's end at -1 (1 + x) or +1 (1 - x)
            let s = if far { l.to_hi } else { l.from_lo } / z.len;
            let mut f = (a * s.ln()).exp();
            for _ in 0..np {
                self.bonded_pair(f, f, &mut pv[at..at + 2], &mut qv[at..at + 2]);
                f *= s;
                at += 2;
            }
        }
    }

    /// eps = artanh(b*) / pi, b* = sqrt(bp bq), of the bonded field.
    fn eps(&self) -> f64 {
        self.k.b_star().atanh() / std::f64::consts::PI
    }

    /// A corner zone's bonded powers (-1 + x)^(beta + j) or (1 - x)^(a + j): their count,
    /// their exponent beta = -1/2 + i eps at x = -1 ([`Kind::Corner`]) or a = conj(beta) at
    /// x = +1 ([`Kind::FarCorner`]), and whether they sit at +1.
    fn corner_powers(&self, kind: Kind) -> Option<(usize, C64, bool)> {
        match kind {
            Kind::Corner(n) => Some((n, C64::new(-0.5, self.eps()), false)),
            Kind::FarCorner(n) => Some((n, C64::new(-0.5, -self.eps()), true)),
            _ => None,
        }
    }

    /// The two real columns of a complex power phi of dp + i dq / delta (A = 1 and A = i),
    /// from phi's value `vp` for p and `vq` for q (the same number for values; H[phi] for
    /// both in transforms, H being real-linear): p = Re(A phi), q = delta Im(A phi).
    fn bonded_pair(&self, vp: C64, vq: C64, p: &mut [f64], q: &mut [f64]) {
        let delta = if self.k.bp > 0.0 {
            (self.k.bq / self.k.bp).sqrt()
        } else {
            0.0
        };
        p[0] = vp.re;
        q[0] = delta * vq.im;
        p[1] = -vp.im;
        q[1] = delta * vq.re;
    }

    /// The columns' H[p] and H[q] at a point (off the zone ends).
    pub(crate) fn hilbert(&self, l: &Loc, hp: &mut [f64], hq: &mut [f64], buf: &mut [f64]) {
        hp.fill(0.0);
        hq.fill(0.0);
        for (j, z) in self.zones.iter().enumerate() {
            let t = self.mapped(l, j);
            let mut at = z.start;
            for b in &z.p {
                let n = b.len();
                b.transforms(t, buf, &mut hp[at..at + n]);
                for v in &mut hp[at..at + n] {
                    *v = -*v;
                }
                if let Some(s) = z.kind.tie() {
                    for jj in at..at + n {
                        hq[jj] = s * self.k.mu * hp[jj];
                    }
                }
                at += n;
            }
            for b in &z.q {
                let n = b.len();
                b.transforms(t, buf, &mut hq[at..at + n]);
                for v in &mut hq[at..at + n] {
                    *v = -*v;
                }
                at += n;
            }
            if let (Some((np, a, far)), Some(bx)) = (self.corner_powers(z.kind), &z.bonded) {
                // H over [1 - len, 1] of (1 - s)^(a + m): at +1 on the powers' own interval
                // (1 - y = hi - x, c - y = -(x - lo)); at -1, H over [-1, -1 + len] of
                // (1 + x)^(beta + m) at y is -conj of it at -y, a = conj(beta) (the
                // reflection s = -x; 1 - (-y) = x - lo, c - (-y) = -(hi - x))
                let (xlo, hix) = self.rel(l, j);
                let mut h = vec![C64::new(0.0, 0.0); np];
                if far {
                    bx.end_powers(hix, -xlo, &mut h);
                } else {
                    bx.end_powers(xlo, -hix, &mut h);
                }
                // divided by len^(exponent + m)
                let mut scale = (-a * z.len.ln()).exp();
                for hm in h.iter().take(np) {
                    let v = if far { *hm * scale } else { -hm.conj() * scale };
                    self.bonded_pair(v, v, &mut hp[at..at + 2], &mut hq[at..at + 2]);
                    scale /= z.len;
                    at += 2;
                }
            }
        }
    }

    /// int p and int q of each column.
    pub(crate) fn integrals(&self) -> (Vec<f64>, Vec<f64>) {
        let (mut ip, mut iq) = (vec![0.0; self.n], vec![0.0; self.n]);
        for z in &self.zones {
            let mut at = z.start;
            for b in &z.p {
                let n = b.len();
                b.integrals(&mut ip[at..at + n]);
                for j in at..at + n {
                    ip[j] *= 0.5 * z.len;
                    if let Some(s) = z.kind.tie() {
                        iq[j] = s * self.k.mu * ip[j];
                    }
                }
                at += n;
            }
            for b in &z.q {
                let n = b.len();
                b.integrals(&mut iq[at..at + n]);
                for v in &mut iq[at..at + n] {
                    *v *= 0.5 * z.len;
                }
                at += n;
            }
            if let Some((np, a, _)) = self.corner_powers(z.kind) {
                // int over the zone of (u / len)^(a + m) = len / (a + m + 1)
                for m in 0..np {
                    let v = (a + (m + 1) as f64).inv() * z.len;
                    let (mut p2, mut q2) = ([0.0; 2], [0.0; 2]);
                    self.bonded_pair(v, v, &mut p2, &mut q2);
                    ip[at..at + 2].copy_from_slice(&p2);
                    iq[at..at + 2].copy_from_slice(&q2);
                    at += 2;
                }
            }
        }
        (ip, iq)
    }

    pub(crate) fn scratch_len(&self) -> usize {
        self.scratch
    }

    /// Collocation points: `per_col` Chebyshev points per column of each zone, and points
    /// spaced geometrically (`per_decade` per decade) towards each end from a tenth of the
    /// zone, down to 1e-6 of it at the contact's ends and to a hundredth of the distance to
    /// the nearest singular point beyond (at most 1e-3) at the others.
    pub(crate) fn collocation(&self, per_col: f64, per_decade: f64) -> Vec<Loc> {
        let mut out = Vec::new();
        for (i, z) in self.zones.iter().enumerate() {
            let m = (per_col * z.count as f64).ceil().max(4.0) as usize;
            for k in 0..m {
                let th = (k as f64 + 0.5) * std::f64::consts::PI / m as f64;
                let (a, b) = ((0.5 * th).sin().powi(2), (0.5 * th).cos().powi(2));
                out.push(Loc {
                    zone: i,
                    from_lo: z.len * a,
                    to_hi: z.len * b,
                });
            }
            for (near, lo_end) in [(z.near[0], true), (z.near[1], false)] {
                let d = match near {
                    None => 1e-6,
                    Some(d) => (1e-2 * d / z.len).min(1e-3),
                };
                let n = ((0.1 / d).log10() * per_decade).ceil().max(1.0) as usize;
                for k in 0..=n {
                    let f = 0.1 * (d / 0.1).powf(k as f64 / n as f64);
                    let (from_lo, to_hi) = if lo_end {
                        (z.len * f, z.len * (1.0 - f))
                    } else {
                        (z.len * (1.0 - f), z.len * f)
                    };
                    out.push(Loc {
                        zone: i,
                        from_lo,
                        to_hi,
                    });
                }
            }
        }
        out
    }
}

/// Chebyshev points per column of a zone: with two rows per stick point and one per slip
/// point, 2 .. 2.6 rows per unknown (the normal-load solver's: 2.6 at its level 1, 1.5
/// above, docs/theory_spectral.md (C1)). At the ply (Q/P = 0.18, fixed geometry) 2.0 instead of 1.3 changed the distance
/// to level 10 by less than its scatter between levels (1e-7, the frame's noise floor there).
const POINTS_PER_COLUMN: f64 = 1.3;

/// Clustered points per decade towards a zone end, per pole per decade: more rows than pole
/// columns over every decade the poles span, so that no decade is fitted by fewer equations
/// than it has unknowns.
const CLUSTER_DENSITY: f64 = 1.5;

/// The gap rule's panels: ratio 0.2 over 20 levels towards each end of every piece (down
/// to 5e-15 of it), 20 points each: section 11's graded quadrature.
const GAP_RATIO: f64 = 0.2;
const GAP_LEVELS: i32 = 20;
const GAP_POINTS: usize = 20;
/// Towards a kink of the forcing, inside a zone, 12 levels (down to 2e-9 of the piece): the
/// forcing is bounded there (|x - kink|^g), the columns smooth, so the panel next to the
/// kink leaves an error of its length^(1 + g), 1e-13; deeper nodes would sit within a few
/// ulps of the kink, where the data's H[q] is evaluated from rounded offsets.
const GAP_LEVELS_KINK: i32 = 12;

/// (point, weight) of a rule for int over a zone of length `len` starting at 1 + x = `opl`,
/// cut at the `kinks` (as 1 + x) inside it: on each piece, panels graded towards both of
/// its ends ([`GAP_RATIO`], [`GAP_LEVELS`]), [`GAP_POINTS`] Gauss-Legendre nodes each, every
/// node's offsets taken from the piece's nearer end (the zone index of the points is 0).
pub(crate) fn gap_rule(len: f64, opl: f64, kinks: &[f64]) -> Vec<(Loc, f64)> {
    let mut ends = vec![0.0];
    ends.extend(
        kinks
            .iter()
            .map(|&c| c - opl)
            .filter(|&d| d > 0.0 && d < len),
    );
    ends.push(len);
    ends.sort_by(f64::total_cmp);
    let (t, wt) = crate::numerics::quadrature::gauss_legendre(GAP_POINTS);
    let mut out = Vec::new();
    for piece in ends.windows(2) {
        let (u, v) = (piece[0], piece[1]);
        let plen = v - u;
        // each half graded towards its end, as deep as that end needs, and its nodes taken
        // by their offsets from that end
        for (from_v, end) in [(false, u), (true, v)] {
            let at_kink = if from_v { v < len } else { u > 0.0 };
            let levels = if at_kink { GAP_LEVELS_KINK } else { GAP_LEVELS };
            let cuts = crate::numerics::quadrature::graded_cuts(plen, GAP_RATIO, levels);
            let half: Vec<f64> = cuts.into_iter().filter(|&c| c <= 0.5 * plen).collect();
            for c in half.windows(2) {
                let (m, h) = (0.5 * (c[0] + c[1]), 0.5 * (c[1] - c[0]));
                for (&ti, &wi) in t.iter().zip(&wt) {
                    let d = m + h * ti;
                    let l = if from_v {
                        Loc {
                            zone: 0,
                            from_lo: end - d,
                            to_hi: (len - end) + d,
                        }
                    } else {
                        Loc {
                            zone: 0,
                            from_lo: end + d,
                            to_hi: (len - end) - d,
                        }
                    };
                    if l.from_lo > 0.0 && l.to_hi > 0.0 {
                        out.push((l, h * wi));
                    }
                }
            }
        }
    }
    out
}

/// A fixed-geometry solve.
pub(crate) struct Solved {
    pub(crate) frame: Frame,
    pub(crate) coef: Vec<f64>,
    /// The border constants (zero at the exact stick-slip points).
    pub(crate) sigma: Vec<f64>,
    /// The largest weighted residual of (A) and (B) at the collocation points, relative to
    /// the largest term of its row.
    pub(crate) residual: f64,
}

/// Solves (A), (B) with `n_sigma` (1 or 2) border constants, the forcing `r` (a function of
/// (1 + x, 1 - x)) and int q = `qp`, on a connected stick set.
pub(crate) fn solve(
    k: Coupling,
    specs: &[ZoneSpec],
    sizes: Sizes,
    n_sigma: usize,
    qp: f64,
    r: &dyn Fn(f64, f64) -> f64,
) -> Result<Solved> {
    solve_parts(k, specs, sizes, n_sigma, qp, r, &[])
}

/// [`solve`] on a stick set of one or more components (maximal runs of stick zones), with
/// `n_sigma` border constants per component (in its own variable tau) and, for each slip
/// zone between two components, the condition that both move with the punch: the slip
/// since the data returns to zero across it, int (H[q] + bq p - r) = 0 over it
/// (docs/theory_tangential.md (C2)); `kinks` are the forcing's singular points (as 1 + x),
/// where that integral's rule is cut. The border constants come component by component.
pub(crate) fn solve_parts(
    k: Coupling,
    specs: &[ZoneSpec],
    sizes: Sizes,
    n_sigma: usize,
    qp: f64,
    r: &dyn Fn(f64, f64) -> f64,
    kinks: &[f64],
) -> Result<Solved> {
    let frame = Frame::new(k, specs, sizes);
    let n = frame.len();
    // the stick set's components (maximal runs of stick zones), each [lo, hi] as offsets
    // (1 + lo, 1 - hi), with its first and last zone
    let parts = frame.stick_parts();
    // a component that begins (ends) with a corner zone reaches x = -1 (+1) with the bonded
    // field's singularity allowed there: one border constant (bounded at its other end only,
    // docs/theory_tangential.md sections 20 and 24)
    let per_part: Vec<usize> = parts
        .iter()
        .map(|&(a, b, ..)| {
            if frame.is_corner(a) || frame.is_corner(b) {
                1
            } else {
                n_sigma
            }
        })
        .collect();
    let first: Vec<usize> = per_part
        .iter()
        .scan(n, |acc, &m| {
            let at = *acc;
            *acc += m;
            Some(at)
        })
        .collect();
    let cols = n + if parts.is_empty() {
        n_sigma
    } else {
        per_part.iter().sum()
    };
    let pts = frame.collocation(POINTS_PER_COLUMN, CLUSTER_DENSITY * sizes.per_decade);
    let g = 0.5 - (k.bp * k.mu).atan() / std::f64::consts::PI;
    let mut rows: Vec<Vec<f64>> = Vec::new();
    let mut rhs = Vec::new();
    let (mut pv, mut qv, mut hp, mut hq) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut buf = vec![0.0; frame.scratch_len()];
    for l in &pts {
        frame.values(l, &mut pv, &mut qv, &mut buf);
        frame.hilbert(l, &mut hp, &mut hq, &mut buf);
        let (opx, omx) = frame.offsets(l);
        let w = (opx * omx).powf(g);
        let mut row = vec![0.0; cols];
        for j in 0..n {
            row[j] = w * (hp[j] - k.bp * qv[j]);
        }
        rows.push(row);
        rhs.push(0.0);
        if frame.is_stick(l.zone) {
            let mut row = vec![0.0; cols];
            for j in 0..n {
                row[j] = w * (hq[j] + k.bq * pv[j]);
            }
            let c = parts
                .iter()
                .position(|&(a, b, _, _)| l.zone >= a && l.zone <= b)
                .unwrap_or(0);
            let (_, _, lo, hi) = parts[c];
            let at = first[c];
            row[at] = -w;
            if per_part[c] > 1 {
                let tau = (opx - lo - (omx - hi)) / (2.0 - lo - hi);
                row[at + 1] = -w * tau;
            }
            rows.push(row);
            rhs.push(w * r(opx, omx));
        }
    }
    // column scales
    let mut scale = vec![0.0; cols];
    for row in &rows {
        for (s, v) in scale.iter_mut().zip(row) {
            *s += v * v;
        }
    }
    for s in &mut scale {
        *s = if *s > 0.0 { 1.0 / s.sqrt() } else { 1.0 };
    }
    for row in &mut rows {
        for (v, s) in row.iter_mut().zip(&scale) {
            *v *= s;
        }
    }
    // constraints
    let (ip, iq) = frame.integrals();
    let mut cons: Vec<(Vec<f64>, f64)> = vec![(ip, 1.0), (iq, qp)];
    let (mut p1, mut q1) = (vec![0.0; n], vec![0.0; n]);
    for i in 0..frame.zone_count() - 1 {
        let a = Loc {
            zone: i,
            from_lo: frame.zones[i].len,
            to_hi: 0.0,
        };
        let b = Loc {
            zone: i + 1,
            from_lo: 0.0,
            to_hi: frame.zones[i + 1].len,
        };
        frame.values(&a, &mut pv, &mut qv, &mut buf);
        frame.values(&b, &mut p1, &mut q1, &mut buf);
        cons.push(((0..n).map(|j| pv[j] - p1[j]).collect(), 0.0));
        cons.push(((0..n).map(|j| qv[j] - q1[j]).collect(), 0.0));
    }
    // two stick components move with the same punch: the slip since the data, whose slope
    // is -(H[q] + bq p - r), returns to zero across the slip zone between them
    for w in parts.windows(2) {
        cons.push(frame.gap_row(w[0].1 + 1, w[1].0, r, kinks));
    }
    let cons: Vec<(Vec<f64>, f64)> = cons
        .into_iter()
        .map(|(row, d)| {
            let mut row: Vec<f64> = row.iter().zip(&scale).map(|(v, s)| v * s).collect();
            row.resize(cols, 0.0);
            (row, d)
        })
        .collect();
    let full = constrained(&rows.concat(), cols, &rhs, cons, n).map_err(|e| {
        Error::NoConvergence(
            match e {
                ConstrainedFailure::DependentConstraints => "exact: dependent constraints",
                ConstrainedFailure::NotFinite => "exact: least-squares solution not finite",
            }
            .to_string(),
        )
    })?;
    let mut residual = 0.0f64;
    for (row, r) in rows.iter().zip(&rhs) {
        let res: f64 = row.iter().zip(&full).map(|(a, x)| a * x).sum::<f64>() - r;
        let size: f64 = row
            .iter()
            .zip(&full)
            .map(|(a, x)| (a * x).abs())
            .fold(0.0, f64::max)
            .max(r.abs());
        if size > 0.0 {
            residual = residual.max(res.abs() / size);
        }
    }
    let coef: Vec<f64> = (0..n).map(|j| full[j] * scale[j]).collect();
    let sigma: Vec<f64> = (n..cols).map(|j| full[j] * scale[j]).collect();
    Ok(Solved {
        frame,
        coef,
        sigma,
        residual,
    })
}

impl Solved {
    /// (p, q) at a point.
    pub(crate) fn tractions_at(&self, l: &Loc) -> (f64, f64) {
        let n = self.frame.len();
        let (mut pv, mut qv) = (vec![0.0; n], vec![0.0; n]);
        let mut buf = vec![0.0; self.frame.scratch_len()];
        self.frame.values(l, &mut pv, &mut qv, &mut buf);
        let dot = |v: &[f64]| v.iter().zip(&self.coef).map(|(a, b)| a * b).sum::<f64>();
        (dot(&pv), dot(&qv))
    }

    /// (H[p], H[q]) at a point off the zone ends.
    pub(crate) fn hilbert_at(&self, l: &Loc) -> (f64, f64) {
        let n = self.frame.len();
        let (mut hp, mut hq) = (vec![0.0; n], vec![0.0; n]);
        let mut buf = vec![0.0; self.frame.scratch_len()];
        self.frame.hilbert(l, &mut hp, &mut hq, &mut buf);
        let dot = |v: &[f64]| v.iter().zip(&self.coef).map(|(a, b)| a * b).sum::<f64>();
        (dot(&hp), dot(&hq))
    }

    /// (p, q) at x given by (1 + x, 1 - x).
    pub(crate) fn tractions(&self, opx: f64, omx: f64) -> (f64, f64) {
        self.tractions_at(&self.frame.locate(opx, omx))
    }

    /// int p and int q.
    #[cfg(test)]
    pub(crate) fn forces(&self) -> (f64, f64) {
        let (ip, iq) = self.frame.integrals();
        let dot = |v: &[f64]| v.iter().zip(&self.coef).map(|(a, b)| a * b).sum::<f64>();
        (dot(&ip), dot(&iq))
    }

    /// The largest residual of H[p] = bp q, relative to bp mu p (to p when bp = 0), and of the
    /// stick rows H[q] + bq p = forcing(1 + x, 1 - x), relative to bq p, at 37 points per zone
    /// midway between Chebyshev points (the checks of docs/theory_tangential.md sections 12,
    /// 14 and 15); asserts p > 0 at every point and |q| <= mu p on the stick zones (not on a
    /// corner zone, whose outer field holds only above its inner region).
    #[cfg(test)]
    pub(crate) fn residual_between_points(&self, forcing: &dyn Fn(f64, f64) -> f64) -> f64 {
        let (f, k) = (&self.frame, &self.frame.k);
        let mut worst = 0.0f64;
        for zone in 0..f.zone_count() {
            let len = f.zone_len(zone);
            for i in 0..37 {
                let th = (i as f64 + 1.0) * std::f64::consts::PI / 38.0;
                let (a, b) = ((0.5 * th).sin().powi(2), (0.5 * th).cos().powi(2));
                let l = Loc {
                    zone,
                    from_lo: len * a,
                    to_hi: len * b,
                };
                let (opx, omx) = f.offsets(&l);
                let (p, q) = self.tractions_at(&l);
                let (hp, hq) = self.hilbert_at(&l);
                let scale = if k.bp > 0.0 { k.bp * k.mu * p } else { p };
                worst = worst.max((hp - k.bp * q).abs() / scale);
                if f.is_stick(zone) {
                    let r2 = hq + k.bq * p - forcing(opx, omx);
                    worst = worst.max(r2.abs() / (k.bq * p));
                    // a corner zone's outer field holds only above its inner region
                    // (docs/theory_tangential.md section 20)
                    if !f.is_corner(zone) {
                        assert!(q.abs() <= k.mu * p * (1.0 + 1e-9), "|q| > mu p at {opx}");
                    }
                }
                assert!(p > 0.0 || f.is_corner(zone), "p = {p} at 1 + x = {opx}");
            }
        }
        worst
    }
}
