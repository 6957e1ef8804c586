"""The vocabulary as Python objects (theory/lexicon.py): what
`load_vocabulary` reads from theory/vocabulary/ is what SWI-Prolog's
vocabulary module holds (parameters with bounds and priors, propositions
with their dimension, rank, gloss and model, each dimension's values in
rank order, the expectations), and an unknown name is refused with the
nearest known ones."""
from __future__ import annotations

import pytest

from pantarhei.bridge.engines.swipl import engine, text
from pantarhei.theory.lexicon import UnknownProposition, load_vocabulary


def prolog(template: str, goal: str) -> list[str]:
    """Each solution of `goal` as the text `template` formats its variables (`V`)."""
    r = engine().once(f"findall(Out_, ({goal}, format(string(Out_), \"{template}\", V)), Outs_)")
    return [text(s) for s in r["Outs_"]]


def _model_text(m) -> str:
    if m.kind == "uniform":
        return f"uniform({m.low},{m.high})"
    return f"relative({m.base},{m.low},{m.high})"


def test_the_vocabulary_is_the_one_prolog_reads() -> None:
    v = load_vocabulary()
    assert [f"{p.name} {p.group} {p.unit} {p.low} {p.high} uniform({p.prior_low},{p.prior_high})"
            for p in v.parameters] == \
        prolog("~w ~w ~w ~w ~w ~w", "vocabulary:parameter(N, G, U, L, H), vocabulary:prior(N, D), "
                                    "V = [N, G, U, L, H, D]")
    assert sorted(f"{p.name}\t{p.dimension}\t{p.rank}\t{p.gloss}" for p in v.propositions.values()) == \
        sorted(prolog("~w\\t~w\\t~w\\t~w", "vocabulary:proposition(N, D, R, G), V = [N, D, R, G]"))
    models = sorted(f"{n} {p.model.param} {_model_text(p.model)}" for n, p in v.propositions.items())
    assert models == sorted(prolog("~w ~w ~w", "vocabulary:model(N, P, M), V = [N, P, M]"))
    assert any("relative(" in m for m in models) and any("uniform(" in m for m in models)
    for d in v.dimensions.values():
        assert list(d.values) == [text(n) for n in engine().once(
            "findall(R-N, vocabulary:proposition(N, D, R, _), RNs), keysort(RNs, S), "
            "pairs_values(S, Ns)", D=d.name)["Ns"]]
    assert [f"{e.name} {e.stage}" for e in v.expectations] == \
        prolog("~w ~w", "vocabulary:expectation(N, S, _), V = [N, S]")


def test_an_unknown_proposition_names_the_nearest() -> None:
    with pytest.raises(UnknownProposition, match=r"^unknown proposition 'pour_form_side' "
                                                 r"\(did you mean pour_to_side"):
        load_vocabulary().proposition("pour_form_side")
    load_vocabulary().check_names(["pour_to_side", "light_liquid"])
