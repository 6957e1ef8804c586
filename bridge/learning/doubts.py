"""Where the general learner doubts its rules' answers, after the
contrasts (generalize.py) are chosen, one expectation at a time. The rules
added here are not bound by `rules_per_expectation`: the cap keeps the
theory readable, not wrong where its pours say otherwise, nor sure where
they say nothing.

- `doubts`: two sure rules that conclude opposite heads and can apply
  together, neither body holding the other, say nothing of a scene of
  both: the rank that orders them is no evidence. The union of their
  bodies gets the model's likelihood where `doubt_support` pours or more
  lie in its support and the model's verdict is not the higher ranked
  part's, and a likelihood held within the uncertain band (`maybe`) where
  fewer do.
- `exceptions`: a body whose own pours contradict a sure answer (at least
  `doubt_confidence`) gets a rule with its own likelihood, in another
  band, where it has `doubt_support` pours or more in its support, or
  fewer whose count would be less likely than `unlikely` under the answer
  (two pours of two that keep the bowl empty, against a `yes` of 94%).
- `neighbours`: where an explored pair of one group of parameters (one
  pose, the liquid, a bowl, the motion: `askable.suspect`) interacts (its
  likelihood lies in another band than each of its parts'), the pairs one
  rank along either proposition's scale (pouring high beside pouring very
  high, over the centre) interact as likely. One with fewer than
  `doubt_support` pours of its own that the rules answer sure gets
  `maybe`.
- `few_pours`: a pair of one group without a rule of its own, whose few
  pours (at least one, fewer than `doubt_support`) each depart from a
  sure answer of the rules, gets `maybe`: the pours are too few to tell,
  and every one there is speaks against the answer.
"""
from __future__ import annotations

# Settings (generalize.py) and Meaning (meaning.py) are named in the
# annotations only: generalize imports this module.

from dataclasses import replace
from itertools import combinations
from typing import Sequence

import numpy as np
from scipy.stats import binom

from pantarhei.oracle.generative import in_support
from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.learning.askable import askable_bodies, suspect, together
from pantarhei.bridge.learning.general_rules import GeneralRule, deciding
from pantarhei.bridge.learning.meaning import held_in_support, pooled


def doubts(rules: list[GeneralRule], k: int, meaning: Meaning, P: np.ndarray,
           s: Settings) -> list[GeneralRule]:
    """The rules for the unions of sure, conflicting rules' bodies (at most
    `max_body` propositions), the most conflicting pair first: where fewer
    than `doubt_support` pours lie in a union's support, a rule whose
    likelihood is the model's (expectation k) held within the uncertain
    band (the pours do not tell); where more do, a rule with the model's
    likelihood when the part that ranks higher answers otherwise."""
    if not s.doubt_support:
        return []
    have = {tuple(sorted(r.body)) for r in rules}
    pairs = []
    for r, q in combinations(rules, 2):
        a, b = set(r.body), set(q.body)
        union = tuple(sorted(a | b))
        if (r.holds == q.holds or not a or not b or a <= b or b <= a
                or len(union) > s.max_body or union in have or not together(r.body, q.body)
                or min(r.confidence, q.confidence) < s.doubt_confidence):
            continue
        pairs.append((-abs(r.likelihood - q.likelihood), union, max(r, q, key=lambda x: x.rank)))
    todo: dict[tuple[str, ...], GeneralRule] = {}     # each union once, with its first pair's top
    for _, union, top in sorted(pairs, key=lambda x: (x[0], x[1])):
        todo.setdefault(union, top)
    if not todo:
        return []
    out: list[GeneralRule] = []
    for (union, top), m in zip(todo.items(), meaning(list(todo))[:, k]):
        if not np.isfinite(m):
            continue
        if int(in_support(P, union).sum()) < s.doubt_support:
            p, why = _maybe(m, s), "unsettled"
        elif s.verdict(m) != s.verdict(top.likelihood):
            p, why = float(m), "parts_disagree"
        else:
            continue
        out.append(added(union, p, rules, out, why))
    return out


def exceptions(rules: list[GeneralRule], bodies: Sequence[tuple[str, ...]], target: np.ndarray,
               held: np.ndarray, n: np.ndarray, s: Settings) -> list[GeneralRule]:
    """The rules for bodies whose own pours contradict a sure answer: a
    body that the rules so far answer at least `doubt_confidence` sure, in
    another band (holds, uncertain, fails) than its own likelihood
    (`target`, its pours counted), with at least `doubt_support` pours in
    its support (`n`, per body) or fewer whose count that holds (`held`)
    is less likely than `unlikely` under the answer, gets a rule with its
    likelihood. Smaller bodies first (a proposition's rule may answer its
    pairs); each rule decides the bodies that hold it before the next is
    weighed."""
    if not s.doubt_support:
        return []
    out: list[GeneralRule] = []
    for i in sorted(range(len(bodies)), key=lambda i: (len(bodies[i]), bodies[i])):
        b, t = bodies[i], float(target[i])
        answer = _sure(rules + out, b, s) if b else None
        if answer is None or s.verdict(answer.likelihood) == s.verdict(t):
            continue
        if n[i] >= s.doubt_support or (n[i] and _unlikely(int(held[i]), int(n[i]), answer.likelihood)
                                       < s.unlikely):
            out.append(added(b, t, rules, out, "pours_contradict"))
    return out


def neighbours(rules: list[GeneralRule], bodies: Sequence[tuple[str, ...]], target: np.ndarray,
               n: np.ndarray, k: int, meaning: Meaning, P: np.ndarray,
               s: Settings) -> list[GeneralRule]:
    """`maybe` for the pairs one rank along a proposition's scale from an
    explored pair of one group (`suspect`; `bodies`, with their
    likelihoods `target` and the pours in their support `n`) with at least
    `doubt_support` pours of its own whose band is neither of its parts':
    each such pair that is no explored body, has fewer than
    `doubt_support` pours in its support, and is answered at least
    `doubt_confidence` sure by the rules, gets a rule whose likelihood is
    the model's (expectation k) held within the uncertain band."""
    if not s.doubt_support:
        return []
    props = load_vocabulary().propositions
    own = {b: float(t) for b, t in zip(bodies, target)}
    near: dict[tuple[str, ...], tuple[str, ...]] = {}     # pair -> the explored pair beside it
    for b, n_b in zip(bodies, n):
        if (not suspect(b) or any((x,) not in own for x in b)
                or any(s.verdict(own[b]) == s.verdict(own[(x,)]) for x in b)
                or n_b < s.doubt_support):
            continue
        for keep, move in (b, b[::-1]):
            m = props[move]
            for q in props.values():
                pair = tuple(sorted((keep, q.name)))
                if (q.dimension == m.dimension and abs(q.rank - m.rank) == 1
                        and pair not in own and together((keep,), (q.name,))):
                    near.setdefault(pair, b)
    todo = [p for p in sorted(near) if int(in_support(P, p).sum()) < s.doubt_support]
    out: list[GeneralRule] = []
    for pair, m in zip(todo, meaning(todo)[:, k] if todo else []):
        if not np.isfinite(m) or _sure(rules + out, pair, s) is None:
            continue
        out.append(replace(added(pair, _maybe(m, s), rules, out, "beside_interaction"),
                           beside=near[pair]))
    return out


def few_pours(rules: list[GeneralRule], pairs: Sequence[tuple[str, ...]], held: np.ndarray,
               n: np.ndarray, k: int, meaning: Meaning, s: Settings) -> list[GeneralRule]:
    """`maybe` for the pairs `thinly_poured` gives (`pairs`, with the
    pours in their support `n`, of which `held` keep expectation k): one
    each of whose pours departs from an answer of the rules at least
    `doubt_confidence` sure gets a rule whose likelihood is its pours
    counted beside the model's (`model_pours`), held within the
    uncertain band."""
    todo = []
    for pair, h, c in zip(pairs, held, n):
        answer = _sure(rules, pair, s)
        if answer is not None and h == (0 if answer.holds else c):
            todo.append((pair, int(h), int(c)))
    out: list[GeneralRule] = []
    for (pair, h, c), m in zip(todo, meaning([t[0] for t in todo])[:, k] if todo else []):
        if np.isfinite(m) and _sure(rules + out, pair, s) is not None:
            out.append(added(pair, _maybe(pooled(h, c, m, s.model_pours), s), rules, out, "few_pours_depart"))
    return out


def thinly_poured(P: np.ndarray, Y: np.ndarray,
                  s: Settings) -> tuple[list[tuple[str, ...]], np.ndarray, np.ndarray]:
    """The askable pairs of one group (`suspect`), explored or not, that
    hold at least one of the pours P (verdicts Y) but fewer than
    `doubt_support` in their support: the pairs, how many of their pours
    keep each expectation, and how many there are."""
    pairs, held, n = [], [], []
    if s.max_body >= 2 and s.doubt_support:
        for b in askable_bodies(2):
            if len(b) == 2 and suspect(b):
                h, c = held_in_support(P, Y, b)
                if 0 < c < s.doubt_support:
                    pairs.append(b), held.append(h), n.append(c)
    return pairs, np.array(held, dtype=int).reshape(-1, Y.shape[1]), np.array(n, dtype=int)


def _sure(rules: list[GeneralRule], body: tuple[str, ...], s: Settings) -> GeneralRule | None:
    """The rule that decides `body`, where it is at least `doubt_confidence`
    sure and `body` has no rule of its own (None otherwise)."""
    if any(tuple(sorted(r.body)) == body for r in rules):
        return None
    j = deciding(rules, set(body))
    return None if j is None or rules[j].confidence < s.doubt_confidence else rules[j]


def _maybe(m: float, s: Settings) -> float:
    """The model's likelihood m held strictly within the uncertain band
    (once written in permille)."""
    inside = s.band - 0.002
    return float(np.clip(m, 0.5 - inside, 0.5 + inside))


def _unlikely(held: int, n: int, answered: float) -> float:
    """The chance, under an answer of likelihood `answered`, of a count of
    pours that hold as far from it as `held` of `n` (one-sided)."""
    return float(binom.cdf(held, n, answered) if answered >= 0.5 else binom.sf(held - 1, n, answered))


def added(body: tuple[str, ...], likelihood: float, rules: list[GeneralRule],
          out: list[GeneralRule], doubt: str) -> GeneralRule:
    """The rule for `body` with `likelihood`, numbered after the rules
    chosen (`rules`, then those added so far, `out`), at its level, saying
    why it was added (`doubt`)."""
    holds = likelihood >= 0.5
    e = rules[0].expectation
    rule = GeneralRule(f"g{len(rules) + len(out)}_{e}", body, e, holds, 0, 0,
                       likelihood if holds else 1 - likelihood, 0, doubt=doubt)
    return replace(rule, level=level(body, holds, rules + out))


def level(body, r_holds: bool, chosen: Sequence[GeneralRule]) -> int:
    """A rule's level: one above the highest level of the rules of the
    other head whose bodies its own holds."""
    under = [r.level for r in chosen if r.holds != r_holds and set(r.body) < set(body)]
    return 1 + max(under) if under else 1
