//! Speed against accuracy: every method at every resolution it offers, on a fixed set of
//! scenes, timed per solve and compared with a high-accuracy COUPLED solution computed in the
//! same run (error in c, and max traction error on |x| <= 0.99); AUTO at the default tolerance
//! is timed too, its row named for the method it chose. COUPLED runs as METHOD_COUPLED does
//! (`coupled::solve_to`, the tolerance on c and on the tractions), "COUPLED (TRACTIONS 1E-8)"
//! at the speed target's accuracy (c to 1e-10, tractions to 1e-8), "ROOT SEARCH" is
//! `coupled::solve` at 1e-10 (the panels' own root search, without the tabulated c) and
//! "C ALONE" COUPLED asked for c only (traction tolerance +infinity).
//!
//! Run: `cargo run --release --example speed_accuracy` (one core is enough; ~6 minutes;
//! writes docs/speed_accuracy.csv, docs/speed_accuracy_medians.md and
//! docs/speed_accuracy.svg). `--quick` skips LCP at N = 3200 (~10 s per solve);
//! `--from-csv` redraws the table and chart from an existing docs/speed_accuracy.csv;
//! `--only METHOD` (e.g. `--only SPENCE`) times that method alone against the same references
//! and prints its rows and medians without writing any file. `--corners` times the methods
//! (LCP up to N = 800) on scenes at the corners of the reduced plane instead (tiny stick
//! zone, thin slip zones, large friction, b* -> 1) and writes
//! docs/speed_accuracy_corners.{csv,md}, one row per scene and method.

mod support;

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use orthoslip::{Contact, Coupling, Material, Profile, coupled, goodman, lcp, spence};
use support::plot::{Scale, Series, chart};

/// A scene: a name, a material and a friction coefficient.
struct Scene {
    name: String,
    coupling: Coupling,
    contact: Contact,
}

/// Scenes at the corners of the reduced plane (docs/theory.md (R2): the material
/// `effective(1, 1 - 2 b*, 1, 1)` with mu = mu~): (b*, mu~, what is extreme there).
const CORNERS: [(f64, f64, &str); 8] = [
    (0.3, 0.01, "stick zone c ~ 1e-21 (full slip)"),
    (0.02, 1.0, "slip zones 1 - c ~ 4e-53 (near-bonded)"),
    (0.2, 5.0, "slip zones 1 - c ~ 8e-9"),
    (0.45, 1e4, "large friction, g = 7e-5"),
    (0.83, 1e3, "large friction at large b*, g = 4e-4"),
    (0.99, 30.0, "b* -> 1"),
    (0.99995, 10.0, "auxetic extreme, nu = -0.9999"),
    (
        0.999999,
        10.0,
        "auxetic limit, 1 - b* = 1e-6 (c extrapolated in b*)",
    ),
];

fn corner_scenes() -> Vec<Scene> {
    CORNERS
        .iter()
        .map(|&(b, mu, what)| {
            let m = Material::effective(1.0, 1.0 - 2.0 * b, 1.0, 1.0).unwrap();
            let mut contact = Contact::new(m);
            contact.set_friction(mu).unwrap();
            Scene {
                name: format!("b* = {b}, mu~ = {mu:e}: {what}"),
                coupling: m.coupling(mu),
                contact,
            }
        })
        .collect()
}

fn scenes() -> Vec<Scene> {
    let materials = support::scene_materials();
    let mut out = Vec::new();
    for (name, m) in materials {
        for mu in [0.1, 0.3, 1.0] {
            let mut contact = Contact::new(m);
            contact.set_friction(mu).unwrap();
            out.push(Scene {
                name: format!("{name}, mu = {mu}"),
                coupling: m.coupling(mu),
                contact,
            });
        }
    }
    out
}

/// Median wall time of repeated solves (at least 3 runs and 0.2 s, at most 200 runs).
fn time_solve<P>(solve: impl Fn() -> orthoslip::Result<P>) -> Option<(Duration, P)> {
    let mut times = Vec::new();
    let start = Instant::now();
    let mut last = None;
    while times.len() < 3 || (start.elapsed() < Duration::from_millis(200) && times.len() < 200) {
        let t = Instant::now();
        let r = solve().ok()?;
        times.push(t.elapsed());
        last = Some(r);
        if times.len() == 1 && times[0] > Duration::from_secs(2) {
            break;
        }
    }
    times.sort();
    Some((times[times.len() / 2], last?))
}

/// Max traction error on |x| <= 0.99 relative to the reference's scale.
fn traction_error(s: &dyn Profile, r: &dyn Profile) -> f64 {
    let xs: Vec<f64> = (0..=198).map(|i| -0.99 + 0.01 * i as f64).collect();
    let refs: Vec<(f64, f64)> = xs.iter().map(|&x| r.tractions(x)).collect();
    let q_scale = refs
        .iter()
        .fold(0.0_f64, |m, t| m.max(t.1.abs()))
        .max(1e-300);
    xs.iter()
        .zip(&refs)
        .map(|(&x, &(pr, qr))| {
            let (p, q) = s.tractions(x);
            ((p - pr).abs() / pr).max((q - qr).abs() / q_scale)
        })
        .fold(0.0, f64::max)
}

struct Row {
    scene: String,
    method: &'static str,
    resolution: String,
    seconds: f64,
    c: f64,
    c_error: f64,
    estimate: f64,
    traction_error: f64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let only = args
        .iter()
        .position(|a| a == "--only")
        .map(|i| args.get(i + 1).ok_or("--only needs a method name"))
        .transpose()?
        .map(|m| m.to_uppercase());
    if only.is_some() {
        let rows = measure(scenes(), true, only.as_deref())?;
        return report(&rows, false);
    }
    if args.iter().any(|a| a == "--corners") {
        std::fs::create_dir_all("docs")?;
        let rows = measure(corner_scenes(), true, None)?;
        write_csv(&rows, "docs/speed_accuracy_corners.csv")?;
        return corner_table(&rows);
    }
    std::fs::create_dir_all("docs")?;
    let rows = if args.iter().any(|a| a == "--from-csv") {
        read_csv(&std::fs::read_to_string("docs/speed_accuracy.csv")?)?
    } else {
        let rows = measure(scenes(), args.iter().any(|a| a == "--quick"), None)?;
        write_csv(&rows, "docs/speed_accuracy.csv")?;
        rows
    };
    report(&rows, true)
}

/// Times every method (or only the one named) at every resolution on every scene (a scene
/// whose reference fails is reported and left out).
fn measure(
    scenes: Vec<Scene>,
    quick: bool,
    only: Option<&str>,
) -> Result<Vec<Row>, Box<dyn std::error::Error>> {
    let wanted = |method: &str| only.is_none_or(|m| m == method);
    let mut rows = Vec::new();
    for scene in &scenes {
        let k = scene.coupling;
        // the most accurate COUPLED that converges (1e-13 on the 12 scenes; the corners
        // may need 1e-10)
        let reference = match [1e-12, 1e-11, 1e-10]
            .iter()
            .fold(coupled::solve(&k, 1e-13), |r, &tol| {
                r.or_else(|_| coupled::solve(&k, tol))
            }) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("{}: reference failed, scene left out: {e}", scene.name);
                continue;
            }
        };
        let c_ref = reference.edge().c;
        eprintln!(
            "{}: c = {c_ref:.15} (+- {:.1e})",
            scene.name,
            reference.numerical_error()
        );
        let mut record =
            |method: &'static str, resolution: String, t: Duration, s: &dyn Profile| {
                rows.push(Row {
                    scene: scene.name.clone(),
                    method,
                    resolution,
                    seconds: t.as_secs_f64(),
                    c: s.edge().c,
                    c_error: (s.edge().c - c_ref).abs(),
                    estimate: s.numerical_error(),
                    traction_error: traction_error(s, &reference),
                })
            };
        if wanted("AUTO")
            && let Some((t, s)) = time_solve(|| scene.contact.solve())
        {
            let chosen = format!("default tol: {:?}", s.method()).to_uppercase();
            record("AUTO", chosen, t, s.profile());
        }
        if wanted("GOODMAN")
            && let Some((t, s)) = time_solve(|| goodman::solve(&k))
        {
            record("GOODMAN", "-".into(), t, &s);
        }
        if wanted("SPENCE")
            && let Some((t, s)) = time_solve(|| spence::solve(&k))
        {
            record("SPENCE", "-".into(), t, &s);
        }
        // COUPLED as METHOD_COUPLED runs it (tolerance tol on c and on the tractions)
        for tol in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
            if wanted("COUPLED")
                && let Some((t, s)) = time_solve(|| coupled::solve_to(&k, tol, tol))
            {
                record("COUPLED", format!("tol {tol:.0e}"), t, &s);
            }
        }
        // the speed target's accuracy: c to 1e-10, tractions to 1e-8
        if wanted("COUPLED (TRACTIONS 1E-8)")
            && let Some((t, s)) = time_solve(|| coupled::solve_to(&k, 1e-10, 1e-8))
        {
            record("COUPLED (TRACTIONS 1E-8)", "tol 1e-10".into(), t, &s);
        }
        // the root search alone (no tabulated c), for the ratio
        if wanted("ROOT SEARCH")
            && let Some((t, s)) = time_solve(|| coupled::solve(&k, 1e-10))
        {
            record("ROOT SEARCH", "tol 1e-10".into(), t, &s);
        }
        // c alone: COUPLED with a traction tolerance of +infinity
        for tol in [1e-6, 1e-8, 1e-10] {
            if wanted("C ALONE")
                && let Some((t, s)) = time_solve(|| coupled::solve_to(&k, tol, f64::INFINITY))
            {
                record("C ALONE", format!("tol {tol:.0e}"), t, &s);
            }
        }
        let max_n = if !wanted("LCP") {
            0
        } else if quick {
            800
        } else {
            3200
        };
        let mut n = 50;
        while n <= max_n {
            if let Some((t, s)) = time_solve(|| lcp::solve(&k, n)) {
                record("LCP", format!("N {n}"), t, &s);
            }
            n *= 2;
        }
    }
    Ok(rows)
}

const CSV_HEADER: &str =
    "scene,method,resolution,seconds_per_solve,c,c_error,own_estimate,traction_error\n";

fn write_csv(rows: &[Row], path: &str) -> std::io::Result<()> {
    let mut csv = String::from(CSV_HEADER);
    for r in rows {
        let _ = writeln!(
            csv,
            "\"{}\",{},{},{:e},{:.16e},{:e},{:e},{:e}",
            r.scene,
            r.method,
            r.resolution,
            r.seconds,
            r.c,
            r.c_error,
            r.estimate,
            r.traction_error
        );
    }
    std::fs::write(path, csv)
}

/// The corner scenes' rows as a table (docs/speed_accuracy_corners.md): the closed forms,
/// COUPLED at 1e-8 and 1e-10, c alone at 1e-10, AUTO and LCP at N = 800.
fn corner_table(rows: &[Row]) -> Result<(), Box<dyn std::error::Error>> {
    let shown = |r: &Row| match r.method {
        "COUPLED" => r.resolution == "tol 1e-8" || r.resolution == "tol 1e-10",
        "C ALONE" => r.resolution == "tol 1e-10",
        "LCP" => r.resolution == "N 800",
        _ => true,
    };
    let mut md = String::from(
        "| scene | method | resolution | time per solve | error in c | own numerical estimate (GOODMAN, SPENCE: without their model error) | traction error (\\|x\\| <= 0.99) |\n|---|---|---|---|---|---|---|\n",
    );
    for r in rows.iter().filter(|r| shown(r)) {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {:.1e} | {:.1e} | {:.1e} |",
            r.scene,
            r.method,
            r.resolution,
            fmt_time(r.seconds),
            r.c_error,
            r.estimate,
            r.traction_error
        );
    }
    std::fs::write("docs/speed_accuracy_corners.md", &md)?;
    println!("{md}");
    println!("wrote docs/speed_accuracy_corners.csv, docs/speed_accuracy_corners.md");
    Ok(())
}

/// Rows from a CSV written by [`write_csv`] (scene names are quoted and contain commas).
fn read_csv(text: &str) -> Result<Vec<Row>, Box<dyn std::error::Error>> {
    let methods = [
        "AUTO",
        "GOODMAN",
        "SPENCE",
        "COUPLED",
        "COUPLED (TRACTIONS 1E-8)",
        "ROOT SEARCH",
        "C ALONE",
        "LCP",
    ];
    let mut rows = Vec::new();
    for line in text.lines().skip(1) {
        let (scene, rest) = line[1..].split_once("\",").ok_or("bad CSV line")?;
        let f: Vec<&str> = rest.split(',').collect();
        let num = |i: usize| f[i].parse::<f64>();
        rows.push(Row {
            scene: scene.to_string(),
            method: methods
                .into_iter()
                .find(|m| *m == f[0])
                .ok_or("bad method")?,
            resolution: f[1].to_string(),
            seconds: num(2)?,
            c: num(3)?,
            c_error: num(4)?,
            estimate: num(5)?,
            traction_error: num(6)?,
        });
    }
    Ok(rows)
}

/// The table of medians over the scenes and the chart of the medians with their Pareto
/// front (written to docs/ when `write` is set; otherwise the rows and the table are printed).
fn report(rows: &[Row], write: bool) -> Result<(), Box<dyn std::error::Error>> {
    if !write {
        for r in rows {
            println!(
                "{}: {} {} {} c = {:.15e} (error {:.1e}), traction error {:.1e}",
                r.scene,
                r.method,
                r.resolution,
                fmt_time(r.seconds),
                r.c,
                r.c_error,
                r.traction_error
            );
        }
    }
    // Medians over scenes per (method, resolution).
    let mut keys: Vec<(&str, String)> = Vec::new();
    for r in rows {
        if !keys.iter().any(|k| k.0 == r.method && k.1 == r.resolution) {
            keys.push((r.method, r.resolution.clone()));
        }
    }
    // Errors below 1e-16 are rounding: the chart's floor.
    let median = |mut v: Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let mut md = String::from(
        "| method | resolution | median time per solve | median error in c | median traction error (|x| <= 0.99) | scenes |\n|---|---|---|---|---|---|\n",
    );
    let mut medians: Vec<(&str, f64, f64)> = Vec::new();
    for (method, res) in &keys {
        let sel: Vec<&Row> = rows
            .iter()
            .filter(|r| r.method == *method && &r.resolution == res)
            .collect();
        let t = median(sel.iter().map(|r| r.seconds).collect());
        let e = median(sel.iter().map(|r| r.c_error).collect());
        let te = median(sel.iter().map(|r| r.traction_error).collect());
        writeln!(
            md,
            "| {method} | {res} | {} | {e:.1e} | {te:.1e} | {} |",
            fmt_time(t),
            sel.len()
        )?;
        medians.push((method, t, e.max(1e-16)));
    }
    print!("{md}");
    if !write {
        return Ok(());
    }
    std::fs::write("docs/speed_accuracy_medians.md", &md)?;

    // Chart: median error in c against median time per solve, one series per method
    // (its resolutions joined), and the Pareto front of those medians.
    let mut series: Vec<Series> = Vec::new();
    for method in [
        "GOODMAN",
        "SPENCE",
        "LCP",
        "COUPLED",
        "ROOT SEARCH",
        "C ALONE",
    ] {
        let pts: Vec<(f64, f64)> = medians
            .iter()
            .filter(|m| m.0 == method)
            .map(|m| (m.1, m.2))
            .collect();
        if !pts.is_empty() {
            series.push(Series {
                name: method.to_string(),
                points: pts,
                line: true,
            });
        }
    }
    let mut all: Vec<(f64, f64)> = medians.iter().map(|m| (m.1, m.2)).collect();
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut front = Vec::new();
    let mut best = f64::INFINITY;
    for p in all {
        if p.1 < best {
            best = p.1;
            front.push(p);
        }
    }
    chart(
        "docs/speed_accuracy.svg",
        "median error in c against median time per solve (12 scenes)",
        ("median time per solve [s]", Scale::Log),
        ("median |c - c_exact|", Scale::Log),
        &series,
        Some(&Series {
            name: "Pareto front".into(),
            points: front,
            line: true,
        }),
    )?;
    println!(
        "wrote docs/speed_accuracy.csv, docs/speed_accuracy_medians.md, docs/speed_accuracy.svg"
    );
    Ok(())
}

fn fmt_time(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.1} us", t * 1e6)
    } else if t < 1.0 {
        format!("{:.2} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}
