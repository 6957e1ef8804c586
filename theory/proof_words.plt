:- begin_tests(proof_words).

:- use_module(proof_words).
:- use_module(plunit_helpers).

theory :-
    load_theory_text("fact(a). rule(r1, defeasible, b). body(r1, a).
                      rule(r2, strict, c). rule(d1, defeater, neg(b)).").

test(a_rule_is_named_with_its_body_arrow_and_head, [setup(theory),
     true(T == "b by rule r1 (a => b); the opposing rule d1 does not apply (e is not concluded)")]) :-
    proof_text(defeasible(r1, b, [given(a)], [inapplicable(d1, e)]), T).

test(a_rule_without_a_body, [setup(theory),
     true(T == "b is not concluded; rule r2 (-> c) applies but is overridden by d1 (~> neg(b))")]) :-
    proof_text(not_concluded(b, [overridden(r2, d1)]), T).

test(a_nearest_rule_and_what_it_needs, [setup(theory),
     true(T == 'rule r1 (a => b) also needs a (instead of z), e (undecided)')]) :-
    reason_text(nearest(r1, [missing(a, false, z), missing(e, undefined, none)]), T).

test(a_rebuttal_in_words, true(T == 'the opposing rule d1 is overridden by r1 (r1 > d1)')) :-
    rebuttal_text(beaten(d1, r1), T).

:- end_tests(proof_words).
