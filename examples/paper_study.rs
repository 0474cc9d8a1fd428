//! The paper's study (its section 5), reproduced: for several orthotropic materials, the
//! stick half-width c against mu by Goodman's and Spence's approximations and by the exact
//! coupled solution, and the traction distributions p(x), q(x).
//!
//! Run: `cargo run --release --example paper_study` (writes docs/study_*.csv and .svg).

mod support;

use std::fmt::Write as _;

use orthoslip::{Contact, Material, Method};
use support::plot::{Scale, Series, chart};

/// The materials of the study: name, and the material.
fn materials() -> Vec<(&'static str, Material)> {
    vec![
        (
            "carbon/epoxy ply (plane stress)",
            Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28).unwrap(),
        ),
        (
            "same ply rotated, E11 <-> E22",
            Material::plane_stress(10.3e9, 181e9, 7.17e9, 0.28 * 10.3 / 181.0).unwrap(),
        ),
        (
            "glass/epoxy ply (plane stress)",
            Material::plane_stress(38.6e9, 8.27e9, 4.14e9, 0.26).unwrap(),
        ),
        (
            "isotropic steel (plane strain)",
            Material::plane_strain(210e9, 210e9, 210e9, 210e9 / 2.6, 0.3, 0.3, 0.3).unwrap(),
        ),
    ]
}

const METHODS: [Method; 3] = [Method::Goodman, Method::Spence, Method::Coupled];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all("docs")?;
    let mus: Vec<f64> = (0..=40)
        .map(|i| 10f64.powf(-2.0 + 3.0 * i as f64 / 40.0))
        .collect();
    let mut csv = String::from("material,method,mu,c,one_minus_c,error_estimate\n");
    for (slug, (name, material)) in materials().into_iter().enumerate() {
        let mut contact = Contact::new(material);
        let mut series = Vec::new();
        for method in METHODS {
            contact.set_method(method);
            let mut points = Vec::new();
            for &mu in &mus {
                contact.set_friction(mu)?;
                match contact.solve() {
                    Ok(s) => {
                        writeln!(
                            csv,
                            "{name},{method:?},{mu:e},{:e},{:e},{:e}",
                            s.c(),
                            s.one_minus_c(),
                            s.error_estimate()
                        )?;
                        points.push((mu, s.c()));
                    }
                    Err(e) => eprintln!("{name}, {method:?}, mu = {mu:e}: {e}"),
                }
            }
            if !points.is_empty() {
                series.push(Series {
                    name: format!("{method:?}"),
                    points,
                    line: true,
                });
            }
        }
        chart(
            &format!("docs/study_c_vs_mu_{slug}.svg"),
            &format!("stick half-width c against friction: {name}"),
            ("friction coefficient mu", Scale::Log),
            ("c / a", Scale::Linear),
            &series,
            None,
        )?;
        // Traction distributions at mu = 0.3 by every method.
        contact.set_friction(0.3)?;
        let xs: Vec<f64> = (0..=200)
            .map(|i| -0.995 + 1.99 * i as f64 / 200.0)
            .collect();
        let mut p_series = Vec::new();
        for method in METHODS {
            contact.set_method(method);
            if let Ok(s) = contact.solve() {
                let tr: Vec<(f64, f64)> = xs.iter().map(|&x| s.tractions(x)).collect();
                p_series.push(Series {
                    name: format!("p, {method:?}"),
                    points: xs.iter().zip(&tr).map(|(&x, t)| (x, t.0)).collect(),
                    line: true,
                });
                p_series.push(Series {
                    name: format!("q, {method:?}"),
                    points: xs.iter().zip(&tr).map(|(&x, t)| (x, t.1)).collect(),
                    line: true,
                });
            }
        }
        chart(
            &format!("docs/study_tractions_{slug}.svg"),
            &format!("tractions per P/a at mu = 0.3: {name}"),
            ("x / a", Scale::Linear),
            ("p, q", Scale::Linear),
            &p_series,
            None,
        )?;
    }
    std::fs::write("docs/study_c_vs_mu.csv", csv)?;
    println!("wrote docs/study_c_vs_mu.csv and docs/study_*.svg");
    Ok(())
}
