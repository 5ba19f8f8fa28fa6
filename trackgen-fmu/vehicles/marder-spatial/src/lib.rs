//! The Marder's spatial FMU library: the FMI 3.0 and 2.0 functions for
//! [`trackgen::vehicles::marder::Marder`] in 3-D, both tracks and the hull
//! (`trackgen_fmu::Spatial`). `tools/build-fmu.sh marder OUTDIR` builds
//! and packs it beside the planar one, as `MarderSpatial.fmu`.

trackgen_fmu::export_spatial_fmu!(trackgen::vehicles::marder::Marder);
