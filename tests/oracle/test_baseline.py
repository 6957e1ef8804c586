"""oracle/baseline.py: the same pours give bit-identical scores whatever the
CPU features the libraries see: every simulating process is started with
the baseline math, and a process knows what it was started with."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from pantarhei.oracle import baseline

#: CPU features hidden from the C library, OpenBLAS and numpy: none, then
#: the wide vector units (what an older x86-64 machine lacks).
MASKS = {
    "none hidden": {},
    "AVX2, FMA and AVX hidden": {
        "GLIBC_TUNABLES": "glibc.cpu.hwcaps=-AVX2,-FMA,-AVX512F,-AVX",
        "OPENBLAS_CORETYPE": "Sandybridge",
        "NPY_DISABLE_CPU_FEATURES": "X86_V3 X86_V4 AVX512_ICL AVX512_SPR"},
}
#: Pours whose scores change under the second mask without the baseline math.
POURS = ("--antecedent", "pour_mid_height,pour_near_rim,pour_steeply_tilted", "-n", "4",
         "--seed", "1")


def simulate(mask: dict[str, str], *args: str) -> list[dict]:
    env = {k: v for k, v in os.environ.items() if k not in baseline.ENVIRONMENT}
    p = subprocess.run([sys.executable, "-m", "pantarhei.bridge", "simulate", *POURS, "--json",
                        "--no-store", "--no-progress", *args], capture_output=True, text=True,
                       env={**env, **mask}, timeout=600, stdin=subprocess.DEVNULL)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


@pytest.mark.slow
@pytest.mark.parametrize("executor", [("--executor", "inline"),
                                      ("--executor", "local", "--workers", "1")],
                         ids=["inline", "local"])
def test_two_cpu_feature_masks_give_bit_identical_scores(executor):
    runs = [simulate(mask, *executor) for mask in MASKS.values()]
    assert [r["params"] for r in runs[0]] == [r["params"] for r in runs[1]]
    assert [r["scores"] for r in runs[0]] == [r["scores"] for r in runs[1]]
    assert [r["record"] for r in runs[0]] == [r["record"] for r in runs[1]]


def test_a_process_knows_what_it_was_started_with():
    """What counts is the environment at start-up (what the libraries read),
    not os.environ changed later."""
    code = ("import os, sys; from pantarhei.oracle import baseline as b; "
            "os.environ.update(b.ENVIRONMENT); print(b.started_with(b.ENVIRONMENT)); "
            "b.require(b.ENVIRONMENT)")
    env = {k: v for k, v in os.environ.items() if k not in baseline.ENVIRONMENT}
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert p.stdout.strip() == "False"
    assert "not started with the baseline math" in p.stderr
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env={**env, **baseline.ENVIRONMENT})
    assert p.returncode == 0 and p.stdout.strip() == "True", p.stderr
