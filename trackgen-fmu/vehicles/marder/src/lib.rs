//! The Marder's FMU library: the FMI 3.0 and 2.0 functions for
//! [`trackgen::vehicles::marder::Marder`], with its engine. `tools/build-fmu.sh marder OUTDIR` builds
//! and packs it.

trackgen_fmu::export_fmu!(
    trackgen::vehicles::marder::Marder,
    powertrain = trackgen::vehicles::marder::powertrain
);
