:- module(proof_words,
          [ proof_text/2,           % +Proof, -Text
            rebuttal_text/2,        % +Rebuttal, -Text
            reason_text/2           % +Reason, -Text
          ]).
/** <module> Proofs in words

A proof of queries:why/4 or queries:why_brief/4 (given, definite,
defeasible, not_concluded), its rebuttals and its reasons, put into
words: one sentence per step, a rule named with its body, arrow and head
as the current theory (theory_store.pl) has it.
*/

:- use_module(theory_store, [rule/3, rule_body/2]).
:- use_module(library(lists)).
:- use_module(library(apply)).

%!  proof_text(+Proof, -Text:string) is det.
%
%   Proof in words, one sentence per step, separated by "; ".
proof_text(Proof, Text) :-
    phrase_proof(Proof, Parts),
    atomic_list_concat(Parts, '; ', A),
    atom_string(A, Text).

phrase_proof(given(L), [P]) :-
    format(atom(P), "~w is given", [L]).
phrase_proof(definite(R, L, Ps), [P|Sub]) :-
    format(atom(P), "~w holds by the strict rule ~w", [L, R]),
    sub_texts(Ps, Sub).
phrase_proof(defeasible(R, L, Ps, Rebs), [P|More]) :-
    rule_words(R, RW),
    format(atom(P), "~w by rule ~w", [L, RW]),
    sub_texts(Ps, Sub),
    maplist(rebuttal_text, Rebs, RT),
    append(Sub, RT, More).
phrase_proof(not_concluded(L, Reasons), [P|RT]) :-
    format(atom(P), "~w is not concluded", [L]),
    maplist(reason_text, Reasons, RT).

sub_texts(Ps, Texts) :-
    foldl(sub_text, Ps, [], Rev), reverse(Rev, Texts).
sub_text(given(_), Acc, Acc) :- !.
sub_text(P, Acc, [T|Acc]) :- proof_text(P, S), atom_string(T, S).

rule_words(R, W) :-
    rule(R, K, H), rule_body(R, Bs),
    arrow(K, Arrow),
    atomic_list_concat(Bs, ', ', BT),
    (   Bs == []
    ->  format(atom(W), "~w (~w ~w)", [R, Arrow, H])
    ;   format(atom(W), "~w (~w ~w ~w)", [R, BT, Arrow, H])
    ).

arrow(strict, '->').
arrow(defeasible, '=>').
arrow(defeater, '~>').

%!  rebuttal_text(+Rebuttal, -Text:atom) is det.
%!  reason_text(+Reason, -Text:atom) is det.
%
%   A rebuttal of a defeasible proof, and a reason of a why-not, in
%   words (answer_words.pl says each part of a proof with them).
rebuttal_text(inapplicable(A, B), T) :-
    format(atom(T), "the opposing rule ~w does not apply (~w is not concluded)", [A, B]).
rebuttal_text(beaten(A, T0), T) :-
    format(atom(T), "the opposing rule ~w is overridden by ~w (~w > ~w)", [A, T0, T0, A]).
rebuttal_text(standing(A), T) :-
    format(atom(T), "the opposing rule ~w is beaten by the rules for it together", [A]).

reason_text(complement_definite(NL), T) :-
    format(atom(T), "its complement ~w is definitely true", [NL]).
reason_text(no_rule(L), T) :-
    format(atom(T), "no rule concludes ~w", [L]).
reason_text(blocked(R, B), T) :-
    rule_words(R, W),
    format(atom(T), "rule ~w does not apply: ~w is not concluded", [W, B]).
reason_text(undecided_body(R, B), T) :-
    rule_words(R, W),
    format(atom(T), "rule ~w may not apply: ~w is undecided", [W, B]).
reason_text(attacked(R, A), T) :-
    rule_words(A, W),
    format(atom(T), "rule ~w is opposed by rule ~w, which it does not override", [R, W]).
reason_text(conflict(A, B), T) :-
    rule_words(A, WA), rule_words(B, WB),
    format(atom(T), "rules ~w and ~w both apply and neither overrides the other", [WA, WB]).
reason_text(no_rule_either(L, NL), T) :-
    format(atom(T), "no rule concludes ~w or ~w", [L, NL]).
reason_text(complement_concluded(NL, R), T) :-
    (   R == fact
    ->  format(atom(T), "its complement ~w is given", [NL])
    ;   rule_words(R, W)
    ->  format(atom(T), "its complement ~w is concluded by rule ~w", [NL, W])
    ;   format(atom(T), "its complement ~w is concluded", [NL])
    ).
reason_text(overridden(A, B), T) :-
    rule_words(A, WA), rule_words(B, WB),
    format(atom(T), "rule ~w applies but is overridden by ~w", [WA, WB]).
reason_text(none_applies(L, NL), T) :-
    format(atom(T), "no rule for ~w or ~w applies", [L, NL]).
reason_text(nearest(R, Ms), T) :-
    rule_words(R, W),
    maplist(missing_text, Ms, MTs),
    atomic_list_concat(MTs, ', ', MT),
    format(atom(T), "rule ~w also needs ~w", [W, MT]).
reason_text(looping(L), T) :-
    format(atom(T), "the support for ~w is ambiguous or circular", [L]).

missing_text(missing(B, V, P), T) :-
    (   V == undefined
    ->  format(atom(T), "~w (undecided)", [B])
    ;   P == none
    ->  T = B
    ;   format(atom(T), "~w (instead of ~w)", [B, P])
    ).
