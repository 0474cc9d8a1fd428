//! The command line, declared with clap's derive API: `orthoslip [solve|sweep] ...`.

use clap::{Args, Parser, Subcommand, ValueEnum};
use orthoslip::{Material, Method};

const EXIT_STATUS: &str = "\
Exit status:
  0  success
  1  the solver failed: no convergence, tolerance not met, no admissible solution or an
     internal error (for sweep: at least one mu failed; its row has status != ok), or the
     output could not be written
  2  bad input: an unknown, missing or unparsable option, or a value the library rejects
     (e.g. mu < 0, an inadmissible material)
Errors are reported on stderr in one line starting with 'orthoslip: '.";

/// Partial-slip contact of a rigid flat-ended punch pressed into an orthotropic elastic
/// half-plane with Coulomb friction: the stick half-width c and the tractions p, q.
#[derive(Parser, Debug)]
#[command(
    name = "orthoslip",
    version,
    long_about = "Partial-slip contact of a rigid flat-ended punch pressed into an orthotropic \
elastic half-plane with Coulomb friction: the stick half-width c and the tractions p, q.\n\n\
Without a command, solves the built-in default scene (a carbon/epoxy ply in plane stress, \
E11 = 181 GPa, E22 = 10.3 GPa, G12 = 7.17 GPa, nu12 = 0.28, mu = 0.3) with every method and \
prints the constants, c, 1 - c, the error estimates, the time per solve and a table of p and \
q.\n\n\
Units: x is in units of the punch half-width a (the punch occupies -1 <= x <= 1); p and q \
are per P/a (P: normal force per unit thickness): sigma_yy(x, 0) = -(P/a) p(x/a), \
sigma_xy(x, 0) = (P/a) q(x/a). Moduli may be given in any one unit; c, p and q do not depend \
on it.",
    after_help = EXIT_STATUS
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Solve one scene: c, 1 - c, the method used, its error estimate and the tractions.
    #[command(after_help = EXIT_STATUS)]
    Solve(SolveArgs),
    /// Solve for a range of friction coefficients: c, 1 - c, method and error estimate
    /// against mu.
    #[command(after_help = EXIT_STATUS)]
    Sweep(SweepArgs),
    /// Fretting: the normal load P, then a tangential load Q: 0 -> Q*, then cycles
    /// Q* -> -Q* -> Q* until the state repeats or --max-cycles; per cycle the dissipated
    /// energy, the slip amplitude, the stick sets and the Ruiz parameters' peaks (or, with
    /// --profile, one cycle's profiles along the contact).
    #[command(after_help = EXIT_STATUS)]
    Fretting(FrettingArgs),
}

#[derive(Args, Debug)]
pub struct FrettingArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Coulomb friction coefficient (finite, > 0).
    #[arg(long, allow_negative_numbers = true)]
    pub mu: f64,
    #[command(flatten)]
    pub amplitude: AmplitudeArgs,
    /// Cycles at most (1 ..= 1000).
    #[arg(long, value_name = "N", default_value_t = 10)]
    pub max_cycles: usize,
    /// Panels per half-width of the grid (8 ..= 2000; cost grows like N^3).
    #[arg(long, value_name = "N", default_value_t = 100)]
    pub panels: usize,
    /// Load steps per quarter cycle (2 ..= 10000).
    #[arg(long, value_name = "N", default_value_t = 10)]
    pub steps: usize,
    /// A cycle repeats when its end state is its start state to this (int |dq| dx in units of
    /// P, the punch displacement in P/E); a repeating cycle dissipating at most this (P^2/E)
    /// is shakedown.
    #[arg(long, value_name = "TOL", default_value = "1e-8")]
    pub repeat_tol: f64,
    /// Instead of the table per cycle, the profiles of cycle K (1-based) at the panel
    /// midpoints: slip amplitude, tau_max, sigma_xx max, F1, F2.
    #[arg(long, value_name = "K")]
    pub profile: Option<usize>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// The amplitude Q*, given as exactly one of two ratios.
#[derive(Args, Debug)]
#[group(required = true, multiple = false)]
pub struct AmplitudeArgs {
    /// The amplitude as Q*/P (0 < Q*/P < mu).
    #[arg(long, value_name = "Q/P", allow_negative_numbers = true)]
    pub amplitude: Option<f64>,
    /// The amplitude as Q*/(mu P) (0 < ratio < 1).
    #[arg(long, value_name = "Q/(MU P)", allow_negative_numbers = true)]
    pub relative_amplitude: Option<f64>,
}

#[derive(Args, Debug)]
pub struct SolveArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Coulomb friction coefficient (finite, >= 0; 0 is the frictionless limit, c = 0).
    #[arg(long, allow_negative_numbers = true)]
    pub mu: f64,
    /// Number of points for the traction table: the midpoints x = (2i + 1 - N)/N,
    /// i = 0 .. N - 1, of N equal cells of the punch (0: no table).
    #[arg(long, value_name = "N", default_value_t = 21,
          value_parser = clap::value_parser!(u32).range(0..=1_000_000))]
    pub points: u32,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

#[derive(Args, Debug)]
pub struct SweepArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// First friction coefficient (>= 0; > 0 with --spacing log).
    #[arg(long, value_name = "MU", allow_negative_numbers = true)]
    pub mu_from: f64,
    /// Last friction coefficient (>= 0; > 0 with --spacing log).
    #[arg(long, value_name = "MU", allow_negative_numbers = true)]
    pub mu_to: f64,
    /// Number of friction coefficients, both ends included.
    #[arg(long, value_name = "N",
          value_parser = clap::value_parser!(u32).range(2..=1_000_000))]
    pub steps: u32,
    /// How the friction coefficients are spaced between --mu-from and --mu-to.
    #[arg(long, value_enum, default_value_t = Spacing::Log)]
    pub spacing: Spacing,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// What solve and sweep share: the material and how to solve.
#[derive(Args, Debug)]
pub struct SceneArgs {
    #[command(flatten)]
    pub material: MaterialArgs,
    /// Solution method.
    #[arg(long, value_enum, default_value_t = MethodArg::Auto)]
    pub method: MethodArg,
    /// Target for |c - c_exact| (0 < TOL < 1): auto picks the cheapest method meeting it,
    /// coupled and lcp refine until they meet it; goodman and spence ignore it.
    #[arg(long, default_value = "1e-8")]
    pub tol: f64,
    /// Target for the traction error, int (|p - p_exact| + |q - q_exact|) dx over the punch
    /// in units of the normal load (default: --tol; inf: the tractions are not needed, only c
    /// counts, and auto may take a cheaper method).
    #[arg(long, value_name = "TOL")]
    pub traction_tol: Option<f64>,
}

/// The material, given as exactly one of three constant sets.
#[derive(Args, Debug)]
#[group(required = true, multiple = false)]
pub struct MaterialArgs {
    /// Plane stress (paper eq. (2)): Young's moduli E11 along the surface (x) and E22 into
    /// the depth (y), in-plane shear modulus G12, Poisson's ratio NU12
    /// (admissible iff NU12^2 < E11/E22).
    #[arg(long, num_args = 4, value_names = ["E11", "E22", "G12", "NU12"],
          allow_negative_numbers = true)]
    pub plane_stress: Option<Vec<f64>>,
    /// Plane strain (paper eq. (3)): moduli E11 (x), E22 (y), E33 (out of plane), shear
    /// modulus G12 and Poisson's ratios NU12, NU13, NU23 (NU_ij: contraction along j under
    /// stress along i); the 3-D compliance must be positive definite.
    #[arg(long, num_args = 7,
          value_names = ["E11", "E22", "E33", "G12", "NU12", "NU13", "NU23"],
          allow_negative_numbers = true)]
    pub plane_strain: Option<Vec<f64>>,
    /// The effective constants of paper eq. (1): stiffness E > 0, Poisson's ratio
    /// -1 < NU < 1, stiffness ratio DELTA > 0, shear parameter KAPPA > -NU (isotropic:
    /// DELTA = KAPPA = 1).
    #[arg(long, num_args = 4, value_names = ["E", "NU", "DELTA", "KAPPA"],
          allow_negative_numbers = true)]
    pub effective: Option<Vec<f64>>,
}

/// A material as given on the command line.
pub struct GivenMaterial {
    pub material: Material,
    /// `plane_stress`, `plane_strain` or `effective`.
    pub model: &'static str,
    /// The constants given, by name.
    pub constants: Vec<(&'static str, f64)>,
}

impl MaterialArgs {
    /// The material the options give (the library checks the constants).
    pub fn material(&self) -> orthoslip::Result<GivenMaterial> {
        const STRESS: [&str; 4] = ["E11", "E22", "G12", "nu12"];
        const STRAIN: [&str; 7] = ["E11", "E22", "E33", "G12", "nu12", "nu13", "nu23"];
        const EFFECTIVE: [&str; 4] = ["E", "nu", "delta", "kappa"];
        let given = |material, model, names: &[&'static str], v: &[f64]| GivenMaterial {
            material,
            model,
            constants: names.iter().copied().zip(v.iter().copied()).collect(),
        };
        // clap lets exactly one set through, with its number of values.
        match (&self.plane_stress, &self.plane_strain, &self.effective) {
            (Some(v), _, _) => {
                let m = Material::plane_stress(v[0], v[1], v[2], v[3])?;
                Ok(given(m, "plane_stress", &STRESS, v))
            }
            (_, Some(v), _) => {
                let m = Material::plane_strain(v[0], v[1], v[2], v[3], v[4], v[5], v[6])?;
                Ok(given(m, "plane_strain", &STRAIN, v))
            }
            (_, _, Some(v)) => {
                let m = Material::effective(v[0], v[1], v[2], v[3])?;
                Ok(given(m, "effective", &EFFECTIVE, v))
            }
            (None, None, None) => unreachable!("clap requires one material option"),
        }
    }
}

/// The `--method` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// The cheapest method whose error estimate meets --tol.
    Auto,
    /// Goodman's approximation (closed form; its empirical model-error bound as estimate).
    Goodman,
    /// Spence's approximation (closed form; its empirical model-error bound as estimate).
    Spence,
    /// The high-order solver of the full coupled equations.
    Coupled,
    /// The paper's linear-complementarity method (first order; slow at small --tol).
    Lcp,
}

impl From<MethodArg> for Method {
    fn from(m: MethodArg) -> Self {
        match m {
            MethodArg::Auto => Method::Auto,
            MethodArg::Goodman => Method::Goodman,
            MethodArg::Spence => Method::Spence,
            MethodArg::Coupled => Method::Coupled,
            MethodArg::Lcp => Method::Lcp,
        }
    }
}

/// The name of a method as `--method` spells it.
pub fn method_name(m: Method) -> &'static str {
    match m {
        Method::Auto => "auto",
        Method::Goodman => "goodman",
        Method::Spence => "spence",
        Method::Coupled => "coupled",
        Method::Lcp => "lcp",
    }
}

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// `name = value` lines, then an aligned table.
    Table,
    /// The table as CSV (header row), preceded by `# name = value` comment lines.
    Csv,
    /// One JSON object; non-finite numbers (e.g. an error estimate outside the model-error table, +inf) and
    /// failed values are null.
    Json,
}

/// Spacing of the friction coefficients of a sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Spacing {
    /// Geometric: equal ratios (both ends > 0).
    Log,
    /// Arithmetic: equal differences.
    Linear,
}
