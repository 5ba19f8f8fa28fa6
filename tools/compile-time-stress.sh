#!/usr/bin/env bash
# Build-time measurements of declarations that stress the macro (issue 12),
# each in its own scratch crate under target/compile-time-stress/, once its
# dependencies are built (incremental compilation off, so the whole crate is
# rebuilt). Prints the wall-clock time of `cargo build` and its CPU time
# (user + system, rustc included), which other jobs on the machine disturb
# much less.
#
#   bad N       N links, each overridden with a mass and an inertia that do
#               not compile (`np.float64(…)`, pasted from Python): a failing
#               debug build. Prints the time and the number of errors, which
#               must be 2 N (each bad expression reported once).
#   hetero N    N links, every link different (mass, inertia, u1, u2 as
#               literals), closed by partitioning: a release build.
#   hetero-const N
#               the same with every number a constant expression
#               (`SHOE_MASS * 1.001`), so every value is a named constant:
#               a release build.
#   large N     N links (up to 1024), a release build of a program that runs
#               the dense `forward_dynamics` on a 2 MiB thread and compares
#               it with `LinearTimeSolver`; prints the build time, runs it,
#               then finds the least stack each route needs (a binary search
#               over runs on smaller and smaller threads: an overflow aborts
#               the process).
#   large-dev N the same, debug build: the declaring crate at opt-level 0
#               (the dev default; its generated code is what needs the
#               stack), its dependencies at opt-level 2 so the O(n³) dense
#               runs stay short.
#
# Usage: tools/compile-time-stress.sh [bad N | hetero N | hetero-const N | large N | large-dev N]...
# Default: bad 128 hetero 128 hetero-const 128.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work="$root/target/compile-time-stress"
args=("$@")
if [ ${#args[@]} -eq 0 ]; then
  args=(bad 128 hetero 128 hetero-const 128)
fi

# The declaration's link overrides, one per link.
overrides() {
  local kind=$1 n=$2 i
  for ((i = 1; i <= n; i++)); do
    case $kind in
      bad)
        echo "        link[$i] { mass: np.float64(18.$i), inertia: np.float64(0.0$i) },"
        ;;
      hetero)
        echo "        link[$i] { mass: 18.$i, inertia: 0.04$i, u1: (-0.077$i, 0.000$i), u2: (0.077$i, -0.000$i) },"
        ;;
      large | large-dev)
        if ((i % 3 == 1)); then
          echo "        link[$i] { mass: 20.5, inertia: 0.05 },"
        elif ((i % 5 == 2)); then
          echo "        link[$i] { u1: (-0.08, 0.004), u2: (0.075, -0.002) },"
        fi
        ;;
      hetero-const)
        echo "        link[$i] { mass: SHOE_MASS * (1.0 + $i.0 * 1e-3), inertia: SHOE_INERTIA + $i.0 * 1e-5, u1: (-PITCH / 2.0 - $i.0 * 1e-6, 0.0), u2: (PITCH / 2.0 + $i.0 * 1e-6, $i.0 * 1e-7) },"
        ;;
    esac
  done
}

crate_dir() {
  local kind=$1 n=$2
  local dir="$work/$kind$n"
  mkdir -p "$dir/src"
  cat > "$dir/Cargo.toml" <<TOML
[package]
name = "stress-$kind$n"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
trackgen = { path = "$root" }

[workspace]

[profile.dev.package."*"]
opt-level = $([ "$kind" = large-dev ] && echo 2 || echo 0)
TOML
  echo "$dir"
}

main_rs() {
  local kind=$1 n=$2
  cat <<RS
#![allow(dead_code)]
use trackgen::nalgebra::{SVector, Vector2};
use trackgen::{RecursiveModel, TrackModel};

const SHOE_MASS: f64 = 18.02;
const SHOE_INERTIA: f64 = 0.04;
const PITCH: f64 = 0.154;

trackgen::model! {
    /// The track under test.
    pub track Track {
        links: $n,
        link { mass: 18.02, inertia: 0.04, u1: (-0.077, 0.0), u2: (0.077, 0.0) },
$(overrides "$kind" "$n")
        closure: partitioned,
    }
}
RS
  if [ "$kind" = large ] || [ "$kind" = large-dev ]; then
    cat <<RS

type Q = SVector<f64, { $n + 2 }>;

fn state() -> (Q, Q) {
    (Q::from_fn(|i, _| 0.3 * (i as f64).sin()), Q::from_fn(|i, _| 0.5 * (i as f64).cos()))
}

/// Runs one route on a thread with the given stack; an overflow aborts.
fn route(name: &str) -> Q {
    let (q, qd) = state();
    let dynamic = |v: &Q| trackgen::nalgebra::DVector::from_column_slice(v.as_slice());
    match name {
        "forward_dynamics" => trackgen::dynamics::forward_dynamics(&Track, &q, &qd, &[]).unwrap().qdd,
        "open_dynamics" => trackgen::dynamics::open_dynamics(&Track, &q, &qd, &[]).unwrap().qdd,
        "linear_time" => trackgen::dynamics::LinearTimeSolver::new(&Track)
            .forward_dynamics(&Track, &q, &qd, &[]).unwrap().qdd,
        "reference" => {
            let r = trackgen::reference::ReferenceModel::new(Track.description())
                .forward_dynamics(&dynamic(&q), &dynamic(&qd), &[]).unwrap();
            Q::from_column_slice(r.qdd.as_slice())
        }
        "body_states" => {
            let (mut r, mut v) = (vec![Vector2::zeros(); $n], vec![Vector2::zeros(); $n]);
            Track.body_states(&q, &qd, &mut r, &mut v);
            Q::from_fn(|i, _| if i < $n { r[i].x + v[i].y } else { 0.0 })
        }
        other => panic!("unknown route {other}"),
    }
}

fn on_thread(stack: usize, name: &'static str) -> Q {
    std::thread::Builder::new().stack_size(stack).spawn(move || route(name))
        .unwrap().join().expect("the worker thread finished")
}

// \`main ROUTE BYTES\` runs a route on a thread with that stack; \`main\`
// alone compares the dense and linear-time routes on a 2 MiB thread.
fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let [_, name, bytes] = &args[..] {
        let name: &'static str = Box::leak(name.clone().into_boxed_str());
        std::hint::black_box(on_thread(bytes.parse().unwrap(), name));
        return;
    }
    let start = std::time::Instant::now();
    let dense = on_thread(2 << 20, "forward_dynamics");
    let dense_time = start.elapsed();
    let start = std::time::Instant::now();
    let linear = on_thread(2 << 20, "linear_time");
    let linear_time = start.elapsed();
    let difference = (dense - linear).amax() / linear.amax();
    println!(
        "  on a 2 MiB thread: dense forward_dynamics {dense_time:.2?}, linear-time {linear_time:.2?} \\
         (solver built and run), relative difference {difference:.1e}"
    );
    assert!(difference < 1e-6, "the routes disagree");
}
RS
  else
    cat <<RS

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
  fi
}

set -- "${args[@]}"
while [ $# -ge 2 ]; do
  kind=$1 n=$2
  shift 2
  dir=$(crate_dir "$kind" "$n")
  case $kind in
    bad) profile=dev ;;
    hetero | hetero-const | large) profile=release ;;
    large-dev) profile=dev ;;
    *) echo "unknown case $kind" >&2; exit 2 ;;
  esac
  # Dependencies first, from a declaration that compiles.
  main_rs hetero 3 > "$dir/src/main.rs"
  (cd "$dir" && cargo build -q --profile $profile --target-dir "$work/target" 2>/dev/null) || true
  main_rs "$kind" "$n" > "$dir/src/main.rs"
  log="$dir/build.log"
  status=0
  /usr/bin/time -f '%e %U %S' -o "$dir/time" \
    bash -c 'cd "$1" && CARGO_INCREMENTAL=0 cargo build -q --profile "$2" --target-dir "$3"' \
    _ "$dir" "$profile" "$work/target" > "$log" 2>&1 || status=$?
  read -r wall user system < <(tail -n 1 "$dir/time")
  errors=$(grep -c '^error\[\|^error:' "$log" || true)
  summary=$(grep -c '^error: could not compile' "$log" || true)
  errors=$((errors - summary))
  printf '%-13s %5d links  %-7s  %7.1f s wall  %7.1f s CPU  exit %d  %d errors\n' \
    "$kind" "$n" "$profile" "$wall" "$(awk "BEGIN { print $user + $system }")" "$status" "$errors"
  if [ "$kind" = bad ]; then
    expected=$((2 * n))
    if [ "$errors" -ne "$expected" ]; then
      echo "  expected $expected errors (each bad expression once); see $log" >&2
    fi
  elif [ "$status" -ne 0 ]; then
    echo "  the build failed; see $log" >&2
  elif [ "$kind" = large ] || [ "$kind" = large-dev ]; then
    dir_name=$([ "$profile" = dev ] && echo debug || echo release)
    binary="$work/target/$dir_name/stress-$kind$n"
    "$binary"
    for r in forward_dynamics open_dynamics linear_time reference body_states; do
      # The least stack (to 4 KiB) the route runs on.
      lo=4096 hi=$((64 << 20))
      while ((hi - lo > 4096)); do
        mid=$(((lo + hi) / 2))
        # In a subshell, so the shell's report of the abort goes quiet too.
        if ("$binary" "$r" "$mid"; exit $?) > /dev/null 2>&1; then hi=$mid; else lo=$mid; fi
      done
      printf '  %-17s needs %6d KiB of stack\n' "$r" $((hi / 1024))
    done
  fi
done
