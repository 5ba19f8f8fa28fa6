//! The vehicle at rest and how it vibrates there: the `modes` subcommand,
//! and `run`'s `--start equilibrium` and `--modes` (the table,
//! `modes.csv`, `modes.svg`, `modes.html`).

use std::error::Error;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use trackgen::analysis::{Equilibrium, EquilibriumOptions, Mode, equilibrium, mode_of, modes};
use trackgen::vehicle::{Vehicle, VehicleDynamics};

use trackgen::scene::{self, Scene};
use trackgen::terrain::Terrain;
use trackgen_draw::{animation, vehicle};

use crate::console::say;
use crate::offered::Offered;

/// The vehicle at rest on flat ground, held by its speed controller at
/// standstill, and its modes there: the lowest printed, every one in
/// `modes.csv`, the six lowest drawn in `modes.svg` and played in
/// `modes.html`.
#[derive(clap::Args, Debug)]
pub struct ModesArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// Output folder (created if missing); default `out/<vehicle>`.
    #[arg(long, value_name = "DIR", value_parser = crate::cli::folder)]
    pub out: Option<PathBuf>,
    /// Also the spatial model's modes at rest (a vehicle declared with a
    /// `tracks` block): settled on its speed drives, linearised, the
    /// hull's bounce, pitch, roll, sway, surge and yaw printed and every
    /// mode up to 30 Hz in `modes-spatial.csv`.
    #[arg(long)]
    pub spatial: bool,
}

/// `modes` for the vehicle `V`: exits 1, saying why, when the rest or the
/// modes cannot be found or written.
pub fn main<V: Vehicle>(entry: &Offered, args: &ModesArgs) -> ExitCode {
    let dir = args
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("out").join(entry.name()));
    let found = || -> Result<Vec<String>, Box<dyn Error>> {
        std::fs::create_dir_all(&dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
        let terrain = Terrain::Flat { height: 0.0 };
        let mut system = V::system(terrain.clone(), V::speed_drive(|_| 0.0))?;
        let (rest, _) = find_rest(&mut system)?;
        let ground = scene::Ground {
            terrain,
            rut: Vec::new(),
        };
        let mut files = report::<V>(&mut system, &rest, &dir, &ground)?.0;
        if args.spatial {
            let found = entry.spatial_modes.ok_or_else(|| {
                format!(
                    "`--spatial` runs the vehicle in 3-D: `{}` is declared without a `tracks` block",
                    entry.name()
                )
            })?;
            files.push(crate::spatial_modes::report(&found()?, &dir)?);
        }
        Ok(files)
    };
    match found() {
        Ok(files) => {
            say!("wrote {}/{{{}}}", dir.display(), files.join(", "));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The vehicle at rest where it stands, and the wall time it took.
pub fn find_rest<S: VehicleDynamics>(system: &mut S) -> Result<(Equilibrium, f64), Box<dyn Error>> {
    let started = Instant::now();
    let rest = equilibrium(system, &EquilibriumOptions::default())
        .map_err(|e| format!("the vehicle at rest: {e}"))?;
    let seconds = started.elapsed().as_secs_f64();
    say!(
        "at rest in {:.0} ms ({} Newton iterations, accelerations left {:.0e}): hull at {:.4} m, pitch {:.5} rad; the ground carries {:.1} kN of {:.1} kN; the drive holds {:.1} N m",
        seconds * 1e3,
        rest.iterations,
        rest.residual,
        rest.height,
        rest.pitch,
        rest.ground_force / 1e3,
        rest.weight / 1e3,
        rest.holding_torque
    );
    Ok((rest, seconds))
}

/// How many modes the table prints and the picture draws.
const PRINTED: usize = 12;
const DRAWN: usize = 6;
/// How far the picture moves the vehicle along a mode: its largest
/// point's displacement, m (exaggerated to be seen).
const DRAWN_AMPLITUDE: f64 = 0.08;

/// The modes at `rest`: printed (the lowest that oscillate), written to
/// `dir/modes.csv` (every one) and drawn in `dir/modes.svg`. Returns the
/// files written and the modes that move the hull (a tenth or more of the
/// mode's kinetic energy in its bounce and pitch), as (frequency in Hz,
/// name): what the seat's spectrum is named against.
pub fn report<V: Vehicle>(
    system: &mut V::System,
    rest: &Equilibrium,
    dir: &Path,
    ground: &scene::Ground,
) -> Result<(Vec<String>, HullModes), Box<dyn Error>> {
    let started = Instant::now();
    let modes = modes(system, rest.t, &rest.state).map_err(|e| format!("the modes: {e}"))?;
    let states = system.layout().dynamic().count();
    say!(
        "modes: {} states linearised at rest in {:.0} ms; the lowest that oscillate:",
        states,
        started.elapsed().as_secs_f64() * 1e3
    );
    say!("    f (Hz)   damping   what moves (share of the kinetic energy)");
    let oscillating: Vec<&Mode> = modes.iter().filter(|m| m.oscillates()).collect();
    for mode in oscillating.iter().take(PRINTED) {
        say!(
            "  {:8.3}   {:7.3}   {}",
            mode.frequency,
            mode.damping_ratio,
            shares(mode, 3)
        );
    }
    let hull: Vec<String> = ["hull bounce", "hull pitch"]
        .iter()
        .filter_map(|motion| {
            mode_of(&modes, motion).map(|m| {
                format!(
                    "{motion} {:.3} Hz (damping {:.2}, {:.0} % of that mode)",
                    m.frequency,
                    m.damping_ratio,
                    100.0 * m.share_of(motion)
                )
            })
        })
        .collect();
    say!("  the hull: {}", hull.join("; "));
    let mut csv = csv::Writer::from_path(dir.join("modes.csv"))?;
    csv.write_record([
        "frequency_hz",
        "damped_frequency_hz",
        "damping_ratio",
        "eigenvalue_re",
        "eigenvalue_im",
        "name",
        "shares",
    ])?;
    for mode in &modes {
        csv.write_record([
            format!("{}", mode.frequency),
            format!("{}", mode.damped_frequency),
            format!("{}", mode.damping_ratio),
            format!("{}", mode.eigenvalue.re),
            format!("{}", mode.eigenvalue.im),
            mode.name.clone(),
            shares(mode, usize::MAX),
        ])?;
    }
    csv.flush()?;
    std::fs::write(
        dir.join("modes.svg"),
        picture::<V>(system, rest, &oscillating, ground)?,
    )?;
    let frames = animation_frames::<V>(system, rest, &oscillating)?;
    let title = format!("{}: the lowest modes at rest", V::NAME);
    std::fs::write(
        dir.join("modes.html"),
        animation::html(&frames, ground, &title),
    )?;
    let hull_modes = oscillating
        .iter()
        .filter(|m| m.share_of("hull bounce") + m.share_of("hull pitch") >= HULL_SHARE)
        .map(|m| (m.frequency, m.name.clone()))
        .collect();
    Ok((
        vec![
            "modes.csv".to_string(),
            "modes.svg".to_string(),
            "modes.html".to_string(),
        ],
        hull_modes,
    ))
}

/// Modes the seat feels: (frequency in Hz, name).
pub type HullModes = Vec<(f64, String)>;

/// The share of a mode's kinetic energy in the hull's bounce and pitch
/// that makes it a mode the seat feels.
const HULL_SHARE: f64 = 0.1;

/// `hull pitch 56 %, track span (links 29–41) 28 %, …`
fn shares(mode: &Mode, most: usize) -> String {
    mode.shares
        .iter()
        .take(most)
        .map(|s| format!("{} {:.0} %", s.what, 100.0 * s.fraction))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The vehicle displaced along each of the lowest modes, one panel each
/// under the next.
fn picture<V: Vehicle>(
    system: &mut V::System,
    rest: &Equilibrium,
    modes: &[&Mode],
    ground: &scene::Ground,
) -> Result<String, Box<dyn Error>> {
    let scene = Scene::of::<V>();
    let (t, y) = (rest.t, &rest.state);
    let (qt0, qc0) = system.coordinates(t, y.as_slice())?;
    let at_rest = scene.frame(t, qt0.as_slice(), qc0.as_slice());
    let mut panels = Vec::new();
    for (k, mode) in modes.iter().take(DRAWN).enumerate() {
        let scale = drawn_scale(system, &scene, (rest, &at_rest), mode)?;
        let (qt, qc) = system.coordinates(t, (y + &mode.shape * scale).as_slice())?;
        let mut frame = scene.frame(t, qt.as_slice(), qc.as_slice());
        frame.label = label(k, mode);
        panels.push(vehicle::svg(&frame, ground));
    }
    Ok(stack(&panels))
}

/// Frames for the animation page: each of the lowest modes in turn, two
/// cycles of its motion `Re(v e^{iφ})` (the mode's own phases between
/// coordinates, its decay left out), at the picture's amplitude.
fn animation_frames<V: Vehicle>(
    system: &mut V::System,
    rest: &Equilibrium,
    modes: &[&Mode],
) -> Result<Vec<scene::Frame>, Box<dyn Error>> {
    const STEPS: usize = 24;
    let scene = Scene::of::<V>();
    let (t, y) = (rest.t, &rest.state);
    let (qt0, qc0) = system.coordinates(t, y.as_slice())?;
    let at_rest = scene.frame(t, qt0.as_slice(), qc0.as_slice());
    let layout = system.layout();
    let mut frames = Vec::new();
    for (k, mode) in modes.iter().take(DRAWN).enumerate() {
        let scale = drawn_scale(system, &scene, (rest, &at_rest), mode)?;
        for step in 0..2 * STEPS {
            let phase = std::f64::consts::TAU * step as f64 / STEPS as f64;
            let turn = trackgen::nalgebra::Complex::new(phase.cos(), phase.sin());
            let mut moved = y.clone();
            for i in layout.positions() {
                moved[i] += scale * (mode.vector[i] * turn).re;
            }
            let (qt, qc) = system.coordinates(t, moved.as_slice())?;
            let mut frame = scene.frame(t, qt.as_slice(), qc.as_slice());
            frame.label = label(k, mode);
            frames.push(frame);
        }
    }
    Ok(frames)
}

/// The label of mode `k` (from 0) in the pictures.
fn label(k: usize, mode: &Mode) -> String {
    format!(
        "mode {}: {:.2} Hz, damping {:.2}: {}",
        k + 1,
        mode.frequency,
        mode.damping_ratio,
        shares(mode, 2)
    )
}

/// The scale of `mode`'s shape that moves the vehicle's farthest-moving
/// point by [`DRAWN_AMPLITUDE`] from `at_rest`.
fn drawn_scale(
    system: &mut impl VehicleDynamics,
    scene: &Scene,
    (rest, at_rest): (&Equilibrium, &scene::Frame),
    mode: &Mode,
) -> Result<f64, Box<dyn Error>> {
    let (t, y) = (rest.t, &rest.state);
    let probe = 1e-4;
    let (qt, qc) = system.coordinates(t, (y + &mode.shape * probe).as_slice())?;
    let reach = largest_move(at_rest, &scene.frame(t, qt.as_slice(), qc.as_slice())) / probe;
    Ok(if reach > 0.0 {
        DRAWN_AMPLITUDE / reach
    } else {
        0.0
    })
}

/// The largest displacement of a track joint or wheel centre between two
/// frames, m.
fn largest_move(a: &scene::Frame, b: &scene::Frame) -> f64 {
    let joints = a
        .joints
        .iter()
        .zip(&b.joints)
        .map(|(p, q)| (p.0 - q.0).hypot(p.1 - q.1));
    let wheels = a
        .wheels
        .iter()
        .zip(&b.wheels)
        .map(|(p, q)| (p.0 - q.0).hypot(p.1 - q.1));
    let hull = a
        .hull
        .iter()
        .zip(&b.hull)
        .map(|(p, q)| (p.0 - q.0).hypot(p.1 - q.1));
    joints.chain(wheels).chain(hull).fold(0.0, f64::max)
}

/// SVG documents one under the other, in one document.
fn stack(panels: &[String]) -> String {
    let size = |svg: &str, key: &str| -> f64 {
        let at = svg.find(&format!("{key}=\"")).map(|i| i + key.len() + 2);
        at.and_then(|i| svg[i..].split('"').next()?.parse().ok())
            .unwrap_or(0.0)
    };
    let width = panels.iter().map(|p| size(p, "width")).fold(0.0, f64::max);
    let mut y = 0.0;
    let mut body = String::new();
    for panel in panels {
        body += &panel.replacen("<svg ", &format!("<svg y=\"{y:.0}\" "), 1);
        y += size(panel, "height");
    }
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{y:.0}\" style=\"background:#fff\">\n{body}</svg>\n"
    )
}
