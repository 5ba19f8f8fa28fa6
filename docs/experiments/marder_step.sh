#!/usr/bin/env bash
# Reproduces docs/experiments/marder-implicit-step.md: the Marder's main
# job with ROS34PW2 at 1e-2 (8 s), one thing changed at a time in a
# throw-away worktree of the commit the experiment was made at (6261a53:
# its edits name that tree's files); prints each variant's steps and
# energy balance. About a minute per variant after the first build.
#
#   docs/experiments/marder_step.sh [VARIANT...]
#
# Variants: declared smooth smooth-regularised weigh-0.5 weigh-0.25
# weigh-0.085 safety-0.8 safety-0.7 beta-0.08 tolerance-2e-2
# tolerance-5e-2 age-2 age-3 (default: all).
set -euo pipefail
root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
work=$(mktemp -d)
trap 'git -C "$root" worktree remove --force "$work/tree" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
git -C "$root" worktree add -q --detach "$work/tree" 6261a53
export CARGO_TARGET_DIR="$root/target/marder-step"

marder=src/vehicles/marder.rs
control=trackgen-runtime/src/integrate/control.rs
stepper=trackgen-runtime/src/integrate/rosenbrock_w.rs

# Each variant: edits to the worktree (sed scripts on files) and the main
# job's extra arguments.
edit() {
  case $1 in
    declared | tolerance-*) ;;
    smooth | smooth-regularised)
      # Hunt-Crossley exponent 1.5: stiffness k/sqrt(δ) keeps the force at
      # δ = 5 mm (ground) and 3 mm (rims, teeth).
      sed -i 's/ground { stiffness: 2e6, chi: 2.0, mu: 0.8 }/ground { stiffness: 2.83e7, exponent: 1.5, chi: 2.0, mu: 0.8 }/;
              s/wheels { stiffness: 1e7, chi: 0.5/wheels { stiffness: 1.83e8, exponent: 1.5, chi: 0.5/;
              s/sprocket { stiffness: 1e7, chi: 0.5/sprocket { stiffness: 1.83e8, exponent: 1.5, chi: 0.5/' $marder
      if [ "$1" = smooth-regularised ]; then
        sed -i 's/exponent: 1.5, chi: 2.0, mu: 0.8 }/exponent: 1.5, chi: 2.0, mu: 0.8, slip: 0.05 }/' $marder
      fi ;;
    weigh-*)
      # The links' angles and rates (the Marder's partitioned state: 2..77
      # and 79..154) weighed by the factor in the error norm.
      python3 - "$stepper" "${1#weigh-}" <<'PY'
import sys
p, w = sys.argv[1], sys.argv[2]
s = open(p).read()
anchor = "        Ok(weighted_rms(\n            &self.error,"
assert anchor in s
s = s.replace(anchor, "        for i in (2..77).chain(79..154) { self.error[i] *= %s; }\n" % w + anchor, 1)
open(p, "w").write(s)
PY
      ;;
    safety-*) sed -i "s/^const SAFETY: f64 = 0.9;/const SAFETY: f64 = ${1#safety-};/" $control ;;
    beta-*) sed -i "s/^const BETA: f64 = 0.04;/const BETA: f64 = ${1#beta-};/" $control ;;
    age-*) sed -i "s/let max_age = if self.own { 1 }/let max_age = if self.own { ${1#age-} }/" $stepper ;;
    *) echo "unknown variant $1" >&2; exit 2 ;;
  esac
}

variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=(declared smooth smooth-regularised weigh-0.5 weigh-0.25
  weigh-0.085 safety-0.8 safety-0.7 beta-0.08 tolerance-2e-2 tolerance-5e-2 age-2 age-3)
for v in "${variants[@]}"; do
  git -C "$work/tree" checkout -q -- .
  (cd "$work/tree" && edit "$v")
  if [ "$v" != declared ] && [ "${v%%-*}" != tolerance ] && git -C "$work/tree" diff --quiet; then
    echo "$v: the edit did not apply" >&2; exit 1
  fi
  tolerance=1e-2
  [ "${v%%-*}" = tolerance ] && tolerance=${v#tolerance-}
  (cd "$work/tree" && cargo build --quiet --release --example m113)
  echo "== $v"
  "$CARGO_TARGET_DIR/release/examples/m113" --vehicle marder --integrator ros34pw2 \
    --tolerance "$tolerance" --out "$work/out" 2>&1 | grep -E '^steps|^energy balance'
done
