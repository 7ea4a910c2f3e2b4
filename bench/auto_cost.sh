#!/bin/bash
# The cost of a run by its instructions inside simulate() (callgrind; deterministic, unlike wall
# time on a shared machine): the measurements behind `auto`'s choice between DOP853 and Taylor
# (kAutoTaylorRtol in core/integrators/stepper.h). Every non-stiff preset under the three explicit
# methods at rtol 1e-3 … 1e-12 (atol rtol/100, the check off), one line a run:
#   preset method rtol instructions steps rhs_evals events
#
#   bench/auto_cost.sh [VIBRO]      (default build/vibro; about half an hour)
set -euo pipefail
vibro=$(realpath "${1:-build/vibro}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# instructions steps rhs_evals events of one run
measure() {
  local preset=$1 method=$2 rtol=$3
  local atol
  atol=$(python3 -c "print($rtol / 100)")
  valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    --toggle-collect='vibro::simulate(vibro::Model const&, vibro::SimOptions const&)' \
    "$vibro" simulate --preset "$preset" --method "$method" \
    --rtol "$rtol" --atol "$atol" --no-check >run.json 2>callgrind.txt
  echo "$(grep -o 'Collected : [0-9]*' callgrind.txt | awk '{print $3}')" \
    "$(python3 -c "import json; s = json.load(open('run.json')); \
print(s['stats']['steps'], s['stats']['rhs_evals'], len(s['events']))")"
}

for preset in paper chatter frictionless-elastic grazing high-frequency impact-oscillator \
  loop mass-ratio plastic-limiter rest-in-cone tiny-radius; do
  for method in dopri5 dop853 taylor; do
    for rtol in 1e-3 1e-4 1e-5 1e-6 1e-7 1e-8 1e-9 1e-10 1e-11 1e-12; do
      echo "$preset $method $rtol $(measure "$preset" $method $rtol)"
    done
  done
done
