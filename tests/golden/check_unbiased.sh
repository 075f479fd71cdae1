#!/usr/bin/env bash
# A new estimator must converge to the same image as the plain path tracer: renders an
# earlier chapter's scene with chapter 16's program, the given integrator and sampler, and asks
# noise_compare whether it agrees with that chapter's converged reference (a many-sample `path`
# render, reference_images/NAME.converged.pfm) within the two renders' own noise.
#   check_unbiased.sh EXE SCENE INTEGRATOR SAMPLER REF_NAME REF_DIR NOISE_COMPARE WIDTH SPP SEED
#                     CONVERGED_SPP [OPTION...]
# OPTIONs go to the program as they are (chapter 17's --quad-lights solid-angle).
# The per-pixel variance of a Sobol' render is the spread of its samples, which overstates the
# error of their mean (the points are spread evenly, not at random): the check is conservative
# there, and a wrong density or a missing MIS weight still shows as a bias many sigmas wide.
set -euo pipefail
exe=$1 scene=$2 integrator=$3 sampler=$4 name=$5 refs=$6 noise_compare=$7
width=$8 spp=$9 seed=${10} converged_spp=${11}
shift 11

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" --scene "$scene" --integrator "$integrator" --sampler "$sampler" --width "$width" \
    --spp "$spp" --seed "$seed" --quiet --out "$tmp/render.pfm" --variance-out "$tmp/variance.pfm" \
    "$@"
if ! "$noise_compare" "$tmp/render.pfm" "$tmp/variance.pfm" "$spp" \
    "$refs/$name.converged.pfm" "$refs/$name.converged-variance.pfm" "$converged_spp"; then
    echo "FAIL: --scene $scene --integrator $integrator --sampler $sampler $* does not converge" \
        "to $name's reference"
    exit 1
fi
