% The defaults of the project, written once and read by SWI-Prolog
% (theory/curiosity.pl, theory/pantarhei.pl) and by Python
% (pantarhei.theory.defaults: the command line and its help).
% Common subset of Prolog and ASP: ground facts, no floats (permille).

% The options of Algorithm 1 (pantarhei explore, explore/1), each declared
% once: option(Name, Type, Range, Default, Help). From this table come the
% command line (--name, underscores as dashes; --no-name for a flag whose
% default is true), the checks of explore/1's options
% (theory/curiosity/settings.pl), the options Python passes to explore/1,
% the setting/2 facts of the learned theory (theory/curiosity/writer.pl),
% the reference page docs/options.md, and default(Name, Value) for Python
% (pantarhei.theory.defaults) and, for the rows of this file, Prolog
% (theory/default_values.pl).
% The rows are in the order of the help and of the setting/2 facts.
% The options that one curiosity alone reads are declared in its module
% (theory/curiosity/NAME.pl, NAME a value of the curiosity row below, the
% one list), as the same option/5 facts, with their course/2 and
% prolog_only/1 facts: their rows follow the curiosity row, the
% curiosities in the list's order, or the row that an
% option_after(Name, Row) fact of the module names (read by
% theory/option_table.py and theory/curiosity/settings.pl). This file
% declares those that several curiosities read, or every one.
% Type and Range:
%   count, range(Low, High): a whole number from Low to High;
%   permille, range(Low, High): a number from Low/1000 to High/1000
%     (High none: no bound), its default in thousandths;
%   choice, one_of(A, B, ...): one of those;
%   oracle, one_of(A, B, ...): an oracle, those the command line offers;
%   flag, none: true or false;
%   antecedent, none: a valid antecedent (propositions);
%   path, none and text, none: a file, or text.
% A Default none is set otherwise: the help says how (a_0's are the
% default_initial facts below). Default default(Key) is the project's
% default(Key, Value) below.
option(oracle, oracle, one_of(pybullet, synthetic), pybullet,
  "the simulation, or analytic test scores (synthetic)").
option(seed, count, range(0, 2147483647), 1,
  "seed of every random choice").
option(batch, count, range(1, 10000), none,
  "pours simulated per batch, for each explored antecedent (default: parameters + 1; learn: learn_batch of theory/defaults.pl)").
option(budget, count, range(1, 100000), 25,
  "the budget: the pours of this many batches, probes included (discover); this many explored antecedents (paper)").
option(curiosity, choice, one_of(learn, discover, paper), learn,
  "learn: from the ordinary pour, explore what questions say, the antecedent whose pours would change the theory most first, and write one layer of rules of the explored antecedents; discover: queue the candidates (moves past where a significant plane's verdict flips, neighbours, random jumps) a forest of the pours so far predicts to show something new, most novel first; paper: Algorithm 1 as the paper states it").
option(ridge, permille, range(0, none), 1000,
  "L2 penalty of the plane fits on normalised parameters; 0 is the paper's plain least squares").
option(qualify, choice, one_of(weighted, argmax), weighted,
  "the consequent of an antecedent: the weighted vote of its simulations (weighted) or the simulation of largest weight (argmax, the paper's)").
option(initial, antecedent, none, none,
  "the initial antecedent a_0, propositions separated by commas").
option(general, flag, none, true,
  "--no-general: write Algorithm 1's rules only, without the general rules learned from every pour (discover and paper; learn writes one layer)").
option(learner, choice, one_of(general), general,
  "the learner of the general rules from every pour (bridge/learning/learners.py; the theory records it, and the evaluation learns again with it)").
option(store, path, none, default(store),
  "SQLite file of simulations and exploration state").
option(out, path, none, default(explore_out),
  "the learned theory; the trace (.trace.jsonl) and its plot (.trace.png) go beside it").
option(resume, flag, none, false,
  "continue the saved exploration with the same settings").
option(executor, choice, one_of(local, ray, inline), local,
  "worker processes here, a Ray cluster, or this process").
option(workers, count, range(1, 1024), none,
  "worker processes (default: one per core)").
option(ray_address, text, none, none,
  "Ray cluster to join (with --executor ray; default: start a local Ray on this machine)").
option(progress, flag, none, true,
  "--no-progress: no progress bar").

% The options explore/1 takes in its option list alone (prolog_only(Name):
% `pantarhei explore` has no flag for them, docs/options.md lists them
% apart): the paper's variants of the planes and of qualify, which the
% default curiosity does not read (the tuning of each curiosity's own
% options is in its module). docs/dropped.md says, with the figure, why
% each value other than the default is not the default.
prolog_only(ridge).
prolog_only(qualify).

% The options that decide an exploration's course, hashed into its run
% key (bridge/exploration/course.py; a saved run resumes only with the
% same): course(Name, When), When every (every run), discover, paper or
% learn (runs of that curiosity), other_than(C) (runs of another curiosity than
% C) or nonzero(Option) (runs where Option is not 0:
% those without it keep their keys). A name with several facts needs all.
course(oracle, every).
course(seed, every).
course(batch, every).
course(initial, every).
course(ridge, every).
course(curiosity, other_than(paper)).

% The options that some curiosities read and others do not: used_by(Name,
% Curiosity), one fact for each curiosity that reads it; an option without
% such facts is read by every curiosity, and one that a curiosity's module
% declares by that curiosity alone. explore/1 refuses, in one line,
% an option that the run's curiosity does not read (theory/curiosity/
% settings.pl), and Python passes it only such options as it reads, or
% set to another value than the default (bridge/exploration/explore_call.py).
% A curiosity's budget is the one of budget and pours that it reads.
used_by(budget, discover).
used_by(budget, paper).
used_by(ridge, discover).
used_by(ridge, paper).
used_by(qualify, discover).
used_by(qualify, paper).
used_by(general, discover).
used_by(general, paper).

% The learned theory's setting/2 facts say how it was learned: the options
% of the run's course/2 above and these, which decide what the theory says
% without changing the course (a run resumes with a larger budget). A
% permille option is written as Name_permille in thousandths, the oracle
% with its version (oracle_version), and the propositions of an
% antecedent one fact each, after the run's own facts.
recorded(budget).
recorded(qualify).
recorded(learner).

% The verdict of a pour: an expectation holds where its score (0 to 1,
% oracle/scoring.py) is above this, and fails otherwise. Read by Python
% (pantarhei.bridge.verdicts.verdicts) and Prolog
% (theory/curiosity/modify.pl) alike.
default(verdict_threshold_permille, 500).

% How deep a term of a theory file may nest (a theory's facts nest two or
% three deep), so that every reader after the two that check it may
% recurse on terms without running out. Read by Python
% (bridge/theories/facts.py) and Prolog (theory/fact_reader.pl) alike,
% each reading this file, the project's own, without the bound first.
default(nesting_at_most, 32).

% After Algorithm 1, the general rules are learned from every pour of the
% exploration (option general above; bridge/learning/).
% Before learning them, the learner simulates pours of its own for the
% ordinary pour and for each proposition asked alone that fewer explored
% pours hold than this (bridge/learning/gaps.py).
default(pours_per_proposition, 12).
% An answer is uncertain where the likelihood that the expectation holds
% lies within this of one half (35% to 65% of such pours).
default(uncertain_band_permille, 150).
% The general learner's tuning (learner general; bridge/learning/generalize.py,
% its Settings, says what each does; docs/dropped.md gives the figures behind
% them): the rules per expectation, the default's included; the most
% propositions of a body; the parameterizations drawn per body; the cost of
% an answer in another band; how much the empty body and a pair count (a
% proposition alone counts 1); the cost a new rule must remove; the pours of
% its own below which a body a sure rule answers may be doubted, how sure
% such a rule is, and how unlikely its pours must be under it; and how many
% pours the model of the pours counts as beside a body's own.
default(general_rules_per_expectation, 12).
default(general_max_body, 2).
default(general_draws, 64).
default(general_miss_permille, 500).
default(general_default_weight, 20).
default(general_pair_weight_permille, 200).
default(general_min_gain_permille, 100).
default(general_doubt_support, 4).
default(general_doubt_confidence_permille, 800).
default(general_unlikely_permille, 50).
default(general_model_pours, 4).

% The pours of a batch of the learning curiosity (the others': parameters + 1).
default(learn_batch, 2).
% The learning curiosity's model of the pours (bridge/exploration/teaching.py):
% parameterizations drawn per candidate pair to average it over (4 times
% as many for one proposition, 16 for the empty antecedent), its rounds
% of boosting (the learner's take 150), and how much the pours grow
% before it is fitted again.
default(learn_draws, 16).
default(learn_rounds, 50).
default(learn_refit_growth_permille, 1200).
% The discovering curiosity's probe passes when the chance it gives of a
% new, reproducible consequent is at least this: more likely than not
% (bridge/exploration/novelty.py).
default(probe_pass_permille, 500).

% Plans (`pantarhei plan`, the report's plans; bridge/reasoning/plan_search.py):
% a plan tried is verified on plan_verify pours, and one whose goals were
% met in plan_min_success of them is confirmed on as many fresh pours (a
% seed of their own): it is verified only if its goals were met in
% plan_min_success of all its pours, pooled (docs/questions.md says why).
% A search simulates plan_pours at most.
default(plan_verify, 10).
default(plan_min_success_permille, 900).
default(plan_pours, 80).

% a_0, the initial antecedent of the discovering and the paper's curiosity:
% an ordinary pour (from mid height, near the destination's rim, steeply
% tilted). The learning curiosity starts from the empty antecedent, the
% ordinary pour as a question means it.
default_initial(pour_mid_height).
default_initial(pour_near_rim).
default_initial(pour_steeply_tilted).

% The largest theory file either reader reads (bytes; 32 MiB, some 200,000
% learned rules): loading and answering are linear in the file, so this
% bounds what a file may cost.
default(theory_bytes_at_most, 33554432).

% Where the learned theory is written (relative to theory/) and the store
% of simulations (relative to the working directory).
default(theory, "learned/pouring.pl").
% Where an exploration writes its theory when not told (relative to the
% working directory): never over the shipped theory, which `pantarhei demo`
% writes by name.
default(explore_out, "explore.pl").
default(store, "pantarhei.sqlite").
