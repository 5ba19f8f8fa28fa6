//! The `.fmu` archive: the model description and the shared library under
//! `binaries/<platform>/`.

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

use zip::write::SimpleFileOptions;

use crate::description;
use crate::error::FmuError;
use crate::plant::Plant;

/// Which standard an archive declares.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Version {
    /// FMI 3.0: `binaries/x86_64-linux/`.
    Fmi3,
    /// FMI 2.0: `binaries/linux64/`.
    Fmi2,
}

/// A failed packaging: the file and the cause.
#[derive(Debug, thiserror::Error)]
pub enum PackageError {
    /// The vehicle's variables could not be listed.
    #[error(transparent)]
    Vehicle(#[from] FmuError),
    /// A file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The archive could not be written.
    #[error("{path}: {source}")]
    Zip {
        /// The archive.
        path: PathBuf,
        /// Why.
        source: zip::result::ZipError,
    },
}

/// Writes `out_dir/<Name>.fmu` (FMI 3.0) or `out_dir/<Name>-fmi2.fmu`
/// (FMI 2.0) for the model `P` (a vehicle `V`, or
/// [`Spatial<V>`](crate::Spatial)), with `library` (the `cdylib` that
/// [`export_fmu!`](crate::export_fmu)`(V)` or
/// [`export_spatial_fmu!`](crate::export_spatial_fmu)`(V)` built) as its
/// binary; returns the archive's path (`<Name>` the model's
/// [`identifier`](crate::description::identifier)).
pub fn write_fmu<P: Plant>(
    library: &Path,
    out_dir: &Path,
    version: Version,
) -> Result<PathBuf, PackageError> {
    let table = P::table()?;
    let id = description::identifier::<P>();
    let (xml, platform, file) = match version {
        Version::Fmi3 => (
            description::fmi3::<P>(&table),
            "x86_64-linux",
            format!("{id}.fmu"),
        ),
        Version::Fmi2 => (
            description::fmi2::<P>(&table),
            "linux64",
            format!("{id}-fmi2.fmu"),
        ),
    };
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| PackageError::Io { path, source }
    };
    let binary = std::fs::read(library).map_err(io(library))?;
    std::fs::create_dir_all(out_dir).map_err(io(out_dir))?;
    let path = out_dir.join(file);
    let zipped = |source| PackageError::Zip {
        path: path.clone(),
        source,
    };
    let mut zip = zip::ZipWriter::new(File::create(&path).map_err(io(&path))?);
    let options = SimpleFileOptions::default();
    zip.start_file("modelDescription.xml", options)
        .map_err(zipped)?;
    zip.write_all(xml.as_bytes()).map_err(io(&path))?;
    zip.start_file(format!("binaries/{platform}/{id}.so"), options)
        .map_err(zipped)?;
    zip.write_all(&binary).map_err(io(&path))?;
    zip.finish().map_err(zipped)?;
    Ok(path)
}
