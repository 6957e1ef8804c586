% The defaults of the project, written once and read by SWI-Prolog
% (theory/curiosity.pl, theory/pantarhei.pl) and by Python
% (pantarhei.theory.defaults: the command line and its help).
% Common subset of Prolog and ASP: ground facts, no floats (permille).

% Algorithm 1 (pantarhei explore): the curiosity (discover: planes tested
% against shuffled pours, and candidates (moves past a significant plane's
% flip, neighbours, random jumps) ranked by the novelty a forest of every
% pour so far predicts, then probed; paper: the paper's own variant), the
% oracle, the budget (explored antecedents for paper; for discover, the
% pours of as many batches), the threshold (for discover, the significance
% level of the permutation test with its number of shuffles; for paper,
% the slope below which nothing new is explored), how many more batches an
% antecedent gets when nothing new is queued after it, the novelty a
% candidate needs to be queued (scaled by the probes' mean score so far),
% how many A_new keeps, how many random valid
% antecedents each step draws as candidates (jumps), the pours of a probe
% (discover: the first pours of a candidate's batch, simulated before the
% rest; a candidate whose probe shows no new, reproducible consequent is
% set aside for the next, at most probe_attempts candidates a step; 0: no
% probes; the last of them goes to the candidate whose rarest proposition
% fewer than cover pours so far hold, the fewest, 0: never), whether
% (1) or not (0) the discovering curiosity explores the priors (the empty
% antecedent: every parameter drawn from its prior, as the parameters a
% question leaves unsaid are) with the last batch of the budget, the ridge of the plane fits, the seed, how many gradient
% components the paper's modify follows, and how an antecedent's
% consequent is qualified (weighted vote or the paper's argmax).
default(curiosity, discover).
default(oracle, pybullet).
default(max_rules, 25).
default(significance_permille, 50).
default(permutations, 199).
default(resample, 2).
default(novelty_permille, 100).
default(queue, 100).
default(jumps, 31).
default(probe, 8).
default(probe_attempts, 3).
default(cover, 0).
default(prior, 1).
default(threshold_permille, 100).
default(ridge_permille, 1000).
default(seed, 1).
default(breadth, 3).
default(qualify, weighted).

% After Algorithm 1, learn general rules from every pour of the
% exploration and add them to the theory (bridge/learning/): true or false.
default(general, true).
% Before learning them, the learner simulates pours of its own for the
% ordinary pour and for each proposition asked alone that fewer explored
% pours hold than this (bridge/learning/gaps.py).
default(pours_per_proposition, 12).
% An answer is uncertain where the likelihood that the expectation holds
% lies within this of one half (35% to 65% of such pours).
default(uncertain_band_permille, 150).

% a_0, the initial antecedent: an ordinary pour (from mid height, near the
% destination's rim, steeply tilted).
default_initial(pour_mid_height).
default_initial(pour_near_rim).
default_initial(pour_steeply_tilted).

% Where the learned theory is written (relative to theory/) and the store
% of simulations (relative to the working directory).
default(theory, "learned/pouring.pl").
default(store, "pantarhei.sqlite").
