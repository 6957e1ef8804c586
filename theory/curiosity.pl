:- module(curiosity,
          [ explore/1,                % +Options
            explore_result/2,         % +Options, -Result
            sample/4,                 % +Props, +N, +Seed, -Rows
            simulate/3,               % +Rows, +Options, -Scores
            default_initial/1,        % -Props
            describe/2,               % +Row, -Props
            direction/3,              % +Gradient, +MeanScore, -Direction
            modify/5,                 % +Props, +Direction, +Breadth, +Exclude, -New
            modify_past/4,            % +Props, +Moves, +Exclude, -New
            parameter_mean/3,         % +Props, +Param, -Mean
            rule_facts/3,             % +Learned, +Qualified, -Facts
            write_theory/5            % +File, +Settings, +Layout, +Facts, +General
          ]).
/** <module> Curiosity-driven exploration: Algorithm 1 of the paper

The control flow of Algorithm 1 lives in the folder curiosity/ beside this
file, one module per concern, in the order of the loop:

  | run.pl      | explore/1: the settings, the loop, the learned theory |
  | settings.pl | the options of explore/1, checked, with their defaults |
  | state.pl    | the loop's state: A_new, the explored antecedents, those set aside |
  | loop.pl     | the loop, its budget, and one step of Algorithm 1 |
  | probe.pl    | which candidate a step explores: the probes |
  | interface.pl | the curiosities: the module of each, and their interface |
  | learn.pl    | the learning curiosity: candidates by what they teach |
  | discover.pl | the discovering curiosity: candidates by novelty |
  | paper.pl    | the paper's curiosity: modify/5 along the steepest plane |
  | plane_steps.pl | what the discovering and the paper's curiosity share |
  | modify.pl   | direction and modify: new antecedents from a plane |
  | writer.pl   | qualify, the general layer, and both written as one theory |
  | oracle_prompt.pl | the oracle at the Prolog prompt: sample, describe, simulate |
  | foreign.pl  | calling the foreign predicates of Python's oracle |

This module loads them and exports what callers outside use (as
curiosity:explore/1, curiosity:modify/5, ...); each module's plunit tests
are in the .plt beside it. The modules are named curiosity_<file>
(curiosity_loop, ...). The numeric work (sampling and simulating, the
weights of equation (1), the weighted plane fits, the novelty of
candidates, the outcome of an antecedent's simulations) is done in Python
behind foreign predicates of the module =bridge=, which `pantarhei
explore` and `pantarhei prolog` register (foreign.pl lists them).

Three curiosities share the loop (option curiosity/1), each a module
behind the interface of interface.pl, which names them:

  - `paper`: Algorithm 1 as the paper states it. The steepest plane of all
    explored antecedents is followed when its slope exceeds slope(X),
    and modify/5 moves the parameters of its largest gradient components by
    one rank.
  - `discover`: a plane's slopes count only where they beat shuffles of the
    same weighted pours (a permutation test at the significance level given
    as significance(X)). The candidates of a step are the antecedents that move
    the pours past the point where a significant plane's verdict flips
    (modify_past/4), the neighbours of the antecedent just explored, and
    `jumps` uniformly random valid antecedents; A_new keeps the most novel
    of them (discover.pl), and each is probed before a batch is spent on
    it (probe.pl). With prior_batch(1) (the default) the last batch of the
    budget goes to the priors, the empty antecedent (loop.pl).
  - `learn`: from the ordinary pour (the empty antecedent), explore what
    questions say: antecedents of one proposition more than one explored,
    up to body(N), the one whose pours would change the theory most first
    (learn.pl); the budget is every pour, pours(N). The theory is one
    layer: the rules of the explored antecedents (writer.pl).
*/

:- use_module(default_values).
:- use_module(curiosity/foreign).
:- use_module(curiosity/settings).
:- use_module(curiosity/state).
:- use_module(curiosity/modify).
:- use_module(curiosity/plane_steps).
:- use_module(curiosity/interface).
:- use_module(curiosity/probe).
:- use_module(curiosity/loop).
:- use_module(curiosity/writer).
:- use_module(curiosity/run).
:- use_module(curiosity/oracle_prompt).
