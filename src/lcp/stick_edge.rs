//! Reading the stick-zone edge c off the discrete complementarity solution.
//!
//! Near c the exact solution has r = mu p - q ~ beta (c - x)^g on the stick side and
//! slip s ~ alpha (x - c)^(1 + g) on the slip side (THEORY.md section 5: p smooth on the
//! stick side, q carries |x - c|^g). So r^(1/g) and s^(1/(1+g)) are locally linear in x;
//! extrapolating each from its two grid points nearest to c gives the distances
//! d_r = c - x_{k-1} and d_s = x_k - c from the last stick point x_{k-1} and the first slip
//! point x_k, and c = x_{k-1} + h d_r / (d_r + d_s). This interpolation is continuous when
//! a point changes from stick to slip (d_r -> 0 or d_s -> 0), so c is not tied to the grid.

use super::discretisation::Grid;

/// Edge estimate: c, the slip width 1 - c (accurate when c is near 1) and the number k of
/// leading stick points (k = 0 or n: c lies in the unresolved half-panel at 0 or 1).
#[derive(Clone, Copy, Debug)]
pub(crate) struct EdgeEstimate {
    pub c: f64,
    pub one_minus_c: f64,
    pub stick_points: usize,
}

/// Distance from x_i to the zero of the local power law f ~ (distance)^e fitted through
/// the values f_i (nearer) and f_j (one panel further away); None if not monotone.
fn power_law_offset(h: f64, near: f64, far: f64, e: f64) -> Option<f64> {
    let (u0, u1) = (near.max(0.0).powf(1.0 / e), far.max(0.0).powf(1.0 / e));
    (u1 > u0).then(|| h * u0 / (u1 - u0))
}

/// Edge from the complementarity pair at the midpoints (a: scaled slip, b: scaled
/// friction reserve), with edge exponent g. Stick points: b_i > a_i.
pub(crate) fn locate(grid: Grid, a: &[f64], b: &[f64], g: f64) -> EdgeEstimate {
    let n = grid.n;
    let h = grid.h;
    let k = (0..n).find(|&i| a[i] >= b[i]).unwrap_or(n);
    // Offsets from the last stick point (stick side) and the first slip point (slip side).
    let d_r = (k >= 2)
        .then(|| power_law_offset(h, b[k - 1], b[k - 2], g))
        .flatten();
    let d_s = (k + 1 < n)
        .then(|| power_law_offset(h, a[k], a[k + 1], 1.0 + g))
        .flatten();
    // Position of c measured from the left end of its bracket [lo, lo + width].
    let (lo, width) = match k {
        0 => (0.0, 0.5 * h),
        _ if k == n => (grid.mid(n - 1), 0.5 * h),
        _ => (grid.mid(k - 1), h),
    };
    let offset = match (k, d_r, d_s) {
        (0, _, Some(ds)) => width - ds,
        (0, _, None) => 0.0,
        (_, Some(dr), _) if k == n => dr,
        (_, None, _) if k == n => width,
        (_, Some(dr), Some(ds)) => h * dr / (dr + ds),
        (_, Some(dr), None) => dr,
        (_, None, Some(ds)) => width - ds,
        (_, None, None) => 0.5 * width,
    }
    .clamp(0.0, width);
    // 1 - c = (1 - lo) - offset, with 1 - lo an exact multiple of h/2.
    let one_minus_lo = if k == 0 {
        1.0
    } else {
        (2 * (n - k) + 1) as f64 * 0.5 * h
    };
    EdgeEstimate {
        c: lo + offset,
        one_minus_c: one_minus_lo - offset,
        stick_points: k,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_an_edge_between_grid_points_from_exact_power_laws() {
        let grid = Grid::new(50);
        let (c, g) = (0.4137, 0.37);
        let a: Vec<f64> = (0..50)
            .map(|i| (grid.mid(i) - c).max(0.0).powf(1.0 + g) * 2.0)
            .collect();
        let b: Vec<f64> = (0..50)
            .map(|i| (c - grid.mid(i)).max(0.0).powf(g) * 0.7)
            .collect();
        let e = locate(grid, &a, &b, g);
        assert_eq!(e.stick_points, 21);
        assert!((e.c - c).abs() < 1e-14 && (e.one_minus_c - (1.0 - c)).abs() < 1e-14);
        // All stick: c in the last half-panel, extrapolated from the reserve.
        let c1 = 1.0 - 0.003;
        let b1: Vec<f64> = (0..50).map(|i| (c1 - grid.mid(i)).powf(g)).collect();
        let e1 = locate(grid, &vec![0.0; 50], &b1, g);
        assert_eq!(e1.stick_points, 50);
        assert!((e1.one_minus_c - 0.003).abs() < 1e-14);
    }
}
