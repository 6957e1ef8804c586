"""The pours the general learner asks for where the exploration left it
without evidence: for the ordinary pour (the empty question) and for each
proposition asked alone, enough pours sampled for it (everything else the
ordinary pour) that the model of the pours sees what that proposition does.

An exploration goes where behaviour changes, so most propositions it
never asks about; the pours it made hold such a proposition only when a
parameter drawn from the priors happens to fall in its range, and for an
extreme value (a heavy liquid, a full source, pouring far away) none does.
The model of the pours would then extrapolate, and answer the question
"a heavy liquid" with what it learned of medium ones. So before learning,
the empty question and each proposition asked alone get pours of their
own, up to `per_body` pours that could have been drawn for them (the
explored ones counted), drawn with a
seed of their own (the same on every machine). Curiosity's pours and
random exploration's get the same treatment, so the comparison of the two
stays one of what the exploration found.
"""
from __future__ import annotations

import zlib
from typing import Sequence

import numpy as np

from pantarhei.oracle.generative import InvalidAntecedent, in_support, sample
from pantarhei.theory.lexicon import load_vocabulary


def _seed(seed: int, body: Sequence[str]) -> int:
    return int(np.random.SeedSequence([int(seed), zlib.crc32(("gap " + " ".join(body)).encode())])
               .generate_state(1)[0])


def thin_bodies(P: np.ndarray, per_body: int) -> list[tuple[tuple[str, ...], int]]:
    """The empty body and each proposition alone, with how many more pours
    each needs to reach `per_body`: pours that could have been drawn for
    it (in the support of P(.|B): the body as asked, the rest an ordinary
    pour)."""
    P = np.atleast_2d(np.asarray(P, dtype=float))
    out: list[tuple[tuple[str, ...], int]] = []
    for body in [()] + [(n,) for n in sorted(load_vocabulary().propositions)]:
        have = int(in_support(P, body).sum()) if len(P) else 0
        if have < per_body:
            out.append((body, per_body - have))
    return out


def gap_pours(P: np.ndarray, per_body: int, seed: int) -> np.ndarray:
    """The parameterizations to simulate so that every thin body has
    `per_body` pours (rows of 30 numbers; none when none is thin)."""
    rows = []
    for body, missing in thin_bodies(P, per_body):
        try:
            rows.append(sample(list(body), missing, _seed(seed, body)))
        except InvalidAntecedent:
            continue
    return np.vstack(rows) if rows else np.empty((0, len(load_vocabulary().parameters)))
