"""`pantarhei ask`'s answers as a person or a program reads them: each
expectation's verdict, the likelihood that it holds (the deciding rule's
estimate, pooled from every pour learned from), the deciding rule in words
with the pours of its body counted for the expectation holding, and with
`--check` what pours of the question simulated did beside each answer."""
from __future__ import annotations

import json
from typing import Callable

#: What the marks and figures of an answer mean, printed below the answers.
LEGEND = ("(yes / no: what such pours do, and the share of them in which the expectation holds, "
          "as the deciding rule estimates it from every pour, pooled; maybe: such pours split, or too few tell; "
          "?: the theory does not say. \"held in K of N pours of B\": the pours learned from that "
          "could have been drawn for B (the rule's body, or what was asked when it was explored), "
          "and in how many the expectation held. "
          "Ask again with --why E for the whole argument)")


def answer(asker, props: list[str], why: str | None = None, as_json: bool = False,
           json_line: dict | None = None, check: Callable | None = None) -> int:
    """Print what the theory `asker` asks (bridge/reasoning/asking.Door, or
    answers.InProcess for a theory held in Python) says of the scene
    `props`, or with `why` (a native literal) the whole argument for it;
    as JSON with `as_json`, on one line beginning with the keys of
    `json_line` when it is given (JSON Lines). With `check` (a Checker),
    what pours of the scene simulated did, beside each answer."""
    def print_json(obj: dict) -> None:
        if json_line is None:
            print(json.dumps(obj, indent=1))
        else:
            print(json.dumps({**json_line, **obj}, separators=(",", ":")))

    scene = props
    if why:
        proof = None
        if as_json and hasattr(asker, "why_proof"):
            words, proof = asker.why_proof(scene, why)
        else:
            words = asker.why(scene, why)
        said = answered(asker, scene, why)
        if as_json:
            print_json({"understood": props, "literal": why, **why_json(words),
                        **({"proof": proof} if proof is not None else {}),
                        **({"answer": answer_json(said)} if said is not None else {})})
        else:
            _print_scene(props, glosses=False)
            print(words.replace("; ", "\n  "))
            if said is not None and said.value != "unknown":
                first, *more = said.because.split("; ")
                print(f"answered [{answer_mark(said).rstrip()}] {first}")
                for line in more:
                    print(f"  {line}")
        return 0
    outcomes = asker.answers(scene)
    reading = getattr(props, "reading", None)      # a question in words: reading.Scene
    if reading is not None:                        # what it asks, or wants, first
        first = [*reading.asked, *(g.removeprefix("neg(").rstrip(")") for g in reading.goals)]
        outcomes = sorted(outcomes, key=lambda o: first.index(o.expectation)
                          if o.expectation in first else len(first))
    observed = check(scene) if check is not None else None
    if as_json:
        from pantarhei.bridge.reasoning.checking import contradicts

        def one(o) -> dict:
            out = answer_json(o)
            if observed is not None:
                seen = observed[o.expectation]
                out["check"] = {**seen.as_json(), "contradicts": contradicts(o.value, seen)}
            return out

        heard = {k: list(getattr(reading, k)) for k in ("asked", "goals", "notes", "ignored")
                 if reading is not None and getattr(reading, k)}
        print_json({"understood": props, **heard, "theory": asker.source,
                    "replaces_shipped": bool(getattr(asker, "replaces", None)),
                    **({"check": check.settings()} if observed is not None else {}),
                    "outcomes": {o.expectation: one(o) for o in outcomes}})
        return 0
    from pantarhei.theory.lexicon import load_vocabulary

    vocab = load_vocabulary()
    _print_scene(props, glosses=True)
    if reading is not None:
        _print_heard(reading)
    print(f"theory: {asker.source}")
    replaces = getattr(asker, "replaces", None)
    if replaces:
        print(f"  (in place of the shipped theory, which is not read: add --theory {replaces} "
              f"to ask it with these rules)")
    glosses = {e.name: e.gloss for e in vocab.expectations}
    said: dict[str, str] = {}     # a why-not already printed, with its expectation as E
    flagged = 0
    for o in outcomes:
        seen = ""
        if observed is not None:
            seen, bad = seen_mark(o.value, observed[o.expectation])
            flagged += bad
        print(f"  [{answer_mark(o)}]{seen} {o.expectation:30} {glosses[o.expectation]}")
        if o.value != "unknown":
            first, *more = o.because.split("; ")
            print(f"          {first}")
            for line in more:
                print(f"            {line}")
            continue
        general = o.reason.replace(o.expectation, "E")
        if general in said:   # the same reasons as for an expectation above
            print(f"          why not: as for {said[general]}")
            continue
        said[general] = o.expectation
        first, *more = o.reason.split("; ")[1:] or [o.reason]
        print(f"          why not: {first}")
        for line in more:
            print(f"            {line}")
    print(LEGEND)
    if observed is not None:
        print(check.summary(flagged))
    return 0


def answer_json(o) -> dict:
    """One answer for programs: its verdict, likelihood, rule, why in one
    line and the pours behind it."""
    return {"verdict": o.value, "likelihood": o.likelihood, "rule": o.rule,
            "because": o.because,
            "evidence": o.evidence.as_json() if o.evidence is not None else None}


def answered(asker, scene: list[str], literal: str):
    """The answer `ask` gives for the expectation of `literal` (a native
    literal, neg(E) for E) in the scene, with its evidence; None when the
    literal is no expectation."""
    expectation = literal[4:-1] if literal.startswith("neg(") else literal
    return next((o for o in asker.answers(scene) if o.expectation == expectation), None)


def why_json(words: str) -> dict:
    """--why's answer for programs: the whole text, and its sentences as
    a list (the conclusion or why-not first, then each rule's part)."""
    return {"why": words, "steps": words.split("; ")}


def seen_mark(verdict: str, observed) -> tuple[str, bool]:
    """The share the pours simulated gave, 11 characters ("  seen  40%",
    with "!" after it where they contradict the answer), and whether
    they do."""
    from pantarhei.bridge.reasoning.checking import contradicts

    bad = contradicts(verdict, observed)
    share = observed.share
    text = f"{round(100 * share):3d}%" if share is not None else "  - "
    return f"  seen {text}{'!' if bad else ' '}", bad


def answer_mark(o) -> str:
    """The verdict and its likelihood, 10 characters: "yes    92%",
    "no      8%", "maybe  55%", "?" for an expectation the theory leaves
    undecided."""
    word = {"holds": "yes", "fails": "no", "uncertain": "maybe", "unknown": "?"}[o.value]
    share = f"{round(100 * o.likelihood):3d}%" if o.likelihood is not None else ""
    return f"{word:6}{share:>4}"


def _print_scene(props: list[str], glosses: bool) -> None:
    """The propositions understood from the question."""
    from pantarhei.theory.lexicon import load_vocabulary

    vocab = load_vocabulary()
    print(f"understood: {', '.join(props) or 'the ordinary pour (nothing said of the scene)'}")
    if glosses:
        for p in props:
            print(f"  {p}: {vocab.propositions[p].gloss}")


def _print_heard(reading) -> None:
    """What else the question said: its everyday words as read, the words
    read as nothing, the expectations it asks about and its goals, with
    how `plan` would pour for them."""
    from pantarhei.theory.lexicon import load_vocabulary

    for note in reading.notes:
        print(f"  {note}")
    if reading.ignored:
        print(f"  ignored: {', '.join(repr(w) for w in reading.ignored)}")
    if reading.asked and len(reading.asked) == len(load_vocabulary().expectations):
        print("asked: what happens, every expectation (answered in their order)")
    elif reading.asked:
        print(f"asked: {', '.join(reading.asked)} (answered first)")
    if reading.goals:
        given = f" --given {','.join(reading.scene)}" if reading.scene else ""
        print(f"wanted: {', '.join(reading.goals)} (answered first; how to pour for it: "
              f"pantarhei plan --goal {','.join(reading.goals)}{given})")


class Checker:
    """`--check N`: N pours of each question sampled with `seed` and
    simulated through the store with the oracle the theory was learned
    from; the pours are kept there. Call it with a scene for its
    observations (checking.observe); use as a context manager."""

    def __init__(self, n: int, seed: int, store: str, oracle: str) -> None:
        from pantarhei.bridge.exploration.simulation import open_simulator, oracle_identity

        self.n, self.seed, self.store, self.oracle = n, seed, store, oracle
        oracle_identity(oracle)     # UserError for an oracle that is unknown or cannot load
        self._sim = open_simulator(oracle, store=store)

    def __enter__(self) -> "Checker":
        self._sim.__enter__()
        return self

    def __exit__(self, *exc) -> None:
        self._sim.__exit__(*exc)

    def __call__(self, scene: list[str]):
        from pantarhei.bridge.reasoning.checking import observe

        return observe(scene, self.n, self.seed, self._sim.simulate)

    def settings(self) -> dict:
        return {"pours": self.n, "seed": self.seed, "oracle": self.oracle, "store": self.store}

    def summary(self, flagged: int) -> str:
        said = (f"{flagged} answer{'s' if flagged != 1 else ''} the pours contradict (!)"
                if flagged else "no answer the pours contradict")
        return (f"checked: {self.n} pours of the question simulated (oracle {self.oracle}, "
                f"seed {self.seed}, kept in {self.store}); seen: the share in which the "
                f"expectation held; {said}")
