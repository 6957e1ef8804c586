:- module(theory_view,
          [ rule/3,                 % ?Id, ?Kind, ?Head
            body/2,                 % ?Id, ?Literal
            sup/2                   % ?Superior, ?Inferior
          ]).
/** <module> The current theory at the prompt

=|swipl theory/pantarhei.pl|= and =|pantarhei prolog|= import these into
the user module, so that =|?- rule(I, K, H).|= lists the rules of the
current theory (defeasible.pl's, as load_theory/1 made it). SWI-Prolog 9
has a rule/3 of its own (the rules of =|=>|= clauses), which this one
stands in place of where it is imported.
*/

:- use_module(defeasible, []).

:- redefine_system_predicate(rule(_, _, _)).

%!  rule(?Id, ?Kind, ?Head) is nondet.
%
%   A rule of the current theory: Kind is =strict=, =defeasible= or
%   =defeater=, Head a literal.
rule(Id, Kind, Head) :- defeasible:rule(Id, Kind, Head).

%!  body(?Id, ?Literal) is nondet.
%
%   A literal of the body of rule Id.
body(Id, Literal) :- defeasible:body(Id, Literal).

%!  sup(?Superior, ?Inferior) is nondet.
%
%   Superior is said to beat Inferior (sup/2 facts; specificity aside).
sup(Superior, Inferior) :- defeasible:sup(Superior, Inferior).
