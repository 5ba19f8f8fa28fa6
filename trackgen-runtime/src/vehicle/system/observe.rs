//! What a vehicle records: [`Simulated`] for [`VehicleSystem`] — its
//! columns, the full row ([`observe`](Simulated::observe)) and the lean
//! one of the hull and the seat
//! ([`observe_some`](Simulated::observe_some)) — and the seat's motion.

use nalgebra::{DVector, SVector, Vector2};

use super::VehicleSystem;
use crate::closure::Switch;
use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;
use crate::multibody::{ChassisModel, TrackModel};
use crate::planar::{Rotation, perp};
use crate::system::Simulated;
use crate::vehicle::Powertrain;
use crate::vehicle::record::{VehicleRecord, sprocket_spans};
use crate::vehicle::workspace::Workspace;

impl<T: TrackModel<DT>, const DT: usize, C: ChassisModel<DC>, const DC: usize> Simulated
    for VehicleSystem<T, DT, C, DC>
{
    fn initial_state(&self) -> DVector<f64> {
        self.y0.clone()
    }

    fn columns(&self) -> Vec<String> {
        let mut c = self.bodies.columns();
        c.extend(VehicleRecord::COLUMNS.iter().map(|c| c.to_string()));
        c
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (bodies, [_, work, dissipated, engine_work], _) = self.split(y);
        self.bodies.observe(t, bodies, row)?;
        let (qc, qdc) = self.evaluate(t, y)?;
        self.bodies.parts_mut().0.accelerations(t)?;
        let seat = self.seat(t, y, &qc, &qdc)?;
        let Workspace {
            links,
            parts,
            tensions,
            offsets,
            books,
            ..
        } = &mut self.work;
        let track = self.bodies.first();
        track.tensions(tensions);
        let spans = self.sprocket.and_then(|s| {
            let sprocket = (parts[s.body].position, s.pitch_radius);
            sprocket_spans(links, &self.forward_joints, sprocket, offsets)
        });
        let tension = |j: Option<usize>| j.and_then(|j| tensions.get(j).copied());
        let (slack, tight) = match spans {
            Some((before, after)) => (tension(Some(before)), tension(Some(after))),
            None => (None, None),
        };
        let (qt, qdt, _) = track.recovered();
        let (track_model, chassis) = (track.model(), self.bodies.second().model());
        let energy = track_model.kinetic_energy(qt, qdt)
            + track_model.potential_energy(qt)
            + chassis.kinetic_energy(&qc, &qdc)
            + chassis.potential_energy(&qc)
            + books.arm_potential
            + books.potential
            + track.closure_energy(qt, qdt).0;
        VehicleRecord {
            x: qc[0],
            y: qc[1],
            pitch: qc[2],
            speed: qdc[0],
            sprocket_speed: self.sprocket.map_or(0.0, |s| s.omega(&qdc)),
            track_speed: self
                .sprocket
                .map_or(0.0, |s| -s.rolling_radius * s.omega(&qdc)),
            sprocket_torque: books.torque,
            engine_load: books.engine_load,
            tension: tension(Some(self.config.tension_link - 1)).unwrap_or(f64::NAN),
            tension_tight: tight.unwrap_or(f64::NAN),
            tension_slack: slack.unwrap_or(f64::NAN),
            ground_normal: books.ground_normal,
            ground_penetration: books.ground_penetration,
            wheel_penetration: books.wheel_penetration,
            sprocket_penetration: books.sprocket_penetration,
            hull_normal: books.hull_normal,
            hull_penetration: books.hull_penetration,
            energy,
            motor_work: work,
            dissipated,
            engine_work,
            engine_power: books.engine.engine_power,
            turbine_power: books.engine.turbine_power,
            engine_speed: books.engine.engine_speed,
            engine_torque: books.engine.engine_torque,
            gear: match &self.config.powertrain {
                Some(Powertrain::Converter(d)) => d.gear_number(books.engine.gear),
                _ => books.engine.gear.map_or(0.0, |g| (g + 1) as f64),
            },
            speed_ratio: books.engine.speed_ratio,
            torque_ratio: books.engine.torque_ratio,
            converter_efficiency: books.engine.speed_ratio * books.engine.torque_ratio,
            locked: f64::from(u8::from(books.engine.locked == Some(true))),
            seat_x: seat.position.x,
            seat_y: seat.position.y,
            seat_ax: seat.acceleration.x,
            seat_az: seat.acceleration.y,
        }
        .extend_row(row);
        Ok(())
    }

    /// Lean when the sinks read only the hull's position, pitch and speed,
    /// the seat's motion and the engine's speed (`x`, `y`, `pitch`,
    /// `speed`, `seat_x`, `seat_y`, `seat_ax`, `seat_az`, `engine_speed`):
    /// the forces and the
    /// chassis' accelerations alone, as [`observe`](Self::observe)
    /// computes them (the same bits), and no track accelerations, link
    /// kinematics, tensions or energies; the rest of the row NaN.
    fn observe_some(
        &mut self,
        t: f64,
        y: &[f64],
        wanted: &[bool],
        row: &mut Vec<f64>,
    ) -> Result<(), SimulationError> {
        let offset = wanted.len().saturating_sub(VehicleRecord::COLUMNS.len());
        let lean = wanted.iter().enumerate().all(|(i, &read)| {
            !read || (i >= offset && LEAN_COLUMNS.contains(&VehicleRecord::COLUMNS[i - offset]))
        });
        if !lean {
            return self.observe(t, y, row);
        }
        row.resize(row.len() + offset, f64::NAN);
        let (qc, qdc) = self.evaluate(t, y)?;
        let seat = self.seat(t, y, &qc, &qdc)?;
        VehicleRecord {
            x: qc[0],
            y: qc[1],
            pitch: qc[2],
            speed: qdc[0],
            seat_x: seat.position.x,
            seat_y: seat.position.y,
            seat_ax: seat.acceleration.x,
            seat_az: seat.acceleration.y,
            engine_speed: self.work.books.engine.engine_speed,
            ..VehicleRecord::unobserved()
        }
        .extend_row(row);
        Ok(())
    }

    fn after_step(
        &mut self,
        t: f64,
        y: &mut [f64],
        switched: &mut dyn FnMut(Switch),
    ) -> Result<bool, SimulationError> {
        let nb = self.bodies.dimension();
        let mut restart = self.bodies.after_step(t, &mut y[..nb], switched)?;
        restart |= self.press_soil(t, y)?;
        restart |= self.apply_brake(t, y);
        restart |= self.shift_and_lock(t, y);
        Ok(restart)
    }
}

/// The columns of a [`VehicleRecord`] a lean observation
/// ([`Simulated::observe_some`]) gives: the hull's, the seat's and the
/// engine's speed (the forces' evaluation gives it).
const LEAN_COLUMNS: [&str; 9] = [
    "x",
    "y",
    "pitch",
    "speed",
    "seat_x",
    "seat_y",
    "seat_ax",
    "seat_az",
    "engine_speed",
];

impl<T, const DT: usize, C, const DC: usize> VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT>,
    C: ChassisModel<DC>,
{
    /// The seat's motion at `(t, y)` after [`evaluate`](Self::evaluate)
    /// gave the chassis' `(q, q̇)`: the chassis' accelerations from the
    /// loads the evaluation left on it.
    fn seat(
        &mut self,
        t: f64,
        y: &[f64],
        qc: &SVector<f64, DC>,
        qdc: &SVector<f64, DC>,
    ) -> Result<PointMotion, SimulationError> {
        let chassis = self.bodies.parts_mut().1;
        let yc = &y[self.layout.chassis.start..self.layout.chassis_rates.end];
        let rates = &mut self.work.chassis_rates;
        chassis.derivative_with_trig(t, yc, &self.work.part_trig, rates)?;
        Ok(seat_motion::<DC>(C::SEAT, qc, qdc, &rates[DC..]))
    }
}

/// A point of the chassis frame in motion: where it is, and its
/// acceleration in the frame's axes.
struct PointMotion {
    /// m, global frame.
    position: Vector2<f64>,
    /// m/s², the frame's axes (x forward, y up), kinematic (no gravity).
    acceleration: Vector2<f64>,
}

/// The frame's point `offset` (from its centroid, in its axes, m) at
/// `(q_i, q̇_i)` with accelerations `qdd`: `p = R + A s̄` and, turned into
/// the frame's axes by `Aᵀ`, `p̈ = R̈ + θ̈ ⟂(A s̄) − θ̇² A s̄` (formulation §0: the
/// frame is the chassis' root body, `q_i = [R, θ, …]`).
fn seat_motion<const DC: usize>(
    offset: [f64; 2],
    q: &SVector<f64, DC>,
    qd: &SVector<f64, DC>,
    qdd: &[f64],
) -> PointMotion {
    let rotation = Rotation::new(q[2]);
    let arm = rotation.apply(Vector2::new(offset[0], offset[1]));
    let (omega, alpha) = (qd[2], qdd[2]);
    let global = Vector2::new(qdd[0], qdd[1]) + perp(arm) * alpha - arm * (omega * omega);
    PointMotion {
        position: Vector2::new(q[0], q[1]) + arm,
        acceleration: rotation.apply_inverse(global),
    }
}
