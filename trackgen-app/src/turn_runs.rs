//! Steady turns run on the spatial vehicle (`steer --spatial`): each at
//! the belt speeds the general theory gives a turn, on firm level
//! ground, so that what the vehicle does in 3-D stands beside what the
//! theory estimates from its loads at rest. Each is the runtime's
//! steady turn ([`steady_turn`]: settled, ramped to its belts, averaged
//! over stretches until two agree), under the declared laws at the
//! explicit method's default tolerance, on the speed drives alone.

use rayon::prelude::*;

use crate::offered::RunTurn;
use trackgen::integrate::Integrator;
use trackgen::mobility::turning::steady_turn;
use trackgen::spatial_vehicle::SpatialVehicleSystem;

/// The steady turns of `V` at each pair of belt speeds (right, left,
/// m/s), run side by side; a run that fails is its error in words.
pub(crate) fn run_turns<V: SpatialVehicleSystem>(
    belts: &[[f64; 2]],
) -> Vec<Result<RunTurn, String>> {
    belts
        .par_iter()
        .map(|&pair| {
            steady_turn::<V>(
                V::declared_laws(),
                pair,
                None,
                Integrator::DEFAULT_EXPLICIT_TOLERANCE,
            )
            .map_err(|e| e.to_string())
        })
        .collect()
}
