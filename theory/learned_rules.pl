:- module(learned_rules,
          [ rank_key/2,             % +Rule, -Key
            rank_order/2,           % +Rules, -Positions
            likelihood/3,           % +Confidence, +Literal, -Likelihood
            verdict/3,              % +Concluded, +Likelihood, -Value
            verdict/4,              % +Concluded, +Likelihood, +Band, -Value
            rule_id/3,              % +Antecedent, +Expectation, -Id
            antecedent_id/2         % ?Antecedent, ?Id
          ]).
/** <module> Learned rules: their rank, what they say, and their names

A learned rule =|B => H|= records the share of its pours that keep its
head, confidence_permille. Where two conflicting rules apply to one scene
and neither beats the other, the higher ranked one decides: the larger
body, then the general layer's, then the surer (confidence further from
one half), then the id (rank_key/2). The rules' likelihood is the share
of such pours in which the expectation holds (likelihood/3), and an
answer is uncertain where it lies within theory/defaults.pl's
uncertain_band of one half (verdict/3). Algorithm 1 names the
antecedents it explores by antecedent_id/2 and its rules by rule_id/3.
queries.pl answers by these predicates; the learner
(bridge/learning/general_rules.py) reads rank and verdict without calling
Prolog, under tests that keep its reading equal to these.
*/

:- use_module(default_values).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(assoc)).

%!  rank_key(+Rule, -Key) is det.
%
%   Rule is =|rule(Id, BodySize, Layer, Confidence)|=: Layer =general= for
%   the general layer's rules (any other atom for the rest), Confidence
%   the share of the body's pours that keep the head, a number from 0 to
%   1, or =none= when the rule records none (as one half). Of two rules,
%   the one with the larger Key in the standard order of terms ranks
%   higher. Key is =|k(BodySize, G, D, Id)|=: G is 1 for the general
%   layer, else 0; D is how far Confidence lies from one half, in
%   billionths, rounded to the nearest (half to even), so that a
%   confidence and its complement are equally sure.
rank_key(rule(Id, N, Layer, C), k(N, G, D, Id)) :-
    (   Layer == general -> G = 1 ; G = 0 ),
    (   number(C) -> distance(C, D) ; D = 0 ).

distance(C, D) :-
    Q is rational(abs(C - 0.5)) * 1000000000,
    F is floor(Q),
    R is Q - F,
    (   R > 1r2 -> D is F + 1
    ;   R < 1r2 -> D = F
    ;   D is F + F mod 2
    ).

%!  rank_order(+Rules:list, -Positions:list) is det.
%
%   Positions has, for each rule of Rules (as rank_key/2 takes it), its
%   place in the rank order of Rules, from 0 for the lowest: of two rules,
%   the one with the larger position ranks higher; equal keys, equal
%   positions. One call ranks a whole batch.
rank_order(Rules, Positions) :-
    maplist(rank_key, Rules, Keys),
    sort(Keys, Sorted),
    foldl(numbered, Sorted, Numbered, 0, _),
    list_to_assoc(Numbered, Assoc),
    maplist(position(Assoc), Keys, Positions).

numbered(K, K-I, I, I1) :- I1 is I + 1.

position(Assoc, K, P) :- get_assoc(K, Assoc, P).

%!  likelihood(+Confidence, +Literal, -Likelihood) is det.
%
%   Likelihood is the share of the pours in which the expectation holds,
%   for a rule whose head is Literal (E or neg(E)) and whose confidence is
%   Confidence, in permille; =none= for a rule that records none.
likelihood(C, L, P) :-
    (   number(C)
    ->  (   L = neg(_) -> P is (1000 - C) / 1000 ; P is C / 1000 )
    ;   P = none
    ).

%!  verdict(+Concluded, +Likelihood, -Value) is det.
%!  verdict(+Concluded, +Likelihood, +Band, -Value) is det.
%
%   Value is =uncertain= when the Likelihood that the expectation holds
%   lies within Band (by default theory/defaults.pl's uncertain_band) of
%   one half, and Concluded (=holds= or =fails=) otherwise, or when the
%   likelihood is =none=.
verdict(V0, P, V) :-
    once(default(uncertain_band, B)),
    verdict(V0, P, B, V).
verdict(V, none, _, V) :- !.
verdict(V0, P, B, V) :-
    (   abs(P - 0.5) < B - 1.0e-9 -> V = uncertain ; V = V0 ).

%!  rule_id(+Antecedent:integer, +Expectation, -Id) is det.
%
%   Id names Algorithm 1's rule for the Antecedent-th explored antecedent
%   (=|a<i>|=) and Expectation: =|r<i>_<E>|=.
rule_id(I, E, Id) :-
    atomic_list_concat([r, I, '_', E], Id).

%!  antecedent_id(+Antecedent:integer, -Id) is det.
%!  antecedent_id(-Antecedent:integer, +Id) is semidet.
%
%   Id names the Antecedent-th explored antecedent in provenance facts
%   and the trace: =|a<i>|=, i in decimal digits. Given Id, Antecedent is
%   its number; it fails for an atom that names no antecedent (=none=).
%   bridge/theories/model.py writes and reads the same names under a test
%   that keeps the two equal.
antecedent_id(I, Id) :-
    integer(I), !,
    format(atom(Id), "a~d", [I]).
antecedent_id(I, Id) :-
    atom(Id),
    atom_concat(a, Digits, Id),
    atom_codes(Digits, Cs),
    Cs \== [],
    maplist(ascii_digit, Cs),
    number_codes(I, Cs).

ascii_digit(C) :-
    between(0'0, 0'9, C).
