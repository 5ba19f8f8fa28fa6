//! The `fmu` subcommand: a vehicle's built FMU library packed into its
//! FMI 3.0 and 2.0 archives.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use trackgen::vehicle::Vehicle;
use trackgen_fmu::{Version, write_fmu};

use crate::offered::Offered;

/// Pack the vehicle's FMU library into `<Name>.fmu` (FMI 3.0) and
/// `<Name>-fmi2.fmu` (FMI 2.0), co-simulation, x86_64 Linux.
///
/// The library is the `cdylib` of a crate whose `lib.rs` calls
/// `trackgen_fmu::export_fmu!(Vehicle)` for this same vehicle (`cargo
/// build --release` writes it as `target/release/lib<crate>.so`).
#[derive(clap::Args, Debug)]
pub struct FmuArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// The built FMU library (`lib<crate>.so`).
    #[arg(long, value_name = "FILE.so")]
    pub library: PathBuf,
    /// Output folder (created if missing); default `out/fmu`.
    #[arg(long, value_name = "DIR", value_parser = crate::cli::folder)]
    pub out: Option<PathBuf>,
}

/// The FMI function every library `export_fmu!` builds exports, looked
/// for in the library's bytes (its dynamic symbol table names it).
const EXPORTED: &[u8] = b"fmi3InstantiateCoSimulation";

/// `fmu` for the vehicle `V`: exits 1, saying why, when the library is
/// missing or exports no FMI functions, or an archive cannot be written.
pub fn main<V: Vehicle>(_entry: &Offered, args: &FmuArgs) -> ExitCode {
    let out = args.out.clone().unwrap_or_else(|| PathBuf::from("out/fmu"));
    match pack::<V>(&args.library, &out) {
        Ok(paths) => {
            for p in paths {
                println!("wrote {}", p.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Both archives, after checking that `library` is an FMU library.
fn pack<V: Vehicle>(library: &Path, out: &Path) -> Result<Vec<PathBuf>, String> {
    let bytes = std::fs::read(library).map_err(|e| format!("{}: {e}", library.display()))?;
    if !bytes.windows(EXPORTED.len()).any(|w| w == EXPORTED) {
        return Err(format!(
            "{} exports no FMI functions: build the `cdylib` of a crate whose lib.rs calls \
             `trackgen_fmu::export_fmu!({})`",
            library.display(),
            V::NAME
        ));
    }
    [Version::Fmi3, Version::Fmi2]
        .into_iter()
        .map(|version| write_fmu::<V>(library, out, version).map_err(|e| e.to_string()))
        .collect()
}
