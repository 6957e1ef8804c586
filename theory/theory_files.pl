:- module(theory_files,
          [ load_facts/2,              % +File, +Module
            check_fact/1,              % +Term
            theory_error_message/2,    % +Error, -Message
            error_message/2            % +Error, -Message
          ]).
/** <module> Reading theory files: the common subset of Prolog and ASP

Every theory file of the project (the vocabulary, the constraints, learned
and hand-written theories) is a list of ground facts that both SWI-Prolog
and clingo read: atoms written as plain identifiers, integers, quoted text
("..."), and compound terms of those. No lists, no floats, no operators, no
quoted atoms, no rules.

This module reads such a file term by term, checks each term, and adds the
facts to a module. A malformed file raises
=|theory_error(File, Line, Expected)|=, which theory_error_message/2 turns
into one line =|File:Line: Expected|=.
*/

:- use_module(library(readutil)).

%!  load_facts(+File, +Module) is det.
%
%   Read the ground facts of File into Module (as dynamic clauses), after
%   checking that each is in the common subset of Prolog and ASP.
%
%   @error theory_error(File, Line, Expected) if a term is malformed.
load_facts(File, Module) :-
    (   exists_file(File)
    ->  true
    ;   throw(theory_error(File, 0, "no such file"))
    ),
    setup_call_cleanup(
        open(File, read, In),
        read_facts(In, File, Facts),
        close(In)),
    forall(member(F, Facts), add_fact(Module, F)).

add_fact(Module, Fact) :-
    functor(Fact, Name, Arity),
    (   current_predicate(Module:Name/Arity)
    ->  true
    ;   dynamic(Module:Name/Arity)
    ),
    assertz(Module:Fact).

read_facts(In, File, Facts) :-
    catch(read_term(In, Term, [term_position(Pos), syntax_errors(error),
                                double_quotes(string), variable_names(Vs)]),
          error(syntax_error(What), Context),
          syntax_error_line(File, What, Context)),
    (   Term == end_of_file
    ->  Facts = []
    ;   stream_position_data(line_count, Pos, Line),
        catch((check_fact(Term), Expected = none), bad_fact(Expected), true),
        (   Expected \== none
        ->  throw(theory_error(File, Line, Expected))
        ;   Vs \== []
        ->  throw(theory_error(File, Line, "a ground fact (no variables)"))
        ;   Facts = [Term|Rest]
        ),
        read_facts(In, File, Rest)
    ).

syntax_error_line(File, What, Context) :-
    (   Context = stream(_, Line, _, _)
    ->  true
    ;   Context = file(_, Line, _, _)
    ->  true
    ;   Line = 0
    ),
    format(string(Msg), "syntax error (~w): expected a fact such as name(arg, 1).", [What]),
    throw(theory_error(File, Line, Msg)).

%!  check_fact(+Term) is det.
%
%   Succeed if Term is a fact in the common subset of Prolog and ASP.
%
%   @error bad_fact(Expected) saying what was expected instead.
check_fact(Term) :-
    (   Term = (_ :- _)
    ->  throw(bad_fact("a fact, not a rule"))
    ;   Term = (:- _)
    ->  throw(bad_fact("a fact, not a directive"))
    ;   true
    ),
    (   callable(Term)
    ->  true
    ;   throw(bad_fact("a fact such as name(arg, 1)"))
    ),
    check_name(Term),
    Term =.. [_|Args],
    maplist(check_arg, Args).

check_arg(A) :- var(A), !,
    throw(bad_fact("a ground fact (no variables)")).
check_arg(A) :- integer(A), !.
check_arg(A) :- string(A), !.
check_arg(A) :- float(A), !,
    throw(bad_fact("an integer, not a float (use integer units such as mm or permille)")).
check_arg(A) :- is_list(A), !,
    throw(bad_fact("an atom, integer, text or term, not a list")).
check_arg(A) :- atom(A), !, check_name(A).
check_arg(A) :- compound(A), !,
    check_name(A),
    A =.. [_|Args],
    maplist(check_arg, Args).
check_arg(_) :-
    throw(bad_fact("an atom, integer, text or term")).

check_name(Term) :-
    functor(Term, Name, _),
    atom_codes(Name, [C|Cs]),
    (   code_type(C, lower),
        forall(member(X, Cs), code_type(X, csym))
    ->  true
    ;   format(string(Msg), "a name in lower case letters, digits and _, not '~w'", [Name]),
        throw(bad_fact(Msg))
    ).

%!  theory_error_message(+Error, -Message:string) is semidet.
%
%   The one-line message for a theory_error/3.
theory_error_message(theory_error(File, Line, Expected), Message) :-
    format(string(Message), "~w:~w: ~w", [File, Line, Expected]).

%!  error_message(+Error, -Message:string) is det.
%
%   One line for any error: that of theory_error_message/2 for a
%   theory_error/3, otherwise SWI-Prolog's own message for Error (its
%   lines joined by spaces), or the error term itself.
error_message(Error, Message) :-
    (   theory_error_message(Error, Message0)
    ->  true
    ;   catch('$messages':translate_message(Error, Lines, []), _, fail)
    ->  with_output_to(string(Text), print_message_lines(current_output, '', Lines)),
        split_string(Text, "\n", " \t", Parts0),
        exclude(==(""), Parts0, Parts),
        atomic_list_concat(Parts, ' ', Message0)
    ;   format(string(Message0), "~p", [Error])
    ),
    (   string(Message0) -> Message = Message0 ; atom_string(Message0, Message) ).
