"""The general theory asked what a person would ask: the questions of
bridge/evaluation/questions.json (20 pours each) and the uniform held-out
scenes, for the general rules of each method's pours beside gradient
boosting of the same pours and the defaults-only theory, and the shipped
theory as SWI-Prolog answers. The measure's stage and headline rows are
here; its report section is report_general.py's."""
from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from pantarhei.theory.lexicon import load_vocabulary

from pantarhei.bridge.evaluation.figures import Evaluation
from pantarhei.bridge.evaluation.formats import num, pct
from pantarhei.bridge.evaluation.inputs import Inputs
from pantarhei.bridge.evaluation.measures import (accuracy, contrast_keys, defaults_only, question_key,
                                                  question_measures, question_shares)
from pantarhei.bridge.verdicts import verdicts
from pantarhei.bridge.evaluation.questions import question_pours, questions
from pantarhei.bridge.evaluation.rule_building import answer_matrix, predict
from pantarhei.bridge.theories.model import Theory

#: The targets of the shipped theory on the questions: coverage and
#: accuracy of the clear keys, accuracy of the contrast keys and coherent
#: answers, at the least; calibration at most, and at most this far behind
#: boosting's (`MODEL_GAP`); general rules per expectation, at most.
COVERAGE, ACCURACY, CONTRAST_ACCURACY, COHERENT = 0.95, 0.95, 0.85, 0.95
CALIBRATION, MODEL_GAP = 0.08, 0.02
RULES_PER_EXPECTATION = 12


@dataclass
class _Keys:
    """The questions' keys from their pours, and the held-out scenes."""
    scenes: list
    key: np.ndarray
    clear: np.ndarray
    share: np.ndarray
    V: np.ndarray
    of: np.ndarray
    held: list
    held_y: np.ndarray
    contrast: np.ndarray

    def scored(self, pred_held: np.ndarray | None, pred_q: np.ndarray,
               lik_q: np.ndarray) -> dict[str, Any]:
        entry = {"questions": question_measures(pred_q, lik_q, self.share, self.key, self.clear,
                                                self.contrast, self.V, self.of),
                 "answers": pred_q.astype(int).tolist(),
                 "likelihood": np.round(lik_q, 3).tolist()}
        if pred_held is not None:
            entry["uniform"] = accuracy(pred_held, self.held_y).as_dict()
        return entry


def general_stage(ev: Evaluation, inputs: Inputs) -> None:
    """The general theory's stage of `pantarhei evaluate` (`general_theories`
    of the stage's `Inputs`): `ev.general`."""
    learned = inputs.learned
    general_theories(ev, learned.theory, inputs.methods, inputs.held, inputs.run,
                     inputs.opts.seed, int(learned.setting("seed", inputs.opts.seed)),
                     learned.rule_bodies if learned.one_layer else None, learned.learner)


def general_headline(ev: Evaluation) -> list[tuple[str, str, str, bool]]:
    """The general theory's rows, on the questions a person would type:
    the shipped theory beside the defaults-only theory and gradient
    boosting of the same pours; accuracy on the contrast keys apart."""
    g = ev.general
    if not g:
        return []
    q = g["shipped"]["questions"]
    base = g["curiosity"]["defaults"]["questions"]
    gbm = g["curiosity"]["boosting"]["questions"]
    n = g["curiosity"]["rules_per_expectation"]
    cal, cal_g, cal_b = q["calibration"], gbm["calibration"], base["calibration"]
    return [
        (f"questions ({len(g['questions'])}): coverage of the {q['clear']} clear keys",
         pct(q["coverage"]), "at least 95%", q["coverage"] >= COVERAGE),
        (f"questions: accuracy on the clear keys (defaults only: {pct(base['accuracy'])})",
         pct(q["accuracy"]), "at least 95%", q["accuracy"] >= ACCURACY),
        (f"questions: accuracy on the {q['contrast']} contrast keys, where the defaults-only "
         f"answer is wrong ({pct(q['contrast']/max(q['clear'], 1))} of the clear keys; "
         f"covered {pct(q['contrast_coverage'])})",
         pct(q["contrast_accuracy"]), "at least 85%", q["contrast_accuracy"] >= CONTRAST_ACCURACY),
        (f"calibration: mean |likelihood - share of the pours| (boosting on the same pours "
         f"{num(cal_g)}, defaults only {num(cal_b)})", num(cal),
         "at most 0.08, within 0.02 of boosting",
         cal is not None and cal <= CALIBRATION and (cal_g is None or cal - cal_g <= MODEL_GAP)),
        ("coherent answers: the decided verdicts are a behaviour one of the question's pours "
         "shows", pct(q["coherent"]), "at least 95%", q["coherent"] >= COHERENT),
        ("general rules per expectation (from curiosity's pours)", f"{n:.1f}", "at most 12",
         n <= RULES_PER_EXPECTATION),
    ]


def general_theories(ev, theory: Theory, methods: dict, held: dict,
                     run: Callable[..., np.ndarray], seed: int, explored_seed: int,
                     explored: list | None = None, learner: str | None = None) -> None:
    """Fill `ev.general`: for each method's pours (`methods`: name -> Pours),
    the general rules learned from them (and from the learner's own pours,
    as `explore` learns them), gradient boosting on the same pours (the
    ceiling of what they support: `Meaning`, averaged over each question's
    meaning) and the defaults-only theory (the majority of those pours,
    whatever is asked); and the shipped theory (both layers, by
    SWI-Prolog). Curiosity's pours are generalized with the exploration's
    seed (`explored_seed`), as `explore` did, so they give the very rules
    the theory holds; the random pours with the evaluation's. The contrast
    keys are the clear keys where the defaults-only theory of curiosity's
    pours is wrong. For the learning curiosity's theory, `explored` are its
    explored antecedents but the wholes: curiosity's rules are learned over
    them from its pours alone, as `explore` wrote them. Every method's rules are learned
    by the learner named `learner` (the theory's; None: the option
    table's default)."""
    t = time.monotonic()
    asked = questions()
    P_q, of = question_pours(asked, seed)
    S_q = run("questions", P_q)
    ok = np.all(np.isfinite(S_q), axis=1)
    key, clear = question_key(S_q[ok], of[ok], len(asked))
    sel, y = held["uniform"]
    k = _Keys([q.antecedent for q in asked], key, clear,
              question_shares(S_q[ok], of[ok], len(asked)), verdicts(S_q[ok]), of[ok],
              sel, y, np.zeros_like(clear))
    out: dict[str, Any] = {"questions": [{"text": q.text, "antecedent": list(q.antecedent)}
                                         for q in asked],
                           "key": key.astype(int).tolist(), "clear": clear.astype(int).tolist(),
                           "share": np.round(k.share, 3).tolist()}
    for method, m in methods.items():
        out[method] = _method(k, m, explored_seed if method == "curiosity" else seed, run,
                              first=method == "curiosity",
                              bodies=explored if method == "curiosity" else None,
                              learner=learner)
        if method == "curiosity":
            out["contrast"] = k.contrast.astype(int).tolist()
    pred, lik = answer_matrix(theory, k.scenes)
    shipped = k.scored(predict(theory, sel), pred, lik)
    shipped["general_rules"] = sum(1 for r in theory.rules if r.id.startswith("g"))
    out["shipped"] = shipped
    ev.general = out
    ev.seconds["general"] = round(time.monotonic() - t, 1)


def _method(k: _Keys, m, seed: int, run: Callable[..., np.ndarray], first: bool,
            bodies: list | None = None, learner: str | None = None) -> dict[str, Any]:
    """One method's entry: its general rules, boosting and defaults-only; the
    first method's defaults-only theory sets the contrast keys. With
    `bodies`, the rules are learned over them from the method's pours alone
    (the learning curiosity's one layer); else over the askable bodies,
    with the learner's own pours."""
    from pantarhei.bridge.learning.generalize import Settings
    from pantarhei.bridge.learning.meaning import Meaning
    from pantarhei.bridge.learning.layers import learn_general

    names = load_vocabulary().expectation_names
    okm = np.all(np.isfinite(m.S), axis=1)
    g, P, S = learn_general(m.P[okm], m.S[okm], seed,
                            None if bodies is not None else
                            lambda X: run("the learner's own pours", X), bodies=bodies,
                            learner=learner)
    Y = verdicts(S)
    base, base_p = defaults_only(Y, len(k.scenes))
    if first:
        k.contrast = contrast_keys(k.key, k.clear, base)
    lik = np.array([[g.answer(q)[e][1] for e in names] for q in k.scenes])
    entry = k.scored(g.predict(k.held), g.predict(k.scenes), lik)
    entry["pours"] = int(len(P))
    entry["rules_per_expectation"] = len(g.rules) / len(names)
    entry["rules"] = [{"id": r.id, "body": list(r.body), "head": r.head, "support": r.support,
                       "kept": r.kept, "confidence": round(r.confidence, 3), "level": r.level}
                      for r in g.rules]
    model = Meaning(P, Y, Settings(seed=seed))
    lik_m = model([tuple(q) for q in k.scenes])
    band = Settings()
    entry["boosting"] = k.scored(band.verdict(model([tuple(a) for a in k.held])),
                                 band.verdict(lik_m), lik_m)
    entry["defaults"] = k.scored(defaults_only(Y, len(k.held))[0], base, base_p)
    return entry
