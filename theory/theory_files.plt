:- use_module(theory_files).
:- use_module(plunit_helpers).

:- begin_tests(theory_files).

write_tmp(Text, File) :-
    text_file(Text, File).

theory_error(Text, Line, Expected) :-
    write_tmp(Text, File),
    catch(load_theory_facts(File, plunit_scratch), theory_error(File, Line, Expected), true),
    delete_file(File).

test(message_is_one_line, M == "f.pl:3: a fact, not a rule") :-
    theory_error_message(theory_error('f.pl', 3, "a fact, not a rule"), M).

test(error_message_of_a_theory_error, M == "f.pl:3: a fact") :-
    error_message(theory_error('f.pl', 3, "a fact"), M).

test(error_message_of_another_error, M == "atom_length/2: Arguments are not sufficiently instantiated") :-
    catch(atom_length(_, _), E, true),
    error_message(E, M).

test(a_rule_of_another_kind_names_its_line, [Line, Expected] == [2, "rule r2: kind strict, defeasible or defeater, not usually"]) :-
    theory_error("rule(r1, defeasible, b).\nrule(r2, usually, c).\n", Line, Expected).

test(a_literal_with_text_is_refused, Line == 1) :-
    theory_error("rule(h2, defeasible, p(\"x\")).\n", Line, _).

test(a_second_rule_of_a_name_is_refused, [Line, Expected] == [3, "a second rule named r1"]) :-
    theory_error("rule(r1, defeasible, b).\nbody(r1, a).\nrule(r1, defeasible, b).\n", Line, Expected).

test(a_body_without_its_rule_is_refused, Line == 2) :-
    theory_error("rule(r1, defeasible, b).\nbody(r9, a).\n", Line, _).

test(a_theory_fact_of_another_arity_is_refused, Expected == "expected rule(Id, Kind, Head), not a rule/2 fact") :-
    theory_error("rule(r1, b).\n", _, Expected).

test(term_text_as_python_writes_it, T == "p(a,-3,\"x\\\"y\")") :-
    term_text(p(a, -3, "x\"y"), T).

test(print_message_prints_the_one_line, S == "f.pl:3: a fact\n") :-
    '$messages':translate_message(theory_error('f.pl', 3, "a fact"), Lines, []),
    with_output_to(string(S), print_message_lines(current_output, '', Lines)).

% the pours of an explored antecedent: counts in range, read and kept
test(explored_antecedents_are_read, [true(F == [explored(a2, light_liquid), held(a2, no_spill, 11, 12)])]) :-
    write_tmp("fact(a).\nexplored(a2, light_liquid).\nheld(a2, no_spill, 11, 12).\n", File),
    read_theory_file(File, LineFacts),
    delete_file(File),
    findall(X, ( member(_-X, LineFacts), X \= fact(_) ), F).

test(pours_held_past_those_counted_are_refused, [Line, Expected] == [2, "held(a2, no_spill, Held, Pours): Held of Pours pours, whole numbers with 0 <= Held <= Pours, not 13 of 12"]) :-
    theory_error("fact(a).\nheld(a2, no_spill, 13, 12).\n", Line, Expected).

test(an_explored_fact_of_another_arity_is_refused, [Line, Expected] == [1, "expected explored(Antecedent, Proposition), not a explored/1 fact"]) :-
    theory_error("explored(a2).\n", Line, Expected).

:- end_tests(theory_files).
