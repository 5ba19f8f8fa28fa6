//! The generated code against an independent rigid-body library: mass
//! matrices and accelerations of four chains computed by Pinocchio 4.1.0
//! (tests/data/pinocchio_chains.json; tests/data/README.md says how it
//! was computed).
//!
//! Tolerance 1e-12 relative (norm-wise, see `support::assert_close`): the
//! reference quotes "about 1e-12", both sides are double precision and the
//! chains are at most 12 coordinates, so a formula error shows as an O(1)
//! difference.

use crate::support;
include!("support/chains.rs");

use support::assert_close;
use support::pinocchio::{case, floats};
use trackgen::multibody::{RecursiveModel, TrackModel};
use trackgen::nalgebra::{SMatrix, SVector};

const REL: f64 = 1e-12;

fn check<M: TrackModel<D>, const D: usize>(model: M, name: &str) {
    let case = case("pinocchio_chains.json", name);
    // The declaration was transcribed from the JSON: check it link by link.
    let desc = model.description();
    let links = case["links"].as_array().unwrap();
    assert_eq!(links.len(), M::BODIES);
    let spans = desc.link_spans().unwrap();
    for (i, link) in links.iter().enumerate() {
        assert_eq!(
            desc.bodies[i].mass,
            link["m"].as_f64().unwrap(),
            "{name} link {i} mass"
        );
        assert_eq!(
            desc.bodies[i].inertia,
            link["J"].as_f64().unwrap(),
            "{name} link {i} inertia"
        );
        let (u1, u2) = (floats(&link["u1"]), floats(&link["u2"]));
        assert_eq!(
            spans[i].as_slice(),
            &[u2[0] - u1[0], u2[1] - u1[1]],
            "{name} link {i} span"
        );
    }
    assert_eq!(
        M::CLOSURE.is_constrained(),
        case["closed"].as_bool().unwrap()
    );
    assert_eq!(desc.gravity.as_slice(), floats(&case["gravity"]).as_slice());

    for (k, state) in case["states"].as_array().unwrap().iter().enumerate() {
        let q = SVector::<f64, D>::from_column_slice(&floats(&state["q"]));
        let qd = SVector::<f64, D>::from_column_slice(&floats(&state["qd"]));
        let mut mass = SMatrix::<f64, D, D>::zeros();
        model.mass_matrix(&q, &mut mass);
        let want: Vec<f64> = state["mass"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(floats)
            .collect();
        // Row-major JSON against column-major storage: M_i is symmetric.
        assert_close(
            &format!("{name} state {k}: M_i"),
            mass.as_slice(),
            &want,
            REL,
            0.0,
        );
        let acc = trackgen::dynamics::dense_forward_dynamics(&model, &q, &qd, &[]).unwrap();
        assert_close(
            &format!("{name} state {k}: q̈_i"),
            acc.qdd.as_slice(),
            &floats(&state["qdd"]),
            REL,
            0.0,
        );
    }
}

#[test]
fn open_3_links_match_pinocchio() {
    check(PinocchioOpen3, "open-3");
}

#[test]
fn closed_4_links_match_pinocchio() {
    check(PinocchioClosed4, "closed-4");
}

#[test]
fn open_10_links_match_pinocchio() {
    check(PinocchioOpen10, "open-10");
}

#[test]
fn closed_10_links_match_pinocchio() {
    check(PinocchioClosed10, "closed-10");
}

/// The reference route is itself checked against Pinocchio, so that it can
/// be trusted as the oracle where no Pinocchio data exist.
#[test]
fn reference_route_matches_pinocchio() {
    use trackgen::nalgebra::DVector;
    use trackgen_runtime::reference::ReferenceModel;
    let models = [
        ("open-3", PinocchioOpen3.description()),
        ("closed-4", PinocchioClosed4.description()),
        ("open-10", PinocchioOpen10.description()),
        ("closed-10", PinocchioClosed10.description()),
    ];
    for (name, desc) in models {
        let reference = ReferenceModel::new(desc);
        let case = case("pinocchio_chains.json", name);
        for state in case["states"].as_array().unwrap() {
            let q = DVector::from_vec(floats(&state["q"]));
            let qd = DVector::from_vec(floats(&state["qd"]));
            let want: Vec<f64> = state["mass"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(floats)
                .collect();
            assert_close(
                &format!("{name}: reference M_i"),
                reference.mass_matrix(&q).as_slice(),
                &want,
                REL,
                0.0,
            );
            let acc = reference.forward_dynamics(&q, &qd, &[]).unwrap();
            assert_close(
                &format!("{name}: reference q̈_i"),
                acc.qdd.as_slice(),
                &floats(&state["qdd"]),
                REL,
                0.0,
            );
        }
    }
}
