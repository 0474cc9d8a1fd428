//! The `orthoslip` command-line tool. Without arguments it runs the main job, the default
//! scene; `orthoslip solve` and `orthoslip sweep` solve scenes given on the command line
//! (`orthoslip --help`). The code lives in `src/cli/`; the library stays free of it.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
