"""The bridge between the theory (Prolog and ASP) and the oracle (the
simulation), and the `pantarhei` command. One folder per concern:

- `engines/`: SWI-Prolog (pyswip) and clingo hosted in this process;
- `theories/`: the theory model and its formats (native facts, DFL);
- `reasoning/`: conclusions, answers to questions, plans, validity;
- `exploration/`: the foreign predicates Algorithm 1 calls, and its state;
- `learning/`: learners that generalize pours into rules;
- `evaluation/`: held-out scenes, measures, baselines and the report;
- `commands/`: the command line only;
- `verdicts.py`: a pour's verdicts and the codes of an answer, which the
  folders above share.
"""
