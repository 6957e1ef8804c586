:- module(curiosity_plane_steps,
          [ plane_step_trace/8,       % +Best, +Followed, +I-Id, +Cand, +Sim, +Added, +Left, -Trace
            general_layer_if_asked/3, % +Facts, +Settings, -General
            general_layer_header/1    % -Lines
          ]).
/** <module> What the curiosities that follow planes share

The discovering and the paper's curiosity (discover.pl, paper.pl) both
follow a plane after each batch: the line of the trace that says so, and
the second layer of their theory, the general rules learned from every
pour (unless general(false)).
*/

:- use_module(library(lists)).
:- use_module(modify).
:- use_module(writer).

%!  plane_step_trace(+Best:dict, +Followed, +Step, +Cand, +Sim:dict, +Added:list,
%!                   +Left:integer, -Trace:dict) is det.
%
%   Trace is the step I-Id (the iteration and the id of the antecedent
%   Cand it explored) as the trace holds it: what was explored, its
%   simulations (Sim, the reply of exploration_simulate), the best plane
%   (plane_trace/3), what was added to A_new and how many are in it
%   (Left). Followed is true when the curiosity follows the plane.
plane_step_trace(Best, Followed, I1-Id, cand(Props, Parent, Via), Sim, Added, Left, Trace) :-
    findall(P, member(cand(P, _, _), Added), AddedProps),
    plane_trace(Best, Followed, BestT),
    format(string(ViaText), "~w", [Via]),
    Trace = _{iteration:I1, id:Id, antecedent:Props, parent:Parent, via:ViaText,
              simulations:Sim.simulations, failed:Sim.failed,
              best:BestT, added:AddedProps, a_new:Left}.

%   plane_trace(+Best, +Followed, -BestT): the best plane in the trace:
%   its antecedent, expectation, slope and mean score, and the five
%   largest components of its direction when it is followed.
plane_trace(Best, Followed, BestT) :-
    dict_pairs(Best.gradient, _, Gradient),
    findall(_{parameter:X, component:G},
            ( Followed == true,
              direction(Gradient, Best.mean, D), top(D, 5, Top), member(X-G, Top) ),
            Dir),
    BestT = _{antecedent:Best.antecedent, expectation:Best.expectation,
              slope:Best.slope, mean:Best.mean, direction:Dir}.

%!  general_layer_if_asked(+Facts:list, +Settings:dict, -General:list) is det.
%
%   General is the general layer after Algorithm 1's rules Facts
%   (general_layer/3 of writer.pl) when Settings ask for it (general(true),
%   the default), else empty.
general_layer_if_asked(Facts, Settings, General) :-
    (   Settings.general == true
    ->  general_layer(Facts, Settings, General)
    ;   General = []
    ).

%!  general_layer_header(-Lines:list) is det.
%
%   The header of the general layer in the theory file (layer_header of
%   the curiosity's theory_layout).
general_layer_header([ "% General rules, learned from every pour of the exploration",
                       "% and the learner's own pours (bridge/learning/gaps.py), by",
                       "% bridge/learning/generalize.py: a default per expectation and the",
                       "% contrasts that move it. provenance(Id, support, N): the pours whose",
                       "% description holds the body; kept: how many of them keep the head;",
                       "% confidence_permille: P(head | body), the share of the pours sampled",
                       "% for the body (the rest an ordinary pour) that keep the head.",
                       "% sup/2 below orders both layers (see bridge/learning/layers.py)." ]).
