//! A self-contained HTML page that plays a run (canvas, no external
//! files): open it in a browser.

use std::fmt::Write;

use trackgen::scene::{Frame, Ground};

/// A coordinate in metres to 0.1 mm, as `{:.4}` writes it but through
/// integer formatting: the page holds ~10⁵ numbers, and float formatting
/// with a precision (its exact, bignum path) was a tenth of the main job's
/// time outside the simulation.
pub(crate) struct Mm(pub(crate) f64);

impl std::fmt::Display for Mm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let tenths = (self.0 * 1e4).round();
        // Not `>=`: a NaN takes the plain path too.
        if tenths.abs().partial_cmp(&1e15) != Some(std::cmp::Ordering::Less) {
            return write!(f, "{:.4}", self.0);
        }
        let sign = if tenths < 0.0 { "-" } else { "" };
        let tenths = tenths.abs() as u64;
        write!(f, "{sign}{}.{:04}", tenths / 10_000, tenths % 10_000)
    }
}

fn list(points: &[(f64, f64)]) -> String {
    let mut s = String::from("[");
    for (i, &(x, y)) in points.iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        let _ = write!(s, "{},{}", Mm(x), Mm(y));
    }
    s + "]"
}

/// The page playing `frames` over `ground` (its rut drawn behind each
/// frame's track front), headed `title`; a frame's label, if it has one,
/// is shown in place of its time.
pub fn html(frames: &[Frame], ground: &Ground, title: &str) -> String {
    let x0 = frames.iter().map(|f| f.chassis.0).fold(f64::MAX, f64::min) - 5.0;
    let x1 = frames.iter().map(|f| f.chassis.0).fold(f64::MIN, f64::max) + 5.0;
    let mut data = String::from("[");
    for (i, f) in frames.iter().enumerate() {
        if i > 0 {
            data.push_str(",\n");
        }
        let wheels: Vec<String> = f
            .wheels
            .iter()
            .map(|&(x, y, r)| format!("[{},{},{}]", Mm(x), Mm(y), Mm(r)))
            .collect();
        let arms: Vec<String> = f
            .arms
            .iter()
            .map(|&((a, b), (c, d))| format!("[{},{},{},{}]", Mm(a), Mm(b), Mm(c), Mm(d)))
            .collect();
        let _ = write!(
            data,
            "{{\"t\":{:.3},\"l\":{:?},\"j\":{},\"w\":[{}],\"a\":[{}],\"h\":{},\"c\":[{},{}]}}",
            f.t,
            f.label,
            list(&f.joints),
            wheels.join(","),
            arms.join(","),
            list(&f.hull),
            Mm(f.chassis.0),
            Mm(f.chassis.1)
        );
    }
    data.push(']');
    let profile = ground.profile(x0, x1);
    let ruts: Vec<(f64, f64)> = profile
        .iter()
        .map(|&(x, _)| (x, ground.rut_depth(x)))
        .collect();
    TEMPLATE
        .replace("__TITLE__", title)
        .replace("__FRAMES__", &data)
        .replace("__GROUND__", &list(&profile))
        .replace("__RUT__", &list(&ruts))
}

const TEMPLATE: &str = r#"<!doctype html>
<html><head><meta charset="utf-8"><title>trackgen: __TITLE__</title>
<style>body{font-family:sans-serif;margin:16px}canvas{border:1px solid #ccc;background:#fff}</style></head>
<body>
<h3>trackgen: __TITLE__</h3>
<canvas id="c" width="1100" height="460"></canvas><br>
<button id="play">pause</button> <input id="s" type="range" min="0" value="0" style="width:800px"> <span id="t"></span>
<script>
const F = __FRAMES__;
const G = __GROUND__;
const R = __RUT__;
const cv = document.getElementById('c'), g = cv.getContext('2d');
const slider = document.getElementById('s'); slider.max = F.length - 1;
let k = 0, playing = true;
document.getElementById('play').onclick = e => { playing = !playing; e.target.textContent = playing ? 'pause' : 'play'; };
slider.oninput = () => { k = +slider.value; draw(); };
function draw() {
  const f = F[k], sc = 110, cx = f.c[0], cy = f.c[1];
  const X = x => (x - cx) * sc + cv.width / 2, Y = y => cv.height * 0.55 - (y - cy) * sc;
  g.clearRect(0, 0, cv.width, cv.height);
  const poly = (p, close) => { g.beginPath(); for (let i = 0; i < p.length; i += 2) { const f2 = i ? 'lineTo' : 'moveTo'; g[f2](X(p[i]), Y(p[i+1])); } if (close) g.closePath(); };
  // The rut left by the end of the run, behind the track's front.
  let front = -Infinity; for (let i = 0; i < f.j.length; i += 2) front = Math.max(front, f.j[i]);
  const S = G.map((v, i) => (i % 2 === 1 && G[i-1] <= front) ? v - R[i] : v);
  poly(S, false); g.lineTo(X(S[S.length-2]), cv.height); g.lineTo(X(S[0]), cv.height); g.closePath();
  g.fillStyle = '#d8c9a8'; g.fill(); g.strokeStyle = '#8a7650'; g.stroke();
  poly(f.h, true); g.fillStyle = '#7d8b6a'; g.fill(); g.strokeStyle = '#3d4633'; g.lineWidth = 2; g.stroke();
  g.strokeStyle = '#444'; g.lineWidth = 6;
  for (const a of f.a) { g.beginPath(); g.moveTo(X(a[0]), Y(a[1])); g.lineTo(X(a[2]), Y(a[3])); g.stroke(); }
  for (const w of f.w) { g.beginPath(); g.arc(X(w[0]), Y(w[1]), w[2] * sc, 0, 2 * Math.PI); g.fillStyle = '#555'; g.fill(); g.lineWidth = 2; g.strokeStyle = '#222'; g.stroke(); }
  poly(f.j, false); g.strokeStyle = '#222'; g.lineWidth = 5; g.stroke();
  g.fillStyle = '#ddd'; for (let i = 0; i < f.j.length; i += 2) { g.beginPath(); g.arc(X(f.j[i]), Y(f.j[i+1]), 2, 0, 2 * Math.PI); g.fill(); }
  document.getElementById('t').textContent = f.l ? f.l : 't = ' + f.t.toFixed(2) + ' s,  x = ' + cx.toFixed(2) + ' m';
  slider.value = k;
}
setInterval(() => { if (playing) { k = (k + 1) % F.length; draw(); } }, 40);
draw();
</script></body></html>
"#;
