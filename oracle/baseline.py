"""The baseline math: a pour computes the same numbers on every x86-64 machine.

Three libraries choose their floating-point routines by the CPU's features
when a process starts, and their variants round differently in the last
bit, which a chaotic pour grows into other scores:

* the C library's math (sin, cos, atan2, acos, exp, ...; called by the
  physics engine and by Python's `math`): variants for FMA with AVX2, for
  FMA4 and for AVX. GLIBC_TUNABLES hides these features from it, so that
  it runs its SSE2 baseline routines.
* OpenBLAS (numpy's dot and matrix products): one kernel per CPU family.
  OPENBLAS_CORETYPE picks Prescott's, the oldest x86-64 kernel.
* numpy's own dispatched loops (exp, log, arccos, ...): NPY_DISABLE_CPU_FEATURES
  turns off every dispatch target above the build's baseline (x86-64-v2).

All three are read once, when the process starts, so a process that
simulates must be started with `ENVIRONMENT` (the executors do it; see
`Oracle.environment`). The same C library and Python packages are assumed
(Debian 12's glibc 2.36, requirements.lock): other versions of them may
compute other last bits.
"""
from __future__ import annotations

import os
import sys
from types import MappingProxyType
from typing import Mapping

#: What a simulating process is started with.
ENVIRONMENT: Mapping[str, str] = MappingProxyType({
    "GLIBC_TUNABLES": "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4,-AVX512F",
    "OPENBLAS_CORETYPE": "Prescott",
    "NPY_DISABLE_CPU_FEATURES": "X86_V3 X86_V4 AVX512_ICL AVX512_SPR",
})


def initial_environment() -> dict[str, str]:
    """The environment this process was started with (what the C library
    and the other libraries read), whatever os.environ says now."""
    try:
        with open("/proc/self/environ", "rb") as f:
            raw = f.read()
    except OSError:
        return dict(os.environ)
    env = {}
    for item in raw.split(b"\0"):
        k, sep, v = item.partition(b"=")
        if sep:
            env[os.fsdecode(k)] = os.fsdecode(v)
    return env


def unmet(env: Mapping[str, str]) -> list[str]:
    """The variables of `env` this process was not started with."""
    initial = initial_environment()
    return [k for k, v in env.items() if initial.get(k) != v]


def started_with(env: Mapping[str, str]) -> bool:
    return not unmet(env)


def require(env: Mapping[str, str]) -> None:
    """RuntimeError unless this process was started with `env`."""
    missing = unmet(env)
    if missing:
        raise RuntimeError("this process was not started with the baseline math "
                           f"({', '.join(f'{k}={env[k]}' for k in missing)})")


def child_environment(env: Mapping[str, str]) -> dict[str, str]:
    """The environment of a process to start with `env`."""
    return {**os.environ, **env}


def restart_with(env: Mapping[str, str]) -> None:
    """Replace this process by the same command started with `env`, unless
    it was started so (then return)."""
    if started_with(env):
        return
    sys.stdout.flush()
    sys.stderr.flush()
    os.execve(sys.executable, sys.orig_argv, child_environment(env))
