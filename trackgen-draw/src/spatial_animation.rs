//! A self-contained HTML page that plays a run of the spatial vehicle:
//! a top view (both tracks, the hull, the path so far and, on soft soil,
//! the ruts pressed by then) beside a side view
//! along the hull's heading (the tracks, the wheels, the hull's outline and
//! the ground under it). Canvas, no external files: open it in a browser.

use std::fmt::Write;

use trackgen::contact::rut_grid::RutPatch;
use trackgen::nalgebra::{Vector2, Vector3};
use trackgen::spatial_vehicle::SpatialScene;

use crate::animation::Mm;

/// `points` as a flat JSON list of their coordinates to 0.1 mm.
fn flat(points: impl IntoIterator<Item = Vector2<f64>>) -> String {
    let mut s = String::from("[");
    for (i, p) in points.into_iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        let _ = write!(s, "{},{}", Mm(p.x), Mm(p.y));
    }
    s + "]"
}

/// The side view's coordinates of a world point: along the hull's
/// horizontal heading `forward` from `centre`, and up from it, m.
fn side(p: &Vector3<f64>, centre: &Vector3<f64>, forward: &Vector2<f64>) -> Vector2<f64> {
    let d = p - centre;
    Vector2::new(d.x * forward.x + d.y * forward.y, d.z)
}

/// One frame's JSON: the top view in world `x, y`; the side view from
/// the centroid along the heading, over the scene's floor.
fn frame(f: &SpatialScene) -> String {
    let heading = f.axes[0].xy();
    let forward = if heading.norm() > 1e-9 {
        heading.normalize()
    } else {
        Vector2::x()
    };
    let top = |points: &[Vector3<f64>]| flat(points.iter().map(|p| p.xy()));
    let seen = |points: &[Vector3<f64>]| flat(points.iter().map(|p| side(p, &f.centre, &forward)));
    let wheels: Vec<String> = f
        .wheels
        .iter()
        .map(|(c, r, s)| {
            let at = side(c, &f.centre, &forward);
            format!("[{},{},{},{s}]", Mm(at.x), Mm(at.y), Mm(*r))
        })
        .collect();
    let floor = flat(f.floor.iter().copied());
    format!(
        "{{\"t\":{:.3},\"tw\":{},\"c\":[{},{}],\"top\":{},\"tr\":[{},{}],\"o\":{},\"sr\":[{},{}],\"w\":[{}],\"g\":{}}}",
        f.t,
        Mm(f.track_width),
        Mm(f.centre.x),
        Mm(f.centre.y),
        top(&f.top),
        top(&f.tracks[0]),
        top(&f.tracks[1]),
        seen(&f.outline),
        seen(&f.tracks[0]),
        seen(&f.tracks[1]),
        wheels.join(","),
        floor
    )
}

/// The ruts' JSON: each square's centre, side and sinkage (to 0.1 mm)
/// and when it was first pressed (s, to the millisecond), flat.
fn ruts(patches: &[RutPatch]) -> String {
    let mut s = String::from("[");
    for (i, p) in patches.iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        let _ = write!(
            s,
            "{},{},{},{},{:.3}",
            Mm(p.centre.x),
            Mm(p.centre.y),
            Mm(p.side),
            Mm(p.sinkage),
            p.since
        );
    }
    s + "]"
}

/// The page playing `frames`, each over its floor, the top view over the
/// `ruts` pressed by each frame's time (none on rigid ground), headed
/// `title`.
pub fn html(frames: &[SpatialScene], ruts_pressed: &[RutPatch], title: &str) -> String {
    let mut data = String::from("[");
    for (i, f) in frames.iter().enumerate() {
        if i > 0 {
            data.push_str(",\n");
        }
        data.push_str(&frame(f));
    }
    data.push(']');
    TEMPLATE
        .replace("__TITLE__", title)
        .replace("__RUTS__", &ruts(ruts_pressed))
        .replace("__FRAMES__", &data)
}

const TEMPLATE: &str = r#"<!doctype html>
<html><head><meta charset="utf-8"><title>trackgen: __TITLE__</title>
<style>body{font-family:sans-serif;margin:16px}canvas{border:1px solid #ccc;background:#fff;margin-right:8px}</style></head>
<body>
<h3>trackgen: __TITLE__</h3>
<canvas id="top" width="560" height="460"></canvas><canvas id="side" width="560" height="460"></canvas><br>
<button id="play">pause</button> <input id="s" type="range" min="0" value="0" style="width:800px"> <span id="t"></span>
<p>Left: from above, the right track dark, the left light (each as wide as its shoes), the path of the hull's centroid dotted, on soft soil the ruts pressed so far in brown (darker deeper). Right: from the right, along the hull's heading, over the ground under the right track as it was then (on soft soil, its rut), the left track and wheels behind in grey.</p>
<script>
const F = __FRAMES__;
const R = __RUTS__;
let deepest = 0; for (let i = 3; i < R.length; i += 5) deepest = Math.max(deepest, R[i]);
const tc = document.getElementById('top').getContext('2d'), sc = document.getElementById('side').getContext('2d');
const slider = document.getElementById('s'); slider.max = F.length - 1;
let k = 0, playing = true;
document.getElementById('play').onclick = e => { playing = !playing; e.target.textContent = playing ? 'pause' : 'play'; };
slider.oninput = () => { k = +slider.value; draw(); };
const M = 60;
function line(g, X, Y, p, close) { g.beginPath(); for (let i = 0; i < p.length; i += 2) g[i ? 'lineTo' : 'moveTo'](X(p[i]), Y(p[i+1])); if (close) g.closePath(); }
function drawTop(f) {
  const g = tc, w = g.canvas.width, h = g.canvas.height;
  const X = x => (x - f.c[0]) * M + w / 2, Y = y => h / 2 - (y - f.c[1]) * M;
  g.clearRect(0, 0, w, h);
  for (let i = 0; i < R.length; i += 5) if (R[i + 4] <= f.t) {
    g.fillStyle = 'rgba(120,85,40,' + (0.15 + 0.75 * R[i + 3] / deepest).toFixed(3) + ')';
    const s = R[i + 2] * M; g.fillRect(X(R[i]) - s / 2, Y(R[i + 1]) - s / 2, s, s);
  }
  g.fillStyle = '#999'; for (let i = 0; i <= k; i++) { g.fillRect(X(F[i].c[0]) - 1, Y(F[i].c[1]) - 1, 2, 2); }
  line(g, X, Y, f.top, true); g.fillStyle = '#7d8b6a'; g.fill(); g.strokeStyle = '#3d4633'; g.lineWidth = 2; g.stroke();
  g.lineCap = 'butt'; g.lineJoin = 'round';
  line(g, X, Y, f.tr[1], false); g.strokeStyle = '#888'; g.lineWidth = f.tw * M; g.stroke();
  line(g, X, Y, f.tr[0], false); g.strokeStyle = '#333'; g.lineWidth = f.tw * M; g.stroke();
}
function drawSide(f) {
  const g = sc, w = g.canvas.width, h = g.canvas.height;
  const X = u => u * M + w / 2, Y = v => h * 0.55 - v * M;
  g.clearRect(0, 0, w, h);
  line(g, X, Y, f.g, false); g.lineTo(X(f.g[f.g.length-2]), h); g.lineTo(X(f.g[0]), h); g.closePath();
  g.fillStyle = '#d8c9a8'; g.fill(); g.strokeStyle = '#8a7650'; g.lineWidth = 1; g.stroke();
  line(g, X, Y, f.sr[1], false); g.strokeStyle = '#aaa'; g.lineWidth = 4; g.stroke();
  for (const c of f.w) if (c[3] === 1) { g.beginPath(); g.arc(X(c[0]), Y(c[1]), c[2] * M, 0, 2 * Math.PI); g.fillStyle = '#bbb'; g.fill(); }
  line(g, X, Y, f.o, true); g.fillStyle = 'rgba(125,139,106,0.85)'; g.fill(); g.strokeStyle = '#3d4633'; g.lineWidth = 2; g.stroke();
  for (const c of f.w) if (c[3] === 0) { g.beginPath(); g.arc(X(c[0]), Y(c[1]), c[2] * M, 0, 2 * Math.PI); g.fillStyle = '#555'; g.fill(); g.strokeStyle = '#222'; g.lineWidth = 2; g.stroke(); }
  line(g, X, Y, f.sr[0], false); g.strokeStyle = '#222'; g.lineWidth = 4; g.stroke();
}
function draw() {
  const f = F[k]; drawTop(f); drawSide(f);
  document.getElementById('t').textContent = 't = ' + f.t.toFixed(2) + ' s,  x = ' + f.c[0].toFixed(2) + ' m,  y = ' + f.c[1].toFixed(2) + ' m';
  slider.value = k;
}
setInterval(() => { if (playing) { k = (k + 1) % F.length; draw(); } }, 40);
draw();
</script></body></html>
"#;

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene of one joint per track and one wheel, its hull's centroid
    /// at `(x, 0, 1)` heading along `x`.
    fn scene(t: f64, x: f64) -> SpatialScene {
        let at = |dx: f64, dy: f64, dz: f64| Vector3::new(x + dx, dy, 1.0 + dz);
        SpatialScene {
            t,
            centre: at(0.0, 0.0, 0.0),
            axes: [Vector3::x(), Vector3::y(), Vector3::z()],
            outline: vec![at(-1.0, 0.0, 0.0), at(1.0, 0.0, 0.5)],
            top: [
                at(1.0, 0.5, 0.0),
                at(1.0, -0.5, 0.0),
                at(-1.0, -0.5, 0.0),
                at(-1.0, 0.5, 0.0),
            ],
            tracks: [vec![at(0.5, -1.0, -0.5)], vec![at(0.5, 1.0, -0.5)]],
            wheels: vec![(at(0.25, -1.0, -0.75), 0.25, 0)],
            track_width: 0.4,
            floor: vec![Vector2::new(-6.0, -0.8), Vector2::new(6.0, -0.8)],
        }
    }

    /// The page holds one frame per scene with its time, its side view
    /// measured from the hull's centroid along its heading (the wheel
    /// 0.25 m ahead and 0.75 m down), and its floor.
    #[test]
    fn the_page_holds_each_scene_seen_from_above_and_from_the_side() {
        let page = html(&[scene(0.0, 0.0), scene(0.04, 0.1)], &[], "Test");
        assert_eq!(page.matches("{\"t\":").count(), 2);
        assert!(page.contains("{\"t\":0.040,\"tw\":0.4000,\"c\":[0.1000,0.0000]"));
        assert!(page.contains("\"w\":[[0.2500,-0.7500,0.2500,0]]"), "{page}");
        let ground = page.split("\"g\":[").nth(1).expect("a ground");
        let ground = &ground[..ground.find(']').expect("its end")];
        let values: Vec<f64> = ground.split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(values, [-6.0, -0.8, 6.0, -0.8]);
        assert!(page.contains("<title>trackgen: Test</title>"));
        assert!(page.contains("const R = [];"));
    }

    /// The ruts go in once, each square as its centre, side, sinkage and
    /// first time, for the page to draw those pressed by a frame's time.
    #[test]
    fn the_page_holds_the_ruts_with_their_times() {
        let patch = RutPatch {
            centre: Vector2::new(1.5, -0.25),
            side: 0.08,
            sinkage: 0.061,
            since: 2.5,
        };
        let page = html(&[scene(0.0, 0.0), scene(0.04, 0.1)], &[patch], "Test");
        assert!(
            page.contains("const R = [1.5000,-0.2500,0.0800,0.0610,2.500];"),
            "{page}"
        );
    }
}
