//! The vehicle drawn: one frame on its ground as a still SVG picture.

use trackgen::scene::{Frame, Ground, Picture};

/// A still picture of one frame on `ground`, SVG: the vehicle (track and
/// hull) with a margin, the ground below it, the frame's label (or its
/// time) in the corner.
pub fn svg(frame: &Frame, ground: &Ground) -> String {
    // The vehicle (track and hull) with a margin, the ground below it.
    let points_x = frame.joints.iter().chain(&frame.hull).map(|p| p.0);
    let (lo, hi) = points_x.fold((f64::MAX, f64::MIN), |(lo, hi), x| (lo.min(x), hi.max(x)));
    let top = frame.hull.iter().map(|p| p.1).fold(f64::MIN, f64::max);
    let bottom = frame.joints.iter().map(|p| p.1).fold(f64::MAX, f64::min);
    let (x0, x1, y0, y1) = (lo - 0.6, hi + 0.6, bottom - 0.8, top + 0.3);
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
    let front = frame.joints.iter().map(|p| p.0).fold(f64::MIN, f64::max);
    let mut terrain_line = ground.surface(x0, x1, front);
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
    let label = if frame.label.is_empty() {
        format!("t = {:.2} s", frame.t)
    } else {
        frame.label.clone()
    };
    s += &format!(
        "<text x=\"10\" y=\"24\" font-family=\"sans-serif\" font-size=\"18\">{label}</text>\n"
    );
    s + "</svg>\n"
}

/// [`svg`] of a [`Picture`].
pub fn picture(picture: &Picture) -> String {
    svg(&picture.frame, &picture.ground)
}

#[cfg(test)]
mod tests {
    use trackgen::scene::{Frame, Ground};
    use trackgen::terrain::Terrain;

    use super::svg;

    /// A frame of four joints, two wheels, an arm and a triangular hull on
    /// flat ground: one SVG document with the ground's and the hull's
    /// polygons, a circle per wheel and per joint, the arm's line, the
    /// track's polyline, and the label (or the time without one).
    #[test]
    fn a_frame_is_drawn_whole() {
        let mut frame = Frame {
            t: 1.25,
            joints: vec![(0.0, 0.1), (1.0, 0.1), (1.0, 0.5), (0.0, 0.5)],
            wheels: vec![(0.2, 0.3, 0.2), (0.8, 0.3, 0.2)],
            arms: vec![((0.3, 0.6), (0.2, 0.3))],
            chassis: (0.5, 0.6, 0.0),
            hull: vec![(-0.1, 0.6), (1.1, 0.6), (0.5, 1.0)],
            label: String::new(),
        };
        let ground = Ground {
            terrain: Terrain::Flat { height: 0.0 },
            rut: Vec::new(),
        };
        let picture = svg(&frame, &ground);
        assert!(picture.starts_with("<svg") && picture.ends_with("</svg>\n"));
        assert_eq!(
            picture.matches("<polygon").count(),
            2,
            "the ground and the hull"
        );
        assert_eq!(
            picture.matches("<circle").count(),
            2 + 4,
            "wheels and joints"
        );
        assert_eq!(picture.matches("<line").count(), 1, "the arm");
        assert_eq!(picture.matches("<polyline").count(), 1, "the track");
        assert!(picture.contains(">t = 1.25 s</text>"), "{picture}");
        frame.label = "step 0.600 m".into();
        assert!(svg(&frame, &ground).contains(">step 0.600 m</text>"));
    }
}
