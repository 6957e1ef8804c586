"""Validity of antecedents (bridge/reasoning/valid_scenes.py): Prolog and clingo
agree, and the count is right. The `check`, `count` and `vocab` commands
that report them: tests/bridge/commands/test_vocab.py."""
from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pantarhei.bridge.reasoning import valid_scenes as validity
from pantarhei.bridge.engines.asp import solve
from pantarhei.bridge.engines.swipl import engine
from pantarhei.theory.lexicon import load_vocabulary


VOCAB = load_vocabulary()
NAMES = sorted(VOCAB.propositions)
# Propositions that constraints link (shared parameters, conflicts): drawing
# from them often makes antecedents invalid in more than one way.
LINKED = sorted(p for p in NAMES if p.split("_")[0] in ("start", "pour", "end", "approach", "retreat"))

antecedents = st.one_of(
    st.lists(st.sampled_from(NAMES), max_size=10),
    st.lists(st.sampled_from(LINKED), max_size=6),
    st.lists(st.sampled_from(NAMES), min_size=10, max_size=30),
)


@settings(max_examples=10_000, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(antecedents)
def test_prolog_and_asp_agree(props):
    by_prolog = validity.violations(props, "prolog")
    by_asp = validity.violations(props, "asp")
    assert by_prolog == by_asp
    assert (not by_prolog) == engine().succeeds("validity:valid_antecedent(Ps)", Ps=props)


def test_the_random_antecedents_are_valid_and_invalid_alike():
    # the agreement test is only worth something if both verdicts are common
    from hypothesis import find

    find(antecedents, lambda ps: len(ps) > 3 and not validity.violations(ps))
    find(antecedents, lambda ps: {v.constraint for v in validity.violations(ps)} >= {
        "one_value_per_dimension", "one_model_per_parameter", "inside_destination"})


def test_count_agrees_with_clingo_enumeration_on_a_sub_vocabulary():
    dims = ["start_height", "start_alignment", "approach_vertical", "approach_horizontal",
            "pour_height", "pour_alignment", "liquid_amount"]
    choice = "{ in(P) : proposition(P, D, _, _), sub(D) }.\n" + "".join(f"sub({d})." for d in dims)
    models = solve(["violations.lp", "valid.lp"], choice, models=0)
    by_components = engine().once("validity:count_valid(Ds, N)", Ds=dims)["N"]
    assert len(models) == by_components
