//! SVG charts for the benchmark and study examples (plotters, SVG backend: no fonts or
//! Python needed).

use plotters::prelude::*;
use plotters::style::colors::colormaps::ViridisRGB;

/// One named series of (x, y) points.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// Join the points with a line (else markers only).
    pub line: bool,
}

/// Axis scaling of a chart.
#[derive(Clone, Copy)]
pub enum Scale {
    Linear,
    Log,
}

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

/// The range covering every point (padded a little; positive ranges on log axes).
fn range(values: impl Iterator<Item = f64>, scale: Scale) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && (matches!(scale, Scale::Linear) || *v > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    match scale {
        Scale::Log => lo / 2.0..hi * 2.0,
        Scale::Linear => {
            let pad = 0.05 * (hi - lo).max(1e-12);
            lo - pad..hi + pad
        }
    }
}

/// A line/marker chart of several series; `highlight` (e.g. a Pareto front) is drawn as a
/// thick black line on top.
pub fn chart(
    path: &str,
    title: &str,
    (x_desc, x_scale): (&str, Scale),
    (y_desc, y_scale): (&str, Scale),
    series: &[Series],
    highlight: Option<&Series>,
) -> Result<(), Box<dyn std::error::Error>> {
    let all = || series.iter().flat_map(|s| s.points.iter().copied());
    let xr = range(all().map(|p| p.0), x_scale);
    let yr = range(all().map(|p| p.1), y_scale);
    let root = SVGBackend::new(path, (960, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut builder = ChartBuilder::on(&root);
    builder
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75);
    macro_rules! draw {
        ($chart:expr) => {{
            let mut chart = $chart;
            let fmt = |scale: Scale| {
                move |v: &f64| match scale {
                    Scale::Log => format!("{v:.0e}"),
                    Scale::Linear => format!("{v:.2}"),
                }
            };
            chart
                .configure_mesh()
                .x_desc(x_desc)
                .y_desc(y_desc)
                .x_label_formatter(&fmt(x_scale))
                .y_label_formatter(&fmt(y_scale))
                .draw()?;
            for (i, s) in series.iter().enumerate() {
                let color = PALETTE[i % PALETTE.len()];
                let pts: Vec<(f64, f64)> = s
                    .points
                    .iter()
                    .copied()
                    .filter(|p| p.0.is_finite() && p.1.is_finite())
                    .collect();
                // Markers unless the series is a dense line.
                let radius = if s.line && pts.len() > 40 { 0 } else { 4 };
                if s.line {
                    chart.draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))?;
                }
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, radius, color.filled())))?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
            }
            if let Some(h) = highlight {
                chart
                    .draw_series(LineSeries::new(h.points.clone(), BLACK.stroke_width(1)))?
                    .label(h.name.as_str())
                    .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
            }
            chart
                .configure_series_labels()
                .position(SeriesLabelPosition::UpperRight)
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .draw()?;
        }};
    }
    match (x_scale, y_scale) {
        (Scale::Log, Scale::Log) => {
            draw!(builder.build_cartesian_2d(xr.log_scale(), yr.log_scale())?)
        }
        (Scale::Log, Scale::Linear) => draw!(builder.build_cartesian_2d(xr.log_scale(), yr)?),
        (Scale::Linear, Scale::Log) => draw!(builder.build_cartesian_2d(xr, yr.log_scale())?),
        (Scale::Linear, Scale::Linear) => draw!(builder.build_cartesian_2d(xr, yr)?),
    }
    root.present()?;
    Ok(())
}

/// A heat map of log10(value) over a grid (x log-spaced, y linear), with band edges at the
/// given decades drawn as contours (cells whose value crosses a level against a neighbour
/// are outlined in black). NaN values (no data: a failed method or reference) are grey.
pub fn heatmap(
    path: &str,
    title: &str,
    (x_desc, xs): (&str, &[f64]),
    (y_desc, ys): (&str, &[f64]),
    values: &[Vec<f64>],
    levels: &[f64],
) -> Result<(), Box<dyn std::error::Error>> {
    let logs: Vec<Vec<f64>> = values
        .iter()
        .map(|row| {
            row.iter()
                .map(|&v| if v.is_nan() { v } else { v.max(1e-17).log10() })
                .collect()
        })
        .collect();
    let (lo, hi) = logs
        .iter()
        .flatten()
        .filter(|v| !v.is_nan())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let root = SVGBackend::new(path, (960, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (main, bar) = root.split_horizontally(860);
    let cell = |i: usize, v: &[f64]| {
        let a = if i == 0 {
            v[0]
        } else {
            (v[i - 1] * v[i]).sqrt()
        };
        let b = if i + 1 == v.len() {
            v[i]
        } else {
            (v[i] * v[i + 1]).sqrt()
        };
        (a, b)
    };
    let celly = |j: usize| {
        let a = if j == 0 {
            ys[0]
        } else {
            0.5 * (ys[j - 1] + ys[j])
        };
        let b = if j + 1 == ys.len() {
            ys[j]
        } else {
            0.5 * (ys[j] + ys[j + 1])
        };
        (a, b)
    };
    let mut chart = ChartBuilder::on(&main)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (xs[0]..xs[xs.len() - 1]).log_scale(),
            ys[0]..ys[ys.len() - 1],
        )?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .draw()?;
    let color = |v: f64| {
        if v.is_nan() {
            RGBColor(200, 200, 200)
        } else {
            ViridisRGB::get_color_normalized(v, lo, hi.max(lo + 1e-9))
        }
    };
    for (j, row) in logs.iter().enumerate() {
        for (i, &v) in row.iter().enumerate() {
            let ((x0, x1), (y0, y1)) = (cell(i, xs), celly(j));
            chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                color(v).filled(),
            )))?;
        }
    }
    // Contours: segments between neighbouring cells on opposite sides of a level.
    for &level in levels {
        let l = level.log10();
        for j in 0..ys.len() {
            for i in 0..xs.len() {
                let v = logs[j][i];
                if i + 1 < xs.len() && (v - l) * (logs[j][i + 1] - l) < 0.0 {
                    let x = cell(i, xs).1;
                    let (y0, y1) = celly(j);
                    chart.draw_series(std::iter::once(PathElement::new(
                        vec![(x, y0), (x, y1)],
                        BLACK.stroke_width(2),
                    )))?;
                }
                if j + 1 < ys.len() && (v - l) * (logs[j + 1][i] - l) < 0.0 {
                    let y = celly(j).1;
                    let (x0, x1) = cell(i, xs);
                    chart.draw_series(std::iter::once(PathElement::new(
                        vec![(x0, y), (x1, y)],
                        BLACK.stroke_width(2),
                    )))?;
                }
            }
        }
    }
    // Colour bar in decades.
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(40)
        .margin_bottom(57)
        .y_label_area_size(45)
        .build_cartesian_2d(0.0..1.0, lo..hi.max(lo + 1e-9))?;
    cb.configure_mesh()
        .disable_x_mesh()
        .disable_x_axis()
        .y_label_formatter(&|v| format!("1e{v:.0}"))
        .draw()?;
    let steps = 100;
    for k in 0..steps {
        let (a, b) = (
            lo + (hi - lo) * k as f64 / steps as f64,
            lo + (hi - lo) * (k + 1) as f64 / steps as f64,
        );
        cb.draw_series(std::iter::once(Rectangle::new(
            [(0.0, a), (1.0, b)],
            color(0.5 * (a + b)).filled(),
        )))?;
    }
    root.present()?;
    Ok(())
}

/// A filled contour map of a field over a regular grid (linear x and y; `values[j][i]` at
/// (xs[i], ys[j])): `bands` equal bands of the value across `span` (values beyond it take the
/// end bands: singular fields are clipped; NaN is grey), each cell coloured by its band (runs
/// of equal band along a row drawn as one rectangle), and the band edges drawn as contour
/// lines (marching squares: in each grid cell the level's crossings of the cell edges, by
/// linear interpolation, joined pairwise). A colour bar shows the bands; `outline` is drawn on
/// top (e.g. the punch) as a thick red line.
#[allow(clippy::too_many_arguments)]
pub fn contour_map(
    path: &str,
    title: &str,
    (x_desc, xs): (&str, &[f64]),
    (y_desc, ys): (&str, &[f64]),
    values: &[Vec<f64>],
    span: (f64, f64),
    bands: usize,
    outline: &[(f64, f64)],
) -> Result<(), Box<dyn std::error::Error>> {
    let (lo, hi) = span;
    let (nx, ny) = (xs.len(), ys.len());
    let width = (hi - lo) / bands as f64;
    let band = |v: f64| ((v - lo) / width).floor().clamp(0.0, bands as f64 - 1.0) as usize;
    let color =
        |b: usize| ViridisRGB::get_color_normalized(lo + (b as f64 + 0.5) * width, lo, hi).filled();
    let grey = RGBColor(200, 200, 200).filled();
    let root = SVGBackend::new(path, (960, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let (main, bar) = root.split_horizontally(860);
    let mut chart = ChartBuilder::on(&main)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(xs[0]..xs[nx - 1], ys[0]..ys[ny - 1])?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .disable_mesh()
        .draw()?;
    // cell i of a grid axis spans the midpoints to its neighbours
    let cell = |v: &[f64], i: usize| {
        let a = if i == 0 {
            v[0]
        } else {
            0.5 * (v[i - 1] + v[i])
        };
        let b = if i + 1 == v.len() {
            v[i]
        } else {
            0.5 * (v[i] + v[i + 1])
        };
        (a, b)
    };
    let mut rects = Vec::new();
    for (j, row) in values.iter().enumerate() {
        let (y0, y1) = cell(ys, j);
        let key = |v: f64| (!v.is_nan()).then(|| band(v));
        let mut start = 0;
        for i in 1..=nx {
            if i == nx || key(row[i]) != key(row[start]) {
                let style = key(row[start]).map_or(grey, color);
                rects.push(Rectangle::new(
                    [(cell(xs, start).0, y0), (cell(xs, i - 1).1, y1)],
                    style,
                ));
                start = i;
            }
        }
    }
    chart.draw_series(rects)?;
    for l in 1..bands {
        let level = lo + l as f64 * width;
        let mut segments = Vec::new();
        for j in 0..ny - 1 {
            for i in 0..nx - 1 {
                let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
                let mut cross = Vec::new();
                for k in 0..4 {
                    let ((ia, ja), (ib, jb)) = (corners[k], corners[(k + 1) % 4]);
                    let (va, vb) = (values[ja][ia], values[jb][ib]);
                    if va.is_finite() && vb.is_finite() && (va - level) * (vb - level) < 0.0 {
                        let s = (level - va) / (vb - va);
                        cross.push((
                            xs[ia] + s * (xs[ib] - xs[ia]),
                            ys[ja] + s * (ys[jb] - ys[ja]),
                        ));
                    }
                }
                for pair in cross.chunks_exact(2) {
                    segments.push(PathElement::new(
                        vec![pair[0], pair[1]],
                        BLACK.mix(0.6).stroke_width(1),
                    ));
                }
            }
        }
        chart.draw_series(segments)?;
    }
    if !outline.is_empty() {
        chart.draw_series(std::iter::once(PathElement::new(
            outline.to_vec(),
            RGBColor(214, 39, 40).stroke_width(4),
        )))?;
    }
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(40)
        .margin_bottom(57)
        .y_label_area_size(50)
        .build_cartesian_2d(0.0..1.0, lo..hi)?;
    cb.configure_mesh()
        .disable_x_mesh()
        .disable_x_axis()
        .y_label_formatter(&|v| format!("{v:.2}"))
        .draw()?;
    cb.draw_series((0..bands).map(|b| {
        let a = lo + b as f64 * width;
        Rectangle::new([(0.0, a), (1.0, a + width)], color(b))
    }))?;
    root.present()?;
    Ok(())
}
