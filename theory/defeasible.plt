:- begin_tests(defeasible).

:- use_module(defeasible).
:- use_module(plunit_helpers).

load_text(Text) :-
    load_theory_text(Text).

sem(S) :- semantics([], S).

test(tweety, [true(Cs == [bird, penguin, neg(flies)])]) :-
    load_text("fact(bird). fact(penguin).
               rule(r1, defeasible, flies). body(r1, bird).
               rule(r2, defeasible, neg(flies)). body(r2, penguin).
               sup(r2, r1)."),
    sem(S), conclusions(S, '+d', Cs).

test(definite, [true(Cs == [bird, penguin])]) :-
    load_text("fact(penguin). rule(r1, strict, bird). body(r1, penguin).
               rule(r2, defeasible, flies). body(r2, bird)."),
    sem(S), conclusions(S, '+D', Cs).

test(loop_well_founded, [true(V == false)]) :-
    load_text("rule(r1, defeasible, p). body(r1, q). rule(r2, defeasible, q). body(r2, p)."),
    sem(S), truth(S, defeasibly(S, p), V).

test(loop_kunen, [true(V == undefined)]) :-
    load_text("rule(r1, defeasible, p). body(r1, q). rule(r2, defeasible, q). body(r2, p)."),
    semantics([well_founded(false)], S), truth(S, defeasibly(S, p), V).

test(team_defeat, [true(Vs == [true, false])]) :-
    load_text("rule(r1, defeasible, p). rule(r2, defeasible, p).
               rule(r3, defeasible, neg(p)). rule(r4, defeasible, neg(p)).
               sup(r1, r3). sup(r2, r4)."),
    semantics([], S1), semantics([team_defeat(false)], S2),
    truth(S1, defeasibly(S1, p), V1), truth(S2, defeasibly(S2, p), V2),
    Vs = [V1, V2].

test(ambiguity, [true(Vs == [true, false])]) :-
    load_text("rule(r1, defeasible, a). rule(r2, defeasible, neg(a)).
               rule(r3, defeasible, b). rule(r4, defeasible, neg(b)). body(r4, a)."),
    semantics([], S1), semantics([ambiguity(propagation)], S2),
    truth(S1, defeasibly(S1, b), V1), truth(S2, defeasibly(S2, b), V2),
    Vs = [V1, V2].

test(specificity, [true(R-S == r2-r1)]) :-
    load_text("rule(r1, defeasible, p). body(r1, a). learned(r1).
               rule(r2, defeasible, neg(p)). body(r2, a). body(r2, b). learned(r2)."),
    theory_loaded, superior(R, S).

% Specificity is looked up in every mode, never held: each mode gives the
% pairs the definition gives (sup/2, or learned rules with complementary
% heads, one body strictly inside the other, sup/2 not saying otherwise).
test(specificity_in_every_mode, [true(Modes == [Pairs, Pairs, Pairs, Pairs])]) :-
    load_text("rule(r1, defeasible, p). body(r1, a). learned(r1).
               rule(r2, defeasible, neg(p)). body(r2, a). body(r2, b). learned(r2).
               rule(r3, defeasible, neg(p)). learned(r3).
               rule(r4, defeasible, p). body(r4, a). body(r4, b). body(r4, c). learned(r4).
               rule(r5, defeasible, p). body(r5, b). learned(r5).
               rule(r6, defeasible, neg(p)). body(r6, a). body(r6, c). body(r6, d).
               rule(r7, defeasible, neg(p)). body(r7, b). body(r7, c). learned(r7).
               sup(r3, r5). sup(r6, r1)."),
    theory_loaded,
    findall(R-S, ( defeasible:rule(R, _, _), defeasible:rule(S, _, _), defined_superior(R, S) ), Ps0),
    sort(Ps0, Pairs),
    findall(R-S, superior(R, S), M1), sort(M1, Free),
    findall(R-S, ( defeasible:rule(R, _, _), superior(R, S) ), M2), sort(M2, First),
    findall(R-S, ( defeasible:rule(S, _, _), superior(R, S) ), M3), sort(M3, Second),
    findall(R-S, ( defeasible:rule(R, _, _), defeasible:rule(S, _, _), superior(R, S) ), M4), sort(M4, Both),
    Modes = [Free, First, Second, Both].

defined_superior(R, S) :- defeasible:sup(R, S).
defined_superior(R, S) :-
    defeasible:learned(R), defeasible:learned(S),
    defeasible:rule(R, _, H), complement(H, NH), defeasible:rule(S, _, NH),
    rule_body(R, BR), rule_body(S, BS), ord_subset(BS, BR), BS \== BR,
    \+ defeasible:sup(S, R).

test(sup_against_specificity, [fail]) :-
    load_text("rule(r1, defeasible, p). body(r1, a). learned(r1).
               rule(r2, defeasible, neg(p)). body(r2, a). body(r2, b). learned(r2).
               sup(r1, r2)."),
    theory_loaded, superior(r2, r1).

test(scene_facts_come_and_go, [true(Vs == [true, false])]) :-
    load_text("rule(r1, defeasible, p). body(r1, a)."),
    sem(S),
    with_scene([a], truth(S, defeasibly(S, p), V1)),
    truth(S, defeasibly(S, p), V2),
    Vs = [V1, V2].

test(bad_kind, [throws(theory_error(_, _, _))]) :-
    load_text("rule(r1, sometimes, p).").

test(ignores_other_predicates, [true(Cs == [a])]) :-
    load_text("fact(a). provenance(r1, runs, 3). setting(seed, 1)."),
    sem(S), conclusions(S, '+D', Cs).

% A defeasible fact is a defeasible rule without body: +d, never +D, and
% it can be defeated.
test(defeasible_fact, [true(Cs == ['+D'-[], '-D'-[a, neg(a)], '+d'-[a], '-d'-[neg(a)]])]) :-
    load_text("rule(f1, defeasible, a)."),
    sem(S), findall(T-Ls, (member(T, ['+D', '-D', '+d', '-d']), conclusions(S, T, Ls)), Cs).

test(defeasible_fact_beaten, [true(Cs == [[neg(a)], [a]])]) :-
    load_text("rule(f1, defeasible, a). rule(f2, defeasible, neg(a)). sup(f2, f1)."),
    sem(S), conclusions(S, '+d', P), conclusions(S, '-d', M), Cs = [P, M].

test(defeasible_fact_against_strict_fact, [true(Cs == [[neg(a)], [neg(a)], [a]])]) :-
    load_text("rule(f1, defeasible, a). fact(neg(a))."),
    sem(S), conclusions(S, '+D', D), conclusions(S, '+d', P), conclusions(S, '-d', M),
    Cs = [D, P, M].

test(defeasible_fact_and_defeater, [true(Cs == [[b], [a, neg(a), neg(b)]])]) :-
    load_text("rule(f1, defeasible, a). rule(d1, defeater, neg(a)). body(d1, b). fact(b)."),
    sem(S), conclusions(S, '+d', P), conclusions(S, '-d', M), Cs = [P, M].

% A theory of facts only, read as in a fresh process: the scratch module
% of load_theory/1 has no rule/3 of its own yet.
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

% The superiority relation must be acyclic.
test(cyclic_superiority, [throws(theory_error(_, 0, "the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic"))]) :-
    load_text("fact(a). rule(r1, defeasible, b). body(r1, a).
               rule(r2, defeasible, neg(b)). body(r2, a). sup(r1, r2). sup(r2, r1).").

test(rule_superior_to_itself, [throws(theory_error(_, 0, "the superiority relation has a cycle, r1 > r1: it must be acyclic"))]) :-
    load_text("rule(r1, defeasible, b). sup(r1, r1).").

test(long_superiority_cycle, [throws(theory_error(_, 0, "the superiority relation has a cycle, r1 > r2 > r3 > r1: it must be acyclic"))]) :-
    load_text("rule(r1, defeasible, b). rule(r2, defeasible, b). rule(r3, defeasible, b).
               sup(r1, r2). sup(r2, r3). sup(r3, r1).").

% sup(r1, r2) and sup(r3, r1), with r2 beating r3 by specificity.
test(cycle_through_specificity, [throws(theory_error(_, 0, "the superiority relation has a cycle, r1 > r2 > r3 > r1: it must be acyclic"))]) :-
    load_text("rule(r1, defeasible, p). body(r1, a).
               rule(r2, defeasible, p). body(r2, a). body(r2, b). learned(r2).
               rule(r3, defeasible, neg(p)). body(r3, a). learned(r3).
               sup(r1, r2). sup(r3, r1).").

test(cyclic_theory_is_forgotten, [true(Cs == [])]) :-
    catch(load_text("fact(a). rule(r1, defeasible, b). sup(r1, r1)."), theory_error(_, _, _), true),
    sem(S), conclusions(S, '+D', Cs).

test(acyclic_superiority_chain, [true(Cs == [a, b])]) :-
    load_text("fact(a). rule(r1, defeasible, b). body(r1, a).
               rule(r2, defeasible, neg(b)). body(r2, a). rule(r3, defeasible, neg(b)).
               sup(r1, r2). sup(r1, r3). sup(r2, r3)."),
    sem(S), conclusions(S, '+d', Cs).

:- end_tests(defeasible).
