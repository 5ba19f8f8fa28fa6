//! [`VehicleDynamics`] for [`VehicleSystem`]: what generic code over any
//! declared vehicle asks of one in motion besides simulating it.

use nalgebra::{DVector, SVector, Vector2};

use super::VehicleSystem;
use crate::contact::GroundFriction;
use crate::contact::soft_ground::Rut;
use crate::integrate::{OdeSystem, SimulationError};
use crate::multibody::{ChassisModel, ChassisPart, TrackModel, TreeDescription};
use crate::system::TreeSystem;
use crate::vehicle::layout::track_coordinates;
use crate::vehicle::{Geometry, StateLayout, VehicleConfig, VehicleDynamics};

impl<T, const DT: usize, C, const DC: usize> VehicleDynamics for VehicleSystem<T, DT, C, DC>
where
    T: TrackModel<DT> + Default + Send,
    C: ChassisModel<DC> + Default + Send,
{
    fn config(&self) -> &VehicleConfig {
        &self.config
    }

    fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    fn sprocket_pitch_radius(&self) -> f64 {
        self.sprocket.map_or(0.0, |s| s.pitch_radius)
    }

    fn sprocket_rolling_radius(&self) -> f64 {
        self.sprocket.map_or(0.0, |s| s.rolling_radius)
    }

    fn rut(&self) -> Option<&Rut> {
        self.soil.as_ref().map(|s| &s.rut)
    }

    fn arms_mut(&mut self) -> &mut [crate::multibody::ArmSpring] {
        &mut self.config.arms
    }

    fn set_drawbar_pull(&mut self, pull: f64) -> Result<(), super::ConfigError> {
        self.config.drawbar_pull = crate::vehicle::DrawbarError::check(pull)?;
        Ok(())
    }

    fn layout(&self) -> StateLayout {
        StateLayout {
            track_coordinates: track_coordinates(DT, self.track().dependent_pair()),
            ..self.layout.clone()
        }
    }

    fn coordinates(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(DVector<f64>, DVector<f64>), SimulationError> {
        if y.len() != self.y0.len() {
            return Err(SimulationError::StateLength {
                t,
                got: y.len(),
                expected: self.y0.len(),
            });
        }
        let (yt, yc) = self.bodies.split(&y[..self.bodies.dimension()]);
        let (qt, _) = self.bodies.parts_mut().0.coordinates(t, yt)?;
        let (qc, _) = TreeSystem::<C, DC>::split(yc);
        Ok((
            DVector::from_column_slice(qt.as_slice()),
            DVector::from_column_slice(qc.as_slice()),
        ))
    }

    fn holds_by_stiction(&self) -> bool {
        self.soil.is_none() && self.config.ground.friction.has_state()
    }

    fn stiction_limits(&mut self, t: f64, y: &[f64]) -> Result<Vec<Option<f64>>, SimulationError> {
        let GroundFriction::Stiction(stiction) = self.config.ground.friction else {
            return Ok(Vec::new());
        };
        if self.soil.is_some() {
            return Ok(Vec::new());
        }
        self.evaluate(t, y)?;
        let unit = stiction.stiffness * self.stiction_scale;
        Ok(self
            .work
            .ground_normal
            .iter()
            .map(|normal| normal.map(|n| stiction.mu * n / unit))
            .collect())
    }

    fn ground_loads(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<Vec<(Vector2<f64>, f64)>, SimulationError> {
        self.evaluate(t, y)?;
        let points = self.geometry.shoe.ground_points.len();
        let corners = self.config.corner_laws();
        let work = &self.work;
        Ok(work
            .contacts
            .iter()
            .filter(|c| c.other.is_none())
            .map(|c| {
                // The evaluation keeps a ground point's normal force where
                // the point has a tangential state (stiction, soil); under
                // regularised friction it has none, and the law gives it
                // (its normal force does not depend on that state).
                let normal = match c.ground_point_slot(points) {
                    Some(slot) => match work.ground_normal.get(slot).copied() {
                        Some(kept) => kept.unwrap_or(0.0),
                        None => self.config.ground.respond(c, 0.0).0.normal,
                    },
                    None => corners.respond(c).normal,
                };
                (c.point, normal)
            })
            .collect())
    }

    fn set_start(&mut self, y: &[f64]) -> Result<(), SimulationError> {
        if y.len() != self.y0.len() {
            return Err(SimulationError::StateLength {
                t: 0.0,
                got: y.len(),
                expected: self.y0.len(),
            });
        }
        if y.iter().any(|v| !v.is_finite()) {
            return Err(SimulationError::NonFinite {
                t: 0.0,
                what: "the start state",
            });
        }
        self.y0.copy_from_slice(y);
        Ok(())
    }

    fn parts() -> &'static [ChassisPart] {
        C::PARTS
    }

    fn hull() -> &'static [[f64; 2]] {
        C::HULL
    }

    fn track_description() -> TreeDescription {
        T::default().description()
    }

    fn chassis_description() -> TreeDescription {
        C::default().description()
    }

    fn track_dof() -> usize {
        DT
    }

    fn chassis_dof() -> usize {
        DC
    }

    fn track_positions(q: &[f64], out: &mut [Vector2<f64>]) {
        T::default().body_positions(&SVector::from_column_slice(q), out);
    }

    fn chassis_positions(q: &[f64], out: &mut [Vector2<f64>]) {
        C::default().body_positions(&SVector::from_column_slice(q), out);
    }
}
