:- begin_tests(ask).

:- use_module(plunit_helpers).

:- use_module(defeasible).
:- use_module(queries).
:- use_module(ask).

example(Name, File) :-
    module_property(ask, file(F)),
    file_directory_name(F, Dir),
    atomic_list_concat([Dir, '/../examples/extend_by_hand/', Name], File).

load_error(Files, Message) :-
    catch(( load_theories(Files, _), Message = loaded ), E,
          ( E = theory_error(F, L, M), format(string(Message), "~w:~w: ~w", [F, L, M]) )).

% with_files(+Texts, -Files, :Goal): Goal with Files holding Texts.
with_files(Texts, Files, Goal) :-
    maplist(text_file, Texts, Files),
    call_cleanup(Goal, maplist(delete_file, Files)).

% a learned theory and rules added by hand, in two files, are one theory
test(two_files_merge, [true(R == h1)]) :-
    example('learned.pl', Learned), example('hand.pl', Hand),
    load_theories([Learned, Hand], []),
    what_happens([light_liquid, pour_steeply_tilted, slow_retreat], Os),
    memberchk(outcome(liquid_leaves_source, holds, _, R), Os).

test(rule_defined_twice, [true(M == "F2:2: rule r1 is already defined in F1")]) :-
    with_files(["fact(a).\nrule(r1, defeasible, b).\n", "fact(c).\nrule(r1, defeasible, d).\n"], [F1, F2], load_error([file(F1, 'F1'), file(F2, 'F2')], M)).

test(sup_names_no_rule, [true(M == "T:2: sup(r1, r9) names r9, which is not a rule")]) :-
    with_files(["rule(r1, defeasible, b).\nsup(r1, r9).\n"], [F], load_error([file(F, 'T')], M)).

test(sup_cycle_across_files,
     [true(M == "A:3: the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic")]) :-
    with_files(["rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\n",
                "sup(r2, r1).\n"], [F1, F2], load_error([file(F1, 'A'), file(F2, 'B')], M)).

test(empty_file, [true(M == "E:0: an empty theory (no facts and no rules)")]) :-
    with_files(["% nothing\n"], [F], load_error([file(F, 'E')], M)).

test(general_rule_outside_the_vocabulary,
     [true(M == "G:2: general rule g1: pour_sideways is not a proposition of the vocabulary")]) :-
    with_files(["rule(g1, defeasible, no_spill).\nbody(g1, pour_sideways).\nprovenance(g1, layer, general).\n"], [F], load_error([file(F, 'G')], M)).

test(general_rule_evidence_out_of_range,
     [true(M == "G:3: general rule g1: 9 pours kept of 4 described")]) :-
    with_files(["rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\nprovenance(g1, kept, 9).\nprovenance(g1, support, 4).\n"], [F], load_error([file(F, 'G')], M)).

% a name the vocabulary does not know, used by no other rule, is said
test(unknown_names, [true(Ws == [unknown("U:2", "rule r1: body", "pour_sidewise"),
                                 unknown("U:3", "rule r2: head", "spilled")])]) :-
    with_files(["rule(r1, defeasible, no_spill).\nbody(r1, pour_sidewise).\nrule(r2, defeasible, spilled).\nbody(r2, pour_to_side).\n"], [F], load_theories([file(F, 'U')], Ws)).

% a stand-in (a DFL file Python read and checked) is not checked again,
% but for its names, at the lines of the DFL file (its written_at/4 facts)
test(checked_stand_in_skips_file_checks, [true(Ws == [])]) :-
    with_files(["rule(r1, defeasible, no_spill).\nbody(r1, pour_sidewise).\n"], [F], load_theories([file(F, 'D', checked)], Ws)).
test(stand_in_names_at_the_lines_written, [true(Ws == [unknown("D:3", "rule r1: body", "pour_sidewise")])]) :-
    with_files(["rule(r1, defeasible, no_spill).\nbody(r1, pour_sidewise).\nwritten_at(3, rule, r1, no_spill).\nwritten_at(3, body, r1, pour_sidewise).\n"], [F], load_theories([file(F, 'D', checked)], Ws)).

% a stand-in's general rules are checked at the lines of the file it
% stands for: a body outside the vocabulary, evidence out of range
test(stand_in_general_rule_at_the_line_written,
     [true(M == "D:7: general rule g1: pour_sideways is not a proposition of the vocabulary")]) :-
    with_files(["rule(g1, defeasible, no_spill).\nbody(g1, pour_sideways).\nprovenance(g1, layer, general).\nwritten_at(7, rule, g1, no_spill).\nwritten_at(7, body, g1, pour_sideways).\nwritten_at(8, provenance, g1, layer).\n"], [F], load_error([file(F, 'D', checked)], M)).
test(stand_in_general_evidence_at_the_line_written,
     [true(M == "D:9: general rule g1: 9 pours kept of 4 described")]) :-
    with_files(["rule(g1, defeasible, no_spill).\nprovenance(g1, layer, general).\nprovenance(g1, kept, 9).\nprovenance(g1, support, 4).\nwritten_at(2, rule, g1, no_spill).\nwritten_at(9, provenance, g1, kept).\nwritten_at(9, provenance, g1, kept).\nwritten_at(11, provenance, g1, support).\n"], [F], load_error([file(F, 'D', checked)], M)).

% a stand-in's cycle is said at the line its written_at/4 gives the pair
test(stand_in_cycle_at_the_line_written,
     [true(M == "D:5: the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic")]) :-
    with_files(["rule(r1, defeasible, b).\nrule(r2, defeasible, neg(b)).\nsup(r1, r2).\nsup(r2, r1).\nwritten_at(5, sup, r1, r2).\nwritten_at(6, sup, r2, r1).\n"], [F], load_error([file(F, 'D', checked)], M)).

% sup_names(false): a sup/2 naming a rule of no file read passes (a file
% of added rules converted alone), and a cycle is still found
test(sup_names_false_lets_a_pair_name_no_rule, [true(Ws == [])]) :-
    with_files(["rule(r1, defeasible, no_spill).\nsup(r1, r9).\n"], [F], load_theories([file(F, 'T')], [sup_names(false)], Ws)).
test(sup_names_false_still_finds_a_cycle,
     [true(M == "T:2: the superiority relation has a cycle, r1 > r1: it must be acyclic")]) :-
    with_files(["rule(r1, defeasible, b).\nsup(r1, r1).\nsup(r1, r9).\n"], [F],
               catch(( load_theories([file(F, 'T')], [sup_names(false)], _), M = loaded ), theory_error(N, L, M0),
                     format(string(M), "~w:~w: ~w", [N, L, M0]))).

:- end_tests(ask).
