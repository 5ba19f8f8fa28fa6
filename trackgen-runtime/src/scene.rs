//! The vehicle's geometry at recorded times, for pictures: its track's
//! joints, wheels, arms and hull from the track's and the chassis'
//! coordinates ([`Scene`]), the ground under it ([`Ground`]), and the two
//! together, one [`Picture`]. Drawing them is the `trackgen-draw` crate's
//! (the main job's `frame.svg` and animation, the mobility report's
//! vehicles at their limits): the physics draws nothing.

use nalgebra::Vector2;

use crate::multibody::PartKind;
use crate::planar::rotate;
use crate::simulate::Results;
use crate::terrain::Terrain;
use crate::vehicle::{Vehicle, VehicleDynamics};

/// One picture's worth of geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    /// The time, s.
    pub t: f64,
    /// Track joints, in order round the loop.
    pub joints: Vec<(f64, f64)>,
    /// Wheels: centre and radius.
    pub wheels: Vec<(f64, f64, f64)>,
    /// Arms: pivot to wheel.
    pub arms: Vec<((f64, f64), (f64, f64))>,
    /// Chassis centroid and pitch.
    pub chassis: (f64, f64, f64),
    /// The hull's outline, m: the declared one (`hull: [...]`), or a side
    /// view drawn over the running gear for a vehicle that declares none.
    pub hull: Vec<(f64, f64)>,
    /// What the picture says in its corner (`t = 1.00 s` when empty).
    pub label: String,
}

/// A frame at time `t` from the track's and the chassis' coordinates.
type FrameOf = Box<dyn Fn(f64, &[f64], &[f64]) -> Frame>;

/// How to draw a vehicle from its recorded coordinates.
pub struct Scene {
    /// Track and chassis coordinates.
    dofs: (usize, usize),
    frame: FrameOf,
}

impl Scene {
    /// The scene of a vehicle declared with `model!`: its wheels, arms
    /// and track from the compiled models, and its declared hull (or, for
    /// a vehicle that declares none, a side view of one drawn over its
    /// running gear).
    pub fn of<V: Vehicle>() -> Scene {
        type S<V> = <V as Vehicle>::System;
        let hull = outline::<V>();
        let joints = S::<V>::track_description()
            .joints()
            .expect("a track has joints");
        let links = joints.len();
        let chassis = S::<V>::chassis_description();
        let bodies = chassis.len();
        let frame = move |t: f64, qt: &[f64], qc: &[f64]| {
            let mut centres = vec![Vector2::zeros(); links];
            S::<V>::track_positions(qt, &mut centres);
            // Each link's rear joint.
            let mut joints: Vec<(f64, f64)> = (0..links)
                .map(|j| centres[j] + rotate(qt[2 + j], joints[j].0))
                .map(|p| (p.x, p.y))
                .collect();
            joints.push(joints[0]);
            let mut positions = vec![Vector2::zeros(); bodies];
            S::<V>::chassis_positions(qc, &mut positions);
            let mut wheels = Vec::new();
            let mut arms = Vec::new();
            for part in S::<V>::parts() {
                let c = positions[part.body];
                wheels.push((c.x, c.y, part.radius));
                if let Some(arm) = &part.arm {
                    let body = &chassis.bodies[arm.body];
                    let pivot = positions[arm.body] + rotate(qc[2 + arm.body], body.at_self);
                    arms.push(((pivot.x, pivot.y), (c.x, c.y)));
                }
            }
            let hull = hull
                .iter()
                .map(|p| positions[0] + rotate(qc[2], *p))
                .map(|p| (p.x, p.y))
                .collect();
            Frame {
                t,
                joints,
                wheels,
                arms,
                chassis: (qc[0], qc[1], qc[2]),
                hull,
                label: String::new(),
            }
        };
        Scene {
            dofs: (S::<V>::track_dof(), S::<V>::chassis_dof()),
            frame: Box::new(frame),
        }
    }

    /// The columns a picture needs: the track's and the chassis'
    /// coordinates (`track.x` and those after it, `chassis.x` and those
    /// after it), out of all the recorded ones; `None` if they are not
    /// there.
    pub fn columns(&self, all: &[String]) -> Option<Vec<String>> {
        let (track, chassis) = self.starts(all)?;
        let mut names = all[track].to_vec();
        names.extend_from_slice(&all[chassis]);
        Some(names)
    }

    /// Where the track's and the chassis' coordinates are among `all`
    /// columns (`track.x` and the ones after it, `chassis.x` and the ones
    /// after it); `None` if they are not all there.
    fn starts(&self, all: &[String]) -> Option<(std::ops::Range<usize>, std::ops::Range<usize>)> {
        let block = |prefix: &str, n: usize| {
            let start = all.iter().position(|c| *c == format!("{prefix}.x"))?;
            (start + n <= all.len()).then_some(start..start + n)
        };
        Some((block("track", self.dofs.0)?, block("chassis", self.dofs.1)?))
    }

    /// The frame at the track's coordinates `qt` and the chassis' `qc`.
    pub fn frame(&self, t: f64, qt: &[f64], qc: &[f64]) -> Frame {
        (self.frame)(t, qt, qc)
    }

    /// The frame at time `t` of a recorded `row` whose columns are
    /// `columns` (every recorded one, or at least
    /// [`Scene::columns`]'); `None` if they are not there.
    pub fn frame_of_row(&self, t: f64, columns: &[String], row: &[f64]) -> Option<Frame> {
        let (track, chassis) = self.starts(columns)?;
        Some((self.frame)(t, row.get(track)?, row.get(chassis)?))
    }

    /// Frames every `dt` (s) of `results` (which hold [`columns`](Self::columns)).
    pub fn frames(&self, results: &Results, dt: f64) -> Vec<Frame> {
        let (track, chassis) = self.starts(results.columns()).expect("coordinates");
        let mut out = Vec::new();
        let mut next = 0.0;
        for i in 0..results.len() {
            let sample = results.sample(i);
            if sample.t + 1e-9 < next {
                continue;
            }
            next = sample.t + dt;
            let values = &sample.values;
            out.push((self.frame)(
                sample.t,
                &values[track.clone()],
                &values[chassis.clone()],
            ));
        }
        out
    }
}

/// The hull's outline that pictures of `V` draw, in the chassis'
/// centroid frame, m: the declared one (`hull: [...]`), or for a vehicle
/// that declares none a side view drawn over its running gear.
pub fn outline<V: Vehicle>() -> Vec<Vector2<f64>> {
    let declared = <V as Vehicle>::System::hull();
    if declared.is_empty() {
        hull::<V>()
    } else {
        declared.iter().map(|&[x, y]| Vector2::new(x, y)).collect()
    }
}

/// A side view of a hull over the running gear (for a vehicle that
/// declares none), in the chassis' centroid frame: from behind the rearmost wheel to past the foremost, its belly
/// clear of the track's upper run, a sloped glacis at the front.
fn hull<V: Vehicle>() -> Vec<Vector2<f64>> {
    type S<V> = <V as Vehicle>::System;
    let mut bodies = vec![Vector2::zeros(); S::<V>::chassis_description().len()];
    S::<V>::chassis_positions(&vec![0.0; S::<V>::chassis_dof()], &mut bodies);
    let parts = || {
        S::<V>::parts()
            .iter()
            .map(|p| (bodies[p.body], p.radius, p.kind))
    };
    let front = parts().map(|(c, r, _)| c.x + r).fold(f64::MIN, f64::max) + 0.15;
    let rear = parts().map(|(c, r, _)| c.x - r).fold(f64::MAX, f64::min) - 0.05;
    let belly = parts()
        .filter(|(_, _, kind)| *kind != PartKind::RoadWheel)
        .map(|(c, r, _)| c.y + r)
        .fold(f64::MIN, f64::max)
        + 0.2;
    [
        (front, belly),
        (front - 0.4, belly + 0.7),
        (front - 1.2, belly + 1.1),
        (rear, belly + 1.1),
        (rear, belly + 0.3),
        (rear + 0.45, belly),
    ]
    .iter()
    .map(|&(x, y)| Vector2::new(x, y))
    .collect()
}

/// The ground a run drove on: its undisturbed profile and, on soft soil,
/// the rut the track left (plastic sinkage against x, in order of x).
#[derive(Debug, Clone, PartialEq)]
pub struct Ground {
    /// The undisturbed ground.
    pub terrain: Terrain,
    /// The rut, `(x, depth)` in m, in order of x (empty on rigid ground).
    pub rut: Vec<(f64, f64)>,
}

impl Ground {
    /// The rut's depth at `x` as drawn, m: the deepest the rut holds
    /// within 6 cm of `x` (half an M113 shoe's pad), so the ground between
    /// two shoes' footprints is drawn at their depth rather than as a
    /// ridge; 0 where the track has not been.
    pub fn rut_depth(&self, x: f64) -> f64 {
        let from = self.rut.partition_point(|p| p.0 < x - 0.06);
        self.rut[from..]
            .iter()
            .take_while(|p| p.0 <= x + 0.06)
            .map(|p| p.1)
            .fold(0.0, f64::max)
    }

    /// Sample points over `[x0, x1]`: the undisturbed surface.
    /// A polyline's own points over the range (its vertical faces drawn as
    /// they are), with its heights at the ends.
    pub fn profile(&self, x0: f64, x1: f64) -> Vec<(f64, f64)> {
        if let Terrain::Profile(profile) = &self.terrain {
            let inside = profile.points().filter(|p| p.0 > x0 && p.0 < x1);
            return std::iter::once((x0, profile.height(x0)))
                .chain(inside)
                .chain(std::iter::once((x1, profile.height(x1))))
                .collect();
        }
        (0..=800)
            .map(|k| x0 + (x1 - x0) * k as f64 / 800.0)
            .map(|x| (x, self.terrain.height(x)))
            .collect()
    }

    /// The surface over `[x0, x1]` as a vehicle whose track's front is at
    /// `front` sees it: rutted behind the front (the rut is the one left
    /// at the end of the run, drawn where the track had passed by then),
    /// undisturbed ahead.
    pub fn surface(&self, x0: f64, x1: f64, front: f64) -> Vec<(f64, f64)> {
        self.profile(x0, x1)
            .into_iter()
            .map(|(x, y)| (x, if x <= front { y - self.rut_depth(x) } else { y }))
            .collect()
    }
}

/// The vehicle at one moment on the ground it drove on: what a still
/// picture shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    /// The vehicle.
    pub frame: Frame,
    /// The ground.
    pub ground: Ground,
}
