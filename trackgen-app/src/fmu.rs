//! The `fmu` subcommand: a vehicle's built FMU library packed into its
//! FMI 3.0 and 2.0 archives, the planar model's or (`--spatial`) the 3-D
//! one's.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use trackgen::vehicle::Vehicle;
use trackgen_fmu::{Plant, Version, write_fmu};

use crate::offered::Offered;

/// Pack the vehicle's FMU library into `<Name>.fmu` (FMI 3.0) and
/// `<Name>-fmi2.fmu` (FMI 2.0), co-simulation, x86_64 Linux.
///
/// The library is the `cdylib` of a crate whose `lib.rs` calls
/// `trackgen_fmu::export_fmu!(Vehicle)` for this same vehicle (`cargo
/// build --release` writes it as `target/release/lib<crate>.so`), or,
/// with `--spatial`, `trackgen_fmu::export_spatial_fmu!(Vehicle)`: its
/// archives are `<Name>Spatial.fmu` and `<Name>Spatial-fmi2.fmu`.
#[derive(clap::Args, Debug)]
pub struct FmuArgs {
    /// The vehicle (the application's first by default).
    #[arg(long, value_name = "NAME")]
    pub vehicle: Option<String>,
    /// The built FMU library (`lib<crate>.so`).
    #[arg(long, value_name = "FILE.so")]
    pub library: PathBuf,
    /// The 3-D model (both tracks and the hull; a vehicle declared with a
    /// `tracks` block): the library calls `export_spatial_fmu!`.
    #[arg(long)]
    pub spatial: bool,
    /// Output folder (created if missing); default `out/fmu`.
    #[arg(long, value_name = "DIR", value_parser = crate::cli::folder)]
    pub out: Option<PathBuf>,
}

/// The FMI function every library `export_fmu!` builds exports, looked
/// for in the library's bytes (its dynamic symbol table names it).
const EXPORTED: &[u8] = b"fmi3InstantiateCoSimulation";

/// `fmu` for the vehicle `V`: exits 1, saying why, when the library is
/// missing or exports no FMI functions, or an archive cannot be written.
pub fn main<V: Vehicle>(entry: &Offered, args: &FmuArgs) -> ExitCode {
    let out = args.out.clone().unwrap_or_else(|| PathBuf::from("out/fmu"));
    let packed = match (args.spatial, entry.spatial_fmu) {
        (false, _) => pack::<V>(&args.library, &out),
        (true, Some(pack_spatial)) => pack_spatial(&args.library, &out),
        (true, None) => Err(format!(
            "{} has no 3-D model: declare it with a `tracks` block and offer it with \
             `Entry::of_spatial`",
            V::NAME
        )),
    };
    match packed {
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

/// Both archives of the model `P`, after checking that `library` is an
/// FMU library.
pub(crate) fn pack<P: Plant>(library: &Path, out: &Path) -> Result<Vec<PathBuf>, String> {
    let bytes = std::fs::read(library).map_err(|e| format!("{}: {e}", library.display()))?;
    if !bytes.windows(EXPORTED.len()).any(|w| w == EXPORTED) {
        return Err(format!(
            "{} exports no FMI functions: build the `cdylib` of a crate whose lib.rs calls \
             `trackgen_fmu::export_fmu!` (or, for {}, `export_spatial_fmu!`) for the vehicle",
            library.display(),
            P::name()
        ));
    }
    [Version::Fmi3, Version::Fmi2]
        .into_iter()
        .map(|version| write_fmu::<P>(library, out, version).map_err(|e| e.to_string()))
        .collect()
}
