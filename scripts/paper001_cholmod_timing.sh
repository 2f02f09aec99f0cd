#!/bin/bash
# The CHOLMOD (auto) vs UMFPACK cost of one linear solve with domain.obq_symmetric:
# paper 000's uniaxial block, Silling, law space, delta = 3.5 h, n particles per side.
# usage: scripts/paper001_cholmod_timing.sh build/bin/pd N ; prints linear_solve seconds of auto (CHOLMOD) and umfpack, 3 alternated runs
PD=$1; N=$2
PD=$(realpath "$PD")
cd "$(dirname "$0")/../studies/constant_strain_obq"
for rep in 1 2 3; do for lin in automatic umfpack; do
  l=$lin; [ $lin = automatic ] && l=auto
  sed -e "s/count: .*/count: $N/" -e "s|directory: .*|directory: ${TMPDIR:-/tmp}/pd_cholmod_timing_t$N$l}|" -e "s/^horizon: .*/horizon: {ratio: 3.5}\nsolver: {linear: $l}/" uniaxial_cut_law_sym.yaml > ${TMPDIR:-/tmp}/pd_cholmod_timing_t$N$l.yaml
  OMP_NUM_THREADS=1 $PD run ${TMPDIR:-/tmp}/pd_cholmod_timing_t$N$l.yaml > /dev/null 2>&1
  python3 -c "import json;d=json.load(open('${TMPDIR:-/tmp}/pd_cholmod_timing_t$N$l/summary.json'));print('$N', d['linear_solver']['method'], 'linear_solve', round(d['seconds']['linear_solve'],3), 'total', round(sum(d['seconds'].values()),3), 'probe', d['probes'][0]['error'] if 'probes' in d else '')"
done; done
