#!/usr/bin/env bash
# Submits a night's validation to Slurm: an array of workers that share the archive's work
# queue, and one summary job that runs once every worker has ended, however it ended
# (--dependency=afterany): a task cancelled, preempted or failed must not keep the summary from
# running. The summary lists what the workers left (a case a stopped worker held, a case nobody
# claimed, a failed case) and exits 1 when anything is left; finish it by running this script
# again (the workers take up only what is not done) or `maxillo nightly --claim`, then
# `maxillo nightly --summary-only --out OUT_FOLDER`.
#
#   MAXILLO_ARCHIVE='postgresql://maxillo@db:5432/maxillo?objects=/shared/maxillo-objects' \
#     scripts/cluster/nightly-slurm.sh /shared/nightly/$(date +%F) 8
#
# Arguments: the shared output folder, the number of workers (default 4). Extra sbatch options
# (partition, account, time limit, memory) go in SBATCH_* environment variables, which sbatch
# reads itself. Prints the two job ids. Every node needs the maxillo program, the database
# reachable and the object folder mounted at the same path.
set -euo pipefail
out=${1:?usage: nightly-slurm.sh OUT_FOLDER [WORKERS]}
workers=${2:-4}
: "${MAXILLO_ARCHIVE:?set MAXILLO_ARCHIVE to the archive address}"
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out/slurm"
export MAXILLO_OUT=$out
array=$(sbatch --parsable --job-name=maxillo-nightly --array="1-$workers" --export=ALL \
  --output="$out/slurm/worker-%a.out" "$here/nightly-worker.sh")
summary=$(sbatch --parsable --job-name=maxillo-summary --dependency="afterany:$array" --export=ALL \
  --output="$out/slurm/summary.out" \
  --wrap="\"${MAXILLO_BIN:-maxillo}\" nightly --summary-only --out \"$out\"")
echo "workers: $array  summary: $summary"
