:- begin_tests(superiority).

:- use_module(superiority).
:- use_module(theory_store).
:- use_module(defeasible).
:- use_module(plunit_helpers).

load_text(Text) :-
    load_theory_text(Text).

sem(S) :- semantics([], S).

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
    findall(R-S, ( theory_store:rule(R, _, _), theory_store:rule(S, _, _), defined_superior(R, S) ), Ps0),
    sort(Ps0, Pairs),
    findall(R-S, superior(R, S), M1), sort(M1, Free),
    findall(R-S, ( theory_store:rule(R, _, _), superior(R, S) ), M2), sort(M2, First),
    findall(R-S, ( theory_store:rule(S, _, _), superior(R, S) ), M3), sort(M3, Second),
    findall(R-S, ( theory_store:rule(R, _, _), theory_store:rule(S, _, _), superior(R, S) ), M4), sort(M4, Both),
    Modes = [Free, First, Second, Both].

defined_superior(R, S) :- theory_store:sup(R, S).
defined_superior(R, S) :-
    theory_store:learned(R), theory_store:learned(S),
    theory_store:rule(R, _, H), complement(H, NH), theory_store:rule(S, _, NH),
    rule_body(R, BR), rule_body(S, BS), ord_subset(BS, BR), BS \== BR,
    \+ theory_store:sup(S, R).

test(sup_against_specificity, [fail]) :-
    load_text("rule(r1, defeasible, p). body(r1, a). learned(r1).
               rule(r2, defeasible, neg(p)). body(r2, a). body(r2, b). learned(r2).
               sup(r1, r2)."),
    theory_loaded, superior(r2, r1).

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

:- end_tests(superiority).
