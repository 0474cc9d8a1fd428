//! `orthoslip fretting`: the normal load, a tangential load Q: 0 -> Q*, then cycles
//! Q* -> -Q* -> Q* (`orthoslip::fretting::Fretting`); a table per cycle, or with `--profile`
//! one cycle's profiles along the contact.

use std::io::Write;

use orthoslip::Contact;
use orthoslip::fretting::{CycleOptions, CycleState, Fretting};

use super::Failure;
use super::args::FrettingArgs;
use super::report::{Name, Report, Value, name};

fn state_name(s: CycleState) -> &'static str {
    match s {
        CycleState::Shakedown => "shakedown",
        CycleState::SteadySlip => "steady_slip",
        CycleState::CycleLimitReached => "cycle_limit_reached",
    }
}

/// Solves the fretting run and writes the report.
pub fn run(args: &FrettingArgs, out: &mut impl Write) -> Result<(), Failure> {
    let given = args.material.material()?;
    let mut contact = Contact::new(given.material);
    contact.set_friction(args.mu)?;
    let q_amp = match (args.amplitude.amplitude, args.amplitude.relative_amplitude) {
        (Some(a), _) => a,
        (_, Some(r)) => {
            if !(r.is_finite() && r > 0.0 && r < 1.0) {
                return Err(Failure::Input(format!(
                    "--relative-amplitude {r} must be in (0, 1) (1 and above: gross sliding)"
                )));
            }
            r * args.mu
        }
        (None, None) => unreachable!("clap requires one amplitude option"),
    };
    let options = CycleOptions {
        panels: args.panels,
        steps: args.steps,
        max_cycles: args.max_cycles,
        repeat_tolerance: args.repeat_tol,
        ..CycleOptions::default()
    };
    let f = Fretting::solve(&contact, q_amp, &options)?;
    let mut material = vec![("model", Value::from(given.model))];
    material.extend(given.constants.into_iter().map(|(k, v)| (k, v.into())));
    let count = f.cycles.len();
    let mut fields = vec![
        (name("material"), Value::Group(material)),
        (name("mu"), args.mu.into()),
        (
            Name {
                key: "q_amp_over_p",
                label: "Q*/P",
            },
            q_amp.into(),
        ),
        (name("method"), "lcp_history".into()),
        (name("panels"), (args.panels as f64).into()),
        (name("steps"), (args.steps as f64).into()),
        (
            Name {
                key: "cycle_count",
                label: "cycles",
            },
            (count as f64).into(),
        ),
        (name("state"), state_name(f.state).into()),
        (
            Name {
                key: "first_loading_energy",
                label: "first loading energy (P^2/E)",
            },
            f.first_loading_dissipation.value.into(),
        ),
        (
            Name {
                key: "first_loading_energy_error",
                label: "its error estimate",
            },
            f.first_loading_dissipation.error.into(),
        ),
    ];
    let report = match args.profile {
        None => {
            let rows = f
                .cycles
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    let amp = c.slip_amplitude.iter().cloned().fold(0.0, f64::max);
                    vec![
                        ((i + 1) as f64).into(),
                        c.dissipation.value.into(),
                        c.dissipation.error.into(),
                        amp.into(),
                        c.slip_amplitude_error.into(),
                        c.stick_at_minus.0.into(),
                        c.stick_at_minus.1.into(),
                        c.stick_at_plus.0.into(),
                        c.stick_at_plus.1.into(),
                        c.stick_error.into(),
                        c.f1_peak.value.into(),
                        c.f1_peak.x.into(),
                        c.f2_peak.value.into(),
                        c.f2_peak.x.into(),
                    ]
                })
                .collect();
            Report {
                fields,
                table_key: "cycles",
                columns: [
                    "cycle",
                    "energy",
                    "energy_error",
                    "max_slip_amplitude",
                    "slip_amplitude_error",
                    "c1_minus",
                    "c2_minus",
                    "c1_plus",
                    "c2_plus",
                    "stick_error",
                    "f1_peak",
                    "x_f1",
                    "f2_peak",
                    "x_f2",
                ]
                .map(name)
                .to_vec(),
                rows,
            }
        }
        Some(k) => {
            if k == 0 || k > count {
                return Err(Failure::Input(format!(
                    "--profile {k}: the run has cycles 1 ..= {count}"
                )));
            }
            let c = &f.cycles[k - 1];
            fields.push((name("profile_cycle"), (k as f64).into()));
            let rows = f
                .nodes
                .iter()
                .enumerate()
                .map(|(i, &x)| {
                    [
                        x,
                        c.slip_amplitude[i],
                        c.tau_max[i],
                        c.sxx_max[i],
                        c.f1[i],
                        c.f2[i],
                    ]
                    .map(Value::from)
                    .to_vec()
                })
                .collect();
            Report {
                fields,
                table_key: "profile",
                columns: ["x", "slip_amplitude", "tau_max", "sxx_max", "f1", "f2"]
                    .map(name)
                    .to_vec(),
                rows,
            }
        }
    };
    report.write(args.format, out)?;
    Ok(())
}
