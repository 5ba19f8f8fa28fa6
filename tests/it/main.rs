//! The integration tests of the workspace, one binary: a module per
//! subject (one link, one build of the generic code they share).
//! `tests/allocations.rs` is a binary of its own: it counts every heap
//! allocation of its process.

mod support;

mod assembly;
mod auto_integrator;
mod brake;
mod chassis_finite_differences;
mod closed_chain_simulation;
mod constant_expressions;
mod contact_geometry;
mod contact_jacobians;
mod contact_laws;
mod converter;
mod derivatives;
mod derivatives_pinocchio;
mod energy_books;
mod engine_dynamics;
mod engine_side;
mod equilibrium;
mod examples;
mod finite_differences;
mod fitted_contact;
mod generated_vs_reference;
mod grade_hold;
mod half_round_lift;
mod hull;
mod integrators;
mod large_tracks;
mod layers;
mod linear_time;
mod mass_matrix_properties;
mod mobility;
mod modes;
mod multiplier_residuals;
mod partition_recovery;
mod pinocchio;
mod powertrain;
mod private_paths;
mod pure_evaluation;
mod readme_figures;
mod ride_chain;
mod rosenbrock_w;
mod run_settings_properties;
mod seat;
mod shift;
mod shifted_chain;
mod soft_ground;
mod soil_laws;
mod stands_alone;
mod stiction;
mod terrain;
mod track_speed;
mod tree_dynamics;
mod vehicle_branches;
mod vehicle_build;
mod vehicle_chassis;
mod vehicle_declaration;
mod vehicle_implicit;
mod vehicle_jacobian;
mod vehicle_m113;
mod vehicle_marder;
mod vehicle_own_solves;
mod vehicle_simulation;
mod vehicle_soil;
