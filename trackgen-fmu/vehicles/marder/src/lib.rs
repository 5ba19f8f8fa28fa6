//! The Marder's FMU library: the FMI 3.0 and 2.0 functions for
//! [`trackgen::vehicles::marder::Marder`]. `tools/build-fmu.sh marder OUTDIR` builds
//! and packs it.

trackgen_fmu::export_fmu!(trackgen::vehicles::marder::Marder);
