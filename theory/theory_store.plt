:- begin_tests(theory_store).

:- use_module(theory_store).
:- use_module(defeasible).
:- use_module(plunit_helpers).

load_text(Text) :-
    load_theory_text(Text).

sem(S) :- semantics([], S).

test(bad_kind, [throws(theory_error(_, _, _))]) :-
    load_text("rule(r1, sometimes, p).").

test(ignores_other_predicates, [true(Cs == [a])]) :-
    load_text("fact(a). provenance(r1, runs, 3). setting(seed, 1)."),
    sem(S), conclusions(S, '+D', Cs).

% A theory of facts only, read as in a fresh process: the scratch module
% of store_theory/1 has no rule/3 of its own yet.
fresh_input :-
    forall(member(P/A, [fact/1, rule/3, body/2, sup/2, learned/1]),
           catch(abolish(defeasible_input:P/A), _, true)).

test(facts_only, [setup(fresh_input), true(Cs == [[a], [a], [neg(a)]])]) :-
    load_text("fact(a)."),
    sem(S), conclusions(S, '+D', D), conclusions(S, '+d', P), conclusions(S, '-d', M),
    Cs = [D, P, M].

test(defeasible_facts_only, [setup(fresh_input), true(Cs == [[], [a]])]) :-
    load_text("rule(f1, defeasible, a)."),
    sem(S), conclusions(S, '+D', D), conclusions(S, '+d', P), Cs = [D, P].

:- end_tests(theory_store).
