use nalgebra::{DVector, SVector, Vector2};

use super::loads::Loads;
use super::mechanics::{masses, mechanics_columns, record_mechanics};
use super::{Simulated, record};
use crate::closure::partitioning::{self, Partition};
use crate::closure::{
    ClosureError, ClosureMethod, MultiplierOptions, ProjectionFailure, RecoveryError, Switch,
    multipliers,
};
use crate::integrate::OdeSystem;
use crate::integrate::SimulationError;
use crate::laws::PenaltyJoint;
use crate::multibody::{BodyLoad, ClosingJoint, Closure, TrackModel, joint_tensions};

record! {
    /// What a track records after its bodies' [`Mechanics`](super::Mechanics).
    pub struct TrackRecord {
        /// `|C|`, the gap at the closing joint, m.
        closure_error,
        /// `|C_q q̇|`, its rate, m/s.
        closure_rate_error,
        /// `|sin|` between the columns of the dependent pair's `C_d`
        /// (partitioning), or of the best pair's (otherwise).
        conditioning,
    }
}

/// How this track is closed, resolved from the declaration and the chosen
/// [`ClosureMethod`].
#[derive(Debug, Clone)]
enum Mode {
    /// The declared dynamics as they are: an open chain, or a chain closed
    /// by its declared penalty joint.
    AsDeclared,
    Partitioned(Partition),
    Multipliers(MultiplierOptions),
    /// A penalty joint chosen at run time.
    Penalty(PenaltyJoint),
}

/// The last state expanded to coordinates: the accepted state of a step is
/// its last stage's (first same as last), so the recovery after the step
/// is this one again.
#[derive(Debug, Clone)]
struct Recovered<const D: usize> {
    valid: bool,
    y: Vec<f64>,
    q: SVector<f64, D>,
    qd: SVector<f64, D>,
    trig: Vec<(f64, f64)>,
}

/// A track in motion, its loop closed by one of the methods of
/// [`crate::closure`].
///
/// The state is `y = [z, ż]` (the `n` independent coordinates) under
/// partitioning, and `y = [q_i, q̇_i]` otherwise.
pub struct TrackSystem<M: TrackModel<D>, const D: usize> {
    model: M,
    mode: Mode,
    y0: DVector<f64>,
    loads: Loads<D>,
    masses: Vec<(f64, f64)>,
    /// `q̈_i` of the last [`accelerations`](Self::accelerations).
    qdd: SVector<f64, D>,
    /// The angle columns of `C_q`, for the partition's conditioning.
    columns: Vec<Vector2<f64>>,
    /// The last state expanded, and what it expanded to.
    recovered: Recovered<D>,
    /// Every joint's force from the last solve (see
    /// [`TrackModel::linear_time_dynamics`]).
    joint_forces: Vec<Vector2<f64>>,
    /// `Σ |d̄ʲ|`, m: the scale of closure tolerances.
    loop_length: f64,
    /// `d̄ʲ` of every link.
    spans: Vec<Vector2<f64>>,
}

impl<M: TrackModel<D>, const D: usize> TrackSystem<M, D> {
    /// The track starting at `(q_i, q̇_i)`, closed by `method`.
    ///
    /// The start is made consistent with the closure: under partitioning
    /// the dependent angles and their rates are recovered from the others;
    /// under multipliers or a run-time penalty, `(q_i, q̇_i)` is projected
    /// onto `C = 0`, `C_q q̇ = 0`.
    pub fn new(
        model: M,
        q: SVector<f64, D>,
        qd: SVector<f64, D>,
        method: ClosureMethod,
    ) -> Result<Self, ClosureError> {
        let description = model.description();
        let spans = description.link_spans().unwrap_or_default();
        let loop_length = spans
            .iter()
            .map(|d| d.norm())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
        let mode = match (method, M::CLOSURE) {
            (ClosureMethod::Declared, Closure::Partitioned) => {
                Mode::Partitioned(Partition::new(Default::default(), loop_length))
            }
            (ClosureMethod::Declared, _) => Mode::AsDeclared,
            (_, Closure::Open) => return Err(ClosureError::DeclaredOpen),
            (_, Closure::Penalty(_)) => return Err(ClosureError::DeclaredPenalty),
            (ClosureMethod::Partitioning(options), Closure::Partitioned) => {
                Mode::Partitioned(Partition::new(options, loop_length))
            }
            (ClosureMethod::Multipliers(options), Closure::Partitioned) => {
                Mode::Multipliers(options)
            }
            (ClosureMethod::Penalty(joint), Closure::Partitioned) => {
                joint.check()?;
                Mode::Penalty(joint)
            }
        };
        let mut system = TrackSystem {
            qdd: SVector::zeros(),
            columns: vec![Vector2::zeros(); M::BODIES],
            recovered: Recovered {
                valid: false,
                y: Vec::new(),
                q: SVector::zeros(),
                qd: SVector::zeros(),
                trig: vec![(0.0, 1.0); M::BODIES],
            },
            joint_forces: vec![Vector2::zeros(); M::BODIES],
            masses: masses(&model),
            model,
            mode,
            y0: DVector::zeros(0),
            loads: Loads::new(M::BODIES),
            loop_length,
            spans,
        };
        system.y0 = system.start(q, qd)?;
        Ok(system)
    }

    /// Applied loads besides gravity (a sprocket torque, say).
    pub fn with_loads(
        mut self,
        loads: impl FnMut(f64, &SVector<f64, D>, &SVector<f64, D>, &mut [BodyLoad]) + Send + 'static,
    ) -> Self {
        self.loads.set_function(Box::new(loads));
        self
    }

    /// The compiled model.
    pub fn model(&self) -> &M {
        &self.model
    }

    /// The dependent links now (numbered from 1), under partitioning.
    pub fn dependent_pair(&self) -> Option<[usize; 2]> {
        match &self.mode {
            Mode::Partitioned(p) => Some(p.pair().map(|l| l + 1)),
            _ => None,
        }
    }

    /// `(q_i, q̇_i)` of the state `y`, the closure recovered under
    /// partitioning.
    pub fn coordinates(
        &mut self,
        t: f64,
        y: &[f64],
    ) -> Result<(SVector<f64, D>, SVector<f64, D>), SimulationError> {
        self.recover(t, y)?;
        Ok((self.recovered.q, self.recovered.qd))
    }

    /// Makes the kept recovery that of `y`: `(q_i, q̇_i)`, the closure
    /// recovered under partitioning, and every link's `(sin θ, cos θ)`
    /// ([`recovered`](Self::recovered)). Asked again for the same state
    /// (after a step, for its last stage's), it is not recovered again.
    pub(crate) fn recover(&mut self, t: f64, y: &[f64]) -> Result<(), SimulationError> {
        if y.len() != self.y0.len() {
            return Err(SimulationError::StateLength {
                t,
                got: y.len(),
                expected: self.y0.len(),
            });
        }
        let kept = &mut self.recovered;
        if kept.valid && kept.y == y {
            return Ok(());
        }
        kept.valid = false;
        match &self.mode {
            Mode::Partitioned(partition) => partition.expand(
                &self.model,
                t,
                y,
                (&mut kept.q, &mut kept.qd),
                &mut kept.trig,
            )?,
            _ => {
                crate::trig::sin_cos_each(&y[2..D], &mut kept.trig);
                kept.q.copy_from_slice(&y[..D]);
                kept.qd.copy_from_slice(&y[D..]);
            }
        }
        kept.valid = true;
        kept.y.clear();
        kept.y.extend_from_slice(y);
        Ok(())
    }

    /// The kept recovery: `q_i`, `q̇_i` and every link's `(sin θ, cos θ)`.
    pub(crate) fn recovered(&self) -> (&SVector<f64, D>, &SVector<f64, D>, &[(f64, f64)]) {
        let kept = &self.recovered;
        (&kept.q, &kept.qd, &kept.trig)
    }

    /// The penalty joint acting, declared or chosen at run time.
    fn penalty(&self) -> Option<PenaltyJoint> {
        match (&self.mode, M::CLOSURE) {
            (Mode::Penalty(joint), _) => Some(*joint),
            (Mode::AsDeclared, Closure::Penalty(joint)) => Some(joint),
            _ => None,
        }
    }

    /// The closing joint's share of the energy books at `(q_i, q̇_i)`: the
    /// elastic energy (J) not already in the model's potential energy, and
    /// the power dissipated (W). A penalty joint's spring and damper (a
    /// declared one's spring is in the model's potential energy already);
    /// zero for constraints (partitioning keeps the closure exactly; the
    /// multiplier method's stabilisation and projection are not
    /// accounted).
    pub(crate) fn closure_energy(&self, q: &SVector<f64, D>, qd: &SVector<f64, D>) -> (f64, f64) {
        let Some(joint) = self.penalty() else {
            return (0.0, 0.0);
        };
        let rate = self.model.closure_jacobian(q) * qd;
        let elastic = match self.mode {
            Mode::Penalty(_) => joint.energy(self.model.closure(q)),
            _ => 0.0,
        };
        (elastic, joint.dissipation(rate))
    }

    /// Makes the start consistent and returns the initial state.
    fn start(
        &mut self,
        mut q: SVector<f64, D>,
        mut qd: SVector<f64, D>,
    ) -> Result<DVector<f64>, ClosureError> {
        let tolerance = self.loop_length * MultiplierOptions::default().tolerance;
        match &mut self.mode {
            Mode::Partitioned(partition) => {
                partition.start(&self.model, &mut q, &mut qd)?;
                let mut y = DVector::zeros(partition.dimension::<D>());
                partition.pack(&q, &qd, y.as_mut_slice());
                Ok(y)
            }
            Mode::Multipliers(_) | Mode::Penalty(_) => {
                let tolerance = match &self.mode {
                    Mode::Multipliers(options) => self.loop_length * options.tolerance,
                    _ => tolerance,
                };
                multipliers::project(&self.model, &mut q, &mut qd, tolerance)?;
                Ok(DVector::from_iterator(
                    2 * D,
                    q.iter().chain(qd.iter()).copied(),
                ))
            }
            Mode::AsDeclared => Ok(DVector::from_iterator(
                2 * D,
                q.iter().chain(qd.iter()).copied(),
            )),
        }
    }

    /// Loads from outside the subsystem (contact with another), added to
    /// gravity and the load function until set again.
    pub(crate) fn set_external(&mut self, loads: &[BodyLoad]) {
        self.loads.set_external(loads);
    }

    /// `q̈_i` at the kept recovery ([`recover`](Self::recover)) under the
    /// current method, by the generated linear-time route (formulation §5). Under
    /// partitioning the state satisfies the closure, where the partitioned
    /// equations and the multiplier form have the same solution. Every
    /// joint's force is kept for [`tensions`](Self::tensions).
    pub(crate) fn accelerations(&mut self, t: f64) -> Result<&SVector<f64, D>, SimulationError> {
        let (q, qd) = (&self.recovered.q, &self.recovered.qd);
        let closing = match &self.mode {
            Mode::Partitioned(_) => ClosingJoint::CLOSED,
            Mode::Multipliers(options) => ClosingJoint::Constrained {
                stabilisation: options
                    .stabilisation(self.model.closure(q), self.model.closure_jacobian(q) * qd),
            },
            Mode::Penalty(_) | Mode::AsDeclared => match self.penalty() {
                Some(joint) => ClosingJoint::Cut {
                    force: joint.force(self.model.closure(q), self.model.closure_jacobian(q) * qd),
                },
                None if M::CLOSURE.is_constrained() => ClosingJoint::CLOSED,
                None => ClosingJoint::OPEN,
            },
        };
        let loads = self.loads.fill(t, q, qd);
        self.model
            .linear_time_dynamics(
                &self.recovered.trig,
                qd,
                loads,
                closing,
                &mut self.qdd,
                &mut self.joint_forces,
            )
            .map_err(|source| SimulationError::Dynamics { t, source })?;
        Ok(&self.qdd)
    }

    /// Every joint's force at the last evaluation, N, global frame: joint
    /// `j` joins link `j` to link `j + 1` (the closing joint joins the last
    /// link to the first), and this is its force on link `j`, link `j + 1`
    /// taking its reverse. For a cut closing joint, the force across the
    /// cut.
    pub fn joint_forces(&self) -> &[Vector2<f64>] {
        &self.joint_forces
    }

    /// The tension (N, positive pulling) in every joint `i → i+1` (the last
    /// is the closing joint `n → 1`) at the last
    /// [`accelerations`](Self::accelerations): the joint's force on link `i`
    /// along its `d̄ⁱ`. For a cut closing joint, the force across the cut.
    pub(crate) fn tensions(&self, out: &mut Vec<f64>) {
        out.clear();
        out.extend(joint_tensions(
            &self.joint_forces,
            &self.spans,
            &self.recovered.trig,
        ));
    }

    /// The state's derivative at the kept recovery
    /// ([`recover`](Self::recover)), so an enclosing system that needs the
    /// coordinates too recovers them once.
    pub(crate) fn derivative_recovered(
        &mut self,
        t: f64,
        dy: &mut [f64],
    ) -> Result<(), SimulationError> {
        self.accelerations(t)?;
        let (qd, qdd) = (&self.recovered.qd, &self.qdd);
        match &self.mode {
            Mode::Partitioned(partition) => partition.pack(qd, qdd, dy),
            _ => {
                dy[..D].copy_from_slice(qd.as_slice());
                dy[D..].copy_from_slice(qdd.as_slice());
            }
        }
        Ok(())
    }
}

impl<M: TrackModel<D>, const D: usize> OdeSystem for TrackSystem<M, D> {
    fn dimension(&self) -> usize {
        self.y0.len()
    }

    fn derivative(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), SimulationError> {
        self.recover(t, y)?;
        self.derivative_recovered(t, dy)
    }
}

impl<M: TrackModel<D>, const D: usize> Simulated for TrackSystem<M, D> {
    fn initial_state(&self) -> DVector<f64> {
        self.y0.clone()
    }

    fn columns(&self) -> Vec<String> {
        let mut c = mechanics_columns(M::BODIES, |b| (b + 1).to_string());
        c.extend(TrackRecord::COLUMNS.iter().map(|c| c.to_string()));
        c
    }

    fn observe(&mut self, t: f64, y: &[f64], row: &mut Vec<f64>) -> Result<(), SimulationError> {
        let (q, qd) = self.coordinates(t, y)?;
        let gap = self.model.closure(&q);
        let cq = self.model.closure_jacobian(&q);
        let spring = match &self.mode {
            Mode::Penalty(joint) => joint.energy(gap),
            _ => 0.0,
        };
        record_mechanics(&self.model, &self.masses, &q, &qd, spring, row);
        self.model
            .closure_columns(&self.recovered.trig, &mut self.columns);
        let conditioning = match &self.mode {
            Mode::Partitioned(partition) => {
                partitioning::conditioning(&self.columns, partition.pair())
            }
            _ => partitioning::best_pair(&self.columns).1,
        };
        TrackRecord {
            closure_error: gap.norm(),
            closure_rate_error: (cq * qd).norm(),
            conditioning,
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
        match &self.mode {
            Mode::AsDeclared | Mode::Penalty(_) => Ok(false),
            Mode::Multipliers(options) => {
                if !options.projection {
                    return Ok(false);
                }
                let tolerance = self.loop_length * options.tolerance;
                let (mut q, mut qd) = self.coordinates(t, y)?;
                multipliers::project(&self.model, &mut q, &mut qd, tolerance).map_err(
                    |failure| match failure {
                        ProjectionFailure::Singular => SimulationError::SingularMatrix {
                            t,
                            what: "C_q C_qᵀ of the projection",
                        },
                        ProjectionFailure::NotConverged {
                            iterations,
                            residual,
                        } => RecoveryError::NewtonFailed {
                            t,
                            iterations,
                            residual,
                        }
                        .into(),
                    },
                )?;
                y[..D].copy_from_slice(q.as_slice());
                y[D..].copy_from_slice(qd.as_slice());
                self.recovered.valid = false;
                Ok(true)
            }
            Mode::Partitioned(_) => {
                let (q, qd) = self.coordinates(t, y)?;
                self.model
                    .closure_columns(&self.recovered.trig, &mut self.columns);
                let Mode::Partitioned(partition) = &mut self.mode else {
                    unreachable!("matched above")
                };
                let switch = partition.accept(t, (&q, &qd), &self.columns, y)?;
                // Newton-Raphson now starts from the accepted pair: a
                // recovery kept from the old start would make the next
                // evaluation at this state depend on what was evaluated
                // before it (the same root, other last bits).
                self.recovered.valid = false;
                match switch {
                    Some(switch) => {
                        switched(switch);
                        Ok(true)
                    }
                    None => Ok(false),
                }
            }
        }
    }
}
