//! The M113's spatial FMU library: the FMI 3.0 and 2.0 functions for
//! [`trackgen::vehicles::m113::M113`] in 3-D, both tracks and the hull
//! (`trackgen_fmu::Spatial`). `tools/build-fmu.sh m113 OUTDIR` builds and
//! packs it beside the planar one, as `M113Spatial.fmu`.

trackgen_fmu::export_spatial_fmu!(trackgen::vehicles::m113::M113);
