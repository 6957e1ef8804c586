:- module(ask,
          [ load_theories/2,        % +Files, -Warnings
            load_theories/3,        % +Files, +Options, -Warnings
            serve/0
          ]).
/** <module> Asking a theory of pouring: `pantarhei ask` in one crossing

`pantarhei ask` turns words into propositions (Python) and hands them to
this module, which does the rest on the theory files as written: reads
them (theory_files.pl's validating reader, several files merged), checks
them as a theory of pouring, answers each of the nine expectations and
puts the deciding rule into words (answer_words.pl, re-exported: answers/3,
named_rule/2, rule_in_words/2, proof_json/2). serve/0 is the door `pantarhei ask`
uses: one swipl process reads the files once and answers one request a
line from standard input (see serve/0 for the protocol).

A file is given as its path, or as =|file(Path, Name)|= to name it Name in
errors and warnings, or =|file(Path, Name, checked)|= when the file read is
a stand-in for another that was read and checked already (a DFL file that
Python read and wrote out natively): then only what concerns the merged
theory is checked, with its general rules and its names at the lines of
Name that its =|written_at(Line, Kind, Id, What)|= facts give (Kind
rule, body or fact and What its literal, as unknown_names/2 reads them;
provenance and What the key; sup and What the rule beaten).

These are the one check of a theory file's general rules and names
(theory_checks.pl), of its sup/2 pairs and of its superiority relation's
cycles: the theories Python reads (a DFL file, or the files of a command
that reasons in Python) are handed here as such stand-ins
(bridge/theories/prolog_checks.py).
*/

:- use_module(theory_files).
:- use_module(theory_checks).
:- use_module(default_values).
:- use_module(vocabulary).
:- use_module(validity).
:- use_module(defeasible).
:- use_module(queries).
:- reexport(answer_words).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(option)).
:- use_module(library(http/json)).

                 /*******************************
                 *        READING THEORIES      *
                 *******************************/

%!  load_theories(+Files:list, -Warnings:list) is det.
%
%   Make the facts of Files (native theory files, merged: a learned theory
%   and rules added by hand) the current theory of defeasible.pl, checked
%   as a theory of pouring: each file not empty; a general rule (its
%   =|provenance(R, layer, general)|=) of the vocabulary's propositions and
%   expectations, with evidence in range; a rule name defined in one file
%   only; sup/2 naming rules; the superiority relation acyclic. Warnings
%   holds =|unknown(Where, What, Name)|= for each of unknown_lines/2.
%
%   @error theory_error(Name, Line, Message), Line 0 where no line is meant.
load_theories(Files, Warnings) :-
    load_theories(Files, [], Warnings).

%!  load_theories(+Files:list, +Options:list, -Warnings:list) is det.
%
%   load_theories/2 with Options: =|sup_names(false)|= lets sup/2 name a
%   rule the files do not define (a file of hand-added rules converted
%   alone, whose sup/2 may name the rules of another).
load_theories(Files, Options, Warnings) :-
    must_be(list, Files),
    maplist(file_name, Files, Named),
    maplist(read_theory, Named, Read),
    maplist(check_read, Read, Warnings0),
    append(Warnings0, Warnings),
    clear_theory,
    forall(append(Earlier, [File|_], Read), add_file(File, Earlier)),
    (   option(sup_names(false), Options) -> true ; check_sup_names(Read) ),
    defeasible:prepare,
    (   defeasible:superiority_cycle(Cycle)
    ->  clear_theory,
        Cycle = [A, B|_],
        sup_line(Read, A, B, Name, Line),
        defeasible:cycle_message(Cycle, M),
        throw(theory_error(Name, Line, M))
    ;   true
    ).

file_name(file(Path, Name, Kind), file(Path, Name, Kind)) :- !.
file_name(file(Path, Name), file(Path, Name, file)) :- !.
file_name(Path, file(Path, Path, file)).

% read_theory(+file(Path, Name, Kind), -read(Name, LineFacts, Kind)):
% errors name Name.
read_theory(file(Path, Name, Kind), read(Name, LineFacts, Kind)) :-
    catch(once(( defeasible:check_size(Path), read_theory_file(Path, LineFacts) )),
          theory_error(_, Line, M),
          throw(theory_error(Name, Line, M))).

% check_read(+read(Name, LineFacts, Kind), -Warnings): one file's own checks;
% of a stand-in (=checked= before) its general rules and its names, at the
% lines of its written_at/4 facts.
check_read(read(Name, LineFacts, checked), Warnings) :- !,
    written_lines(LineFacts, Written),
    check_general_rules(Name, Written),
    findall([L, K, R, Lit], member(_-written_at(L, K, R, Lit), LineFacts), Rows),
    unknown_names(Rows, Unknown),
    named_lines(Name, Unknown, Warnings).
check_read(read(Name, LineFacts, _), Warnings) :-
    (   member(_-F, LineFacts), \+ aside(F)
    ->  true
    ;   check_message(empty_theory, [], M),
        throw(theory_error(Name, 0, M))
    ),
    check_general_rules(Name, LineFacts),
    unknown_lines(LineFacts, Unknown),
    named_lines(Name, Unknown, Warnings).

named_lines(Name, Unknown, Warnings) :-
    findall(unknown(Where, What, T), ( member([Line, What, T], Unknown),
                                       format(string(Where), "~w:~w", [Name, Line]) ), Warnings).

% aside(+Fact): a fact that alone makes no theory (it says something of a
% rule).
aside(body(_, _)).
aside(learned(_)).
aside(provenance(_, _, _)).

% add_file(+Read, +Earlier): its facts added to the current theory; a
% rule name defined by one of the files read before it (Earlier) is
% refused.
add_file(read(Name, LineFacts, _), Earlier) :-
    forall(member(Line-F, LineFacts), add_line(Name, Earlier, Line, F)).

add_line(Name, Earlier, Line, F) :-
    (   F = rule(R, _, _), defeasible:rule(R, _, _)
    ->  once(( member(read(Other, Facts, _), Earlier), memberchk(_-rule(R, _, _), Facts) )),
        check_message(already_defined, [R, Other], M),
        throw(theory_error(Name, Line, M))
    ;   F = fact(L), defeasible:fact(L)
    ->  true
    ;   add_theory_fact(F)
    ).

check_sup_names(Read) :-
    forall(( member(read(Name, LineFacts, Kind), Read), member(Line0-sup(A, B), LineFacts),
             member(X, [A, B]), \+ defeasible:rule(X, _, _) ),
           ( written_line(Kind, LineFacts, Line0, A, B, Line),
             check_message(sup_not_a_rule, [A, B, X], M),
             throw(theory_error(Name, Line, M)) )).

sup_line(Read, A, B, Name, Line) :-
    (   member(read(Name, LineFacts, Kind), Read), memberchk(Line0-sup(A, B), LineFacts)
    ->  written_line(Kind, LineFacts, Line0, A, B, Line)
    ;   Read = [read(Name, _, _)|_], Line = 0
    ).

% written_line(+Kind, +LineFacts, +Line0, +A, +B, -Line): the line of the
% file as written that says sup(A, B): Line0 of a file read as written; of
% a stand-in, the line its written_at(Line, sup, A, B) fact gives (0 if
% none does).
written_line(checked, LineFacts, _, A, B, Line) :- !,
    (   memberchk(_-written_at(Line, sup, A, B), LineFacts) -> true ; Line = 0 ).
written_line(_, _, Line, _, _, Line).

                 /*******************************
                 *            SERVING           *
                 *******************************/

%!  serve is det.
%
%   `pantarhei ask`'s door. The theory files are the command line's
%   arguments after =|--|=, two for each: =|file:Path|= (or
%   =|checked:Path|= for a stand-in checked before) and the name to say
%   for it (see the module comment). Reads them (load_theories/2) and says, one line each,
%   =|warning<TAB>Where<TAB>What<TAB>Name|= for each unknown name and then
%   =|loaded|= or =|error<TAB>Message|=. Then reads one request a line,
%   =|answer(Scene).|= or =|why(Scene, Literal).|=, until the end of
%   input, and replies with lines ending in =|end|=:
%   =|invalid<TAB>Constraint<TAB>P1<TAB>P2|= for each violated constraint
%   (nothing more then), =|error<TAB>Message|= when the theory was not
%   read, else =|answer<TAB>E<TAB>V<TAB>P<TAB>R<TAB>Because<TAB>Reason<TAB>Held<TAB>Of<TAB>Body<TAB>Unruled<TAB>Explored<TAB>Counted|=
%   per expectation (evidence_fields/7), or =|why<TAB>Text|=.
serve :-
    current_prolog_flag(argv, Argv),
    (   append(_, ['--'|Args], Argv) -> true ; Args = Argv ),
    file_args(Args, Files),
    catch(( load_theories(Files, Warnings), Loaded = true ),
          E, ( error_line(E, Loaded) )),
    (   Loaded == true
    ->  forall(member(unknown(W, What, N), Warnings),
               format("warning\t~w\t~w\t~w~n", [W, What, N])),
        format("loaded~n")
    ;   format("error\t~w~n", [Loaded])
    ),
    flush_output,
    serve_requests(Loaded).

file_args([], []).
file_args([Arg, Name|Args], [file(Path, Name, Kind)|Files]) :-
    sub_atom(Arg, B, _, A, ':'), !,
    sub_atom(Arg, 0, B, _, Kind), sub_atom(Arg, _, A, 0, Path),
    file_args(Args, Files).

error_line(theory_error(Name, 0, M), Line) :- !,
    format(string(Line), "~w: ~w", [Name, M]).
error_line(E, Line) :-
    error_message(E, Line).

% evidence_fields(+Evidence, -Held, -Of, -Body, -Unruled, -Explored, -Counted):
% an answer's evidence as the reply's fields (none for no count, lists
% comma-joined): Held of Of pours counted of the propositions Counted
% (the explored antecedent Explored asked, or none and the rule's Body).
evidence_fields(none, none, none, '', '', none, '').
evidence_fields(pours(H, S, B, U), H, S, BT, UT, none, BT) :-
    atomic_list_concat(B, ',', BT), atomic_list_concat(U, ',', UT).
evidence_fields(none(B, U), none, none, BT, UT, none, BT) :-
    atomic_list_concat(B, ',', BT), atomic_list_concat(U, ',', UT).
evidence_fields(explored(A, Of, H, N, B, U), H, N, BT, UT, A, OfT) :-
    atomic_list_concat(B, ',', BT), atomic_list_concat(U, ',', UT),
    atomic_list_concat(Of, ',', OfT).

serve_requests(Loaded) :-
    read_term(user_input, Request, []),
    (   Request == end_of_file
    ->  true
    ;   catch(reply(Request, Loaded), E,
              ( error_message(E, M), format("error\t~w~n", [M]) )),
        format("end~n"),
        flush_output,
        serve_requests(Loaded)
    ).

reply(Request, Loaded) :-
    arg(1, Request, Scene),
    findall(v(C, P1, P2), violation(Scene, C, P1, P2), Vs0),
    sort(Vs0, Vs),
    (   Vs \== []
    ->  forall(member(v(C, P1, P2), Vs), format("invalid\t~w\t~w\t~w~n", [C, P1, P2]))
    ;   Loaded \== true
    ->  format("error\t~w~n", [Loaded])
    ;   Request = answer(_)
    ->  answers(Scene, [], As),
        forall(member(answer(E, V, P, R, Because, Reason, Evidence), As),
               ( evidence_fields(Evidence, Held, Of, Body, Unruled, Explored, Counted),
                 format("answer\t~w\t~w\t~w\t~w\t~w\t~w\t~w\t~w\t~w\t~w\t~w\t~w~n",
                        [E, V, P, R, Because, Reason, Held, Of, Body, Unruled,
                         Explored, Counted]) ))
    ;   Request = why(_, Literal)
    ->  why(Scene, Literal, [], Proof),
        proof_text(Proof, Text),
        format("why\t~w~n", [Text]),
        proof_json(Proof, Dict),
        atom_json_dict(Json, Dict, [width(0)]),
        format("proof\t~w~n", [Json])
    ).

