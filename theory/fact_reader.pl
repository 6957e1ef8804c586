:- module(fact_reader,
          [ read_fact_file/2,          % +File, -LineFacts
            load_facts/2,              % +File, +Module
            check_fact/1,              % +Term
            check_message/3,           % +Key, +Args, -Message
            add_fact/2                 % +Module, +Fact
          ]).
/** <module> The language of theory files: the common subset of Prolog and ASP

Every theory file of the project (the vocabulary, the constraints, learned
and hand-written theories) is a list of ground facts that both SWI-Prolog
and clingo read the same way: ASCII text; facts =|name.|= or
=|name(Arg, ...).|=, where an argument is a name (=|[a-z][A-Za-z0-9_]*|=),
an integer in decimal from -2147483648 to 2147483647 (what clingo holds),
quoted text ("...", with =|\\|=, =|\"|= and =|\n|= as its only escapes) or
a term of those; =|%|= starts a comment. No directives (=|:- ...|=,
=|#include|=, =|#script|=), rules, variables, lists, floats, operators,
quoted atoms or block comments: a theory file is data.

This module reads such a file term by term with read_term/3, checks each
term against the text it was read from (so that =|'a'|=, =|0x1F|= or
=|"\x41\"|=, which SWI-Prolog reads but clingo does not, are refused), and
adds the facts to a module. Python reads the same language
(bridge/theories/facts.py): both refuse the same files with the same
message (its words theory/check_messages.pl's, check_message/3), naming
the line where the offending fact starts (or of the offending byte). A
malformed file raises =|theory_error(File, Line, Expected)|=, which
theory_files:theory_error_message/2 turns into one line
=|File:Line: Expected|=. What the facts of a theory must be besides is
theory_files.pl's.
*/

:- use_module(library(readutil)).
:- use_module(library(lists)).
:- use_module(library(apply)).

%!  load_facts(+File, +Module) is det.
%
%   Read the ground facts of File into Module (as dynamic clauses), after
%   checking that each is in the common subset of Prolog and ASP.
%
%   @error theory_error(File, Line, Expected) if a term is malformed.
load_facts(File, Module) :-
    read_fact_file(File, LineFacts),
    forall(member(_-F, LineFacts), add_fact(Module, F)).

%!  add_fact(+Module, +Fact) is det.
%
%   Add Fact to Module as a dynamic clause (its predicate made dynamic if
%   Module has none of its name and arity).
add_fact(Module, Fact) :-
    functor(Fact, Name, Arity),
    (   current_predicate(Module:Name/Arity)
    ->  true
    ;   dynamic(Module:Name/Arity)
    ),
    assertz(Module:Fact).

%!  read_fact_file(+File, -LineFacts:list) is det.
%
%   The facts of File as Line-Fact pairs in file order, Line where the
%   fact starts.
%
%   @error theory_error(File, Line, Expected) if File is not of the
%   language (see the module comment).
read_fact_file(File, LineFacts) :-
    (   exists_file(File)
    ->  true
    ;   check_message(no_such_file, [], M),
        throw(theory_error(File, 0, M))
    ),
    read_file_to_string(File, Text, [encoding(octet)]),
    check_bytes(File, Text),
    setup_call_cleanup(
        open_string(Text, In),
        read_facts(In, Text, File, LineFacts),
        close(In)).

% check_bytes(+File, +Text): every byte printable ASCII, tab, newline or
% carriage return.
check_bytes(File, Text) :-
    bad_bytes(Bad),
    split_string(Text, Bad, "", [First|_]),
    string_length(First, N0),
    string_codes(Nul, [0]),
    (   once(sub_string(Text, Z, 1, _, Nul)), Z < N0
    ->  N = Z                           % (split_string/4 stops at a NUL separator)
    ;   N = N0
    ),
    string_length(Text, Len),
    (   N =:= Len
    ->  true
    ;   N1 is N + 1,
        string_code(N1, Text, C),
        sub_string(Text, 0, N, _, Before),
        split_string(Before, "\n", "", Lines),
        length(Lines, Line),
        format(string(Byte), "0x~|~`0t~16r~2+", [C]),
        check_message(not_ascii, [Byte], M),
        throw(theory_error(File, Line, M))
    ).

bad_bytes(Bad) :-                       % (without NUL: see check_bytes/2)
    numlist(1, 255, All),
    exclude(good_byte, All, Codes),
    string_codes(Bad, Codes).

good_byte(C) :- C >= 0x20, C =< 0x7e, !.
good_byte(0'\t).
good_byte(0'\n).
good_byte(0'\r).

read_facts(In, Text, File, Facts) :-
    skip_layout(In),
    peek_char(In, C0),
    (   C0 == end_of_file
    ->  Facts = []
    ;   line_count(In, Line),
        catch(read_term(In, Term, [subterm_positions(Pos), syntax_errors(error),
                                    double_quotes(string), comments(Comments)]),
              error(syntax_error(_), _),
              Term = '$syntax_error'),
        (   C0 == '#'
        ->  check_message(hash_directive, [], M),
            throw(theory_error(File, Line, M))
        ;   Term == '$syntax_error'
        ->  check_message(expected_fact, [], M),
            throw(theory_error(File, Line, M))
        ;   catch(( check_fact_text(Term, Pos, Comments, Text), Expected = none ),
                  bad_fact(Expected), true),
            Expected \== none
        ->  throw(theory_error(File, Line, Expected))
        ;   Facts = [Line-Term|Rest],
            read_facts(In, Text, File, Rest)
        )
    ).

% skip_layout(+In): past white space and % comments, to the next fact.
skip_layout(In) :-
    peek_char(In, C),
    (   C == end_of_file
    ->  true
    ;   char_type(C, space)
    ->  get_char(In, _), skip_layout(In)
    ;   C == '%'
    ->  skip(In, 0'\n), skip_layout(In)
    ;   true
    ).

% check_fact_text(+Term, +Pos, +Comments, +Text): Term, read at Pos from
% Text, is a fact of the language.
check_fact_text(Term, Pos, Comments, Text) :-
    term_start(Pos, Start),
    (   member(CPos-C, Comments), sub_string(C, 0, 2, _, "/*"),
        stream_position_data(char_count, CPos, At), At < Start
    ->  bad(expected)
    ;   true
    ),
    check_top(Term),
    check_text(Pos, Term, Text, top-0),
    (   member(_-C, Comments), sub_string(C, 0, 2, _, "/*")
    ->  bad(expected)
    ;   true
    ).

term_start(From-_, From) :- !.
term_start(P, From) :- compound(P), arg(1, P, From), integer(From), !.
term_start(_, 0).

% bad(+Check), bad(+Check, +Args): raise bad_fact(Message), the message
% of Check (theory/check_messages.pl; expected: expected_fact).
bad(expected) :- !, bad(expected_fact, []).
bad(Check) :- bad(Check, []).
bad(Check, Args) :-
    check_message(Check, Args, M),
    throw(bad_fact(M)).

% check_top(+Term): Term, as read, is no directive and no rule (a
% variable is check_text/4's to say).
check_top(Term) :-
    (   var(Term)
    ->  true
    ;   check_clause(Term)
    ).

% check_clause(+Term): Term (bound) is no directive and no rule.
check_clause(Term) :-
    (   Term = (:- _)
    ->  bad(directive)
    ;   Term = (?- _)
    ->  bad(directive)
    ;   Term = (_ :- _)
    ->  bad(rule_not_fact)
    ;   true
    ).

% check_text(+Pos, +Term, +Text, +Where-Depth): Term is written in Text as
% the language writes it (an unquoted name, a decimal integer, "..." with
% the three escapes, name(...) without layout before the parenthesis),
% nested at most nesting_at_most/1 deep (Depth: the terms it lies in).
check_text(_, T, _, _) :-
    var(T), !,
    bad(variable).
check_text(_, T, _, _) :-
    float(T), !,
    bad(float).
check_text(_, T, _, _) :-
    ( T == [] ; T = [_|_] ), !,
    bad(list).
check_text(_-_, not, _, _) :-
    !,
    bad(not_name).
check_text(From-To, T, Text, Where-_) :-
    !,
    (   atom(T)
    ->  atom_length(T, N),
        (   To - From =:= N, lower_name(T) -> true ; bad(expected) )
    ;   integer(T), Where == arg
    ->  Len is To - From,
        sub_string(Text, From, Len, _, Raw),
        check_integer(Raw, T)
    ;   bad(expected)
    ).
check_text(string_position(From, To), T, Text, arg-_) :-
    string(T), !,
    Len is To - From,
    sub_string(Text, From, Len, _, Raw),
    string_codes(Raw, Codes),
    (   phrase(quoted(Escapes), Codes)
    ->  (   Escapes == ok -> true
        ;   bad(text_escape)
        )
    ;   bad(expected)
    ).
check_text(term_position(From, _, From, FTo, ArgsPos), T, Text, _-Depth) :-
    compound(T),
    compound_name_arguments(T, Name, Args),
    Args \== [],
    atom_length(Name, N),
    FTo - From =:= N,
    lower_name(Name),
    sub_string(Text, FTo, 1, _, "("),
    !,
    (   Name == not
    ->  bad(not_name)
    ;   true
    ),
    (   nesting_at_most(Most), Depth >= Most
    ->  bad(nesting, [Most])
    ;   Depth1 is Depth + 1
    ),
    foldl(check_arg_text(Text, Depth1), ArgsPos, Args, 0, _).
check_text(_, _, _, _) :-
    bad(expected).

check_arg_text(Text, Depth, Pos, Arg, N, N1) :-
    N1 is N + 1,
    check_text(Pos, Arg, Text, arg-Depth).

% nesting_at_most(-Most): how deep a term may nest (a theory's facts nest
% two or three deep), so that every reader after this one may recurse on
% terms: default(nesting_at_most, Most) of defaults.pl beside this file,
% read when this module loads (as bridge/theories/facts.py reads it), the
% file itself without the bound, which is not known yet.
:- dynamic nesting_at_most/1.

load_nesting_bound :-
    prolog_load_context(directory, Dir),
    directory_file_path(Dir, 'defaults.pl', File),
    retractall(nesting_at_most(_)),
    read_fact_file(File, LineFacts),
    memberchk(_-default(nesting_at_most, Most), LineFacts),
    assertz(nesting_at_most(Most)).

check_integer(Raw, N) :-
    (   string_codes(Raw, Cs),
        ( Cs = [0'-|Ds] -> true ; Ds = Cs ),
        Ds \== [],
        forall(member(D, Ds), code_type(D, digit(_))),
        forall(member(D, Ds), D =< 0'9)
    ->  integer_shown(Raw, Shown),
        (   N >= -2147483648, N =< 2147483647
        ->  (   number_string(N, Raw) , format(string(Raw), "~d", [N])
            ->  true
            ;   bad(int_form, [Shown])
            )
        ;   bad(int_range, [Shown])
        )
    ;   bad(expected)
    ).

% integer_shown(+Raw, -Shown): an integer's text as a message shows it:
% whole up to 24 characters, a longer one by its ends and its number of
% digits (as bridge/theories/facts.py).
integer_shown(Raw, Shown) :-
    string_length(Raw, L),
    (   L =< 24
    ->  Shown = Raw
    ;   sub_string(Raw, 0, 12, _, Head),
        sub_string(Raw, _, 4, 0, Tail),
        (   sub_string(Raw, 0, 1, _, "-") -> D is L - 1 ; D = L ),
        format(string(Shown), "~s...~s (~d digits)", [Head, Tail, D])
    ).

% quoted(-Escapes)// : "..." whose escapes are \\, \" and \n (Escapes = ok),
% or others too (Escapes = bad).
quoted(E) --> [0'"], quoted_codes(ok, E), [0'"].

quoted_codes(E0, E) --> [0'\\, C], !,
    { memberchk(C, [0'\\, 0'", 0'n]) -> E1 = E0 ; E1 = bad },
    quoted_codes(E1, E).
quoted_codes(E0, E) --> [C], { C \== 0'", C \== 0'\\ }, !, quoted_codes(E0, E).
quoted_codes(E, E) --> [].

%!  check_fact(+Term) is det.
%
%   Succeed if Term, as read, is a fact in the common subset of Prolog and
%   ASP (check_fact_text/4 checks how it was written as well).
%
%   @error bad_fact(Expected) saying what was expected instead.
check_fact(Term) :-
    (   var(Term)
    ->  bad(variable)
    ;   true
    ),
    check_clause(Term),
    (   Term = [_|_]
    ->  bad(list)
    ;   Term == []
    ->  bad(list)
    ;   callable(Term)
    ->  true
    ;   bad(expected)
    ),
    (   compound(Term)
    ->  compound_name_arguments(Term, _, Args),
        maplist(check_arg, Args)
    ;   true
    ).

check_arg(A) :- var(A), !,
    bad(variable).
check_arg(A) :- integer(A), !.
check_arg(A) :- string(A), !.
check_arg(A) :- float(A), !,
    bad(float).
check_arg(A) :- ( A == [] ; A = [_|_] ), !,
    bad(list).
check_arg(A) :- atom(A), !.
check_arg(A) :- compound(A), !,
    compound_name_arguments(A, _, Args),
    maplist(check_arg, Args).
check_arg(_) :-
    bad(expected).

% lower_name(+Atom): [a-z][A-Za-z0-9_]*, in ASCII.
lower_name(Name) :-
    atom_codes(Name, [C|Cs]),
    C >= 0'a, C =< 0'z,
    name_codes(Cs).

name_codes([]).
name_codes([C|Cs]) :-
    (   C >= 0'a, C =< 0'z -> true
    ;   C >= 0'0, C =< 0'9 -> true
    ;   C =:= 0'_ -> true
    ;   C >= 0'A, C =< 0'Z
    ),
    name_codes(Cs).

%!  check_message(+Key, +Args:list, -Message:string) is det.
%
%   The message of the check Key of a theory file, from its one text in
%   theory/check_messages.pl (which Python reads too:
%   pantarhei.theory.check_message), with Args in place of its ~w.
check_message(Key, Args, Message) :-
    once(check_messages:check_message(Key, Format)),
    format(string(Message), Format, Args).

load_check_messages :-
    prolog_load_context(directory, Dir),
    directory_file_path(Dir, 'check_messages.pl', File),
    load_facts(File, check_messages).

:- load_check_messages.

:- load_nesting_bound.
