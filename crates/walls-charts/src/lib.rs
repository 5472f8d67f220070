//! What the chart binaries share: drawing a chart of named series to SVG and PNG with
//! its data as CSV beside them, in `docs/charts/`, and finding a Pareto front.
//!
//! Each binary under `src/bin` measures one thing and writes one or more charts (but
//! `peers`, which draws what `scripts/bench-peers` measured with LAMMPS and LIGGGHTS);
//! `scripts/charts` runs them all. PNGs are drawn with the DejaVu Sans font embedded
//! here (`assets/`, under its own licence), so nothing depends on the fonts a machine
//! has.

use plotters::coord::Shift;
use plotters::prelude::*;
use std::io;
use std::path::{Path, PathBuf};

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points, with a dot at each.
    Line,
    /// Dots only.
    Dots,
    /// A dashed line, for a front or a reference.
    Dashed,
}

/// One named series of (x, y) points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend's name, also the CSV's `series` column.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub mark: Mark,
}

impl Series {
    /// A series drawn as `mark`.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark) -> Series {
        Series {
            name: name.into(),
            points,
            mark,
        }
    }
}

/// A chart: its file name (without extension), title, axis labels and scales.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// File name in `docs/charts`, without extension.
    pub name: String,
    /// Title over the plot.
    pub title: String,
    /// The x axis's label.
    pub x_label: String,
    /// The y axis's label.
    pub y_label: String,
    /// Logarithmic x axis.
    pub log_x: bool,
    /// Logarithmic y axis.
    pub log_y: bool,
}

/// The folder the charts go to: `docs/charts` of the repository.
pub fn out_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/charts")
}

/// The points of `points` not dominated by another (smaller or equal in both
/// coordinates, smaller in one), sorted by x: the Pareto front when both are costs.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut sorted: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in sorted {
        if front.last().is_none_or(|last| p.1 < last.1) {
            front.push(p);
        }
    }
    front
}

/// Writes `chart` of `series` as `<name>.csv`, `<name>.svg` and `<name>.png` in `dir`.
pub fn write(dir: &Path, chart: &Chart, series: &[Series]) -> io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let mut csv = csv::Writer::from_path(dir.join(format!("{}.csv", chart.name)))?;
    csv.write_record(["series", "x", "y"])?;
    for s in series {
        for (x, y) in &s.points {
            csv.write_record([s.name.clone(), x.to_string(), y.to_string()])?;
        }
    }
    csv.flush()?;
    write_pictures(dir, chart, series)
}

/// Writes `chart` of `series` as `<name>.svg` and `<name>.png` in `dir`, without the
/// CSV (for a chart drawn from data measured elsewhere).
pub fn write_pictures(dir: &Path, chart: &Chart, series: &[Series]) -> io::Result<()> {
    write_named_pictures(dir, chart, &[], series)
}

/// Writes `chart` of `series` as [`write_pictures`] does, its x axis a row of `names`
/// when there are any: the points at x = k belong to `names[k]` (a series may place
/// its points a little to either side, so that the tools of a name stand side by side).
/// `chart.log_x` is then ignored.
pub fn write_named_pictures(
    dir: &Path,
    chart: &Chart,
    names: &[String],
    series: &[Series],
) -> io::Result<()> {
    std::fs::create_dir_all(dir)?;
    register_font();
    let svg = dir.join(format!("{}.svg", chart.name));
    draw(
        SVGBackend::new(&svg, (900, 600)).into_drawing_area(),
        chart,
        names,
        series,
    )?;
    let png = dir.join(format!("{}.png", chart.name));
    draw(
        BitMapBackend::new(&png, (900, 600)).into_drawing_area(),
        chart,
        names,
        series,
    )
}

/// Makes the embedded font plotters' sans-serif, once.
fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TrueType font, so this cannot fail in practice; if it
        // did, the PNG would lack text, which the SVG (text as text) would not.
        let _ = plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            include_bytes!("../assets/DejaVuSans.ttf"),
        );
    });
}

/// The range covering every finite point's coordinate `pick`, padded a little (in
/// decades when logarithmic).
fn range(series: &[Series], pick: fn(&(f64, f64)) -> f64, log: bool) -> (f64, f64) {
    let values = series
        .iter()
        .flat_map(|s| s.points.iter().map(pick))
        .filter(|v| v.is_finite() && (!log || *v > 0.0));
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (0.0, 1.0) };
    }
    if log {
        (lo / 2.0, hi * 2.0)
    } else {
        let pad = ((hi - lo) * 0.05).max(1e-12);
        (lo - pad, hi + pad)
    }
}

/// Where the legend hides the fewest points of the series (and of the midpoints of their
/// lines): the middle of the right side unless something is under it, then the
/// corners. The legend is taken as a box of 30 % of the plot's width and 5 % of its
/// height a series.
fn legend_place(
    series: &[Series],
    chart: &Chart,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> SeriesLabelPosition {
    let unit = |v: f64, lo: f64, hi: f64, log: bool| {
        if log {
            (v.ln() - lo.ln()) / (hi.ln() - lo.ln())
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let mut points: Vec<(f64, f64)> = Vec::new();
    for s in series {
        let placed: Vec<(f64, f64)> = (s.points.iter())
            .filter(|(x, y)| {
                x.is_finite()
                    && y.is_finite()
                    && (!chart.log_x || *x > 0.0)
                    && (!chart.log_y || *y > 0.0)
            })
            .map(|&(x, y)| (unit(x, x0, x1, chart.log_x), unit(y, y0, y1, chart.log_y)))
            .collect();
        points.extend(
            placed
                .windows(2)
                .map(|w| (0.5 * (w[0].0 + w[1].0), 0.5 * (w[0].1 + w[1].1))),
        );
        points.extend(placed);
    }
    let (w, h) = (0.3, (0.05 * series.len() as f64 + 0.04).min(1.0));
    let candidates = [
        (SeriesLabelPosition::MiddleRight, 1.0 - w, 0.5 - h / 2.0),
        (SeriesLabelPosition::UpperRight, 1.0 - w, 1.0 - h),
        (SeriesLabelPosition::UpperLeft, 0.0, 1.0 - h),
        (SeriesLabelPosition::LowerRight, 1.0 - w, 0.0),
        (SeriesLabelPosition::LowerLeft, 0.0, 0.0),
        (SeriesLabelPosition::MiddleLeft, 0.0, 0.5 - h / 2.0),
    ];
    let hidden = |&(_, left, bottom): &(SeriesLabelPosition, f64, f64)| {
        (points.iter())
            .filter(|(x, y)| (left..=left + w).contains(x) && (bottom..=bottom + h).contains(y))
            .count()
    };
    // The first of the least hidden (`min_by_key` keeps the first of equals).
    let best = candidates.iter().min_by_key(|c| hidden(c));
    best.map_or(SeriesLabelPosition::MiddleRight, |c| c.0.clone())
}

/// The labelled and the unlabelled grid lines of a logarithmic axis over [lo, hi]: the
/// labels at m·10ᵏ for m in 1…9 over at most 1.2 decades, 1, 2 and 5 over at most 3,
/// 1 beyond (so that no two labels come closer than about 20 pixels on a 600-pixel
/// chart); the other m·10ᵏ unlabelled.
fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let decades = (hi / lo).log10();
    let labelled: &[u32] = if decades <= 1.2 {
        &[1, 2, 3, 4, 5, 6, 7, 8, 9]
    } else if decades <= 3.0 {
        &[1, 2, 5]
    } else {
        &[1]
    };
    let (mut bold, mut light) = (Vec::new(), Vec::new());
    for k in lo.log10().floor() as i32..=hi.log10().ceil() as i32 {
        for m in 1..=9 {
            let v = f64::from(m) * 10f64.powi(k);
            if (lo..=hi).contains(&v) {
                if labelled.contains(&m) {
                    &mut bold
                } else {
                    &mut light
                }
                .push(v);
            }
        }
    }
    (bold, light)
}

/// The label of `v` on an axis of `names` at 0, 1, …: its name at a whole number, none
/// between; `tick`'s on a numbered axis.
fn x_tick(names: &[String], v: f64) -> String {
    if names.is_empty() {
        return tick(v);
    }
    let k = v.round();
    match names.get(k as usize) {
        Some(name) if k >= 0.0 && (v - k).abs() < 1e-9 => name.clone(),
        _ => String::new(),
    }
}

/// A linear axis whose only grid lines and labels are at the given places (the names'
/// axis). plotters' `(x0..x1).with_key_points(…)` would place them, but it forwards an
/// f64 axis's `NoDefaultFormatting` without its `ValueFormatter`, so `configure_mesh`
/// refuses it (plotters 0.3.7).
struct Places {
    linear: plotters::coord::types::RangedCoordf64,
    at: Vec<f64>,
}

impl Ranged for Places {
    type ValueType = f64;
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.linear.map(value, limit)
    }

    fn key_points<Hint: plotters::coord::ranged1d::KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.at.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.linear.range()
    }
}

/// Picks the axis type for each scale and draws.
fn draw<DB: DrawingBackend>(
    area: DrawingArea<DB, Shift>,
    chart: &Chart,
    names: &[String],
    series: &[Series],
) -> io::Result<()>
where
    DB::ErrorType: 'static,
{
    let named = !names.is_empty();
    let log_x = chart.log_x && !named;
    let (x0, x1) = if named {
        (-0.5, names.len() as f64 - 0.5)
    } else {
        range(series, |p| p.0, log_x)
    };
    let (y0, y1) = range(series, |p| p.1, chart.log_y);
    let chart = &Chart {
        log_x,
        ..chart.clone()
    };
    let failed = |e: String| io::Error::other(e);
    area.fill(&WHITE).map_err(|e| failed(e.to_string()))?;
    let mut builder = ChartBuilder::on(&area);
    builder
        .caption(&chart.title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75);
    macro_rules! plot {
        ($x:expr, $y:expr) => {{
            let mut ctx = builder
                .build_cartesian_2d($x, $y)
                .map_err(|e| failed(e.to_string()))?;
            ctx.configure_mesh()
                .x_desc(&chart.x_label)
                .y_desc(&chart.y_label)
                .x_label_formatter(&|v| x_tick(names, *v))
                .y_label_formatter(&|v| tick(*v))
                .label_style(("sans-serif", 14))
                .draw()
                .map_err(|e| failed(e.to_string()))?;
            for (k, s) in series.iter().enumerate() {
                let color = Palette99::pick(k).to_rgba();
                let points: Vec<(f64, f64)> = s
                    .points
                    .iter()
                    .copied()
                    .filter(|(x, y)| {
                        x.is_finite()
                            && y.is_finite()
                            && (!chart.log_x || *x > 0.0)
                            && (!chart.log_y || *y > 0.0)
                    })
                    .collect();
                let drawn = match s.mark {
                    Mark::Line => {
                        ctx.draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))
                            .map_err(|e| failed(e.to_string()))?;
                        ctx.draw_series(points.iter().map(|p| Circle::new(*p, 3, color.filled())))
                    }
                    Mark::Dots => {
                        ctx.draw_series(points.iter().map(|p| Circle::new(*p, 4, color.filled())))
                    }
                    Mark::Dashed => ctx.draw_series(DashedLineSeries::new(
                        points.clone(),
                        8,
                        5,
                        BLACK.stroke_width(2),
                    )),
                };
                let legend_color = if s.mark == Mark::Dashed {
                    BLACK.to_rgba()
                } else {
                    color
                };
                drawn
                    .map_err(|e| failed(e.to_string()))?
                    .label(&s.name)
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], legend_color.stroke_width(2))
                    });
            }
            ctx.configure_series_labels()
                .position(legend_place(series, chart, (x0, x1), (y0, y1)))
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font(("sans-serif", 13))
                .draw()
                .map_err(|e| failed(e.to_string()))?;
        }};
    }
    // Logarithmic axes take their grid from `log_ticks`: plotters' own labels each of
    // 1…10 × 10ᵏ over two decades, which overlap.
    let log = |lo: f64, hi: f64| {
        let (bold, light) = log_ticks(lo, hi);
        (lo..hi)
            .log_scale()
            .with_key_points(bold)
            .with_light_points(light)
    };
    let places = || Places {
        linear: (x0..x1).into(),
        at: (0..names.len()).map(|k| k as f64).collect(),
    };
    match (named, chart.log_x, chart.log_y) {
        (true, _, true) => plot!(places(), log(y0, y1)),
        (true, _, false) => plot!(places(), y0..y1),
        (false, true, true) => plot!(log(x0, x1), log(y0, y1)),
        (false, true, false) => plot!(log(x0, x1), y0..y1),
        (false, false, true) => plot!(x0..x1, log(y0, y1)),
        (false, false, false) => plot!(x0..x1, y0..y1),
    }
    area.present().map_err(|e| failed(e.to_string()))
}

/// A tick label: three significant digits, in scientific notation outside 10⁻³…10⁴.
fn tick(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let a = v.abs();
    if (1e-3..1e4).contains(&a) {
        let digits = (2 - a.log10().floor() as i32).max(0) as usize;
        let text = format!("{v:.digits$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        format!("{v:.1e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_labels_thin_out_as_the_decades_grow() {
        let (bold, light) = log_ticks(3e6, 3e7);
        assert_eq!(bold, [3e6, 4e6, 5e6, 6e6, 7e6, 8e6, 9e6, 1e7, 2e7, 3e7]);
        assert!(light.is_empty());
        let (bold, light) = log_ticks(2.4e6, 2e8);
        assert_eq!(bold, [5e6, 1e7, 2e7, 5e7, 1e8, 2e8]);
        assert_eq!(light.len(), 12);
        let (bold, _) = log_ticks(50.0, 2e5);
        assert_eq!(bold, [100.0, 1e3, 1e4, 1e5]);
    }

    #[test]
    fn a_named_chart_draws_its_names_under_their_places_and_log_labels_on_y() {
        let dir = tempfile::tempdir().unwrap();
        let chart = Chart {
            name: "named".into(),
            title: "t".into(),
            x_label: "scene".into(),
            y_label: "rate".into(),
            log_x: true,
            log_y: true,
        };
        let names = ["cup: 10,640".to_string(), "poly: 100,000".to_string()];
        let series = [Series::new(
            "walls-sim",
            vec![(-0.1, 3e6), (1.1, 3e7)],
            Mark::Dots,
        )];
        write_named_pictures(dir.path(), &chart, &names, &series).unwrap();
        let svg = std::fs::read_to_string(dir.path().join("named.svg")).unwrap();
        // Each label once: a name under its place, none between; y's 1, 2 and 5 × 10ᵏ.
        for label in ["cup: 10,640", "poly: 100,000", "5.0e6", "1.0e7"] {
            let text = format!(">\n{label}\n</text>");
            assert_eq!(svg.matches(&text).count(), 1, "{label}");
        }
        assert!(dir.path().join("named.png").exists());
    }

    #[test]
    fn a_named_axis_labels_its_whole_places_only() {
        let names = ["cup".to_string(), "poly".to_string()];
        assert_eq!(x_tick(&names, 1.0), "poly");
        assert_eq!(x_tick(&names, 0.5), "");
        assert_eq!(x_tick(&names, 2.0), "");
        assert_eq!(x_tick(&names, -1.0), "");
        assert_eq!(x_tick(&[], 1000.0), "1000");
    }
}
