//! Collocation points of the half problem (docs/theory_spectral.md, (C1)): Chebyshev points of
//! each zone, plus points spaced geometrically towards x = c from both sides over the decades
//! the poles span (down to a hundredth of the smaller of c and 1 - c relative to the zone).

/// A point 0 <= x < 1 with its offsets 1 - x and x - c, each to full relative accuracy.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Pt {
    pub(crate) x: f64,
    pub(crate) omx: f64,
    pub(crate) xmc: f64,
}

impl Pt {
    /// The point 0 <= x < 1 for the stick edge c, on the stick side at x = c.
    pub(crate) fn at(x: f64, c: f64) -> Self {
        let xmc = x - c;
        Pt {
            x,
            omx: 1.0 - x,
            xmc: if xmc == 0.0 { -0.0 } else { xmc },
        }
    }

    /// The point with 1 - x = `omx` (0 < omx <= 1 - c) for the slip width w = 1 - c, its offset
    /// x - c taken as w - omx (from a rounded x it would lose eps / w of the zone), on the
    /// stick side where that is 0.
    pub(crate) fn from_end(omx: f64, w: f64) -> Self {
        let xmc = w - omx;
        Pt {
            x: 1.0 - omx,
            omx,
            xmc: if xmc == 0.0 { -0.0 } else { xmc },
        }
    }

    /// Whether the point lies on the stick zone: x < c, or x = c from the stick side (xmc = -0.0,
    /// where the edge factors (c - x)^g vanish as they do in the limit; at
    /// xmc = -f64::MIN_POSITIVE they were (2e-308)^g, 1e-9 at g = 0.03 and 1e-3 at g = 0.01,
    /// docs/theory_spectral.md section 7).
    pub(crate) fn on_stick(&self) -> bool {
        self.xmc < 0.0 || (self.xmc == 0.0 && self.xmc.is_sign_negative())
    }
}

/// Geometric points per decade towards the ends.
const PER_DECADE: f64 = 3.0;

/// The slip zone's geometric cluster starts at this fraction of the zone.
const CLUSTER_FROM: f64 = 0.1;

/// The stick zone's geometric cluster starts at this fraction of the zone, where its
/// Chebyshev points thin out: at level 1.5 the nearest lies 2e-3 c from x = c, so from a
/// tenth of the zone down to there the cluster's points only doubled theirs. Measured on
/// the 10 spectral speed scenes with the cluster towards x = 1 gone ([`collocation`]; c to
/// 1e-10; thread CPU time, the median over the scenes, alternated in one run; true error
/// against the panels at (1e-13, 1e-11)), both clusters from the same fraction:
///
/// | clusters from | tractions 1e-8 | largest true / estimate |
/// |---|---|---|
/// | 0.1 | 0.139 ms | 0.051 |
/// | 0.03 | 0.133 ms | 0.050 |
/// | 0.01 | 0.126 ms | 0.056 |
///
/// (every answer at the same level and within its estimate). The slip zone's cluster keeps
/// 0.1: from 0.01 there, `coupled::tests::spectral_agrees_with_the_panels_on_a_grid` caught
/// b* = 0.4933, mu~ = 0.1196 (c = 2.3e-3) answering 6.1e-9 from the panels against an
/// estimate of 6.8e-9 (from 0.1: 3.5e-12 against 5.7e-10), the slip tractions next to a
/// small stick zone varying on the scale c out to a tenth of the zone; the stick zone's
/// from 0.01 left that point and the slow tier's thin slip zones within their estimates.
/// Fewer points per decade instead (2, both from 0.1) let the ply at mu = 0.1
/// (c = 4.8e-5) answer 2.7e-9 from the panels against an estimate of 2.9e-9.
const STICK_CLUSTER_FROM: f64 = 0.01;

/// The clusters reach at least this fraction of the zone.
const CLUSTER_FLOOR: f64 = 1e-3;

/// The clusters reach down to this fraction of the smaller scale at the stick edge (the
/// nearest pole sits at a tenth of it, docs/theory_spectral.md (B4)).
const CLUSTER_DEPTH: f64 = 1e-2;

/// log-spaced fractions from `from` down to `depth`.
fn decades(from: f64, depth: f64) -> Vec<f64> {
    let n = ((from / depth).log10() * PER_DECADE).ceil().max(1.0) as usize;
    (0..=n)
        .map(|i| from * (depth / from).powf(i as f64 / n as f64))
        .collect()
}

/// Stick points (x < c) and slip points (x > c) for the stick edge c (1 - c = w), with about
/// `stick` and `slip` Chebyshev points.
///
/// No cluster towards x = 1: the edge exponent is in the slip families' weight, and the
/// Chebyshev points reach 1.5e-3 (1 - c) from the end at level 1.5. A cluster there of three
/// points per decade down to 1e-6 (1 - c) (16 rows, a fifth of level 1.5's) changed no
/// answer's level on the 10 spectral speed scenes and made them 1.14-1.16 times faster
/// (median 0.160 to 0.139 ms at tractions to 1e-8, 0.405 to 0.349 ms at 1e-10, alternated in
/// one run; largest true error / estimate against the panels 0.033 to 0.051 and 0.083 to
/// 0.093); down to 1e-3 or 1e-2 (1 - c) it gave 0.146 and 0.141 ms.
pub(crate) fn collocation(c: f64, w: f64, stick: usize, slip: usize) -> (Vec<Pt>, Vec<Pt>) {
    // the stick functions' poles sit at 1 + zeta, zeta >= (1 - c) / 10; the slip functions' at
    // -(c + eta), eta >= c / 10: the clusters reach a hundredth of those scales
    let (stick_depth, slip_depth) = (
        (CLUSTER_DEPTH * w / c).min(CLUSTER_FLOOR),
        (CLUSTER_DEPTH * c / w).min(CLUSTER_FLOOR),
    );
    let mut st = Vec::new();
    // tau = cos(theta), theta in (0, pi/2): c - x = c (1 - cos theta) = 2 c sin^2(theta / 2)
    for i in 0..stick {
        let th = (i as f64 + 0.5) * std::f64::consts::FRAC_PI_2 / stick as f64;
        let d = 2.0 * c * (0.5 * th).sin().powi(2);
        st.push(Pt {
            x: c - d,
            omx: w + d,
            xmc: -d,
        });
    }
    for f in decades(STICK_CLUSTER_FROM, stick_depth) {
        let d = c * f;
        st.push(Pt {
            x: c - d,
            omx: w + d,
            xmc: -d,
        });
    }
    let mut sl = Vec::new();
    // s = -cos(theta): x - c = w sin^2(theta / 2), 1 - x = w cos^2(theta / 2)
    for i in 0..slip {
        let th = (i as f64 + 0.5) * std::f64::consts::PI / slip as f64;
        let (a, b) = ((0.5 * th).sin().powi(2), (0.5 * th).cos().powi(2));
        sl.push(Pt {
            x: c + w * a,
            omx: w * b,
            xmc: w * a,
        });
    }
    for f in decades(CLUSTER_FROM, slip_depth) {
        sl.push(Pt {
            x: c + w * f,
            omx: w * (1.0 - f),
            xmc: w * f,
        });
    }
    (st, sl)
}

/// More slip points towards x = c for a small stick zone ([`super::system::SMALL_STICK_BELOW`]):
/// `per_decade` per decade of x - c over the range of [`collocation`]'s cluster there (from
/// [`CLUSTER_FROM`] of the slip zone down to [`CLUSTER_DEPTH`] c), log-spaced at the
/// midpoints of their own steps. The slip poles at x = -(c + eta) put the slip columns'
/// variation over the decades of x - c from c / 10 up (docs/theory_spectral.md (C1)).
pub(crate) fn small_stick_slip_points(c: f64, w: f64, per_decade: f64) -> Vec<Pt> {
    let depth = (CLUSTER_DEPTH * c / w).min(CLUSTER_FLOOR);
    let n = ((CLUSTER_FROM / depth).log10() * per_decade)
        .ceil()
        .max(1.0) as usize;
    (0..n)
        .map(|i| {
            let f = CLUSTER_FROM * (depth / CLUSTER_FROM).powf((i as f64 + 0.5) / n as f64);
            Pt {
                x: c + w * f,
                omx: w * (1.0 - f),
                xmc: w * f,
            }
        })
        .collect()
}
