:- use_module(theory_files).
:- use_module(plunit_helpers).

:- begin_tests(theory_files).

write_tmp(Text, File) :-
    text_file(Text, File).

load_error(Text, Line, Expected) :-
    write_tmp(Text, File),
    catch(load_facts(File, plunit_scratch), theory_error(File, Line, Expected), true),
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

:- end_tests(theory_files).
