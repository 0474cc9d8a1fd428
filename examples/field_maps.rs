//! What the default scene (the carbon/epoxy ply, plane stress, mu = 0.3) does to the solid:
//! contour maps of sxx, syy, sxy and the maximum in-plane shear stress under the punch (to
//! depth 2a), the surface stress sxx(x, 0) with the tractions, its edge singularity on log
//! axes against the documented asymptote, and the slip.
//!
//! Run: `cargo run --release --example field_maps` (writes docs/field_*.csv and .svg).

mod support;

use std::fmt::Write as _;

use orthoslip::{Contact, Material};
use support::plot::{Scale, Series, chart, contour_map};

/// The (lo, hi) quantiles of the finite values: the colour span of a map whose field is
/// singular at the punch edges.
fn span(values: &[Vec<f64>], lo: f64, hi: f64) -> (f64, f64) {
    let mut v: Vec<f64> = values
        .iter()
        .flatten()
        .copied()
        .filter(|v| v.is_finite())
        .collect();
    v.sort_by(f64::total_cmp);
    let at = |q: f64| v[((v.len() - 1) as f64 * q) as usize];
    (at(lo), at(hi))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all("docs")?;
    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28)?;
    let e = ply.constants();
    let mu = 0.3;
    let mut contact = Contact::new(ply);
    contact.set_friction(mu)?;
    let s = contact.solve()?;
    let c = s.c();
    let (k, g) = s.edge_intensity();
    let amplitude = -k * (e.delta * e.delta + (1.0 - e.nu) * mu * mu);
    println!(
        "default scene by {:?}: c = {c:.6}; edge: p ~ k (1 - |x|)^(-g), k = {k:.6}, g = {g:.6}; \
         sxx(x, 0) ~ A (1 - |x|)^(-g), A = -k (delta^2 + (1 - nu) mu^2) = {amplitude:.6}",
        s.method()
    );

    // maps under the punch: |x| <= 2, -2 <= y <= 0
    let xs: Vec<f64> = (0..=160).map(|i| -2.0 + 4.0 * i as f64 / 160.0).collect();
    let ys: Vec<f64> = (0..=80).map(|j| -2.0 + 2.0 * j as f64 / 80.0).collect();
    let mut fields = vec![vec![vec![0.0; xs.len()]; ys.len()]; 4];
    // the CSV on every other grid line
    let mut csv = String::from("x,y,sxx,syy,sxy,tau_max\n");
    for (j, &y) in ys.iter().enumerate() {
        for (i, &x) in xs.iter().enumerate() {
            let [sxx, syy, sxy] = s.stresses(x, y)?;
            // at the punch edges sxx = syy = -infinity: tau is infinite there too
            let tau = (0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy).sqrt();
            let tau = if tau.is_nan() { f64::INFINITY } else { tau };
            for (f, v) in fields.iter_mut().zip([sxx, syy, sxy, tau]) {
                f[j][i] = v;
            }
            if i % 2 == 0 && j % 2 == 0 {
                writeln!(csv, "{x},{y},{sxx:.6e},{syy:.6e},{sxy:.6e},{tau:.6e}")?;
            }
        }
    }
    std::fs::write("docs/field_map.csv", csv)?;
    let punch = [(-1.0, 0.0), (1.0, 0.0)];
    for (f, (name, what)) in fields.iter().zip([
        ("sxx", "sigma_xx"),
        ("syy", "sigma_yy"),
        ("sxy", "sigma_xy"),
        (
            "tau_max",
            "max in-plane shear sqrt(((sxx - syy)/2)^2 + sxy^2)",
        ),
    ]) {
        let (lo, hi) = span(f, 0.01, 0.99);
        contour_map(
            &format!("docs/field_{name}.svg"),
            &format!("{what} per P/a, carbon/epoxy ply, mu = 0.3 (punch in red)"),
            ("x / a", &xs),
            ("y / a", &ys),
            f,
            (lo, hi),
            14,
            &punch,
        )?;
    }

    // the surface: sxx(x, 0) with -p and q, points clustered at the punch and stick edges
    let mut xs: Vec<f64> = (0..=600).map(|i| -1.4 + 2.8 * i as f64 / 600.0).collect();
    for edge in [-1.0, -c, c, 1.0] {
        xs.extend((1..=40).flat_map(|i| {
            let d = 10f64.powf(-8.0 + 6.0 * i as f64 / 40.0);
            [edge - d, edge + d]
        }));
    }
    xs.sort_by(f64::total_cmp);
    let mut csv = String::from("x,p,q,sxx\n");
    let (mut sxx, mut p, mut q) = (Vec::new(), Vec::new(), Vec::new());
    for &x in &xs {
        let (pv, qv) = s.tractions(x);
        let v = s.stresses(x, 0.0)?[0];
        writeln!(csv, "{x},{pv:e},{qv:e},{v:e}")?;
        // the chart leaves out the last 1e-2 on both sides of the punch edges (singular)
        if (x.abs() - 1.0).abs() > 1e-2 {
            sxx.push((x, v));
            p.push((x, -pv));
            q.push((x, qv));
        }
    }
    std::fs::write("docs/field_surface.csv", csv)?;
    let line = |name: &str, points: Vec<(f64, f64)>| Series {
        name: name.into(),
        points,
        line: true,
    };
    chart(
        "docs/field_surface_sxx.svg",
        &format!("Surface stresses per P/a, carbon/epoxy ply, mu = 0.3 (stick zone |x| < {c:.3})"),
        ("x / a", Scale::Linear),
        ("stress per P/a", Scale::Linear),
        &[
            line("sigma_xx(x, 0)", sxx),
            line("sigma_yy(x, 0) = -p", p),
            line("sigma_xy(x, 0) = q", q),
        ],
        None,
    )?;

    // the edge: |sxx(x, 0)| and p against 1 - x on log axes, with the asymptotes
    let mut csv = String::from("one_minus_x,p,sxx,sxx_asymptote\n");
    let (mut sxx, mut p, mut asym_s, mut asym_p) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for i in 0..=90 {
        let d = 10f64.powf(-10.0 + 9.0 * i as f64 / 90.0);
        let x = 1.0 - d;
        let d = 1.0 - x;
        let v = s.stresses(x, 0.0)?[0];
        let pv = s.tractions(x).0;
        let a = amplitude * d.powf(-g);
        writeln!(csv, "{d:e},{pv:e},{v:e},{a:e}")?;
        sxx.push((d, -v));
        p.push((d, pv));
        asym_s.push((d, -a));
        asym_p.push((d, k * d.powf(-g)));
    }
    let ratio = s.stresses(1.0 - 1e-10, 0.0)?[0] / (amplitude * (1e-10f64).powf(-g));
    println!("sxx(1 - 1e-10, 0) / asymptote = {ratio:.9}");
    std::fs::write("docs/field_edge.csv", csv)?;
    chart(
        "docs/field_edge_sxx.svg",
        &format!(
            "Punch edge: -sxx(x, 0) ~ {:.4} (1 - x)^-{g:.4}, p ~ {k:.4} (1 - x)^-{g:.4}",
            -amplitude
        ),
        ("1 - x", Scale::Log),
        ("per P/a", Scale::Log),
        &[
            line("-sigma_xx(x, 0)", sxx),
            line("-A (1 - x)^-g", asym_s),
            line("p(x)", p),
            line("k (1 - x)^-g", asym_p),
        ],
        None,
    )?;

    // the slip
    let mut csv = String::from("x,slip\n");
    let mut slip = Vec::new();
    for i in 0..=520 {
        let x = -1.3 + 2.6 * i as f64 / 520.0;
        let u = s.slip(x)?;
        writeln!(csv, "{x},{u:e}")?;
        slip.push((x, u));
    }
    std::fs::write("docs/field_slip.csv", csv)?;
    chart(
        "docs/field_slip.svg",
        &format!(
            "Slip: tangential surface displacement relative to the punch, per P/E (|x| < {c:.3} sticks)"
        ),
        ("x / a", Scale::Linear),
        ("u per P/E", Scale::Linear),
        &[line("slip u(x)", slip)],
        None,
    )?;
    Ok(())
}
