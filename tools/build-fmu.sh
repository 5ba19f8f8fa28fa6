#!/usr/bin/env bash
# Builds a vehicle's FMU: tools/build-fmu.sh VEHICLE OUTDIR (VEHICLE: m113
# or marder) writes OUTDIR/<Name>.fmu (FMI 3.0 co-simulation) and
# OUTDIR/<Name>-fmi2.fmu (FMI 2.0), x86_64 Linux binaries: the vehicle's
# FMU library (trackgen-fmu/vehicles/VEHICLE) built, then packed by the
# main binary's `fmu` subcommand (as any vehicle's application packs its
# own). Where the vehicle has a spatial FMU library too
# (trackgen-fmu/vehicles/VEHICLE-spatial: both tracks and the hull in 3-D),
# it is built and packed beside it as OUTDIR/<Name>Spatial.fmu and
# OUTDIR/<Name>Spatial-fmi2.fmu. The guide's chapter "The vehicle as an FMU" says what they hold
# and how to drive them.
# TRACKGEN_FMU_PROFILE=dev builds with the test profile instead of release,
# and with the features `cargo test --workspace` resolves (every member's
# dev-dependencies take part), so that after it only the vehicles'
# libraries and the benches' dependencies are compiled (CI's use).
set -euo pipefail
if [ $# -ne 2 ] || { [ "$1" != m113 ] && [ "$1" != marder ]; }; then
    echo "usage: tools/build-fmu.sh m113|marder OUTDIR" >&2
    exit 2
fi
vehicle=$1
out=$2
cd "$(dirname "$0")/.."
profile=${TRACKGEN_FMU_PROFILE:-release}
spatial=()
[ -d "trackgen-fmu/vehicles/$vehicle-spatial" ] && spatial=(-p "trackgen-fmu-$vehicle-spatial")
if [ "$profile" = dev ]; then
  cargo build --profile dev --quiet --workspace --lib --bins --tests --examples
else
  cargo build --profile "$profile" --quiet -p "trackgen-fmu-$vehicle" "${spatial[@]}" -p trackgen-cli
fi
dir=${CARGO_TARGET_DIR:-target}/$([ "$profile" = dev ] && echo debug || echo "$profile")
"$dir/trackgen" fmu --vehicle "$vehicle" --library "$dir/libtrackgen_fmu_$vehicle.so" --out "$out"
if [ ${#spatial[@]} -gt 0 ]; then
  "$dir/trackgen" fmu --spatial --vehicle "$vehicle" \
    --library "$dir/libtrackgen_fmu_${vehicle}_spatial.so" --out "$out"
fi
