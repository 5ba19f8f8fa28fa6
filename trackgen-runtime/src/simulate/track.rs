use nalgebra::{DVector, SVector, Vector2};

use super::loads::Loads;
use super::observe::{masses, mechanics_columns, record_mechanics};
use super::{Simulated, SimulationError, Switch};
use crate::closure::{
    ClosureMethod, MultiplierOptions, PartitionOptions, ProjectionFailure, multipliers,
    partitioning, penalty,
};
use crate::dynamics::LinearTimeSolver;
use crate::integrate::OdeSystem;
use crate::model::{BodyLoad, Closure, TrackModel};

/// How this track is closed, resolved from the declaration and the chosen
/// [`ClosureMethod`].
#[derive(Debug, Clone)]
enum Mode {
    /// The declared dynamics as they are: an open chain, or a chain closed
    /// by its declared penalty joint.
    AsDeclared,
    Partitioned {
        options: PartitionOptions,
        /// The dependent links, 0-based.
        pair: [usize; 2],
        independent: Vec<usize>,
        /// The dependent angles last recovered: Newton-Raphson's start.
        guess: [f64; 2],
    },
    Multipliers(MultiplierOptions),
    Penalty {
        stiffness: f64,
        damping: f64,
    },
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
    /// Linear-time forward dynamics (spec §5) with its scratch space.
    solver: LinearTimeSolver,
    /// `Σ |d̄ʲ|`, m: the scale of closure tolerances.
    loop_length: f64,
    /// `d̄ʲ` of every link.
    spans: Vec<Vector2<f64>>,
    switches: Vec<Switch>,
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
    ) -> Result<Self, SimulationError> {
        let declared = M::CLOSURE;
        let mode = match (method, declared) {
            (ClosureMethod::Declared, Closure::Partitioned) => {
                Self::partitioned(PartitionOptions::default())
            }
            (ClosureMethod::Declared, _) => Mode::AsDeclared,
            (_, Closure::Open) => {
                return Err(SimulationError::Setup(
                    "the track is declared `closure: open`; declare it `partitioned` to close its loop".into(),
                ));
            }
            (_, Closure::Penalty { .. }) => {
                return Err(SimulationError::Setup(
                    "the track is declared with a penalty joint; declare it `partitioned` to choose the closure method at run time".into(),
                ));
            }
            (ClosureMethod::Partitioning(options), Closure::Partitioned) => {
                Self::partitioned(options)
            }
            (ClosureMethod::Multipliers(options), Closure::Partitioned) => {
                Mode::Multipliers(options)
            }
            (ClosureMethod::Penalty { stiffness, damping }, Closure::Partitioned) => {
                if !(stiffness > 0.0
                    && stiffness.is_finite()
                    && damping >= 0.0
                    && damping.is_finite())
                {
                    return Err(SimulationError::Setup(format!(
                        "penalty stiffness must be positive and damping non-negative, got k = {stiffness}, c = {damping}"
                    )));
                }
                Mode::Penalty { stiffness, damping }
            }
        };
        let description = model.description();
        let spans = description.link_spans().unwrap_or_default();
        let loop_length = spans
            .iter()
            .map(|d| d.norm())
            .sum::<f64>()
            .max(f64::MIN_POSITIVE);
        let mut system = TrackSystem {
            solver: LinearTimeSolver::new(&model),
            masses: masses(&model),
            model,
            mode,
            y0: DVector::zeros(0),
            loads: Loads::new(M::BODIES),
            loop_length,
            spans,
            switches: Vec::new(),
        };
        system.y0 = system.start(q, qd)?;
        Ok(system)
    }

    fn partitioned(options: PartitionOptions) -> Mode {
        Mode::Partitioned {
            options,
            pair: [0, 1],
            independent: Vec::new(),
            guess: [0.0; 2],
        }
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
            Mode::Partitioned { pair, .. } => Some([pair[0] + 1, pair[1] + 1]),
            _ => None,
        }
    }

    /// `(q_i, q̇_i)` of the state `y`, the closure recovered under
    /// partitioning.
    pub fn coordinates(
        &mut self,
        t: f64,
        y: &DVector<f64>,
    ) -> Result<(SVector<f64, D>, SVector<f64, D>), SimulationError> {
        if y.len() != self.y0.len() {
            return Err(SimulationError::Setup(format!(
                "a state of {} values for a system of {}",
                y.len(),
                self.y0.len()
            )));
        }
        match &self.mode {
            Mode::Partitioned { .. } => self.expand(t, y, None),
            _ => Ok((
                SVector::from_fn(|i, _| y[i]),
                SVector::from_fn(|i, _| y[D + i]),
            )),
        }
    }

    /// [`coordinates`](Self::coordinates), also writing every link's
    /// `(sin θ, cos θ)` at the recovered angles into `trig`.
    pub(crate) fn coordinates_with_trig(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        trig: &mut [(f64, f64)],
    ) -> Result<(SVector<f64, D>, SVector<f64, D>), SimulationError> {
        if let Mode::Partitioned { .. } = self.mode
            && y.len() == self.y0.len()
        {
            return self.expand(t, y, Some(trig));
        }
        let (q, qd) = self.coordinates(t, y)?;
        for (j, sc) in trig.iter_mut().enumerate() {
            *sc = q[2 + j].sin_cos();
        }
        Ok((q, qd))
    }

    /// The closing joint's share of the energy books at `(q_i, q̇_i)`: the
    /// elastic energy (J) not already in the model's potential energy, and
    /// the power dissipated (W). A penalty joint's spring `½ k |C|²` and
    /// damper `c |Ċ|²`; zero for constraints (partitioning keeps the closure
    /// exactly; the multiplier method's stabilisation and projection are
    /// not accounted).
    pub(crate) fn closure_energy(&self, q: &SVector<f64, D>, qd: &SVector<f64, D>) -> (f64, f64) {
        let rate = || (self.model.closure_jacobian(q) * qd).norm_squared();
        match (&self.mode, M::CLOSURE) {
            (Mode::Penalty { stiffness, damping }, _) => (
                penalty::energy(self.model.closure(q), *stiffness),
                damping * rate(),
            ),
            (Mode::AsDeclared, Closure::Penalty { damping, .. }) => (0.0, damping * rate()),
            _ => (0.0, 0.0),
        }
    }

    fn tolerance(&self, fraction: f64) -> f64 {
        fraction * self.loop_length
    }

    /// Makes the start consistent and returns the initial state.
    fn start(
        &mut self,
        mut q: SVector<f64, D>,
        mut qd: SVector<f64, D>,
    ) -> Result<DVector<f64>, SimulationError> {
        let singular = |what| SimulationError::SingularMatrix { t: 0.0, what };
        let tolerance = match &self.mode {
            Mode::Partitioned { options, .. } => self.tolerance(options.newton_tolerance),
            Mode::Multipliers(options) => self.tolerance(options.tolerance),
            Mode::Penalty { .. } => self.tolerance(MultiplierOptions::default().tolerance),
            Mode::AsDeclared => 0.0,
        };
        match &mut self.mode {
            Mode::Partitioned {
                options,
                pair,
                independent,
                guess,
            } => {
                let cq = self.model.closure_jacobian(&q);
                *pair = match options.initial_pair {
                    Some([a, b])
                        if a != b && (1..=D - 2).contains(&a) && (1..=D - 2).contains(&b) =>
                    {
                        [a - 1, b - 1]
                    }
                    Some(p) => {
                        return Err(SimulationError::Setup(format!(
                            "initial_pair {p:?}: two different links from 1 to {}",
                            D - 2
                        )));
                    }
                    None => partitioning::best_pair(&cq).0,
                };
                *independent = partitioning::independent_coordinates(D, *pair);
                partitioning::recover_positions(
                    &self.model,
                    &mut q,
                    *pair,
                    tolerance,
                    options.newton_max_iterations,
                )
                .map_err(|(iterations, residual)| {
                    SimulationError::NewtonFailed {
                        t: 0.0,
                        iterations,
                        residual,
                    }
                })?;
                *guess = [q[2 + pair[0]], q[2 + pair[1]]];
                let cq = self.model.closure_jacobian(&q);
                partitioning::recover_velocities(&cq, &mut qd, *pair)
                    .ok_or_else(|| singular("C_d at the start"))?;
                Ok(Self::pack(independent, &q, &qd))
            }
            Mode::Multipliers(_) | Mode::Penalty { .. } => {
                multipliers::project(&self.model, &mut q, &mut qd, tolerance).map_err(|failure| {
                    SimulationError::Setup(format!(
                        "the initial state cannot be projected onto the loop closure: {failure:?}"
                    ))
                })?;
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

    fn pack(independent: &[usize], q: &SVector<f64, D>, qd: &SVector<f64, D>) -> DVector<f64> {
        let n = independent.len();
        DVector::from_fn(2 * n, |i, _| {
            if i < n {
                q[independent[i]]
            } else {
                qd[independent[i - n]]
            }
        })
    }

    /// Partitioning: `(q_i, q̇_i)` from `[z, ż]`.
    fn expand(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        trig: Option<&mut [(f64, f64)]>,
    ) -> Result<(SVector<f64, D>, SVector<f64, D>), SimulationError> {
        let tolerance = match &self.mode {
            Mode::Partitioned { options, .. } => self.tolerance(options.newton_tolerance),
            _ => unreachable!("expand is for partitioned states"),
        };
        let Mode::Partitioned {
            options,
            pair,
            independent,
            guess,
        } = &mut self.mode
        else {
            unreachable!()
        };
        let n = independent.len();
        let mut q = SVector::<f64, D>::zeros();
        let mut qd = SVector::<f64, D>::zeros();
        for (i, &c) in independent.iter().enumerate() {
            q[c] = y[i];
            qd[c] = y[n + i];
        }
        q[2 + pair[0]] = guess[0];
        q[2 + pair[1]] = guess[1];
        partitioning::recover(
            &self.spans,
            &mut q,
            Some(&mut qd),
            *pair,
            tolerance,
            options.newton_max_iterations,
            trig,
        )
        .map_err(|(iterations, residual)| SimulationError::NewtonFailed {
            t,
            iterations,
            residual,
        })?;
        // The start is the last accepted state's pair (never a rejected
        // trial's), so the result does not depend on the call history; a
        // jump of more than π/2 is the closure's mirror solution.
        let jump = (q[2 + pair[0]] - guess[0])
            .abs()
            .max((q[2 + pair[1]] - guess[1]).abs());
        if jump > std::f64::consts::FRAC_PI_2 {
            return Err(SimulationError::BranchJump {
                t,
                pair: [pair[0] + 1, pair[1] + 1],
                jump,
            });
        }
        Ok((q, qd))
    }

    /// Loads from outside the subsystem (contact with another), added to
    /// gravity and the load function until set again.
    pub(crate) fn set_external(&mut self, loads: &[BodyLoad]) {
        self.loads.set_external(loads);
    }

    /// `q̈_i` at `(q_i, q̇_i)` under the current method, by the
    /// linear-time route (spec §5). Under partitioning the state satisfies
    /// the closure, where the partitioned equations and the multiplier
    /// form have the same solution.
    pub(crate) fn accelerations(
        &mut self,
        t: f64,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        trig: Option<&[(f64, f64)]>,
    ) -> Result<SVector<f64, D>, SimulationError> {
        let loads = self.loads.fill(t, q, qd);
        let dynamics = |source| SimulationError::Dynamics { t, source };
        let (constrained, stabilisation, penalty) = match &self.mode {
            Mode::AsDeclared => {
                return Ok(self
                    .solver
                    .forward_dynamics(&self.model, q, qd, loads)
                    .map_err(dynamics)?
                    .qdd);
            }
            Mode::Penalty { stiffness, damping } => {
                let rate = self.model.closure_jacobian(q) * qd;
                (
                    false,
                    Vector2::zeros(),
                    Some(-self.model.closure(q) * *stiffness - rate * *damping),
                )
            }
            Mode::Multipliers(options) => {
                let (c, rate) = (self.model.closure(q), self.model.closure_jacobian(q) * qd);
                let omega = options.baumgarte;
                (true, rate * (2.0 * omega) + c * (omega * omega), None)
            }
            Mode::Partitioned { .. } => (true, Vector2::zeros(), None),
        };
        let (qdd, _) = self
            .solver
            .accelerations_with_trig(q, qd, loads, constrained, stabilisation, penalty, trig)
            .map_err(dynamics)?;
        Ok(qdd)
    }
}

impl<M: TrackModel<D>, const D: usize> OdeSystem for TrackSystem<M, D> {
    fn dimension(&self) -> usize {
        self.y0.len()
    }

    fn derivative(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        dy: &mut DVector<f64>,
    ) -> Result<(), SimulationError> {
        let (q, qd) = self.coordinates(t, y)?;
        self.derivative_at(t, &q, &qd, dy, None)
    }
}

impl<M: TrackModel<D>, const D: usize> TrackSystem<M, D> {
    /// The state's derivative from coordinates already recovered by
    /// [`coordinates`](Self::coordinates) (so an enclosing system that needs
    /// them too recovers them once).
    pub(crate) fn derivative_at(
        &mut self,
        t: f64,
        q: &SVector<f64, D>,
        qd: &SVector<f64, D>,
        dy: &mut DVector<f64>,
        trig: Option<&[(f64, f64)]>,
    ) -> Result<(), SimulationError> {
        let qdd = self.accelerations(t, q, qd, trig)?;
        match &self.mode {
            Mode::Partitioned { independent, .. } => {
                let n = independent.len();
                for (i, &c) in independent.iter().enumerate() {
                    dy[i] = qd[c];
                    dy[n + i] = qdd[c];
                }
            }
            _ => {
                for i in 0..D {
                    dy[i] = qd[i];
                    dy[D + i] = qdd[i];
                }
            }
        }
        Ok(())
    }
}

impl<M: TrackModel<D>, const D: usize> Simulated for TrackSystem<M, D> {
    fn initial_state(&self) -> DVector<f64> {
        self.y0.clone()
    }

    fn columns(&self) -> Vec<String> {
        let mut c = mechanics_columns(M::BODIES, |b| (b + 1).to_string());
        c.extend(["closure_error", "closure_rate_error", "conditioning"].map(String::from));
        c
    }

    fn observe(
        &mut self,
        t: f64,
        y: &DVector<f64>,
        row: &mut Vec<f64>,
    ) -> Result<(), SimulationError> {
        let (q, qd) = self.coordinates(t, y)?;
        let gap = self.model.closure(&q);
        let cq = self.model.closure_jacobian(&q);
        let spring = match &self.mode {
            Mode::Penalty { stiffness, .. } => penalty::energy(gap, *stiffness),
            _ => 0.0,
        };
        record_mechanics(&self.model, &self.masses, &q, &qd, spring, row);
        let conditioning = match &self.mode {
            Mode::Partitioned { pair, .. } => partitioning::conditioning(&cq, *pair),
            _ => partitioning::best_pair(&cq).1,
        };
        row.extend([gap.norm(), (cq * qd).norm(), conditioning]);
        Ok(())
    }

    fn after_step(&mut self, t: f64, y: &mut DVector<f64>) -> Result<bool, SimulationError> {
        match &self.mode {
            Mode::AsDeclared | Mode::Penalty { .. } => Ok(false),
            Mode::Multipliers(options) => {
                if !options.projection {
                    return Ok(false);
                }
                let tolerance = self.tolerance(options.tolerance);
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
                        } => SimulationError::NewtonFailed {
                            t,
                            iterations,
                            residual,
                        },
                    },
                )?;
                for i in 0..D {
                    y[i] = q[i];
                    y[D + i] = qd[i];
                }
                Ok(true)
            }
            Mode::Partitioned { .. } => {
                let (q, qd) = self.expand(t, y, None)?;
                let cq = self.model.closure_jacobian(&q);
                let Mode::Partitioned {
                    options,
                    pair,
                    independent,
                    guess,
                } = &mut self.mode
                else {
                    unreachable!()
                };
                *guess = [q[2 + pair[0]], q[2 + pair[1]]];
                let now = partitioning::conditioning(&cq, *pair);
                if !options.switching {
                    if now < options.singular_below {
                        return Err(SimulationError::SingularPartition {
                            t,
                            pair: [pair[0] + 1, pair[1] + 1],
                            conditioning: now,
                        });
                    }
                    return Ok(false);
                }
                if now >= options.switch_below {
                    return Ok(false);
                }
                let (best, better) = partitioning::best_pair(&cq);
                if best == *pair {
                    return Ok(false);
                }
                self.switches.push(Switch {
                    t,
                    from: [pair[0] + 1, pair[1] + 1],
                    to: [best[0] + 1, best[1] + 1],
                    conditioning: now,
                    new_conditioning: better,
                });
                *pair = best;
                *independent = partitioning::independent_coordinates(D, best);
                *guess = [q[2 + best[0]], q[2 + best[1]]];
                *y = Self::pack(independent, &q, &qd);
                Ok(true)
            }
        }
    }

    fn switches(&self) -> Vec<Switch> {
        self.switches.clone()
    }
}
