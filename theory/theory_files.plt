:- use_module(theory_files).
:- use_module(plunit_helpers).

:- begin_tests(theory_files).

write_tmp(Text, File) :-
    text_file(Text, File).

load_error(Text, Line, Expected) :-
    write_tmp(Text, File),
    catch(load_facts(File, plunit_scratch), theory_error(File, Line, Expected), true),
    delete_file(File).

theory_error(Text, Line, Expected) :-
    write_tmp(Text, File),
    catch(load_theory_facts(File, plunit_scratch), theory_error(File, Line, Expected), true),
    delete_file(File).

test(facts_are_loaded, X-T == f(a, -3)-"some text") :-
    write_tmp("p(f(a, -3), \"some text\").\n", File),
    load_facts(File, plunit_loaded),
    plunit_loaded:p(X, T),
    delete_file(File).

test(a_float_is_refused, [Line, Expected] == [2, "an integer, not a float (use integer units such as mm or permille)"]) :-
    load_error("a(1).\nb(1.5).\n", Line, Expected).

test(a_list_is_refused, Line == 1) :-
    load_error("a([1,2]).\n", Line, _).

test(a_rule_is_refused, Expected == "a fact, not a rule") :-
    load_error("a(1).\nb(X) :- a(X).\n", _, Expected).

test(a_variable_is_refused, [Line, Expected] == [3, "a ground fact (no variables)"]) :-
    load_error("a(1).\n\nb(X).\n", Line, Expected).

test(a_quoted_atom_is_refused, Line == 1) :-
    load_error("a('Hello world').\n", Line, _).

test(a_syntax_error_names_its_line, Line == 2) :-
    load_error("a(1).\nb(1,.\n", Line, _).

test(message_is_one_line, M == "f.pl:3: a fact, not a rule") :-
    theory_error_message(theory_error('f.pl', 3, "a fact, not a rule"), M).

test(error_message_of_a_theory_error, M == "f.pl:3: a fact") :-
    error_message(theory_error('f.pl', 3, "a fact"), M).

test(error_message_of_another_error, M == "atom_length/2: Arguments are not sufficiently instantiated") :-
    catch(atom_length(_, _), E, true),
    error_message(E, M).

test(an_include_is_refused, [Line, Expected] == [2, "a fact, not a directive (#include, #script, ...): a theory file is data"]) :-
    load_error("a(1).\n#include \"other.pl\".\n", Line, Expected).

test(a_directive_is_refused, Expected == "a fact, not a directive: a theory file is data") :-
    load_error(":- initialization(halt).\n", _, Expected).

test(an_integer_clingo_cannot_hold_is_refused, Expected == "an integer from -2147483648 to 2147483647, not 3000000000") :-
    load_error("size(3000000000).\n", _, Expected).

test(an_integer_of_thousands_of_digits_is_shown_by_its_ends, [Line, Expected] == [2, "an integer from -2147483648 to 2147483647, not 999999999999...9999 (5001 digits)"]) :-
    length(Ds, 5001), maplist(=(0'9), Ds), string_codes(Big, Ds),
    format(string(Text), "a(1).\nsize(~s).\n", [Big]),
    load_error(Text, Line, Expected).

test(an_integer_in_another_notation_is_refused, Line == 1) :-
    load_error("a(0x1F).\n", Line, _).

test(a_non_ascii_byte_names_its_line, [Line, Expected] == [3, "byte 0xc3 is not printable ASCII: a theory file is ASCII text (no other characters, no invalid UTF-8)"]) :-
    load_error("a(1).\n\n% caf\u00e9\n", Line, Expected).

test(an_escape_clingo_does_not_read_is_refused, Expected == "quoted text with \\\\, \\\" and \\n as its only escapes") :-
    load_error("a(\"x\\ty\").\n", _, Expected).

test(quoted_text_keeps_its_escapes, T == "a\"b\nc") :-
    write_tmp("p(\"a\\\"b\\nc\").\n", File),
    load_facts(File, plunit_text),
    plunit_text:p(T),
    delete_file(File).

test(an_error_names_the_line_where_the_fact_starts, Line == 2) :-
    load_error("a(1).\nb(1,\n  2,\n  'x').\n", Line, _).

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

% a check's message is theory/check_messages.pl's text with its arguments
test(check_message_from_the_table, M == "the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic") :-
    check_message(superiority_cycle, ['r1 > r2 > r1'], M).

test(check_message_of_no_check, fail) :-
    check_message(no_such_check, [], _).

:- end_tests(theory_files).
