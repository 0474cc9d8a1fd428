//! The README's tested snippets, so that what a reader copies is what the tests run.
//!
//! A fenced code block right after a line `<!-- test: ROUTE FILE -->` is the content of
//! FILE; right after `<!-- test: ROUTE -->` it is shell lines. A route's shell lines, in README
//! order, form one bash script (run with `-euo pipefail`, so variables carry over as when the
//! blocks are pasted into one shell). Which test runs which route is in [`ROUTES`].

use std::path::Path;
use std::process::Command;

/// The routes and the tests that run them; a mark naming another route is an error.
pub const ROUTES: [&str; 4] = [
    "packaging",      // tests/packaging.rs: C/CMake, pkg-config, C++, Fortran
    "python-install", // tests/python.rs, slow tier: installs the package (run in the checkout)
    "python",         // tests/python.rs, both tiers: scripts run in the virtual environment
    "cli",            // tests/cli.rs: the command-line tool
];

/// The snippets of one route.
#[derive(Debug, Default)]
pub struct Route {
    /// (file name, content) in README order.
    pub files: Vec<(String, String)>,
    /// The shell lines, joined.
    pub script: String,
}

impl Route {
    /// Writes the route's files into `dir` and returns a bash command that runs the route's
    /// script there.
    pub fn bash(&self, dir: &Path) -> Command {
        for (name, text) in &self.files {
            std::fs::write(dir.join(name), text)
                .unwrap_or_else(|e| panic!("cannot write {name} into {}: {e}", dir.display()));
        }
        let mut cmd = Command::new("bash");
        cmd.args(["-euo", "pipefail", "-c", &self.script])
            .current_dir(dir);
        cmd
    }
}

/// The snippets of `route` in README.md; panics on a malformed mark or an empty route.
pub fn route(route: &str) -> Route {
    let readme = Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md");
    let text = std::fs::read_to_string(&readme).expect("README.md");
    let mut found = Route::default();
    let mut lines = text.lines().enumerate();
    while let Some((n, line)) = lines.next() {
        let Some(mark) = line
            .strip_prefix("<!-- test:")
            .and_then(|l| l.strip_suffix("-->"))
        else {
            continue;
        };
        let words: Vec<&str> = mark.split_whitespace().collect();
        let (name, file) = match words[..] {
            [name] => (name, None),
            [name, file] => (name, Some(file)),
            _ => panic!(
                "README.md:{}: expected `<!-- test: ROUTE [FILE] -->`",
                n + 1
            ),
        };
        assert!(
            ROUTES.contains(&name),
            "README.md:{}: unknown route {name:?} (known: {ROUTES:?})",
            n + 1
        );
        let fence = lines.next().map(|(_, l)| l).unwrap_or_default();
        assert!(
            fence.starts_with("```"),
            "README.md:{}: a test mark must be followed by a fenced code block",
            n + 1
        );
        let mut block = String::new();
        for (_, l) in lines.by_ref().take_while(|(_, l)| !l.starts_with("```")) {
            block.push_str(l);
            block.push('\n');
        }
        if name != route {
            continue;
        }
        match file {
            Some(file) => found.files.push((file.to_owned(), block)),
            None => found.script.push_str(&block),
        }
    }
    assert!(
        !found.script.is_empty(),
        "README.md has no shell lines marked `<!-- test: {route} -->`"
    );
    found
}

/// The numbers printed after `c = ` at the start of a line (`c = 0.1` or `c = 0.1 ...`).
pub fn printed_c(output: &str) -> Vec<f64> {
    output
        .lines()
        .filter_map(|l| l.strip_prefix("c = "))
        .map(|rest| {
            let number = rest.split_whitespace().next().unwrap_or_default();
            number
                .parse()
                .unwrap_or_else(|e| panic!("cannot parse c = {rest:?}: {e}"))
        })
        .collect()
}
