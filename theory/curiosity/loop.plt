:- begin_tests(curiosity_loop).

:- use_module(loop).
:- use_module(state).

% The priors (the empty antecedent) take the last batch of the budget, or
% the next when A_new is empty, once; a_0 alone starts A_new.
test(the_priors_take_the_last_batch_once) :-
    Settings = _{curiosity:discover, initial:[pour_low], prior_batch:1, budget:4,
                 batch:10, probe:2, probe_attempts:3},
    initial_state(_{}, Settings, S0),
    S0 == st(0, [], [cand([pour_low], none, initial)], []),
    C = cand([pour_high], none, jump),
    A1 = ant(a1, [pour_low], none, initial),
    % 10 spent: a step (at most 14) and the priors (10) fit in 40
    next_move(st(1, [A1], [C], []), Settings, step),
    % 20 spent: a step and the priors would not, the priors alone do
    next_move(st(2, [A1], [C], []), Settings, priors),
    % A_new empty: the priors before stopping
    next_move(st(1, [A1], [], []), Settings, priors),
    % explored once, never again
    P = ant(a2, [], none, prior),
    next_move(st(3, [A1, P], [C], []), Settings, stop(budget)),
    next_move(st(2, [A1, P], [], []), Settings, stop(a_new_empty)),
    next_move(st(2, [A1, P], [C], []), Settings, step),
    % not when they would exceed the budget, nor without prior_batch(1), nor for
    % the paper's curiosity
    next_move(st(4, [A1], [C], []), Settings, stop(budget)),
    next_move(st(2, [A1], [C], []), Settings.put(prior_batch, 0), step),
    next_move(st(2, [A1], [C], []), Settings.put(curiosity, paper), step),
    initial_state(_{}, Settings.put(prior_batch, 0), S0).

% A step's draws: each probe's first pours of its attempt's batch, in the
% order probed, then what the explored antecedent's probe left of its batch;
% without probes, the whole batch of attempt 0.
test(a_step_records_its_pours_as_draws) :-
    Settings = _{curiosity:discover, batch:10, probe:3},
    draws([probe([pour_low], 0.2, false, 0), probe([pour_high], 0.9, true, 1)], Settings,
          [pour_high], 1, 3, Draws),
    Draws = [_{antecedent:[pour_low], attempt:0, pours:[0, 3]},
              _{antecedent:[pour_high], attempt:1, pours:[0, 3]},
              _{antecedent:[pour_high], attempt:1, pours:[3, 10]}],
    draws([], Settings.put(curiosity, learn), [], 0, 0, Alone),
    Alone = [_{antecedent:[], attempt:0, pours:[0, 10]}].

:- end_tests(curiosity_loop).
