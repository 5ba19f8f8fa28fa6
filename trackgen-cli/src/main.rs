//! The main job and the project's command line: the application
//! (`trackgen_app`) over the two vehicles the project declares, the M113
//! (the default) and the Marder (`--vehicle marder`).
//!
//! `cargo run --release -p trackgen-cli -- --help`; the subcommands `run`
//! (the default), `mobility`, `modes`, `steer` and `fmu`.

use std::process::ExitCode;

use trackgen::vehicles::m113::{self, M113};
use trackgen::vehicles::marder::{self, Marder};
use trackgen_app::{App, Entry};

fn main() -> ExitCode {
    App::new()
        .vehicle(Entry::of_spatial::<M113>().published(&m113::PUBLISHED))
        .vehicle(Entry::of_spatial::<Marder>().published(&marder::PUBLISHED))
        .main()
}
