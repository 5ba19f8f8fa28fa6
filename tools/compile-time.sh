#!/usr/bin/env bash
# Measures how long a crate that declares one N-link track takes to build,
# debug and release, once its dependencies are built (the cost a user pays
# on every edit of the declaring crate; incremental compilation off, so the
# whole crate is rebuilt). Usage: tools/compile-time.sh [N...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work="$root/target/compile-time"
sizes=("${@:-64 128}")
for n in ${sizes[@]}; do
  dir="$work/track$n"
  mkdir -p "$dir/src"
  cat > "$dir/Cargo.toml" <<TOML
[package]
name = "track$n"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
trackgen = { path = "$root" }

[workspace]
TOML
  cat > "$dir/src/main.rs" <<RS
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::{RecursiveModel, TrackModel};

trackgen::model! {
    /// The track under test.
    pub track Track {
        links: $n,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
        closure: partitioned,
    }
}

// Uses every generated function, so none is left out of the build.
fn main() {
    let q = SVector::<f64, { $n + 2 }>::from_fn(|i, _| i as f64 * 0.1);
    let qd = SVector::<f64, { $n + 2 }>::from_fn(|i, _| 1.0 - i as f64 * 0.01);
    let a = trackgen::dynamics::forward_dynamics(&Track, &q, &qd, &[]).unwrap();
    let mut r = vec![Vector2::zeros(); $n];
    Track.body_positions(&q, &mut r);
    Track.body_velocities(&q, &qd, &mut r);
    Track.velocity_terms(&q, &qd, &mut r);
    let e = Track.kinetic_energy(&q, &qd) + Track.potential_energy(&q) + Track.closure(&q).norm();
    println!("{} {} {} {}", a.qdd.norm(), r[3], e, Track.description().len());
}
RS
  for profile in dev release; do
    (cd "$dir" && cargo build -q --profile $profile --target-dir "$work/target" 2>/dev/null) # dependencies
    touch "$dir/src/main.rs"
    start=$(date +%s.%N)
    (cd "$dir" && CARGO_INCREMENTAL=0 cargo build -q --profile $profile --target-dir "$work/target")
    end=$(date +%s.%N)
    printf '%4d links  %-7s  %6.1f s\n' "$n" "$profile" "$(awk "BEGIN { print $end - $start }")"
  done
done
