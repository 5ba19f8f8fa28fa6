//! The run's time histories (SVG): chassis speed, height and pitch,
//! sprocket torque and speed, the tension in link 1 and the ground's
//! normal force, one panel each, from the recorded columns [`columns`]
//! names.

use std::error::Error;
use std::path::Path;

use plotters::prelude::*;
use trackgen::simulate::Results;

/// Panels: title, unit, and (column, scale, label) series.
type Panel = (
    &'static str,
    &'static str,
    &'static [(&'static str, f64, &'static str)],
);

const PANELS: [Panel; 6] = [
    ("chassis speed", "m/s", &[("speed", 1.0, "speed")]),
    (
        "chassis height and pitch",
        "m, deg",
        &[
            ("y", 1.0, "centroid y (m)"),
            ("pitch", 57.29577951308232, "pitch (deg)"),
        ],
    ),
    (
        "sprocket torque",
        "kN m",
        &[("sprocket_torque", 1e-3, "torque")],
    ),
    (
        "sprocket speed",
        "rad/s",
        &[("sprocket_speed", 1.0, "relative to chassis")],
    ),
    ("tension in link 1", "kN", &[("tension", 1e-3, "tension")]),
    (
        "ground normal force",
        "kN",
        &[("ground_normal", 1e-3, "sum over shoes")],
    ),
];

/// The columns the plots draw.
pub fn columns() -> Vec<String> {
    PANELS
        .iter()
        .flat_map(|(_, _, series)| series.iter().map(|(c, _, _)| c.to_string()))
        .collect()
}

/// Draws the panels from `results` (which must hold [`columns`]) into the
/// SVG file `path`.
pub fn draw(results: &Results, path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1000, 1050)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((3, 2));
    let t = results.times();
    let t_end = t.last().copied().unwrap_or(1.0).max(1e-3);
    for ((title, unit, series), area) in PANELS.iter().zip(areas.iter()) {
        let data: Vec<(Vec<(f64, f64)>, &str)> = series
            .iter()
            .map(|(col, scale, label)| {
                let v = results.column(col).unwrap_or_default();
                (
                    t.iter().zip(v).map(|(&t, v)| (t, v * scale)).collect(),
                    *label,
                )
            })
            .collect();
        let (lo, hi) = data
            .iter()
            .flat_map(|(d, _)| d.iter().map(|p| p.1))
            .filter(|v| v.is_finite())
            .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
        let (lo, hi) = if lo < hi {
            (lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
        } else {
            (lo - 1.0, lo + 1.0)
        };
        let mut chart = ChartBuilder::on(area)
            .caption(*title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(30)
            .y_label_area_size(55)
            .build_cartesian_2d(0.0..t_end, lo..hi)?;
        chart
            .configure_mesh()
            .x_desc("t (s)")
            .y_desc(*unit)
            .draw()?;
        for (k, (d, label)) in data.into_iter().enumerate() {
            let color = Palette99::pick(k).to_rgba();
            chart
                .draw_series(LineSeries::new(d, color.stroke_width(2)))?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], color));
        }
        if series.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.9))
                .border_style(BLACK)
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}
