#!/usr/bin/env bash
# One chapter's golden-image test (run by CTest; settings in reference_images/goldens.txt).
#   check_golden.sh CHAPTER_EXE NAME REF_DIR NOISE_COMPARE WIDTH SPP SEED CONVERGED_SPP [PRECISION]
# 1. renders the chapter at the golden settings (PNG, PFM and the per-pixel variance);
# 2. idiff against reference_images/NAME.png and NAME.pfm: a regression check, same settings and
#    seed, so on the blessing machine the images are identical; the thresholds only absorb
#    last-bit differences of another libm or CPU (see reference_images/README.md);
# 3. noise_compare against NAME.converged.pfm: the render must agree with a many-sample render
#    within its own noise, so the golden itself is right, not just unchanged.
# PRECISION float (the float build) skips step 2: the goldens are double renders, and a float
# render rounds differently, so its paths and its noise differ from the first bounce on. It is
# judged by step 3 alone, against the same converged (double) reference.
# RT_GOLDEN_NOISE_ONLY=1 in the environment skips step 2 too: tools/bug-zoo judges a mistake the
# way a student's correct code is judged, whose random numbers need not be drawn in our order.
# RT_GOLDEN_KEEP=DIR (tools/exercise check) keeps the render there, beside a difference map
# against the converged reference (|render - reference|, four times brighter), and says where.
set -euo pipefail
exe=$1 name=$2 refs=$3 noise_compare=$4 width=$5 spp=$6 seed=$7 converged_spp=$8
precision=${9:-double}

# Thresholds, in linear units for the PFM and display units (0..1) for the PNG.
IDIFF_ARGS=(-fail 0.02 -failpercent 0.5 -hardfail 0.5 -warn 0.004 -warnpercent 0.5)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" --width "$width" --spp "$spp" --seed "$seed" --quiet \
    --out "$tmp/$name.png" --out "$tmp/$name.pfm" --variance-out "$tmp/$name.variance.pfm"

status=0
exts=(png pfm)
[ "$precision" = float ] && exts=()
[ "${RT_GOLDEN_NOISE_ONLY:-0}" = 1 ] && exts=()
for ext in "${exts[@]}"; do
    # idiff exits 0 for a match, 1 for a warning (still a pass), 2+ for a failure.
    set +e
    idiff "${IDIFF_ARGS[@]}" "$refs/$name.$ext" "$tmp/$name.$ext"
    rc=$?
    set -e
    if [ "$rc" -gt 1 ]; then
        echo "FAIL: $name.$ext differs from its golden (idiff exit $rc)"
        status=1
    fi
done
if [ -n "${RT_GOLDEN_KEEP:-}" ]; then
    mkdir -p "$RT_GOLDEN_KEEP"
    cp "$tmp/$name.png" "$RT_GOLDEN_KEEP/$name.png"
    oiiotool "$tmp/$name.pfm" "$refs/$name.converged.pfm" --absdiff --mulc 4 \
        -o "$RT_GOLDEN_KEEP/$name.difference.png"
    echo "render: $RT_GOLDEN_KEEP/$name.png"
    echo "difference map: $RT_GOLDEN_KEEP/$name.difference.png (|render - converged| x 4)"
fi
if ! "$noise_compare" "$tmp/$name.pfm" "$tmp/$name.variance.pfm" "$spp" \
    "$refs/$name.converged.pfm" "$refs/$name.converged-variance.pfm" "$converged_spp"; then
    echo "FAIL: $name does not match its converged reference within its noise"
    status=1
fi
exit $status
