#!/usr/bin/env bash
# Builds a vehicle's FMU: tools/build-fmu.sh VEHICLE OUTDIR (VEHICLE: m113
# or marder) writes OUTDIR/<Name>.fmu (FMI 3.0 co-simulation) and
# OUTDIR/<Name>-fmi2.fmu (FMI 2.0), x86_64 Linux binaries: the vehicle's
# FMU library (trackgen-fmu/vehicles/VEHICLE) built, then packed by the
# main binary's `fmu` subcommand (as any vehicle's application packs its
# own). The guide's chapter "The vehicle as an FMU" says what they hold
# and how to drive them.
# TRACKGEN_FMU_PROFILE=dev builds with the test profile instead of release,
# and with the tests' features (`--all-targets`: their dev-dependencies
# take part in the feature resolution), so that after `cargo test` nothing
# but the vehicle's library is compiled (CI's use).
set -euo pipefail
if [ $# -ne 2 ] || { [ "$1" != m113 ] && [ "$1" != marder ]; }; then
    echo "usage: tools/build-fmu.sh m113|marder OUTDIR" >&2
    exit 2
fi
vehicle=$1
out=$2
cd "$(dirname "$0")/.."
profile=${TRACKGEN_FMU_PROFILE:-release}
targets=()
[ "$profile" = dev ] && targets=(--all-targets)
cargo build --profile "$profile" --quiet "${targets[@]}" -p "trackgen-fmu-$vehicle" -p trackgen-cli
dir=${CARGO_TARGET_DIR:-target}/$([ "$profile" = dev ] && echo debug || echo "$profile")
"$dir/trackgen" fmu --vehicle "$vehicle" --library "$dir/libtrackgen_fmu_$vehicle.so" --out "$out"
