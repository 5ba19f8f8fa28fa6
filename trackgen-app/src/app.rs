//! The application: the vehicles it offers ([`App`], [`Entry`]), its
//! command line (a subcommand each, `run` the default) and the dispatch of
//! a parsed command to the chosen vehicle's type.

use std::ffi::OsString;
use std::process::ExitCode;

use clap::builder::PossibleValuesParser;
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use trackgen::mobility::Published;
use trackgen::spatial_vehicle::SpatialVehicleSystem;
use trackgen::vehicle::{Powertrain, Vehicle};

use crate::cli::RunArgs;
use crate::fmu::FmuArgs;
use crate::mobility::MobilityArgs;
use crate::modes::ModesArgs;
use crate::offered::{Offered, SpatialEvents};
use crate::spatial::SpatialArgs;
use crate::steer::SteerArgs;

/// Drive a declared tracked vehicle over a course (`run`, the default;
/// `spatial` in 3-D), find its mobility limits (`mobility`), its modes at
/// rest (`modes`), estimate its steady turns (`steer`), or pack it as an
/// FMU (`fmu`).
#[derive(Parser, Debug)]
#[command(
    version,
    allow_negative_numbers = true,
    args_conflicts_with_subcommands = true
)]
pub(crate) struct Cli {
    /// What to do; `run` when none is given.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// `run`'s options, given without the subcommand.
    #[command(flatten)]
    pub run: RunArgs,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub(crate) enum Command {
    /// The main job: the vehicle assembled, settled, driven over a course,
    /// with its files and report (the default).
    Run(RunArgs),
    /// The mobility engineer's pitch-plane events, each a limit found over
    /// runs through the vehicle's engine, with a report.
    Mobility(MobilityArgs),
    /// The vehicle at rest on flat ground and its modes there.
    Modes(ModesArgs),
    /// Its steady turns on firm ground, estimated from its loads at rest
    /// by the general theory of skid steering.
    Steer(SteerArgs),
    /// The main job in 3-D: both tracks and the hull, settled, driven over
    /// the course, then turned (a vehicle declared with a `tracks` block).
    Spatial(SpatialArgs),
    /// Packs the vehicle's built FMU library (`export_fmu!`) into FMI 3.0
    /// and 2.0 archives.
    Fmu(FmuArgs),
}

/// The subcommands' names, each of which takes `--vehicle`.
const SUBCOMMANDS: [&str; 6] = ["run", "mobility", "modes", "steer", "spatial", "fmu"];

/// A vehicle the application offers: its type, the name `--vehicle` and
/// the output folders know it by, and what its declaration does not say.
pub struct Entry {
    offered: Offered,
    dispatch: fn(&Offered, Command) -> ExitCode,
    /// `spatial` for a vehicle declared with both tracks.
    spatial: Option<fn(&Offered, &SpatialArgs) -> ExitCode>,
}

impl Entry {
    /// The declared vehicle `V`: named by its declared name in lower case
    /// (`M113` → `m113`), driven through its declared powertrain
    /// ([`Vehicle::powertrain`]) where one is declared, with no published
    /// figures.
    pub fn of<V: Vehicle>() -> Self {
        Entry {
            offered: Offered {
                name: V::NAME.to_lowercase(),
                powertrain: V::powertrain(),
                published: Vec::new(),
                gauge: None,
                turn_runs: None,
                spatial_events: None,
                spatial_modes: None,
                spatial_fmu: None,
            },
            dispatch: dispatch::<V>,
            spatial: None,
        }
    }

    /// [`of`](Self::of) a vehicle declared with a `tracks` block: its
    /// `spatial` subcommand drives both tracks and the hull in 3-D, and
    /// `steer` turns two of its planar tracks at its declared gauge.
    pub fn of_spatial<V: SpatialVehicleSystem>() -> Self {
        let mut entry = Entry {
            spatial: Some(crate::spatial::main::<V>),
            ..Entry::of::<V>()
        };
        entry.offered.gauge = Some(V::layout().gauge);
        entry.offered.turn_runs = Some(crate::turn_runs::run_turns::<V>);
        entry.offered.spatial_modes = Some(crate::spatial_modes::modes_at_rest::<V>);
        entry.offered.spatial_fmu = Some(crate::fmu::pack::<trackgen_fmu::Spatial<V>>);
        entry.offered.spatial_events = Some(SpatialEvents {
            side_slope: |settings| {
                trackgen::mobility::side_slope::steepest::<V>(settings, V::declared_laws())
            },
            smallest_radius: |settings, ratio| {
                trackgen::mobility::turning::smallest_radius::<V>(
                    settings,
                    V::declared_laws(),
                    ratio,
                )
            },
            pivot: |settings| trackgen::mobility::turning::pivot::<V>(settings, V::declared_laws()),
            cornering: |settings, circle| {
                trackgen::mobility::cornering::fastest::<V>(settings, V::declared_laws(), circle)
            },
        });
        entry
    }

    /// The name `--vehicle` takes and the output folders use.
    pub fn named(mut self, name: &str) -> Self {
        self.offered.name = name.to_string();
        self
    }

    /// The powertrain `run --engine` and the mobility events drive through,
    /// in place of the declared one.
    pub fn powertrain(mut self, powertrain: Powertrain) -> Self {
        self.offered.powertrain = Some(powertrain);
        self
    }

    /// The real vehicle's gauge, m (its tracks' centre lines apart), which
    /// `steer` turns two of its planar tracks at: for a vehicle declared
    /// without a `tracks` block (one declared with one has its gauge).
    pub fn gauge(mut self, gauge: f64) -> Self {
        self.offered.gauge = Some(gauge);
        self
    }

    /// The real vehicle's published figures, which the mobility report
    /// prints beside its answers.
    pub fn published(mut self, figures: &[Published]) -> Self {
        self.offered.published = figures.to_vec();
        self
    }
}

/// Runs `command` for the vehicle type `V`.
fn dispatch<V: Vehicle>(entry: &Offered, command: Command) -> ExitCode {
    match command {
        Command::Run(args) => crate::run::main::<V>(entry, &args),
        Command::Mobility(args) => crate::mobility::main::<V>(entry, &args),
        Command::Modes(args) => crate::modes::main::<V>(entry, &args),
        Command::Steer(args) => crate::steer::main::<V>(entry, &args),
        Command::Spatial(_) => {
            eprintln!(
                "error: the vehicle `{}` is offered in the plane only: declare it with a \
                 `tracks` block and offer it with `Entry::of_spatial`",
                entry.name()
            );
            ExitCode::FAILURE
        }
        Command::Fmu(args) => crate::fmu::main::<V>(entry, &args),
    }
}

/// The application over the vehicles it offers.
#[derive(Default)]
pub struct App {
    vehicles: Vec<Entry>,
}

impl App {
    /// An application offering no vehicle yet.
    pub fn new() -> Self {
        App::default()
    }

    /// Offers `entry` as well; the first offered is the default.
    pub fn vehicle(mut self, entry: Entry) -> Self {
        self.vehicles.push(entry);
        self
    }

    /// The command line with `--vehicle` taking the offered names, the
    /// first the default.
    pub(crate) fn command(&self) -> clap::Command {
        let names: Vec<String> = self
            .vehicles
            .iter()
            .map(|e| e.offered.name.clone())
            .collect();
        let vehicle = |arg: clap::Arg| {
            let arg = arg.value_parser(PossibleValuesParser::new(names.clone()));
            match names.first() {
                Some(first) => arg.default_value(first.clone()),
                None => arg,
            }
        };
        let mut command = Cli::command().mut_arg("vehicle", vehicle);
        for sub in SUBCOMMANDS {
            command = command.mut_subcommand(sub, |c| c.mut_arg("vehicle", vehicle));
        }
        command
    }

    /// Parses the process's arguments and runs the command: exits 2 on a
    /// bad command line (clap's message), 1 when the command fails.
    pub fn main(self) -> ExitCode {
        self.main_from(std::env::args_os())
    }

    /// [`main`](Self::main) on the arguments given (the first is the
    /// program's name).
    pub fn main_from<I, T>(self, args: I) -> ExitCode
    where
        I: IntoIterator<Item = T>,
        T: Into<OsString> + Clone,
    {
        if self.vehicles.is_empty() {
            eprintln!("error: the application offers no vehicle (`App::vehicle`)");
            return ExitCode::FAILURE;
        }
        let matches = match self.command().try_get_matches_from(args) {
            Ok(m) => m,
            Err(e) => {
                let _ = e.print();
                return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
            }
        };
        let cli = match Cli::from_arg_matches(&matches) {
            Ok(cli) => cli,
            Err(e) => {
                let _ = e.print();
                return ExitCode::from(2);
            }
        };
        let command = cli.command.unwrap_or(Command::Run(cli.run));
        let name = match &command {
            Command::Run(a) => a.vehicle.clone(),
            Command::Mobility(a) => a.vehicle.clone(),
            Command::Modes(a) => a.vehicle.clone(),
            Command::Steer(a) => a.vehicle.clone(),
            Command::Spatial(a) => a.vehicle.clone(),
            Command::Fmu(a) => a.vehicle.clone(),
        };
        // The parser took only offered names; without a name, the first.
        let entry = name
            .and_then(|n| self.vehicles.iter().find(|e| e.offered.name == n))
            .unwrap_or(&self.vehicles[0]);
        match (&command, entry.spatial) {
            (Command::Spatial(args), Some(spatial)) => spatial(&entry.offered, args),
            _ => (entry.dispatch)(&entry.offered, command),
        }
    }
}

/// The application for the one vehicle `V` ([`Entry::of`]): every
/// subcommand, option, output and report, for a user's own binary.
pub fn main<V: Vehicle>() -> ExitCode {
    App::new().vehicle(Entry::of::<V>()).main()
}

#[cfg(test)]
mod tests {
    use trackgen::vehicles::m113::M113;
    use trackgen::vehicles::marder::Marder;

    use super::{App, Entry};

    /// The guide's table of a subcommand's options (`book/src/commands.md`,
    /// the section headed with the subcommand's name): (option, values,
    /// default).
    fn guide_table(subcommand: &str) -> Vec<(String, String, String)> {
        let page = include_str!("../../book/src/commands.md");
        let heading = format!("## `{subcommand}`");
        let start = page
            .find(&heading)
            .unwrap_or_else(|| panic!("the guide has no section {heading}"));
        page[start..]
            .lines()
            .skip_while(|l| !l.starts_with("| option"))
            .skip(2)
            .take_while(|l| l.starts_with('|'))
            .map(|line| {
                let cells: Vec<&str> = line
                    .split(" | ")
                    .map(|c| c.trim_matches(['|', ' ']))
                    .collect();
                let option = cells[0].trim_matches('`').to_string();
                (option, cells[1].to_string(), cells[2].to_string())
            })
            .collect()
    }

    /// Every option of every subcommand is in the guide's table of that
    /// subcommand, every row of a table is an option, and where the option
    /// has a default the table's default starts with it (as `--help`
    /// prints it); `--vehicle`'s default is the application's first
    /// vehicle, which the guide calls "the first". Checked on the
    /// project's binary's application (the M113 and the Marder).
    #[test]
    fn the_guide_lists_every_option_with_its_default() {
        let app = App::new()
            .vehicle(Entry::of::<M113>())
            .vehicle(Entry::of::<Marder>());
        let command = app.command();
        let subcommands: Vec<&str> = command
            .get_subcommands()
            .map(|c| c.get_name())
            .filter(|n| *n != "help")
            .collect();
        assert_eq!(
            subcommands,
            ["run", "mobility", "modes", "steer", "spatial", "fmu"]
        );
        for sub in subcommands {
            let table = guide_table(sub);
            let options: Vec<_> = command
                .find_subcommand(sub)
                .expect("listed")
                .get_arguments()
                .filter_map(|a| a.get_long().map(|long| (format!("--{long}"), a)))
                .filter(|(long, _)| long != "--help" && long != "--version")
                .collect();
            for (long, arg) in &options {
                let row = table.iter().find(|(option, _, _)| option == long);
                let Some((_, _, default)) = row else {
                    panic!("`{sub} {long}` is not in the guide's table of options");
                };
                if let Some(value) = arg.get_default_values().first() {
                    let value = value.to_string_lossy();
                    let shown = default.trim_matches('`');
                    let first = long == "--vehicle" && value == "m113" && shown == "the first";
                    assert!(
                        first || shown.starts_with(value.as_ref()),
                        "`{sub} {long}`: the guide's default `{default}`, --help's `{value}`"
                    );
                }
            }
            for (option, _, _) in &table {
                assert!(
                    options.iter().any(|(long, _)| long == option),
                    "the guide's table of `{sub}` lists `{option}`, which it does not take"
                );
            }
        }
    }
}
