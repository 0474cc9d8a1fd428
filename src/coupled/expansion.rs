//! COUPLED's tractions as the field's [`Expansion`], from its own panels: each panel's blocks
//! are weighted Legendre families already (the weights carry (1 - x)^(-g), (x - c)^g,
//! (c - x)^g). The wrong-c modes are left out: their coefficient vanishes at the physical c
//! (it is the root function), and `tractions` leaves them out too. The central panel,
//! whose series are in Y = 2 x^2 / l^2 - 1, is resampled as a plain panel on [0, l] (p and
//! q / x are polynomials in x^2, so the fit is exact). The panels at c with a log weight
//! ((1 -+ t)^g - 1) / g (large friction, g below [`super::mesh::LOG_BELOW`]) are resampled as
//! plain panels graded towards c ([`graded_at_c`]). q = delta q~.

use super::mesh::{self, Pt};
use super::{CoupledSolution, Discrete, Regime};
use crate::field::{
    Expand, Expansion, Exponents, Family, Panel, fit, fitted_panel, graded, graded_plain, sample,
};
use crate::numerics::cauchy::Weight;
use crate::spectral::Spectral;

/// A panel at c whose basis holds a log weight, as plain panels graded towards c
/// ([`graded_plain`]): the field takes Jacobi weights, and the log weight split into its
/// parts (1 -+ t)^g / g and -1 / g left the near-field transforms' own rounding multiplied by
/// 1 / g (at b* = 0.7, mu~ = 1e6, g = 4.5e-7, the slip came out wrong in sign inside that
/// panel). The ends are the mesh's own points (Pt::from_edge), so that they meet its other
/// panels exactly.
fn graded_at_c(d: &Discrete, panel: &mesh::Panel, delta: f64) -> Vec<Panel> {
    let (c, w) = (d.mesh.c, d.mesh.w);
    let at = |s: f64| Pt::from_edge(c, w, s);
    let span = if panel.stick { -2.0 } else { 2.0 } * panel.h;
    graded_plain(
        span,
        |s| at(s).x,
        |s| {
            let (p, q) = d.eval(at(s));
            (p, delta * q)
        },
    )
}

/// Adds `coef` (times `scale`) to the p or q series of the family with `weight`.
fn add(families: &mut Vec<Family>, weight: Weight, coef: &[f64], scale: f64, is_q: bool) {
    let i = match families.iter().position(|f| f.weight == weight) {
        Some(i) => i,
        None => {
            families.push(Family {
                weight,
                p: Vec::new(),
                q: Vec::new(),
            });
            families.len() - 1
        }
    };
    let series = if is_q {
        &mut families[i].q
    } else {
        &mut families[i].p
    };
    if series.len() < coef.len() {
        series.resize(coef.len(), 0.0);
    }
    for (s, c) in series.iter_mut().zip(coef) {
        *s += scale * c;
    }
}

fn from_discrete(d: &Discrete, delta: f64) -> Expansion {
    let g = d.k.g;
    let has_log = |panel: &mesh::Panel| {
        let mut blocks = panel.p.iter().chain(&panel.q);
        blocks.any(|b| b.basis.weight(g).log_parts().is_some())
    };
    let panels = d
        .mesh
        .panels
        .iter()
        .flat_map(|panel| {
            if has_log(panel) {
                return graded_at_c(d, panel, delta);
            }
            let (a, b) = (panel.a.x, panel.b.x);
            if panel.central {
                let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
                let at = |t: f64| {
                    let x = m + h * t;
                    d.eval(Pt { x, u: 1.0 - x })
                };
                return vec![Panel {
                    a,
                    b,
                    families: vec![Family {
                        weight: Weight::One,
                        p: fit(|t| at(t).0),
                        q: fit(|t| delta * at(t).1),
                    }],
                }];
            }
            let mut families = Vec::new();
            let mut col = panel.p_offset;
            let mut p_blocks = Vec::new();
            for block in &panel.p {
                p_blocks.push((block.basis, &d.coef[col..col + block.count]));
                col += block.count;
            }
            for &(basis, coef) in p_blocks.iter().filter(|(b, _)| !b.is_wrong_c()) {
                add(&mut families, basis.weight(g), coef, 1.0, false);
                if !panel.stick {
                    add(&mut families, basis.weight(g), coef, delta * d.k.mu, true);
                }
            }
            let mut col = panel.q_offset;
            for block in &panel.q {
                let coef = &d.coef[col..col + block.count];
                col += block.count;
                if !block.basis.is_wrong_c() {
                    add(&mut families, block.basis.weight(g), coef, delta, true);
                }
            }
            vec![Panel { a, b, families }]
        })
        .collect();
    Expansion { panels }
}

/// Makes a Legendre series on [-1, 1] vanish at t = -1 by taking off its value there times
/// (1 - t) / 2 (the right end unchanged). q is odd, so q(0) = 0 exactly, but the fit of
/// the panel starting at x = 0 returns it to the tractions' rounding noise; the mirror then
/// makes that a jump of twice it at x = 0, and the field's sxx grows like its logarithm in
/// the depth (steel, mu = 0.3: noise 1.4e-11, sxx 1.2e-9 off its surface value at depth
/// 1e-10, larger than at 1e-8).
fn vanish_at_left_end(coef: &mut [f64]) {
    let v: f64 = coef
        .iter()
        .enumerate()
        .map(|(k, c)| if k % 2 == 0 { *c } else { -*c })
        .sum();
    if coef.len() >= 2 {
        coef[0] -= 0.5 * v;
        coef[1] += 0.5 * v;
    }
}

/// The spectral solution as panels of the field's families, exact in form: the panels touching
/// c carry its split q = q_plain + (c - x)^g q_edge (stick side) and p = p_plain +
/// (x - c)^g p_edge (slip side) as a plain family plus one weighted at c, each smooth there
/// (`Fixed::stick_split`, `Fixed::slip_split`); the panels graded away from c on both sides
/// are plain (the (c -+ x)^g at least their width away); the last, [(1 + c)/2, 1], carries
/// (1 - t)^(-g). The panels at c are min(c, 1 - c) / 2 wide: the bases' poles lie at
/// least (1 - c) / 10 and c / 10 beyond the zones, so the fits' cofactors are analytic over
/// twice the panels' width at least. q = delta q~, and q~ = mu~ p on the slip zone.
fn from_spectral(s: &Spectral, delta: f64) -> Expansion {
    let f = &s.fixed;
    let (c, w) = (s.edge.c, s.edge.one_minus_c);
    let (g, mu) = (f.basis.k.g, f.basis.k.mu);
    let near = 0.5 * c.min(w);
    let h = 0.5 * near;
    let plain = |a: f64, b: f64| {
        let (m, hw) = (0.5 * (a + b), 0.5 * (b - a));
        let at = |t: f64| f.at(m + hw * t);
        let p = fit(|t| at(t).0);
        let q = if a >= c {
            p.iter().map(|v| delta * mu * v).collect()
        } else {
            let mut q = fit(|t| delta * at(t).1);
            if a == 0.0 {
                vanish_at_left_end(&mut q);
            }
            q
        };
        Panel {
            a,
            b,
            families: vec![Family {
                weight: Weight::One,
                p,
                q,
            }],
        }
    };
    let mut panels = Vec::new();
    // stick side: [0, c - d_last], ..., [c - d_1, c - d_0], then the split panel at c
    let stick: Vec<f64> = graded(near, c);
    let mut left = 0.0;
    for &d in stick.iter().rev() {
        if c - d > left {
            panels.push(plain(left, c - d));
            left = c - d;
        }
    }
    // c - x = h (1 - t) on [c - near, c]
    let split = |t: f64| f.stick_split(c - h * (1.0 - t));
    let scale = h.powf(g);
    panels.push(Panel {
        a: left,
        b: c,
        families: vec![
            Family {
                weight: Weight::One,
                p: fit(|t| split(t).0),
                q: fit(|t| delta * split(t).1),
            },
            Family {
                weight: Weight::Right(g),
                p: vec![0.0],
                q: fit(|t| delta * scale * split(t).2),
            },
        ],
    });
    // slip side: x - c = h (1 + t) on [c, c + near]
    let split = |t: f64| f.slip_split(c + h * (1.0 + t));
    let p_plain = fit(|t| split(t).0);
    let p_edge = fit(|t| scale * split(t).1);
    let times = |v: &[f64]| v.iter().map(|x| delta * mu * x).collect();
    panels.push(Panel {
        a: c,
        b: c + near,
        families: vec![
            Family {
                weight: Weight::One,
                q: times(&p_plain),
                p: p_plain,
            },
            Family {
                weight: Weight::Left(g),
                q: times(&p_edge),
                p: p_edge,
            },
        ],
    });
    let end = c + 0.5 * w;
    let mut right = c + near;
    for &d in graded(near, 0.5 * w).iter().skip(1) {
        if c + d < end && c + d > right {
            panels.push(plain(right, c + d));
            right = c + d;
        }
    }
    if end > right {
        panels.push(plain(right, end));
    }
    panels.push(fitted_panel(end, 1.0, Weight::Right(-g), |omt, _| {
        let (p, _) = f.at(1.0 - 0.25 * w * omt);
        (p, delta * mu * p)
    }));
    Expansion { panels }
}

impl Expand for CoupledSolution {
    fn expansion(&self) -> Expansion {
        match &self.regime {
            Regime::Panels(d) => from_discrete(d, self.delta),
            Regime::Spectral(s) => from_spectral(s, self.delta),
            Regime::Uncoupled(g) | Regime::Tabulated(g) => g.expansion(),
            Regime::FullSlip(f) => f.expansion(),
            Regime::NearBonded(b) => b.expansion(),
            Regime::LargeFriction(l) => l.expansion(),
            // mu = 0: p = p0 exactly, q = 0
            Regime::Frictionless => sample(
                self,
                Exponents {
                    edge: 0.5,
                    stick: 0.5,
                },
            ),
        }
    }

    fn edge_intensity(&self, e: &Expansion) -> Option<(f64, f64)> {
        match &self.regime {
            Regime::NearBonded(b) => b.edge_intensity(e),
            _ => e.edge_intensity(),
        }
    }
}
