:- begin_tests(queries).

:- use_module(plunit_helpers).

:- use_module(defeasible).
:- use_module(queries).

example(File) :-
    module_property(queries, file(F)),
    file_directory_name(F, Dir),
    atom_concat(Dir, '/../examples/extend_by_hand/learned.pl', File).

setup :- example(F), load_theory(F).

% a hand-written rule records no likelihood
test(what_happens, [setup(setup), true(O == outcome(no_spill, fails, none, r1))]) :-
    what_happens([pour_to_side], Os),
    length(Os, 9),
    memberchk(outcome(no_spill, _, _, _), Os),
    member(O, Os), O = outcome(no_spill, _, _, _).

test(unknown_without_rules, [setup(setup), true(V-P-R == unknown-none-none)]) :-
    what_happens([pour_centred], Os),
    memberchk(outcome(destination_still_settle, V, P, R), Os).

test(specific_rule_decides, [setup(setup), true(R == r4)]) :-
    what_happens([pour_steeply_tilted, light_liquid], Os),
    memberchk(outcome(liquid_leaves_source, fails, _, R), Os).

% learned rules carry the share of their pours that keep the head: the
% answer is its likelihood, uncertain where such pours split (within
% uncertain_band of one half), and the most specific rule decides
likely_theory :-
    clear_theory,
    maplist(add_theory_fact,
            [ rule(g0, defeasible, no_spill), learned(g0),
              provenance(g0, confidence_permille, 900),
              rule(g1, defeasible, neg(no_spill)), body(g1, pour_to_side), learned(g1),
              provenance(g1, confidence_permille, 550),
              rule(g2, defeasible, neg(no_spill)), body(g2, pour_far_away), learned(g2),
              provenance(g2, confidence_permille, 800),
              rule(g3, defeasible, neg(no_spill)), body(g3, pour_far_away),
              body(g3, heavy_liquid), learned(g3),
              provenance(g3, confidence_permille, 950)
            ]).

test(likelihoods, [setup(likely_theory), cleanup(clear_theory),
                   true(Vs == [holds-0.9-g0, uncertain-0.45-g1, fails-0.2-g2, fails-0.05-g3])]) :-
    findall(V-P-R,
            ( member(Scene, [[], [pour_to_side], [pour_far_away], [pour_far_away, heavy_liquid]]),
              what_happens(Scene, Os),
              memberchk(outcome(no_spill, V, P0, R), Os),
              P is round(P0 * 100) / 100 ),
            Vs).

test(why, [setup(setup), true(Rebs == [beaten(r3, r4), inapplicable(r5, pour_upside_down)])]) :-
    why([pour_steeply_tilted, light_liquid], neg(liquid_leaves_source),
        defeasible(r4, _, _, Rebs0)),
    msort(Rebs0, Rebs).

test(why_not, [setup(setup), true(Reasons == [blocked(r2, pour_centred)])]) :-
    why([pour_to_side], no_spill, not_concluded(no_spill, Reasons)).

test(why_not_no_rule, [setup(setup), true(Reasons == [no_rule(source_clear_ever)])]) :-
    why([], source_clear_ever, not_concluded(_, Reasons)).

test(words, [setup(setup)]) :-
    explain([pour_to_side], neg(no_spill), [], Text),
    once(sub_string(Text, _, _, _, "by rule r1 (pour_to_side => neg(no_spill))")).

test(scene_does_not_stay, [setup(setup), true(V == false)]) :-
    what_happens([pour_to_side], _),
    semantics([], S),
    truth(S, defeasibly(S, neg(no_spill)), V).

test(brief_is_why_when_concluded, [setup(setup), true(Brief == Full)]) :-
    explain_brief([pour_to_side], neg(no_spill), [], Brief),
    explain([pour_to_side], neg(no_spill), [], Full).

test(brief_complement_concluded, [setup(setup),
                                  true(Reasons == [complement_concluded(neg(no_spill), r1)])]) :-
    why_brief([pour_to_side], no_spill, [], not_concluded(no_spill, Reasons)).

test(brief_conflict, [setup(setup), true(Reasons == [conflict(r2, r1)])]) :-
    why_brief([pour_to_side, pour_centred], no_spill, [], not_concluded(_, Reasons)).

test(brief_no_rule_either, [setup(setup),
                            true(Reasons == [no_rule_either(source_clear_ever,
                                                            neg(source_clear_ever))])]) :-
    why_brief([], source_clear_ever, [], not_concluded(_, Reasons)).

test(brief_nearest_first, [setup(setup),
                           true(Reasons == [ none_applies(liquid_remains_in_destination,
                                                          neg(liquid_remains_in_destination)),
                                             nearest(r8, [missing(pour_centred, false, pour_to_side)]),
                                             nearest(r7, [missing(end_low, false, none),
                                                          missing(end_upright, false, none),
                                                          missing(light_liquid, false, none)]) ])]) :-
    why_brief([pour_to_side], liquid_remains_in_destination, [], not_concluded(_, Reasons)).

test(brief_words, [setup(setup)]) :-
    explain_brief([pour_to_side], liquid_remains_in_destination, [], Text),
    once(sub_string(Text, _, _, _,
                    "rule r8 (pour_centred => liquid_remains_in_destination) also needs \c
                     pour_centred (instead of pour_to_side)")).

% A theory of 40 rules for one literal, rule rI needing p0, ..., pI. In the
% scene p0 none applies: the brief why-not names the three nearest, why/4
% every rule.
many_rules(File) :-
    with_output_to(string(Text),
                   forall(between(1, 40, I),
                          ( format("rule(r~w, defeasible, no_spill).~n", [I]),
                            forall(between(0, I, J), format("body(r~w, p~w).~n", [I, J])) ))),
    text_file(Text, File).

test(brief_names_three_rules,
     [ setup((many_rules(F), load_theory(F))), cleanup(delete_file(F)),
       true(Reasons == [none_applies(no_spill, neg(no_spill)),
                        nearest(r1, [missing(p1, false, none)]),
                        nearest(r2, [missing(p1, false, none), missing(p2, false, none)]),
                        nearest(r3, [missing(p1, false, none), missing(p2, false, none),
                                     missing(p3, false, none)])]) ]) :-
    why_brief([p0], no_spill, [], not_concluded(_, Reasons)),
    why([p0], no_spill, [], not_concluded(_, Full)),
    length(Full, 40).

:- end_tests(queries).
