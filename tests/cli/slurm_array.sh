#!/usr/bin/env bash
# tools/slurm/render-array.sbatch, run as Slurm would run a job array of four tasks (its
# environment variables set by hand; no Slurm needed), renders parts that tools/merge puts
# together into the single run's image: rows byte for byte, sample ranges within 1e-6.
#   slurm_array.sh CHAPTER_EXE MERGE_PARTS ARGS...
set -euo pipefail
exe=$1
export RT_MERGE_PARTS=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
tools=$here/../../tools
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

"$exe" --quiet "$@" --out full.png --out full.pfm --variance-out full-variance.pfm
for split in rows samples; do
    for task in 10 11 12 13; do  # an array --array=10-13: tasks are counted from its first
        SLURM_ARRAY_TASK_ID=$task SLURM_ARRAY_TASK_MIN=10 SLURM_ARRAY_TASK_COUNT=4 \
            SLURM_CPUS_PER_TASK=1 SPLIT=$split CHAPTER=$(basename "$exe") ARGS="$*" \
            RT_BIN=$(dirname "$exe") PARTS_DIR=$split bash "$tools/slurm/render-array.sbatch" \
            2>>log.txt || { cat log.txt; echo "FAIL: task $task ($split)"; exit 1; }
    done
    [ "$(ls $split/*.json | wc -l)" -eq 4 ] || { echo "FAIL: not four $split parts"; exit 1; }
done
"$tools/merge" --out rows.png --out rows.pfm rows/*.json
cmp full.png rows.png && cmp full.pfm rows.pfm ||
    { echo "FAIL: the rows merged differ from the single run"; exit 1; }
echo "ok: four row bands merged equal one run byte for byte"
"$tools/merge" --out samples.pfm --variance-out samples-variance.pfm samples/*.json
python3 "$here/compare_pfm.py" full.pfm samples.pfm 1e-6
python3 "$here/compare_pfm.py" full-variance.pfm samples-variance.pfm 1e-6
echo "ok: four sample ranges merged equal one run within 1e-6"
