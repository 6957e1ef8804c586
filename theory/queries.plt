:- begin_tests(queries).

:- use_module(defeasible).
:- use_module(queries).

example(File) :-
    module_property(queries, file(F)),
    file_directory_name(F, Dir),
    atom_concat(Dir, '/../examples/extend_by_hand/learned.pl', File).

setup :- example(F), load_theory(F).

test(what_happens, [setup(setup), true(O == outcome(no_spill, fails, r1))]) :-
    what_happens([pour_to_side], Os),
    length(Os, 9),
    memberchk(outcome(no_spill, _, _), Os),
    member(O, Os), O = outcome(no_spill, _, _).

test(unknown_without_rules, [setup(setup), true(V-R == unknown-none)]) :-
    what_happens([pour_centred], Os),
    memberchk(outcome(destination_still_settle, V, R), Os).

test(specific_rule_decides, [setup(setup), true(R == r4)]) :-
    what_happens([pour_steeply_tilted, light_liquid], Os),
    memberchk(outcome(liquid_leaves_source, fails, R), Os).

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

:- end_tests(queries).
