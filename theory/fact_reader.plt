:- use_module(fact_reader).
:- use_module(plunit_helpers).

:- begin_tests(fact_reader).

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

% a check's message is theory/check_messages.pl's text with its arguments
% The bound on nesting is defaults.pl's: a fact whose terms nest as deep
% (the fact itself counted) is read, one deeper is refused with the bound
% in the message.
test(the_nesting_bound_is_the_default_s, Expected == M) :-
    defaults:default(nesting_at_most, Most),
    fact_reader:nesting_at_most(Most),
    Inner is Most - 1, nested(Inner, Deepest), nested_fact(Deepest, Fine),
    write_tmp(Fine, File), load_facts(File, plunit_nested), delete_file(File),
    nested(Most, Too), nested_fact(Too, Bad),
    load_error(Bad, 1, Expected),
    check_message(nesting, [Most], M).

nested(0, "a") :- !.
nested(N, T) :- N1 is N - 1, nested(N1, T1), format(string(T), "f(~s)", [T1]).
nested_fact(Term, Text) :- format(string(Text), "p(~s).~n", [Term]).

test(check_message_from_the_table, M == "the superiority relation has a cycle, r1 > r2 > r1: it must be acyclic") :-
    check_message(superiority_cycle, ['r1 > r2 > r1'], M).

test(check_message_of_no_check, fail) :-
    check_message(no_such_check, [], _).

:- end_tests(fact_reader).
