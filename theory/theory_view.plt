:- begin_tests(theory_view).

:- use_module(plunit_helpers).
:- use_module(defeasible).
:- use_module(theory_view).

% at the prompt (the user module, which imports this module) rule/3 is
% the theory's, not SWI-Prolog's own
test(rule_at_the_prompt, [true(Rs-Bs-Ss == [r1-defeasible-no_spill]-[r1-pour_to_side]-[r1-r0])]) :-
    once(load_theory_text("rule(r1, defeasible, no_spill).\nbody(r1, pour_to_side).\nrule(r0, defeasible, neg(no_spill)).\nsup(r1, r0).\n")),
    findall(I-K-H, ( user:rule(I, K, H), I == r1 ), Rs),
    findall(I-B, user:body(I, B), Bs),
    findall(A-B, user:sup(A, B), Ss).

:- end_tests(theory_view).
