//! Packs a built FMU library: `trackgen-fmu VEHICLE LIBRARY OUTDIR` writes
//! `OUTDIR/<Name>.fmu` (FMI 3.0) and `OUTDIR/<Name>-fmi2.fmu` (FMI 2.0).
//! `tools/build-fmu.sh` builds the library and calls this.

use std::path::Path;
use std::process::ExitCode;

use trackgen::vehicle::Vehicle;
use trackgen::vehicles::{m113::M113, marder::Marder};
use trackgen_fmu::{PackageError, Version, write_fmu};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [vehicle, library, out] = args.as_slice() else {
        eprintln!("usage: trackgen-fmu m113|marder LIBRARY.so OUTDIR");
        return ExitCode::from(2);
    };
    let written = match vehicle.as_str() {
        "m113" => pack::<M113>(library.as_ref(), out.as_ref()),
        "marder" => pack::<Marder>(library.as_ref(), out.as_ref()),
        other => {
            eprintln!("error: `{other}` is no vehicle here; m113 or marder");
            return ExitCode::from(2);
        }
    };
    match written {
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

fn pack<V: Vehicle>(library: &Path, out: &Path) -> Result<Vec<std::path::PathBuf>, PackageError> {
    Ok(vec![
        write_fmu::<V>(library, out, Version::Fmi3)?,
        write_fmu::<V>(library, out, Version::Fmi2)?,
    ])
}
