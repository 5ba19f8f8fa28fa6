//! The vehicle's geometry at recorded times, for pictures.

use trackgen::contact::Terrain;
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::simulate::Results;
use trackgen::vehicles::m113::{M113Chassis, M113Track};
use trackgen::{ChassisModel, RecursiveModel, rotate};

const DT: usize = 66;
const DC: usize = 16;

/// The chassis outline in its centroid frame, m (a side view of the hull).
const HULL: [(f64, f64); 6] = [
    (2.4, 0.05),
    (2.0, 0.75),
    (1.2, 1.15),
    (-2.35, 1.15),
    (-2.35, 0.35),
    (-1.9, 0.05),
];

/// One picture's worth of geometry.
#[derive(Debug, Clone)]
pub struct Frame {
    pub t: f64,
    /// Track joints, in order round the loop.
    pub joints: Vec<(f64, f64)>,
    /// Wheels: centre and radius.
    pub wheels: Vec<(f64, f64, f64)>,
    /// Arms: pivot to wheel.
    pub arms: Vec<((f64, f64), (f64, f64))>,
    /// Chassis centroid and pitch.
    pub chassis: (f64, f64, f64),
    pub hull: Vec<(f64, f64)>,
}

/// The columns a picture needs: the track's and the chassis' coordinates
/// (`track.x` and the 65 after it, `chassis.x` and the 15 after it), out
/// of all the recorded ones; `None` if they are not there.
pub fn columns(all: &[String]) -> Option<Vec<String>> {
    let block = |prefix: &str, n: usize| {
        let start = all.iter().position(|c| *c == format!("{prefix}.x"))?;
        all.get(start..start + n).map(<[String]>::to_vec)
    };
    let mut names = block("track", DT)?;
    names.extend(block("chassis", DC)?);
    Some(names)
}

fn vector<const D: usize>(results: &Results, i: usize, prefix: &str) -> SVector<f64, D> {
    let start = results
        .columns()
        .iter()
        .position(|c| c == &format!("{prefix}.x"))
        .expect("coordinates");
    SVector::from_column_slice(&results.sample(i).values[start..start + D])
}

/// Frames every `dt` (s).
pub fn frames(results: &Results, dt: f64) -> Vec<Frame> {
    let mut out = Vec::new();
    let mut next = 0.0;
    for i in 0..results.len() {
        let t = results.sample(i).t;
        if t + 1e-9 < next {
            continue;
        }
        next = t + dt;
        out.push(frame(results, i));
    }
    out
}

fn frame(results: &Results, i: usize) -> Frame {
    let qt = vector::<DT>(results, i, "track");
    let qc = vector::<DC>(results, i, "chassis");
    let mut links = vec![Vector2::zeros(); 64];
    M113Track.body_positions(&qt, &mut links);
    let u1 = Vector2::new(-0.077, 0.0);
    let mut joints: Vec<(f64, f64)> = (0..64)
        .map(|j| links[j] + rotate(qt[2 + j], u1))
        .map(|p| (p.x, p.y))
        .collect();
    joints.push(joints[0]);
    let mut bodies = vec![Vector2::zeros(); 14];
    M113Chassis.body_positions(&qc, &mut bodies);
    let description = M113Chassis.description();
    let mut wheels = Vec::new();
    let mut arms = Vec::new();
    for part in <M113Chassis as ChassisModel<DC>>::PARTS {
        let c = bodies[part.body];
        wheels.push((c.x, c.y, part.radius));
        if let Some(arm) = &part.arm {
            let body = &description.bodies[arm.body];
            let pivot = bodies[arm.body] + rotate(qc[2 + arm.body], body.at_self);
            arms.push(((pivot.x, pivot.y), (c.x, c.y)));
        }
    }
    let hull = HULL
        .iter()
        .map(|&(x, y)| bodies[0] + rotate(qc[2], Vector2::new(x, y)))
        .map(|p| (p.x, p.y))
        .collect();
    Frame {
        t: results.sample(i).t,
        joints,
        wheels,
        arms,
        chassis: (qc[0], qc[1], qc[2]),
        hull,
    }
}

/// The terrain as a polyline over `[x0, x1]`.
pub fn ground(terrain: &Terrain, x0: f64, x1: f64) -> Vec<(f64, f64)> {
    (0..=400)
        .map(|k| x0 + (x1 - x0) * k as f64 / 400.0)
        .map(|x| (x, terrain.height(x)))
        .collect()
}

/// A still picture of one frame, SVG.
pub fn svg(frame: &Frame, terrain: &Terrain) -> String {
    let (cx, cy, _) = frame.chassis;
    let (x0, x1, y0, y1) = (cx - 3.5, cx + 3.5, cy - 1.6, cy + 1.6);
    let scale = 140.0;
    let px = |x: f64| (x - x0) * scale;
    let py = |y: f64| (y1 - y) * scale;
    let points = |ps: &[(f64, f64)]| {
        ps.iter()
            .map(|&(x, y)| format!("{:.1},{:.1}", px(x), py(y)))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0}\" height=\"{:.0}\" style=\"background:#fff\">\n",
        (x1 - x0) * scale,
        (y1 - y0) * scale
    );
    let mut terrain_line = ground(terrain, x0, x1);
    terrain_line.push((x1, y0));
    terrain_line.push((x0, y0));
    s += &format!(
        "<polygon points=\"{}\" fill=\"#d8c9a8\" stroke=\"#8a7650\"/>\n",
        points(&terrain_line)
    );
    s += &format!(
        "<polygon points=\"{}\" fill=\"#7d8b6a\" stroke=\"#3d4633\" stroke-width=\"2\"/>\n",
        points(&frame.hull)
    );
    for &((ax, ay), (bx, by)) in &frame.arms {
        s += &format!(
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#444\" stroke-width=\"7\"/>\n",
            px(ax),
            py(ay),
            px(bx),
            py(by)
        );
    }
    for &(x, y, r) in &frame.wheels {
        s += &format!(
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{:.1}\" fill=\"#555\" stroke=\"#222\" stroke-width=\"2\"/>\n",
            px(x),
            py(y),
            r * scale
        );
    }
    s += &format!(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#222\" stroke-width=\"6\"/>\n",
        points(&frame.joints)
    );
    for &(x, y) in &frame.joints {
        s += &format!(
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"2.5\" fill=\"#ddd\"/>\n",
            px(x),
            py(y)
        );
    }
    s += &format!(
        "<text x=\"10\" y=\"24\" font-family=\"sans-serif\" font-size=\"18\">t = {:.2} s</text>\n",
        frame.t
    );
    s + "</svg>\n"
}
