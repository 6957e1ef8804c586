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

test(scene_facts_come_and_go, [true(Vs == [true, false])]) :-
    load_text("rule(r1, defeasible, p). body(r1, a)."),
    sem(S),
    with_scene([a], truth(S, defeasibly(S, p), V1)),
    truth(S, defeasibly(S, p), V2),
    Vs = [V1, V2].

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

:- end_tests(defeasible).
