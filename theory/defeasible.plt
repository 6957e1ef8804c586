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

:- end_tests(defeasible).
