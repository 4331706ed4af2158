#!/usr/bin/env bash
# softchain runs on OpenBLAS's best kernel for this CPU (use_the_cpus_blas_kernel):
#  - a user's OPENBLAS_CORETYPE stands: OpenBLAS is loaded once, with that kernel;
#  - without it, on a CPU with AVX2 and FMA the kernel in use is not the SSE3
#    fallback Prescott, and the program restarted itself at most once.
# OPENBLAS_VERBOSE=2 makes OpenBLAS print "Core: NAME" each time it is loaded.
# Exit 77 (skipped) where the BLAS is not a runtime-dispatching OpenBLAS.
# usage: blas_kernel.sh SOFTCHAIN
set -euo pipefail
softchain=$1
kernels() { OPENBLAS_VERBOSE=2 "$@" 2>&1 >/dev/null | sed -n 's/^Core: //p'; }

chosen=$(OPENBLAS_CORETYPE=Haswell kernels "$softchain" help)
if [ -z "$chosen" ]; then
  echo "skipped: the BLAS does not report its kernel (not OpenBLAS with runtime dispatch)"
  exit 77
fi
if [ "$chosen" != Haswell ]; then
  echo "FAIL: with OPENBLAS_CORETYPE=Haswell the kernels loaded were: $chosen"
  exit 1
fi

unset OPENBLAS_CORETYPE
loaded=$(kernels "$softchain" help)
echo "kernels loaded: $(echo $loaded)"
if [ "$(echo "$loaded" | wc -l)" -gt 2 ]; then
  echo "FAIL: OpenBLAS was loaded more than twice (one restart at most)"
  exit 1
fi
if grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo &&
   [ "$(echo "$loaded" | tail -1)" = Prescott ]; then
  echo "FAIL: a CPU with AVX2 and FMA runs OpenBLAS's SSE3 kernel Prescott"
  exit 1
fi
