:- module(curiosity_explore,
          [ explore/1,                % +Options
            explore_result/2          % +Options, -Result
          ]).
/** <module> Running an exploration: explore/1

The entry of Algorithm 1: read the options (settings.pl), begin the
exploration on the oracle's side, run the loop (loop.pl) from a_0 or the
saved state (state.pl), qualify the explored antecedents and write the
learned theory (rules.pl), and end. An error ends the exploration on the
oracle's side too (aborted), then propagates.
*/

:- use_module(library(lists)).
:- use_module(bridge).
:- use_module(settings).
:- use_module(state).
:- use_module(loop).
:- use_module(rules).

%!  explore(+Options:list) is det.
%
%   Run Algorithm 1 and write the learned theory. Options (the defaults
%   of those marked * are in theory/defaults.pl):
%
%     - oracle(+Name)*: pybullet or synthetic
%     - max_rules(+N)*: stop after N explored antecedents (discover: the
%       pours of N batches, its batches and probes)
%     - samples(+N): simulations per explored antecedent (default: the
%       number of parameters plus one)
%     - curiosity(+Mode)*: discover or paper (see theory/curiosity.pl)
%     - queue(+N)*: A_new keeps the N most novel candidates (discover)
%     - jumps(+N)*: uniformly random valid antecedents drawn as candidates
%       each step (discover)
%     - threshold(+X)*: for discover, the significance level of the
%       permutation test (default significance_permille); for paper, the
%       slope below which nothing new is explored (default threshold_permille)
%     - permutations(+N)*: shuffles of the permutation test (discover)
%     - resample(+N)*: more batches of an antecedent whose planes are all
%       undecided and that queued nothing new (discover); max_rules then
%       counts batches
%     - novelty(+X)*: the estimated chance of a new behaviour, from 0 to 1,
%       a candidate needs to be queued, scaled by the probes' mean score
%       so far (discover; default novelty_permille)
%     - probe(+N)*: pours of a candidate's probe, 0 for none (discover)
%     - probe_attempts(+N)*: candidates probed at most in a step (discover)
%     - cover(+N)*: the last probe of a step goes to the candidate whose
%       rarest proposition the fewest pours so far hold, when fewer than N
%       do; 0 for never (discover)
%     - prior(+B)*: 1 to explore the priors (the empty antecedent, every
%       parameter from its prior, as a question's unsaid ones) with the
%       last batch of the budget, 0 not to (discover)
%     - seed(+S)*: seed of every random choice
%     - initial(+Props)*: a_0 (default_initial/1)
%     - breadth(+K)*: the paper's modify uses the K largest gradient components
%     - ridge(+X)*: L2 penalty of the plane fits (0 is plain least squares)
%     - qualify(+Mode)*: weighted or argmax (the paper's rule)
%     - out(+File)*: the learned theory (relative to theory/)
%     - store(+File): the SQLite store of simulations and state
%     - resume(+Bool): continue the saved exploration with these settings
%     - executor(+E), workers(+N), ray_address(+A): where to simulate
%     - oracle_options(+Dict): arguments of the oracle (a dict or JSON text)
%     - progress(+Bool): show a progress bar (default true)
%
%   @error exploration_error(Text) for bad options or a failing oracle.
explore(Options) :-
    settings(Options, Settings),
    call_bridge(exploration_begin, Settings, Begun),
    catch(explore_loop(Settings, Begun), E,
          ( catch(call_bridge(exploration_end, _{aborted:true}, _), _, true),
            throw(E) )).

%   explore_loop(+Settings, +Begun): the loop from its initial state, then
%   the learned theory written and the exploration ended.
explore_loop(Settings, Begun) :-
    initial_state(Begun, Settings, S0),
    loop(S0, Settings, S, Stop),
    S = st(_, Explored, ANew, SetAside),
    length(ANew, Left),
    learned(Explored, SetAside, Settings, Stop, Left, Facts),
    write_theory(Settings.out, Settings, Facts),
    length(Explored, N),
    call_bridge(exploration_end, _{out:Settings.out, stopped:Stop, explored:N,
                                   a_new:Left}, _).

%!  explore_result(+Options:list, -Result) is det.
%
%   Like explore/1, but never throws: Result is ok, or error(Text) with one
%   line saying what went wrong. For hosts that want a value, not an
%   exception.
explore_result(Options, Result) :-
    catch(( explore(Options), Result = ok ), E, error_result(E, Result)).

%   error_result(+Error, -Result): error(Text), Text the first line of
%   Error's message.
error_result(exploration_error(Text), error(Text)) :- !.
error_result(E, error(Text)) :-
    (   catch(message_lines(E, Lines), _, fail)
    ->  with_output_to(string(Text0), print_message_lines(current_output, '', Lines)),
        split_string(Text0, "\n", " ", [Text|_])
    ;   format(string(Text), "~q", [E])
    ).

message_lines(E, Lines) :-
    '$messages':translate_message(E, Lines, []).
