"""Learners that turn pours into rules. Algorithm 1's own rules are built by
the exploration (theory/curiosity.pl); learners here generalize from every
pour of an exploration."""
