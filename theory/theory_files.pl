:- module(theory_files,
          [ load_theory_facts/2,       % +File, +Module
            read_theory_file/2,        % +File, -LineFacts
            check_theory_fact/2,       % +Fact, -Problem
            term_text/2,               % +Term, -Text
            theory_error_message/2,    % +Error, -Message
            error_message/2            % +Error, -Message
          ]).
/** <module> Reading theory files: the facts of a theory, and errors as one line

A theory file is written in the language of fact_reader.pl (the common
subset of Prolog and ASP), whose predicates this module exports too
(read_fact_file/2, load_facts/2, check_fact/1, check_message/3). This
module checks what the facts of a theory must be besides: each theory
predicate (fact/1, rule/3, body/2, sup/2, learned/1, setting/2,
provenance/3, explored/2, held/4) of its form, a rule name given once,
every body/2 of a rule; writes a term back as native text (term_text/2,
as Python writes it); and says an error in one line: a
=|theory_error(File, Line, Expected)|= as =|File:Line: Expected|=
(theory_error_message/2), any other error as SWI-Prolog says it
(error_message/2).
*/

:- reexport(fact_reader, except([add_fact/2])).
:- use_module(fact_reader, [add_fact/2]).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(assoc)).

%!  load_theory_facts(+File, +Module) is det.
%
%   As load_facts/2, for a theory: the facts of its predicates (fact/1,
%   rule/3, body/2, sup/2, learned/1, setting/2, provenance/3, explored/2,
%   held/4) must also be
%   of their forms (check_theory_fact/2), a rule name is given once, and
%   every body/2 belongs to a rule. Facts of other predicates are read and
%   checked but not added: one named like a built-in (=|halt.|=,
%   =|call(a).|=) is data like any other, as Python's reader keeps it.
%
%   @error theory_error(File, Line, Expected) naming the first offence.
load_theory_facts(File, Module) :-
    read_theory_file(File, LineFacts),
    forall(( member(_-F, LineFacts), functor(F, Name, Arity), theory_form(Name, _, Arity) ),
           add_fact(Module, F)).

%!  read_theory_file(+File, -LineFacts:list) is det.
%
%   The facts of a theory file as Line-Fact pairs in file order, checked
%   as load_theory_facts/2 checks them.
%
%   @error theory_error(File, Line, Expected) naming the first offence.
read_theory_file(File, LineFacts) :-
    read_fact_file(File, LineFacts),
    empty_assoc(Rules0),
    foldl(check_theory_line(File), LineFacts, Rules0, Rules),
    (   member(Line-body(R, _), LineFacts),
        \+ get_assoc(R, Rules, _)
    ->  check_message(dangling_body, [R, R, R], M),
        throw(theory_error(File, Line, M))
    ;   true
    ).

check_theory_line(File, Line-Fact, Rules0, Rules) :-
    (   check_theory_fact(Fact, Problem)
    ->  throw(theory_error(File, Line, Problem))
    ;   true
    ),
    (   Fact = rule(R, _, _)
    ->  (   get_assoc(R, Rules0, _)
        ->  check_message(second_rule, [R], M),
            throw(theory_error(File, Line, M))
        ;   put_assoc(R, Rules0, Line, Rules)
        )
    ;   Rules = Rules0
    ).

%!  check_theory_fact(+Fact, -Problem:string) is semidet.
%
%   Problem says how Fact, a fact of a theory predicate as read_fact_file/2
%   gives it (its atoms are names), is not of its form; fails if it is
%   (or if it is of another predicate).
check_theory_fact(Fact, Problem) :-
    functor(Fact, Name, Arity),
    theory_form(Name, Form, _),
    (   \+ theory_form(Name, _, Arity)
    ->  check_message(arity, [Form, Name, Arity], Problem)
    ;   Fact =.. [_|Args],
        theory_names(Name, Ns),
        member(I, Ns), nth0(I, Args, A), \+ plain_name(A)
    ->  term_text(A, T),
        check_message(name_argument, [Form, T], Problem)
    ;   Fact = rule(R, K, _), \+ memberchk(K, [strict, defeasible, defeater])
    ->  term_text(K, T),
        check_message(kind, [R, T], Problem)
    ;   Fact = held(A, E, K, N), \+ ( integer(K), integer(N), 0 =< K, K =< N )
    ->  term_text(K, KT), term_text(N, NT),
        check_message(held, [A, E, KT, NT], Problem)
    ;   Fact = provenance(R, confidence_permille, C), \+ ( integer(C), between(1, 1000, C) )
    ->  term_text(C, T),            % some of its pours keep its head, or it concludes the other
        check_message(confidence, [R, T], Problem)
    ;   theory_literal_arg(Fact, L),
        literal_problem(L, Problem)
    ->  true
    ).

theory_form(fact, "fact(L)", 1).
theory_form(rule, "rule(Id, Kind, Head)", 3).
theory_form(body, "body(Id, L)", 2).
theory_form(sup, "sup(R1, R2)", 2).
theory_form(learned, "learned(Id)", 1).
theory_form(setting, "setting(Key, Value)", 2).
theory_form(provenance, "provenance(Id, Key, Value)", 3).
theory_form(explored, "explored(Antecedent, Proposition)", 2).
theory_form(held, "held(Antecedent, Expectation, Held, Pours)", 4).

theory_names(rule, [0]).
theory_names(body, [0]).
theory_names(sup, [0, 1]).
theory_names(learned, [0]).
theory_names(setting, [0]).
theory_names(provenance, [0, 1]).
theory_names(explored, [0, 1]).
theory_names(held, [0, 1]).
theory_names(fact, []).

theory_literal_arg(fact(L), L).
theory_literal_arg(rule(_, _, L), L).
theory_literal_arg(body(_, L), L).

% (every atom read_fact_file/2 gives is a name: lower_name/1)
plain_name(A) :- atom(A).

literal_problem(L, Problem) :-
    (   L = neg(neg(_))
    ->  term_text(L, T),
        check_message(double_negation, [T], Problem)
    ;   \+ literal(L)
    ->  term_text(L, T),
        check_message(literal, [T], Problem)
    ).

literal(neg(A)) :- !, literal_atom(A).
literal(A) :- literal_atom(A).

literal_atom(A) :- atom(A), !.
literal_atom(A) :-
    compound(A),
    compound_name_arguments(A, _, Args),
    constants(Args).

constants([]).
constants([X|Xs]) :- ( integer(X) -> true ; atom(X) ), constants(Xs).

%!  term_text(+Term, -Text:string) is det.
%
%   Term as native text, as Python writes it (model.term_text): names and
%   integers as they are, text quoted and escaped, terms =|name(a,b)|=.
term_text(T, Text) :-
    string(T), !,
    string_codes(T, Cs),
    foldl(escape_code, Cs, Out, []),
    string_codes(S, Out),
    string_concat("\"", S, S1),
    string_concat(S1, "\"", Text).
term_text(T, Text) :-
    compound(T), !,
    compound_name_arguments(T, N, Args),
    maplist(term_text, Args, Ts),
    atomic_list_concat(Ts, ',', Inner),
    format(string(Text), "~w(~w)", [N, Inner]).
term_text(T, Text) :-
    format(string(Text), "~w", [T]).

escape_code(0'\\, [0'\\, 0'\\|T], T) :- !.
escape_code(0'", [0'\\, 0'"|T], T) :- !.
escape_code(0'\n, [0'\\, 0'n|T], T) :- !.
escape_code(C, [C|T], T).

:- multifile prolog:message//1.

%   A theory_error/3 printed by print_message/2 (plain swipl loading a bad
%   theory): its one line, not "Unknown message".
prolog:message(theory_error(File, Line, Expected)) -->
    [ '~w:~w: ~w'-[File, Line, Expected] ].

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
