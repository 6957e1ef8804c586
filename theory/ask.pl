:- module(ask,
          [ load_theories/2,        % +Files, -Warnings
            load_theories/3,        % +Files, +Options, -Warnings
            unknown_names/2,        % +Rows, -Unknown
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

These are the one check of a theory file's general rules, of its names
and of its superiority relation's cycles: the theories Python reads (a
DFL file, or the files of a command that reasons in Python) are handed
here as such stand-ins (bridge/theories/prolog_checks.py).
*/

:- use_module(theory_files).
:- use_module(default_values).
:- use_module(vocabulary).
:- use_module(validity).
:- use_module(defeasible).
:- use_module(queries).
:- reexport(answer_words).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(assoc)).
:- use_module(library(ordsets)).
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

% written_lines(+LineFacts, -Written): the rule/3, body/2 and provenance/3
% facts of a stand-in at the lines of the file it stands for (its
% written_at/4 facts; line 0 for a fact they do not place).
written_lines(LineFacts, Written) :-
    findall(Key-L, ( member(_-written_at(L, K, R, X), LineFacts), written_key(K, R, X, Key) ),
            Pairs0),
    msort(Pairs0, Sorted),
    sort(1, @<, Sorted, Pairs),         % the first line of each (sort/4 keeps the first)
    list_to_assoc(Pairs, Lines),
    findall(L-F, ( member(_-F, LineFacts), fact_key(F, Key),
                   ( get_assoc(Key, Lines, L) -> true ; L = 0 ) ), Written).

written_key(rule, R, _, rule(R)).
written_key(body, R, B, body(R, B)).
written_key(provenance, R, K, provenance(R, K)).
written_key(sup, A, B, sup(A, B)).

fact_key(rule(R, _, _), rule(R)).
fact_key(body(R, B), body(R, B)).
fact_key(provenance(R, K, _), provenance(R, K)).

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

% check_general_rules(+Name, +LineFacts): a general rule speaks the
% vocabulary's words, and its evidence is in range.
check_general_rules(Name, LineFacts) :-
    findall(R, member(_-provenance(R, layer, general), LineFacts), General0),
    sort(General0, General),
    (   General == []
    ->  true
    ;   bodies_by_rule(LineFacts, Bodies),
        forall(( member(Line-rule(R, _, H), LineFacts), ord_memberchk(R, General) ),
               check_general_rule(Name, Bodies, Line, R, H)),
        evidence_by_rule(LineFacts, Evidence),
        forall(( member(R, General), get_assoc(R, Evidence, Facts),
                 member(Key, [confidence_permille, support, kept]),
                 last(Facts, R, Key, V) ),
               check_evidence(Name, Facts, R, Key, V))
    ).

% evidence_by_rule(+LineFacts, -Evidence): an assoc of each rule's
% Line-provenance(R, Key, V) facts of its evidence, in file order.
evidence_by_rule(LineFacts, Evidence) :-
    findall(R-(Line-provenance(R, K, V)),
            ( member(Line-provenance(R, K, V), LineFacts),
              memberchk(K, [confidence_permille, support, kept]) ),
            Pairs0),
    sort(1, @=<, Pairs0, Pairs),
    group_pairs_by_key(Pairs, Grouped),
    list_to_assoc(Grouped, Evidence).

% last(+Facts, +R, +Key, -V): the value the last provenance(R, Key, V)
% of Facts gives.
last(Facts, R, Key, V) :-
    findall(V0, member(_-provenance(R, Key, V0), Facts), Vs),
    last(Vs, V).

check_general_rule(Name, Bodies, Line, R, H) :-
    rule_bodies(Bodies, R, LineBodies),
    (   member(BLine-B, LineBodies), \+ proposition(B, _, _, _)
    ->  term_text(B, BT),
        check_message(general_body, [R, BT], M),
        throw(theory_error(Name, BLine, M))
    ;   literal_atom(H, E), \+ expectation(E, _, _)
    ->  term_text(E, ET),
        check_message(general_head, [R, ET], M),
        throw(theory_error(Name, Line, M))
    ;   true
    ).

% bodies_by_rule(+LineFacts, -Bodies): an assoc of each rule's body
% literals, Line-Literal in file order, the first line of each literal.
bodies_by_rule(LineFacts, Bodies) :-
    findall(R-(Line-B), member(Line-body(R, B), LineFacts), Pairs0),
    sort(1, @=<, Pairs0, Pairs),
    group_pairs_by_key(Pairs, Grouped0),
    maplist(first_lines, Grouped0, Grouped),
    list_to_assoc(Grouped, Bodies).

first_lines(R-LineBodies0, R-LineBodies) :-
    empty_assoc(Seen),
    first_line(LineBodies0, Seen, LineBodies).

% first_line(+LineBodies0, +Seen, -LineBodies): each literal once, at its
% first line (the literals seen in an assoc: a body of 20,000 literals
% searched a list for each).
first_line([], _, []).
first_line([Line-B|T], Seen, Out) :-
    (   get_assoc(B, Seen, _)
    ->  Out = Rest, Seen1 = Seen
    ;   Out = [Line-B|Rest], put_assoc(B, Seen, t, Seen1)
    ),
    first_line(T, Seen1, Rest).

rule_bodies(Bodies, R, LineBodies) :-
    (   get_assoc(R, Bodies, LineBodies) -> true ; LineBodies = [] ).

check_evidence(Name, LineFacts, R, Key, V) :-
    (   Key == confidence_permille, \+ ( integer(V), between(0, 1000, V) )
    ->  term_text(V, T),
        Check = general_confidence, Args = [R, T]
    ;   memberchk(Key, [support, kept]), \+ ( integer(V), V >= 0 )
    ->  term_text(V, T),
        Check = general_count, Args = [R, Key, T]
    ;   Key == kept, last(LineFacts, R, support, S), integer(S), V > S
    ->  Check = general_kept, Args = [R, V, S]
    ;   fail
    ),
    !,
    memberchk(Line-provenance(R, Key, _), LineFacts),
    check_message(Check, Args, M),
    throw(theory_error(Name, Line, M)).
check_evidence(_, _, _, _, _).

%!  unknown_names(+Rows:list, -Unknown:list) is det.
%
%   unknown_lines/2 of a theory Python read (a DFL file, or one a command
%   reasons with in Python), Rows its facts at the lines read: =|[Line,
%   rule|body|fact, R, Literal]|=, a literal as a term or its text (rows
%   of other kinds, provenance and sup, are passed over).
unknown_names(Rows, Unknown) :-
    must_be(list, Rows),
    convlist(row_fact, Rows, LineFacts),
    unknown_lines(LineFacts, Unknown).

% row_fact(+Row, -LineFact): a row of a literal (none of provenance/3 or
% sup/2, which name none) as the fact it says.
row_fact([Line, Kind, R, L0], Line-F) :-
    memberchk(Kind, [rule, body, fact]),
    (   compound(L0) -> L = L0 ; term_string(L, L0) ),
    memberchk(Kind-F, [rule-rule(R, defeasible, L), body-body(R, L), fact-fact(L)]).

% unknown_lines(+LineFacts, -Unknown): [Line, What, LiteralName] by line for
% each literal naming nothing of the vocabulary that the theory's own rules do
% not use (a body none concludes, a head or fact no body uses): such a rule
% never fires, or concludes nothing asked for.
unknown_lines(LineFacts, Unknown) :-
    findall(A, ( member(_-F, LineFacts), concluded(F, L), literal_atom(L, A) ), C0),
    set_assoc(C0, Concluded),
    findall(A, ( member(_-body(_, L), LineFacts), literal_atom(L, A) ), U0),
    set_assoc(U0, Used),
    bodies_by_rule(LineFacts, Bodies),
    findall(Line-W, unknown_name(LineFacts, Bodies, Concluded, Used, Line, W), Pairs),
    sort(1, @=<, Pairs, Sorted),
    findall([Line, What, T], member(Line-unknown(What, T), Sorted), Unknown).

% set_assoc(+List, -Assoc): the members of List as the keys of an assoc.
set_assoc(List, Assoc) :-
    sort(List, Set),
    findall(X-t, member(X, Set), Pairs),
    list_to_assoc(Pairs, Assoc).

concluded(rule(_, _, H), H).
concluded(fact(F), F).

unknown_name(LineFacts, Bodies, Concluded, Used, Line, unknown(What, T)) :-
    member(RLine-F, LineFacts),
    (   F = rule(R, _, H),
        (   rule_bodies(Bodies, R, LineBodies),
            member(Line-B, LineBodies), literal_atom(B, A),
            \+ known_name(A), \+ get_assoc(A, Concluded, _),
            format(string(What), "rule ~w: body", [R])
        ;   literal_atom(H, A), \+ known_name(A), \+ get_assoc(A, Used, _),
            Line = RLine,
            format(string(What), "rule ~w: head", [R])
        )
    ;   F = fact(L), literal_atom(L, A), \+ known_name(A), \+ get_assoc(A, Used, _),
        Line = RLine, What = "fact"
    ),
    term_text(A, T).

known_name(A) :- atom(A), ( proposition(A, _, _, _) -> true ; expectation(A, _, _) ).

literal_atom(neg(A), A) :- !.
literal_atom(A, A).

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

