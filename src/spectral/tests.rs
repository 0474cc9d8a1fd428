//! The spectral solver against the panels (an independent discretisation) and the
//! tabulated stick edge.

use super::*;

fn consts(b: f64, mu: f64) -> Constants {
    Constants {
        b,
        mu,
        g: 0.5 - (b * mu).atan() / std::f64::consts::PI,
    }
}

/// The constants, the tabulated stick edge lc and its bound where the table covers (b*, mu~)
/// and the bases serve it.
fn served_edge(b: f64, mu: f64) -> Option<(Constants, f64, f64)> {
    let (lc, bound) = crate::stick_edge_table::lookup(b, mu)?;
    let k = consts(b, mu);
    serves(k, lc).then_some((k, lc, bound))
}

/// Mid-range scenes (c = 0.04 .. 0.92), c by the root search (no bound on the starting c):
/// c within the tabulated stick edge's bound plus the estimate (the table was built by the
/// panels, an independent discretisation), and both estimates hold against a solve to
/// tolerances 100 times tighter.
#[test]
fn mid_range_meets_its_estimates() {
    for (b, mu) in [(0.3, 0.5), (0.6, 1.0), (0.3, 0.11), (0.45, 0.3), (0.8, 2.0)] {
        let k = consts(b, mu);
        let (lc, bound) = crate::stick_edge_table::lookup(b, mu).expect("tabulated");
        let table = StickEdge::from_logit(lc);
        // no bound: the root search (the Newton ladder) fixes c
        let s = from_edge(k, lc, f64::INFINITY, 1e-8, 1e-6, 1.0)
            .unwrap_or_else(|| panic!("({b}, {mu}): no answer"));
        let fine = from_edge(k, lc, f64::INFINITY, 1e-10, 1e-8, 1.0)
            .unwrap_or_else(|| panic!("({b}, {mu}): none at 1e-10"));
        eprintln!(
            "b* = {b}, mu~ = {mu}: c = {} (table {} +- {bound:.1e}); estimates {:.1e} / {:.1e} at level {} ({} unknowns), {:.1e} / {:.1e} at level {}",
            fine.edge.c,
            table.c,
            s.error,
            s.traction_parts.0 + s.traction_parts.1,
            s.level,
            s.unknowns(),
            fine.error,
            fine.traction_parts.0 + fine.traction_parts.1,
            fine.level
        );
        assert!(
            fine.edge.distance(table) <= bound + fine.error,
            "({b}, {mu}): c off the table"
        );
        let true_c = s.edge.distance(fine.edge);
        assert!(
            true_c <= s.error + fine.error,
            "({b}, {mu}): c off by {true_c:e}, estimate {:e}",
            s.error
        );
        let (dp, dq) = distance(&s.fixed, &fine.fixed).parts;
        let est = s.traction_parts.0 + s.traction_parts.1;
        let fine_est = fine.traction_parts.0 + fine.traction_parts.1;
        assert!(
            dp + dq <= est + fine_est,
            "({b}, {mu}): tractions off by {:e}, estimate {est:e}",
            dp + dq
        );
    }
}

/// The equations themselves at points that are not collocation points, by the zone
/// transforms (E1) and (E2) with sigma = 0, and int p = 1 by Gauss-Jacobi rules.
#[test]
fn residuals_off_the_collocation_points() {
    let (b, mu) = (0.45, 0.3);
    let k = consts(b, mu);
    let (lc, _) = crate::stick_edge_table::lookup(b, mu).expect("tabulated");
    let s = from_edge(k, lc, f64::INFINITY, 1e-10, 1e-8, 1.0).expect("answer");
    let f = &s.fixed;
    let (c, w) = (f.basis.c, f.basis.w);
    let mut worst: f64 = 0.0;
    for i in 1..40 {
        // between the Chebyshev points of both zones
        let t = i as f64 / 40.0;
        for x in [c * t * t.sqrt(), c + w * t * t] {
            let r = f.residuals(x);
            let scale = f.at(x).0;
            worst = worst.max(r.0.abs() / scale).max(r.1.abs() / scale);
        }
    }
    eprintln!("largest residual relative to p: {worst:.1e}");
    assert!(worst < 1e-7, "residual {worst:e}");
    let total = f.integral_of_p();
    // enforced by elimination; the frame's cancellation leaves a few hundred ulps
    assert!((total - 1.0).abs() < 1e-12, "int p = {total}");
}

/// Over the tabulated part of the reduced plane (a grid of the table's coordinates) with
/// g >= [`G_MIN`] and c >= [`C_MIN`]: the spectral solver answers at (1e-10, 1e-8), its c within the table's
/// bound plus its own estimate. Returns (answered, tried, the largest distance from the table
/// over the bound plus the estimate); `grid` points per coordinate over the patches' extent.
fn sweep(grid: usize) -> (usize, usize, f64) {
    // the patches' extent; its points outside every patch are left out (lookup is None)
    let ([lo_b, hi_b], [lo_z, hi_z]) = crate::spectral::served_extent();
    let (mut answered, mut tried, mut worst) = (0, 0, 0.0f64);
    for i in 0..grid {
        for j in 0..grid {
            let beta = lo_b + (hi_b - lo_b) * (i as f64 + 0.5) / grid as f64;
            let zeta = lo_z + (hi_z - lo_z) * (j as f64 + 0.5) / grid as f64;
            let (b, mu) = crate::stick_edge_table::coupling_at(beta, zeta);
            let Some((k, lc, bound)) = served_edge(b, mu) else {
                continue;
            };
            tried += 1;
            let s = from_edge(k, lc, bound, 1e-10, 1e-8, 1.0);
            let Some(s) = s else {
                let e = StickEdge::from_logit(lc);
                eprintln!(
                    "no answer: b* = {b:.4}, mu~ = {mu:.3e}, c = {:.3e}, 1 - c = {:.3e}",
                    e.c, e.one_minus_c
                );
                continue;
            };
            answered += 1;
            let off = s.edge.distance(StickEdge::from_logit(lc));
            worst = worst.max(off / (bound + s.error));
            assert!(
                off <= bound + s.error,
                "b* = {b}, mu~ = {mu}: c = {} off the table by {off:e} (bound {bound:e}, \
                 estimate {:e})",
                s.edge.c,
                s.error
            );
        }
    }
    (answered, tried, worst)
}

#[test]
fn agrees_with_the_table_on_a_coarse_grid() {
    let (answered, tried, worst) = sweep(5);
    eprintln!("answered {answered} of {tried}; largest distance / (bound + estimate) {worst:.2}");
    assert_eq!(answered, tried, "points the bases serve left to the panels");
}

#[test]
#[ignore = "slow tier: a 24 x 24 grid of the table's coordinates"]
fn agrees_with_the_table_on_a_fine_grid() {
    let (answered, tried, worst) = sweep(24);
    eprintln!("answered {answered} of {tried}; largest distance / (bound + estimate) {worst:.2}");
    assert_eq!(answered, tried, "points the bases serve left to the panels");
}

/// The root search from a starting c off by 1e-6 in lc (about 1e-7 in c): it moves to the
/// table's c within the table's bound plus its estimate.
#[test]
fn newton_ladder_moves_to_the_root() {
    for (b, mu) in [(0.3, 0.5), (0.45, 0.3)] {
        let k = consts(b, mu);
        let (lc, bound) = crate::stick_edge_table::lookup(b, mu).expect("tabulated");
        for off in [1e-6, -1e-6] {
            let s = from_edge(k, lc + off, f64::INFINITY, 1e-10, 1e-8, 1.0)
                .unwrap_or_else(|| panic!("({b}, {mu}) from {off:e}: no answer"));
            let d = s.edge.distance(StickEdge::from_logit(lc));
            eprintln!(
                "({b}, {mu}) from {off:e}: level {}, c off the table by {d:.1e}, estimate {:.1e}",
                s.level, s.error
            );
            assert!(
                d <= bound + s.error,
                "({b}, {mu}) from {off:e}: off by {d:e}"
            );
        }
    }
}

/// The bounds that stand in for the measured slope and moves per lc and per sigma at a known
/// stick edge ([`SLOPE_FLOOR`], [`SENSITIVITY_BOUNDS`], measured on a 53 x 53 grid, and
/// [`RATE_PER_C`], on a 161 x 161 grid) hold on another grid of the table's coordinates
/// (37 x 37 cell midpoints; only its centre is a node of the others) and at the smallest
/// stick zones served, measured as [`First::measured`] measures them.
#[test]
fn sensitivity_bounds_hold() {
    let ([lo_b, hi_b], [lo_z, hi_z]) = crate::spectral::served_extent();
    let grid = 37;
    let mut scenes: Vec<(f64, f64)> = (0..grid * grid)
        .map(|n| {
            let (i, j) = (n / grid, n % grid);
            let beta = lo_b + (hi_b - lo_b) * (i as f64 + 0.5) / grid as f64;
            let zeta = lo_z + (hi_z - lo_z) * (j as f64 + 0.5) / grid as f64;
            crate::stick_edge_table::coupling_at(beta, zeta)
        })
        .collect();
    // the smallest stick zones served (c = 4.2e-5 .. 9e-5), and the smallest b* of the table
    // at its smallest stick zone served and near its top
    scenes.extend([
        (0.02, 0.0028),
        (0.02, 0.061),
        (0.25, 0.0354),
        (0.4, 0.0619),
        (0.6, 0.1082),
        (0.8, 0.1893),
        (0.99, 0.6659),
    ]);
    let (mut served, mut worst) = (0, [0.0f64; 5]);
    for (b, mu) in scenes {
        let Some((k, lc, _)) = served_edge(b, mu) else {
            continue;
        };
        let e = StickEdge::from_logit(lc);
        let base = sigma_at(k, lc, Sizes::at(FIRST_LEVEL, e.c, e.one_minus_c)).expect("level 1");
        let mut first = First {
            lc,
            base: Some(base),
            measured: None,
        };
        let s = first.measured(k).expect("measured");
        served += 1;
        worst[0] = worst[0].max(SLOPE_FLOOR * b / s.slope.abs());
        let (rate_bound, sigma_rate_bound) = sensitivity_bounds(b, k.g, e.c, e.one_minus_c);
        worst[1] = worst[1].max(s.rate.0 / rate_bound.0);
        worst[2] = worst[2].max(s.rate.1 / rate_bound.1);
        let per_sigma = (s.rate.0 / s.slope.abs(), s.rate.1 / s.slope.abs());
        worst[3] = worst[3].max(per_sigma.0 / sigma_rate_bound.0);
        worst[4] = worst[4].max(per_sigma.1 / sigma_rate_bound.1);
        assert!(
            per_sigma.0 <= sigma_rate_bound.0 && per_sigma.1 <= sigma_rate_bound.1,
            "({b}, {mu}): move per sigma {per_sigma:?} above the bound"
        );
        assert!(
            s.slope.abs() >= SLOPE_FLOOR * b,
            "({b}, {mu}): slope {:e} below the floor",
            s.slope
        );
        assert!(
            s.rate.0 <= rate_bound.0 && s.rate.1 <= rate_bound.1,
            "({b}, {mu}): move per lc {:?} above the bound",
            s.rate
        );
    }
    eprintln!(
        "{served} served points; floor / slope at most {:.2}, rate / bound at most {:.2} (p), \
         {:.2} (q), per sigma / bound at most {:.2} (p), {:.2} (q)",
        worst[0], worst[1], worst[2], worst[3], worst[4]
    );
    assert!(served > 250, "only {served} served points");
}

/// Prints the tractions' move per unit of c, (int |dp|, int |dq~|) / dc = rate / (c (1 - c)),
/// measured as [`First::measured_at`] measures it at levels 1, 2 and 3, the largest per band
/// of b* and of c on an n x n grid of the table's coordinates (n from ORTHOSLIP_GRID, 161 by
/// default; 19 s): the table behind [`RATE_PER_C`]. A measurement, not a check: `measure`
/// feature only (`cargo test --release --features measure -- --ignored measure_rate_per_c`).
#[cfg(feature = "measure")]
#[test]
#[ignore = "measurement"]
fn measure_rate_per_c_by_b() {
    let ([lo_b, hi_b], [lo_z, hi_z]) = crate::spectral::served_extent();
    let grid: usize = std::env::var("ORTHOSLIP_GRID").map_or(161, |v| v.parse().unwrap());
    let b_edges = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 1.0];
    let c_edges = [1e-4, 1e-3, 0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 1.0];
    let mut worst = vec![[0.0f64; 2]; b_edges.len() * c_edges.len()];
    let mut count = vec![0usize; b_edges.len() * c_edges.len()];
    for n in 0..grid * grid {
        let (i, j) = (n / grid, n % grid);
        let beta = lo_b + (hi_b - lo_b) * i as f64 / (grid - 1) as f64;
        let zeta = lo_z + (hi_z - lo_z) * j as f64 / (grid - 1) as f64;
        let (b, mu) = crate::stick_edge_table::coupling_at(beta, zeta);
        let Some((k, lc, _)) = served_edge(b, mu) else {
            continue;
        };
        let e = StickEdge::from_logit(lc);
        let (Some(bi), Some(ci)) = (
            b_edges.iter().position(|&v| b < v),
            c_edges.iter().position(|&v| e.c < v),
        ) else {
            continue;
        };
        let cell = bi * c_edges.len() + ci;
        for level in 1..=3 {
            let sizes = Sizes::at(level, e.c, e.one_minus_c);
            let Some(cur) = sigma_at(k, lc, sizes) else {
                continue;
            };
            let mut first = First {
                lc,
                base: None,
                measured: None,
            };
            let Some(s) = first.measured_at(k, &cur.fixed, sizes) else {
                continue;
            };
            let cw = e.c * e.one_minus_c;
            worst[cell][0] = worst[cell][0].max(s.rate.0 / cw);
            worst[cell][1] = worst[cell][1].max(s.rate.1 / cw);
        }
        count[cell] += 1;
    }
    println!("| b* below | c below | points | p per c | q~ per c |");
    for (bi, bv) in b_edges.iter().enumerate() {
        for (ci, cv) in c_edges.iter().enumerate() {
            let cell = bi * c_edges.len() + ci;
            if count[cell] > 0 {
                println!(
                    "| {bv} | {cv} | {} | {:.3e} | {:.3e} |",
                    count[cell], worst[cell][0], worst[cell][1]
                );
            }
        }
    }
}

/// Prints sigma at the stick edge (the table's, else the panels' at 1e-12) of thin slip zones
/// and small edge exponents, half level by half level: as solved, the change with the rows
/// reversed (another rounding of the same least squares), the change from the half level
/// below, the largest coefficient and the residual (R1): the rounding floor of sigma, and so
/// of c, in docs/theory_spectral.md section 5. A measurement, not a check: `measure` feature
/// only (a few seconds; the panels' c at 1e-12 for the untabulated scenes).
#[cfg(feature = "measure")]
#[test]
#[ignore = "measurement"]
fn measure_sigma_noise_in_thin_slip_zones() {
    use crate::problem::Profile;
    for (b, mu) in [
        (0.3, 0.5),
        (0.2857142857142857, 1.0),
        (0.45, 2.0),
        (0.25, 100.0),
        (0.33, 400.0),
        (0.2, 3.0949),
        (0.2, 10.0),
        (0.1, 1.5),
    ] {
        let (lc, bound) = crate::stick_edge_table::lookup(b, mu).unwrap_or_else(|| {
            let k = crate::problem::Coupling { bp: b, bq: b, mu };
            let s = crate::coupled::solve_panels_to(&k, 1e-12, f64::INFINITY).unwrap();
            let e = s.edge();
            (e.logit(), s.numerical_error())
        });
        let k = consts(b, mu);
        let e = StickEdge::from_logit(lc);
        println!(
            "({b}, {mu}) g {:.4} 1-c {:.3e} bound {bound:.1e}",
            k.g, e.one_minus_c
        );
        let mut prev: Option<f64> = None;
        for half in 3..=14 {
            let sizes = Sizes::at_real(0.5 * half as f64, e.c, e.one_minus_c);
            let sys = Assembled::new(k, e.c, e.one_minus_c, sizes);
            let cur = sys.solve().unwrap();
            let order: Vec<usize> = (0..sys.rows()).rev().collect();
            let rev = sys.solve_rows(&order).unwrap();
            let big = cur.coef.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            println!(
                "  half {half} n {} sigma {:+.3e} reversed {:+.2e} below {:+.2e} max|coef| \
                 {big:.1e} residual {:.1e}",
                cur.unknowns(),
                cur.sigma,
                rev.sigma - cur.sigma,
                prev.map_or(f64::NAN, |p| p - cur.sigma),
                cur.residual
            );
            prev = Some(cur.sigma);
        }
    }
}

/// The stick side's split q = q_plain + (c - x)^g q_edge (the field's expansion at x = c)
/// reproduces the solution's q with the quotient family too (its plain part takes -1/g of
/// its polynomials), to the rounding that 1/g amplifies: measured 8e-13 at g = 1e-4 and
/// 5.8e-12 at g = 0.01 (b* = 0.45, 1 - c = 1.2e-3; 2.8e-12 with the power family there).
#[test]
fn stick_split_reproduces_q_at_small_g() {
    for (b, g) in [(0.75, 1e-4), (0.45, 0.01)] {
        let mu = 1.0 / ((std::f64::consts::PI * g).tan() * b);
        let k = consts(b, mu);
        let (lc, bound) = crate::stick_edge_table::lookup(b, mu).expect("tabulated");
        let s = from_edge(k, lc, bound, 1e-10, 1e-8, 1.0).expect("answered");
        let c = s.edge.c;
        for d in [0.5, 1e-2, 1e-5, 1e-9] {
            let x = c * (1.0 - d);
            let (p, q_plain, q_edge) = s.fixed.stick_split(x);
            let q = q_plain + (c - x).powf(k.g) * q_edge;
            let (p0, q0) = s.fixed.at(x);
            eprintln!(
                "b* = {b}, g = {g}, x = c (1 - {d:e}): p {:.1e}, q {:.1e}",
                p - p0,
                q - q0
            );
            assert!((p - p0).abs() <= 1e-13 * (1.0 + p0.abs()), "p at {x}");
            assert!((q - q0).abs() <= 1e-13 / k.g * (1.0 + q0.abs()), "q at {x}");
        }
    }
}

/// The tractions' move per unit of lc grows as the move shrinks, as docs/theory_spectral.md
/// (S11) derives from the edge terms (c - x)^g and (x - c)^g ([`edge_move_factor`]): at a
/// level's fixed sizes, the move of q~ over lc + 1e-9 per unit of lc against the move over
/// [`SLOPE_STEP`], both by a rule graded down to 1e-15 at x = c
/// ([`crate::problem::traction_parts`]), lies within 20 % of the edge terms' ratio
/// (1 - d^g / (1 + g)) at the two moves d of c (the smooth terms move linearly; measured
/// 1.004 .. 2.64 against 1.006 .. 2.37); and the move over 1e-9, so resolved, is within
/// [`SAFETY`] times the factor times the move over the step as the estimates measure it
/// ([`distance`]'s 32 points per zone, which miss part of the edge terms' move next to c:
/// measured 1.04 .. 1.29 times less at the step).
#[test]
fn move_per_lc_grows_as_the_edge_terms_say() {
    for (b, g) in [
        (0.99, 1e-3),
        (0.75, 1e-3),
        (0.6, 0.01),
        (0.5, 0.1),
        (0.3, 0.3),
    ] {
        let mu = 1.0 / ((std::f64::consts::PI * g).tan() * b);
        let k = consts(b, mu);
        let (lc, _) = crate::stick_edge_table::lookup(b, mu).expect("tabulated");
        let e = StickEdge::from_logit(lc);
        let sizes = Sizes::at(4, e.c, e.one_minus_c);
        let at = |dlc: f64| {
            let e = StickEdge::from_logit(lc + dlc);
            Assembled::new(k, e.c, e.one_minus_c, sizes)
                .solve()
                .expect("solved")
        };
        let base = at(0.0);
        let resolved = |h: f64| {
            let moved = at(h);
            let edges = [moved.basis.c, base.basis.c];
            crate::problem::traction_parts(|x| moved.at(x), |x| base.at(x), edges).1 / h
        };
        let small = 1e-9;
        let ratio = resolved(small) / resolved(SLOPE_STEP);
        let cw = e.c * e.one_minus_c;
        let moved = |d: f64| 1.0 - d.powf(k.g) / (1.0 + k.g);
        let edge_terms = moved(small * cw) / moved(SLOPE_STEP * cw);
        let factor = edge_move_factor(k.g, e.c, e.one_minus_c);
        let estimated = distance(&at(SLOPE_STEP), &base).parts.1 / SLOPE_STEP;
        let needed = resolved(small) / estimated;
        eprintln!(
            "b* = {b}, g = {g}: ratio {ratio:.3}, the edge terms' {edge_terms:.3}; over the \
             estimates' move at the step {needed:.3}, factor {factor:.3}"
        );
        assert!((ratio / edge_terms - 1.0).abs() <= 0.2, "b* = {b}, g = {g}");
        assert!(needed <= SAFETY * factor, "b* = {b}, g = {g}");
    }
}
