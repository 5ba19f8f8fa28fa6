// After an error in a declaration, every item it would generate still
// exists: code that uses each of them reports nothing more than the one
// real error (a negative mass).
use trackgen::terrain::Terrain;
use trackgen::system::Simulated;
use trackgen::multibody::{RecursiveModel, TrackModel};
use trackgen::vehicle::{Vehicle, VehicleDynamics};
use trackgen::spatial::SpatialVehicle;

trackgen::model! {
    pub vehicle Tank {
        chassis { mass: -1000.0, inertia: 500.0 },
        sprocket drive { at: (0.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25, teeth: 10 },
        road_wheel rw[2] { at: [(-1.0, -0.2), (-2.0, -0.2)], mass: 30.0, inertia: 2.0, radius: 0.3,
            arm { pivot_offset: (0.3, 0.1), mass: 20.0, inertia: 0.2, stiffness: 1e4, damping: 100.0 } },
        idler rear { at: (-3.0, 0.0), mass: 20.0, inertia: 1.0, radius: 0.25 },
        track { links: 40, link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) } },
        shoe { ground_points: [(-0.06, -0.03), (0.06, -0.03)], inner_offset: 0.03,
               pins: [(0.0535, 0.0), (-0.061, 0.0)], pin_radius: 0.015, width: 0.38 },
        tracks {
            gauge: 2.2,
            hull { mass: 2000.0, inertia: (600.0, 1000.0, 1200.0) },
            left { links: 39 },
        },
    }

    pub track Chain {
        links: 4,
        link { mass: 18.0, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
    }
}

fn main() {
    let _ = (Tank, Tank::TRACK, Tank::CHASSIS, TankTrack, TankChassis);
    let _ = (Tank::TRACK_DOF, Tank::CHASSIS_DOF, TankTrack::LINKS, Chain::LINKS);
    let _ = (TankChassis::FRAME, TankChassis::DRIVE, TankChassis::RW1, TankChassis::RW2_ARM);
    let _ = (TankChassis::REAR, <Tank as Vehicle>::NAME);
    let system: Result<TankSystem, _> =
        Tank::system(Terrain::Flat { height: 0.0 }, Tank::speed_drive(|_| 1.0));
    let _ = system.map(|s| s.initial_state());
    let _ = (Tank::geometry(), <Tank as Vehicle>::System::track_dof());
    let q = trackgen::nalgebra::SVector::<f64, 42>::zeros();
    let _ = TankTrack.closure(&q);
    let _ = (Tank::HULL, TankHull::FRAME, TankHull::RIGHT_RW1, TankHull::LEFT_RW2_ARM, TankLeftTrack);
    let _ = (<Tank as SpatialVehicle>::HULL_DOF, <Tank as SpatialVehicle>::LEFT_TRACK_DOF, Tank::layout());
    let _ = <TankHull as RecursiveModel<{ <Tank as SpatialVehicle>::HULL_DOF }>>::description(&TankHull);
    let _ = TankLeftTrack.closure(&trackgen::nalgebra::SVector::<f64, 41>::zeros());
    let _ = Chain.kinetic_energy(&trackgen::nalgebra::SVector::<f64, 6>::zeros(), &q.fixed_rows::<6>(0).into());
}
