#!/usr/bin/env bash
# One nightly worker: a Slurm array task (nightly-slurm.sh) or a Kubernetes Indexed Job pod
# (nightly-job.yaml) runs this. It claims cases from the archive's work queue until every case is
# finished (`maxillo nightly --claim`). A worker that dies (a signal, the OOM killer) is started
# again, up to three times: it resumes the queue, and a case it held is claimed again once its
# lease ends. Exit 0 once the queue is done; the summary step runs after every worker however
# it ended (afterany), and lists what is left.
#
#   MAXILLO_ARCHIVE   the archive (postgresql://USER@HOST/DB?objects=/shared/folder)
#   MAXILLO_OUT       shared output folder (case-<id>/ folders; the summary goes there too)
#   MAXILLO_LEASE     seconds before a dead worker's case is taken over (default 600)
#   MAXILLO_BIN       the maxillo program (default: maxillo on PATH)
set -uo pipefail
: "${MAXILLO_ARCHIVE:?set MAXILLO_ARCHIVE}" "${MAXILLO_OUT:?set MAXILLO_OUT}"
maxillo=${MAXILLO_BIN:-maxillo}
task=${SLURM_ARRAY_TASK_ID:-${JOB_COMPLETION_INDEX:-0}}
mkdir -p "$MAXILLO_OUT/workers"
for attempt in 1 2 3; do
  "$maxillo" nightly --claim --lease "${MAXILLO_LEASE:-600}" --out "$MAXILLO_OUT" &
  worker=$!
  # Which process is this task's worker, for an operator (or a test) to look at.
  echo "$worker" > "$MAXILLO_OUT/workers/task-$task.pid"
  wait "$worker"
  status=$?
  [ "$status" -eq 0 ] && exit 0
  # 1: some cases failed (they are recorded as failed and not retried): the queue is done.
  [ "$status" -eq 1 ] && exit 0
  echo "nightly worker (task $task, attempt $attempt) ended with status $status; starting it again" >&2
done
exit 1
