//! The FMU's instance against native runs, its refusals and its model
//! description. The C API over it is checked by fmpy in CI
//! (`tools/fmu-check.py`).

use trackgen::integrate::Integrator;
use trackgen::scenario::Scenario;
use trackgen::simulate::{Output, Results, simulate};
use trackgen::terrain::Terrain;
use trackgen::vehicle::{Vehicle, VehicleConfig, speed_ramp};
use trackgen::vehicles::m113::M113;
use trackgen_fmu::variables::Role;
use trackgen_fmu::{FmuError, Instance, Mode};

mod common;

/// The main job's integrator at its default tolerances.
const INTEGRATOR: Integrator = Integrator::DEFAULT;

fn reference(name: &str) -> u32 {
    Instance::<M113>::new()
        .unwrap()
        .variables()
        .iter()
        .find(|v| v.name == name)
        .unwrap_or_else(|| panic!("no variable {name}"))
        .value_reference
}

/// The main job's configuration: the bump 0.1 m high at 12 m, the speed
/// ramp to 3 m/s from 1 s over 2 s.
fn main_job_config() -> VehicleConfig {
    M113::declared_config(
        Terrain::Bump {
            centre: 12.0,
            width: 1.0,
            height: 0.1,
        },
        M113::speed_drive(speed_ramp(1.0, 2.0, 3.0)),
    )
}

fn native(config: VehicleConfig, t_end: f64, every: f64) -> Results {
    let mut system = M113::system_with(config).unwrap();
    simulate(&mut system, INTEGRATOR, 0.0, t_end, Output::Every(every)).unwrap()
}

/// Runs `instance` to `t_end` in steps of `h`, reading every recorded
/// column at every communication point (the start's included).
fn run_fmu(instance: &mut Instance<M113>, t_end: f64, h: f64) -> Vec<Vec<f64>> {
    instance.setup_experiment(None, 0.0, Some(t_end)).unwrap();
    instance.enter_initialization().unwrap();
    instance.exit_initialization().unwrap();
    let columns: Vec<u32> = instance
        .variables()
        .iter()
        .filter(|v| matches!(v.role, Role::Column(_)))
        .map(|v| v.value_reference)
        .collect();
    let read = |instance: &Instance<M113>| {
        let mut row = vec![0.0; columns.len()];
        instance.get_f64(&columns, &mut row).unwrap();
        row
    };
    let mut rows = vec![read(instance)];
    // The grid as fmpy makes it: points `k h`, steps the differences (so
    // each step ends exactly on the next point, as a native run's rows).
    let n = (t_end / h).round() as usize;
    for k in 0..n {
        let (t, next) = (k as f64 * h, (k + 1) as f64 * h);
        instance.do_step(t, next - t).unwrap();
        rows.push(read(instance));
    }
    rows
}

fn assert_same(fmu: &[Vec<f64>], native: &Results) {
    assert_eq!(fmu.len(), native.len());
    for (i, row) in fmu.iter().enumerate() {
        let sample = native.sample(i);
        for (j, (a, b)) in row.iter().zip(sample.values).enumerate() {
            assert_eq!(
                a.to_bits(),
                b.to_bits(),
                "t = {} s, {}: FMU {a} against native {b}",
                native.times()[i],
                native.columns()[j]
            );
        }
    }
}

/// The FMU's parameters at their start values name the main job's run:
/// the instance's scenario is `Scenario::default()`, and that scenario's
/// configuration runs bit for bit as this file's main job, written out
/// from the guide's figures (the bump 0.1 m high at 12 m, the ramp to
/// 3 m/s from 1 s over 2 s), and through the FMU.
#[test]
fn the_default_parameters_are_the_main_jobs_scenario() {
    let mut instance = Instance::<M113>::new().unwrap();
    let scenario = instance.scenario().unwrap();
    assert_eq!(scenario, Scenario::default());
    let config = scenario.config::<M113>(scenario.terrain().unwrap(), None);
    let from_scenario = native(config, 1.5, 0.01);
    let fmu = run_fmu(&mut instance, 1.5, 0.01);
    assert_same(&fmu, &from_scenario);
    let written_out = native(main_job_config(), 1.5, 0.01);
    let rows: Vec<Vec<f64>> = (0..written_out.len())
        .map(|i| written_out.sample(i).values.to_vec())
        .collect();
    assert_same(&rows, &from_scenario);
}

/// The FMU's outputs are the native run's bit for bit: the same steps (to
/// the stop time, never clipped at a communication point), the same
/// dense output. At 10 ms (the main job's rows; a step covers at most one
/// point) and at 3 ms (a step covers several).
#[test]
fn outputs_are_the_native_runs() {
    for h in [0.01, 0.003] {
        let t_end = if h == 0.01 { 2.0 } else { 1.2 };
        let mut instance = Instance::<M113>::new().unwrap();
        let fmu = run_fmu(&mut instance, t_end, h);
        assert_same(&fmu, &native(main_job_config(), t_end, h));
    }
}

/// The arms' rates are parameters: set, they reach the vehicle (the run
/// equals a native one with the same rates) without rebuilding anything.
#[test]
fn spring_rates_are_parameters() {
    let mut instance = Instance::<M113>::new().unwrap();
    let k = reference("rw1.arm_stiffness");
    let c = reference("rw1.arm_damping");
    let mut declared = [0.0; 2];
    instance.get_f64(&[k, c], &mut declared).unwrap();
    let rates = [0.6 * declared[0], 2.0 * declared[1]];
    instance.set_f64(&[k, c], &rates).unwrap();
    let fmu = run_fmu(&mut instance, 1.0, 0.01);

    let mut config = main_job_config();
    let (_, rw1) = trackgen_fmu::variables::arm_names::<M113>()
        .into_iter()
        .find(|(part, _)| *part == "rw1")
        .unwrap();
    let arm = config.arms.iter_mut().find(|a| a.body == rw1).unwrap();
    arm.spring.stiffness = rates[0];
    arm.spring.damping = rates[1];
    let softer = native(config, 1.0, 0.01);
    assert_same(&fmu, &softer);
    // And differs from the declared rates' run.
    let declared_run = native(main_job_config(), 1.0, 0.01);
    let y = declared_run
        .columns()
        .iter()
        .position(|c| c == "y")
        .unwrap();
    assert_ne!(
        fmu.last().unwrap()[y],
        declared_run.last().unwrap().values[y]
    );
}

/// The speed input: unchanged, the run is the native run with that
/// constant target; changed at a communication point, the rows before it
/// are the same and the vehicle then follows the new target.
#[test]
fn speed_input_changes_at_communication_points() {
    let start = |instance: &mut Instance<M113>| {
        instance.set_string(reference("drive"), "speed").unwrap();
        instance.set_string(reference("course"), "flat").unwrap();
        instance
            .set_f64(&[reference("target_speed")], &[1.0])
            .unwrap();
        instance.setup_experiment(None, 0.0, Some(4.0)).unwrap();
        instance.enter_initialization().unwrap();
        instance.exit_initialization().unwrap();
    };
    let speed = reference("speed");
    let read = |instance: &Instance<M113>| {
        let mut v = [0.0];
        instance.get_f64(&[speed], &mut v).unwrap();
        v[0]
    };
    let (mut steady, mut changed) = (
        Instance::<M113>::new().unwrap(),
        Instance::<M113>::new().unwrap(),
    );
    start(&mut steady);
    start(&mut changed);
    let mut native_rows = {
        let mut system = M113::system_with(M113::declared_config(
            Terrain::Flat { height: 0.0 },
            M113::speed_drive(|_| 1.0),
        ))
        .unwrap();
        simulate(&mut system, INTEGRATOR, 0.0, 4.0, Output::Every(0.01))
            .unwrap()
            .column("speed")
            .unwrap()
            .into_iter()
    };
    assert_eq!(
        read(&steady).to_bits(),
        native_rows.next().unwrap().to_bits()
    );
    for k in 0..400 {
        let (t, next) = (k as f64 * 0.01, (k + 1) as f64 * 0.01);
        if k == 200 {
            // The same value again is no change; a new one is.
            steady
                .set_f64(&[reference("target_speed")], &[1.0])
                .unwrap();
            changed
                .set_f64(&[reference("target_speed")], &[2.0])
                .unwrap();
        }
        steady.do_step(t, next - t).unwrap();
        changed.do_step(t, next - t).unwrap();
        let native = native_rows.next().unwrap();
        assert_eq!(read(&steady).to_bits(), native.to_bits(), "t = {next} s");
        if k < 200 {
            assert_eq!(read(&changed).to_bits(), native.to_bits());
        }
    }
    // Two seconds after the change the controller has it near 2 m/s
    // (its settling time on the M113 is about a second).
    assert!((read(&changed) - 2.0).abs() < 0.1, "{}", read(&changed));
    assert!((read(&steady) - 1.0).abs() < 0.1, "{}", read(&steady));
}

/// Every bad value is refused with its name and range, and leaves the
/// instance usable; calls out of FMI's order are refused.
#[test]
fn bad_values_are_refused_by_name() {
    let mut instance = Instance::<M113>::new().unwrap();
    let numbers = [
        ("bump_height", 5.0),
        ("bump_at", f64::NAN),
        ("tolerance", 1.0),
        ("profile_speed", 30.0),
        ("rw1.arm_stiffness", -1.0),
        ("rw2.arm_damping", f64::INFINITY),
        ("drawbar_pull", f64::NAN),
        ("course_length", 5.0),
    ];
    for (name, value) in numbers {
        let e = instance.set_f64(&[reference(name)], &[value]).unwrap_err();
        assert!(
            matches!(&e, FmuError::Parameter { name: n, .. } if n == name),
            "{name}: {e}"
        );
    }
    let strings = [
        ("course", "moon"),
        ("soil", "mud"),
        ("roughness", "rough"),
        ("obstacle", "step"),
        ("drive", "pedal"),
    ];
    for (name, value) in strings {
        let e = instance.set_string(reference(name), value).unwrap_err();
        assert!(e.to_string().starts_with(name), "{name}: {e}");
    }
    // Outputs are computed when initialisation ends.
    assert!(instance.get_f64(&[reference("x")], &mut [0.0]).is_err());
    // No such variable; not a string.
    assert!(instance.get_f64(&[100_000], &mut [0.0]).is_err());
    assert!(instance.get_string(reference("x")).is_err());
    // A file that is not there: an error when the vehicle is built.
    instance.set_string(reference("course"), "file").unwrap();
    instance
        .set_string(reference("course_file"), "/nonexistent.csv")
        .unwrap();
    instance.setup_experiment(None, 0.0, Some(1.0)).unwrap();
    instance.enter_initialization().unwrap();
    let e = instance.exit_initialization().unwrap_err();
    assert!(e.to_string().contains("/nonexistent.csv"), "{e}");
    // Still usable: a good terrain, and it runs.
    instance.set_string(reference("course"), "flat").unwrap();
    instance.exit_initialization().unwrap();
    assert_eq!(instance.mode(), Mode::Step);
    // Parameters are fixed once it runs; the time must be the one reached.
    assert!(
        instance
            .set_f64(&[reference("bump_height")], &[0.2])
            .is_err()
    );
    assert!(instance.do_step(0.5, 0.01).is_err());
    assert!(instance.do_step(0.0, -0.01).is_err());
    assert!(instance.do_step(0.0, 2.0).is_err());
    instance.do_step(0.0, 0.01).unwrap();
    // Reset: back to the start values.
    instance.reset();
    let mut height = [0.0];
    instance
        .get_f64(&[reference("bump_height")], &mut height)
        .unwrap();
    assert_eq!(height[0], 0.1);
    assert_eq!(instance.get_string(reference("course")).unwrap(), "bump");
}

/// A random course, an obstacle and soft soil build and run (their syntax
/// is the main job's).
#[test]
fn every_course_kind_runs() {
    let cases: [&[(&str, &str)]; 4] = [
        &[("course", "random"), ("roughness", "C")],
        &[("course", "obstacle"), ("obstacle", "half-round:0.2")],
        &[("course", "flat"), ("soil", "dry-sand")],
        &[("course", "flat"), ("drive", "torque")],
    ];
    for case in cases {
        let mut instance = Instance::<M113>::new().unwrap();
        for (name, value) in case {
            instance.set_string(reference(name), value).unwrap();
        }
        instance
            .set_f64(&[reference("drive_torque")], &[-500.0])
            .unwrap();
        let rows = run_fmu(&mut instance, 0.3, 0.05);
        assert!(rows.iter().flatten().all(|v| v.is_finite()), "{case:?}");
    }
}

/// The description's table: one name per variable, the value reference
/// its place, one independent variable (time), every unit defined.
#[test]
fn the_table_is_consistent() {
    let instance = Instance::<M113>::new().unwrap();
    common::assert_table_is_consistent::<M113>(instance.variables());
}

/// The guide's chapter lists every parameter and input (arms by their
/// pattern).
#[test]
fn the_guide_lists_every_setting() {
    let guide = include_str!("../../book/src/fmu.md");
    let instance = Instance::<M113>::new().unwrap();
    for v in instance.variables() {
        let listed = match v.role {
            Role::ArmStiffness(_) => "`<part>.arm_stiffness`".to_string(),
            Role::ArmDamping(_) => "`<part>.arm_damping`".to_string(),
            Role::Setting(_) | Role::Input(_) => format!("`{}`", v.name),
            _ => continue,
        };
        assert!(guide.contains(&listed), "the guide lists {listed}");
    }
}

/// `write_fmu` packs the description and the library where FMI 3.0 and
/// 2.0 look for them.
#[test]
fn write_fmu_lays_out_the_archive() {
    let dir = std::env::temp_dir().join(format!("trackgen-fmu-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let library = dir.join("libfake.so");
    std::fs::write(&library, b"not really a library").unwrap();
    for (version, file, binary) in [
        (
            trackgen_fmu::Version::Fmi3,
            "M113.fmu",
            "binaries/x86_64-linux/M113.so",
        ),
        (
            trackgen_fmu::Version::Fmi2,
            "M113-fmi2.fmu",
            "binaries/linux64/M113.so",
        ),
    ] {
        let path = trackgen_fmu::write_fmu::<M113>(&library, &dir, version).unwrap();
        assert_eq!(path, dir.join(file));
        let bytes = std::fs::read(&path).unwrap();
        let has = |name: &str| bytes.windows(name.len()).any(|w| w == name.as_bytes());
        assert!(has("modelDescription.xml") && has(binary), "{file}");
        assert!(has("not really a library"), "{file}: the library, stored");
    }
    // A library that is not there: an error naming it.
    let e =
        trackgen_fmu::write_fmu::<M113>(&dir.join("missing.so"), &dir, trackgen_fmu::Version::Fmi3)
            .unwrap_err();
    assert!(e.to_string().contains("missing.so"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `engine = 1` drives through the engine the library was exported with:
/// the run is the native run with that powertrain; without one it is
/// refused, and only 0 and 1 are values.
#[test]
fn engine_parameter_drives_through_the_powertrain() {
    let engine = reference("engine");
    let mut without = Instance::<M113>::new().unwrap();
    assert!(without.set_i32(&[engine], &[2]).is_err());
    without.set_i32(&[engine], &[1]).unwrap();
    without.setup_experiment(None, 0.0, Some(1.0)).unwrap();
    without.enter_initialization().unwrap();
    let e = without.exit_initialization().unwrap_err();
    assert!(e.to_string().contains("has no engine"), "{e}");

    let powertrain = trackgen::vehicles::m113::powertrain();
    let mut with = Instance::<M113>::with_engine(Some(powertrain.clone())).unwrap();
    with.set_i32(&[engine], &[1]).unwrap();
    let fmu = run_fmu(&mut with, 1.5, 0.01);
    let mut config = main_job_config();
    config.powertrain = Some(powertrain);
    assert_same(&fmu, &native(config, 1.5, 0.01));
}
