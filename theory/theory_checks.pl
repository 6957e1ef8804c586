:- module(theory_checks,
          [ check_general_rules/2,  % +Name, +LineFacts
            unknown_lines/2,        % +LineFacts, -Unknown
            unknown_names/2,        % +Rows, -Unknown
            written_lines/2         % +LineFacts, -Written
          ]).
/** <module> The checks of a theory of pouring's files made once

What a file of a theory of pouring says that its reader cannot refuse
but the vocabulary can: a general rule (=|provenance(R, layer,
general)|=) whose body names no proposition, whose head is no
expectation or whose evidence is out of range (an error), and a name no
rule of the theory and nothing of the vocabulary knows (a warning).
ask.pl's load_theories/3 makes these checks of every file it reads, as
written or a stand-in for a file Python read (its facts at the lines
Python read them: written_lines/2, unknown_names/2), so that each is
written here alone, its message theory/check_messages.pl's. The file's
facts come as Line-Fact pairs (theory_files.pl's read_theory_file/2).
*/

:- use_module(theory_files).
:- use_module(vocabulary).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(assoc)).
:- use_module(library(ordsets)).

%!  written_lines(+LineFacts:list, -Written:list) is det.
%
%   The rule/3, body/2 and provenance/3 facts of a stand-in, Line-Fact, at
%   the lines of the file it stands for (its written_at/4 facts; line 0
%   for a fact they do not place).
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

%!  check_general_rules(+Name, +LineFacts:list) is det.
%
%   A general rule (=|provenance(R, layer, general)|=) of LineFacts
%   (Line-Fact, a file's) speaks the vocabulary's words: its body
%   propositions, its head an expectation; and its evidence is in range.
%
%   @error theory_error(Name, Line, Message) at the first that does not.
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

%!  unknown_lines(+LineFacts:list, -Unknown:list) is det.
%
%   [Line, What, LiteralName] by line for each literal of LineFacts
%   naming nothing of the vocabulary that the theory's own rules do not
%   use (a body none concludes, a head or fact no body uses): such a rule
%   never fires, or concludes nothing asked for.
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

