"""What a learned theory says of its exploration (explored_pours.py): the
antecedents it explored, in order, and their pours drawn again as the
exploration simulated them, on theories learned from the synthetic oracle."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.evaluation import pipeline as E
from pantarhei.bridge.evaluation.explored_pours import exploration_draws, one_layer, read_learned
from pantarhei.bridge.exploration.curiosity_sides import curiosities


def test_read_learned_finds_the_explored_antecedents_in_order(learned):
    theory, _ = learned
    L = read_learned(theory)
    trace = [json.loads(line) for line in theory.with_suffix(".trace.jsonl").read_text().splitlines()]
    # a batch per iteration; an antecedent whose planes were undecided got more than one
    assert len(trace) == sum(L.batches) and len(L.batches) == len(L.antecedents)
    # the candidates set aside after their probe, iteration by iteration
    aside = [tuple(sorted(p["antecedent"])) for t in trace for p in t.get("probes", [])
             if not p["kept"]]
    assert aside
    assert [tuple(sorted(d.antecedent)) for d in L.draws if not d.explored] == aside
    firsts = [t for t in trace if not t["via"].startswith("more")]
    assert [tuple(sorted(t["antecedent"])) for t in firsts] == L.antecedents
    assert [sum(1 for t in trace if t["id"] == f"a{i}") for i in range(1, len(firsts) + 1)] == L.batches
    assert L.setting("oracle") == "synthetic" and L.setting("batch") == 12


def test_the_pours_drawn_again_are_the_very_pours_of_the_run(explored):
    """Every pour of the run, probes too, in the order simulated: read from
    the trace's draws, not from a restatement of the probe schedule."""
    theory, _, (params, scores) = explored
    L = read_learned(theory)
    P, drawn, of, ends = exploration_draws(L)
    assert np.array_equal(P, params)
    assert len(drawn) == len(of) == ends[-1] == len(P)
    assert sorted(set(of.tolist())) == [-1, *range(len(L.antecedents))]
    assert [a for a, i in zip(drawn, of) if i >= 0] == [L.antecedents[i] for i in of if i >= 0]


def test_a_trace_without_its_draws_is_refused_in_one_line(learned, tmp_path):
    theory, _ = learned
    copy = tmp_path / "copy.pl"
    copy.write_text(theory.read_text())
    lines = [json.loads(line) for line in theory.with_suffix(".trace.jsonl").read_text().splitlines()]
    del lines[1]["draws"]
    copy.with_suffix(".trace.jsonl").write_text("".join(json.dumps(t) + "\n" for t in lines))
    with pytest.raises(UserError, match="line 2 of the trace does not record its draws"):
        read_learned(copy)
    copy.with_suffix(".trace.jsonl").unlink()
    with pytest.raises(UserError, match="trace"):
        read_learned(copy)


def test_read_learned_refuses_a_hand_written_theory(tmp_path):
    p = tmp_path / "hand.pl"
    p.write_text("rule(r1, defeasible, no_spill).\nbody(r1, pour_low).\n")
    with pytest.raises(UserError, match="not a theory written by"):
        read_learned(p)


def test_the_theory_is_reproduced_from_its_pours_or_the_evaluation_says_not(learned, tmp_path):
    theory, store = learned
    from pantarhei.bridge.exploration.simulation import open_simulator

    def reproduced(path: Path) -> bool:
        ev = E.Evaluation(theory=str(path), oracle="synthetic", settings={}, budget=0)
        with open_simulator("synthetic", "inline", None, store) as sim:
            E.exploration_pours(read_learned(path), E.Simulations(sim, ev, False), ev)
        return ev.reproduced

    assert reproduced(theory)
    text = theory.read_text()
    edited = tmp_path / "edited.pl"
    head = next(line for line in text.splitlines() if line.startswith("rule(r2_no_spill,"))
    flipped = (head.replace("neg(no_spill)", "no_spill") if "neg(" in head
               else head.replace(", no_spill)", ", neg(no_spill))"))
    edited.write_text(text.replace(head, flipped))
    edited.with_suffix(".trace.jsonl").write_text(theory.with_suffix(".trace.jsonl").read_text())
    assert not reproduced(edited)


def test_a_theory_is_one_layer_as_its_recorded_curiosity_lays_it_out(toy_curiosities):
    """One layer is what the module of the theory's curiosity says of its
    layout (theory_layout's `rules`), whatever the curiosity's name: a toy
    curiosity's theory is one layer, or not, as its module says."""
    from pantarhei.bridge.engines.swipl import engine

    one, two = toy_curiosities
    assert one_layer({"curiosity": [one]}) and one_layer({"curiosity": one})
    assert not one_layer({"curiosity": [two]}) and not one_layer({"curiosity": two})
    # no curiosity recorded, one without a module, or two: not one layer
    assert not one_layer({}) and not one_layer({"curiosity": ["nonesuch"]})
    assert not one_layer({"curiosity": [one, two]})
    for c in curiosities():
        laid_out = engine().once("curiosity_interface:by_curiosity(_{curiosity:C}, "
                                 "theory_layout(L)), get_dict(rules, L, R)", C=c)
        assert one_layer({"curiosity": [c]}) == (str(laid_out["R"]) == "false"), c


def test_a_learned_theory_of_the_discovering_curiosity_is_two_layers(learned):
    assert not read_learned(learned[0]).one_layer


def test_swi_prolog_answers_the_learned_theory_from_its_file_as_written(learned, monkeypatch):
    """The evaluation's answers of the learned theory (rule_building's
    answer_matrix, paper_rules' what_happens) are SWI-Prolog's of the file
    as written, not of Python's text of it, and the same as the text's;
    a theory built in Python (theory_of) has no file and is given as text."""
    from pantarhei.bridge.engines.swipl import Engine, engine
    from pantarhei.bridge.evaluation.rule_building import answer_matrix, theory_of
    from pantarhei.bridge.reasoning import logic
    from pantarhei.bridge.reasoning.answers import what_happens

    L = read_learned(learned[0])
    scenes = [(), ("pour_to_side",), ("light_liquid", "pour_low")] + \
        list(dict.fromkeys(tuple(sorted(r.body)) for r in L.theory.rules))[:12]
    with monkeypatch.context() as m:
        m.setattr(logic, "load_as_written", lambda theory: None)    # Python's text
        as_text = answer_matrix(L.theory, scenes), what_happens(L.theory, list(scenes[1]))
    given, load_text = [], Engine.load_theory_file

    def text_given(self, path: str, source: str) -> None:
        given.append(source)
        load_text(self, path, source)
    monkeypatch.setattr(Engine, "load_theory_file", text_given)
    engine().theory_digest = ""         # as in a new process: nothing read yet
    pred, lik = answer_matrix(L.theory, scenes)
    assert (pred == as_text[0][0]).all() and np.array_equal(lik, as_text[0][1], equal_nan=True)
    assert what_happens(L.theory, list(scenes[1])) == as_text[1]
    assert given == []
    answer_matrix(theory_of([("pour_low",)], np.ones((1, 9), dtype=bool), "in memory"), scenes[:1])
    assert given == ["in memory"]
