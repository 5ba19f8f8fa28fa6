//! The Mule's application: `mule run`, `mule mobility`, `mule modes`,
//! `mule steer`, `mule spatial` (both tracks in 3-D: its `tracks` block),
//! `mule fmu`, with every option the project's own binary has.

use trackgen_app::{App, Entry};

fn main() -> std::process::ExitCode {
    App::new().vehicle(Entry::of_spatial::<mule::Mule>()).main()
}
