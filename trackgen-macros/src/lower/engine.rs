//! Lowering a powertrain's engine dynamics: `engine_inertia` and
//! `engine_drag` together (the engine's speed then a state of the run),
//! with the governor's time and the lock-up clutch's capacity, stiffness
//! and damping optional (the runtime's `EngineDynamics` defaults).

use super::Lowering;
use super::keys::Fields;
use super::powertrain::Table;
use crate::ir::EngineDynamics;

/// The keys that need `engine_inertia`.
const WITH_INERTIA: [&str; 5] = [
    "engine_drag",
    "governor_time",
    "lockup_capacity",
    "lockup_stiffness",
    "lockup_damping",
];

impl Lowering<'_> {
    /// The engine's dynamics: `None` inside when none is declared; every
    /// problem at its token.
    pub(super) fn engine_dynamics(&mut self, fields: &Fields) -> Option<Option<EngineDynamics>> {
        if !fields.map.contains_key("engine_inertia") {
            let mut fine = true;
            for key in WITH_INERTIA {
                if let Some(expr) = fields.map.get(key) {
                    self.errors.spanned(
                        *expr,
                        format!(
                            "`{key}` belongs to an engine whose speed is a state: declare its `engine_inertia` (kg m²) and `engine_drag` with it"
                        ),
                    );
                    fine = false;
                }
            }
            return fine.then_some(None);
        }
        let inertia = self.positive(fields, "engine_inertia", true);
        let drag = if fields.map.contains_key("engine_drag") {
            self.table(fields, "engine_drag", Table::Drag)
        } else {
            self.errors.spanned(
                fields.map["engine_inertia"],
                "an engine with its inertia needs its torque at no fuel: `engine_drag: [(ω, T), …]` (rad/s, N m ≤ 0)",
            );
            None
        };
        let optional = |this: &mut Self, key: &str| match fields.map.get(key) {
            Some(_) => this.positive(fields, key, true).map(Some),
            None => Some(None),
        };
        let governor_time = optional(self, "governor_time");
        let lockup_capacity = optional(self, "lockup_capacity");
        let lockup_stiffness = optional(self, "lockup_stiffness");
        let lockup_damping = optional(self, "lockup_damping");
        Some(Some(EngineDynamics {
            inertia: inertia?,
            drag: drag?,
            governor_time: governor_time?,
            lockup_capacity: lockup_capacity?,
            lockup_stiffness: lockup_stiffness?,
            lockup_damping: lockup_damping?,
        }))
    }
}
