//! What a set writes: a CSV per event, every trial, the curves, the
//! pictures of the largest obstacles crossed, and the report page.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use plotters::prelude::*;
use trackgen::mobility::Published;

use super::tasks::{EVENTS, Row};
use super::text::{Against, against, parameter_text, value_text};

pub(super) fn write_all(
    dir: &Path,
    name: &str,
    published: &[Published],
    rows: &[Row],
    wall: f64,
) -> Result<Vec<String>, Box<dyn std::error::Error>> {
    fs::create_dir_all(dir)?;
    let mut files = Vec::new();
    for event in EVENTS {
        let mine: Vec<&Row> = rows.iter().filter(|r| r.event == event).collect();
        if mine.is_empty() {
            continue;
        }
        let file = format!("{event}.csv");
        let mut w = csv::Writer::from_path(dir.join(&file))?;
        w.write_record([
            "parameter",
            "parameter_value",
            "parameter_unit",
            "quantity",
            "relation",
            "value",
            "unit",
            "runs",
            "wall_s",
            "failure",
        ])?;
        for r in mine {
            let (p, pv, pu) = r
                .parameter
                .map_or(("", String::new(), ""), |(a, b, c)| (a, b.to_string(), c));
            w.write_record([
                p,
                &pv,
                pu,
                r.quantity,
                r.relation,
                &r.value.to_string(),
                r.unit,
                &r.runs.to_string(),
                &format!("{:.3}", r.wall),
                r.failure.as_deref().unwrap_or(""),
            ])?;
        }
        w.flush()?;
        files.push(file);
    }
    let mut w = csv::Writer::from_path(dir.join("trials.csv"))?;
    w.write_record([
        "event",
        "fixed",
        "fixed_value",
        "trial",
        "parameter",
        "figure",
        "passed",
        "confirming",
    ])?;
    for r in rows {
        let (p, pv) = r
            .parameter
            .map_or(("", String::new()), |(a, b, _)| (a, b.to_string()));
        for s in r.search.iter() {
            // The confirming trials (at the tighter tolerance) are the
            // last ones.
            let first = s.confirmation.map_or(s.trials.len(), |c| c.first_trial);
            for (k, t) in s.trials.iter().enumerate() {
                w.write_record([
                    r.event,
                    p,
                    &pv,
                    &k.to_string(),
                    &t.parameter.to_string(),
                    &t.figure.to_string(),
                    &t.passed.to_string(),
                    &(k >= first).to_string(),
                ])?;
            }
        }
    }
    w.flush()?;
    files.push("trials.csv".into());
    // Only a set with an event that has a curve draws them.
    let svg = curves(rows)?;
    if let Some(svg) = &svg {
        fs::write(dir.join("summary.svg"), svg)?;
        files.push("summary.svg".into());
    }
    // The vehicle at each obstacle's limit: a picture per search that
    // drew one.
    for r in rows {
        if let Some(picture) = r.picture.as_ref() {
            let file = format!("{}-limit.svg", r.event);
            fs::write(dir.join(&file), picture)?;
            files.push(file);
        }
    }
    fs::write(
        dir.join("report.html"),
        report(
            name,
            published,
            rows,
            wall,
            svg.as_deref().unwrap_or_default(),
        ),
    )?;
    files.push("report.html".into());
    Ok(files)
}

/// The curves of the events with a parameter: one panel each; `None`
/// for a set without any (obstacles alone).
fn curves(rows: &[Row]) -> Result<Option<String>, Box<dyn std::error::Error>> {
    let panels: [(&str, &str, &str, f64); 3] = [
        (
            "ride",
            "RMS roughness, in",
            "ride-limiting speed, m/s",
            1.0 / 0.0254,
        ),
        (
            "half-round",
            "half-round height, in",
            "speed at 2.5 g, m/s",
            1.0 / 0.0254,
        ),
        ("grade", "grade, %", "speed at full power, m/s", 100.0),
    ];
    // A panel per event of the set that has a curve, two to a row.
    let ran = |event: &str| rows.iter().any(|r| r.event == event);
    let panels: Vec<_> = panels.iter().filter(|p| ran(p.0)).collect();
    let soil = ran("soil");
    let count = panels.len() + usize::from(soil);
    if count == 0 {
        return Ok(None);
    }
    let (rows_of, columns) = (count.div_ceil(2), count.min(2));
    let mut svg = String::new();
    {
        let size = (600 * columns as u32, 380 * rows_of as u32);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE)?;
        let areas = root.split_evenly((rows_of, columns));
        if soil {
            drawbar_panel(rows, &areas[panels.len()])?;
        }
        for (&(event, x_label, y_label, scale), area) in panels.iter().zip(areas.iter()) {
            let points: Vec<(f64, f64, &str)> = rows
                .iter()
                .filter(|r| r.event == *event)
                .filter_map(|r| {
                    r.parameter
                        .map(|(_, p, _)| (p * scale, r.value, r.relation))
                })
                .filter(|(_, v, _)| v.is_finite())
                .collect();
            let x_max = points.iter().map(|p| p.0).fold(1e-9, f64::max) * 1.1;
            let y_max = points.iter().map(|p| p.1).fold(1e-9, f64::max) * 1.2;
            let mut chart = panel(area, event, (x_label, x_max), (y_label, y_max))?;
            chart.draw_series(LineSeries::new(points.iter().map(|p| (p.0, p.1)), &BLUE))?;
            // A limit beyond the search's range is drawn hollow.
            chart.draw_series(points.iter().map(|p| {
                let style = if p.2 == "=" {
                    BLUE.filled()
                } else {
                    BLUE.stroke_width(2)
                };
                Circle::new((p.0, p.1), 4, style)
            }))?;
        }
        root.present()?;
    }
    Ok(Some(svg))
}

/// One panel of the curves: `caption` over axes from 0 to `x_max` and
/// `y_max`, labelled, its mesh drawn.
fn panel<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    (x_label, x_max): (&str, f64),
    (y_label, y_max): (&str, f64),
) -> Result<
    ChartContext<
        'a,
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    Box<dyn std::error::Error>,
>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(48)
        .build_cartesian_2d(0.0..x_max, 0.0..y_max)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()?;
    Ok(chart)
}

/// The soil event's curves: drawbar pull over weight against slip, a line
/// per soil (from rest: no pull, no slip), the points the drive held with
/// a slip below 1.
fn drawbar_panel<DB: DrawingBackend>(
    rows: &[Row],
    area: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let mut soils: Vec<(&str, Vec<(f64, f64)>)> = Vec::new();
    for r in rows
        .iter()
        .filter(|r| r.event == "soil" && r.quantity == "slip")
    {
        let Some((soil, pull, _)) = r.parameter else {
            continue;
        };
        if !r.value.is_finite() {
            continue;
        }
        match soils.iter_mut().find(|(name, _)| *name == soil) {
            Some((_, points)) => points.push((r.value, pull)),
            None => soils.push((soil, vec![(0.0, 0.0), (r.value, pull)])),
        }
    }
    let x_max = soils
        .iter()
        .flat_map(|(_, p)| p.iter().map(|q| q.0))
        .fold(1e-3, f64::max)
        * 1.1;
    let y_max = soils
        .iter()
        .flat_map(|(_, p)| p.iter().map(|q| q.1))
        .fold(1e-3, f64::max)
        * 1.2;
    let mut chart = panel(
        area,
        "soil",
        ("slip", x_max),
        ("drawbar pull / weight", y_max),
    )?;
    const COLOURS: [RGBColor; 4] = [BLUE, RED, GREEN, MAGENTA];
    for ((soil, points), &colour) in soils.iter().zip(COLOURS.iter().cycle()) {
        chart
            .draw_series(LineSeries::new(points.iter().copied(), colour))?
            .label(*soil)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], colour));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
    }
    if !soils.is_empty() {
        chart
            .configure_series_labels()
            .background_style(WHITE)
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
    }
    Ok(())
}

fn report(name: &str, published: &[Published], rows: &[Row], wall: f64, svg: &str) -> String {
    let runs: usize = rows.iter().map(|r| r.runs).sum();
    let mut html = String::new();
    let _ = write!(
        html,
        "<!doctype html><html><head><meta charset=\"utf-8\"><title>{name}: mobility</title>\
         <style>body{{font-family:sans-serif;margin:2em}}td,th{{padding:2px 10px;text-align:left}}\
         td.n{{text-align:right}}tr:nth-child(even){{background:#f4f4f4}}</style></head><body>\
         <h1>{name}: pitch-plane mobility events</h1>\
         <p>{} results from {runs} runs in {wall:.1} s of wall time. A limit marked &gt; lies beyond \
         the searched range, &lt; before it; <i>stalled</i>: the vehicle did not get over (hover for where). Events, criteria and what the answers rest on: \
         the guide's Mobility chapter.</p>{svg}<table><tr><th>event</th><th>parameter</th>\
         <th>quantity</th><th>value</th><th>unit</th><th>runs</th><th>wall, s</th></tr>",
        rows.len()
    );
    for r in rows {
        let value = value_text(r).replace('>', "&gt;").replace('<', "&lt;");
        let title = r.failure.as_deref().unwrap_or("").replace('"', "&quot;");
        let _ = write!(
            html,
            "<tr title=\"{title}\"><td>{}</td><td>{}</td><td>{}</td><td class=\"n\">{value}</td><td>{}</td>\
             <td class=\"n\">{}</td><td class=\"n\">{:.1}</td></tr>",
            r.event,
            parameter_text(r),
            r.quantity,
            r.unit,
            r.runs,
            r.wall
        );
    }
    html.push_str("</table>");
    let against = against(published, rows);
    if !against.is_empty() {
        html.push_str(
            "<h2>Against the real vehicle</h2><table><tr><th>quantity</th><th>answer</th>\
             <th>published</th><th>unit</th><th>ratio</th><th>verdict</th><th>source</th></tr>",
        );
        for Against {
            figure,
            answer,
            ratio,
            verdict,
        } in against
        {
            let _ = write!(
                html,
                "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.3}</td><td>{}</td>\
                 <td class=\"n\">{ratio:.2}</td><td>{verdict}</td><td>{}</td></tr>",
                figure.quantity,
                answer.replace('>', "&gt;").replace('<', "&lt;"),
                figure.value,
                figure.unit,
                figure.source
            );
        }
        html.push_str("</table>");
    }
    let pictures: Vec<(&Row, &String)> = rows
        .iter()
        .filter_map(|r| Some((r, r.picture.as_ref()?)))
        .collect();
    if !pictures.is_empty() {
        html.push_str(
            "<h2>At the limits</h2><p>Each obstacle's largest crossed, the vehicle at its \
             steepest moment on it (the largest pitch of that run).</p>",
        );
        for (r, picture) in pictures {
            let _ = write!(
                html,
                "<figure><figcaption>{}: {} {}</figcaption>{picture}</figure>",
                r.quantity,
                value_text(r),
                r.unit
            );
        }
    }
    html.push_str("</body></html>\n");
    html
}
