% The validity constraints on antecedents (sets of scene propositions).
%
% Read by SWI-Prolog and by clingo alike: ground facts only. Each constraint
% is written once here; theory/validity.pl (Prolog) and theory/violations.lp
% (ASP) derive their checks from these same facts.
%
% constraint(Name, Gloss): a named constraint, in words.
% conflict(Name, P1, P2): propositions P1 and P2 may not hold together,
%   because of constraint Name.
%
% Two constraints have no conflict facts: their pairs follow from the
% vocabulary itself. one_value_per_dimension forbids two propositions of one
% dimension; one_model_per_parameter forbids two propositions (of different
% dimensions) whose generative models draw the same parameter.

constraint(one_value_per_dimension, "the values of one dimension exclude each other").
constraint(one_model_per_parameter, "two propositions cannot both set the same parameter").
constraint(inside_destination, "the source cannot be below the destination's rim unless it is far from the destination: it would be inside the destination's wall").

conflict(inside_destination, start_below_rim, start_centred).
conflict(inside_destination, start_below_rim, start_near_rim).
conflict(inside_destination, start_below_rim, start_to_side).
conflict(inside_destination, pour_below_rim, pour_centred).
conflict(inside_destination, pour_below_rim, pour_near_rim).
conflict(inside_destination, pour_below_rim, pour_to_side).
conflict(inside_destination, end_below_rim, end_centred).
conflict(inside_destination, end_below_rim, end_near_rim).
conflict(inside_destination, end_below_rim, end_to_side).
