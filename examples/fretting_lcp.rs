//! Fretting by the grid LCP with a loading history (issue 27; docs/theory_tangential.md):
//! the default scene's carbon/epoxy ply (plane stress, mu = 0.3) pressed by P, then Q cycled
//! +Q* -> -Q* -> +Q* at Q*/(mu P) = 0.3, 0.6, 0.9; the dissipation cycle by cycle, the stick
//! set against Q, the refinement table in the panels, and two isotropic-form scenes of
//! stronger coupling for contrast.
//!
//! Run: `cargo run --release --example fretting_lcp` (about 2 min on one core, most of it
//! the N = 800 row of the refinement table). Writes docs/fretting_lcp.csv, one row per
//! load step (kind = step: cycle 0 is the first loading; step = 1.. within the cycle), per
//! cycle (kind = cycle), per refinement level (kind = refine; step = steps per quarter,
//! c2 at +Q*, c1 at -Q*) and per step count (kind = steps; step = steps per quarter), with
//! energies in pi B P^2 and displacements in pi B P (default ply: times 1.3718 for P^2/E,
//! P/E); and docs/fretting_lcp_profiles.csv: p, q at +-Q* and the first cycle's slip
//! amplitude along the contact, N = 200.

use std::fmt::Write as _;
use std::time::Instant;

use orthoslip::lcp::history::{Cycles, State, Zone, cycles};
use orthoslip::{Coupling, Material};

/// Panels per half-width of the cycle runs, load steps per quarter cycle, cycles.
const N: usize = 200;
const STEPS: usize = 10;
const CYCLES: usize = 5;

fn count(s: &State, z: Zone) -> usize {
    s.zones.iter().filter(|&&v| v == z).count()
}

/// One line per cycle plus the stick set along the first loading and the first cycle.
fn report(name: &str, amp: f64, run: &Cycles, to_e: Option<f64>, csv: &mut String) {
    let in_e = |w: f64| to_e.map_or("n/a".to_string(), |f| format!("{:.5e}", w * f));
    let mu_amp = run.first_loading.last().map_or(0.0, |s| s.q_over_p);
    println!(
        "\n== {name}, Q*/(mu P) = {amp}, Q*/P = {mu_amp:.4}, N = {N}, {STEPS} steps per quarter"
    );
    println!(
        "normal load: stick set [{:.4}, {:.4}]",
        run.normal_load.stick.0, run.normal_load.stick.1
    );
    let w0: f64 = run.first_loading.iter().map(|s| s.dissipation).sum();
    let last = run.first_loading.last().unwrap_or(&run.normal_load);
    println!(
        "first loading 0 -> Q*: dissipation {w0:.5e} pi B P^2 = {} P^2/E; at Q*: moment int x p = {:+.5e} P a",
        in_e(w0),
        last.moment(run.h)
    );
    println!(" Q/P      c1        c2     slip- slip+   D (pi B P)   W_step");
    let mut all: Vec<(usize, usize, &State)> = run
        .first_loading
        .iter()
        .enumerate()
        .map(|(j, s)| (0, j + 1, s))
        .collect();
    for (c, cy) in run.cycles.iter().enumerate() {
        all.extend(cy.states.iter().enumerate().map(|(j, s)| (c + 1, j + 1, s)));
    }
    for &(c, j, s) in &all {
        if c <= 1 {
            println!(
                "{:+.4} {:+.5} {:+.5} {:5} {:5} {:+.6e} {:.3e}",
                s.q_over_p,
                s.stick.0,
                s.stick.1,
                count(s, Zone::SlipNegative),
                count(s, Zone::SlipPositive),
                s.punch,
                s.dissipation
            );
        }
        let _ = writeln!(
            csv,
            "step,{name},{amp},{N},{c},{j},{},{},{},{},{},{},{},,,,,,,",
            s.q_over_p,
            s.punch,
            s.stick.0,
            s.stick.1,
            count(s, Zone::SlipNegative),
            count(s, Zone::SlipPositive),
            s.dissipation
        );
    }
    println!(
        " cycle  W (pi B P^2)   W (P^2/E)    loop work    P dV        dPi       balance  max slip amp (pi B P)"
    );
    for (c, cy) in run.cycles.iter().enumerate() {
        let amp_max = cy.slip_amplitude.iter().fold(0.0f64, |m, v| m.max(*v));
        println!(
            " {:3}  {:.5e}  {:>11}  {:+.4e}  {:+.3e}  {:+.3e}  {:+.1e}  {:.4e}",
            c + 1,
            cy.dissipation,
            in_e(cy.dissipation),
            cy.loop_work,
            cy.normal_work,
            cy.energy_change,
            cy.balance_residual,
            amp_max
        );
        let _ = writeln!(
            csv,
            "cycle,{name},{amp},{N},{},,,,,,,,,{},{},{},{},{},{},",
            c + 1,
            cy.dissipation,
            cy.loop_work,
            cy.normal_work,
            cy.energy_change,
            cy.balance_residual,
            amp_max
        );
    }
}

/// p, q at +Q* (end of the first loading) and at -Q* (end of the first unloading), and the
/// first cycle's slip amplitude, along the contact.
fn profiles(amp: f64, run: &Cycles, out: &mut String) {
    let (Some(up), Some(cy)) = (run.first_loading.last(), run.cycles.first()) else {
        return;
    };
    let down = &cy.states[cy.states.len() / 2 - 1];
    for (i, x) in run.nodes.iter().enumerate() {
        let _ = writeln!(
            out,
            "{amp},{x},{},{},{},{},{}",
            up.p[i], up.q[i], down.p[i], down.q[i], cy.slip_amplitude[i]
        );
    }
}

fn orders(v: &[f64]) -> Vec<f64> {
    let d: Vec<f64> = v.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    d.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all("docs")?;
    let ply = Material::plane_stress(181e9, 10.3e9, 7.17e9, 0.28)?;
    let mu = 0.3;
    let k = ply.coupling(mu);
    // energies: units of pi B P^2 -> P^2 / E
    let to_e = std::f64::consts::PI * ply.green().b * ply.constants().e;
    println!(
        "carbon/epoxy ply, plane stress, mu = {mu}: bp = {:.6}, bq = {:.6}, b* = {:.6}; \
         pi B E = {to_e:.6}",
        k.bp,
        k.bq,
        k.b_star()
    );
    let mut csv = String::from(
        "kind,scene,amp_over_mu,n,cycle,step,q_over_p,punch_d,c1,c2,slip_neg_nodes,slip_pos_nodes,\
         w_step,w_cycle,loop_work,normal_work,energy_change,balance_residual,max_slip_amplitude,\
         w_first_loading\n",
    );
    let mut prof = String::from(
        "amp_over_mu,x,p_at_plus_qstar,q_at_plus_qstar,p_at_minus_qstar,q_at_minus_qstar,\
         slip_amplitude_cycle1\n",
    );
    for amp in [0.3, 0.6, 0.9] {
        let t = Instant::now();
        let run = cycles(&k, N, amp * mu, CYCLES, STEPS)?;
        report("ply", amp, &run, Some(to_e), &mut csv);
        profiles(amp, &run, &mut prof);
        println!("({:.1} s)", t.elapsed().as_secs_f64());
    }

    // Refinement in N at Q*/(mu P) = 0.6, one cycle, 5 steps per quarter.
    println!("\n== refinement at Q*/(mu P) = 0.6 (5 steps per quarter)");
    println!(
        "    N   c2(+Q*, first loading)  c1(-Q*, first unloading)  W1 (pi B P^2)    W0 (first loading)   \
         time    trailing-edge panel at +Q*: slip+ nodes, reserve 1 - |q|/(mu p)"
    );
    let (mut c2s, mut c1s, mut w1s, mut w0s) = (vec![], vec![], vec![], vec![]);
    for n in [100, 200, 400, 800] {
        let t = Instant::now();
        let run = cycles(&k, n, 0.6 * mu, 1, 5)?;
        let c2 = run.first_loading.last().map_or(f64::NAN, |s| s.stick.1);
        let c1 = run.cycles[0].states[9].stick.0;
        let w1 = run.cycles[0].dissipation;
        let w0: f64 = run.first_loading.iter().map(|s| s.dissipation).sum();
        let up = run.first_loading.last().unwrap_or(&run.normal_load);
        let reserve = 1.0 - up.q[0].abs() / (mu * up.p[0]);
        println!(
            "{n:5}   {c2:+.8}            {c1:+.8}              {w1:.8e}   {w0:.8e}   {:5.1} s   {}   {reserve:.4e}",
            t.elapsed().as_secs_f64(),
            count(up, Zone::SlipPositive)
        );
        let _ = writeln!(csv, "refine,ply,0.6,{n},1,5,,,{c1},{c2},,,,{w1},,,,,,{w0}");
        c2s.push(c2);
        c1s.push(c1);
        w1s.push(w1);
        w0s.push(w0);
    }
    println!(
        "observed orders (log2 of successive difference ratios): c2 {:?}, c1 {:?}, W1 {:?}, W0 {:?}",
        orders(&c2s),
        orders(&c1s),
        orders(&w1s),
        orders(&w0s)
    );

    // The dissipation's step error (the states at +-Q* do not depend on the steps).
    println!(
        "\n== load steps at Q*/(mu P) = 0.6, N = {N}: steps per quarter, c1(-Q*), W1 (pi B P^2)"
    );
    let mut ws = vec![];
    for steps in [5, 10, 20, 40] {
        let run = cycles(&k, N, 0.6 * mu, 1, steps)?;
        let cy = &run.cycles[0];
        let c1 = cy.states[2 * steps - 1].stick.0;
        println!("{steps:4}  {c1:+.10}  {:.8e}", cy.dissipation);
        let _ = writeln!(
            csv,
            "steps,ply,0.6,{N},1,{steps},,,{c1},,,,,{},,,,,,",
            cy.dissipation
        );
        ws.push(cy.dissipation);
    }
    println!("observed orders in the step: {:?}", orders(&ws));

    // Coupling strength: dissipation per cycle, isotropic form, N = 100, 5 steps per quarter.
    println!(
        "\n== isotropic form (bp = bq = b*), N = 100, 5 steps per quarter: W per cycle (pi B P^2)"
    );
    for (bs, m) in [(0.5, 0.5), (0.7, 1.0), (0.8, 2.0), (0.9, 1.0)] {
        for amp in [0.3, 0.6, 0.9] {
            let kk = Coupling {
                bp: bs,
                bq: bs,
                mu: m,
            };
            match cycles(&kk, 100, amp * m, CYCLES, 5) {
                Ok(run) => {
                    let up = run.first_loading.last().unwrap_or(&run.normal_load);
                    let w: Vec<String> = run
                        .cycles
                        .iter()
                        .map(|c| format!("{:.3e}", c.dissipation))
                        .collect();
                    println!(
                        "b* = {bs}, mu = {m}, Q*/(mu P) = {amp}: stick at +Q* [{:+.4}, {:+.4}], \
                         slip+ nodes {}, W {}",
                        up.stick.0,
                        up.stick.1,
                        count(up, Zone::SlipPositive),
                        w.join(" ")
                    );
                }
                Err(e) => println!("b* = {bs}, mu = {m}, Q*/(mu P) = {amp}: {e}"),
            }
        }
    }

    // Stronger coupling, isotropic form (bp = bq = b*), for contrast.
    for (bs, m, amp) in [(0.5, 0.5, 0.9), (0.9, 1.0, 0.3)] {
        let kk = Coupling {
            bp: bs,
            bq: bs,
            mu: m,
        };
        let t = Instant::now();
        let run = cycles(&kk, N, amp * m, CYCLES, STEPS)?;
        report(&format!("b*={bs} mu={m}"), amp, &run, None, &mut csv);
        println!(
            "({:.1} s; energies in pi B P^2 only)",
            t.elapsed().as_secs_f64()
        );
    }
    std::fs::write("docs/fretting_lcp.csv", csv)?;
    std::fs::write("docs/fretting_lcp_profiles.csv", prof)?;
    println!("\nwrote docs/fretting_lcp.csv, docs/fretting_lcp_profiles.csv");
    Ok(())
}
