:- module(answer_words,
          [ answers/3,              % +Scene, +Options, -Answers
            evidence/4,             % +Rule, +Expectation, +Scene, -Evidence
            named_rule/2,           % +Rule, -Named
            rule_in_words/2,        % +Rule, -Text
            proof_json/2            % +Proof, -Dict
          ]).
/** <module> Answers in words, with their evidence in one voice

The answers `pantarhei ask` gives (ask.pl re-exports this module): one per
expectation with the deciding rule in words, the likelihood that the
expectation holds (the rule's estimate, pooled from every pour) and the
pours of the rule's body counted for the expectation holding, whatever
the polarity of the rule's head; and the argument of `--why` as a
structure (proof_json/2).
*/

:- use_module(defeasible, []).
:- use_module(queries).
:- use_module(proof_words, []).
:- use_module(vocabulary).
:- use_module(theory_files, [term_text/2]).
:- use_module(learned_rules, [verdict/3]).
:- use_module(library(lists)).
:- use_module(library(apply)).


%!  answers(+Scene:list, +Options:list, -Answers:list) is det.
%
%   One =|answer(Expectation, Value, Likelihood, Rule, Because, Reason,
%   Evidence)|= per expectation, in the vocabulary's order:
%   queries:what_happens/3's outcome, with Rule the rule to name for it
%   (named_rule/2; =none= for an undecided expectation), Because why the
%   answer is what it is in one line ("because " and the deciding rule in
%   words, "given", or for an undecided expectation "why not: " and the
%   nearest reason), Reason the brief why-not of an undecided one
%   (queries:explain_brief/4; "" for the others) and Evidence the pours
%   behind the answer (evidence/4).
answers(Scene, Options, Answers) :-
    what_happens(Scene, Options, Outcomes),
    maplist(answer(Scene, Options), Outcomes, Answers).

answer(Scene, Options, outcome(E, V, P, R0),
       answer(E, V, P, R, Because, Reason, Evidence)) :-
    (   V == unknown
    ->  explain_brief(Scene, E, Options, Reason),
        atomic_list_concat([_|Rest0], '; ', Reason),
        (   Rest0 == [] -> Rest = [Reason] ; Rest = Rest0 ),
        atomic_list_concat(Rest, '; ', Nearest),
        format(string(Because), "why not: ~w", [Nearest]),
        R = R0, Evidence = none
    ;   Reason = "",
        named_rule(R0, R),
        (   memberchk(R, [fact, none])
        ->  Because = "given", Evidence = none
        ;   evidence(R, E, Scene, Evidence),
            because(R, V, Evidence, Because)
        )
    ).

% because(+Rule, +Value, +Evidence, -Because): why an answer of Value
% that Rule decides is what it is, in one line: the rule in words, with
% the pours of the antecedent asked when it was explored, else of the
% rule's body, and the propositions asked that no rule of their own
% decides.
because(R, V, explored(_, Of, Held, N, _, _), Because) :- !,
    rule_said(R, Where, Said),
    where(Of, Asked),
    Share is Held / N,
    (   Share >= 0.5 -> V0 = holds ; V0 = fails ),
    verdict(V0, Share, Seen),
    (   Seen == V
    ->  format(string(Agree), "its pours agree with rule ~w", [R])
    ;   format(string(Agree), "rule ~w decides, though its pours differ", [R])
    ),
    format(string(Because),
           "because ~w~w; held in ~w of ~w pours of ~w (explored, no rule of its own: ~w)",
           [Where, Said, Held, N, Asked, Agree]).
because(R, _, Evidence, Because) :-
    rule_in_words(R, Words),
    unruled_words(Evidence, Unruled),
    format(string(Because), "because ~w~w", [Words, Unruled]).

%!  evidence(+Rule, +Expectation, +Scene, -Evidence) is det.
%
%   The pours behind an answer that Rule decides, counted for the
%   Expectation holding (the polarity of the likelihood shown beside the
%   answer, whatever the rule's head):
%   =|pours(Held, Of, Body, Unruled)|=, Held of the Of pours learned from
%   that could have been drawn for the rule's Body (its provenance
%   support and kept, the latter counting the pours that keep its head),
%   Unruled the propositions of the Scene that the rule's body does not
%   hold (the rule answers for them as for its body: no rule of their own
%   decides); or =|none(Body, Unruled)|= for a rule that records no pours
%   (a rule written by hand, or one of Algorithm 1's). Where the Scene
%   holds more than the rule's body and is an explored antecedent A
%   (explored/2, with held/4 facts of some pours for the Expectation), it
%   is =|explored(A, Scene, Held, Of, Body, Unruled)|=: Held of the Of
%   pours that could have been drawn for the Scene, as the theory records
%   them.
evidence(R, E, Scene, Evidence) :-
    rule_body_set(R, Body),
    msort(Scene, Scene1),
    list_to_set(Scene1, SceneSet),
    subtract(SceneSet, Body, Unruled),
    (   Unruled \== [],
        explored_antecedent(SceneSet, A),
        defeasible:held(A, E, Held, Of), integer(Of), Of > 0
    ->  Evidence = explored(A, SceneSet, Held, Of, Body, Unruled)
    ;   defeasible:provenance(R, support, S), integer(S),
        defeasible:provenance(R, kept, K), integer(K),
        defeasible:rule(R, _, H)
    ->  (   H == neg(E) -> Held is S - K ; Held = K ),
        Evidence = pours(Held, S, Body, Unruled)
    ;   Evidence = none(Body, Unruled)
    ).

% explored_antecedent(+Props, -A): A is an explored antecedent that says
% exactly the propositions Props (a sorted set, not empty).
explored_antecedent([P|Ps], A) :-
    defeasible:explored(A, P),
    findall(Q, defeasible:explored(A, Q), Qs0),
    sort(Qs0, Qs),
    Qs == [P|Ps],
    !.

rule_body_set(R, Body) :-
    findall(B, defeasible:body(R, B), Bs0),
    list_to_set(Bs0, Body).

% unruled_words(+Evidence, -Text): "" or, for the scene's propositions
% that the deciding rule's body does not hold, that no rule of their own
% decides the answer.
unruled_words(Evidence, Text) :-
    (   ( Evidence = pours(_, _, Body, Unruled) ; Evidence = none(Body, Unruled) ),
        Unruled \== []
    ->  maplist(gloss, Unruled, Gs),
        atomic_list_concat(Gs, ', ', Said),
        where(Body, Where),
        (   Unruled = [_] -> Own = "its own decides this, so it is"
        ;   Own = "their own decides this, so they are"
        ),
        format(string(Text), "; ~w: no rule of ~w answered as ~w", [Said, Own, Where])
    ;   Text = ""
    ).

%!  named_rule(+Rule, -Named) is det.
%
%   The rule to name for a conclusion that Rule decides: where Rule is one
%   of Algorithm 1's and the general layer has a rule with the same body
%   and head (the empty body, when the priors were explored), the first
%   such general rule, which ranks above it and whose evidence is every
%   pour; Rule itself otherwise.
named_rule(R, Named) :-
    (   \+ defeasible:provenance(R, layer, general),
        defeasible:rule(R, _, H),
        defeasible:rule_body(R, Bs),
        defeasible:rule(G, _, H), G \== R,
        defeasible:provenance(G, layer, general),
        defeasible:rule_body(G, Bs)
    ->  Named = G
    ;   Named = R
    ).

%!  rule_in_words(+Rule, -Text:string) is det.
%
%   The deciding rule in words, its evidence in one voice: its body's
%   glosses (or "an ordinary pour" for the empty body), the likelihood
%   that its expectation holds in such pours (the estimate pooled from
%   every pour), and the pours of its body counted for the expectation
%   holding, e.g. "pour from the side: holds in 2% of such pours (the
%   pooled estimate); held in 0 of 12 pours of pour from the side (rule
%   g5_no_spill)".
rule_in_words(R, Text) :-
    (   defeasible:rule(R, _, H)
    ->  rule_body_set(R, Body),
        rule_said(R, Where, Said),
        literal_atom(H, E),
        evidence_words(R, E, Body, Ev),
        (   Ev == "" -> Also = " (" ; format(string(Also), "; ~w (", [Ev]) ),
        format(string(Text), "~w~w~wrule ~w)", [Where, Said, Also, R])
    ;   format(string(Text), "~w", [R])
    ).

% rule_said(+Rule, -Where, -Said): the rule's body in words, and the
% likelihood that its expectation holds in such pours ("" for none).
rule_said(R, Where, Said) :-
    defeasible:rule(R, _, H),
    rule_body_set(R, Body),
    where(Body, Where),
    queries:likelihood(R, H, P),
    (   P == none
    ->  Said = ""
    ;   percent(P, Pc),
        doubt_words(R, Why),
        format(string(Said), ": holds in ~w% of such pours (the pooled estimate)~w", [Pc, Why])
    ).

% doubt_words(+Rule, -Text): why the learner doubted the answer of the
% rules of the body's parts and wrote this rule (its doubt provenance,
% bridge/learning/doubts.py), "" for a rule it did not doubt.
doubt_words(R, Text) :-
    (   defeasible:provenance(R, doubt, D),
        doubt_text(D, R, Text0)
    ->  format(string(Text), "; ~w", [Text0])
    ;   Text = ""
    ).

doubt_text(unsettled, _, "maybe: the rules of its parts disagree, and too few of its own pours tell").
doubt_text(parts_disagree, _, "the rules of its parts disagree, and its own pours tell").
doubt_text(pours_contradict, _, "its own pours depart from what the rules of its parts say").
doubt_text(few_pours_depart, _, "maybe: too few of its own pours tell, and each of them departs from what the rules of its parts say").
doubt_text(beside_interaction, R, Text) :-
    findall(B, defeasible:provenance(R, beside, B), Bs),
    where(Bs, Where),
    format(string(Text), "maybe: beside ~w, whose pours depart from what its parts do, and too few of its own pours tell", [Where]).

% where(+Body, -Text): a body in words, "an ordinary pour" for the empty one.
where(Body, Where) :-
    maplist(gloss, Body, Gs),
    (   Gs == [] -> Where = "an ordinary pour" ; atomic_list_concat(Gs, ', ', Where) ).

gloss(B, G) :-
    (   proposition(B, _, _, G0) -> G = G0 ; term_text(B, G) ).

% percent(+Share, -Percent): 100 x Share to the nearest integer, a half
% to the even one (as the share is shown beside the answer).
percent(P, Pc) :-
    X is 100 * P,
    F is floor(X),
    (   X - F =:= 0.5
    ->  (   F mod 2 =:= 0 -> Pc = F ; Pc is F + 1 )
    ;   Pc is round(X)
    ).

% evidence_words(+Rule, +Expectation, +Body, -Text): the pours behind a
% learned rule counted for the expectation holding ("" when it records
% none).
evidence_words(R, E, Body, Text) :-
    (   evidence(R, E, [], pours(Held, S, _, _))
    ->  (   S == 0
        ->  Text = "no such pour simulated: estimated from the pours nearby"
        ;   Body == []
        ->  format(string(Text), "held in ~w of ~w ordinary pours", [Held, S])
        ;   where(Body, Where),
            format(string(Text), "held in ~w of ~w pours of ~w", [Held, S, Where])
        )
    ;   defeasible:provenance(R, antecedent, A)
    ->  format(string(Text), "the weighted pours of ~w", [A])
    ;   \+ defeasible:learned(R)
    ->  Text = "written by hand: no pours recorded"
    ;   Text = ""
    ).

%!  proof_json(+Proof, -Dict) is det.
%
%   A proof of queries:why/4 as a dict for JSON: =kind= (given, definite,
%   defeasible or not_concluded), =literal= and =text= (its words, as
%   proof_text/2 says them), and as the kind has them =rule= (the rule that
%   concludes it), =body= (the proofs of its body's literals),
%   =rebuttals= (each rule for the complement and why it does not win) or
%   =reasons= (why it is not concluded), each with =kind=, =rules= (the
%   rules it names), =literals= (those it names) and =text=.
proof_json(Proof, Dict) :-
    proof_text(Proof, Text0),
    atomic_list_concat([Text|_], '; ', Text0),
    proof_parts(Proof, Kind, L, Parts),
    term_text(L, LT),
    dict_pairs(Dict, json, [kind-Kind, literal-LT, text-Text|Parts]).

proof_parts(given(L), given, L, []).
proof_parts(definite(R, L, Ps), definite, L, [rule-R, body-Js]) :-
    maplist(proof_json, Ps, Js).
proof_parts(defeasible(R, L, Ps, Rebs), defeasible, L, [rule-R, body-Js, rebuttals-RJs]) :-
    maplist(proof_json, Ps, Js),
    maplist(part_json(rebuttal_text), Rebs, RJs).
proof_parts(not_concluded(L, Reasons), not_concluded, L, [reasons-RJs]) :-
    maplist(part_json(reason_text), Reasons, RJs).

% part_json(+Words, +Part, -Dict): a rebuttal or reason: its kind, the
% rules and literals it names, and its words (proof_words:Words/2).
part_json(Words, Part, _{kind:Kind, rules:Rules, literals:Literals, text:Text}) :-
    Part =.. [Kind|Args],
    partition(is_rule, Args, Rules0, Others),
    maplist(term_text, Rules0, Rules),
    findall(T, ( member(A, Others), \+ is_list(A), term_text(A, T) ), Ls0),
    findall(T, ( member(A, Others), is_list(A), member(X, A), term_text(X, T) ), Ls1),
    append(Ls0, Ls1, Literals),
    (   catch(proof_words:call(Words, Part, Text0), _, fail) -> Text = Text0 ; term_text(Part, Text) ).

is_rule(A) :- atom(A), defeasible:rule(A, _, _).

literal_atom(neg(A), A) :- !.
literal_atom(A, A).

