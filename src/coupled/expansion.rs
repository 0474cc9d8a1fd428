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
use crate::field::{Expand, Expansion, Exponents, Family, Panel, fit, graded_plain, sample};
use crate::numerics::cauchy::Weight;

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

impl Expand for CoupledSolution {
    fn expansion(&self) -> Expansion {
        match &self.regime {
            Regime::Panels(d) => from_discrete(d, self.delta),
            Regime::Spectral(_) => {
                let g = self.coupling.reduced().0.edge_exponent();
                sample(self, Exponents { edge: g, stick: g })
            }
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
}
