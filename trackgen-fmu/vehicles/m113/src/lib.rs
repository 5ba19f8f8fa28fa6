//! The M113's FMU library: the FMI 3.0 and 2.0 functions for
//! [`trackgen::vehicles::m113::M113`], with its engine. `tools/build-fmu.sh m113 OUTDIR` builds
//! and packs it.

trackgen_fmu::export_fmu!(
    trackgen::vehicles::m113::M113,
    powertrain = trackgen::vehicles::m113::powertrain
);
