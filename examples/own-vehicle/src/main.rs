//! The Mule's application: `mule run`, `mule mobility`, `mule modes`,
//! `mule fmu`, with every option the project's own binary has.

fn main() -> std::process::ExitCode {
    trackgen_app::main::<mule::Mule>()
}
