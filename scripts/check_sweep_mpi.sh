#!/usr/bin/env bash
# Checks that tumble sweep's sweep.csv is the same bytes on 1 and 2 threads and on 1 and 2 MPI
# processes (mpirun on this machine). ctest runs it where the build has MPI.
#   scripts/check_sweep_mpi.sh TUMBLE_EXE MPIEXEC
set -euo pipefail
exe=${1:?usage: scripts/check_sweep_mpi.sh TUMBLE_EXE MPIEXEC}
mpiexec=${2:?usage: scripts/check_sweep_mpi.sh TUMBLE_EXE MPIEXEC}
root="$(cd "$(dirname "$0")/.." && pwd)"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Open MPI refuses to start as root unless told, and in a container its shared-memory transport
# may not map another process's memory: neither matters for a check on one machine.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1

sweep=(sweep "$root/examples/backspin_disk.yaml" --vary v0=1:4:5 --vary w0=20:80:3
       --record "roll=first(floor.rolls)" --record "v_end=final(disk.vx)")
"$exe" "${sweep[@]}" --threads 1 --out "$out/threads1" >/dev/null
"$exe" "${sweep[@]}" --threads 2 --out "$out/threads2" >/dev/null
"$mpiexec" -np 1 "$exe" "${sweep[@]}" --threads 1 --out "$out/np1" >/dev/null
"$mpiexec" -np 2 "$exe" "${sweep[@]}" --threads 1 --out "$out/np2" >"$out/np2.txt"
grep -q "1 thread x 2 processes" "$out/np2.txt" || {
  echo "mpirun -np 2 did not run two processes:"; cat "$out/np2.txt"; exit 1; }
status=0
for run in threads2 np1 np2; do
  if ! cmp -s "$out/threads1/sweep.csv" "$out/$run/sweep.csv"; then
    echo "sweep.csv differs between --threads 1 and $run:"
    diff "$out/threads1/sweep.csv" "$out/$run/sweep.csv" | head -20
    status=1
  fi
done
[ $status -eq 0 ] && echo "sweep.csv is the same bytes on 1 and 2 threads and 1 and 2 processes ($(($(wc -l <"$out/threads1/sweep.csv") - 1)) runs)"
exit $status
